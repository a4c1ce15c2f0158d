!> Dynamic writer, the frames of the lines: each line's rows of the line tables
!> (dynamic_nodes, _elements, _ends, _lines, _ends_step.csv), laid out by
!> rodyn_output_table with their heads (line, node, s, ...) made once at open, and each
!> line's group of dynamic.h5 (/dynamic/LINE: its static datasets, the time histories
!> of a row per frame and the support forces of a row per step).
module rodyn_output_dynamic_lines
   use rodyn_format, only: put_text, put_int, put_real
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t
   use rodyn_results, only: line_result_t
   use rodyn_hdf5, only: hdf5_file_t, hdf5_series_t, hdf5_write_attribute, &
      hdf5_open_series, hdf5_append_steps
   use rodyn_outfile, only: out_file_t, outfile_put
   use rodyn_output_common, only: wall_tension_of, seabed_force_of, touchdown_of
   use rodyn_output_table, only: line_table_t, line_table, line_rows, line_row_kept, &
                                 line_row_head, put_line_values, put_end_values, group_name, &
                                 write_described, create_described_series, &
                                 bending_curvature_at, row_len, start_line_group
   use rodyn_output_dynamic_files, only: dynamic_files_t, table_name, tb_nodes, tb_elements, &
                                         tb_ends, tb_lines, tb_ends_step
   use rodyn_output_dynamic_series, only: chunk_bytes, log_chunk
   implicit none
   private
   public :: line_out_t, n_line_tables, n_line_series, n_frame_series, dynamic_h5
   public :: line_tables, set_up_line, create_h5_lines, open_h5_lines
   public :: write_frame_rows, write_frame_h5, write_ends_step

   character(len=*), parameter :: dynamic_h5 = 'dynamic.h5'
   ! The tables of the lines, laid out by rodyn_output_table (index into line_out_t%head)
   integer, parameter :: lt_nodes = 1, lt_elements = 2, lt_ends = 3, lt_lines = 4, &
      lt_ends_step = 5, n_line_tables = 5
   !> the table of the file list (rodyn_output_dynamic_files) each is written to
   integer, parameter :: line_file(n_line_tables) = [tb_nodes, tb_elements, tb_ends, &
      tb_lines, tb_ends_step]
   ! The members of /dynamic besides the lines' groups (group_name)
   character(len=*), parameter :: dynamic_members(3) = [character(len=4) :: 'time', &
      'log', 'sea']

   ! Time histories of a line in dynamic.h5 (index into line_out_t%series): a row per
   ! frame, then a row per step (the support forces of every step)
   integer, parameter :: ls_x = 1, ls_y = 2, ls_z = 3, ls_tension = 4, ls_moment_1 = 5, &
      ls_moment_2 = 6, ls_torque = 7, ls_curvature = 8, ls_reactions = 9, &
      ls_end_tension = 10, ls_wall_tension = 11, ls_seabed_normal = 12, &
      ls_seabed_friction = 13, ls_touchdown = 14, n_frame_series = 14, &
      ls_step_reactions = 15, ls_step_end_tension = 16, ls_step_time = 17, n_line_series = 17
   character(len=*), parameter :: line_series_name(n_line_series) = [character(len=17) :: &
      'x', 'y', 'z', 'effective_tension', 'moment_1', 'moment_2', 'torque', &
      'bending_curvature', 'reactions', 'end_tension', 'wall_tension', 'seabed_normal', &
      'seabed_friction', 'touchdown_s', 'step_reactions', 'step_end_tension', 'step_time']

   !> A string of its own length (rows of an array of texts differ in length).
   type :: text_t
      character(len=:), allocatable :: s !< the text
   end type text_t

   !> The heads of a line's rows in one table (line_row_head), made once at open.
   type :: heads_t
      type(text_t), allocatable :: row(:)  !< (line_rows) ',LINE,node,s_m', ...
   end type heads_t

   !> One line: its sizes, the fixed start of its CSV rows and its open HDF5 series.
   type :: line_out_t
      integer :: nn = 0                              !< nodes
      integer :: ng = 0                              !< integration points
      logical :: end_held(2) = .false.               !< ends written to the ends tables
      type(heads_t) :: head(n_line_tables)           !< its rows' heads in each table
      type(hdf5_series_t) :: series(n_line_series)   !< the line's time histories
   end type line_out_t

contains

   !> The layouts of the line tables (rodyn_output_table).
   subroutine line_tables(tables, err)
      type(line_table_t), intent(out) :: tables(n_line_tables) !< the layouts
      type(error_t), intent(inout) :: err                      !< status
      integer :: i
      do i = 1, n_line_tables
         tables(i) = line_table(trim(table_name(line_file(i))), err)
      end do
   end subroutine line_tables

   !> A line's sizes and the heads of its rows in each line table (after the leading
   !> step and time columns; rodyn_output_table).
   subroutine set_up_line(lo, r, tables)
      type(line_out_t), intent(out) :: lo            !< the line's output state
      type(line_result_t), intent(in) :: r           !< the line at open
      type(line_table_t), intent(in) :: tables(:)    !< (n_line_tables) layouts
      integer :: k, tb
      lo%nn = size(r%node_s)
      lo%ng = size(r%gp_s)
      lo%end_held = r%end_held
      do tb = 1, n_line_tables
         allocate (lo%head(tb)%row(line_rows(tables(tb), r)))
         do k = 1, size(lo%head(tb)%row)
            lo%head(tb)%row(k)%s = line_row_head(tables(tb), r, k)
         end do
      end do
   end subroutine set_up_line

   !> Every line's group of dynamic.h5: its static datasets and its empty time
   !> histories, left open in lo for appending.
   subroutine create_h5_lines(h5, lines, lo, err)
      type(hdf5_file_t), intent(in) :: h5          !< open file
      type(line_result_t), intent(in) :: lines(:)  !< the lines at open
      type(line_out_t), intent(inout) :: lo(:)     !< their output (series)
      type(error_t), intent(inout) :: err          !< status
      integer :: i
      do i = 1, size(lines)
         call create_h5_line(h5, '/dynamic/'//group_name(lines(i)%name, i, &
                             dynamic_members), lines(i), lo(i), err)
      end do
   end subroutine create_h5_lines

   !> One line's group: its static datasets and its empty time histories, left open in
   !> lo for appending.
   subroutine create_h5_line(h5, g, r, lo, err)
      type(hdf5_file_t), intent(in) :: h5    !< open file
      character(len=*), intent(in) :: g      !< group path
      type(line_result_t), intent(in) :: r   !< the line at open
      type(line_out_t), intent(inout) :: lo  !< the line's output (its series)
      type(error_t), intent(inout) :: err    !< status
      integer :: k, cols(ls_seabed_friction)
      cols = [integer :: size(r%node_s), size(r%node_s), size(r%node_s), &
              (size(r%gp_s), k = 1, 5), 12, 2, size(r%gp_s), size(r%node_s), size(r%node_s)]
      call start_line_group(h5, dynamic_h5, g, r, err)
      call write_described(h5, dynamic_h5, g//'/gp_s', err, g, x1=r%gp_s)
      call write_described(h5, dynamic_h5, g//'/gp_element', err, g, i1=r%gp_element)
      call write_described(h5, dynamic_h5, g//'/gp_point', err, g, i1=r%gp_point)
      ! the frames' histories ls_x .. ls_seabed_friction, cols(k) values a frame
      do k = 1, ls_seabed_friction
         call create_described_series(h5, dynamic_h5, g//'/'//trim(line_series_name(k)), &
                                      cols(k), err, max(8, chunk_bytes/(8*cols(k))), g, &
                                      series=lo%series(k))
         if (k == ls_reactions) call hdf5_write_attribute(h5, g//'/reactions', 'end_held', &
                                                          merge(1, 0, r%end_held), err)
      end do
      call create_described_series(h5, dynamic_h5, g//'/step_time', 0, err, log_chunk, g, &
                                   series=lo%series(ls_step_time))
      call create_described_series(h5, dynamic_h5, g//'/step_reactions', 12, err, &
                                   log_chunk/4, g, series=lo%series(ls_step_reactions))
      call hdf5_write_attribute(h5, g//'/step_reactions', 'end_held', &
         merge(1, 0, r%end_held), err)
      call create_described_series(h5, dynamic_h5, g//'/step_end_tension', 2, err, &
                                   log_chunk, g, series=lo%series(ls_step_end_tension))
      call create_described_series(h5, dynamic_h5, g//'/'//trim(line_series_name(ls_touchdown)), &
                                   0, err, chunk_bytes/8, g, series=lo%series(ls_touchdown))
   end subroutine create_h5_line

   !> Open every time history of the lines' groups of an existing dynamic.h5 for
   !> appending.
   subroutine open_h5_lines(h5, lines, lo, err)
      type(hdf5_file_t), intent(in) :: h5          !< open file
      type(line_result_t), intent(in) :: lines(:)  !< the lines (names)
      type(line_out_t), intent(inout) :: lo(:)     !< their output (series)
      type(error_t), intent(inout) :: err          !< status
      character(len=:), allocatable :: g
      integer :: i, k
      do i = 1, size(lines)
         g = '/dynamic/'//group_name(lines(i)%name, i, dynamic_members)
         do k = 1, n_line_series
            call hdf5_open_series(h5, g//'/'//trim(line_series_name(k)), lo(i)%series(k), err)
         end do
      end do
   end subroutine open_h5_lines

   !> The frame's rows of dynamic_nodes.csv, dynamic_elements.csv, dynamic_ends.csv and
   !> dynamic_lines.csv, held until the next sync (failures are kept in the tables).
   subroutine write_frame_rows(tables, lo, lines, time, fl)
      type(line_table_t), intent(in) :: tables(:)  !< (n_line_tables) layouts
      type(line_out_t), intent(in) :: lo(:)        !< the lines' heads
      type(line_result_t), intent(in) :: lines(:)  !< state
      real(wp), intent(in) :: time                 !< time of the frame [s]
      type(dynamic_files_t), intent(inout) :: fl   !< the tables
      character(len=64) :: t
      integer :: nt, tb
      nt = 0
      call put_real(t, nt, time)
      do tb = lt_nodes, lt_lines
         call append_rows(tables(tb), tb, lo, lines, t(:nt), fl%f(line_file(tb)))
      end do
   end subroutine write_frame_rows

   !> Append to table f (layout t, table number tb) the rows of every line: `lead`, then
   !> the row's head made at open, then its values (rodyn_output_table).
   subroutine append_rows(t, tb, lo, lines, lead, f)
      type(line_table_t), intent(in) :: t          !< layout
      integer, intent(in) :: tb                    !< lt_* of the table
      type(line_out_t), intent(in) :: lo(:)        !< the lines' heads
      type(line_result_t), intent(in) :: lines(:)  !< state
      character(len=*), intent(in) :: lead         !< the leading fields ('time')
      type(out_file_t), intent(inout) :: f         !< the table
      character(len=row_len) :: row
      integer :: i, k, n
      do i = 1, size(lines)
         do k = 1, size(lo(i)%head(tb)%row)
            if (.not. line_row_kept(t, lo(i)%end_held, k)) cycle
            n = 0
            call put_text(row, n, lead)
            call put_text(row, n, lo(i)%head(tb)%row(k)%s)
            call put_line_values(t, lines(i), k, row, n)
            call outfile_put(f, row(:n))
         end do
      end do
   end subroutine append_rows

   !> The frame's values of every line appended to its series in dynamic.h5 (held in
   !> memory until the next sync).
   subroutine write_frame_h5(lo, lines, err)
      type(line_out_t), intent(inout) :: lo(:)     !< the lines' series
      type(line_result_t), intent(in) :: lines(:)  !< state
      type(error_t), intent(inout) :: err          !< status
      integer :: i
      do i = 1, size(lines)
         associate (r => lines(i), s => lo(i)%series)
            call hdf5_append_steps(s(ls_x), r%node_x(1, :), err)
            call hdf5_append_steps(s(ls_y), r%node_x(2, :), err)
            call hdf5_append_steps(s(ls_z), r%node_x(3, :), err)
            call hdf5_append_steps(s(ls_tension), r%tension, err)
            call hdf5_append_steps(s(ls_moment_1), r%moment(1, :), err)
            call hdf5_append_steps(s(ls_moment_2), r%moment(2, :), err)
            call hdf5_append_steps(s(ls_torque), r%torque, err)
            call hdf5_append_steps(s(ls_curvature), bending_curvature(r%curvature), err)
            call hdf5_append_steps(s(ls_reactions), reshape(r%reaction, [12]), err)
            call hdf5_append_steps(s(ls_end_tension), &
               [norm2(r%reaction(1:3, 1)), norm2(r%reaction(1:3, 2))], err)
            call hdf5_append_steps(s(ls_wall_tension), wall_tension_of(r), err)
            call hdf5_append_steps(s(ls_seabed_normal), seabed_force_of(r, 1), err)
            call hdf5_append_steps(s(ls_seabed_friction), seabed_force_of(r, 2), err)
            call hdf5_append_steps(s(ls_touchdown), [touchdown_of(r)], err)
         end associate
      end do
   end subroutine write_frame_h5

   !> The support forces at the end of step `step`, time `time`: one row per held end
   !> to dynamic_ends_step.csv (when csv), one row to each line's step_time,
   !> step_reactions and step_end_tension (when hdf5). reaction(:, k, l): force and
   !> moment of the support on line l at end k (A, B).
   subroutine write_ends_step(tables, lo, step, time, reaction, csv, hdf5, fl, err)
      type(line_table_t), intent(in) :: tables(:)   !< (n_line_tables) layouts
      type(line_out_t), intent(inout) :: lo(:)      !< the lines' heads and series
      integer, intent(in) :: step                   !< step number (0: start) [-]
      real(wp), intent(in) :: time                  !< time at the end of the step [s]
      real(wp), intent(in) :: reaction(:, :, :)     !< (6, 2, lines) [N, N m]
      logical, intent(in) :: csv                    !< write the CSV rows
      logical, intent(in) :: hdf5                   !< write the dynamic.h5 rows
      type(dynamic_files_t), intent(inout) :: fl    !< the tables
      type(error_t), intent(inout) :: err           !< status of dynamic.h5
      character(len=row_len) :: row
      integer :: i, j, n
      do i = 1, size(lo)
         if (csv) then
            do j = 1, 2
               if (.not. line_row_kept(tables(lt_ends_step), lo(i)%end_held, j)) cycle
               n = 0
               call put_int(row, n, step)
               call put_real(row, n, time)
               call put_text(row, n, lo(i)%head(lt_ends_step)%row(j)%s)
               call put_end_values(tables(lt_ends_step), reaction(:, j, i), row, n)
               call outfile_put(fl%f(tb_ends_step), row(:n))
            end do
         end if
         if (hdf5) then
            associate (s => lo(i)%series)
               call hdf5_append_steps(s(ls_step_time), [time], err)
               call hdf5_append_steps(s(ls_step_reactions), reshape(reaction(:, :, i), [12]), &
                                      err)
               call hdf5_append_steps(s(ls_step_end_tension), [norm2(reaction(1:3, 1, i)), &
                                                               norm2(reaction(1:3, 2, i))], err)
            end associate
         end if
      end do
   end subroutine write_ends_step

   !> Bending curvature sqrt(K1^2 + K2^2) of each point [1/m] (rodyn_output_table's
   !> bending_curvature_at, that of the CSV tables: both hold the same bits).
   pure function bending_curvature(curv) result(kb)
      real(wp), intent(in) :: curv(:, :)  !< (3, n) curvatures K1, K2, K3 [1/m]
      real(wp) :: kb(size(curv, 2))
      integer :: k
      do k = 1, size(curv, 2)
         kb(k) = bending_curvature_at(curv(:, k))
      end do
   end function bending_curvature

end module rodyn_output_dynamic_lines
