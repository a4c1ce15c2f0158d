!> What a dynamic run reports of its sea and vessels (docs/output.md, "Waves and vessels";
!> docs/theory.md eqs. (83), (99)): the wave elevation at the points of *WAVE PROBE, the
!> pose of each vessel and the forces its line ends put on it, at a time t from the support
!> forces r of that time. Computed only for a scene that has probes or vessels
!> (sea_scene_build).
!>
!> Elevation at probe (x, y): eta(x, y, t) of the run's sea, ramp included (rodyn_waves).
!>
!> Vessel pose (rodyn_motion's vessel_pose): reference point X_ref (global), the angles
!> roll, pitch, yaw of Rv = Rz(yaw) Ry(pitch) Rx(roll) and the heading psi of the mean
!> axes (psi0 + the slow heading); vessel axes turn by R = Rz(psi) Rv. The ramp is that of
!> the vessel's first *MOTION, TYPE=VESSEL (its connections move with it; none: 1).
!>
!> Connection c (a node with *MOTION, TYPE=VESSEL): the force and moment the line puts
!> on the vessel at the connection point, F_c = -r(1:3), M_c = -r(4:6) (r the force and
!> moment of the support on the line, as dynamic_ends.csv; M_c = 0 at a pinned end), in
!> global axes and in vessel axes (R^T F_c, R^T M_c). Per vessel, their sum: F = sum F_c
!> and the moment about the reference point M = sum (X_c - X_ref) x F_c + M_c, X_c =
!> X_ref + R p_c the connection point (p_c in vessel axes, where the node is at t = 0).
!>
!> Body b (*BODY): its reference point R = G + D (R - G)_body, D its directors, the
!> rotation vector log D from the start, and the force of its lines on it (minus the
!> forces r at the line ends on its points) with their moment about R.
module rodyn_sea_output
   use rodyn_kinds, only: wp
   use rodyn_model, only: model_t, motion_vessel, end_a, end_b
   use rodyn_mesh, only: mesh_t, mesh_node
   use rodyn_waves, only: wave_field_t, wave_elevation
   use rodyn_vessel, only: vessel_rotation, vessel_local_point
   use rodyn_motion, only: vessel_pose
   use rodyn_rotation, only: rotation_log
   implicit none
   private
   public :: sea_scene_t, sea_values_t, sea_scene_build, sea_values, sea_rotation

   !> The probes, vessels and connections of a run (fixed after sea_scene_build).
   type :: sea_scene_t
      logical :: active = .false.             !< the run writes sea and vessel outputs
      integer :: n_probes = 0                 !< wave probes
      integer :: n_vessels = 0                !< vessels
      integer :: n_conn = 0                   !< vessel connections
      real(wp), allocatable :: probe_xy(:, :) !< (2, np) x, y [m]
      real(wp), allocatable :: ramp(:)        !< (nv) ramp of the vessel's pose [s]
      integer, allocatable :: conn_vessel(:)  !< (nc) vessel of each connection
      integer, allocatable :: conn_line(:)    !< (nc) line of each connection
      integer, allocatable :: conn_node(:)    !< (nc) its node in the mesh
      character(len=8), allocatable :: conn_end(:) !< (nc) 'A', 'B' or the node number
      real(wp), allocatable :: conn_p(:, :)   !< (3, nc) point p_c in vessel axes [m]
      integer :: n_bodies = 0                 !< bodies (*BODY)
      integer, allocatable :: body_node(:)    !< (nb) each body's node (at G)
      real(wp), allocatable :: body_rg(:, :)  !< (3, nb) R - G, body axes [m]
      integer, allocatable :: bend_node(:)    !< (ne) line ends on bodies: their node
      integer, allocatable :: bend_body(:)    !< (ne) and their body
   end type sea_scene_t

   !> The outputs at one time.
   type :: sea_values_t
      real(wp), allocatable :: eta(:)       !< (np) elevation at the probes [m]
      real(wp), allocatable :: pose(:, :)   !< (7, nv) x, y, z [m], roll, pitch, yaw,
                                            !< heading [rad]
      real(wp), allocatable :: load(:, :)   !< (12, nv) F, M about X_ref global, then the
                                            !< same in vessel axes [N, N m]
      real(wp), allocatable :: conn(:, :)   !< (12, nc) F_c, M_c global, then in vessel
                                            !< axes [N, N m]
      !> (12, nb) each body's R [m], rotation vector [rad], force of its lines [N] and
      !> their moment about R [N m], global axes
      real(wp), allocatable :: body(:, :)
   end type sea_values_t

contains

   !> The scene of a run: its probes, vessels and the nodes fixed to them, with each
   !> connection's point in vessel axes from the node's position at t = 0 (x_start).
   pure subroutine sea_scene_build(model, mesh, x_start, scene)
      type(model_t), intent(in) :: model      !< model
      type(mesh_t), intent(in) :: mesh        !< mesh
      real(wp), intent(in) :: x_start(:, :)   !< (3, nn) positions at t = 0 [m]
      type(sea_scene_t), intent(out) :: scene !< the scene
      integer :: k, c, v
      character(len=16) :: buf
      scene%n_probes = 0
      if (allocated(model%waves%probe_name)) scene%n_probes = size(model%waves%probe_name)
      scene%n_vessels = 0
      if (allocated(model%vessels)) scene%n_vessels = size(model%vessels)
      allocate (scene%probe_xy(2, scene%n_probes), scene%ramp(scene%n_vessels))
      if (scene%n_probes > 0) scene%probe_xy = model%waves%probe_xy
      scene%ramp = -1.0_wp
      c = 0
      if (allocated(model%motions)) c = count(model%motions%kind == motion_vessel .and. &
                                              model%motions%line > 0)
      scene%n_conn = c
      allocate (scene%conn_vessel(c), scene%conn_line(c), scene%conn_node(c), &
                scene%conn_end(c), scene%conn_p(3, c))
      c = 0
      if (allocated(model%motions)) then
         do k = 1, size(model%motions)
            associate (mo => model%motions(k))
               if (mo%kind /= motion_vessel .or. mo%line == 0) cycle  ! (a body's)
               c = c + 1
               v = mo%vessel
               scene%conn_vessel(c) = v
               scene%conn_line(c) = mo%line
               scene%conn_node(c) = mesh_node(mesh, mo%line, mo%node)
               if (mo%node == end_a) then
                  scene%conn_end(c) = 'A'
               else if (mo%node == end_b) then
                  scene%conn_end(c) = 'B'
               else
                  write (buf, '(i0)') mo%node
                  scene%conn_end(c) = trim(buf)
               end if
               scene%conn_p(:, c) = vessel_local_point(model%vessels(v)%origin, &
                  model%vessels(v)%heading, x_start(:, scene%conn_node(c)))
               if (scene%ramp(v) < 0.0_wp) scene%ramp(v) = mo%ramp
            end associate
         end do
      end if
      where (scene%ramp < 0.0_wp) scene%ramp = 0.0_wp
      call body_scene(model, mesh, scene)
      scene%active = scene%n_probes > 0 .or. scene%n_vessels > 0 .or. scene%n_bodies > 0
   end subroutine sea_scene_build

   !> The bodies of the scene and the line ends on them.
   pure subroutine body_scene(model, mesh, scene)
      type(model_t), intent(in) :: model        !< model
      type(mesh_t), intent(in) :: mesh          !< mesh
      type(sea_scene_t), intent(inout) :: scene !< bodies set
      integer :: b, l, k, e
      scene%n_bodies = size(mesh%body_node)
      allocate (scene%body_node(scene%n_bodies), scene%body_rg(3, scene%n_bodies))
      do b = 1, scene%n_bodies
         scene%body_node(b) = mesh%body_node(b)
         scene%body_rg(:, b) = -model%bodies(b)%cog
      end do
      allocate (scene%bend_node(0), scene%bend_body(0))
      do l = 1, mesh%n_lines
         do k = 1, 2
            b = findloc(scene%body_node, mesh%end_point_node(k, l), dim=1)
            if (mesh%end_point_node(k, l) == 0 .or. b == 0) cycle
            e = mesh_node(mesh, l, merge(end_a, end_b, k == 1))
            scene%bend_node = [scene%bend_node, e]
            scene%bend_body = [scene%bend_body, b]
         end do
      end do
   end subroutine body_scene

   !> R = Rz(psi) Rv(roll, pitch, yaw): the rotation of vessel axes for a pose.
   pure function sea_rotation(pose) result(r)
      real(wp), intent(in) :: pose(7)   !< x, y, z, roll, pitch, yaw, psi
      real(wp) :: r(3, 3)
      real(wp) :: rz(3, 3)
      rz = 0.0_wp
      rz(1, 1) = cos(pose(7))
      rz(2, 1) = sin(pose(7))
      rz(1, 2) = -sin(pose(7))
      rz(2, 2) = cos(pose(7))
      rz(3, 3) = 1.0_wp
      r = matmul(rz, vessel_rotation(pose(4:6)))
   end function sea_rotation

   !> The outputs at time t (module header): r(:, node) the force and moment of the
   !> support on the line at each held node (and of a point or body on a line end); x, d
   !> the state at t (the bodies').
   pure subroutine sea_values(scene, model, field, t, r, x, d, v)
      type(sea_scene_t), intent(in) :: scene  !< the scene
      type(model_t), intent(in) :: model      !< model (vessels)
      type(wave_field_t), intent(in) :: field !< the run's sea
      real(wp), intent(in) :: t               !< time [s]
      real(wp), intent(in) :: r(:, :)         !< (6, nn) support forces [N, N m]
      real(wp), intent(in) :: x(:, :)         !< (3, nn) positions at t [m]
      real(wp), intent(in) :: d(:, :, :)      !< (3, 3, nn) directors at t
      type(sea_values_t), intent(inout) :: v  !< the values (allocated here once)
      real(wp) :: rot(3, 3), f(3), m(3), arm(3)
      integer :: k, c, iv
      if (.not. allocated(v%eta)) allocate (v%eta(scene%n_probes), &
         v%pose(7, scene%n_vessels), v%load(12, scene%n_vessels), v%conn(12, scene%n_conn), &
         v%body(12, scene%n_bodies))
      do k = 1, scene%n_bodies
         c = scene%body_node(k)
         v%body(1:3, k) = x(:, c) + matmul(d(:, :, c), scene%body_rg(:, k))
         v%body(4:6, k) = rotation_log(d(:, :, c)) + 0.0_wp
         v%body(7:12, k) = 0.0_wp
      end do
      do k = 1, size(scene%bend_node)
         c = scene%bend_node(k)
         iv = scene%bend_body(k)
         f = 0.0_wp - r(1:3, c)
         v%body(7:9, iv) = v%body(7:9, iv) + f
         v%body(10:12, iv) = v%body(10:12, iv) + cross(x(:, c) - v%body(1:3, iv), f)
      end do
      do k = 1, scene%n_probes
         ! + 0: a zero elevation (before the ramp) written as 0, not -0
         v%eta(k) = wave_elevation(field, scene%probe_xy(1, k), scene%probe_xy(2, k), t) &
                    + 0.0_wp
      end do
      do iv = 1, scene%n_vessels
         v%pose(:, iv) = vessel_pose(model%vessels(iv), t, scene%ramp(iv)) + 0.0_wp
      end do
      v%load = 0.0_wp
      do c = 1, scene%n_conn
         iv = scene%conn_vessel(c)
         rot = sea_rotation(v%pose(:, iv))
         f = 0.0_wp - r(1:3, scene%conn_node(c))   ! (0 - 0 = +0: no -0 written)
         m = 0.0_wp - r(4:6, scene%conn_node(c))
         v%conn(1:3, c) = f
         v%conn(4:6, c) = m
         v%conn(7:9, c) = matmul(transpose(rot), f)
         v%conn(10:12, c) = matmul(transpose(rot), m)
         arm = matmul(rot, scene%conn_p(:, c))
         v%load(1:3, iv) = v%load(1:3, iv) + f
         v%load(4:6, iv) = v%load(4:6, iv) + cross(arm, f) + m
      end do
      do iv = 1, scene%n_vessels
         rot = sea_rotation(v%pose(:, iv))
         v%load(7:9, iv) = matmul(transpose(rot), v%load(1:3, iv))
         v%load(10:12, iv) = matmul(transpose(rot), v%load(4:6, iv))
      end do
   end subroutine sea_values

   !> a x b.
   pure function cross(a, b) result(c)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross
end module rodyn_sea_output
