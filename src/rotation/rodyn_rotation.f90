!> Rotation algebra on SO(3): skew matrices, the Cayley transform used for the
!> director updates, its inverse and tangent map, and the exponential map used to build
!> curved stress-free shapes (docs/theory.md section 3, eqs. (13)-(18)).
!>
!> Conventions: a rotation vector t is the spatial (left) increment, R_new = cay(t) R.
!> cay(t) = I + 4/(4 + t.t) (T + T^2/2), T = skew(t), which rotates by 2 atan(|t|/2)
!> about t/|t|.
module rodyn_rotation
   use rodyn_kinds, only: wp
   implicit none
   private
   public :: skew, axial, rotation_cayley, rotation_cayley_inverse
   public :: rotation_cayley_tangent, rotation_exp, rotation_log, rotation_frame
   public :: cross, norm3, relative_rotation

contains

   !> Cross product a x b.
   pure function cross(a, b) result(c)
      real(wp), intent(in) :: a(3) !< first vector
      real(wp), intent(in) :: b(3) !< second vector
      real(wp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross

   !> Skew-symmetric matrix: skew(v) w = v x w.
   !> docs/theory.md eq. (13).
   pure function skew(v) result(s)
      real(wp), intent(in) :: v(3) !< axial vector
      real(wp) :: s(3, 3)
      s(:, 1) = [0.0_wp, v(3), -v(2)]
      s(:, 2) = [-v(3), 0.0_wp, v(1)]
      s(:, 3) = [v(2), -v(1), 0.0_wp]
   end function skew

   !> Axial vector of the skew-symmetric part: axial(A) = vee((A - A^T)/2).
   !> docs/theory.md eq. (13).
   pure function axial(a) result(v)
      real(wp), intent(in) :: a(3, 3) !< any 3x3 matrix
      real(wp) :: v(3)
      v = 0.5_wp*[a(3, 2) - a(2, 3), a(1, 3) - a(3, 1), a(2, 1) - a(1, 2)]
   end function axial

   !> Cayley transform cay(t) = I + 4/(4 + t.t) (T + T^2/2) (docs/theory.md eqs. (14)-(15)).
   pure function rotation_cayley(t) result(r)
      real(wp), intent(in) :: t(3) !< rotation vector, |t| = 2 tan(angle/2) [-]
      real(wp) :: r(3, 3)
      real(wp) :: c, tt, h
      integer :: i, j
      ! skew(t)^2 = t t^T - |t|^2 I: r = I + c (skew(t) + (t t^T - |t|^2 I)/2)
      tt = dot_product(t, t)
      c = 4.0_wp/(4.0_wp + tt)
      h = 0.5_wp*c
      do j = 1, 3
         do i = 1, 3
            r(i, j) = h*t(i)*t(j)
         end do
         r(j, j) = r(j, j) + (1.0_wp - h*tt)
      end do
      r(2, 1) = r(2, 1) + c*t(3)
      r(1, 2) = r(1, 2) - c*t(3)
      r(3, 1) = r(3, 1) - c*t(2)
      r(1, 3) = r(1, 3) + c*t(2)
      r(3, 2) = r(3, 2) + c*t(1)
      r(2, 3) = r(2, 3) - c*t(1)
   end function rotation_cayley

   !> The rotation R = D1 D0^T that turns the directors D0 (columns) into D1. (Explicit
   !> products: matmul(d1, transpose(d0)) on array sections made heap temporaries in
   !> the time loop.)
   pure function relative_rotation(d1, d0) result(r)
      real(wp), intent(in) :: d1(3, 3) !< directors after, d1(:, i) = d_i
      real(wp), intent(in) :: d0(3, 3) !< directors before
      real(wp) :: r(3, 3)
      integer :: i, j
      do j = 1, 3
         do i = 1, 3
            r(i, j) = d1(i, 1)*d0(j, 1) + d1(i, 2)*d0(j, 2) + d1(i, 3)*d0(j, 3)
         end do
      end do
   end function relative_rotation

   !> Inverse Cayley transform: t with cay(t) = R, t = 4 axial(R) / (1 + tr R) (eq. (16)).
   !> Defined for rotation angles below pi.
   pure function rotation_cayley_inverse(r) result(t)
      real(wp), intent(in) :: r(3, 3) !< rotation matrix
      real(wp) :: t(3)
      t = 4.0_wp*axial(r)/(1.0_wp + r(1, 1) + r(2, 2) + r(3, 3))
   end function rotation_cayley_inverse

   !> Tangent map of the Cayley transform (docs/theory.md eq. (17)): the spatial angular
   !> increment dw with
   !> cay(t + dt) = cay(dw) cay(t) to first order is dw = H(t) dt,
   !> H(t) = 4/(4 + t.t) (I + skew(t)/2).
   pure function rotation_cayley_tangent(t) result(h)
      real(wp), intent(in) :: t(3) !< rotation vector [-]
      real(wp) :: h(3, 3)
      integer :: i
      h = 0.5_wp*skew(t)
      do i = 1, 3
         h(i, i) = h(i, i) + 1.0_wp
      end do
      h = 4.0_wp/(4.0_wp + dot_product(t, t))*h
   end function rotation_cayley_tangent

   !> Exponential map (Rodrigues, docs/theory.md eq. (18)): rotation by |phi| about phi/|phi|.
   pure function rotation_exp(phi) result(r)
      real(wp), intent(in) :: phi(3) !< rotation vector [rad]
      real(wp) :: r(3, 3)
      real(wp) :: s(3, 3), a, c1, c2
      integer :: i
      a = norm2(phi)
      s = skew(phi)
      if (a < 1.0e-4_wp) then
         c1 = 1.0_wp - a**2/6.0_wp + a**4/120.0_wp
         c2 = 0.5_wp - a**2/24.0_wp + a**4/720.0_wp
      else
         c1 = sin(a)/a
         c2 = (1.0_wp - cos(a))/a**2
      end if
      r = c1*s + c2*matmul(s, s)
      do i = 1, 3
         r(i, i) = r(i, i) + 1.0_wp
      end do
   end function rotation_exp

   !> Logarithm of a rotation: phi with exp(phi) = R, |phi| in [0, pi].
   !> docs/theory.md eq. (18).
   pure function rotation_log(r) result(phi)
      real(wp), intent(in) :: r(3, 3) !< rotation matrix
      real(wp) :: phi(3)
      real(wp) :: c, a, v(3), b(3, 3)
      integer :: k
      c = min(1.0_wp, max(-1.0_wp, 0.5_wp*(r(1, 1) + r(2, 2) + r(3, 3) - 1.0_wp)))
      a = acos(c)
      v = axial(r)
      if (a < 1.0e-6_wp) then
         phi = v*(1.0_wp + a**2/6.0_wp)
      else if (a < 3.14_wp) then
         phi = v*a/sin(a)
      else
         ! near pi: axis from the symmetric part, sign from the skew part
         b = 0.5_wp*(r + transpose(r))
         do k = 1, 3
            b(k, k) = b(k, k) - c
         end do
         k = maxloc([b(1, 1), b(2, 2), b(3, 3)], dim=1)
         phi = b(:, k)/norm2(b(:, k))
         if (dot_product(phi, v) < 0.0_wp) phi = -phi
         phi = a*phi
      end if
   end function rotation_log

   !> Orthonormal frame [d1 d2 d3] with d3 along t and d1 as close as possible to the
   !> hint h (h must not be parallel to t).
   pure function rotation_frame(t, h) result(d)
      real(wp), intent(in) :: t(3) !< tangent direction (any length > 0)
      real(wp), intent(in) :: h(3) !< direction for d1 (projected normal to t)
      real(wp) :: d(3, 3)
      d(:, 3) = t/norm2(t)
      d(:, 1) = h - dot_product(h, d(:, 3))*d(:, 3)
      d(:, 1) = d(:, 1)/norm2(d(:, 1))
      d(:, 2) = cross(d(:, 3), d(:, 1))
   end function rotation_frame

   !> |v| of a 3-vector as sqrt(v.v). The vectors of rodyn's kernels (x', velocities,
   !> positions) are far from overflow, against which Fortran's norm2 guards at several
   !> times the cost (norm3 serves the water and cable kernels, called at every point).
   pure real(wp) function norm3(v)
      real(wp), intent(in) :: v(3) !< vector
      norm3 = sqrt(v(1)*v(1) + v(2)*v(2) + v(3)*v(3))
   end function norm3
end module rodyn_rotation
