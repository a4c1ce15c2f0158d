!> Newton-Raphson driver with an energy line search, force and displacement criteria
!> and an iteration log (docs/theory.md section 6, eqs. (45)-(53)). The problem is a type
!> extending newton_problem_t; statics and each time integrator provide one.
!>
!> Line search (Crisfield, "Non-linear Finite Element Analysis of Solids and
!> Structures", vol. 1, 1991, section 9.3): along the correction du the slope of the
!> energy is s(alpha) = du . r(u + alpha du). The full step is kept when
!> |s(1)| <= ls_ratio |s(0)|; otherwise alpha is moved to the zero of s by secant
!> (regula falsi) steps, bounded to [ls_min, 1]. A residual-norm merit function is
!> useless here: with EA >> EI any step along the linearised direction stretches the
!> rod at second order and the axial rows grow, even for tiny steps.
!>
!> Convergence: scaled residual <= force_tol AND scaled correction <= disp_tol, or the
!> residual already below force_tol at the first evaluation, or (quadratic regime) a
!> full step that cut the residual tenfold to below force_tol with a correction below
!> sqrt(disp_tol): the error left is of order correction^2 <= disp_tol. With stiff sections
!> (EA/EI ~ 1e4 and more) round-off puts a floor under the residual: a correction below
!> roundoff_correction with a residual below roundoff_factor * force_tol is accepted
!> too (the configuration can no longer change in double precision), and logged so.
!> So is a full correction within disp_tol that did not halve a residual already below
!> 100 force_tol, or below 100 times the problem's estimate of its round-off floor
!> (residual_floor, docs/theory.md eq. (51); the floor grows as elements get shorter, and
!> on fine meshes it lies above 100 force_tol, where new tangents would be formed only to
!> confirm it).
!>
!> Tangent reuse (modified Newton, opts%reuse_tangent): the factorised tangent of an
!> earlier iteration, or of an earlier time step, is used again while it still contracts
!> the residual by the factor opts%reuse_ratio per iteration; an iteration that does
!> worse makes the next one form and factorise a new tangent. Residual-only evaluations
!> then cost a fraction of a tangent (docs/benchmarks.md, "skips"). With a reused tangent
!> convergence is linear, so the quadratic-regime acceptance is not used for it. When
!> the reused tangent made the residual grow, the new one is formed at the iterate
!> before (the better of the two): a tangent formed at a diverged iterate contracts
!> much more slowly than one formed at the iterate before it.
!> After the first iteration of a solve begun with an earlier solve's tangent, a residual
!> above sqrt(force_tol) renews the tangent at once.
module rodyn_newton
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error, set_error, stat_numerical
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: newton_problem_t, newton_options_t, newton_stats_t, newton_solve

   !> Controls of one Newton solve.
   type :: newton_options_t
      integer :: max_iterations = 30          !< iterations before giving up
      real(wp) :: force_tol = 1.0e-10_wp      !< scaled residual tolerance [-]
      real(wp) :: disp_tol = 1.0e-10_wp       !< scaled correction tolerance [-]
      logical :: line_search = .false.        !< energy line search along the correction
      integer :: max_backtracks = 5           !< line-search trials after the full step
      real(wp) :: ls_ratio = 0.8_wp           !< accept when |s(alpha)| <= ls_ratio |s(0)|
      real(wp) :: ls_min = 0.05_wp            !< smallest step length [-]
      integer :: log_unit = -1                !< unit for the iteration log (< 0: none)
      real(wp) :: roundoff_correction = 1.0e-12_wp !< correction at round-off level [-]
      real(wp) :: roundoff_factor = 1.0e4_wp  !< residual floor allowed, x force_tol
      logical :: reuse_tangent = .false.      !< keep factorised tangents while they work
      real(wp) :: reuse_ratio = 0.25_wp       !< new tangent if rn > reuse_ratio rn_prev
      !> Anderson acceleration of the reused-tangent iterations (rodyn_anderson), when
      !> the problem keeps a history for it; not with the line search
      logical :: anderson = .false.
   end type newton_options_t

   !> What one solve did.
   type :: newton_stats_t
      logical :: converged = .false.
      integer :: iterations = 0               !< linear solves done
      integer :: tangents = 0                 !< tangents formed and factorised
      real(wp) :: residual = 0.0_wp           !< final scaled residual
      real(wp) :: correction = 0.0_wp         !< last scaled correction
   end type newton_stats_t

   !> Where one solve stands between the steps of an iteration (newton_solve).
   type :: newton_iterate_t
      integer :: it = 0                   !< the iteration under way
      real(wp) :: rn = 0.0_wp             !< scaled residual of the iterate [-]
      real(wp) :: rn_prev = 0.0_wp        !< that of the iterate before [-]
      real(wp) :: rn_trial = 0.0_wp       !< scaled residual at the trial step [-]
      real(wp) :: cn = 0.0_wp             !< scaled norm of the correction [-]
      real(wp) :: cn_prev = huge(1.0_wp)  !< the correction taken before, alpha cn [-]
      real(wp) :: alpha = 1.0_wp          !< step length along the correction [-]
      logical :: refresh = .false.        !< the next correction forms a new tangent
      logical :: fresh = .false.          !< this correction's tangent was just formed
   end type newton_iterate_t

   !> A nonlinear problem r(u) = 0 on a configuration updated by u. The flags tell the
   !> problem's solve whether the tangent was just formed (factorise it) or whether the
   !> factors of an earlier one are to be used; whoever changes the problem so that they
   !> no longer fit (a new time step size) clears factors_ok.
   type, abstract :: newton_problem_t
      logical :: tangent_new = .false.        !< tangent formed, not yet factorised
      logical :: factors_ok = .false.         !< factors of a tangent are held
      integer :: iteration = 0                !< the iteration under way (1: a new solve)
      !> the last solve begun with an earlier solve's tangent renewed it after its first
      !> iteration (then this one forms its tangent with that iteration's residual);
      !> cleared with factors_ok wherever a run must repeat itself (a checkpoint)
      logical :: renew_first = .false.
      logical :: accelerate = .false.         !< accelerate the chord steps (rodyn_anderson)
   contains
      !> Evaluate the residual at the current configuration (and the tangent).
      procedure(evaluate_iface), deferred :: evaluate
      !> Scaled residual norm of the last evaluation (dimensionless).
      procedure(norm_iface), deferred :: residual_norm
      !> Solve for the correction from the last residual and tangent.
      procedure(solve_iface), deferred :: solve
      !> Scaled norm of the correction (dimensionless).
      procedure(norm_iface), deferred :: correction_norm
      !> Energy slope du . r of the correction against the last residual [J].
      procedure(norm_iface), deferred :: slope
      !> Remember the current configuration as the base of the update.
      procedure(base_iface), deferred :: save_base
      !> Configuration <- base updated by alpha times the correction.
      procedure(apply_iface), deferred :: apply_correction
      !> Estimate of the scaled residual that round-off alone leaves (0: none).
      procedure(norm_iface), deferred :: residual_floor
   end type newton_problem_t

   abstract interface
      subroutine evaluate_iface(this, want_k, err)
         import :: newton_problem_t, error_t
         class(newton_problem_t), intent(inout) :: this
         logical, intent(in) :: want_k
         type(error_t), intent(inout) :: err
      end subroutine evaluate_iface
      function norm_iface(this) result(v)
         import :: newton_problem_t, wp
         class(newton_problem_t), intent(in) :: this
         real(wp) :: v
      end function norm_iface
      subroutine solve_iface(this, err)
         import :: newton_problem_t, error_t
         class(newton_problem_t), intent(inout) :: this
         type(error_t), intent(inout) :: err
      end subroutine solve_iface
      subroutine base_iface(this)
         import :: newton_problem_t
         class(newton_problem_t), intent(inout) :: this
      end subroutine base_iface
      subroutine apply_iface(this, alpha)
         import :: newton_problem_t, wp
         class(newton_problem_t), intent(inout) :: this
         real(wp), intent(in) :: alpha
      end subroutine apply_iface
   end interface

contains

   !> Solve the problem from its current configuration. Non-convergence is reported in
   !> stats (the caller cuts the step); err is set only for a failure that a smaller
   !> step cannot cure (never: singular tangents and NaN are also returned as
   !> non-convergence, with the reason in err for the caller to log or raise).
   !> docs/theory.md eqs. (45)-(53).
   subroutine newton_solve(prob, opts, stats, err)
      class(newton_problem_t), intent(inout) :: prob !< problem, configuration updated
      type(newton_options_t), intent(in) :: opts     !< controls
      type(newton_stats_t), intent(out) :: stats     !< what happened
      type(error_t), intent(inout) :: err            !< reason of a failure
      type(newton_iterate_t) :: ni
      integer :: it
      prob%accelerate = opts%anderson .and. opts%reuse_tangent .and. .not. opts%line_search
      ni%refresh = .not. opts%reuse_tangent .or. .not. prob%factors_ok
      call newton_evaluate(prob, ni%refresh, err)
      if (has_error(err)) return
      ni%rn = prob%residual_norm()
      if (.not. ieee_is_finite(ni%rn)) then
         call set_diverged(err)
         return
      end if
      call log_line(opts, 0, ni%rn, 0.0_wp, 0.0_wp)
      stats%residual = ni%rn
      if (ni%rn <= opts%force_tol) then
         stats%converged = .true.
         return
      end if
      do it = 1, opts%max_iterations
         ni%it = it
         call newton_correction(prob, ni, stats, err)
         if (has_error(err)) return
         call line_search(prob, opts, ni, err)
         if (has_error(err)) return
         if (.not. ieee_is_finite(ni%rn_trial)) then
            call set_diverged(err)
            return
         end if
         ni%rn_prev = ni%rn
         ni%rn = ni%rn_trial
         stats%residual = ni%rn
         stats%correction = ni%alpha*ni%cn
         call log_line(opts, it, ni%rn, ni%alpha*ni%cn, ni%alpha)
         stats%converged = newton_converged(prob, opts, ni)
         if (stats%converged) return
         call renew_tangent(prob, opts, ni, stats, err)
         if (has_error(err)) return
      end do
   end subroutine newton_solve

   !> The correction of iteration ni%it, K du = -r (docs/theory.md eq. (45)): with the
   !> tangent of this residual formed first when ni%refresh asks for one (ni%fresh: the
   !> tangent was just formed), and its scaled norm ni%cn (eq. (49)).
   subroutine newton_correction(prob, ni, stats, err)
      class(newton_problem_t), intent(inout) :: prob !< problem, residual evaluated
      type(newton_iterate_t), intent(inout) :: ni    !< the solve's iterate
      type(newton_stats_t), intent(inout) :: stats   !< tangents and iterations counted
      type(error_t), intent(inout) :: err            !< reason of a failure
      if (ni%refresh .and. .not. prob%tangent_new) then
         call newton_evaluate(prob, .true., err)   ! same residual, with its tangent
         if (has_error(err)) return
      end if
      ni%fresh = prob%tangent_new
      if (ni%fresh) stats%tangents = stats%tangents + 1
      prob%iteration = ni%it
      call prob%solve(err)
      if (has_error(err)) return
      stats%iterations = ni%it
      ni%cn = prob%correction_norm()
   end subroutine newton_correction

   !> The step length ni%alpha along the correction and the scaled residual ni%rn_trial
   !> there (module header; docs/theory.md eqs. (46), (52)): the full step, or with
   !> opts%line_search regula-falsi steps towards the zero of the energy slope; a step
   !> whose residual overflows is halved.
   subroutine line_search(prob, opts, ni, err)
      class(newton_problem_t), intent(inout) :: prob !< problem, configuration updated
      type(newton_options_t), intent(in) :: opts     !< controls
      type(newton_iterate_t), intent(inout) :: ni    !< the solve's iterate
      type(error_t), intent(inout) :: err            !< reason of a failure
      real(wp) :: s0, st, a_lo, s_lo, a_hi, s_hi, a_new
      integer :: bt
      call prob%save_base()
      s0 = prob%slope()
      ni%alpha = 1.0_wp
      a_lo = 0.0_wp          ! bracket: s(a_lo) < 0 < s(a_hi)
      s_lo = s0
      a_hi = 1.0_wp
      s_hi = 0.0_wp
      do bt = 0, opts%max_backtracks
         call prob%apply_correction(ni%alpha)
         ! a correction small enough for the quadratic-regime acceptance most likely
         ! ends the solve: its residual is evaluated alone (a tangent follows if not).
         ! The first correction with an earlier solve's tangent, when the last such
         ! solve renewed its tangent right after it (renew_tangent), is evaluated with
         ! its tangent: one residual evaluation less than forming it after
         call newton_evaluate(prob, (.not. opts%reuse_tangent .and. &
                              ni%alpha*ni%cn > sqrt(opts%disp_tol)) &
                       .or. (ni%it == 1 .and. .not. ni%fresh .and. prob%renew_first .and. &
                             .not. opts%line_search), err)
         if (has_error(err)) return
         ni%rn_trial = prob%residual_norm()
         if (.not. ieee_is_finite(ni%rn_trial)) then
            ni%alpha = 0.5_wp*ni%alpha            ! overflow: plain halving
            a_hi = ni%alpha
            cycle
         end if
         if (.not. opts%line_search .or. s0 >= 0.0_wp) exit
         st = prob%slope()
         if (abs(st) <= opts%ls_ratio*abs(s0) .or. bt == opts%max_backtracks) exit
         if (st < 0.0_wp) then
            if (ni%alpha >= 1.0_wp) exit      ! energy still falling at the full step
            a_lo = ni%alpha
            s_lo = st
         else
            a_hi = ni%alpha
            s_hi = st
         end if
         a_new = a_lo - s_lo*(a_hi - a_lo)/(s_hi - s_lo)
         a_new = min(a_hi, max(opts%ls_min, a_new))
         if (abs(a_new - ni%alpha) < 1.0e-3_wp) exit
         ni%alpha = a_new
      end do
   end subroutine line_search

   !> The iterate converged (module header; docs/theory.md eqs. (50)-(51)): residual and
   !> correction within their tolerances, or the quadratic regime, or the round-off floor
   !> (logged so).
   logical function newton_converged(prob, opts, ni) result(converged)
      class(newton_problem_t), intent(in) :: prob    !< problem (residual floor)
      type(newton_options_t), intent(in) :: opts     !< controls
      type(newton_iterate_t), intent(in) :: ni       !< the solve's iterate
      converged = .true.
      if (ni%rn <= opts%force_tol .and. ni%alpha*ni%cn <= opts%disp_tol) return
      ! quadratic regime: a full step that cut the residual tenfold to below FORCE TOL
      ! leaves an error of order correction^2, so a correction below sqrt(DISP TOL)
      ! already meets DISP TOL (saves the iteration that would only confirm it)
      if (ni%fresh .and. ni%rn <= opts%force_tol .and. ni%alpha == 1.0_wp .and. &
          ni%rn <= 0.1_wp*ni%rn_prev .and. ni%cn <= sqrt(opts%disp_tol)) return
      if (ni%cn <= opts%roundoff_correction .and. &
          ni%rn <= opts%roundoff_factor*opts%force_tol) then
         if (opts%log_unit >= 0) write (opts%log_unit, '(4x,a)') &
            'converged to round-off (correction below 1e-12, residual at its floor)'
         return
      end if
      ! the same floor reached earlier: a full correction within DISP TOL that did not
      ! even halve a residual already within 100 FORCE TOL. The residual that round-off
      ! leaves grows with the element count (strains from coordinate differences over
      ! ever shorter elements); on fine meshes the round-off rule above alone would take
      ! one or two iterations more (and new tangents) to end each step
      if (ni%alpha == 1.0_wp .and. ni%cn <= opts%disp_tol .and. &
          ni%rn > 0.5_wp*ni%rn_prev) then
         if (at_floor(prob, opts, ni%rn)) then
            if (opts%log_unit >= 0) write (opts%log_unit, '(4x,a)') &
               'converged to round-off (correction within DISP TOL, residual not falling)'
            return
         end if
      end if
      converged = .false.
   end function newton_converged

   !> Whether the next correction forms a new tangent (ni%refresh; module header,
   !> docs/theory.md eq. (53)): a tangent that no longer contracts the residual fast
   !> enough is renewed, at the iterate before if this reused one made things worse.
   subroutine renew_tangent(prob, opts, ni, stats, err)
      class(newton_problem_t), intent(inout) :: prob !< problem, configuration updated
      type(newton_options_t), intent(in) :: opts     !< controls
      type(newton_iterate_t), intent(inout) :: ni    !< the solve's iterate
      type(newton_stats_t), intent(inout) :: stats   !< residual
      type(error_t), intent(inout) :: err            !< reason of a failure
      ni%refresh = .not. opts%reuse_tangent .or. ni%rn > opts%reuse_ratio*ni%rn_prev
      ! ... unless the residual has reached its round-off floor (within 100 FORCE TOL)
      ! while the tangent still works: a full correction a tenth of the one before. A
      ! residual that then stalls is round-off, which a new tangent does not cure; the
      ! next correction ends the solve by the round-off rule (newton_converged; on fine
      ! meshes the floor lies well above FORCE TOL, and new tangents would only confirm
      ! it).
      if (ni%refresh .and. opts%reuse_tangent .and. ni%alpha == 1.0_wp .and. &
          ni%cn <= 0.1_wp*ni%cn_prev) then
         if (at_floor(prob, opts, ni%rn)) ni%refresh = .false.
      end if
      ni%cn_prev = ni%alpha*ni%cn
      ! the first correction of a solve with an earlier solve's tangent takes the
      ! step's linear part (support motion, inertia) and leaves its nonlinear part;
      ! unless that is already small, the next tangent is formed here rather than
      ! after an iteration that the old tangent does poorly (fewer iterations a step
      ! for slightly more tangents)
      if (ni%it == 1 .and. .not. ni%fresh .and. ni%rn > sqrt(opts%force_tol)) &
         ni%refresh = .true.
      if (ni%it == 1 .and. .not. ni%fresh) prob%renew_first = ni%refresh
      ! (full step: back to base)
      if (ni%refresh .and. opts%reuse_tangent .and. .not. ni%fresh .and. &
          ni%rn > ni%rn_prev .and. ni%alpha == 1.0_wp) then
         call prob%apply_correction(0.0_wp)
         call newton_evaluate(prob, .true., err)
         if (has_error(err)) return
         ni%rn = prob%residual_norm()
         stats%residual = ni%rn
      end if
   end subroutine renew_tangent

   !> The scaled residual r may be at its round-off floor: within 100 force_tol, or
   !> within 100 times the problem's estimate of the floor (prob%residual_floor, which
   !> grows as the elements get shorter; asked only when the first test fails;
   !> docs/theory.md eq. (51)).
   logical function at_floor(prob, opts, r)
      class(newton_problem_t), intent(in) :: prob !< problem
      type(newton_options_t), intent(in) :: opts  !< controls
      real(wp), intent(in) :: r                   !< scaled residual [-]
      at_floor = r <= 1.0e2_wp*opts%force_tol
      if (.not. at_floor) at_floor = r <= 1.0e2_wp*prob%residual_floor()
   end function at_floor

   !> Evaluate the residual, and the tangent if want_k (then to be factorised).
   subroutine newton_evaluate(prob, want_k, err)
      class(newton_problem_t), intent(inout) :: prob !< problem
      logical, intent(in) :: want_k                  !< form the tangent
      type(error_t), intent(inout) :: err            !< reason of a failure
      call prob%evaluate(want_k, err)
      if (.not. want_k) return
      prob%tangent_new = .true.
      prob%factors_ok = .false.
   end subroutine newton_evaluate

   !> The error of a residual that overflowed.
   subroutine set_diverged(err)
      type(error_t), intent(inout) :: err            !< reason of the failure
      call set_error(err, stat_numerical, 'newton_solve: the residual '// &
                     'overflowed (not finite): the state diverged')
   end subroutine set_diverged

   !> One line of the iteration log (none with opts%log_unit < 0).
   subroutine log_line(opts, i, r, c, a)
      type(newton_options_t), intent(in) :: opts     !< controls (log unit)
      integer, intent(in) :: i                       !< iteration
      real(wp), intent(in) :: r                      !< scaled residual [-]
      real(wp), intent(in) :: c                      !< scaled correction taken [-]
      real(wp), intent(in) :: a                      !< step length [-]
      if (opts%log_unit < 0) return
      write (opts%log_unit, '(4x,a,i3,a,es10.3,a,es10.3,a,f6.4)') 'iteration', i, &
         '  residual', r, '  correction', c, '  step', a
   end subroutine log_line
end module rodyn_newton
