!> The dynamic analysis as the program runs it: set-up from the start state, the time
!> loop, and the outputs written while it runs (frames, step log, progress line).
!> The run's context (its writer, the start state, the pending support forces, the
!> progress clock) is a timeloop observer, dynamic_run_t, that lives for one call of
!> run_dynamic; the time loop hands it back at each frame, step and checkpoint.
module rodyn_run_dynamic
   use, intrinsic :: iso_fortran_env, only: error_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error, set_error, clear_error
   use rodyn_model, only: model_t, end_a, end_b
   use rodyn_mesh, only: mesh_t, mesh_node
   use rodyn_state, only: state_t, state_copy
   use rodyn_results, only: line_result_t, run_summary_t, step_log_t
   use rodyn_dynamics, only: dynamic_problem_t, dynamics_setup
   use rodyn_system_dynamics, only: apply_initial_velocities
   use rodyn_timeloop, only: timeloop_run, timeloop_state_t, timeloop_observer_t
   use rodyn_checkpoint, only: checkpoint_t, checkpoint_write, checkpoint_file, &
                               checkpoint_problem, checkpoint_program_id, pending_forces_t
   use rodyn_outfile, only: remove_file, path_join
   use rodyn_water, only: water_set_time
   use rodyn_recovery, only: recover_state
   use rodyn_output_dynamic, only: dynamic_writer_t, dynamic_output_open, &
                                   dynamic_output_frame, dynamic_output_step, &
                                   dynamic_output_close, dynamic_output_ends_step, &
                                   dynamic_output_mark, dynamic_output_sea, &
                                   dynamic_output_keeps_frames
   use rodyn_sea_output, only: sea_scene_t, sea_values_t, sea_scene_build, sea_values
   implicit none
   private
   public :: run_dynamic, dynamic_not_available, stderr_is_terminal

   interface
      function c_isatty(fd) result(r) bind(c, name='isatty')
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: r
      end function c_isatty
      !> raise(3): the test hook's SIGKILL.
      function c_raise(sig) result(r) bind(c, name='raise')
         import :: c_int
         integer(c_int), value :: sig
         integer(c_int) :: r
      end function c_raise
   end interface

   !> The context of one call of run_dynamic, as the time loop's observer.
   type, extends(timeloop_observer_t) :: dynamic_run_t
      type(dynamic_writer_t) :: writer
      type(line_result_t), allocatable :: frame_lines(:)
      type(model_t), pointer :: model => null()
      type(run_summary_t), pointer :: summary => null()
      character(len=:), allocatable :: dir           !< output folder (checkpoints)
      character(len=:), allocatable :: program_id    !< checkpoint_program_id(), once a run
      type(state_t) :: start_state                   !< state at t = 0 (checkpoints)
      integer :: kill_after = -1                     !< test hook: SIGKILL after this step
      real(wp), allocatable :: r_start(:, :)        !< support forces of the start state
      ! Support forces at the end of every step (see write_pending): the last step
      ! waits, pending, for the step after it; so does a frame at its end
      type(pending_forces_t) :: pend
      real(wp), allocatable :: r_frame(:, :)      !< (6, nn) the forces written
      logical :: show_progress = .false.
      type(sea_scene_t) :: scene      !< probes, vessels and connections written (if any)
      type(sea_values_t) :: sea_now   !< their values at the last time written
      integer(kind=8) :: clock0 = 0, clock_last = 0, clock_rate = 1
   contains
      procedure :: on_frame
      procedure :: on_step
      procedure :: after_step
      procedure :: on_checkpoint
      procedure :: write_pending
      procedure :: end_forces
   end type dynamic_run_t

contains

   !> Features the deck language accepts but this version does not compute: a message
   !> for the user (empty when the deck can run).
   function dynamic_not_available(model) result(msg)
      type(model_t), intent(in) :: model !< model
      character(len=:), allocatable :: msg
      msg = ''
      if (.not. model%dynamic%requested) return
   end function dynamic_not_available

   !> True when standard error is a terminal (the progress line is shown there).
   logical function stderr_is_terminal()
      stderr_is_terminal = c_isatty(2_c_int) == 1_c_int
   end function stderr_is_terminal

   !> Run the dynamic analysis from state (the static solution or the defined start) and
   !> write its outputs into dir. r0: support forces of the start state (for frame 0).
   !> With resume (rodyn --restart), continue the run of that checkpoint instead: the
   !> state is the checkpoint's start state, and the files in dir are continued.
   !> The environment variable RODYN_TEST_KILL_AFTER_STEP=N (a test hook) makes the
   !> program kill itself with SIGKILL once step N has been handed to the writer.
   subroutine run_dynamic(model, mesh, state, r0, dir, summary, err, log_unit, progress, &
                          resume)
      type(model_t), intent(in), target :: model     !< model
      type(mesh_t), intent(in), target :: mesh       !< mesh
      type(state_t), intent(inout), target :: state  !< start, then final state
      real(wp), intent(in) :: r0(:, :)               !< (6, nn) start support forces
      character(len=*), intent(in) :: dir            !< output folder
      type(run_summary_t), intent(inout), target :: summary !< progress (dynamic fields)
      type(error_t), intent(inout) :: err            !< status
      integer, intent(in) :: log_unit                !< Newton log (< 0: none)
      logical, intent(in) :: progress                !< show the progress line
      type(checkpoint_t), intent(in), optional :: resume !< continue from this checkpoint
      type(dynamic_problem_t) :: prob
      type(error_t) :: werr
      type(dynamic_run_t), target :: run
      run%model => model
      run%summary => summary
      call set_up(run, prob, mesh, state, r0, dir, progress, present(resume))
      if (present(resume)) then
         call dynamic_output_open(run%writer, dir, model, run%frame_lines, err, &
                                  resume=resume%mark, sea=run%scene)
         if (.not. has_error(err)) call restore(run, prob, resume)
      else
         ! a checkpoint of an earlier run in this folder no longer fits its files
         call remove_file(path_join(dir, checkpoint_file))
         call dynamic_output_open(run%writer, dir, model, run%frame_lines, err, sea=run%scene)
      end if
      if (has_error(err)) then
         ! status.txt says so (it must not keep the static run's complete = true)
         summary%dynamic = .true.
         summary%complete = .false.
         summary%status = err%message
         call dynamic_output_close(run%writer, summary, werr)
         return
      end if
      call system_clock(run%clock0, run%clock_rate)
      run%clock_last = run%clock0
      summary%dynamic = .true.
      run%after_step_used = .true.
      run%checkpoints_used = .true.
      if (present(resume)) then
         call timeloop_run(prob, model, summary, err, log_unit, run, resume%loop)
      else
         call timeloop_run(prob, model, summary, err, log_unit, run)
      end if
      block
         integer(kind=8) :: clock_end
         call system_clock(clock_end)
         ! wall time of the whole run: the static solve before plus the dynamics
         summary%wall_time = summary%wall_time + real(clock_end - run%clock0, wp) &
                             /real(run%clock_rate, wp)
      end block
      if (run%show_progress) write (error_unit, '(a)') ''
      ! the last step (and a frame at its end) still waiting for the step after it (the
      ! run stopped, or the step past the end failed): extrapolated
      if (run%pend%pending) then
         call clear_error(werr)
         call run%write_pending(prob, .false., werr)
         if (has_error(werr) .and. .not. has_error(err)) call set_error(err, werr%code, &
                                                                        werr%message)
      end if
      if (.not. has_error(err)) then
         summary%complete = .true.
         summary%status = 'complete'
      else
         summary%complete = .false.
         if (.not. allocated(summary%status)) summary%status = err%message
      end if
      call dynamic_output_close(run%writer, summary, werr)
      if (has_error(werr) .and. .not. has_error(err)) call set_error(err, werr%code, werr%message)
   end subroutine run_dynamic

   !> The run's context before its output is opened (run%model set): the test hook, no
   !> support forces pending, the start state (with its initial velocities unless the
   !> run starts from the static state or a checkpoint), the problem set up from it, the
   !> sea scene, and the start state's results in run%frame_lines.
   subroutine set_up(run, prob, mesh, state, r0, dir, progress, resuming)
      type(dynamic_run_t), intent(inout) :: run      !< the run
      type(dynamic_problem_t), intent(inout) :: prob !< problem, set up
      type(mesh_t), intent(in), target :: mesh       !< mesh
      type(state_t), intent(inout), target :: state  !< start state
      real(wp), intent(in) :: r0(:, :)               !< (6, nn) start support forces
      character(len=*), intent(in) :: dir            !< output folder
      logical, intent(in) :: progress                !< show the progress line
      logical, intent(in) :: resuming                !< continued from a checkpoint
      character(len=32) :: hook
      integer :: stat
      run%dir = dir
      run%program_id = ''
      if (run%model%dynamic%checkpoint > 0.0_wp) run%program_id = checkpoint_program_id()
      run%kill_after = -1
      call get_environment_variable('RODYN_TEST_KILL_AFTER_STEP', hook, status=stat)
      if (stat == 0) read (hook, *, iostat=stat) run%kill_after
      run%r_start = r0
      run%pend%pending = .false.
      run%pend%have_back = .false.
      run%pend%frame_waiting = .false.
      run%pend%k_pend = 0
      if (allocated(run%pend%r_pend)) deallocate (run%pend%r_pend, run%pend%r_back, run%r_frame)
      allocate (run%pend%r_pend(6, mesh%n_nodes), run%pend%r_back(6, mesh%n_nodes), &
                run%r_frame(6, mesh%n_nodes))
      run%show_progress = progress
      if (.not. run%model%dynamic%start_static .and. .not. resuming) &
         call apply_initial_velocities(run%model, mesh, state)
      run%start_state = state
      call dynamics_setup(prob, run%model, mesh, state)
      call sea_scene_build(run%model, mesh, prob%x_start, run%scene)
      run%sea_now = sea_values_t()
      call recover_state(run%model, mesh, state, 1.0_wp, run%r_start, prob%sup%held, &
                         run%frame_lines, prob%water, 0.0_wp)
   end subroutine set_up

   !> The problem and the pending support forces as the checkpoint holds them (the
   !> problem set up from the start state; a frame waiting recovered again, with the
   !> water at the last step's force time as then).
   subroutine restore(run, prob, ck)
      type(dynamic_run_t), intent(inout) :: run      !< the run
      type(dynamic_problem_t), intent(inout) :: prob !< problem, set up
      type(checkpoint_t), intent(in) :: ck           !< the checkpoint
      type(checkpoint_t) :: c
      c = ck
      call checkpoint_problem(prob, c, .false.)
      run%pend = ck%pend
      if (run%pend%frame_waiting) then
         if (prob%water%active) call water_set_time(prob%water, prob%t0 + prob%wf*prob%dt, &
                                                    .true.)
         call recover_state(run%model, prob%mesh, prob%s1, 1.0_wp, prob%r, &
                            prob%sup%held, run%frame_lines, prob%water, ck%loop%t)
      end if
   end subroutine restore

   !> A checkpoint (CHECKPOINT of *DYNAMIC): the output files synced, then everything the
   !> run carries to the next step written to checkpoint.h5 (rodyn_checkpoint).
   subroutine on_checkpoint(this, ls, prob, err)
      class(dynamic_run_t), intent(inout) :: this      !< the run
      type(timeloop_state_t), intent(in) :: ls         !< the time loop's state
      type(dynamic_problem_t), intent(inout) :: prob   !< problem after the step
      type(error_t), intent(inout) :: err              !< status
      type(checkpoint_t) :: ck
      ck%loop = ls
      ck%summary = this%summary
      ck%start = this%start_state
      call checkpoint_problem(prob, ck, .true.)
      ck%pend = this%pend
      call dynamic_output_mark(this%writer, ck%mark, err)
      call checkpoint_write(this%dir, this%model, this%program_id, ck, err)
   end subroutine on_checkpoint

   !> A frame: positions and section forces of the state at t; its support forces wait
   !> with the step that ends at t for the next step (write_pending), but at t = 0 (the
   !> start state's, also the first row of the support forces of every step). The last
   !> frame's next step is the time loop's step past the end.
   subroutine on_frame(this, t, prob, err)
      class(dynamic_run_t), intent(inout) :: this      !< the run
      real(wp), intent(in) :: t                        !< time [s]
      type(dynamic_problem_t), intent(inout) :: prob   !< converged state
      type(error_t), intent(inout) :: err              !< status
      ! the step before, if waiting
      if (this%pend%pending) call this%write_pending(prob, .true., err)
      if (has_error(err)) return
      if (t > 0.0_wp) then
         ! (no results formed for a writer without files)
         if (dynamic_output_keeps_frames(this%writer)) &
            call recover_state(this%model, prob%mesh, prob%s1, 1.0_wp, prob%r, &
                               prob%sup%held, this%frame_lines, prob%water, t)
         this%pend%frame_waiting = .true.
      else
         call recover_state(this%model, prob%mesh, prob%s1, 1.0_wp, this%r_start, &
                            prob%sup%held, this%frame_lines, prob%water, t)
         if (this%scene%active) then
            call sea_values(this%scene, this%model, prob%water%field, t, this%r_start, &
                            prob%s1%x, prob%s1%d, this%sea_now)
            call dynamic_output_sea(this%writer, 0, t, this%sea_now, .true., err)
         end if
         call dynamic_output_ends_step(this%writer, 0, t, this%end_forces(prob, this%r_start), &
                                       err)
         call dynamic_output_frame(this%writer, t, this%frame_lines, err)
      end if
   end subroutine on_frame

   !> Write the support forces at the end t_k of the pending step k (and the frame
   !> waiting there, with the same forces): the step
   !> force of step k belongs to its force point t_{k-1} + w h_k (w = 1/2, or 1 - alpha_f
   !> with SCHEME=ALPHA), so written at t_k it would lag by (1 - w) h_k (a first-order
   !> error in time, a visible fraction of the top tension's dynamic range at the paper's
   !> dt = 0.1 s; the interpolation removes most of it). With the
   !> step after the frame (next: its force in prob%r, its length prob%dt) the value is
   !> interpolated between the two force points,
   !>   R(t_k) = R_k + (R_{k+1} - R_k) (1 - w) h_k / ((1 - w) h_k + w h_{k+1}),
   !> otherwise (a run that stopped, or whose step past the end failed) extrapolated from
   !> the step before,
   !>   R(t_k) = R_k + (R_k - R_{k-1}) (1 - w) h_k / (w h_k + (1 - w) h_{k-1}).
   subroutine write_pending(this, prob, next, err)
      class(dynamic_run_t), intent(inout) :: this !< the run
      type(dynamic_problem_t), intent(in) :: prob !< problem (after the next step if next)
      logical, intent(in) :: next                 !< prob%r is the force of the next step
      type(error_t), intent(inout) :: err         !< status
      real(wp) :: w, reaction(6, 2, size(this%frame_lines))
      integer :: l, k
      w = prob%wf
      associate (q => this%pend)
         if (next) then
            this%r_frame = q%r_pend + (prob%r - q%r_pend)*(1.0_wp - w)*q%h_pend &
                           /((1.0_wp - w)*q%h_pend + w*prob%dt)
         else if (q%have_back) then
            this%r_frame = q%r_pend + (q%r_pend - q%r_back)*(1.0_wp - w)*q%h_pend &
                           /(w*q%h_pend + (1.0_wp - w)*q%h_back)
         else
            this%r_frame = q%r_pend
         end if
      end associate
      this%pend%pending = .false.
      reaction = this%end_forces(prob, this%r_frame)
      if (this%scene%active) then
         ! (the state at t_pend: the next step's start, or the last state)
         if (next) then
            call sea_values(this%scene, this%model, prob%water%field, this%pend%t_pend, &
                            this%r_frame, prob%s0%x, prob%s0%d, this%sea_now)
         else
            call sea_values(this%scene, this%model, prob%water%field, this%pend%t_pend, &
                            this%r_frame, prob%s1%x, prob%s1%d, this%sea_now)
         end if
         call dynamic_output_sea(this%writer, this%pend%k_pend, this%pend%t_pend, this%sea_now, &
                                 this%pend%frame_waiting, err)
      end if
      call dynamic_output_ends_step(this%writer, this%pend%k_pend, this%pend%t_pend, reaction, err)
      if (.not. this%pend%frame_waiting) return
      do l = 1, size(this%frame_lines)
         do k = 1, 2
            if (this%frame_lines(l)%end_held(k)) &
               this%frame_lines(l)%reaction(:, k) = reaction(:, k, l)
         end do
      end do
      this%pend%frame_waiting = .false.
      call dynamic_output_frame(this%writer, this%pend%t_pend, this%frame_lines, err)
   end subroutine write_pending

   !> The support forces of the held line ends (zero at free ends) from the forces r
   !> at the nodes: (6, 2, lines), force and moment at end A, end B of each line.
   function end_forces(this, prob, r) result(reaction)
      class(dynamic_run_t), intent(in) :: this         !< the run
      type(dynamic_problem_t), intent(in) :: prob      !< problem (mesh)
      real(wp), intent(in) :: r(:, :)                  !< (6, nodes) [N, N m]
      real(wp) :: reaction(6, 2, size(this%frame_lines))
      integer :: l, k, node
      reaction = 0.0_wp
      do l = 1, size(this%frame_lines)
         do k = 1, 2
            if (.not. this%frame_lines(l)%end_held(k)) cycle
            node = mesh_node(prob%mesh, l, merge(end_a, end_b, k == 1))
            reaction(:, k, l) = r(:, node)
         end do
      end do
   end function end_forces

   subroutine on_step(this, log, err)
      class(dynamic_run_t), intent(inout) :: this !< the run
      type(step_log_t), intent(in) :: log   !< step
      type(error_t), intent(inout) :: err   !< status
      call dynamic_output_step(this%writer, log, err)
   end subroutine on_step

   !> After every converged step: the pending frame's support forces, and the progress
   !> line on stderr, at most twice a second: percent, time, speed, time left.
   subroutine after_step(this, t, prob, err)
      class(dynamic_run_t), intent(inout) :: this      !< the run
      real(wp), intent(in) :: t                        !< time reached [s]
      type(dynamic_problem_t), intent(inout) :: prob   !< problem after the step
      type(error_t), intent(inout) :: err              !< status
      integer(kind=8) :: now
      integer(c_int) :: stat_kill
      real(wp) :: wall, frac, rate, left
      ! after every step: the step before (and a frame at its end) waiting for this step
      ! is written, and this step waits for the next (not the step past the end)
      if (this%pend%pending .and. t > this%pend%t_pend .and. .not. has_error(err)) &
         call this%write_pending(prob, .true., err)
      if (this%writer%steps == this%kill_after .and. t <= this%model%dynamic%duration) then
         stat_kill = c_raise(9_c_int)       ! the test hook: SIGKILL, as a killed job
      end if
      if (t <= this%model%dynamic%duration + 1.0e-9_wp*this%model%dynamic%dt) then
         if (this%pend%k_pend > 0 .or. this%pend%pending) then
            this%pend%r_back = this%pend%r_pend
            this%pend%h_back = this%pend%h_pend
            this%pend%have_back = .true.
         end if
         this%pend%r_pend = prob%r
         this%pend%h_pend = prob%dt
         this%pend%t_pend = t
         this%pend%k_pend = this%writer%steps
         this%pend%pending = .true.
      end if
      if (.not. this%show_progress .or. has_error(err) .or. .not. associated(prob%mesh)) return
      ! past the end
      if (t > this%model%dynamic%duration + 1.0e-9_wp*this%model%dynamic%dt) return
      call system_clock(now)
      if (real(now - this%clock_last, wp) < 0.5_wp*real(this%clock_rate, wp) .and. &
          t < this%model%dynamic%duration) return
      this%clock_last = now
      wall = real(now - this%clock0, wp)/real(this%clock_rate, wp)
      frac = t/this%model%dynamic%duration
      rate = real(this%writer%steps, wp)/max(wall, 1.0e-9_wp)
      left = wall*(1.0_wp - frac)/max(frac, 1.0e-9_wp)
      write (error_unit, '(a,f6.1,a,es11.4,a,f9.1,a,f8.1,a)', advance='no') &
         achar(13)//'  ', 100.0_wp*frac, ' %   t = ', t, ' s   ', rate, ' steps/s   ', &
         left, ' s left  '
      flush (error_unit)
   end subroutine after_step
end module rodyn_run_dynamic
