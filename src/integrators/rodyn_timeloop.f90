!> Time stepping of a dynamic run: steps of DT (a failed step is retried once with the
!> energy line search, then halved, at most CUTBACKS times in a row, growing back after
!> two good sub-steps), outputs at the frame times,
!> and the energy and momentum balance of every step (docs/theory.md eqs. (41)-(43)).
!>
!> Energy bookkeeping: total = kinetic + strain + gravity potential (-sum f_g . x).
!> External work sums what the supports (prescribed motions) and the point loads did to
!> the line, R . dx with R the residual at held nodes (the force the support applies) and
!> F(t_{n+1/2}) . dx; damping work sums what Rayleigh damping and the sections'
!> structural damping took out (the work of their forces over the step, eq. (119) for
!> the latter); hydro and seabed
!> work sum f_water . dx and f_seabed . dx (buoyancy, drag, added mass; contact, damping,
!> friction) with the forces of the converged step. Under EMC,
!> total(t) - total(0) = external + hydro + seabed work - damping work to the Newton
!> tolerance.
module rodyn_timeloop
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error, set_error, clear_error, stat_numerical
   use rodyn_model, only: model_t, scheme_emc
   use rodyn_load_check, only: load_divergence_hint
   use rodyn_newton, only: newton_options_t, newton_stats_t, newton_solve
   use rodyn_dynamics, only: dynamic_problem_t, dynamics_begin_step, dynamics_end_step, &
                             dynamics_accept_step
   use rodyn_step_energy, only: step_energies, converged_energies, step_work
   use rodyn_results, only: step_log_t, run_summary_t
   use rodyn_state, only: state_copy
   use rodyn_mesh_checks, only: mesh_spurious_shape
   use rodyn_numerical_dissipation, only: numdiss_step
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: timeloop_run, frame_callback, step_callback, step_energies
   public :: timeloop_state_t, checkpoint_callback, timeloop_observer_t
   public :: timeloop_begin, timeloop_advance

   !> What the time loop carries from one step to the next besides the problem (a
   !> checkpoint holds it; timeloop_run continues from it).
   type :: timeloop_state_t
      real(wp) :: t = 0.0_wp               !< time reached [s]
      real(wp) :: next_frame = 0.0_wp     !< time of the next output frame [s]
      real(wp) :: next_checkpoint = 0.0_wp !< time of the next checkpoint [s]
      integer :: level = 0                 !< halvings of DT in force
      integer :: good = 0                  !< good sub-steps at this level
      type(step_log_t) :: log              !< the last step's energies and works
   end type timeloop_state_t

   !> The controls of a run's steps, fixed over the run (step_controls).
   type :: step_controls_t
      type(newton_options_t) :: opts     !< Newton controls of a step
      real(wp) :: dt = 0.0_wp            !< time step DT [s]
      real(wp) :: t_end = 0.0_wp         !< end of the run [s]
      real(wp) :: t_pause = huge(1.0_wp) !< where the run waits for its host [s]
      real(wp) :: interval = 0.0_wp      !< time between output frames [s]
      real(wp) :: tol_t = 0.0_wp         !< tolerance of a time [s]
      real(wp) :: e_tol = 0.0_wp         !< EMC's energy identity: mismatch / exchange [-]
      real(wp) :: checkpoint = 0.0_wp    !< time between checkpoints (<= 0: none) [s]
      integer :: max_cutbacks = 0        !< halvings of DT in a row before giving up
   end type step_controls_t

   !> The step under way: where it ends, how it is tried, and what its last solve gave
   !> (solve_step).
   type :: step_attempt_t
      real(wp) :: t1 = 0.0_wp            !< end of the step [s]
      logical :: retried = .false.       !< tried again, with the line search
      integer :: cuts = 0                !< halvings of DT since the last step taken
      type(newton_stats_t) :: stats      !< the last Newton solve
      type(error_t) :: nerr              !< its reason of failure
      logical :: accepted = .false.      !< converged and, for EMC, keeping eq. (43)
      type(step_log_t) :: trial          !< energies at the step's end
      real(wp) :: w_ext = 0.0_wp         !< work of supports and loads in the step [J]
      real(wp) :: w_damp = 0.0_wp        !< energy taken by damping in the step [J]
      real(wp) :: w_hydro = 0.0_wp       !< work of the water in the step [J]
      real(wp) :: w_seabed = 0.0_wp      !< work of the seabed in the step [J]
      real(wp) :: w_num = 0.0_wp         !< numerical dissipation in the step [J]
   end type step_attempt_t

   !> What a run does at its frames, steps and checkpoints, with the context it needs
   !> as components of an extension (a run's writers and pending outputs live there, not
   !> in module variables). after_step and on_checkpoint are called only when
   !> after_step_used and checkpoints_used are set (with after_step, the time loop also
   !> takes the step past the end, look_ahead).
   type, abstract :: timeloop_observer_t
      logical :: after_step_used = .false.  !< call after_step after every step
      logical :: checkpoints_used = .false. !< call on_checkpoint at checkpoints
   contains
      procedure(observe_frame), deferred :: on_frame
      procedure(observe_step), deferred :: on_step
      procedure(observe_frame), deferred :: after_step
      procedure(observe_checkpoint), deferred :: on_checkpoint
   end type timeloop_observer_t

   !> A timeloop_observer_t from plain procedures (timeloop_run_procedures).
   type, extends(timeloop_observer_t) :: procedure_observer_t
      procedure(frame_callback), nopass, pointer :: frame => null()
      procedure(step_callback), nopass, pointer :: step => null()
      procedure(frame_callback), nopass, pointer :: after => null()
      procedure(checkpoint_callback), nopass, pointer :: checkpoint => null()
   contains
      procedure :: on_frame => procedure_frame
      procedure :: on_step => procedure_step
      procedure :: after_step => procedure_after
      procedure :: on_checkpoint => procedure_checkpoint
   end type procedure_observer_t

   !> timeloop_run with an observer, or with the callbacks as procedures.
   interface timeloop_run
      module procedure timeloop_run_observer, timeloop_run_procedures
   end interface timeloop_run

   abstract interface
      !> At t = 0 and at every output time with the converged state in prob.
      subroutine observe_frame(this, t, prob, err)
         import :: timeloop_observer_t, wp, dynamic_problem_t, error_t
         class(timeloop_observer_t), intent(inout) :: this
         real(wp), intent(in) :: t
         type(dynamic_problem_t), intent(inout) :: prob
         type(error_t), intent(inout) :: err
      end subroutine observe_frame
      !> After every converged step.
      subroutine observe_step(this, log, err)
         import :: timeloop_observer_t, step_log_t, error_t
         class(timeloop_observer_t), intent(inout) :: this
         type(step_log_t), intent(in) :: log
         type(error_t), intent(inout) :: err
      end subroutine observe_step
      !> At a checkpoint, after a converged step, with what the loop carries.
      subroutine observe_checkpoint(this, ls, prob, err)
         import :: timeloop_observer_t, timeloop_state_t, dynamic_problem_t, error_t
         class(timeloop_observer_t), intent(inout) :: this
         type(timeloop_state_t), intent(in) :: ls
         type(dynamic_problem_t), intent(inout) :: prob
         type(error_t), intent(inout) :: err
      end subroutine observe_checkpoint
      !> Called at t = 0 and at every output time with the converged state in prob.
      subroutine frame_callback(t, prob, err)
         import :: wp, dynamic_problem_t, error_t
         real(wp), intent(in) :: t
         type(dynamic_problem_t), intent(inout) :: prob
         type(error_t), intent(inout) :: err
      end subroutine frame_callback
      !> Called after every converged step.
      subroutine step_callback(log, err)
         import :: step_log_t, error_t
         type(step_log_t), intent(in) :: log
         type(error_t), intent(inout) :: err
      end subroutine step_callback
      !> Called at a checkpoint, after a converged step, with what the loop carries.
      subroutine checkpoint_callback(ls, prob, err)
         import :: timeloop_state_t, dynamic_problem_t, error_t
         type(timeloop_state_t), intent(in) :: ls
         type(dynamic_problem_t), intent(inout) :: prob
         type(error_t), intent(inout) :: err
      end subroutine checkpoint_callback
   end interface

contains

   !> timeloop_run with the callbacks as procedures (no context; a test's callbacks).
   subroutine timeloop_run_procedures(prob, model, summary, err, log_unit, on_frame, &
                                      on_step, after_step, on_checkpoint, resume)
      type(dynamic_problem_t), intent(inout) :: prob  !< set-up problem, start state
      type(model_t), intent(in) :: model              !< model (dynamic options)
      type(run_summary_t), intent(inout) :: summary   !< progress
      type(error_t), intent(inout) :: err             !< status
      integer, intent(in) :: log_unit                 !< Newton log unit (< 0: silent)
      procedure(frame_callback) :: on_frame           !< output of a frame
      procedure(step_callback) :: on_step             !< output of a step log
      procedure(frame_callback), optional :: after_step !< called after every step
      procedure(checkpoint_callback), optional :: on_checkpoint !< called at checkpoints
      type(timeloop_state_t), intent(in), optional :: resume !< continue from a checkpoint
      type(procedure_observer_t) :: obs
      obs%frame => on_frame
      obs%step => on_step
      if (present(after_step)) then
         obs%after => after_step
         obs%after_step_used = .true.
      end if
      if (present(on_checkpoint)) then
         obs%checkpoint => on_checkpoint
         obs%checkpoints_used = .true.
      end if
      call timeloop_run_observer(prob, model, summary, err, log_unit, obs, resume)
   end subroutine timeloop_run_procedures

   !> Run the dynamic analysis from the state in prob (time 0, or the checkpoint's with
   !> resume) to model%dynamic%duration. With CHECKPOINT=c of *DYNAMIC, on_checkpoint is
   !> called after the first step that reaches each multiple of c (before the end), and
   !> the step after it forms a new tangent: a run continued from the checkpoint holds
   !> no factorised tangent, so both runs take the same iterates (tangent reuse makes
   !> the iterate depend on the tangent held).
   !> docs/theory.md sections 5-7.
   subroutine timeloop_run_observer(prob, model, summary, err, log_unit, obs, resume)
      type(dynamic_problem_t), intent(inout) :: prob  !< set-up problem, start state
      type(model_t), intent(in) :: model              !< model (dynamic options)
      type(run_summary_t), intent(inout) :: summary   !< progress
      type(error_t), intent(inout) :: err             !< status
      integer, intent(in) :: log_unit                 !< Newton log unit (< 0: silent)
      class(timeloop_observer_t), intent(inout) :: obs !< frames, steps, checkpoints
      type(timeloop_state_t), intent(in), optional :: resume !< continue from a checkpoint
      type(step_controls_t) :: ctl
      type(timeloop_state_t) :: ls
      logical :: halt
      ctl = step_controls(model, log_unit)
      summary%dynamic = .true.
      if (present(resume)) then
         ls = resume
         prob%factors_ok = .false.
         prob%renew_first = .false.
      else
         call timeloop_start(prob, ctl, obs, ls, err)
         if (has_error(err)) return
      end if
      call timeloop_advance(prob, model, summary, err, log_unit, obs, ls, ctl%t_end, halt)
      if (halt) return
      summary%complete = .true.
      summary%status = 'complete'
      if (obs%after_step_used) call look_ahead(prob, ctl, obs, ls, err)
   end subroutine timeloop_run_observer

   !> The loop's state at t = 0 for a run driven step by step (timeloop_advance): the
   !> energies of the start state, the frame at t = 0 handed to obs.
   subroutine timeloop_begin(prob, model, err, obs, ls)
      type(dynamic_problem_t), intent(inout) :: prob   !< set-up problem, start state
      type(model_t), intent(in) :: model               !< model (dynamic options)
      type(error_t), intent(inout) :: err              !< status
      class(timeloop_observer_t), intent(inout) :: obs !< frames
      type(timeloop_state_t), intent(out) :: ls        !< the state at t = 0
      call timeloop_start(prob, step_controls(model, -1), obs, ls, err)
   end subroutine timeloop_begin

   !> Advance the run from ls%t to t_until (a host program's coupling step, or the end
   !> of the run): steps of DT, halved where Newton needs it, the last one ending at
   !> t_until (a pause: frames are written at their times and the run's end only).
   !> halt: the run stopped (err set).
   subroutine timeloop_advance(prob, model, summary, err, log_unit, obs, ls, t_until, halt)
      type(dynamic_problem_t), intent(inout) :: prob   !< problem, state at ls%t
      type(model_t), intent(in) :: model               !< model (dynamic options)
      type(run_summary_t), intent(inout) :: summary    !< progress
      type(error_t), intent(inout) :: err              !< status
      integer, intent(in) :: log_unit                  !< Newton log unit (< 0: silent)
      class(timeloop_observer_t), intent(inout) :: obs !< frames, steps, checkpoints
      type(timeloop_state_t), intent(inout) :: ls      !< the loop's state, advanced
      real(wp), intent(in) :: t_until                  !< time to reach [s]
      logical, intent(out) :: halt                     !< the run stopped
      type(step_controls_t) :: ctl
      type(step_attempt_t) :: att
      ctl = step_controls(model, log_unit)
      ctl%t_pause = min(t_until, ctl%t_end)
      halt = .false.
      do while (ls%t < ctl%t_pause - ctl%tol_t)
         att%t1 = step_end(ctl, ls)
         ! factors of a tangent formed for another step size no longer fit
         if (abs((att%t1 - ls%t) - prob%dt) > ctl%tol_t) prob%factors_ok = .false.
         call solve_step(prob, ctl, ls%log, ls%t, att%t1 - ls%t, att%retried, att)
         summary%step_iterations = summary%step_iterations + att%stats%iterations
         summary%step_tangents = summary%step_tangents + att%stats%tangents
         if (att%accepted) then
            call take_step(prob, model, ctl, obs, att, ls, summary, err, halt)
         else
            call failed_step(prob, model, ctl, att, ls, summary, err, halt)
         end if
         if (halt) return
      end do
   end subroutine timeloop_advance

   !> The controls of a run's steps from its *DYNAMIC options: Newton's, the output
   !> interval (DT when not given), the tolerance of a time, and that of EMC's energy
   !> identity (energy_identity_holds; docs/theory.md eq. (43)).
   pure function step_controls(model, log_unit) result(ctl)
      type(model_t), intent(in) :: model   !< model (dynamic options)
      integer, intent(in) :: log_unit      !< Newton log unit (< 0: silent)
      type(step_controls_t) :: ctl         !< the controls
      ctl%opts%max_iterations = model%dynamic%max_iterations
      ctl%opts%force_tol = model%dynamic%force_tol
      ctl%opts%disp_tol = model%dynamic%disp_tol
      ctl%opts%log_unit = log_unit
      ctl%opts%reuse_tangent = model%dynamic%reuse_tangent
      ! the reused tangent's chord steps Anderson-accelerated (rodyn_anderson); with the
      ! history correcting what the held tangent misses, a tangent is renewed only when
      ! an iteration fails to halve the residual (a looser rule than the plain chord
      ! iteration's 0.25, since the history keeps the iteration contracting)
      ctl%opts%anderson = .true.
      ctl%opts%reuse_ratio = 0.5_wp
      ctl%dt = model%dynamic%dt
      ctl%t_end = model%dynamic%duration
      ctl%interval = model%dynamic%output_interval
      if (ctl%interval <= 0.0_wp) ctl%interval = ctl%dt
      ctl%tol_t = 1.0e-9_wp*ctl%dt
      ctl%e_tol = min(0.1_wp, 1.0e4_wp*max(ctl%opts%force_tol, ctl%opts%disp_tol))
      ctl%checkpoint = model%dynamic%checkpoint
      ctl%max_cutbacks = model%dynamic%max_cutbacks
   end function step_controls

   !> The loop's state at t = 0: the energies of the start state (docs/theory.md eq.
   !> (41)), no work done, the first output frame and checkpoint ahead; the frame at
   !> t = 0 written.
   subroutine timeloop_start(prob, ctl, obs, ls, err)
      type(dynamic_problem_t), intent(inout) :: prob   !< set-up problem, start state
      type(step_controls_t), intent(in) :: ctl         !< controls
      class(timeloop_observer_t), intent(inout) :: obs !< frames
      type(timeloop_state_t), intent(inout) :: ls      !< the state at t = 0
      type(error_t), intent(inout) :: err              !< status
      ls%next_checkpoint = huge(1.0_wp)
      if (ctl%checkpoint > 0.0_wp) ls%next_checkpoint = ctl%checkpoint
      ls%t = 0.0_wp
      ls%next_frame = ctl%interval
      ! an output time less than half a step before the end is replaced by the end
      ! (no sliver of a step between the two)
      if (ctl%t_end - ls%next_frame < 0.5_wp*ctl%dt) ls%next_frame = ctl%t_end
      call step_energies(prob, ls%log)
      ls%log%external_work = 0.0_wp
      ls%log%damping_work = 0.0_wp
      ls%log%hydro_work = 0.0_wp
      ls%log%seabed_work = 0.0_wp
      ls%log%numerical_work = 0.0_wp
      ls%log%numerical_energy = prob%nd%energy
      call obs%on_frame(ls%t, prob, err)
      if (has_error(err)) return
      ls%level = 0
      ls%good = 0
   end subroutine timeloop_start

   !> End [s] of the step from ls%t: DT halved ls%level times, not beyond the next output
   !> time, the end or the pause (timeloop_advance). A remainder of less than half a step
   !> before one is shared with
   !> the step before it: no step is cut down to a sliver (over a sliver the inertia of
   !> the unresolved axial vibration is averaged over too short a time, and the tension
   !> of that step is far off).
   pure real(wp) function step_end(ctl, ls) result(t1)
      type(step_controls_t), intent(in) :: ctl !< controls
      type(timeloop_state_t), intent(in) :: ls !< time [s], next frame [s], halvings
      real(wp) :: h, t_next
      h = ctl%dt*0.5_wp**ls%level
      t_next = min(ctl%t_end, ls%next_frame, ctl%t_pause)
      t1 = min(on_grid(ls%t + h, h), t_next)
      ! a sliver left before the next stop (a host's pause summed step by step drifts off
      ! the grid by round-off, 1e-11 s after 10^4 steps) joins this step: a step of 1e-11 s
      ! would scale the inertia by 1/h^2 and Newton would fail
      if (t_next > t1 .and. t_next - t1 < 1.0e-6_wp*h) t1 = t_next
      if (t_next - ls%t > h + ctl%tol_t .and. t_next - ls%t < 1.5_wp*h) &
         t1 = ls%t + 0.5_wp*(t_next - ls%t)
      if (ls%next_frame - t1 < ctl%tol_t) t1 = ls%next_frame
      if (ctl%t_end - t1 < ctl%tol_t) t1 = ctl%t_end
      if (ctl%t_pause - t1 < ctl%tol_t) t1 = ctl%t_pause
   end function step_end

   !> Solve the step from t0 to t0 + h (retry: the second attempt, with the line search
   !> and a new tangent) into att: the Newton solve, the works of the step and, in
   !> att%trial, the energies at t0 + h; att%accepted = converged and, for EMC, keeping
   !> the energy identity. docs/theory.md eqs. (41), (43).
   subroutine solve_step(prob, ctl, log, t0, h, retry, att)
      type(dynamic_problem_t), intent(inout) :: prob !< problem, state at t0
      type(step_controls_t), intent(in) :: ctl       !< controls
      type(step_log_t), intent(in) :: log            !< energies and works at t0
      real(wp), intent(in) :: t0                     !< start of the step [s]
      real(wp), intent(in) :: h                      !< step [s]
      logical, intent(in) :: retry                   !< the second attempt
      type(step_attempt_t), intent(inout) :: att     !< the solve's outcome
      type(newton_options_t) :: opts
      call dynamics_begin_step(prob, t0, h)
      call clear_error(att%nerr)
      opts = ctl%opts
      opts%line_search = retry
      opts%reuse_tangent = ctl%opts%reuse_tangent .and. .not. retry
      call newton_solve(prob, opts, att%stats, att%nerr)
      att%accepted = att%stats%converged .and. .not. has_error(att%nerr)
      if (.not. att%accepted) return
      call dynamics_end_step(prob)
      call step_work(prob, att%w_ext, att%w_damp, att%w_hydro, att%w_seabed)
      att%w_num = 0.0_wp
      ! (the dissipative EMC takes the rods' strain increments from the energy pass)
      if (prob%nd%on .and. prob%fields0) prob%nd%eps_prev = prob%epsn
      att%trial = log
      call converged_energies(prob, att%trial)
      if (prob%nd%on) then
         if (prob%fields0) then
            call numdiss_step(prob%nd, prob%mesh, prob%s0, prob%s1, prob%dt, &
                              prob%nd%eps_prev, prob%epsn)
         else
            call numdiss_step(prob%nd, prob%mesh, prob%s0, prob%s1, prob%dt)
         end if
         att%w_num = prob%nd%work_new
      end if
      if (prob%scheme /= scheme_emc) return
      att%accepted = energy_identity_holds(log, att%trial, att%w_ext + att%w_hydro + &
                                           att%w_seabed, att%w_damp + att%w_num, &
                                           ctl%e_tol, 0.0_wp)
      ! (the residual's work, needed only by steps near the bound, computed for them)
      if (.not. att%accepted) att%accepted = energy_identity_holds(log, att%trial, &
                                             att%w_ext + att%w_hydro + att%w_seabed, &
                                             att%w_damp + att%w_num, ctl%e_tol, &
                                             residual_work(prob))
      if (.not. att%accepted) call set_error(att%nerr, stat_numerical, 'the converged '// &
         'step breaks the energy identity of EMC (a spurious root)')
      if (.not. att%accepted .and. ctl%opts%log_unit >= 0) write (ctl%opts%log_unit, &
         '(a)') '  step rejected: '//att%nerr%message
   end subroutine solve_step

   !> Take the step solved in att: book it, hand it to the observer, write the frame
   !> when one is due, grow DT back after two good sub-steps, and hand over the
   !> checkpoint when one is due. halt: the run stops (err set).
   subroutine take_step(prob, model, ctl, obs, att, ls, summary, err, halt)
      type(dynamic_problem_t), intent(inout) :: prob   !< problem (step converged)
      type(model_t), intent(in) :: model               !< model
      type(step_controls_t), intent(in) :: ctl         !< controls
      class(timeloop_observer_t), intent(inout) :: obs !< frames, steps, checkpoints
      type(step_attempt_t), intent(inout) :: att       !< the step solved
      type(timeloop_state_t), intent(inout) :: ls      !< advanced to the step's end
      type(run_summary_t), intent(inout) :: summary    !< progress
      type(error_t), intent(inout) :: err              !< status
      logical, intent(out) :: halt                     !< the run stops
      call dynamics_accept_step(prob)
      call book_step(prob, att, ls, summary)
      halt = .true.
      call obs%on_step(ls%log, err)
      if (has_error(err)) return
      if (ls%t >= ls%next_frame - ctl%tol_t .or. ls%t >= ctl%t_end - ctl%tol_t) then
         call write_frame(prob, model, ctl, obs, ls, summary, err)
         if (has_error(err)) return
      end if
      halt = .false.
      if (obs%after_step_used) call obs%after_step(ls%t, prob, err)
      if (ls%level > 0) then
         ls%good = ls%good + 1
         if (ls%good >= 2) then
            ls%level = ls%level - 1
            ls%good = 0
         end if
      end if
      if (ls%t >= ls%next_checkpoint - ctl%tol_t .and. ls%t < ctl%t_end - ctl%tol_t .and. &
          obs%checkpoints_used .and. .not. has_error(err)) then
         call take_checkpoint(prob, ctl, obs, ls, err)
         halt = has_error(err)
      end if
   end subroutine take_step

   !> Book the step taken into the run: its log (the works of the step added to the
   !> run's; docs/theory.md eq. (43)), the time reached, and a new step to try.
   pure subroutine book_step(prob, att, ls, summary)
      type(dynamic_problem_t), intent(in) :: prob    !< problem (step accepted)
      type(step_attempt_t), intent(inout) :: att     !< the step solved
      type(timeloop_state_t), intent(inout) :: ls    !< advanced to the step's end
      type(run_summary_t), intent(inout) :: summary  !< progress
      summary%steps = summary%steps + 1
      att%trial%step = summary%steps
      att%trial%time = att%t1
      att%trial%dt = att%t1 - ls%t
      att%trial%iterations = att%stats%iterations
      att%trial%tangents = att%stats%tangents
      att%trial%cutbacks = att%cuts
      att%trial%external_work = ls%log%external_work + att%w_ext
      att%trial%damping_work = ls%log%damping_work + att%w_damp
      att%trial%hydro_work = ls%log%hydro_work + att%w_hydro
      att%trial%seabed_work = ls%log%seabed_work + att%w_seabed
      att%trial%numerical_work = ls%log%numerical_work + att%w_num
      if (prob%nd%on) att%trial%numerical_energy = prob%nd%energy_new
      ls%log = att%trial
      ls%t = att%t1
      summary%time_reached = ls%t
      att%cuts = 0
      att%retried = .false.
   end subroutine book_step

   !> The frame at ls%t, unless a cubic rod has taken the spurious shape of its
   !> quadrature (rodyn_mesh): that stops the run before the frame is written. The next
   !> output time follows (the end, when less than half a step before it).
   subroutine write_frame(prob, model, ctl, obs, ls, summary, err)
      type(dynamic_problem_t), intent(inout) :: prob   !< problem (step converged)
      type(model_t), intent(in) :: model               !< model
      type(step_controls_t), intent(in) :: ctl         !< controls
      class(timeloop_observer_t), intent(inout) :: obs !< frames
      type(timeloop_state_t), intent(inout) :: ls      !< next frame advanced
      type(run_summary_t), intent(inout) :: summary    !< status of a stop
      type(error_t), intent(inout) :: err              !< status
      character(len=240) :: msg
      character(len=:), allocatable :: why
      why = mesh_spurious_shape(model, prob%mesh, prob%s1)
      if (len(why) > 0) then
         write (msg, '(a,es12.5,a)') 'dynamics: at t = ', ls%t, ' s,'
         why = trim(msg)//' '//why//damping_note(model)//'; the frames before it '// &
               'are written (the shape may have formed after the last of them)'
         call set_error(err, stat_numerical, why)
         summary%status = why
         return
      end if
      call obs%on_frame(ls%t, prob, err)
      if (has_error(err)) return
      ls%next_frame = on_grid(ls%next_frame + ctl%interval, ctl%interval)
      if (ctl%t_end - ls%next_frame < 0.5_wp*ctl%dt) ls%next_frame = ctl%t_end
   end subroutine write_frame

   !> t put on the grid of multiples of h when it is within 1e-6 h of one: times summed
   !> step by step drift by round-off (2.7e-10 s over 24 000 steps of 0.025 s), and a
   !> drifted end would take a sliver of a step; k h is one rounding off the grid.
   pure real(wp) function on_grid(t, h) result(tg)
      real(wp), intent(in) :: t   !< time [s]
      real(wp), intent(in) :: h   !< spacing of the grid [s], > 0
      real(wp) :: k
      k = anint(t/h)
      tg = t
      if (abs(t - k*h) <= 1.0e-6_wp*h) tg = k*h
   end function on_grid

   !> The checkpoint due at ls%t: the next one set a multiple of CHECKPOINT later, the
   !> loop's state handed to the observer, and the factorised tangent dropped, as in a
   !> run continued from here (which holds none).
   subroutine take_checkpoint(prob, ctl, obs, ls, err)
      type(dynamic_problem_t), intent(inout) :: prob   !< problem (step converged)
      type(step_controls_t), intent(in) :: ctl         !< controls
      class(timeloop_observer_t), intent(inout) :: obs !< checkpoints
      type(timeloop_state_t), intent(inout) :: ls      !< next checkpoint advanced
      type(error_t), intent(inout) :: err              !< status
      do while (ls%next_checkpoint <= ls%t + ctl%tol_t)
         ls%next_checkpoint = on_grid(ls%next_checkpoint + ctl%checkpoint, ctl%checkpoint)
      end do
      call obs%on_checkpoint(ls, prob, err)
      if (has_error(err)) return
      prob%factors_ok = .false.   ! as in a run continued from here
      prob%renew_first = .false.
   end subroutine take_checkpoint

   !> After a step that failed: NaN or Inf stops the run (where, from the failed
   !> iterate); otherwise the state goes back to t_n and the step is tried again, first
   !> with the line search, then halved, at most CUTBACKS times in a row. halt: the run
   !> stops (err set).
   subroutine failed_step(prob, model, ctl, att, ls, summary, err, halt)
      type(dynamic_problem_t), intent(inout) :: prob !< problem (the failed iterate)
      type(model_t), intent(in) :: model             !< model
      type(step_controls_t), intent(in) :: ctl       !< controls
      type(step_attempt_t), intent(inout) :: att     !< the step that failed
      type(timeloop_state_t), intent(inout) :: ls    !< halvings of DT
      type(run_summary_t), intent(inout) :: summary  !< progress
      type(error_t), intent(inout) :: err            !< status
      logical, intent(out) :: halt                   !< the run stops
      character(len=240) :: msg
      character(len=:), allocatable :: why
      logical :: nonfinite
      halt = .true.
      ! (two tests: Fortran does not promise to skip the second when the first fails,
      ! and nerr%message is unallocated without an error)
      nonfinite = .false.
      if (has_error(att%nerr)) nonfinite = index(att%nerr%message, 'not finite') > 0
      if (nonfinite) then
         write (msg, '(a,es12.5,a)') 'dynamics: NaN or Inf at t = ', att%t1, &
            ' s ('//nonfinite_where(prob)//'); results up to t = '
         write (msg, '(a,es12.5,a)') trim(msg), ls%t, ' s are written'
         call state_copy(prob%s0, prob%s1)
         call set_error(err, stat_numerical, trim(msg))
         summary%status = trim(msg)
         return
      end if
      halt = .false.
      call state_copy(prob%s0, prob%s1)
      if (.not. att%retried) then
         att%retried = .true.       ! the same step again, with the line search
         if (ctl%opts%log_unit >= 0) write (ctl%opts%log_unit, '(a,es12.5,a)') &
            '  step to t = ', att%t1, ' s failed: retry with the line search'
         return
      end if
      att%retried = .false.
      if (ctl%opts%log_unit >= 0) write (ctl%opts%log_unit, '(a,es12.5,a)') &
         '  step to t = ', att%t1, ' s failed: halving'
      ls%level = ls%level + 1
      ls%good = 0
      att%cuts = att%cuts + 1
      summary%step_cutbacks = summary%step_cutbacks + 1
      if (ls%level <= ctl%max_cutbacks) return
      write (msg, '(a,es12.5,a,i0,a)') 'dynamics: no convergence at t = ', ls%t, &
         ' s after ', ctl%max_cutbacks, ' halvings of the step'
      ! what diverged: a load beyond the lines' reach, else the solver's reason
      why = load_divergence_hint(model)
      if (len(why) == 0 .and. has_error(att%nerr)) why = att%nerr%message
      if (len(why) > 0) why = ' ('//why//')'
      call set_error(err, stat_numerical, trim(msg)//why)
      summary%status = trim(msg)//why
      halt = .true.
   end subroutine failed_step

   !> One step past the end, only for the support forces of the last frame: they are
   !> interpolated between the step forces on both sides of the frame time, like
   !> every other frame's (extrapolated from the steps before, the last frame's
   !> support forces would be off by a visible fraction of their range).
   !> The step is solved like the others (for EMC, its energy identity checked),
   !> handed to after_step at t_end + h, and then undone: the state returned is the
   !> one at t_end, and the step is not counted in the summary. A *MOTION table that ends
   !> before it continues on the straight line of its last step (dynamics_begin_step);
   !> the other motions as they are defined. Should it fail, the caller extrapolates.
   subroutine look_ahead(prob, ctl, obs, ls, err)
      type(dynamic_problem_t), intent(inout) :: prob   !< problem, state at the end
      type(step_controls_t), intent(in) :: ctl         !< controls
      class(timeloop_observer_t), intent(inout) :: obs !< after_step
      type(timeloop_state_t), intent(in) :: ls         !< the state at the end
      type(error_t), intent(inout) :: err              !< status
      type(step_attempt_t) :: att
      real(wp) :: h_last
      h_last = prob%dt
      if (ctl%opts%log_unit >= 0) write (ctl%opts%log_unit, '(a)') &
         '  step past the end (support forces of the last frame)'
      call solve_step(prob, ctl, ls%log, ls%t, h_last, .false., att)
      if (att%accepted) call obs%after_step(ls%t + h_last, prob, err)
      call state_copy(prob%s0, prob%s1)
   end subroutine look_ahead

   !> Bound of the work the residual left by Newton (within its tolerance) does over the
   !> step: 2 sum over nodes of |r_x| |x^n+1 - x^n| + |r_theta| phi, free unknowns
   !> only (phi the angle the node turned in the step). EMC's energy identity holds up to this work:
   !> in a small vibration under a large prestress it is not small against the energy
   !> exchanged, and without it a sound step would be taken for a spurious root (a taut
   !> wire vibrating at 1e-4 of its length).
   !> docs/theory.md eq. (43).
   function residual_work(prob) result(b)
      type(dynamic_problem_t), intent(in) :: prob !< problem (converged step)
      real(wp) :: b
      real(wp) :: rx, rt
      integer :: node, k, j
      b = 0.0_wp
      do node = 1, prob%mesh%n_nodes
         k = prob%sup%first(node) - 1
         rx = 0.0_wp
         rt = 0.0_wp
         do j = 1, 3
            if (.not. prob%sup%held(j, node)) rx = rx + prob%rhs(k + j)**2
         end do
         if (prob%sup%ndof(node) == 6) then
            do j = 1, 3
               if (.not. prob%sup%held(3 + j, node)) rt = rt + prob%rhs(k + 3 + j)**2
            end do
         end if
         b = b + sqrt(rx)*norm2(prob%dx(:, node))
         ! the step's rotation angle from the directors: |d^n+1 - d^n|_F = 2 sqrt(2)
         ! |sin(phi/2)|, about sqrt(2) phi (the factor 2 below covers the difference)
         if (rt > 0.0_wp) b = b + sqrt(rt)*norm2(prob%s1%d(:, :, node) - &
                                                 prob%s0%d(:, :, node))/sqrt(2.0_wp)
      end do
      b = 2.0_wp*b
   end function residual_work

   !> EMC's discrete energy identity over one converged step: the change of total energy
   !> equals the work of supports and loads less the damping work, up to the Newton
   !> tolerance (the work the residual left does, residual_work, and tol of the energy
   !> exchanged; docs/theory.md eq. (43)). A converged step keeps it to a small fraction
   !> of the largest energy exchanged in the step (change of kinetic, strain or gravity
   !> energy, or the work); a root of the step equations far from the motion, which a
   !> line search can reach after wandering, breaks it by the order of the exchange
   !> itself. Such a step is treated as not converged.
   logical function energy_identity_holds(before, after, w_ext, w_damp, tol, slack)
      type(step_log_t), intent(in) :: before  !< energies at t_n
      type(step_log_t), intent(in) :: after   !< energies at t_n+1
      real(wp), intent(in) :: w_ext           !< work of supports and loads in the step [J]
      real(wp), intent(in) :: w_damp          !< energy taken by damping in the step [J]
      real(wp), intent(in) :: tol             !< allowed mismatch / exchange [-]
      real(wp), intent(in) :: slack           !< work of the residual left (bound) [J]
      real(wp) :: mismatch, exchange, level
      mismatch = abs((after%total - before%total) - (w_ext - w_damp))
      exchange = max(abs(after%kinetic - before%kinetic), abs(after%strain - before%strain), &
                     abs(after%gravity - before%gravity), abs(w_ext), abs(w_damp))
      level = abs(after%kinetic) + abs(after%strain) + abs(after%gravity)
      energy_identity_holds = mismatch <= tol*exchange + slack + epsilon(1.0_wp)* &
                              (1.0e3_wp*level + 1.0e2_wp*max(before%strain_scale, &
                                                             after%strain_scale))
   end function energy_identity_holds

   !> Where a failed iterate is not finite, for the message: the first node (line name,
   !> node number along the line, arc length) whose residual or position is NaN or Inf,
   !> and how many nodes are; with none, the node of the largest residual.
   function nonfinite_where(prob) result(text)
      type(dynamic_problem_t), intent(in) :: prob !< problem (the failed iterate)
      character(len=:), allocatable :: text
      character(len=160) :: buf
      real(wp) :: big, v
      integer :: node, first, worst, count, l
      first = 0
      count = 0
      worst = 1
      big = -1.0_wp
      do node = 1, prob%mesh%n_nodes
         v = maxval(abs(prob%r(:, node)))
         if (.not. ieee_is_finite(v) .or. any(.not. ieee_is_finite(prob%s1%x(:, node)))) then
            count = count + 1
            if (first == 0) first = node
         else if (v > big) then
            big = v
            worst = node
         end if
      end do
      node = merge(first, worst, first > 0)
      l = prob%mesh%node_line(node)
      write (buf, '(a,i0,a,g0.6,a)') 'line '//trim(prob%model%lines(l)%name)//' node ', &
         node - prob%mesh%line_first_node(l) + 1, ' at s = ', prob%mesh%node_s(node), ' m'
      if (first > 0) then
         write (buf, '(a,i0,a,i0,a)') 'first at '//trim(buf)//'; ', count, ' of ', &
            prob%mesh%n_nodes, ' nodes not finite'
      else
         buf = 'largest residual at '//trim(buf)
      end if
      text = trim(buf)
   end function nonfinite_where

   !> '; the run's *DAMPING (FILE:LINE): ALPHA = a 1/s, BETA = b s' when the deck has
   !> one (damping ratio ALPHA/(2 omega) + BETA omega/2, docs/deck.md), else ''.
   function damping_note(model) result(text)
      type(model_t), intent(in) :: model          !< model
      character(len=:), allocatable :: text       !< the note
      character(len=16) :: a, b
      text = ''
      if (.not. allocated(model%dynamic%damping_at)) return
      write (a, '(es9.2)') model%dynamic%rayleigh_alpha
      write (b, '(es9.2)') model%dynamic%rayleigh_beta
      text = "; the run's *DAMPING ("//model%dynamic%damping_at//'): ALPHA = '// &
             trim(adjustl(a))//' 1/s, BETA = '//trim(adjustl(b))//' s'
   end function damping_note
   subroutine procedure_frame(this, t, prob, err)
      class(procedure_observer_t), intent(inout) :: this !< observer
      real(wp), intent(in) :: t                          !< time [s]
      type(dynamic_problem_t), intent(inout) :: prob     !< problem
      type(error_t), intent(inout) :: err                !< status
      call this%frame(t, prob, err)
   end subroutine procedure_frame

   subroutine procedure_step(this, log, err)
      class(procedure_observer_t), intent(inout) :: this !< observer
      type(step_log_t), intent(in) :: log                !< step
      type(error_t), intent(inout) :: err                !< status
      call this%step(log, err)
   end subroutine procedure_step

   subroutine procedure_after(this, t, prob, err)
      class(procedure_observer_t), intent(inout) :: this !< observer
      real(wp), intent(in) :: t                          !< time [s]
      type(dynamic_problem_t), intent(inout) :: prob     !< problem
      type(error_t), intent(inout) :: err                !< status
      if (associated(this%after)) call this%after(t, prob, err)
   end subroutine procedure_after

   subroutine procedure_checkpoint(this, ls, prob, err)
      class(procedure_observer_t), intent(inout) :: this !< observer
      type(timeloop_state_t), intent(in) :: ls           !< loop state
      type(dynamic_problem_t), intent(inout) :: prob     !< problem
      type(error_t), intent(inout) :: err                !< status
      if (associated(this%checkpoint)) call this%checkpoint(ls, prob, err)
   end subroutine procedure_checkpoint
end module rodyn_timeloop
