!> General banded matrix in LAPACK band storage, element assembly, constraint rows, and
!> the LU factorisation/solve of docs/theory.md eq. (45); and the dense LU of small
!> systems (dense_factor, dense_solve). LAPACK's INFO is mapped into error_t here and
!> nowhere else.
!> Storage is allocated once; nothing inside the Newton loop allocates.
!>
!> Two factorisations (bm%pivoting):
!> - with partial pivoting, LAPACK's dgbtrf/dgbtrs (the default);
!> - without pivoting (Doolittle, A = L U with unit lower L, in the same band storage:
!>   no fill above the ku superdiagonals), for the dynamic tangent: n kl ku multiply-adds
!>   instead of dgbtrf's n kl (kl + ku), with contiguous column updates, and a solve of
!>   2 n kl. Rod tangents are symmetric positive definite up to the non-symmetric terms
!>   of the rotations and the scheme (plus the mass in dynamics), for which elimination
!>   without pivoting is stable; should a pivot lose all but 1e-12 of its original
!>   diagonal (cancellation: the matrix needs pivoting), banded_factor reports a
!>   numerical failure and switches the matrix to partial pivoting for good (the caller's
!>   next tangent is factorised by dgbtrf).
!>
!> The envelope (banded_set_reach): within the band a line's matrix is a chain of dense
!> element blocks; the interior unknowns of an element couple only to that element's
!> unknowns. reach(k) is the last unknown that unknown k couples to (k + kl at most),
!> top(k) the first whose reach includes k. Without pivoting there is no fill outside
!> an envelope whose reach does not decrease (Jennings' profile LU, as in skyline
!> solvers), so the column updates and the solves run over reach(k) - k rows and
!> k - top(k) columns instead of kl and ku: on the paper's case 1 (cubic elements,
!> kl = 23) the factorisation does 4269 instead of 6003 multiply-adds an element and
!> a solve 522 instead of 828.
!>
!> Block-diagonal matrices (banded_solve_range): a system's lines concatenated in one
!> band, none coupled to another, give a matrix whose diagonal blocks (a line's rows
!> lo..hi) have no entry outside their own rows and columns. Both factorisations keep
!> that: without pivoting L and U have the zero pattern of A outside the blocks; with
!> partial pivoting dgbtrf chooses each pivot among the rows of the column's own block
!> (the others hold exact zeros), so ipiv(lo:hi) stays in lo..hi, and the fill of U
!> (the kl rows above the superdiagonals) stays in the block too. Each block is then
!> solved alone, with the factors of the whole band; and it can be factorised alone
!> (banded_factor with lo, hi), which gives the same factors.
module rodyn_banded
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, set_error, stat_numerical, stat_input
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: banded_t, banded_init, banded_zero, banded_add, banded_fix_dof
   public :: banded_factor, banded_solve, banded_solve_range, banded_matvec
   public :: banded_keep_column
   public :: banded_kept_axpy, banded_free, banded_set_pivoting, banded_set_reach
   public :: dense_factor, dense_solve, dense_sym_eigen

   !> banded_solve_range(bm, b, lo, hi, err): solve A x = b for the rows lo..hi of a
   !> diagonal block alone (solve_range), b(:) one right-hand side or b(:, :) several.
   interface banded_solve_range
      module procedure solve_range_vector, solve_range_matrix
   end interface banded_solve_range

   !> A square banded matrix with kl sub- and ku super-diagonals: A(i, j) is ab(kv + i - j,
   !> j). Stored for dgbtrf with pivoting (ldab = 2 kl + ku + 1, kv = kl + ku + 1: the
   !> first kl rows are LU fill), compact without (ldab = kl + ku + 1, kv = ku + 1).
   type :: banded_t
      integer :: n = 0                        !< order
      integer :: kl = 0                       !< subdiagonals
      integer :: ku = 0                       !< superdiagonals
      integer :: ldab = 0                     !< leading dimension of ab
      integer :: kv = 0                       !< row of the diagonal in ab
      real(wp), allocatable :: ab(:, :)       !< (ldab, n) band storage
      integer, allocatable :: ipiv(:)         !< (n) pivots of the LU factors
      logical :: factored = .false.           !< ab holds LU factors
      logical :: pivoting = .true.            !< dgbtrf (true) or LU without pivoting
      real(wp), allocatable :: diag(:)        !< (n) diagonal before an unpivoted LU
      integer :: n_kept = 0                   !< columns kept (banded_keep_column)
      integer, allocatable :: kept_dof(:)     !< (n_kept) their dofs
      real(wp), allocatable :: kept(:, :)     !< (kl + ku + 1, n_kept) their band entries
      integer, allocatable :: reach(:)        !< (n) last unknown coupled to unknown k
      integer, allocatable :: top(:)          !< (n) first unknown whose reach includes k
      integer, allocatable :: ipiv_range(:)   !< (n) scratch: pivots of one range, shifted
   end type banded_t

   interface
      subroutine dsygv(itype, jobz, uplo, n, a, lda, b, ldb, w, work, lwork, info)
         import :: wp
         integer, intent(in) :: itype, n, lda, ldb, lwork
         character(len=1), intent(in) :: jobz, uplo
         real(wp), intent(inout) :: a(lda, *), b(ldb, *)
         real(wp), intent(out) :: w(*), work(*)
         integer, intent(out) :: info
      end subroutine dsygv
      subroutine dgbtrf(m, n, kl, ku, ab, ldab, ipiv, info)
         import :: wp
         integer, intent(in) :: m, n, kl, ku, ldab
         real(wp), intent(inout) :: ab(ldab, *)
         integer, intent(out) :: ipiv(*)
         integer, intent(out) :: info
      end subroutine dgbtrf
      subroutine dgetrf(m, n, a, lda, ipiv, info)
         import :: wp
         integer, intent(in) :: m, n, lda
         real(wp), intent(inout) :: a(lda, *)
         integer, intent(out) :: ipiv(*)
         integer, intent(out) :: info
      end subroutine dgetrf
      subroutine dgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: wp
         character(len=1), intent(in) :: trans
         integer, intent(in) :: n, nrhs, lda, ldb
         real(wp), intent(in) :: a(lda, *)
         integer, intent(in) :: ipiv(*)
         real(wp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dgetrs
      subroutine dgbtrs(trans, n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb, info)
         import :: wp
         character(len=1), intent(in) :: trans
         integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb
         real(wp), intent(in) :: ab(ldab, *)
         integer, intent(in) :: ipiv(*)
         real(wp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dgbtrs
   end interface

contains

   !> Allocate an n x n band matrix with kl = ku = half_bandwidth.
   subroutine banded_init(bm, n, half_bandwidth)
      type(banded_t), intent(inout) :: bm   !< matrix
      integer, intent(in) :: n              !< order
      integer, intent(in) :: half_bandwidth !< kl = ku
      integer :: k
      bm%n = n
      bm%kl = min(half_bandwidth, max(n - 1, 0))
      bm%ku = bm%kl
      bm%ldab = bm%kl + bm%ku + 1
      if (bm%pivoting) bm%ldab = bm%ldab + bm%kl
      bm%kv = bm%ldab - bm%kl
      if (allocated(bm%ab)) deallocate (bm%ab, bm%ipiv, bm%diag, bm%ipiv_range)
      allocate (bm%ab(bm%ldab, n), bm%ipiv(n), bm%diag(n), bm%ipiv_range(n))
      if (allocated(bm%kept_dof)) deallocate (bm%kept_dof, bm%kept)
      bm%n_kept = 0
      bm%ab = 0.0_wp
      bm%factored = .false.
      call banded_set_reach(bm, [(min(n, k + bm%kl), k=1, n)])
   end subroutine banded_init

   !> The envelope of the matrix (module header): reach(k) >= k, the last unknown that
   !> unknown k couples to. It is clipped to the band and made non-decreasing, so that
   !> the LU without pivoting has no fill outside it; every entry assembled later must
   !> lie inside it.
   pure subroutine banded_set_reach(bm, reach)
      type(banded_t), intent(inout) :: bm !< matrix
      integer, intent(in) :: reach(:)     !< (n) last unknown coupled to each unknown
      integer :: k, i
      if (allocated(bm%reach)) deallocate (bm%reach, bm%top)
      allocate (bm%reach(bm%n), bm%top(bm%n))
      do k = 1, bm%n
         bm%reach(k) = min(bm%n, k + bm%kl, max(k, reach(k)))
         if (k > 1) bm%reach(k) = max(bm%reach(k), bm%reach(k - 1))
      end do
      i = 1
      do k = 1, bm%n
         do while (bm%reach(i) < k)
            i = i + 1
         end do
         bm%top(k) = max(i, k - bm%ku)
      end do
   end subroutine banded_set_reach

   !> Choose the factorisation (see the module header): the storage is allocated again
   !> for it, zero, when it changes (outside the Newton loop, or once after a failed
   !> pivot); kept columns stay.
   subroutine banded_set_pivoting(bm, pivoting)
      type(banded_t), intent(inout) :: bm !< matrix
      logical, intent(in) :: pivoting     !< partial pivoting (dgbtrf) or none
      integer :: ldab
      ldab = bm%kl + bm%ku + 1
      if (pivoting) ldab = ldab + bm%kl
      bm%pivoting = pivoting
      bm%factored = .false.
      if (ldab == bm%ldab) return
      bm%ldab = ldab
      bm%kv = ldab - bm%kl
      deallocate (bm%ab)
      allocate (bm%ab(bm%ldab, bm%n))
      bm%ab = 0.0_wp
   end subroutine banded_set_pivoting

   !> Release the storage (the matrix is no longer needed).
   subroutine banded_free(bm)
      type(banded_t), intent(inout) :: bm !< matrix
      if (allocated(bm%ab)) deallocate (bm%ab, bm%ipiv, bm%diag, bm%ipiv_range)
      if (allocated(bm%kept_dof)) deallocate (bm%kept_dof, bm%kept)
      if (allocated(bm%reach)) deallocate (bm%reach, bm%top)
      bm%n = 0
      bm%n_kept = 0
      bm%factored = .false.
   end subroutine banded_free

   !> Set all entries to zero.
   subroutine banded_zero(bm)
      type(banded_t), intent(inout) :: bm !< matrix
      bm%ab = 0.0_wp
      bm%factored = .false.
   end subroutine banded_zero

   !> Add an element matrix ke on the global rows/columns dofs (which must fit the band).
   pure subroutine banded_add(bm, dofs, ke)
      type(banded_t), intent(inout) :: bm   !< matrix
      integer, intent(in) :: dofs(:)        !< global dof numbers of the element
      real(wp), intent(in) :: ke(:, :)      !< element matrix (size(dofs) square)
      integer, parameter :: max_runs = 16   ! (fixed size: automatic arrays are heap ones)
      integer :: i, j, r, off, nr, lo(max_runs), hi(max_runs), col, row0
      ! runs of consecutive global dofs (a node's 6 or 3 unknowns) are contiguous in a
      ! band column: each is added as one stretch of the column, in a loop (cheaper than
      ! one entry at a time, and than a section assignment)
      nr = 0
      do i = 1, size(dofs)
         if (nr > 0) then
            if (dofs(i) == dofs(i - 1) + 1) then
               hi(nr) = i
               cycle
            end if
         end if
         if (nr == max_runs) then          ! scattered dofs: one entry at a time
            nr = -1
            exit
         end if
         nr = nr + 1
         lo(nr) = i
         hi(nr) = i
      end do
      if (nr < 0) then
         do j = 1, size(dofs)
            do i = 1, size(dofs)
               bm%ab(bm%kv + dofs(i) - dofs(j), dofs(j)) = &
                  bm%ab(bm%kv + dofs(i) - dofs(j), dofs(j)) + ke(i, j)
            end do
         end do
         return
      end if
      do j = 1, size(dofs)
         col = dofs(j)
         off = bm%kv - col
         do r = 1, nr
            row0 = off + dofs(lo(r)) - lo(r)
            do i = lo(r), hi(r)
               bm%ab(row0 + i, col) = bm%ab(row0 + i, col) + ke(i, j)
            end do
         end do
      end do
   end subroutine banded_add

   !> Replace row and column k by the identity (a held degree of freedom).
   pure subroutine banded_fix_dof(bm, k)
      type(banded_t), intent(inout) :: bm !< matrix
      integer, intent(in) :: k            !< dof to hold
      integer :: i, j, off
      off = bm%kv
      do j = max(1, k - bm%ku), min(bm%n, k + bm%kl)
         bm%ab(off + k - j, j) = 0.0_wp       ! row k
      end do
      do i = max(1, k - bm%ku), min(bm%n, k + bm%kl)
         bm%ab(off + i - k, k) = 0.0_wp       ! column k
      end do
      bm%ab(off, k) = 1.0_wp
   end subroutine banded_fix_dof

   !> Keep a copy of column k (its band) before the column is cleared for a held dof, so
   !> that a prescribed value of that dof can be moved to the right-hand side later, also
   !> while the matrix holds LU factors (a tangent reused over several Newton steps).
   !> The storage grows only when a new dof is kept (the first tangent of a run).
   subroutine banded_keep_column(bm, k)
      type(banded_t), intent(inout) :: bm !< matrix (not factored)
      integer, intent(in) :: k            !< column
      integer, allocatable :: dofs(:)
      real(wp), allocatable :: cols(:, :)
      integer :: slot
      slot = kept_slot(bm, k)
      if (slot == 0) then
         if (.not. allocated(bm%kept_dof)) allocate (bm%kept_dof(0), bm%kept(bm%kl + bm%ku + 1, 0))
         allocate (dofs(bm%n_kept + 1), cols(bm%kl + bm%ku + 1, bm%n_kept + 1))
         dofs(1:bm%n_kept) = bm%kept_dof(1:bm%n_kept)
         cols(:, 1:bm%n_kept) = bm%kept(:, 1:bm%n_kept)
         call move_alloc(dofs, bm%kept_dof)
         call move_alloc(cols, bm%kept)
         bm%n_kept = bm%n_kept + 1
         slot = bm%n_kept
         bm%kept_dof(slot) = k
      end if
      bm%kept(:, slot) = bm%ab(bm%kv - bm%ku:bm%ldab, k)
   end subroutine banded_keep_column

   !> y(i) = y(i) + value * A(i, k) for the rows i /= k in the band of column k, A(:, k)
   !> as kept by banded_keep_column (nothing if it was never kept): moves a prescribed
   !> value of the held dof k to the right-hand side.
   pure subroutine banded_kept_axpy(bm, k, value, y)
      type(banded_t), intent(in) :: bm  !< matrix (factored or not)
      integer, intent(in) :: k          !< column
      real(wp), intent(in) :: value     !< prescribed value of dof k
      real(wp), intent(inout) :: y(:)   !< vector (n)
      integer :: i, slot
      slot = kept_slot(bm, k)
      if (slot == 0) return
      do i = max(1, k - bm%ku), min(bm%n, k + bm%kl)
         if (i /= k) y(i) = y(i) + value*bm%kept(bm%ku + 1 + i - k, slot)
      end do
   end subroutine banded_kept_axpy

   !> Slot of dof k among the kept columns, 0 if not kept.
   pure integer function kept_slot(bm, k)
      type(banded_t), intent(in) :: bm !< matrix
      integer, intent(in) :: k         !< column
      integer :: i
      kept_slot = 0
      do i = 1, bm%n_kept
         if (bm%kept_dof(i) == k) then
            kept_slot = i
            return
         end if
      end do
   end function kept_slot

   !> y = A x (before factorisation; used by tests).
   pure subroutine banded_matvec(bm, x, y)
      type(banded_t), intent(in) :: bm !< matrix (not factored)
      real(wp), intent(in) :: x(:)     !< vector (n)
      real(wp), intent(out) :: y(:)    !< product (n)
      integer :: i, j, off
      off = bm%kv
      y = 0.0_wp
      do j = 1, bm%n
         do i = max(1, j - bm%ku), min(bm%n, j + bm%kl)
            y(i) = y(i) + bm%ab(off + i - j, j)*x(j)
         end do
      end do
   end subroutine banded_matvec

   !> LU-factorise in place (dgbtrf). A zero pivot is a numerical error naming the dof,
   !> and its node and the node's own dof if the first dof of each node is given.
   !> With lo and hi, only the diagonal block of rows lo..hi of a block-diagonal matrix
   !> (module header), as if it were alone: a matrix factorised block by block, each
   !> block's solves done while its factors are in cache (rodyn_arrowhead). The factors
   !> and pivots are those of the whole matrix; bm%factored is set after each block,
   !> and the caller factorises every block before it solves with one.
   subroutine banded_factor(bm, err, first, lo, hi)
      type(banded_t), intent(inout) :: bm       !< matrix, replaced by its LU factors
      type(error_t), intent(inout) :: err       !< status
      integer, intent(in), optional :: first(:) !< (nn) first dof of each node (increasing)
      integer, intent(in), optional :: lo       !< first row of the block (default 1)
      integer, intent(in), optional :: hi       !< last row of the block (default n)
      integer :: info, node, k0, k1, k
      character(len=240) :: msg
      k0 = 1
      k1 = bm%n
      if (present(lo)) k0 = lo
      if (present(hi)) k1 = hi
      if (k0 < 1 .or. k1 > bm%n .or. k1 < k0 - 1) then
         write (msg, '(a,i0,a,i0,a,i0)') 'banded_factor: rows ', k0, '..', k1, &
            ' of a matrix of order ', bm%n
         call set_error(err, stat_input, trim(msg))
         return
      end if
      if (k1 < k0) then                   ! nothing to factorise
         bm%factored = .true.
         return
      end if
      ! an overflowed state, not a mechanism: say so rather than blame the supports (the
      ! diagonal only: n values, against n kl ku operations of the factorisation)
      if (.not. all(ieee_is_finite(bm%ab(bm%kv, k0:k1)))) then
         call set_error(err, stat_numerical, 'banded_factor: the stiffness holds Inf or '// &
                        'NaN: the state diverged (overflow), not a singular tangent')
         return
      end if
      if (.not. bm%pivoting) then
         call factor_unpivoted(bm, info, k0, k1)
         if (info /= 0) then
            call banded_set_pivoting(bm, .true.)
            write (msg, '(a,i0,a)') 'banded_factor: pivot ', info, ' cancelled without '// &
               'pivoting: factorised with partial pivoting from now on'
            call set_error(err, stat_numerical, trim(msg))
            return
         end if
         bm%factored = .true.
         return
      end if
      call dgbtrf(k1 - k0 + 1, k1 - k0 + 1, bm%kl, bm%ku, bm%ab(1, k0), bm%ldab, &
                  bm%ipiv(k0), info)
      do k = k0, k1                       ! the block's pivots as rows of the whole
         bm%ipiv(k) = bm%ipiv(k) + k0 - 1
      end do
      if (info > 0) info = info + k0 - 1
      if (info /= 0) then
         if (present(first)) then
            node = count(first <= abs(info))
            write (msg, '(a,i0,a,i0,a,i0,a)') 'banded_factor: dgbtrf info = ', info, &
               ': singular stiffness at node ', node, ', dof ', abs(info) - first(node) + 1, &
               ' (a mechanism, or a stiffness swamped by a far larger one: check the'// &
               ' supports, and loads or coefficients of absurd size)'
         else
            write (msg, '(a,i0,a,i0,a)') 'banded_factor: dgbtrf info = ', info, &
               ': singular stiffness at dof ', abs(info), ' (a mechanism, or a stiffness'// &
               ' swamped by a far larger one: check the supports, and loads or'// &
               ' coefficients of absurd size)'
         end if
         call set_error(err, stat_numerical, trim(msg))
         return
      end if
      bm%factored = .true.
   end subroutine banded_factor

   !> A = L U without pivoting, in place (no fill outside the envelope), for the rows
   !> lo..hi of a diagonal block (1..n: the whole matrix; the envelope clipped to the
   !> block): for k = lo .. hi, with r = min(reach(k), hi),
   !>   l_ik = a_ik / a_kk (i = k+1 .. r),  a_ij -= l_ik a_kj (j = k+1 .. r).
   !> info = k > 0 when pivot k is zero, not finite or below 1e-12 of its original
   !> diagonal (1e-12 of the column's largest entry if that diagonal was zero).
   pure subroutine factor_unpivoted(bm, info, lo, hi)
      type(banded_t), intent(inout) :: bm !< matrix, replaced by L and U
      integer, intent(out) :: info        !< 0, or the first failed pivot
      integer, intent(in) :: lo           !< first row of the block
      integer, intent(in) :: hi           !< last row of the block
      integer :: k, j, m, kv, i1, last, i
      real(wp) :: piv, akj, ref, rp
      kv = bm%kv
      associate (ab => bm%ab, ku => bm%ku)
         do k = lo, hi
            bm%diag(k) = ab(kv, k)
         end do
         info = 0
         do k = lo, hi
            piv = ab(kv, k)
            ref = abs(bm%diag(k))
            m = min(bm%reach(k), hi) - k  ! rows of column k inside the envelope
            if (ref == 0.0_wp) ref = maxval(abs(ab(kv - min(ku, k - 1):kv + m, k)))
            if (.not. (abs(piv) > 1.0e-12_wp*ref)) then
               info = k
               return
            end if
            bm%ipiv(k) = k
            if (m == 0) cycle
            rp = 1.0_wp/piv
            do i = 1, m
               ab(kv + i, k) = ab(kv + i, k)*rp
            end do
            last = k + m                  ! and columns of row k
            do j = k + 1, last
               i1 = kv + k - j               ! row of a_kj in column j
               akj = ab(i1, j)
               if (akj == 0.0_wp) cycle
               do i = 1, m
                  ab(i1 + i, j) = ab(i1 + i, j) - akj*ab(kv + i, k)
               end do
            end do
         end do
      end associate
   end subroutine factor_unpivoted

   !> Solve L U X = B in place with unpivoted factors, for the rows lo..hi of a diagonal
   !> block (1..n: the whole matrix): forward with unit L by columns, then back with U by
   !> columns (contiguous band columns in both; each band column applied to every right-
   !> hand side while it is in cache). The envelope is clipped to the block, so it need
   !> not know the block boundaries (outside the block L and U hold zeros).
   pure subroutine solve_unpivoted(bm, nrhs, b, lo, hi)
      type(banded_t), intent(in) :: bm  !< factored matrix (factor_unpivoted)
      integer, intent(in) :: nrhs       !< right-hand sides
      integer, intent(in) :: lo         !< first row of the block
      integer, intent(in) :: hi         !< last row of the block
      real(wp), intent(inout) :: b(hi - lo + 1, nrhs) !< rows lo..hi of the right-hand
                                        !< sides, replaced by the solutions
      integer :: k, m, kv, i, o, c
      real(wp) :: bk
      kv = bm%kv
      o = lo - 1                                  ! b(k - o, :) is row k
      associate (ab => bm%ab)
         do k = lo, hi - 1
            m = min(bm%reach(k), hi) - k
            do c = 1, nrhs
               bk = b(k - o, c)
               if (bk == 0.0_wp) cycle
               do i = 1, m
                  b(k - o + i, c) = b(k - o + i, c) - bk*ab(kv + i, k)
               end do
            end do
         end do
         do k = hi, lo, -1
            m = k - max(bm%top(k), lo)
            do c = 1, nrhs
               b(k - o, c) = b(k - o, c)/ab(kv, k)
               bk = b(k - o, c)
               if (bk == 0.0_wp) cycle
               do i = 1, m
                  b(k - o - i, c) = b(k - o - i, c) - bk*ab(kv - i, k)
               end do
            end do
         end do
      end associate
   end subroutine solve_unpivoted

   !> Solve A x = b in place with the LU factors (dgbtrs, or the unpivoted solve).
   subroutine banded_solve(bm, b, err)
      type(banded_t), intent(in) :: bm    !< factored matrix
      real(wp), intent(inout) :: b(:)     !< right-hand side, replaced by the solution
      type(error_t), intent(inout) :: err !< status
      integer :: info
      if (.not. bm%pivoting) then
         call solve_unpivoted(bm, 1, b, 1, bm%n)
         return
      end if
      call dgbtrs('N', bm%n, bm%kl, bm%ku, 1, bm%ab, bm%ldab, bm%ipiv, b, bm%n, info)
      if (info /= 0) call set_error(err, stat_numerical, 'banded_solve: dgbtrs failed')
   end subroutine banded_solve

   !> banded_solve_range for one right-hand side: b (hi - lo + 1) holds the rows lo..hi
   !> (pass b(lo:hi) of a whole vector, or a vector of its own).
   subroutine solve_range_vector(bm, b, lo, hi, err)
      type(banded_t), intent(inout) :: bm !< factored matrix (the scratch is used)
      real(wp), intent(inout) :: b(:)     !< (hi - lo + 1) right-hand side, then solution
      integer, intent(in) :: lo           !< first row of the block
      integer, intent(in) :: hi           !< last row of the block
      type(error_t), intent(inout) :: err !< status
      if (range_ok(bm, size(b), lo, hi, err)) call solve_range(bm, 1, b, lo, hi, err)
   end subroutine solve_range_vector

   !> banded_solve_range for several right-hand sides at once (one sweep over the band):
   !> b (hi - lo + 1, nrhs) holds their rows lo..hi, one column each.
   subroutine solve_range_matrix(bm, b, lo, hi, err)
      type(banded_t), intent(inout) :: bm  !< factored matrix (the scratch is used)
      real(wp), intent(inout) :: b(:, :)   !< (hi - lo + 1, nrhs) right-hand sides, then
                                           !< solutions
      integer, intent(in) :: lo            !< first row of the block
      integer, intent(in) :: hi            !< last row of the block
      type(error_t), intent(inout) :: err  !< status
      if (range_ok(bm, size(b, 1), lo, hi, err)) &
         call solve_range(bm, size(b, 2), b, lo, hi, err)
   end subroutine solve_range_matrix

   !> True when lo..hi are rows of the factorised matrix (an empty range lo = hi + 1
   !> included) and nb = hi - lo + 1; an input error naming banded_solve_range if not.
   logical function range_ok(bm, nb, lo, hi, err)
      type(banded_t), intent(in) :: bm    !< matrix
      integer, intent(in) :: nb           !< rows of the right-hand side given
      integer, intent(in) :: lo           !< first row of the block
      integer, intent(in) :: hi           !< last row of the block
      type(error_t), intent(inout) :: err !< status
      character(len=160) :: msg
      range_ok = .false.
      if (lo < 1 .or. hi > bm%n .or. hi < lo - 1 .or. nb /= hi - lo + 1) then
         write (msg, '(a,i0,a,i0,a,i0,a,i0)') 'banded_solve_range: rows ', lo, '..', hi, &
            ' with ', nb, ' values, of a matrix of order ', bm%n
         call set_error(err, stat_input, trim(msg))
      else if (.not. bm%factored) then
         call set_error(err, stat_input, 'banded_solve_range: the matrix is not factorised')
      else
         range_ok = .true.
      end if
   end function range_ok

   !> Solve A X = B in place for the rows lo..hi alone, with the LU factors of the whole
   !> band, when those rows are a diagonal block of A: no unknown in lo..hi coupled to
   !> one outside (block-diagonal matrices in the module header). Without pivoting the
   !> solve runs over lo..hi (the envelope clipped to them); with pivoting, dgbtrs on
   !> the sub-matrix from column lo, its pivots shifted by lo - 1 into the scratch
   !> bm%ipiv_range (nothing allocates; the scratch makes bm intent(inout), so concurrent
   !> solves need copies of bm). A pivot of rows lo..hi outside them (A not
   !> block-diagonal there) is a numerical error.
   subroutine solve_range(bm, nrhs, b, lo, hi, err)
      type(banded_t), intent(inout) :: bm !< factored matrix
      integer, intent(in) :: nrhs         !< right-hand sides
      integer, intent(in) :: lo           !< first row of the block
      integer, intent(in) :: hi           !< last row of the block
      real(wp), intent(inout) :: b(hi - lo + 1, nrhs) !< their rows lo..hi, then solutions
      type(error_t), intent(inout) :: err !< status
      integer :: info, k, nr
      character(len=160) :: msg
      nr = hi - lo + 1
      if (nr == 0 .or. nrhs == 0) return
      if (.not. bm%pivoting) then
         call solve_unpivoted(bm, nrhs, b, lo, hi)
         return
      end if
      do k = 1, nr
         bm%ipiv_range(k) = bm%ipiv(lo - 1 + k) - (lo - 1)
         if (bm%ipiv_range(k) < 1 .or. bm%ipiv_range(k) > nr) then
            write (msg, '(a,i0,a,i0,a,i0,a,i0,a)') 'banded_solve_range: row ', &
               lo - 1 + k, ' pivoted with row ', bm%ipiv(lo - 1 + k), ', outside rows ', &
               lo, '..', hi, ' (the matrix is not block-diagonal there)'
            call set_error(err, stat_numerical, trim(msg))
            return
         end if
      end do
      call dgbtrs('N', nr, bm%kl, bm%ku, nrhs, bm%ab(1, lo), bm%ldab, bm%ipiv_range, b, &
                  nr, info)
      if (info /= 0) call set_error(err, stat_numerical, 'banded_solve_range: dgbtrs failed')
   end subroutine solve_range

   !> LU-factorise a dense square matrix in place with partial pivoting (dgetrf): the
   !> small junction systems of rodyn_arrowhead. A zero pivot is a numerical error.
   subroutine dense_factor(a, ipiv, err)
      real(wp), intent(inout) :: a(:, :)  !< (n, n) matrix, replaced by its LU factors
      integer, intent(out) :: ipiv(:)     !< (n) pivots
      type(error_t), intent(inout) :: err !< status
      integer :: info
      character(len=80) :: msg
      if (size(a, 1) == 0) return
      call dgetrf(size(a, 1), size(a, 2), a, size(a, 1), ipiv, info)
      if (info /= 0) then
         write (msg, '(a,i0)') 'dense_factor: singular matrix, zero pivot at unknown ', info
         call set_error(err, stat_numerical, trim(msg))
      end if
   end subroutine dense_factor

   !> Solve A X = B in place with the factors of dense_factor (dgetrs).
   subroutine dense_solve(a, ipiv, b, err)
      real(wp), intent(in) :: a(:, :)     !< (n, n) LU factors
      integer, intent(in) :: ipiv(:)      !< (n) pivots
      real(wp), intent(inout) :: b(:, :)  !< (n, nrhs) right-hand sides, then solutions
      type(error_t), intent(inout) :: err !< status
      integer :: info
      if (size(a, 1) == 0) return
      call dgetrs('N', size(a, 1), size(b, 2), a, size(a, 1), ipiv, b, size(b, 1), info)
      if (info /= 0) call set_error(err, stat_numerical, 'dense_solve: dgetrs failed')
   end subroutine dense_solve

   !> The generalized symmetric eigenproblem K v = lambda M v (dsygv; M positive
   !> definite): eigenvalues ascending in lambda, M-normalised eigenvectors in the
   !> columns of k. A failure (M not positive definite) is a numerical error.
   subroutine dense_sym_eigen(k, m, lambda, err)
      real(wp), intent(inout) :: k(:, :)      !< (n, n) K (upper triangle), then the vectors
      real(wp), intent(inout) :: m(:, :)      !< (n, n) M (upper triangle), then overwritten
      real(wp), intent(out) :: lambda(:)      !< (n) eigenvalues
      type(error_t), intent(inout) :: err     !< status
      real(wp), allocatable :: work(:)
      integer :: n, info
      character(len=80) :: msg
      n = size(k, 1)
      if (n == 0) return
      allocate (work(max(1, 8*n)))
      call dsygv(1, 'V', 'U', n, k, n, m, n, lambda, work, size(work), info)
      if (info /= 0) then
         write (msg, '(a,i0)') 'dense_sym_eigen: dsygv info = ', info
         call set_error(err, stat_numerical, trim(msg)//' (the mass matrix is not '// &
                        'positive definite, or the eigenproblem did not converge)')
      end if
   end subroutine dense_sym_eigen
end module rodyn_banded
