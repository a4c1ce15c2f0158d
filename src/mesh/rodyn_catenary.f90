!> Elastic catenary of a line hanging between two points (Irvine, "Cable Structures",
!> MIT Press 1981, section 2.2), with S the unstretched arc length from end A:
!>   X(S) = H S/EA + (H/w) [asinh(V(S)/H) - asinh(V0/H)]
!>   Z(S) = (V0 S + w S^2/2)/EA + (H/w) [sqrt(1 + (V(S)/H)^2) - sqrt(1 + (V0/H)^2)]
!>   V(S) = V0 + w S,  T(S) = sqrt(H^2 + V(S)^2)
!> X is horizontal (along the span), Z upwards (against gravity); H is the horizontal
!> tension and V0 the vertical tension component at A (positive upwards along the line).
!> Used to start a line held at both ends (docs/theory.md eqs. (112)-(115): a start free
!> of the zero-tension singularity) and
!> as the reference solution of the catenary verification test.
!>
!> With a grounded length (catenary_grounded): the lower end A lies on a horizontal
!> seabed, without friction, the line lies on it from A to S = L_B and hangs above
!> (Jonkman, NREL/TP-500-47535, 2009, eq. 2-2 with C_B = 0; MoorPy's catenary):
!>   X_F = L_B + (H/w) asinh(V_F/H) + H L/EA,   L_B = L - V_F/w
!>   Z_F = (H/w) [sqrt(1 + (V_F/H)^2) - 1] + V_F^2/(2 EA w)
!> with V_F the vertical tension at B; the grounded part carries T = H.
module rodyn_catenary
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, set_error, stat_numerical
   implicit none
   private
   public :: catenary_t, catenary_solve, catenary_point, catenary_grounded

   !> A solved catenary.
   type :: catenary_t
      real(wp) :: w = 0.0_wp     !< weight per unstretched length [N/m]
      real(wp) :: ea = 0.0_wp    !< axial stiffness [N]
      real(wp) :: length = 0.0_wp !< unstretched length [m]
      real(wp) :: h = 0.0_wp     !< horizontal tension [N]
      real(wp) :: v0 = 0.0_wp    !< vertical tension component at A [N]
      real(wp) :: lb = 0.0_wp    !< grounded length from A (catenary_grounded) [m]
   end type catenary_t

contains

   !> Span X(L) and rise Z(L) for given H, V0, and their Jacobian.
   !> docs/theory.md eq. (112).
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
   !> docs/theory.md eqs. (112)-(114).
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
         if (res <= 1.0e-13_wp*hanging_length(cat)) return
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
      if (res <= 1.0e-10_wp*hanging_length(cat)) return
      if (hanging_length(cat) < huge(1.0_wp) .and. res < huge(1.0_wp)) then
         write (msg, '(a,es10.3,a,es10.3,a)') 'the starting catenary does not converge '// &
            '(end misfit ', res, ' m on a hanging length of ', hanging_length(cat), ' m)'
      else
         write (msg, '(a,es11.3e3,a,es11.3e3,a)') 'the starting catenary does not '// &
            'converge (its tensions overflow or underflow: weight ', w, ' N/m, EA ', ea, ' N)'
      end if
      call set_error(err, stat_numerical, trim(msg))
   end subroutine catenary_solve

   !> Length of the line as it hangs, stretched by its largest tension: L (1 + T_max/EA),
   !> the scale of the end misfit's round-off (a line of tiny EA stretches to many times
   !> its unstretched length, and the misfit with it). Infinite when EA underflows it.
   pure real(wp) function hanging_length(cat) result(ls)
      type(catenary_t), intent(in) :: cat !< catenary with trial h, v0
      real(wp) :: tmax
      tmax = max(hypot(cat%h, cat%v0), hypot(cat%h, cat%v0 + cat%w*cat%length))
      ls = cat%length + cat%length*(tmax/cat%ea)
   end function hanging_length

   !> Position (X, Z) and unit tangent (tX, tZ) at unstretched arc length s; tension.
   !> With a grounded length lb > 0 (v0 = 0): on the seabed for s <= lb, stretched by H.
   !> docs/theory.md eqs. (112)-(113).
   pure subroutine catenary_point(cat, s, xz, tangent, tension)
      type(catenary_t), intent(in) :: cat  !< solved catenary
      real(wp), intent(in) :: s            !< unstretched arc length from A [m]
      real(wp), intent(out) :: xz(2)       !< (X, Z) relative to A [m]
      real(wp), intent(out) :: tangent(2)  !< unit tangent [-]
      real(wp), intent(out) :: tension     !< effective tension T(s) [N]
      real(wp) :: vs, h, w, ss, x0
      h = cat%h
      w = cat%w
      ss = s - cat%lb
      x0 = 0.0_wp
      if (cat%lb > 0.0_wp) then
         x0 = min(s, cat%lb)*(1.0_wp + h/cat%ea)
         if (ss <= 0.0_wp) then
            xz = [x0, 0.0_wp]
            tangent = [1.0_wp, 0.0_wp]
            tension = h
            return
         end if
      else
         ss = s
      end if
      vs = cat%v0 + w*ss
      xz(1) = x0 + h*ss/cat%ea + h/w*(asinh(vs/h) - asinh(cat%v0/h))
      xz(2) = (cat%v0*ss + 0.5_wp*w*ss**2)/cat%ea &
              + (sqrt(h**2 + vs**2) - sqrt(h**2 + cat%v0**2))/w
      tension = sqrt(h**2 + vs**2)
      tangent = [h, vs]/tension
   end subroutine catenary_point

   !> The catenary with a grounded length (module header): H and V_F such that end B
   !> sits at span xs > 0 and height zs > 0 above end A on the seabed. ok is false when
   !> the line does not touch (V_F > w L: the free catenary applies) or no solution.
   !> docs/theory.md eq. (115).
   subroutine catenary_grounded(w, ea, length, xs, zs, cat, ok)
      real(wp), intent(in) :: w            !< submerged weight per unstretched length [N/m]
      real(wp), intent(in) :: ea           !< axial stiffness [N]
      real(wp), intent(in) :: length       !< unstretched length [m]
      real(wp), intent(in) :: xs           !< horizontal span of B from A, > 0 [m]
      real(wp), intent(in) :: zs           !< height of B above A, > 0 [m]
      type(catenary_t), intent(out) :: cat !< solution (v0 = 0, lb the grounded length)
      logical, intent(out) :: ok           !< a grounded solution was found
      real(wp) :: h, v, f(2), j(2, 2), det, dh, dv, res, res_new, a, h1, v1
      integer :: it, ls
      ok = .false.
      cat%w = w
      cat%ea = ea
      cat%length = length
      ! start: inextensible hanging part with H = w zs
      h = w*zs
      v = min(w*sqrt(3.0_wp)*zs, 0.9_wp*w*length)
      call residual(h, v, f, j)
      res = norm2(f)
      do it = 1, 200
         if (res <= 1.0e-13_wp*length) exit
         det = j(1, 1)*j(2, 2) - j(1, 2)*j(2, 1)
         dh = -(j(2, 2)*f(1) - j(1, 2)*f(2))/det
         dv = -(-j(2, 1)*f(1) + j(1, 1)*f(2))/det
         a = 1.0_wp
         do ls = 1, 60
            h1 = h + a*dh
            v1 = v + a*dv
            if (h1 > 0.0_wp .and. v1 > 0.0_wp) then
               call residual(h1, v1, f, j)
               res_new = norm2(f)
               if (res_new < res) exit
            end if
            a = 0.5_wp*a
         end do
         if (ls > 60) exit
         h = h1
         v = v1
         res = res_new
      end do
      if (res > 1.0e-9_wp*length .or. v > w*length) return
      cat%h = h
      cat%v0 = 0.0_wp
      cat%lb = length - v/w
      ok = .true.
   contains
      !> Misfit of the end (Jonkman's equations) and its Jacobian in (H, V_F).
      pure subroutine residual(hh, vv, r, jac)
         real(wp), intent(in) :: hh, vv
         real(wp), intent(out) :: r(2), jac(2, 2)
         real(wp) :: u, q
         u = vv/hh
         q = sqrt(1.0_wp + u**2)
         r(1) = length - vv/w + hh/w*asinh(u) + hh*length/ea - xs
         r(2) = hh/w*(q - 1.0_wp) + vv**2/(2.0_wp*ea*w) - zs
         jac(1, 1) = asinh(u)/w - u/(w*q) + length/ea
         jac(1, 2) = -1.0_wp/w + 1.0_wp/(w*q)
         jac(2, 1) = (q - 1.0_wp)/w - u**2/(w*q)
         jac(2, 2) = u/(w*q) + vv/(ea*w)
      end subroutine residual
   end subroutine catenary_grounded
end module rodyn_catenary
