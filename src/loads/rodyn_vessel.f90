!> Rigid-body motion of a vessel and of points fixed to it (docs/vessels.md;
!> docs/theory.md eqs. (99)-(101)).
!>
!> Vessel axes: origin at the vessel's reference point (the RAO origin and RAO phase
!> origin), x forward, y to port, z up; at rest the reference point is at O (global) and
!> the vessel is turned by its heading psi0 about global z: R0 = Rz(psi0).
!>
!> Motion: xi = (surge, sway, heave [m], roll, pitch, yaw [rad]) of the reference point,
!> in vessel axes. A point p given in vessel axes is at
!>   X(t) = O + R0 (xi_1:3 + Rv(xi_4:6) p),   Rv = Rz(yaw) Ry(pitch) Rx(roll),
!> the rotations composed exactly (roll about the vessel's x axis first, then pitch about
!> y, then yaw about z, all fixed axes; equivalently yaw, pitch', roll'' about the
!> turning ones), never added as small angles.
!>
!> First-order motion from displacement RAOs, for wave components j whose elevation at
!> O is eta_j(t) = a_j cos(omega_j t + phi_j), travelling towards beta_j (global, from x
!> towards y), relative to the vessel gamma_j = beta_j - psi0 (0: following waves from the
!> stern, 180 deg: head seas):
!>   xi_k(t) = Re sum_j a_j H_k(omega_j, gamma_j) exp(i (omega_j t + phi_j)),
!> H_k the complex RAO per unit wave amplitude. From amplitude R_k and phase eps_k of a
!> table, H_k = R_k exp(-i eps_k) when the phase is a lag (the response peaks eps_k after
!> the crest passes O; OrcaFlex and Flexcom write lags) and R_k exp(+i eps_k) when it is a
!> lead. The complex factors c_kj = a_j H_k exp(i phi_j) are formed once
!> (vessel_coefficients), so that a time costs one cosine and sine per component.
!>
!> Interpolation of the table: bilinear in wave period and relative heading (headings
!> periodic over 360 deg) on the complex values (COMPLEX, the default) or on amplitude and
!> phase, the phase along the shorter arc (POLAR). Outside the table's periods the RAO
!> is zero (as Flexcom takes it): a component there does not move the vessel.
module rodyn_vessel
   use rodyn_kinds, only: wp, pi, two_pi
   use rodyn_model, only: vessel_rao_t, rao_interp_complex
   implicit none
   private
   public :: vessel_rotation, vessel_rao_value, vessel_coefficients, vessel_harmonic_motion
   public :: vessel_point_position, vessel_local_point


contains

   !> Rv = Rz(yaw) Ry(pitch) Rx(roll) (module header): the rotation of vessel axes.
   !> docs/theory.md eq. (99).
   pure function vessel_rotation(angles) result(r)
      real(wp), intent(in) :: angles(3) !< roll, pitch, yaw [rad]
      real(wp) :: r(3, 3)
      real(wp) :: cr, sr, cp, sp, cy, sy
      cr = cos(angles(1))
      sr = sin(angles(1))
      cp = cos(angles(2))
      sp = sin(angles(2))
      cy = cos(angles(3))
      sy = sin(angles(3))
      r(1, :) = [cy*cp, cy*sp*sr - sy*cr, cy*sp*cr + sy*sr]
      r(2, :) = [sy*cp, sy*sp*sr + cy*cr, sy*sp*cr - cy*sr]
      r(3, :) = [-sp, cp*sr, cp*cr]
   end function vessel_rotation

   !> X = O + R0 (xi_1:3 + Rv(xi_4:6) p) (module header).
   !> docs/theory.md eq. (99).
   pure function vessel_point_position(origin, psi0, xi, p) result(x)
      real(wp), intent(in) :: origin(3) !< reference point at rest, global [m]
      real(wp), intent(in) :: psi0      !< heading of the vessel at rest [rad]
      real(wp), intent(in) :: xi(6)     !< motion of the reference point [m, rad]
      real(wp), intent(in) :: p(3)      !< point in vessel axes [m]
      real(wp) :: x(3)
      real(wp) :: v(3)
      v = xi(1:3) + matmul(vessel_rotation(xi(4:6)), p)
      x(1) = origin(1) + cos(psi0)*v(1) - sin(psi0)*v(2)
      x(2) = origin(2) + sin(psi0)*v(1) + cos(psi0)*v(2)
      x(3) = origin(3) + v(3)
   end function vessel_point_position

   !> p = R0^T (x - O): the point of vessel axes at x when the vessel is at rest.
   pure function vessel_local_point(origin, psi0, x) result(p)
      real(wp), intent(in) :: origin(3) !< reference point at rest, global [m]
      real(wp), intent(in) :: psi0      !< heading of the vessel at rest [rad]
      real(wp), intent(in) :: x(3)      !< global position [m]
      real(wp) :: p(3)
      p(1) = cos(psi0)*(x(1) - origin(1)) + sin(psi0)*(x(2) - origin(2))
      p(2) = -sin(psi0)*(x(1) - origin(1)) + cos(psi0)*(x(2) - origin(2))
      p(3) = x(3) - origin(3)
   end function vessel_local_point

   !> H_k(T, gamma), k = 1..6: the table interpolated bilinearly in period T and relative
   !> heading gamma (periodic); zero outside the table's periods.
   !> docs/theory.md eq. (100).
   pure function vessel_rao_value(rao, period, gamma) result(h)
      type(vessel_rao_t), intent(in) :: rao !< table
      real(wp), intent(in) :: period        !< wave period [s]
      real(wp), intent(in) :: gamma         !< heading relative to the vessel [rad]
      complex(wp) :: h(6)
      integer :: i0, i1, j0, j1, nh, np
      real(wp) :: u, w, g
      complex(wp) :: h0(6), h1(6)
      real(wp) :: tp
      np = size(rao%period)
      nh = size(rao%heading)
      h = (0.0_wp, 0.0_wp)
      ! (the ends within round-off belong to the table: 2 pi / (2 pi / T) need not be T)
      if (period < rao%period(1)*(1.0_wp - 1.0e-12_wp) .or. &
          period > rao%period(np)*(1.0_wp + 1.0e-12_wp)) return
      tp = min(max(period, rao%period(1)), rao%period(np))
      ! period bracket [i0, i1], weight u of i1
      i0 = 1
      do while (i0 < np - 1 .and. tp > rao%period(min(i0 + 1, np)))
         i0 = i0 + 1
      end do
      i1 = min(i0 + 1, np)
      u = 0.0_wp
      if (i1 > i0) u = (tp - rao%period(i0))/(rao%period(i1) - rao%period(i0))
      ! heading bracket [j0, j1] on the circle, weight w of j1
      g = modulo(gamma, two_pi)
      if (nh == 1) then
         j0 = 1
         j1 = 1
         w = 0.0_wp
      else if (g < rao%heading(1) .or. g >= rao%heading(nh)) then
         j0 = nh            ! the gap across 360 deg
         j1 = 1
         w = modulo(g - rao%heading(nh), two_pi)/ &
             modulo(rao%heading(1) - rao%heading(nh), two_pi)
      else
         j0 = 1
         do while (g >= rao%heading(j0 + 1))
            j0 = j0 + 1
         end do
         j1 = j0 + 1
         w = (g - rao%heading(j0))/(rao%heading(j1) - rao%heading(j0))
      end if
      h0 = blend(rao%h(:, i0, j0), rao%h(:, i1, j0), u)
      h1 = blend(rao%h(:, i0, j1), rao%h(:, i1, j1), u)
      h = blend(h0, h1, w)
   contains
      !> (1 - t) a + t b, on the complex values or on amplitude and (shorter-arc) phase.
      pure function blend(a, b, t) result(c)
         complex(wp), intent(in) :: a(6), b(6)
         real(wp), intent(in) :: t
         complex(wp) :: c(6)
         real(wp) :: ra, rb, pa, dp
         integer :: k
         if (rao%interp == rao_interp_complex) then
            c = (1.0_wp - t)*a + t*b
            return
         end if
         do k = 1, 6
            ra = abs(a(k))
            rb = abs(b(k))
            pa = atan2(aimag(a(k)), real(a(k), wp))
            dp = modulo(atan2(aimag(b(k)), real(b(k), wp)) - pa + pi, two_pi) - pi
            c(k) = ((1.0_wp - t)*ra + t*rb)*exp(cmplx(0.0_wp, pa + t*dp, wp))
         end do
      end function blend
   end function vessel_rao_value

   !> c_kj = a_j H_k(2 pi / omega_j, beta_j - psi0) exp(i phi_j) (module header).
   !> docs/theory.md eq. (100).
   pure subroutine vessel_coefficients(rao, psi0, amp, omega, beta, phi, c)
      type(vessel_rao_t), intent(in) :: rao  !< displacement RAOs
      real(wp), intent(in) :: psi0           !< vessel heading at rest [rad]
      real(wp), intent(in) :: amp(:)         !< (nc) wave amplitudes a_j [m]
      real(wp), intent(in) :: omega(:)       !< (nc) angular frequencies [rad/s]
      real(wp), intent(in) :: beta(:)        !< (nc) directions of travel, global [rad]
      real(wp), intent(in) :: phi(:)         !< (nc) phases of the elevation at O [rad]
      complex(wp), intent(out) :: c(:, :)    !< (6, nc) complex response factors [m, rad]
      integer :: j
      do j = 1, size(amp)
         c(:, j) = amp(j)*vessel_rao_value(rao, two_pi/omega(j), beta(j) - psi0)* &
                   exp(cmplx(0.0_wp, phi(j), wp))
      end do
   end subroutine vessel_coefficients

   !> xi_k(t) = Re sum_j c_kj exp(i omega_j t) (module header).
   !> docs/theory.md eq. (100).
   pure function vessel_harmonic_motion(c, omega, t) result(xi)
      complex(wp), intent(in) :: c(:, :)  !< (6, nc) vessel_coefficients
      real(wp), intent(in) :: omega(:)    !< (nc) angular frequencies [rad/s]
      real(wp), intent(in) :: t           !< time [s]
      real(wp) :: xi(6)
      real(wp) :: cs, sn
      integer :: j
      xi = 0.0_wp
      do j = 1, size(omega)
         cs = cos(omega(j)*t)
         sn = sin(omega(j)*t)
         xi = xi + real(c(:, j), wp)*cs - aimag(c(:, j))*sn
      end do
   end function vessel_harmonic_motion
end module rodyn_vessel
