!> Dynamic writer, the time histories of dynamic.h5 as lists of series (a line's, the
!> sea's): the sizes of their chunks and of what is held in memory between syncs, and
!> one loop to hold or cut back, write or close a list (series_do). In a list the first
!> n_frame series take a row per frame, the others a row per step.
module rodyn_output_dynamic_series
   use rodyn_error, only: error_t
   use rodyn_hdf5, only: hdf5_series_t, hdf5_series_hold, hdf5_series_write_held, &
      hdf5_series_truncate, hdf5_close_series
   implicit none
   private
   public :: log_block, frame_block, hold_bytes, chunk_bytes, log_chunk
   public :: series_do, s_hold, s_cut, s_write, s_close

   integer, parameter :: log_block = 1024  !< step rows kept for dynamic.h5 at most
   integer, parameter :: frame_block = 256  !< frames held for dynamic.h5 at most
   integer, parameter :: hold_bytes = 8*1024*1024 !< and at most this much memory
   integer, parameter :: chunk_bytes = 8192 !< target HDF5 chunk size of the frames
   integer, parameter :: log_chunk = 1024   !< steps per HDF5 chunk of the step log
   !> What series_do does to a list of series
   integer, parameter :: s_hold = 1, s_cut = 2, s_write = 3, s_close = 4

contains

   !> Act on every open series of s: hold its rows in memory, up to n rows (s_hold), or
   !> cut its dataset back to its first n rows (s_cut, the rows of a checkpoint; err says
   !> why it cannot be), n = frames for s(1:n_frame) and steps for the others; write the
   !> rows held (s_write); or close it, writing what it holds unless err holds an error
   !> (s_close).
   subroutine series_do(s, action, err, n_frame, frames, steps)
      type(hdf5_series_t), intent(inout) :: s(:)   !< the series
      integer, intent(in) :: action                !< s_hold, s_cut, s_write or s_close
      type(error_t), intent(inout) :: err          !< status
      integer, intent(in), optional :: n_frame     !< series of a row per frame
      integer, intent(in), optional :: frames      !< rows of a series of frames
      integer, intent(in), optional :: steps       !< rows of a series of steps
      integer :: k, n
      do k = 1, size(s)
         if (s(k)%id < 0) cycle
         if (action == s_hold .or. action == s_cut) n = merge(frames, steps, k <= n_frame)
         select case (action)
         case (s_hold)
            call hdf5_series_hold(s(k), n)
         case (s_cut)
            call hdf5_series_truncate(s(k), n, err)
         case (s_write)
            call hdf5_series_write_held(s(k), err)
         case (s_close)
            call hdf5_close_series(s(k), err)
         end select
      end do
   end subroutine series_do

end module rodyn_output_dynamic_series
