!> One time step of the rod dynamics (docs/theory.md sections 5 and 7), solved by Newton:
!> for every free node a, with velocities updated by the midpoint relations
!>   v^{n+1} = 2/dt (x^{n+1} - x^n) - v^n,    ddot_i^{n+1} = 2/dt (d_i^{n+1} - d_i^n) - ddot_i^n,
!> the residual
!>   r_x = m_a (v^{n+1} - v^n)/dt + f_x - f_ext(t_{n+1/2}) + alpha m_a (x^{n+1} - x^n)/dt
!>   r_theta = sum_i d_i^{n+1/2} x [M_ia (ddot_i^{n+1} - ddot_i^n)/dt
!>             + alpha M_ia (d_i^{n+1} - d_i^n)/dt] + f_theta - m_ext(t_{n+1/2})
!> vanishes (eqs. (37)-(39); f: the step internal force of the scheme, rodyn_rod_dynamic;
!> alpha: Rayleigh mass-proportional damping; f also holds the sections' structural
!> damping, rodyn_assembly_damping, eqs. (116)-(121)). Held nodes follow their prescribed
!> position at t_{n+1}; a clamped end on a vessel and a body moved with one also their
!> directors d_i^{n+1} = Q(t_{n+1}) d_i(0), Q the vessel's turn since rest (rodyn_motion's
!> motion_rotation), set in the predictor and kept by the held rotation unknowns. The
!> rotation rows are projected with the midpoint directors: no Lagrange multipliers of
!> the orthonormality constraints appear (discrete null-space method).
!>
!> SCHEME=ALPHA is the generalized-alpha method (Chung & Hulbert, J. Appl. Mech. 60, 1993;
!> docs/theory.md eqs. (56)-(60))
!> on the director coordinates, whose mass matrix is constant: inertia at t_{n+1-alpha_m},
!> forces at q_f = alpha_f q^n + (1 - alpha_f) q^{n+1} (projection with its directors),
!> Newmark updates a^{n+1} = (q^{n+1} - q^n - dt v^n - dt^2 (1/2 - beta) a^n)/(beta dt^2),
!> v^{n+1} = v^n + dt ((1 - gamma) a^n + gamma a^{n+1}), and
!>   alpha_m = (2 rho - 1)/(rho + 1), alpha_f = rho/(rho + 1),
!>   gamma = 1/2 - alpha_m + alpha_f, beta = (1 - alpha_m + alpha_f)^2/4:
!> second order, spectral radius rho = rho_inf at infinite frequency; rho = 1 is the
!> undamped average-acceleration rule.
!> The step displacement dx = x^{n+1} - x^n is carried as such (predictor plus Newton
!> corrections), never recovered as a difference of positions: far from the origin that
!> difference loses eps |x| / dt of velocity per step, and the angular momentum of a rod
!> flying away from the origin would drift.
module rodyn_dynamics
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, end_a, end_b, scheme_alpha, scheme_emc, scheme_trapezoidal, &
                          motion_vessel, vessel_t
   use rodyn_mesh, only: mesh_t, mesh_node
   use rodyn_state, only: state_t, state_allocate, state_copy, state_gather, copy_values
   use rodyn_rod_element, only: rod_gp_t, max_points, rod_element_fields, &
                                rod_element_energy_scale, rod_energy_of_strains
   use rodyn_cable_element, only: cable_element_energy_scale
   use rodyn_shape, only: max_nen
   use rodyn_assembly, only: supports_t, loads_t, supports_build, loads_build, &
                             assemble_dynamic, apply_supports, add_node_block, &
                             external_force, assemble_water, assemble_dynamic_cables
   use rodyn_roll_gauges, only: roll_gauges, add_roll_gauges
   use rodyn_assembly_damping, only: section_damping_rates, assemble_section_damping
   use rodyn_numerical_dissipation, only: numdiss_t, numdiss_setup, numdiss_offsets, &
                                          numdiss_accept
   use rodyn_water, only: water_loads_t, water_loads_build, water_set_time
   use rodyn_bodies, only: body_water_set
   use rodyn_rod_problem, only: rod_problem_t, rod_problem_init
   use rodyn_banded, only: banded_set_pivoting
   use rodyn_anderson, only: anderson_init
   use rodyn_junctions, only: junctions_condense, junctions_place, junctions_clamp
   use rodyn_system_dynamics, only: point_velocities, added_mass_force, added_mass_emc, &
                                    failures_t, failures_build, failures_step, &
                                    body_waves_start, motion_nodes, held_motion
   use rodyn_assembly_bodies, only: assemble_bodies
   use rodyn_rotation, only: cross
   use rodyn_inertia, only: inertia_t, inertia_build
   use rodyn_motion, only: vessel_offset_rest
   implicit none
   private
   public :: dynamic_problem_t, dynamics_setup, dynamics_begin_step, dynamics_end_step
   public :: dynamics_accept_step, dynamics_strain_energy
   public :: mesh_strain_energy

   !> Columns of the Anderson history of the step's chord iterations (rodyn_anderson;
   !> docs/theory.md eq. (53)); deeper histories gain little (docs/benchmarks.md)
   integer, parameter :: anderson_depth = 3

   !> The step problem and its workspace (allocated once in dynamics_setup).
   type, extends(rod_problem_t) :: dynamic_problem_t
      type(model_t), pointer :: model => null()
      type(failures_t) :: fl                   !< line ends that fail (*FAILURE)
      type(state_t), pointer :: s1 => null()   !< state at t_n+1 (the iterate)
      type(state_t) :: s0                      !< state at t_n
      type(loads_t) :: loads
      type(water_loads_t) :: water             !< water and seabed (scene in water only)
      real(wp), allocatable :: xf(:, :)        !< (3, nn) positions at the force point [m]
      real(wp), allocatable :: vf(:, :)        !< (3, nn) velocities at the force point [m/s]
      real(wp), allocatable :: af_acc(:, :)    !< (3, nn) accelerations of the scheme [m/s2]
      real(wp), allocatable :: gfac(:)         !< (0:nl) ones: the weight in full
      type(inertia_t) :: inert
      !> roll gauges (rodyn_statics' header) of the runs of rod elements whose roll has
      !> no inertia (no OD, no RHOI) nor support: node (0 after the last), stiffness
      integer, allocatable :: gauge_node(:)
      real(wp), allocatable :: gauge_k(:)      !< [N m/rad]
      integer :: scheme = 1
      real(wp) :: alpha = 0.0_wp               !< Rayleigh mass-proportional damping [1/s]
      real(wp) :: beta_d = 0.0_wp              !< Rayleigh stiffness-proportional damping [s]
      real(wp) :: wf = 0.5_wp                  !< weight of t_n+1 in the force point
      real(wp) :: am = 0.5_wp, af = 0.5_wp     !< generalized-alpha alpha_m, alpha_f
      real(wp) :: beta_n = 0.25_wp, gamma_n = 0.5_wp !< Newmark beta, gamma
      real(wp) :: t0 = 0.0_wp                  !< time t_n [s]
      real(wp) :: dt = 0.0_wp                  !< step [s]
      integer, allocatable :: motion_node(:)   !< (nm) each node moved by a *MOTION
      integer, allocatable :: motion_of(:)     !< (nm) its motion (model%motions; a point's
                                               !< moves the line ends on it)
      real(wp), allocatable :: x_start(:, :)   !< (3, nn) positions at t = 0 [m]
      !> (n motions) the motion's node is clamped on a vessel: its directors follow the
      !> vessel's turn, d_i = Q(t) d_i(0) (rodyn_motion's motion_rotation)
      logical, allocatable :: motion_turns(:)
      real(wp), allocatable :: d_start(:, :, :) !< (3, 3, n motions) their directors at t = 0
      !> the model's vessels as the motions see them: with OFFSET START=STATIC and a start
      !> from the static solution, at rest at their offset (vessel_offset_rest)
      type(vessel_t), allocatable :: vessels(:)
      real(wp), allocatable :: x_held(:, :)    !< (3, nn) prescribed positions at t_n+1 [m]
      !> (3, 0:3, nn) the inertia's part per unit mass that does not depend on the unknowns
      !> (inertia_rest), of the position (0) and of the directors d_1, d_2, for the step
      real(wp), allocatable :: rest(:, :, :)
      real(wp), allocatable :: fdamp(:, :)     !< (6, nn) stiffness-proportional and
                                               !< structural damping forces [N, N m]
      !> structural damping (mesh%damped): the nodal rates at the force point are
      !> sd_cv (q^{n+1} - q^n) + srate (rodyn_assembly_damping's section_damping_rates)
      real(wp), allocatable :: srate(:, :, :)  !< (3, 4, nn) [m/s, 1/s]
      real(wp) :: sd_cv = 0.0_wp               !< [1/s]
      !> the dissipative EMC (RHO INF < 1 with EMC; rodyn_numerical_dissipation)
      type(numdiss_t) :: nd
      real(wp), allocatable :: dx(:, :)        !< (3, nn) x^{n+1} - x^n, carried as such
      real(wp), allocatable :: dx_base(:, :)   !< (3, nn) dx at the base of the line search
      logical :: ref_pending = .true.          !< the step's reference force is still to set
      real(wp) :: f_last = 0.0_wp, m_last = 0.0_wp !< force/moment scale of the last iterate
      real(wp) :: f_conv = 0.0_wp, m_conv = 0.0_wp !< the same at the last converged step
      logical :: have_conv = .false.           !< a step has converged
      !> EMC and TRAPEZOIDAL: each rod element's fields and strains of the state at t_n at
      !> its points (rod_element_fields), formed once per step
      type(rod_gp_t), allocatable :: gp0(:, :)    !< (max_points, ne)
      real(wp), allocatable :: epsn(:, :, :)      !< (6, max_points, ne)
      logical :: fields0 = .false.              !< gp0 and epsn are used
      !> gp0 and epsn hold the fields of s1 (dynamics_strain_energy, on a converged
      !> step) and, once the step is accepted, of the next step's t_n: the energy pass
      !> and the next step's fields are one pass over the rods, not two
      logical :: fields_s1 = .false.
      logical :: fields_next = .false.
   contains
      procedure :: evaluate => dyn_evaluate
      procedure :: save_base => dyn_save_base
      procedure :: apply_correction => dyn_apply_correction
   end type dynamic_problem_t

contains

   !> Build supports, loads, inertia and the workspace; state holds the start (t = 0).
   !> docs/theory.md eq. (56) (ALPHA parameters).
   subroutine dynamics_setup(prob, model, mesh, state)
      type(dynamic_problem_t), intent(inout) :: prob !< problem
      type(model_t), intent(in), target :: model     !< model
      type(mesh_t), intent(in), target :: mesh       !< mesh
      type(state_t), intent(in), target :: state     !< start state, then the iterate
      integer :: nn, i
      call supports_build(model, mesh, state, prob%sup)
      call rod_problem_init(prob, model, mesh)
      call junctions_clamp(prob%jn, state%d)
      call failures_build(model, mesh, prob%fl)
      call anderson_init(prob%aa, prob%sup%n_dof, anderson_depth)
      ! the step tangent is factorised without pivoting (cheaper; stable when mass-led)
      call banded_set_pivoting(prob%bm, .false.)
      prob%model => model
      prob%s1 => state
      nn = mesh%n_nodes
      prob%sup%moved = .false.     ! POSITION targets were reached in statics
      call loads_build(model, mesh, prob%loads)
      call water_loads_build(model, mesh, prob%water)
      if (prob%water%active) call body_waves_start(model, prob%water%field, state, prob%bl)
      allocate (prob%gfac(0:mesh%n_lines))
      prob%gfac = 1.0_wp
      if (prob%water%active) then
         allocate (prob%xf(3, nn), prob%vf(3, nn), prob%af_acc(3, nn))
         prob%xf = 0.0_wp
         prob%vf = 0.0_wp
         prob%af_acc = 0.0_wp
      end if
      call inertia_build(model, mesh, prob%inert)
      ! a free roll without inertia is a null vector of the step's tangent, as in statics
      call roll_gauges(mesh, prob%sup, prob%loads, prob%gauge_node, prob%gauge_k, &
                       prob%inert%md(1, :) + prob%inert%md(2, :))
      prob%scheme = model%dynamic%scheme
      call state_allocate(prob%s0, nn, prob%scheme == scheme_alpha)
      prob%fields0 = (prob%scheme == scheme_emc .or. prob%scheme == scheme_trapezoidal) &
                     .and. .not. all(mesh%elem_cable)
      if (prob%fields0) allocate (prob%gp0(max_points, mesh%n_elements), &
                                  prob%epsn(6, max_points, mesh%n_elements))
      prob%alpha = model%dynamic%rayleigh_alpha
      prob%beta_d = model%dynamic%rayleigh_beta
      if (prob%scheme == scheme_alpha) then
         associate (rho => model%dynamic%rho_inf)
            prob%am = (2.0_wp*rho - 1.0_wp)/(rho + 1.0_wp)
            prob%af = rho/(rho + 1.0_wp)
         end associate
         prob%gamma_n = 0.5_wp - prob%am + prob%af
         prob%beta_n = 0.25_wp*(1.0_wp - prob%am + prob%af)**2
         prob%wf = 1.0_wp - prob%af
      end if
      if (prob%scheme == scheme_emc) call numdiss_setup(prob%nd, mesh, state, &
                                                        model%dynamic%rho_inf, model%dynamic%dt)
      allocate (prob%x_start(3, nn), prob%x_held(3, nn), prob%fdamp(6, nn), prob%dx(3, nn), &
                prob%dx_base(3, nn), prob%rest(3, 0:3, nn))
      if (mesh%damped) then
         allocate (prob%srate(3, 4, nn))
         prob%srate = 0.0_wp
      end if
      prob%x_start = state%x
      prob%x_held = state%x
      call motion_nodes(model, mesh, prob%motion_node, prob%motion_of)
      prob%sup%moved(prob%motion_node) = .true.
      ! the static solution has the vessels at their offsets (rodyn_statics'
      ! vessel_offsets): the offset is their rest pose, not ramped in again
      if (allocated(model%vessels)) then
         prob%vessels = model%vessels
         do i = 1, size(prob%vessels)
            if (model%dynamic%start_static .and. model%vessels(i)%offset_static) &
               prob%vessels(i) = vessel_offset_rest(model%vessels(i))
         end do
      end if
      ! a clamped end on a vessel (its rotations held) and a FIXED body moved with a
      ! vessel turn with it: their directors are prescribed like their position
      allocate (prob%motion_turns(size(prob%motion_node)), &
                prob%d_start(3, 3, size(prob%motion_node)))
      do i = 1, size(prob%motion_node)
         associate (node => prob%motion_node(i))
            prob%motion_turns(i) = model%motions(prob%motion_of(i))%kind == motion_vessel .and. &
                                   prob%sup%ndof(node) == 6 .and. all(prob%sup%held(4:6, node))
            prob%d_start(:, :, i) = state%d(:, :, node)
         end associate
      end do
   end subroutine dynamics_setup

   !> Start a step from t0 to t0 + dt: remember the state at t_n, set the loads at the
   !> midpoint and the prescribed positions at t_n+1, and predict the iterate by the state
   !> at t_n (the paper's predictor), but at the nodes of cable elements alone (three
   !> unknowns, no directors), which start from x^n + dt v^n (docs/theory.md eq. (33)).
   !> Extrapolating predictors are worse for rods: under EMC a stiff mode with
   !> omega dt >> 1 changes sign every step, so x^n + dt v^n, or x^n plus the last step's
   !> displacement, predicts it with the wrong sign and Newton needs many more iterations
   !> and step halvings. Cable nodes have no directors that the predicted positions would
   !> shear, and there the extrapolation saves iterations and tangents.
   subroutine dynamics_begin_step(prob, t0, dt)
      type(dynamic_problem_t), intent(inout) :: prob !< problem
      real(wp), intent(in) :: t0                     !< time at the start of the step [s]
      real(wp), intent(in) :: dt                     !< step [s]
      real(wp) :: tm, w0, scale0, u(3), q(3, 3)
      integer :: node, i, k
      logical :: released
      ! a line end whose failure is due is released (rodyn_system_dynamics)
      if (prob%fl%n > 0) then
         call failures_step(prob%fl, prob%sup, prob%jn, prob%r, t0, released)
         if (released) prob%factors_ok = .false.
      end if
      prob%t0 = t0
      prob%dt = dt
      prob%base_set = .false.
      call state_copy(prob%s1, prob%s0)
      ! the rods' fields and strains of s0 at their points, unless the accepted step before
      ! left them (its energy, formed in the same pass, is not needed here)
      if (prob%fields0 .and. .not. prob%fields_next) &
         call mesh_strain_energy(prob%mesh, prob%s0, w0, scale0, prob%gp0, prob%epsn)
      prob%fields_next = .false.
      prob%fields_s1 = .false.
      ! the inertia's constant part, once a step instead of once an iteration
      do node = 1, prob%mesh%n_nodes
         prob%rest(:, 0, node) = inertia_rest(prob, prob%s0%v(:, node), node, 0)
         do i = 1, 3
            if (prob%inert%md(i, node) == 0.0_wp .and. &
                findloc(prob%inert%ma_node, node, dim=1) == 0) cycle
            prob%rest(:, i, node) = inertia_rest(prob, prob%s0%dd(:, i, node), node, i)
         end do
      end do
      ! the dissipative EMC: the history stress of the step
      if (prob%nd%on) call numdiss_offsets(prob%nd, prob%mesh, dt)
      ! structural damping: the rates of the scheme at its force point
      if (prob%mesh%damped) then
         if (prob%scheme == scheme_alpha) then
            call section_damping_rates(prob%s0, prob%af, prob%gamma_n, prob%beta_n, dt, &
                                       prob%srate, prob%sd_cv)
         else
            prob%sd_cv = 1.0_wp/dt
         end if
      end if
      ! external forces at the force point: weight, point loads times their amplitudes
      tm = t0 + prob%wf*dt
      call external_force(prob%mesh, prob%loads, prob%gfac, 1.0_wp, tm, prob%fext)
      if (prob%water%active) call water_set_time(prob%water, tm, .true., prob%s0%x, &
                                                 prob%s0%v, prob%wf*dt)
      if (prob%bl%nb > 0 .and. prob%water%active) call body_water_set(prob%bl, &
         prob%water%env%water, prob%water%env%r_current, prob%water%field, &
         prob%water%wave_on, tm, prob%s0%x, prob%s0%d, prob%s0%v, prob%wf*dt)
      call held_positions(prob, t0, dt)
      prob%ref_pending = .not. prob%have_conv
      if (prob%have_conv) then
         prob%f_extra = prob%f_conv
         prob%m_extra = prob%m_conv
      end if
      ! predictor: the state at t_n (held nodes reach x_held through the gap)
      ! (cable nodes: x^n + dt v^n, see above)
      do node = 1, prob%mesh%n_nodes
         if (prob%sup%ndof(node) == 3) then
            prob%dx(:, node) = dt*prob%s0%v(:, node)
         else
            prob%dx(:, node) = 0.0_wp
         end if
      end do
      ! a FIXED body moved (*MOTION, BODY=) starts the step where it is prescribed (its
      ! rows held; no free row couples to them but through its line ends)
      do i = 1, size(prob%motion_node)
         if (prob%model%motions(prob%motion_of(i))%body == 0) cycle
         node = prob%motion_node(i)
         prob%dx(:, node) = prob%x_held(:, node) - prob%s0%x(:, node)
      end do
      ! a line end on a FREE point or body moves with it (theory.md (131)): its predictor
      do k = 1, prob%jn%ns
         if (.not. prob%jn%s_on(k)) cycle
         prob%dx(:, prob%jn%s_node(k)) = prob%dx(:, prob%jn%m_node(prob%jn%s_m(k)))
      end do
      prob%s1%x = prob%s0%x + prob%dx
      prob%s1%d = prob%s0%d
      ! a clamped end on a vessel: its directors at t_n+1, d_i = Q d_i(0); its rotation
      ! unknowns are held (their Newton corrections are zero), so they stay there
      do i = 1, size(prob%motion_node)
         if (.not. prob%motion_turns(i)) cycle
         node = prob%motion_node(i)
         call held_motion(prob%model%motions(prob%motion_of(i)), prob%vessels, &
                          prob%x_start(:, node), t0, dt, past_end(prob, t0, dt), u, q)
         prob%s1%d(:, :, node) = matmul(q, prob%d_start(:, :, i))
      end do
   end subroutine dynamics_begin_step

   !> The prescribed positions at the end of the step, x_held (held_motion: the step past
   !> the run's end continues a motion whose data end before it).
   subroutine held_positions(prob, t0, dt)
      type(dynamic_problem_t), intent(inout) :: prob !< problem (x_held set)
      real(wp), intent(in) :: t0                     !< time at the start of the step [s]
      real(wp), intent(in) :: dt                     !< step [s]
      real(wp) :: u(3)
      integer :: node, i
      do i = 1, size(prob%motion_node)
         node = prob%motion_node(i)
         ! (vessels unallocated, as in a model built without a deck, is an absent
         ! optional argument)
         call held_motion(prob%model%motions(prob%motion_of(i)), prob%vessels, &
                          prob%x_start(:, node), t0, dt, past_end(prob, t0, dt), u)
         prob%x_held(:, node) = prob%x_start(:, node) + u
      end do
   end subroutine held_positions

   !> The step from t0 is the one past the run's end (rodyn_timeloop's look_ahead).
   pure logical function past_end(prob, t0, dt)
      type(dynamic_problem_t), intent(in) :: prob !< problem
      real(wp), intent(in) :: t0                  !< time at the start of the step [s]
      real(wp), intent(in) :: dt                  !< step [s]
      past_end = t0 >= prob%model%dynamic%duration - 1.0e-9_wp*dt
   end function past_end

   !> A step is accepted: its forces become the residual's reference of the next step.
   subroutine dynamics_accept_step(prob)
      type(dynamic_problem_t), intent(inout) :: prob !< problem
      prob%f_conv = prob%f_last
      prob%m_conv = prob%m_last
      prob%have_conv = .true.
      prob%fields_next = prob%fields_s1     ! s1 becomes the next step's t_n
      if (prob%nd%on) call numdiss_accept(prob%nd)
   end subroutine dynamics_accept_step

   !> Stored energy of the whole mesh in the iterate s1 [J] and its round-off scale [J]
   !> (mesh_strain_energy). With EMC and TRAPEZOIDAL the rods' fields and strains of s1
   !> are kept in gp0 and epsn (fields_s1): the next step, if this one is accepted,
   !> starts from them instead of forming them again. For a converged step only: the
   !> step's own passes no longer read gp0.
   subroutine dynamics_strain_energy(prob, w, scale)
      type(dynamic_problem_t), intent(inout) :: prob !< problem (s1 converged)
      real(wp), intent(out) :: w                     !< stored energy [J]
      real(wp), intent(out) :: scale                 !< its round-off scale [J]
      if (prob%fields0) then
         call mesh_strain_energy(prob%mesh, prob%s1, w, scale, prob%gp0, prob%epsn)
      else
         call mesh_strain_energy(prob%mesh, prob%s1, w, scale)
      end if
      prob%fields_s1 = prob%fields0
   end subroutine dynamics_strain_energy

   !> Stored energy of the whole mesh in state s [J] and its round-off scale [J]
   !> (rod_element_energy_scale, cable_element_energy_scale); with gp and eps, the rods'
   !> fields and strains at their points are left there (rod_element_fields).
   !> docs/theory.md eq. (21), (61).
   subroutine mesh_strain_energy(mesh, s, w, scale, gp, eps)
      type(mesh_t), intent(in) :: mesh                       !< mesh
      type(state_t), intent(in) :: s                         !< configuration
      real(wp), intent(out) :: w                             !< stored energy [J]
      real(wp), intent(out) :: scale                         !< its round-off scale [J]
      type(rod_gp_t), intent(inout), optional :: gp(:, :)    !< (max_points, ne) fields
      real(wp), intent(inout), optional :: eps(:, :, :)      !< (6, max_points, ne) strains
      real(wp) :: xe(3, max_nen), de(3, 3, max_nen), we, se
      integer :: e, p
      w = 0.0_wp
      scale = 0.0_wp
      do e = 1, mesh%n_elements
         p = mesh%line_order(mesh%elem_line(e))
         call state_gather(s, mesh%elem_nodes(1:p + 1, e), xe, de)
         if (mesh%elem_cable(e)) then
            call cable_element_energy_scale(p, mesh%elem_le(e), mesh%elem_c(3, e), &
                                            xe(:, 1:p + 1), mesh%rules(p), we, se)
         else if (present(gp) .and. present(eps)) then
            call rod_element_fields(p, mesh%elem_le(e), xe(:, 1:p + 1), de(:, :, 1:p + 1), &
                                    mesh%rules(p), gp(:, e), eps(:, :, e))
            call rod_energy_of_strains(mesh%elem_le(e), mesh%elem_c(:, e), &
                                       mesh%eps0(:, :, e), eps(:, :, e), mesh%rules(p), we, se)
         else
            call rod_element_energy_scale(p, mesh%elem_le(e), mesh%elem_c(:, e), &
                                          mesh%eps0(:, :, e), xe(:, 1:p + 1), &
                                          de(:, :, 1:p + 1), we, se, mesh%rules(p))
         end if
         w = w + we
         scale = scale + se
      end do
   end subroutine mesh_strain_energy

   !> Close a converged step: velocities by the midpoint relations (docs/theory.md eq.
   !> (33)), or by the Newmark relations for the generalized-alpha scheme (eq. (58)).
   subroutine dynamics_end_step(prob)
      type(dynamic_problem_t), intent(inout) :: prob !< problem
      real(wp) :: c, bdt2
      if (prob%scheme == scheme_alpha) then
         bdt2 = prob%beta_n*prob%dt**2
         prob%s1%a = (prob%dx - prob%dt*prob%s0%v - prob%dt**2*(0.5_wp - prob%beta_n)* &
                      prob%s0%a)/bdt2
         prob%s1%ad = (prob%s1%d - prob%s0%d - prob%dt*prob%s0%dd - prob%dt**2* &
                       (0.5_wp - prob%beta_n)*prob%s0%ad)/bdt2
         prob%s1%v = prob%s0%v + prob%dt*((1.0_wp - prob%gamma_n)*prob%s0%a &
                                          + prob%gamma_n*prob%s1%a)
         prob%s1%dd = prob%s0%dd + prob%dt*((1.0_wp - prob%gamma_n)*prob%s0%ad &
                                            + prob%gamma_n*prob%s1%ad)
         return
      end if
      c = 2.0_wp/prob%dt
      prob%s1%v = c*prob%dx - prob%s0%v
      call trapezoidal_rate(size(prob%s1%dd), c, prob%s1%d, prob%s0%d, prob%s0%dd, &
                            prob%s1%dd)
   end subroutine dynamics_end_step

   !> r1 = c (q1 - q0) - r0 over n values: the rates of the trapezoidal rule, c = 2/dt
   !> (explicit shapes, as copy_values: the compiler then knows the arrays do not overlap
   !> and vectorises the loop)
   !> docs/theory.md eq. (33).
   pure subroutine trapezoidal_rate(n, c, q1, q0, r0, r1)
      integer, intent(in) :: n       !< values
      real(wp), intent(in) :: c      !< 2/dt [1/s]
      real(wp), intent(in) :: q1(n)  !< values at t_n+1
      real(wp), intent(in) :: q0(n)  !< values at t_n
      real(wp), intent(in) :: r0(n)  !< rates at t_n
      real(wp), intent(out) :: r1(n) !< rates at t_n+1
      r1 = c*(q1 - q0) - r0
   end subroutine trapezoidal_rate

   !> Residual (and tangent): step internal force, inertia, damping, supports.
   !> docs/theory.md eqs. (37)-(40), (59)-(60).
   subroutine dyn_evaluate(this, want_k, err)
      class(dynamic_problem_t), intent(inout) :: this !< problem
      logical, intent(in) :: want_k                   !< form the tangent
      type(error_t), intent(inout) :: err             !< status (cannot fail)
      real(wp) :: c2, kb(6, 6), bdt2, wp_
      real(wp) :: fx, mx
      integer :: node
      if (has_error(err)) return
      ! a tangent formed after a correction takes its stresses from the strains
      ! linearized from the iterate before (rodyn_rod_dynamic's header, EMC only)
      if (this%fields0 .and. this%base_set .and. this%scheme == scheme_emc) then
         call assemble_dynamic(this%mesh, this%sup, this%s0, this%s1, this%scheme, this%wf, &
                               this%beta_d, this%dt, this%fint, this%fdamp, this%bm, want_k, &
                               this%gp0, this%epsn, this%x_base, this%d_base, this%nd%fac, &
                               this%nd%off)
      else if (this%fields0) then
         call assemble_dynamic(this%mesh, this%sup, this%s0, this%s1, this%scheme, this%wf, &
                               this%beta_d, this%dt, this%fint, this%fdamp, this%bm, want_k, &
                               this%gp0, this%epsn, nd_fac=this%nd%fac, nd_off=this%nd%off)
      else
         call assemble_dynamic(this%mesh, this%sup, this%s0, this%s1, this%scheme, this%wf, &
                               this%beta_d, this%dt, this%fint, this%fdamp, this%bm, want_k, &
                               nd_fac=this%nd%fac, nd_off=this%nd%off)
      end if
      if (this%mesh%n_cable > 0) &
         call assemble_dynamic_cables(this%mesh, this%sup, this%s0, this%s1, this%scheme, &
                                      this%wf, this%beta_d, this%dt, this%fint, this%fdamp, &
                                      this%bm, want_k, this%nd%fac, this%nd%off)
      if (this%mesh%damped) &
         call assemble_section_damping(this%mesh, this%sup, this%s0, this%s1, this%srate, &
                                       this%sd_cv, this%wf, this%scheme, this%fint, &
                                       this%fdamp, this%bm, want_k)
      if (this%water%active) call water_loads_step(this, want_k)
      if (this%bl%nb > 0) call assemble_bodies(this%bl, this%sup, this%s0%x, this%s1%x, &
                                               this%s0%d, this%s1%d, this%wf, this%fext, &
                                               this%loads%gravity, this%fint, this%bm, &
                                               want_k, this%dt)
      fx = 0.0_wp
      mx = 0.0_wp
      do node = 1, this%mesh%n_nodes
         fx = max(fx, maxval(abs(this%fint(1:3, node))))
         mx = max(mx, maxval(abs(this%fint(4:6, node))))
      end do
      ! inertia (and mass-proportional damping): force = mass * (c2 dq - g0), its
      ! derivative mass * c2, projected with the directors of the force point (weight wp)
      if (this%scheme == scheme_alpha) then
         bdt2 = this%beta_n*this%dt**2
         c2 = (1.0_wp - this%am)/bdt2 + this%alpha*(1.0_wp - this%af)*this%gamma_n/ &
              (this%beta_n*this%dt)
      else
         c2 = 2.0_wp/this%dt**2 + this%alpha/this%dt
      end if
      wp_ = this%wf
      do node = 1, this%mesh%n_nodes
         call node_inertia(this%inert%m(node), this%inert%md(:, node), c2, wp_, &
                           this%dx(:, node), this%rest(:, :, node), this%s0%d(:, :, node), &
                           this%s1%d(:, :, node), this%fint(:, node), fx, kb, want_k)
         if (want_k) call add_node_block(this%sup, node, kb, this%bm)
      end do
      call added_mass_step(this, c2, wp_, want_k)
      ! the roll gauges: k_g d3 d3^T in the iteration matrix, the residual unchanged
      if (want_k) call add_roll_gauges(this%sup, this%gauge_node, this%gauge_k, this%s1%d, &
                                       this%bm)
      ! The residual's reference force and moment stay fixed while Newton iterates: those
      ! of the last converged step (the first step: of its first evaluation). An iterate's
      ! own would grow with a diverging iterate, which could then pass as converged (the
      ! paper's cable heaved 2 m at 2 Hz, bench/decks/violent_2m_2hz.inp); the predictor's
      ! inertia term 2 m v^n / dt is no force of the motion, and sets a loose tolerance.
      this%f_last = fx
      this%m_last = mx
      if (this%ref_pending) then
         this%f_extra = fx
         this%m_extra = mx
         this%ref_pending = .false.
      end if
      call difference_values(size(this%r), this%fint, this%fext, this%r)
      do node = 1, this%mesh%n_nodes
         this%gap(:, node) = 0.0_wp
         if (this%sup%held(1, node)) this%gap(:, node) = this%x_held(:, node) - this%s1%x(:, node)
      end do
      call apply_supports(this%sup, this%r, this%gap, this%rhs, this%bm, want_k)
      call junctions_condense(this%jn, this%sup, this%rhs, this%bm, want_k, this%s0%d, &
                              this%s1%d, this%wf)
   end subroutine dyn_evaluate

   !> The bodies' added mass on their accelerations (theory.md (142), (154)): the
   !> accelerations those of a unit mass and director inertias 1/2; in EMC a
   !> translational added mass with its discrete Munk moment, (151).
   subroutine added_mass_step(this, c2, wp_, want_k)
      class(dynamic_problem_t), intent(inout) :: this !< problem
      real(wp), intent(in) :: c2                      !< d(acceleration)/d(increment) [1/s2]
      real(wp), intent(in) :: wp_                     !< weight of t_n+1 at the force point
      logical, intent(in) :: want_k                   !< form the tangent
      real(wp) :: kb(6, 6), acc(6), dacc(6, 6), fx_acc
      integer :: node, i
      do i = 1, size(this%inert%ma_node)
         node = this%inert%ma_node(i)
         if (this%scheme == scheme_emc .and. this%inert%ma_trans(i)) then
            call added_mass_emc(this%inert%ma(1:3, 1:3, i), this%s0%d(:, :, node), &
                                this%s1%d(:, :, node), this%s0%v(:, node), this%dx(:, node), &
                                this%dt, this%fint(:, node), kb, want_k)
         else
            acc = 0.0_wp
            fx_acc = 0.0_wp
            call node_inertia(1.0_wp, [0.5_wp, 0.5_wp, 0.5_wp], c2, wp_, this%dx(:, node), &
                              this%rest(:, :, node), this%s0%d(:, :, node), &
                              this%s1%d(:, :, node), acc, fx_acc, dacc, want_k)
            call added_mass_force(this%inert%ma(:, :, i), this%s0%d(:, :, node), &
                                  this%s1%d(:, :, node), wp_, this%dt, this%dx(:, node), acc, &
                                  dacc, this%fint(:, node), kb, want_k)
         end if
         if (want_k) call add_node_block(this%sup, node, kb, this%bm)
      end do
   end subroutine added_mass_step

   !> The water's and seabed's loads of the step (rodyn_water) at the force point of the
   !> scheme (docs/theory.md eq. (72)): x_f = x^n + w dx, with the scheme's velocity and
   !> acceleration there,
   !>   midpoint family: v_f = dx/dt, a_f = (v^{n+1} - v^n)/dt = 2 dx/dt^2 - 2 v^n/dt
   !>   generalized-alpha: v_f = (1 - af) v^{n+1} + af v^n, a_f = (1 - am) a^{n+1} + am a^n
   !> and their derivatives with respect to x^{n+1} (c_v, c_a), so that the tangent holds
   !> the velocity dependence through the scheme's update.
   subroutine water_loads_step(this, want_k)
      class(dynamic_problem_t), intent(inout) :: this !< problem
      logical, intent(in) :: want_k                   !< form the tangent
      real(wp) :: cv, ca, b, gm, dt, a1(3), v1(3)
      integer :: node
      dt = this%dt
      if (this%scheme == scheme_alpha) then
         b = this%beta_n
         gm = this%gamma_n
         do node = 1, this%mesh%n_nodes
            associate (v0 => this%s0%v(:, node), a0 => this%s0%a(:, node))
               a1 = (this%dx(:, node) - dt*v0 - dt**2*(0.5_wp - b)*a0)/(b*dt**2)
               v1 = v0 + dt*((1.0_wp - gm)*a0 + gm*a1)
               this%vf(:, node) = (1.0_wp - this%af)*v1 + this%af*v0
               this%af_acc(:, node) = (1.0_wp - this%am)*a1 + this%am*a0
            end associate
         end do
         cv = (1.0_wp - this%af)*gm/(b*dt)
         ca = (1.0_wp - this%am)/(b*dt**2)
      else
         call trapezoidal_motion(size(this%dx), dt, this%dx, this%s0%v, this%vf, &
                                 this%af_acc)
         cv = 1.0_wp/dt
         ca = 2.0_wp/dt**2
      end if
      call force_point(size(this%dx), this%wf, this%s0%x, this%dx, this%xf)
      call assemble_water(this%water, this%mesh, this%sup, this%xf, this%vf, this%af_acc, &
                          this%wf, cv, ca, this%fint, this%bm, want_k)
   end subroutine water_loads_step

   !> The part of mass * (inertia + damping) per unit mass that does not depend on the
   !> unknowns: with dq = q^{n+1} - q^n the force is mass * (c2 dq - rest). The
   !> acceleration at t_n (generalized-alpha only: the other schemes' states hold
   !> none) is node's, of its position (i = 0) or of its director i.
   !> docs/theory.md eqs. (39), (59).
   pure function inertia_rest(this, v0, node, i) result(g)
      type(dynamic_problem_t), intent(in) :: this !< problem (scheme, step, state at t_n)
      real(wp), intent(in) :: v0(3) !< velocity at t_n
      integer, intent(in) :: node   !< node
      integer, intent(in) :: i      !< 0: position, 1 or 2: director d_i
      real(wp) :: g(3)
      real(wp) :: b, gm, dt, a0(3)
      if (this%scheme == scheme_alpha) then
         if (i == 0) then
            a0 = this%s0%a(:, node)
         else
            a0 = this%s0%ad(:, i, node)
         end if
         ! (1-am) a1 + am a0 + alpha v_f, a1 = (dq - dt v0 - dt^2 (1/2 - b) a0)/(b dt^2),
         ! v_f = (1-af) v1 + af v0, v1 = v0 + dt ((1-gm) a0 + gm a1)
         b = this%beta_n
         gm = this%gamma_n
         dt = this%dt
         g = (1.0_wp - this%am)*(v0/(b*dt) + (0.5_wp - b)/b*a0) - this%am*a0 &
             - this%alpha*(v0 + (1.0_wp - this%af)*dt*((1.0_wp - gm)*a0 &
             - gm*(v0/(b*dt) + (0.5_wp - b)/b*a0)))
      else
         g = 2.0_wp/this%dt*v0
      end if
   end function inertia_rest

   !> Remember the iterate (positions, directors, step displacement) as the base of the
   !> update.
   subroutine dyn_save_base(this)
      class(dynamic_problem_t), intent(inout) :: this !< problem
      call copy_values(size(this%x_base), this%s1%x, this%x_base)
      ! (directors turn at rod nodes and at bodies' only)
      if (this%mesh%n_cable < this%mesh%n_elements .or. size(this%mesh%body_node) > 0) &
         call copy_values(size(this%d_base), this%s1%d, this%d_base)
      call copy_values(size(this%dx_base), this%dx, this%dx_base)
      this%base_set = .true.
   end subroutine dyn_save_base

   !> x = x^n + dx, dx = dx_base + alpha du_x;  d_i = cay(alpha du_theta) d_i,base.
   !> docs/theory.md eqs. (32), (46).
   subroutine dyn_apply_correction(this, alpha)
      class(dynamic_problem_t), intent(inout) :: this !< problem
      real(wp), intent(in) :: alpha                   !< step length [-]
      integer :: node, k
      if (this%sup%uniform) then      ! (two loops: the rod's layout costs what it did)
         do node = 1, this%mesh%n_nodes
            k = 6*(node - 1)
            this%dx(:, node) = this%dx_base(:, node) + alpha*this%du(k + 1:k + 3)
            this%s1%x(:, node) = this%s0%x(:, node) + this%dx(:, node)
         end do
      else
         do node = 1, this%mesh%n_nodes
            k = this%sup%first(node) - 1
            this%dx(:, node) = this%dx_base(:, node) + alpha*this%du(k + 1:k + 3)
            this%s1%x(:, node) = this%s0%x(:, node) + this%dx(:, node)
         end do
      end if
      call this%rotate_from_base(alpha, this%s1%d)
      ! the ends on bodies (and points) exactly where their masters put them
      if (this%jn%ns > 0) then
         call junctions_place(this%jn, this%s1%x, this%s1%d)
         do k = 1, this%jn%ns
            node = this%jn%s_node(k)
            this%dx(:, node) = this%s1%x(:, node) - this%s0%x(:, node)
         end do
      end if
   end subroutine dyn_apply_correction

   !> One node's inertia (and mass-proportional damping) force added to f, mass * (c2 dq
   !> - g0) projected with the directors of the force point (weight wp), and its
   !> derivative kb when want_k (dyn_evaluate). fx is raised to the largest translational
   !> inertia force (docs/theory.md eqs. (37)-(39), (59)). Explicit shapes, so that the
   !> compiler sees plain arrays rather than the problem's components.
   pure subroutine node_inertia(m, md, c2, wp_, dx, rest, d0, d1, f, fx, kb, want_k)
      real(wp), intent(in) :: m            !< translational mass [kg]
      real(wp), intent(in) :: md(3)        !< director inertias [kg m2] (d3: a body's)
      real(wp), intent(in) :: c2           !< d(acceleration)/d(increment) [1/s2]
      real(wp), intent(in) :: wp_          !< weight of t_n+1 in the force point [-]
      real(wp), intent(in) :: dx(3)        !< position increment [m]
      real(wp), intent(in) :: rest(3, 0:3) !< the step's constant parts (inertia_rest)
      real(wp), intent(in) :: d0(3, 3)     !< directors at t_n
      real(wp), intent(in) :: d1(3, 3)     !< directors at t_n+1
      real(wp), intent(inout) :: f(6)      !< nodal force [N, N m]
      real(wp), intent(inout) :: fx        !< largest force component so far [N]
      real(wp), intent(out) :: kb(6, 6)    !< derivative (if want_k)
      logical, intent(in) :: want_k        !< form kb
      real(wp) :: fi(3), h(3), dm(3), blk(3, 3), mi, hd, dmd1
      integer :: i, j, k
      fi = m*(c2*dx - rest(:, 0))
      f(1:3) = f(1:3) + fi
      fx = max(fx, maxval(abs(fi)))
      if (want_k) then
         kb = 0.0_wp
         do j = 1, 3
            kb(j, j) = c2*m
         end do
      end if
      do i = 1, 3
         mi = md(i)
         if (mi == 0.0_wp) cycle
         dm = (1.0_wp - wp_)*d0(:, i) + wp_*d1(:, i)
         h = mi*(c2*(d1(:, i) - d0(:, i)) - rest(:, i))
         f(4:6) = f(4:6) + cross(dm, h)
         if (.not. want_k) cycle
         ! d(dm x h) = wp (dth x d1) x h + dm x (mi c2 dth x d1)
         hd = dot_product(h, d1(:, i))
         dmd1 = dot_product(dm, d1(:, i))
         do k = 1, 3
            do j = 1, 3
               blk(j, k) = wp_*d1(j, i)*h(k) - mi*c2*d1(j, i)*dm(k)
            end do
            blk(k, k) = blk(k, k) - wp_*hd + mi*c2*dmd1
         end do
         kb(4:6, 4:6) = kb(4:6, 4:6) + blk
      end do
   end subroutine node_inertia


   !> The velocity and acceleration of the trapezoidal rule over n values, v = dx/dt and
   !> a = 2 dx/dt^2 - 2 v0/dt (explicit shapes, as rodyn_state's copy_values: the loops
   !> vectorise).
   !> docs/theory.md eq. (72).
   pure subroutine trapezoidal_motion(n, dt, dx, v0, v, a)
      integer, intent(in) :: n       !< values
      real(wp), intent(in) :: dt     !< step [s]
      real(wp), intent(in) :: dx(n)  !< increments [m]
      real(wp), intent(in) :: v0(n)  !< velocities at t_n [m/s]
      real(wp), intent(out) :: v(n)  !< velocities [m/s]
      real(wp), intent(out) :: a(n)  !< accelerations [m/s2]
      v = dx/dt
      a = 2.0_wp*dx/dt**2 - 2.0_wp*v0/dt
   end subroutine trapezoidal_motion

   !> The positions at the force point over n values, xf = x0 + w dx.
   pure subroutine force_point(n, w, x0, dx, xf)
      integer, intent(in) :: n       !< values
      real(wp), intent(in) :: w      !< weight of t_n+1 [-]
      real(wp), intent(in) :: x0(n)  !< positions at t_n [m]
      real(wp), intent(in) :: dx(n)  !< increments [m]
      real(wp), intent(out) :: xf(n) !< positions at the force point [m]
      xf = x0 + w*dx
   end subroutine force_point

   !> c = a - b over n values (explicit shapes, as rodyn_state's copy_values).
   pure subroutine difference_values(n, a, b, c)
      integer, intent(in) :: n      !< values
      real(wp), intent(in) :: a(n)  !< minuend
      real(wp), intent(in) :: b(n)  !< subtrahend
      real(wp), intent(out) :: c(n) !< difference
      c = a - b
   end subroutine difference_values

end module rodyn_dynamics
