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
      real(wp) :: rn, cn, alpha, s0, st, a_lo, s_lo, a_hi, s_hi, a_new
      real(wp) :: rn_trial, rn_prev, cn_prev
      integer :: it, bt
      logical :: refresh, fresh
      rn_trial = 0.0_wp
      cn_prev = huge(1.0_wp)
      prob%accelerate = opts%anderson .and. opts%reuse_tangent .and. .not. opts%line_search
      refresh = .not. opts%reuse_tangent .or. .not. prob%factors_ok
      call evaluate(refresh)
      if (has_error(err)) return
      rn = prob%residual_norm()
      if (.not. ieee_is_finite(rn)) then
         call set_error(err, stat_numerical, 'newton_solve: the residual '// &
                        'overflowed (not finite): the state diverged')
         return
      end if
      call log_line(0, rn, 0.0_wp, 0.0_wp)
      stats%residual = rn
      if (rn <= opts%force_tol) then
         stats%converged = .true.
         return
      end if
      do it = 1, opts%max_iterations
         if (refresh .and. .not. prob%tangent_new) then
            call evaluate(.true.)          ! same residual, with its tangent
            if (has_error(err)) return
         end if
         fresh = prob%tangent_new
         if (fresh) stats%tangents = stats%tangents + 1
         prob%iteration = it
         call prob%solve(err)
         if (has_error(err)) return
         stats%iterations = it
         cn = prob%correction_norm()
         call prob%save_base()
         s0 = prob%slope()
         alpha = 1.0_wp
         a_lo = 0.0_wp          ! bracket: s(a_lo) < 0 < s(a_hi)
         s_lo = s0
         a_hi = 1.0_wp
         s_hi = 0.0_wp
         do bt = 0, opts%max_backtracks
            call prob%apply_correction(alpha)
            ! a correction small enough for the quadratic-regime acceptance most likely
            ! ends the solve: its residual is evaluated alone (a tangent follows if not).
            ! The first correction with an earlier solve's tangent, when the last such
            ! solve renewed its tangent right after it (below), is evaluated with its
            ! tangent: one residual evaluation less than forming it after
            call evaluate((.not. opts%reuse_tangent .and. alpha*cn > sqrt(opts%disp_tol)) &
                          .or. (it == 1 .and. .not. fresh .and. prob%renew_first .and. &
                                .not. opts%line_search))
            if (has_error(err)) return
            rn_trial = prob%residual_norm()
            if (.not. ieee_is_finite(rn_trial)) then
               alpha = 0.5_wp*alpha            ! overflow: plain halving
               a_hi = alpha
               cycle
            end if
            if (.not. opts%line_search .or. s0 >= 0.0_wp) exit
            st = prob%slope()
            if (abs(st) <= opts%ls_ratio*abs(s0) .or. bt == opts%max_backtracks) exit
            if (st < 0.0_wp) then
               if (alpha >= 1.0_wp) exit      ! energy still falling at the full step
               a_lo = alpha
               s_lo = st
            else
               a_hi = alpha
               s_hi = st
            end if
            a_new = a_lo - s_lo*(a_hi - a_lo)/(s_hi - s_lo)
            a_new = min(a_hi, max(opts%ls_min, a_new))
            if (abs(a_new - alpha) < 1.0e-3_wp) exit
            alpha = a_new
         end do
         if (.not. ieee_is_finite(rn_trial)) then
            call set_error(err, stat_numerical, 'newton_solve: the residual '// &
                        'overflowed (not finite): the state diverged')
            return
         end if
         rn_prev = rn
         rn = rn_trial
         stats%residual = rn
         stats%correction = alpha*cn
         call log_line(it, rn, alpha*cn, alpha)
         if (rn <= opts%force_tol .and. alpha*cn <= opts%disp_tol) then
            stats%converged = .true.
            return
         end if
         ! quadratic regime: a full step that cut the residual tenfold to below FORCE TOL
         ! leaves an error of order correction^2, so a correction below sqrt(DISP TOL)
         ! already meets DISP TOL (saves the iteration that would only confirm it)
         if (fresh .and. rn <= opts%force_tol .and. alpha == 1.0_wp .and. &
             rn <= 0.1_wp*rn_prev .and. cn <= sqrt(opts%disp_tol)) then
            stats%converged = .true.
            return
         end if
         if (cn <= opts%roundoff_correction .and. rn <= opts%roundoff_factor*opts%force_tol) then
            if (opts%log_unit >= 0) write (opts%log_unit, '(4x,a)') &
               'converged to round-off (correction below 1e-12, residual at its floor)'
            stats%converged = .true.
            return
         end if
         ! the same floor reached earlier: a full correction within DISP TOL that did not
         ! even halve a residual already within 100 FORCE TOL. The residual that round-off
         ! leaves grows with the element count (strains from coordinate differences over
         ! ever shorter elements); on fine meshes the round-off rule above alone would take
         ! one or two iterations more (and new tangents) to end each step
         if (alpha == 1.0_wp .and. cn <= opts%disp_tol .and. rn > 0.5_wp*rn_prev) then
            if (at_floor(rn)) then
               if (opts%log_unit >= 0) write (opts%log_unit, '(4x,a)') &
                  'converged to round-off (correction within DISP TOL, residual not falling)'
               stats%converged = .true.
               return
            end if
         end if
         ! a tangent that no longer contracts the residual fast enough is renewed, at the
         ! iterate before if this reused one made things worse (full step: back to base)
         refresh = .not. opts%reuse_tangent .or. rn > opts%reuse_ratio*rn_prev
         ! ... unless the residual has reached its round-off floor (within 100 FORCE TOL)
         ! while the tangent still works: a full correction a tenth of the one before. A
         ! residual that then stalls is round-off, which a new tangent does not cure; the
         ! next correction ends the solve by the round-off rule above (on fine meshes the
         ! floor lies well above FORCE TOL, and new tangents would only confirm it).
         if (refresh .and. opts%reuse_tangent .and. alpha == 1.0_wp .and. &
             cn <= 0.1_wp*cn_prev) then
            if (at_floor(rn)) refresh = .false.
         end if
         cn_prev = alpha*cn
         ! the first correction of a solve with an earlier solve's tangent takes the
         ! step's linear part (support motion, inertia) and leaves its nonlinear part;
         ! unless that is already small, the next tangent is formed here rather than
         ! after an iteration that the old tangent does poorly (fewer iterations a step
         ! for slightly more tangents)
         if (it == 1 .and. .not. fresh .and. rn > sqrt(opts%force_tol)) refresh = .true.
         if (it == 1 .and. .not. fresh) prob%renew_first = refresh
         if (refresh .and. opts%reuse_tangent .and. .not. fresh .and. rn > rn_prev .and. &
             alpha == 1.0_wp) then
            call prob%apply_correction(0.0_wp)
            call evaluate(.true.)
            if (has_error(err)) return
            rn = prob%residual_norm()
            stats%residual = rn
         end if
      end do
   contains
      !> The scaled residual r may be at its round-off floor: within 100 force_tol, or
      !> within 100 times the problem's estimate of the floor (prob%residual_floor, which
      !> grows as the elements get shorter; asked only when the first test fails)
      logical function at_floor(r)
         real(wp), intent(in) :: r
         at_floor = r <= 1.0e2_wp*opts%force_tol
         if (.not. at_floor) at_floor = r <= 1.0e2_wp*prob%residual_floor()
      end function at_floor
      !> Evaluate the residual, and the tangent if want_k (then to be factorised).
      subroutine evaluate(want_k)
         logical, intent(in) :: want_k
         call prob%evaluate(want_k, err)
         if (.not. want_k) return
         prob%tangent_new = .true.
         prob%factors_ok = .false.
      end subroutine evaluate
      subroutine log_line(i, r, c, a)
         integer, intent(in) :: i
         real(wp), intent(in) :: r, c, a
         if (opts%log_unit < 0) return
         write (opts%log_unit, '(4x,a,i3,a,es10.3,a,es10.3,a,f6.4)') 'iteration', i, &
            '  residual', r, '  correction', c, '  step', a
      end subroutine log_line
   end subroutine newton_solve
end module rodyn_newton
