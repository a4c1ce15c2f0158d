!> librodyn's C functions: MoorDyn v2's C API (src/capi/include/MoorDyn2.h, MoorDyn.h;
!> docs/capi.md) over md_system_t (rodyn_capi_system). A MoorDyn handle is a pointer
!> to a capi_system_t; a line or point handle a pointer to an item of it. IDs of lines
!> and points count from 1 and nodes from 0, as MoorDyn's. Every function returns one
!> of MoorDyn's codes; a message goes to stderr. No error stops the host.
module rodyn_capi
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_double, c_null_ptr, c_loc, &
                                          c_f_pointer, c_associated
   use, intrinsic :: iso_fortran_env, only: error_unit
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error, stat_input, stat_io
   use rodyn_capi_system, only: system_create, system_init, system_step, system_ndof, &
                                system_break
   use rodyn_capi_outputs, only: channels_parse, out_open, out_row, out_close
   use rodyn_capi_handles, only: capi_system_t, capi_item_t, system_of, item_of, f_string, &
                                 md_success, &
                                 md_invalid_input, md_nan_error, md_invalid_value, &
                                 md_invalid_output_file
   implicit none
   private
   public :: md_create, md_init, md_step, md_close, md_get_line, md_get_point

contains

   !> MoorDyn_Create: the system of a MoorDyn v2 input file; NULL when it cannot be read
   !> (the reader's 'FILE:LINE: error: ...' on stderr).
   function md_create(infile) result(h) bind(c, name='MoorDyn_Create')
      type(c_ptr), value :: infile          !< const char*
      type(c_ptr) :: h
      type(capi_system_t), pointer :: cs
      type(error_t) :: err
      integer :: k
      h = c_null_ptr
      allocate (cs)
      cs%path = f_string(infile)
      call system_create(cs%s, cs%path, err)
      if (.not. has_error(err)) call channels_parse(cs%s, cs%path, cs%s%info%outputs, &
                                                    cs%s%info%output_line, cs%ch, err)
      cs%write_units = cs%s%info%write_units
      if (has_error(err)) then
         write (error_unit, '(a)') err%message
         deallocate (cs)
         return
      end if
      allocate (cs%lines(size(cs%s%model%lines)), cs%points(cs%s%n_points), &
                cs%bodies(cs%s%n_bodies), cs%rods(size(cs%s%info%rod_nodes)))
      do k = 1, size(cs%bodies)
         cs%bodies(k)%sys => cs
         cs%bodies(k)%index = k
      end do
      do k = 1, size(cs%rods)
         cs%rods(k)%sys => cs
         cs%rods(k)%index = k
      end do
      do k = 1, size(cs%lines)
         cs%lines(k)%sys => cs
         cs%lines(k)%index = k
      end do
      do k = 1, size(cs%points)
         cs%points(k)%sys => cs
         cs%points(k)%index = k
      end do
      h = c_loc(cs)
   end function md_create

   !> MoorDyn_NCoupledDOF: 6 a coupled body, 3 a coupled point.
   function md_ncoupled(h, n) result(code) bind(c, name='MoorDyn_NCoupledDOF')
      type(c_ptr), value :: h               !< system
      integer(c_int), intent(out) :: n      !< unsigned int*
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      n = 0
      n = int(system_ndof(cs%s), c_int)
      code = md_success
   end function md_ncoupled

   !> MoorDyn_SetVerbosity, MoorDyn_SetLogLevel: accepted (rodyn writes errors only).
   function md_verbosity(h, v) result(code) bind(c, name='MoorDyn_SetVerbosity')
      type(c_ptr), value :: h               !< system
      integer(c_int), value :: v            !< level
      integer(c_int) :: code
      code = merge(md_success, md_invalid_value, c_associated(h) .and. v >= 0)
   end function md_verbosity

   function md_log_level(h, v) result(code) bind(c, name='MoorDyn_SetLogLevel')
      type(c_ptr), value :: h               !< system
      integer(c_int), value :: v            !< level
      integer(c_int) :: code
      code = md_verbosity(h, v)
   end function md_log_level

   !> MoorDyn_Init: the coupled points at x, the statics solved (MoorDyn's initial
   !> condition), the dynamics set up at t = 0.
   function md_init(h, x, xd) result(code) bind(c, name='MoorDyn_Init')
      type(c_ptr), value :: h               !< system
      type(c_ptr), value :: x, xd           !< const double* (the coupled DOFs)
      integer(c_int) :: code
      code = init_system(h, x, xd, .false.)
   end function md_init

   !> MoorDyn_Init_NoIC: as MoorDyn_Init without the statics: the dynamics start at rest
   !> from the lines' starting shapes (catenaries between their ends' points, docs/
   !> systems.md), the free points and bodies where the file puts them.
   function md_init_noic(h, x, xd) result(code) bind(c, name='MoorDyn_Init_NoIC')
      type(c_ptr), value :: h               !< system
      type(c_ptr), value :: x, xd           !< const double* (the coupled DOFs)
      integer(c_int) :: code
      code = init_system(h, x, xd, .true.)
   end function md_init_noic

   !> The system of h initialised at x (the velocities xd are not used: a run starts at
   !> rest; MoorDyn asks for both), with or without the statics; FILE.out opened.
   function init_system(h, x, xd, no_statics) result(code)
      type(c_ptr), intent(in) :: h          !< system
      type(c_ptr), intent(in) :: x, xd      !< const double* (the coupled DOFs)
      logical, intent(in) :: no_statics     !< start from the starting shapes
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      real(c_double), pointer :: xp(:)
      type(error_t) :: err
      integer :: n
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      if (cs%s%stage /= 0) return
      n = system_ndof(cs%s)
      if (n > 0 .and. .not. (c_associated(x) .and. c_associated(xd))) return
      if (n > 0) then
         call c_f_pointer(x, xp, [n])
         call system_init(cs%s, real(xp, wp), err, no_statics)
      else
         call system_init(cs%s, [real(wp) ::], err, no_statics)
      end if
      if (size(cs%ch) > 0 .and. .not. has_error(err)) then
         call out_open(cs%out, cs%path, cs%ch, cs%write_units, err)
         if (.not. has_error(err)) call out_row(cs%out, cs%s, cs%ch, err)
      end if
      code = code_of(err)
   end function init_system

   !> MoorDyn_Step: from *t with the coupled points from x at velocities xd, *dt on;
   !> f the lines' forces on them at the end, *t advanced.
   function md_step(h, x, xd, f, t, dt) result(code) bind(c, name='MoorDyn_Step')
      type(c_ptr), value :: h               !< system
      type(c_ptr), value :: x, xd, f        !< const double*, const double*, double*
      real(c_double), intent(inout) :: t    !< time [s]
      real(c_double), intent(inout) :: dt   !< coupling step [s]
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      real(c_double), pointer :: xp(:), xdp(:), fp(:)
      real(wp), allocatable :: fw(:)
      type(error_t) :: err
      integer :: n
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      if (cs%s%stage /= 1) return
      n = system_ndof(cs%s)
      allocate (fw(n))
      if (n > 0) then
         if (.not. (c_associated(x) .and. c_associated(xd) .and. c_associated(f))) return
         call c_f_pointer(x, xp, [n])
         call c_f_pointer(xd, xdp, [n])
         call c_f_pointer(f, fp, [n])
         call system_step(cs%s, real(xp, wp), real(xdp, wp), real(dt, wp), fw, err)
         fp = real(fw, c_double)
      else
         call system_step(cs%s, [real(wp) ::], [real(wp) ::], real(dt, wp), fw, err)
      end if
      if (size(cs%ch) > 0 .and. dt > 0.0_c_double .and. .not. has_error(err)) &
         call out_row(cs%out, cs%s, cs%ch, err)
      code = code_of(err)
      if (code == md_success) t = real(cs%s%t, c_double)
   end function md_step

   !> MoorDyn_BreakLine: the line leaves the point at the start of the next step (the end
   !> then free: no new point is made, as MoorDyn makes one of no mass). Handles of
   !> another system, or a line not on the point: MOORDYN_INVALID_VALUE or _INPUT.
   function md_break_line(h, p, l) result(code) bind(c, name='MoorDyn_BreakLine')
      type(c_ptr), value :: h, p, l         !< system, point, line
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      type(capi_item_t), pointer :: ip, il
      type(error_t) :: err
      cs => system_of(h)
      ip => item_of(p)
      il => item_of(l)
      code = md_invalid_value
      if (.not. (associated(cs) .and. associated(ip) .and. associated(il))) return
      if (.not. (associated(ip%sys, cs) .and. associated(il%sys, cs))) return
      if (ip%index > size(cs%points) .or. il%index > size(cs%lines)) return
      if (.not. (associated(ip, cs%points(ip%index)) .and. &
                 associated(il, cs%lines(il%index)))) return
      call system_break(cs%s, ip%index, il%index, err)
      code = code_of(err)
   end function md_break_line

   !> MoorDyn_Close: the system freed.
   function md_close(h) result(code) bind(c, name='MoorDyn_Close')
      type(c_ptr), value :: h               !< system
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      type(error_t) :: err
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      if (size(cs%ch) > 0) call out_close(cs%out, err)
      code = code_of(err)
      deallocate (cs)
   end function md_close

   !> MoorDyn's code of an error_t: bad input, a numerical failure, else success; the
   !> message on stderr.
   integer(c_int) function code_of(err) result(code)
      type(error_t), intent(in) :: err      !< status
      code = md_success
      if (.not. has_error(err)) return
      write (error_unit, '(a)') 'rodyn: error: '//err%message
      code = md_nan_error
      if (err%code == stat_input) code = md_invalid_input
      if (err%code == stat_io) code = md_invalid_output_file
   end function code_of

   !> MoorDyn_GetNumberLines, _GetNumberPoints, _GetNumberBodies, _GetNumberRods.
   function md_nlines(h, n) result(code) bind(c, name='MoorDyn_GetNumberLines')
      type(c_ptr), value :: h               !< system
      integer(c_int), intent(out) :: n      !< unsigned int*
      integer(c_int) :: code
      code = count_of(h, 1, n)
   end function md_nlines

   function md_npoints(h, n) result(code) bind(c, name='MoorDyn_GetNumberPoints')
      type(c_ptr), value :: h               !< system
      integer(c_int), intent(out) :: n      !< unsigned int*
      integer(c_int) :: code
      code = count_of(h, 2, n)
   end function md_npoints

   function md_nbodies(h, n) result(code) bind(c, name='MoorDyn_GetNumberBodies')
      type(c_ptr), value :: h               !< system
      integer(c_int), intent(out) :: n      !< unsigned int*
      integer(c_int) :: code
      code = count_of(h, 3, n)
   end function md_nbodies

   function md_nrods(h, n) result(code) bind(c, name='MoorDyn_GetNumberRods')
      type(c_ptr), value :: h               !< system
      integer(c_int), intent(out) :: n      !< unsigned int*
      integer(c_int) :: code
      code = count_of(h, 4, n)
   end function md_nrods

   !> The number of lines, points or bodies of a system.
   function count_of(h, kind, n) result(code)
      type(c_ptr), intent(in) :: h          !< system
      integer, intent(in) :: kind           !< 1 lines, 2 points, 3 bodies, 4 rods
      integer(c_int), intent(out) :: n      !< how many
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      n = 0
      n = int(count_items(cs, kind), c_int)
      code = md_success
   end function count_of

   !> MoorDyn_GetLine, MoorDyn_GetPoint: the handle of line (point) ID l, from 1; NULL
   !> when there is none.
   type(c_ptr) function md_get_line(h, l) bind(c, name='MoorDyn_GetLine')
      type(c_ptr), value :: h               !< system
      integer(c_int), value :: l            !< unsigned int ID
      md_get_line = handle(h, l, 1)
   end function md_get_line

   type(c_ptr) function md_get_point(h, c) bind(c, name='MoorDyn_GetPoint')
      type(c_ptr), value :: h               !< system
      integer(c_int), value :: c            !< unsigned int ID
      md_get_point = handle(h, c, 2)
   end function md_get_point

   type(c_ptr) function md_get_body(h, b) bind(c, name='MoorDyn_GetBody')
      type(c_ptr), value :: h               !< system
      integer(c_int), value :: b            !< unsigned int ID
      md_get_body = handle(h, b, 3)
   end function md_get_body

   type(c_ptr) function md_get_rod(h, r) bind(c, name='MoorDyn_GetRod')
      type(c_ptr), value :: h               !< system
      integer(c_int), value :: r            !< unsigned int ID
      md_get_rod = handle(h, r, 4)
   end function md_get_rod

   !> The number of lines (kind 1), points (2), bodies (3) or rods (4) of a system.
   pure integer function count_items(cs, kind) result(n)
      type(capi_system_t), intent(in) :: cs !< the system
      integer, intent(in) :: kind           !< which
      select case (kind)
      case (1)
         n = size(cs%lines)
      case (2)
         n = size(cs%points)
      case (3)
         n = size(cs%bodies)
      case default
         n = size(cs%rods)
      end select
   end function count_items

   !> The handle of line, point or body k of a system (NULL, and a message, when there is
   !> none).
   function handle(h, k, kind) result(item)
      type(c_ptr), intent(in) :: h          !< system
      integer(c_int), intent(in) :: k       !< ID, from 1
      integer, intent(in) :: kind           !< 1 a line, 2 a point, 3 a body, 4 a rod
      type(c_ptr) :: item
      character(len=5), parameter :: what(4) = ['line ', 'point', 'body ', 'rod  ']
      type(capi_system_t), pointer :: cs
      integer :: n
      item = c_null_ptr
      cs => system_of(h)
      if (.not. associated(cs)) return
      n = count_items(cs, kind)
      if (k >= 1 .and. k <= n) then
         if (kind == 1) item = c_loc(cs%lines(k))
         if (kind == 2) item = c_loc(cs%points(k))
         if (kind == 3) item = c_loc(cs%bodies(k))
         if (kind == 4) item = c_loc(cs%rods(k))
      else
         write (error_unit, '(a,i0)') 'Error: There is not such '//trim(what(kind))//' ', k
      end if
   end function handle
end module rodyn_capi
