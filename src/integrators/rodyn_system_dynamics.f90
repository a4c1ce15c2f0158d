!> What the dynamics of a mooring system adds to a line's (docs/systems.md): the velocities
!> of FREE points and of the ends on points and bodies at the start, a body's added mass
!> (docs/theory.md eqs. (142), (154); in EMC a translational one with its discrete Munk
!> moment, (151)), and line failure: a line end released from its support, point or body
!> at a given time or when its force first reaches a break load (*FAILURE; eq. (143)),
!> after which the run goes on with the system that remains; the bodies' wave loads set
!> up in the sea (eq. (150)); the nodes the *MOTIONs move (motion_nodes) and where a
!> step takes them (held_motion); and the initial velocities of lines and bodies
!> (*INITIAL VELOCITY).
module rodyn_system_dynamics
   use rodyn_kinds, only: wp
   use rodyn_model, only: model_t, end_a, end_b, motion_t, motion_table, motion_vessel, &
                          vessel_t, vessel_from_rao
   use rodyn_motion, only: motion_displacement, motion_rotation, vessel_motion, &
                           vessel_slow_motion
   use rodyn_mesh, only: mesh_t, mesh_node
   use rodyn_state, only: state_t
   use rodyn_rotation, only: cross, skew, rotation_cayley_inverse, relative_rotation
   use rodyn_assembly, only: supports_t, supports_held_lists
   use rodyn_junctions, only: junctions_t, junctions_release
   use rodyn_bodies, only: body_loads_t, body_waves_build
   use rodyn_waves, only: wave_field_t
   use rodyn_body_mass, only: added_mass_global
   implicit none
   private
   public :: point_velocities, added_mass_force, added_mass_emc, failures_t, failures_build
   public :: failures_step, failures_add, end_released, motion_nodes
   public :: apply_initial_velocities
   public :: body_waves_start, held_motion

   !> The line ends that fail (*FAILURE) and whether they have.
   type :: failures_t
      integer :: n = 0                         !< ends that may fail
      integer, allocatable :: node(:)          !< (n) the end's node
      real(wp), allocatable :: time(:)         !< (n) release time [s] (< 0: none)
      real(wp), allocatable :: break_load(:)   !< (n) force that releases it [N] (<= 0: none)
      logical, allocatable :: failed(:)        !< (n) released
      real(wp), allocatable :: t_failed(:)     !< (n) time of the release [s]
   end type failures_t

contains

   !> The ends of the model's *FAILURE cards.
   subroutine failures_build(model, mesh, fl)
      type(model_t), intent(in) :: model    !< model
      type(mesh_t), intent(in) :: mesh      !< mesh
      type(failures_t), intent(out) :: fl   !< failures
      integer :: i
      fl%n = 0
      if (allocated(model%failures)) fl%n = size(model%failures)
      allocate (fl%node(fl%n), fl%time(fl%n), fl%break_load(fl%n), fl%failed(fl%n), &
                fl%t_failed(fl%n))
      do i = 1, fl%n
         associate (f => model%failures(i))
            fl%node(i) = mesh_node(mesh, f%line, merge(end_a, end_b, f%end == 1))
            fl%time(i) = f%time
            fl%break_load(i) = f%break_load
         end associate
      end do
      fl%failed = .false.
      fl%t_failed = -1.0_wp
   end subroutine failures_build

   !> Before the step from t0: release each end whose time has come (t0 >= its time) or
   !> whose force in the last converged state r reached its break load (eq. (143)): an end
   !> on a point or body leaves it (junctions_release), a held end is held no more. The
   !> tangent then has to be formed again (factors_ok cleared by the caller when any).
   subroutine failures_step(fl, sup, jn, r, t0, any_released)
      type(failures_t), intent(inout) :: fl   !< failures
      type(supports_t), intent(inout) :: sup  !< supports: a released end's held cleared
      type(junctions_t), intent(inout) :: jn  !< junctions: a released end off its master
      real(wp), intent(in) :: r(:, :)         !< (6, nn) forces of the last converged state
      real(wp), intent(in) :: t0              !< time at the start of the step [s]
      logical, intent(out) :: any_released    !< an end was released
      integer :: i, n
      logical :: due, on_master
      any_released = .false.
      do i = 1, fl%n
         if (fl%failed(i)) cycle
         n = fl%node(i)
         due = fl%time(i) >= 0.0_wp .and. t0 >= fl%time(i)*(1.0_wp - 1.0e-12_wp)
         if (fl%break_load(i) > 0.0_wp) due = due .or. norm2(r(1:3, n)) >= fl%break_load(i)
         if (.not. due) cycle
         call junctions_release(jn, n, on_master)
         if (.not. on_master) then
            sup%held(1:3, n) = .false.
            sup%moved(n) = .false.
            call supports_held_lists(sup)
         end if
         fl%failed(i) = .true.
         fl%t_failed(i) = t0
         any_released = .true.
      end do
   end subroutine failures_step

   !> A release of the line end at node added to fl, due at time t: a host's break
   !> (MoorDyn_BreakLine) done at the start of the next step from t_n >= t, eq. (143). An
   !> end already listed is given the earlier time.
   subroutine failures_add(fl, node, t)
      type(failures_t), intent(inout) :: fl  !< failures
      integer, intent(in) :: node            !< the end's node
      real(wp), intent(in) :: t              !< time of the release [s]
      integer :: i
      i = findloc(fl%node(1:fl%n), node, dim=1)
      if (i > 0) then
         if (fl%time(i) < 0.0_wp .or. fl%time(i) > t) fl%time(i) = t
         return
      end if
      fl%n = fl%n + 1
      fl%node = [fl%node(1:fl%n - 1), node]
      fl%time = [fl%time(1:fl%n - 1), t]
      fl%break_load = [fl%break_load(1:fl%n - 1), 0.0_wp]
      fl%failed = [fl%failed(1:fl%n - 1), .false.]
      fl%t_failed = [fl%t_failed(1:fl%n - 1), -1.0_wp]
   end subroutine failures_add

   !> Whether the line end at node has been released.
   pure logical function end_released(fl, node) result(yes)
      type(failures_t), intent(in) :: fl     !< failures
      integer, intent(in) :: node            !< the end's node
      integer :: i
      yes = .false.
      do i = 1, fl%n
         if (fl%node(i) == node .and. fl%failed(i)) yes = .true.
      end do
   end function end_released

   !> Each FREE point's velocity the mean of its ends', and the ends' the point's; the
   !> ends on a body move with it, v_e = v_b + omega x a (a body starts at rest).
   pure subroutine point_velocities(mesh, state)
      type(mesh_t), intent(in) :: mesh       !< mesh with its point and body nodes
      type(state_t), intent(inout) :: state  !< velocities
      integer :: q, l, k, n, ne, m, i
      real(wp) :: v(3), om(3), a(3)
      do q = 1, size(mesh%point_node)
         if (mesh%point_node(q) == 0) cycle
         v = 0.0_wp
         ne = 0
         do l = 1, mesh%n_lines
            do k = 1, 2
               if (mesh%end_point_node(k, l) /= mesh%point_node(q)) cycle
               n = mesh_node(mesh, l, merge(end_a, end_b, k == 1))
               v = v + state%v(:, n)
               ne = ne + 1
            end do
         end do
         state%v(:, mesh%point_node(q)) = v/real(max(ne, 1), wp)
      end do
      do l = 1, mesh%n_lines
         do k = 1, 2
            m = mesh%end_point_node(k, l)
            if (m == 0) cycle
            n = mesh_node(mesh, l, merge(end_a, end_b, k == 1))
            om = 0.5_wp*(cross(state%d(:, 1, m), state%dd(:, 1, m)) + &
                         cross(state%d(:, 2, m), state%dd(:, 2, m)) + &
                         cross(state%d(:, 3, m), state%dd(:, 3, m)))
            a = matmul(state%d(:, :, m), mesh%end_offset(:, k, l))
            state%v(:, n) = state%v(:, m) + cross(om, a)
            if (.not. mesh%end_clamped(k, l)) cycle
            do i = 1, 3                  ! a clamped end turns with its body
               state%dd(:, i, n) = cross(om, state%d(:, i, n))
            end do
         end do
      end do
   end subroutine point_velocities

   !> A body's added mass (docs/theory.md eqs. (142), (154)): the force and moment on G,
   !> R_f A_G (R_f^T acc + (R_1 - R_0)^T (dx, theta)/dt^2), R = blkdiag(D, D) of its
   !> directors at t_n, t_n+1 and the force point, acc the step's accelerations of G and
   !> of the rotation (node_inertia with unit mass and director inertias 1/2), theta the
   !> step's turn: the change of the body-axes velocities over the step, so that with the
   !> midpoint its work is the change of 1/2 nu^T A_G nu to second order in the step; its
   !> derivative R_f A_G R_f^T d(acc)/dq (the turn of D left out).
   pure subroutine added_mass_force(ag, d0, d1, wf, dt, dx, acc, dacc, f, kb, want_k)
      real(wp), intent(in) :: ag(6, 6)     !< added mass at G, body axes [kg, kg m, kg m2]
      real(wp), intent(in) :: d0(3, 3)     !< directors at t_n
      real(wp), intent(in) :: d1(3, 3)     !< directors at t_n+1
      real(wp), intent(in) :: wf           !< weight of t_n+1 at the force point [-]
      real(wp), intent(in) :: dt           !< step [s]
      real(wp), intent(in) :: dx(3)        !< the step's move of G [m]
      real(wp), intent(in) :: acc(6)       !< accelerations [m/s2, 1/s2]
      real(wp), intent(in) :: dacc(6, 6)   !< their derivative (if want_k) [1/s2]
      real(wp), intent(inout) :: f(6)      !< nodal force [N, N m]
      real(wp), intent(out) :: kb(6, 6)    !< derivative (if want_k)
      logical, intent(in) :: want_k        !< form kb
      real(wp) :: df(3, 3), dd(3, 3), ab(6), q(6)
      df = (1.0_wp - wf)*d0 + wf*d1
      dd = d1 - d0
      q(1:3) = dx
      q(4:6) = rotation_cayley_inverse(relative_rotation(d1, d0))
      ab(1:3) = matmul(transpose(df), acc(1:3)) + matmul(transpose(dd), q(1:3))/dt**2
      ab(4:6) = matmul(transpose(df), acc(4:6)) + matmul(transpose(dd), q(4:6))/dt**2
      ab = matmul(ag, ab)
      f(1:3) = f(1:3) + matmul(df, ab(1:3))
      f(4:6) = f(4:6) + matmul(df, ab(4:6))
      if (want_k) kb = matmul(added_mass_global(ag, df), dacc)
   end subroutine added_mass_force

   !> A body's translational added mass in its axes in the EMC step (docs/theory.md eq.
   !> (151)): with S = D A D^T at each end of the step, v1 = 2 dx/dt - v0 and Q = D1 D0^T,
   !> the force (S1 v1 - S0 v0)/dt and the moment -(1/2) [(X v1) x v0 + (Y^T v0) x v1],
   !> X = (I + Q^T) S1/2, Y = S0 (I + Q^T)/2 (the discrete Munk moment). Over the step
   !> their work on (dx, theta), theta the Cayley parameter of Q, is the change of
   !> 1/2 v^T S v exactly, however the body turns. Tangent: the force's with respect to dx
   !> and the rotation, the moment's with respect to dx (with respect to the rotation, of
   !> the order of A v^2, left out).
   pure subroutine added_mass_emc(at, d0, d1, v0, dx, dt, f, kb, want_k)
      real(wp), intent(in) :: at(3, 3)     !< added mass of G's translation, body axes [kg]
      real(wp), intent(in) :: d0(3, 3)     !< directors at t_n
      real(wp), intent(in) :: d1(3, 3)     !< directors at t_n+1
      real(wp), intent(in) :: v0(3)        !< velocity at t_n [m/s]
      real(wp), intent(in) :: dx(3)        !< position increment [m]
      real(wp), intent(in) :: dt           !< time step [s]
      real(wp), intent(inout) :: f(6)      !< nodal force [N, N m]
      real(wp), intent(out) :: kb(6, 6)    !< derivative (if want_k)
      logical, intent(in) :: want_k        !< form kb
      real(wp) :: s0(3, 3), s1(3, 3), iq(3, 3), v1(3), p1(3)
      integer :: j
      s0 = matmul(d0, matmul(at, transpose(d0)))
      s1 = matmul(d1, matmul(at, transpose(d1)))
      v1 = 2.0_wp*dx/dt - v0
      p1 = matmul(s1, v1)
      f(1:3) = f(1:3) + (p1 - matmul(s0, v0))/dt
      iq = transpose(relative_rotation(d1, d0))
      do j = 1, 3
         iq(j, j) = iq(j, j) + 1.0_wp
      end do
      f(4:6) = f(4:6) - 0.25_wp*(cross(matmul(iq, p1), v0) + &
                                 cross(matmul(transpose(iq), matmul(s0, v0)), v1))
      if (.not. want_k) return
      kb = 0.0_wp
      kb(1:3, 1:3) = 2.0_wp/dt**2*s1
      kb(1:3, 4:6) = (matmul(s1, skew(v1)) - skew(p1))/dt
      kb(4:6, 1:3) = (matmul(skew(v0), matmul(iq, s1)) - &
                      skew(matmul(transpose(iq), matmul(s0, v0))))/(2.0_wp*dt)
   end subroutine added_mass_emc

   !> The bodies' wave loads in the sea (rodyn_bodies' body_waves_build, eq. (150)), each
   !> at its reference point's position in the start state.
   pure subroutine body_waves_start(model, field, state, bl)
      type(model_t), intent(in) :: model       !< model
      type(wave_field_t), intent(in) :: field  !< the sea
      type(state_t), intent(in) :: state       !< start state
      type(body_loads_t), intent(inout) :: bl  !< bodies' loads (their wave factors set)
      real(wp) :: xr(3, bl%nb)
      integer :: k, node
      do k = 1, bl%nb
         node = bl%node(k)
         xr(:, k) = state%x(:, node) + matmul(state%d(:, :, node), bl%rr(:, k))
      end do
      call body_waves_build(model, field, xr, bl)
   end subroutine body_waves_start

   !> The nodes the *MOTIONs move and the motion of each: a line's node, a FIXED body's
   !> node (its G), or each line end on a FIXED point.
   subroutine motion_nodes(model, mesh, node, of)
      type(model_t), intent(in) :: model             !< model
      type(mesh_t), intent(in) :: mesh               !< mesh
      integer, allocatable, intent(out) :: node(:)   !< nodes moved
      integer, allocatable, intent(out) :: of(:)     !< the motion of each
      integer :: i, l
      allocate (node(0), of(0))
      if (.not. allocated(model%motions)) return
      do i = 1, size(model%motions)
         associate (mo => model%motions(i))
            if (mo%body > 0) then
               node = [node, mesh%body_node(mo%body)]
               of = [of, i]
            else if (mo%point > 0) then
               do l = 1, mesh%n_lines
                  if (model%lines(l)%point_a == mo%point) then
                     node = [node, mesh_node(mesh, l, end_a)]
                     of = [of, i]
                  end if
                  if (model%lines(l)%point_b == mo%point) then
                     node = [node, mesh_node(mesh, l, end_b)]
                     of = [of, i]
                  end if
               end do
            else
               node = [node, mesh_node(mesh, mo%line, mo%node)]
               of = [of, i]
            end if
         end associate
      end do
   end subroutine motion_nodes

   !> Rigid-body initial velocities (*INITIAL VELOCITY): v_a = v + omega x (x_a - c),
   !> ddot_ia = omega x d_ia, c the given centre or the mean of the line's nodes (a body:
   !> its node G, c its reference point R unless given; its ends then move with it). A FREE
   !> point moves with the ends on it: its velocity is the mean of theirs, and they take
   !> it (ends of lines given different velocities meet at the point's).
   subroutine apply_initial_velocities(model, mesh, state)
      type(model_t), intent(in) :: model     !< model
      type(mesh_t), intent(in) :: mesh       !< mesh
      type(state_t), intent(inout) :: state  !< velocities set
      real(wp) :: c(3)
      integer :: k, n0, nn, a, i
      if (.not. allocated(model%initial_velocities)) return
      do k = 1, size(model%initial_velocities)
         associate (iv => model%initial_velocities(k))
            if (iv%body > 0) then       ! a body's node (its G), about R unless given
               a = mesh%body_node(iv%body)
               c = model%bodies(iv%body)%position
               if (iv%has_centre) c = iv%centre
               state%v(:, a) = iv%velocity + cross(iv%omega, state%x(:, a) - c)
               do i = 1, 3
                  state%dd(:, i, a) = cross(iv%omega, state%d(:, i, a))
               end do
               cycle
            end if
            n0 = mesh%line_first_node(iv%line)
            nn = mesh%line_n_nodes(iv%line)
            if (iv%has_centre) then
               c = iv%centre
            else
               c = sum(state%x(:, n0:n0 + nn - 1), dim=2)/real(nn, wp)
            end if
            do a = n0, n0 + nn - 1
               state%v(:, a) = iv%velocity + cross(iv%omega, state%x(:, a) - c)
               do i = 1, 3
                  state%dd(:, i, a) = cross(iv%omega, state%d(:, i, a))
               end do
            end do
         end associate
      end do
      call point_velocities(mesh, state)
   end subroutine apply_initial_velocities
   !> Where a prescribed motion takes a node over the step t0 -> t0 + dt: its
   !> displacement u from x0 (its position at t = 0) and, if asked, its rotation q at
   !> t0 + dt (rodyn_motion; q = I but for a vessel's). The step past the run's end (past:
   !> rodyn_timeloop's look_ahead, for the last frame's support forces) continues a
   !> motion whose data end before t0 + dt on the path of its last step: a *MOTION table
   !> by u(t0 + dt) = 2 u(t0) - u(t0 - dt), a vessel's motion and drift tables by a row
   !> at t0 + dt continuing them so (extend_vessel), from which every point of the
   !> vessel, and a body on it, moves as one rigid body. Held constant past their last
   !> row, the tables would stop the path there.
   pure subroutine held_motion(mo, vessels, x0, t0, dt, past, u, q)
      type(motion_t), intent(in) :: mo                   !< the motion
      type(vessel_t), intent(in), optional :: vessels(:) !< the model's (motion_vessel)
      real(wp), intent(in) :: x0(3)                      !< the node at t = 0 [m]
      real(wp), intent(in) :: t0                         !< start of the step [s]
      real(wp), intent(in) :: dt                         !< step [s]
      logical, intent(in) :: past                        !< the step past the run's end
      real(wp), intent(out) :: u(3)                      !< displacement at t0 + dt [m]
      real(wp), intent(out), optional :: q(3, 3)         !< rotation at t0 + dt [-]
      type(vessel_t), allocatable :: vx(:)
      if (past .and. motion_data_end(mo, vessels) < t0 + dt) then
         if (mo%kind == motion_vessel) then
            vx = vessels
            call extend_vessel(vx(mo%vessel), t0, dt)
            u = motion_displacement(mo, t0 + dt, vx, x0)
            if (present(q)) q = motion_rotation(mo, t0 + dt, vx)
         else
            u = 2.0_wp*motion_displacement(mo, t0, vessels, x0) - &
                motion_displacement(mo, t0 - dt, vessels, x0)
            if (present(q)) q = motion_rotation(mo, t0 + dt, vessels)
         end if
      else
         u = motion_displacement(mo, t0 + dt, vessels, x0)
         if (present(q)) q = motion_rotation(mo, t0 + dt, vessels)
      end if
   end subroutine held_motion

   !> A vessel's motion and drift tables that end before t0 + dt given a row there that
   !> continues each on the straight line of the step t0 - dt -> t0.
   pure subroutine extend_vessel(ve, t0, dt)
      type(vessel_t), intent(inout) :: ve !< vessel (rows appended)
      real(wp), intent(in) :: t0          !< start of the step [s]
      real(wp), intent(in) :: dt          !< step [s]
      type(vessel_t) :: vt
      real(wp) :: xi(6), d(4)
      integer :: n
      if (ve%kind /= vessel_from_rao .and. allocated(ve%time)) then
         n = size(ve%time)
         if (ve%time(n) < t0 + dt) then
            xi = 2.0_wp*vessel_motion(ve, t0) - vessel_motion(ve, t0 - dt)
            ve%time = [ve%time, t0 + dt]
            ve%motion = reshape([ve%motion, xi], [6, n + 1])
         end if
      end if
      if (.not. allocated(ve%drift_time)) return
      n = size(ve%drift_time)
      if (ve%drift_time(n) >= t0 + dt) return
      vt = ve                       ! the drift table's part alone of the slow motion
      vt%offset = 0.0_wp
      vt%drift_period = 0.0_wp
      d = 2.0_wp*vessel_slow_motion(vt, t0) - vessel_slow_motion(vt, t0 - dt)
      ve%drift_time = [ve%drift_time, t0 + dt]
      ve%drift_table = reshape([ve%drift_table, d], [4, n + 1])
   end subroutine extend_vessel

   !> The last time a motion's data define it: a *MOTION table's last row, the earlier
   !> of the last rows of a vessel's motion and drift tables; huge() for a harmonic
   !> motion and a vessel moved by its RAOs.
   pure real(wp) function motion_data_end(mo, vessels) result(te)
      type(motion_t), intent(in) :: mo                   !< the motion
      type(vessel_t), intent(in), optional :: vessels(:) !< the model's (motion_vessel)
      te = huge(1.0_wp)
      if (mo%kind == motion_table) then
         te = mo%time(size(mo%time))
      else if (mo%kind == motion_vessel .and. present(vessels)) then
         associate (ve => vessels(mo%vessel))
            if (ve%kind /= vessel_from_rao .and. allocated(ve%time)) &
               te = ve%time(size(ve%time))
            if (allocated(ve%drift_time)) te = min(te, ve%drift_time(size(ve%drift_time)))
         end associate
      end if
   end function motion_data_end

end module rodyn_system_dynamics
