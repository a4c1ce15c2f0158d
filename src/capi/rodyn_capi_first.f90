!> MoorDyn's first C API (its source/MoorDyn.h; docs/capi.md): one system per program,
!> over the second API as MoorDyn's own MoorDyn.cpp puts it. The one system is the one
!> module variable of librodyn: the first API has no handle to hold it. Without a system
!> every function returns what MoorDyn's does (MOORDYN_MEM_ERROR, -1, 0 or nothing).
module rodyn_capi_first
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_double, c_float, c_null_ptr, &
                                          c_associated
   use rodyn_capi, only: md_create, md_init, md_step, md_close, md_get_line, md_get_point
   use rodyn_capi_items, only: line_fair_ten, fast_tens, point_pos, point_force, node_pos
   use rodyn_capi_handles, only: md_success, md_unhandled
   use rodyn_capi_wavekin, only: md_wk_init, md_wk_coords, md_wk_set
   implicit none
   private

   !> MOORDYN_MEM_ERROR: what the first API's getters return without a system
   integer(c_int), parameter :: md_mem_error = -5

   !> The one system of MoorDyn's first API.
   type(c_ptr), save :: old_api = c_null_ptr


contains

   !> MoorDynInit: the one system of infile, initialised at x (MOORDYN_UNHANDLED_ERROR
   !> when one exists already or the file cannot be read).
   function old_init(x, xd, infile) result(code) bind(c, name='MoorDynInit')
      type(c_ptr), value :: x, xd, infile   !< const double[], const double[], const char*
      integer(c_int) :: code
      code = md_unhandled
      if (c_associated(old_api)) return
      old_api = md_create(infile)
      if (.not. c_associated(old_api)) return
      code = md_init(old_api, x, xd)
      if (code == md_success) return
      if (md_close(old_api) == md_success) old_api = c_null_ptr
   end function old_init

   !> MoorDynStep: a step of the one system.
   function old_step(x, xd, f, t, dt) result(code) bind(c, name='MoorDynStep')
      type(c_ptr), value :: x, xd, f        !< const double[], const double[], double[]
      real(c_double), intent(inout) :: t, dt !< time, step [s]
      integer(c_int) :: code
      code = md_step(old_api, x, xd, f, t, dt)
   end function old_step

   !> MoorDynClose: the one system freed (MOORDYN_INVALID_VALUE when there is none).
   function old_close() result(code) bind(c, name='MoorDynClose')
      integer(c_int) :: code
      code = md_close(old_api)
      old_api = c_null_ptr
   end function old_close

   !> externalWaveKinInit: the points of external wave kinematics (0 when none or no
   !> system); getWaveKinCoordinates, setWaveKin: over MoorDyn_ExternalWaveKin*.
   integer(c_int) function old_wave_init() bind(c, name='externalWaveKinInit')
      integer(c_int) :: n
      old_wave_init = 0
      if (.not. c_associated(old_api)) return
      if (md_wk_init(old_api, n) == md_success) old_wave_init = n
   end function old_wave_init

   subroutine old_wave_coords(r) bind(c, name='getWaveKinCoordinates')
      type(c_ptr), value :: r               !< double[]
      if (c_associated(old_api)) then
         if (md_wk_coords(old_api, r) /= md_success) return
      end if
   end subroutine old_wave_coords

   subroutine old_wave_set(u, ud, t) bind(c, name='setWaveKin')
      type(c_ptr), value :: u, ud           !< const double[], const double[]
      real(c_double), value :: t            !< time [s]
      if (c_associated(old_api)) then
         if (md_wk_set(old_api, u, ud, t) /= md_success) return
      end if
   end subroutine old_wave_set

   !> GetFairTen: the fairlead tension of line l [N] (-1 without a system).
   real(c_double) function old_fair_ten(l) bind(c, name='GetFairTen')
      integer(c_int), value :: l            !< line ID
      old_fair_ten = -1.0_c_double
      if (.not. c_associated(old_api)) return
      if (line_fair_ten(md_get_line(old_api, l), old_fair_ten) /= md_success) &
         old_fair_ten = -1.0_c_double
   end function old_fair_ten

   !> GetFASTtens: MoorDyn_GetFASTtens of the one system.
   integer(c_int) function old_fast_tens(nl, fh, fv, ah, av) bind(c, name='GetFASTtens')
      integer(c_int), intent(in) :: nl      !< lines to fill
      real(c_float), intent(out) :: fh(*), fv(*), ah(*), av(*) !< tensions [N]
      old_fast_tens = md_mem_error
      if (c_associated(old_api)) old_fast_tens = fast_tens(old_api, nl, fh, fv, ah, av)
   end function old_fast_tens

   !> GetPointPos, GetPointForce: of point l of the one system.
   integer(c_int) function old_point_pos(l, pos) bind(c, name='GetPointPos')
      integer(c_int), value :: l            !< point ID
      real(c_double), intent(out) :: pos(3) !< position [m]
      old_point_pos = md_mem_error
      if (c_associated(old_api)) old_point_pos = point_pos(md_get_point(old_api, l), pos)
   end function old_point_pos

   integer(c_int) function old_point_force(l, f) bind(c, name='GetPointForce')
      integer(c_int), value :: l            !< point ID
      real(c_double), intent(out) :: f(3)   !< force [N]
      old_point_force = md_mem_error
      if (c_associated(old_api)) old_point_force = point_force(md_get_point(old_api, l), f)
   end function old_point_force

   !> GetNodePos: node k (from 0) of line l of the one system [m].
   integer(c_int) function old_node_pos(l, k, pos) bind(c, name='GetNodePos')
      integer(c_int), value :: l, k         !< line ID, node
      real(c_double), intent(out) :: pos(3) !< position [m]
      old_node_pos = md_mem_error
      if (c_associated(old_api)) old_node_pos = node_pos(md_get_line(old_api, l), k, pos)
   end function old_node_pos

   !> AllOutput: nothing to do (MoorDynInit and MoorDynStep write the outputs, as in
   !> MoorDyn v2); SetDisableConsole: nothing to do (librodyn opens no console).
   subroutine old_all_output(t, dt) bind(c, name='AllOutput')
      real(c_double), value :: t, dt        !< time, step [s]
   end subroutine old_all_output

   subroutine old_disable_console(disable) bind(c, name='SetDisableConsole')
      integer(c_int), value :: disable      !< 1: no console
   end subroutine old_disable_console

end module rodyn_capi_first
