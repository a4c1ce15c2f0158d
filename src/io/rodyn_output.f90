!> Output writers: the static results as CSV tables and an HDF5 file, and the run's
!> status file. The layout of every file is documented in docs/output.md.
!>
!> Every file is first written under a hidden temporary name in the output folder
!> ('.static_nodes.csv.tmp') and renamed into place only when written whole and closed
!> without error (rodyn_outfile, which checks every write), so a reader never sees a
!> half-written file. The folder is created (with its parents) if missing. status.txt
!> is written last and says complete = true only when every file was written.
module rodyn_output
   use rodyn_kinds, only: wp, i8, rodyn_version
   use rodyn_error, only: error_t, set_error, has_error, stat_io
   use rodyn_model, only: model_t, parameter_value_t
   use rodyn_results, only: line_result_t, run_summary_t
   use rodyn_outfile, only: out_file_t, outfile_create, outfile_put, outfile_commit, &
      temp_name, commit_rename, remove_file
   use rodyn_outdir, only: outdir_make
   use rodyn_output_schema, only: schema_header
   use rodyn_hdf5, only: hdf5_file_t, hdf5_create_file, hdf5_close_file, &
      hdf5_create_group, hdf5_write_dataset, hdf5_write_attribute
   use rodyn_output_common, only: text_of, status_of, path_join, one_line, &
                                  describe_dataset, csv_name, env_item_t, environment_items, &
                                  write_environment_h5, wall_tension_of, seabed_force_of, &
                                  water_fields_fit, touchdown_of, write_parameters_h5
   implicit none
   private
   public :: output_write_static, output_write_status, output_write_environment
   public :: committed_t

   !> The committed size of a table that grows while a run goes: status.txt's key
   !> 'committed_bytes.<name>' (docs/output.md). A reader trusts the first `bytes` bytes
   !> of the file; anything beyond is an uncommitted tail (a kill inside a sync).
   type :: committed_t
      character(len=:), allocatable :: name  !< file name, 'dynamic_nodes.csv'
      integer(i8) :: bytes = 0_i8            !< bytes committed at the last sync
   end type committed_t

   character(len=*), parameter :: nodes_csv = 'static_nodes.csv'
   character(len=*), parameter :: elements_csv = 'static_elements.csv'
   character(len=*), parameter :: reactions_csv = 'static_reactions.csv'
   character(len=*), parameter :: lines_csv = 'static_lines.csv'
   character(len=*), parameter :: environment_csv = 'environment.csv'
   character(len=*), parameter :: results_h5 = 'results.h5'
   character(len=*), parameter :: status_txt = 'status.txt'
   character(len=*), parameter :: units_si = 'SI: m, s, kg, N, N m, rad'


contains

   ! ------------------------------------------------------------------ public

   !> Write the static results into folder `dir`: the CSV tables and results.h5 as
   !> model%output asks, then status.txt (always). With summary%complete false the
   !> lines hold the last converged state and status.txt says how far the run got.
   !> Works even when err already holds an error (a failed analysis still writes its
   !> outputs); an output failure is then recorded only if err was clear.
   subroutine output_write_static(dir, model, lines, summary, err)
      character(len=*), intent(in) :: dir            !< output folder (created if missing)
      type(model_t), intent(in) :: model             !< the model (title, deck, options)
      type(line_result_t), intent(in) :: lines(:)    !< static results per line
      type(run_summary_t), intent(in) :: summary     !< how the run went
      type(error_t), intent(inout) :: err            !< status
      ! the files in the order written (after environment.csv, results.h5)
      character(len=*), parameter :: order(*) = [character(len=20) :: nodes_csv, &
         elements_csv, reactions_csv, lines_csv, environment_csv, results_h5]
      type(error_t) :: e, e_status
      type(run_summary_t) :: s
      integer :: k, j
      call outdir_make(dir, e)
      if (has_error(e)) then
         call set_error(err, e%code, e%message)
         return
      end if
      call check_lines(lines, e)
      k = 0
      do while (k < size(order) .and. .not. has_error(e))
         k = k + 1
         select case (k)
         case (1)
            if (model%output%csv) call write_nodes_csv(dir, lines, e)
         case (2)
            if (model%output%csv) call write_elements_csv(dir, lines, e)
         case (3)
            if (model%output%csv) call write_reactions_csv(dir, lines, e)
         case (4)
            if (model%output%csv) call write_lines_csv(dir, lines, e)
         case (5)
            if (model%output%csv) call output_write_environment(dir, model, e)
         case (6)
            if (model%output%hdf5) call write_results_h5(dir, model, lines, summary, e)
         end select
      end do
      ! status.txt last, and true: not complete when a file could not be written
      s = summary
      if (has_error(e)) then
         s%complete = .false.
         s%status = e%message
         ! the file that failed is gone; no older file stands for those not written
         do j = max(k, 1), size(order)
            if (merge(model%output%hdf5, model%output%csv, j == size(order))) &
               call remove_file(path_join(dir, trim(order(j))))
         end do
      end if
      call output_write_status(dir, s, e_status, deck_file=text_of(model%deck_file), &
                               params=model%parameters)
      if (has_error(e)) call set_error(err, e%code, e%message)
      if (has_error(e_status)) call set_error(err, e_status%code, e_status%message)
   end subroutine output_write_static

   !> Write only status.txt into folder `dir` (created if missing): for a run that
   !> stops before it has results to write, and for the dynamic writer (which adds the
   !> keys dynamic ... step_cutbacks when summary%dynamic is true). Acts even when err
   !> already holds an error. The deck parameters `params` (if any) follow the key deck,
   !> one line 'parameter.NAME = text' each. The committed sizes of a dynamic run's
   !> tables `committed` (if any) follow the dynamic keys (frames, then one line
   !> 'committed_bytes.NAME = bytes' each).
   subroutine output_write_status(dir, summary, err, deck_file, params, committed)
      character(len=*), intent(in) :: dir                 !< output folder
      type(run_summary_t), intent(in) :: summary          !< how the run went
      type(error_t), intent(inout) :: err                 !< status
      character(len=*), intent(in), optional :: deck_file !< path of the deck
      type(parameter_value_t), intent(in), optional :: params(:) !< deck parameters used
      type(committed_t), intent(in), optional :: committed(:) !< sizes of live tables
      type(error_t) :: e
      type(out_file_t) :: f
      integer :: k, attempt
      call outdir_make(dir, e)
      do attempt = 1, 2
         if (attempt == 2) then
            ! a full disk: the old status.txt goes first, to make room for the new one
            call remove_file(path_join(dir, status_txt))
            e = error_t()
         end if
         call outfile_create(f, dir, status_txt, e)
         if (.not. has_error(e)) then
            call outfile_put(f, 'complete = '//trim(merge('true ', 'false', summary%complete)))
            call outfile_put(f, 'status = '//one_line(status_of(summary)))
            call outfile_put(f, 'load_factor = '//real_str(summary%load_factor))
            call outfile_put(f, 'increments = '//int_str(summary%increments))
            call outfile_put(f, 'iterations = '//int_str(summary%iterations))
            call outfile_put(f, 'cutbacks = '//int_str(summary%cutbacks))
            call outfile_put(f, 'wall_time_s = '//real_str(summary%wall_time))
            if (summary%dynamic) then
               call outfile_put(f, 'dynamic = true')
               call outfile_put(f, 'time_reached_s = '//real_str(summary%time_reached))
               call outfile_put(f, 'steps = '//int_str(summary%steps))
               call outfile_put(f, 'step_iterations = '//int_str(summary%step_iterations))
               call outfile_put(f, 'step_tangents = '//int_str(summary%step_tangents))
               call outfile_put(f, 'step_cutbacks = '//int_str(summary%step_cutbacks))
               call outfile_put(f, 'frames = '//int_str(summary%frames))
               if (present(committed)) then
                  do k = 1, size(committed)
                     call outfile_put(f, 'committed_bytes.'//committed(k)%name//' = '// &
                        int8_str(committed(k)%bytes))
                  end do
               end if
            end if
            call outfile_put(f, 'rodyn_version = '//rodyn_version)
            if (present(deck_file)) then
               call outfile_put(f, 'deck = '//one_line(deck_file))
            else
               call outfile_put(f, 'deck = ')
            end if
            if (present(params)) then
               do k = 1, size(params)
                  call outfile_put(f, 'parameter.'//params(k)%name//' = '// &
                     one_line(params(k)%text))
               end do
            end if
            call outfile_commit(f, e)
         end if
         if (.not. has_error(e)) exit
      end do
      if (has_error(e)) then
         ! no status.txt rather than one that is not this run's, or not true
         call remove_file(path_join(dir, status_txt))
         call set_error(err, e%code, e%message)
      end if
   end subroutine output_write_status

   !> Write environment.csv into folder `dir` (key, value, unit rows of the sea, current
   !> and seabed; docs/output.md) when the model has water; for a dry model remove an
   !> environment.csv an earlier run left there, so that plots never draw a stale sea.
   !> Written as the static tables are (temporary file, then rename).
   subroutine output_write_environment(dir, model, err)
      character(len=*), intent(in) :: dir         !< output folder (exists)
      type(model_t), intent(in) :: model          !< model (water, seabed)
      type(error_t), intent(inout) :: err         !< status
      type(env_item_t), allocatable :: items(:)
      type(out_file_t) :: f
      integer :: k
      if (has_error(err)) return
      if (.not. model%water%present) then
         call remove_file(path_join(dir, environment_csv))
         return
      end if
      items = environment_items(model)
      call outfile_create(f, dir, environment_csv, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(environment_csv))
      do k = 1, size(items)
         call outfile_put(f, items(k)%key//','//real_str(items(k)%value)//','// &
            items(k)%unit)
      end do
      call outfile_commit(f, err)
   end subroutine output_write_environment

   ! ------------------------------------------------------------------ CSV tables

   !> static_nodes.csv: one row per node, numbered from 1 along each line, with the
   !> seabed contact force per length.
   subroutine write_nodes_csv(dir, lines, err)
      character(len=*), intent(in) :: dir         !< output folder
      type(line_result_t), intent(in) :: lines(:) !< results
      type(error_t), intent(inout) :: err         !< status
      real(wp), allocatable :: fn(:), ff(:)
      type(out_file_t) :: f
      integer :: i, k
      if (has_error(err)) return
      call outfile_create(f, dir, nodes_csv, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(nodes_csv))
      do i = 1, size(lines)
         fn = seabed_force_of(lines(i), 1)
         ff = seabed_force_of(lines(i), 2)
         do k = 1, size(lines(i)%node_s)
            call outfile_put(f, csv_name(lines(i)%name)//','//int_str(k)//','// &
               reals_str([lines(i)%node_s(k), lines(i)%node_x(:, k), fn(k), ff(k)]))
         end do
      end do
      call outfile_commit(f, err)
   end subroutine write_nodes_csv

   !> static_elements.csv: section forces and strains, one row per integration point.
   subroutine write_elements_csv(dir, lines, err)
      character(len=*), intent(in) :: dir         !< output folder
      type(line_result_t), intent(in) :: lines(:) !< results
      type(error_t), intent(inout) :: err         !< status
      real(wp), allocatable :: tw(:)
      type(out_file_t) :: f
      integer :: i, k
      if (has_error(err)) return
      call outfile_create(f, dir, elements_csv, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(elements_csv))
      do i = 1, size(lines)
         associate (r => lines(i))
            tw = wall_tension_of(r)
            do k = 1, size(r%gp_s)
               call outfile_put(f, csv_name(r%name)//','//int_str(r%gp_element(k))//','// &
                  int_str(r%gp_point(k))//','//reals_str([r%gp_s(k), r%tension(k), tw(k), &
                  r%shear(:, k), r%moment(:, k), r%torque(k), r%curvature(:, k), &
                  hypot(r%curvature(1, k), r%curvature(2, k))]))
            end do
         end associate
      end do
      call outfile_commit(f, err)
   end subroutine write_elements_csv

   !> static_reactions.csv: force and moment of each support on the line, global axes.
   subroutine write_reactions_csv(dir, lines, err)
      character(len=*), intent(in) :: dir         !< output folder
      type(line_result_t), intent(in) :: lines(:) !< results
      type(error_t), intent(inout) :: err         !< status
      character(len=1), parameter :: end_name(2) = ['A', 'B']
      type(out_file_t) :: f
      integer :: i, j
      if (has_error(err)) return
      call outfile_create(f, dir, reactions_csv, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(reactions_csv))
      do i = 1, size(lines)
         do j = 1, 2
            if (.not. lines(i)%end_held(j)) cycle
            call outfile_put(f, csv_name(lines(i)%name)//','//end_name(j)//','// &
               reals_str([lines(i)%reaction(:, j), norm2(lines(i)%reaction(1:3, j))]))
         end do
      end do
      call outfile_commit(f, err)
   end subroutine write_reactions_csv

   !> static_lines.csv: one row per line: unstretched length and touchdown point
   !> (largest arc length in contact with the seabed; -1 when none touches).
   subroutine write_lines_csv(dir, lines, err)
      character(len=*), intent(in) :: dir         !< output folder
      type(line_result_t), intent(in) :: lines(:) !< results
      type(error_t), intent(inout) :: err         !< status
      type(out_file_t) :: f
      integer :: i
      if (has_error(err)) return
      call outfile_create(f, dir, lines_csv, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(lines_csv))
      do i = 1, size(lines)
         associate (r => lines(i))
            call outfile_put(f, csv_name(r%name)//','//reals_str([r%node_s(size(r%node_s)), &
               touchdown_of(r)]))
         end associate
      end do
      call outfile_commit(f, err)
   end subroutine write_lines_csv

   ! ------------------------------------------------------------------ HDF5

   !> results.h5: root attributes, /deck, /static and one group per line.
   subroutine write_results_h5(dir, model, lines, summary, err)
      character(len=*), intent(in) :: dir         !< output folder
      type(model_t), intent(in) :: model          !< the model
      type(line_result_t), intent(in) :: lines(:) !< results
      type(run_summary_t), intent(in) :: summary  !< how the run went
      type(error_t), intent(inout) :: err         !< status
      type(hdf5_file_t) :: h5
      character(len=:), allocatable :: tmp
      integer :: i
      if (has_error(err)) return
      tmp = temp_name(dir, results_h5)
      call hdf5_create_file(h5, tmp, err)
      call hdf5_write_attribute(h5, '/', 'program', 'rodyn', err)
      call hdf5_write_attribute(h5, '/', 'version', rodyn_version, err)
      call hdf5_write_attribute(h5, '/', 'deck_file', text_of(model%deck_file), err)
      call hdf5_write_attribute(h5, '/', 'title', text_of(model%title), err)
      call hdf5_write_attribute(h5, '/', 'units', units_si, err)
      call hdf5_write_attribute(h5, '/', 'complete', merge(1, 0, summary%complete), err)
      call hdf5_write_attribute(h5, '/', 'status', one_line(status_of(summary)), err)
      call hdf5_write_dataset(h5, '/deck', text_of(model%deck_text), err)
      call describe_dataset(h5, results_h5, '/deck', err)
      call hdf5_create_group(h5, '/static', err)
      call hdf5_write_attribute(h5, '/static', 'load_factor', summary%load_factor, err)
      call hdf5_write_attribute(h5, '/static', 'increments', summary%increments, err)
      call hdf5_write_attribute(h5, '/static', 'iterations', summary%iterations, err)
      call hdf5_write_attribute(h5, '/static', 'cutbacks', summary%cutbacks, err)
      call hdf5_write_attribute(h5, '/static', 'wall_time_s', summary%wall_time, err)
      call write_environment_h5(h5, model, err)
      call write_parameters_h5(h5, model, err)
      do i = 1, size(lines)
         call write_h5_line(h5, '/static/'//group_name(lines(i)%name, i), lines(i), err)
      end do
      call hdf5_close_file(h5, err)
      if (.not. has_error(err)) call commit_rename(tmp, path_join(dir, results_h5), err)
      if (has_error(err)) then
         if (index(err%message, path_join(dir, results_h5)//'''') == 0) err%message = &
            'cannot write '''//path_join(dir, results_h5)//''': '//err%message
         ! nothing incomplete, nor an older results.h5, next to this run's status.txt
         call remove_file(tmp)
         call remove_file(path_join(dir, results_h5))
      end if
   end subroutine write_results_h5

   !> One line's group: node and integration-point datasets and the reactions.
   subroutine write_h5_line(h5, g, r, err)
      type(hdf5_file_t), intent(in) :: h5       !< open file
      character(len=*), intent(in) :: g         !< group path
      type(line_result_t), intent(in) :: r      !< results of the line
      type(error_t), intent(inout) :: err       !< status
      call hdf5_create_group(h5, g, err)
      call hdf5_write_attribute(h5, g, 'name', trim(r%name), err)
      call hdf5_write_dataset(h5, g//'/node_s', r%node_s, err)
      call describe_dataset(h5, results_h5, g//'/node_s', err, line_group=g)
      call hdf5_write_dataset(h5, g//'/node_xyz', r%node_x, err)
      call describe_dataset(h5, results_h5, g//'/node_xyz', err, line_group=g)
      call hdf5_write_dataset(h5, g//'/gp_element', r%gp_element, err)
      call describe_dataset(h5, results_h5, g//'/gp_element', err, line_group=g)
      call hdf5_write_dataset(h5, g//'/gp_point', r%gp_point, err)
      call describe_dataset(h5, results_h5, g//'/gp_point', err, line_group=g)
      call hdf5_write_dataset(h5, g//'/gp_s', r%gp_s, err)
      call describe_dataset(h5, results_h5, g//'/gp_s', err, line_group=g)
      call hdf5_write_attribute(h5, g, 'touchdown_s', touchdown_of(r), err)
      call hdf5_write_dataset(h5, g//'/effective_tension', r%tension, err)
      call describe_dataset(h5, results_h5, g//'/effective_tension', err, line_group=g)
      call hdf5_write_dataset(h5, g//'/wall_tension', wall_tension_of(r), err)
      call describe_dataset(h5, results_h5, g//'/wall_tension', err, line_group=g)
      call hdf5_write_dataset(h5, g//'/shear', r%shear, err)
      call describe_dataset(h5, results_h5, g//'/shear', err, line_group=g)
      call hdf5_write_dataset(h5, g//'/moment', r%moment, err)
      call describe_dataset(h5, results_h5, g//'/moment', err, line_group=g)
      call hdf5_write_dataset(h5, g//'/torque', r%torque, err)
      call describe_dataset(h5, results_h5, g//'/torque', err, line_group=g)
      call hdf5_write_dataset(h5, g//'/curvature', r%curvature, err)
      call describe_dataset(h5, results_h5, g//'/curvature', err, line_group=g)
      call hdf5_write_dataset(h5, g//'/reactions', r%reaction, err)
      call describe_dataset(h5, results_h5, g//'/reactions', err, line_group=g)
      call hdf5_write_attribute(h5, g//'/reactions', 'end_held', &
         merge(1, 0, r%end_held), err)
      call hdf5_write_dataset(h5, g//'/seabed_normal', seabed_force_of(r, 1), err)
      call describe_dataset(h5, results_h5, g//'/seabed_normal', err, line_group=g)
      call hdf5_write_dataset(h5, g//'/seabed_friction', seabed_force_of(r, 2), err)
      call describe_dataset(h5, results_h5, g//'/seabed_friction', err, line_group=g)
   end subroutine write_h5_line



   ! ------------------------------------------------------------------ checks, files

   !> Check that every line's arrays are allocated with consistent sizes.
   subroutine check_lines(lines, err)
      type(line_result_t), intent(in) :: lines(:) !< results
      type(error_t), intent(inout) :: err         !< status
      integer :: i, nn, ng
      logical :: ok
      do i = 1, size(lines)
         associate (r => lines(i))
            ok = allocated(r%node_s) .and. allocated(r%node_x) .and. &
               allocated(r%gp_element) .and. allocated(r%gp_point) .and. &
               allocated(r%gp_s) .and. allocated(r%tension) .and. allocated(r%shear) .and. &
               allocated(r%moment) .and. allocated(r%torque) .and. allocated(r%curvature)
            if (ok) then
               nn = size(r%node_s)
               ng = size(r%gp_s)
               ok = all(shape(r%node_x) == [3, nn]) .and. size(r%gp_element) == ng .and. &
                  size(r%gp_point) == ng .and. size(r%tension) == ng .and. &
                  all(shape(r%shear) == [2, ng]) .and. all(shape(r%moment) == [2, ng]) .and. &
                  size(r%torque) == ng .and. all(shape(r%curvature) == [3, ng]) .and. &
                  water_fields_fit(r, nn, ng)
            end if
            if (.not. ok) then
               call set_error(err, stat_io, 'output_write_static: results of line '''// &
                  trim(r%name)//''' are missing or of inconsistent sizes')
               return
            end if
         end associate
      end do
   end subroutine check_lines

   ! ------------------------------------------------------------------ text helpers


   !> A real with 17 significant digits (round-trips binary64), no blanks, exponent of
   !> two digits unless three are needed: 1.2345678901234567E+05.
   pure function real_str(x) result(s)
      real(wp), intent(in) :: x             !< value
      character(len=:), allocatable :: s    !< text
      character(len=32) :: buf
      integer :: k
      write (buf, '(es25.16e3)') x
      buf = adjustl(buf)
      k = index(buf, 'E')
      if (k > 0) then
         if (buf(k + 2:k + 2) == '0') buf = buf(:k + 1)//buf(k + 3:)
      end if
      s = trim(buf)
   end function real_str

   !> Comma-separated real_str of each value.
   pure function reals_str(x) result(s)
      real(wp), intent(in) :: x(:)          !< values
      character(len=:), allocatable :: s    !< 'x1,x2,...'
      integer :: i
      s = ''
      do i = 1, size(x)
         if (i > 1) s = s//','
         s = s//real_str(x(i))
      end do
   end function reals_str

   !> A 64-bit integer without blanks.
   pure function int8_str(i) result(s)
      integer(i8), intent(in) :: i          !< value
      character(len=:), allocatable :: s    !< text
      character(len=24) :: buf
      write (buf, '(i0)') i
      s = trim(buf)
   end function int8_str

   !> An integer without blanks.
   pure function int_str(i) result(s)
      integer, intent(in) :: i              !< value
      character(len=:), allocatable :: s    !< text
      character(len=16) :: buf
      write (buf, '(i0)') i
      s = trim(buf)
   end function int_str


   !> HDF5 group name of a line: its name with '/' replaced; 'line_<i>' if blank.
   pure function group_name(name, i) result(s)
      character(len=*), intent(in) :: name  !< line name
      integer, intent(in) :: i              !< line number
      character(len=:), allocatable :: s    !< group name
      integer :: k
      s = trim(name)
      if (len(s) == 0 .or. s == '.') s = 'line_'//int_str(i)
      do k = 1, len(s)
         if (s(k:k) == '/') s(k:k) = '_'
      end do
   end function group_name




end module rodyn_output
