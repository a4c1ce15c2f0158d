!> The junctions of a mooring system in the Newton step: the FREE points' unknowns and
!> the line ends on them (docs/theory.md section 17, eqs. (131)-(134)).
!>
!> A line end on a FREE point is pinned to it: its position is the point's, x_e = x_p.
!> The global band (rodyn_banded) is assembled as for separate lines, every node with
!> its own unknowns, the point's node (no element) with its own loads only. Then the
!> ends' translations are eliminated (u_e = u_p):
!>
!>   r_p <- r_p + sum_e r_e,   r_e <- 0                                          (131)
!>   K_pp <- K_pp + sum_{e,e'} K_ee',  K_ip <- K_ie,  K_pi <- K_ei  (i a line unknown) (132)
!>
!> The lines no longer couple to one another through the band, which keeps each line's
!> unknowns (the ends' and the points' rows become identity rows); K_ip, K_pi and K_pp
!> are the arrowhead's E, F and C (rodyn_arrowhead), solved by condensing each line
!> onto the points it touches:
!>
!>   (C - sum_i F_i A_i^-1 E_i) du_p = -(r_p - sum_i F_i A_i^-1 r_i)             (133)
!>   du_i = -A_i^-1 (r_i + E_i du_p),   du_e = du_p                              (134)
!>
!> Nothing here allocates after junctions_build.
module rodyn_junctions
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_mesh, only: mesh_t, mesh_node
   use rodyn_model, only: end_a, end_b
   use rodyn_banded, only: banded_t, banded_fix_dof
   use rodyn_arrowhead, only: arrowhead_t, arrowhead_init, arrowhead_block_init, &
                              arrowhead_zero, arrowhead_factor, arrowhead_solve
   use rodyn_assembly, only: supports_t
   implicit none
   private
   public :: junctions_t, junctions_build, junctions_condense, junctions_factor, &
             junctions_solve, junctions_stiffness

   !> The junction unknowns, the ends on them and the arrowhead matrix.
   type :: junctions_t
      integer :: nj = 0                      !< junction unknowns: 3 per FREE point
      integer, allocatable :: jdof(:)        !< (nj) the band's dof of each
      integer :: ns = 0                      !< line ends on FREE points
      integer, allocatable :: s_node(:)      !< (ns) node of each end
      integer, allocatable :: s_j0(:)        !< (ns) its point's first junction unknown - 1
      integer, allocatable :: s_line(:)      !< (ns) its line (the arrowhead block)
      integer, allocatable :: s_col(:)       !< (ns) its point's first column - 1 in E_line
      type(arrowhead_t) :: ah                !< E, F, C and the factors
      real(wp), allocatable :: y(:)          !< (nj) scratch
   end type junctions_t

contains

   !> The junctions of a mesh (none without FREE points: nj = 0, and nothing else is
   !> done by the routines below).
   subroutine junctions_build(mesh, sup, jn)
      type(mesh_t), intent(in) :: mesh       !< mesh with its point nodes
      type(supports_t), intent(in) :: sup    !< dof map
      type(junctions_t), intent(out) :: jn   !< junctions
      integer :: k, l, c, q, n, ns, np
      integer, allocatable :: jpt(:)         ! (nn) first junction unknown - 1 of a point node
      integer :: cols(6), nc
      np = count(mesh%point_node > 0)
      jn%nj = 3*np
      allocate (jn%jdof(jn%nj), jn%y(jn%nj), jpt(mesh%n_nodes))
      jpt = -1
      k = 0
      do q = 1, size(mesh%point_node)
         n = mesh%point_node(q)
         if (n == 0) cycle
         jpt(n) = k
         jn%jdof(k + 1:k + 3) = [(sup%first(n) + c - 1, c=1, 3)]
         k = k + 3
      end do
      ns = count(mesh%end_point_node > 0)
      jn%ns = ns
      allocate (jn%s_node(ns), jn%s_j0(ns), jn%s_line(ns), jn%s_col(ns))
      if (jn%nj == 0) return
      call arrowhead_init(jn%ah, mesh%n_lines, jn%nj)
      k = 0
      do l = 1, mesh%n_lines
         nc = 0
         do c = 1, 2
            q = mesh%end_point_node(c, l)
            if (q == 0) cycle
            k = k + 1
            jn%s_node(k) = mesh_node(mesh, l, merge(end_a, end_b, c == 1))
            jn%s_j0(k) = jpt(q)
            jn%s_line(k) = l
            jn%s_col(k) = nc
            cols(nc + 1:nc + 3) = [(jpt(q) + n, n=1, 3)]
            nc = nc + 3
         end do
         n = mesh_node(mesh, l, end_b)
         call arrowhead_block_init(jn%ah, l, sup%first(mesh_node(mesh, l, end_a)), &
                                   sup%first(n) + sup%ndof(n) - 1, cols(1:nc))
      end do
   end subroutine junctions_build

   !> Eliminate the ends' translations (eqs. (131)-(132)): the right-hand side always,
   !> the tangent when it was formed (want_k; after apply_supports).
   subroutine junctions_condense(jn, sup, rhs, bm, want_k)
      type(junctions_t), intent(inout) :: jn !< junctions: E, F, C set when want_k
      type(supports_t), intent(in) :: sup    !< dof map
      real(wp), intent(inout) :: rhs(:)      !< (n_dof) right-hand side
      type(banded_t), intent(inout) :: bm    !< tangent (its rows of ends and points cleared)
      logical, intent(in) :: want_k          !< the tangent was formed
      integer :: s, c, k
      if (jn%nj == 0) return
      do s = 1, jn%ns
         k = sup%first(jn%s_node(s)) - 1
         do c = 1, 3
            rhs(jn%jdof(jn%s_j0(s) + c)) = rhs(jn%jdof(jn%s_j0(s) + c)) + rhs(k + c)
            rhs(k + c) = 0.0_wp
         end do
      end do
      if (.not. want_k) return
      call arrowhead_zero(jn%ah)
      call point_blocks(jn, bm)
      do s = 1, jn%ns
         call end_couplings(jn, sup, bm, s)
      end do
      do s = 1, jn%ns
         k = sup%first(jn%s_node(s)) - 1
         do c = 1, 3
            call banded_fix_dof(bm, k + c)
         end do
      end do
      do k = 1, jn%nj
         call banded_fix_dof(bm, jn%jdof(k))
      end do
   end subroutine junctions_condense

   !> C(p, p) = the points' own 3 x 3 blocks (their loads and inertia) of the band.
   subroutine point_blocks(jn, bm)
      type(junctions_t), intent(inout) :: jn !< junctions
      type(banded_t), intent(in) :: bm       !< tangent
      integer :: j0, a, b
      do j0 = 0, jn%nj - 3, 3
         do b = 1, 3
            do a = 1, 3
               jn%ah%c(j0 + a, j0 + b) = band_entry(bm, jn%jdof(j0 + a), jn%jdof(j0 + b))
            end do
         end do
      end do
   end subroutine point_blocks

   !> The couplings of end s's translations with its line (E, F of the line's block) and
   !> with the ends of that line on points (C), read from the band (eq. (132)).
   subroutine end_couplings(jn, sup, bm, s)
      type(junctions_t), intent(inout) :: jn !< junctions
      type(supports_t), intent(in) :: sup    !< dof map
      type(banded_t), intent(in) :: bm       !< tangent
      integer, intent(in) :: s               !< the end
      integer :: c, col, row, lo, hi, j, jr
      associate (blk => jn%ah%blocks(jn%s_line(s)))
         lo = blk%lo
         hi = blk%hi
         do c = 1, 3
            col = sup%first(jn%s_node(s)) + c - 1
            j = jn%s_j0(s) + c
            do row = max(lo, col - bm%kl), min(hi, col + bm%kl)
               jr = end_unknown(jn, sup, s, row)
               if (jr > 0) then              ! an end on a point: C
                  jn%ah%c(jr, j) = jn%ah%c(jr, j) + band_entry(bm, row, col)
               else
                  blk%e(row - lo + 1, jn%s_col(s) + c) = band_entry(bm, row, col)
                  blk%f(jn%s_col(s) + c, row - lo + 1) = band_entry(bm, col, row)
               end if
            end do
         end do
      end associate
   end subroutine end_couplings

   !> The junction unknown of band dof `row` when it is a translation of an end on a
   !> point of the same line as end s, else 0.
   pure integer function end_unknown(jn, sup, s, row) result(j)
      type(junctions_t), intent(in) :: jn !< junctions
      type(supports_t), intent(in) :: sup !< dof map
      integer, intent(in) :: s            !< an end
      integer, intent(in) :: row          !< band dof
      integer :: k, t
      j = 0
      do t = max(1, s - 1), min(jn%ns, s + 1)     ! a line's two ends are neighbours
         if (jn%s_line(t) /= jn%s_line(s)) cycle
         k = row - sup%first(jn%s_node(t)) + 1
         if (k < 1 .or. k > 3) cycle
         j = jn%s_j0(t) + k
         return
      end do
   end function end_unknown

   !> A(i, j) of a band matrix (0 outside the band).
   pure real(wp) function band_entry(bm, i, j)
      type(banded_t), intent(in) :: bm !< matrix
      integer, intent(in) :: i, j      !< row, column
      band_entry = 0.0_wp
      if (i - j > bm%kl .or. j - i > bm%ku) return
      band_entry = bm%ab(bm%kv + i - j, j)
   end function band_entry

   !> Factorise the band and the condensed junction system (eq. (133)).
   subroutine junctions_factor(jn, bm, err)
      type(junctions_t), intent(inout) :: jn !< junctions
      type(banded_t), intent(inout) :: bm    !< tangent, replaced by its factors
      type(error_t), intent(inout) :: err    !< status
      call arrowhead_factor(jn%ah, bm, err)
   end subroutine junctions_factor

   !> Solve K du = b in place (b = du on entry), with the factors of junctions_factor;
   !> the ends take their points' correction (eq. (134)).
   subroutine junctions_solve(jn, sup, bm, du, err)
      type(junctions_t), intent(inout) :: jn !< junctions (scratch y)
      type(supports_t), intent(in) :: sup    !< dof map
      type(banded_t), intent(inout) :: bm    !< factors (and their scratch)
      real(wp), intent(inout) :: du(:)       !< right-hand side, then the solution
      type(error_t), intent(inout) :: err    !< status
      integer :: s, c, k
      jn%y = du(jn%jdof)
      call arrowhead_solve(jn%ah, bm, du, jn%y, err)
      if (has_error(err)) return
      du(jn%jdof) = jn%y
      do s = 1, jn%ns
         k = sup%first(jn%s_node(s)) - 1
         do c = 1, 3
            du(k + c) = du(jn%jdof(jn%s_j0(s) + c))
         end do
      end do
   end subroutine junctions_solve

   !> The stiffness of the system at its FREE points, the lines in equilibrium: the Schur
   !> complement K = C - sum_i F_i A_i^-1 E_i of (133) before its LU, from a condensed
   !> tangent (junctions_condense with want_k; the band is factorised here). K_jk is the
   !> change of the residual of junction unknown j with a unit move of unknown k, minus
   !> the change of the force of the lines on the points (docs/systems.md).
   subroutine junctions_stiffness(jn, bm, k, err)
      type(junctions_t), intent(inout) :: jn !< junctions with a condensed tangent
      type(banded_t), intent(inout) :: bm    !< tangent, replaced by its factors
      real(wp), intent(out) :: k(:, :)       !< (nj, nj) stiffness [N/m]
      type(error_t), intent(inout) :: err    !< status
      integer :: i, a, c, r
      call arrowhead_factor(jn%ah, bm, err)
      if (has_error(err)) return
      k = jn%ah%c
      do i = 1, size(jn%ah%blocks)
         associate (b => jn%ah%blocks(i))
            do c = 1, size(b%junctions)
               do a = 1, size(b%junctions)
                  do r = 1, size(b%w, 1)
                     k(b%junctions(a), b%junctions(c)) = k(b%junctions(a), b%junctions(c)) &
                                                         - b%f(a, r)*b%w(r, c)
                  end do
               end do
            end do
         end associate
      end do
   end subroutine junctions_stiffness
end module rodyn_junctions
