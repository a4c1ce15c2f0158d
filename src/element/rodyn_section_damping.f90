!> Structural (material) damping of a section over a time step (docs/theory.md section
!> 15, eqs. (116)-(121)): a viscous stress proportional to the rate of the axial strain
!> and, for rods, of the bending curvatures,
!>   N_d = C_a d(Gamma3)/dt,   M_d1 = C_b1 dK1/dt,   M_d2 = C_b2 dK2/dt,
!> acting through the strain Jacobian B at the force point of the scheme, with its
!> consistent tangent with respect to the unknowns at t_n+1.
!>
!> The rates are those of the scheme at its force point: with u the nodal rates,
!>   u = cv (q^{n+1} - q^n) + g
!> (midpoint family: cv = 1/dt, g = 0, so u = (q^{n+1} - q^n)/dt; generalized-alpha: the
!> velocity at t_{n+1-alpha_f} of the Newmark update, cv = (1 - alpha_f) gamma/(beta dt)),
!> the strain rate at a point is eps_dot = B(q_f) u. For the rod the strains are
!> quadratic in q, so with the midpoint (EMC, MIDPOINT, TRAPEZOIDAL) B(q^{n+1/2})
!> (q^{n+1} - q^n) = eps^{n+1} - eps^n exactly and the work of the damping force over the
!> step is
!>   sum over the points of wj C ((eps^{n+1} - eps^n)/dt)^2 dt >= 0     (eq. (119)),
!> the dissipation the energy log books. The cable's stretch lambda = |x'| is not
!> quadratic; there the midpoint family uses the discrete gradient of lambda,
!> (x'_n + x'_n+1)/(lambda_n + lambda_n+1), whose product with x'_n+1 - x'_n is
!> lambda_n+1 - lambda_n exactly, with the same dissipation C_a (dlambda/dt)^2 dt per
!> unit length (eq. (120)). The damping acts slack or taut, as MoorDyn's.
module rodyn_section_damping
   use rodyn_kinds, only: wp
   use rodyn_schemes, only: scheme_alpha
   use rodyn_shape, only: max_nen
   use rodyn_rod_element, only: rod_gp_t, rod_rule_t, rod_gp_kinematics, rod_gp_qforce, &
                                rod_gp_jacobian_row, rod_gp_geometric, rod_project_qforce, &
                                rod_rotation_geometric
   use rodyn_rotation, only: norm3
   implicit none
   private
   public :: rod_section_damping, cable_section_damping, rod_strain_rates

contains

   !> Damping force fe (6, p+1) of one rod element projected with the directors of the
   !> force point, and its tangent ke with respect to (dx, dtheta) at t_n+1
   !> (dd_i^{n+1} = dtheta x d_i^{n+1}).
   !> docs/theory.md eqs. (116)-(117), (119), (121).
   pure subroutine rod_section_damping(p, le, cd, x0, d0, x1, d1, g, cv, wq, fe, ke, &
                                       want_k, rule)
      integer, intent(in) :: p                !< element order
      real(wp), intent(in) :: le              !< unstretched element length [m]
      !> coefficients of the six strain rates (Gamma1, Gamma2, Gamma3, K1, K2, K3):
      !> structural damping (0, 0, C_a, C_b1, C_b2, 0) [N s, N m2 s]
      real(wp), intent(in) :: cd(6)
      real(wp), intent(in) :: x0(3, p + 1)    !< positions at t_n [m]
      real(wp), intent(in) :: d0(3, 3, p + 1) !< directors at t_n
      real(wp), intent(in) :: x1(3, p + 1)    !< positions at t_n+1 [m]
      real(wp), intent(in) :: d1(3, 3, p + 1) !< directors at t_n+1
      !> the rates' constant part: (:, 1, a) of x_a [m/s], (:, 1 + i, a) of d_ia [1/s]
      real(wp), intent(in) :: g(3, 4, p + 1)
      real(wp), intent(in) :: cv              !< d(rate)/d(q^{n+1}) [1/s]
      real(wp), intent(in) :: wq              !< weight of q^{n+1} in the force point [-]
      real(wp), intent(out) :: fe(6, p + 1)   !< projected damping force [N, N m]
      real(wp), intent(out) :: ke(:, :)       !< (6(p+1), 6(p+1)) tangent, if want_k
      logical, intent(in) :: want_k           !< form the tangent
      type(rod_rule_t), intent(in) :: rule    !< rod_rule(p): points, shape functions
      real(wp) :: xf(3, max_nen), df(3, 3, max_nen), ux(3, max_nen), ud(3, 3, max_nen)
      real(wp) :: fq(3, 4, max_nen), n(max_nen), dn(max_nen), wj, cg(6), s(6)
      real(wp) :: bl(6*max_nen), br(6*max_nen), bu(6*max_nen)
      type(rod_gp_t) :: kf, ku
      integer :: nen, nd, a, ig, k, j
      nen = p + 1
      nd = 6*nen
      do a = 1, nen
         xf(:, a) = (1.0_wp - wq)*x0(:, a) + wq*x1(:, a)
         df(:, :, a) = (1.0_wp - wq)*d0(:, :, a) + wq*d1(:, :, a)
         ux(:, a) = cv*(x1(:, a) - x0(:, a)) + g(:, 1, a)
         ud(:, :, a) = cv*(d1(:, :, a) - d0(:, :, a)) + g(:, 2:4, a)
      end do
      fq(:, :, 1:nen) = 0.0_wp
      if (want_k) ke(1:nd, 1:nd) = 0.0_wp
      do ig = 1, rule%np
         cg = cd*rule%mask(:, ig)
         if (all(cg == 0.0_wp)) cycle
         n(1:nen) = rule%n(1:nen, ig)
         dn(1:nen) = rule%dn(1:nen, ig)*2.0_wp/le
         wj = rule%w(ig)*0.5_wp*le
         call rod_gp_kinematics(nen, n(1:nen), dn(1:nen), xf(:, 1:nen), df(:, :, 1:nen), kf)
         call rod_gp_kinematics(nen, n(1:nen), dn(1:nen), ux(:, 1:nen), ud(:, :, 1:nen), ku)
         s = cg*rod_strain_rates(kf, ku)
         call rod_gp_qforce(nen, n(1:nen), dn(1:nen), kf, s, wj, fq(:, :, 1:nen))
         if (.not. want_k) cycle
         ! B(q_f)^T s changing with q_f (weight wq): the stress stiffness of s
         call rod_gp_geometric(nen, n(1:nen), dn(1:nen), s, df(:, :, 1:nen), d1, wq*wj, ke)
         ! s changing: eps_dot = B(q_f) u is bilinear (symmetric) in q_f and u, so
         ! d eps_dot = cv B(q_f) dq + wq B(u) dq
         do k = 1, 6
            if (cg(k) == 0.0_wp) cycle
            call rod_gp_jacobian_row(nen, n(1:nen), dn(1:nen), kf, df(:, :, 1:nen), k, &
                                     bl(1:nd))
            call rod_gp_jacobian_row(nen, n(1:nen), dn(1:nen), kf, d1, k, br(1:nd))
            call rod_gp_jacobian_row(nen, n(1:nen), dn(1:nen), ku, d1, k, bu(1:nd))
            br(1:nd) = wj*cg(k)*(cv*br(1:nd) + wq*bu(1:nd))
            do j = 1, nd
               ke(1:nd, j) = ke(1:nd, j) + br(j)*bl(1:nd)
            end do
         end do
      end do
      call rod_project_qforce(nen, fq(:, :, 1:nen), df(:, :, 1:nen), fe)
      ! the projection's directors turning with the increment
      if (want_k) call rod_rotation_geometric(nen, fq(:, :, 1:nen), d1, wq, ke(1:nd, 1:nd))
   end subroutine rod_section_damping

   !> The rates of the strains (Gamma1, Gamma2, Gamma3, K1, K2, K3) at a point, B(q) u,
   !> from the fields of the configuration (kf) and of the rates (ku): the strains are
   !> quadratic forms of the fields, and their rates the symmetric bilinear forms.
   !> docs/theory.md eq. (117).
   pure function rod_strain_rates(kf, ku) result(rate)
      type(rod_gp_t), intent(in) :: kf !< fields of the configuration
      type(rod_gp_t), intent(in) :: ku !< fields of the rates [1/s, 1/(m s)]
      real(wp) :: rate(6)
      integer :: k, i, j
      do k = 1, 3
         rate(k) = dot_product(ku%xp, kf%d(:, k)) + dot_product(kf%xp, ku%d(:, k))
      end do
      do k = 4, 6
         i = mod(k - 3, 3) + 1
         j = mod(k - 2, 3) + 1
         ! K = (d_i'.d_j - d_j'.d_i)/2
         rate(k) = 0.5_wp*(dot_product(ku%dp(:, i), kf%d(:, j)) &
                           + dot_product(kf%dp(:, i), ku%d(:, j)) &
                           - dot_product(ku%dp(:, j), kf%d(:, i)) &
                           - dot_product(kf%dp(:, j), ku%d(:, i)))
      end do
   end function rod_strain_rates

   !> Damping force fe (3, p+1) of one cable element and its tangent ke with respect to
   !> x_n+1 (module header): the midpoint family with the discrete gradient of the stretch
   !> (N_d = C_a cv (lambda_n+1 - lambda_n), direction (x'_n + x'_n+1)/(lambda_n +
   !> lambda_n+1)), ALPHA at its force point (N_d = C_a t_f . u', direction t_f).
   !> docs/theory.md eqs. (120)-(121).
   pure subroutine cable_section_damping(p, le, ca, x0, x1, g, cv, wq, scheme, fe, ke, &
                                         want_k, rule)
      integer, intent(in) :: p                !< element order
      real(wp), intent(in) :: le              !< unstretched element length [m]
      real(wp), intent(in) :: ca              !< C_a [N s]
      real(wp), intent(in) :: x0(3, p + 1)    !< positions at t_n [m]
      real(wp), intent(in) :: x1(3, p + 1)    !< positions at t_n+1 [m]
      real(wp), intent(in) :: g(3, p + 1)     !< the rates' constant part [m/s] (ALPHA)
      real(wp), intent(in) :: cv              !< d(rate)/d(x^{n+1}) [1/s]
      real(wp), intent(in) :: wq              !< ALPHA: weight of x^{n+1} in x_f [-]
      integer, intent(in) :: scheme           !< scheme_* constant
      real(wp), intent(out) :: fe(3, p + 1)   !< damping force [N]
      real(wp), intent(out) :: ke(:, :)       !< (3(p+1), 3(p+1)) tangent, if want_k
      logical, intent(in) :: want_k           !< form the tangent
      type(rod_rule_t), intent(in) :: rule    !< rod_rule(p): its first p points are used
      real(wp) :: dn(max_nen), wj, xp0(3), xp1(3), up(3), l0, l1, ls, dl, nd, th(3)
      real(wp) :: dfg(3, 3), t1(3), proj(3, 3)
      integer :: ig, nen, a, i
      nen = p + 1
      fe = 0.0_wp
      if (want_k) ke(1:3*nen, 1:3*nen) = 0.0_wp
      do ig = 1, p
         dn(1:nen) = rule%dn(1:nen, ig)*2.0_wp/le
         wj = rule%w(ig)*0.5_wp*le
         xp0 = 0.0_wp
         xp1 = 0.0_wp
         up = 0.0_wp
         do a = 1, nen
            xp0 = xp0 + dn(a)*x0(:, a)
            xp1 = xp1 + dn(a)*x1(:, a)
            up = up + dn(a)*(cv*(x1(:, a) - x0(:, a)) + g(:, a))
         end do
         if (scheme == scheme_alpha) then
            th = (1.0_wp - wq)*xp0 + wq*xp1           ! x'_f
            ls = norm3(th)
            if (.not. ls > 0.0_wp) cycle
            th = th/ls                                ! t_f
            nd = ca*dot_product(th, up)
            fe(:, 1:nen) = fe(:, 1:nen) + spread(wj*nd*th, 2, nen)*spread(dn(1:nen), 1, 3)
            if (.not. want_k) cycle
            do i = 1, 3
               proj(:, i) = -th*th(i)
               proj(i, i) = proj(i, i) + 1.0_wp
            end do
            ! d(N_d t_f)/dx'_n+1 = C_a t_f (cv t_f + wq P u'/ls)^T + N_d wq P/ls
            do i = 1, 3
               dfg(:, i) = ca*th*(cv*th(i) + wq*dot_product(proj(:, i), up)/ls) &
                           + nd*wq*proj(:, i)/ls
            end do
         else
            l0 = norm3(xp0)
            l1 = norm3(xp1)
            ls = l0 + l1
            if (.not. (ls > 0.0_wp .and. l1 > 0.0_wp)) cycle
            th = (xp0 + xp1)/ls                       ! discrete gradient of lambda
            dl = dot_product(th, xp1 - xp0)           ! lambda_n+1 - lambda_n
            nd = ca*cv*dl
            fe(:, 1:nen) = fe(:, 1:nen) + spread(wj*nd*th, 2, nen)*spread(dn(1:nen), 1, 3)
            if (.not. want_k) cycle
            ! d(N_d th)/dx'_n+1 = C_a cv th t1^T + N_d (I - th t1^T)/ls
            t1 = xp1/l1
            do i = 1, 3
               dfg(:, i) = (ca*cv - nd/ls)*th*t1(i)
               dfg(i, i) = dfg(i, i) + nd/ls
            end do
         end if
         call add_block(nen, dn(1:nen), wj, dfg, ke)
      end do
   end subroutine cable_section_damping

   !> ke(a, b blocks) += wj dN_a dN_b dfg.
   pure subroutine add_block(nen, dn, wj, dfg, ke)
      integer, intent(in) :: nen             !< nodes of the element
      real(wp), intent(in) :: dn(nen)        !< dN/dS [1/m]
      real(wp), intent(in) :: wj             !< Gauss weight times Jacobian [m]
      real(wp), intent(in) :: dfg(3, 3)      !< point block
      real(wp), intent(inout) :: ke(:, :)    !< element matrix (3 nen square)
      integer :: a, b
      do b = 1, nen
         do a = 1, nen
            ke(3*a - 2:3*a, 3*b - 2:3*b) = ke(3*a - 2:3*a, 3*b - 2:3*b) + (wj*dn(a)*dn(b))*dfg
         end do
      end do
   end subroutine add_block
end module rodyn_section_damping
