!> The output folder of a run: created (with its parents), locked for the run, and
!> cleared of the temporaries a killed run left (docs/output.md, "One run per folder").
!>
!> The lock is the file '<dir>/.rodyn.lock', created with O_EXCL (Fortran
!> status='new'), holding the process id and the host name of the run. A second run
!> finds it and is refused. A lock whose process is gone (same host, kill(pid, 0) says
!> no such process) is stale and taken over. The program removes its lock on every way
!> out (rodyn_main's finish).
module rodyn_outdir
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_size_t, c_ptr, c_null_char, &
      c_associated
   use rodyn_error, only: error_t, set_error, has_error, stat_io
   use rodyn_outfile, only: path_join, out_file_t, outfile_create, outfile_put, outfile_commit, &
      temp_name, remove_file, system_errno, path_prefixes
   use rodyn_format, only: int_text
   implicit none
   private
   public :: outdir_lock_t, outdir_make, outdir_lock, outdir_unlock, lock_name, temp_files

   character(len=*), parameter :: lock_name = '.rodyn.lock'   !< the lock file's name
   !> Files written whole through a temporary '.<name>.tmp' (cleaned by outdir_lock).
   character(len=*), parameter :: temp_files(*) = [character(len=20) :: 'status.txt', &
      'static_nodes.csv', 'static_elements.csv', 'static_reactions.csv', &
      'static_lines.csv', 'environment.csv', 'results.h5', 'dynamic.h5', &
      'checkpoint.h5', lock_name]
   integer(c_int), parameter :: esrch = 3   !< errno: no such process (Linux)

   !> A lock held on an output folder (path allocated while held).
   type :: outdir_lock_t
      character(len=:), allocatable :: path   !< the lock file
   end type outdir_lock_t

   interface
      !> POSIX mkdir(2).
      function c_mkdir(path, mode) bind(c, name='mkdir') result(r)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*) !< NUL-terminated path
         integer(c_int), value :: mode                 !< permissions (before umask)
         integer(c_int) :: r                           !< 0, or -1 on failure
      end function c_mkdir
      !> POSIX opendir(3), used to check that a folder exists.
      function c_opendir(path) bind(c, name='opendir') result(d)
         import :: c_char, c_ptr
         character(kind=c_char), intent(in) :: path(*) !< NUL-terminated path
         type(c_ptr) :: d                              !< DIR *, null on failure
      end function c_opendir
      !> POSIX closedir(3).
      function c_closedir(d) bind(c, name='closedir') result(r)
         import :: c_ptr, c_int
         type(c_ptr), value :: d                       !< DIR * from c_opendir
         integer(c_int) :: r                           !< 0, or -1 on failure
      end function c_closedir
      !> POSIX getpid(2).
      function c_getpid() bind(c, name='getpid') result(pid)
         import :: c_int
         integer(c_int) :: pid                         !< this process
      end function c_getpid
      !> POSIX kill(2) (signal 0: only whether the process exists).
      function c_kill(pid, sig) bind(c, name='kill') result(r)
         import :: c_int
         integer(c_int), value :: pid                  !< process
         integer(c_int), value :: sig                  !< signal
         integer(c_int) :: r                           !< 0, or -1 (errno)
      end function c_kill
      !> POSIX gethostname(2).
      function c_gethostname(name, n) bind(c, name='gethostname') result(r)
         import :: c_char, c_int, c_size_t
         character(kind=c_char), intent(out) :: name(*) !< NUL-terminated host name
         integer(c_size_t), value :: n                  !< room in name
         integer(c_int) :: r                            !< 0, or -1
      end function c_gethostname
   end interface

contains

   !> Create folder `dir` and its parents (mkdir per path component), then check it.
   subroutine outdir_make(dir, err)
      character(len=*), intent(in) :: dir !< folder path ('' means '.')
      type(error_t), intent(inout) :: err !< status
      integer(c_int), parameter :: mode = int(o'777', c_int)
      character(len=:), allocatable :: d
      type(c_ptr) :: handle
      integer :: k
      integer(c_int) :: r
      d = trim(dir)
      if (len(d) == 0) d = '.'
      associate (ends => path_prefixes(d))
         do k = 1, size(ends)
            r = c_mkdir(d(:ends(k))//c_null_char, mode)  ! fails harmlessly when it exists
         end do
      end associate
      handle = c_opendir(d//c_null_char)
      if (.not. c_associated(handle)) then
         call set_error(err, stat_io, 'output: cannot create folder '''//d//'''')
         return
      end if
      r = c_closedir(handle)
   end subroutine outdir_make

   !> Make folder `dir`, take its lock for this run, and remove the temporaries an
   !> earlier (killed) run left. Refused with stat_io, naming the other run, when a live
   !> run holds the folder.
   subroutine outdir_lock(dir, lock, err)
      character(len=*), intent(in) :: dir          !< output folder
      type(outdir_lock_t), intent(inout) :: lock   !< the lock (held on success)
      type(error_t), intent(inout) :: err          !< status
      character(len=:), allocatable :: path, d, owner_host
      integer :: attempt, ios, u, k, owner_pid
      logical :: stale
      type(error_t) :: e
      if (has_error(err)) return
      call outdir_make(dir, err)
      if (has_error(err)) return
      d = trim(dir)
      if (len(d) == 0) d = '.'
      path = path_join(d, lock_name)
      do attempt = 1, 3
         open (newunit=u, file=path, status='new', action='write', iostat=ios)
         if (ios == 0) then
            close (u)
            lock%path = path
            call write_owner(d, e)
            if (has_error(e)) then
               call outdir_unlock(lock)
               call set_error(err, stat_io, 'output: cannot lock folder '''//d//''': '// &
                  e%message)
               return
            end if
            do k = 1, size(temp_files) - 1
               call remove_file(temp_name(d, trim(temp_files(k))))
            end do
            return
         end if
         call read_owner(path, owner_pid, owner_host)
         stale = owner_pid > 0 .and. owner_host == host_name()
         if (stale) stale = c_kill(int(owner_pid, c_int), 0_c_int) /= 0
         if (stale) stale = system_errno() == esrch
         if (.not. stale) exit
         call remove_file(path)     ! the run that held it is gone: take it over
      end do
      if (owner_pid > 0) then
         call set_error(err, stat_io, 'output folder '''//d//''' is in use by another '// &
            'rodyn run (process '//int_text(owner_pid)//' on '//owner_host// &
            '); run into another folder (-o DIR), or remove '''//path// &
            ''' if that run is gone')
      else
         call set_error(err, stat_io, 'output folder '''//d//''' is in use by another '// &
            'rodyn run (lock file '''//path//''' without a process id); run into '// &
            'another folder (-o DIR), or remove that file if no run is using the folder')
      end if
   end subroutine outdir_lock

   !> Give the lock up (remove the lock file); nothing when not held.
   subroutine outdir_unlock(lock)
      type(outdir_lock_t), intent(inout) :: lock   !< the lock
      if (.not. allocated(lock%path)) return
      call remove_file(lock%path)
      deallocate (lock%path)
   end subroutine outdir_unlock

   ! ------------------------------------------------------------------ internals

   !> Write 'pid host' into the lock file (created empty by outdir_lock).
   subroutine write_owner(d, err)
      character(len=*), intent(in) :: d        !< folder
      type(error_t), intent(inout) :: err      !< status
      type(out_file_t) :: f
      ! written through a temporary and renamed over the empty lock: never half-written
      call outfile_create(f, d, lock_name, err)
      if (has_error(err)) return
      call outfile_put(f, int_text(int(c_getpid()))//' '//host_name())
      call outfile_commit(f, err)
   end subroutine write_owner

   !> Process id and host of a lock file; pid 0 when it cannot be read.
   subroutine read_owner(path, pid, host)
      character(len=*), intent(in) :: path                !< lock file
      integer, intent(out) :: pid                         !< owner's process id
      character(len=:), allocatable, intent(out) :: host  !< owner's host
      character(len=512) :: line
      integer :: u, ios, k
      pid = 0
      host = '?'
      open (newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) return
      read (u, '(a)', iostat=ios) line
      close (u)
      if (ios /= 0) return
      line = adjustl(line)
      k = index(line, ' ')
      read (line(:k), *, iostat=ios) pid
      if (ios /= 0) pid = 0
      host = trim(adjustl(line(k:)))
   end subroutine read_owner

   !> This machine's host name.
   function host_name() result(s)
      character(len=:), allocatable :: s  !< host name ('?' when unknown)
      character(kind=c_char, len=256) :: buf
      integer :: k
      buf = ''
      if (c_gethostname(buf, int(len(buf) - 1, c_size_t)) /= 0) then
         s = '?'
         return
      end if
      k = index(buf, c_null_char)
      if (k == 0) k = len(buf) + 1
      s = buf(:k - 1)
   end function host_name

end module rodyn_outdir
