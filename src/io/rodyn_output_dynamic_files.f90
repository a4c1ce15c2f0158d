!> Dynamic writer, the file list: the CSV tables of a dynamic run (the lines' tables,
!> the step log, the sea, vessel and body tables) as one list, so that creating,
!> flushing, marking and closing them are one loop each, and the sizes status.txt
!> (committed) and a checkpoint (written) give of them. Every table is a live file of
!> rodyn_outfile, created with its header (rodyn_output_schema) and grown as the run goes.
module rodyn_output_dynamic_files
   use rodyn_kinds, only: i8
   use rodyn_error, only: error_t, has_error
   use rodyn_output, only: committed_t
   use rodyn_output_schema, only: schema_header
   use rodyn_outfile, only: out_file_t, outfile_create, outfile_put, outfile_flush, &
      outfile_mark, outfile_close, outfile_abort, outfile_pending, outfile_committed, &
      outfile_reopen
   implicit none
   private
   public :: dynamic_files_t, n_tables, table_name
   public :: tb_nodes, tb_elements, tb_ends, tb_lines, tb_log, tb_ends_step
   public :: tb_waves, tb_waves_step, tb_vessels, tb_vessels_step, tb_conn, tb_conn_step
   public :: tb_bodies, tb_bodies_step
   public :: files_create, files_reopen, files_flush, files_mark, files_close
   public :: files_committed, files_pending, files_written

   ! The tables, in the order they are flushed and status.txt gives them
   integer, parameter :: tb_nodes = 1, tb_elements = 2, tb_ends = 3, tb_lines = 4, &
      tb_log = 5, tb_ends_step = 6, tb_waves = 7, tb_waves_step = 8, tb_vessels = 9, &
      tb_vessels_step = 10, tb_conn = 11, tb_conn_step = 12, tb_bodies = 13, &
      tb_bodies_step = 14, n_tables = 14
   character(len=*), parameter :: table_name(n_tables) = [character(len=28) :: &
      'dynamic_nodes.csv', 'dynamic_elements.csv', 'dynamic_ends.csv', 'dynamic_lines.csv', &
      'dynamic_log.csv', 'dynamic_ends_step.csv', &
      'dynamic_waves.csv', 'dynamic_waves_step.csv', 'dynamic_vessels.csv', &
      'dynamic_vessels_step.csv', 'dynamic_connections.csv', 'dynamic_connections_step.csv', &
      'dynamic_bodies.csv', 'dynamic_bodies_step.csv']
   !> The order the tables are created and closed in
   integer, parameter :: creation_order(n_tables) = [tb_nodes, tb_elements, tb_ends, &
      tb_log, tb_ends_step, tb_lines, tb_waves, tb_waves_step, tb_vessels, &
      tb_vessels_step, tb_conn, tb_conn_step, tb_bodies, tb_bodies_step]
   !> The order of their sizes in a checkpoint (dynamic_output_mark_t%csv_bytes), the
   !> order they are opened again in
   integer, parameter :: mark_order(n_tables) = [tb_nodes, tb_elements, tb_ends, tb_log, &
      tb_lines, tb_ends_step, tb_waves, tb_waves_step, tb_vessels, tb_vessels_step, &
      tb_conn, tb_conn_step, tb_bodies, tb_bodies_step]

   !> The CSV tables of a dynamic run.
   type :: dynamic_files_t
      type(out_file_t) :: f(n_tables)          !< the tables (tb_*)
      logical :: on(n_tables) = .false.        !< which of them the run writes
   end type dynamic_files_t

contains

   !> Create (truncate) every table the run writes in folder dir and write its header
   !> (flushed: a table of no frame). Stops at the first failure.
   subroutine files_create(fl, dir, err)
      type(dynamic_files_t), intent(inout) :: fl  !< the tables
      character(len=*), intent(in) :: dir         !< output folder
      type(error_t), intent(inout) :: err         !< status
      integer :: i, k
      do i = 1, n_tables
         k = creation_order(i)
         if (.not. fl%on(k) .or. has_error(err)) cycle
         call outfile_create(fl%f(k), dir, trim(table_name(k)), err, live=.true.)
         if (has_error(err)) return
         call outfile_put(fl%f(k), schema_header(trim(table_name(k))))
         call outfile_flush(fl%f(k), err)
         call outfile_mark(fl%f(k))
      end do
   end subroutine files_create

   !> Open the tables of an interrupted run in folder dir again, each cut back to its
   !> size at the checkpoint (bytes, in mark_order). Stops at the first failure.
   subroutine files_reopen(fl, dir, bytes, err)
      type(dynamic_files_t), intent(inout) :: fl  !< the tables
      character(len=*), intent(in) :: dir         !< output folder
      integer(i8), intent(in) :: bytes(:)         !< (n_tables) sizes [bytes]
      type(error_t), intent(inout) :: err         !< status
      integer :: i, k
      do i = 1, n_tables
         k = mark_order(i)
         if (.not. fl%on(k) .or. has_error(err)) cycle
         call outfile_reopen(fl%f(k), dir, trim(table_name(k)), bytes(i), err)
      end do
   end subroutine files_reopen

   !> Hand every row held to the system (failures recorded in err).
   subroutine files_flush(fl, err)
      type(dynamic_files_t), intent(inout) :: fl  !< the tables
      type(error_t), intent(inout) :: err         !< status
      integer :: k
      do k = 1, n_tables
         call outfile_flush(fl%f(k), err)
      end do
   end subroutine files_flush

   !> Record that every table ends with a whole frame (after a flush).
   subroutine files_mark(fl)
      type(dynamic_files_t), intent(inout) :: fl  !< the tables
      integer :: k
      do k = 1, n_tables
         call outfile_mark(fl%f(k))
      end do
   end subroutine files_mark

   !> Close every table (errors recorded in err); when `abandon`, drop the rows held
   !> instead and cut each table back to its last mark.
   subroutine files_close(fl, abandon, err)
      type(dynamic_files_t), intent(inout) :: fl  !< the tables (closed on return)
      logical, intent(in) :: abandon              !< a write failed: drop what is held
      type(error_t), intent(inout) :: err         !< status
      integer :: i
      do i = 1, n_tables
         if (abandon) then
            call outfile_abort(fl%f(creation_order(i)))
         else
            call outfile_close(fl%f(creation_order(i)), err)
         end if
      end do
   end subroutine files_close

   !> The committed size of each table the run writes (its last sync), for status.txt.
   function files_committed(fl) result(c)
      type(dynamic_files_t), intent(in) :: fl   !< the tables
      type(committed_t), allocatable :: c(:)    !< one per table written
      integer :: k
      allocate (c(0))
      do k = 1, n_tables
         if (fl%on(k)) c = [c, committed_t(trim(table_name(k)), outfile_committed(fl%f(k)))]
      end do
   end function files_committed

   !> Characters of rows held in memory.
   pure integer function files_pending(fl)
      type(dynamic_files_t), intent(in) :: fl   !< the tables
      integer :: k
      files_pending = sum([(outfile_pending(fl%f(k)), k = 1, n_tables)])
   end function files_pending

   !> Bytes handed to the system of each table, in mark_order (a checkpoint's csv_bytes).
   pure function files_written(fl) result(bytes)
      type(dynamic_files_t), intent(in) :: fl   !< the tables
      integer(i8) :: bytes(n_tables)            !< sizes [bytes]
      bytes = fl%f(mark_order)%written
   end function files_written

end module rodyn_output_dynamic_files
