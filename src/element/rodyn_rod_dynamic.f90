!> Internal force of the director rod over a time step (docs/theory.md eqs. (35)-(36),
!> (44), (54)-(57)),
!> projected with the midpoint directors d^{n+1/2} = (d^n + d^{n+1})/2, and its tangent
!> with respect to the unknowns at n+1 (dx, dtheta; dd^{n+1} = dtheta x d^{n+1}):
!>   EMC          S = C ((eps(q^n) + eps(q^{n+1}))/2 - eps0), B at q^{n+1/2}
!>   MIDPOINT     S = C (eps(q^{n+1/2}) - eps0),                B at q^{n+1/2}
!>   TRAPEZOIDAL  f = (f(q^n) + f(q^{n+1}))/2
!>   ALPHA        S = C (eps(q_f) - eps0), B at q_f = (1 - w) q^n + w q^{n+1}, w = 1 - alpha_f
!>                (generalized-alpha; the projection uses the directors of q_f too)
!> With the EMC choice the work of the internal force over the step equals the change of
!> stored energy exactly (strains quadratic in q), the root of energy conservation.
!>
!> Stresses of the EMC tangent (argument xb, db: Newton's base, the iterate q^k that the
!> last correction started from). A correction is linear in q, the strains are not: an
!> iterate q^{k+1} carries besides the strain change B(q^k) dq the second-order part of
!> it, and with EA >> tension that part sets the stress: an early iterate's axial
!> strain can be orders of magnitude above the converged one. A tangent formed there
!> has stress terms far off, and the reused-tangent iterations after it contract
!> slowly. With the base given, every stress term of the tangent (the geometric
!> sums and the projection's q-forces) takes instead the stress of the strain linearized
!> from the base,
!>   eps_lin = eps(q^k) + B(q^k) (q^{k+1} - q^k)_lin = eps(q_l) - eps2(dq_l) (+ e3),
!>   q_l = q^k + dq_l,  dq_l = (x^{k+1} - x^k,  theta x d^k),  theta = cay^-1(d^{k+1} d^k^T),
!> with eps2 the strains' quadratic part of the increment fields alone (the strains are
!> bilinear in x', d_i, d_i'): S_lin = C ((eps(q^n) + eps_lin)/2 - eps0). This is the
!> stress Newton's iteration of the mixed (Hellinger-Reissner) form carries, the
!> point stresses being unknowns of their own: eliminated point by point, that
!> iteration has the same residual and the same material part as this one and differs
!> only in the stress of the stress terms. The converged step does not change (the
!> residual is untouched); only the iterates do, and in fewer iterations
!> (docs/theory.md eq. (44)).
module rodyn_rod_dynamic
   use rodyn_kinds, only: wp
   use rodyn_schemes, only: scheme_emc, scheme_midpoint, scheme_trapezoidal, scheme_alpha
   use rodyn_shape, only: max_nen
   use rodyn_rotation, only: skew, cross, rotation_cayley_inverse, relative_rotation
   use rodyn_rod_element, only: rod_gp_t, rod_gp_kinematics, rod_strains, rod_gp_qforce, &
                                rod_gp_jacobian_row, rod_project_qforce, &
                                rod_rotation_geometric, rod_rule_t, max_points, &
                                rod_gp_kinematics_shear, rod_strains_shear, &
                                rod_gp_qforce_shear
   implicit none
   private
   public :: rod_element_dynamic

contains

   !> Step internal force fe (6, p+1) and tangent ke of one element for a scheme.
   !> docs/theory.md eqs. (35), (44), (54)-(57).
   pure subroutine rod_element_dynamic(p, le, c, eps0, x0, d0, x1, d1, scheme, wf, fe, ke, &
                                       want_k, rule, gp0, epsn, xb, db, kd, off)
      integer, intent(in) :: p                    !< element order
      real(wp), intent(in) :: le                  !< unstretched element length [m]
      real(wp), intent(in) :: c(6)                !< diag(GA1,GA2,EA,EI1,EI2,GJ)
      real(wp), intent(in) :: eps0(6, max_points) !< stress-free strains
      real(wp), intent(in) :: x0(3, p + 1)        !< positions at t_n [m]
      real(wp), intent(in) :: d0(3, 3, p + 1)     !< directors at t_n
      real(wp), intent(in) :: x1(3, p + 1)        !< positions at t_n+1 [m]
      real(wp), intent(in) :: d1(3, 3, p + 1)     !< directors at t_n+1
      integer, intent(in) :: scheme               !< scheme_* constant
      real(wp), intent(in) :: wf                  !< ALPHA: weight of q^{n+1} in q_f [-]
      real(wp), intent(out) :: fe(6, p + 1)       !< projected internal force [N, N m]
      real(wp), intent(out) :: ke(:, :)           !< (6(p+1), 6(p+1)) tangent, if want_k
      logical, intent(in) :: want_k               !< form the tangent
      type(rod_rule_t), intent(in) :: rule        !< rod_rule(p): points, shape functions
      !> EMC, TRAPEZOIDAL: the fields and strains of q^n at the points (rod_element_fields),
      !> constant over a step; computed here if absent
      type(rod_gp_t), intent(in), optional :: gp0(max_points)
      real(wp), intent(in), optional :: epsn(6, max_points)
      !> EMC: Newton's base, the iterate that the last correction started from (header:
      !> the tangent's stresses are then those of the strains linearized from it)
      real(wp), intent(in), optional :: xb(3, p + 1), db(3, 3, p + 1)
      !> EMC with RHO INF < 1 (docs/theory.md eq. (126)): the numerical stress
      !> kd (eps^{n+1} - eps^n) - off at each point, kd = K0 (c1 + 2 c2) [N, N m2]
      real(wp), intent(in), optional :: kd(6), off(6, max_points)
      real(wp) :: n(max_nen), dn(max_nen), wj, cg(6), s(6), s1(6), e0(6), e1(6), cgt(6)
      ! the linearized increment from the base (dxl, ddl) and its end (x1, dl); the
      ! q-forces of the linearized stresses (fql), for the projection's tangent
      real(wp) :: dxl(3, max_nen), ddl(3, 3, max_nen), dl(3, 3, max_nen), fql(3, 4, max_nen)
      real(wp) :: sl(6)
      logical :: have0, lin
      real(wp) :: xm(3, max_nen), dm(3, 3, max_nen), fq(3, 4, max_nen)
      ! the material part's rows of all points: force strains (Gamma) in blt/cr(1:nf),
      ! curvatures (K: no x columns; blc holds the rotation entries only) in blc/crc(1:nc)
      real(wp) :: blt(6*max_nen, 3*max_points), cr(3*max_points, 6*max_nen)
      real(wp) :: blc(3*max_nen, 3*max_points), crc(3*max_points, 6*max_nen)
      integer :: nf, nc
      ! the stress (geometric) part of all points, per node pair (add_geometric)
      real(wp) :: pg(3, max_nen, max_nen), mg(3, max_nen, max_nen)
      type(rod_gp_t) :: k0, k1, km
      real(wp) :: wq, sh(2), sh1(2)
      integer :: g, nen, nd, np
      nen = p + 1
      nd = 6*nen
      have0 = present(gp0) .and. present(epsn)
      ! evaluation point: the midpoint, or q_f for the generalized-alpha scheme
      wq = 0.5_wp
      if (scheme == scheme_alpha) wq = wf
      xm(:, 1:nen) = (1.0_wp - wq)*x0 + wq*x1
      dm(:, :, 1:nen) = (1.0_wp - wq)*d0 + wq*d1
      np = rule%np
      fq(:, :, 1:nen) = 0.0_wp
      lin = want_k .and. present(xb) .and. present(db) .and. scheme == scheme_emc
      if (lin) then
         call linear_increment(nen, x1, d1, xb, db, dxl, ddl, dl, lin)
         fql(:, :, 1:nen) = 0.0_wp
      end if
      if (want_k) ke(1:nd, 1:nd) = 0.0_wp
      nf = 0
      nc = 0
      if (want_k) then
         pg(:, 1:nen, 1:nen) = 0.0_wp
         mg(:, 1:nen, 1:nen) = 0.0_wp
      end if
      do g = 1, np
         n(1:nen) = rule%n(1:nen, g)
         dn(1:nen) = rule%dn(1:nen, g)*2.0_wp/le
         wj = rule%w(g)*0.5_wp*le
         cg = c*rule%mask(:, g)
         ! a shear-only point (Gamma1 and Gamma2 alone: the extra points of order 3), with
         ! the fields and B rows the shear strains need
         if (rule%shear_only(g)) then
            call rod_gp_kinematics_shear(nen, n(1:nen), dn(1:nen), x1, d1, k1)
            s = 0.0_wp
            if (scheme == scheme_emc .or. scheme == scheme_trapezoidal) then
               if (have0) then   ! q^n's fields and strains, given or computed
                  k0 = gp0(g)
                  e0(1:2) = epsn(1:2, g)
               else
                  call rod_gp_kinematics_shear(nen, n(1:nen), dn(1:nen), x0, d0, k0)
                  e0(1:2) = rod_strains_shear(k0)
               end if
            end if
            select case (scheme)
            case (scheme_midpoint, scheme_alpha)
               call rod_gp_kinematics_shear(nen, n(1:nen), dn(1:nen), xm(:, 1:nen), &
                                            dm(:, :, 1:nen), km)
               sh = cg(1:2)*(rod_strains_shear(km) - eps0(1:2, g))
               call rod_gp_qforce_shear(nen, n(1:nen), dn(1:nen), km, sh, wj, fq(:, :, 1:nen))
               if (.not. want_k) cycle
               call add_material(nen, n(1:nen), dn(1:nen), km, dm(:, :, 1:nen), km, d1, cg, &
                                 wq*wj, blt, cr, nf, blc, crc, nc)
               s(1:2) = sh
               call add_geometric(nen, n(1:nen), dn(1:nen), s, wq*wj, pg, mg)
            case (scheme_trapezoidal)
               sh = cg(1:2)*(e0(1:2) - eps0(1:2, g))
               sh1 = cg(1:2)*(rod_strains_shear(k1) - eps0(1:2, g))
               call rod_gp_qforce_shear(nen, n(1:nen), dn(1:nen), k0, sh, 0.5_wp*wj, &
                                        fq(:, :, 1:nen))
               call rod_gp_qforce_shear(nen, n(1:nen), dn(1:nen), k1, sh1, 0.5_wp*wj, &
                                        fq(:, :, 1:nen))
               if (.not. want_k) cycle
               call add_material(nen, n(1:nen), dn(1:nen), k1, dm(:, :, 1:nen), k1, d1, cg, &
                                 0.5_wp*wj, blt, cr, nf, blc, crc, nc)
               s(1:2) = sh1
               call add_geometric(nen, n(1:nen), dn(1:nen), s, 0.5_wp*wj, pg, mg)
            case default ! scheme_emc
               km%xp = 0.5_wp*(k0%xp + k1%xp)
               km%d(:, 1:2) = 0.5_wp*(k0%d(:, 1:2) + k1%d(:, 1:2))
               e1(1:2) = rod_strains_shear(k1)
               sh = cg(1:2)*(0.5_wp*(e0(1:2) + e1(1:2)) - eps0(1:2, g))
               cgt = cg
               if (present(kd)) then
                  sh = sh + rule%mask(1:2, g)*(kd(1:2)*(e1(1:2) - e0(1:2)) - off(1:2, g))
                  cgt = cg + 2.0_wp*kd*rule%mask(:, g)
               end if
               call rod_gp_qforce_shear(nen, n(1:nen), dn(1:nen), km, sh, wj, fq(:, :, 1:nen))
               if (.not. want_k) cycle
               call add_material(nen, n(1:nen), dn(1:nen), km, dm(:, :, 1:nen), k1, d1, cgt, &
                                 0.5_wp*wj, blt, cr, nf, blc, crc, nc)
               s(1:2) = sh
               if (lin) then
                  sl = linearized_strains(nen, n(1:nen), dn(1:nen), x1, dl(:, :, 1:nen), &
                                          dxl(:, 1:nen), ddl(:, :, 1:nen))
                  s(1:2) = cg(1:2)*(0.5_wp*(e0(1:2) + sl(1:2)) - eps0(1:2, g))
                  if (present(kd)) s(1:2) = s(1:2) + rule%mask(1:2, g)* &
                                            (kd(1:2)*(sl(1:2) - e0(1:2)) - off(1:2, g))
                  call rod_gp_qforce_shear(nen, n(1:nen), dn(1:nen), km, s(1:2), wj, &
                                           fql(:, :, 1:nen))
               end if
               call add_geometric(nen, n(1:nen), dn(1:nen), s, 0.5_wp*wj, pg, mg)
            end select
            cycle
         end if
         call rod_gp_kinematics(nen, n(1:nen), dn(1:nen), x1, d1, k1)
         if (scheme == scheme_emc .or. scheme == scheme_trapezoidal) then
            if (have0) then   ! q^n's fields and strains, given or computed
               k0 = gp0(g)
               e0 = epsn(:, g)
            else
               call rod_gp_kinematics(nen, n(1:nen), dn(1:nen), x0, d0, k0)
               e0 = rod_strains(k0)
            end if
         end if
         select case (scheme)
         case (scheme_midpoint, scheme_alpha)
            call rod_gp_kinematics(nen, n(1:nen), dn(1:nen), xm(:, 1:nen), dm(:, :, 1:nen), km)
            s = cg*(rod_strains(km) - eps0(:, g))
            call rod_gp_qforce(nen, n(1:nen), dn(1:nen), km, s, wj, fq(:, :, 1:nen))
            if (.not. want_k) cycle
            call add_material(nen, n(1:nen), dn(1:nen), km, dm(:, :, 1:nen), km, d1, cg, &
                              wq*wj, blt, cr, nf, blc, crc, nc)
            call add_geometric(nen, n(1:nen), dn(1:nen), s, wq*wj, pg, mg)
         case (scheme_trapezoidal)
            s = cg*(e0 - eps0(:, g))
            s1 = cg*(rod_strains(k1) - eps0(:, g))
            call rod_gp_qforce(nen, n(1:nen), dn(1:nen), k0, s, 0.5_wp*wj, fq(:, :, 1:nen))
            call rod_gp_qforce(nen, n(1:nen), dn(1:nen), k1, s1, 0.5_wp*wj, fq(:, :, 1:nen))
            if (.not. want_k) cycle
            call add_material(nen, n(1:nen), dn(1:nen), k1, dm(:, :, 1:nen), k1, d1, cg, &
                              0.5_wp*wj, blt, cr, nf, blc, crc, nc)
            call add_geometric(nen, n(1:nen), dn(1:nen), s1, 0.5_wp*wj, pg, mg)
         case default ! scheme_emc
            ! the fields are linear in the nodal values: midpoint = mean of the ends
            km%xp = 0.5_wp*(k0%xp + k1%xp)
            km%d = 0.5_wp*(k0%d + k1%d)
            km%dp = 0.5_wp*(k0%dp + k1%dp)
            e1 = rod_strains(k1)
            s = cg*(0.5_wp*(e0 + e1) - eps0(:, g))
            cgt = cg
            if (present(kd)) then
               s = s + rule%mask(:, g)*(kd*(e1 - e0) - off(:, g))
               cgt = cg + 2.0_wp*kd*rule%mask(:, g)
            end if
            call rod_gp_qforce(nen, n(1:nen), dn(1:nen), km, s, wj, fq(:, :, 1:nen))
            if (.not. want_k) cycle
            call add_material(nen, n(1:nen), dn(1:nen), km, dm(:, :, 1:nen), k1, d1, cgt, &
                              0.5_wp*wj, blt, cr, nf, blc, crc, nc)
            if (lin) then
               sl = linearized_strains(nen, n(1:nen), dn(1:nen), x1, dl(:, :, 1:nen), &
                                       dxl(:, 1:nen), ddl(:, :, 1:nen))
               s = cg*(0.5_wp*(e0 + sl) - eps0(:, g))
               if (present(kd)) s = s + rule%mask(:, g)*(kd*(sl - e0) - off(:, g))
               call rod_gp_qforce(nen, n(1:nen), dn(1:nen), km, s, wj, fql(:, :, 1:nen))
            end if
            call add_geometric(nen, n(1:nen), dn(1:nen), s, 0.5_wp*wj, pg, mg)
         end select
      end do
      call rod_project_qforce(nen, fq(:, :, 1:nen), dm(:, :, 1:nen), fe)
      if (want_k) call material_update(nen, blt, cr, nf, blc, crc, nc, ke(1:nd, 1:nd))
      if (want_k) call geometric_update(nen, pg, mg, dm(:, :, 1:nen), d1, ke(1:nd, 1:nd))
      if (lin) then
         call rod_rotation_geometric(nen, fql(:, :, 1:nen), d1, wq, ke(1:nd, 1:nd))
      else if (want_k) then
         call rod_rotation_geometric(nen, fq(:, :, 1:nen), d1, wq, ke(1:nd, 1:nd))
      end if
   end subroutine rod_element_dynamic

   !> The correction from Newton's base (xb, db) to the iterate (x1, d1), linearized:
   !> dxl = x1 - xb, ddl_i = theta x db_i with theta = cay^-1(d1 db^T) (the Cayley
   !> parameter of the director update), and dl = db + ddl, per node. Not ok where a
   !> node turned by 120 degrees or more (1 + tr R <= 1; cay^-1 is singular at 180): such
   !> an iterate is far from this tangent's purpose, which then keeps its own stresses.
   !> docs/theory.md eq. (44).
   pure subroutine linear_increment(nen, x1, d1, xb, db, dxl, ddl, dl, ok)
      integer, intent(in) :: nen                 !< nodes of the element
      real(wp), intent(in) :: x1(3, nen)         !< iterate positions [m]
      real(wp), intent(in) :: d1(3, 3, nen)      !< iterate directors
      real(wp), intent(in) :: xb(3, nen)         !< base positions [m]
      real(wp), intent(in) :: db(3, 3, nen)      !< base directors
      real(wp), intent(out) :: dxl(:, :)         !< (3, >= nen) position increment [m]
      real(wp), intent(out) :: ddl(:, :, :)      !< (3, 3, >= nen) linearized director increment
      real(wp), intent(out) :: dl(:, :, :)       !< (3, 3, >= nen) db + ddl
      logical, intent(out) :: ok                 !< every node turned by less than 120 deg
      real(wp) :: th(3), r(3, 3)
      integer :: a, i
      ok = .true.
      do a = 1, nen
         r = relative_rotation(d1(:, :, a), db(:, :, a))
         if (1.0_wp + r(1, 1) + r(2, 2) + r(3, 3) <= 1.0_wp) then
            ok = .false.
            return
         end if
         th = rotation_cayley_inverse(r)
         do i = 1, 3
            ddl(:, i, a) = cross(th, db(:, i, a))
         end do
         dl(:, :, a) = db(:, :, a) + ddl(:, :, a)
         dxl(:, a) = x1(:, a) - xb(:, a)
      end do
   end subroutine linear_increment

   !> The strains at a point linearized from the base (module header): eps of the fields
   !> of (x1, dl) less the quadratic part eps2 of the increment fields (dxl, ddl) alone;
   !> rod_strains of the increment fields is eps2 with -1 in its axial strain.
   !> docs/theory.md eq. (44).
   pure function linearized_strains(nen, n, dn, x1, dl, dxl, ddl) result(eps)
      integer, intent(in) :: nen                 !< nodes of the element
      real(wp), intent(in) :: n(nen)             !< shape functions
      real(wp), intent(in) :: dn(nen)            !< dN/dS [1/m]
      real(wp), intent(in) :: x1(3, nen)         !< iterate positions [m]
      real(wp), intent(in) :: dl(3, 3, nen)      !< base directors plus their increment
      real(wp), intent(in) :: dxl(3, nen)        !< position increment [m]
      real(wp), intent(in) :: ddl(3, 3, nen)     !< linearized director increment
      real(wp) :: eps(6)
      type(rod_gp_t) :: kl, kd
      call rod_gp_kinematics(nen, n, dn, x1, dl, kl)
      call rod_gp_kinematics(nen, n, dn, dxl, ddl, kd)
      eps = rod_strains(kl) - rod_strains(kd)
      eps(3) = eps(3) - 1.0_wp
   end function linearized_strains

   !> The stress (geometric) stiffness of one point, rod_rod_element's rod_gp_geometric,
   !> summed over the points before it is formed: with the nodal directors the same at
   !> every point, its blocks are linear in
   !>   pg(k, a, b) = sum_g f dN_a N_b s_k          (k = 1..3, contact forces)
   !>   mg(:, a, b) = sum_g f (dN_a N_b - N_a dN_b)/2 (s_4, s_5, s_6)   (moments)
   !> (geometric_update forms them once per element, not once per point).
   !> docs/theory.md eq. (27).
   pure subroutine add_geometric(nen, n, dn, s, f, pg, mg)
      integer, intent(in) :: nen                     !< nodes of the element
      real(wp), intent(in) :: n(nen)                 !< shape functions
      real(wp), intent(in) :: dn(nen)                !< dN/dS [1/m]
      real(wp), intent(in) :: s(6)                   !< stress resultants [N, N m]
      real(wp), intent(in) :: f                      !< weight (Gauss weight, Jacobian)
      real(wp), intent(inout) :: pg(:, :, :)         !< (3, >= nen, >= nen) force sums
      real(wp), intent(inout) :: mg(:, :, :)         !< (3, >= nen, >= nen) moment sums
      real(wp) :: h
      integer :: a, b
      do b = 1, nen
         do a = 1, nen
            pg(:, a, b) = pg(:, a, b) + (f*dn(a)*n(b))*s(1:3)
            if (a == b) cycle
            h = 0.5_wp*f*(dn(a)*n(b) - n(a)*dn(b))
            mg(:, a, b) = mg(:, a, b) + h*s(4:6)
         end do
      end do
   end subroutine add_geometric

   !> Add the stress stiffness of the sums of add_geometric to ke (P(d) = -skew(d), as
   !> in rod_gp_geometric):
   !>   x_a - theta_b:      -skew(sum_k pg(k, a, b) dr_kb)
   !>   theta_a - x_b:       skew(sum_k pg(k, b, a) dl_ka)
   !>   theta_a - theta_b:   tr(M) I - M,  M = Dr_b skew(mg(:, a, b)) Dl_a^T
   !> (Dl_a, Dr_b: the nodal directors as columns, test side and increment side).
   !> docs/theory.md eq. (27).
   pure subroutine geometric_update(nen, pg, mg, dl, dr, ke)
      integer, intent(in) :: nen                  !< nodes of the element
      real(wp), intent(in) :: pg(:, :, :)         !< force sums (add_geometric)
      real(wp), intent(in) :: mg(:, :, :)         !< moment sums (add_geometric)
      real(wp), intent(in) :: dl(3, 3, nen)       !< nodal directors, test side
      real(wp), intent(in) :: dr(3, 3, nen)       !< nodal directors, increment side
      real(wp), intent(inout) :: ke(:, :)         !< element matrix (6 nen square)
      real(wp) :: v(3), st(3, 3), w(3, 3), m(3, 3), tr
      integer :: a, b, ra, rb, i, j
      do b = 1, nen
         rb = 6*(b - 1)
         do a = 1, nen
            ra = 6*(a - 1)
            v = pg(1, a, b)*dr(:, 1, b) + pg(2, a, b)*dr(:, 2, b) + pg(3, a, b)*dr(:, 3, b)
            ke(ra + 1:ra + 3, rb + 4:rb + 6) = ke(ra + 1:ra + 3, rb + 4:rb + 6) - skew(v)
            v = pg(1, b, a)*dl(:, 1, a) + pg(2, b, a)*dl(:, 2, a) + pg(3, b, a)*dl(:, 3, a)
            ke(ra + 4:ra + 6, rb + 1:rb + 3) = ke(ra + 4:ra + 6, rb + 1:rb + 3) + skew(v)
            if (a == b) cycle
            st = skew(mg(:, a, b))
            ! w = st Dl_a^T, m = Dr_b w
            do j = 1, 3
               w(:, j) = st(:, 1)*dl(j, 1, a) + st(:, 2)*dl(j, 2, a) + st(:, 3)*dl(j, 3, a)
            end do
            do j = 1, 3
               m(:, j) = dr(:, 1, b)*w(1, j) + dr(:, 2, b)*w(2, j) + dr(:, 3, b)*w(3, j)
            end do
            tr = m(1, 1) + m(2, 2) + m(3, 3)
            do j = 1, 3
               do i = 1, 3
                  ke(ra + 3 + i, rb + 3 + j) = ke(ra + 3 + i, rb + 3 + j) - m(i, j)
               end do
               ke(ra + 3 + j, rb + 3 + j) = ke(ra + 3 + j, rb + 3 + j) + tr
            end do
         end do
      end do
   end subroutine geometric_update

   !> Append the point's material part f bl^T diag(cg) br, over the strains integrated
   !> here (cg /= 0), to the rows of the element (material_update adds them to ke):
   !> row k of bl (the strain Jacobian of the test side: fields kl, nodal directors dl)
   !> as column nf of blt (force strains) or, its rotation entries only (3 a - 2 .. 3 a
   !> for node a), as column nc of blc (curvatures); f cg(k) times row k of br (the
   !> increment side: kr, dr) as row nf of cr or nc of crc. Only the rows used are formed
   !> (rod_gp_jacobian_row): at a full point of order 3 Gamma3 and the curvatures, at a
   !> shear-only point Gamma1 and Gamma2.
   !> docs/theory.md eq. (26).
   pure subroutine add_material(nen, n, dn, kl, dl, kr, dr, cg, f, blt, cr, nf, blc, crc, nc)
      integer, intent(in) :: nen                 !< nodes of the element
      real(wp), intent(in) :: n(nen)             !< shape functions
      real(wp), intent(in) :: dn(nen)            !< dN/dS [1/m]
      type(rod_gp_t), intent(in) :: kl, kr       !< fields of the test and increment sides
      real(wp), intent(in) :: dl(3, 3, nen)      !< nodal directors, test side
      real(wp), intent(in) :: dr(3, 3, nen)      !< nodal directors, increment side
      real(wp), intent(in) :: cg(6)              !< stiffness of the strains integrated here
      real(wp), intent(in) :: f                  !< weight
      real(wp), intent(inout) :: blt(6*max_nen, 3*max_points), cr(3*max_points, 6*max_nen)
      integer, intent(inout) :: nf               !< force-strain rows used
      real(wp), intent(inout) :: blc(3*max_nen, 3*max_points), crc(3*max_points, 6*max_nen)
      integer, intent(inout) :: nc               !< curvature rows used
      real(wp) :: row(6*max_nen)
      integer :: k, nd, a
      nd = 6*nen
      do k = 1, 6
         if (cg(k) == 0.0_wp) cycle
         call rod_gp_jacobian_row(nen, n, dn, kr, dr, k, row(1:nd))
         if (k <= 3) then
            nf = nf + 1
            call rod_gp_jacobian_row(nen, n, dn, kl, dl, k, blt(1:nd, nf))
            cr(nf, 1:nd) = (f*cg(k))*row(1:nd)
         else
            nc = nc + 1
            crc(nc, 1:nd) = (f*cg(k))*row(1:nd)
            call rod_gp_jacobian_row(nen, n, dn, kl, dl, k, row(1:nd))
            do a = 1, nen                  ! the rotation entries only
               blc(3*a - 2:3*a, nc) = row(6*a - 2:6*a)
            end do
         end if
      end do
   end subroutine add_material

   !> ke += blt(:, 1:nf) cr(1:nf, :) + blc(:, 1:nc) crc(1:nc, :), column by column and
   !> row by row down a column (the loop the compiler vectorizes). The curvatures do not
   !> depend on the positions: blc holds their rotation rows only, and a rotation column
   !> of ke takes them through its rotation rows gathered into one vector.
   pure subroutine material_update(nen, blt, cr, nf, blc, crc, nc, ke)
      integer, intent(in) :: nen                      !< nodes of the element
      real(wp), intent(in) :: blt(6*max_nen, 3*max_points), cr(3*max_points, 6*max_nen)
      integer, intent(in) :: nf                       !< force-strain rows
      real(wp), intent(in) :: blc(3*max_nen, 3*max_points), crc(3*max_points, 6*max_nen)
      integer, intent(in) :: nc                       !< curvature rows
      real(wp), intent(inout) :: ke(:, :)             !< element matrix (6 nen square)
      real(wp) :: c, kr(3*max_nen)
      integer :: j, i, k, a
      do j = 1, 6*nen
         do k = 1, nf
            c = cr(k, j)
            do i = 1, 6*nen
               ke(i, j) = ke(i, j) + c*blt(i, k)
            end do
         end do
         if (mod(j - 1, 6) < 3) cycle       ! an x column: no curvature terms
         do a = 1, nen
            kr(3*a - 2:3*a) = ke(6*a - 2:6*a, j)
         end do
         do k = 1, nc
            c = crc(k, j)
            do i = 1, 3*nen
               kr(i) = kr(i) + c*blc(i, k)
            end do
         end do
         do a = 1, nen
            ke(6*a - 2:6*a, j) = kr(3*a - 2:3*a)
         end do
      end do
   end subroutine material_update
end module rodyn_rod_dynamic
