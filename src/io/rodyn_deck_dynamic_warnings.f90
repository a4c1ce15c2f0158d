!> Deck reader, the warnings of a dynamic analysis that cannot resolve what it is given
!> (docs/dynamics.md, "Time step and output interval warnings"): a DT not well below the
!> shortest period of the harmonic *MOTIONs, or longer than the sampling interval of a
!> *MOTION or *AMPLITUDE table; an OUTPUT INTERVAL too long for that period. rodyn_deck
!> adds them to the deck's warnings once the model is validated; the run goes on.
module rodyn_deck_dynamic_warnings
   use rodyn_kinds, only: wp
   use rodyn_model, only: model_t, motion_harmonic, motion_vessel
   use rodyn_deck_lexer, only: deck_t, last_card
   use rodyn_deck_card, only: card_t, card_find_param
   use rodyn_deck_numbers, only: real_str, int_str
   implicit none
   private
   public :: dynamic_warnings

   ! Time resolution of the prescribed motions and loads: below these a run may be
   ! meaningless
   real(wp), parameter :: min_steps_per_period = 10.0_wp   !< steps a shortest period
   real(wp), parameter :: min_frames_per_period = 10.0_wp  !< frames a shortest period
   character(len=1), parameter :: lf = achar(10)

contains

   !> Warnings 'FILE:LINE: warning: *DYNAMIC: ...' (each ended by a newline; '' if none)
   !> for a dynamic analysis that cannot resolve what it is given: a DT not well below
   !> the shortest period of the harmonic *MOTIONs (fewer than min_steps_per_period steps
   !> a period) or longer than the sampling interval of a *MOTION table or of an
   !> *AMPLITUDE table used by a *LOAD (the steps skip its points); an OUTPUT INTERVAL
   !> that writes fewer than min_frames_per_period frames a shortest harmonic period (the
   !> results miss the extremes of the motion). The run goes on.
   function dynamic_warnings(deck, model) result(text)
      type(deck_t), intent(in) :: deck      !< all cards
      type(model_t), intent(in) :: model    !< the validated model
      character(len=:), allocatable :: text !< the warning lines
      real(wp) :: dt, out, period, sampling
      integer :: ic, idyn, j, im, ia
      character(len=:), allocatable :: dt_at, out_at, what, shortest
      text = ''
      if (.not. model%dynamic%requested) return
      idyn = last_card(deck, 'DYNAMIC')
      if (idyn == 0) return
      dt = model%dynamic%dt
      out = model%dynamic%output_interval
      dt_at = param_at(deck%cards(idyn), 'DT')
      out_at = param_at(deck%cards(idyn), 'OUTPUT INTERVAL')
      ! the shortest harmonic period, and where
      period = huge(1.0_wp)
      shortest = ''
      im = 0
      do ic = 1, deck%n_cards
         if (deck%cards(ic)%keyword /= 'MOTION') cycle
         im = im + 1
         if (im > size(model%motions)) exit
         associate (mo => model%motions(im), card => deck%cards(ic))
            if (mo%kind == motion_harmonic) then
               do j = 1, 3
                  if (.not. (mo%frequency(j) > 0.0_wp .and. mo%amplitude(j) /= 0.0_wp)) cycle
                  if (1.0_wp/mo%frequency(j) < period) then
                     period = 1.0_wp/mo%frequency(j)
                     shortest = 'the motion at '//real_str(mo%frequency(j))//' Hz (*MOTION'// &
                                ' at '//card%file//':'//int_str(card%line)//')'
                  end if
               end do
            else if (mo%kind == motion_vessel .and. mo%vessel > 0) then
               associate (ve => model%vessels(mo%vessel))
                  if (allocated(ve%time)) then
                     if (size(ve%time) >= 2) then
                        sampling = minval(ve%time(2:) - ve%time(:size(ve%time) - 1))
                        what = 'the motion table '//ve%file//' of *VESSEL '// &
                               trim(ve%name)//' (*MOTION at '//card%file//':'// &
                               int_str(card%line)//')'
                        call check_sampling(sampling, what)
                     end if
                  end if
               end associate
            else if (allocated(mo%time)) then
               if (size(mo%time) >= 2) then
                  sampling = minval(mo%time(2:) - mo%time(:size(mo%time) - 1))
                  what = 'the *MOTION table '//mo%file//' (*MOTION at '//card%file//':'// &
                         int_str(card%line)//')'
                  call check_sampling(sampling, what)
               end if
            end if
         end associate
      end do
      ia = 0
      do ic = 1, deck%n_cards
         if (deck%cards(ic)%keyword /= 'AMPLITUDE') cycle
         ia = ia + 1
         if (ia > size(model%amplitudes)) exit
         if (.not. allocated(model%loads)) exit
         if (.not. any(model%loads%amplitude == ia)) cycle
         associate (amp => model%amplitudes(ia), card => deck%cards(ic))
            if (size(amp%time) < 2) cycle
            sampling = minval(amp%time(2:) - amp%time(:size(amp%time) - 1))
            what = 'the *AMPLITUDE '//trim(amp%name)//' (at '//card%file//':'// &
                   int_str(card%line)//'), used by a *LOAD'
            call check_sampling(sampling, what)
         end associate
      end do
      if (len(shortest) == 0) return
      if (dt > period/min_steps_per_period) then
         text = text//dt_at//': warning: *DYNAMIC: DT='//real_str(dt)//' s is not well '// &
                'below the period of '//shortest//', '//num3(period)//' s: '// &
                num3(period/dt)//' steps a period, fewer than '// &
                num3(min_steps_per_period)//' (at 2 or fewer the motion is aliased '// &
                'away); take DT <= '//num3_down(period/min_steps_per_period)//' s'//lf
      else if (out > 0.0_wp .and. out > period/min_frames_per_period) then
         text = text//out_at//': warning: *DYNAMIC: OUTPUT INTERVAL='//real_str(out)// &
                ' s writes '//num3(period/out)//' frames a period of '//shortest// &
                ', fewer than '//num3(min_frames_per_period)//': the results miss '// &
                'the extremes of the motion; take OUTPUT INTERVAL <= '// &
                num3_down(period/min_frames_per_period)//' s'//lf
      end if
   contains
      !> Warn when DT is longer than a table's sampling interval.
      subroutine check_sampling(dtab, name)
         real(wp), intent(in) :: dtab          !< shortest interval between rows [s]
         character(len=*), intent(in) :: name  !< the table, for the message
         if (.not. dt > dtab*(1.0_wp + 1.0e-9_wp)) return
         text = text//dt_at//': warning: *DYNAMIC: DT='//real_str(dt)//' s is longer '// &
                'than the sampling interval of '//name//', '//num3(dtab)//' s: the '// &
                'steps skip its points; take DT <= '//num3_down(dtab*(1.0_wp + 1.0e-9_wp))// &
                ' s'//lf
      end subroutine check_sampling
   end function dynamic_warnings

   !> A positive number with 3 significant digits, for a message: '3.04', '0.152'.
   pure function num3(x) result(t)
      real(wp), intent(in) :: x           !< the number
      character(len=:), allocatable :: t  !< its text
      character(len=32) :: b, f
      integer :: d
      d = 2 - floor(log10(max(abs(x), tiny(x))))
      if (d < 0 .or. d > 9) then
         write (b, '(es9.2)') x
      else
         write (f, '(a,i0,a)') '(f0.', d, ')'
         write (b, f) x
      end if
      t = trim(adjustl(b))
      if (index(t, '.') > 0 .and. index(t, 'E') == 0) then
         do while (t(len(t):len(t)) == '0')
            t = t(:len(t) - 1)
         end do
         if (t(len(t):len(t)) == '.') t = t(:len(t) - 1)
      end if
      if (t(1:1) == '.') t = '0'//t
   end function num3

   !> A positive number rounded down to 3 significant digits (a bound to stay below).
   pure function num3_down(x) result(t)
      real(wp), intent(in) :: x           !< the number, > 0
      character(len=:), allocatable :: t  !< its text
      real(wp) :: scale
      scale = 10.0_wp**(floor(log10(x)) - 2)
      t = num3(floor(x/scale)*scale)
   end function num3_down

   !> 'FILE:LINE' of parameter `name` of a card (the keyword line's if not given).
   pure function param_at(card, name) result(at)
      type(card_t), intent(in) :: card     !< the card
      character(len=*), intent(in) :: name !< parameter name
      character(len=:), allocatable :: at  !< location
      integer :: ip
      ip = card_find_param(card, name)
      if (ip > 0) then
         at = card%file//':'//int_str(card%params(ip)%line)
      else
         at = card%file//':'//int_str(card%line)
      end if
   end function param_at

end module rodyn_deck_dynamic_warnings
