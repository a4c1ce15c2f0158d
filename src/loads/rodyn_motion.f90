!> Time functions of a dynamic run: prescribed motions of held nodes (harmonic per
!> direction or a displacement table, times a smooth ramp-in) and load amplitudes.
module rodyn_motion
   use rodyn_kinds, only: wp, pi, two_pi
   use rodyn_model, only: motion_t, amplitude_t, motion_harmonic, motion_table
   implicit none
   private
   public :: motion_displacement, amplitude_value, ramp_factor

contains

   !> Ramp-in r(t) = (1 - cos(pi t / T))/2 for t < T, 1 after; r = 1 when T = 0.
   !> r(0) = r'(0) = 0, so a motion multiplied by it starts from rest.
   pure real(wp) function ramp_factor(t, ramp)
      real(wp), intent(in) :: t     !< time [s]
      real(wp), intent(in) :: ramp  !< ramp duration T [s]
      if (ramp <= 0.0_wp .or. t >= ramp) then
         ramp_factor = 1.0_wp
      else if (t <= 0.0_wp) then
         ramp_factor = 0.0_wp
      else
         ramp_factor = 0.5_wp*(1.0_wp - cos(pi*t/ramp))
      end if
   end function ramp_factor

   !> Displacement of a moved node at time t, from its position at t = 0 [m].
   pure function motion_displacement(mo, t) result(u)
      type(motion_t), intent(in) :: mo !< motion
      real(wp), intent(in) :: t        !< time [s]
      real(wp) :: u(3)
      integer :: j
      select case (mo%kind)
      case (motion_harmonic)
         do j = 1, 3
            u(j) = mo%amplitude(j)*sin(two_pi*mo%frequency(j)*t + mo%phase(j))
         end do
      case (motion_table)
         do j = 1, 3
            u(j) = interpolate(mo%time, mo%disp(j, :), t)
         end do
      case default
         u = 0.0_wp
      end select
      u = ramp_factor(t, mo%ramp)*u
   end function motion_displacement

   !> Value of an amplitude at time t (linear interpolation, constant beyond the ends).
   pure real(wp) function amplitude_value(amp, t)
      type(amplitude_t), intent(in) :: amp !< amplitude table
      real(wp), intent(in) :: t            !< time [s]
      amplitude_value = interpolate(amp%time, amp%value, t)
   end function amplitude_value

   !> Piecewise-linear interpolation in (tt, yy), constant beyond the ends.
   pure real(wp) function interpolate(tt, yy, t)
      real(wp), intent(in) :: tt(:) !< increasing abscissae
      real(wp), intent(in) :: yy(:) !< values
      real(wp), intent(in) :: t     !< where
      integer :: lo, hi, mid
      if (t <= tt(1)) then
         interpolate = yy(1)
         return
      end if
      if (t >= tt(size(tt))) then
         interpolate = yy(size(tt))
         return
      end if
      lo = 1
      hi = size(tt)
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         if (tt(mid) <= t) then
            lo = mid
         else
            hi = mid
         end if
      end do
      interpolate = yy(lo) + (yy(hi) - yy(lo))*(t - tt(lo))/(tt(hi) - tt(lo))
   end function interpolate
end module rodyn_motion
