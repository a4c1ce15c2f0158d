!> Deck reader, the waves: *WAVE (read_wave_card), its whole-deck check (validate_waves:
!> the deck has *WATER, whose depth the dispersion relation uses) and its warning
!> (wave_warnings: a wave or a sea steeper than the breaking limit). docs/deck.md
!> describes the keyword, docs/waves.md the kinematics; rodyn_deck hands the cards to
!> these readers.
module rodyn_deck_waves
   use rodyn_kinds, only: wp, i8, pi, two_pi
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, waves_t, stretch_names, sea_names, sea_airy, &
                          sea_jonswap, sea_table, sea_record
   use rodyn_deck_lexer, only: deck_t, last_card
   use rodyn_deck_card, only: card_t, card_check_params, card_error, card_check_data, &
                              card_data_error, card_find_param, card_file_error, param_len
   use rodyn_deck_card_values, only: card_get_real, card_get_int, card_get_choice, card_get_name, &
                                     card_data_reals
   use rodyn_deck_table, only: table_t, card_data_table, card_get_table
   use rodyn_deck_numbers, only: real_str, int_str
   use rodyn_deck_support, only: get_bounded, param_fail, location, data_check, refuse
   use rodyn_deck_dynamic, only: record_table, check_time_table
   use rodyn_waves, only: wave_number, jonswap_gamma, sea_components, record_components
   implicit none
   private
   public :: read_wave_card, validate_waves, wave_warnings, read_wave_probe_card

   real(wp), parameter :: deg = pi/180.0_wp        !< one degree [rad]
   real(wp), parameter :: steep_deep = 1.0_wp/7.0_wp !< breaking limit of H/L [-]
   real(wp), parameter :: steep_depth = 0.78_wp    !< breaking limit of H/d [-]
   real(wp), parameter :: steep_sea_short = 1.0_wp/15.0_wp !< limit of S_p, Tp <= tp_short
   real(wp), parameter :: steep_sea_long = 1.0_wp/25.0_wp  !< limit of S_p, Tp >= tp_long
   real(wp), parameter :: tp_short = 8.0_wp        !< [s]
   real(wp), parameter :: tp_long = 15.0_wp        !< [s]
   real(wp), parameter :: max_gamma = 20.0_wp      !< largest JONSWAP GAMMA [-]
   integer, parameter :: max_components = 100000   !< most components of a sea
   integer, parameter :: max_directions = 360      !< most directions of a spread sea
   integer, parameter :: default_directions = 15   !< directions when SPREADING is given
   real(wp), parameter :: record_spacing = 1.0e-6_wp !< tolerance of a record's step [dt]
   character(len=1), parameter :: lf = achar(10)
   character(len=*), parameter :: not_of = ' is not a parameter of TYPE=' !< refuse's why

contains

   !> *WAVE [, TYPE=AIRY], HEIGHT=, PERIOD= [, PHASE=]: a regular Airy wave of height H
   !> [m] and period T [s], eta = H/2 cos(k (x cos beta + y sin beta) - 2 pi t/T +
   !> PHASE) [deg]. *WAVE, TYPE=JONSWAP|PM, HS=, TP= [, GAMMA=] or TYPE=SPECTRUM with data
   !> lines omega [rad/s], S [m2 s/rad]: an irregular sea of COMPONENTS (200) components
   !> between OMEGA MIN and OMEGA MAX [rad/s] (0.5 and 4 omega_p; the table's ends),
   !> drawn from SEED (1) by sea_components, spread over DIRECTIONS (15) by the cos-2s
   !> exponent SPREADING (none). *WAVE, TYPE=RECORD, INPUT=file [, X=, Y=]: the
   !> components of an elevation record (read_record). All: HEADING [deg, from +x towards +y],
   !> STRETCHING=WHEELER (default), VERTICAL, EXTRAPOLATION or NONE, RAMP [s] (0).
   !> At most one.
   subroutine read_wave_card(deck, ic, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      integer, intent(in) :: ic               !< index of the *WAVE card
      type(model_t), intent(inout) :: model   !< model: waves set
      type(error_t), intent(inout) :: err     !< status
      real(wp) :: h, t, heading, phase
      integer :: k, j

      associate (card => deck%cards(ic), wv => model%waves)
         do j = 1, ic - 1
            if (deck%cards(j)%keyword /= 'WAVE') cycle
            call card_error(card, 'given twice (first at '//location(deck, j)//')', err)
            return
         end do
         call card_check_params(card, [character(len=param_len) :: 'TYPE', 'HEIGHT', &
                                'PERIOD', 'HEADING', 'PHASE', 'STRETCHING', 'RAMP', 'HS', &
                                'TP', 'GAMMA', 'COMPONENTS', 'SEED', 'OMEGA MIN', &
                                'OMEGA MAX', 'SPREADING', 'DIRECTIONS', 'INPUT', 'X', &
                                'Y'], err)
         if (has_error(err)) return
         k = sea_airy
         call card_get_choice(card, 'TYPE', sea_names, k, err)
         if (has_error(err)) return
         wv%kind = k
         heading = 0.0_wp
         call card_get_real(card, 'HEADING', heading, err)
         if (has_error(err)) return
         k = wv%stretching
         call card_get_choice(card, 'STRETCHING', stretch_names, k, err)
         if (has_error(err)) return
         wv%stretching = k
         call get_bounded(card, 'RAMP', wv%ramp, .false., err)
         if (has_error(err)) return
         if (wv%kind == sea_record) then
            wv%heading = [heading*deg]
            call read_record(card, model, err)
            if (has_error(err)) return
            wv%present = .true.
            return
         end if
         call refuse(card, [character(len=param_len) :: 'INPUT', 'X', 'Y'], &
                     not_of//trim(sea_names(wv%kind)), err)
         if (has_error(err)) return
         if (wv%kind /= sea_airy) then
            call read_sea(card, wv, err)
            if (has_error(err)) return
            wv%heading = [heading*deg]
            call sea_components(wv)
            wv%present = .true.
            return
         end if
         call refuse(card, [character(len=param_len) :: 'HS', 'TP', 'GAMMA', 'COMPONENTS', &
                     'SEED', 'OMEGA MIN', 'OMEGA MAX', 'SPREADING', 'DIRECTIONS'], &
                     not_of//'AIRY', err)
         call card_check_data(card, 0, 0, err)
         h = 0.0_wp
         call get_bounded(card, 'HEIGHT', h, .true., err, required=.true.)
         t = 0.0_wp
         call get_bounded(card, 'PERIOD', t, .true., err, required=.true.)
         phase = 0.0_wp
         call card_get_real(card, 'PHASE', phase, err)
         if (has_error(err)) return
         wv%height = [h]
         wv%period = [t]
         wv%heading = [heading*deg]
         wv%phase = [phase*deg]
         wv%present = .true.
      end associate
   end subroutine read_wave_card

   !> The spectrum of an irregular sea (TYPE=JONSWAP, PM or SPECTRUM): HS, TP, GAMMA
   !> (JONSWAP only; default jonswap_gamma), or the table; COMPONENTS, SEED, OMEGA MIN,
   !> OMEGA MAX.
   subroutine read_sea(card, wv, err)
      type(card_t), intent(in) :: card      !< the *WAVE card
      type(waves_t), intent(inout) :: wv    !< the sea
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: what = 'omega, S'
      type(table_t) :: table
      real(wp) :: m0
      integer :: k, n
      logical :: found

      call refuse(card, [character(len=param_len) :: 'HEIGHT', 'PERIOD', 'PHASE'], &
                  not_of//trim(sea_names(wv%kind)), err)
      if (wv%kind /= sea_jonswap) call refuse(card, [character(len=param_len) :: 'GAMMA'], &
                                              not_of//trim(sea_names(wv%kind)), err)
      if (has_error(err)) return
      if (wv%kind == sea_table) then
         call refuse(card, [character(len=param_len) :: 'HS', 'TP'], not_of//'SPECTRUM', err)
         call card_data_table(card, 2, what, table, err, nmin=2)
         if (has_error(err)) return
         n = table%n_rows
         do k = 1, n
            call data_check(card, k, 'omega', table%values(1, k), .true., err)
            call data_check(card, k, 'S', table%values(2, k), .false., err)
            if (has_error(err)) return
            if (k == 1) cycle
            if (.not. table%values(1, k) > table%values(1, k - 1)) then
               call card_data_error(card, k, 'the frequencies must increase: omega = '// &
                                    real_str(table%values(1, k))//' after '// &
                                    real_str(table%values(1, k - 1)), err)
               return
            end if
         end do
         wv%tab_omega = table%values(1, 1:n)
         wv%tab_s = table%values(2, 1:n)
         m0 = 0.5_wp*sum((wv%tab_s(2:) + wv%tab_s(:n - 1))*(wv%tab_omega(2:) &
                                                             - wv%tab_omega(:n - 1)))
         if (.not. m0 > 0.0_wp) then
            call card_error(card, 'the spectrum is zero everywhere', err)
            return
         end if
         wv%hs = 4.0_wp*sqrt(m0)
         wv%omega_min = wv%tab_omega(1)
         wv%omega_max = wv%tab_omega(n)
      else
         call card_check_data(card, 0, 0, err)
         call get_bounded(card, 'HS', wv%hs, .true., err, required=.true.)
         call get_bounded(card, 'TP', wv%tp, .true., err, required=.true.)
         if (has_error(err)) return
         wv%gamma = 1.0_wp
         if (wv%kind == sea_jonswap) wv%gamma = jonswap_gamma(wv%hs, wv%tp)
         call card_get_real(card, 'GAMMA', wv%gamma, err, found)
         if (has_error(err)) return
         if (found .and. .not. (wv%gamma >= 1.0_wp .and. wv%gamma <= max_gamma)) then
            call param_fail(card, 'GAMMA', 'GAMMA must be >= 1 and <= 20, got '// &
                            real_str(wv%gamma), err)
            return
         end if
         wv%omega_min = 0.5_wp*two_pi/wv%tp
         wv%omega_max = 4.0_wp*two_pi/wv%tp
      end if
      call card_get_int(card, 'COMPONENTS', wv%components, err)
      if (has_error(err)) return
      if (wv%components < 1 .or. wv%components > max_components) then
         call param_fail(card, 'COMPONENTS', 'COMPONENTS must be >= 1 and <= 100000, got '// &
                         int_str(wv%components), err)
         return
      end if
      call read_spreading(card, wv, err)
      call card_get_int(card, 'SEED', wv%seed, err)
      call get_bounded(card, 'OMEGA MIN', wv%omega_min, .true., err)
      call get_bounded(card, 'OMEGA MAX', wv%omega_max, .true., err)
      if (has_error(err)) return
      if (.not. wv%omega_max > wv%omega_min) then
         call param_fail(card, 'OMEGA MAX', 'OMEGA MAX must be > OMEGA MIN ('// &
                         real_str(wv%omega_min)//' rad/s), got '//real_str(wv%omega_max), err)
         return
      end if
   end subroutine read_sea

   !> TYPE=RECORD, INPUT=file of rows t [s], eta [m] (at least 2, equally spaced in
   !> time) [, X=, Y= of the point the record was taken at, m]: the record's Fourier
   !> components (record_components) towards HEADING.
   subroutine read_record(card, model, err)
      type(card_t), intent(in) :: card      !< the *WAVE card
      type(model_t), intent(inout) :: model !< model: waves set, the table recorded
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: what = 't, eta'
      type(table_t) :: table
      real(wp) :: dt, tk
      integer :: k, n
      call refuse(card, [character(len=param_len) :: 'HEIGHT', 'PERIOD', 'PHASE', 'HS', &
                  'TP', 'GAMMA', 'COMPONENTS', 'SEED', 'OMEGA MIN', 'OMEGA MAX', &
                  'SPREADING', 'DIRECTIONS'], not_of//'RECORD', err)
      call card_check_data(card, 0, 0, err)
      call card_get_real(card, 'X', model%waves%point(1), err)
      call card_get_real(card, 'Y', model%waves%point(2), err)
      if (has_error(err)) return
      call card_get_table(card, 'INPUT', 2, what, table, err, required=.true.)
      if (has_error(err)) return
      call check_time_table(card, table, .true., what, err)
      if (has_error(err)) return
      n = table%n_rows
      dt = (table%values(1, n) - table%values(1, 1))/real(n - 1, wp)
      do k = 2, n
         tk = table%values(1, 1) + real(k - 1, wp)*dt
         if (abs(table%values(1, k) - tk) > record_spacing*dt) then
            call card_file_error(card, table%path, table%line(k), 'the samples must be'// &
                                 ' equally spaced (every '//real_str(dt)//' s from the'// &
                                 ' first and last times): t = '// &
                                 real_str(table%values(1, k))//', expected '// &
                                 real_str(tk), err)
            return
         end if
      end do
      call record_components(table%values(1, 1), dt, table%values(2, 1:n), model%waves)
      call record_table(table, model)
   end subroutine read_record

   !> SPREADING (the cos-2s exponent s, > 0) and DIRECTIONS (M, 1 to 360; 15 when
   !> SPREADING is given, and only with it); COMPONENTS x DIRECTIONS at most 100000.
   subroutine read_spreading(card, wv, err)
      type(card_t), intent(in) :: card      !< the *WAVE card
      type(waves_t), intent(inout) :: wv    !< the sea: spreading, directions set
      type(error_t), intent(inout) :: err   !< status
      logical :: found
      call get_bounded(card, 'SPREADING', wv%spreading, .true., err)
      if (has_error(err)) return
      wv%directions = 1
      if (wv%spreading > 0.0_wp) wv%directions = default_directions
      call card_get_int(card, 'DIRECTIONS', wv%directions, err, found)
      if (has_error(err)) return
      if (found .and. .not. wv%spreading > 0.0_wp) then
         call param_fail(card, 'DIRECTIONS', 'DIRECTIONS needs SPREADING (the cos-2s '// &
                         'exponent): without it the sea is long-crested', err)
         return
      end if
      if (wv%directions < 1 .or. wv%directions > max_directions) then
         call param_fail(card, 'DIRECTIONS', 'DIRECTIONS must be >= 1 and <= 360, got '// &
                         int_str(wv%directions), err)
         return
      end if
      if (int(wv%components, i8)*int(wv%directions, i8) > int(max_components, i8)) then
         call param_fail(card, 'DIRECTIONS', 'COMPONENTS x DIRECTIONS must be <= 100000, '// &
                         'got '//int_str(wv%components)//' x '//int_str(wv%directions), err)
         return
      end if
   end subroutine read_spreading

   !> *WAVE PROBE, NAME=: one data line x, y [m] (global): a point whose wave elevation
   !> is written with the frames and every step (dynamic_waves.csv, docs/output.md).
   !> Names are unique among the probes; the deck needs *WAVE (validate_waves).
   subroutine read_wave_probe_card(deck, ic, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      integer, intent(in) :: ic               !< index of the *WAVE PROBE card
      type(model_t), intent(inout) :: model   !< model: one probe appended
      type(error_t), intent(inout) :: err     !< status
      character(len=:), allocatable :: name
      character(len=len(model%waves%probe_name)), allocatable :: names(:)
      real(wp) :: xy(2)
      real(wp), allocatable :: pts(:, :)
      integer :: n, j

      associate (card => deck%cards(ic), wv => model%waves)
         call card_check_params(card, [character(len=param_len) :: 'NAME'], err)
         call card_get_name(card, 'NAME', name, err, required=.true.)
         if (has_error(err)) return
         if (len(name) > len(names)) then
            call card_error(card, 'NAME '''//name//''' is longer than '// &
                            int_str(len(names))//' characters', err)
            return
         end if
         call card_check_data(card, 1, 1, err, 'x, y')
         call card_data_reals(card, 1, 2, xy, err, 'x, y')
         if (has_error(err)) return
         n = 0
         if (allocated(wv%probe_name)) n = size(wv%probe_name)
         do j = 1, n
            if (wv%probe_name(j) /= name) cycle
            call card_error(card, 'probe '''//name//''' is defined twice', err)
            return
         end do
         allocate (names(n + 1), pts(2, n + 1))
         if (n > 0) then
            names(1:n) = wv%probe_name
            pts(:, 1:n) = wv%probe_xy
         end if
         names(n + 1) = name
         pts(:, n + 1) = xy
         call move_alloc(names, wv%probe_name)
         call move_alloc(pts, wv%probe_xy)
      end associate
   end subroutine read_wave_probe_card

   !> Whole-deck check: waves need *WATER (its DEPTH enters the dispersion relation;
   !> validate_water has made gravity point along -z); a *WAVE PROBE needs *WAVE.
   subroutine validate_waves(deck, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(model_t), intent(in) :: model      !< the model read
      type(error_t), intent(inout) :: err     !< status
      integer :: ic
      if (.not. model%waves%present) then
         do ic = 1, deck%n_cards
            if (deck%cards(ic)%keyword /= 'WAVE PROBE') cycle
            call card_error(deck%cards(ic), 'a probe needs waves (no *WAVE in the deck)', err)
            return
         end do
      end if
      if (.not. model%waves%present .or. model%water%present) return
      do ic = 1, deck%n_cards
         if (deck%cards(ic)%keyword /= 'WAVE') cycle
         if (.not. model%water%present) &
            call card_error(deck%cards(ic), 'waves need *WATER: its DEPTH and SURFACE '// &
                            'set the dispersion relation and the mean surface (no *WATER '// &
                            'in the deck)', err)
         return
      end do
   end subroutine validate_waves

   !> 'FILE:LINE: warning: *WAVE: ...' when a regular wave is steeper than the breaking limit,
   !> H/L > 1/7 (L = 2 pi/k at the water depth) or H/d > 0.78 (DNV-RP-C205, 2021,
   !> section 3.4.6), or an irregular sea (JONSWAP, PM, SPECTRUM) steeper than DNV-RP-C205's
   !> limiting average steepness (section 3.5.5): S_p = 2 pi Hs/(g Tp^2) > 1/15 for
   !> Tp <= 8 s, 1/25 for Tp >= 15 s, linear in Tp between (sea_steepness); linear
   !> theory describes such a wave badly. '' otherwise.
   function wave_warnings(deck, model) result(text)
      type(deck_t), intent(in) :: deck      !< all cards
      type(model_t), intent(in) :: model    !< the validated model
      character(len=:), allocatable :: text !< the warning lines
      real(wp) :: h, d, el, sp, lim, tp
      integer :: ic, i
      text = ''
      if (.not. model%waves%present .or. .not. model%water%present) return
      ic = last_card(deck, 'WAVE')
      if (ic == 0) return
      d = model%water%depth
      if (model%waves%kind == sea_record) return
      if (model%waves%kind /= sea_airy) then
         call sea_steepness(model%waves, norm2(model%gravity), tp, sp, lim)
         if (sp > lim) text = location(deck, ic)//': warning: *WAVE: the sea of HS='// &
                              real_str(rounded(model%waves%hs))//' m and TP='// &
                              real_str(rounded(tp))//' s is steeper than the breaking'// &
                              ' limit: 2 pi Hs/(g Tp^2) = '//real_str(rounded(sp))//' > '// &
                              real_str(rounded(lim))//" (DNV-RP-C205's limiting average"// &
                              ' steepness: 1/15 for Tp <= 8 s, 1/25 for Tp >= 15 s, linear'// &
                              ' between); linear theory describes it badly'//lf
         return
      end if
      do i = 1, size(model%waves%height)
         h = model%waves%height(i)
         el = two_pi/wave_number(two_pi/model%waves%period(i), d, norm2(model%gravity))
         if (h/el > steep_deep) then
            text = text//location(deck, ic)//': warning: *WAVE: the wave of HEIGHT='// &
                   real_str(h)//' m and PERIOD='//real_str(model%waves%period(i))// &
                   ' s is steeper than the breaking limit: H/L = '//real_str(rounded(h/el))// &
                   ' > 1/7 (L = '//real_str(rounded(el))//' m at DEPTH='//real_str(d)// &
                   ' m); linear theory describes it badly'//lf
         else if (h/d > steep_depth) then
            text = text//location(deck, ic)//': warning: *WAVE: the wave of HEIGHT='// &
                   real_str(h)//' m is higher than the breaking limit in DEPTH='// &
                   real_str(d)//' m: H/d = '//real_str(rounded(h/d))//' > 0.78'//lf
         end if
      end do
   contains
      !> x to 4 significant digits, for the message.
      pure real(wp) function rounded(x)
         real(wp), intent(in) :: x !< a positive number
         real(wp) :: sc
         sc = 10.0_wp**(3 - floor(log10(x)))
         rounded = anint(x*sc)/sc
      end function rounded
   end function wave_warnings

   !> The average steepness S_p = 2 pi Hs/(g Tp^2) of an irregular sea and DNV-RP-C205's
   !> limit at its Tp (wave_warnings); Tp of a SPECTRUM table at its largest S (the
   !> first row of the largest), its Hs 4 sqrt(m0).
   pure subroutine sea_steepness(wv, g, tp, sp, lim)
      type(waves_t), intent(in) :: wv  !< an irregular sea (JONSWAP, PM, SPECTRUM)
      real(wp), intent(in) :: g        !< |gravity| [m/s2]
      real(wp), intent(out) :: tp      !< peak period [s]
      real(wp), intent(out) :: sp      !< S_p [-]
      real(wp), intent(out) :: lim     !< the limit at tp [-]
      tp = wv%tp
      if (wv%kind == sea_table) tp = two_pi/wv%tab_omega(maxloc(wv%tab_s, 1))
      sp = two_pi*wv%hs/(g*tp**2)
      lim = steep_sea_short + (steep_sea_long - steep_sea_short) &
            *min(1.0_wp, max(0.0_wp, (tp - tp_short)/(tp_long - tp_short)))
   end subroutine sea_steepness
end module rodyn_deck_waves
