!> Deck reader, the waves: *WAVE (read_wave_card), its whole-deck check (validate_waves:
!> the deck has *WATER, whose depth the dispersion relation uses) and its warning
!> (wave_warnings: a wave steeper than the breaking limit). docs/deck.md describes the
!> keyword, docs/waves.md the kinematics; rodyn_deck hands the cards to these readers.
module rodyn_deck_waves
   use rodyn_kinds, only: wp, pi, two_pi
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, stretch_names
   use rodyn_deck_lexer, only: deck_t, card_t, card_check_params, card_error, &
                               card_get_real, card_get_choice, card_check_data, real_str, &
                               param_len
   use rodyn_deck_support, only: get_bounded, param_fail, location
   use rodyn_waves, only: wave_number
   implicit none
   private
   public :: read_wave_card, validate_waves, wave_warnings

   real(wp), parameter :: deg = pi/180.0_wp        !< one degree [rad]
   real(wp), parameter :: steep_deep = 1.0_wp/7.0_wp !< breaking limit of H/L [-]
   real(wp), parameter :: steep_depth = 0.78_wp    !< breaking limit of H/d [-]
   character(len=1), parameter :: lf = achar(10)

contains

   !> *WAVE, HEIGHT=, PERIOD= [, HEADING=, PHASE=, STRETCHING=, RAMP=]: a regular Airy
   !> wave of height H [m] and period T [s] travelling towards HEADING [deg, from +x
   !> towards +y], eta = H/2 cos(k (x cos beta + y sin beta) - 2 pi t/T + PHASE) [deg];
   !> STRETCHING=WHEELER (default), VERTICAL, EXTRAPOLATION or NONE; ramped in over
   !> RAMP [s] (default 0: none). No data lines; at most one.
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
         call card_check_params(card, [character(len=param_len) :: 'HEIGHT', 'PERIOD', &
                                'HEADING', 'PHASE', 'STRETCHING', 'RAMP'], err)
         if (has_error(err)) return
         call card_check_data(card, 0, 0, err)
         if (has_error(err)) return
         h = 0.0_wp
         call card_get_real(card, 'HEIGHT', h, err, required=.true.)
         if (has_error(err)) return
         if (.not. h > 0.0_wp) then
            call param_fail(card, 'HEIGHT', 'HEIGHT must be > 0, got '//real_str(h), err)
            return
         end if
         t = 0.0_wp
         call card_get_real(card, 'PERIOD', t, err, required=.true.)
         if (has_error(err)) return
         if (.not. t > 0.0_wp) then
            call param_fail(card, 'PERIOD', 'PERIOD must be > 0, got '//real_str(t), err)
            return
         end if
         heading = 0.0_wp
         phase = 0.0_wp
         call card_get_real(card, 'HEADING', heading, err)
         call card_get_real(card, 'PHASE', phase, err)
         if (has_error(err)) return
         k = wv%stretching
         call card_get_choice(card, 'STRETCHING', stretch_names, k, err)
         if (has_error(err)) return
         wv%stretching = k
         call get_bounded(card, 'RAMP', wv%ramp, .false., err)
         if (has_error(err)) return
         wv%height = [h]
         wv%period = [t]
         wv%heading = [heading*deg]
         wv%phase = [phase*deg]
         wv%present = .true.
      end associate
   end subroutine read_wave_card

   !> Whole-deck check: waves need *WATER (its DEPTH enters the dispersion relation;
   !> validate_water has made gravity point along -z).
   subroutine validate_waves(deck, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(model_t), intent(in) :: model      !< the model read
      type(error_t), intent(inout) :: err     !< status
      integer :: ic
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

   !> 'FILE:LINE: warning: *WAVE: ...' when the wave is steeper than the breaking limit,
   !> H/L > 1/7 (L = 2 pi/k at the water depth) or H/d > 0.78 (DNV-RP-C205, 2021,
   !> section 3.4.6): linear theory describes such a wave badly. '' otherwise.
   function wave_warnings(deck, model) result(text)
      type(deck_t), intent(in) :: deck      !< all cards
      type(model_t), intent(in) :: model    !< the validated model
      character(len=:), allocatable :: text !< the warning lines
      real(wp) :: h, d, el
      integer :: ic, i
      text = ''
      if (.not. model%waves%present .or. .not. model%water%present) return
      ic = 0
      do i = 1, deck%n_cards
         if (deck%cards(i)%keyword == 'WAVE') ic = i
      end do
      if (ic == 0) return
      d = model%water%depth
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
end module rodyn_deck_waves
