!> Small helpers shared by the static and dynamic output writers: file paths, names as
!> CSV fields, one-line texts, status words, and the description attributes of HDF5
!> datasets.
module rodyn_output_common
   use rodyn_results, only: run_summary_t
   use rodyn_hdf5, only: hdf5_file_t, hdf5_write_attribute
   use rodyn_error, only: error_t
   implicit none
   private
   public :: text_of, status_of, path_join, one_line, describe, csv_name

contains

   !> The text of an optional allocatable string ('' when unallocated).
   pure function text_of(text) result(s)
      character(len=:), allocatable, intent(in) :: text !< string, maybe unallocated
      character(len=:), allocatable :: s                 !< its value or ''
      if (allocated(text)) then
         s = text
      else
         s = ''
      end if
   end function text_of

   !> The status message of a summary, with a default when none was set.
   pure function status_of(summary) result(s)
      type(run_summary_t), intent(in) :: summary !< how the run went
      character(len=:), allocatable :: s         !< message
      if (allocated(summary%status)) then
         s = summary%status
      else if (summary%complete) then
         s = 'complete'
      else
         s = 'incomplete'
      end if
   end function status_of

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

   !> Text on one line: line breaks and tabs become blanks, trailing blanks dropped.
   pure function one_line(text) result(s)
      character(len=*), intent(in) :: text  !< text
      character(len=:), allocatable :: s    !< same text on one line
      integer :: k
      s = text
      do k = 1, len(s)
         if (iachar(s(k:k)) < 32) s(k:k) = ' '
      end do
      s = trim(s)
   end function one_line

   !> Attach the `units` and `description` attributes to a dataset.
   subroutine describe(h5, path, units, description, err)
      type(hdf5_file_t), intent(in) :: h5           !< open file
      character(len=*), intent(in) :: path          !< dataset path
      character(len=*), intent(in) :: units         !< units text ('-': none)
      character(len=*), intent(in) :: description   !< one-line description
      type(error_t), intent(inout) :: err           !< status
      call hdf5_write_attribute(h5, path, 'units', units, err)
      call hdf5_write_attribute(h5, path, 'description', description, err)
   end subroutine describe

   !> A line name as a CSV field: as given, quoted only if it holds a comma or quote.
   pure function csv_name(name) result(s)
      character(len=*), intent(in) :: name  !< line name
      character(len=:), allocatable :: s    !< field
      integer :: i
      if (scan(trim(name), ',"') == 0) then
         s = trim(name)
         return
      end if
      s = '"'
      do i = 1, len_trim(name)
         if (name(i:i) == '"') then
            s = s//'""'
         else
            s = s//name(i:i)
         end if
      end do
      s = s//'"'
   end function csv_name
end module rodyn_output_common
