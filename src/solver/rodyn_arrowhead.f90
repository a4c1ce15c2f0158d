!> Linear systems of lines coupled through a few shared unknowns (the tangent of a
!> mooring system: all lines' unknowns concatenated in one band, no line coupled to
!> another, joined only through the junction unknowns of the points and bodies they
!> attach to): an arrowhead matrix
!>
!>   [ A_1              E_1 ] [ x_1 ]   [ f_1 ]
!>   [       ...        ... ] [ ... ] = [ ... ]
!>   [            A_m   E_m ] [ x_m ]   [ f_m ]
!>   [ F_1  ...   F_m   C   ] [  y  ]   [  g  ]
!>
!> where A = diag(A_1, ..., A_m) is the one shared band (rodyn_banded, order n) and
!> A_i its diagonal block of rows lo_i..hi_i (n_i = hi_i - lo_i + 1 of them); E_i
!> (n_i x k_i) and F_i (k_i x n_i) are dense over the k_i junction unknowns that block i
!> couples to (its `junctions`, indices into y), C dense (n_j x n_j). Solved by
!> condensing each block onto the junctions (Schur complement):
!>
!>   S = C - sum_i P_i F_i W_i P_i^T,              W_i = A_i^{-1} E_i,
!>   S y = g - sum_i P_i F_i A_i^{-1} f_i,         x_i = A_i^{-1} f_i - W_i P_i^T y,
!>
!> P_i scattering block i's junction rows into y. Because no unknown of a block couples
!> to one outside it, A is factorised block by block (banded_factor on a block's rows:
!> the factors of the whole band, W_i computed right after while they are in cache)
!> and each A_i^{-1} is a solve of the block's rows alone (banded_solve_range).
!>
!> Rows of the band in no block (held unknowns between the lines: identity rows) are
!> solved in the same way, each maximal run of them as a block without junctions:
!> every block and every such run must be a diagonal block of A. Blocks are numbered
!> in increasing row order and do not overlap (arrowhead_factor checks both).
!>
!> Cost: the band's factorisation and a range solve of k_i right-hand sides per block
!> (k_i is 3 to 12 for a line with two ends on points or bodies), one dense LU of
!> order n_j, and per solve one range solve per block: linear in the total length of
!> the lines for a fixed number of junctions. Storage is allocated by arrowhead_init
!> and arrowhead_block_init; arrowhead_zero, arrowhead_factor and arrowhead_solve
!> allocate nothing.
module rodyn_arrowhead
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, set_error, has_error, stat_input
   use rodyn_banded, only: banded_t, banded_factor, banded_solve_range, banded_matvec, &
                           dense_factor, dense_solve
   implicit none
   private
   public :: arrow_block_t, arrowhead_t, arrowhead_init, arrowhead_block_init
   public :: arrowhead_zero, arrowhead_factor, arrowhead_solve, arrowhead_matvec

   !> One block: its rows in the band, its couplings to the junctions and W = A_i^-1 E_i.
   type :: arrow_block_t
      integer :: lo = 1                      !< first row of the block in the band
      integer :: hi = 0                      !< last row (n_i = hi - lo + 1)
      integer, allocatable :: junctions(:)   !< (k) junction unknowns it couples to
      real(wp), allocatable :: e(:, :)       !< (n_i, k) columns of those junctions
      real(wp), allocatable :: f(:, :)       !< (k, n_i) their rows over the block
      real(wp), allocatable :: w(:, :)       !< (n_i, k) A_i^-1 E_i (arrowhead_factor)
   end type arrow_block_t

   !> The couplings of the blocks of a shared band, the junction block and the factors.
   type :: arrowhead_t
      integer :: nj = 0                             !< junction unknowns
      type(arrow_block_t), allocatable :: blocks(:) !< (m), in increasing row order
      real(wp), allocatable :: c(:, :)              !< (nj, nj) junction block
      real(wp), allocatable :: s(:, :)              !< (nj, nj) Schur complement, LU
      integer, allocatable :: ipiv(:)               !< (nj) its pivots
      real(wp), allocatable :: rhs(:, :)            !< (nj, 1) scratch of the dense solve
      logical :: factored = .false.                 !< s, w and the band factorised
   end type arrowhead_t

contains

   !> m blocks (set each with arrowhead_block_init) and nj junction unknowns; C = 0.
   subroutine arrowhead_init(ah, m, nj)
      type(arrowhead_t), intent(inout) :: ah !< matrix
      integer, intent(in) :: m               !< blocks
      integer, intent(in) :: nj              !< junction unknowns
      if (allocated(ah%blocks)) deallocate (ah%blocks, ah%c, ah%s, ah%ipiv, ah%rhs)
      allocate (ah%blocks(m), ah%c(nj, nj), ah%s(nj, nj), ah%ipiv(nj), ah%rhs(nj, 1))
      ah%nj = nj
      ah%c = 0.0_wp
      ah%factored = .false.
   end subroutine arrowhead_init

   !> Block i: the rows lo..hi of the band, coupled to the junction unknowns junctions
   !> (any order; none for a block coupled to no junction); E_i = 0, F_i = 0.
   subroutine arrowhead_block_init(ah, i, lo, hi, junctions)
      type(arrowhead_t), intent(inout) :: ah  !< matrix
      integer, intent(in) :: i                !< block
      integer, intent(in) :: lo               !< its first row in the band
      integer, intent(in) :: hi               !< its last row
      integer, intent(in) :: junctions(:)     !< (k) junction unknowns it couples to
      integer :: k, n
      k = size(junctions)
      n = max(hi - lo + 1, 0)
      associate (b => ah%blocks(i))
         if (allocated(b%e)) deallocate (b%junctions, b%e, b%f, b%w)
         b%lo = lo
         b%hi = hi
         allocate (b%junctions(k), b%e(n, k), b%f(k, n), b%w(n, k))
         b%junctions(:) = junctions
         b%e = 0.0_wp
         b%f = 0.0_wp
         b%w = 0.0_wp
      end associate
      ah%factored = .false.
   end subroutine arrowhead_block_init

   !> E_i, F_i and C to zero before an assembly (the band is zeroed by banded_zero).
   subroutine arrowhead_zero(ah)
      type(arrowhead_t), intent(inout) :: ah !< matrix
      integer :: i
      do i = 1, size(ah%blocks)
         ah%blocks(i)%e(:, :) = 0.0_wp
         ah%blocks(i)%f(:, :) = 0.0_wp
      end do
      ah%c(:, :) = 0.0_wp
      ah%factored = .false.
   end subroutine arrowhead_zero

   !> The blocks lie in the band in increasing row order without overlap, and their
   !> junctions in 1..nj: an input error naming the block otherwise.
   subroutine check_layout(ah, bm, err)
      type(arrowhead_t), intent(in) :: ah  !< matrix
      type(banded_t), intent(in) :: bm     !< the shared band
      type(error_t), intent(inout) :: err  !< status
      integer :: i, last
      character(len=160) :: msg
      last = 0
      do i = 1, size(ah%blocks)
         associate (b => ah%blocks(i))
            if (.not. allocated(b%junctions)) then
               write (msg, '(a,i0,a)') 'arrowhead_factor: block ', i, ' was never set'
            else if (b%lo <= last .or. b%hi < b%lo .or. b%hi > bm%n) then
               write (msg, '(a,i0,a,i0,a,i0,a,i0,a,i0)') 'arrowhead_factor: block ', i, &
                  ' at rows ', b%lo, '..', b%hi, ' after row ', last, &
                  ' of a band of order ', bm%n
            else if (any(b%junctions < 1 .or. b%junctions > ah%nj)) then
               write (msg, '(a,i0,a,i0)') 'arrowhead_factor: block ', i, &
                  ' coupled to a junction outside 1..', ah%nj
            else
               last = b%hi
               cycle
            end if
         end associate
         call set_error(err, stat_input, trim(msg))
         return
      end do
   end subroutine check_layout

   !> Factorise (module header): the band bm, assembled but not yet factorised, by
   !> banded_factor block by block (each run of rows in no block too), each block's
   !> W_i = A_i^-1 E_i by one range solve of its k_i columns right after its LU, while
   !> that is in cache; then S = C - sum_i P_i F_i W_i P_i^T and its dense LU. A failure
   !> of the band's LU is banded_factor's (without pivoting it switches bm to pivoting:
   !> the caller assembles it again).
   subroutine arrowhead_factor(ah, bm, err)
      type(arrowhead_t), intent(inout) :: ah !< matrix, then its factors
      type(banded_t), intent(inout) :: bm    !< the shared band, then its LU factors
      type(error_t), intent(inout) :: err    !< status
      integer :: i, a, c, r, ja, jc, last
      real(wp) :: t
      if (has_error(err)) return
      ah%factored = .false.
      call check_layout(ah, bm, err)
      if (has_error(err)) return
      ah%s(:, :) = ah%c
      last = 0
      do i = 1, size(ah%blocks)
         associate (b => ah%blocks(i))
            call banded_factor(bm, err, lo=last + 1, hi=b%lo - 1)
            call banded_factor(bm, err, lo=b%lo, hi=b%hi)
            if (has_error(err)) return
            last = b%hi
            b%w(:, :) = b%e
            call banded_solve_range(bm, b%w, b%lo, b%hi, err)
            if (has_error(err)) return
            do r = 1, size(b%w, 1)          ! S -= F W by F's columns (its nonzero ones:
               if (.not. any(b%f(:, r) /= 0.0_wp)) cycle    ! a line's end rows)
               do c = 1, size(b%junctions)
                  jc = b%junctions(c)
                  t = b%w(r, c)
                  do a = 1, size(b%junctions)
                     ja = b%junctions(a)
                     ah%s(ja, jc) = ah%s(ja, jc) - b%f(a, r)*t
                  end do
               end do
            end do
         end associate
      end do
      call banded_factor(bm, err, lo=last + 1, hi=bm%n)
      if (has_error(err)) return
      call dense_factor(ah%s, ah%ipiv, err)
      ah%factored = .not. has_error(err)
   end subroutine arrowhead_factor

   !> Solve in place (module header): x holds f (the band's rows) and y holds g; they
   !> are replaced by the solution. Each block by a range solve, each run of rows in no
   !> block too (as banded_solve would), then the junctions, then the blocks' correction.
   subroutine arrowhead_solve(ah, bm, x, y, err)
      type(arrowhead_t), intent(inout) :: ah !< factorised matrix (its scratch is used)
      type(banded_t), intent(inout) :: bm    !< the shared band's LU factors
      real(wp), intent(inout) :: x(:)        !< (bm%n) band right-hand side, then solution
      real(wp), intent(inout) :: y(:)        !< (nj) junction right-hand side, then solution
      type(error_t), intent(inout) :: err    !< status
      integer :: i, a, c, r, last, o
      real(wp) :: t
      if (has_error(err)) return
      if (.not. ah%factored .or. size(x) /= bm%n .or. size(y) /= ah%nj) then
         call set_error(err, stat_input, 'arrowhead_solve: not factorised, or x and y '// &
                        'not of the band''s order and the junctions''')
         return
      end if
      last = 0
      do i = 1, size(ah%blocks)
         associate (b => ah%blocks(i))
            call banded_solve_range(bm, x(last + 1:b%lo - 1), last + 1, b%lo - 1, err)
            call banded_solve_range(bm, x(b%lo:b%hi), b%lo, b%hi, err)
            o = b%lo - 1
            do r = 1, size(b%f, 2)           ! y -= F x by F's columns
               t = x(o + r)
               do a = 1, size(b%junctions)
                  y(b%junctions(a)) = y(b%junctions(a)) - b%f(a, r)*t
               end do
            end do
            last = b%hi
         end associate
      end do
      call banded_solve_range(bm, x(last + 1:bm%n), last + 1, bm%n, err)
      if (has_error(err)) return
      ah%rhs(:, 1) = y
      call dense_solve(ah%s, ah%ipiv, ah%rhs, err)
      y(:) = ah%rhs(:, 1)
      do i = 1, size(ah%blocks)
         associate (b => ah%blocks(i))
            o = b%lo - 1
            do c = 1, size(b%junctions)
               t = y(b%junctions(c))
               do r = 1, size(b%w, 1)
                  x(o + r) = x(o + r) - b%w(r, c)*t
               end do
            end do
         end associate
      end do
   end subroutine arrowhead_solve

   !> The product of the matrix before arrowhead_factor (band not factorised) with
   !> (x, y): rx = A x, plus E_i P_i^T y on block i's rows; ry = C y + sum_i P_i F_i x_i.
   subroutine arrowhead_matvec(ah, bm, x, y, rx, ry)
      type(arrowhead_t), intent(in) :: ah  !< matrix
      type(banded_t), intent(in) :: bm     !< the shared band (not factorised)
      real(wp), intent(in) :: x(:)         !< (bm%n) band part of the vector
      real(wp), intent(in) :: y(:)         !< (nj) junction part
      real(wp), intent(out) :: rx(:)       !< (bm%n) band part of the product
      real(wp), intent(out) :: ry(:)       !< (nj) junction part
      integer :: i, a, c, r, o
      call banded_matvec(bm, x, rx)
      ry(:) = 0.0_wp
      do c = 1, ah%nj
         do r = 1, ah%nj
            ry(r) = ry(r) + ah%c(r, c)*y(c)
         end do
      end do
      do i = 1, size(ah%blocks)
         associate (b => ah%blocks(i))
            o = b%lo - 1
            do a = 1, size(b%junctions)
               do r = 1, size(b%e, 1)
                  rx(o + r) = rx(o + r) + b%e(r, a)*y(b%junctions(a))
                  ry(b%junctions(a)) = ry(b%junctions(a)) + b%f(a, r)*x(o + r)
               end do
            end do
         end associate
      end do
   end subroutine arrowhead_matvec
end module rodyn_arrowhead
