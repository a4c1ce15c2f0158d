!> The cable element: a line with axial stiffness only (*LINE, ELEMENT=CABLE), for
!> chain, wire and rope, whose bending and torsion do not matter (docs/element.md;
!> docs/theory.md section 8, eqs. (61)-(66)).
!>
!> Per node a the unknown is the position x_a; positions are interpolated with the
!> Lagrange functions of order p (the rod's) and, per unit unstretched length S,
!>   stretch     lambda = |x'|,   t = x'/lambda
!>   tension     N = EA max(lambda - 1, 0)         (no compression: a slack cable
!>                                                  carries nothing, as in MoorDyn)
!>   energy      W = 1/2 EA max(lambda - 1, 0)^2
!>   force       f_a = int N t dN_a/dS dS  (= dW/dx_a),
!>   tangent     d(N t)/dx' = phi I + phi' x' x'^T / lambda,   phi = N / lambda.
!> Quadrature: the p Gauss points of the rod's reduced rule (the points where results
!> are reported); x' is of degree p - 1, so no spurious mode escapes them.
!>
!> Over a time step (as the rod, rodyn_rod_dynamic) the force is
!>   EMC          N_hat x'_m,  x'_m = (x'_n + x'_n+1)/2,
!>                N_hat = 2 (W(lambda_n+1) - W(lambda_n)) / (lambda_n+1^2 - lambda_n^2)
!>                (the discrete gradient of W(C), C = x'.x': its work over the step is
!>                the change of W exactly; both ends taut: N_hat = EA (lambda_n +
!>                lambda_n+1 - 2)/(lambda_n + lambda_n+1), the tension over the mean stretch)
!>   MIDPOINT     phi(x'_m) x'_m          ALPHA   phi(x'_f) x'_f, x_f = (1 - w) x_n + w x_n+1
!>   TRAPEZOIDAL  (phi(x'_n) x'_n + phi(x'_n+1) x'_n+1)/2
!> with their tangents with respect to x_n+1.
module rodyn_cable_element
   use rodyn_kinds, only: wp
   use rodyn_schemes, only: scheme_emc, scheme_midpoint, scheme_trapezoidal, scheme_alpha
   use rodyn_shape, only: max_nen
   use rodyn_rod_element, only: rod_rule_t
   use rodyn_rotation, only: norm3
   implicit none
   private
   public :: cable_element_static, cable_element_dynamic, cable_element_energy
   public :: cable_element_tension, cable_element_energy_scale

   real(wp), parameter :: slack_floor = 1.0e-6_wp !< least phi / EA in the static matrix

contains

   !> Internal force fe (3, p+1) and tangent ke (3(p+1), 3(p+1)) of one element. With
   !> slack_axial (the static Newton iteration matrix) a slack point (lambda <= 1) takes
   !> the axial stiffness slack_floor EA/lambda t t^T, and the geometric stiffness phi I
   !> no smaller than slack_floor EA, in the matrix only (not in the force): it would
   !> otherwise be singular wherever a stretch of line starts slack or unstretched (the
   !> grounded part of a leg's start); the full EA there would move a slack stretch by
   !> the residual over EA a correction, and Newton would stall. The equilibrium found
   !> is the same.
   !> docs/theory.md eqs. (61)-(62).
   pure subroutine cable_element_static(p, le, ea, xe, fe, ke, want_k, rule, slack_axial)
      integer, intent(in) :: p                !< element order
      real(wp), intent(in) :: le              !< unstretched element length [m]
      real(wp), intent(in) :: ea              !< axial stiffness [N]
      real(wp), intent(in) :: xe(3, p + 1)    !< nodal positions [m]
      real(wp), intent(out) :: fe(3, p + 1)   !< internal force [N]
      real(wp), intent(out) :: ke(:, :)       !< (3(p+1), 3(p+1)) tangent, if want_k
      logical, intent(in) :: want_k           !< form the tangent
      type(rod_rule_t), intent(in) :: rule    !< rod_rule(p): its first p points are used
      logical, intent(in), optional :: slack_axial !< keep EA in the matrix where slack
      real(wp) :: dn(max_nen), wj, xp(3), lam, phi, dphi, dfg(3, 3)
      integer :: g, nen
      logical :: floor
      floor = .false.
      if (present(slack_axial)) floor = slack_axial
      nen = p + 1
      fe = 0.0_wp
      if (want_k) ke(1:3*nen, 1:3*nen) = 0.0_wp
      do g = 1, p
         dn(1:nen) = rule%dn(1:nen, g)*2.0_wp/le
         wj = rule%w(g)*0.5_wp*le
         xp = matmul(xe, dn(1:nen))
         lam = norm3(xp)
         call tension_law(ea, lam, phi, dphi)
         call add_force(nen, dn(1:nen), wj*phi*xp, fe)
         if (.not. want_k) cycle
         if (floor .and. lam <= 1.0_wp) dphi = slack_floor*ea/lam**2
         if (floor) phi = max(phi, slack_floor*ea)
         call law_tangent(xp, lam, phi, dphi, 1.0_wp, dfg)
         call add_tangent(nen, dn(1:nen), wj, dfg, ke)
      end do
   end subroutine cable_element_static

   !> Step internal force fe (3, p+1) of one element for a scheme (module header) and
   !> its tangent with respect to x_n+1.
   !> docs/theory.md eqs. (63)-(66).
   pure subroutine cable_element_dynamic(p, le, ea, x0, x1, scheme, wf, fe, ke, want_k, rule, &
                                         kd, off)
      integer, intent(in) :: p                !< element order
      real(wp), intent(in) :: le              !< unstretched element length [m]
      real(wp), intent(in) :: ea              !< axial stiffness [N]
      real(wp), intent(in) :: x0(3, p + 1)    !< positions at t_n [m]
      real(wp), intent(in) :: x1(3, p + 1)    !< positions at t_n+1 [m]
      integer, intent(in) :: scheme           !< scheme_* constant
      real(wp), intent(in) :: wf              !< ALPHA: weight of x_n+1 in x_f [-]
      real(wp), intent(out) :: fe(3, p + 1)   !< step internal force [N]
      real(wp), intent(out) :: ke(:, :)       !< (3(p+1), 3(p+1)) tangent, if want_k
      logical, intent(in) :: want_k           !< form the tangent
      type(rod_rule_t), intent(in) :: rule    !< rod_rule(p): its first p points are used
      !> EMC with RHO INF < 1 (docs/theory.md eqs. (126)-(127)): the numerical tension
      !> N_d = kd (lambda_n+1 - lambda_n) - off at each point along the discrete gradient
      !> (x'_n + x'_n+1)/(lambda_n + lambda_n+1), kd = EA (c1 + 2 c2) [N]
      real(wp), intent(in), optional :: kd, off(:)
      real(wp) :: dn(max_nen), wj, xp0(3), xp1(3), xpm(3), l0, l1, lm, phi, dphi, wq
      real(wp) :: nh, dnh, dfg(3, 3), phi0, dphi0, ndn, ls
      integer :: g, nen, i
      nen = p + 1
      fe = 0.0_wp
      if (want_k) ke(1:3*nen, 1:3*nen) = 0.0_wp
      wq = 0.5_wp
      if (scheme == scheme_alpha) wq = wf
      do g = 1, p
         dn(1:nen) = rule%dn(1:nen, g)*2.0_wp/le
         wj = rule%w(g)*0.5_wp*le
         xp0 = 0.0_wp           ! x' at t_n and t_n+1 (explicit loops: cheaper than
         xp1 = 0.0_wp           ! matmul on these small arrays)
         do i = 1, nen
            xp0 = xp0 + x0(:, i)*dn(i)
            xp1 = xp1 + x1(:, i)*dn(i)
         end do
         l0 = norm3(xp0)
         l1 = norm3(xp1)
         select case (scheme)
         case (scheme_emc)
            xpm = 0.5_wp*(xp0 + xp1)
            call discrete_gradient(ea, l0, l1, nh, dnh)
            if (present(kd)) then
               ! N_d t_hat = (2 N_d/(lambda_n + lambda_n+1)) x'_m
               ls = l0 + l1
               ndn = kd*(l1 - l0) - off(g)
               nh = nh + 2.0_wp*ndn/ls
               dnh = dnh + 2.0_wp*kd/ls - 2.0_wp*ndn/ls**2
            end if
            call add_force(nen, dn(1:nen), wj*nh*xpm, fe)
            if (.not. want_k) cycle
            ! d(N_hat x'_m)/dx'_n+1 = N_hat/2 I + x'_m (dN_hat/dlambda_n+1) t_n+1^T
            do i = 1, 3
               dfg(:, i) = dnh*xpm*xp1(i)/l1
               dfg(i, i) = dfg(i, i) + 0.5_wp*nh
            end do
            call add_tangent(nen, dn(1:nen), wj, dfg, ke)
         case (scheme_midpoint, scheme_alpha)
            xpm = (1.0_wp - wq)*xp0 + wq*xp1
            lm = norm3(xpm)
            call tension_law(ea, lm, phi, dphi)
            call add_force(nen, dn(1:nen), wj*phi*xpm, fe)
            if (.not. want_k) cycle
            call law_tangent(xpm, lm, phi, dphi, wq, dfg)
            call add_tangent(nen, dn(1:nen), wj, dfg, ke)
         case (scheme_trapezoidal)
            call tension_law(ea, l0, phi0, dphi0)
            call tension_law(ea, l1, phi, dphi)
            call add_force(nen, dn(1:nen), 0.5_wp*wj*(phi0*xp0 + phi*xp1), fe)
            if (.not. want_k) cycle
            call law_tangent(xp1, l1, phi, dphi, 0.5_wp, dfg)
            call add_tangent(nen, dn(1:nen), wj, dfg, ke)
         end select
      end do
   end subroutine cable_element_dynamic

   !> Stored energy of one element, sum over the points of wj W(lambda) [J].
   !> docs/theory.md eq. (61).
   pure function cable_element_energy(p, le, ea, xe, rule) result(energy)
      integer, intent(in) :: p                !< element order
      real(wp), intent(in) :: le              !< unstretched element length [m]
      real(wp), intent(in) :: ea              !< axial stiffness [N]
      real(wp), intent(in) :: xe(3, p + 1)    !< nodal positions [m]
      type(rod_rule_t), intent(in) :: rule    !< rod_rule(p): its first p points are used
      real(wp) :: energy
      real(wp) :: scale
      call cable_element_energy_scale(p, le, ea, xe, rule, energy, scale)
   end function cable_element_energy

   !> The stored energy (cable_element_energy) and its round-off scale, the sum over the
   !> points of wj N [J] (as rod_element_energy_scale).
   pure subroutine cable_element_energy_scale(p, le, ea, xe, rule, energy, scale)
      integer, intent(in) :: p                !< element order
      real(wp), intent(in) :: le              !< unstretched element length [m]
      real(wp), intent(in) :: ea              !< axial stiffness [N]
      real(wp), intent(in) :: xe(3, p + 1)    !< nodal positions [m]
      type(rod_rule_t), intent(in) :: rule    !< rod_rule(p): its first p points are used
      real(wp), intent(out) :: energy         !< stored energy [J]
      real(wp), intent(out) :: scale          !< its round-off scale [J]
      real(wp) :: lam, wj
      integer :: g
      energy = 0.0_wp
      scale = 0.0_wp
      do g = 1, p
         wj = rule%w(g)*0.5_wp*le
         lam = norm3(cable_xp(p, le, xe, rule%dn(1:p + 1, g)))
         energy = energy + wj*strain_energy(ea, lam)
         scale = scale + wj*ea*max(lam - 1.0_wp, 0.0_wp)
      end do
   end subroutine cable_element_energy_scale

   !> Tension N = EA max(lambda - 1, 0) [N] and the unit tangent at the p points.
   !> docs/theory.md eq. (61).
   pure subroutine cable_element_tension(p, le, ea, xe, rule, tension, tangent)
      integer, intent(in) :: p                !< element order
      real(wp), intent(in) :: le              !< unstretched element length [m]
      real(wp), intent(in) :: ea              !< axial stiffness [N]
      real(wp), intent(in) :: xe(3, p + 1)    !< nodal positions [m]
      type(rod_rule_t), intent(in) :: rule    !< rod_rule(p): its first p points are used
      real(wp), intent(out) :: tension(p)     !< tension [N]
      real(wp), intent(out) :: tangent(3, p)  !< unit tangent [-]
      real(wp) :: xp(3), lam
      integer :: g
      do g = 1, p
         xp = cable_xp(p, le, xe, rule%dn(1:p + 1, g))
         lam = norm3(xp)
         tension(g) = ea*max(lam - 1.0_wp, 0.0_wp)
         tangent(:, g) = xp/lam
      end do
   end subroutine cable_element_tension

   !> x' = sum_a x_a dN_a/dS at a point (dN_a/dxi given; no array temporary).
   pure function cable_xp(p, le, xe, dnxi) result(xp)
      integer, intent(in) :: p                !< element order
      real(wp), intent(in) :: le              !< unstretched element length [m]
      real(wp), intent(in) :: xe(3, p + 1)    !< nodal positions [m]
      real(wp), intent(in) :: dnxi(p + 1)     !< dN_a/dxi at the point
      real(wp) :: xp(3)
      integer :: a
      xp = 0.0_wp
      do a = 1, p + 1
         xp = xp + dnxi(a)*xe(:, a)
      end do
      xp = xp*(2.0_wp/le)
   end function cable_xp

   !> W(lambda) = 1/2 EA max(lambda - 1, 0)^2 [J/m].
   !> docs/theory.md eq. (61).
   pure real(wp) function strain_energy(ea, lam)
      real(wp), intent(in) :: ea, lam
      strain_energy = 0.5_wp*ea*max(lam - 1.0_wp, 0.0_wp)**2
   end function strain_energy

   !> phi = N/lambda and dphi/dlambda.
   !> docs/theory.md eqs. (61)-(62).
   pure subroutine tension_law(ea, lam, phi, dphi)
      real(wp), intent(in) :: ea, lam
      real(wp), intent(out) :: phi, dphi
      if (lam > 1.0_wp) then
         phi = ea*(lam - 1.0_wp)/lam
         dphi = ea/lam**2
      else
         phi = 0.0_wp
         dphi = 0.0_wp
      end if
   end subroutine tension_law

   !> scale * d(phi x')/dx' = scale (phi I + dphi x' x'^T / lambda).
   !> docs/theory.md eq. (62).
   pure subroutine law_tangent(xp, lam, phi, dphi, scale, dfg)
      real(wp), intent(in) :: xp(3), lam, phi, dphi, scale
      real(wp), intent(out) :: dfg(3, 3)
      integer :: i
      do i = 1, 3
         dfg(:, i) = scale*dphi*xp*xp(i)/lam
         dfg(i, i) = dfg(i, i) + scale*phi
      end do
   end subroutine law_tangent

   !> N_hat of the EMC step (module header) and dN_hat/dlambda_n+1. Where both
   !> stretches are taut the closed form; where they are close, the midpoint limit
   !> W'(lambda_m)/lambda_m; otherwise the difference quotient.
   !> docs/theory.md eq. (63).
   pure subroutine discrete_gradient(ea, l0, l1, nh, dnh)
      real(wp), intent(in) :: ea, l0, l1
      real(wp), intent(out) :: nh, dnh
      real(wp) :: den, lm, phi, dphi
      if (l0 >= 1.0_wp .and. l1 >= 1.0_wp) then
         nh = ea*(l0 + l1 - 2.0_wp)/(l0 + l1)
         dnh = 2.0_wp*ea/(l0 + l1)**2
      else if (l0 <= 1.0_wp .and. l1 <= 1.0_wp) then
         nh = 0.0_wp
         dnh = 0.0_wp
      else if (abs(l1 - l0) <= 1.0e-8_wp*(l0 + l1)) then
         lm = 0.5_wp*(l0 + l1)
         call tension_law(ea, lm, phi, dphi)
         nh = phi
         dnh = 0.5_wp*dphi
      else
         den = l1**2 - l0**2
         nh = 2.0_wp*(strain_energy(ea, l1) - strain_energy(ea, l0))/den
         dnh = (2.0_wp*ea*max(l1 - 1.0_wp, 0.0_wp) - 2.0_wp*nh*l1)/den
      end if
   end subroutine discrete_gradient

   !> fe(:, a) += fg dN_a.
   pure subroutine add_force(nen, dn, fg, fe)
      integer, intent(in) :: nen
      real(wp), intent(in) :: dn(nen), fg(3)
      real(wp), intent(inout) :: fe(3, nen)
      integer :: a
      do a = 1, nen
         fe(:, a) = fe(:, a) + dn(a)*fg
      end do
   end subroutine add_force

   !> ke(a, b blocks) += wj dN_a dN_b dfg.
   pure subroutine add_tangent(nen, dn, wj, dfg, ke)
      integer, intent(in) :: nen
      real(wp), intent(in) :: dn(nen), wj, dfg(3, 3)
      real(wp), intent(inout) :: ke(:, :)
      integer :: a, b
      do b = 1, nen
         do a = 1, nen
            ke(3*a - 2:3*a, 3*b - 2:3*b) = ke(3*a - 2:3*a, 3*b - 2:3*b) + &
                                           (wj*dn(a)*dn(b))*dfg
         end do
      end do
   end subroutine add_tangent
end module rodyn_cable_element
