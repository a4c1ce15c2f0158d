!> Dynamic writer, the time histories of dynamic.h5 as lists of series (a line's, the
!> sea's): the sizes of their chunks and of what is held in memory between syncs, and
!> one loop each to hold or cut back, write and close a list. In a list the first n_frame
!> series take a row per frame, the others a row per step.
module rodyn_output_dynamic_series
   use rodyn_error, only: error_t
   use rodyn_hdf5, only: hdf5_series_t, hdf5_series_hold, hdf5_series_write_held, &
      hdf5_series_truncate, hdf5_close_series
   implicit none
   private
   public :: log_block, frame_block, hold_bytes, chunk_bytes, log_chunk
   public :: series_rows, series_write_held, series_close

   integer, parameter :: log_block = 1024  !< step rows kept for dynamic.h5 at most
   integer, parameter :: frame_block = 256  !< frames held for dynamic.h5 at most
   integer, parameter :: hold_bytes = 8*1024*1024 !< and at most this much memory
   integer, parameter :: chunk_bytes = 8192 !< target HDF5 chunk size of the frames
   integer, parameter :: log_chunk = 1024   !< steps per HDF5 chunk of the step log

contains

   !> Write the rows held of every series of s.
   subroutine series_write_held(s, err)
      type(hdf5_series_t), intent(inout) :: s(:)   !< the series
      type(error_t), intent(inout) :: err          !< status
      integer :: k
      do k = 1, size(s)
         call hdf5_series_write_held(s(k), err)
      end do
   end subroutine series_write_held

   !> The rows of the open series of s, n = frames for s(1:n_frame) and steps for the
   !> others: held in memory up to n rows (cut = .false.), or the dataset cut back to its
   !> first n rows (cut = .true., the rows of a checkpoint; err says why it cannot be).
   subroutine series_rows(s, n_frame, frames, steps, cut, err)
      type(hdf5_series_t), intent(inout) :: s(:)   !< the series
      integer, intent(in) :: n_frame               !< series of a row per frame
      integer, intent(in) :: frames                !< rows of a series of frames
      integer, intent(in) :: steps                 !< rows of a series of steps
      logical, intent(in) :: cut                   !< cut back instead of hold
      type(error_t), intent(inout) :: err          !< status
      integer :: k
      do k = 1, size(s)
         if (s(k)%id < 0) cycle
         if (cut) then
            call hdf5_series_truncate(s(k), merge(frames, steps, k <= n_frame), err)
         else
            call hdf5_series_hold(s(k), merge(frames, steps, k <= n_frame))
         end if
      end do
   end subroutine series_rows

   !> Close every series of s (writing what it holds unless err holds an error).
   subroutine series_close(s, err)
      type(hdf5_series_t), intent(inout) :: s(:)   !< the series
      type(error_t), intent(inout) :: err          !< status
      integer :: k
      do k = 1, size(s)
         call hdf5_close_series(s(k), err)
      end do
   end subroutine series_close

end module rodyn_output_dynamic_series
