!> Static equilibrium (docs/theory.md section 14, eqs. (107)-(111)): residual
!> r = f_int(q) - f_ext(lambda) = 0 solved by Newton in load increments, each halved on
!> failure up to a bounded depth.
!>
!> Load factor lambda in [0, 1] scales the point loads and the stress-free strains
!> (built-in curvature), and moves prescribed positions from the start to the target.
!> The starting shape u0 is rarely an exact equilibrium (a catenary start ignores EI),
!> so the equations solved are the Newton homotopy
!>   r(u) - (1 - lambda) r0(u) = 0,   r0 = [r_F(u0); R r_M(u0)],  R = d d0^T per node,
!> which u0 satisfies at lambda = 0 and which is the true problem at lambda = 1; a
!> failed increment can then always be cut, even when no load is ramped. The start's
!> unbalanced moments r_M(u0) turn with their node (R: from the start's directors d0
!> to the current ones), so that the homotopy, like the rod, does not change when the
!> whole line rolls about its centreline (a fixed moment would: under a load across
!> the plane of a hanging line it left a torque no configuration could balance); its
!> tangent adds (1 - lambda) skew(R r_M(u0)) to each node's rotation block.
!> A failed increment is first retried with the energy line search, then halved.
!>
!> Roll gauge. A line, or a run of rod elements between cable ones, whose sections are
!> all transversely isotropic (GA1 = GA2, EI1 = EI2), with no rotation held at any node
!> and no point moment, can roll about its own centreline, uniformly, without any
!> change of energy: that roll is a null vector of the static tangent, and its
!> round-off would blow the Newton corrections up to thousands of radians. The iteration
!> matrix of such a run (not its residual) gets the stiffness k_g d3 d3^T against
!> rotation about d3 at one node, its middle one, k_g = max(EI, GJ)/le of an element
!> there. The residual is unchanged and is orthogonal to the null vector, so each
!> Newton step is the exact one with its roll at that node set to zero, and the
!> converged shape is the same.
!>
!> Self-weight is applied in full from the start on a line that starts as a catenary
!> (it nearly hangs in equilibrium already); on any other line it is ramped with lambda,
!> and so is the line's buoyancy (sections and attachments): the weight in water is
!> ramped, never the weight alone under full buoyancy, which can float a free-hanging
!> riser in a current up, flip it, and converge to the unstable upside-down
!> equilibrium.
module rodyn_statics
   use rodyn_kinds, only: wp
   use rodyn_rotation, only: skew
   use rodyn_error, only: error_t, has_error, set_error, clear_error, stat_numerical
   use rodyn_model, only: model_t, motion_vessel
   use rodyn_motion, only: vessel_offset_point, rotation_z
   use rodyn_load_check, only: load_divergence_hint
   use rodyn_mesh, only: mesh_t, mesh_node
   use rodyn_mesh_checks, only: mesh_spurious_shape, mesh_cable_like_rods
   use rodyn_state, only: state_t
   use rodyn_junctions, only: junctions_condense, junctions_place, junctions_clamp
   use rodyn_assembly_bodies, only: assemble_bodies
   use rodyn_bodies, only: body_water_set
   use rodyn_assembly, only: supports_t, loads_t, supports_build, loads_build, &
                             assemble_static, apply_supports, external_force, assemble_water, &
                             add_node_block
   use rodyn_roll_gauges, only: roll_gauges, add_roll_gauges
   use rodyn_water, only: water_loads_t, water_loads_build
   use rodyn_environment, only: current_factor
   use rodyn_newton, only: newton_options_t, newton_stats_t, newton_solve
   use rodyn_rod_problem, only: rod_problem_t, rod_problem_init
   use rodyn_results, only: run_summary_t
   implicit none
   private
   public :: static_problem_t, statics_setup, statics_solve, statics_run, static_set_load_factor
   public :: statics_start_forces

   !> The static problem with its workspace (allocated once in statics_setup).
   type, extends(rod_problem_t) :: static_problem_t
      type(state_t), pointer :: state => null()
      type(loads_t) :: loads
      type(water_loads_t) :: water            !< water and seabed (scene in water only)
      real(wp), allocatable :: zero3(:, :)    !< (3, nn) zero velocities and accelerations
      real(wp) :: lam = 0.0_wp                !< load factor of the current increment
      real(wp), allocatable :: gfac(:)        !< (0:nl) gravity factor of each line, 0: points
      real(wp), allocatable :: r0(:, :)       !< (6, nn) residual of the start, lam = 0
      real(wp), allocatable :: d0(:, :, :)    !< (3, 3, nn) directors of the start
      integer, allocatable :: gauge_node(:)   !< (ne) node of each roll gauge, 0: none
      real(wp), allocatable :: gauge_k(:)     !< (ne) its stiffness k_g [N m/rad]
      real(wp), allocatable :: x_held(:, :)   !< (3, nn) position prescribed at lam [m]
      real(wp), allocatable :: x_conv(:, :)   !< (3, nn) last converged increment
      real(wp), allocatable :: d_conv(:, :, :) !< (3, 3, nn)
      !> clamped ends on a vessel turned by its static offset heading (vessel_offsets):
      !> node, heading offset [rad], directors at rest; d_i = Rz(lam psi) d_i(rest)
      integer, allocatable :: turn_node(:)
      real(wp), allocatable :: turn_psi(:)
      real(wp), allocatable :: turn_d(:, :, :)
   contains
      procedure :: evaluate => static_evaluate
      procedure :: save_base => static_save_base
      procedure :: apply_correction => static_apply_correction
   end type static_problem_t

contains

   !> Allocate the workspace and build supports and loads.
   subroutine statics_setup(prob, model, mesh, state)
      type(static_problem_t), intent(inout) :: prob !< problem
      type(model_t), intent(in) :: model            !< model
      type(mesh_t), intent(in), target :: mesh      !< mesh
      type(state_t), intent(in), target :: state    !< configuration, updated by solves
      integer :: nn
      call supports_build(model, mesh, state, prob%sup)
      call rod_problem_init(prob, model, mesh)
      call junctions_clamp(prob%jn, state%d)
      prob%state => state
      nn = mesh%n_nodes
      call loads_build(model, mesh, prob%loads)
      call water_loads_build(model, mesh, prob%water)
      allocate (prob%zero3(3, nn))
      prob%zero3 = 0.0_wp
      allocate (prob%gfac(0:mesh%n_lines), prob%r0(6, nn), prob%x_held(3, nn), &
                prob%x_conv(3, nn), prob%d_conv(3, 3, nn), prob%d0(3, 3, nn))
      prob%gfac = 1.0_wp
      prob%r0 = 0.0_wp
      prob%d0 = state%d
      call roll_gauges(mesh, prob%sup, prob%loads, prob%gauge_node, prob%gauge_k)
      call vessel_offsets(model, mesh, state, prob%sup, prob%turn_node, prob%turn_psi, &
                          prob%turn_d)
   end subroutine statics_setup

   !> The vessels' static offsets (OFFSET START=STATIC, docs/vessels.md): a node on a
   !> vessel (*MOTION, TYPE=VESSEL) is moved by the load steps from its place with the
   !> vessel at rest to the same vessel point with the vessel at its offset,
   !>   X = O + offset_1:3 + Rz(psi0 + offset_psi) p,  p = Rz(psi0)^T (x - O),
   !> and a clamped one (rotations held) is turned by Rz(lam offset_psi) with it.
   !> docs/theory.md eqs. (103), (105).
   pure subroutine vessel_offsets(model, mesh, state, sup, turn_node, turn_psi, turn_d)
      type(model_t), intent(in) :: model         !< model
      type(mesh_t), intent(in) :: mesh           !< mesh
      type(state_t), intent(in) :: state         !< start configuration
      type(supports_t), intent(inout) :: sup     !< targets of the moved nodes set
      integer, allocatable, intent(out) :: turn_node(:)    !< clamped nodes turned
      real(wp), allocatable, intent(out) :: turn_psi(:)    !< their turn [rad]
      real(wp), allocatable, intent(out) :: turn_d(:, :, :) !< their directors at rest
      integer :: i, node
      allocate (turn_node(0), turn_psi(0), turn_d(3, 3, 0))
      if (.not. allocated(model%motions)) return
      do i = 1, size(model%motions)
         associate (mo => model%motions(i))
            if (mo%kind /= motion_vessel .or. mo%line == 0) cycle  ! (a body: no offset)
            associate (ve => model%vessels(mo%vessel))
               if (.not. ve%offset_static .or. all(ve%offset == 0.0_wp)) cycle
               node = mesh_node(mesh, mo%line, mo%node)
               sup%x_target(:, node) = vessel_offset_point(ve, sup%x_target(:, node), 1.0_wp)
               sup%moved(node) = .true.
               if (sup%ndof(node) /= 6 .or. .not. all(sup%held(4:6, node)) .or. &
                   ve%offset(4) == 0.0_wp) cycle
               turn_node = [turn_node, node]
               turn_psi = [turn_psi, ve%offset(4)]
               turn_d = reshape([turn_d, state%d(:, :, node)], [3, 3, size(turn_node)])
            end associate
         end associate
      end do
   end subroutine vessel_offsets


   !> Set the load factor lam and the factor cur on the current's velocity: external
   !> forces and the prescribed positions of held nodes (reached by the next Newton step,
   !> see apply_supports).
   !> docs/theory.md eq. (109) and the list above it.
   subroutine static_set_load_factor(prob, lam, cur)
      type(static_problem_t), intent(inout) :: prob !< problem
      real(wp), intent(in) :: lam                   !< load factor [-]
      real(wp), intent(in) :: cur                   !< current factor [-]
      integer :: i
      prob%lam = lam
      ! (a FREE point's own weight and buoyancy in full, gfac(0): the homotopy holds the
      ! point where it starts at lam = 0)
      where (.not. prob%mesh%line_catenary) prob%gfac(1:) = lam
      ! the buoyancy with the weight: the weight in water is what is ramped (buoyancy in
      ! full under a tenth of the weight floated a free-hanging riser up and flipped it)
      if (prob%water%active) prob%water%bfac = prob%gfac
      call external_force(prob%mesh, prob%loads, prob%gfac, lam, 0.0_wp, prob%fext)
      ! the current's drag is a load like the others
      if (prob%water%active) prob%water%env%r_current = cur*current_factor(prob%water%env% &
                                                                            water, 0.0_wp)
      prob%x_held = prob%sup%x_start + lam*(prob%sup%x_target - prob%sup%x_start)
      ! clamped ends on a vessel at its offset (vessel_offsets): their held rotation
      ! unknowns keep these directors through Newton
      do i = 1, size(prob%turn_node)
         prob%state%d(:, :, prob%turn_node(i)) = matmul(rotation_z(lam*prob%turn_psi(i)), &
                                                        prob%turn_d(:, :, i))
      end do
   end subroutine static_set_load_factor

   !> Residual r = f_int - f_water - f_ext - (1 - lambda) r_0 (module header) and, if
   !> want_k, its tangent; the supports applied (apply_supports).
   !> docs/theory.md eqs. (107)-(108).
   subroutine static_evaluate(this, want_k, err)
      class(static_problem_t), intent(inout) :: this !< problem
      logical, intent(in) :: want_k                  !< form the tangent
      type(error_t), intent(inout) :: err            !< status (unused: cannot fail)
      integer :: node
      if (has_error(err)) return
      call assemble_static(this%mesh, this%sup, this%state, this%lam, this%fint, this%bm, &
                           want_k)
      ! seabed contact in full from the start, buoyancy with the weight (bfac), current
      ! drag times lambda
      if (this%water%active) call assemble_water(this%water, this%mesh, this%sup, &
                                                 this%state%x, this%zero3, this%zero3, &
                                                 1.0_wp, 0.0_wp, 0.0_wp, this%fint, &
                                                 this%bm, want_k)
      if (this%bl%nb > 0 .and. this%water%active) call body_water_set(this%bl, &
         this%water%env%water, this%water%env%r_current, this%water%field, .false., 0.0_wp, &
         this%state%x, this%state%d)
      if (this%bl%nb > 0) call assemble_bodies(this%bl, this%sup, this%state%x, this%state%x, &
                                               this%state%d, this%state%d, 1.0_wp, &
                                               this%fext, this%loads%gravity, this%fint, &
                                               this%bm, want_k)
      call homotopy_and_gauge(this, want_k)
      do node = 1, this%mesh%n_nodes
         this%gap(:, node) = 0.0_wp
         if (this%sup%moved(node)) this%gap(:, node) = this%x_held(:, node) - this%state%x(:, node)
      end do
      call apply_supports(this%sup, this%r, this%gap, this%rhs, this%bm, want_k)
      call junctions_condense(this%jn, this%sup, this%rhs, this%bm, want_k, this%state%d, &
                              this%state%d, 1.0_wp)
      ! the reactions are this problem's reference force and moment
      this%f_extra = 0.0_wp
      this%m_extra = 0.0_wp
      do node = 1, this%mesh%n_nodes
         if (any(this%sup%held(1:3, node))) &
            this%f_extra = max(this%f_extra, maxval(abs(this%r(1:3, node))))
         if (any(this%sup%held(4:6, node))) &
            this%m_extra = max(this%m_extra, maxval(abs(this%r(4:6, node))))
      end do
   end subroutine static_evaluate

   !> r = f_int - f_ext - (1 - lambda) r0(u), the start's moments turned with their
   !> node, and (want_k) their tangent and the roll gauges (module header).
   !> docs/theory.md eqs. (108), (111).
   subroutine homotopy_and_gauge(this, want_k)
      class(static_problem_t), intent(inout) :: this !< problem
      logical, intent(in) :: want_k                  !< add to the tangent
      real(wp) :: m0(3), kb(6, 6), w
      integer :: node
      w = 1.0_wp - this%lam
      if (w == 0.0_wp) then                  ! the last increment: the problem itself
         this%r = this%fint - this%fext
      else
         do node = 1, this%mesh%n_nodes
            m0 = turned_moment(this%state%d(:, :, node), this%d0(:, :, node), &
                               this%r0(4:6, node))
            this%r(1:3, node) = this%fint(1:3, node) - this%fext(1:3, node) &
                                - w*this%r0(1:3, node)
            this%r(4:6, node) = this%fint(4:6, node) - this%fext(4:6, node) - w*m0
            if (want_k .and. any(m0 /= 0.0_wp)) then
               kb = 0.0_wp
               kb(4:6, 4:6) = w*skew(m0)
               call add_node_block(this%sup, node, kb, this%bm)
            end if
         end do
      end if
      if (want_k) call add_roll_gauges(this%sup, this%gauge_node, this%gauge_k, &
                                       this%state%d, this%bm)
   end subroutine homotopy_and_gauge

   !> d d0^T m: a moment m given in the axes d0 carried into the axes d. (Explicit
   !> shapes; the nested matmul of the sections made two heap temporaries a node and
   !> evaluation, which bench/alloc_check.sh caught.)
   pure function turned_moment(d, d0, m) result(mt)
      real(wp), intent(in) :: d(3, 3)   !< directors now, d(:, i) = d_i
      real(wp), intent(in) :: d0(3, 3)  !< directors the moment was given in
      real(wp), intent(in) :: m(3)      !< moment [N m]
      real(wp) :: mt(3)                 !< the moment turned with the directors [N m]
      real(wp) :: c(3)
      integer :: i
      do i = 1, 3
         c(i) = d0(1, i)*m(1) + d0(2, i)*m(2) + d0(3, i)*m(3)
      end do
      mt = d(:, 1)*c(1) + d(:, 2)*c(2) + d(:, 3)*c(3)
   end function turned_moment

   subroutine static_save_base(this)
      class(static_problem_t), intent(inout) :: this !< problem
      this%x_base = this%state%x
      this%d_base = this%state%d
   end subroutine static_save_base

   !> x = x_base + alpha du_x;  d_i = cay(alpha du_theta) d_i,base (docs/theory.md eq. (46)).
   subroutine static_apply_correction(this, alpha)
      class(static_problem_t), intent(inout) :: this !< problem
      real(wp), intent(in) :: alpha                  !< step length [-]
      integer :: node, k
      do node = 1, this%mesh%n_nodes
         k = this%sup%first(node) - 1
         this%state%x(:, node) = this%x_base(:, node) + alpha*this%du(k + 1:k + 3)
      end do
      call this%rotate_from_base(alpha, this%state%d)
      call junctions_place(this%jn, this%state%x, this%state%d)
   end subroutine static_apply_correction

   !> Load stepping from lambda = 0 to 1 with bounded halving of failed increments.
   !> On failure the state is the last converged one and summary says how far it got.
   !> The current's velocity grows with lambda, but where a line is not started as a
   !> catenary and the deck has a current, in a second stage: lambda to 1 in still
   !> water, then the current's factor from 0 to 1 in as many increments. A line that
   !> starts straight and slack (a free-hanging riser) has no tension at the start and
   !> so no stiffness against swinging about its top: the first Newton step under a
   !> drag load across it turned it by thousands of radians, and the solve ended in the
   !> upside-down equilibrium. With its weight in full first the line is taut.
   !> docs/theory.md eqs. (109)-(110).
   subroutine statics_solve(prob, model, summary, err, log_unit)
      type(static_problem_t), intent(inout) :: prob !< set-up problem
      type(model_t), intent(in) :: model            !< model (static options)
      type(run_summary_t), intent(inout) :: summary !< progress
      type(error_t), intent(inout) :: err           !< status
      integer, intent(in) :: log_unit               !< log unit (< 0: silent)
      type(newton_options_t) :: opts
      type(newton_stats_t) :: stats
      type(error_t) :: nerr
      real(wp) :: lam, dlam, dlam0, lam_try
      integer :: level, stage, n_stages
      logical :: retried, staged
      character(len=:), allocatable :: why
      opts = static_newton_options(model, log_unit)
      dlam0 = 1.0_wp/real(model%static%increments, wp)
      staged = .false.
      if (prob%water%active .and. allocated(model%water%cur_z)) &
         staged = size(model%water%cur_z) > 0 .and. .not. all(prob%mesh%line_catenary)
      n_stages = merge(2, 1, staged)
      lam = 0.0_wp
      call set_factor(1, lam)
      call prob%evaluate(.false., nerr)
      prob%r0 = prob%fint - prob%fext
      prob%d0 = prob%state%d
      do stage = 1, n_stages
      lam = 0.0_wp
      level = 0
      retried = .false.
      do while (lam < 1.0_wp)
         dlam = dlam0*0.5_wp**level
         lam_try = min(1.0_wp, lam + dlam)
         if (1.0_wp - lam_try < 1.0e-12_wp) lam_try = 1.0_wp
         if (log_unit >= 0) write (log_unit, '(a,i0,3a,f10.7)') 'increment ', &
            summary%increments + 1, ': ', factor_name(stage), ' ', lam_try
         prob%x_conv = prob%state%x
         prob%d_conv = prob%state%d
         call set_factor(stage, lam_try)
         call clear_error(nerr)
         opts%line_search = model%static%line_search .or. retried
         call newton_solve(prob, opts, stats, nerr)
         summary%iterations = summary%iterations + stats%iterations
         if (stats%converged .and. .not. has_error(nerr)) then
            lam = lam_try
            summary%increments = summary%increments + 1
            if (stage == 1) summary%load_factor = lam
            if (level > 0) level = level - 1
            retried = .false.
            cycle
         end if
         ! failed: back to the last converged state, halve the increment
         prob%state%x = prob%x_conv
         prob%state%d = prob%d_conv
         call set_factor(stage, lam)
         if (log_unit >= 0) then
            if (has_error(nerr)) then
               write (log_unit, '(2a)') '  failed: ', nerr%message
            else
               write (log_unit, '(a,es10.3)') '  not converged, residual ', stats%residual
            end if
         end if
         if (.not. retried .and. .not. model%static%line_search) then
            retried = .true.             ! same increment again, with the line search
            if (log_unit >= 0) write (log_unit, '(a)') '  retry with the line search'
            cycle
         end if
         retried = .false.
         if (level >= model%static%max_cutbacks) then
            why = no_convergence(model, prob%mesh, stage, lam, level, nerr)
            call set_error(err, stat_numerical, why)
            summary%status = why
            summary%complete = .false.
            return
         end if
         level = level + 1
         summary%cutbacks = summary%cutbacks + 1
      end do
      end do
      ! a converged shape can still be a spurious one of cubic rods (rodyn_mesh)
      why = mesh_spurious_shape(model, prob%mesh, prob%state)
      if (len(why) > 0) then
         call set_error(err, stat_numerical, 'statics: '//why)
         summary%status = 'statics: '//why
         summary%complete = .false.
         return
      end if
      summary%complete = .true.
      summary%status = 'complete'
   contains
      !> Stage 1: the load factor f (with the current unless staged); 2: the current's.
      subroutine set_factor(stage, f)
         integer, intent(in) :: stage   !< 1 or 2
         real(wp), intent(in) :: f      !< factor of the stage [-]
         if (stage == 1) then
            call static_set_load_factor(prob, f, merge(0.0_wp, f, staged))
         else
            call static_set_load_factor(prob, 1.0_wp, f)
         end if
      end subroutine set_factor
   end subroutine statics_solve

   !> Newton's options of the statics (*STATIC).
   pure function static_newton_options(model, log_unit) result(opts)
      type(model_t), intent(in) :: model     !< model (static options)
      integer, intent(in) :: log_unit        !< log unit (< 0: silent)
      type(newton_options_t) :: opts
      opts%max_iterations = model%static%max_iterations
      opts%force_tol = model%static%force_tol
      opts%disp_tol = model%static%disp_tol
      opts%line_search = model%static%line_search
      opts%log_unit = log_unit
   end function static_newton_options

   !> The name of the factor stage 1 (the loads) or 2 (the current) raises.
   pure function factor_name(stage) result(name)
      integer, intent(in) :: stage   !< 1 or 2
      character(len=:), allocatable :: name
      if (stage == 1) then
         name = 'load factor'
      else
         name = 'current factor (the weight in full)'
      end if
   end function factor_name

   !> The message of statics that stopped at factor lam after `level` halvings: what
   !> diverged (a load beyond the lines' reach, else the solver's reason) and, for rods
   !> that are cables in all but name, that advice.
   function no_convergence(model, mesh, stage, lam, level, nerr) result(text)
      type(model_t), intent(in) :: model     !< model
      type(mesh_t), intent(in) :: mesh       !< mesh
      integer, intent(in) :: stage           !< 1 or 2 (factor_name)
      real(wp), intent(in) :: lam            !< the factor reached [-]
      integer, intent(in) :: level           !< halvings of the increment
      type(error_t), intent(in) :: nerr      !< the last Newton's error, if any
      character(len=:), allocatable :: text
      character(len=200) :: msg
      character(len=:), allocatable :: why, hint
      write (msg, '(3a,f9.6,a,i0,a)') 'statics: no convergence beyond ', &
         factor_name(stage), ' ', lam, ' after ', level, ' halvings of the increment'
      why = load_divergence_hint(model)
      if (len(why) == 0 .and. has_error(nerr)) why = nerr%message
      if (len(why) > 0) why = ' ('//why//')'
      hint = mesh_cable_like_rods(model, mesh)
      if (len(hint) > 0) why = why//'; '//hint
      text = trim(msg)//why
   end function no_convergence
   !> Set up and solve the static problem of a built mesh; wall time into summary.
   subroutine statics_run(prob, model, mesh, state, summary, err, log_unit)
      type(static_problem_t), intent(inout) :: prob  !< problem (workspace allocated here)
      type(model_t), intent(in) :: model             !< model
      type(mesh_t), intent(in), target :: mesh       !< mesh
      type(state_t), intent(inout), target :: state  !< initial, then solved configuration
      type(run_summary_t), intent(inout) :: summary  !< progress
      type(error_t), intent(inout) :: err            !< status
      integer, intent(in) :: log_unit                !< iteration log unit (< 0: silent)
      integer(kind=8) :: t0, t1, rate
      call system_clock(t0, rate)
      call statics_setup(prob, model, mesh, state)
      call statics_solve(prob, model, summary, err, log_unit)
      call system_clock(t1)
      summary%wall_time = real(t1 - t0, wp)/real(rate, wp)
   end subroutine statics_run

   !> The support forces (prob%r) of the start state with every load in full, without
   !> solving: a run that starts its dynamics from the lines' starting shapes (a host's
   !> MoorDyn_Init_NoIC) reads them until its first step. docs/theory.md eq. (108) at
   !> lambda = 1.
   subroutine statics_start_forces(prob, model, mesh, state)
      type(static_problem_t), intent(inout) :: prob    !< problem (r set)
      type(model_t), intent(in) :: model               !< model
      type(mesh_t), intent(in), target :: mesh         !< mesh
      type(state_t), intent(in), target :: state       !< the start state
      type(error_t) :: nerr
      call statics_setup(prob, model, mesh, state)
      call static_set_load_factor(prob, 1.0_wp, 1.0_wp)
      call prob%evaluate(.false., nerr)
   end subroutine statics_start_forces
end module rodyn_statics
