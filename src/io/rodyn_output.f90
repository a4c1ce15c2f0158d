!> Output writers: the static results as CSV tables and an HDF5 file, and the run's
!> status file. The layout of every file is documented in docs/output.md.
!>
!> Every file is first written under a hidden temporary name in the output folder
!> ('.static_nodes.csv.tmp') and renamed into place only when complete, so a reader
!> never sees a half-written file. The folder is created (with its parents) if missing.
module rodyn_output
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_ptr, c_null_char, c_associated
   use rodyn_kinds, only: wp, rodyn_version
   use rodyn_error, only: error_t, set_error, has_error, stat_io
   use rodyn_model, only: model_t, parameter_value_t
   use rodyn_results, only: line_result_t, run_summary_t
   use rodyn_hdf5, only: hdf5_file_t, hdf5_create_file, hdf5_close_file, &
      hdf5_create_group, hdf5_write_dataset, hdf5_write_attribute
   use rodyn_output_common, only: text_of, status_of, path_join, one_line, describe, &
                                  csv_name, env_item_t, environment_items, &
                                  write_environment_h5, wall_tension_of, seabed_force_of, &
                                  water_fields_fit, touchdown_of, write_parameters_h5
   implicit none
   private
   public :: output_write_static, output_write_status, output_write_environment

   character(len=*), parameter :: nodes_csv = 'static_nodes.csv'
   character(len=*), parameter :: elements_csv = 'static_elements.csv'
   character(len=*), parameter :: reactions_csv = 'static_reactions.csv'
   character(len=*), parameter :: lines_csv = 'static_lines.csv'
   character(len=*), parameter :: environment_csv = 'environment.csv'
   character(len=*), parameter :: results_h5 = 'results.h5'
   character(len=*), parameter :: status_txt = 'status.txt'
   character(len=*), parameter :: units_si = 'SI: m, s, kg, N, N m, rad'

   interface
      !> POSIX mkdir(2).
      function c_mkdir(path, mode) bind(c, name='mkdir') result(r)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*) !< NUL-terminated path
         integer(c_int), value :: mode                 !< permissions (before umask)
         integer(c_int) :: r                           !< 0, or -1 on failure
      end function c_mkdir
      !> C rename(3): atomic replacement within one file system.
      function c_rename(old, new) bind(c, name='rename') result(r)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: old(*)  !< NUL-terminated source
         character(kind=c_char), intent(in) :: new(*)  !< NUL-terminated destination
         integer(c_int) :: r                           !< 0, or -1 on failure
      end function c_rename
      !> C remove(3).
      function c_remove(path) bind(c, name='remove') result(r)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*) !< NUL-terminated path
         integer(c_int) :: r                           !< 0, or -1 on failure
      end function c_remove
      !> POSIX opendir(3), used to check that a folder exists.
      function c_opendir(path) bind(c, name='opendir') result(d)
         import :: c_char, c_ptr
         character(kind=c_char), intent(in) :: path(*) !< NUL-terminated path
         type(c_ptr) :: d                              !< DIR *, null on failure
      end function c_opendir
      !> POSIX closedir(3).
      function c_closedir(d) bind(c, name='closedir') result(r)
         import :: c_ptr, c_int
         type(c_ptr), value :: d                       !< DIR * from c_opendir
         integer(c_int) :: r                           !< 0, or -1 on failure
      end function c_closedir
   end interface

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
      type(error_t) :: e, e_status
      call make_directory(dir, e)
      if (has_error(e)) then
         call set_error(err, e%code, e%message)
         return
      end if
      call check_lines(lines, e)
      if (model%output%csv) then
         call write_nodes_csv(dir, lines, e)
         call write_elements_csv(dir, lines, e)
         call write_reactions_csv(dir, lines, e)
         call write_lines_csv(dir, lines, e)
         call output_write_environment(dir, model, e)
      end if
      if (model%output%hdf5) call write_results_h5(dir, model, lines, summary, e)
      call output_write_status(dir, summary, e_status, deck_file=text_of(model%deck_file), &
                               params=model%parameters)
      if (has_error(e)) call set_error(err, e%code, e%message)
      if (has_error(e_status)) call set_error(err, e_status%code, e_status%message)
   end subroutine output_write_static

   !> Write only status.txt into folder `dir` (created if missing): for a run that
   !> stops before it has results to write, and for the dynamic writer (which adds the
   !> keys dynamic ... step_cutbacks when summary%dynamic is true). Acts even when err
   !> already holds an error. The deck parameters `params` (if any) follow the key deck,
   !> one line 'parameter.NAME = text' each.
   subroutine output_write_status(dir, summary, err, deck_file, params)
      character(len=*), intent(in) :: dir                 !< output folder
      type(run_summary_t), intent(in) :: summary          !< how the run went
      type(error_t), intent(inout) :: err                 !< status
      character(len=*), intent(in), optional :: deck_file !< path of the deck
      type(parameter_value_t), intent(in), optional :: params(:) !< deck parameters used
      type(error_t) :: e
      integer :: u, ios, k
      character(len=512) :: msg
      call make_directory(dir, e)
      call open_temp(dir, status_txt, u, e)
      if (.not. has_error(e)) then
         ios = 0
         msg = ''
         call put_line(u, 'complete = '//trim(merge('true ', 'false', summary%complete)), &
            ios, msg)
         call put_line(u, 'status = '//one_line(status_of(summary)), ios, msg)
         call put_line(u, 'load_factor = '//real_str(summary%load_factor), ios, msg)
         call put_line(u, 'increments = '//int_str(summary%increments), ios, msg)
         call put_line(u, 'iterations = '//int_str(summary%iterations), ios, msg)
         call put_line(u, 'cutbacks = '//int_str(summary%cutbacks), ios, msg)
         call put_line(u, 'wall_time_s = '//real_str(summary%wall_time), ios, msg)
         if (summary%dynamic) then
            call put_line(u, 'dynamic = true', ios, msg)
            call put_line(u, 'time_reached_s = '//real_str(summary%time_reached), ios, msg)
            call put_line(u, 'steps = '//int_str(summary%steps), ios, msg)
            call put_line(u, 'step_iterations = '//int_str(summary%step_iterations), ios, &
               msg)
            call put_line(u, 'step_tangents = '//int_str(summary%step_tangents), ios, msg)
            call put_line(u, 'step_cutbacks = '//int_str(summary%step_cutbacks), ios, msg)
         end if
         call put_line(u, 'rodyn_version = '//rodyn_version, ios, msg)
         if (present(deck_file)) then
            call put_line(u, 'deck = '//one_line(deck_file), ios, msg)
         else
            call put_line(u, 'deck = ', ios, msg)
         end if
         if (present(params)) then
            do k = 1, size(params)
               call put_line(u, 'parameter.'//params(k)%name//' = '// &
                  one_line(params(k)%text), ios, msg)
            end do
         end if
         call commit_temp(dir, status_txt, u, ios, msg, e)
      end if
      if (has_error(e)) call set_error(err, e%code, e%message)
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
      integer :: u, ios, k
      integer(c_int) :: r
      character(len=512) :: msg
      if (has_error(err)) return
      if (.not. model%water%present) then
         r = c_remove(path_join(dir, environment_csv)//c_null_char)
         return
      end if
      items = environment_items(model)
      call open_temp(dir, environment_csv, u, err)
      if (has_error(err)) return
      ios = 0
      msg = ''
      call put_line(u, 'key,value,unit', ios, msg)
      do k = 1, size(items)
         call put_line(u, items(k)%key//','//real_str(items(k)%value)//','// &
            items(k)%unit, ios, msg)
      end do
      call commit_temp(dir, environment_csv, u, ios, msg, err)
   end subroutine output_write_environment

   ! ------------------------------------------------------------------ CSV tables

   !> static_nodes.csv: one row per node, numbered from 1 along each line, with the
   !> seabed contact force per length.
   subroutine write_nodes_csv(dir, lines, err)
      character(len=*), intent(in) :: dir         !< output folder
      type(line_result_t), intent(in) :: lines(:) !< results
      type(error_t), intent(inout) :: err         !< status
      real(wp), allocatable :: fn(:), ff(:)
      integer :: u, ios, i, k
      character(len=512) :: msg
      if (has_error(err)) return
      call open_temp(dir, nodes_csv, u, err)
      if (has_error(err)) return
      ios = 0
      msg = ''
      call put_line(u, 'line,node,s_m,x_m,y_m,z_m,seabed_normal_N_per_m,'// &
         'seabed_friction_N_per_m', ios, msg)
      do i = 1, size(lines)
         fn = seabed_force_of(lines(i), 1)
         ff = seabed_force_of(lines(i), 2)
         do k = 1, size(lines(i)%node_s)
            call put_line(u, csv_name(lines(i)%name)//','//int_str(k)//','// &
               reals_str([lines(i)%node_s(k), lines(i)%node_x(:, k), fn(k), ff(k)]), &
               ios, msg)
         end do
      end do
      call commit_temp(dir, nodes_csv, u, ios, msg, err)
   end subroutine write_nodes_csv

   !> static_elements.csv: section forces and strains, one row per integration point.
   subroutine write_elements_csv(dir, lines, err)
      character(len=*), intent(in) :: dir         !< output folder
      type(line_result_t), intent(in) :: lines(:) !< results
      type(error_t), intent(inout) :: err         !< status
      real(wp), allocatable :: tw(:)
      integer :: u, ios, i, k
      character(len=512) :: msg
      if (has_error(err)) return
      call open_temp(dir, elements_csv, u, err)
      if (has_error(err)) return
      ios = 0
      msg = ''
      call put_line(u, 'line,element,point,s_m,effective_tension_N,wall_tension_N,'// &
         'shear_1_N,shear_2_N,moment_1_Nm,moment_2_Nm,torque_Nm,curvature_1_per_m,'// &
         'curvature_2_per_m,twist_per_m,curvature_per_m', ios, msg)
      do i = 1, size(lines)
         associate (r => lines(i))
            tw = wall_tension_of(r)
            do k = 1, size(r%gp_s)
               call put_line(u, csv_name(r%name)//','//int_str(r%gp_element(k))//','// &
                  int_str(r%gp_point(k))//','//reals_str([r%gp_s(k), r%tension(k), tw(k), &
                  r%shear(:, k), r%moment(:, k), r%torque(k), r%curvature(:, k), &
                  hypot(r%curvature(1, k), r%curvature(2, k))]), ios, msg)
            end do
         end associate
      end do
      call commit_temp(dir, elements_csv, u, ios, msg, err)
   end subroutine write_elements_csv

   !> static_reactions.csv: force and moment of each support on the line, global axes.
   subroutine write_reactions_csv(dir, lines, err)
      character(len=*), intent(in) :: dir         !< output folder
      type(line_result_t), intent(in) :: lines(:) !< results
      type(error_t), intent(inout) :: err         !< status
      character(len=1), parameter :: end_name(2) = ['A', 'B']
      integer :: u, ios, i, j
      character(len=512) :: msg
      if (has_error(err)) return
      call open_temp(dir, reactions_csv, u, err)
      if (has_error(err)) return
      ios = 0
      msg = ''
      call put_line(u, 'line,end,Fx_N,Fy_N,Fz_N,Mx_Nm,My_Nm,Mz_Nm,tension_N', ios, msg)
      do i = 1, size(lines)
         do j = 1, 2
            if (.not. lines(i)%end_held(j)) cycle
            call put_line(u, csv_name(lines(i)%name)//','//end_name(j)//','// &
               reals_str([lines(i)%reaction(:, j), norm2(lines(i)%reaction(1:3, j))]), &
               ios, msg)
         end do
      end do
      call commit_temp(dir, reactions_csv, u, ios, msg, err)
   end subroutine write_reactions_csv

   !> static_lines.csv: one row per line: unstretched length and touchdown point
   !> (largest arc length in contact with the seabed; -1 when none touches).
   subroutine write_lines_csv(dir, lines, err)
      character(len=*), intent(in) :: dir         !< output folder
      type(line_result_t), intent(in) :: lines(:) !< results
      type(error_t), intent(inout) :: err         !< status
      integer :: u, ios, i
      character(len=512) :: msg
      if (has_error(err)) return
      call open_temp(dir, lines_csv, u, err)
      if (has_error(err)) return
      ios = 0
      msg = ''
      call put_line(u, 'line,length_m,touchdown_s_m', ios, msg)
      do i = 1, size(lines)
         associate (r => lines(i))
            call put_line(u, csv_name(r%name)//','//reals_str([r%node_s(size(r%node_s)), &
               touchdown_of(r)]), ios, msg)
         end associate
      end do
      call commit_temp(dir, lines_csv, u, ios, msg, err)
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
      integer :: i, r
      if (has_error(err)) return
      tmp = path_join(dir, '.'//results_h5//'.tmp')
      call hdf5_create_file(h5, tmp, err)
      if (has_error(err)) return
      call hdf5_write_attribute(h5, '/', 'program', 'rodyn', err)
      call hdf5_write_attribute(h5, '/', 'version', rodyn_version, err)
      call hdf5_write_attribute(h5, '/', 'deck_file', text_of(model%deck_file), err)
      call hdf5_write_attribute(h5, '/', 'title', text_of(model%title), err)
      call hdf5_write_attribute(h5, '/', 'units', units_si, err)
      call hdf5_write_attribute(h5, '/', 'complete', merge(1, 0, summary%complete), err)
      call hdf5_write_attribute(h5, '/', 'status', one_line(status_of(summary)), err)
      call hdf5_write_dataset(h5, '/deck', text_of(model%deck_text), err)
      call describe(h5, '/deck', '-', 'full text of the input deck, includes expanded', err)
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
      if (.not. has_error(err)) then
         r = c_rename(tmp//c_null_char, path_join(dir, results_h5)//c_null_char)
         if (r /= 0) call set_error(err, stat_io, 'output_write_static: cannot rename '''// &
            tmp//''' to '''//path_join(dir, results_h5)//'''')
      end if
      if (has_error(err)) r = c_remove(tmp//c_null_char)
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
      call describe(h5, g//'/node_s', 'm', 'unstretched arc length of the nodes', err)
      call hdf5_write_dataset(h5, g//'/node_xyz', r%node_x, err)
      call describe(h5, g//'/node_xyz', 'm', &
         'node positions, one row per node, columns x, y, z (global axes)', err)
      call hdf5_write_dataset(h5, g//'/gp_element', r%gp_element, err)
      call describe(h5, g//'/gp_element', '-', &
         'element of each integration point, numbered from 1 along the line', err)
      call hdf5_write_dataset(h5, g//'/gp_point', r%gp_point, err)
      call describe(h5, g//'/gp_point', '-', &
         'integration point number within its element, from 1', err)
      call hdf5_write_dataset(h5, g//'/gp_s', r%gp_s, err)
      call describe(h5, g//'/gp_s', 'm', &
         'unstretched arc length of the integration points', err)
      call hdf5_write_attribute(h5, g, 'touchdown_s', touchdown_of(r), err)
      call hdf5_write_dataset(h5, g//'/effective_tension', r%tension, err)
      call describe(h5, g//'/effective_tension', 'N', &
         'effective tension N3 along d3, positive in tension', err)
      call hdf5_write_dataset(h5, g//'/wall_tension', wall_tension_of(r), err)
      call describe(h5, g//'/wall_tension', 'N', 'wall (true) tension, '// &
         'T_eff + p_o A_o - p_i A_i, positive in tension', err)
      call hdf5_write_dataset(h5, g//'/shear', r%shear, err)
      call describe(h5, g//'/shear', 'N', 'shear forces, columns N1 along d1, N2 along d2', &
         err)
      call hdf5_write_dataset(h5, g//'/moment', r%moment, err)
      call describe(h5, g//'/moment', 'N m', &
         'bending moments, columns M1 about d1, M2 about d2', err)
      call hdf5_write_dataset(h5, g//'/torque', r%torque, err)
      call describe(h5, g//'/torque', 'N m', 'torsional moment M3 about d3', err)
      call hdf5_write_dataset(h5, g//'/curvature', r%curvature, err)
      call describe(h5, g//'/curvature', '1/m', &
         'section-frame curvatures, columns K1 (about d1), K2 (about d2), K3 (twist)', err)
      call hdf5_write_dataset(h5, g//'/reactions', r%reaction, err)
      call describe(h5, g//'/reactions', 'N (columns 1-3), N m (columns 4-6)', &
         'force and moment of the support on the line, global axes; rows end A, end B; '// &
         'columns Fx, Fy, Fz, Mx, My, Mz; zero where end_held is 0', err)
      call hdf5_write_attribute(h5, g//'/reactions', 'end_held', &
         merge(1, 0, r%end_held), err)
      call hdf5_write_dataset(h5, g//'/seabed_normal', seabed_force_of(r, 1), err)
      call describe(h5, g//'/seabed_normal', 'N/m', &
         'seabed normal contact force per unit length at the nodes (0: no contact)', err)
      call hdf5_write_dataset(h5, g//'/seabed_friction', seabed_force_of(r, 2), err)
      call describe(h5, g//'/seabed_friction', 'N/m', &
         'magnitude of the seabed friction force per unit length at the nodes', err)
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

   !> Create folder `dir` and its parents (mkdir per path component), then check it.
   subroutine make_directory(dir, err)
      character(len=*), intent(in) :: dir !< folder path ('' means '.')
      type(error_t), intent(inout) :: err !< status
      integer(c_int), parameter :: mode = int(o'777', c_int)
      character(len=:), allocatable :: d
      type(c_ptr) :: handle
      integer :: k
      integer(c_int) :: r
      d = trim(dir)
      if (len(d) == 0) d = '.'
      do k = 2, len(d) + 1
         if (k <= len(d)) then
            if (d(k:k) /= '/') cycle
         end if
         if (d(k - 1:k - 1) == '/') cycle
         r = c_mkdir(d(:k - 1)//c_null_char, mode)  ! fails harmlessly when it exists
      end do
      handle = c_opendir(d//c_null_char)
      if (.not. c_associated(handle)) then
         call set_error(err, stat_io, 'output: cannot create folder '''//d//'''')
         return
      end if
      r = c_closedir(handle)
   end subroutine make_directory

   !> Open '<dir>/.<name>.tmp' for writing.
   subroutine open_temp(dir, name, u, err)
      character(len=*), intent(in) :: dir  !< output folder
      character(len=*), intent(in) :: name !< final file name
      integer, intent(out) :: u            !< unit
      type(error_t), intent(inout) :: err  !< status
      integer :: ios
      character(len=512) :: msg
      u = -1
      if (has_error(err)) return
      open (newunit=u, file=path_join(dir, '.'//name//'.tmp'), status='replace', &
         action='write', form='formatted', access='sequential', iostat=ios, iomsg=msg)
      if (ios /= 0) call set_error(err, stat_io, 'output: cannot write '''// &
         path_join(dir, name)//''': '//trim(msg))
   end subroutine open_temp

   !> Close the temporary file and rename it into place, or delete it after a failure.
   subroutine commit_temp(dir, name, u, ios, msg, err)
      character(len=*), intent(in) :: dir     !< output folder
      character(len=*), intent(in) :: name    !< final file name
      integer, intent(in) :: u                !< unit from open_temp
      integer, intent(inout) :: ios           !< status of the writes so far
      character(len=*), intent(inout) :: msg  !< message of the failed write
      type(error_t), intent(inout) :: err     !< status
      character(len=:), allocatable :: tmp, final
      integer :: ios2
      integer(c_int) :: r
      tmp = path_join(dir, '.'//name//'.tmp')
      final = path_join(dir, name)
      if (ios == 0) then
         close (u, iostat=ios, iomsg=msg)
      else
         close (u, status='delete', iostat=ios2)
      end if
      if (ios /= 0) then
         r = c_remove(tmp//c_null_char)
         call set_error(err, stat_io, 'output: cannot write '''//final//''': '//trim(msg))
         return
      end if
      r = c_rename(tmp//c_null_char, final//c_null_char)
      if (r /= 0) then
         r = c_remove(tmp//c_null_char)
         call set_error(err, stat_io, 'output: cannot rename '''//tmp//''' to '''// &
            final//'''')
      end if
   end subroutine commit_temp

   !> Write one record unless an earlier write failed.
   subroutine put_line(u, text, ios, msg)
      integer, intent(in) :: u               !< unit
      character(len=*), intent(in) :: text   !< record
      integer, intent(inout) :: ios          !< 0, or the first failure
      character(len=*), intent(inout) :: msg !< message of the first failure
      if (ios /= 0) return
      write (u, '(a)', iostat=ios, iomsg=msg) text
   end subroutine put_line

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
