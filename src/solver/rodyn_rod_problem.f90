!> What the static problem and the time-step problem share as Newton problems: the
!> banded workspace, the supports, the convergence scales, and the residual norm, linear
!> solve, correction norm and energy slope (rodyn_newton). Each problem adds its own
!> residual (evaluate) and configuration update (save_base, apply_correction).
!> docs/theory.md eqs. (46), (49)-(52).
module rodyn_rod_problem
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error, set_error, stat_numerical
   use rodyn_model, only: model_t
   use rodyn_mesh, only: mesh_t
   use rodyn_banded, only: banded_t, banded_init, banded_factor, banded_solve, &
                           banded_set_reach
   use rodyn_assembly, only: supports_t, dof_reach
   use rodyn_newton, only: newton_problem_t
   use rodyn_rotation, only: rotation_cayley
   use rodyn_anderson, only: anderson_t, anderson_clear, anderson_step
   use rodyn_junctions, only: junctions_t, junctions_build, junctions_factor, junctions_solve
   use rodyn_bodies, only: body_loads_t, body_loads_build
   implicit none
   private
   public :: rod_problem_t, rod_problem_init, rod_factor, rod_back_solve

   !> Shared part of the rod Newton problems.
   type, abstract, extends(newton_problem_t) :: rod_problem_t
      type(mesh_t), pointer :: mesh => null()
      type(supports_t) :: sup                  !< supports
      real(wp), allocatable :: fint(:, :)      !< (6, nn) internal forces (and inertia)
      real(wp), allocatable :: fext(:, :)      !< (6, nn) external forces
      real(wp), allocatable :: r(:, :)         !< (6, nn) residual, global axes
      real(wp), allocatable :: gap(:, :)       !< (3, nn) prescribed - current position [m]
      real(wp), allocatable :: rhs(:)          !< (n_dof) residual in node bases, held = -gap
      real(wp), allocatable :: du(:)           !< (n_dof) Newton correction
      real(wp), allocatable :: x_base(:, :)    !< (3, nn) base of the line search
      real(wp), allocatable :: d_base(:, :, :) !< (3, 3, nn)
      !> x_base and d_base hold the iterate that the last correction of this solve
      !> started from (Newton's base); cleared by a problem when it starts a new solve
      logical :: base_set = .false.
      type(banded_t) :: bm                     !< tangent, then its LU factors
      type(junctions_t) :: jn                  !< FREE points: their unknowns and line ends
      type(body_loads_t) :: bl                 !< FREE bodies' turning loads
      type(anderson_t) :: aa                   !< history of the accelerated chord steps
      real(wp) :: lref = 1.0_wp                !< length scale of the criteria [m]
      real(wp) :: href = 1.0_wp                !< shortest element [m]
      real(wp) :: f_floor = 0.0_wp             !< round-off level of the section forces [N]
      real(wp) :: m_floor = 0.0_wp             !< round-off level of the moments [N m]
      !> round-off of the section forces per metre of coordinate, eps max_e C/le [N/m],
      !> and of the moments, eps max_e EI/le [N m] (rod_residual_floor)
      real(wp) :: f_round = 0.0_wp
      real(wp) :: m_round = 0.0_wp
      real(wp) :: f_extra = 0.0_wp             !< problem's own reference force [N]
      real(wp) :: m_extra = 0.0_wp             !< problem's own reference moment [N m]
   contains
      procedure :: residual_norm => rod_residual_norm
      procedure :: solve => rod_solve
      procedure :: correction_norm => rod_correction_norm
      procedure :: slope => rod_slope
      procedure :: rotate_from_base => rod_rotate_from_base
      procedure :: residual_floor => rod_residual_floor
   end type rod_problem_t

contains

   !> Allocate the shared workspace of a mesh and set the convergence scales; the
   !> supports (prob%sup, with their dof map) are built before.
   subroutine rod_problem_init(prob, model, mesh)
      class(rod_problem_t), intent(inout) :: prob !< problem
      type(model_t), intent(in) :: model          !< model
      type(mesh_t), intent(in), target :: mesh    !< mesh
      integer :: nn
      integer, allocatable :: reach(:)
      prob%mesh => mesh
      nn = mesh%n_nodes
      allocate (prob%fint(6, nn), prob%fext(6, nn), prob%r(6, nn), prob%gap(3, nn), &
                prob%rhs(prob%sup%n_dof), prob%du(prob%sup%n_dof), prob%x_base(3, nn), &
                prob%d_base(3, 3, nn))
      prob%fext = 0.0_wp
      prob%gap = 0.0_wp
      call banded_init(prob%bm, prob%sup%n_dof, prob%sup%half_bw)
      allocate (reach(prob%sup%n_dof))
      call dof_reach(mesh, prob%sup, reach)
      call banded_set_reach(prob%bm, reach)
      call junctions_build(mesh, prob%sup, prob%jn)
      call body_loads_build(model, mesh, prob%bl)
      prob%lref = maxval(model%lines%length)
      prob%href = minval(mesh%elem_le)
      ! forces below what a strain of sqrt(epsilon) produces are numerically zero: the
      ! floor of the residual scale when there is no load and no reaction to compare with
      prob%f_floor = sqrt(epsilon(1.0_wp))*maxval(mesh%elem_c(1:3, :))
      prob%m_floor = sqrt(epsilon(1.0_wp))*maxval(mesh%elem_c(4:6, :))/prob%lref
      prob%f_round = epsilon(1.0_wp)*maxval(maxval(mesh%elem_c(1:3, :), dim=1)/mesh%elem_le)
      prob%m_round = epsilon(1.0_wp)*maxval(maxval(mesh%elem_c(4:6, :), dim=1)/mesh%elem_le)
      prob%x_base = 0.0_wp
   end subroutine rod_problem_init

   !> max(|r_F| / F_ref, |r_M| / M_ref) over free dofs (docs/theory.md eq. (49)). F_ref:
   !> largest applied force, the problem's own reference (reactions in statics, inertia and
   !> internal forces in a time step) or moment over the line length; M_ref likewise, or
   !> F_ref times the shortest element; neither below the round-off level of the section
   !> forces.
   function rod_residual_norm(this) result(v)
      class(rod_problem_t), intent(in) :: this !< problem
      real(wp) :: v
      real(wp) :: fref, mref, rf, rm
      integer :: node, k
      rf = 0.0_wp
      rm = 0.0_wp
      ! two loops: the uniform layout (6 unknowns a node) takes the simpler one
      if (this%sup%uniform) then
         call uniform_residual_max(this%mesh%n_nodes, this%rhs, this%sup%held, rf, rm)
      else
         do node = 1, this%mesh%n_nodes
            k = this%sup%first(node) - 1
            rf = max(rf, maxval(abs(this%rhs(k + 1:k + 3)), mask=.not. this%sup%held(1:3, node)))
            if (this%sup%ndof(node) == 3) cycle
            rm = max(rm, maxval(abs(this%rhs(k + 4:k + 6)), mask=.not. this%sup%held(4:6, node)))
         end do
      end if
      call rod_residual_refs(this, fref, mref)
      v = max(rf/fref, rm/mref)
   end function rod_residual_norm

   !> The reference force and moment of rod_residual_norm.
   pure subroutine rod_residual_refs(this, fref, mref)
      class(rod_problem_t), intent(in) :: this !< problem
      real(wp), intent(out) :: fref            !< F_ref [N]
      real(wp), intent(out) :: mref            !< M_ref [N m]
      mref = max(maxval(abs(this%fext(4:6, :))), this%m_extra, this%m_floor)
      fref = max(maxval(abs(this%fext(1:3, :))), this%f_extra, mref/this%lref, this%f_floor)
      mref = max(mref, fref*this%href)
   end subroutine rod_residual_refs

   !> Estimate of the scaled residual that round-off alone leaves (newton_solve's floor
   !> rules). A strain formed from node coordinates of size |x| over an element of length
   !> le carries an error of about eps |x| / le, so a section force one of eps |x| C / le
   !> (C = GA1, GA2 or EA), a moment one of eps EI / le (unit directors):
   !>   floor = max(eps |x|_max max_e(C/le) / F_ref,  eps max_e(EI/le) / M_ref)
   !> with |x|_max over Newton's base and the references of rod_residual_norm
   !> (docs/theory.md eq. (51)). The residuals at which steps stall are a few times this
   !> estimate (a node's residual sums the point forces of its elements), hence the factor
   !> 100 of newton_solve's rule.
   function rod_residual_floor(this) result(v)
      class(rod_problem_t), intent(in) :: this !< problem
      real(wp) :: v
      real(wp) :: fref, mref
      call rod_residual_refs(this, fref, mref)
      v = max(this%f_round*maxval(abs(this%x_base))/fref, this%m_round/mref)
   end function rod_residual_floor

   !> du = -K^{-1} rhs (banded LU): a tangent just formed is factorised first, otherwise
   !> the factors held are used again. With this%accelerate, du is the Anderson
   !> correction of the chord step (rodyn_anderson), its history cleared by a new tangent
   !> or a new solve.
   subroutine rod_solve(this, err)
      class(rod_problem_t), intent(inout) :: this !< problem
      type(error_t), intent(inout) :: err         !< status
      if (this%accelerate .and. (this%tangent_new .or. this%iteration <= 1)) &
         call anderson_clear(this%aa)
      if (this%tangent_new) then
         this%tangent_new = .false.
         call rod_factor(this, err)
         if (has_error(err)) return
         this%factors_ok = .true.
      else if (.not. this%factors_ok) then
         call set_error(err, stat_numerical, 'rod_solve: no tangent to solve with')
         return
      end if
      this%du = -this%rhs
      call rod_back_solve(this, this%du, err)
      if (this%accelerate) call anderson_step(this%aa, this%du)
   end subroutine rod_solve

   !> Factorise the tangent bm: by junction condensation when the mesh has junctions
   !> (rodyn_junctions), else the banded LU.
   subroutine rod_factor(this, err)
      class(rod_problem_t), intent(inout) :: this !< problem, bm formed
      type(error_t), intent(inout) :: err         !< status
      if (this%jn%nj > 0) then
         call junctions_factor(this%jn, this%bm, err)
      else
         call banded_factor(this%bm, err, this%sup%first)
      end if
   end subroutine rod_factor

   !> x = K^{-1} x with the factors of rod_factor.
   subroutine rod_back_solve(this, x, err)
      class(rod_problem_t), intent(inout) :: this !< problem, bm factorised
      real(wp), intent(inout) :: x(:)             !< (n_dof) right-hand side, solution
      type(error_t), intent(inout) :: err         !< status
      if (this%jn%nj > 0) then
         call junctions_solve(this%jn, this%sup, this%bm, x, err)
      else
         call banded_solve(this%bm, x, err)
      end if
   end subroutine rod_back_solve

   !> max(|du_x| / L_ref, |du_theta|).
   function rod_correction_norm(this) result(v)
      class(rod_problem_t), intent(in) :: this !< problem
      real(wp) :: v
      integer :: node, k
      v = 0.0_wp
      if (this%sup%uniform) then
         call uniform_correction_max(this%mesh%n_nodes, this%du, this%lref, v)
         return
      end if
      do node = 1, this%mesh%n_nodes
         k = this%sup%first(node) - 1
         v = max(v, maxval(abs(this%du(k + 1:k + 3)))/this%lref)
         if (this%sup%ndof(node) == 6) v = max(v, maxval(abs(this%du(k + 4:k + 6))))
      end do
   end function rod_correction_norm

   !> Energy slope du . r [J] (line search).
   function rod_slope(this) result(v)
      class(rod_problem_t), intent(in) :: this !< problem
      real(wp) :: v
      v = dot_product(this%du, this%rhs)
   end function rod_slope

   !> d_i = cay(alpha du_theta) d_i,base at every node (docs/theory.md eq. (46)), the rotation
   !> taken back to global axes at nodes with their own basis.
   subroutine rod_rotate_from_base(this, alpha, d)
      class(rod_problem_t), intent(in) :: this !< problem
      real(wp), intent(in) :: alpha            !< step length [-]
      real(wp), intent(inout) :: d(:, :, :)    !< (3, 3, nn) directors updated
      real(wp) :: th(3), rot(3, 3)
      integer :: node, k
      if (this%sup%uniform) then      ! (two loops: the rod's layout costs what it did)
         do node = 1, this%mesh%n_nodes
            k = 6*(node - 1)
            th = alpha*this%du(k + 4:k + 6)
            if (this%sup%rotated(node)) th = matmul(this%sup%basis(:, :, node), th)
            rot = rotation_cayley(th)
            call turn_directors(rot, this%d_base(:, :, node), d(:, :, node))
         end do
         return
      end if
      do node = 1, this%mesh%n_nodes
         ! no rotation unknowns: the directors stay as they were at save_base (nothing
         ! turns them in between), so they are not copied back (nor saved, for a mesh of
         ! cables only)
         if (this%sup%ndof(node) == 3) cycle
         k = this%sup%first(node) - 1
         th = alpha*this%du(k + 4:k + 6)
         if (this%sup%rotated(node)) th = matmul(this%sup%basis(:, :, node), th)
         rot = rotation_cayley(th)
         call turn_directors(rot, this%d_base(:, :, node), d(:, :, node))
      end do
   end subroutine rod_rotate_from_base

   !> The largest free force and moment entries of a right-hand side with 6 unknowns a
   !> node (rod_residual_norm). Explicit shapes, so that the loop vectorises.
   pure subroutine uniform_residual_max(nn, rhs, held, rf, rm)
      integer, intent(in) :: nn             !< nodes
      real(wp), intent(in) :: rhs(6, nn)    !< right-hand side
      logical, intent(in) :: held(6, nn)    !< held dofs
      real(wp), intent(inout) :: rf, rm     !< largest force, moment [N, N m]
      integer :: node
      do node = 1, nn
         rf = max(rf, maxval(abs(rhs(1:3, node)), mask=.not. held(1:3, node)))
         rm = max(rm, maxval(abs(rhs(4:6, node)), mask=.not. held(4:6, node)))
      end do
   end subroutine uniform_residual_max

   !> The largest scaled correction with 6 unknowns a node (rod_correction_norm).
   pure subroutine uniform_correction_max(nn, du, lref, v)
      integer, intent(in) :: nn          !< nodes
      real(wp), intent(in) :: du(6, nn)  !< correction
      real(wp), intent(in) :: lref       !< reference length [m]
      real(wp), intent(inout) :: v       !< largest scaled entry [-]
      integer :: node
      do node = 1, nn
         v = max(v, maxval(abs(du(1:3, node)))/lref, maxval(abs(du(4:6, node))))
      end do
   end subroutine uniform_correction_max

   !> d = rot db for one node's directors (3 x 3 explicit shapes: unrolled by the
   !> compiler, unlike matmul on assumed-shape sections)
   pure subroutine turn_directors(rot, db, d)
      real(wp), intent(in) :: rot(3, 3) !< rotation
      real(wp), intent(in) :: db(3, 3)  !< directors at the base, db(:, i) = d_i
      real(wp), intent(out) :: d(3, 3)  !< turned directors
      integer :: i
      do i = 1, 3
         d(:, i) = rot(:, 1)*db(1, i) + rot(:, 2)*db(2, i) + rot(:, 3)*db(3, i)
      end do
   end subroutine turn_directors
end module rodyn_rod_problem
