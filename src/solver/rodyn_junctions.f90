!> The junctions of a mooring system in the Newton step: the FREE points' and FREE
!> bodies' unknowns and the line ends on them (docs/theory.md section 17, eqs.
!> (131)-(136)).
!>
!> A line end e on a FREE point p is pinned to it, x_e = x_p; on a FREE body b at the
!> body-axes offset r from its node (its centre of gravity G, directors d_i), x_e = x_b +
!> a, a = sum_i r_i d_i. A virtual move of the end is T q_m of its master's (point or
!> body) unknowns: T = I for a point, T = [I, -skew(a)] for a body (135). A rod's end
!> clamped to a body (CONNECTION=CLAMPED) also turns with it, its directors d_e = D R_e
!> (R_e their body-axes components at the start): its rotation unknowns are eliminated
!> too, T = [I, -skew(a); 0, I], and its moment goes to the body's rotation rows.
!> The global band (rodyn_banded) is assembled as for separate lines, every node with
!> its own unknowns, a master's node (no element) with its own loads and inertia only.
!> Then the ends' translations (and a clamped end's rotations) are eliminated, with T_f =
!> T at the scheme's force point
!> (a_f of its directors; a at t_n+1 for the kinematics):
!>
!>   r_m <- r_m + sum_e T_f^T r_e,   r_e <- 0                                     (131)
!>   K_mm' <- K_mm' + sum T_f^T K_ee' T,  K_im <- K_ie T,  K_mi <- T_f^T K_ei        (132)
!>   K_rot,rot <- + w (a r_e^T - (a . r_e) I)   (a body: the turning end force)   (136)
!>
!> The lines no longer couple to one another through the band, which keeps each line's
!> unknowns (the ends' and the masters' rows become identity rows); K_im, K_mi and K_mm
!> are the arrowhead's E, F and C (rodyn_arrowhead), solved by condensing each line
!> onto the masters it touches (133)-(134). After a correction the ends are placed on
!> their masters exactly (junctions_place).
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
   use rodyn_rotation, only: skew
   implicit none
   private
   public :: junctions_t, junctions_build, junctions_condense, junctions_factor, &
             junctions_solve, junctions_stiffness, junctions_place, junctions_release, &
             junctions_clamp

   !> The junction unknowns, the ends on them and the arrowhead matrix.
   type :: junctions_t
      integer :: nj = 0                      !< junction unknowns: 3 a FREE point, 6 a body
      integer, allocatable :: jdof(:)        !< (nj) the band's dof of each
      logical, allocatable :: held(:)        !< (nj) held (a FIXED body's)
      real(wp), allocatable :: rhs_held(:)   !< (nj) scratch: their right-hand side
      !> held masters free (the system's stiffness, junctions_stiffness; default held)
      logical :: free_all = .false.
      integer :: nm = 0                      !< masters (FREE points, then FREE bodies)
      integer, allocatable :: m_node(:)      !< (nm) node of each
      integer, allocatable :: m_j0(:)        !< (nm) its first junction unknown - 1
      integer, allocatable :: m_n(:)         !< (nm) its unknowns, 3 or 6
      integer :: ns = 0                      !< line ends on masters
      integer, allocatable :: s_node(:)      !< (ns) node of each end
      integer, allocatable :: s_m(:)         !< (ns) its master
      integer, allocatable :: s_line(:)      !< (ns) its line (the arrowhead block)
      integer, allocatable :: s_col(:)       !< (ns) its master's first column - 1 in E_line
      real(wp), allocatable :: s_r(:, :)     !< (3, ns) its offset, body axes from G [m]
      logical, allocatable :: s_on(:)        !< (ns) still on its master (not released)
      integer, allocatable :: s_ne(:)        !< (ns) its unknowns eliminated: 3, 6 clamped
      real(wp), allocatable :: s_rd(:, :, :) !< (3, 3, ns) a clamped end's R_e (junctions_clamp)
      real(wp), allocatable :: tk(:, :, :)   !< (6, 6, ns) T of the kinematics (scratch)
      real(wp), allocatable :: tf(:, :, :)   !< (6, 6, ns) T at the force point (scratch)
      type(arrowhead_t) :: ah                !< E, F, C and the factors
      real(wp), allocatable :: y(:)          !< (nj) scratch
   end type junctions_t

contains

   !> The junctions of a mesh (none without FREE points or bodies: nj = 0, and nothing
   !> else is done by the routines below).
   subroutine junctions_build(mesh, sup, jn)
      type(mesh_t), intent(in) :: mesh       !< mesh with its point and body nodes
      type(supports_t), intent(in) :: sup    !< dof map
      type(junctions_t), intent(out) :: jn   !< junctions
      integer :: k, l, c, n, m, nc
      integer, allocatable :: m_of(:)        ! (nn) master of a node, 0: none
      integer :: cols(12)
      jn%nm = count(mesh%point_node > 0) + count(mesh%body_node > 0)
      allocate (jn%m_node(jn%nm), jn%m_j0(jn%nm), jn%m_n(jn%nm), m_of(mesh%n_nodes))
      jn%m_node = [pack(mesh%point_node, mesh%point_node > 0), &
                   pack(mesh%body_node, mesh%body_node > 0)]
      m_of = 0
      jn%nj = 0
      do m = 1, jn%nm
         m_of(jn%m_node(m)) = m
         jn%m_j0(m) = jn%nj
         jn%m_n(m) = sup%ndof(jn%m_node(m))
         jn%nj = jn%nj + jn%m_n(m)
      end do
      allocate (jn%jdof(jn%nj), jn%y(jn%nj), jn%held(jn%nj), jn%rhs_held(jn%nj))
      do m = 1, jn%nm
         jn%jdof(jn%m_j0(m) + 1:jn%m_j0(m) + jn%m_n(m)) = &
            [(sup%first(jn%m_node(m)) + c - 1, c=1, jn%m_n(m))]
         jn%held(jn%m_j0(m) + 1:jn%m_j0(m) + jn%m_n(m)) = sup%held(1:jn%m_n(m), jn%m_node(m))
      end do
      jn%ns = count(mesh%end_point_node > 0)
      allocate (jn%s_node(jn%ns), jn%s_m(jn%ns), jn%s_line(jn%ns), jn%s_col(jn%ns), &
                jn%s_r(3, jn%ns), jn%tk(6, 6, jn%ns), jn%tf(6, 6, jn%ns), jn%s_on(jn%ns), &
                jn%s_ne(jn%ns), jn%s_rd(3, 3, jn%ns))
      jn%s_on = .true.
      jn%s_ne = 3
      jn%s_rd = 0.0_wp
      if (jn%nj == 0) return
      call arrowhead_init(jn%ah, mesh%n_lines, jn%nj)
      k = 0
      do l = 1, mesh%n_lines
         nc = 0
         do c = 1, 2
            n = mesh%end_point_node(c, l)
            if (n == 0) cycle
            k = k + 1
            m = m_of(n)
            jn%s_node(k) = mesh_node(mesh, l, merge(end_a, end_b, c == 1))
            jn%s_m(k) = m
            jn%s_line(k) = l
            jn%s_col(k) = nc
            jn%s_r(:, k) = mesh%end_offset(:, c, l)
            if (mesh%end_clamped(c, l) .and. jn%m_n(m) == 6 .and. &
                sup%ndof(jn%s_node(k)) == 6) jn%s_ne(k) = 6
            cols(nc + 1:nc + jn%m_n(m)) = [(jn%m_j0(m) + n, n=1, jn%m_n(m))]
            nc = nc + jn%m_n(m)
         end do
         n = mesh_node(mesh, l, end_b)
         call arrowhead_block_init(jn%ah, l, sup%first(mesh_node(mesh, l, end_a)), &
                                   sup%first(n) + sup%ndof(n) - 1, cols(1:nc))
      end do
   end subroutine junctions_build

   !> T of each end (135), of the kinematics (directors d1) and at the force point
   !> ((1 - w) d0 + w d1).
   pure subroutine transfer_matrices(jn, d0, d1, w)
      type(junctions_t), intent(inout) :: jn !< junctions: tk, tf set
      real(wp), intent(in) :: d0(:, :, :)    !< (3, 3, nn) directors at t_n
      real(wp), intent(in) :: d1(:, :, :)    !< (3, 3, nn) directors now
      real(wp), intent(in) :: w              !< weight of d1 at the force point
      real(wp) :: a1(3), af(3)
      integer :: s, c, n
      do s = 1, jn%ns
         jn%tk(:, :, s) = 0.0_wp
         do c = 1, 6
            jn%tk(c, c, s) = 1.0_wp
         end do
         jn%tf(:, :, s) = jn%tk(:, :, s)
         if (jn%m_n(jn%s_m(s)) == 3) cycle
         n = jn%m_node(jn%s_m(s))
         a1 = matmul(d1(:, :, n), jn%s_r(:, s))
         af = (1.0_wp - w)*matmul(d0(:, :, n), jn%s_r(:, s)) + w*a1
         jn%tk(1:3, 4:6, s) = -skew(a1)
         jn%tf(1:3, 4:6, s) = -skew(af)
      end do
   end subroutine transfer_matrices

   !> Eliminate the ends' translations (eqs. (131), (132), (136)): the right-hand side
   !> always, the tangent when it was formed (want_k; after apply_supports). d0, d1 and
   !> w as for transfer_matrices (statics: d0 = d1, w = 1). A held master unknown (a
   !> FIXED body's) keeps apply_supports' row: C's row and column, E's column and F's row
   !> of it are those of the identity; with jn%free_all (the stiffness of the system,
   !> junctions_stiffness) it is free like the others (with no load of its own).
   subroutine junctions_condense(jn, sup, rhs, bm, want_k, d0, d1, w)
      type(junctions_t), intent(inout) :: jn !< junctions: E, F, C set when want_k
      type(supports_t), intent(in) :: sup    !< dof map
      real(wp), intent(inout) :: rhs(:)      !< (n_dof) right-hand side
      type(banded_t), intent(inout) :: bm    !< tangent (its rows of ends and masters cleared)
      logical, intent(in) :: want_k          !< the tangent was formed
      real(wp), intent(in) :: d0(:, :, :)    !< (3, 3, nn) directors at t_n
      real(wp), intent(in) :: d1(:, :, :)    !< (3, 3, nn) directors now
      real(wp), intent(in) :: w              !< weight of d1 at the force point
      real(wp) :: re(6), a1(3)
      integer :: s, c, k, j0, nm, ne
      logical :: hold
      if (jn%nj == 0) return
      hold = .not. jn%free_all
      call transfer_matrices(jn, d0, d1, w)
      jn%rhs_held = rhs(jn%jdof)
      if (want_k) then
         call arrowhead_zero(jn%ah)
         call master_blocks(jn, bm, hold)
         do s = 1, jn%ns
            if (jn%s_on(s)) call end_couplings(jn, sup, bm, s)
         end do
      end if
      do s = 1, jn%ns
         if (.not. jn%s_on(s)) cycle
         k = sup%first(jn%s_node(s)) - 1
         j0 = jn%m_j0(jn%s_m(s))
         nm = jn%m_n(jn%s_m(s))
         ne = jn%s_ne(s)
         re(1:ne) = rhs(k + 1:k + ne)
         do c = 1, nm
            rhs(jn%jdof(j0 + c)) = rhs(jn%jdof(j0 + c)) + &
                                   dot_product(jn%tf(1:ne, c, s), re(1:ne))
         end do
         rhs(k + 1:k + ne) = 0.0_wp
         if (.not. want_k) cycle
         do c = 1, ne
            call banded_fix_dof(bm, k + c)
         end do
         if (nm == 3) cycle
         ! (136): the end's force turning with the body
         a1 = matmul(d1(:, :, jn%m_node(jn%s_m(s))), jn%s_r(:, s))
         do c = 1, 3
            jn%ah%c(j0 + 4:j0 + 6, j0 + 3 + c) = jn%ah%c(j0 + 4:j0 + 6, j0 + 3 + c) &
                                                 + w*a1*re(c)
            jn%ah%c(j0 + 3 + c, j0 + 3 + c) = jn%ah%c(j0 + 3 + c, j0 + 3 + c) &
                                              - w*dot_product(a1, re(1:3))
         end do
      end do
      if (hold) then
         where (jn%held) rhs(jn%jdof) = jn%rhs_held
      end if
      if (.not. want_k) return
      do k = 1, jn%nj
         call banded_fix_dof(bm, jn%jdof(k))
      end do
      if (hold .and. any(jn%held)) call hold_masters(jn)
   end subroutine junctions_condense

   !> The held master unknowns decoupled: identity rows and columns of C, no E column
   !> and F row.
   subroutine hold_masters(jn)
      type(junctions_t), intent(inout) :: jn !< junctions
      integer :: j, i, c
      do j = 1, jn%nj
         if (.not. jn%held(j)) cycle
         jn%ah%c(j, :) = 0.0_wp
         jn%ah%c(:, j) = 0.0_wp
         jn%ah%c(j, j) = 1.0_wp
      end do
      do i = 1, size(jn%ah%blocks)
         associate (b => jn%ah%blocks(i))
            do c = 1, size(b%junctions)
               if (.not. jn%held(b%junctions(c))) cycle
               b%e(:, c) = 0.0_wp
               b%f(c, :) = 0.0_wp
            end do
         end associate
      end do
   end subroutine hold_masters

   !> C = the masters' own blocks (their loads and inertia) of the band; a held
   !> master's (a FIXED body: no load of its own) zero when it is not held (hold false).
   subroutine master_blocks(jn, bm, hold)
      type(junctions_t), intent(inout) :: jn !< junctions
      type(banded_t), intent(in) :: bm       !< tangent
      logical, intent(in) :: hold            !< held masters held
      integer :: m, j0, a, b
      do m = 1, jn%nm
         j0 = jn%m_j0(m)
         do b = 1, jn%m_n(m)
            do a = 1, jn%m_n(m)
               jn%ah%c(j0 + a, j0 + b) = band_entry(bm, jn%jdof(j0 + a), jn%jdof(j0 + b))
               if (.not. hold .and. jn%held(j0 + a)) jn%ah%c(j0 + a, j0 + b) = 0.0_wp
            end do
         end do
      end do
   end subroutine master_blocks

   !> The couplings of end s's translations with its line (E, F of the line's block) and
   !> with the ends of that line on masters (C), read from the band (eq. (132)).
   subroutine end_couplings(jn, sup, bm, s)
      type(junctions_t), intent(inout) :: jn !< junctions
      type(supports_t), intent(in) :: sup    !< dof map
      type(banded_t), intent(in) :: bm       !< tangent
      integer, intent(in) :: s               !< the end
      integer :: c, col, row, lo, hi, t, cr, nm, nt, j0, jt, a, b
      real(wp) :: kv, kh
      nm = jn%m_n(jn%s_m(s))
      j0 = jn%m_j0(jn%s_m(s))
      associate (blk => jn%ah%blocks(jn%s_line(s)))
         lo = blk%lo
         hi = blk%hi
         do c = 1, jn%s_ne(s)
            col = sup%first(jn%s_node(s)) + c - 1
            do row = max(lo, col - bm%kl), min(hi, col + bm%kl)
               kv = band_entry(bm, row, col)      ! K(row, end)
               kh = band_entry(bm, col, row)      ! K(end, row)
               call end_of(jn, sup, s, row, t, cr)
               if (t > 0) then                    ! another end's (or its own) row: C
                  nt = jn%m_n(jn%s_m(t))
                  jt = jn%m_j0(jn%s_m(t))
                  do b = 1, nm
                     do a = 1, nt
                        jn%ah%c(jt + a, j0 + b) = jn%ah%c(jt + a, j0 + b) &
                                                  + jn%tf(cr, a, t)*kv*jn%tk(c, b, s)
                     end do
                  end do
               else
                  do b = 1, nm
                     blk%e(row - lo + 1, jn%s_col(s) + b) = &
                        blk%e(row - lo + 1, jn%s_col(s) + b) + kv*jn%tk(c, b, s)
                     blk%f(jn%s_col(s) + b, row - lo + 1) = &
                        blk%f(jn%s_col(s) + b, row - lo + 1) + jn%tf(c, b, s)*kh
                  end do
               end if
            end do
         end do
      end associate
   end subroutine end_couplings

   !> The end t of the same line as end s whose translation c is band dof `row` (t = 0:
   !> none).
   pure subroutine end_of(jn, sup, s, row, t, c)
      type(junctions_t), intent(in) :: jn !< junctions
      type(supports_t), intent(in) :: sup !< dof map
      integer, intent(in) :: s            !< an end
      integer, intent(in) :: row          !< band dof
      integer, intent(out) :: t           !< the end, or 0
      integer, intent(out) :: c           !< its unknown 1..3 (a clamped end's 1..6)
      do t = max(1, s - 1), min(jn%ns, s + 1)     ! a line's two ends are neighbours
         if (jn%s_line(t) /= jn%s_line(s) .or. .not. jn%s_on(t)) cycle
         c = row - sup%first(jn%s_node(t)) + 1
         if (c >= 1 .and. c <= jn%s_ne(t)) return
      end do
      t = 0
      c = 0
   end subroutine end_of

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
   !> the ends take their masters' correction, T du_m (eq. (134)).
   subroutine junctions_solve(jn, sup, bm, du, err)
      type(junctions_t), intent(inout) :: jn !< junctions (scratch y)
      type(supports_t), intent(in) :: sup    !< dof map
      type(banded_t), intent(inout) :: bm    !< factors (and their scratch)
      real(wp), intent(inout) :: du(:)       !< right-hand side, then the solution
      type(error_t), intent(inout) :: err    !< status
      integer :: s, c, k, j0, nm
      jn%y = du(jn%jdof)
      call arrowhead_solve(jn%ah, bm, du, jn%y, err)
      if (has_error(err)) return
      du(jn%jdof) = jn%y
      do s = 1, jn%ns
         if (.not. jn%s_on(s)) cycle
         k = sup%first(jn%s_node(s)) - 1
         j0 = jn%m_j0(jn%s_m(s))
         nm = jn%m_n(jn%s_m(s))
         do c = 1, jn%s_ne(s)
            du(k + c) = dot_product(jn%tk(c, 1:nm, s), du(jn%jdof(j0 + 1:j0 + nm)))
         end do
      end do
   end subroutine junctions_solve

   !> Place every end on its master exactly: x_e = x_m + sum_i r_i d_i (a body's turn
   !> is not linear in its correction), and a clamped end's directors d_e = D R_e.
   pure subroutine junctions_place(jn, x, d)
      type(junctions_t), intent(in) :: jn   !< junctions
      real(wp), intent(inout) :: x(:, :)    !< (3, nn) positions: the ends' set
      real(wp), intent(inout) :: d(:, :, :) !< (3, 3, nn) directors: clamped ends' set
      integer :: s, n
      do s = 1, jn%ns
         if (.not. jn%s_on(s)) cycle
         n = jn%m_node(jn%s_m(s))
         x(:, jn%s_node(s)) = x(:, n) + d(:, 1, n)*jn%s_r(1, s) + d(:, 2, n)*jn%s_r(2, s) &
                              + d(:, 3, n)*jn%s_r(3, s)
         if (jn%s_ne(s) == 6) d(:, :, jn%s_node(s)) = matmul(d(:, :, n), jn%s_rd(:, :, s))
      end do
   end subroutine junctions_place

   !> A clamped end's directors in its body's axes, R_e = D^T d_e, from the directors d of
   !> the start state (the end keeps that attitude on the body).
   pure subroutine junctions_clamp(jn, d)
      type(junctions_t), intent(inout) :: jn !< junctions (s_rd set)
      real(wp), intent(in) :: d(:, :, :)     !< (3, 3, nn) directors at the start
      integer :: s
      do s = 1, jn%ns
         if (jn%s_ne(s) /= 6) cycle
         jn%s_rd(:, :, s) = matmul(transpose(d(:, :, jn%m_node(jn%s_m(s)))), &
                                   d(:, :, jn%s_node(s)))
      end do
   end subroutine junctions_clamp

   !> The stiffness of the system at its FREE points and bodies (about each body's G),
   !> every other unknown in equilibrium: the Schur
   !> complement K = C - sum_i F_i A_i^-1 E_i of (133) before its LU, from a condensed
   !> tangent (junctions_condense with want_k; the band is factorised here). K_jk is the
   !> change of the residual of junction unknown j with a unit move of unknown k, minus
   !> the change of the force of the lines on the points (docs/systems.md).
   subroutine junctions_stiffness(jn, bm, k, err)
      type(junctions_t), intent(inout) :: jn !< junctions with a condensed tangent
      type(banded_t), intent(inout) :: bm    !< tangent, replaced by its factors
      real(wp), intent(out) :: k(:, :)       !< (nj, nj) stiffness [N/m, N, N m/rad]
      type(error_t), intent(inout) :: err    !< status
      integer :: i, a, c, r
      type(error_t) :: e
      ! (the complement need not be regular: a FIXED body's turn may have no stiffness
      ! from its lines; only the lines' bands must factorise)
      call arrowhead_factor(jn%ah, bm, e)
      if (has_error(e)) then
         if (index(e%message, 'dense_factor') == 0) then
            err = e
            return
         end if
      end if
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

   !> Release the line end at node `node` from its master (a line failure): it is no
   !> longer eliminated; released is false when no end on a master is at that node.
   subroutine junctions_release(jn, node, released)
      type(junctions_t), intent(inout) :: jn !< junctions
      integer, intent(in) :: node            !< the end's node
      logical, intent(out) :: released       !< an end was released
      integer :: s
      released = .false.
      do s = 1, jn%ns
         if (jn%s_node(s) /= node .or. .not. jn%s_on(s)) cycle
         jn%s_on(s) = .false.
         released = .true.
      end do
   end subroutine junctions_release
end module rodyn_junctions
