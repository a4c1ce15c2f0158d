!> The dissipative energy-momentum scheme: EMC with RHO INF < 1 (docs/theory.md
!> section 16, eqs. (124)-(130)).
!>
!> A numerical stress is added at each integration point of each element, for every strain
!> e (the rod's Gamma1, Gamma2, Gamma3, K1, K2, K3 where the quadrature integrates them; the
!> cable's stretch lambda):
!>   sigma_d = K0 [ c1 (de - h rho) + 2 c2 (de - h r) ]                      (eq. (126))
!> with K0 the section's stiffness of that strain (GA, EA, EI, GJ), h the step, de the
!> strain's increment over the step, rho the previous step's mean rate de/h and r the
!> trapezoidal rate, r^{n+1} = 2 de/h - r^n (eq. (125)), started from the rates of the
!> initial velocities. The element kernels (rod_element_dynamic, cable_element_dynamic)
!> add it to the EMC stress, acting through the strain Jacobian at the midpoint
!> configuration, so the step conserves linear and angular momentum as EMC does;
!> numdiss_offsets gives them the history part. Its work over a step at a constant h,
!>   sigma_d de = N^{n+1} - N^n + (c1 K0/2) (de - h rho)^2,                  (eq. (128))
!>   N = (K0 h^2/2) (c1 rho^2 + c2 r^2),
!> makes E + N non-increasing in free flight (E the kinetic and stored energy): the
!> numerical energy N is O(h^2) for a resolved motion and the loss is the square of the
!> strain rate's jump between steps, O(h^4) for a resolved motion: the scheme stays
!> second order. The coefficients c2 = 2 c1^2 and c1 from the spectral radius at
!> infinite frequency asked for (edmc_coefficients, eq. (129)); RHO INF = 1 is EMC and
!> never calls this module.
module rodyn_numerical_dissipation
   use rodyn_kinds, only: wp
   use rodyn_mesh, only: mesh_t
   use rodyn_state, only: state_t, state_gather
   use rodyn_shape, only: max_nen
   use rodyn_rotation, only: norm3
   use rodyn_rod_element, only: rod_gp_t, rod_rule_t, rod_gp_kinematics, max_points
   use rodyn_section_damping, only: rod_strain_rates
   implicit none
   private
   public :: numdiss_t, edmc_coefficients, edmc_rho_inf
   public :: numdiss_setup, numdiss_offsets, numdiss_step, numdiss_accept

   !> c1 of the lowest spectral radius at infinite frequency of the family c2 = 2 c1^2,
   !> 0.519 (edmc_rho_min rounds it up; eq. (129))
   real(wp), parameter :: edmc_c1_max = 0.086_wp

   !> The scheme's parameters and history (per element point), and its energy.
   type :: numdiss_t
      logical :: on = .false.                 !< RHO INF < 1 with EMC
      real(wp) :: c1 = 0.0_wp, c2 = 0.0_wp    !< eq. (126) [-]
      real(wp), allocatable :: rho(:, :, :)   !< (6, max_points, ne) last step's de/h
      real(wp), allocatable :: r(:, :, :)     !< (6, max_points, ne) trapezoidal rates
      real(wp), allocatable :: step_rate(:, :, :) !< (6, max_points, ne) this step's de/h
      !> c1 + 2 c2 and the step's history stress (6, max_points, ne) [N, N m]
      !> (numdiss_offsets), allocated only when on: passed to the assembly, where
      !> unallocated means absent
      real(wp), allocatable :: fac
      real(wp), allocatable :: off(:, :, :)
      !> (6, max_points, ne) scratch: the rods' strains at t_n, kept over the energy pass
      real(wp), allocatable :: eps_prev(:, :, :)
      real(wp) :: energy = 0.0_wp             !< N at t_n [J]
      real(wp) :: energy_new = 0.0_wp         !< N at t_n+1 of the step solved [J]
      real(wp) :: work_new = 0.0_wp           !< work of sigma_d over the step solved [J]
   end type numdiss_t

contains

   !> Spectral radius at infinite frequency for (c1, c2 = 2 c1^2): the largest root of
   !> (1 + 2c1 + 4c2) z^3 + (2 - 2c1 - 8c2) z^2 + (1 - 2c1 + 4c2) z + 2c1 = 0 (eq. (129)),
   !> found by the Durand-Kerner iteration.
   pure real(wp) function edmc_rho_inf(c1) result(rho)
      real(wp), intent(in) :: c1 !< [-]
      complex(wp) :: z(3), a(4), num, den
      real(wp) :: c2
      integer :: it, i, j
      c2 = 2.0_wp*c1*c1
      a = [cmplx(1.0_wp + 2.0_wp*c1 + 4.0_wp*c2, 0.0_wp, wp), &
           cmplx(2.0_wp - 2.0_wp*c1 - 8.0_wp*c2, 0.0_wp, wp), &
           cmplx(1.0_wp - 2.0_wp*c1 + 4.0_wp*c2, 0.0_wp, wp), cmplx(2.0_wp*c1, 0.0_wp, wp)]
      a = a/a(1)
      z = [(cmplx(0.4_wp, 0.9_wp, wp)**i, i=0, 2)]
      do it = 1, 500
         do i = 1, 3
            num = ((z(i) + a(2))*z(i) + a(3))*z(i) + a(4)
            den = (1.0_wp, 0.0_wp)
            do j = 1, 3
               if (j /= i) den = den*(z(i) - z(j))
            end do
            z(i) = z(i) - num/den
         end do
      end do
      rho = maxval(abs(z))
   end function edmc_rho_inf

   !> c1 and c2 = 2 c1^2 for a spectral radius rho_inf in [edmc_rho_min, 1] at infinite
   !> frequency (bisection on c1 in [0, edmc_c1_max], where edmc_rho_inf falls
   !> monotonically from 1). eq. (129).
   pure subroutine edmc_coefficients(rho_inf, c1, c2)
      real(wp), intent(in) :: rho_inf !< [-]
      real(wp), intent(out) :: c1     !< [-]
      real(wp), intent(out) :: c2     !< [-]
      real(wp) :: lo, hi
      integer :: it
      lo = 0.0_wp
      hi = edmc_c1_max
      do it = 1, 60
         c1 = 0.5_wp*(lo + hi)
         if (edmc_rho_inf(c1) > rho_inf) then
            lo = c1
         else
            hi = c1
         end if
      end do
      c1 = 0.5_wp*(lo + hi)
      if (rho_inf >= 1.0_wp) c1 = 0.0_wp
      c2 = 2.0_wp*c1*c1
   end subroutine edmc_coefficients

   !> Set up for a run (rho_inf < 1): coefficients, and the rates of the initial state's
   !> velocities as both histories (eq. (125)); N^0 with the step dt.
   subroutine numdiss_setup(nd, mesh, s0, rho_inf, dt)
      type(numdiss_t), intent(inout) :: nd   !< scheme data
      type(mesh_t), intent(in) :: mesh       !< mesh
      type(state_t), intent(in) :: s0        !< start state (x, d, v, dd)
      real(wp), intent(in) :: rho_inf        !< spectral radius at infinite frequency [-]
      real(wp), intent(in) :: dt             !< step [s]
      nd%on = rho_inf < 1.0_wp
      if (.not. nd%on) return
      call edmc_coefficients(rho_inf, nd%c1, nd%c2)
      allocate (nd%rho(6, max_points, mesh%n_elements), nd%r(6, max_points, mesh%n_elements), &
                nd%step_rate(6, max_points, mesh%n_elements), &
                nd%off(6, max_points, mesh%n_elements), &
                nd%eps_prev(6, max_points, mesh%n_elements))
      nd%fac = nd%c1 + 2.0_wp*nd%c2
      call point_rates(mesh, s0, s0, 1.0_wp, .true., nd%r)
      nd%rho = nd%r
      nd%energy = history_energy(nd, mesh, dt, nd%rho, nd%r)
   end subroutine numdiss_setup

   !> The history stress of every point for the step t_n -> t_n + dt,
   !> off = K0 dt (c1 rho^n + 2 c2 r^n) (eq. (126)): the element kernels
   !> (rod_element_dynamic, cable_element_dynamic) add kd (eps^{n+1} - eps^n) - off with
   !> kd = K0 fac, fac = c1 + 2 c2, to the EMC stress, and its modulus to the tangent.
   subroutine numdiss_offsets(nd, mesh, dt)
      type(numdiss_t), intent(inout) :: nd   !< scheme data (off set)
      type(mesh_t), intent(in) :: mesh       !< mesh
      real(wp), intent(in) :: dt             !< step [s]
      integer :: e, g
      do e = 1, mesh%n_elements
         do g = 1, max_points
            nd%off(:, g, e) = dt*mesh%elem_c(:, e)*(nd%c1*nd%rho(:, g, e) &
                                                    + 2.0_wp*nd%c2*nd%r(:, g, e))
         end do
      end do
   end subroutine numdiss_offsets

   !> For a converged step: its mean strain rates, the work of sigma_d over it and N^{n+1}
   !> (eqs. (126), (128)); the histories are advanced by numdiss_accept.
   subroutine numdiss_step(nd, mesh, s0, s1, dt, eps0, eps1)
      type(numdiss_t), intent(inout) :: nd   !< scheme data
      type(mesh_t), intent(in) :: mesh       !< mesh
      type(state_t), intent(in) :: s0        !< state at t_n
      type(state_t), intent(in) :: s1        !< converged state at t_n+1
      real(wp), intent(in) :: dt             !< step [s]
      !> (6, max_points, ne) the rods' strains at t_n and t_n+1 at their points, when
      !> formed already (the energy pass): their difference is the rods' increment
      real(wp), intent(in), optional :: eps0(:, :, :), eps1(:, :, :)
      real(wp) :: w, en, k0(6), sd(6), m(6), wj, de(6), r1(6)
      integer :: e, p, ig, np
      call point_rates(mesh, s0, s1, dt, .false., nd%step_rate, &
                       present(eps0) .and. present(eps1))
      if (present(eps0) .and. present(eps1)) then
         do e = 1, mesh%n_elements
            if (.not. mesh%elem_cable(e)) nd%step_rate(:, :, e) = (eps1(:, :, e) - &
                                                                   eps0(:, :, e))/dt
         end do
      end if
      ! the work of sigma_d over the step and N^{n+1}, with r^{n+1} = 2 de/h - r^n
      w = 0.0_wp
      en = 0.0_wp
      do e = 1, mesh%n_elements
         p = mesh%line_order(mesh%elem_line(e))
         k0 = mesh%elem_c(:, e)
         call point_set(mesh, e, np)
         do ig = 1, np
            call point_mask(mesh, e, ig, m)
            wj = mesh%rules(p)%w(ig)*0.5_wp*mesh%elem_le(e)
            de = dt*nd%step_rate(:, ig, e)
            sd = k0*m*(nd%c1*(de - dt*nd%rho(:, ig, e)) &
                       + 2.0_wp*nd%c2*(de - dt*nd%r(:, ig, e)))
            w = w + wj*dot_product(sd, de)
            r1 = 2.0_wp*nd%step_rate(:, ig, e) - nd%r(:, ig, e)
            en = en + wj*0.5_wp*dt**2*sum(k0*m*(nd%c1*nd%step_rate(:, ig, e)**2 &
                                                + nd%c2*r1**2))
         end do
      end do
      nd%work_new = w
      nd%energy_new = en
   end subroutine numdiss_step

   !> Advance the histories past the step numdiss_step measured (eq. (125)).
   subroutine numdiss_accept(nd)
      type(numdiss_t), intent(inout) :: nd !< scheme data
      nd%r = 2.0_wp*nd%step_rate - nd%r
      nd%rho = nd%step_rate
      nd%energy = nd%energy_new
   end subroutine numdiss_accept

   !> N = sum over the points of wj (K0 h^2/2) (c1 rho^2 + c2 r^2) (eq. (128)).
   function history_energy(nd, mesh, dt, rho, r) result(en)
      type(numdiss_t), intent(in) :: nd      !< scheme data
      type(mesh_t), intent(in) :: mesh       !< mesh
      real(wp), intent(in) :: dt             !< step [s]
      real(wp), intent(in) :: rho(:, :, :)   !< mean rates
      real(wp), intent(in) :: r(:, :, :)     !< trapezoidal rates
      real(wp) :: en
      real(wp) :: m(6), wj
      integer :: e, p, ig, np
      en = 0.0_wp
      do e = 1, mesh%n_elements
         p = mesh%line_order(mesh%elem_line(e))
         call point_set(mesh, e, np)
         do ig = 1, np
            call point_mask(mesh, e, ig, m)
            wj = mesh%rules(p)%w(ig)*0.5_wp*mesh%elem_le(e)
            en = en + wj*0.5_wp*dt**2*sum(mesh%elem_c(:, e)*m*(nd%c1*rho(:, ig, e)**2 &
                                                               + nd%c2*r(:, ig, e)**2))
         end do
      end do
   end function history_energy

   !> The points of element e the scheme uses: the rod's rule, the cable's first p.
   pure subroutine point_set(mesh, e, np)
      type(mesh_t), intent(in) :: mesh !< mesh
      integer, intent(in) :: e         !< element
      integer, intent(out) :: np       !< points
      np = mesh%line_order(mesh%elem_line(e))
      if (.not. mesh%elem_cable(e)) np = mesh%rules(np)%np
   end subroutine point_set

   !> The strains integrated at point ig of element e (the cable: its stretch, slot 3).
   pure subroutine point_mask(mesh, e, ig, m)
      type(mesh_t), intent(in) :: mesh !< mesh
      integer, intent(in) :: e         !< element
      integer, intent(in) :: ig        !< point
      real(wp), intent(out) :: m(6)    !< 1 where integrated
      if (mesh%elem_cable(e)) then
         m = [0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
      else
         m = mesh%rules(mesh%line_order(mesh%elem_line(e)))%mask(:, ig)
      end if
   end subroutine point_mask

   !> Strain rates at every point: with start, the rates of the velocities of sa
   !> (B(q) v); else the mean rates (eps(sb) - eps(sa))/dt of a step, B(q^{n+1/2})
   !> (q^{n+1} - q^n)/dt for the rod (exact: its strains are quadratic) and (lambda^{n+1}
   !> - lambda^n)/dt for the cable.
   subroutine point_rates(mesh, sa, sb, dt, start, rate, cables_only)
      type(mesh_t), intent(in) :: mesh          !< mesh
      type(state_t), intent(in) :: sa           !< state at t_n (or the start)
      type(state_t), intent(in) :: sb           !< state at t_n+1 (unused with start)
      real(wp), intent(in) :: dt                !< step [s] (unused with start)
      logical, intent(in) :: start              !< rates of the velocities of sa
      real(wp), intent(inout) :: rate(:, :, :)  !< (6, max_points, ne)
      logical, intent(in), optional :: cables_only !< leave the rods' rates as they are
      real(wp) :: x0(3, max_nen), x1(3, max_nen), d0(3, 3, max_nen), d1(3, 3, max_nen)
      real(wp) :: xf(3, max_nen), df(3, 3, max_nen), ux(3, max_nen), ud(3, 3, max_nen)
      real(wp) :: dn(max_nen), xp0(3), xp1(3)
      type(rod_gp_t) :: kf, ku
      integer :: e, p, nen, ig
      do e = 1, mesh%n_elements
         p = mesh%line_order(mesh%elem_line(e))
         nen = p + 1
         associate (nodes => mesh%elem_nodes(1:nen, e), rule => mesh%rules(p))
            if (mesh%elem_cable(e)) then
               rate(:, :, e) = 0.0_wp
               call cable_rates(nen, nodes, rule, mesh%elem_le(e))
               cycle
            end if
            if (present(cables_only)) then
               if (cables_only) cycle
            end if
            rate(:, :, e) = 0.0_wp
            call state_gather(sa, nodes, x0, d0)
            if (start) then
               xf(:, 1:nen) = x0(:, 1:nen)
               df(:, :, 1:nen) = d0(:, :, 1:nen)
               ux(:, 1:nen) = sa%v(:, nodes)
               ud(:, :, 1:nen) = sa%dd(:, :, nodes)
            else
               call state_gather(sb, nodes, x1, d1)
               xf(:, 1:nen) = 0.5_wp*(x0(:, 1:nen) + x1(:, 1:nen))
               df(:, :, 1:nen) = 0.5_wp*(d0(:, :, 1:nen) + d1(:, :, 1:nen))
               ux(:, 1:nen) = (x1(:, 1:nen) - x0(:, 1:nen))/dt
               ud(:, :, 1:nen) = (d1(:, :, 1:nen) - d0(:, :, 1:nen))/dt
            end if
            do ig = 1, rule%np
               dn(1:nen) = rule%dn(1:nen, ig)*2.0_wp/mesh%elem_le(e)
               call rod_gp_kinematics(nen, rule%n(1:nen, ig), dn(1:nen), xf(:, 1:nen), &
                                      df(:, :, 1:nen), kf)
               call rod_gp_kinematics(nen, rule%n(1:nen, ig), dn(1:nen), ux(:, 1:nen), &
                                      ud(:, :, 1:nen), ku)
               rate(:, ig, e) = rod_strain_rates(kf, ku)
            end do
         end associate
      end do
   contains
      !> The stretch rates of cable element e (slot 3) at its first p points.
      subroutine cable_rates(nen, nodes, rule, le)
         integer, intent(in) :: nen            !< nodes of the element
         integer, intent(in) :: nodes(nen)     !< its global nodes
         type(rod_rule_t), intent(in) :: rule  !< its rule
         real(wp), intent(in) :: le            !< its length [m]
         integer :: a
         do ig = 1, nen - 1
            dn(1:nen) = rule%dn(1:nen, ig)*2.0_wp/le
            xp0 = 0.0_wp
            xp1 = 0.0_wp
            do a = 1, nen
               xp0 = xp0 + dn(a)*sa%x(:, nodes(a))
               if (start) then
                  xp1 = xp1 + dn(a)*sa%v(:, nodes(a))
               else
                  xp1 = xp1 + dn(a)*sb%x(:, nodes(a))
               end if
            end do
            if (start) then
               if (norm3(xp0) > 0.0_wp) rate(3, ig, e) = dot_product(xp0, xp1)/norm3(xp0)
            else
               rate(3, ig, e) = (norm3(xp1) - norm3(xp0))/dt
            end if
         end do
      end subroutine cable_rates
   end subroutine point_rates
end module rodyn_numerical_dissipation
