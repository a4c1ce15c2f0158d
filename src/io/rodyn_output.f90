!> Output writers: the static results as CSV tables and an HDF5 file, and the run's
!> status file. The layout of every file is documented in docs/output.md; the tables'
!> rows, the datasets and their descriptions are made by rodyn_output_table (the one
!> table writer, shared with rodyn_output_dynamic): here each static table is a
!> one-shot table, written whole.
!>
!> Every file is first written under a hidden temporary name in the output folder
!> ('.static_nodes.csv.tmp') and renamed into place only when written whole and closed
!> without error (rodyn_outfile, which checks every write), so a reader never sees a
!> half-written file. The folder is created (with its parents) if missing. status.txt
!> is written last and says complete = true only when every file was written and the
!> deck has nothing left to do: after the statics of a deck with *DYNAMIC it says
!> complete = false, status = status_dynamics_to_run (docs/output.md, "status.txt").
module rodyn_output
   use rodyn_kinds, only: i8, rodyn_version
   use rodyn_error, only: error_t, set_error, has_error, stat_io
   use rodyn_model, only: model_t, parameter_value_t
   use rodyn_results, only: line_result_t, run_summary_t, system_result_t
   use rodyn_outfile, only: out_file_t, outfile_create, outfile_put, outfile_commit, &
      temp_name, commit_rename, remove_file
   use rodyn_outdir, only: outdir_make
   use rodyn_output_schema, only: schema_header
   use rodyn_format, only: real_text, int_text
   use rodyn_hdf5, only: hdf5_file_t, hdf5_create_file, hdf5_close_file, &
      hdf5_create_group, hdf5_write_attribute
   use rodyn_output_common, only: text_or, status_of, path_join, one_line, env_item_t, &
                                  environment_items, write_environment_h5, wall_tension_of, &
                                  seabed_force_of, touchdown_of, write_parameters_h5
   use rodyn_output_points, only: write_system_table, system_tables
   use rodyn_output_modal, only: write_modes_csv, modes_csv, mode_shapes_csv, write_modes_h5
   use rodyn_output_table, only: write_line_table, write_described, write_h5_root, &
                                 group_name, check_line_results, start_line_group
   implicit none
   private
   public :: output_write_static, output_write_status, output_write_environment
   public :: committed_t, status_dynamics_to_run, status_dynamics_pending

   !> status.txt's status after the statics of a deck with *DYNAMIC, until its dynamics
   !> start (complete = false): what the deck still has to do.
   character(len=*), parameter :: status_dynamics_to_run = 'statics complete, dynamics to run'

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

contains

   ! ------------------------------------------------------------------ public

   !> Write the static results into folder `dir`: the CSV tables and results.h5 as
   !> model%output asks, then status.txt (always). With summary%complete false the
   !> lines hold the last converged state and status.txt says how far the run got. A
   !> deck with *DYNAMIC is not complete when its statics are: status.txt then says
   !> complete = false, status = status_dynamics_to_run (results.h5's root attributes
   !> describe the static analysis the file holds, complete or not).
   !> Works even when err already holds an error (a failed analysis still writes its
   !> outputs); an output failure is then recorded only if err was clear.
   subroutine output_write_static(dir, model, lines, summary, err, system)
      character(len=*), intent(in) :: dir            !< output folder (created if missing)
      type(model_t), intent(in) :: model             !< the model (title, deck, options)
      type(line_result_t), intent(in) :: lines(:)    !< static results per line
      type(run_summary_t), intent(in) :: summary     !< how the run went
      type(error_t), intent(inout) :: err            !< status
      type(system_result_t), intent(in), optional :: system !< the system's stiffness
      ! the files in the order written
      character(len=*), parameter :: order(*) = [character(len=24) :: nodes_csv, &
         elements_csv, reactions_csv, lines_csv, system_tables, modes_csv, &
         mode_shapes_csv, environment_csv, results_h5]
      type(system_result_t) :: sys
      type(error_t) :: e, e_status
      type(run_summary_t) :: s
      integer :: k, j
      call outdir_make(dir, e)
      if (has_error(e)) then
         call set_error(err, e%code, e%message)
         return
      end if
      if (present(system)) sys = system      ! (else none: no system's tables)
      call check_line_results(lines, 'output_write_static', e)
      k = 0
      do while (k < size(order) .and. .not. has_error(e))
         k = k + 1
         if (k < size(order) .and. .not. model%output%csv) cycle
         select case (k)
         case (1:4)
            call write_line_table(dir, trim(order(k)), lines, e)
         case (5:9)
            call write_system_table(dir, trim(order(k)), model, lines, sys, e)
         case (10)
            call write_modes_csv(dir, model, lines, sys, e)
         case (11)      ! (written with static_modes.csv)
         case (12)
            call output_write_environment(dir, model, e)
         case (13)
            if (model%output%hdf5) call write_results_h5(dir, model, lines, summary, e, sys)
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
      ! the statics of a deck with *DYNAMIC done: the dynamics remain to be run
      if (s%complete .and. model%dynamic%requested) then
         s%complete = .false.
         s%status = status_dynamics_to_run
      end if
      call output_write_status(dir, s, e_status, deck_file=text_or(model%deck_file, ''), &
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
            call put('complete', trim(merge('true ', 'false', summary%complete)))
            call put('status', one_line(status_of(summary)))
            call put('load_factor', real_text(summary%load_factor))
            call put('increments', int_text(summary%increments))
            call put('iterations', int_text(summary%iterations))
            call put('cutbacks', int_text(summary%cutbacks))
            call put('wall_time_s', real_text(summary%wall_time))
            if (summary%dynamic) then
               call put('dynamic', 'true')
               call put('time_reached_s', real_text(summary%time_reached))
               call put('steps', int_text(summary%steps))
               call put('step_iterations', int_text(summary%step_iterations))
               call put('step_tangents', int_text(summary%step_tangents))
               call put('step_cutbacks', int_text(summary%step_cutbacks))
               call put('frames', int_text(summary%frames))
               if (present(committed)) then
                  do k = 1, size(committed)
                     call put('committed_bytes.'//committed(k)%name, int_text(committed(k)%bytes))
                  end do
               end if
            end if
            call put('rodyn_version', rodyn_version)
            if (present(deck_file)) then
               call put('deck', one_line(deck_file))
            else
               call put('deck', '')
            end if
            if (present(params)) then
               do k = 1, size(params)
                  call put('parameter.'//params(k)%name, one_line(params(k)%text))
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
   contains
      !> One line 'key = value'.
      subroutine put(key, value)
         character(len=*), intent(in) :: key    !< key
         character(len=*), intent(in) :: value  !< its value
         call outfile_put(f, key//' = '//value)
      end subroutine put
   end subroutine output_write_status

   !> Whether status.txt in folder `dir` says that the statics of a deck with *DYNAMIC
   !> are done and its dynamics have not started (complete = false, status =
   !> status_dynamics_to_run): a run killed between the two. False when the file is
   !> missing or unreadable.
   logical function status_dynamics_pending(dir)
      character(len=*), intent(in) :: dir   !< output folder
      character(len=512) :: line
      logical :: there, incomplete, to_run
      integer :: u, stat
      status_dynamics_pending = .false.
      inquire (file=path_join(dir, status_txt), exist=there)
      if (.not. there) return
      open (newunit=u, file=path_join(dir, status_txt), action='read', status='old', &
            iostat=stat)
      if (stat /= 0) return
      incomplete = .false.
      to_run = .false.
      do
         read (u, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (line == 'complete = false') incomplete = .true.
         if (line == 'status = '//status_dynamics_to_run) to_run = .true.
      end do
      close (u)
      status_dynamics_pending = incomplete .and. to_run
   end function status_dynamics_pending

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
         call outfile_put(f, items(k)%key//','//real_text(items(k)%value)//','// &
            items(k)%unit)
      end do
      call outfile_commit(f, err)
   end subroutine output_write_environment

   ! ------------------------------------------------------------------ HDF5

   !> results.h5: root attributes, /deck, /static and one group per line.
   subroutine write_results_h5(dir, model, lines, summary, err, system)
      character(len=*), intent(in) :: dir         !< output folder
      type(model_t), intent(in) :: model          !< the model
      type(line_result_t), intent(in) :: lines(:) !< results
      type(run_summary_t), intent(in) :: summary  !< how the run went
      type(error_t), intent(inout) :: err         !< status
      type(system_result_t), intent(in) :: system  !< the modes (*MODAL), may be none
      type(hdf5_file_t) :: h5
      character(len=:), allocatable :: tmp
      integer :: i
      if (has_error(err)) return
      tmp = temp_name(dir, results_h5)
      call hdf5_create_file(h5, tmp, err)
      call write_h5_root(h5, model, summary%complete, one_line(status_of(summary)), err)
      call write_described(h5, results_h5, '/deck', err, text=text_or(model%deck_text, ''))
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
      call write_modes_h5(h5, lines, system, err)
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
      call start_line_group(h5, results_h5, g, r, err)
      call write_described(h5, results_h5, g//'/node_xyz', err, g, x2=r%node_x)
      call write_described(h5, results_h5, g//'/gp_element', err, g, i1=r%gp_element)
      call write_described(h5, results_h5, g//'/gp_point', err, g, i1=r%gp_point)
      call write_described(h5, results_h5, g//'/gp_s', err, g, x1=r%gp_s)
      call hdf5_write_attribute(h5, g, 'touchdown_s', touchdown_of(r), err)
      call write_described(h5, results_h5, g//'/effective_tension', err, g, x1=r%tension)
      call write_described(h5, results_h5, g//'/wall_tension', err, g, x1=wall_tension_of(r))
      call write_described(h5, results_h5, g//'/shear', err, g, x2=r%shear)
      call write_described(h5, results_h5, g//'/moment', err, g, x2=r%moment)
      call write_described(h5, results_h5, g//'/torque', err, g, x1=r%torque)
      call write_described(h5, results_h5, g//'/curvature', err, g, x2=r%curvature)
      call write_described(h5, results_h5, g//'/reactions', err, g, x2=r%reaction)
      call hdf5_write_attribute(h5, g//'/reactions', 'end_held', &
         merge(1, 0, r%end_held), err)
      call write_described(h5, results_h5, g//'/seabed_normal', err, g, x1=seabed_force_of(r, 1))
      call write_described(h5, results_h5, g//'/seabed_friction', err, g, x1=seabed_force_of(r, 2))
   end subroutine write_h5_line
end module rodyn_output
