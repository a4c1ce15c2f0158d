!> Elastic catenary of a line hanging between two points (Irvine, "Cable Structures",
!> MIT Press 1981, section 2.2), with S the unstretched arc length from end A:
!>   X(S) = H S/EA + (H/w) [asinh(V(S)/H) - asinh(V0/H)]
!>   Z(S) = (V0 S + w S^2/2)/EA + (H/w) [sqrt(1 + (V(S)/H)^2) - sqrt(1 + (V0/H)^2)]
!>   V(S) = V0 + w S,  T(S) = sqrt(H^2 + V(S)^2)
!> X is horizontal (along the span), Z upwards (against gravity); H is the horizontal
!> tension and V0 the vertical tension component at A (positive upwards along the line).
!> Used to start a line held at both ends (note section 5, zero-tension singularity) and
!> as the reference solution of the catenary verification test.
module rodyn_catenary
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, set_error, stat_numerical
   implicit none
   private
   public :: catenary_t, catenary_solve, catenary_point

   !> A solved catenary.
   type :: catenary_t
      real(wp) :: w = 0.0_wp     !< weight per unstretched length [N/m]
      real(wp) :: ea = 0.0_wp    !< axial stiffness [N]
      real(wp) :: length = 0.0_wp !< unstretched length [m]
      real(wp) :: h = 0.0_wp     !< horizontal tension [N]
      real(wp) :: v0 = 0.0_wp    !< vertical tension component at A [N]
   end type catenary_t

contains

   !> Span X(L) and rise Z(L) for given H, V0, and their Jacobian.
   pure subroutine catenary_ends(cat, f, jac)
      type(catenary_t), intent(in) :: cat !< catenary with trial h, v0
      real(wp), intent(out) :: f(2)       !< (X(L), Z(L)) [m]
      real(wp), intent(out) :: jac(2, 2)  !< d f / d (H, V0) [m/N]
      real(wp) :: h, v0, v1, t0, t1, w, l
      h = cat%h
      v0 = cat%v0
      w = cat%w
      l = cat%length
      v1 = v0 + w*l
      t0 = sqrt(h**2 + v0**2)
      t1 = sqrt(h**2 + v1**2)
      f(1) = h*l/cat%ea + h/w*(asinh(v1/h) - asinh(v0/h))
      f(2) = (v0*l + 0.5_wp*w*l**2)/cat%ea + (t1 - t0)/w
      jac(1, 1) = l/cat%ea + (asinh(v1/h) - asinh(v0/h))/w - (v1/t1 - v0/t0)/w
      jac(1, 2) = h/w*(1.0_wp/t1 - 1.0_wp/t0)
      jac(2, 1) = h/w*(1.0_wp/t1 - 1.0_wp/t0)
      jac(2, 2) = l/cat%ea + (v1/t1 - v0/t0)/w
   end subroutine catenary_ends

   !> Solve for H and V0 so that end B sits at span xs > 0 and rise zs from end A.
   subroutine catenary_solve(w, ea, length, xs, zs, cat, err)
      real(wp), intent(in) :: w            !< weight per unstretched length, > 0 [N/m]
      real(wp), intent(in) :: ea           !< axial stiffness [N]
      real(wp), intent(in) :: length       !< unstretched length [m]
      real(wp), intent(in) :: xs           !< horizontal span of B from A, > 0 [m]
      real(wp), intent(in) :: zs           !< height of B above A [m]
      type(catenary_t), intent(out) :: cat !< solution
      type(error_t), intent(inout) :: err  !< status
      real(wp) :: f(2), jac(2, 2), dx(2), det, lam, res, res_new, alpha, h_old, v_old
      integer :: it, ls
      character(len=160) :: msg
      cat%w = w
      cat%ea = ea
      cat%length = length
      ! start: inextensible estimate (as in MoorDyn's catenary routine, Hall 2015)
      if (length**2 <= xs**2 + zs**2) then
         lam = 0.2_wp
      else
         lam = sqrt(3.0_wp*((length**2 - zs**2)/xs**2 - 1.0_wp))
      end if
      lam = min(lam, 1.0e3_wp)
      cat%h = max(abs(0.5_wp*w*xs/lam), 1.0e-6_wp*w*length)
      cat%v0 = 0.5_wp*w*(zs/tanh(lam) + length) - w*length
      call catenary_ends(cat, f, jac)
      res = norm2(f - [xs, zs])
      do it = 1, 200
         if (res <= 1.0e-13_wp*length) return
         det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
         dx(1) = -(jac(2, 2)*(f(1) - xs) - jac(1, 2)*(f(2) - zs))/det
         dx(2) = -(-jac(2, 1)*(f(1) - xs) + jac(1, 1)*(f(2) - zs))/det
         h_old = cat%h
         v_old = cat%v0
         alpha = 1.0_wp
         do ls = 1, 60
            cat%h = h_old + alpha*dx(1)
            cat%v0 = v_old + alpha*dx(2)
            if (cat%h > 0.0_wp) then
               call catenary_ends(cat, f, jac)
               res_new = norm2(f - [xs, zs])
               if (res_new < res) exit
            end if
            alpha = 0.5_wp*alpha
         end do
         if (ls > 60) exit
         res = res_new
      end do
      if (res <= 1.0e-10_wp*length) return
      write (msg, '(a,es10.3,a)') 'catenary_solve: no convergence (end misfit ', res, ' m)'
      call set_error(err, stat_numerical, trim(msg))
   end subroutine catenary_solve

   !> Position (X, Z) and unit tangent (tX, tZ) at unstretched arc length s; tension.
   pure subroutine catenary_point(cat, s, xz, tangent, tension)
      type(catenary_t), intent(in) :: cat  !< solved catenary
      real(wp), intent(in) :: s            !< unstretched arc length from A [m]
      real(wp), intent(out) :: xz(2)       !< (X, Z) relative to A [m]
      real(wp), intent(out) :: tangent(2)  !< unit tangent [-]
      real(wp), intent(out) :: tension     !< effective tension T(s) [N]
      real(wp) :: vs, h, w
      h = cat%h
      w = cat%w
      vs = cat%v0 + w*s
      xz(1) = h*s/cat%ea + h/w*(asinh(vs/h) - asinh(cat%v0/h))
      xz(2) = (cat%v0*s + 0.5_wp*w*s**2)/cat%ea &
              + (sqrt(h**2 + vs**2) - sqrt(h**2 + cat%v0**2))/w
      tension = sqrt(h**2 + vs**2)
      tangent = [h, vs]/tension
   end subroutine catenary_point
end module rodyn_catenary
