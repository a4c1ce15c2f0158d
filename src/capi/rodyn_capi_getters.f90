!> librodyn's further getters of points, bodies, lines and rods (MoorDyn v2's Point.h,
!> Body.h, Line.h and Rod.h; docs/capi.md): a point's velocity and the line ends on it, a
!> body's type, position, angles and their rates, a line's axial stiffness, a fixed
!> rod's nodes. IDs from 1, attachments
!> and nodes from 0, as MoorDyn's.
module rodyn_capi_getters
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_double, c_loc, c_null_ptr
   use rodyn_kinds, only: wp
   use rodyn_model, only: body_fixed, end_a, end_b
   use rodyn_mesh, only: mesh_node
   use rodyn_system_dynamics, only: end_released
   use rodyn_capi_system, only: system_body_state, system_point_node, system_end_force
   use rodyn_capi_items, only: line_id
   use rodyn_capi_handles, only: capi_item_t, item_of, md_success, md_invalid_value, &
                                 md_unhandled
   use, intrinsic :: iso_fortran_env, only: error_unit
   implicit none
   private

contains

   !> MoorDyn_GetPointVel: the point's velocity [m/s]: a coupled point's the host's, another
   !> that of a line end on it, once initialised; 0 before.
   function point_vel(h, v) result(code) bind(c, name='MoorDyn_GetPointVel')
      type(c_ptr), value :: h               !< point
      real(c_double), intent(out) :: v(3)   !< velocity [m/s]
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      integer :: node, k
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      v = 0.0_c_double
      if (it%sys%s%stage == 1) then
         node = system_point_node(it%sys%s, it%index)
         if (node > 0) v = real(it%sys%s%state%v(:, node), c_double)
         ! a coupled point: the host's velocity over the last step (the node's rate at the
         ! step's end is the midpoint rule's, eq. (33), 2 dx/dt - v_n: after a jump in
         ! the host's velocity it alternates about it)
         k = findloc(it%sys%s%coupled, it%index, dim=1)
         if (k > 0 .and. allocated(it%sys%s%xd_last)) then
            k = 6*size(it%sys%s%cbody) + 3*k
            v = real(it%sys%s%xd_last(k - 2:k), c_double)
         end if
      end if
      code = md_success
   end function point_vel

   !> MoorDyn_GetPointNAttached: the line ends on the point (a broken one no more).
   function point_n_attached(h, n) result(code) bind(c, name='MoorDyn_GetPointNAttached')
      type(c_ptr), value :: h               !< point
      integer(c_int), intent(out) :: n      !< unsigned int: how many
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      integer :: l, e
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      n = 0
      l = 0
      e = 0
      call attached(it, huge(1), l, e, n)
      code = md_success
   end function point_n_attached

   !> MoorDyn_GetPointAttached: line end i (from 0) on the point, in MoorDyn's order (the
   !> lines in turn, end A before end B): its line's handle and the end, 0 A, 1 B.
   function point_attached(h, i, lh, e) result(code) bind(c, name='MoorDyn_GetPointAttached')
      type(c_ptr), value :: h               !< point
      integer(c_int), value :: i            !< unsigned int: the end, from 0
      type(c_ptr), intent(out) :: lh        !< MoorDynLine*
      integer(c_int), intent(out) :: e      !< int*: 0 end A, 1 end B
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      integer :: l, k, n
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it) .or. i < 0) return
      lh = c_null_ptr
      e = 0
      call attached(it, int(i) + 1, l, k, n)
      if (l == 0) return
      lh = c_loc(it%sys%lines(l))
      e = int(k - 1, c_int)
      code = md_success
   end function point_attached

   !> The j-th line end still on point it (line l, end k; l = 0 when there are fewer),
   !> and how many ends there are up to it (all of them when j is larger).
   subroutine attached(it, j, l, k, n)
      type(capi_item_t), intent(in) :: it   !< the point
      integer, intent(in) :: j              !< which, from 1
      integer, intent(out) :: l, k          !< its line and end (1 A, 2 B)
      integer(c_int), intent(out) :: n      !< ends counted
      integer :: ll, kk, node
      n = 0
      associate (s => it%sys%s)
         do ll = 1, size(s%model%lines)
            do kk = 1, 2
               if (merge(s%model%lines(ll)%point_a, s%model%lines(ll)%point_b, kk == 1) &
                   /= it%index) cycle
               if (s%stage == 1) then    ! (meshed: a broken end is off it)
                  node = mesh_node(s%mesh, ll, merge(end_a, end_b, kk == 1))
                  if (end_released(s%prob%fl, node)) cycle
               end if
               n = n + 1
               if (n == j) then
                  l = ll
                  k = kk
                  return
               end if
            end do
         end do
      end associate
      l = 0
      k = 0
   end subroutine attached

   !> MoorDyn_GetBodyType: -1 coupled (moved by the host), 0 free, 1 fixed.
   function body_type(h, t) result(code) bind(c, name='MoorDyn_GetBodyType')
      type(c_ptr), value :: h               !< body
      integer(c_int), intent(out) :: t      !< its type
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      t = 0
      if (it%sys%s%model%bodies(it%index)%kind == body_fixed) t = 1
      if (any(it%sys%s%cbody == it%index)) t = -1
      code = md_success
   end function body_type

   !> MoorDyn_GetBodyPos, _GetBodyAngle, _GetBodyVel, _GetBodyAngVel: parts of
   !> MoorDyn_GetBodyState (its reference point, angles r, p, y, velocity, angular
   !> velocity), once initialised.
   function body_pos(h, r) result(code) bind(c, name='MoorDyn_GetBodyPos')
      type(c_ptr), value :: h               !< body
      real(c_double), intent(out) :: r(3)   !< reference point [m]
      integer(c_int) :: code
      code = body_part(h, 1, r)
   end function body_pos

   function body_angle(h, r) result(code) bind(c, name='MoorDyn_GetBodyAngle')
      type(c_ptr), value :: h               !< body
      real(c_double), intent(out) :: r(3)   !< angles r, p, y [rad]
      integer(c_int) :: code
      code = body_part(h, 2, r)
   end function body_angle

   function body_vel(h, v) result(code) bind(c, name='MoorDyn_GetBodyVel')
      type(c_ptr), value :: h               !< body
      real(c_double), intent(out) :: v(3)   !< velocity [m/s]
      integer(c_int) :: code
      code = body_part(h, 3, v)
   end function body_vel

   function body_ang_vel(h, w) result(code) bind(c, name='MoorDyn_GetBodyAngVel')
      type(c_ptr), value :: h               !< body
      real(c_double), intent(out) :: w(3)   !< angular velocity [rad/s]
      integer(c_int) :: code
      code = body_part(h, 4, w)
   end function body_ang_vel

   !> Part p (1 position, 2 angles, 3 velocity, 4 angular velocity) of a body's state.
   function body_part(h, p, v) result(code)
      type(c_ptr), intent(in) :: h          !< body
      integer, intent(in) :: p              !< which part
      real(c_double), intent(out) :: v(3)   !< its three values
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      real(wp) :: r(6), rd(6), both(12)
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      v = 0.0_c_double
      if (it%sys%s%stage /= 1) return
      call system_body_state(it%sys%s, it%index, r, rd)
      both = [r, rd]
      v = real(both(3*p - 2:3*p), c_double)
      code = md_success
   end function body_part

   !> MoorDyn_IsLineConstantEA: 1 (rodyn reads no nonlinear axial stiffness: a MoorDyn
   !> line with a table of EA is refused when read); MoorDyn_GetLineConstantEA: its EA
   !> [N]; MoorDyn_IsLinePressBend: 0 (no pressure bending).
   function line_is_const_ea(h, b) result(code) bind(c, name='MoorDyn_IsLineConstantEA')
      type(c_ptr), value :: h               !< line
      integer(c_int), intent(out) :: b      !< 1: constant
      integer(c_int) :: code
      b = 1
      code = md_success
      if (.not. associated(item_of(h))) code = md_invalid_value
   end function line_is_const_ea

   function line_const_ea(h, ea) result(code) bind(c, name='MoorDyn_GetLineConstantEA')
      type(c_ptr), value :: h               !< line
      real(c_double), intent(out) :: ea     !< axial stiffness [N]
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      ea = 0.0_c_double
      associate (m => it%sys%s%model)
         ea = real(m%sections(m%lines(it%index)%section)%ea, c_double)
      end associate
      code = md_success
   end function line_const_ea

   function line_is_press_bend(h, b) result(code) bind(c, name='MoorDyn_IsLinePressBend')
      type(c_ptr), value :: h               !< line
      integer(c_int), intent(out) :: b      !< 0: no pressure bending
      integer(c_int) :: code
      b = 0
      code = md_success
      if (.not. associated(item_of(h))) code = md_invalid_value
   end function line_is_press_bend

   !> MoorDyn_GetRodID; MoorDyn_GetRodType: 2, MoorDyn's FIXED (rodyn reads fixed rods; a
   !> coupled one is refused by MoorDyn_Create, a moving one when read).
   function rod_id(h, id) result(code) bind(c, name='MoorDyn_GetRodID')
      type(c_ptr), value :: h               !< rod
      integer(c_int), intent(out) :: id     !< its ID
      integer(c_int) :: code
      code = line_id(h, id)
   end function rod_id

   function rod_type(h, t) result(code) bind(c, name='MoorDyn_GetRodType')
      type(c_ptr), value :: h               !< rod
      integer(c_int), intent(out) :: t      !< its type
      integer(c_int) :: code
      code = md_invalid_value
      if (.not. associated(item_of(h))) return
      t = 2
      code = md_success
   end function rod_type

   !> MoorDyn_GetRodN (NumSegs), MoorDyn_GetRodNumberNodes (NumSegs + 1).
   function rod_n(h, n) result(code) bind(c, name='MoorDyn_GetRodN')
      type(c_ptr), value :: h               !< rod
      integer(c_int), intent(out) :: n      !< unsigned int: segments
      integer(c_int) :: code
      code = rod_nodes(h, n)
      if (code == md_success) n = n - 1
   end function rod_n

   function rod_nodes(h, n) result(code) bind(c, name='MoorDyn_GetRodNumberNodes')
      type(c_ptr), value :: h               !< rod
      integer(c_int), intent(out) :: n      !< unsigned int: nodes
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      n = int(it%sys%s%info%rod_nodes(it%index), c_int)
      code = md_success
   end function rod_nodes

   !> MoorDyn_GetRodNodePos: node i (from 0 at end A) of the rod, its nodes evenly along
   !> it [m]; MoorDyn_GetRodNodeVel: 0 (a fixed rod).
   function rod_node_pos(h, i, pos) result(code) bind(c, name='MoorDyn_GetRodNodePos')
      type(c_ptr), value :: h               !< rod
      integer(c_int), value :: i            !< unsigned int: node
      real(c_double), intent(out) :: pos(3) !< position [m]
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      integer :: n
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      n = it%sys%s%info%rod_nodes(it%index) - 1
      if (i < 0 .or. i > n) return
      associate (e => it%sys%s%info%rod_ends(:, it%index))
         pos = real(e(1:3) + (e(4:6) - e(1:3))*real(i, wp)/real(n, wp), c_double)
      end associate
      code = md_success
   end function rod_node_pos

   function rod_node_vel(h, i, v) result(code) bind(c, name='MoorDyn_GetRodNodeVel')
      type(c_ptr), value :: h               !< rod
      integer(c_int), value :: i            !< unsigned int: node
      real(c_double), intent(out) :: v(3)   !< velocity [m/s]
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      if (i < 0 .or. i >= it%sys%s%info%rod_nodes(it%index)) return
      v = 0.0_c_double
      code = md_success
   end function rod_node_vel

   !> MoorDyn_GetLineNodeForce at an end held by a point (fixed, coupled, or on a fixed or
   !> coupled body): the force the line exerts on it [N] (MoorDyn's net force on the end
   !> node, which its point takes); at another node MOORDYN_UNHANDLED_ERROR (not served).
   function line_node_force(h, i, f) result(code) bind(c, name='MoorDyn_GetLineNodeForce')
      type(c_ptr), value :: h               !< line
      integer(c_int), value :: i            !< unsigned int: node, from 0
      real(c_double), intent(out) :: f(3)   !< force [N]
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      real(wp) :: fw(3)
      integer :: n
      logical :: ok
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      if (it%sys%s%stage /= 1) return
      n = it%sys%s%mesh%line_n_nodes(it%index) - 1
      if (i < 0 .or. i > n) return
      ok = .false.
      if (i == 0 .or. i == n) call system_end_force(it%sys%s, it%index, &
                                                   merge(1, 2, i == 0), fw, ok)
      code = md_unhandled
      if (.not. ok) then
         write (error_unit, '(a)') 'rodyn: error: MoorDyn_GetLineNodeForce is served at '// &
            'a line''s ends held by points, not at this node'
         return
      end if
      f = real(fw, c_double)
      code = md_success
   end function line_node_force

end module rodyn_capi_getters
