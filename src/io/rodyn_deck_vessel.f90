!> Deck reader, *VESSEL (docs/deck.md, docs/vessels.md): a vessel's reference point at
!> rest, its heading, and its motion, from displacement RAOs (TYPE=RAO) or from a 6-DOF
!> time series (TYPE=TABLE), both read from INPUT=file; and the whole-deck checks of
!> vessels (validate_vessels: unique names, the VESSEL= of *MOTION, no hinged end on a
!> vessel, a sea for RAOs, and the RAO vessels' response factors in that sea).
module rodyn_deck_vessel
   use rodyn_kinds, only: wp, pi, two_pi
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, vessel_t, vessel_rao_t, vessel_from_rao, vessel_from_table, &
                          rao_interp_complex, rao_interp_polar, motion_vessel, bc_hinged
   use rodyn_deck_lexer, only: deck_t
   use rodyn_deck_card, only: card_t, card_check_params, card_error, card_find_param, &
                              card_file_error, card_check_data, param_len
   use rodyn_deck_card_values, only: card_get_real, card_get_name, card_get_choice, card_data_reals
   use rodyn_deck_table, only: table_t, card_get_table
   use rodyn_deck_numbers, only: real_str, int_str
   use rodyn_deck_support, only: pending_t, reading_t, param_fail, location, node_count, &
                                 node_number, &
                                 node_label, refuse
   use rodyn_deck_dynamic, only: record_table, check_time_table
   use rodyn_deck_waves, only: validate_waves
   use rodyn_waves, only: wave_field_t, waves_build
   use rodyn_vessel, only: vessel_coefficients
   use rodyn_sort, only: sorted_order
   implicit none
   private
   public :: read_vessel_card, validate_vessels, rao_grid, rao_options

   character(len=*), parameter :: what_rao = 'period, heading, surge, sway, heave, roll,'// &
                                  ' pitch, yaw amplitudes, the same 6 phases'
   character(len=*), parameter :: what_motion = 't, surge, sway, heave, roll, pitch, yaw'
   real(wp), parameter :: deg = pi/180.0_wp   !< one degree [rad]

contains

   !> *VESSEL, NAME=, TYPE=RAO|TABLE, INPUT=file [, PHASE=LAG|LEAD]
   !> [, ROTATION UNITS=DEG|RAD] [, INTERPOLATION=COMPLEX|POLAR]; one data line
   !> x, y, z [m], heading [deg] of the reference point at rest.
   !> RAO rows: period [s], relative heading [deg], 6 amplitudes (m/m for translations,
   !> ROTATION UNITS per m for rotations), 6 phases [deg], on a full grid of periods and
   !> headings. TABLE rows: t [s], surge, sway, heave [m], roll, pitch, yaw (ROTATION UNITS).
   subroutine read_vessel_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: one vessel appended
      type(error_t), intent(inout) :: err     !< status
      type(vessel_t) :: ve
      type(table_t) :: table
      character(len=:), allocatable :: name
      real(wp) :: v(4), rot
      integer :: it, iphase, iunit, interp, n

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call card_check_params(card, [character(len=param_len) :: 'NAME', 'TYPE', 'INPUT', &
                                'PHASE', 'ROTATION UNITS', 'INTERPOLATION', 'OFFSET X', &
                                'OFFSET Y', 'OFFSET Z', 'OFFSET HEADING', 'DRIFT X', &
                                'DRIFT Y', 'DRIFT YAW', 'DRIFT PERIOD', 'DRIFT PHASE', &
                                'DRIFT INPUT', 'OFFSET START'], err)
         call card_get_name(card, 'NAME', name, err, required=.true.)
         if (has_error(err)) return
         ve%name = name
         it = 0
         call card_get_choice(card, 'TYPE', [character(len=8) :: 'RAO', 'TABLE'], it, err, &
                              required=.true.)
         if (has_error(err)) return
         ve%kind = merge(vessel_from_rao, vessel_from_table, it == 1)
         iunit = 1
         call card_get_choice(card, 'ROTATION UNITS', [character(len=8) :: 'DEG', 'RAD'], &
                              iunit, err)
         if (has_error(err)) return
         rot = merge(deg, 1.0_wp, iunit == 1)
         call rao_options(card, iphase, interp, err)
         if (has_error(err)) return
         if (ve%kind == vessel_from_table) call refuse(card, [character(len=param_len) :: &
                                                   'PHASE', 'INTERPOLATION'], &
                                                   ' is only allowed with TYPE=RAO', err)
         call card_check_data(card, 1, 1, err, 'x, y, z, heading')
         call card_data_reals(card, 1, 4, v, err, 'x, y, z, heading')
         if (has_error(err)) return
         ve%origin = v(1:3)
         ve%heading = v(4)*deg
         call read_slow_motion(card, ve, model, err)
         if (has_error(err)) return

         if (ve%kind == vessel_from_table) then
            call card_get_table(card, 'INPUT', 7, what_motion, table, err, required=.true.)
            if (has_error(err)) return
            call check_motion_table(card, table, err)
            if (has_error(err)) return
            n = table%n_rows
            ve%file = table%path
            ve%time = table%values(1, 1:n)
            ve%motion = table%values(2:7, 1:n)
            ve%motion(4:6, :) = rot*ve%motion(4:6, :)
         else
            call card_get_table(card, 'INPUT', 14, what_rao, table, err, required=.true.)
            if (has_error(err)) return
            ve%file = table%path
            ve%rao%interp = merge(rao_interp_complex, rao_interp_polar, interp == 1)
            call rao_grid(card, table, rot, iphase == 1, what_rao, ve%rao, err)
            if (has_error(err)) return
         end if
         call record_table(table, model)
         pend%n_vessels = pend%n_vessels + 1
         model%vessels(pend%n_vessels) = ve
         pend%vessel_card(pend%n_vessels) = ic
      end associate
   end subroutine read_vessel_card

   !> The slow motion of the reference point, global (rodyn_motion's vessel_slow_motion):
   !> OFFSET X, Y, Z [m], OFFSET HEADING [deg] (0); a harmonic drift of amplitudes
   !> DRIFT X, DRIFT Y [m], DRIFT YAW [deg] (0), DRIFT PERIOD [s] (> 0, required with an
   !> amplitude and only with one), DRIFT PHASE [deg] (0, only with a drift); or a drift
   !> table, DRIFT INPUT=file of rows t [s], x, y, z [m], heading [deg]. OFFSET
   !> START=STATIC (default) or DYNAMIC: the offset in the static analysis, or ramped in
   !> with the dynamics.
   subroutine read_slow_motion(card, ve, model, err)
      type(card_t), intent(in) :: card      !< the *VESSEL card
      type(vessel_t), intent(inout) :: ve   !< vessel: offset and drift set
      type(model_t), intent(inout) :: model !< model: the drift table recorded
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: what_drift = 't, x, y, z, heading'
      type(table_t) :: table
      character(len=param_len), parameter :: off(4) = [character(len=param_len) :: &
                                             'OFFSET X', 'OFFSET Y', 'OFFSET Z', &
                                             'OFFSET HEADING']
      character(len=param_len), parameter :: amp(3) = [character(len=param_len) :: &
                                             'DRIFT X', 'DRIFT Y', 'DRIFT YAW']
      real(wp) :: ph
      logical :: found, any_amp
      integer :: j
      do j = 1, 4
         call card_get_real(card, trim(off(j)), ve%offset(j), err)
      end do
      if (has_error(err)) return
      ve%offset(4) = ve%offset(4)*deg
      j = 1
      call card_get_choice(card, 'OFFSET START', [character(len=8) :: 'STATIC', 'DYNAMIC'], &
                           j, err)
      if (has_error(err)) return
      ve%offset_static = j == 1
      any_amp = .false.
      do j = 1, 3
         call card_get_real(card, trim(amp(j)), ve%drift(merge(j, 4, j < 3)), err, found)
         any_amp = any_amp .or. found
      end do
      if (has_error(err)) return
      ve%drift(4) = ve%drift(4)*deg
      call card_get_real(card, 'DRIFT PERIOD', ve%drift_period, err, found)
      if (has_error(err)) return
      if (any_amp .and. .not. found) then
         call card_error(card, 'a drift (DRIFT X, DRIFT Y or DRIFT YAW) needs its DRIFT '// &
                         'PERIOD', err)
         return
      end if
      if (found .and. .not. any_amp) then
         call param_fail(card, 'DRIFT PERIOD', 'DRIFT PERIOD without a drift amplitude '// &
                         '(DRIFT X, DRIFT Y or DRIFT YAW)', err)
         return
      end if
      if (found .and. .not. ve%drift_period > 0.0_wp) then
         call param_fail(card, 'DRIFT PERIOD', 'DRIFT PERIOD must be > 0, got '// &
                         real_str(ve%drift_period), err)
         return
      end if
      ph = 0.0_wp
      call card_get_real(card, 'DRIFT PHASE', ph, err, found)
      if (has_error(err)) return
      if (found .and. .not. any_amp) then
         call param_fail(card, 'DRIFT PHASE', 'DRIFT PHASE without a drift amplitude '// &
                         '(DRIFT X, DRIFT Y or DRIFT YAW)', err)
         return
      end if
      ve%drift_phase = ph*deg
      call card_get_table(card, 'DRIFT INPUT', 5, what_drift, table, err, found)
      if (has_error(err) .or. .not. found) return
      if (any_amp) then
         call param_fail(card, 'DRIFT INPUT', 'DRIFT INPUT (a drift table) or DRIFT X, '// &
                         'DRIFT Y, DRIFT YAW (a harmonic drift), not both', err)
         return
      end if
      call check_time_table(card, table, .true., what_drift, err)
      if (has_error(err)) return
      ve%drift_time = table%values(1, 1:table%n_rows)
      ve%drift_table = table%values(2:5, 1:table%n_rows)
      ve%drift_table(4, :) = ve%drift_table(4, :)*deg
      call record_table(table, model)
   end subroutine read_slow_motion

   !> A 6-DOF motion table: at least 2 rows, times increasing strictly, finite values.
   subroutine check_motion_table(card, table, err)
      type(card_t), intent(in) :: card      !< the *VESSEL card
      type(table_t), intent(in) :: table    !< rows t, 6 motions
      type(error_t), intent(inout) :: err   !< status
      integer :: k
      if (table%n_rows < 2) then
         call param_fail(card, 'INPUT', "'"//table%path//"' has "//int_str(table%n_rows)// &
                         ' row(s) ('//what_motion//'): at least 2 are needed', err)
         return
      end if
      do k = 2, table%n_rows
         if (.not. table%values(1, k) > table%values(1, k - 1)) then
            call card_file_error(card, table%path, table%line(k), 'times must increase'// &
                                 ' strictly: t = '//real_str(table%values(1, k))// &
                                 ' follows t = '//real_str(table%values(1, k - 1)), err)
            return
         end if
      end do
   end subroutine check_motion_table

   !> An RAO table's PHASE=LAG|LEAD (iphase 1 or 2) and INTERPOLATION=COMPLEX|POLAR
   !> (interp 1 or 2), both 1 by default.
   subroutine rao_options(card, iphase, interp, err)
      type(card_t), intent(in) :: card      !< the *VESSEL or *BODY WAVE LOAD card
      integer, intent(out) :: iphase        !< 1: lags, 2: leads
      integer, intent(out) :: interp        !< 1: complex values, 2: amplitude and phase
      type(error_t), intent(inout) :: err   !< status
      iphase = 1
      call card_get_choice(card, 'PHASE', [character(len=8) :: 'LAG', 'LEAD'], iphase, err)
      if (has_error(err)) return
      interp = 1
      call card_get_choice(card, 'INTERPOLATION', [character(len=8) :: 'COMPLEX', &
                           'POLAR'], interp, err)
   end subroutine rao_options

   !> The RAO rows as a full grid of periods (increasing) and headings (in [0, 360) deg):
   !> every heading has every period once; amplitudes not negative, periods positive.
   !> H = R exp(-i eps) for a lag eps, R exp(+i eps) for a lead.
   subroutine rao_grid(card, table, rot, lag, what, rao, err)
      type(card_t), intent(in) :: card      !< the *VESSEL or *BODY WAVE LOAD card
      type(table_t), intent(in) :: table    !< rows of 14 values
      real(wp), intent(in) :: rot           !< scale of the rotation (moment) amplitudes
      logical, intent(in) :: lag            !< phases are lags (else leads)
      character(len=*), intent(in) :: what  !< names of the columns
      type(vessel_rao_t), intent(inout) :: rao !< period, heading, h set
      type(error_t), intent(inout) :: err   !< status
      real(wp), allocatable :: periods(:), headings(:)
      logical, allocatable :: seen(:, :)
      real(wp) :: h, amp(6), sgn
      integer :: k, ip, ih, np, nh, row

      if (table%n_rows < 1) then
         call param_fail(card, 'INPUT', "'"//table%path//"' has no rows ("//what//')', err)
         return
      end if
      allocate (periods(0), headings(0))
      do k = 1, table%n_rows
         associate (r => table%values(:, k))
            if (.not. r(1) > 0.0_wp) then
               call card_file_error(card, table%path, table%line(k), 'the wave period'// &
                                    ' must be positive, got '//real_str(r(1)), err)
               return
            end if
            if (any(r(3:8) < 0.0_wp)) then
               call card_file_error(card, table%path, table%line(k), 'RAO amplitudes'// &
                                    ' must not be negative', err)
               return
            end if
            h = modulo(r(2), 360.0_wp)
            if (.not. any(periods == r(1))) periods = [periods, r(1)]
            if (.not. any(headings == h)) headings = [headings, h]
         end associate
      end do
      periods = periods(sorted_order(periods))
      headings = headings(sorted_order(headings))
      np = size(periods)
      nh = size(headings)
      allocate (seen(np, nh), rao%h(6, np, nh))
      seen = .false.
      rao%period = periods
      rao%heading = headings*pi/180.0_wp
      sgn = merge(-1.0_wp, 1.0_wp, lag)
      do k = 1, table%n_rows
         associate (r => table%values(:, k))
            ip = findloc(periods, r(1), dim=1)
            ih = findloc(headings, modulo(r(2), 360.0_wp), dim=1)
            if (seen(ip, ih)) then
               call card_file_error(card, table%path, table%line(k), 'period '// &
                                    real_str(r(1))//' s at heading '//real_str(r(2))// &
                                    ' deg is given twice', err)
               return
            end if
            seen(ip, ih) = .true.
            amp = r(3:8)
            amp(4:6) = rot*amp(4:6)
            rao%h(:, ip, ih) = amp*exp(cmplx(0.0_wp, sgn*r(9:14)*pi/180.0_wp, wp))
         end associate
      end do
      do ih = 1, nh
         do ip = 1, np
            if (seen(ip, ih)) cycle
            row = table%line(table%n_rows)
            call card_file_error(card, table%path, row, 'the RAO table is not a full'// &
                                 ' grid: heading '//real_str(headings(ih))//' deg has no'// &
                                 ' row for period '//real_str(periods(ip))//' s (every'// &
                                 ' heading needs every period)', err)
            return
         end do
      end do
   end subroutine rao_grid

   !> Whole-deck checks of vessels: unique names; each *MOTION, TYPE=VESSEL names one
   !> (its index set); its node is not hinged (the hinge's axis would not turn with the
   !> vessel; a clamped end turns with it, rodyn_dynamics); a vessel moved by RAOs needs
   !> a sea (*WAVE), and gets its response factors in it (vessel_in_sea). The waves are
   !> checked first (validate_waves).
   subroutine validate_vessels(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< vessel and motion cards, VESSEL= names
      type(model_t), intent(inout) :: model   !< motions' vessel indices set
      type(error_t), intent(inout) :: err     !< status
      integer :: i, j, k, ib, nn, node
      character(len=:), allocatable :: what
      call validate_waves(deck, model, err)
      if (has_error(err)) return
      do i = 1, size(model%vessels)
         do j = 1, i - 1
            if (model%vessels(j)%name /= model%vessels(i)%name) cycle
            call param_fail(deck%cards(pend%vessel_card(i)), 'NAME', 'vessel '// &
                            trim(model%vessels(i)%name)//' is already defined (at '// &
                            location(deck, pend%vessel_card(j))//')', err)
            return
         end do
         if (model%vessels(i)%kind == vessel_from_rao) then
            if (.not. model%waves%present) then
               call card_error(deck%cards(pend%vessel_card(i)), 'TYPE=RAO moves the'// &
                               ' vessel in the waves of the deck, and it has no *WAVE', err)
               return
            end if
            call vessel_in_sea(model, model%vessels(i))
         end if
      end do
      do k = 1, size(model%motions)
         if (model%motions(k)%kind /= motion_vessel) cycle
         associate (card => deck%cards(pend%motion_line(k)%card), &
                    name => pend%motion_vessel(k)%name, mo => model%motions(k))
            do i = 1, size(model%vessels)
               if (model%vessels(i)%name == name) exit
            end do
            if (i > size(model%vessels)) then
               call param_fail(card, 'VESSEL', "VESSEL '"//name//"' is not defined (no"// &
                               ' *VESSEL with NAME='//name//' in the deck)', err)
               return
            end if
            mo%vessel = i
            if (mo%body > 0 .or. mo%point > 0) then
               ! a body or point on the vessel: fixed to it where it is at rest in the
               ! statics
               associate (ve => model%vessels(i))
                  if (ve%offset_static .and. any(ve%offset /= 0.0_wp)) then
                     if (mo%body > 0) then
                        what = 'body '//trim(model%bodies(mo%body)%name)
                     else
                        what = 'point '//trim(model%points(mo%point)%name)
                     end if
                     call card_error(card, what//' is moved with vessel '//trim(ve%name)// &
                                     ', whose static offset the statics does not give a '// &
                                     what(1:index(what, ' ') - 1)//': ramp the offset in'// &
                                     ' with OFFSET START=DYNAMIC', err)
                  end if
               end associate
               if (has_error(err)) return
               cycle
            end if
            nn = node_count(model%lines(mo%line))
            node = node_number(mo%node, nn)
            do ib = 1, size(model%constraints)
               associate (b => model%constraints(ib))
                  if (b%line /= mo%line .or. node_number(b%node, nn) /= node) cycle
                  if (b%kind /= bc_hinged) cycle
                  call card_error(card, 'line '//trim(model%lines(mo%line)%name)//' '// &
                                  node_label(node, nn)//' is HINGED (*BOUNDARY at '// &
                                  location(deck, pend%bc_line(ib)%card)//'): a hinge'// &
                                  "'s axis does not turn with a vessel yet; hold the"// &
                                  ' end PINNED or CLAMPED', err)
                  return
               end associate
            end do
         end associate
      end do
   end subroutine validate_vessels

   !> The response factors of an RAO vessel in the deck's sea (rodyn_vessel's
   !> vessel_coefficients): component j of the sea, eta_j = a_j cos(k_j.x - omega_j t
   !> + phase_j) (rodyn_waves), has at the reference point O the elevation
   !> a_j cos(omega_j t + phi_j) with phi_j = -(k_j.O) - phase_j. The sea's ramp is the
   !> vessel's too (vessel_motion). A vessel at rest at its static offset (OFFSET
   !> START=STATIC and a dynamics started from the statics) meets the waves there: O +
   !> offset_1:3 and relative heading beta_j - (psi0 + offset_psi).
   subroutine vessel_in_sea(model, ve)
      type(model_t), intent(in) :: model     !< model with its waves and water
      type(vessel_t), intent(inout) :: ve    !< coef, omega and ramp set
      type(wave_field_t) :: field
      real(wp), allocatable :: phi(:), beta(:)
      real(wp) :: o(3), psi
      call waves_build(model%waves, model%water%depth, model%water%surface, &
                       norm2(model%gravity), field)
      o = ve%origin
      psi = ve%heading
      if (ve%offset_static .and. model%dynamic%start_static) then
         o = o + ve%offset(1:3)
         psi = psi + ve%offset(4)
      end if
      phi = -(field%kx*o(1) + field%ky*o(2)) - field%phase
      beta = atan2(field%sb, field%cb)
      if (allocated(ve%coef)) deallocate (ve%coef, ve%omega)
      allocate (ve%coef(6, field%n))
      ve%omega = field%omega
      call vessel_coefficients(ve%rao, psi, field%amp, field%omega, beta, phi, ve%coef)
      ve%sea_ramp = field%ramp
   end subroutine vessel_in_sea
end module rodyn_deck_vessel
