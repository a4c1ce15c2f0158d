!> librodyn's functions of a line and a point (MoorDyn v2's Line.h and Point.h), and the
!> fairlead and anchor tensions of MoorDyn_GetFASTtens (docs/capi.md).
module rodyn_capi_items
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_double, c_float, c_null_ptr, &
                                          c_associated
   use, intrinsic :: iso_fortran_env, only: error_unit
   use rodyn_kinds, only: wp
   use rodyn_model, only: end_a, end_b, point_free
   use rodyn_mesh, only: mesh_node
   use rodyn_capi_system, only: system_node_x, system_node_tension, system_forces, &
                                system_ndof, system_body_state, system_point_x, &
                                system_tension_served, system_end_force
   use rodyn_capi_handles, only: capi_item_t, capi_system_t, system_of, item_of, &
                                 md_success, md_invalid_value, md_unhandled
   implicit none
   private

   public :: line_fair_ten, fast_tens, point_pos, point_force, node_pos, line_id

contains

   !> MoorDyn_GetLineID, MoorDyn_GetLineN (segments), MoorDyn_GetLineNumberNodes.
   function line_id(h, id) result(code) bind(c, name='MoorDyn_GetLineID')
      type(c_ptr), value :: h               !< line
      integer(c_int), intent(out) :: id     !< its ID
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      id = int(it%index, c_int)
      code = md_success
   end function line_id

   function line_n(h, n) result(code) bind(c, name='MoorDyn_GetLineN')
      type(c_ptr), value :: h               !< line
      integer(c_int), intent(out) :: n      !< unsigned int*: segments
      integer(c_int) :: code
      code = line_nodes(h, n)
      if (code == md_success) n = n - 1
   end function line_n

   function line_nodes(h, n) result(code) bind(c, name='MoorDyn_GetLineNumberNodes')
      type(c_ptr), value :: h               !< line
      integer(c_int), intent(out) :: n      !< unsigned int*: nodes
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      n = 0
      if (it%sys%s%stage == 0) then      ! not meshed yet: the file's segments
         n = int(it%sys%s%model%lines(it%index)%n_elements* &
                 it%sys%s%model%lines(it%index)%order + 1, c_int)
      else
         n = int(it%sys%s%mesh%line_n_nodes(it%index), c_int)
      end if
      code = md_success
   end function line_nodes

   !> MoorDyn_GetLineUnstretchedLength [m].
   function line_length(h, ul) result(code) bind(c, name='MoorDyn_GetLineUnstretchedLength')
      type(c_ptr), value :: h               !< line
      real(c_double), intent(out) :: ul     !< length [m]
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      ul = real(it%sys%s%model%lines(it%index)%length, c_double)
      code = md_success
   end function line_length

   !> The line and node of a handle and index i (from 0), when both exist and the system
   !> is initialised.
   function node_of(h, i) result(it)
      type(c_ptr), intent(in) :: h          !< line
      integer(c_int), intent(in) :: i       !< node, from 0
      type(capi_item_t), pointer :: it
      it => item_of(h)
      if (.not. associated(it)) return
      if (it%sys%s%stage /= 1 .or. i < 0) then
         it => null()
      else if (i >= it%sys%s%mesh%line_n_nodes(it%index)) then
         it => null()
      end if
   end function node_of

   !> MoorDyn_GetLineNodePos: node i (from 0) [m].
   function node_pos(h, i, pos) result(code) bind(c, name='MoorDyn_GetLineNodePos')
      type(c_ptr), value :: h               !< line
      integer(c_int), value :: i            !< node, from 0
      real(c_double), intent(out) :: pos(3) !< position [m]
      integer(c_int) :: code
      code = node_vector(h, i, pos, 'x')
   end function node_pos

   !> MoorDyn_GetLineNodeTen: MoorDyn's tension vector of node i [N].
   function node_ten(h, i, t) result(code) bind(c, name='MoorDyn_GetLineNodeTen')
      type(c_ptr), value :: h               !< line
      integer(c_int), value :: i            !< node, from 0
      real(c_double), intent(out) :: t(3)   !< tension [N]
      integer(c_int) :: code
      code = node_vector(h, i, t, 't')
   end function node_ten

   !> MoorDyn_GetLineNodeVel: the velocity of node i [m/s].
   function node_vel(h, i, v) result(code) bind(c, name='MoorDyn_GetLineNodeVel')
      type(c_ptr), value :: h               !< line
      integer(c_int), value :: i            !< node, from 0
      real(c_double), intent(out) :: v(3)   !< velocity [m/s]
      integer(c_int) :: code
      code = node_vector(h, i, v, 'v')
   end function node_vel

   !> The position (t: the tension vector, v: the velocity) of node i of a line.
   function node_vector(h, i, v, what) result(code)
      type(c_ptr), intent(in) :: h          !< line
      integer(c_int), intent(in) :: i       !< node, from 0
      real(c_double), intent(out) :: v(3)   !< [m], [N] or [m/s]
      character(len=1), intent(in) :: what  !< 'x', 't' or 'v'
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      it => node_of(h, i)
      code = md_invalid_value
      if (.not. associated(it)) return
      v = 0.0_c_double
      associate (s => it%sys%s)
         select case (what)
         case ('t')
            if (.not. system_tension_served(s, it%index)) then
               code = not_linear()
               return
            end if
            v = real(system_node_tension(s, it%index, int(i)), c_double)
         case ('v')
            v = real(s%state%v(:, mesh_node(s%mesh, it%index, int(i) + 1)), c_double)
         case default
            v = real(system_node_x(s, it%index, int(i)), c_double)
         end select
      end associate
      code = md_success
   end function node_vector

   !> MoorDyn_GetLineMaxTen: the largest node tension of a line [N].
   function line_max_ten(h, t) result(code) bind(c, name='MoorDyn_GetLineMaxTen')
      type(c_ptr), value :: h               !< line
      real(c_double), intent(out) :: t      !< tension [N]
      integer(c_int) :: code
      code = line_tension(h, t, .true.)
   end function line_max_ten

   !> The largest node tension of a line, or (top false) that at end B [N].
   function line_tension(h, t, top) result(code)
      type(c_ptr), intent(in) :: h          !< line
      real(c_double), intent(out) :: t      !< tension [N]
      logical, intent(in) :: top            !< the largest, else end B's
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      integer :: k, n
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      t = 0.0_c_double
      if (it%sys%s%stage /= 1) return
      if (.not. system_tension_served(it%sys%s, it%index)) then
         code = not_linear()
         return
      end if
      n = it%sys%s%mesh%line_n_nodes(it%index) - 1
      do k = merge(0, n, top), n
         t = max(t, real(norm2(system_node_tension(it%sys%s, it%index, k)), c_double))
      end do
      code = md_success
   end function line_tension

   !> MoorDyn_GetLineNodeCurv: 0, a cable line's (rodyn's cable elements carry no
   !> bending; a line with EI > 0 is not yet served).
   function node_curv(h, i, c) result(code) bind(c, name='MoorDyn_GetLineNodeCurv')
      type(c_ptr), value :: h               !< line
      integer(c_int), value :: i            !< node, from 0
      real(c_double), intent(out) :: c      !< curvature [1/m]
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      it => node_of(h, i)
      code = md_invalid_value
      if (.not. associated(it)) return
      c = 0.0_c_double
      code = md_success
      if (it%sys%s%model%sections(it%sys%s%model%lines(it%index)%section)%ei1 > 0.0_wp) &
         code = md_unhandled
   end function node_curv

   !> MoorDyn_GetLineFairTen: the tension at end B (MoorDyn's fairlead end) [N].
   function line_fair_ten(h, t) result(code) bind(c, name='MoorDyn_GetLineFairTen')
      type(c_ptr), value :: h               !< line
      real(c_double), intent(out) :: t      !< tension [N]
      integer(c_int) :: code
      code = line_tension(h, t, .false.)
   end function line_fair_ten

   !> MoorDyn_GetPointID.
   function point_id(h, id) result(code) bind(c, name='MoorDyn_GetPointID')
      type(c_ptr), value :: h               !< point
      integer(c_int), intent(out) :: id     !< its ID
      integer(c_int) :: code
      code = line_id(h, id)
   end function point_id

   !> MoorDyn_GetPointType: MoorDyn's point types, -1 coupled (a host moves it), 0 free,
   !> 1 fixed (an anchor, or on a body).
   function point_type(h, t) result(code) bind(c, name='MoorDyn_GetPointType')
      type(c_ptr), value :: h               !< point
      integer(c_int), intent(out) :: t      !< its type
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      t = 1
      if (it%sys%s%model%points(it%index)%kind == point_free) t = 0
      if (any(it%sys%s%coupled == it%index)) t = -1
      code = md_success
   end function point_type

   !> MoorDyn_GetBodyID.
   function body_id(h, id) result(code) bind(c, name='MoorDyn_GetBodyID')
      type(c_ptr), value :: h               !< body
      integer(c_int), intent(out) :: id     !< its ID
      integer(c_int) :: code
      code = line_id(h, id)
   end function body_id

   !> MoorDyn_GetBodyState: its reference point and angles r, p, y (Rx Ry Rz), their
   !> rates (velocity, angular velocity), once initialised [m, rad, m/s, rad/s].
   function body_state(h, r, rd) result(code) bind(c, name='MoorDyn_GetBodyState')
      type(c_ptr), value :: h               !< body
      real(c_double), intent(out) :: r(6)   !< position and angles
      real(c_double), intent(out) :: rd(6)  !< their rates
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      real(wp) :: rw(6), rdw(6)
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      r = 0.0_c_double
      rd = 0.0_c_double
      if (it%sys%s%stage /= 1) return
      call system_body_state(it%sys%s, it%index, rw, rdw)
      r = real(rw, c_double)
      rd = real(rdw, c_double)
      code = md_success
   end function body_state

   !> MoorDyn_GetPointPos: where the point is [m] (a point on a line end: that end's
   !> node, once initialised).
   function point_pos(h, pos) result(code) bind(c, name='MoorDyn_GetPointPos')
      type(c_ptr), value :: h               !< point
      real(c_double), intent(out) :: pos(3) !< position [m]
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      pos = real(system_point_x(it%sys%s, it%index), c_double)
      code = md_success
   end function point_pos

   !> MoorDyn_GetPointForce: the lines' force on a coupled point [N] (0 on the others,
   !> not yet served).
   function point_force(h, f) result(code) bind(c, name='MoorDyn_GetPointForce')
      type(c_ptr), value :: h               !< point
      real(c_double), intent(out) :: f(3)   !< force [N]
      integer(c_int) :: code
      type(capi_item_t), pointer :: it
      real(wp), allocatable :: fa(:)
      integer :: k
      it => item_of(h)
      code = md_invalid_value
      if (.not. associated(it)) return
      f = 0.0_c_double
      if (it%sys%s%stage /= 1) return
      k = findloc(it%sys%s%coupled, it%index, dim=1)
      code = md_unhandled
      if (k == 0) return
      allocate (fa(system_ndof(it%sys%s)))
      call system_forces(it%sys%s, fa)
      k = k + 2*size(it%sys%s%cbody)    ! (after the bodies' 6 DOFs)
      f = real(fa(3*k - 2:3*k), c_double)
      code = md_success
   end function point_force

   !> MoorDyn_GetFASTtens: for each line, the horizontal and vertical tension at end B
   !> (fairlead) and end A (anchor) [N]: MoorDyn's node tension of the end segments on a
   !> line of linear elements of one section; on another line (a deck's), the force of
   !> the line on the point that holds the end (system_end_force), an end not held
   !> refused.
   function fast_tens(h, nl, fh, fv, ah, av) result(code) bind(c, name='MoorDyn_GetFASTtens')
      type(c_ptr), value :: h               !< system
      integer(c_int), intent(in) :: nl      !< lines to fill
      real(c_float), intent(out) :: fh(*), fv(*), ah(*), av(*) !< tensions [N]
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      real(wp) :: t(3), ta(3)
      logical :: held
      integer :: l, n
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      if (cs%s%stage /= 1 .or. nl > size(cs%lines)) return
      do l = 1, nl
         if (system_tension_served(cs%s, l)) then
            n = cs%s%mesh%line_n_nodes(l) - 1
            t = system_node_tension(cs%s, l, n)
            ta = system_node_tension(cs%s, l, 0)
         else
            call system_end_force(cs%s, l, 2, t, held)
            if (held) call system_end_force(cs%s, l, 1, ta, held)
            if (.not. held) then
               code = not_held()
               return
            end if
         end if
         fh(l) = real(norm2(t(1:2)), c_float)
         fv(l) = real(abs(t(3)), c_float)
         ah(l) = real(norm2(ta(1:2)), c_float)
         av(l) = real(abs(ta(3)), c_float)
      end do
      code = md_success
   end function fast_tens

   !> MOORDYN_UNHANDLED_ERROR, and why on stderr: GetFASTtens on a deck's line with an
   !> end not held by a point.
   integer(c_int) function not_held() result(code)
      write (error_unit, '(a)') 'rodyn: error: MoorDyn_GetFASTtens: on a line of a deck '// &
         '(not linear elements of one section), the end forces are served where both ends '// &
         'are held by points'
      code = md_unhandled
   end function not_held

   !> MOORDYN_UNHANDLED_ERROR, and why on stderr: MoorDyn's node tension on a deck's line
   !> of higher order or of several segments.
   integer(c_int) function not_linear() result(code)
      write (error_unit, '(a)') 'rodyn: error: MoorDyn''s node tension is served on lines '// &
         'of linear elements of one section (a MoorDyn file''s), not on this deck''s line'
      code = md_unhandled
   end function not_linear
end module rodyn_capi_items
