!> The water around the lines (docs/water.md; docs/theory.md eqs. (80)-(81)): the
!> water's kinematics (the seabed plane is rodyn_seabed's). Everything a load needs to
!> know of the water at a point and time comes through fluid_kinematics, so that waves
!> only add to it.
!>
!> Current: speed U(z) and heading psi(z) linear between the levels of *CURRENT, constant
!> beyond them, u = r(t) U (cos psi, sin psi, 0), r(t) the ramp-in (1 - cos(pi t/T))/2
!> (statics is t = 0: no current when a ramp is given).
module rodyn_environment
   use rodyn_kinds, only: wp
   use rodyn_model, only: water_t
   use rodyn_motion, only: ramp_factor
   implicit none
   private
   public :: fluid_kinematics, current_factor

contains

   !> Ramp factor of the current at time t (1 without a ramp) [-].
   !> docs/theory.md eq. (81).
   pure real(wp) function current_factor(water, t)
      type(water_t), intent(in) :: water !< water
      real(wp), intent(in) :: t          !< time [s]
      current_factor = ramp_factor(t, water%cur_ramp)
   end function current_factor

   !> Velocity u and acceleration a of the water at point x and time t, and du/dx
   !> (u_i,j), for the Morison loads; r = current_factor(water, t) passed in.
   !> docs/theory.md eq. (80).
   pure subroutine fluid_kinematics(water, r, x, u, dudx, a)
      type(water_t), intent(in) :: water !< water (current profile)
      real(wp), intent(in) :: r          !< current ramp factor [-]
      real(wp), intent(in) :: x(3)       !< point [m]
      real(wp), intent(out) :: u(3)      !< water velocity [m/s]
      real(wp), intent(out) :: dudx(3, 3) !< du_i/dx_j [1/s]
      real(wp), intent(out) :: a(3)      !< water acceleration [m/s2]
      real(wp) :: sp, hd, dsp, dhd, f
      integer :: n, k
      u = 0.0_wp
      dudx = 0.0_wp
      a = 0.0_wp
      if (.not. allocated(water%cur_z)) return
      n = size(water%cur_z)
      if (n == 0 .or. r == 0.0_wp) return
      dsp = 0.0_wp
      dhd = 0.0_wp
      if (x(3) <= water%cur_z(1)) then
         sp = water%cur_speed(1)
         hd = water%cur_heading(1)
      else if (x(3) >= water%cur_z(n)) then
         sp = water%cur_speed(n)
         hd = water%cur_heading(n)
      else
         do k = 1, n - 1
            if (x(3) < water%cur_z(k + 1)) exit
         end do
         f = (x(3) - water%cur_z(k))/(water%cur_z(k + 1) - water%cur_z(k))
         dsp = (water%cur_speed(k + 1) - water%cur_speed(k))/(water%cur_z(k + 1) - water%cur_z(k))
         dhd = (water%cur_heading(k + 1) - water%cur_heading(k)) &
               /(water%cur_z(k + 1) - water%cur_z(k))
         sp = water%cur_speed(k) + f*(water%cur_speed(k + 1) - water%cur_speed(k))
         hd = water%cur_heading(k) + f*(water%cur_heading(k + 1) - water%cur_heading(k))
      end if
      u = r*sp*[cos(hd), sin(hd), 0.0_wp]
      dudx(:, 3) = r*(dsp*[cos(hd), sin(hd), 0.0_wp] + sp*dhd*[-sin(hd), cos(hd), 0.0_wp])
   end subroutine fluid_kinematics
end module rodyn_environment
