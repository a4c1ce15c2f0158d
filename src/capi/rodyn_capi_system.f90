!> A mooring system driven by a host program step by step, as MoorDyn's C API drives
!> one (docs/capi.md): a run's data by lifetime in one object, md_system_t: the model
!> read from a MoorDyn file (parameters), the mesh, the dynamic problem and the time
!> loop's state (the state the steps advance), the results of the state last asked
!> for (scratch). The C functions (rodyn_capi) hold a pointer to it.
!>
!> Life: system_create reads the file; system_init puts the coupled points where the
!> host says, solves the statics (MoorDyn's initial condition) and sets up the dynamics;
!> each system_step moves the coupled points on the straight line from x (at t) with
!> velocity xd to x + xd dt, advances rodyn's implicit steps to t + dt (one step of dt,
!> halved where Newton needs it) and gives the lines' forces on the coupled points at
!> t + dt.
module rodyn_capi_system
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error, set_error, stat_input, stat_numerical
   use rodyn_model, only: model_t, motion_t, motion_table, end_a, end_b, point_free, &
                          point_body, body_fixed
   use rodyn_mesh, only: mesh_t, mesh_build, mesh_node
   use rodyn_state, only: state_t
   use rodyn_statics, only: static_problem_t, statics_run, statics_start_forces
   use rodyn_results, only: run_summary_t, step_log_t
   use rodyn_dynamics, only: dynamic_problem_t, dynamics_setup
   use rodyn_system_dynamics, only: failures_add, end_released
   use rodyn_timeloop, only: timeloop_state_t, timeloop_observer_t, timeloop_begin, &
                             timeloop_advance
   use rodyn_moordyn, only: moordyn_read, moordyn_file, md_info_t
   use rodyn_deck, only: deck_read
   use rodyn_rotation, only: axial, cross
   use rodyn_capi_bodies, only: add_body_vessels, body_pose_row, body_forces
   implicit none
   private
   public :: md_system_t, system_create, system_init, system_step, system_forces
   public :: system_node_x, system_node_tension, system_ndof, system_body_state
   public :: system_break, system_point_node, system_point_x, system_end_force
   public :: system_tension_served

   !> What the time loop hands a host-driven run: the step forces of the last three steps,
   !> from which the forces at the end of the step are taken (support_forces).
   type, extends(timeloop_observer_t) :: host_observer_t
      !> (6, nn) step forces of the last step, the one before and the one before that
      real(wp), allocatable :: r_last(:, :), r_back(:, :), r_back2(:, :)
      real(wp) :: h_last = 0.0_wp, h_back = 0.0_wp, h_back2 = 0.0_wp !< their steps [s]
      logical :: have_last = .false., have_back = .false., have_back2 = .false.
   contains
      procedure :: on_frame => host_frame
      procedure :: on_step => host_step
      procedure :: after_step => host_after
      procedure :: on_checkpoint => host_checkpoint
   end type host_observer_t

   !> A mooring system a host drives.
   type :: md_system_t
      type(model_t) :: model                    !< parameters: the model read
      type(mesh_t) :: mesh                      !< the mesh
      type(state_t) :: state                    !< the statics, then the steps' iterate
      type(dynamic_problem_t) :: prob           !< the dynamic problem
      type(timeloop_state_t) :: ls              !< the time loop's state
      type(run_summary_t) :: summary            !< counters
      type(host_observer_t) :: obs              !< the step forces
      integer, allocatable :: coupled(:)        !< model%points moved by the host, in order
      integer, allocatable :: cbody(:)          !< model%bodies moved by the host, in order
      integer, allocatable :: cvessel(:)        !< the vessel of each (prob%vessels)
      integer, allocatable :: motion(:)         !< the motion of each (model%motions)
      real(wp), allocatable :: x0(:, :)         !< (3, n) where each is at t = 0 [m]
      real(wp), allocatable :: r_static(:, :)   !< (6, nn) support forces of the statics
      real(wp) :: t = 0.0_wp                    !< time reached [s]
      real(wp) :: dt_max = 0.0_wp               !< largest step (MoorDyn_SetDt; 0: none) [s]
      real(wp), allocatable :: xd_last(:)       !< the coupled DOFs' rates of the last step
      integer :: stage = 0                      !< 0 read, 1 initialised, -1 failed
      integer :: n_points = 0                   !< MoorDyn's points: model%points(1:n)
      integer :: n_bodies = 0                   !< MoorDyn's bodies: model%bodies(1:n)
      character(len=:), allocatable :: notes    !< the reader's notes
      type(md_info_t) :: info                   !< the file's besides the model
   end type md_system_t

contains

   !> Read the MoorDyn file or rodyn deck at path into sys: the coupled points and bodies
   !> are those with HOST=YES, in order. Errors as the reader's (stat_input); a coupled
   !> rod is refused (not driven through the API).
   subroutine system_create(sys, path, err)
      type(md_system_t), intent(inout), target :: sys !< the system
      character(len=*), intent(in) :: path            !< the MoorDyn file
      type(error_t), intent(inout) :: err             !< status
      character(len=:), allocatable :: warnings
      if (moordyn_file(path)) then
         call moordyn_read(path, sys%model, err, sys%notes, warnings, host=.true., &
                           info=sys%info)
      else
         call deck_create(sys, path, err)
      end if
      if (has_error(err)) return
      sys%coupled = host_points(sys%model)
      sys%cbody = host_bodies(sys%model)
      sys%n_points = sys%info%n_points
      sys%n_bodies = sys%info%n_bodies
      if (size(sys%info%coupled_rods) > 0) call set_error(err, stat_input, path// &
         ': error: RODS: a coupled rod is not driven through librodyn (docs/capi.md)')
      sys%stage = 0
   end subroutine system_create

   !> A rodyn deck (docs/deck.md) as a system: its own *DYNAMIC steps through the host's
   !> calls, driven by its *MOTIONs, waves and current and by the host for the points and
   !> bodies with HOST=YES; every point and body of the deck as MoorDyn's points and
   !> bodies, its lines in deck order.
   subroutine deck_create(sys, path, err)
      type(md_system_t), intent(inout) :: sys !< the system
      character(len=*), intent(in) :: path    !< the deck
      type(error_t), intent(inout) :: err     !< status
      sys%notes = ''
      call deck_read(path, sys%model, err)
      if (has_error(err)) return
      if (.not. sys%model%dynamic%requested) then
         call set_error(err, stat_input, path//': error: a deck driven through librodyn '// &
                        'needs its *DYNAMIC (the scheme and tolerances of its steps)')
         return
      end if
      allocate (sys%info%coupled_rods(0), sys%info%rod_nodes(0), sys%info%rod_ends(6, 0), &
                sys%info%outputs(0), sys%info%output_line(0))
      if (allocated(sys%model%points)) sys%info%n_points = size(sys%model%points)
      if (allocated(sys%model%bodies)) sys%info%n_bodies = size(sys%model%bodies)
   end subroutine deck_create

   !> The coupled bodies (6 a body: MoorDyn's pose) and points (3 a point) to x, in
   !> MoorDyn's order, the statics solved, the dynamics set up from it (t = 0). x:
   !> MoorDyn_Init's positions; their velocities are not used (the statics start at
   !> rest). A body turned at Init is refused (rodyn's bodies start with the global axes).
   subroutine system_init(sys, x, err, no_statics)
      type(md_system_t), intent(inout), target :: sys !< the system
      real(wp), intent(in) :: x(:)                    !< (system_ndof) coupled DOFs
      type(error_t), intent(inout) :: err             !< status
      !> start the dynamics from the lines' starting shapes, the points and bodies where the
      !> file has them, without the statics (MoorDyn_Init_NoIC)
      logical, intent(in), optional :: no_statics
      type(static_problem_t), allocatable :: sp
      integer :: i, ip, nm, nb
      logical :: solve
      nb = 6*size(sys%cbody)
      do i = 1, size(sys%cbody)
         if (any(abs(x(6*i - 2:6*i)) > 1.0e-12_wp)) then
            call set_error(err, stat_input, 'MoorDyn_Init: coupled body '// &
                           trim(sys%model%bodies(sys%cbody(i))%name)//' turned: rodyn''s '// &
                           'bodies start with the global axes')
            return
         end if
         sys%model%bodies(sys%cbody(i))%position = x(6*i - 5:6*i - 3)
         do ip = 1, size(sys%model%points)
            if (sys%model%points(ip)%body /= sys%cbody(i)) cycle
            call move_point(sys%model, ip, x(6*i - 5:6*i - 3) + sys%model%points(ip)%position)
         end do
      end do
      do i = 1, size(sys%coupled)
         sys%model%points(sys%coupled(i))%position = x(nb + 3*i - 2:nb + 3*i)
         call move_point(sys%model, sys%coupled(i), x(nb + 3*i - 2:nb + 3*i))
      end do
      call mesh_build(sys%model, sys%mesh, sys%state, err, initial_shape=.true.)
      if (has_error(err)) return
      allocate (sp)
      solve = .true.
      if (present(no_statics)) solve = .not. no_statics
      if (solve) then
         call statics_run(sp, sys%model, sys%mesh, sys%state, sys%summary, err, -1)
      else
         call statics_start_forces(sp, sys%model, sys%mesh, sys%state)
      end if
      if (has_error(err)) then
         sys%stage = -1
         return
      end if
      sys%r_static = sp%r
      deallocate (sp)
      ! each coupled point moved by a table the steps extend, from where it is
      nm = 0
      if (allocated(sys%model%motions)) nm = size(sys%model%motions)
      allocate (sys%motion(size(sys%coupled)), sys%x0(3, size(sys%coupled)))
      do i = 1, size(sys%coupled)
         sys%x0(:, i) = x(nb + 3*i - 2:nb + 3*i)
         sys%motion(i) = nm + i
      end do
      call add_motions(sys%model, sys%coupled)
      allocate (sys%cvessel(size(sys%cbody)))
      call add_body_vessels(sys%model, sys%cbody, sys%cvessel)
      sys%model%dynamic%duration = huge(1.0_wp)
      call dynamics_setup(sys%prob, sys%model, sys%mesh, sys%state)
      call timeloop_begin(sys%prob, sys%model, err, sys%obs, sys%ls)
      sys%obs%after_step_used = .true.
      sys%t = 0.0_wp
      sys%stage = 1
   end subroutine system_init

   !> Point ip at x (global), with the line ends on it.
   subroutine move_point(model, ip, x)
      type(model_t), intent(inout) :: model !< model
      integer, intent(in) :: ip             !< the point
      real(wp), intent(in) :: x(3)          !< where [m]
      integer :: l
      model%points(ip)%global = x
      do l = 1, size(model%lines)
         if (model%lines(l)%point_a == ip) model%lines(l)%end_a = x
         if (model%lines(l)%point_b == ip) model%lines(l)%end_b = x
      end do
   end subroutine move_point

   !> The points with HOST=YES, in order.
   pure function host_points(model) result(ip)
      type(model_t), intent(in) :: model    !< the system
      integer, allocatable :: ip(:)         !< their indices in model%points
      integer :: i
      allocate (ip(0))
      if (.not. allocated(model%points)) return
      ip = pack([(i, i=1, size(model%points))], model%points%host)
   end function host_points

   !> The bodies with HOST=YES, in order.
   pure function host_bodies(model) result(ib)
      type(model_t), intent(in) :: model    !< the system
      integer, allocatable :: ib(:)         !< their indices in model%bodies
      integer :: i
      allocate (ib(0))
      if (.not. allocated(model%bodies)) return
      ib = pack([(i, i=1, size(model%bodies))], model%bodies%host)
   end function host_bodies

   !> MoorDyn's coupled DOFs: 6 a coupled body, 3 a coupled point.
   pure integer function system_ndof(sys) result(n)
      type(md_system_t), intent(in) :: sys  !< the system
      n = 6*size(sys%cbody) + 3*size(sys%coupled)
   end function system_ndof

   !> A table motion at rest for each coupled point, appended to model%motions.
   subroutine add_motions(model, points)
      type(model_t), intent(inout) :: model !< model
      integer, intent(in) :: points(:)      !< the points
      type(motion_t), allocatable :: mo(:)
      integer :: i, n
      n = 0
      if (allocated(model%motions)) n = size(model%motions)
      allocate (mo(n + size(points)))
      if (n > 0) mo(1:n) = model%motions
      do i = 1, size(points)
         mo(n + i)%point = points(i)
         mo(n + i)%line = 0
         mo(n + i)%kind = motion_table
         mo(n + i)%ramp = 0.0_wp
         mo(n + i)%file = 'host'
         mo(n + i)%time = [0.0_wp]
         mo(n + i)%disp = reshape([0.0_wp, 0.0_wp, 0.0_wp], [3, 1])
      end do
      call move_alloc(mo, model%motions)
   end subroutine add_motions

   !> One coupling step of the host from t = sys%t: the coupled points from x with
   !> velocity xd to x + xd dt, the system advanced to t + dt, f the lines' forces on the
   !> coupled points at t + dt [N] (3 a point). dt <= 0: f only.
   subroutine system_step(sys, x, xd, dt, f, err)
      type(md_system_t), intent(inout), target :: sys !< the system
      real(wp), intent(in) :: x(:)                    !< (system_ndof) DOFs at t [m, rad]
      real(wp), intent(in) :: xd(:)                   !< (system_ndof) their rates
      real(wp), intent(in) :: dt                      !< coupling step [s]
      real(wp), intent(out) :: f(:)                   !< (system_ndof) forces at t + dt
      type(error_t), intent(inout) :: err             !< status
      real(wp) :: t1
      logical :: halt
      integer :: i, nb
      if (dt > 0.0_wp) then
         t1 = sys%t + dt
         nb = 6*size(sys%cbody)
         do i = 1, size(sys%cbody)
            call body_pose_row(sys%prob%vessels(sys%cvessel(i)), t1, &
                               x(6*i - 5:6*i) + xd(6*i - 5:6*i)*dt)
         end do
         do i = 1, size(sys%coupled)
            ! the table's last row (at t) and the step's end: all a step and its halvings
            ! read (a table grown a row a step would be copied whole every step)
            associate (mo => sys%model%motions(sys%motion(i)))
               mo%time = [mo%time(size(mo%time)), t1]
               mo%disp = reshape([mo%disp(:, size(mo%disp, 2)), x(nb + 3*i - 2:nb + 3*i) + &
                                  xd(nb + 3*i - 2:nb + 3*i)*dt - sys%x0(:, i)], [3, 2])
            end associate
         end do
         ! one step a coupling step, or the fewest equal steps no longer than dt_max
         sys%model%dynamic%dt = dt
         if (sys%dt_max > 0.0_wp) sys%model%dynamic%dt = &
            dt/real(max(1, ceiling(dt/sys%dt_max - 1.0e-9_wp)), wp)
         call timeloop_advance(sys%prob, sys%model, sys%summary, err, -1, sys%obs, sys%ls, &
                               t1, halt)
         if (halt .or. has_error(err)) then
            sys%stage = -1
            if (.not. has_error(err)) call set_error(err, stat_numerical, &
                                                     'the step to t = t + dt failed')
            return
         end if
         sys%t = t1
         sys%xd_last = xd
      end if
      call system_forces(sys, f)
   end subroutine system_step

   !> The lines' forces on the coupled bodies (force and moment about the reference point,
   !> 6 a body) and points (3 a point) at sys%t [N, N m]: minus the support forces of the
   !> line ends on each, the step forces extrapolated from their force points to the
   !> step's end (the statics' before the first step).
   subroutine system_forces(sys, f)
      type(md_system_t), intent(in) :: sys  !< the system
      real(wp), intent(out) :: f(:)         !< (system_ndof) forces [N, N m]
      real(wp), allocatable :: r(:, :)
      real(wp) :: rb(3)
      integer :: i, l, k, node, nb
      r = support_forces(sys)
      f = 0.0_wp
      nb = 6*size(sys%cbody)
      do i = 1, size(sys%cbody)
         rb = sys%model%bodies(sys%cbody(i))%position
         if (sys%stage == 1) then
            associate (ve => sys%prob%vessels(sys%cvessel(i)))
               rb = ve%origin + ve%motion(1:3, size(ve%time))
            end associate
         end if
         f(6*i - 5:6*i) = body_forces(sys%model, sys%mesh, sys%prob%fl, sys%state%x, r, &
                                       sys%cbody(i), rb)
      end do
      do i = 1, size(sys%coupled)
         do l = 1, size(sys%model%lines)
            do k = 1, 2
               if (merge(sys%model%lines(l)%point_a, sys%model%lines(l)%point_b, k == 1) &
                   /= sys%coupled(i)) cycle
               node = mesh_node(sys%mesh, l, merge(end_a, end_b, k == 1))
               if (end_released(sys%prob%fl, node)) cycle
               f(nb + 3*i - 2:nb + 3*i) = f(nb + 3*i - 2:nb + 3*i) - r(1:3, node)
            end do
         end do
      end do
   end subroutine system_forces

   !> The support forces of every node at sys%t [N, N m]: the statics' before the first
   !> step. After three steps, from the step forces at the force points t_k of the last
   !> three: through them r(t) = a + b t + c (-1)^k, a line and a part alternating from
   !> step to step (the dissipative scheme's history stress and a held node's inertia,
   !> docs/capi.md), and at the step's end its line, a + b t (exact for forces linear in
   !> time). After one or two steps: the last step's force, or the line through the two.
   function support_forces(sys) result(r)
      type(md_system_t), intent(in) :: sys  !< the system
      real(wp), allocatable :: r(:, :)      !< (6, nn)
      real(wp) :: w, t0, t1, t2
      w = sys%prob%wf
      if (.not. sys%obs%have_last) then
         r = sys%r_static
      else if (sys%obs%have_back2) then
         associate (o => sys%obs)
            ! the force points from the step's end (t = 0)
            t2 = -(1.0_wp - w)*o%h_last
            t1 = -o%h_last - (1.0_wp - w)*o%h_back
            t0 = -o%h_last - o%h_back - (1.0_wp - w)*o%h_back2
            ! b = (r2 - r0)/(t2 - t0) (the alternating part cancels), a = mean of r1 - b t1
            ! and r2 - b t2 (it cancels there too)
            r = 0.5_wp*(o%r_last + o%r_back) - (o%r_last - o%r_back2)*(0.5_wp*(t1 + t2)/ &
                (t2 - t0))
         end associate
      else if (sys%obs%have_back) then
         r = sys%obs%r_last + (sys%obs%r_last - sys%obs%r_back)*(1.0_wp - w)*sys%obs%h_last &
             /(w*sys%obs%h_last + (1.0_wp - w)*sys%obs%h_back)
      else
         r = sys%obs%r_last
      end if
   end function support_forces

   !> The force line l's end k (1 A, 2 B) exerts on the point holding it at sys%t [N]
   !> (minus its support force); ok false for an end not held (free, on a free point or
   !> body, or released).
   subroutine system_end_force(sys, l, k, f, ok)
      type(md_system_t), intent(in) :: sys  !< the system
      integer, intent(in) :: l, k           !< line, end
      real(wp), intent(out) :: f(3)         !< force [N]
      logical, intent(out) :: ok            !< an end held by a point
      real(wp), allocatable :: r(:, :)
      integer :: node, ip
      f = 0.0_wp
      node = mesh_node(sys%mesh, l, merge(end_a, end_b, k == 1))
      ip = merge(sys%model%lines(l)%point_a, sys%model%lines(l)%point_b, k == 1)
      ok = ip /= 0
      if (.not. ok) return
      associate (p => sys%model%points(ip))
         ! held: a fixed or coupled point, or one on a fixed or coupled body
         ok = p%kind /= point_free .and. .not. end_released(sys%prob%fl, node)
         if (ok .and. p%kind == point_body) ok = sys%model%bodies(p%body)%kind == body_fixed
      end associate
      if (.not. ok) return
      r = support_forces(sys)
      f = -r(1:3, node)
   end subroutine system_end_force

   !> MoorDyn_BreakLine: the end of line l on point ip (model%points) leaves it at the
   !> start of the next step (eq. (143)); the point's force counts it no more. An error if
   !> the system is not initialised or the line has no end on the point still on it.
   subroutine system_break(sys, ip, l, err)
      type(md_system_t), intent(inout) :: sys !< the system
      integer, intent(in) :: ip               !< the point
      integer, intent(in) :: l                !< the line
      type(error_t), intent(inout) :: err     !< status
      integer :: k, node
      if (sys%stage /= 1) then
         call set_error(err, stat_input, 'a line is broken only after Init')
         return
      end if
      do k = 1, 2
         if (merge(sys%model%lines(l)%point_a, sys%model%lines(l)%point_b, k == 1) /= ip) &
            cycle
         node = mesh_node(sys%mesh, l, merge(end_a, end_b, k == 1))
         if (end_released(sys%prob%fl, node)) cycle
         call failures_add(sys%prob%fl, node, sys%t)
         return
      end do
      call set_error(err, stat_input, 'line '//trim(sys%model%lines(l)%name)// &
                     ' has no end still on point '//trim(sys%model%points(ip)%name))
   end subroutine system_break

   !> The node of the first line end still on point ip (model%points), 0 when none.
   pure integer function system_point_node(sys, ip) result(node)
      type(md_system_t), intent(in) :: sys  !< the system
      integer, intent(in) :: ip             !< the point
      integer :: l, k
      do l = 1, size(sys%model%lines)
         do k = 1, 2
            if (merge(sys%model%lines(l)%point_a, sys%model%lines(l)%point_b, k == 1) &
                /= ip) cycle
            node = mesh_node(sys%mesh, l, merge(end_a, end_b, k == 1))
            if (.not. end_released(sys%prob%fl, node)) return
         end do
      end do
      node = 0
   end function system_point_node

   !> Where point ip is [m]: the node of a line end still on it once initialised, else
   !> where the file puts it (global axes).
   function system_point_x(sys, ip) result(x)
      type(md_system_t), intent(in) :: sys  !< the system
      integer, intent(in) :: ip             !< the point
      real(wp) :: x(3)
      integer :: node
      x = sys%model%points(ip)%global
      if (sys%stage /= 1) return
      node = system_point_node(sys, ip)
      if (node > 0) x = sys%state%x(:, node)
   end function system_point_x

   !> MoorDyn's state of body ib: its reference point and angles r, p, y (its orientation
   !> Q = Rx(r) Ry(p) Rz(y), the directors of its node), and their rates: the velocity of
   !> the reference point and the angular velocity (axial(dQ/dt Q^T)) [m, rad, m/s,
   !> rad/s].
   subroutine system_body_state(sys, ib, r, rd)
      type(md_system_t), intent(in) :: sys  !< the system
      integer, intent(in) :: ib             !< the body (model%bodies)
      real(wp), intent(out) :: r(6)         !< position and angles
      real(wp), intent(out) :: rd(6)        !< velocity and angular velocity
      real(wp) :: q(3, 3), w(3), g(3)
      integer :: n
      n = sys%mesh%body_node(ib)
      q = sys%state%d(:, :, n)
      g = matmul(q, sys%model%bodies(ib)%cog)
      w = axial(matmul(sys%state%dd(:, :, n), transpose(q)))
      r(1:3) = sys%state%x(:, n) - g
      r(5) = asin(max(-1.0_wp, min(1.0_wp, q(1, 3))))
      r(4) = atan2(-q(2, 3), q(3, 3))
      r(6) = atan2(-q(1, 2), q(1, 1))
      rd(1:3) = sys%state%v(:, n) - cross(w, g)
      rd(4:6) = w
   end subroutine system_body_state

   !> Position of node k (0 at end A) of line l [m].
   function system_node_x(sys, l, k) result(x)
      type(md_system_t), intent(in) :: sys  !< the system
      integer, intent(in) :: l              !< line
      integer, intent(in) :: k              !< node, from 0
      real(wp) :: x(3)
      x = sys%state%x(:, mesh_node(sys%mesh, l, k + 1))
   end function system_node_x

   !> MoorDyn's tension of node k (0 at end A) of line l [N]: the tension vector of each
   !> segment (EA strain times its unit vector, from A to B), at an inner node the mean
   !> of the two segments beside it, at an end the end segment's (MoorDyn's
   !> Line::getNodeTen). A segment is an element between nodes k and k + 1 (order 1, as
   !> a MoorDyn line is read); its tension is the cable law's at its stretch.
   !> Whether MoorDyn's node tension (system_node_tension) is served on line l: a line of
   !> linear elements of one section (as a MoorDyn line is read; a deck's line of higher
   !> order or of several segments is not).
   pure logical function system_tension_served(sys, l) result(yes)
      type(md_system_t), intent(in) :: sys  !< the system
      integer, intent(in) :: l              !< line
      yes = sys%model%lines(l)%order == 1
      if (allocated(sys%model%lines(l)%seg_section)) &
         yes = yes .and. size(sys%model%lines(l)%seg_section) <= 1
   end function system_tension_served

   function system_node_tension(sys, l, k) result(t)
      type(md_system_t), intent(in) :: sys  !< the system
      integer, intent(in) :: l              !< line
      integer, intent(in) :: k              !< node, from 0
      real(wp) :: t(3)
      integer :: n
      n = sys%mesh%line_n_nodes(l) - 1
      if (k == 0) then
         t = segment(0)
      else if (k >= n) then
         t = segment(n - 1)
      else
         t = 0.5_wp*(segment(k - 1) + segment(k))
      end if
   contains
      !> Tension vector of the segment from node j to j + 1.
      function segment(j) result(tv)
         integer, intent(in) :: j
         real(wp) :: tv(3), dx(3), len0, ea
         dx = system_node_x(sys, l, j + 1) - system_node_x(sys, l, j)
         len0 = sys%model%lines(l)%length/real(n, wp)
         ea = sys%model%sections(sys%model%lines(l)%section)%ea
         tv = max(0.0_wp, ea*(norm2(dx)/len0 - 1.0_wp))*dx/norm2(dx)
      end function segment
   end function system_node_tension

   subroutine host_frame(this, t, prob, err)
      class(host_observer_t), intent(inout) :: this !< the observer
      real(wp), intent(in) :: t                     !< time [s]
      type(dynamic_problem_t), intent(inout) :: prob !< problem
      type(error_t), intent(inout) :: err           !< status
   end subroutine host_frame

   subroutine host_step(this, log, err)
      class(host_observer_t), intent(inout) :: this !< the observer
      type(step_log_t), intent(in) :: log           !< the step
      type(error_t), intent(inout) :: err           !< status
   end subroutine host_step

   subroutine host_checkpoint(this, ls, prob, err)
      class(host_observer_t), intent(inout) :: this  !< the observer
      type(timeloop_state_t), intent(in) :: ls       !< the loop
      type(dynamic_problem_t), intent(inout) :: prob !< problem
      type(error_t), intent(inout) :: err            !< status
   end subroutine host_checkpoint

   !> After each step: its step forces kept, with the two steps' before.
   subroutine host_after(this, t, prob, err)
      class(host_observer_t), intent(inout) :: this !< the observer
      real(wp), intent(in) :: t                     !< time reached [s]
      type(dynamic_problem_t), intent(inout) :: prob !< problem after the step
      type(error_t), intent(inout) :: err           !< status
      if (this%have_back) then
         this%r_back2 = this%r_back
         this%h_back2 = this%h_back
         this%have_back2 = .true.
      end if
      if (this%have_last) then
         this%r_back = this%r_last
         this%h_back = this%h_last
         this%have_back = .true.
      end if
      this%r_last = prob%r
      this%h_last = prob%dt
      this%have_last = .true.
   end subroutine host_after
end module rodyn_capi_system
