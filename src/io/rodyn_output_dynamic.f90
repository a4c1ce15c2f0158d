!> Writers for a dynamic run: time histories written while the run goes, so that a run
!> that fails or is killed leaves everything up to its last output frame readable.
!> The layout of every file is documented in docs/output.md ("Dynamic runs").
!>
!> Life cycle: dynamic_output_open (after output_write_static has written the static
!> files), then dynamic_output_step after every time step and dynamic_output_frame at
!> every output time, in any order, then dynamic_output_close. The CSV tables are
!> created under their final names (truncating older ones) with their header, and grow
!> as the run goes; dynamic.h5 is created under a temporary name and renamed into place
!> once its header and empty datasets are on disk.
!>
!> What is on disk when (the flush policy; cost measured in test_output_dynamic.pf):
!> frames and step rows are held in memory (CSV rows as text, rodyn_outfile; dynamic.h5
!> values with hdf5_series_hold, at most frame_block frames or hold_bytes) and written
!> together, in a "sync": the CSV rows (write(2), checked), then dynamic.h5 (one block
!> per dataset, the step rows, H5Fflush), then status.txt (temporary file + rename) with
!> complete = false, status = running, the time, steps and frames of the last sync and
!> the committed size of each CSV table (committed_bytes.NAME, its bytes at that sync).
!> A sync happens at the first frame, after a frame when status_interval (1 s) of wall
!> time has passed since the last one, when the hold is full (or log_block step rows
!> are), and at close. So status.txt, the CSV tables and dynamic.h5 hold the same frames
!> whenever the run is killed, up to the sizes status.txt gives: a kill inside a sync
!> can leave the data files one block ahead of status.txt (an uncommitted tail, which
!> readers ignore and a restart cuts off), never behind it.
!> On a write failure (a full disk) nothing more is written: the CSV tables are cut back
!> to their last sync (whole frames), a dynamic.h5 whose write failed is removed, and
!> status.txt says complete = false, the failure, and the time and steps of that sync.
!> There is no fsync: the files survive the process being killed, not a machine crash.
!> HDF5 file format: the default (oldest) one, so that a killed run's file opens
!> without h5clear (see docs/output.md for what HDF5 allows while the run is live).
!>
!> The rows of the line tables (nodes, elements, ends, lines, ends_step) and the
!> described datasets are made by rodyn_output_table, the table writer the static
!> output uses too: a line's row heads (line, node, s, ...) are made once at open, and
!> each frame appends the time, the head and the values; numbers are written by
!> rodyn_format (17 significant digits, 1.2345678901234567E+05), as in every table.
module rodyn_output_dynamic
   use rodyn_format, only: put_text, put_int, put_real, put_reals
   use rodyn_kinds, only: wp, i8
   use rodyn_error, only: error_t, set_error, has_error, stat_io
   use rodyn_model, only: model_t, scheme_names, parameter_value_t, model_ramp
   use rodyn_results, only: line_result_t, run_summary_t, step_log_t
   use rodyn_hdf5, only: hdf5_file_t, hdf5_series_t, hdf5_create_file, hdf5_close_file, &
      hdf5_flush, hdf5_create_group, hdf5_write_attribute, hdf5_open_series, &
      hdf5_close_series, hdf5_series_hold, hdf5_series_write_held, hdf5_series_truncate, &
      hdf5_open_file, hdf5_append_steps
   use rodyn_output, only: output_write_status, output_write_environment, committed_t
   use rodyn_output_schema, only: schema_header
   use rodyn_sea_output, only: sea_scene_t, sea_values_t
   use rodyn_outfile, only: out_file_t, outfile_create, outfile_put, outfile_flush, &
      outfile_mark, outfile_close, outfile_abort, outfile_pending, outfile_committed, &
      temp_name, commit_rename, remove_file, outfile_reopen
   use rodyn_output_common, only: text_of, status_of, path_join, one_line, csv_name, &
                                  write_environment_h5, wall_tension_of, seabed_force_of, &
                                  touchdown_of, write_parameters_h5
   use rodyn_output_table, only: line_table_t, line_table, line_rows, line_row_kept, &
                                 line_row_head, put_line_values, put_end_values, group_name, &
                                 write_described, create_described_series, write_h5_root, &
                                 line_result_complete, line_result_fits, &
                                 bending_curvature_at, row_len
   implicit none
   private
   public :: dynamic_writer_t
   public :: dynamic_output_open, dynamic_output_frame, dynamic_output_step
   public :: dynamic_output_ends_step, dynamic_output_mark, dynamic_output_mark_t
   public :: dynamic_output_close, dynamic_output_sea, dynamic_output_keeps_frames

   character(len=*), parameter :: nodes_csv = 'dynamic_nodes.csv'
   character(len=*), parameter :: elements_csv = 'dynamic_elements.csv'
   character(len=*), parameter :: ends_csv = 'dynamic_ends.csv'
   character(len=*), parameter :: ends_step_csv = 'dynamic_ends_step.csv'
   character(len=*), parameter :: log_csv = 'dynamic_log.csv'
   character(len=*), parameter :: lines_csv = 'dynamic_lines.csv'
   character(len=*), parameter :: dynamic_h5 = 'dynamic.h5'
   ! The tables of the lines, laid out by rodyn_output_table (index into line_out_t%head)
   integer, parameter :: lt_nodes = 1, lt_elements = 2, lt_ends = 3, lt_lines = 4, &
      lt_ends_step = 5, n_line_tables = 5
   character(len=*), parameter :: line_csv(n_line_tables) = [character(len=21) :: &
      nodes_csv, elements_csv, ends_csv, lines_csv, ends_step_csv]
   ! The members of /dynamic besides the lines' groups (group_name)
   character(len=*), parameter :: dynamic_members(3) = [character(len=4) :: 'time', &
      'log', 'sea']
   ! Tables of the sea and the vessels (written only for a scene with probes or vessels)
   integer, parameter :: sf_waves = 1, sf_waves_step = 2, sf_vessels = 3, &
      sf_vessels_step = 4, sf_conn = 5, sf_conn_step = 6, sf_bodies = 7, &
      sf_bodies_step = 8, n_sea = 8
   character(len=*), parameter :: sea_csv(n_sea) = [character(len=28) :: &
      'dynamic_waves.csv', 'dynamic_waves_step.csv', 'dynamic_vessels.csv', &
      'dynamic_vessels_step.csv', 'dynamic_connections.csv', 'dynamic_connections_step.csv', &
      'dynamic_bodies.csv', 'dynamic_bodies_step.csv']
   ! The same in dynamic.h5, /dynamic/sea (index into dynamic_writer_t%sea_h5): at the
   ! frames and at every step
   integer, parameter :: sh_elevation = 1, sh_motion = 2, sh_load = 3, sh_conn = 4, &
      sh_step_elevation = 5, sh_step_motion = 6, sh_step_load = 7, sh_step_conn = 8, &
      sh_step_time = 9, sh_body = 10, sh_step_body = 11, n_sea_h5 = 11
   character(len=*), parameter :: sea_h5_name(n_sea_h5) = [character(len=24) :: &
      'probe_elevation', 'vessel_motion', 'vessel_load', 'connection_load', &
      'step_probe_elevation', 'step_vessel_motion', 'step_vessel_load', &
      'step_connection_load', 'step_time', 'body_motion', 'step_body_motion']
   character(len=*), parameter :: running = 'running'

   integer, parameter :: log_block = 1024  !< step rows kept for dynamic.h5 at most
   integer, parameter :: frame_block = 256  !< frames held for dynamic.h5 at most
   integer, parameter :: hold_bytes = 8*1024*1024 !< and at most this much memory
   integer, parameter :: chunk_bytes = 8192 !< target HDF5 chunk size of the frames
   integer, parameter :: log_chunk = 1024   !< steps per HDF5 chunk of the step log
   real(wp), parameter :: status_interval = 1.0_wp !< least wall time between rewrites
                                                   !< of status.txt while running [s]

   ! Time histories of a line in dynamic.h5 (index into line_out_t%series)
   integer, parameter :: ls_x = 1, ls_y = 2, ls_z = 3, ls_tension = 4, ls_moment_1 = 5, &
      ls_moment_2 = 6, ls_torque = 7, ls_curvature = 8, ls_reactions = 9, &
      ls_end_tension = 10, ls_wall_tension = 11, ls_seabed_normal = 12, &
      ls_seabed_friction = 13, ls_touchdown = 14, n_line_series = 14
   character(len=*), parameter :: line_series_name(n_line_series) = [character(len=17) :: &
      'x', 'y', 'z', 'effective_tension', 'moment_1', 'moment_2', 'torque', &
      'bending_curvature', 'reactions', 'end_tension', 'wall_tension', 'seabed_normal', &
      'seabed_friction', 'touchdown_s']

   ! Step log in dynamic.h5 (index into dynamic_writer_t%log), one dataset per quantity
   integer, parameter :: lg_step = 1, lg_time = 2, lg_dt = 3, lg_iterations = 4, &
      lg_cutbacks = 5, lg_kinetic = 6, lg_strain = 7, lg_gravity = 8, &
      lg_external_work = 9, lg_damping_work = 10, lg_total = 11, lg_momentum = 12, &
      lg_angular_momentum = 13, lg_hydro_work = 14, lg_seabed_work = 15, &
      lg_numerical_work = 16, lg_numerical_energy = 17, n_log_series = 17
   character(len=*), parameter :: log_series_name(n_log_series) = [character(len=16) :: &
      'step', 'time', 'dt', 'iterations', 'cutbacks', 'kinetic', 'strain', 'gravity', &
      'external_work', 'damping_work', 'total', 'momentum', 'angular_momentum', &
      'hydro_work', 'seabed_work', 'numerical_work', 'numerical_energy']


   !> A string of its own length (rows of an array of texts differ in length).
   type :: text_t
      character(len=:), allocatable :: s !< the text
   end type text_t

   !> The heads of a line's rows in one table (line_row_head), made once at open.
   type :: heads_t
      type(text_t), allocatable :: row(:)  !< (line_rows) ',LINE,node,s_m', ...
   end type heads_t

   !> Where the output of a run stands at a checkpoint (dynamic_output_mark): what the
   !> files hold, and the writer's counters; dynamic_output_open continues from it.
   type :: dynamic_output_mark_t
      integer(i8) :: csv_bytes(14) = 0_i8 !< bytes of dynamic_nodes, _elements, _ends,
                                          !< _log, _lines, _ends_step.csv, then of the
                                          !< sea tables (sea_csv; 0 when not written)
      integer :: frames = 0               !< frames written
      integer :: steps = 0                !< step rows written
      integer :: end_rows = 0             !< rows of support forces of every step
      real(wp) :: last_time = 0.0_wp      !< time of the last frame [s]
      integer :: step_iterations = 0      !< Newton iterations so far
      integer :: step_tangents = 0        !< tangents so far
      integer :: step_cutbacks = 0        !< halvings so far
   end type dynamic_output_mark_t

   !> One line: its sizes, the fixed start of its CSV rows and its open HDF5 series.
   type :: line_out_t
      integer :: nn = 0                              !< nodes
      integer :: ng = 0                              !< integration points
      logical :: end_held(2) = .false.               !< ends written to the ends tables
      type(heads_t) :: head(n_line_tables)           !< its rows' heads in each table
      type(hdf5_series_t) :: series(n_line_series)   !< the line's time histories
      type(hdf5_series_t) :: step_reactions          !< support forces, row per step
      type(hdf5_series_t) :: step_end_tension        !< their magnitudes, row per step
      type(hdf5_series_t) :: step_time               !< their times, row per step
   end type line_out_t

   !> The open output of a dynamic run: file units, the HDF5 file and its open datasets,
   !> scratch allocated once at open, and counters. Components are private except the
   !> counters, which callers may read.
   type :: dynamic_writer_t
      private
      logical :: is_open = .false.                   !< between open and close
      logical :: csv = .false.                       !< CSV tables requested
      logical :: hdf5 = .false.                      !< dynamic.h5 requested
      character(len=:), allocatable :: dir           !< output folder
      character(len=:), allocatable :: deck_file     !< deck path, for status.txt
      type(parameter_value_t), allocatable :: params(:) !< deck parameters, for status.txt
      type(out_file_t) :: f_nodes                    !< dynamic_nodes.csv
      type(out_file_t) :: f_elements                 !< dynamic_elements.csv
      type(out_file_t) :: f_ends                     !< dynamic_ends.csv
      type(out_file_t) :: f_log                      !< dynamic_log.csv
      type(out_file_t) :: f_ends_step                !< dynamic_ends_step.csv
      type(out_file_t) :: f_lines                    !< dynamic_lines.csv
      type(line_table_t) :: table(n_line_tables)     !< the layouts of the line tables
      type(out_file_t) :: f_sea(n_sea)               !< the tables of sea_csv
      logical :: sea_on(n_sea) = .false.             !< which of them are written
      type(text_t), allocatable :: probe_head(:)     !< (np) ',PROBE,x,y'
      type(text_t), allocatable :: vessel_head(:)    !< (nv) ',VESSEL'
      type(text_t), allocatable :: body_head(:)      !< (nb) ',BODY'
      type(text_t), allocatable :: conn_head(:)      !< (nc) ',VESSEL,LINE,END'
      integer :: sea_cols(n_sea_h5) = 0              !< columns of each /dynamic/sea series
      real(wp), allocatable :: probe_xy(:, :)        !< (2, np) the probes' points [m]
      type(hdf5_series_t) :: sea_h5(n_sea_h5)        !< /dynamic/sea, open when sea_cols > 0
      logical :: failed = .false.                    !< a write failed: nothing more written
      logical :: h5_failed = .false.                 !< an HDF5 call on dynamic.h5 failed
      character(len=:), allocatable :: why           !< the first failure
      real(wp) :: last_time = 0.0_wp                 !< time of the last frame [s]
      integer :: steps_held = 0                      !< step rows since the last sync
      type(hdf5_file_t) :: h5                        !< dynamic.h5
      type(hdf5_series_t) :: time                    !< /dynamic/time
      type(hdf5_series_t) :: log(n_log_series)       !< /dynamic/log/*
      type(line_out_t), allocatable :: line(:)       !< per line
      type(step_log_t), allocatable :: pending(:)    !< (log_block) rows not in .h5 yet
      integer :: n_pending = 0                       !< rows held in pending
      integer :: hold_frames = frame_block           !< frames held between syncs at most
      integer :: frames_held = 0                     !< frames since the last sync
      type(run_summary_t) :: progress                !< what status.txt says while running
      type(run_summary_t) :: synced                  !< progress as of the last sync
      real(wp) :: static_wall_time = 0.0_wp          !< wall time before open [s]
      integer(i8) :: clock_start = 0_i8              !< system_clock count at open
      integer(i8) :: clock_status = 0_i8             !< count at the last status.txt
      integer, public :: frames = 0                  !< frames written
      integer, public :: steps = 0                   !< step rows written
      integer, public :: end_rows = 0                !< rows of support forces written
      real(wp), public :: flush_time = 0.0_wp        !< wall time spent flushing [s]
   end type dynamic_writer_t

contains

   ! ------------------------------------------------------------------ public

   !> Create the dynamic output files in folder `dir` (created if missing) as
   !> model%output asks, write their headers, the static datasets of dynamic.h5 and a
   !> status.txt saying the run is in progress. No frame is written: call
   !> dynamic_output_frame for the initial state if it is wanted. On failure everything
   !> opened is closed again (dynamic_output_close may still be called).
   subroutine dynamic_output_open(w, dir, model, lines, err, static_summary, resume, sea)
      type(dynamic_writer_t), intent(inout) :: w        !< the writer (not open)
      character(len=*), intent(in) :: dir               !< output folder
      type(model_t), intent(in) :: model                !< model (title, deck, options)
      type(line_result_t), intent(in) :: lines(:)       !< initial state: names, sizes
      type(error_t), intent(inout) :: err               !< status
      type(run_summary_t), intent(in), optional :: static_summary !< the static run,
                                                        !< kept in status.txt meanwhile
      type(dynamic_output_mark_t), intent(in), optional :: resume !< continue the files
                                                        !< of a run from this checkpoint
      type(sea_scene_t), intent(in), optional :: sea    !< probes, vessels, connections:
                                                        !< their tables are written
      character(len=*), parameter :: where = 'dynamic_output_open'
      type(error_t) :: e
      integer :: i
      if (has_error(err)) return
      if (w%is_open) then
         call set_error(err, stat_io, where//': the writer is already open')
         return
      end if
      w%dir = dir
      w%deck_file = text_of(model%deck_file)
      if (allocated(model%parameters)) w%params = model%parameters
      w%csv = model%output%csv
      w%hdf5 = model%output%hdf5
      w%frames = 0
      w%steps = 0
      w%end_rows = 0
      w%n_pending = 0
      w%frames_held = 0
      w%steps_held = 0
      w%last_time = 0.0_wp
      w%failed = .false.
      w%h5_failed = .false.
      w%flush_time = 0.0_wp
      w%progress = run_summary_t()
      if (present(static_summary)) w%progress = static_summary
      w%progress%complete = .false.
      w%progress%status = running
      w%progress%dynamic = .true.
      w%progress%time_reached = 0.0_wp
      w%progress%steps = 0
      w%progress%step_iterations = 0
      w%progress%step_tangents = 0
      w%progress%step_cutbacks = 0
      if (present(resume)) then
         w%frames = resume%frames
         w%steps = resume%steps
         w%end_rows = resume%end_rows
         w%last_time = resume%last_time
         w%progress%time_reached = resume%last_time
         w%progress%steps = resume%steps
         w%progress%step_iterations = resume%step_iterations
         w%progress%step_tangents = resume%step_tangents
         w%progress%step_cutbacks = resume%step_cutbacks
      end if
      w%synced = w%progress
      w%static_wall_time = w%progress%wall_time
      call system_clock(w%clock_start)
      w%clock_status = w%clock_start
      do i = 1, size(lines)
         if (.not. line_result_complete(lines(i))) then
            call set_error(err, stat_io, where//': results of line '''// &
               trim(lines(i)%name)//''' are missing or of inconsistent sizes')
            return
         end if
      end do
      do i = 1, n_line_tables
         w%table(i) = line_table(trim(line_csv(i)), err)
      end do
      if (has_error(err)) return
      call output_write_status(dir, w%progress, e, w%deck_file, w%params)  ! makes the folder
      allocate (w%line(size(lines)), w%pending(log_block))
      do i = 1, size(lines)
         call set_up_line(w%line(i), lines(i), w%table)
      end do
      w%sea_on = .false.
      w%sea_cols = 0
      if (present(sea)) call set_up_sea(w, model, sea)
      if (w%csv .and. present(resume)) then
         call reopen_csv(nodes_csv, w%f_nodes, 1)
         call reopen_csv(elements_csv, w%f_elements, 2)
         call reopen_csv(ends_csv, w%f_ends, 3)
         call reopen_csv(log_csv, w%f_log, 4)
         call reopen_csv(lines_csv, w%f_lines, 5)
         call reopen_csv(ends_step_csv, w%f_ends_step, 6)
         do i = 1, n_sea
            if (w%sea_on(i)) call reopen_csv(trim(sea_csv(i)), w%f_sea(i), 6 + i)
         end do
      else if (w%csv) then
         call open_csv(w, nodes_csv, schema_header(nodes_csv), w%f_nodes, e)
         call open_csv(w, elements_csv, schema_header(elements_csv), w%f_elements, e)
         call open_csv(w, ends_csv, schema_header(ends_csv), w%f_ends, e)
         call open_csv(w, log_csv, schema_header(log_csv), w%f_log, e)
         call open_csv(w, ends_step_csv, schema_header(ends_step_csv), w%f_ends_step, e)
         call open_csv(w, lines_csv, schema_header(lines_csv), w%f_lines, e)
         do i = 1, n_sea
            if (w%sea_on(i)) call open_csv(w, trim(sea_csv(i)), &
                                           schema_header(trim(sea_csv(i))), w%f_sea(i), e)
         end do
      end if
      if (w%csv) call output_write_environment(dir, model, e)
      if (w%hdf5 .and. .not. has_error(e)) then
         if (present(resume)) then
            call reopen_h5(w, lines, resume, e)
         else
            call create_h5(w, model, lines, e)
         end if
         if (has_error(e)) w%h5_failed = .true.
      end if
      if (has_error(e)) then
         call note_failure(w, e)
         call release_all(w, e)
         call set_error(err, e%code, e%message)
         return
      end if
      w%is_open = .true.
   contains
      !> A CSV table of the interrupted run, cut back to the checkpoint's bytes.
      subroutine reopen_csv(name, f, k)
         character(len=*), intent(in) :: name       !< file name
         type(out_file_t), intent(inout) :: f       !< the table
         integer, intent(in) :: k                   !< its index in csv_bytes
         if (has_error(e)) return
         call outfile_reopen(f, dir, name, resume%csv_bytes(k), e)
      end subroutine reopen_csv
   end subroutine dynamic_output_open

   !> A checkpoint of the output: write everything held (a sync, status.txt too) and
   !> return what the files then hold and the writer's counters.
   subroutine dynamic_output_mark(w, mark, err)
      type(dynamic_writer_t), intent(inout) :: w          !< open writer
      type(dynamic_output_mark_t), intent(out) :: mark    !< where the output stands
      type(error_t), intent(inout) :: err                 !< status
      type(error_t) :: e
      if (has_error(err)) return
      if (.not. w%is_open .or. w%failed) then
         call set_error(err, stat_io, 'dynamic_output_mark: the writer is not open')
         return
      end if
      call sync(w, e)
      if (has_error(e)) then
         call note_failure(w, e)
         call set_error(err, e%code, e%message)
         return
      end if
      mark%csv_bytes = [w%f_nodes%written, w%f_elements%written, w%f_ends%written, &
                        w%f_log%written, w%f_lines%written, w%f_ends_step%written, &
                        w%f_sea%written]
      mark%frames = w%frames
      mark%steps = w%steps
      mark%end_rows = w%end_rows
      mark%last_time = w%last_time
      mark%step_iterations = w%progress%step_iterations
      mark%step_tangents = w%progress%step_tangents
      mark%step_cutbacks = w%progress%step_cutbacks
   end subroutine dynamic_output_mark

   !> Append one output frame at time `time`: every line's nodes, integration points
   !> and held ends, to the CSV tables and dynamic.h5 (with the step rows still held),
   !> flush them, and update status.txt if it is older than status_interval.
   subroutine dynamic_output_frame(w, time, lines, err)
      type(dynamic_writer_t), intent(inout) :: w    !< open writer
      real(wp), intent(in) :: time                  !< time of the frame [s]
      type(line_result_t), intent(in) :: lines(:)   !< state, lines and sizes as at open
      type(error_t), intent(inout) :: err           !< status
      character(len=*), parameter :: where = 'dynamic_output_frame'
      type(error_t) :: e
      integer :: i
      logical :: due
      if (has_error(err)) return
      if (.not. w%is_open) then
         call set_error(err, stat_io, where//': the writer is not open')
         return
      end if
      if (size(lines) /= size(w%line)) then
         call set_error(err, stat_io, where//': number of lines differs from the one at open')
         return
      end if
      do i = 1, size(lines)
         if (.not. line_result_fits(lines(i), w%line(i)%nn, w%line(i)%ng)) then
            call set_error(err, stat_io, where//': results of line '''// &
               trim(lines(i)%name)//''' are missing or of other sizes than at open')
            return
         end if
      end do
      if (w%failed) then
         call set_error(err, stat_io, w%why)
         return
      end if
      if (w%csv) call write_frame_csv(w, time, lines)
      if (w%hdf5) then
         call write_frame_h5(w, time, lines, e)
         if (has_error(e)) w%h5_failed = .true.
      end if
      if (.not. has_error(e)) then
         w%frames = w%frames + 1
         w%frames_held = w%frames_held + 1
         w%last_time = time
         due = seconds_since(w%clock_status) >= status_interval
         ! frames, steps and status.txt synced with the first frame, every second, and
         ! when the hold is full
         if (due .or. w%frames == 1 .or. w%frames_held >= w%hold_frames .or. &
             csv_held(w) > hold_bytes) call sync(w, e)
      end if
      if (has_error(e)) then
         call note_failure(w, e)
         call set_error(err, e%code, e%message)
      end if
   end subroutine dynamic_output_frame

   !> The writer keeps its frames in a file (CSV or HDF5). A deck that asks for neither
   !> (*OUTPUT, CSV=NO, HDF5=NO: status.txt only) has no use for a frame's results, and
   !> its run need not form them (dynamic_output_frame still counts the frame).
   pure logical function dynamic_output_keeps_frames(w)
      type(dynamic_writer_t), intent(in) :: w !< writer
      dynamic_output_keeps_frames = w%csv .or. w%hdf5
   end function dynamic_output_keeps_frames

   !> Append one time step's row: to dynamic_log.csv at once (flushed), to dynamic.h5
   !> with the next frame (or when log_block rows are held).
   subroutine dynamic_output_step(w, log, err)
      type(dynamic_writer_t), intent(inout) :: w  !< open writer
      type(step_log_t), intent(in) :: log         !< the step's effort and balances
      type(error_t), intent(inout) :: err         !< status
      type(error_t) :: e
      character(len=row_len) :: row
      integer :: n
      if (.not. writer_ready(w, 'dynamic_output_step', err)) return
      if (w%csv) then
         n = 0
         call put_int(row, n, log%step)
         call put_real(row, n, log%time)
         call put_real(row, n, log%dt)
         call put_int(row, n, log%iterations)
         call put_int(row, n, log%cutbacks)
         call put_reals(row, n, [log%kinetic, log%strain, log%gravity, log%external_work, &
            log%damping_work, log%hydro_work, log%seabed_work, log%numerical_work, &
            log%numerical_energy, log%total, log%momentum, log%angular_momentum])
         call outfile_put(w%f_log, row(:n))
      end if
      if (w%hdf5) then
         w%n_pending = w%n_pending + 1
         w%pending(w%n_pending) = log
      end if
      w%steps = w%steps + 1
      w%steps_held = w%steps_held + 1
      w%progress%step_iterations = w%progress%step_iterations + log%iterations
      w%progress%step_tangents = w%progress%step_tangents + log%tangents
      w%progress%step_cutbacks = w%progress%step_cutbacks + log%cutbacks
      if (w%steps_held >= log_block) call sync(w, e)
      if (has_error(e)) call note_failure(w, e)
      if (has_error(e)) call set_error(err, e%code, e%message)
   end subroutine dynamic_output_step

   !> Append the support forces at the end of step `step` (0: the start state), at time
   !> `time`: one row per held end to dynamic_ends_step.csv, one row to each line's
   !> step_time, step_reactions and step_end_tension in dynamic.h5 (held until the next
   !> sync). reaction(:, k, l): force and moment of the
   !> support on line l at end k (A, B), as the frames' reactions (docs/output.md).
   subroutine dynamic_output_ends_step(w, step, time, reaction, err)
      type(dynamic_writer_t), intent(inout) :: w    !< open writer
      integer, intent(in) :: step                   !< step number (0: start) [-]
      real(wp), intent(in) :: time                  !< time at the end of the step [s]
      real(wp), intent(in) :: reaction(:, :, :)     !< (6, 2, lines) [N, N m]
      type(error_t), intent(inout) :: err           !< status
      character(len=row_len) :: row
      type(error_t) :: e
      integer :: i, j, n
      if (.not. writer_ready(w, 'dynamic_output_ends_step', err)) return
      do i = 1, size(w%line)
         associate (lo => w%line(i))
            if (w%csv) then
               do j = 1, 2
                  if (.not. line_row_kept(w%table(lt_ends_step), lo%end_held, j)) cycle
                  n = 0
                  call put_int(row, n, step)
                  call put_real(row, n, time)
                  call put_text(row, n, lo%head(lt_ends_step)%row(j)%s)
                  call put_end_values(w%table(lt_ends_step), reaction(:, j, i), row, n)
                  call outfile_put(w%f_ends_step, row(:n))
               end do
            end if
            if (w%hdf5) then
               call hdf5_append_steps(lo%step_time, [time], e)
               call hdf5_append_steps(lo%step_reactions, reshape(reaction(:, :, i), [12]), e)
               call hdf5_append_steps(lo%step_end_tension, [norm2(reaction(1:3, 1, i)), &
                                                            norm2(reaction(1:3, 2, i))], e)
            end if
         end associate
      end do
      if (has_error(e)) w%h5_failed = .true.
      if (.not. has_error(e)) w%end_rows = w%end_rows + 1
      if (has_error(e)) call note_failure(w, e)
      if (has_error(e)) call set_error(err, e%code, e%message)
   end subroutine dynamic_output_ends_step

   !> Append the sea and vessel outputs at the end of step `step` (0: the start state),
   !> time `time`: a row per probe, vessel and connection to the _step tables, and, when
   !> `frame`, to the frame tables (call before dynamic_output_frame of that time, so
   !> that the rows are synced with the frame). Does nothing for a run without them.
   subroutine dynamic_output_sea(w, step, time, v, frame, err)
      type(dynamic_writer_t), intent(inout) :: w    !< open writer
      integer, intent(in) :: step                   !< step number (0: start) [-]
      real(wp), intent(in) :: time                  !< time at the end of the step [s]
      type(sea_values_t), intent(in) :: v           !< the values (rodyn_sea_output)
      logical, intent(in) :: frame                  !< also a frame's rows
      type(error_t), intent(inout) :: err           !< status
      character(len=row_len) :: row
      integer :: k, n, ns
      type(error_t) :: e
      if (.not. any(w%sea_on)) return
      if (.not. writer_ready(w, 'dynamic_output_sea', err)) return
      if (w%hdf5) then
         call append_sea_h5(w, time, v, frame, e)
         if (has_error(e)) then
            w%h5_failed = .true.
            call note_failure(w, e)
            call set_error(err, e%code, e%message)
            return
         end if
      end if
      if (.not. w%csv) return
      ns = 0
      call put_int(row, ns, step)
      call put_real(row, ns, time)
      if (w%sea_on(sf_waves)) then
         do k = 1, size(w%probe_head)
            n = ns
            call put_text(row, n, w%probe_head(k)%s)
            call put_reals(row, n, [v%eta(k)])
            call outfile_put(w%f_sea(sf_waves_step), row(:n))
            if (frame) call outfile_put(w%f_sea(sf_waves), row(index(row, ',') + 1:n))
         end do
      end if
      if (w%sea_on(sf_vessels)) then
         do k = 1, size(w%vessel_head)
            n = ns
            call put_text(row, n, w%vessel_head(k)%s)
            call put_reals(row, n, v%pose(:, k))
            call put_reals(row, n, v%load(:, k))
            call outfile_put(w%f_sea(sf_vessels_step), row(:n))
            if (frame) call outfile_put(w%f_sea(sf_vessels), row(index(row, ',') + 1:n))
         end do
      end if
      if (w%sea_on(sf_conn)) then
         do k = 1, size(w%conn_head)
            n = ns
            call put_text(row, n, w%conn_head(k)%s)
            call put_reals(row, n, [v%conn(:, k), norm2(v%conn(1:3, k))])
            call outfile_put(w%f_sea(sf_conn_step), row(:n))
            if (frame) call outfile_put(w%f_sea(sf_conn), row(index(row, ',') + 1:n))
         end do
      end if
      if (w%sea_on(sf_bodies)) then
         do k = 1, size(w%body_head)
            n = ns
            call put_text(row, n, w%body_head(k)%s)
            call put_reals(row, n, v%body(:, k))
            call outfile_put(w%f_sea(sf_bodies_step), row(:n))
            if (frame) call outfile_put(w%f_sea(sf_bodies), row(index(row, ',') + 1:n))
         end do
      end if
   end subroutine dynamic_output_sea

   !> The values of dynamic_output_sea appended to /dynamic/sea (held until the next sync).
   subroutine append_sea_h5(w, time, v, frame, err)
      type(dynamic_writer_t), intent(inout) :: w    !< open writer
      real(wp), intent(in) :: time                  !< time [s]
      type(sea_values_t), intent(in) :: v           !< the values
      logical, intent(in) :: frame                  !< also at the frames
      type(error_t), intent(inout) :: err           !< status
      integer :: k
      real(wp), allocatable :: conn(:, :)
      allocate (conn(13, size(w%conn_head)))
      do k = 1, size(w%conn_head)
         conn(1:12, k) = v%conn(:, k)
         conn(13, k) = norm2(v%conn(1:3, k))
      end do
      call hdf5_append_steps(w%sea_h5(sh_step_time), [time], err)
      call put(sh_step_elevation, v%eta)
      call put(sh_step_motion, reshape(v%pose, [size(v%pose)]))
      call put(sh_step_load, reshape(v%load, [size(v%load)]))
      call put(sh_step_conn, reshape(conn, [size(conn)]))
      call put(sh_step_body, reshape(v%body, [size(v%body)]))
      if (.not. frame) return
      call put(sh_body, reshape(v%body, [size(v%body)]))
      call put(sh_elevation, v%eta)
      call put(sh_motion, reshape(v%pose, [size(v%pose)]))
      call put(sh_load, reshape(v%load, [size(v%load)]))
      call put(sh_conn, reshape(conn, [size(conn)]))
   contains
      !> One row of series k, if the run has it.
      subroutine put(k, row)
         integer, intent(in) :: k            !< sh_* index
         real(wp), intent(in) :: row(:)      !< the row
         if (w%sea_cols(k) > 0) call hdf5_append_steps(w%sea_h5(k), row, err)
      end subroutine put
   end subroutine append_sea_h5

   !> /dynamic/sea: the names of the probes, vessels and connections (attributes), the
   !> probes' points, and the empty series of the sea and vessel outputs (module header).
   subroutine create_h5_sea(w, err)
      type(dynamic_writer_t), intent(inout) :: w   !< writer, dynamic.h5 open
      type(error_t), intent(inout) :: err          !< status
      character(len=*), parameter :: g = '/dynamic/sea'
      real(wp), allocatable :: xy(:, :)
      integer :: k
      if (.not. any(w%sea_cols > 0) .or. has_error(err)) return
      associate (h5 => w%h5)
         call hdf5_create_group(h5, g, err)
         call hdf5_write_attribute(h5, g, 'probes', names(w%probe_head, 1), err)
         call hdf5_write_attribute(h5, g, 'vessels', names(w%vessel_head, 1), err)
         call hdf5_write_attribute(h5, g, 'connections', names(w%conn_head, 3), err)
         call hdf5_write_attribute(h5, g, 'bodies', names(w%body_head, 1), err)
         if (size(w%probe_head) > 0) then
            xy = w%probe_xy     ! (2, np): h5py's (np, 2), a row per probe
            call write_described(h5, dynamic_h5, g//'/probe_xy', err, x2=xy)
         end if
         do k = 1, n_sea_h5
            if (w%sea_cols(k) == 0) cycle
            if (k == sh_step_time) then
               call create_described_series(h5, dynamic_h5, g//'/'//trim(sea_h5_name(k)), &
                                            0, err, log_chunk, series=w%sea_h5(k))
            else
               call create_described_series(h5, dynamic_h5, g//'/'//trim(sea_h5_name(k)), &
                  w%sea_cols(k), err, max(8, chunk_bytes/(8*w%sea_cols(k))), &
                  series=w%sea_h5(k))
            end if
         end do
      end associate
   contains
      !> The names of the rows' heads ',A,B,...': the first nf fields, '/'-joined, then
      !> ', '-joined over the rows ('' when none).
      function names(heads, nf) result(s)
         type(text_t), intent(in) :: heads(:)  !< the heads
         integer, intent(in) :: nf             !< fields per name
         character(len=:), allocatable :: s
         character(len=:), allocatable :: h
         integer :: i, j, c
         s = ''
         do i = 1, size(heads)
            h = heads(i)%s(2:)//','
            c = 0
            do j = 1, len(h)
               if (h(j:j) /= ',') cycle
               c = c + 1
               if (c == nf) exit
               h(j:j) = '/'
            end do
            if (i > 1) s = s//', '
            s = s//h(:j - 1)
         end do
      end function names
   end subroutine create_h5_sea

   !> Finish the run's output: write everything still held (a last sync), the final
   !> attributes of dynamic.h5 (complete, status, steps, time reached, ...), close every
   !> file and rewrite status.txt from `summary` with the dynamic keys. Acts even when err
   !> already holds an error (a failed run still closes its files); an output failure
   !> is then recorded only if err was clear. After a write failure status.txt gives the
   !> time and steps of the last sync (what the files hold) and complete = false; a
   !> dynamic.h5 whose write failed is removed. Does nothing for a writer never opened.
   subroutine dynamic_output_close(w, summary, err)
      type(dynamic_writer_t), intent(inout) :: w   !< writer (closed on return)
      type(run_summary_t), intent(in) :: summary   !< how the run went
      type(error_t), intent(inout) :: err          !< status
      type(run_summary_t) :: s
      type(error_t) :: e, eh
      s = summary
      s%dynamic = .true.
      if (w%is_open .and. .not. w%failed) then
         call sync(w, e, rewrite_status=.false.)
         if (has_error(e)) call note_failure(w, e)
      end if
      if (w%failed) call as_synced(w, s)
      if (w%is_open .and. w%hdf5 .and. .not. w%h5_failed) then
         call write_final_attributes(w, s, eh)
         if (has_error(eh)) then
            w%h5_failed = .true.
            call note_failure(w, eh)
         end if
      end if
      call release_all(w, e)
      if (w%failed) call as_synced(w, s)
      if (.not. w%failed) s%frames = w%frames
      if (allocated(w%dir)) call output_write_status(w%dir, s, e, text_of(w%deck_file), &
                                                     w%params, committed_sizes(w))
      if (has_error(e)) call set_error(err, e%code, e%message)
      if (w%failed) call set_error(err, stat_io, w%why)
   end subroutine dynamic_output_close

   ! ------------------------------------------------------------------ set-up

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

   !> The sea and vessel tables a scene asks for, and the fixed start of their rows
   !> (after the step and time columns): the probes' names and points, the vessels'
   !> names, each connection's vessel, line and end.
   subroutine set_up_sea(w, model, sea)
      type(dynamic_writer_t), intent(inout) :: w  !< writer
      type(model_t), intent(in) :: model          !< model (names)
      type(sea_scene_t), intent(in) :: sea        !< the scene
      character(len=row_len) :: row
      integer :: k, n
      if (.not. sea%active) return
      w%sea_on(sf_waves) = sea%n_probes > 0
      w%sea_on(sf_waves_step) = sea%n_probes > 0
      w%sea_on(sf_vessels) = sea%n_vessels > 0
      w%sea_on(sf_vessels_step) = sea%n_vessels > 0
      w%sea_on(sf_conn) = sea%n_conn > 0
      w%sea_on(sf_conn_step) = sea%n_conn > 0
      w%sea_on(sf_bodies) = sea%n_bodies > 0
      w%sea_on(sf_bodies_step) = sea%n_bodies > 0
      allocate (w%probe_head(sea%n_probes), w%vessel_head(sea%n_vessels), &
                w%conn_head(sea%n_conn), w%body_head(sea%n_bodies))
      w%probe_xy = sea%probe_xy
      w%sea_cols = 0
      w%sea_cols([sh_elevation, sh_step_elevation]) = sea%n_probes
      w%sea_cols([sh_motion, sh_step_motion]) = 7*sea%n_vessels
      w%sea_cols([sh_load, sh_step_load]) = 12*sea%n_vessels
      w%sea_cols([sh_conn, sh_step_conn]) = 13*sea%n_conn
      w%sea_cols([sh_body, sh_step_body]) = 12*sea%n_bodies
      w%sea_cols(sh_step_time) = 1
      do k = 1, sea%n_probes
         n = 0
         call put_text(row, n, ','//csv_name(model%waves%probe_name(k)))
         call put_reals(row, n, sea%probe_xy(:, k))
         w%probe_head(k)%s = row(:n)
      end do
      do k = 1, sea%n_vessels
         w%vessel_head(k)%s = ','//csv_name(model%vessels(k)%name)
      end do
      do k = 1, sea%n_bodies
         w%body_head(k)%s = ','//csv_name(model%bodies(k)%name)
      end do
      do k = 1, sea%n_conn
         w%conn_head(k)%s = ','//csv_name(model%vessels(sea%conn_vessel(k))%name)//','// &
                            csv_name(model%lines(sea%conn_line(k))%name)//','// &
                            trim(sea%conn_end(k))
      end do
   end subroutine set_up_sea

   !> Create (truncate) one CSV table and write its header (flushed: a table of no frame).
   subroutine open_csv(w, name, header, f, err)
      type(dynamic_writer_t), intent(inout) :: w  !< writer (folder)
      character(len=*), intent(in) :: name        !< file name
      character(len=*), intent(in) :: header      !< header row
      type(out_file_t), intent(inout) :: f        !< the table
      type(error_t), intent(inout) :: err         !< status
      if (has_error(err)) return
      call outfile_create(f, w%dir, name, err, live=.true.)
      if (has_error(err)) return
      call outfile_put(f, header)
      call outfile_flush(f, err)
      call outfile_mark(f)
   end subroutine open_csv

   !> Create dynamic.h5: root attributes, /deck, each line's static datasets and empty
   !> time histories, the empty step log; keep the histories open (from their creation);
   !> flush.
   subroutine create_h5(w, model, lines, err)
      type(dynamic_writer_t), intent(inout) :: w   !< writer
      type(model_t), intent(in) :: model           !< model
      type(line_result_t), intent(in) :: lines(:)  !< initial state
      type(error_t), intent(inout) :: err          !< status
      integer :: i
      if (has_error(err)) return
      ! under a temporary name until the header and the empty datasets are on disk
      call hdf5_create_file(w%h5, temp_name(w%dir, dynamic_h5), err)
      if (has_error(err)) return
      associate (h5 => w%h5)
         call write_h5_root(h5, model, .false., running, err)
         call hdf5_write_attribute(h5, '/', 'scheme', scheme_name(model%dynamic%scheme), err)
         call hdf5_write_attribute(h5, '/', 'rho_inf', model%dynamic%rho_inf, err)
         call hdf5_write_attribute(h5, '/', 'dt', model%dynamic%dt, err)
         call write_described(h5, dynamic_h5, '/deck', err, text=text_of(model%deck_text))
         call hdf5_create_group(h5, '/dynamic', err)
         call hdf5_write_attribute(h5, '/dynamic', 'duration_s', model%dynamic%duration, err)
         call hdf5_write_attribute(h5, '/dynamic', 'output_interval_s', &
            model%dynamic%output_interval, err)
         call hdf5_write_attribute(h5, '/dynamic', 'ramp_s', model_ramp(model), err)
         call write_environment_h5(h5, model, err)
         call write_parameters_h5(h5, model, err)
         call create_described_series(h5, dynamic_h5, '/dynamic/time', 0, err, chunk_bytes/8, &
                                      series=w%time)
         do i = 1, size(lines)
            call create_h5_line(h5, '/dynamic/'//group_name(lines(i)%name, i, &
                                dynamic_members), lines(i), w%line(i), err)
         end do
         call create_h5_log(h5, w%log, err)
      end associate
      call create_h5_sea(w, err)
      call hold_h5_series(w, err)
      call flush_h5(w, err)
      if (.not. has_error(err)) then
         call commit_rename(temp_name(w%dir, dynamic_h5), path_join(w%dir, dynamic_h5), err)
         if (.not. has_error(err)) w%h5%path = path_join(w%dir, dynamic_h5)
      end if
   end subroutine create_h5

   !> Open every time history of an existing dynamic.h5 (w%h5 open) for appending, and
   !> hold the frames and the support forces of every step in memory (hold_h5_series).
   subroutine open_h5_series(w, lines, err)
      type(dynamic_writer_t), intent(inout) :: w   !< writer, w%h5 open
      type(line_result_t), intent(in) :: lines(:)  !< the lines (names)
      type(error_t), intent(inout) :: err          !< status
      character(len=:), allocatable :: g
      integer :: i, k
      call hdf5_open_series(w%h5, '/dynamic/time', w%time, err)
      do i = 1, size(lines)
         g = '/dynamic/'//group_name(lines(i)%name, i, dynamic_members)
         do k = 1, n_line_series
            call hdf5_open_series(w%h5, g//'/'//trim(line_series_name(k)), &
               w%line(i)%series(k), err)
         end do
         call hdf5_open_series(w%h5, g//'/step_reactions', w%line(i)%step_reactions, err)
         call hdf5_open_series(w%h5, g//'/step_end_tension', w%line(i)%step_end_tension, err)
         call hdf5_open_series(w%h5, g//'/step_time', w%line(i)%step_time, err)
      end do
      do k = 1, n_log_series
         call hdf5_open_series(w%h5, '/dynamic/log/'//trim(log_series_name(k)), w%log(k), &
            err)
      end do
      do k = 1, n_sea_h5
         if (w%sea_cols(k) > 0) call hdf5_open_series(w%h5, '/dynamic/sea/'// &
                                                      trim(sea_h5_name(k)), w%sea_h5(k), err)
      end do
      call hold_h5_series(w, err)
   end subroutine open_h5_series

   !> Hold the frames and the support forces of every step of the open time histories in
   !> memory (see the flush policy), to be written in blocks.
   subroutine hold_h5_series(w, err)
      type(dynamic_writer_t), intent(inout) :: w   !< writer, its histories open
      type(error_t), intent(inout) :: err          !< status
      integer :: i, k, nv
      if (has_error(err)) return
      nv = 1
      do i = 1, size(w%line)
         do k = 1, n_line_series
            nv = nv + int(w%line(i)%series(k)%n_cols)
         end do
      end do
      w%hold_frames = max(1, min(frame_block, hold_bytes/(8*nv)))
      call hdf5_series_hold(w%time, w%hold_frames)
      do i = 1, size(w%line)
         do k = 1, n_line_series
            call hdf5_series_hold(w%line(i)%series(k), w%hold_frames)
         end do
         call hdf5_series_hold(w%line(i)%step_reactions, log_block + 2)
         call hdf5_series_hold(w%line(i)%step_end_tension, log_block + 2)
         call hdf5_series_hold(w%line(i)%step_time, log_block + 2)
      end do
      do k = 1, n_sea_h5
         if (w%sea_cols(k) == 0) cycle
         call hdf5_series_hold(w%sea_h5(k), merge(w%hold_frames, log_block + 2, k < &
                                                  sh_step_elevation))
      end do
   end subroutine hold_h5_series

   !> Open the dynamic.h5 of an interrupted run again and cut every time history back
   !> to the rows of the checkpoint `mark` (frames, steps, rows of support forces).
   subroutine reopen_h5(w, lines, mark, err)
      type(dynamic_writer_t), intent(inout) :: w   !< writer
      type(line_result_t), intent(in) :: lines(:)  !< the lines (names)
      type(dynamic_output_mark_t), intent(in) :: mark !< rows kept
      type(error_t), intent(inout) :: err          !< status
      integer :: i, k
      if (has_error(err)) return
      call hdf5_open_file(w%h5, path_join(w%dir, dynamic_h5), err, writable=.true.)
      call hdf5_write_attribute(w%h5, '/', 'complete', 0, err)
      call hdf5_write_attribute(w%h5, '/', 'status', running, err)
      call open_h5_series(w, lines, err)
      call hdf5_series_truncate(w%time, mark%frames, err)
      do i = 1, size(lines)
         do k = 1, n_line_series
            call hdf5_series_truncate(w%line(i)%series(k), mark%frames, err)
         end do
         call hdf5_series_truncate(w%line(i)%step_reactions, mark%end_rows, err)
         call hdf5_series_truncate(w%line(i)%step_end_tension, mark%end_rows, err)
         call hdf5_series_truncate(w%line(i)%step_time, mark%end_rows, err)
      end do
      do k = 1, n_log_series
         call hdf5_series_truncate(w%log(k), mark%steps, err)
      end do
      do k = 1, n_sea_h5
         if (w%sea_cols(k) > 0) call hdf5_series_truncate(w%sea_h5(k), &
            merge(mark%frames, mark%end_rows, k < sh_step_elevation), err)
      end do
      call flush_h5(w, err)
   end subroutine reopen_h5

   !> One line's group: its static datasets and its empty time histories, left open in
   !> lo for appending.
   subroutine create_h5_line(h5, g, r, lo, err)
      type(hdf5_file_t), intent(in) :: h5    !< open file
      character(len=*), intent(in) :: g      !< group path
      type(line_result_t), intent(in) :: r   !< the line at open
      type(line_out_t), intent(inout) :: lo  !< the line's output (its series)
      type(error_t), intent(inout) :: err    !< status
      integer :: nn, ng
      nn = size(r%node_s)
      ng = size(r%gp_s)
      call hdf5_create_group(h5, g, err)
      call hdf5_write_attribute(h5, g, 'name', trim(r%name), err)
      call write_described(h5, dynamic_h5, g//'/node_s', err, g, x1=r%node_s)
      call write_described(h5, dynamic_h5, g//'/gp_s', err, g, x1=r%gp_s)
      call write_described(h5, dynamic_h5, g//'/gp_element', err, g, i1=r%gp_element)
      call write_described(h5, dynamic_h5, g//'/gp_point', err, g, i1=r%gp_point)
      call history(ls_x, nn)
      call history(ls_y, nn)
      call history(ls_z, nn)
      call history(ls_tension, ng)
      call history(ls_moment_1, ng)
      call history(ls_moment_2, ng)
      call history(ls_torque, ng)
      call history(ls_curvature, ng)
      call history(ls_reactions, 12)
      call hdf5_write_attribute(h5, g//'/reactions', 'end_held', merge(1, 0, r%end_held), &
         err)
      call history(ls_end_tension, 2)
      call history(ls_wall_tension, ng)
      call history(ls_seabed_normal, nn)
      call history(ls_seabed_friction, nn)
      call create_described_series(h5, dynamic_h5, g//'/step_time', 0, err, log_chunk, g, &
                                   series=lo%step_time)
      call create_described_series(h5, dynamic_h5, g//'/step_reactions', 12, err, &
                                   log_chunk/4, g, series=lo%step_reactions)
      call hdf5_write_attribute(h5, g//'/step_reactions', 'end_held', &
         merge(1, 0, r%end_held), err)
      call create_described_series(h5, dynamic_h5, g//'/step_end_tension', 2, err, &
                                   log_chunk, g, series=lo%step_end_tension)
      call create_described_series(h5, dynamic_h5, g//'/'//trim(line_series_name(ls_touchdown)), &
                                   0, err, chunk_bytes/8, g, series=lo%series(ls_touchdown))
   contains
      !> The empty history k (ls_*) of n values per frame, with its units and description.
      subroutine history(k, n)
         integer, intent(in) :: k                     !< ls_* index
         integer, intent(in) :: n                     !< values per frame
         call create_described_series(h5, dynamic_h5, g//'/'//trim(line_series_name(k)), n, &
                                      err, max(8, chunk_bytes/(8*n)), g, series=lo%series(k))
      end subroutine history
   end subroutine create_h5_line

   !> /dynamic/log: one empty 1-D dataset per quantity of step_log_t (momenta: 3 columns).
   subroutine create_h5_log(h5, log, err)
      type(hdf5_file_t), intent(in) :: h5    !< open file
      type(hdf5_series_t), intent(inout) :: log(:) !< (n_log_series) left open
      type(error_t), intent(inout) :: err    !< status
      character(len=*), parameter :: g = '/dynamic/log/'
      ! the 1-D datasets in the order created (the order h5py lists them)
      integer, parameter :: order(15) = [lg_step, lg_time, lg_dt, lg_iterations, &
         lg_cutbacks, lg_kinetic, lg_strain, lg_gravity, lg_external_work, lg_damping_work, &
         lg_hydro_work, lg_seabed_work, lg_numerical_work, lg_numerical_energy, lg_total]
      integer :: k
      call hdf5_create_group(h5, '/dynamic/log', err)
      do k = 1, size(order)
         call column(order(k), any(order(k) == [lg_step, lg_iterations, lg_cutbacks]))
      end do
      call create_described_series(h5, dynamic_h5, g//trim(log_series_name(lg_momentum)), 3, &
                                   err, log_chunk, series=log(lg_momentum))
      call create_described_series(h5, dynamic_h5, &
                                   g//trim(log_series_name(lg_angular_momentum)), 3, err, &
                                   log_chunk, series=log(lg_angular_momentum))
   contains
      !> One 1-D dataset of the log.
      subroutine column(k, integers)
         integer, intent(in) :: k                     !< lg_* index
         logical, intent(in) :: integers              !< integer values
         call create_described_series(h5, dynamic_h5, g//trim(log_series_name(k)), 0, &
                                      err, log_chunk, integers=integers, series=log(k))
      end subroutine column
   end subroutine create_h5_log

   ! ------------------------------------------------------------------ frames

   !> The frame's rows of dynamic_nodes.csv, dynamic_elements.csv, dynamic_ends.csv and
   !> dynamic_lines.csv, held until the next sync (failures are kept in the tables).
   subroutine write_frame_csv(w, time, lines)
      type(dynamic_writer_t), intent(inout) :: w   !< open writer
      real(wp), intent(in) :: time                 !< time of the frame [s]
      type(line_result_t), intent(in) :: lines(:)  !< state
      character(len=64) :: t
      integer :: nt
      nt = 0
      call put_real(t, nt, time)
      call append_rows(w%table(lt_nodes), lt_nodes, w%line, lines, t(:nt), w%f_nodes)
      call append_rows(w%table(lt_elements), lt_elements, w%line, lines, t(:nt), &
                       w%f_elements)
      call append_rows(w%table(lt_ends), lt_ends, w%line, lines, t(:nt), w%f_ends)
      call append_rows(w%table(lt_lines), lt_lines, w%line, lines, t(:nt), w%f_lines)
   end subroutine write_frame_csv

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

   !> The frame's values appended to dynamic.h5's series (held in memory until the
   !> next sync).
   subroutine write_frame_h5(w, time, lines, err)
      type(dynamic_writer_t), intent(inout) :: w   !< open writer
      real(wp), intent(in) :: time                 !< time of the frame [s]
      type(line_result_t), intent(in) :: lines(:)  !< state
      type(error_t), intent(inout) :: err          !< status
      integer :: i
      if (has_error(err)) return
      do i = 1, size(lines)
         associate (r => lines(i), s => w%line(i)%series)
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
      call hdf5_append_steps(w%time, [time], err)
   end subroutine write_frame_h5

   !> Sync: write everything held to disk, in this order: the CSV rows (the tables
   !> then marked as ending with a whole frame), the frames and step rows of dynamic.h5
   !> and its flush, then (unless rewrite_status is false) status.txt with the time and
   !> steps of the last frame: the files and status.txt then tell the same story.
   subroutine sync(w, err, rewrite_status)
      type(dynamic_writer_t), intent(inout) :: w      !< open writer
      type(error_t), intent(inout) :: err             !< status
      logical, intent(in), optional :: rewrite_status !< rewrite status.txt (default yes)
      type(error_t) :: eh
      integer(i8) :: c0
      integer :: i, k
      if (has_error(err) .or. w%failed) return
      if (w%csv) then
         call system_clock(c0)
         call outfile_flush(w%f_nodes, err)
         call outfile_flush(w%f_elements, err)
         call outfile_flush(w%f_ends, err)
         call outfile_flush(w%f_lines, err)
         call outfile_flush(w%f_log, err)
         call outfile_flush(w%f_ends_step, err)
         do i = 1, n_sea
            call outfile_flush(w%f_sea(i), err)
         end do
         w%flush_time = w%flush_time + seconds_since(c0)
         if (has_error(err)) return
      end if
      if (w%hdf5) then
         call hdf5_series_write_held(w%time, eh)
         do i = 1, size(w%line)
            do k = 1, n_line_series
               call hdf5_series_write_held(w%line(i)%series(k), eh)
            end do
            call hdf5_series_write_held(w%line(i)%step_reactions, eh)
            call hdf5_series_write_held(w%line(i)%step_end_tension, eh)
            call hdf5_series_write_held(w%line(i)%step_time, eh)
         end do
         do k = 1, n_sea_h5
            call hdf5_series_write_held(w%sea_h5(k), eh)
         end do
         call write_pending_log(w, eh)
         call flush_h5(w, eh)
         if (has_error(eh)) then
            w%h5_failed = .true.
            call set_error(err, eh%code, eh%message)
            return
         end if
      end if
      if (w%csv) then
         call outfile_mark(w%f_nodes)
         call outfile_mark(w%f_elements)
         call outfile_mark(w%f_ends)
         call outfile_mark(w%f_lines)
         call outfile_mark(w%f_log)
         call outfile_mark(w%f_ends_step)
         do i = 1, n_sea
            call outfile_mark(w%f_sea(i))
         end do
      end if
      w%frames_held = 0
      w%steps_held = 0
      w%progress%time_reached = w%last_time
      w%progress%steps = w%steps
      w%progress%frames = w%frames
      w%synced = w%progress
      if (present(rewrite_status)) then
         if (.not. rewrite_status) return
      end if
      w%progress%wall_time = w%static_wall_time + seconds_since(w%clock_start)
      call output_write_status(w%dir, w%progress, err, w%deck_file, w%params, &
                               committed_sizes(w))
      call system_clock(w%clock_status)
   end subroutine sync

   !> The writer takes rows: err clear, the writer open and not failed; else err says
   !> why (the failure recorded, or `who` called on a writer not open).
   logical function writer_ready(w, who, err) result(ok)
      type(dynamic_writer_t), intent(in) :: w      !< writer
      character(len=*), intent(in) :: who          !< caller, for the message
      type(error_t), intent(inout) :: err          !< status
      ok = .false.
      if (has_error(err)) return
      if (.not. w%is_open) then
         call set_error(err, stat_io, who//': the writer is not open')
      else if (w%failed) then
         call set_error(err, stat_io, w%why)
      else
         ok = .true.
      end if
   end function writer_ready

   !> The committed sizes of the CSV tables (their last sync) for status.txt; none when
   !> the run writes no CSV.
   function committed_sizes(w) result(c)
      type(dynamic_writer_t), intent(in) :: w   !< writer
      type(committed_t), allocatable :: c(:)    !< (6 + sea tables) or (0)
      integer :: k
      allocate (c(0))
      if (.not. w%csv) return
      c = [committed_t(nodes_csv, outfile_committed(w%f_nodes)), &
           committed_t(elements_csv, outfile_committed(w%f_elements)), &
           committed_t(ends_csv, outfile_committed(w%f_ends)), &
           committed_t(lines_csv, outfile_committed(w%f_lines)), &
           committed_t(log_csv, outfile_committed(w%f_log)), &
           committed_t(ends_step_csv, outfile_committed(w%f_ends_step))]
      do k = 1, n_sea
         if (w%sea_on(k)) c = [c, committed_t(trim(sea_csv(k)), outfile_committed(w%f_sea(k)))]
      end do
   end function committed_sizes

   !> Characters of CSV rows held in memory.
   pure integer function csv_held(w)
      type(dynamic_writer_t), intent(in) :: w   !< writer
      integer :: k
      csv_held = outfile_pending(w%f_nodes) + outfile_pending(w%f_elements) + &
         outfile_pending(w%f_ends) + outfile_pending(w%f_lines) + outfile_pending(w%f_log) &
         + outfile_pending(w%f_ends_step) + sum([(outfile_pending(w%f_sea(k)), k = 1, n_sea)])
   end function csv_held

   !> Record a write failure: nothing more is written.
   subroutine note_failure(w, e)
      type(dynamic_writer_t), intent(inout) :: w   !< writer
      type(error_t), intent(in) :: e               !< the failure
      if (w%failed .or. .not. has_error(e)) return
      w%failed = .true.
      w%why = e%message
   end subroutine note_failure

   !> A summary after a write failure: incomplete, the failure as status, and the time
   !> and steps of the last sync (what the files hold).
   subroutine as_synced(w, s)
      type(dynamic_writer_t), intent(in) :: w      !< writer (failed)
      type(run_summary_t), intent(inout) :: s      !< summary to adjust
      s%complete = .false.
      s%time_reached = w%synced%time_reached
      s%steps = w%synced%steps
      s%frames = w%synced%frames
      s%step_iterations = w%synced%step_iterations
      s%step_tangents = w%synced%step_tangents
      s%step_cutbacks = w%synced%step_cutbacks
      if (.not. allocated(s%status)) s%status = w%why
      if (s%status == 'complete' .or. s%status == running) s%status = w%why
   end subroutine as_synced

   !> Append the step rows held in memory to /dynamic/log and forget them.
   subroutine write_pending_log(w, err)
      type(dynamic_writer_t), intent(inout) :: w   !< open writer
      type(error_t), intent(inout) :: err          !< status
      real(wp), allocatable :: vec(:, :)
      integer :: n, k
      n = w%n_pending
      if (n == 0 .or. has_error(err)) return
      associate (p => w%pending(1:n), s => w%log)
         call hdf5_append_steps(s(lg_step), p%step, err)
         call hdf5_append_steps(s(lg_time), p%time, err)
         call hdf5_append_steps(s(lg_dt), p%dt, err)
         call hdf5_append_steps(s(lg_iterations), p%iterations, err)
         call hdf5_append_steps(s(lg_cutbacks), p%cutbacks, err)
         call hdf5_append_steps(s(lg_kinetic), p%kinetic, err)
         call hdf5_append_steps(s(lg_strain), p%strain, err)
         call hdf5_append_steps(s(lg_gravity), p%gravity, err)
         call hdf5_append_steps(s(lg_external_work), p%external_work, err)
         call hdf5_append_steps(s(lg_damping_work), p%damping_work, err)
         call hdf5_append_steps(s(lg_hydro_work), p%hydro_work, err)
         call hdf5_append_steps(s(lg_seabed_work), p%seabed_work, err)
         call hdf5_append_steps(s(lg_numerical_work), p%numerical_work, err)
         call hdf5_append_steps(s(lg_numerical_energy), p%numerical_energy, err)
         call hdf5_append_steps(s(lg_total), p%total, err)
         allocate (vec(3, n))
         do k = 1, n
            vec(:, k) = p(k)%momentum
         end do
         call hdf5_append_steps(s(lg_momentum), vec, err)
         do k = 1, n
            vec(:, k) = p(k)%angular_momentum
         end do
         call hdf5_append_steps(s(lg_angular_momentum), vec, err)
      end associate
      w%n_pending = 0
   end subroutine write_pending_log

   !> Final attributes of dynamic.h5 from the run summary.
   subroutine write_final_attributes(w, s, err)
      type(dynamic_writer_t), intent(inout) :: w   !< open writer
      type(run_summary_t), intent(in) :: s         !< how the run went
      type(error_t), intent(inout) :: err          !< status
      associate (h5 => w%h5)
         call hdf5_write_attribute(h5, '/', 'complete', merge(1, 0, s%complete), err)
         call hdf5_write_attribute(h5, '/', 'status', one_line(status_of(s)), err)
         call hdf5_write_attribute(h5, '/dynamic', 'frames', w%frames, err)
         call hdf5_write_attribute(h5, '/dynamic', 'steps', s%steps, err)
         call hdf5_write_attribute(h5, '/dynamic', 'time_reached_s', s%time_reached, err)
         call hdf5_write_attribute(h5, '/dynamic', 'step_iterations', s%step_iterations, err)
         call hdf5_write_attribute(h5, '/dynamic', 'step_tangents', s%step_tangents, err)
         call hdf5_write_attribute(h5, '/dynamic', 'step_cutbacks', s%step_cutbacks, err)
         call hdf5_write_attribute(h5, '/dynamic', 'wall_time_s', s%wall_time, err)
      end associate
   end subroutine write_final_attributes

   ! ------------------------------------------------------------------ files

   !> Close every file and dataset of the writer (errors recorded in err) and free its
   !> scratch; keeps dir and deck_file for status.txt. After a failure (w%failed) the
   !> CSV tables are cut back to their last sync and what dynamic.h5 holds in memory is
   !> dropped; a dynamic.h5 whose write or close failed is removed.
   subroutine release_all(w, err)
      type(dynamic_writer_t), intent(inout) :: w   !< writer
      type(error_t), intent(inout) :: err          !< status
      type(error_t) :: eh
      integer :: i, k
      if (w%failed) then     ! rows held since the last sync are dropped
         call outfile_abort(w%f_nodes)
         call outfile_abort(w%f_elements)
         call outfile_abort(w%f_ends)
         call outfile_abort(w%f_log)
         call outfile_abort(w%f_ends_step)
         call outfile_abort(w%f_lines)
         do k = 1, n_sea
            call outfile_abort(w%f_sea(k))
         end do
      else
         call outfile_close(w%f_nodes, err)
         call outfile_close(w%f_elements, err)
         call outfile_close(w%f_ends, err)
         call outfile_close(w%f_log, err)
         call outfile_close(w%f_ends_step, err)
         call outfile_close(w%f_lines, err)
         do k = 1, n_sea
            call outfile_close(w%f_sea(k), err)
         end do
      end if
      ! after a failure the held steps are dropped (the series see an error)
      if (w%failed) call set_error(eh, stat_io, w%why)
      call hdf5_close_series(w%time, eh)
      do k = 1, n_log_series
         call hdf5_close_series(w%log(k), eh)
      end do
      if (allocated(w%line)) then
         do i = 1, size(w%line)
            do k = 1, n_line_series
               call hdf5_close_series(w%line(i)%series(k), eh)
            end do
            call hdf5_close_series(w%line(i)%step_reactions, eh)
            call hdf5_close_series(w%line(i)%step_end_tension, eh)
            call hdf5_close_series(w%line(i)%step_time, eh)
         end do
         deallocate (w%line)
      end if
      do k = 1, n_sea_h5
         call hdf5_close_series(w%sea_h5(k), eh)
      end do
      if (w%h5%id >= 0) then
         call hdf5_close_file(w%h5, eh)
         if (has_error(eh)) then
            w%h5_failed = .true.
            call note_failure(w, eh)
         end if
      end if
      if (w%h5_failed .and. allocated(w%dir)) then
         call remove_file(temp_name(w%dir, dynamic_h5))
         call remove_file(path_join(w%dir, dynamic_h5))
      end if
      if (allocated(w%pending)) deallocate (w%pending)
      w%n_pending = 0
      w%is_open = .false.
   end subroutine release_all

   !> Flush dynamic.h5, timing it.
   subroutine flush_h5(w, err)
      type(dynamic_writer_t), intent(inout) :: w  !< writer (flush_time)
      type(error_t), intent(inout) :: err         !< status
      integer(i8) :: c0
      call system_clock(c0)
      call hdf5_flush(w%h5, err)
      w%flush_time = w%flush_time + seconds_since(c0)
   end subroutine flush_h5


   ! ------------------------------------------------------------------ helpers

   !> The time-integration scheme's name ('EMC', ...).
   pure function scheme_name(scheme) result(s)
      integer, intent(in) :: scheme         !< scheme_* constant
      character(len=:), allocatable :: s    !< its name
      if (scheme >= 1 .and. scheme <= size(scheme_names)) then
         s = trim(scheme_names(scheme))
      else
         s = 'UNKNOWN'
      end if
   end function scheme_name




   !> Wall time since a system_clock count [s].
   real(wp) function seconds_since(c0)
      integer(i8), intent(in) :: c0  !< earlier count of system_clock
      integer(i8) :: c, rate
      call system_clock(c, rate)
      seconds_since = real(c - c0, wp)/real(max(rate, 1_i8), wp)
   end function seconds_since

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

end module rodyn_output_dynamic
