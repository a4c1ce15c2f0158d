!> The one description of rodyn's output: every column of every CSV table, with its
!> unit and a one-line meaning, in the order written, and every HDF5 dataset with its
!> units and description, looked up. The rows are held in src/io/rodyn_output_schema.txt
!> (its head describes them and who reads them); tools/gen_output_schema.py writes them at
!> build time as the tables of module rodyn_output_schema_rows, which this module passes
!> on with the lookups the writers use (rodyn_output_table, rodyn_output_common).
!>
!> A row of `output_columns` is 'file | column | unit | meaning'; the unit '-' means
!> none (a name, a count, a ratio).
module rodyn_output_schema
   use rodyn_output_schema_rows, only: output_columns, output_datasets, status_keys, &
                                       environment_datasets, output_attributes, row_len
   implicit none
   private
   public :: output_columns, output_datasets, schema_field, schema_header, schema_tables
   public :: schema_dataset, status_keys, environment_datasets, schema_environment
   public :: output_attributes, row_len

contains

   !> Field k (1: file, 2: column, 3: unit, 4: meaning) of a row of output_columns,
   !> without the blanks around it.
   pure function schema_field(row, k) result(s)
      character(len=*), intent(in) :: row   !< a row of output_columns
      integer, intent(in) :: k              !< field number, 1 to 4
      character(len=:), allocatable :: s    !< the field
      integer :: i, a, b
      a = 1
      do i = 1, k - 1
         b = index(row(a:), '|')
         if (b == 0) then
            s = ''
            return
         end if
         a = a + b
      end do
      b = index(row(a:), '|')
      if (b == 0 .or. k == 4) then
         s = trim(adjustl(row(a:)))
      else
         s = trim(adjustl(row(a:a + b - 2)))
      end if
   end function schema_field

   !> The row of output_datasets for dataset `path` of file `file` ('' when none): a
   !> line's dataset is looked up with its group name replaced by LINE, from `line_group`
   !> ('/static/RISER': '/static/LINE/node_s' for '/static/RISER/node_s').
   pure function schema_dataset(file, path, line_group) result(row)
      character(len=*), intent(in) :: file                 !< 'results.h5', 'dynamic.h5'
      character(len=*), intent(in) :: path                 !< dataset path in the file
      character(len=*), intent(in), optional :: line_group !< group of the line, if any
      character(len=:), allocatable :: row                 !< the row, or ''
      character(len=:), allocatable :: key, needle
      integer :: k
      key = path
      if (present(line_group)) then
         if (index(path, line_group//'/') == 1) key = &
            line_group(:index(line_group, '/', back=.true.))//'LINE'//path(len(line_group) + 1:)
      end if
      row = ''
      ! every row begins 'file | key |' (test_output's test_schema_rows_found holds the
      ! table to it): compared in place, not field by field (cutting every row's fields
      ! out would cost a good part of a short run)
      needle = file//' | '//key//' |'
      if (len(needle) > row_len) return
      do k = 1, size(output_datasets)
         if (output_datasets(k)(1:len(needle)) == needle) then
            row = trim(output_datasets(k))
            return
         end if
      end do
   end function schema_dataset

   !> The row of environment_datasets for dataset `path` ('/environment/depth'); ''
   !> when none.
   pure function schema_environment(path) result(row)
      character(len=*), intent(in) :: path   !< dataset path
      character(len=:), allocatable :: row   !< the row, or ''
      integer :: k
      row = ''
      do k = 1, size(environment_datasets)
         if (schema_field(environment_datasets(k), 2) == path) then
            row = trim(environment_datasets(k))
            return
         end if
      end do
   end function schema_environment

   !> The header row of CSV table `file`: its column names, comma-separated, in order
   !> ('' for a file the schema does not know).
   pure function schema_header(file) result(s)
      character(len=*), intent(in) :: file  !< 'dynamic_nodes.csv', ...
      character(len=:), allocatable :: s    !< 'time_s,line,node,...'
      integer :: k
      s = ''
      do k = 1, size(output_columns)
         if (schema_field(output_columns(k), 1) /= file) cycle
         if (len(s) > 0) s = s//','
         s = s//schema_field(output_columns(k), 2)
      end do
   end function schema_header

   !> The files of the schema, each once, in the order of output_columns, as one
   !> comma-separated text.
   pure function schema_tables() result(s)
      character(len=:), allocatable :: s    !< 'static_nodes.csv,static_elements.csv,...'
      character(len=:), allocatable :: file
      integer :: k
      s = ','
      do k = 1, size(output_columns)
         file = schema_field(output_columns(k), 1)
         if (index(s, ','//file//',') == 0) s = s//file//','
      end do
      s = s(2:len(s) - 1)
   end function schema_tables
end module rodyn_output_schema
