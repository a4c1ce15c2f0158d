!> The one table writer of rodyn's output, used by the static writer (rodyn_output, a
!> "one-shot" table: every row written at once) and the dynamic one
!> (rodyn_output_dynamic, which appends a frame's rows to the same tables while the run
!> goes): the rows of a line's tables, the described HDF5 datasets, the group names.
!>
!> A line's table (nodes, elements, ends/reactions, lines; static and dynamic) is laid
!> out from its columns in rodyn_output_schema (line_table): leading columns the caller
!> gives as text (step, time_s), then the row's head, the same in every frame (line,
!> node, element, point, s_m, end), then its values. The table has a row per node
!> (a column 'node'), per integration point ('element'), per held end ('end'), or one
!> per line. A row is
!>     lead // head // ',' value_1 // ',' value_2 ...
!> with each field formatted by rodyn_format (17 significant digits). Values:
!>   x_m, y_m, z_m        node_x(:, k)          s_m      node_s(k) or gp_s(k)
!>   seabed_*_N_per_m     seabed_normal/_friction(k), 0 when not computed (dry)
!>   effective_tension_N  tension(k)            wall_tension_N  wall_tension(k), or
!>                                                              tension(k) when dry
!>   shear_i_N, moment_i_Nm, torque_Nm, curvature_i_per_m, twist_per_m: the section
!>   forces and curvatures of point k; curvature_per_m = hypot(K1, K2) (the bending
!>   curvature, also of dynamic.h5's bending_curvature)
!>   Fx_N ... Mz_Nm       reaction(:, end)      tension_N  |reaction(1:3, end)|
!>   length_m             node_s(nn)            touchdown_s_m  touchdown_s, -1 if none
!> A column the schema lists and this module cannot fill is an error when the table is
!> laid out (the writer and the schema out of step), never a wrong column.
!>
!> Every HDF5 dataset a writer creates is created with its `units` and `description`
!> from the schema (write_described, create_described_series).
module rodyn_output_table
   use rodyn_kinds, only: wp, rodyn_version
   use rodyn_error, only: error_t, set_error, has_error, stat_io
   use rodyn_model, only: model_t
   use rodyn_results, only: line_result_t
   use rodyn_format, only: put_text, put_int, put_real, put_reals
   use rodyn_outfile, only: out_file_t, outfile_create, outfile_put, outfile_commit
   use rodyn_output_schema, only: output_columns, schema_field, schema_header, &
      schema_len => row_len
   use rodyn_hdf5, only: hdf5_file_t, hdf5_write_dataset, hdf5_write_attribute, &
      hdf5_create_series, hdf5_create_series_1d, hdf5_series_t, hdf5_create_group
   use rodyn_output_common, only: csv_name, touchdown_of, water_fields_fit, text_or, &
      described, dataset_texts
   implicit none
   private
   public :: line_table_t, line_table, line_rows, line_row_kept, line_row_head
   public :: put_line_values, put_end_values, line_row_values, end_row_values
   public :: write_line_table
   public :: group_name, write_described, create_described_series, write_h5_root
   public :: start_line_group
   public :: line_result_complete, line_result_fits, bending_curvature_at
   public :: check_line_results
   public :: row_len, units_si

   integer, parameter :: row_len = 1024    !< longest CSV row (19 fields of <= 26 characters)
   character(len=*), parameter :: units_si = 'SI: m, s, kg, N, N m, rad' !< root `units`

   ! What a line's table has a row for
   integer, parameter :: per_line = 1, per_node = 2, per_point = 3, per_end = 4

   ! Where each column comes from: the row's head, then the values
   integer, parameter :: c_line = 1, c_node = 2, c_element = 3, c_point = 4, &
      c_s = 5, c_end = 6, c_x = 7, c_y = 8, c_z = 9, c_seabed_normal = 10, &
      c_seabed_friction = 11, c_tension = 12, c_wall_tension = 13, c_shear_1 = 14, &
      c_shear_2 = 15, c_moment_1 = 16, c_moment_2 = 17, c_torque = 18, c_curvature_1 = 19, &
      c_curvature_2 = 20, c_twist = 21, c_bending = 22, c_fx = 23, c_mz = 28, &
      c_end_tension = 29, c_length = 30, c_touchdown = 31, n_codes = 31
   integer, parameter :: last_head = c_end !< codes up to this one are the row's head
   character(len=*), parameter :: column_name(n_codes) = [character(len=23) :: 'line', &
      'node', 'element', 'point', 's_m', 'end', 'x_m', 'y_m', 'z_m', &
      'seabed_normal_N_per_m', 'seabed_friction_N_per_m', 'effective_tension_N', &
      'wall_tension_N', 'shear_1_N', 'shear_2_N', 'moment_1_Nm', 'moment_2_Nm', &
      'torque_Nm', 'curvature_1_per_m', 'curvature_2_per_m', 'twist_per_m', &
      'curvature_per_m', 'Fx_N', 'Fy_N', 'Fz_N', 'Mx_Nm', 'My_Nm', 'Mz_Nm', 'tension_N', &
      'length_m', 'touchdown_s_m']
   ! the rows each column can be written for (0: any)
   integer, parameter :: column_per(n_codes) = [0, per_node, per_point, per_point, 0, &
      per_end, per_node, per_node, per_node, per_node, per_node, per_point, per_point, &
      per_point, per_point, per_point, per_point, per_point, per_point, per_point, &
      per_point, per_point, per_end, per_end, per_end, per_end, per_end, per_end, &
      per_end, per_line, per_line]

   !> A line's table laid out from the schema (line_table).
   type :: line_table_t
      character(len=:), allocatable :: file  !< 'static_nodes.csv', ...
      integer :: per = per_line              !< a row per line, node, point or held end
      integer :: n_lead = 0                  !< leading columns the caller writes
      integer, allocatable :: head(:)        !< c_* of the head's columns
      integer, allocatable :: value(:)       !< c_* of the value columns
   end type line_table_t

contains

   ! ------------------------------------------------------------------ line tables

   !> The layout of CSV table `file` from its columns in rodyn_output_schema: leading
   !> 'step' and 'time_s' are the caller's, then the head's and the values' columns.
   !> An unknown table or a column this module cannot fill is an error.
   function line_table(file, err) result(t)
      character(len=*), intent(in) :: file  !< 'static_nodes.csv', 'dynamic_ends.csv', ...
      type(error_t), intent(inout) :: err   !< status
      type(line_table_t) :: t               !< its layout
      character(len=:), allocatable :: name
      integer :: k, c
      t%file = file
      allocate (t%head(0), t%value(0))
      do k = 1, size(output_columns)
         if (schema_field(output_columns(k), 1) /= file) cycle
         name = schema_field(output_columns(k), 2)
         if ((name == 'step' .or. name == 'time_s') .and. size(t%head) == 0) then
            t%n_lead = t%n_lead + 1
            cycle
         end if
         c = n_codes
         do while (c > 0)
            if (column_name(c) == name) exit   ! (findloc: gfortran 12 compares unpadded)
            c = c - 1
         end do
         if (c == 0) then
            call fail('has no source')
            return
         end if
         if (c == c_node) t%per = per_node
         if (c == c_element) t%per = per_point
         if (c == c_end) t%per = per_end
         if (c <= last_head) then
            if (size(t%value) > 0) then
               call fail('follows a value column')
               return
            end if
            t%head = [t%head, c]
         else
            t%value = [t%value, c]
         end if
      end do
      if (size(t%head) == 0) then
         call set_error(err, stat_io, 'line_table: '//file//' is not a line''s table '// &
            'in rodyn_output_schema')
         return
      end if
      do k = 1, size(t%head) + size(t%value)
         if (k <= size(t%head)) then
            c = t%head(k)
         else
            c = t%value(k - size(t%head))
         end if
         if (column_per(c) /= 0 .and. column_per(c) /= t%per) then
            name = trim(column_name(c))
            call fail('is not of its rows')
            return
         end if
      end do
   contains
      !> Column `name` of `file` cannot be written.
      subroutine fail(why)
         character(len=*), intent(in) :: why   !< the reason
         call set_error(err, stat_io, 'line_table: column '//name//' of '//file//' '// &
            why//' in rodyn_output_table')
      end subroutine fail
   end function line_table

   !> The rows of line r in table t: nodes, points, 2 (ends; line_row_kept tells the
   !> held ones) or 1.
   pure integer function line_rows(t, r)
      type(line_table_t), intent(in) :: t    !< layout
      type(line_result_t), intent(in) :: r   !< the line (node_s, gp_s allocated)
      select case (t%per)
      case (per_node)
         line_rows = size(r%node_s)
      case (per_point)
         line_rows = size(r%gp_s)
      case (per_end)
         line_rows = 2
      case default
         line_rows = 1
      end select
   end function line_rows

   !> Whether row k of a line is written: every row but those of an end not held.
   pure logical function line_row_kept(t, end_held, k)
      type(line_table_t), intent(in) :: t    !< layout
      logical, intent(in) :: end_held(2)     !< the line's ends A, B carry a support
      integer, intent(in) :: k               !< row, 1 to line_rows
      line_row_kept = .true.
      if (t%per == per_end) line_row_kept = end_held(k)
   end function line_row_kept

   !> The head of row k of line r: its fields, each preceded by ',' (',CABLE,3,1.5E+00').
   function line_row_head(t, r, k) result(s)
      type(line_table_t), intent(in) :: t    !< layout
      type(line_result_t), intent(in) :: r   !< the line
      integer, intent(in) :: k               !< row, 1 to line_rows
      character(len=:), allocatable :: s     !< the head
      character(len=*), parameter :: end_name = 'AB'
      character(len=row_len) :: row
      integer :: j, n
      row(1:1) = ' '        ! (non-empty: put_* write a ',' before each field)
      n = 1
      do j = 1, size(t%head)
         select case (t%head(j))
         case (c_line)
            call put_text(row, n, ','//csv_name(r%name))
         case (c_node)
            call put_int(row, n, k)
         case (c_element)
            call put_int(row, n, r%gp_element(k))
         case (c_point)
            call put_int(row, n, r%gp_point(k))
         case (c_s)
            if (t%per == per_node) then
               call put_real(row, n, r%node_s(k))
            else
               call put_real(row, n, r%gp_s(k))
            end if
         case (c_end)
            call put_text(row, n, ','//end_name(k:k))
         end select
      end do
      s = row(2:n)
   end function line_row_head

   !> Append the values of row k of line r to row(1:n), each preceded by ','.
   subroutine put_line_values(t, r, k, row, n)
      type(line_table_t), intent(in) :: t     !< layout
      type(line_result_t), intent(in) :: r    !< the line, sizes checked
      integer, intent(in) :: k                !< row, 1 to line_rows
      character(len=*), intent(inout) :: row  !< row being built
      integer, intent(inout) :: n             !< characters used
      real(wp) :: v(n_codes)
      call line_row_values(t, r, k, v)
      call put_reals(row, n, v(1:size(t%value)))
   end subroutine put_line_values

   !> Append the values of an end's row (a per_end table) to row(1:n), each preceded by
   !> ',': the support force and moment `reaction` and the force's magnitude.
   subroutine put_end_values(t, reaction, row, n)
      type(line_table_t), intent(in) :: t     !< layout (per_end)
      real(wp), intent(in) :: reaction(6)     !< Fx, Fy, Fz, Mx, My, Mz [N, N m]
      character(len=*), intent(inout) :: row  !< row being built
      integer, intent(inout) :: n             !< characters used
      real(wp) :: v(n_codes)
      call end_row_values(t, reaction, v)
      call put_reals(row, n, v(1:size(t%value)))
   end subroutine put_end_values

   !> The values of row k of line r, v(1:size(t%value)), as the module header gives them.
   pure subroutine line_row_values(t, r, k, v)
      type(line_table_t), intent(in) :: t     !< layout
      type(line_result_t), intent(in) :: r    !< the line, sizes checked
      integer, intent(in) :: k                !< row, 1 to line_rows
      real(wp), intent(out) :: v(:)           !< values (at least size(t%value))
      integer :: j
      if (t%per == per_end) then
         call end_row_values(t, r%reaction(:, k), v)
         return
      end if
      do j = 1, size(t%value)
         select case (t%value(j))
         case (c_x:c_z)
            v(j) = r%node_x(t%value(j) - c_x + 1, k)
         case (c_seabed_normal)
            v(j) = 0.0_wp
            if (allocated(r%seabed_normal)) v(j) = r%seabed_normal(k)
         case (c_seabed_friction)
            v(j) = 0.0_wp
            if (allocated(r%seabed_friction)) v(j) = r%seabed_friction(k)
         case (c_tension)
            v(j) = r%tension(k)
         case (c_wall_tension)
            v(j) = r%tension(k)
            if (allocated(r%wall_tension)) v(j) = r%wall_tension(k)
         case (c_shear_1, c_shear_2)
            v(j) = r%shear(t%value(j) - c_shear_1 + 1, k)
         case (c_moment_1, c_moment_2)
            v(j) = r%moment(t%value(j) - c_moment_1 + 1, k)
         case (c_torque)
            v(j) = r%torque(k)
         case (c_curvature_1:c_twist)
            v(j) = r%curvature(t%value(j) - c_curvature_1 + 1, k)
         case (c_bending)
            v(j) = bending_curvature_at(r%curvature(:, k))
         case (c_length)
            v(j) = r%node_s(size(r%node_s))
         case (c_touchdown)
            v(j) = touchdown_of(r)
         end select
      end do
   end subroutine line_row_values

   !> The values of an end's row, v(1:size(t%value)): the support force and moment
   !> `reaction` and the force's magnitude |reaction(1:3)|.
   pure subroutine end_row_values(t, reaction, v)
      type(line_table_t), intent(in) :: t     !< layout (per_end)
      real(wp), intent(in) :: reaction(6)     !< Fx, Fy, Fz, Mx, My, Mz [N, N m]
      real(wp), intent(out) :: v(:)           !< values (at least size(t%value))
      integer :: j
      do j = 1, size(t%value)
         if (t%value(j) == c_end_tension) then
            v(j) = norm2(reaction(1:3))
         else
            v(j) = reaction(t%value(j) - c_fx + 1)
         end if
      end do
   end subroutine end_row_values

   !> Write line table `file` whole (a one-shot table: no leading columns) into folder
   !> `dir`: header from the schema, then the rows of each line; temporary file, renamed
   !> into place when written whole (rodyn_outfile).
   subroutine write_line_table(dir, file, lines, err)
      character(len=*), intent(in) :: dir         !< output folder
      character(len=*), intent(in) :: file        !< 'static_nodes.csv', ...
      type(line_result_t), intent(in) :: lines(:) !< results, sizes checked
      type(error_t), intent(inout) :: err         !< status
      type(line_table_t) :: t
      type(out_file_t) :: f
      character(len=row_len) :: row
      character(len=:), allocatable :: head
      integer :: i, k, n
      if (has_error(err)) return
      t = line_table(file, err)
      if (has_error(err)) return
      call outfile_create(f, dir, file, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(file))
      do i = 1, size(lines)
         do k = 1, line_rows(t, lines(i))
            if (.not. line_row_kept(t, lines(i)%end_held, k)) cycle
            head = line_row_head(t, lines(i), k)
            n = 0
            call put_text(row, n, head(2:))
            call put_line_values(t, lines(i), k, row, n)
            call outfile_put(f, row(:n))
         end do
      end do
      call outfile_commit(f, err)
   end subroutine write_line_table

   !> Bending curvature sqrt(K1^2 + K2^2) of one point [1/m]: the tables' and
   !> dynamic.h5's, one code path so that both hold the same bits.
   pure real(wp) function bending_curvature_at(curv)
      real(wp), intent(in) :: curv(3)     !< curvatures K1, K2, K3 [1/m]
      bending_curvature_at = hypot(curv(1), curv(2))
   end function bending_curvature_at

   ! ------------------------------------------------------------------ line results

   !> Check that every line's arrays are allocated with consistent sizes; err names the
   !> caller `who` and the first line that is not.
   subroutine check_line_results(lines, who, err)
      type(line_result_t), intent(in) :: lines(:) !< results
      character(len=*), intent(in) :: who         !< the caller, for the message
      type(error_t), intent(inout) :: err         !< status
      integer :: i
      do i = 1, size(lines)
         if (.not. line_result_complete(lines(i))) then
            call set_error(err, stat_io, who//': results of line '''// &
               trim(lines(i)%name)//''' are missing or of inconsistent sizes')
            return
         end if
      end do
   end subroutine check_line_results

   !> Whether every array of a line result is allocated with consistent sizes.
   pure logical function line_result_complete(r)
      type(line_result_t), intent(in) :: r  !< line result
      integer :: nn, ng
      line_result_complete = allocated(r%node_s) .and. allocated(r%gp_element) .and. &
         allocated(r%gp_point) .and. allocated(r%gp_s) .and. allocated(r%shear)
      if (.not. line_result_complete) return
      nn = size(r%node_s)
      ng = size(r%gp_s)
      line_result_complete = size(r%gp_element) == ng .and. size(r%gp_point) == ng .and. &
         all(shape(r%shear) == [2, ng]) .and. line_result_fits(r, nn, ng)
   end function line_result_complete

   !> Whether the arrays a frame writes are allocated for nn nodes and ng points.
   pure logical function line_result_fits(r, nn, ng)
      type(line_result_t), intent(in) :: r  !< line result
      integer, intent(in) :: nn             !< nodes
      integer, intent(in) :: ng             !< integration points
      line_result_fits = allocated(r%node_x) .and. allocated(r%tension) .and. &
         allocated(r%moment) .and. allocated(r%torque) .and. allocated(r%curvature)
      if (.not. line_result_fits) return
      line_result_fits = all(shape(r%node_x) == [3, nn]) .and. size(r%tension) == ng .and. &
         all(shape(r%moment) == [2, ng]) .and. size(r%torque) == ng .and. &
         all(shape(r%curvature) == [3, ng]) .and. water_fields_fit(r, nn, ng)
   end function line_result_fits

   ! ------------------------------------------------------------------ HDF5

   !> HDF5 group name of line i: its name with '/' replaced by '_'; 'line_<i>' if blank
   !> or one of the names `reserved` (the other members of its parent group: 'time',
   !> 'log', 'sea' in /dynamic; deck names are upper case, so a deck never hits them).
   pure function group_name(name, i, reserved) result(s)
      character(len=*), intent(in) :: name                  !< line name
      integer, intent(in) :: i                              !< line number
      character(len=*), intent(in), optional :: reserved(:) !< names taken
      character(len=:), allocatable :: s                    !< group name
      character(len=16) :: buf
      integer :: k, n
      logical :: taken
      s = trim(name)
      taken = len(s) == 0 .or. s == '.'
      if (present(reserved)) taken = taken .or. any(reserved == s)
      if (taken) then
         n = 0
         call put_int(buf, n, i)
         s = 'line_'//buf(:n)
      end if
      do k = 1, len(s)
         if (s(k:k) == '/') s(k:k) = '_'
      end do
   end function group_name

   !> Start the group g of line r in HDF5 file `file` (its schema name): the group, its
   !> attribute name, and the nodes' arc lengths node_s.
   subroutine start_line_group(h5, file, g, r, err)
      type(hdf5_file_t), intent(in) :: h5    !< open file
      character(len=*), intent(in) :: file   !< 'results.h5', 'dynamic.h5'
      character(len=*), intent(in) :: g      !< group path
      type(line_result_t), intent(in) :: r   !< the line
      type(error_t), intent(inout) :: err    !< status
      call hdf5_create_group(h5, g, err)
      call hdf5_write_attribute(h5, g, 'name', trim(r%name), err)
      call write_described(h5, file, g//'/node_s', err, g, x1=r%node_s)
   end subroutine start_line_group

   !> The root attributes both HDF5 files start with: program, version, deck_file,
   !> title, units, complete (0/1) and status.
   subroutine write_h5_root(h5, model, complete, status, err)
      type(hdf5_file_t), intent(in) :: h5          !< open file
      type(model_t), intent(in) :: model           !< model (deck file, title)
      logical, intent(in) :: complete              !< attribute complete
      character(len=*), intent(in) :: status       !< attribute status
      type(error_t), intent(inout) :: err          !< status of the writing
      call hdf5_write_attribute(h5, '/', 'program', 'rodyn', err)
      call hdf5_write_attribute(h5, '/', 'version', rodyn_version, err)
      call hdf5_write_attribute(h5, '/', 'deck_file', text_or(model%deck_file, ''), err)
      call hdf5_write_attribute(h5, '/', 'title', text_or(model%title, ''), err)
      call hdf5_write_attribute(h5, '/', 'units', units_si, err)
      call hdf5_write_attribute(h5, '/', 'complete', merge(1, 0, complete), err)
      call hdf5_write_attribute(h5, '/', 'status', status, err)
   end subroutine write_h5_root

   !> Write dataset `path` of file `file` (its schema name), its values the one of
   !> x1 (real 1-D), x2 (real 2-D), i1 (integer 1-D) or text given, and attach the
   !> `units` and `description` rodyn_output_schema gives it.
   subroutine write_described(h5, file, path, err, line_group, x1, x2, i1, text)
      type(hdf5_file_t), intent(in) :: h5                  !< open file
      character(len=*), intent(in) :: file                 !< 'results.h5', 'dynamic.h5'
      character(len=*), intent(in) :: path                 !< dataset path
      type(error_t), intent(inout) :: err                  !< status
      character(len=*), intent(in), optional :: line_group !< group of the line, if any
      real(wp), intent(in), optional :: x1(:)              !< real values
      real(wp), intent(in), optional :: x2(:, :)           !< real table
      integer, intent(in), optional :: i1(:)               !< integer values
      character(len=*), intent(in), optional :: text       !< a text
      character(len=schema_len) :: texts(2)
      call dataset_texts(file, path, texts, err, line_group)
      if (has_error(err)) return
      if (present(x1)) call hdf5_write_dataset(h5, path, x1, err, described, texts)
      if (present(x2)) call hdf5_write_dataset(h5, path, x2, err, described, texts)
      if (present(i1)) call hdf5_write_dataset(h5, path, i1, err, described, texts)
      if (present(text)) call hdf5_write_dataset(h5, path, text, err, described, texts)
   end subroutine write_described

   !> An empty time history (rows appended later, rodyn_hdf5's series) of `n_cols` values
   !> a row (0: a 1-D series, one value a row) with its units and description.
   subroutine create_described_series(h5, file, path, n_cols, err, chunk_steps, &
                                      line_group, integers, series)
      type(hdf5_file_t), intent(in) :: h5                  !< open file
      character(len=*), intent(in) :: file                 !< 'dynamic.h5'
      character(len=*), intent(in) :: path                 !< dataset path
      integer, intent(in) :: n_cols                        !< values a row; 0: 1-D
      type(error_t), intent(inout) :: err                  !< status
      integer, intent(in) :: chunk_steps                   !< rows per HDF5 chunk
      character(len=*), intent(in), optional :: line_group !< group of the line, if any
      logical, intent(in), optional :: integers            !< 1-D integer series
      type(hdf5_series_t), intent(inout), optional :: series !< kept open (hdf5_create_series)
      character(len=schema_len) :: texts(2)
      call dataset_texts(file, path, texts, err, line_group)
      if (has_error(err)) return
      if (n_cols == 0) then
         call hdf5_create_series_1d(h5, path, err, chunk_steps=chunk_steps, &
                                    integers=integers, names=described, texts=texts, &
                                    series=series)
      else
         call hdf5_create_series(h5, path, n_cols, err, chunk_steps=chunk_steps, &
                                 names=described, texts=texts, series=series)
      end if
   end subroutine create_described_series
end module rodyn_output_table
