!> Deck reader, dynamic-analysis keywords: *DYNAMIC, *DAMPING, *AMPLITUDE, *MOTION and
!> *INITIAL VELOCITY, one routine per keyword, and their whole-deck checks
!> (validate_dynamics: the AMPLITUDE= of *LOAD, read by rodyn_deck, names an *AMPLITUDE;
!> the node of a *MOTION is held in position and has one *MOTION at most; one *INITIAL
!> VELOCITY per line, and only with START=DEFINED). docs/deck.md describes every
!> keyword, default and check. rodyn_deck hands the cards to these readers and calls
!> validate_dynamics; the warnings of a time step too long for what the deck prescribes
!> are rodyn_deck_dynamic_warnings'.
module rodyn_deck_dynamic
   use rodyn_kinds, only: wp, pi
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, dynamic_options_t, amplitude_t, motion_t, &
                          initial_velocity_t, scheme_alpha, scheme_emc, edmc_rho_min, &
                          scheme_names, &
                          motion_harmonic, motion_table, motion_vessel, bc_free, end_a, &
                          body_fixed, body_free
   use rodyn_deck_lexer, only: deck_t
   use rodyn_deck_card, only: card_t, card_check_params, card_find_param, card_error, &
                              card_data_error, card_file_error, card_check_data, card_data_count, &
                              param_len
   use rodyn_deck_card_values, only: card_get_real, card_get_name, card_get_choice, card_get_int, &
                                     card_data_reals, card_data_real
   use rodyn_deck_table, only: table_t, card_data_table, card_get_table
   use rodyn_deck_numbers, only: real_str, int_str
   use rodyn_deck_params, only: upper_case
   use rodyn_deck_targets, only: resolve_item_body, resolve_motion_point
   use rodyn_deck_support, only: ref_t, pending_t, reading_t, get_item_name, &
                                 max_cutbacks, check_card, get_node, &
                                 max_iterations, max_frequency, &
                                 get_bounded, get_tolerance, data_check, param_fail, &
                                 get_int_range, &
                                 location, resolve_line, node_count, node_number, node_label, &
                                 check_node_once, refuse, &
                                 check_at_most
   implicit none
   private
   public :: read_dynamic_card, read_damping_card, read_amplitude_card, read_motion_card
   public :: read_initial_velocity_card, validate_dynamics, record_table
   public :: check_time_table

   integer, parameter :: max_steps = 100000000    !< most time steps TIME/DT of a run
   real(wp), parameter :: rho_inf_alpha = 0.8_wp  !< default RHO INF with SCHEME=ALPHA [-]
   ! Rayleigh coefficients beyond which every mode a line analysis shows is overdamped
   real(wp), parameter :: max_alpha = 1.0e3_wp    !< largest *DAMPING ALPHA [1/s]
   real(wp), parameter :: max_beta = 1.0e3_wp     !< largest *DAMPING BETA [s]
   character(len=*), parameter :: what_amp = 't, value'          !< *AMPLITUDE columns
   character(len=*), parameter :: what_table = 't, ux, uy, uz'   !< *MOTION table columns
   character(len=*), parameter :: what_harm = &                  !< *MOTION harmonic line
      'direction, amplitude, frequency, phase'
   character(len=1), parameter :: lf = achar(10)

contains

   ! ================================================================ card readers

   !> *DYNAMIC, DT=, TIME= [, SCHEME=, RHO INF=, OUTPUT INTERVAL=, START=, MAX ITERATIONS=,
   !> CUTBACKS=, FORCE TOL=, DISP TOL=, TANGENT=, CHECKPOINT=]: time step, duration, scheme
   !> (docs/theory.md sections 5 and 7), Newton controls and the checkpoint interval.
   !> No data lines; at most one. RHO INF only with SCHEME=ALPHA, where it defaults to 0.8,
   !> and EMC, where it defaults to 1 (no numerical dissipation) and may be as low as
   !> edmc_rho_min (rodyn_numerical_dissipation).
   subroutine read_dynamic_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: dynamic options set
      type(error_t), intent(inout) :: err     !< status
      character(len=8), parameter :: starts(2) = [character(len=8) :: 'STATIC', 'DEFINED']
      character(len=8), parameter :: tangents(2) = [character(len=8) :: 'NEW', 'REUSE']
      integer :: k

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic), dy => model%dynamic)
         call check_card(deck, ic, [character(len=param_len) :: 'DT', 'TIME', 'SCHEME', &
                         'RHO INF', 'OUTPUT INTERVAL', 'START', 'MAX ITERATIONS', &
                         'CUTBACKS', 'FORCE TOL', 'DISP TOL', 'TANGENT', 'CHECKPOINT'], 0, 0, err, &
                         first=pend%dynamic)
         if (has_error(err)) return
         dy%requested = .true.

         call get_times(card, dy, err)
         if (has_error(err)) return
         call get_scheme(card, dy, err)
         if (has_error(err)) return

         k = merge(1, 2, dy%start_static)
         call card_get_choice(card, 'START', starts, k, err)
         if (has_error(err)) return
         dy%start_static = k == 1
         k = merge(2, 1, dy%reuse_tangent)
         call card_get_choice(card, 'TANGENT', tangents, k, err)
         if (has_error(err)) return
         dy%reuse_tangent = k == 2
         call get_int_range(card, 'MAX ITERATIONS', 1, max_iterations, dy%max_iterations, &
                            err)
         call get_int_range(card, 'CUTBACKS', 0, max_cutbacks, dy%max_cutbacks, err)
         call get_tolerance(card, 'FORCE TOL', dy%force_tol, err)
         call get_tolerance(card, 'DISP TOL', dy%disp_tol, err)
      end associate
   end subroutine read_dynamic_card

   !> DT, TIME, OUTPUT INTERVAL and CHECKPOINT of *DYNAMIC: DT > 0, DT <= TIME, at most
   !> max_steps steps; OUTPUT INTERVAL 0 (every step) or >= DT; CHECKPOINT 0 (none) or
   !> between DT and TIME.
   subroutine get_times(card, dy, err)
      type(card_t), intent(in) :: card                !< the *DYNAMIC card
      type(dynamic_options_t), intent(inout) :: dy    !< options: times set
      type(error_t), intent(inout) :: err             !< status
      call get_bounded(card, 'DT', dy%dt, .true., err, required=.true.)
      call get_bounded(card, 'TIME', dy%duration, .true., err, required=.true.)
      if (has_error(err)) return
      if (dy%duration < dy%dt) then
         call param_fail(card, 'TIME', 'TIME must be >= DT ('//real_str(dy%dt)// &
                         '), got '//real_str(dy%duration), err)
         return
      end if
      if (dy%duration/dy%dt > real(max_steps, wp)) then
         call param_fail(card, 'TIME', 'TIME/DT is '//real_str(dy%duration/dy%dt)// &
                         ' time steps, more than the '//int_str(max_steps)// &
                         ' allowed', err)
         return
      end if
      call get_bounded(card, 'OUTPUT INTERVAL', dy%output_interval, .false., err)
      if (has_error(err)) return
      if (dy%output_interval > 0.0_wp .and. dy%output_interval < dy%dt) then
         call param_fail(card, 'OUTPUT INTERVAL', 'OUTPUT INTERVAL must be 0 (every'// &
                         ' step) or >= DT ('//real_str(dy%dt)//'), got '// &
                         real_str(dy%output_interval), err)
         return
      end if

      call card_get_real(card, 'CHECKPOINT', dy%checkpoint, err)
      if (has_error(err)) return
      if (.not. (dy%checkpoint == 0.0_wp .or. (dy%checkpoint >= dy%dt .and. &
                                               dy%checkpoint <= dy%duration))) then
         call param_fail(card, 'CHECKPOINT', 'CHECKPOINT must be 0 (none) or between'// &
                         ' DT ('//real_str(dy%dt)//') and TIME ('// &
                         real_str(dy%duration)//'), got '//real_str(dy%checkpoint), err)
         return
      end if
   end subroutine get_times

   !> SCHEME and RHO INF of *DYNAMIC: RHO INF only with SCHEME=ALPHA (default
   !> rho_inf_alpha) or EMC (at least edmc_rho_min), between 0 and 1.
   subroutine get_scheme(card, dy, err)
      type(card_t), intent(in) :: card                !< the *DYNAMIC card
      type(dynamic_options_t), intent(inout) :: dy    !< options: scheme set
      type(error_t), intent(inout) :: err             !< status
      call card_get_choice(card, 'SCHEME', scheme_names, dy%scheme, err)
      if (has_error(err)) return
      if (dy%scheme == scheme_alpha) dy%rho_inf = rho_inf_alpha
      if (card_find_param(card, 'RHO INF') > 0) then
         if (dy%scheme /= scheme_alpha .and. dy%scheme /= scheme_emc) then
            call param_fail(card, 'RHO INF', 'RHO INF is only allowed with SCHEME=ALPHA'// &
                            ' or EMC (the scheme is '//trim(scheme_names(dy%scheme))// &
                            ')', err)
            return
         end if
         call card_get_real(card, 'RHO INF', dy%rho_inf, err)
         if (has_error(err)) return
         dy%rho_inf_given = .true.
         if (.not. (dy%rho_inf >= 0.0_wp .and. dy%rho_inf <= 1.0_wp)) then
            call param_fail(card, 'RHO INF', 'RHO INF must be between 0 and 1, got '// &
                            real_str(dy%rho_inf), err)
            return
         end if
         if (dy%scheme == scheme_emc .and. dy%rho_inf < edmc_rho_min) then
            call param_fail(card, 'RHO INF', 'RHO INF with SCHEME=EMC (the dissipative '// &
                            'energy-momentum scheme) must be between '// &
                            real_str(edmc_rho_min)//' and 1, got '// &
                            real_str(dy%rho_inf)//'; SCHEME=ALPHA reaches 0', err)
            return
         end if
      end if
   end subroutine get_scheme

   !> *DAMPING, ALPHA=a, BETA=b: Rayleigh damping C = a M + b K, a [1/s], b [s], both
   !> >= 0, at least one given (the other stays 0). No data lines; at most one.
   subroutine read_damping_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: Rayleigh coefficients set
      type(error_t), intent(inout) :: err     !< status
      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call check_card(deck, ic, [character(len=param_len) :: 'ALPHA', 'BETA'], 0, 0, err, &
                         first=pend%damping)
         if (has_error(err)) return
         if (card_find_param(card, 'ALPHA') == 0 .and. card_find_param(card, 'BETA') == 0) then
            call card_error(card, 'give ALPHA or BETA, or both (C = ALPHA M + BETA K)', err)
            return
         end if
         call get_bounded(card, 'ALPHA', model%dynamic%rayleigh_alpha, .false., err)
         call get_bounded(card, 'BETA', model%dynamic%rayleigh_beta, .false., err)
         ! damping ratio ALPHA/(2 omega) + BETA omega/2 (docs/deck.md, *DAMPING)
         call check_at_most(card, 'ALPHA', model%dynamic%rayleigh_alpha, max_alpha, ' 1/s', &
                            'the mass-proportional term alone damps every mode below '// &
                            int_str(nint(max_alpha/(4.0_wp*pi)))//' Hz beyond critical '// &
                            '(damping ratio ALPHA/(2 omega) > 1); a ratio zeta at omega '// &
                            'is ALPHA = '// &
                            '2 zeta omega', err)
         call check_at_most(card, 'BETA', model%dynamic%rayleigh_beta, max_beta, ' s', &
                            'the stiffness-proportional term alone damps every mode of '// &
                            'period below '//int_str(nint(pi*max_beta))//' s beyond critical '// &
                            '(damping ratio BETA omega/2 > 1); a ratio zeta at omega is '// &
                            'BETA = 2 zeta/omega', err)
         model%dynamic%damping_at = location(deck, ic)
      end associate
   end subroutine read_damping_card

   !> *AMPLITUDE, NAME= [, INPUT=file]: pairs t, value, one per data line or one per
   !> row of the file; at least 2, times increasing strictly. Names are unique.
   subroutine read_amplitude_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: one amplitude appended
      type(error_t), intent(inout) :: err     !< status
      type(amplitude_t) :: amp
      type(table_t) :: table
      character(len=:), allocatable :: name
      logical :: from_file
      integer :: n

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call card_check_params(card, [character(len=param_len) :: 'NAME', 'INPUT'], err)
         call get_item_name(deck, ic, model%amplitudes(1:pend%n_amplitudes)%name, &
                            pend%amplitude_card(1:pend%n_amplitudes), 'amplitude', name, err)
         if (has_error(err)) return
         amp%name = name

         from_file = card_find_param(card, 'INPUT') > 0
         if (from_file) then
            if (card%n_data > 0) then
               call card_data_error(card, 1, 'data lines are not allowed with INPUT= (the'// &
                                    ' pairs '//what_amp//' are read from the file)', err)
               return
            end if
            call card_get_table(card, 'INPUT', 2, what_amp, table, err)
         else
            call card_data_table(card, 2, what_amp, table, err, nmin=1)
         end if
         if (has_error(err)) return
         call check_time_table(card, table, from_file, what_amp, err)
         if (has_error(err)) return
         if (from_file) call record_table(table, model)
         n = table%n_rows
         amp%time = table%values(1, 1:n)
         amp%value = table%values(2, 1:n)
         pend%n_amplitudes = pend%n_amplitudes + 1
         model%amplitudes(pend%n_amplitudes) = amp
         pend%amplitude_card(pend%n_amplitudes) = ic
      end associate
   end subroutine read_amplitude_card

   !> *MOTION, LINE=, END=|NODE=, TYPE=HARMONIC|TABLE [, RAMP=] [, INPUT=]: displacement
   !> of a held node in time. HARMONIC: 1 to 3 data lines direction, amplitude [m],
   !> frequency [Hz], phase [deg] (stored in rad). TABLE: rows t, ux, uy, uz from INPUT.
   subroutine read_motion_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: one motion appended
      type(error_t), intent(inout) :: err     !< status
      character(len=8), parameter :: types(3) = [character(len=8) :: 'HARMONIC', 'TABLE', &
                                                 'VESSEL']
      integer, parameter :: kinds(3) = [motion_harmonic, motion_table, motion_vessel]
      type(motion_t) :: mo
      type(table_t) :: table
      character(len=:), allocatable :: line, vessel
      integer :: it, n
      logical :: on_body, on_point

      vessel = ''
      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call card_check_params(card, [character(len=param_len) :: 'LINE', 'BODY', 'POINT', &
                                'END', 'NODE', 'TYPE', 'RAMP', 'INPUT', 'VESSEL'], err)
         if (has_error(err)) return
         call motion_target(card, mo, line, on_body, on_point, err)
         it = 0
         call card_get_choice(card, 'TYPE', types, it, err, required=.true.)
         if (has_error(err)) return
         mo%kind = kinds(it)
         call get_bounded(card, 'RAMP', mo%ramp, .false., err)
         if (has_error(err)) return

         if (mo%kind /= motion_vessel) call refuse(card, [character(len=6) :: 'VESSEL'], &
                                                   ' is only allowed with TYPE=VESSEL', err)
         if (mo%kind /= motion_table) call refuse(card, [character(len=5) :: 'INPUT'], &
                                                  ' is only allowed with TYPE=TABLE', err)
         if (has_error(err)) return
         select case (mo%kind)
         case (motion_vessel)
            if (card%n_data > 0) then
               call card_data_error(card, 1, 'data lines are not allowed with TYPE=VESSEL'// &
                                    ' (the motion is the vessel''s, *VESSEL)', err)
               return
            end if
            call card_get_name(card, 'VESSEL', vessel, err, required=.true.)
         case (motion_harmonic)
            call read_harmonic_lines(card, mo, err)
         case (motion_table)
            if (card%n_data > 0) then
               call card_data_error(card, 1, 'data lines are not allowed with TYPE=TABLE'// &
                                    ' (the rows '//what_table//' are read from INPUT=file)', &
                                    err)
               return
            end if
            if (card_find_param(card, 'INPUT') == 0) then
               call card_error(card, 'TYPE=TABLE needs INPUT=file (rows '//what_table// &
                               ')', err)
               return
            end if
            call card_get_table(card, 'INPUT', 4, what_table, table, err)
            if (has_error(err)) return
            call check_time_table(card, table, .true., what_table, err)
            if (has_error(err)) return
            call record_table(table, model)
            n = table%n_rows
            mo%file = table%path
            mo%time = table%values(1, 1:n)
            mo%disp = table%values(2:4, 1:n)
         end select
         if (has_error(err)) return
         pend%n_motions = pend%n_motions + 1
         model%motions(pend%n_motions) = mo
         pend%motion_line(pend%n_motions) = ref_t(line, ic)
         pend%motion_vessel(pend%n_motions) = ref_t(vessel, ic)
         pend%motion_body(pend%n_motions) = on_body
         pend%motion_point(pend%n_motions) = on_point
      end associate
   end subroutine read_motion_card

   !> *INITIAL VELOCITY, LINE=: data lines vx, vy, vz [m/s]; wx, wy, wz [rad/s];
   !> optionally the centre cx, cy, cz [m] of the rotation.
   subroutine read_initial_velocity_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: one initial velocity appended
      type(error_t), intent(inout) :: err     !< status
      type(initial_velocity_t) :: iv
      character(len=:), allocatable :: line
      logical :: on_body

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call card_check_params(card, [character(len=param_len) :: 'LINE', 'BODY'], err)
         if (has_error(err)) return
         on_body = card_find_param(card, 'BODY') > 0
         if (on_body .and. card_find_param(card, 'LINE') > 0) then
            call card_error(card, 'give one of LINE= (a line) and BODY= (a FREE body)', err)
            return
         end if
         call card_get_name(card, merge('BODY', 'LINE', on_body), line, err, required=.true.)
         call card_check_data(card, 1, 3, err, 'vx, vy, vz')
         if (has_error(err)) return
         if (card%n_data < 2) then
            call card_error(card, 'missing data line (wx, wy, wz)', err)
            return
         end if
         call card_data_reals(card, 1, 3, iv%velocity, err, 'vx, vy, vz')
         call card_data_reals(card, 2, 3, iv%omega, err, 'wx, wy, wz')
         if (has_error(err)) return
         if (card%n_data == 3) then
            call card_data_reals(card, 3, 3, iv%centre, err, 'cx, cy, cz')
            if (has_error(err)) return
            iv%has_centre = .true.
         end if
         pend%n_ivs = pend%n_ivs + 1
         model%initial_velocities(pend%n_ivs) = iv
         pend%iv_line(pend%n_ivs) = ref_t(line, ic)
         pend%iv_body(pend%n_ivs) = on_body
      end associate
   end subroutine read_initial_velocity_card

   ! ============================================================ reader helpers

   !> What a *MOTION moves: one of LINE= (and its END or NODE), BODY= and POINT= (neither
   !> with END or NODE); `name` the one given.
   subroutine motion_target(card, mo, name, on_body, on_point, err)
      type(card_t), intent(in) :: card          !< the *MOTION card
      type(motion_t), intent(inout) :: mo       !< its node set (LINE=)
      character(len=:), allocatable, intent(out) :: name !< the line, body or point
      logical, intent(out) :: on_body           !< BODY= given
      logical, intent(out) :: on_point          !< POINT= given
      type(error_t), intent(inout) :: err       !< status
      on_body = card_find_param(card, 'BODY') > 0
      on_point = card_find_param(card, 'POINT') > 0
      if (count([on_body, on_point, card_find_param(card, 'LINE') > 0]) > 1) then
         call card_error(card, 'give one of LINE= (a line''s node), BODY= (a FIXED '// &
                         'body) and POINT= (a FIXED point)', err)
         return
      end if
      if (on_body .or. on_point) then
         call card_get_name(card, trim(merge('BODY ', 'POINT', on_body)), name, err, &
                            required=.true.)
         if (card_find_param(card, 'END') + card_find_param(card, 'NODE') > 0) &
            call card_error(card, 'END and NODE are a line''s: not with BODY= or POINT=', err)
      else
         call card_get_name(card, 'LINE', name, err, required=.true.)
         if (has_error(err)) return
         call get_node(card, mo%node, err)
      end if
   end subroutine motion_target

   !> The data lines of a TYPE=HARMONIC *MOTION: u_j(t) = A sin(2 pi f t + phase) for
   !> each direction j given (X|Y|Z or 1|2|3, each at most once).
   subroutine read_harmonic_lines(card, mo, err)
      type(card_t), intent(in) :: card      !< the *MOTION card
      type(motion_t), intent(inout) :: mo   !< motion: amplitude, frequency, phase set
      type(error_t), intent(inout) :: err   !< status
      character(len=1), parameter :: axes(3) = ['X', 'Y', 'Z']
      integer :: first_line(3), id, j, k, n
      real(wp) :: v(3)

      call card_check_data(card, 1, 3, err, what_harm)
      if (has_error(err)) return
      first_line = 0
      do id = 1, card%n_data
         n = card_data_count(card, id)
         if (n /= 4) then
            call card_data_error(card, id, 'expected 4 values, got '//int_str(n)//' ('// &
                                 what_harm//')', err)
            return
         end if
         associate (d => card%data(id)%fields(1)%s)
            select case (upper_case(d))
            case ('X', '1')
               j = 1
            case ('Y', '2')
               j = 2
            case ('Z', '3')
               j = 3
            case default
               call card_data_error(card, id, "direction must be X, Y, Z, 1, 2 or 3, got '"// &
                                    d//"' (direction, value 1 of 4)", err)
               return
            end select
         end associate
         if (first_line(j) > 0) then
            call card_data_error(card, id, 'direction '//axes(j)//' given twice (first on'// &
                                 ' line '//int_str(first_line(j))//')', err)
            return
         end if
         first_line(j) = card%data(id)%line
         do k = 1, 3
            call card_data_real(card, id, k + 1, v(k), err, what_harm)
            if (has_error(err)) return
         end do
         call data_check(card, id, 'frequency', v(2), .false., err)
         if (has_error(err)) return
         if (v(2) > max_frequency) then
            call card_data_error(card, id, 'a frequency of '//real_str(v(2))//' Hz is not '// &
                                 'physical for a line: it must be at most '// &
                                 real_str(max_frequency)//' Hz', err)
            return
         end if
         mo%amplitude(j) = v(1)
         mo%frequency(j) = v(2)
         mo%phase(j) = v(3)*pi/180.0_wp
      end do
   end subroutine read_harmonic_lines

   !> A table of rows (t, ...): at least 2 rows, t increasing strictly. Errors name the
   !> row's file and line; too few rows, the card (data lines) or its INPUT= (a file).
   subroutine check_time_table(card, table, from_file, what, err)
      type(card_t), intent(in) :: card      !< the card the table belongs to
      type(table_t), intent(in) :: table    !< the rows, time first
      logical, intent(in) :: from_file      !< read from INPUT= (else the data lines)
      character(len=*), intent(in) :: what  !< names of the columns
      type(error_t), intent(inout) :: err   !< status
      character(len=:), allocatable :: rows
      integer :: k

      if (table%n_rows < 2) then
         if (from_file) then
            rows = ' rows'
            if (table%n_rows == 1) rows = ' row'
            call param_fail(card, 'INPUT', "'"//table%path//"' has "// &
                            int_str(table%n_rows)//rows//' ('//what//'): at least 2 are'// &
                            ' needed', err)
         else
            call card_error(card, 'at least 2 data lines ('//what//') are needed, got '// &
                            int_str(table%n_rows), err)
         end if
         return
      end if
      do k = 2, table%n_rows
         associate (t => table%values(1, k), t_before => table%values(1, k - 1))
            if (.not. t > t_before) then
               call card_file_error(card, table%path, table%line(k), 'times must increase'// &
                                    ' strictly: t = '//real_str(t)//' follows t = '// &
                                    real_str(t_before), err)
               return
            end if
         end associate
      end do
   end subroutine check_time_table

   !> Keep the text of a table file with the deck text (once per file), headed like the
   !> files of the deck: '** ---- file: PATH'.
   subroutine record_table(table, model)
      type(table_t), intent(in) :: table     !< a table read from a file
      type(model_t), intent(inout) :: model  !< model whose deck_text is extended
      character(len=:), allocatable :: head
      head = '** ---- file: '//table%path//lf
      if (index(model%deck_text, head) > 0) return
      model%deck_text = model%deck_text//head//table%text
   end subroutine record_table

   ! ================================================================ validation

   !> Whole-deck checks of the dynamic keywords, once the lines and boundaries are
   !> resolved: AMPLITUDE= of *LOAD names an *AMPLITUDE; a *MOTION's line and node exist,
   !> the node is held in position and has one *MOTION at most; an *INITIAL VELOCITY's
   !> line exists, has one at most, and the deck has *DYNAMIC with START=DEFINED.
   subroutine validate_dynamics(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< references to resolve
      type(model_t), intent(inout) :: model   !< model with lines and boundaries resolved
      type(error_t), intent(inout) :: err     !< status
      integer :: k, ia, iref, ib

      ! AMPLITUDE= of *LOAD
      do k = 1, size(model%loads)
         associate (ref => pend%load_amp(k))
            if (len(ref%name) == 0) cycle
            do ia = 1, size(model%amplitudes)
               if (model%amplitudes(ia)%name == ref%name) exit
            end do
            if (ia > size(model%amplitudes)) then
               call param_fail(deck%cards(ref%card), 'AMPLITUDE', "AMPLITUDE '"//ref%name// &
                               "' is not defined (no *AMPLITUDE with NAME="//ref%name// &
                               ' in the deck)', err)
               return
            end if
            model%loads(k)%amplitude = ia
         end associate
      end do

      ! *MOTION: line and node exist, the node is held in position, one motion per node
      do k = 1, size(model%motions)
         associate (card => deck%cards(pend%motion_line(k)%card))
            if (pend%motion_body(k)) then
               call resolve_item_body(deck, model, pend%motion_line(1:k), &
                                      model%motions(1:k - 1)%body, body_fixed, ib, err)
               if (has_error(err)) return
               model%motions(k)%body = ib
               model%motions(k)%line = 0
               cycle
            end if
            if (pend%motion_point(k)) then
               call resolve_motion_point(deck, pend, model, k, err)
               if (has_error(err)) return
               cycle
            end if
            call resolve_line(card, pend%motion_line(k)%name, model, iref, &
                              model%motions(k)%node, err)
            if (has_error(err)) return
            model%motions(k)%line = iref
            call check_motion_held(card, model, k, err)
            if (has_error(err)) return
            call check_node_once(deck, model, model%motions(1:k)%line, &
                                 model%motions(1:k)%node, pend%motion_line(1:k)%card, k, &
                                 'MOTION', err)
            if (has_error(err)) return
         end associate
      end do

      ! *INITIAL VELOCITY: line exists, one per line, only with START=DEFINED
      do k = 1, size(model%initial_velocities)
         associate (card => deck%cards(pend%iv_line(k)%card))
            if (pend%iv_body(k)) then
               call resolve_item_body(deck, model, pend%iv_line(1:k), &
                                      model%initial_velocities(1:k - 1)%body, body_free, ib, &
                                      err)
               if (.not. has_error(err)) model%initial_velocities(k)%body = ib
            else
               call resolve_line(card, pend%iv_line(k)%name, model, iref, end_a, err)
               if (has_error(err)) return
               model%initial_velocities(k)%line = iref
               call check_unique_velocity(deck, pend, model, k, err)
            end if
            if (has_error(err)) return
            if (.not. model%dynamic%requested) then
               call card_error(card, 'an initial velocity only acts with *DYNAMIC,'// &
                               ' START=DEFINED (the deck has no *DYNAMIC)', err)
            else if (model%dynamic%start_static) then
               call card_error(card, 'an initial velocity only acts with *DYNAMIC,'// &
                               ' START=DEFINED (the *DYNAMIC at '// &
                               location(deck, pend%dynamic)//' has START=STATIC)', err)
            end if
            if (has_error(err)) return
         end associate
      end do
   end subroutine validate_dynamics

   !> The node of motion `im` must have a *BOUNDARY that holds it in position (PINNED,
   !> HINGED, CLAMPED or POSITION): the motion moves that support.
   subroutine check_motion_held(card, model, im, err)
      type(card_t), intent(in) :: card      !< the *MOTION card
      type(model_t), intent(in) :: model    !< model with resolved constraints
      integer, intent(in) :: im             !< motion to check
      type(error_t), intent(inout) :: err   !< status
      integer :: ib, nn, node

      associate (mo => model%motions(im))
         nn = node_count(model%lines(mo%line))
         node = node_number(mo%node, nn)
         do ib = 1, size(model%constraints)
            associate (b => model%constraints(ib))
               if (b%line /= mo%line .or. b%kind == bc_free) cycle
               if (node_number(b%node, nn) == node) return
            end associate
         end do
         call card_error(card, 'line '//trim(model%lines(mo%line)%name)//' '// &
                         node_label(node, nn)//' is not held in position: a *MOTION needs'// &
                         ' a *BOUNDARY of TYPE PINNED, HINGED, CLAMPED or POSITION at its'// &
                         ' node', err)
      end associate
   end subroutine check_motion_held

   !> Refuse a second *INITIAL VELOCITY for the same line.
   subroutine check_unique_velocity(deck, pend, model, iv, err)
      type(deck_t), intent(in) :: deck       !< all cards
      type(pending_t), intent(in) :: pend    !< card of each initial velocity
      type(model_t), intent(in) :: model     !< model with velocities 1..iv resolved
      integer, intent(in) :: iv              !< initial velocity to check
      type(error_t), intent(inout) :: err    !< status
      integer :: jv

      associate (il => model%initial_velocities(iv)%line)
         do jv = 1, iv - 1
            if (model%initial_velocities(jv)%line /= il .or. il == 0) cycle
            call card_error(deck%cards(pend%iv_line(iv)%card), 'line '// &
                            trim(model%lines(il)%name)//' already has an *INITIAL VELOCITY'// &
                            ' (at '//location(deck, pend%iv_line(jv)%card)//')', err)
            return
         end do
      end associate
   end subroutine check_unique_velocity

end module rodyn_deck_dynamic
