!> Deck reader, *BODY WAVE LOAD (docs/deck.md; docs/systems.md, "Wave loads on a body";
!> docs/theory.md eq. (150)): a FREE body's first-order wave force and moment at its
!> reference point R per metre of wave amplitude, by wave period and heading relative to
!> the body's x axis (force RAOs, as a diffraction program gives them), read as a vessel's
!> displacement RAOs are (rodyn_deck_vessel's rao_grid); and its whole-deck checks and
!> warnings.
module rodyn_deck_body_waves
   use rodyn_kinds, only: wp, two_pi
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, body_free, rao_interp_complex, rao_interp_polar, sea_airy
   use rodyn_deck_lexer, only: deck_t
   use rodyn_deck_card, only: card_t, card_check_params, card_error, card_find_param, &
                              card_check_data, param_len
   use rodyn_deck_card_values, only: card_get_name
   use rodyn_deck_table, only: table_t, card_get_table, card_data_table
   use rodyn_deck_numbers, only: real_str
   use rodyn_deck_support, only: pending_t, reading_t, param_fail, location, sub_wave
   use rodyn_deck_body, only: body_of_card, body_card_once
   use rodyn_deck_vessel, only: rao_grid, rao_options
   use rodyn_deck_dynamic, only: record_table
   implicit none
   private
   public :: read_body_wave_load_card, check_body_wave_loads, body_wave_warnings

   character(len=*), parameter :: what_load = 'period, heading, Fx, Fy, Fz, Mx, My, Mz'// &
                                  ' amplitudes, the same 6 phases'

contains

   !> *BODY WAVE LOAD, BODY=name [, INPUT=file] [, PHASE=LAG|LEAD]
   !> [, INTERPOLATION=COMPLEX|POLAR]: rows of period [s], heading relative to the body's
   !> x axis [deg], the amplitudes of Fx, Fy, Fz [N/m] and Mx, My, Mz about R [N m/m]
   !> per metre of wave amplitude, and their 6 phases [deg] (lags behind the crest at R
   !> by default), on a full grid of periods and headings: from INPUT=file or from the
   !> card's data lines. One per body, after its *BODY card.
   subroutine read_body_wave_load_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< the body's wave load set
      type(error_t), intent(inout) :: err     !< status
      type(table_t) :: table
      character(len=:), allocatable :: name
      integer :: ib, iphase, interp
      logical :: found
      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call body_of_card(deck, ic, model, pend, [character(len=param_len) :: 'BODY', &
                           'INPUT', 'PHASE', 'INTERPOLATION'], name, ib, err)
         if (has_error(err)) return         ! (name is not set)
         call body_card_once(deck, ic, pend, name, ib, err)
         call rao_options(card, iphase, interp, err)
         if (has_error(err)) return
         call card_get_table(card, 'INPUT', 14, what_load, table, err, found)
         if (has_error(err)) return
         if (found) then
            call card_check_data(card, 0, 0, err)
         else
            call card_check_data(card, 1, -1, err, what_load//'; or INPUT=file')
            if (.not. has_error(err)) call card_data_table(card, 14, what_load, table, err)
         end if
         if (has_error(err)) return
         associate (rao => model%bodies(ib)%wave_load)
            rao%interp = merge(rao_interp_complex, rao_interp_polar, interp == 1)
            call rao_grid(card, table, 1.0_wp, iphase == 1, what_load, rao, err)
         end associate
         if (has_error(err)) return
         if (found) call record_table(table, model)
         model%bodies(ib)%wave_load_at = location(deck, ic)
      end associate
   end subroutine read_body_wave_load_card

   !> A wave load acts on a FREE body, in the deck's sea, in a dynamic analysis.
   subroutine check_body_wave_loads(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< card of each body's wave load
      type(model_t), intent(inout) :: model      !< model
      type(error_t), intent(inout) :: err     !< status
      integer :: ib
      do ib = 1, size(model%bodies)
         if (pend%body_sub(sub_wave, ib) == 0) cycle
         associate (card => deck%cards(pend%body_sub(sub_wave, ib)))
            if (model%bodies(ib)%kind /= body_free) then
               call param_fail(card, 'BODY', "body '"//trim(model%bodies(ib)%name)// &
                               "' is FIXED: a wave load moves a FREE body only", err)
            else if (.not. model%waves%present) then
               call card_error(card, 'a body''s wave load acts in the deck''s sea, and the'// &
                               ' deck has no *WAVE', err)
            else if (.not. model%dynamic%requested) then
               call card_error(card, 'a body''s wave load acts in a dynamic analysis, and'// &
                               ' the deck has no *DYNAMIC', err)
            end if
         end associate
         if (has_error(err)) return
      end do
   end subroutine check_body_wave_loads

   !> 'FILE:LINE: warning:' lines for a body's wave load whose table misses part of the
   !> sea: a regular wave's period, or part of a spectrum's band, outside the table's
   !> periods (the load is zero there).
   function body_wave_warnings(model) result(text)
      type(model_t), intent(in) :: model   !< model
      character(len=:), allocatable :: text
      character(len=:), allocatable :: what
      real(wp) :: tlo, thi, p1, p2
      integer :: ib, np
      text = ''
      if (.not. (allocated(model%bodies) .and. model%waves%present)) return
      if (model%waves%kind == sea_airy) then
         tlo = minval(model%waves%period)
         thi = maxval(model%waves%period)
      else
         if (.not. model%waves%omega_max > 0.0_wp) return
         tlo = two_pi/model%waves%omega_max
         thi = two_pi/max(model%waves%omega_min, tiny(1.0_wp))
      end if
      do ib = 1, size(model%bodies)
         if (.not. allocated(model%bodies(ib)%wave_load%period)) cycle
         np = size(model%bodies(ib)%wave_load%period)
         p1 = model%bodies(ib)%wave_load%period(1)
         p2 = model%bodies(ib)%wave_load%period(np)
         if (tlo >= p1*(1.0_wp - 1.0e-12_wp) .and. thi <= p2*(1.0_wp + 1.0e-12_wp)) cycle
         if (tlo == thi) then
            what = 'the wave''s period '//real_str(tlo)//' s lies'
         else
            what = 'the sea''s periods '//real_str(tlo)//' to '//real_str(thi)//' s reach'
         end if
         text = text//model%bodies(ib)%wave_load_at//': warning: *BODY WAVE LOAD: '// &
                what//' outside the table''s '//real_str(p1)//' to '//real_str(p2)// &
                ' s: body '//trim(model%bodies(ib)%name)//' takes no wave load there'// &
                new_line('a')
      end do
   end function body_wave_warnings
end module rodyn_deck_body_waves
