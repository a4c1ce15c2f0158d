!> Deck reader, the sea and what lies in it: *WATER, *CURRENT, *SEABED, *SEGMENT and
!> *ATTACHMENT (one routine per keyword), the hydrodynamic and contents parameters of
!> *SECTION (read_section_hydro), and their whole-deck checks: resolve_segments (every
!> line gets its segments, its total length and elements) and validate_water (*CURRENT
!> and *SEABED need *WATER, current levels in the water, attachments on their line,
!> sections in water have a buoyancy diameter, no line end below the seabed).
!> docs/deck.md describes every keyword, default and check; rodyn_deck hands the cards
!> to these readers and calls the checks.
module rodyn_deck_water
   use rodyn_kinds, only: wp, i8, pi
   use rodyn_error, only: error_t, has_error
   use rodyn_seabed, only: seabed_z
   use rodyn_model, only: model_t, section_t, line_def_t, attachment_t, end_a, bc_position, &
                          scheme_emc, rho_inf_emc_water
   use rodyn_deck_lexer, only: deck_t
   use rodyn_deck_card, only: card_t, card_check_params, card_find_param, card_error, &
                              card_data_error, card_check_data, param_len
   use rodyn_deck_card_values, only: card_get_real, card_get_int, card_get_name, card_data_real
   use rodyn_deck_table, only: table_t, card_data_table
   use rodyn_deck_numbers, only: real_str, int_str
   use rodyn_deck_support, only: ref_t, pending_t, reading_t, max_elements, check_once, &
                                 get_bounded, &
                                 get_lumped_body, check_card, get_pair, &
                                 data_check, param_fail, location, resolve_line, &
                                 resolve_section, check_at_most, get_int_range
   use rodyn_sort, only: sorted_order
   implicit none
   private

   !> densest water accepted [kg/m3]: beyond any liquid
   real(wp), parameter :: max_water_density = 2.0e4_wp
   !> largest drag or added-mass coefficient accepted [-]
   real(wp), parameter :: max_coefficient = 100.0_wp
   character(len=*), parameter :: coeff_why = 'no section has such a drag or added-mass '// &
      'coefficient (a cylinder: CDN about 1.2, CAN 1; a studless chain on its nominal '// &
      'diameter: CDN 2.4, CDA 1.15)'
   public :: read_water_card, read_current_card, read_seabed_card, read_segment_card
   public :: read_attachment_card, read_section_hydro, resolve_segments, validate_water
   public :: dynamic_scheme_default

   real(wp), parameter :: deg = pi/180.0_wp          !< one degree [rad]
   real(wp), parameter :: max_slope_deg = 90.0_wp    !< SLOPE must stay below [deg]
   real(wp), parameter :: seg_length_tol = 1.0e-9_wp !< LENGTH vs sum of segments, relative
   real(wp), parameter :: arc_tol = 1.0e-9_wp        !< S beyond LENGTH, relative
   real(wp), parameter :: bed_tol_rel = 1.0e-6_wp    !< end below the seabed, times DEPTH
   real(wp), parameter :: bed_tol_abs = 1.0e-9_wp    !< end below the seabed, absolute [m]
   character(len=*), parameter :: what_cur = 'z, speed, heading' !< *CURRENT columns

contains

   ! ================================================================ card readers

   !> *WATER, DEPTH= [, SURFACE=, DENSITY=]: still water level z = SURFACE, depth below
   !> it (the seabed lies there, so the seabed is present too) and density. No data
   !> lines; at most one.
   subroutine read_water_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: water and seabed present
      type(error_t), intent(inout) :: err     !< status

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic), w => model%water)
         call check_card(deck, ic, [character(len=param_len) :: 'DEPTH', 'SURFACE', &
                         'DENSITY'], 0, 0, err, first=pend%water)
         call get_bounded(card, 'DEPTH', w%depth, .true., err, required=.true.)
         call card_get_real(card, 'SURFACE', w%surface, err)
         call get_bounded(card, 'DENSITY', w%density, .true., err)
         call check_at_most(card, 'DENSITY', w%density, max_water_density, ' kg/m3', &
                            'denser than any liquid (mercury: 13 546 kg/m3; sea water '// &
                            'about 1025 kg/m3)', err)
         if (has_error(err)) return
         w%present = .true.
         model%seabed%present = .true.
      end associate
   end subroutine read_water_card

   !> *CURRENT [, RAMP=]: data lines z [m], speed [m/s], heading [deg] (the direction
   !> the water flows towards, from +x towards +y), one level per line; levels distinct,
   !> stored by increasing z, headings in rad. At most one. That the deck has *WATER and
   !> no level is above its surface is checked by validate_water.
   subroutine read_current_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: current profile set
      type(error_t), intent(inout) :: err     !< status
      type(table_t) :: table
      integer, allocatable :: order(:)
      integer :: j, k, n

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic), w => model%water)
         call check_once(deck, ic, pend%current, err)
         call card_check_params(card, [character(len=param_len) :: 'RAMP'], err)
         call get_bounded(card, 'RAMP', w%cur_ramp, .false., err)
         call card_data_table(card, 3, what_cur, table, err, nmin=1)
         if (has_error(err)) return
         n = table%n_rows
         do k = 1, n
            call data_check(card, k, 'speed', table%values(2, k), .false., err)
            if (has_error(err)) return
            do j = 1, k - 1
               if (table%values(1, j) /= table%values(1, k)) cycle
               call card_data_error(card, k, 'level z = '//real_str(table%values(1, k))// &
                                    ' given twice (first on line '// &
                                    int_str(card%data(j)%line)//')', err)
               return
            end do
         end do
         order = sorted_order(table%values(1, 1:n))
         w%cur_z = table%values(1, order)
         w%cur_speed = table%values(2, order)
         w%cur_heading = table%values(3, order)*deg
      end associate
   end subroutine read_current_card

   !> *SEABED [, SLOPE=, SLOPE DIRECTION=, STIFFNESS=, DAMPING=, FRICTION= | AXIAL
   !> FRICTION=, LATERAL FRICTION=, MOBILISATION VELOCITY=]: the properties of the plane
   !> seabed at the water depth (angles in deg, stored in rad). No data lines; at most
   !> one. That the deck has *WATER is checked by validate_water.
   subroutine read_seabed_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: seabed properties set
      type(error_t), intent(inout) :: err     !< status
      real(wp) :: slope, dir

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic), sb => model%seabed)
         call check_card(deck, ic, [character(len=param_len) :: 'SLOPE', 'SLOPE DIRECTION', &
                         'STIFFNESS', 'DAMPING', 'FRICTION', 'AXIAL FRICTION', &
                         'LATERAL FRICTION', 'MOBILISATION VELOCITY'], 0, 0, err, &
                         first=pend%seabed)
         if (has_error(err)) return

         slope = sb%slope/deg
         call card_get_real(card, 'SLOPE', slope, err)
         if (has_error(err)) return
         if (.not. (slope >= 0.0_wp .and. slope < max_slope_deg)) then
            call param_fail(card, 'SLOPE', 'SLOPE must be >= 0 and < 90 (degrees), got '// &
                            real_str(slope), err)
            return
         end if
         dir = sb%slope_dir/deg
         call card_get_real(card, 'SLOPE DIRECTION', dir, err)
         if (has_error(err)) return
         sb%slope = slope*deg
         sb%slope_dir = dir*deg

         call get_bounded(card, 'STIFFNESS', sb%stiffness, .true., err)
         call get_bounded(card, 'DAMPING', sb%damping, .false., err)
         call get_bounded(card, 'MOBILISATION VELOCITY', sb%v_mob, .true., err)
         if (has_error(err)) return
         call get_pair(card, 'FRICTION', 'AXIAL FRICTION', 'LATERAL FRICTION', sb%mu_axial, &
                       sb%mu_lateral, .false., err)
      end associate
   end subroutine read_seabed_card

   !> *SEGMENT, LINE=, SECTION=, LENGTH=, ELEMENTS=: one stretch of a line, in order
   !> from end A as in the deck. No data lines. Names are resolved by resolve_segments.
   subroutine read_segment_card(card, ic, pend, err)
      type(card_t), intent(in) :: card        !< the *SEGMENT card
      integer, intent(in) :: ic               !< its index
      type(pending_t), intent(inout) :: pend  !< one segment appended
      type(error_t), intent(inout) :: err     !< status
      character(len=:), allocatable :: line, section
      real(wp) :: length
      integer :: n

      block
         call card_check_params(card, [character(len=param_len) :: 'LINE', 'SECTION', &
                                'LENGTH', 'ELEMENTS'], err)
         call card_check_data(card, 0, 0, err)
         call card_get_name(card, 'LINE', line, err, required=.true.)
         call card_get_name(card, 'SECTION', section, err, required=.true.)
         length = 0.0_wp
         call get_bounded(card, 'LENGTH', length, .true., err, required=.true.)
         n = 0
         call get_int_range(card, 'ELEMENTS', 1, max_elements, n, err, required=.true.)
         if (has_error(err)) return
      end block
      pend%n_segments = pend%n_segments + 1
      pend%seg_line(pend%n_segments) = ref_t(line, ic)
      pend%seg_section(pend%n_segments) = ref_t(section, ic)
      pend%seg_length(pend%n_segments) = length
      pend%seg_elements(pend%n_segments) = n
   end subroutine read_segment_card

   !> *ATTACHMENT, LINE=, S= [, MASS=, VOLUME=, CDA=, CA=]: a clump weight or buoy at
   !> arc length S of a line. No data lines. S within the line and the need for *WATER
   !> are checked by validate_water.
   subroutine read_attachment_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: one attachment appended
      type(error_t), intent(inout) :: err     !< status
      type(attachment_t) :: att
      character(len=:), allocatable :: line

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call check_card(deck, ic, [character(len=param_len) :: 'LINE', 'S', 'MASS', &
                         'VOLUME', 'CDA', 'CA'], 0, 0, err)
         call card_get_name(card, 'LINE', line, err, required=.true.)
         call get_bounded(card, 'S', att%s, .false., err, required=.true.)
         if (has_error(err)) return
         if (card_find_param(card, 'MASS') == 0 .and. card_find_param(card, 'VOLUME') == 0 &
             .and. card_find_param(card, 'CDA') == 0 .and. card_find_param(card, 'CA') == 0) &
            then
            call card_error(card, 'give MASS, VOLUME, CDA or CA (an attachment without'// &
                            ' them does nothing)', err)
            return
         end if
         call get_lumped_body(card, att%mass, att%volume, att%cda_area, att%ca, err)
         if (has_error(err)) return
         pend%n_attachments = pend%n_attachments + 1
         model%attachments(pend%n_attachments) = att
         pend%att_line(pend%n_attachments) = ref_t(line, ic)
      end associate
   end subroutine read_attachment_card

   !> The hydrodynamic and contents parameters of a *SECTION card (BUOYANCY DIAMETER,
   !> DRAG DIAMETER, CDN, CDA, CAN, CAA, ID, CONTENTS DENSITY, CONTENTS PRESSURE,
   !> PRESSURE Z), read after OD. Diameters and coefficients >= 0; contents need ID > 0;
   !> ID smaller than OD and the buoyancy diameter when those are > 0. The diameters not
   !> given stay < 0 (resolved by rodyn_deck's resolve_section_defaults).
   subroutine read_section_hydro(card, sec, err)
      type(card_t), intent(in) :: card        !< the *SECTION card
      type(section_t), intent(inout) :: sec   !< section: OD read, hydro fields set
      type(error_t), intent(inout) :: err     !< status

      if (has_error(err)) return
      call get_bounded(card, 'BUOYANCY DIAMETER', sec%db, .false., err)
      call get_bounded(card, 'DRAG DIAMETER', sec%dd, .false., err)
      call get_bounded(card, 'CDN', sec%cdn, .false., err)
      call get_bounded(card, 'CDA', sec%cda, .false., err)
      call get_bounded(card, 'CAN', sec%can, .false., err)
      call get_bounded(card, 'CAA', sec%caa, .false., err)
      call check_at_most(card, 'CDN', sec%cdn, max_coefficient, '', coeff_why, err)
      call check_at_most(card, 'CDA', sec%cda, max_coefficient, '', coeff_why, err)
      call check_at_most(card, 'CAN', sec%can, max_coefficient, '', coeff_why, err)
      call check_at_most(card, 'CAA', sec%caa, max_coefficient, '', coeff_why, err)
      call get_bounded(card, 'ID', sec%id, .false., err)
      call get_bounded(card, 'CONTENTS DENSITY', sec%rho_i, .false., err)
      call card_get_real(card, 'CONTENTS PRESSURE', sec%p_i, err)
      call card_get_real(card, 'PRESSURE Z', sec%z_pi, err)
      if (has_error(err)) return

      if (sec%id > 0.0_wp) then
         if (sec%od > 0.0_wp .and. sec%id >= sec%od) then
            call param_fail(card, 'ID', 'ID ('//real_str(sec%id)//' m) must be smaller'// &
                            ' than OD ('//real_str(sec%od)//' m)', err)
         else if (sec%db > 0.0_wp .and. sec%id >= sec%db) then
            call param_fail(card, 'ID', 'ID ('//real_str(sec%id)//' m) must be smaller'// &
                            ' than BUOYANCY DIAMETER ('//real_str(sec%db)//' m)', err)
         end if
      else if (sec%rho_i > 0.0_wp) then
         call param_fail(card, 'CONTENTS DENSITY', 'CONTENTS DENSITY > 0 needs ID > 0 (the'// &
                         ' diameter of the contents)', err)
      else if (sec%p_i /= 0.0_wp) then
         call param_fail(card, 'CONTENTS PRESSURE', 'CONTENTS PRESSURE needs ID > 0 (the'// &
                         ' diameter the pressure acts on)', err)
      end if
   end subroutine read_section_hydro

   ! ================================================================ validation

   !> Give every line its segments (docs/deck.md, *SEGMENT): the *SEGMENT cards naming
   !> it in deck order, or one segment of its SECTION=, LENGTH=, ELEMENTS=. The line's
   !> length and elements become the totals (the given LENGTH and ELEMENTS must equal
   !> them), its section that of the first segment. Errors name the *SEGMENT card (an
   !> unknown LINE or SECTION) or the *LINE card (SECTION with segments, SECTION
   !> missing without them, totals).
   subroutine resolve_segments(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< segments and line references
      type(model_t), intent(inout) :: model   !< model: lines get their segments
      type(error_t), intent(inout) :: err     !< status
      integer :: iline(pend%n_segments), isec(pend%n_segments)
      integer :: k, il, n, first

      do k = 1, pend%n_segments
         associate (card => deck%cards(pend%seg_line(k)%card))
            call resolve_line(card, pend%seg_line(k)%name, model, iline(k), end_a, err)
            if (has_error(err)) return
            call resolve_section(card, pend%seg_section(k)%name, model, isec(k), err)
            if (has_error(err)) return
         end associate
      end do

      do il = 1, size(model%lines)
         associate (card => deck%cards(pend%line_section(il)%card), line => model%lines(il))
            n = count(iline == il)
            if (n == 0) then
               if (len(pend%line_section(il)%name) == 0) then
                  call card_error(card, 'missing parameter SECTION (a line without'// &
                                  ' *SEGMENT cards needs SECTION=, LENGTH= and ELEMENTS=)', &
                                  err)
                  return
               end if
               call resolve_section(card, pend%line_section(il)%name, model, line%section, &
                                    err)
               if (has_error(err)) return
               line%seg_section = [line%section]
               line%seg_length = [line%length]
               line%seg_elements = [line%n_elements]
               cycle
            end if
            first = findloc(iline, il, dim=1)
            if (len(pend%line_section(il)%name) > 0) then
               call param_fail(card, 'SECTION', 'line '//trim(line%name)//' has *SEGMENT'// &
                               ' cards (first at '//location(deck, pend%seg_line(first)%card)// &
                               '): give its sections there, not SECTION=', err)
               return
            end if
            line%seg_section = pack(isec, iline == il)
            line%seg_length = pack(pend%seg_length(1:pend%n_segments), iline == il)
            line%seg_elements = pack(pend%seg_elements(1:pend%n_segments), iline == il)
            call check_segment_totals(card, line, err)
            if (has_error(err)) return
         end associate
      end do
   end subroutine resolve_segments

   !> The totals of a segmented line: at most max_elements elements; LENGTH and ELEMENTS,
   !> when the *LINE card gives them (> 0), equal the sums (LENGTH to seg_length_tol).
   !> Sets the line's length, n_elements and section (that of the first segment).
   subroutine check_segment_totals(card, line, err)
      type(card_t), intent(in) :: card          !< the *LINE card
      type(line_def_t), intent(inout) :: line   !< line with its segments
      type(error_t), intent(inout) :: err       !< status
      integer(i8) :: n_total
      real(wp) :: total

      total = sum(line%seg_length)
      n_total = sum(int(line%seg_elements, i8))
      if (n_total > max_elements) then
         call card_error(card, 'the segments of line '//trim(line%name)//' have '// &
                         int_str(int(min(n_total, int(huge(1), i8))))//' elements in all,'// &
                         ' more than the '//int_str(max_elements)//' allowed', err)
         return
      end if
      if (line%length > 0.0_wp .and. abs(total - line%length) > seg_length_tol*line%length) &
         then
         call param_fail(card, 'LENGTH', 'segment lengths add up to '//real_str(total)// &
                         ' m, not LENGTH='//real_str(line%length), err)
         return
      end if
      if (line%n_elements > 0 .and. line%n_elements /= n_total) then
         call param_fail(card, 'ELEMENTS', 'segment elements add up to '// &
                         int_str(int(n_total))//', not ELEMENTS='// &
                         int_str(line%n_elements), err)
         return
      end if
      line%length = total
      line%n_elements = int(n_total)
      line%section = line%seg_section(1)
   end subroutine check_segment_totals

   !> Whole-deck checks of the sea, once lines, segments and boundaries are resolved:
   !> *CURRENT and *SEABED need *WATER; no current level above the sea surface; with
   !> *WATER, gravity along -z (the surface is a level z = SURFACE); every
   !> *ATTACHMENT names a line, lies within it, and has no VOLUME, CDA or CA without
   !> *WATER; in water, every section used by a line has a buoyancy diameter (OD= or
   !> BUOYANCY DIAMETER=); no end of a line nor a POSITION target lies below the seabed.
   !> Sets EMC's RHO INF in water when *DYNAMIC gives none (dynamic_scheme_default).
   subroutine validate_water(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< references to resolve
      type(model_t), intent(inout) :: model   !< model with lines resolved
      type(error_t), intent(inout) :: err     !< status
      character(len=*), parameter :: no_water = ' (no *WATER in the deck)'
      real(wp) :: z
      integer :: id

      associate (w => model%water)
         if (pend%current > 0) then
            associate (card => deck%cards(pend%current))
               if (.not. w%present) then
                  call card_error(card, 'a current needs *WATER'//no_water, err)
                  return
               end if
               do id = 1, card%n_data
                  call card_data_real(card, id, 1, z, err, what_cur)
                  if (has_error(err)) return
                  if (z > w%surface) then
                     call card_data_error(card, id, 'level z = '//real_str(z)//' is above'// &
                                          ' the sea surface (SURFACE='// &
                                          real_str(w%surface)//' of the *WATER at '// &
                                          location(deck, pend%water)//')', err)
                     return
                  end if
               end do
            end associate
         end if
         if (pend%seabed > 0 .and. .not. w%present) then
            call card_error(deck%cards(pend%seabed), 'a seabed needs *WATER: it lies at'// &
                            ' the water DEPTH'//no_water, err)
            return
         end if
         if (w%present .and. pend%gravity > 0) then
            associate (g => model%gravity)
               if (g(1) /= 0.0_wp .or. g(2) /= 0.0_wp .or. .not. g(3) < 0.0_wp) then
                  call card_data_error(deck%cards(pend%gravity), 1, 'with *WATER (at '// &
                                       location(deck, pend%water)//') gravity must point'// &
                                       ' along -z (gx = gy = 0, gz < 0): the sea surface'// &
                                       ' is the level z = SURFACE', err)
                  return
               end if
            end associate
         end if
      end associate

      call check_attachments(deck, pend, model, err)
      if (has_error(err)) return
      call dynamic_scheme_default(model)
      if (.not. model%water%present) return
      call check_sections_in_water(deck, pend, model, err)
      if (has_error(err)) return
      call check_ends_above_seabed(deck, pend, model, err)
   end subroutine validate_water

   !> Each *ATTACHMENT: its line exists; 0 <= S <= the line's length (S a little beyond,
   !> within arc_tol, is set to the length); VOLUME, CDA and CA only with *WATER.
   subroutine check_attachments(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< LINE= of each attachment
      type(model_t), intent(inout) :: model   !< model: attachments get their line
      type(error_t), intent(inout) :: err     !< status
      character(len=*), parameter :: no_water = ' needs *WATER (no *WATER in the deck)'
      integer :: k, il
      real(wp) :: length

      do k = 1, size(model%attachments)
         associate (card => deck%cards(pend%att_line(k)%card), att => model%attachments(k))
            call resolve_line(card, pend%att_line(k)%name, model, il, end_a, err)
            if (has_error(err)) return
            att%line = il
            length = model%lines(il)%length
            if (att%s > length*(1.0_wp + arc_tol)) then
               call param_fail(card, 'S', 'S='//real_str(att%s)//' is beyond the length'// &
                               ' of line '//trim(model%lines(il)%name)//' ('// &
                               real_str(length)//' m)', err)
               return
            end if
            att%s = min(att%s, length)
            if (model%water%present) cycle
            if (att%volume > 0.0_wp) then
               call param_fail(card, 'VOLUME', 'VOLUME > 0'//no_water, err)
            else if (att%cda_area > 0.0_wp) then
               call param_fail(card, 'CDA', 'CDA > 0'//no_water, err)
            else if (att%ca > 0.0_wp) then
               call param_fail(card, 'CA', 'CA > 0'//no_water, err)
            end if
            if (has_error(err)) return
         end associate
      end do
   end subroutine check_attachments

   !> In water, every section used by a line (or a segment) needs a buoyancy diameter:
   !> OD= or BUOYANCY DIAMETER= (0 for none). Reported at the *SECTION card.
   subroutine check_sections_in_water(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< card of each section
      type(model_t), intent(in) :: model      !< model with segments resolved
      type(error_t), intent(inout) :: err     !< status
      integer :: is, il

      do is = 1, size(model%sections)
         associate (s => model%sections(is))
            if (s%db >= 0.0_wp .or. s%od > 0.0_wp) cycle
            do il = 1, size(model%lines)
               if (.not. any(model%lines(il)%seg_section == is)) cycle
               call card_error(deck%cards(pend%section_card(is)), 'section '// &
                               trim(s%name)//' (used by line '// &
                               trim(model%lines(il)%name)//') in water needs OD= or'// &
                               ' BUOYANCY DIAMETER= (give BUOYANCY DIAMETER=0 for no'// &
                               ' buoyancy)', err)
               return
            end do
         end associate
      end do
   end subroutine check_sections_in_water

   !> No end of a line (as given on the *LINE data line) and no TYPE=POSITION target of a
   !> *BOUNDARY lies below the seabed plane by more than bed_tol_rel DEPTH + bed_tol_abs.
   !> Reported at the data line of the *LINE or *BOUNDARY.
   subroutine check_ends_above_seabed(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< card of each line
      type(model_t), intent(in) :: model      !< model with water and seabed
      type(error_t), intent(inout) :: err     !< status
      character(len=1), parameter :: ends(2) = ['A', 'B']
      real(wp) :: x(3), below, tol
      integer :: il, k

      tol = bed_tol_rel*model%water%depth + bed_tol_abs
      do il = 1, size(model%lines)
         do k = 1, 2
            if (k == 1) then
               x = model%lines(il)%end_a
            else
               x = model%lines(il)%end_b
            end if
            below = seabed_z(model, x(1), x(2)) - x(3)
            if (below <= tol) cycle
            call card_data_error(deck%cards(pend%line_section(il)%card), 1, 'end '// &
                                 ends(k)//' of line '//trim(model%lines(il)%name)//' is '// &
                                 real_str(below)//' m below the seabed (z = '// &
                                 real_str(x(3))//', the seabed is at z = '// &
                                 real_str(x(3) + below)//' there)', err)
            return
         end do
      end do
      do k = 1, size(model%constraints)
         if (model%constraints(k)%kind /= bc_position) cycle
         x = model%constraints(k)%position
         below = seabed_z(model, x(1), x(2)) - x(3)
         if (below <= tol) cycle
         call card_data_error(deck%cards(pend%bc_line(k)%card), 1, 'the position is '// &
                              real_str(below)//' m below the seabed (z = '// &
                              real_str(x(3))//', the seabed is at z = '// &
                              real_str(x(3) + below)//' there)', err)
         return
      end do
   end subroutine check_ends_above_seabed

   !> The RHO INF of EMC when the card gives none: rho_inf_emc_water (the dissipative
   !> EMC) in a deck with *WATER, where lines with a free or slack end excite axial modes
   !> that a step does not resolve; 1 (EMC conserving) in a dry deck (docs/dynamics.md,
   !> "Choosing the scheme").
   subroutine dynamic_scheme_default(model)
      type(model_t), intent(inout) :: model !< model (*DYNAMIC and *WATER read)
      associate (dy => model%dynamic)
         if (dy%scheme == scheme_emc .and. .not. dy%rho_inf_given .and. &
             model%water%present) dy%rho_inf = rho_inf_emc_water
      end associate
   end subroutine dynamic_scheme_default
end module rodyn_deck_water
