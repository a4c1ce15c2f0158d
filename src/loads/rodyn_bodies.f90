!> The loads of a rigid body that turn with it (docs/theory.md section 17, eqs.
!> (137)-(139)): the buoyancy rho_w g V at its centre of buoyancy B, the linear
!> waterplane restoring about its reference point R, and the moment about G of a load
!> given at R (*LOAD, BODY=). The weight acts at G, the body's node (rodyn_assembly's
!> loads_build), and the load's force and its moment about R are point loads there.
!>
!> All are forces and moments on the body's node at its centre of gravity G, evaluated
!> at the scheme's force point: with a the body-axes offset r carried by the directors
!> at the force point, a_f = (1 - w) D0 r + w D1 r, a force F at that point gives the
!> moment a_f x F (137), whose work over the step is F . (a^{n+1} - a^n) exactly for
!> EMC (w = 1/2 and the Cayley update). The waterplane acts on q_R = (x_R - x_R0,
!> theta), theta = log(D1) the body's rotation (its axes are the global ones at the
!> start):
!>
!>   F_w = -C q_R (force at R, moment about R),                                 (138)
!>   its tangent S C T_R, T_R = [I, -skew(a_R); 0, I], S = T_R^T          (139)
!>
!> (the rotation's log linearised as theta: exact at small rotations, which is what a
!> linear C describes).
!>
!> The first-order wave load of *BODY WAVE LOAD (eq. (150)): for the sea's components j,
!> of amplitude a_j, frequency omega_j, heading beta_j and elevation a_j cos(omega_j t +
!> phi_j) at R's position R_s at the start of the dynamics (phi_j = -k_j . R_s - phase_j,
!> rodyn_waves), the force and moment at R
!>   F_k(t) = r(t) Re sum_j a_j X_k(T_j, beta_j) exp(i (omega_j t + phi_j)),     (150)
!> X_k the table's complex value per metre of amplitude (rodyn_vessel's interpolation, the
!> body's heading at rest 0: its axes are the global ones at the start) and r(t) the
!> sea's ramp. It acts in global axes at R's position at the start (the linear theory's
!> mean position), its moment moved to G as the waterplane's; it is booked with the
!> water's work.
module rodyn_bodies
   use rodyn_kinds, only: wp, two_pi
   use rodyn_model, only: model_t, body_free
   use rodyn_mesh, only: mesh_t
   use rodyn_rotation, only: cross, skew, rotation_log
   use rodyn_waves, only: wave_field_t, wave_ramp, wave_kinematics
   use rodyn_vessel, only: vessel_coefficients, vessel_harmonic_motion
   use rodyn_model, only: water_t
   use rodyn_environment, only: fluid_kinematics
   implicit none
   private
   public :: body_loads_t, body_loads_build, body_force, body_damping, body_current_drag
   public :: body_waves_build, body_waves_at, body_water_set, body_transfer

   !> The bodies' loads, fixed for the run (and the last forces, for the work's books).
   type :: body_loads_t
      integer :: nb = 0                        !< FREE bodies
      integer, allocatable :: node(:)          !< (nb) node of each
      integer, allocatable :: body(:)          !< (nb) its model%bodies index
      real(wp), allocatable :: fb(:, :)        !< (3, nb) buoyancy force, global [N]
      real(wp), allocatable :: rb(:, :)        !< (3, nb) B - G, body axes [m]
      real(wp), allocatable :: rr(:, :)        !< (3, nb) R - G, body axes [m]
      real(wp), allocatable :: xr0(:, :)       !< (3, nb) R at the start [m]
      real(wp), allocatable :: c(:, :, :)      !< (6, 6, nb) waterplane restoring about R
      real(wp), allocatable :: b(:, :, :)      !< (6, 6, nb) linear damping about R
      !> (6, nb) quadratic drag in body axes: 1/2 rho_w CdA_i [kg/m], C_ri [N m s2]
      real(wp), allocatable :: q(:, :)
      real(wp), allocatable :: fd(:, :)        !< (6, nb) last damping force and moment at G
      real(wp), allocatable :: fh(:, :)        !< (6, nb) last water force and moment at G
      real(wp), allocatable :: fe(:, :)        !< (3, nb) last moment of the loads at R about G
      logical :: off = .false.                 !< none of these loads (the lines' stiffness)
      !> first-order wave loads (eq. (150); body_waves_build): the sea's frequencies, the
      !> complex factors a_j X_k exp(i phi_j) of each body with a table, the sea's ramp
      real(wp), allocatable :: womega(:)       !< (nw) angular frequencies [rad/s]
      complex(wp), allocatable :: wc(:, :, :)  !< (6, nw, nb) [N, N m]
      logical, allocatable :: waved(:)         !< (nb) the body has a wave load
      real(wp) :: wramp = 0.0_wp               !< ramp-in of the sea [s]
      real(wp), allocatable :: fx(:, :)        !< (6, nb) wave force and moment at R now
      !> (3, nb) the water's velocity at R for the drag (current and waves; body_water_set)
      real(wp), allocatable :: uw(:, :)
   end type body_loads_t

contains

   !> The FREE bodies' loads of a model.
   subroutine body_loads_build(model, mesh, bl)
      type(model_t), intent(in) :: model     !< model
      type(mesh_t), intent(in) :: mesh       !< mesh with its body nodes
      type(body_loads_t), intent(out) :: bl  !< loads
      integer :: i, k
      bl%nb = 0
      if (allocated(model%bodies)) bl%nb = count(model%bodies%kind == body_free)
      allocate (bl%node(bl%nb), bl%body(bl%nb), bl%fb(3, bl%nb), bl%rb(3, bl%nb), &
                bl%rr(3, bl%nb), bl%xr0(3, bl%nb), bl%c(6, 6, bl%nb), &
                bl%fh(6, bl%nb), bl%fe(3, bl%nb), bl%b(6, 6, bl%nb), bl%fd(6, bl%nb), &
                bl%q(6, bl%nb), bl%fx(6, bl%nb), bl%waved(bl%nb), bl%uw(3, bl%nb))
      bl%fx = 0.0_wp
      bl%uw = 0.0_wp
      bl%waved = .false.
      bl%fh = 0.0_wp
      bl%fd = 0.0_wp
      bl%fe = 0.0_wp
      k = 0
      do i = 1, size(mesh%body_node)
         if (model%bodies(i)%kind /= body_free) cycle
         k = k + 1
         associate (b => model%bodies(i))
            bl%node(k) = mesh%body_node(i)
            bl%body(k) = i
            bl%fb(:, k) = 0.0_wp
            if (model%water%present) bl%fb(:, k) = -model%water%density*b%volume*model%gravity
            bl%rb(:, k) = b%cob - b%cog
            bl%rr(:, k) = -b%cog
            bl%xr0(:, k) = b%position
            bl%c(:, :, k) = b%hydrostatic
            bl%b(:, :, k) = b%damping
            bl%q(1:3, k) = 0.5_wp*model%water%density*b%drag(1:3)
            bl%q(4:6, k) = b%drag(4:6)
         end associate
      end do
   end subroutine body_loads_build

   !> The factors of each body's wave load in the sea `field` (eq. (150)), with R at
   !> xr (its position at the start of the dynamics).
   pure subroutine body_waves_build(model, field, xr, bl)
      type(model_t), intent(in) :: model       !< model with the bodies' tables
      type(wave_field_t), intent(in) :: field  !< the sea
      real(wp), intent(in) :: xr(:, :)         !< (3, nb) R of each FREE body [m]
      type(body_loads_t), intent(inout) :: bl  !< womega, wc, waved, wramp set
      real(wp), allocatable :: phi(:), beta(:)
      integer :: k
      allocate (bl%wc(6, field%n, bl%nb))
      bl%womega = field%omega
      bl%wramp = field%ramp
      bl%wc = (0.0_wp, 0.0_wp)
      beta = atan2(field%sb, field%cb)
      do k = 1, bl%nb
         associate (rao => model%bodies(bl%body(k))%wave_load)
            bl%waved(k) = allocated(rao%period) .and. field%n > 0
            if (.not. bl%waved(k)) cycle
            phi = -(field%kx*xr(1, k) + field%ky*xr(2, k)) - field%phase
            call vessel_coefficients(rao, 0.0_wp, field%amp, field%omega, beta, phi, &
                                     bl%wc(:, :, k))
         end associate
      end do
   end subroutine body_waves_build

   !> Each body's wave force and moment at R at time t (eq. (150)), kept in bl%fx for
   !> body_force.
   pure subroutine body_waves_at(bl, t)
      type(body_loads_t), intent(inout) :: bl  !< loads (fx set)
      real(wp), intent(in) :: t                !< time [s]
      real(wp) :: r, dr
      integer :: k
      call wave_ramp(bl%wramp, t, r, dr)
      do k = 1, bl%nb
         bl%fx(:, k) = 0.0_wp
         if (bl%waved(k)) bl%fx(:, k) = r*vessel_harmonic_motion(bl%wc(:, :, k), bl%womega, t)
      end do
   end subroutine body_waves_at

   !> The water at the bodies at the force time t: the wave loads (body_waves_at) and,
   !> for a body with a drag, the water's velocity at R (eq. (149)): the current's, times
   !> its ramp r_cur, and with waves the wave's at R's predicted force point x + h v (the
   !> body's node's x, d and v at the start of the step; statics: x and d now, no v).
   pure subroutine body_water_set(bl, water, r_cur, field, waves, t, x, d, v, h)
      type(body_loads_t), intent(inout) :: bl  !< loads (fx, uw set)
      type(water_t), intent(in) :: water       !< water and current profile
      real(wp), intent(in) :: r_cur            !< current ramp factor [-]
      type(wave_field_t), intent(in) :: field  !< the sea
      logical, intent(in) :: waves             !< the step has waves
      real(wp), intent(in) :: t                !< force time [s]
      real(wp), intent(in) :: x(:, :)          !< (3, nn) positions [m]
      real(wp), intent(in) :: d(:, :, :)       !< (3, 3, nn) directors
      real(wp), intent(in), optional :: v(:, :) !< (3, nn) velocities [m/s]
      real(wp), intent(in), optional :: h      !< time to the force point [s]
      real(wp) :: xr(3), u(3), dudx(3, 3), a(3), eta
      integer :: k
      if (allocated(bl%womega)) call body_waves_at(bl, t)
      do k = 1, bl%nb
         bl%uw(:, k) = 0.0_wp
         if (.not. any(bl%q(1:3, k) > 0.0_wp)) cycle
         xr = x(:, bl%node(k)) + matmul(d(:, :, bl%node(k)), bl%rr(:, k))
         if (present(v) .and. present(h)) xr = xr + h*v(:, bl%node(k))
         call fluid_kinematics(water, r_cur, xr, bl%uw(:, k), dudx, a)
         if (.not. waves) cycle
         call wave_kinematics(field, xr, t, eta, u, a)
         bl%uw(:, k) = bl%uw(:, k) + u
      end do
   end subroutine body_water_set

   !> The steady drag of the current on body k in the statics (eq. (149) with the body at
   !> rest): the force -D q |u| u, u = D^T (0 - u_w) in the body's axes, at R, moved to G,
   !> and its tangent with respect to the body's rotation (the turn of D left out, as in
   !> the dynamics).
   pure subroutine body_current_drag(bl, k, d, f, kb)
      type(body_loads_t), intent(in) :: bl     !< loads (uw set)
      integer, intent(in) :: k                 !< body
      real(wp), intent(in) :: d(3, 3)          !< its directors
      real(wp), intent(out) :: f(6)            !< force and moment on the node [N, N m]
      real(wp), intent(out) :: kb(6, 6)        !< d f / d (x, theta) of the node
      real(wp) :: u(3), ar(3)
      u = -matmul(transpose(d), bl%uw(:, k))
      ar = matmul(d, bl%rr(:, k))
      f(1:3) = -matmul(d, bl%q(1:3, k)*abs(u)*u)
      f(4:6) = cross(ar, f(1:3))
      kb = 0.0_wp
      kb(4:6, 4:6) = moment_tangent(ar, f(1:3))
   end subroutine body_current_drag

   !> Body k's turning loads at the force point (eqs. (137)-(139)): force and moment f
   !> on its node, and their derivative kb with respect to its translation and rotation
   !> at t_n+1 (the residual's is -kb). xg0, xg1: G at t_n and now; d0, d1 its directors;
   !> w the weight of t_n+1; fr the force of the loads given at R at the force time (their
   !> amplitudes and load factor applied: the node's point loads).
   pure subroutine body_force(bl, k, xg0, xg1, d0, d1, w, fr, f, kb)
      type(body_loads_t), intent(inout) :: bl  !< loads (fh, fe: the forces kept)
      integer, intent(in) :: k                 !< body
      real(wp), intent(in) :: xg0(3), xg1(3)   !< G at t_n and at t_n+1 [m]
      real(wp), intent(in) :: d0(3, 3), d1(3, 3) !< directors at t_n and t_n+1
      real(wp), intent(in) :: w                !< weight of t_n+1 at the force point
      real(wp), intent(in) :: fr(3)            !< force of the loads at R [N]
      real(wp), intent(out) :: f(6)            !< force and moment on the node [N, N m]
      real(wp), intent(out) :: kb(6, 6)        !< d f / d (x, theta) of the node
      real(wp) :: dm(3, 3), ab(3), ar(3), ar1(3), q(6), fw(6), t(6, 6), fe(3)
      dm = (1.0_wp - w)*d0 + w*d1
      ab = matmul(dm, bl%rb(:, k))
      ar = matmul(dm, bl%rr(:, k))
      ar1 = matmul(d1, bl%rr(:, k))
      ! buoyancy at B and the wave load at R, the loads' force at R (its moment about R
      ! is a point load)
      f(1:3) = bl%fb(:, k) + bl%fx(1:3, k)
      fe = cross(ar, fr)
      f(4:6) = cross(ab, bl%fb(:, k)) + bl%fx(4:6, k) + cross(ar, bl%fx(1:3, k))
      kb = 0.0_wp
      kb(4:6, 4:6) = w*(moment_tangent(matmul(d1, bl%rb(:, k)), bl%fb(:, k)) &
                        + moment_tangent(ar1, fr + bl%fx(1:3, k)))
      ! waterplane about R, at the force point
      q(1:3) = (1.0_wp - w)*xg0 + w*xg1 + ar - bl%xr0(:, k)
      q(4:6) = rotation_log(dm)
      fw = -matmul(bl%c(:, :, k), q)
      fw(4:6) = fw(4:6) + cross(ar, fw(1:3))
      t = body_transfer(ar1)
      kb = kb - w*matmul(transpose(t), matmul(bl%c(:, :, k), t))
      bl%fh(1:3, k) = f(1:3) + fw(1:3)
      bl%fh(4:6, k) = f(4:6) + fw(4:6)
      bl%fe(:, k) = fe
      f = bl%fh(:, k)
      f(4:6) = f(4:6) + fe
   end subroutine body_force

   !> Body k's linear damping and quadratic drag over a time step dt (eqs. (141), (149)):
   !> the velocity of R and the angular velocity of the step, v = (x_R^{n+1} - x_R^n)/dt,
   !> omega = theta/dt (theta the Cayley parameter of the step's turn, given), the force
   !> and moment about R -B (v, omega) - D_f Q D_f^T (v - u_w, omega), Q = diag(q_i |u_i|),
   !> u the relative velocity in the body axes at the force point (u_w the water's velocity
   !> at R, body_water_set), moved to G at the force point (as the waterplane's, (138)); f
   !> the force on the node and kb its derivative (c_v: d velocity / d increment, 1/dt; the
   !> drag's 2 q_i |u_i|, the turn of D_f left out). In still water the drag's work,
   !> f . (dx, theta) = -dt sum_i q_i |u_i| u_i^2 <= 0, dissipates (fd); in moving water
   !> the translation's drag is booked with the water's (fh).
   pure subroutine body_damping(bl, k, xg0, xg1, d0, d1, w, dt, th, f, kb)
      type(body_loads_t), intent(inout) :: bl  !< loads (fd: the force kept)
      integer, intent(in) :: k                 !< body
      real(wp), intent(in) :: xg0(3), xg1(3)   !< G at t_n and at t_n+1 [m]
      real(wp), intent(in) :: d0(3, 3), d1(3, 3) !< directors at t_n and t_n+1
      real(wp), intent(in) :: w                !< weight of t_n+1 at the force point
      real(wp), intent(in) :: dt               !< time step [s]
      real(wp), intent(in) :: th(3)            !< Cayley parameter of the step's turn [rad]
      real(wp), intent(out) :: f(6)            !< force and moment on the node [N, N m]
      real(wp), intent(out) :: kb(6, 6)        !< d f / d (x, theta) of the node
      real(wp) :: ar(3), ar0(3), ar1(3), v(6), t(6, 6), bq(6, 6), df(3, 3), u(3), vr(3)
      real(wp) :: fq(6)
      integer :: i, j
      ar0 = matmul(d0, bl%rr(:, k))
      ar1 = matmul(d1, bl%rr(:, k))
      ar = (1.0_wp - w)*ar0 + w*ar1
      v(1:3) = (xg1 + ar1 - xg0 - ar0)/dt
      v(4:6) = th/dt
      f = -matmul(bl%b(:, :, k), v)
      fq = 0.0_wp
      bq = 0.0_wp
      if (any(bl%q(:, k) > 0.0_wp)) then
         df = (1.0_wp - w)*d0 + w*d1
         do i = 0, 3, 3
            ! the translation's drag on the velocity relative to the water at R
            vr = v(i + 1:i + 3)
            if (i == 0) vr = vr - bl%uw(:, k)
            u = matmul(transpose(df), vr)
            fq(i + 1:i + 3) = -matmul(df, bl%q(i + 1:i + 3, k)*abs(u)*u)
            do j = 1, 3
               bq(i + 1:i + 3, i + j) = matmul(df, 2.0_wp*bl%q(i + 1:i + 3, k)*abs(u)*df(j, :))
            end do
         end do
      end if
      f(4:6) = f(4:6) + cross(ar, f(1:3))
      f(4:6) = f(4:6) + fq(4:6)                 ! the turn's drag: damping
      ! the translation's drag: damping in still water; in moving water it can do work on
      ! the body, and is booked with the water's (fh)
      fq(4:6) = cross(ar, fq(1:3))
      if (any(bl%uw(:, k) /= 0.0_wp)) then
         bl%fh(:, k) = bl%fh(:, k) + fq(1:6)
         bl%fd(:, k) = f
         f = f + fq
      else
         f = f + fq
         bl%fd(:, k) = f
      end if
      t = body_transfer(ar1)
      kb = -matmul(transpose(t), matmul(bl%b(:, :, k) + bq, t))/dt
   end subroutine body_damping

   !> d(a x F)/d theta for a vector a = D r turning with the body and a fixed F:
   !> a F^T - (a . F) I.
   pure function moment_tangent(a, force) result(k)
      real(wp), intent(in) :: a(3)       !< arm [m]
      real(wp), intent(in) :: force(3)   !< force [N]
      real(wp) :: k(3, 3)
      integer :: i
      do i = 1, 3
         k(:, i) = a*force(i)
         k(i, i) = k(i, i) - dot_product(a, force)
      end do
   end function moment_tangent

   !> The transfer T_R = [I, -skew(a); 0, I] of a body's six motions to a point at a
   !> from its reference point. docs/theory.md eq. (139).
   pure function body_transfer(a) result(t)
      real(wp), intent(in) :: a(3)   !< the point from R [m]
      real(wp) :: t(6, 6)            !< the transfer
      integer :: i
      t = 0.0_wp
      do i = 1, 6
         t(i, i) = 1.0_wp
      end do
      t(1:3, 4:6) = -skew(a)
   end function body_transfer
end module rodyn_bodies
