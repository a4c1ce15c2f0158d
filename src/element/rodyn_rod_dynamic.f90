!> Internal force of the director rod over a time step (formulation note sections 3-4),
!> projected with the midpoint directors d^{n+1/2} = (d^n + d^{n+1})/2, and its tangent
!> with respect to the unknowns at n+1 (dx, dtheta; dd^{n+1} = dtheta x d^{n+1}):
!>   EMC          S = C ((eps(q^n) + eps(q^{n+1}))/2 - eps0), B at q^{n+1/2}
!>   MIDPOINT     S = C (eps(q^{n+1/2}) - eps0),                B at q^{n+1/2}
!>   TRAPEZOIDAL  f = (f(q^n) + f(q^{n+1}))/2
!>   ALPHA        S = C (eps(q_f) - eps0), B at q_f = (1 - w) q^n + w q^{n+1}, w = 1 - alpha_f
!>                (generalized-alpha; the projection uses the directors of q_f too)
!> With the EMC choice the work of the internal force over the step equals the change of
!> stored energy exactly (strains quadratic in q), the root of energy conservation.
module rodyn_rod_dynamic
   use rodyn_kinds, only: wp
   use rodyn_model, only: scheme_emc, scheme_midpoint, scheme_trapezoidal, scheme_alpha
   use rodyn_shape, only: max_nen
   use rodyn_rod_element, only: rod_gp_t, rod_gp_kinematics, rod_strains, rod_gp_qforce, &
                                rod_gp_jacobian, rod_gp_geometric, rod_project_qforce, &
                                rod_rotation_geometric, rod_rule_t, max_points, &
                                rod_gp_kinematics_shear, rod_strains_shear, &
                                rod_gp_qforce_shear, rod_gp_jacobian_shear
   implicit none
   private
   public :: rod_element_dynamic

contains

   !> Step internal force fe (6, p+1) and tangent ke of one element for a scheme.
   pure subroutine rod_element_dynamic(p, le, c, eps0, x0, d0, x1, d1, scheme, wf, fe, ke, &
                                       want_k, rule)
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
      real(wp) :: n(max_nen), dn(max_nen), wj, cg(6), s(6), s1(6)
      real(wp) :: xm(3, max_nen), dm(3, 3, max_nen), fq(3, 4, max_nen)
      real(wp) :: bl(6, 6*max_nen), br(6, 6*max_nen)
      type(rod_gp_t) :: k0, k1, km
      real(wp) :: wq, sh(2), sh1(2)
      integer :: g, nen, nd, np
      nen = p + 1
      nd = 6*nen
      ! evaluation point: the midpoint, or q_f for the generalized-alpha scheme
      wq = 0.5_wp
      if (scheme == scheme_alpha) wq = wf
      xm(:, 1:nen) = (1.0_wp - wq)*x0 + wq*x1
      dm(:, :, 1:nen) = (1.0_wp - wq)*d0 + wq*d1
      np = rule%np
      fq(:, :, 1:nen) = 0.0_wp
      if (want_k) ke(1:nd, 1:nd) = 0.0_wp
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
            select case (scheme)
            case (scheme_midpoint, scheme_alpha)
               call rod_gp_kinematics_shear(nen, n(1:nen), dn(1:nen), xm(:, 1:nen), &
                                            dm(:, :, 1:nen), km)
               sh = cg(1:2)*(rod_strains_shear(km) - eps0(1:2, g))
               call rod_gp_qforce_shear(nen, n(1:nen), dn(1:nen), km, sh, wj, fq(:, :, 1:nen))
               if (.not. want_k) cycle
               call rod_gp_jacobian_shear(nen, n(1:nen), dn(1:nen), km, dm(:, :, 1:nen), &
                                          bl(:, 1:nd))
               call rod_gp_jacobian_shear(nen, n(1:nen), dn(1:nen), km, d1, br(:, 1:nd))
               call add_material(nd, cg, bl, br, wq*wj, ke)
               s(1:2) = sh
               call rod_gp_geometric(nen, n(1:nen), dn(1:nen), s, dm(:, :, 1:nen), d1, &
                                     wq*wj, ke(1:nd, 1:nd))
            case (scheme_trapezoidal)
               call rod_gp_kinematics_shear(nen, n(1:nen), dn(1:nen), x0, d0, k0)
               sh = cg(1:2)*(rod_strains_shear(k0) - eps0(1:2, g))
               sh1 = cg(1:2)*(rod_strains_shear(k1) - eps0(1:2, g))
               call rod_gp_qforce_shear(nen, n(1:nen), dn(1:nen), k0, sh, 0.5_wp*wj, &
                                        fq(:, :, 1:nen))
               call rod_gp_qforce_shear(nen, n(1:nen), dn(1:nen), k1, sh1, 0.5_wp*wj, &
                                        fq(:, :, 1:nen))
               if (.not. want_k) cycle
               call rod_gp_jacobian_shear(nen, n(1:nen), dn(1:nen), k1, dm(:, :, 1:nen), &
                                          bl(:, 1:nd))
               call rod_gp_jacobian_shear(nen, n(1:nen), dn(1:nen), k1, d1, br(:, 1:nd))
               call add_material(nd, cg, bl, br, 0.5_wp*wj, ke)
               s(1:2) = sh1
               call rod_gp_geometric(nen, n(1:nen), dn(1:nen), s, dm(:, :, 1:nen), d1, &
                                     0.5_wp*wj, ke(1:nd, 1:nd))
            case default ! scheme_emc
               call rod_gp_kinematics_shear(nen, n(1:nen), dn(1:nen), x0, d0, k0)
               km%xp = 0.5_wp*(k0%xp + k1%xp)
               km%d(:, 1:2) = 0.5_wp*(k0%d(:, 1:2) + k1%d(:, 1:2))
               sh = cg(1:2)*(0.5_wp*(rod_strains_shear(k0) + rod_strains_shear(k1)) &
                             - eps0(1:2, g))
               call rod_gp_qforce_shear(nen, n(1:nen), dn(1:nen), km, sh, wj, fq(:, :, 1:nen))
               if (.not. want_k) cycle
               call rod_gp_jacobian_shear(nen, n(1:nen), dn(1:nen), km, dm(:, :, 1:nen), &
                                          bl(:, 1:nd))
               call rod_gp_jacobian_shear(nen, n(1:nen), dn(1:nen), k1, d1, br(:, 1:nd))
               call add_material(nd, cg, bl, br, 0.5_wp*wj, ke)
               s(1:2) = sh
               call rod_gp_geometric(nen, n(1:nen), dn(1:nen), s, dm(:, :, 1:nen), d1, &
                                     0.5_wp*wj, ke(1:nd, 1:nd))
            end select
            cycle
         end if
         call rod_gp_kinematics(nen, n(1:nen), dn(1:nen), x1, d1, k1)
         select case (scheme)
         case (scheme_midpoint, scheme_alpha)
            call rod_gp_kinematics(nen, n(1:nen), dn(1:nen), xm(:, 1:nen), dm(:, :, 1:nen), km)
            s = cg*(rod_strains(km) - eps0(:, g))
            call rod_gp_qforce(nen, n(1:nen), dn(1:nen), km, s, wj, fq(:, :, 1:nen))
            if (.not. want_k) cycle
            call rod_gp_jacobian(nen, n(1:nen), dn(1:nen), km, dm(:, :, 1:nen), bl(:, 1:nd))
            call rod_gp_jacobian(nen, n(1:nen), dn(1:nen), km, d1, br(:, 1:nd))
            call add_material(nd, cg, bl, br, wq*wj, ke)
            call rod_gp_geometric(nen, n(1:nen), dn(1:nen), s, dm(:, :, 1:nen), d1, &
                                  wq*wj, ke(1:nd, 1:nd))
         case (scheme_trapezoidal)
            call rod_gp_kinematics(nen, n(1:nen), dn(1:nen), x0, d0, k0)
            s = cg*(rod_strains(k0) - eps0(:, g))
            s1 = cg*(rod_strains(k1) - eps0(:, g))
            call rod_gp_qforce(nen, n(1:nen), dn(1:nen), k0, s, 0.5_wp*wj, fq(:, :, 1:nen))
            call rod_gp_qforce(nen, n(1:nen), dn(1:nen), k1, s1, 0.5_wp*wj, fq(:, :, 1:nen))
            if (.not. want_k) cycle
            call rod_gp_jacobian(nen, n(1:nen), dn(1:nen), k1, dm(:, :, 1:nen), bl(:, 1:nd))
            call rod_gp_jacobian(nen, n(1:nen), dn(1:nen), k1, d1, br(:, 1:nd))
            call add_material(nd, cg, bl, br, 0.5_wp*wj, ke)
            call rod_gp_geometric(nen, n(1:nen), dn(1:nen), s1, dm(:, :, 1:nen), d1, &
                                  0.5_wp*wj, ke(1:nd, 1:nd))
         case default ! scheme_emc
            call rod_gp_kinematics(nen, n(1:nen), dn(1:nen), x0, d0, k0)
            ! the fields are linear in the nodal values: midpoint = mean of the ends
            km%xp = 0.5_wp*(k0%xp + k1%xp)
            km%d = 0.5_wp*(k0%d + k1%d)
            km%dp = 0.5_wp*(k0%dp + k1%dp)
            s = cg*(0.5_wp*(rod_strains(k0) + rod_strains(k1)) - eps0(:, g))
            call rod_gp_qforce(nen, n(1:nen), dn(1:nen), km, s, wj, fq(:, :, 1:nen))
            if (.not. want_k) cycle
            call rod_gp_jacobian(nen, n(1:nen), dn(1:nen), km, dm(:, :, 1:nen), bl(:, 1:nd))
            call rod_gp_jacobian(nen, n(1:nen), dn(1:nen), k1, d1, br(:, 1:nd))
            call add_material(nd, cg, bl, br, 0.5_wp*wj, ke)
            call rod_gp_geometric(nen, n(1:nen), dn(1:nen), s, dm(:, :, 1:nen), d1, &
                                  0.5_wp*wj, ke(1:nd, 1:nd))
         end select
      end do
      call rod_project_qforce(nen, fq(:, :, 1:nen), dm(:, :, 1:nen), fe)
      if (want_k) call rod_rotation_geometric(nen, fq(:, :, 1:nen), d1, wq, ke(1:nd, 1:nd))
   end subroutine rod_element_dynamic
   !> ke += f bl^T diag(cg) br over the strains integrated at the point (cg /= 0).
   pure subroutine add_material(nd, cg, bl, br, f, ke)
      integer, intent(in) :: nd            !< element unknowns
      real(wp), intent(in) :: cg(6)        !< stiffness of the strains integrated here
      real(wp), intent(in) :: bl(:, :)     !< (6, >= nd) test-side strain Jacobian
      real(wp), intent(in) :: br(:, :)     !< (6, >= nd) increment-side strain Jacobian
      real(wp), intent(in) :: f            !< weight
      real(wp), intent(inout) :: ke(:, :)  !< element matrix
      real(wp) :: blt(6*max_nen, 6), cr(6, 6*max_nen)
      integer :: j, k, nk
      ! active rows only, bl transposed so that the update runs down contiguous columns
      nk = 0
      do k = 1, 6
         if (cg(k) == 0.0_wp) cycle
         nk = nk + 1
         blt(1:nd, nk) = bl(k, 1:nd)
         cr(nk, 1:nd) = (f*cg(k))*br(k, 1:nd)
      end do
      do j = 1, nd
         do k = 1, nk
            ke(1:nd, j) = ke(1:nd, j) + blt(1:nd, k)*cr(k, j)
         end do
      end do
   end subroutine add_material
end module rodyn_rod_dynamic
