!> The energy and momentum balance of a dynamic step (docs/theory.md eqs. (41)-(43)):
!> the energies and momenta of a state, and the works of the supports and point loads,
!> damping, the water and the seabed over the step just solved. The time loop
!> (rodyn_timeloop) books them into each step's log.
module rodyn_step_energy
   use rodyn_kinds, only: wp
   use rodyn_dynamics, only: dynamic_problem_t, dynamics_strain_energy, mesh_strain_energy
   use rodyn_inertia, only: kinetic_energy, linear_momentum, angular_momentum
   use rodyn_rotation, only: rotation_cayley_inverse, relative_rotation
   use rodyn_results, only: step_log_t
   implicit none
   private
   public :: step_energies, converged_energies, step_work

contains

   !> Energies and momenta of the iterate state into log (work terms untouched).
   !> docs/theory.md eqs. (41)-(42).
   subroutine step_energies(prob, log)
      type(dynamic_problem_t), intent(in) :: prob !< problem
      type(step_log_t), intent(inout) :: log      !< filled
      call mesh_strain_energy(prob%mesh, prob%s1, log%strain, log%strain_scale)
      call other_energies(prob, log)
   end subroutine step_energies

   !> step_energies of a converged step, whose pass over the rods also keeps their
   !> fields of s1 for the next step (dynamics_strain_energy).
   subroutine converged_energies(prob, log)
      type(dynamic_problem_t), intent(inout) :: prob !< problem (s1 converged)
      type(step_log_t), intent(inout) :: log         !< filled
      call dynamics_strain_energy(prob, log%strain, log%strain_scale)
      call other_energies(prob, log)
   end subroutine converged_energies

   !> The energies and momenta of step_energies other than the stored energy.
   subroutine other_energies(prob, log)
      type(dynamic_problem_t), intent(in) :: prob !< problem
      type(step_log_t), intent(inout) :: log      !< log%strain filled
      log%kinetic = kinetic_energy(prob%inert, prob%s1)
      log%gravity = -sum(prob%loads%gravity*prob%s1%x)
      log%total = log%kinetic + log%strain + log%gravity
      log%momentum = linear_momentum(prob%inert, prob%s1)
      log%angular_momentum = angular_momentum(prob%inert, prob%s1)
   end subroutine other_energies

   !> Work of supports and point loads, and work of damping, over the step just solved.
   !> docs/theory.md eq. (43).
   subroutine step_work(prob, w_ext, w_damp, w_hydro, w_seabed)
      type(dynamic_problem_t), intent(in) :: prob !< problem (converged step)
      real(wp), intent(out) :: w_ext              !< external work [J]
      real(wp), intent(out) :: w_damp             !< energy taken by damping [J]
      real(wp), intent(out) :: w_hydro            !< work of the water [J]
      real(wp), intent(out) :: w_seabed           !< work of the seabed [J]
      real(wp) :: dx(3), th(3), grav(3)
      integer :: node, i
      w_ext = 0.0_wp
      w_damp = 0.0_wp
      w_hydro = 0.0_wp
      w_seabed = 0.0_wp
      if (prob%water%active) then
         w_hydro = sum(prob%water%fh*prob%dx)
         w_seabed = sum(prob%water%fs*prob%dx)
      end if
      ! the bodies' buoyancy and waterplane (water), the moment of their loads at R
      do i = 1, prob%bl%nb
         node = prob%bl%node(i)
         th = rotation_cayley_inverse(relative_rotation(prob%s1%d(:, :, node), &
                                                        prob%s0%d(:, :, node)))
         w_hydro = w_hydro + dot_product(prob%bl%fh(1:3, i), prob%dx(:, node)) &
                   + dot_product(prob%bl%fh(4:6, i), th)
         w_ext = w_ext + dot_product(prob%bl%fe(:, i), th)
         w_damp = w_damp - dot_product(prob%bl%fd(1:3, i), prob%dx(:, node)) &
                  - dot_product(prob%bl%fd(4:6, i), th)
      end do
      ! a held body moved (*MOTION, BODY=): the work of its line ends' forces
      do i = 1, prob%jn%ns
         if (.not. prob%jn%s_on(i)) cycle
         if (.not. prob%jn%held(prob%jn%m_j0(prob%jn%s_m(i)) + 1)) cycle
         node = prob%jn%s_node(i)
         w_ext = w_ext + dot_product(prob%r(1:3, node), prob%dx(:, node))
         if (prob%jn%s_ne(i) == 6) w_ext = w_ext + dot_product(prob%r(4:6, node), &
            rotation_cayley_inverse(relative_rotation(prob%s1%d(:, :, node), &
                                                      prob%s0%d(:, :, node))))
      end do
      do node = 1, prob%mesh%n_nodes
         dx = prob%dx(:, node)
         grav = prob%loads%gravity(:, node)
         ! point loads (external force beyond the weight) and supports (the residual)
         w_ext = w_ext + dot_product(prob%fext(1:3, node) - grav, dx)
         if (any(prob%fext(4:6, node) /= 0.0_wp) .or. prob%sup%held(4, node)) then
            th = rotation_cayley_inverse(relative_rotation(prob%s1%d(:, :, node), &
                                                   prob%s0%d(:, :, node)))
            w_ext = w_ext + dot_product(prob%fext(4:6, node), th)
            if (prob%sup%held(4, node)) w_ext = w_ext + dot_product(prob%r(4:6, node), th)
         end if
         if (prob%sup%held(1, node)) w_ext = w_ext + dot_product(prob%r(1:3, node), dx)
         if (prob%beta_d > 0.0_wp .or. prob%mesh%damped) then
            th = rotation_cayley_inverse(relative_rotation(prob%s1%d(:, :, node), &
                                                   prob%s0%d(:, :, node)))
            w_damp = w_damp + dot_product(prob%fdamp(1:3, node), dx) &
                     + dot_product(prob%fdamp(4:6, node), th)
         end if
         if (prob%alpha > 0.0_wp) then
            w_damp = w_damp + prob%alpha*prob%inert%m(node)*dot_product(dx, dx)/prob%dt
            do i = 1, 3
               w_damp = w_damp + prob%alpha*prob%inert%md(i, node)/prob%dt* &
                        sum((prob%s1%d(:, i, node) - prob%s0%d(:, i, node))**2)
            end do
         end if
      end do
   end subroutine step_work
end module rodyn_step_energy
