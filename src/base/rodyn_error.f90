!> Status type returned by library routines. Only the main program stops the run;
!> library code fills an error_t and returns. The codes are the program's exit codes.
module rodyn_error
   implicit none
   private
   public :: error_t, set_error, has_error, clear_error
   public :: stat_ok, stat_input, stat_numerical, stat_io

   integer, parameter :: stat_ok = 0         !< success
   integer, parameter :: stat_input = 1      !< bad input (deck, command line)
   integer, parameter :: stat_numerical = 2  !< numerical failure (divergence, NaN, singular)
   integer, parameter :: stat_io = 3         !< file could not be read or written

   !> An error: a code (one of stat_*) and a one-line message.
   type :: error_t
      integer :: code = stat_ok                 !< stat_* code
      character(len=:), allocatable :: message  !< what went wrong, naming where
   end type error_t

contains

   !> Record an error (the first one wins: a later call does not overwrite it).
   subroutine set_error(err, code, message)
      type(error_t), intent(inout) :: err     !< status to fill
      integer, intent(in) :: code             !< stat_* code
      character(len=*), intent(in) :: message !< message, already naming file/line or routine
      if (err%code /= stat_ok) return
      err%code = code
      err%message = message
   end subroutine set_error

   !> True when err holds an error.
   pure logical function has_error(err)
      type(error_t), intent(in) :: err !< status to test
      has_error = err%code /= stat_ok
   end function has_error

   !> Reset to success.
   subroutine clear_error(err)
      type(error_t), intent(inout) :: err !< status to reset
      err%code = stat_ok
      if (allocated(err%message)) deallocate (err%message)
   end subroutine clear_error
end module rodyn_error
