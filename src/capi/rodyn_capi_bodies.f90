!> Coupled bodies of a host-driven system (docs/capi.md, "Coupled bodies"): a MoorDyn
!> body coupled to the host (Coupled, Vessel) is a FIXED body moved with a vessel whose
!> six motions the host's steps give, row by row (the vessel's table in the dynamic
!> problem, prob%vessels, grows a row a step), and the lines' force and moment on it are
!> the sum over its points' line ends.
!>
!> MoorDyn's six coupled DOFs of a body are its reference point's position and three
!> angles r, p, y with its orientation Rx(r) Ry(p) Rz(y) (MoorDyn's Euler2Quat, as for
!> a body's r0, p0, y0 in the file); rodyn's vessel turns by Rz(yaw) Ry(pitch) Rx(roll)
!> (rodyn_vessel, vessel_rotation), so each pose is converted through its rotation
!> matrix (mdc_angles).
module rodyn_capi_bodies
   use rodyn_kinds, only: wp
   use rodyn_model, only: model_t, vessel_t, motion_t, motion_vessel, vessel_from_table, &
                          end_a, end_b
   use rodyn_mesh, only: mesh_t, mesh_node
   use rodyn_rotation, only: cross
   use rodyn_system_dynamics, only: failures_t, end_released
   implicit none
   private
   public :: add_body_vessels, body_pose_row, body_forces, mdc_angles, mdc_rotation

contains

   !> A vessel at rest at each coupled body's reference point, its table one row at
   !> t = 0, and the body's *MOTION with it (no ramp): appended to model%vessels and
   !> model%motions; vessel(i) is the index of body i's.
   subroutine add_body_vessels(model, bodies, vessel)
      type(model_t), intent(inout) :: model !< model
      integer, intent(in) :: bodies(:)      !< the coupled bodies (model%bodies)
      integer, intent(out) :: vessel(:)     !< their vessels (model%vessels)
      type(vessel_t), allocatable :: ve(:)
      type(motion_t), allocatable :: mo(:)
      integer :: i, nv, nm
      nv = 0
      nm = 0
      if (allocated(model%vessels)) nv = size(model%vessels)
      if (allocated(model%motions)) nm = size(model%motions)
      allocate (ve(nv + size(bodies)), mo(nm + size(bodies)))
      if (nv > 0) ve(1:nv) = model%vessels
      if (nm > 0) mo(1:nm) = model%motions
      do i = 1, size(bodies)
         vessel(i) = nv + i
         ve(nv + i)%name = 'host_'//trim(model%bodies(bodies(i))%name)
         ve(nv + i)%origin = model%bodies(bodies(i))%position
         ve(nv + i)%heading = 0.0_wp
         ve(nv + i)%kind = vessel_from_table
         ve(nv + i)%file = 'host'
         ve(nv + i)%time = [0.0_wp]
         ve(nv + i)%motion = reshape([(0.0_wp, i = 1, 6)], [6, 1])
         mo(nm + i)%body = bodies(i)
         mo(nm + i)%line = 0
         mo(nm + i)%point = 0
         mo(nm + i)%kind = motion_vessel
         mo(nm + i)%vessel = nv + i
         mo(nm + i)%ramp = 0.0_wp
      end do
      call move_alloc(ve, model%vessels)
      call move_alloc(mo, model%motions)
   end subroutine add_body_vessels

   !> The vessel's table to its last row and a row at t, the body at MoorDyn's pose q
   !> (x, y, z, r, p, y): all a step and its halvings read (a table grown a row a step
   !> would be copied whole every step).
   subroutine body_pose_row(ve, t, q)
      type(vessel_t), intent(inout) :: ve   !< the body's vessel (in the dynamic problem)
      real(wp), intent(in) :: t             !< time [s]
      real(wp), intent(in) :: q(6)          !< MoorDyn's pose [m, rad]
      integer :: n
      n = size(ve%time)
      ve%time = [ve%time(n), t]
      ve%motion = reshape([ve%motion(:, n), q(1:3) - ve%origin, mdc_angles(q(4:6))], [6, 2])
   end subroutine body_pose_row

   !> rodyn's vessel angles (roll, pitch, yaw of Rz Ry Rx) of MoorDyn's Rx Ry Rz.
   pure function mdc_angles(a) result(b)
      real(wp), intent(in) :: a(3)          !< MoorDyn's r, p, y [rad]
      real(wp) :: b(3)                      !< roll, pitch, yaw [rad]
      real(wp) :: r(3, 3)
      r = mdc_rotation(a)
      b(2) = -asin(max(-1.0_wp, min(1.0_wp, r(3, 1))))
      b(1) = atan2(r(3, 2), r(3, 3))
      b(3) = atan2(r(2, 1), r(1, 1))
   end function mdc_angles

   !> MoorDyn's orientation Rx(a1) Ry(a2) Rz(a3).
   pure function mdc_rotation(a) result(r)
      real(wp), intent(in) :: a(3)          !< r, p, y [rad]
      real(wp) :: r(3, 3)
      real(wp) :: rx(3, 3), ry(3, 3), rz(3, 3)
      rx = reshape([1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, cos(a(1)), sin(a(1)), 0.0_wp, &
                    -sin(a(1)), cos(a(1))], [3, 3])
      ry = reshape([cos(a(2)), 0.0_wp, -sin(a(2)), 0.0_wp, 1.0_wp, 0.0_wp, sin(a(2)), &
                    0.0_wp, cos(a(2))], [3, 3])
      rz = reshape([cos(a(3)), sin(a(3)), 0.0_wp, -sin(a(3)), cos(a(3)), 0.0_wp, 0.0_wp, &
                    0.0_wp, 1.0_wp], [3, 3])
      r = matmul(rx, matmul(ry, rz))
   end function mdc_rotation

   !> The lines' force and moment about the body's reference point rb on body ib [N, N m]
   !> from the support forces r of the line ends on its points.
   function body_forces(model, mesh, fl, x, r, ib, rb) result(f)
      type(model_t), intent(in) :: model    !< model
      type(mesh_t), intent(in) :: mesh      !< mesh
      type(failures_t), intent(in) :: fl    !< released ends (not counted)
      real(wp), intent(in) :: x(:, :)       !< (3, nn) node positions [m]
      real(wp), intent(in) :: r(:, :)       !< (6, nn) support forces [N, N m]
      integer, intent(in) :: ib             !< the body
      real(wp), intent(in) :: rb(3)         !< where its reference point is [m]
      real(wp) :: f(6)
      integer :: l, k, node, ip
      f = 0.0_wp
      do l = 1, size(model%lines)
         do k = 1, 2
            ip = merge(model%lines(l)%point_a, model%lines(l)%point_b, k == 1)
            if (ip == 0) cycle
            if (model%points(ip)%body /= ib) cycle
            node = mesh_node(mesh, l, merge(end_a, end_b, k == 1))
            if (end_released(fl, node)) cycle
            f(1:3) = f(1:3) - r(1:3, node)
            f(4:6) = f(4:6) - cross(x(:, node) - rb, r(1:3, node))
            if (size(r, 1) >= 6) f(4:6) = f(4:6) - r(4:6, node)
         end do
      end do
   end function body_forces
end module rodyn_capi_bodies
