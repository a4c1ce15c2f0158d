!> Deck reader: keyword deck (docs/deck.md) -> validated model_t.
!>
!> deck_read lexes the deck (rodyn_deck_lexer), hands each card to the reader of its
!> keyword (one routine per *KEYWORD), then validates the whole model: names referred
!> to exist, lines get their segments and total length, node numbers exist, no node is
!> constrained twice, the sea is consistent, defaults resolved,
!> and a line that is not held at both ends starts straight (its end distance equals
!> its length). The first error found ends the reading with a located message
!> 'FILE:LINE: error: *KEYWORD: message' in err (code stat_input).
!>
!> The readers of the dynamic-analysis keywords (*DYNAMIC, *DAMPING, *AMPLITUDE,
!> *MOTION, *INITIAL VELOCITY) and their whole-deck checks are in rodyn_deck_dynamic;
!> those of the sea (*WATER, *CURRENT, *SEABED), of *SEGMENT and *ATTACHMENT, the
!> hydrodynamic parameters of *SECTION, the lines' segments and totals and the checks
!> of the sea in rodyn_deck_water; what the readers remember for validation and their
!> shared checks, in rodyn_deck_support.
module rodyn_deck
   use rodyn_section, only: section_default_rotary_inertia
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, set_error, has_error, stat_input
   use rodyn_model, only: model_t, section_t, line_def_t, constraint_t, point_load_t, &
                          bc_free, bc_pinned, bc_hinged, bc_clamped, bc_position, end_a, end_b, &
                          element_names, element_cable, element_rod
   use rodyn_deck_lexer, only: deck_t, deck_lex, keyword_count, deck_source_t
   use rodyn_deck_card, only: card_t, card_check_params, card_find_param, card_error, &
                              card_param_error, card_data_error, card_check_data, card_data_count, &
                              param_len
   use rodyn_deck_card_values, only: card_get_real, card_get_int, card_get_name, card_get_choice, &
                                     card_get_yesno, card_data_reals
   use rodyn_deck_numbers, only: real_str, int_str
   use rodyn_deck_params, only: param_override_t
   use rodyn_deck_support, only: ref_t, pending_t, reading_t, get_item_name, &
                                 max_cutbacks, max_elements, check_card, &
                                 max_gravity, max_distance, max_increments, max_iterations, &
                                 get_node, get_pair, &
                                 get_bounded, get_tolerance, data_check, param_fail, &
                                 location, resolve_line, check_node_once, &
                                 get_int_range
   use rodyn_deck_dynamic, only: read_dynamic_card, read_damping_card, &
                                 read_amplitude_card, read_motion_card, &
                                 read_initial_velocity_card, validate_dynamics
   use rodyn_deck_dynamic_warnings, only: dynamic_warnings
   use rodyn_deck_body_waves, only: read_body_wave_load_card, check_body_wave_loads, &
                                    body_wave_warnings
   use rodyn_deck_vessel, only: read_vessel_card, validate_vessels
   use rodyn_deck_section_damping, only: read_section_damping
   use rodyn_deck_water, only: read_water_card, read_current_card, read_seabed_card, &
                               read_segment_card, read_attachment_card, read_section_hydro, &
                               resolve_segments, validate_water
   use rodyn_deck_waves, only: read_wave_card, wave_warnings, &
                               read_wave_probe_card
   use rodyn_deck_line, only: read_line_card, all_cable, check_line_element, &
                              check_line_geometry, static_analysis_runs, check_supported, &
                              check_straight_start
   use rodyn_deck_body, only: read_body_card, read_body_hydrostatics_card, &
                              read_body_added_mass_card, read_offset_curve_card, &
                              resolve_offset_curve, read_modal_card, check_modal, &
                              resolve_point_bodies, resolve_load_bodies, check_bodies
   use rodyn_deck_system, only: read_failure_card, check_failures, &
                                read_point_card, resolve_line_points, resolve_load_points, &
                                check_clamped_ends, check_point_ends, system_complete
   implicit none
   private
   public :: deck_read, deck_source_t

   !> A whole-deck check, run once all cards are read (validate_model).
   abstract interface
      subroutine deck_check_i(deck, pend, model, err)
         import :: deck_t, pending_t, model_t, error_t
         type(deck_t), intent(in) :: deck        !< all cards
         type(pending_t), intent(in) :: pend     !< what the cards named
         type(model_t), intent(inout) :: model   !< model being completed
         type(error_t), intent(inout) :: err     !< status
      end subroutine deck_check_i
   end interface

   !> One entry of the table of whole-deck checks.
   type :: deck_check_t
      procedure(deck_check_i), pointer, nopass :: run => null() !< the check
   end type deck_check_t

contains

   !> Read the deck `path` into `model`, fully validated (docs/deck.md). err must be
   !> clear on entry. On error, err holds a message 'FILE:LINE: error: ...' (stat_input),
   !> model%deck_text what was read, and the model arrays the items read before the error.
   !> `overrides` are the --set values of parameters (rodyn_deck_params); model%parameters
   !> gets the values used; `warnings` the lines 'FILE:LINE: warning: ...' to show
   !> (parameters never used), each ended by a newline ('' if none). With `source`, the
   !> deck is its text (a MoorDyn file translated), located at the lines of path it maps.
   subroutine deck_read(path, model, err, overrides, warnings, source)
      character(len=*), intent(in) :: path    !< path of the main deck file
      type(model_t), intent(out) :: model     !< the model read
      type(error_t), intent(inout) :: err     !< status (stat_input on a bad rd%deck)
      type(param_override_t), intent(in), optional :: overrides(:) !< --set values
      character(len=:), allocatable, intent(out), optional :: warnings !< warning lines
      type(deck_source_t), intent(in), optional :: source !< the deck's text, for path's
      type(reading_t) :: rd
      integer :: ic

      model%deck_file = path
      model%deck_text = ''
      model%title = ''
      call deck_lex(path, rd%deck, err, overrides, source)
      if (allocated(rd%deck%text)) model%deck_text = rd%deck%text
      if (has_error(err)) rd%deck%n_cards = 0
      allocate (model%parameters(rd%deck%params%n))
      do ic = 1, rd%deck%params%n
         model%parameters(ic)%name = rd%deck%params%p(ic)%name
         model%parameters(ic)%text = rd%deck%params%p(ic)%text
         model%parameters(ic)%is_number = rd%deck%params%p(ic)%is_number
         model%parameters(ic)%value = rd%deck%params%p(ic)%value
      end do
      if (present(warnings)) then
         warnings = ''
         if (allocated(rd%deck%warnings)) then
            do ic = 1, size(rd%deck%warnings)
               warnings = warnings//rd%deck%warnings(ic)%s//new_line('a')
            end do
         end if
      end if

      call size_items(rd%deck, model, rd%pend)
      if (has_error(err)) return

      do ic = 1, rd%deck%n_cards
         rd%ic = ic
         call read_card(rd, model, err)
         if (has_error(err)) then
            call trim_model(rd%pend, model)
            return
         end if
      end do
      call validate_model(rd%deck, rd%pend, model, err)
      if (present(warnings) .and. .not. has_error(err)) &
         warnings = warnings//dynamic_warnings(rd%deck, model)//wave_warnings(rd%deck, model)// &
                    body_wave_warnings(model)
   end subroutine deck_read

   !> Size the model's arrays and the readers' records from the keyword counts; the
   !> cards then fill them one by one.
   subroutine size_items(deck, model, pend)
      type(deck_t), intent(in) :: deck        !< all cards
      type(model_t), intent(inout) :: model   !< model: item arrays allocated
      type(pending_t), intent(inout) :: pend  !< records allocated
      character(len=16), parameter :: keywords(13) = [character(len=16) :: 'SECTION', &
         'LINE', 'BOUNDARY', 'LOAD', 'AMPLITUDE', 'MOTION', 'VESSEL', 'INITIAL VELOCITY', &
         'ATTACHMENT', 'POINT', 'BODY', 'FAILURE', 'SEGMENT']
      integer :: n(13), k
      n = [(keyword_count(deck, keywords(k)), k = 1, 13)]
      allocate (model%sections(n(1)), model%lines(n(2)), model%constraints(n(3)), &
                model%loads(n(4)), model%amplitudes(n(5)), model%motions(n(6)), &
                model%vessels(n(7)), model%initial_velocities(n(8)), &
                model%attachments(n(9)), model%points(n(10)), model%bodies(n(11)), &
                model%failures(n(12)))
      allocate (model%water%cur_z(0), model%water%cur_speed(0), model%water%cur_heading(0))
      allocate (pend%section_card(n(1)), pend%line_section(n(2)), pend%line_point_a(n(2)), &
                pend%line_point_b(n(2)), pend%bc_line(n(3)), pend%load_line(n(4)), &
                pend%load_amp(n(4)), pend%load_point(n(4)), pend%load_body(n(4)), &
                pend%amplitude_card(n(5)), pend%motion_line(n(6)), pend%motion_vessel(n(6)), &
                pend%motion_body(n(6)), pend%motion_point(n(6)), pend%vessel_card(n(7)), &
                pend%iv_line(n(8)), pend%iv_body(n(8)), pend%att_line(n(9)), &
                pend%point_card(n(10)), pend%point_body(n(10)), pend%body_card(n(11)), &
                pend%body_sub(5, n(11)), pend%failure_line(n(12)), pend%seg_line(n(13)), &
                pend%seg_section(n(13)), pend%seg_length(n(13)), pend%seg_elements(n(13)))
   end subroutine size_items

   !> After an error: shrink the model's arrays to the items actually read.
   subroutine trim_model(pend, model)
      type(pending_t), intent(in) :: pend    !< how many items were read
      type(model_t), intent(inout) :: model  !< model to trim
      model%sections = model%sections(1:pend%n_sections)
      model%lines = model%lines(1:pend%n_lines)
      model%constraints = model%constraints(1:pend%n_constraints)
      model%loads = model%loads(1:pend%n_loads)
      model%amplitudes = model%amplitudes(1:pend%n_amplitudes)
      model%motions = model%motions(1:pend%n_motions)
      model%vessels = model%vessels(1:pend%n_vessels)
      model%initial_velocities = model%initial_velocities(1:pend%n_ivs)
      model%attachments = model%attachments(1:pend%n_attachments)
      model%points = model%points(1:pend%n_points)
      model%bodies = model%bodies(1:pend%n_bodies)
      model%failures = model%failures(1:pend%n_failures)
   end subroutine trim_model

   !> Hand card rd%ic to the reader of its keyword.
   subroutine read_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card to read, the records
      type(model_t), intent(inout) :: model   !< model being filled
      type(error_t), intent(inout) :: err     !< status

      associate (card => rd%deck%cards(rd%ic))
         select case (card%keyword)
         case ('HEADING')
            call read_heading_card(rd, model, err)
         case ('GRAVITY')
            call read_gravity_card(rd, model, err)
         case ('SECTION')
            call read_section_card(rd, model, err)
         case ('LINE')
            call read_line_card(rd, model, err)
         case ('BOUNDARY')
            call read_boundary_card(card, rd%ic, model, rd%pend, err)
         case ('LOAD')
            call read_load_card(card, rd%ic, model, rd%pend, err)
         case ('STATIC')
            call read_static_card(rd, model, err)
         case ('OUTPUT')
            call read_output_card(rd, model, err)
         case ('DYNAMIC')
            call read_dynamic_card(rd, model, err)
         case ('DAMPING')
            call read_damping_card(rd, model, err)
         case ('AMPLITUDE')
            call read_amplitude_card(rd, model, err)
         case ('MOTION')
            call read_motion_card(rd, model, err)
         case ('INITIAL VELOCITY')
            call read_initial_velocity_card(rd, model, err)
         case ('WATER')
            call read_water_card(rd, model, err)
         case ('CURRENT')
            call read_current_card(rd, model, err)
         case ('SEABED')
            call read_seabed_card(rd, model, err)
         case ('SEGMENT')
            call read_segment_card(card, rd%ic, rd%pend, err)
         case ('ATTACHMENT')
            call read_attachment_card(rd, model, err)
         case ('POINT')
            call read_point_card(rd, model, err)
         case ('BODY')
            call read_body_card(rd, model, err)
         case ('BODY HYDROSTATICS', 'BODY DAMPING')
            call read_body_hydrostatics_card(rd, model, err)
         case ('BODY ADDED MASS', 'BODY DRAG')
            call read_body_added_mass_card(rd, model, err)
         case ('BODY WAVE LOAD')
            call read_body_wave_load_card(rd, model, err)
         case ('FAILURE')
            call read_failure_card(rd, model, err)
         case ('OFFSET CURVE')
            call read_offset_curve_card(rd, model, err)
         case ('MODAL')
            call read_modal_card(rd, model, err)
         case ('VESSEL')
            call read_vessel_card(rd, model, err)
         case ('WAVE')
            call read_wave_card(rd%deck, rd%ic, model, err)
         case ('WAVE PROBE')
            call read_wave_probe_card(rd%deck, rd%ic, model, err)
         case default
            if (index(card%keyword, '=') > 0) then
               call card_error(card, 'unknown keyword (a comma missing after the keyword?)', &
                               err)
            else
               call card_error(card, 'unknown keyword', err)
            end if
         end select
      end associate
   end subroutine read_card

   ! ================================================================ card readers

   !> *HEADING: free-text data lines, the first one is the title. At most one.
   subroutine read_heading_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: title set
      type(error_t), intent(inout) :: err     !< status

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call check_card(deck, ic, [character(len=param_len) ::], 1, -1, err, first=pend%heading, &
                         what='the title')
         if (has_error(err)) return
         model%title = card%data(1)%text
      end associate
   end subroutine read_heading_card

   !> *GRAVITY: one data line gx, gy, gz [m/s2]. At most one; zero is allowed.
   subroutine read_gravity_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: gravity set
      type(error_t), intent(inout) :: err     !< status
      character(len=*), parameter :: what = 'gx, gy, gz'
      real(wp) :: g(3)

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call check_card(deck, ic, [character(len=param_len) ::], 1, 1, err, first=pend%gravity, &
                         what=what)
         call card_data_reals(card, 1, 3, g, err, what)
         if (has_error(err)) return
         if (norm2(g) > max_gravity) then
            call card_data_error(card, 1, 'the gravity of '//real_str(norm2(g))// &
                                 ' m/s2 is not physical: its magnitude must be at most '// &
                                 real_str(max_gravity)//' m/s2 (about 100 g)', err)
            return
         end if
         model%gravity = g
      end associate
   end subroutine read_gravity_card

   !> *SECTION: cross-section properties; data line EA, EI1, EI2, GJ, MASS and an
   !> optional line K1, K2, K3 (stress-free curvature). GA/RHOI set both components.
   !> The structural damping (AXIAL DAMPING, ...) is read by rodyn_deck_section_damping.
   !> Defaults (GA -> EA, RHOI -> MASS*OD**2/16, the buoyancy and drag diameters) are
   !> resolved in validate_model; the hydrodynamic and contents parameters are read by
   !> rodyn_deck_water's read_section_hydro.
   subroutine read_section_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: one section appended
      type(error_t), intent(inout) :: err     !< status
      character(len=*), parameter :: what1 = 'EA, EI1, EI2, GJ, MASS'
      character(len=*), parameter :: what2 = 'K1, K2, K3'
      type(section_t) :: sec
      character(len=:), allocatable :: name
      real(wp) :: v(5), k(3)
      integer :: elem

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call card_check_params(card, [character(len=param_len) :: 'NAME', 'OD', 'GA', &
                                'GA1', 'GA2', 'RHOI', 'RHOI1', 'RHOI2', &
                                'BUOYANCY DIAMETER', 'DRAG DIAMETER', 'CDN', 'CDA', 'CAN', &
                                'CAA', 'ID', 'CONTENTS DENSITY', 'CONTENTS PRESSURE', &
                                'PRESSURE Z', 'ELEMENT', 'AXIAL DAMPING', &
                                'AXIAL DAMPING RATIO', 'BENDING DAMPING'], err)
         call get_item_name(deck, ic, model%sections(1:pend%n_sections)%name, &
                            pend%section_card(1:pend%n_sections), 'section', name, err)
         if (has_error(err)) return
         sec%name = name

         call get_bounded(card, 'OD', sec%od, .false., err)
         call get_pair(card, 'GA', 'GA1', 'GA2', sec%ga1, sec%ga2, .true., err)
         call get_pair(card, 'RHOI', 'RHOI1', 'RHOI2', sec%rhoi1, sec%rhoi2, .false., err)
         call read_section_hydro(card, sec, err)

         call card_check_data(card, 1, 2, err, what1)
         call card_data_reals(card, 1, 5, v, err, what1)
         if (has_error(err)) return
         ! EI1, EI2, GJ > 0 for a rod; all three 0 make a cable section (ELEMENT=CABLE
         ! by default), and a cable section may give any values >= 0 (it reads EA only)
         elem = 0
         call card_get_choice(card, 'ELEMENT', element_names, elem, err)
         if (has_error(err)) return
         if (elem == 0 .and. all(v(2:4) == 0.0_wp)) elem = element_cable
         if (elem == 0) elem = element_rod
         sec%element = elem
         call data_check(card, 1, 'EA', v(1), .true., err)
         call data_check(card, 1, 'EI1', v(2), elem == element_rod, err)
         call data_check(card, 1, 'EI2', v(3), elem == element_rod, err)
         call data_check(card, 1, 'GJ', v(4), elem == element_rod, err)
         call data_check(card, 1, 'MASS', v(5), .false., err)
         if (has_error(err)) return
         sec%ea = v(1)
         sec%ei1 = v(2)
         sec%ei2 = v(3)
         sec%gj = v(4)
         sec%mass = v(5)
         call read_section_damping(card, sec, err)
         if (has_error(err)) return
         if (card%n_data >= 2) then
            call card_data_reals(card, 2, 3, k, err, what2)
            if (has_error(err)) return
            sec%kappa0 = k
         end if
         pend%n_sections = pend%n_sections + 1
         model%sections(pend%n_sections) = sec
         pend%section_card(pend%n_sections) = ic
      end associate
   end subroutine read_section_card

   !> *BOUNDARY: a node constraint of TYPE FREE, PINNED, HINGED (data line: axis),
   !> CLAMPED or POSITION (data line: position), at END=A|B or NODE=k of LINE=name.
   subroutine read_boundary_card(card, ic, model, pend, err)
      type(card_t), intent(in) :: card        !< the *BOUNDARY card
      integer, intent(in) :: ic               !< its index
      type(model_t), intent(inout) :: model   !< model: one constraint appended
      type(pending_t), intent(inout) :: pend  !< remembers the LINE= reference
      type(error_t), intent(inout) :: err     !< status
      character(len=8), parameter :: types(5) = &
         [character(len=8) :: 'FREE', 'PINNED', 'HINGED', 'CLAMPED', 'POSITION']
      integer, parameter :: kinds(5) = [bc_free, bc_pinned, bc_hinged, bc_clamped, &
                                        bc_position]
      type(constraint_t) :: bc
      character(len=:), allocatable :: line
      real(wp) :: v(3), vn
      integer :: it

      call card_check_params(card, [character(len=param_len) :: 'LINE', 'END', 'NODE', &
                             'TYPE'], err)
      call card_get_name(card, 'LINE', line, err, required=.true.)
      call get_node(card, bc%node, err)
      it = 0
      call card_get_choice(card, 'TYPE', types, it, err, required=.true.)
      if (has_error(err)) return
      bc%kind = kinds(it)

      select case (bc%kind)
      case (bc_hinged)
         call card_check_data(card, 1, 1, err, 'hinge axis ax, ay, az')
         call card_data_reals(card, 1, 3, v, err, 'ax, ay, az')
         if (has_error(err)) return
         vn = norm2(v)
         if (.not. vn > 0.0_wp) then
            call card_data_error(card, 1, 'the hinge axis ax, ay, az is zero', err)
            return
         end if
         bc%axis = v/vn
      case (bc_position)
         call card_check_data(card, 1, 1, err, 'position x, y, z')
         call card_data_reals(card, 1, 3, v, err, 'x, y, z')
         if (has_error(err)) return
         bc%position = v
      case default
         if (card%n_data > 0) then
            call card_data_error(card, 1, 'data lines are not allowed with TYPE='// &
                                 trim(types(it)), err)
            return
         end if
      end select
      pend%n_constraints = pend%n_constraints + 1
      model%constraints(pend%n_constraints) = bc
      pend%bc_line(pend%n_constraints) = ref_t(line, ic)
   end subroutine read_boundary_card

   !> *LOAD: a point force (3 values) or force and moment (6 values), fixed in space,
   !> at END=A|B or NODE=k of LINE=name, optionally scaled by AMPLITUDE=name in time.
   subroutine read_load_card(card, ic, model, pend, err)
      type(card_t), intent(in) :: card        !< the *LOAD card
      integer, intent(in) :: ic               !< its index
      type(model_t), intent(inout) :: model   !< model: one load appended
      type(pending_t), intent(inout) :: pend  !< remembers the LINE= reference
      type(error_t), intent(inout) :: err     !< status
      character(len=*), parameter :: what = 'Fx, Fy, Fz, Mx, My, Mz'
      type(point_load_t) :: load
      character(len=:), allocatable :: line, amplitude, point, body
      real(wp) :: v(6)
      integer :: n

      call card_check_params(card, [character(len=param_len) :: 'LINE', 'END', 'NODE', &
                             'AMPLITUDE', 'POINT', 'BODY'], err)
      line = ''
      point = ''
      body = ''
      call card_get_name(card, 'POINT', point, err)
      call card_get_name(card, 'BODY', body, err)
      if (has_error(err)) return
      if (len(point) > 0 .or. len(body) > 0) then   ! on a FREE point or body
         if (card_find_param(card, 'LINE') > 0 .or. card_find_param(card, 'END') > 0 .or. &
             card_find_param(card, 'NODE') > 0 .or. (len(point) > 0 .and. len(body) > 0)) then
            call param_fail(card, merge('POINT', 'BODY ', len(point) > 0), 'give one of'// &
                            ' POINT=, BODY=, or LINE= with END= or NODE=', err)
            return
         end if
      else
         call card_get_name(card, 'LINE', line, err, required=.true.)
         call get_node(card, load%node, err)
         if (has_error(err)) return
      end if
      amplitude = ''
      call card_get_name(card, 'AMPLITUDE', amplitude, err)
      call card_check_data(card, 1, 1, err, 'Fx, Fy, Fz [, Mx, My, Mz]')
      if (has_error(err)) return
      n = card_data_count(card, 1)
      if (n /= 3 .and. n /= 6) then
         call card_data_error(card, 1, 'expected 3 or 6 values, got '//int_str(n)// &
                              ' (Fx, Fy, Fz [, Mx, My, Mz])', err)
         return
      end if
      v = 0.0_wp
      call card_data_reals(card, 1, n, v(1:n), err, what(1:merge(10, len(what), n == 3)))
      if (has_error(err)) return
      load%force = v(1:3)
      load%moment = v(4:6)
      load%card_at = card%file//':'//int_str(card%line)
      pend%n_loads = pend%n_loads + 1
      model%loads(pend%n_loads) = load
      pend%load_line(pend%n_loads) = ref_t(line, ic)
      pend%load_point(pend%n_loads) = ref_t(point, ic)
      pend%load_body(pend%n_loads) = ref_t(body, ic)
      pend%load_amp(pend%n_loads) = ref_t(amplitude, ic)
   end subroutine read_load_card

   !> *STATIC: request a static analysis and set its options. No data lines.
   subroutine read_static_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: static options set
      type(error_t), intent(inout) :: err     !< status

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic), st => model%static)
         call check_card(deck, ic, [character(len=param_len) :: 'INCREMENTS', 'MAX ITERATIONS', &
                         'CUTBACKS', 'FORCE TOL', 'DISP TOL', 'LINE SEARCH'], 0, 0, err, &
                         first=pend%static)
         st%requested = .true.
         call get_int_range(card, 'INCREMENTS', 1, max_increments, st%increments, err)
         call get_int_range(card, 'MAX ITERATIONS', 1, max_iterations, st%max_iterations, err)
         call get_int_range(card, 'CUTBACKS', 0, max_cutbacks, st%max_cutbacks, err)
         call get_tolerance(card, 'FORCE TOL', st%force_tol, err)
         call get_tolerance(card, 'DISP TOL', st%disp_tol, err)
         if (has_error(err)) return
         call card_get_yesno(card, 'LINE SEARCH', st%line_search, err)
      end associate
   end subroutine read_static_card

   !> *OUTPUT: which result files to write (CSV=YES|NO, HDF5=YES|NO). No data lines.
   subroutine read_output_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: output options set
      type(error_t), intent(inout) :: err     !< status

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call check_card(deck, ic, [character(len=param_len) :: 'CSV', 'HDF5'], 0, 0, err, &
                         first=pend%output)
         call card_get_yesno(card, 'CSV', model%output%csv, err)
         if (has_error(err)) return
         call card_get_yesno(card, 'HDF5', model%output%hdf5, err)
      end associate
   end subroutine read_output_card

   ! ================================================================ validation

   !> Whole-deck checks after all cards are read: at least one *SECTION and *LINE, then
   !> the checks of the table below in its order, each on the model the ones before it
   !> completed: the lines' sections and segments, the points and bodies the lines and
   !> loads name, the lines' geometry with the total length, references resolved in
   !> card order (LINE=, NODE range, one *BOUNDARY per node), the dynamic keywords'
   !> references, the sea, seabed and attachments (and EMC's RHO INF in water), the
   !> mooring system, waves and vessels; section defaults; lines not held at both ends
   !> start straight; every line is held somewhere when a static analysis will run.
   subroutine validate_model(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< references to resolve
      type(model_t), intent(inout) :: model   !< model to complete
      type(error_t), intent(inout) :: err     !< status
      type(deck_check_t) :: checks(19)
      integer :: k

      if (size(model%sections) == 0) then
         call set_error(err, stat_input, deck%main_file//':1: error: no *SECTION in deck')
         return
      end if
      if (size(model%lines) == 0) then
         call set_error(err, stat_input, deck%main_file//':1: error: no *LINE in deck')
         return
      end if
      checks = [deck_check_t(resolve_segments), deck_check_t(resolve_point_bodies), &
                deck_check_t(resolve_line_points), deck_check_t(check_lines), &
                deck_check_t(check_clamped_ends), deck_check_t(resolve_node_refs), &
                deck_check_t(resolve_load_points), deck_check_t(resolve_load_bodies), &
                deck_check_t(check_point_ends), deck_check_t(validate_dynamics), &
                deck_check_t(validate_water), deck_check_t(system_complete), &
                deck_check_t(check_bodies), deck_check_t(check_body_wave_loads), &
                deck_check_t(check_failures), deck_check_t(resolve_offset_curve), &
                deck_check_t(check_modal), deck_check_t(validate_vessels), &
                deck_check_t(check_lines_start)]
      do k = 1, size(checks)
         call checks(k)%run(deck, pend, model, err)
         if (has_error(err)) return
      end do
   end subroutine validate_model

   !> Each line's geometry with its total length, and its element.
   subroutine check_lines(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< card of each line
      type(model_t), intent(inout) :: model   !< model with the segments resolved
      type(error_t), intent(inout) :: err     !< status
      integer :: il
      do il = 1, size(model%lines)
         call check_line_geometry(deck%cards(pend%line_section(il)%card), model%lines(il), &
                                  err)
         if (has_error(err)) return
         call check_line_element(deck%cards(pend%line_section(il)%card), model, il, err)
         if (has_error(err)) return
      end do
   end subroutine check_lines

   !> The LINE= and node of each *BOUNDARY and of each *LOAD on a line, in card order:
   !> the line exists, the node is on it, one *BOUNDARY per node; a cable line has no
   !> rotations to hold and takes no moment.
   subroutine resolve_node_refs(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< LINE= of each constraint and load
      type(model_t), intent(inout) :: model   !< constraints and loads get their line
      type(error_t), intent(inout) :: err     !< status
      integer :: ic, ib, iload, iref

      ib = 0
      iload = 0
      do ic = 1, deck%n_cards
         select case (deck%cards(ic)%keyword)
         case ('BOUNDARY')
            ib = ib + 1
            call resolve_line(deck%cards(ic), pend%bc_line(ib)%name, model, &
                              iref, model%constraints(ib)%node, err)
            if (has_error(err)) return
            model%constraints(ib)%line = iref
            call check_node_once(deck, model, model%constraints(1:ib)%line, &
                                 model%constraints(1:ib)%node, pend%bc_line(1:ib)%card, ib, &
                                 'BOUNDARY', err)
            if (has_error(err)) return
            if (all_cable(model, iref) .and. &
                (model%constraints(ib)%kind == bc_hinged .or. &
                 model%constraints(ib)%kind == bc_clamped)) &
               call param_fail(deck%cards(ic), 'TYPE', 'line '// &
                               trim(model%lines(iref)%name)//' is made of cable '// &
                               'elements, which have no rotations to hold: TYPE '// &
                               'must be FREE, PINNED or POSITION', err)
         case ('LOAD')
            iload = iload + 1
            if (len(pend%load_point(iload)%name) > 0) cycle   ! (resolve_load_points)
            if (len(pend%load_body(iload)%name) > 0) cycle    ! (resolve_load_bodies)
            call resolve_line(deck%cards(ic), pend%load_line(iload)%name, model, &
                              iref, model%loads(iload)%node, err)
            if (has_error(err)) return
            model%loads(iload)%line = iref
            if (all_cable(model, iref) .and. any(model%loads(iload)%moment /= 0.0_wp)) &
               call card_data_error(deck%cards(ic), 1, 'line '//trim(model%lines(iref)%name)// &
                                    ' is made of cable elements, which take no moment: '// &
                                    'give Fx, Fy, Fz only', err)
         end select
         if (has_error(err)) return
      end do
   end subroutine resolve_node_refs

   !> The section defaults (resolve_section_defaults), then each line not held at both
   !> ends starts straight, and is held somewhere when a static analysis will run.
   subroutine check_lines_start(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< card of each line
      type(model_t), intent(inout) :: model   !< model to complete
      type(error_t), intent(inout) :: err     !< status
      integer :: il
      call resolve_section_defaults(model)
      do il = 1, size(model%lines)
         call check_straight_start(deck%cards(pend%line_section(il)%card), model, il, err)
         if (has_error(err)) return
         if (.not. static_analysis_runs(model)) cycle
         call check_supported(deck%cards(pend%line_section(il)%card), model, il, err)
         if (has_error(err)) return
      end do
   end subroutine check_lines_start
   !> Resolve the section defaults: GA1, GA2 -> EA (penalty on shear, formulation
   !> note); RHOI1, RHOI2 -> MASS*OD**2/16 (solid circular section; 0 without OD);
   !> buoyancy diameter -> OD (0 without OD: validate_water has refused that in water);
   !> drag diameter -> the buoyancy diameter.
   subroutine resolve_section_defaults(model)
      type(model_t), intent(inout) :: model  !< model whose sections are completed
      integer :: is
      do is = 1, size(model%sections)
         associate (s => model%sections(is))
            if (s%ga1 < 0.0_wp) s%ga1 = s%ea
            if (s%ga2 < 0.0_wp) s%ga2 = s%ea
            if (s%rhoi1 < 0.0_wp) s%rhoi1 = section_default_rotary_inertia(s%mass, s%od)
            if (s%rhoi2 < 0.0_wp) s%rhoi2 = section_default_rotary_inertia(s%mass, s%od)
            if (s%db < 0.0_wp) s%db = max(s%od, 0.0_wp)
            if (s%dd < 0.0_wp) s%dd = s%db
         end associate
      end do
   end subroutine resolve_section_defaults

end module rodyn_deck
