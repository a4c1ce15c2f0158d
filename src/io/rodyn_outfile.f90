!> Checked output files: the one place where rodyn's text outputs reach the disk.
!>
!> Every byte goes to the operating system through write(2), whose result is checked,
!> and every file is closed with close(2), checked. (Fortran I/O cannot be trusted for
!> this: gfortran 12 reports iostat = 0 on WRITE, FLUSH and CLOSE of a file on a full
!> disk while the data are lost.) A failure is reported with the file's final name and
!> the system's reason ('No space left on device').
!>
!> Two kinds of file:
!> - written whole (`outfile_create` without `live`): the text goes to a hidden
!>   temporary '<dir>/.<name>.tmp', and `outfile_commit` renames it to '<dir>/<name>'
!>   only after everything was written and the file closed without error. On failure
!>   the temporary is removed, and so is an older '<dir>/<name>' (no file of another
!>   run, or an incomplete one, stands under the final name next to this run's status).
!> - live (`live = .true.`, the tables of a dynamic run): written under the final name
!>   and grown while the run goes. `outfile_mark` records the end of the last whole
!>   group of rows (a frame); `outfile_close` after a failure cuts the file back to that
!>   mark (removes it when not even the header was written), so the file always ends
!>   with a whole frame.
!> Text is held in the file's buffer and handed to the system when the buffer is full
!> (a whole file) or at `outfile_flush` (a live file: nothing is written in between).
module rodyn_outfile
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_long, c_size_t, c_ptr, &
      c_null_char, c_f_pointer, c_associated
   use rodyn_kinds, only: i8
   use rodyn_error, only: error_t, set_error, stat_io
   implicit none
   private
   public :: out_file_t, outfile_create, outfile_put, outfile_flush, outfile_mark
   public :: outfile_commit, outfile_close, outfile_abort, outfile_pending
   public :: outfile_reopen, outfile_size, outfile_committed
   public :: temp_name, commit_rename, remove_file, system_error, system_errno, path_join
   public :: text_or, path_prefixes

   integer, parameter :: chunk = 65536   !< buffer of a whole file, written when full

   !> One output file being written.
   type :: out_file_t
      integer(c_int) :: fd = -1                  !< file descriptor (< 0: not open)
      logical :: live = .false.                  !< written under its final name
      character(len=:), allocatable :: path      !< file written (temporary or final)
      character(len=:), allocatable :: final     !< final name, for messages
      character(len=:), allocatable :: buf       !< text not yet written
      integer :: n = 0                           !< characters used in buf
      integer(i8) :: written = 0_i8              !< bytes handed to the system
      integer(i8) :: good = 0_i8                 !< bytes at the last outfile_mark
      logical :: failed = .false.                !< a write or close failed
      character(len=:), allocatable :: why       !< the first failure
   end type out_file_t

   interface
      !> POSIX creat(2): create or truncate a file for writing.
      function c_creat(path, mode) bind(c, name='creat') result(fd)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*) !< NUL-terminated path
         integer(c_int), value :: mode                 !< permissions (before umask)
         integer(c_int) :: fd                          !< descriptor, or -1
      end function c_creat
      !> POSIX write(2).
      function c_write(fd, buf, n) bind(c, name='write') result(r)
         import :: c_char, c_int, c_size_t, c_long
         integer(c_int), value :: fd                   !< descriptor
         character(kind=c_char), intent(in) :: buf(*)  !< bytes
         integer(c_size_t), value :: n                 !< how many
         integer(c_long) :: r                          !< bytes written, or -1
      end function c_write
      !> open(2) without a mode (no O_CREAT).
      function c_open(path, flags) bind(c, name='open') result(fd)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*) !< NUL-terminated path
         integer(c_int), value :: flags                !< O_* flags
         integer(c_int) :: fd                          !< descriptor, or -1
      end function c_open
      !> lseek(2).
      function c_lseek(fd, offset, whence) bind(c, name='lseek') result(r)
         import :: c_int, c_long
         integer(c_int), value :: fd                   !< descriptor
         integer(c_long), value :: offset              !< offset [bytes]
         integer(c_int), value :: whence               !< SEEK_SET (0), ...
         integer(c_long) :: r                          !< new offset, or -1
      end function c_lseek
      !> POSIX close(2).
      function c_close(fd) bind(c, name='close') result(r)
         import :: c_int
         integer(c_int), value :: fd                   !< descriptor
         integer(c_int) :: r                           !< 0, or -1
      end function c_close
      !> POSIX ftruncate(2) (off_t is a long on LP64 Linux).
      function c_ftruncate(fd, length) bind(c, name='ftruncate') result(r)
         import :: c_int, c_long
         integer(c_int), value :: fd                   !< descriptor
         integer(c_long), value :: length              !< new length [bytes]
         integer(c_int) :: r                           !< 0, or -1
      end function c_ftruncate
      !> C rename(3): atomic replacement within one file system.
      function c_rename(old, new) bind(c, name='rename') result(r)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: old(*)  !< NUL-terminated source
         character(kind=c_char), intent(in) :: new(*)  !< NUL-terminated destination
         integer(c_int) :: r                           !< 0, or -1
      end function c_rename
      !> C remove(3).
      function c_remove(path) bind(c, name='remove') result(r)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*) !< NUL-terminated path
         integer(c_int) :: r                           !< 0, or -1
      end function c_remove
      !> glibc's location of errno.
      function c_errno_location() bind(c, name='__errno_location') result(p)
         import :: c_ptr
         type(c_ptr) :: p                              !< int *
      end function c_errno_location
      !> C strerror(3).
      function c_strerror(errnum) bind(c, name='strerror') result(p)
         import :: c_int, c_ptr
         integer(c_int), value :: errnum               !< error number
         type(c_ptr) :: p                              !< char *, NUL-terminated
      end function c_strerror
   end interface

contains

   !> '<dir>/.<name>.tmp', the temporary name of a file written whole.
   pure function temp_name(dir, name) result(path)
      character(len=*), intent(in) :: dir   !< folder
      character(len=*), intent(in) :: name  !< final file name
      character(len=:), allocatable :: path !< temporary path
      path = path_join(dir, '.'//name//'.tmp')
   end function temp_name

   !> Create a file in `dir`: '<dir>/.<name>.tmp' to be committed, or with live true
   !> '<dir>/<name>' itself (truncated). On failure f%fd < 0 and err names the file.
   subroutine outfile_create(f, dir, name, err, live)
      type(out_file_t), intent(out) :: f          !< the file
      character(len=*), intent(in) :: dir         !< output folder (exists)
      character(len=*), intent(in) :: name        !< final file name
      type(error_t), intent(inout) :: err         !< status
      logical, intent(in), optional :: live       !< write under the final name
      f%live = .false.
      if (present(live)) f%live = live
      f%final = path_join(dir, name)
      if (f%live) then
         f%path = f%final
      else
         f%path = temp_name(dir, name)
      end if
      allocate (character(len=chunk) :: f%buf)
      f%fd = c_creat(f%path//c_null_char, int(o'666', c_int))
      if (f%fd < 0) then
         call fail(f, 'cannot create '''//f%path//''': '//system_error())
         call set_error(err, stat_io, f%why)
      end if
   end subroutine outfile_create

   !> Open the live file '<dir>/<name>' of an interrupted run again, cut back to its
   !> first `bytes` bytes (the rows of a checkpoint), to append to it. On failure (no
   !> such file, or a shorter one) f%fd < 0 and err names the file.
   subroutine outfile_reopen(f, dir, name, bytes, err)
      type(out_file_t), intent(out) :: f          !< the file
      character(len=*), intent(in) :: dir         !< output folder
      character(len=*), intent(in) :: name        !< file name
      integer(i8), intent(in) :: bytes            !< length kept [bytes]
      type(error_t), intent(inout) :: err         !< status
      integer(c_int), parameter :: o_wronly = 1_c_int   ! Linux <fcntl.h>
      f%live = .true.
      f%final = path_join(dir, name)
      f%path = f%final
      allocate (character(len=chunk) :: f%buf)
      if (outfile_size(f%path) < bytes) then
         call fail(f, 'cannot continue '''//f%path//''': missing, or shorter than at '// &
            'the checkpoint')
      else
         f%fd = c_open(f%path//c_null_char, o_wronly)
         if (f%fd < 0) then
            call fail(f, 'cannot open '''//f%path//''': '//system_error())
         else if (c_ftruncate(f%fd, int(bytes, c_long)) /= 0 .or. &
                  c_lseek(f%fd, int(bytes, c_long), 0_c_int) /= int(bytes, c_long)) then
            call fail(f, 'cannot cut back '''//f%path//''': '//system_error())
         end if
      end if
      if (f%failed) then
         call set_error(err, stat_io, f%why)
         return
      end if
      f%written = bytes
      f%good = bytes
   end subroutine outfile_reopen

   !> Size of a file [bytes]; -1 when it does not exist.
   function outfile_size(path) result(bytes)
      character(len=*), intent(in) :: path   !< file path
      integer(i8) :: bytes
      logical :: there
      inquire (file=path, exist=there, size=bytes)
      if (.not. there) bytes = -1_i8
   end function outfile_size

   !> Append one line (text and a line feed). A whole file's buffer is written when
   !> full; a live file's grows until outfile_flush. Failures are kept in f.
   subroutine outfile_put(f, text)
      type(out_file_t), intent(inout) :: f      !< open file
      character(len=*), intent(in) :: text      !< the line, without line feed
      integer :: need
      if (f%failed) return
      need = f%n + len(text) + 1
      if (need > len(f%buf)) then
         if (.not. f%live) call write_buffer(f)
         if (f%failed) return
         need = f%n + len(text) + 1
         if (need > len(f%buf)) call grow(f, need)
      end if
      f%buf(f%n + 1:f%n + len(text)) = text
      f%buf(need:need) = achar(10)
      f%n = need
   end subroutine outfile_put

   !> Characters held in the buffer, not yet handed to the system.
   pure integer function outfile_pending(f)
      type(out_file_t), intent(in) :: f  !< file
      outfile_pending = f%n
   end function outfile_pending

   !> Bytes of a live file at its last outfile_mark: what a reader may trust.
   pure function outfile_committed(f) result(bytes)
      type(out_file_t), intent(in) :: f  !< file
      integer(i8) :: bytes               !< bytes
      bytes = f%good
   end function outfile_committed

   !> Hand everything held to the system; a failure (now or before) is recorded in err.
   subroutine outfile_flush(f, err)
      type(out_file_t), intent(inout) :: f  !< open file
      type(error_t), intent(inout) :: err   !< status
      call write_buffer(f)
      if (f%failed) call set_error(err, stat_io, f%why)
   end subroutine outfile_flush

   !> Record that the file ends with a whole group of rows (after a successful flush).
   subroutine outfile_mark(f)
      type(out_file_t), intent(inout) :: f  !< open file
      if (.not. f%failed .and. f%n == 0) f%good = f%written
   end subroutine outfile_mark

   !> Finish a file written whole: write what is held, close, rename into place. On any
   !> failure the temporary and an older file of the final name are removed, and err
   !> names the file.
   subroutine outfile_commit(f, err)
      type(out_file_t), intent(inout) :: f  !< open file (closed on return)
      type(error_t), intent(inout) :: err   !< status
      type(error_t) :: e
      if (f%fd < 0 .and. .not. f%failed) return
      call write_buffer(f)
      call close_fd(f)
      if (.not. f%failed) call commit_rename(f%path, f%final, e)
      if (f%failed) then
         call remove_file(f%path)
         call remove_file(f%final)
         call set_error(err, stat_io, f%why)
      else if (e%code /= 0) then
         call set_error(err, e%code, e%message)
      end if
      if (allocated(f%buf)) deallocate (f%buf)
   end subroutine outfile_commit

   !> Close a live file: write what is held; after a failure (now or before) cut it back
   !> to its last mark, or remove it when nothing whole was marked. err gets the failure.
   subroutine outfile_close(f, err)
      type(out_file_t), intent(inout) :: f  !< file (closed on return)
      type(error_t), intent(inout) :: err   !< status
      if (f%fd < 0 .and. .not. f%failed) return
      if (f%fd >= 0) call write_buffer(f)
      call end_live(f)
      if (f%failed) call set_error(err, stat_io, f%why)
   end subroutine outfile_close

   !> Give a file up without writing what is held: a temporary is removed, a live file
   !> cut back to its last mark (removed when none). Nothing is reported.
   subroutine outfile_abort(f)
      type(out_file_t), intent(inout) :: f  !< file (closed on return)
      f%n = 0
      if (.not. allocated(f%path)) return
      if (f%live) then
         if (.not. f%failed) call fail(f, 'abandoned')
         call end_live(f)
      else
         if (f%fd >= 0) call close_fd(f)
         call remove_file(f%path)
      end if
   end subroutine outfile_abort

   !> Rename `tmp` to `final` (a file written whole); on failure remove the temporary
   !> and set err.
   subroutine commit_rename(tmp, final, err)
      character(len=*), intent(in) :: tmp     !< temporary path
      character(len=*), intent(in) :: final   !< final path
      type(error_t), intent(inout) :: err     !< status
      if (c_rename(tmp//c_null_char, final//c_null_char) == 0) return
      call set_error(err, stat_io, 'cannot rename '''//tmp//''' to '''//final//''': '// &
         system_error())
      call remove_file(tmp)
   end subroutine commit_rename

   !> Remove a file if it exists (errors ignored).
   subroutine remove_file(path)
      character(len=*), intent(in) :: path  !< file path
      integer(c_int) :: r
      r = c_remove(path//c_null_char)
   end subroutine remove_file

   !> The text of the current errno ('No space left on device').
   function system_error() result(s)
      character(len=:), allocatable :: s    !< strerror(errno)
      type(c_ptr) :: p
      character(kind=c_char), pointer :: chars(:)
      integer :: k
      p = c_strerror(system_errno())
      s = 'error '
      if (.not. c_associated(p)) return
      call c_f_pointer(p, chars, [256])
      s = ''
      do k = 1, 256
         if (chars(k) == c_null_char) exit
         s = s//chars(k)
      end do
   end function system_error

   !> The current errno.
   integer(c_int) function system_errno()
      integer(c_int), pointer :: p
      call c_f_pointer(c_errno_location(), p)
      system_errno = p
   end function system_errno

   ! ------------------------------------------------------------------ internals

   !> Write the buffer with write(2), looping over partial writes.
   subroutine write_buffer(f)
      type(out_file_t), intent(inout) :: f  !< file
      integer :: k
      integer(c_long) :: r
      if (f%failed .or. f%n == 0) return
      if (f%fd < 0) then
         call fail(f, 'cannot write '''//f%final//''': not open')
         return
      end if
      k = 0
      do while (k < f%n)
         r = c_write(f%fd, f%buf(k + 1:f%n), int(f%n - k, c_size_t))
         if (r <= 0) then
            call fail(f, 'cannot write '''//f%final//''': '//system_error())
            return
         end if
         k = k + int(r)
         f%written = f%written + int(r, i8)
      end do
      f%n = 0
   end subroutine write_buffer

   !> Close the descriptor, recording a failure.
   subroutine close_fd(f)
      type(out_file_t), intent(inout) :: f  !< file
      if (f%fd < 0) return
      if (c_close(f%fd) /= 0) call fail(f, 'cannot write '''//f%final//''': '// &
         system_error())
      f%fd = -1
   end subroutine close_fd

   !> Close a live file; after a failure cut it back to its mark or remove it.
   subroutine end_live(f)
      type(out_file_t), intent(inout) :: f  !< file
      integer(c_int) :: r
      logical :: was_failed
      was_failed = f%failed
      if (was_failed .and. f%fd >= 0 .and. f%good > 0) &
         r = c_ftruncate(f%fd, int(f%good, c_long))
      call close_fd(f)
      if (f%failed .and. (.not. was_failed .or. f%good == 0)) call remove_file(f%path)
      if (allocated(f%buf)) deallocate (f%buf)
      f%n = 0
   end subroutine end_live

   !> Record the first failure.
   subroutine fail(f, why)
      type(out_file_t), intent(inout) :: f    !< file
      character(len=*), intent(in) :: why     !< message
      if (f%failed) return
      f%failed = .true.
      f%why = why
   end subroutine fail

   !> Enlarge the buffer to hold at least `need` characters.
   subroutine grow(f, need)
      type(out_file_t), intent(inout) :: f   !< file
      integer, intent(in) :: need            !< characters needed
      character(len=:), allocatable :: b
      allocate (character(len=max(need, 2*len(f%buf))) :: b)
      b(1:f%n) = f%buf(1:f%n)
      call move_alloc(b, f%buf)
   end subroutine grow

   !> A string that may be unallocated: its value, or `default` when unallocated.
   pure function text_or(text, default) result(s)
      character(len=:), allocatable, intent(in) :: text !< string, maybe unallocated
      character(len=*), intent(in) :: default            !< the text when unallocated
      character(len=:), allocatable :: s                 !< its value or default
      if (allocated(text)) then
         s = text
      else
         s = default
      end if
   end function text_or

   !> Where the leading parts of a path end, the path itself last: path(:ends(j)) is
   !> the j-th ('/a//b/c': '/a', '/a//b', '/a//b/c').
   pure function path_prefixes(path) result(ends)
      character(len=*), intent(in) :: path  !< path
      integer, allocatable :: ends(:)       !< end of each part
      integer :: k
      allocate (ends(0))
      do k = 2, len(path) + 1
         if (k <= len(path)) then
            if (path(k:k) /= '/') cycle
         end if
         if (path(k - 1:k - 1) /= '/') ends = [ends, k - 1]
      end do
   end function path_prefixes

   !> dir/name (no doubled slash).
   pure function path_join(dir, name) result(path)
      character(len=*), intent(in) :: dir   !< folder
      character(len=*), intent(in) :: name  !< file name
      character(len=:), allocatable :: path !< joined path
      if (len_trim(dir) == 0) then
         path = name
      else if (dir(len_trim(dir):len_trim(dir)) == '/') then
         path = trim(dir)//name
      else
         path = trim(dir)//'/'//name
      end if
   end function path_join
end module rodyn_outfile
