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
!> What each part writes: the CSV tables as one list (rodyn_output_dynamic_files), the
!> lines' rows and groups (rodyn_output_dynamic_lines), the step log
!> (rodyn_output_dynamic_log), the sea, vessel and body outputs
!> (rodyn_output_dynamic_sea); this module opens, syncs and closes them together. The
!> rows of the line tables and the described datasets are laid out by
!> rodyn_output_table, the table writer the static output uses too; numbers are written
!> by rodyn_format (17 significant digits, 1.2345678901234567E+05), as in every table.
module rodyn_output_dynamic
   use rodyn_kinds, only: wp, i8
   use rodyn_error, only: error_t, set_error, has_error, stat_io
   use rodyn_model, only: model_t, scheme_names, parameter_value_t, model_ramp
   use rodyn_results, only: line_result_t, run_summary_t, step_log_t
   use rodyn_hdf5, only: hdf5_file_t, hdf5_series_t, hdf5_create_file, hdf5_close_file, &
      hdf5_flush, hdf5_create_group, hdf5_write_attribute, hdf5_open_series, &
      hdf5_close_series, hdf5_series_hold, hdf5_series_write_held, hdf5_series_truncate, &
      hdf5_open_file, hdf5_append_steps
   use rodyn_output, only: output_write_status, output_write_environment
   use rodyn_sea_output, only: sea_scene_t, sea_values_t
   use rodyn_outfile, only: temp_name, commit_rename, remove_file
   use rodyn_output_common, only: text_or, status_of, path_join, one_line, &
                                  write_environment_h5, write_parameters_h5
   use rodyn_output_table, only: line_table_t, write_described, create_described_series, &
                                 write_h5_root, check_line_results, line_result_fits
   use rodyn_output_dynamic_files, only: dynamic_files_t, n_tables, tb_log, &
      tb_waves, tb_bodies_step, files_create, files_reopen, files_flush, files_mark, &
      files_close, files_committed, files_pending, files_written
   use rodyn_output_dynamic_series, only: log_block, frame_block, hold_bytes, chunk_bytes, &
      series_do, s_hold, s_cut, s_write, s_close
   use rodyn_output_dynamic_lines, only: line_out_t, n_line_tables, &
      n_frame_series, dynamic_h5, line_tables, set_up_line, create_h5_lines, open_h5_lines, &
      write_frame_rows, write_frame_h5, write_ends_step
   use rodyn_output_dynamic_log, only: n_log_series, write_log_row, create_h5_log, &
      open_h5_log, write_log_h5
   use rodyn_output_dynamic_sea, only: sea_out_t, n_sea_frame, set_up_sea, sea_tables, &
      write_sea_rows, write_sea_h5, create_h5_sea, open_h5_sea
   implicit none
   private
   public :: dynamic_writer_t
   public :: dynamic_output_open, dynamic_output_frame, dynamic_output_step
   public :: dynamic_output_ends_step, dynamic_output_mark, dynamic_output_mark_t
   public :: dynamic_output_close, dynamic_output_sea, dynamic_output_keeps_frames

   character(len=*), parameter :: running = 'running'
   real(wp), parameter :: status_interval = 1.0_wp !< least wall time between rewrites
                                                   !< of status.txt while running [s]

   !> Where the output of a run stands at a checkpoint (dynamic_output_mark): what the
   !> files hold, and the writer's counters; dynamic_output_open continues from it.
   type :: dynamic_output_mark_t
      integer(i8) :: csv_bytes(n_tables) = 0_i8 !< bytes of dynamic_nodes, _elements,
                                          !< _ends, _log, _lines, _ends_step.csv, then of
                                          !< the sea tables (0 when not written)
      integer :: frames = 0               !< frames written
      integer :: steps = 0                !< step rows written
      integer :: end_rows = 0             !< rows of support forces of every step
      real(wp) :: last_time = 0.0_wp      !< time of the last frame [s]
      integer :: step_iterations = 0      !< Newton iterations so far
      integer :: step_tangents = 0        !< tangents so far
      integer :: step_cutbacks = 0        !< halvings so far
   end type dynamic_output_mark_t

   !> The open output of a dynamic run: its tables, the HDF5 file and its open datasets,
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
      type(dynamic_files_t) :: files                 !< the CSV tables
      type(line_table_t) :: table(n_line_tables)     !< the layouts of the line tables
      type(sea_out_t) :: sea                         !< the sea, vessel and body outputs
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
      w%deck_file = text_or(model%deck_file, '')
      if (allocated(model%parameters)) w%params = model%parameters
      w%csv = model%output%csv
      w%hdf5 = model%output%hdf5
      call start_counters(w, static_summary, resume)
      call check_line_results(lines, where, err)
      call line_tables(w%table, err)
      if (has_error(err)) return
      call output_write_status(dir, w%progress, e, w%deck_file, w%params)  ! makes the folder
      allocate (w%line(size(lines)), w%pending(log_block))
      do i = 1, size(lines)
         call set_up_line(w%line(i), lines(i), w%table)
      end do
      w%sea = sea_out_t()
      if (present(sea)) call set_up_sea(w%sea, model, sea)
      w%files%on = .false.
      if (w%csv) then
         w%files%on(:tb_waves - 1) = .true.
         w%files%on(tb_waves:tb_bodies_step) = sea_tables(w%sea)
      end if
      if (present(resume)) then
         call files_reopen(w%files, dir, resume%csv_bytes, e)
      else
         call files_create(w%files, dir, e)
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
         call note_failure(w, e, err)
         call release_all(w, e)
         return
      end if
      w%is_open = .true.
   end subroutine dynamic_output_open

   !> The writer's counters and its progress at open: from zero, or from the checkpoint
   !> `resume`; status.txt keeps the static run's summary meanwhile.
   subroutine start_counters(w, static_summary, resume)
      type(dynamic_writer_t), intent(inout) :: w        !< the writer
      type(run_summary_t), intent(in), optional :: static_summary !< the static run
      type(dynamic_output_mark_t), intent(in), optional :: resume !< a checkpoint
      type(dynamic_output_mark_t) :: m
      m = dynamic_output_mark_t()
      if (present(resume)) m = resume
      w%frames = m%frames
      w%steps = m%steps
      w%end_rows = m%end_rows
      w%last_time = m%last_time
      w%n_pending = 0
      w%frames_held = 0
      w%steps_held = 0
      w%failed = .false.
      w%h5_failed = .false.
      w%flush_time = 0.0_wp
      w%progress = run_summary_t()
      if (present(static_summary)) w%progress = static_summary
      w%progress%complete = .false.
      w%progress%status = running
      w%progress%dynamic = .true.
      w%progress%time_reached = m%last_time
      w%progress%steps = m%steps
      w%progress%step_iterations = m%step_iterations
      w%progress%step_tangents = m%step_tangents
      w%progress%step_cutbacks = m%step_cutbacks
      w%synced = w%progress
      w%static_wall_time = w%progress%wall_time
      call system_clock(w%clock_start)
      w%clock_status = w%clock_start
   end subroutine start_counters

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
      call note_failure(w, e, err)
      if (has_error(e)) return
      mark%csv_bytes = files_written(w%files)
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
      if (.not. writer_ready(w, where, err)) return
      if (w%csv) call write_frame_rows(w%table, w%line, lines, time, w%files)
      if (w%hdf5) then
         call write_frame_h5(w%line, lines, e)
         call hdf5_append_steps(w%time, [time], e)
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
             files_pending(w%files) > hold_bytes) call sync(w, e)
      end if
      call note_failure(w, e, err)
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
      if (.not. writer_ready(w, 'dynamic_output_step', err)) return
      if (w%csv) call write_log_row(log, w%files%f(tb_log))
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
      call note_failure(w, e, err)
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
      type(error_t) :: e
      if (.not. writer_ready(w, 'dynamic_output_ends_step', err)) return
      call write_ends_step(w%table, w%line, step, time, reaction, w%csv, w%hdf5, w%files, e)
      if (.not. has_error(e)) w%end_rows = w%end_rows + 1
      call note_failure(w, e, err, h5=.true.)
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
      type(error_t) :: e
      if (.not. w%sea%active) return
      if (.not. writer_ready(w, 'dynamic_output_sea', err)) return
      if (w%hdf5) then
         call write_sea_h5(w%sea, time, v, frame, e)
         call note_failure(w, e, err, h5=.true.)
         if (has_error(e)) return
      end if
      if (w%csv) call write_sea_rows(w%sea, w%files, step, time, v, frame)
   end subroutine dynamic_output_sea

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
         call note_failure(w, e)
      end if
      if (w%failed) call as_synced(w, s)
      if (w%is_open .and. w%hdf5 .and. .not. w%h5_failed) then
         call write_final_attributes(w, s, eh)
         call note_failure(w, eh, h5=.true.)
      end if
      call release_all(w, e)
      if (w%failed) call as_synced(w, s)
      if (.not. w%failed) s%frames = w%frames
      if (allocated(w%dir)) call output_write_status(w%dir, s, e, text_or(w%deck_file, ''), &
                                                     w%params, files_committed(w%files))
      if (has_error(e)) call set_error(err, e%code, e%message)
      if (w%failed) call set_error(err, stat_io, w%why)
   end subroutine dynamic_output_close

   ! ------------------------------------------------------------------ dynamic.h5

   !> Create dynamic.h5: root attributes, /deck, each line's static datasets and empty
   !> time histories, the empty step log and sea series; keep the histories open (from
   !> their creation); flush.
   subroutine create_h5(w, model, lines, err)
      type(dynamic_writer_t), intent(inout) :: w   !< writer
      type(model_t), intent(in) :: model           !< model
      type(line_result_t), intent(in) :: lines(:)  !< initial state
      type(error_t), intent(inout) :: err          !< status
      if (has_error(err)) return
      ! under a temporary name until the header and the empty datasets are on disk
      call hdf5_create_file(w%h5, temp_name(w%dir, dynamic_h5), err)
      if (has_error(err)) return
      associate (h5 => w%h5)
         call write_h5_root(h5, model, .false., running, err)
         call hdf5_write_attribute(h5, '/', 'scheme', scheme_name(model%dynamic%scheme), err)
         call hdf5_write_attribute(h5, '/', 'rho_inf', model%dynamic%rho_inf, err)
         call hdf5_write_attribute(h5, '/', 'dt', model%dynamic%dt, err)
         call write_described(h5, dynamic_h5, '/deck', err, text=text_or(model%deck_text, ''))
         call hdf5_create_group(h5, '/dynamic', err)
         call hdf5_write_attribute(h5, '/dynamic', 'duration_s', model%dynamic%duration, err)
         call hdf5_write_attribute(h5, '/dynamic', 'output_interval_s', &
            model%dynamic%output_interval, err)
         call hdf5_write_attribute(h5, '/dynamic', 'ramp_s', model_ramp(model), err)
         call write_environment_h5(h5, model, err)
         call write_parameters_h5(h5, model, err)
         call create_described_series(h5, dynamic_h5, '/dynamic/time', 0, err, chunk_bytes/8, &
                                      series=w%time)
         call create_h5_lines(h5, lines, w%line, err)
         call create_h5_log(h5, w%log, err)
         call create_h5_sea(w%sea, h5, err)
      end associate
      call hold_h5_series(w, err)
      call flush_h5(w, err)
      if (.not. has_error(err)) then
         call commit_rename(temp_name(w%dir, dynamic_h5), path_join(w%dir, dynamic_h5), err)
         if (.not. has_error(err)) w%h5%path = path_join(w%dir, dynamic_h5)
      end if
   end subroutine create_h5

   !> Hold the frames and the support forces of every step of the open time histories in
   !> memory (see the flush policy), to be written in blocks.
   subroutine hold_h5_series(w, err)
      type(dynamic_writer_t), intent(inout) :: w   !< writer, its histories open
      type(error_t), intent(inout) :: err          !< status
      integer :: i, k, nv
      if (has_error(err)) return
      nv = 1
      do i = 1, size(w%line)
         do k = 1, n_frame_series
            nv = nv + int(w%line(i)%series(k)%n_cols)
         end do
      end do
      w%hold_frames = max(1, min(frame_block, hold_bytes/(8*nv)))
      call hdf5_series_hold(w%time, w%hold_frames)
      do i = 1, size(w%line)
         call series_do(w%line(i)%series, s_hold, err, n_frame_series, w%hold_frames, &
                        log_block + 2)
      end do
      call series_do(w%sea%h5, s_hold, err, n_sea_frame, w%hold_frames, log_block + 2)
   end subroutine hold_h5_series

   !> Open the dynamic.h5 of an interrupted run again and cut every time history back
   !> to the rows of the checkpoint `mark` (frames, steps, rows of support forces); hold
   !> the frames and the support forces of every step in memory (hold_h5_series).
   subroutine reopen_h5(w, lines, mark, err)
      type(dynamic_writer_t), intent(inout) :: w   !< writer
      type(line_result_t), intent(in) :: lines(:)  !< the lines (names)
      type(dynamic_output_mark_t), intent(in) :: mark !< rows kept
      type(error_t), intent(inout) :: err          !< status
      integer :: i
      if (has_error(err)) return
      call hdf5_open_file(w%h5, path_join(w%dir, dynamic_h5), err, writable=.true.)
      call hdf5_write_attribute(w%h5, '/', 'complete', 0, err)
      call hdf5_write_attribute(w%h5, '/', 'status', running, err)
      call hdf5_open_series(w%h5, '/dynamic/time', w%time, err)
      call open_h5_lines(w%h5, lines, w%line, err)
      call open_h5_log(w%h5, w%log, err)
      call open_h5_sea(w%sea, w%h5, err)
      call hold_h5_series(w, err)
      call hdf5_series_truncate(w%time, mark%frames, err)
      do i = 1, size(lines)
         call series_do(w%line(i)%series, s_cut, err, n_frame_series, mark%frames, &
                        mark%end_rows)
      end do
      call series_do(w%log, s_cut, err, 0, mark%steps, mark%steps)
      call series_do(w%sea%h5, s_cut, err, n_sea_frame, mark%frames, mark%end_rows)
      call flush_h5(w, err)
   end subroutine reopen_h5

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
      integer :: i
      if (has_error(err) .or. w%failed) return
      if (w%csv) then
         call system_clock(c0)
         call files_flush(w%files, err)
         w%flush_time = w%flush_time + seconds_since(c0)
         if (has_error(err)) return
      end if
      if (w%hdf5) then
         call hdf5_series_write_held(w%time, eh)
         do i = 1, size(w%line)
            call series_do(w%line(i)%series, s_write, eh)
         end do
         call series_do(w%sea%h5, s_write, eh)
         if (.not. has_error(eh)) then
            call write_log_h5(w%log, w%pending(1:w%n_pending), eh)
            w%n_pending = 0
         end if
         call flush_h5(w, eh)
         if (has_error(eh)) then
            w%h5_failed = .true.
            call set_error(err, eh%code, eh%message)
            return
         end if
      end if
      if (w%csv) call files_mark(w%files)
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
                               files_committed(w%files))
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

   !> Record a write failure e (nothing when e holds none): nothing more is written. h5:
   !> a failure of dynamic.h5; err, the caller's status, gets it too.
   subroutine note_failure(w, e, err, h5)
      type(dynamic_writer_t), intent(inout) :: w    !< writer
      type(error_t), intent(in) :: e                !< the failure, if any
      type(error_t), intent(inout), optional :: err !< the caller's status
      logical, intent(in), optional :: h5           !< a failure of dynamic.h5
      if (.not. has_error(e)) return
      if (present(h5)) w%h5_failed = w%h5_failed .or. h5
      if (present(err)) call set_error(err, e%code, e%message)
      if (w%failed) return
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

   !> Close every file and dataset of the writer (errors recorded in err) and free its
   !> scratch; keeps dir and deck_file for status.txt. After a failure (w%failed) the
   !> CSV tables are cut back to their last sync and what dynamic.h5 holds in memory is
   !> dropped; a dynamic.h5 whose write or close failed is removed.
   subroutine release_all(w, err)
      type(dynamic_writer_t), intent(inout) :: w   !< writer
      type(error_t), intent(inout) :: err          !< status
      type(error_t) :: eh
      integer :: i
      ! after a failure the rows held since the last sync are dropped
      call files_close(w%files, w%failed, err)
      ! after a failure the held steps are dropped (the series see an error)
      if (w%failed) call set_error(eh, stat_io, w%why)
      call hdf5_close_series(w%time, eh)
      call series_do(w%log, s_close, eh)
      if (allocated(w%line)) then
         do i = 1, size(w%line)
            call series_do(w%line(i)%series, s_close, eh)
         end do
         deallocate (w%line)
      end if
      call series_do(w%sea%h5, s_close, eh)
      if (w%h5%id >= 0) then
         call hdf5_close_file(w%h5, eh)
         call note_failure(w, eh, h5=.true.)
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

end module rodyn_output_dynamic
