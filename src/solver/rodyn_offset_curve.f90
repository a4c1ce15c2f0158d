!> The offset-restoring-force curve of a body (*OFFSET CURVE; docs/systems.md): from the
!> static equilibrium, a horizontal force at the body's reference point R raised in equal
!> steps, each a static solution (statics_solve from the one before); the offset of R along
!> the force, its position and rotation, and the largest force on a line end on the body.
!> The equilibrium is restored afterwards (a dynamic analysis starts from it).
module rodyn_offset_curve
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t
   use rodyn_mesh, only: mesh_node
   use rodyn_model, only: end_a, end_b
   use rodyn_state, only: state_t
   use rodyn_statics, only: static_problem_t, statics_solve, static_set_load_factor
   use rodyn_results, only: run_summary_t, system_result_t
   use rodyn_rotation, only: rotation_log
   implicit none
   private
   public :: offset_curve

contains

   !> The curve of model%offset_curve into sys%curve (nothing without *OFFSET CURVE).
   subroutine offset_curve(prob, model, sys, err)
      type(static_problem_t), intent(inout) :: prob  !< solved problem (restored after)
      type(model_t), intent(in) :: model             !< model
      type(system_result_t), intent(inout) :: sys    !< curve set
      type(error_t), intent(inout) :: err            !< status
      type(state_t) :: keep
      type(run_summary_t) :: summ
      real(wp) :: dir(3), x0(3)
      integer :: k, n, np
      associate (oc => model%offset_curve)
         if (oc%body == 0) return
         n = prob%mesh%body_node(oc%body)
         keep = prob%state
         dir = [cos(oc%heading), sin(oc%heading), 0.0_wp]
         np = size(prob%loads%pt_node)
         prob%loads%pt_node = [prob%loads%pt_node, n]
         prob%loads%pt_amp = [prob%loads%pt_amp, 0]
         prob%loads%pt_fm = reshape([prob%loads%pt_fm, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, &
                                     0.0_wp, 0.0_wp]], [6, np + 1])
         allocate (sys%curve(9, 0:oc%steps))
         call curve_point(0, 0.0_wp)
         x0 = sys%curve(3:5, 0)
         sys%curve(2, 0) = 0.0_wp
         do k = 1, oc%steps
            prob%loads%pt_fm(1:3, np + 1) = oc%force*real(k, wp)/real(oc%steps, wp)*dir
            call statics_solve(prob, model, summ, err, -1)
            if (has_error(err)) then
               sys%curve = sys%curve(:, 0:k - 1)
               exit
            end if
            call curve_point(k, oc%force*real(k, wp)/real(oc%steps, wp))
            sys%curve(2, k) = dot_product(sys%curve(3:5, k) - x0, dir)
         end do
         prob%loads%pt_node = prob%loads%pt_node(1:np)
         prob%loads%pt_amp = prob%loads%pt_amp(1:np)
         prob%loads%pt_fm = prob%loads%pt_fm(:, 1:np)
         prob%state = keep
         call static_set_load_factor(prob, 1.0_wp, 1.0_wp)
         call prob%evaluate(.false., err)
      end associate
   contains
      !> Point k of the curve at force f from the problem's state.
      subroutine curve_point(k, f)
         integer, intent(in) :: k
         real(wp), intent(in) :: f
         integer :: l, j, e
         real(wp) :: tmax
         associate (b => model%bodies(model%offset_curve%body))
            sys%curve(1, k) = f
            sys%curve(3:5, k) = prob%state%x(:, n) + matmul(prob%state%d(:, :, n), -b%cog)
            sys%curve(6:8, k) = rotation_log(prob%state%d(:, :, n))
         end associate
         call prob%evaluate(.false., err)
         tmax = 0.0_wp
         do l = 1, prob%mesh%n_lines
            do j = 1, 2
               if (prob%mesh%end_point_node(j, l) /= n) cycle
               e = mesh_node(prob%mesh, l, merge(end_a, end_b, j == 1))
               tmax = max(tmax, norm2(prob%r(1:3, e)))
            end do
         end do
         sys%curve(9, k) = tmax
      end subroutine curve_point
   end subroutine offset_curve
end module rodyn_offset_curve
