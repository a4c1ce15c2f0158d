!> Print rodyn's description of its output tables (rodyn_output_schema) for
!> check_output_schema.py: one line per column, 'COLUMN<TAB>file<TAB>column<TAB>unit<TAB>
!> meaning', then one line per file, 'HEADER<TAB>file<TAB>header row the writers write',
!> then one line per HDF5 dataset, 'DATASET<TAB>file<TAB>path<TAB>units<TAB>description',
!> then one per key of status.txt, 'STATUS<TAB>key<TAB>unit<TAB>meaning', then one per
!> dataset of /environment, 'ENVIRONMENT<TAB>files<TAB>path<TAB>units<TAB>description',
!> then one per attribute, 'ATTRIBUTE<TAB>file<TAB>object:attribute<TAB>unit<TAB>meaning'.
program output_schema_dump
   use rodyn_output_schema, only: output_columns, output_datasets, schema_field, &
      schema_header, schema_tables, status_keys, environment_datasets, &
      output_attributes
   implicit none
   character(len=:), allocatable :: files, file
   character(len=1), parameter :: tab = achar(9)
   integer :: k, c
   do k = 1, size(output_columns)
      write (*, '(a)') 'COLUMN'//tab//schema_field(output_columns(k), 1)//tab// &
         schema_field(output_columns(k), 2)//tab//schema_field(output_columns(k), 3)// &
         tab//schema_field(output_columns(k), 4)
   end do
   files = schema_tables()//','
   do while (len(files) > 0)
      c = index(files, ',')
      file = files(:c - 1)
      files = files(c + 1:)
      write (*, '(a)') 'HEADER'//tab//file//tab//schema_header(file)
   end do
   do k = 1, size(output_datasets)
      write (*, '(a)') 'DATASET'//tab//schema_field(output_datasets(k), 1)//tab// &
         schema_field(output_datasets(k), 2)//tab//schema_field(output_datasets(k), 3)// &
         tab//schema_field(output_datasets(k), 4)
   end do
   do k = 1, size(status_keys)
      write (*, '(a)') 'STATUS'//tab//schema_field(status_keys(k), 2)//tab// &
         schema_field(status_keys(k), 3)//tab//schema_field(status_keys(k), 4)
   end do
   do k = 1, size(environment_datasets)
      write (*, '(a)') 'ENVIRONMENT'//tab//schema_field(environment_datasets(k), 1)//tab// &
         schema_field(environment_datasets(k), 2)//tab// &
         schema_field(environment_datasets(k), 3)//tab//schema_field(environment_datasets(k), 4)
   end do
   do k = 1, size(output_attributes)
      write (*, '(a)') 'ATTRIBUTE'//tab//schema_field(output_attributes(k), 1)//tab// &
         schema_field(output_attributes(k), 2)//tab// &
         schema_field(output_attributes(k), 3)//tab//schema_field(output_attributes(k), 4)
   end do
end program output_schema_dump
