!> A host's saved state (MoorDyn_Save, MoorDyn_Load of MoorDyn2.h; docs/capi.md): the
!> dynamics of a system between two coupling steps, written to one HDF5 file as the
!> program's checkpoint (rodyn_checkpoint: the time loop, the state at t_n, the last
!> step's support forces, the dissipative scheme's histories) with what the host
!> observer carries (the last three steps' support forces, rodyn_capi_system's
!> support_forces), the host's time, last rates and where each coupled point and body
!> was moved to. A system created from the same file and initialised as the saving one
!> was (MoorDyn_Init, or MoorDyn_Init_NoIC: the dissipative scheme's reference stiffness
!> comes from the start state) loads it and then steps as the saving system does, to the
!> bit: both form their next tangent anew. Refused: another start state, a line broken,
!> water kinematics from the host.
module rodyn_capi_save
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int
   use, intrinsic :: iso_fortran_env, only: error_unit
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error, set_error, stat_input
   use rodyn_hdf5, only: hdf5_file_t, hdf5_open_file, hdf5_close_file, hdf5_write_dataset, &
                         hdf5_read_dataset
   use rodyn_checkpoint, only: checkpoint_t, checkpoint_write, checkpoint_read, &
                               checkpoint_program_id, checkpoint_problem
   use rodyn_capi_system, only: md_system_t, system_ndof
   use rodyn_capi_handles, only: capi_system_t, system_of, f_string, md_success, &
                                 md_invalid_value, md_unhandled
   implicit none
   private

contains

   !> MoorDyn_Save: the system's state after its last step, to the file at path.
   function md_save(h, path) result(code) bind(c, name='MoorDyn_Save')
      type(c_ptr), value :: h               !< system
      type(c_ptr), value :: path            !< file to write (a C string)
      integer(c_int) :: code
      code = on_file(h, path, .true.)
   end function md_save

   !> MoorDyn_Load: the state a system of the same file saved, into this one.
   function md_load(h, path) result(code) bind(c, name='MoorDyn_Load')
      type(c_ptr), value :: h               !< system
      type(c_ptr), value :: path            !< file to read (a C string)
      integer(c_int) :: code
      code = on_file(h, path, .false.)
   end function md_load

   !> system_save (save) or system_load of system h with the file at path: MoorDyn's
   !> code, the error on stderr.
   integer(c_int) function on_file(h, path, save) result(code)
      type(c_ptr), intent(in) :: h          !< system
      type(c_ptr), intent(in) :: path       !< file (a C string)
      logical, intent(in) :: save           !< save, else load
      type(capi_system_t), pointer :: cs
      type(error_t) :: err
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      if (save) then
         call system_save(cs%s, f_string(path), err)
         code = outcome(err, 'MoorDyn_Save')
      else
         call system_load(cs%s, f_string(path), err)
         code = outcome(err, 'MoorDyn_Load')
      end if
   end function on_file

   !> MOORDYN_SUCCESS, or the error on stderr and MOORDYN_UNHANDLED_ERROR.
   integer(c_int) function outcome(err, what) result(code)
      type(error_t), intent(in) :: err      !< status
      character(len=*), intent(in) :: what  !< the function
      code = md_success
      if (.not. has_error(err)) return
      write (error_unit, '(a)') 'rodyn: error: '//what//': '//err%message
      code = md_unhandled
   end function outcome

   !> Refused (err): a system not initialised, a line broken, the host's water.
   subroutine check_savable(sys, err)
      type(md_system_t), intent(in) :: sys  !< the system
      type(error_t), intent(inout) :: err   !< status
      if (sys%stage /= 1) then
         call set_error(err, stat_input, 'the system is not initialised, or its last '// &
                        'step failed')
      else if (sys%prob%fl%n > 0) then
         call set_error(err, stat_input, 'a system with line failures (MoorDyn_BreakLine, '// &
                        '*FAILURE) is not saved')
      else if (sys%info%external_waves) then
         call set_error(err, stat_input, 'a system whose water kinematics the host gives '// &
                        '(WaveKin 1) is not saved')
      end if
   end subroutine check_savable

   !> Write the state (module header) to path.
   subroutine system_save(sys, path, err)
      type(md_system_t), intent(inout), target :: sys !< the system
      character(len=*), intent(in) :: path            !< file to write
      type(error_t), intent(inout) :: err             !< status
      type(checkpoint_t) :: ck
      type(hdf5_file_t) :: h5
      type(error_t) :: e
      integer :: nn
      call check_savable(sys, err)
      if (has_error(err)) return
      associate (p => sys%prob, o => sys%obs)
         nn = size(p%r, 2)
         ck%loop = sys%ls
         ck%summary = sys%summary
         ck%start = sys%state                ! (the iterate's shape: its positions at t = 0)
         ck%start%x = p%x_start
         call checkpoint_problem(p, ck, .true.)
         allocate (ck%pend%r_pend(6, nn), ck%pend%r_back(6, nn))
         ck%pend%r_pend = 0.0_wp
         ck%pend%r_back = 0.0_wp
         call checkpoint_write(folder(path), sys%model, checkpoint_program_id(), ck, err, &
                               base_name(path))
         if (has_error(err)) return
         call hdf5_open_file(h5, path, e, writable=.true.)
         call hdf5_write_dataset(h5, '/host_reals', [sys%t, sys%dt_max, o%h_last, &
                                                     o%h_back, o%h_back2], e)
         call hdf5_write_dataset(h5, '/host_flags', [merge(1, 0, o%have_last), &
                                 merge(1, 0, o%have_back), merge(1, 0, o%have_back2)], e)
         call hdf5_write_dataset(h5, '/host_r', reshape(forces(), [6, 3*nn]), e)
         call hdf5_write_dataset(h5, '/host_xd', [last_rates(), 0.0_wp], e)
         call hdf5_write_dataset(h5, '/host_moved', moved(sys), e)
         call hdf5_close_file(h5, e)
      end associate
      if (has_error(e)) call set_error(err, stat_input, 'cannot write '''//path//''': '// &
                                       e%message)
      ! the saving system forms its next tangent anew, as the loading one will
      sys%prob%factors_ok = .false.
      sys%prob%renew_first = .false.
   contains
      !> The coupled DOFs' rates of the last step (zero before the first).
      function last_rates() result(xd)
         real(wp) :: xd(system_ndof(sys))
         xd = 0.0_wp
         if (allocated(sys%xd_last)) xd = sys%xd_last
      end function last_rates

      !> The last three steps' support forces, side by side (zero where not yet set).
      function forces() result(r)
         real(wp) :: r(6, nn, 3)
         r = 0.0_wp
         if (sys%obs%have_last) r(:, :, 1) = sys%obs%r_last
         if (sys%obs%have_back) r(:, :, 2) = sys%obs%r_back
         if (sys%obs%have_back2) r(:, :, 3) = sys%obs%r_back2
      end function forces
   end subroutine system_save

   !> Where each coupled body (6: its vessel's motion) and point (3: its table's
   !> displacement) was moved to at sys%t, in one column each.
   function moved(sys) result(q)
      type(md_system_t), intent(in) :: sys  !< the system
      real(wp), allocatable :: q(:, :)      !< (6, bodies + points)
      integer :: i, nb
      nb = size(sys%cbody)
      allocate (q(6, nb + size(sys%coupled)))
      q = 0.0_wp
      do i = 1, nb
         associate (ve => sys%prob%vessels(sys%cvessel(i)))
            q(:, i) = ve%motion(:, size(ve%time))
         end associate
      end do
      do i = 1, size(sys%coupled)
         associate (mo => sys%model%motions(sys%motion(i)))
            q(1:3, nb + i) = mo%disp(:, size(mo%time))
         end associate
      end do
   end function moved

   !> Read the state (module header) from path into an initialised system of the same
   !> file.
   subroutine system_load(sys, path, err)
      type(md_system_t), intent(inout), target :: sys !< the system
      character(len=*), intent(in) :: path            !< file to read
      type(error_t), intent(inout) :: err             !< status
      type(checkpoint_t) :: ck
      type(hdf5_file_t) :: h5
      type(error_t) :: e
      real(wp), allocatable :: reals(:), r(:, :), xd(:), q(:, :)
      integer, allocatable :: flags(:)
      integer :: nn
      call check_savable(sys, err)
      if (has_error(err)) return
      call checkpoint_read(folder(path), sys%model, sys%prob%s1, ck, err, base_name(path))
      if (has_error(err)) then
         err%message = 'not a state of this system: '//err%message
         return
      end if
      call hdf5_open_file(h5, path, e)
      call hdf5_read_dataset(h5, '/host_reals', reals, e)
      call hdf5_read_dataset(h5, '/host_flags', flags, e)
      call hdf5_read_dataset(h5, '/host_r', r, e)
      call hdf5_read_dataset(h5, '/host_xd', xd, e)
      call hdf5_read_dataset(h5, '/host_moved', q, e)
      call hdf5_close_file(h5, e)
      nn = size(sys%prob%r, 2)
      if (.not. has_error(e)) then
         if (size(reals) /= 5 .or. size(flags) /= 3 .or. size(r, 2) /= 3*nn .or. &
             size(xd) /= system_ndof(sys) + 1 .or. size(q, 2) /= &
             size(sys%cbody) + size(sys%coupled)) call set_error(e, stat_input, 'wrong sizes')
      end if
      if (has_error(e)) then
         call set_error(err, stat_input, ''''//path//''' is not a state MoorDyn_Save '// &
                        'wrote of this system: '//e%message)
         return
      end if
      if (any(sys%prob%x_start /= ck%start%x)) then
         call set_error(err, stat_input, 'the saving system started from another state: '// &
                        'initialise this one as it was (MoorDyn_Init, or MoorDyn_Init_NoIC) '// &
                        'before MoorDyn_Load')
         return
      end if
      call restore_problem(sys, ck)
      sys%t = reals(1)
      sys%dt_max = reals(2)
      sys%obs%h_last = reals(3)
      sys%obs%h_back = reals(4)
      sys%obs%h_back2 = reals(5)
      sys%obs%have_last = flags(1) == 1
      sys%obs%have_back = flags(2) == 1
      sys%obs%have_back2 = flags(3) == 1
      sys%obs%r_last = r(:, 1:nn)
      sys%obs%r_back = r(:, nn + 1:2*nn)
      sys%obs%r_back2 = r(:, 2*nn + 1:3*nn)
      sys%xd_last = xd(1:system_ndof(sys))
      call restore_moved(sys, q)
   end subroutine system_load

   !> The problem's state, last step and time loop from ck; its next tangent formed anew
   !> and its rods' fields formed again from the state.
   subroutine restore_problem(sys, ck)
      type(md_system_t), intent(inout), target :: sys !< the system
      type(checkpoint_t), intent(in) :: ck            !< the saved checkpoint
      type(checkpoint_t) :: c
      c = ck
      call checkpoint_problem(sys%prob, c, .false.)
      sys%prob%factors_ok = .false.
      sys%prob%renew_first = .false.
      sys%prob%fields_next = .false.
      sys%ls = ck%loop
      sys%summary = ck%summary
   end subroutine restore_problem

   !> Each coupled body's vessel and point's table from where it was moved to at sys%t.
   subroutine restore_moved(sys, q)
      type(md_system_t), intent(inout), target :: sys !< the system
      real(wp), intent(in) :: q(:, :)                 !< (6, bodies + points)
      integer :: i, nb
      nb = size(sys%cbody)
      do i = 1, nb
         associate (ve => sys%prob%vessels(sys%cvessel(i)))
            ve%time = [sys%t]
            ve%motion = reshape(q(:, i), [6, 1])
         end associate
      end do
      do i = 1, size(sys%coupled)
         associate (mo => sys%model%motions(sys%motion(i)))
            mo%time = [sys%t]
            mo%disp = reshape(q(1:3, nb + i), [3, 1])
         end associate
      end do
   end subroutine restore_moved

   !> The folder of a path ('' for a bare name).
   pure function folder(path) result(dir)
      character(len=*), intent(in) :: path   !< file path
      character(len=:), allocatable :: dir
      integer :: k
      k = index(path, '/', back=.true.)
      dir = path(1:max(k - 1, 0))
      if (k == 1) dir = '/'
   end function folder

   !> The file name of a path.
   pure function base_name(path) result(name)
      character(len=*), intent(in) :: path   !< file path
      character(len=:), allocatable :: name
      name = path(index(path, '/', back=.true.) + 1:)
   end function base_name
end module rodyn_capi_save
