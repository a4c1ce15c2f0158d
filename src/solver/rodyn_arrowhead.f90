!> Linear systems of lines coupled through a few shared unknowns (the tangent of a
!> mooring system: each line's unknowns in a band of their own, joined only through the
!> unknowns of the points and bodies they attach to): an arrowhead matrix
!>
!>   [ A_1              E_1 ] [ x_1 ]   [ f_1 ]
!>   [       ...        ... ] [ ... ] = [ ... ]
!>   [            A_m   E_m ] [ x_m ]   [ f_m ]
!>   [ F_1  ...   F_m   C   ] [  y  ]   [  g  ]
!>
!> with A_i banded (rodyn_banded), E_i (n_i x k_i) and F_i (k_i x n_i) dense over the k_i
!> junction unknowns that block i couples to (its `junctions`, indices into y), C dense
!> (n_j x n_j). Solved by condensing each block onto the junctions (Schur complement):
!>
!>   S = C - sum_i P_i F_i A_i^{-1} E_i P_i^T,     W_i = A_i^{-1} E_i,
!>   S y = g - sum_i P_i F_i A_i^{-1} f_i,         x_i = A_i^{-1} f_i - W_i P_i^T y,
!>
!> P_i scattering block i's junction rows into y. Cost: each band's factorisation and
!> k_i band solves (k_i is 3 to 12 for a line with two ends on points or bodies), one
!> dense LU of order n_j, and per solve one band solve per block: linear in the total
!> length of the lines for a fixed number of junctions.
!>
!> Unknowns are numbered block by block, then the junctions: block i at offset(i) + 1 ..
!> offset(i) + n_i, junction j at offset(m + 1) + j.
module rodyn_arrowhead
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_banded, only: banded_t, banded_init, banded_factor, banded_solve, &
                           banded_matvec, dense_factor, dense_solve
   implicit none
   private
   public :: arrow_block_t, arrowhead_t, arrowhead_init, arrowhead_block_init
   public :: arrowhead_factor, arrowhead_solve, arrowhead_matvec, arrowhead_size

   !> One block: its band, its couplings to the junctions and the scratch W = A^-1 E.
   type :: arrow_block_t
      type(banded_t) :: a                    !< the block's own matrix
      integer, allocatable :: junctions(:)   !< (k) junction unknowns it couples to
      real(wp), allocatable :: e(:, :)       !< (n, k) columns of those junctions
      real(wp), allocatable :: f(:, :)       !< (k, n) their rows over the block
      real(wp), allocatable :: w(:, :)       !< (n, k) A^-1 E (arrowhead_factor)
   end type arrow_block_t

   !> The whole matrix, its factors and its numbering.
   type :: arrowhead_t
      integer :: nj = 0                             !< junction unknowns
      type(arrow_block_t), allocatable :: blocks(:) !< (m)
      integer, allocatable :: offset(:)             !< (m + 1) first unknown - 1
      real(wp), allocatable :: c(:, :)              !< (nj, nj) junction block
      real(wp), allocatable :: s(:, :)              !< (nj, nj) Schur complement, LU
      integer, allocatable :: ipiv(:)               !< (nj) its pivots
      logical :: factored = .false.                 !< s, w and the bands factorised
   end type arrowhead_t

contains

   !> m blocks (set each with arrowhead_block_init) and nj junction unknowns; C = 0.
   subroutine arrowhead_init(ah, m, nj)
      type(arrowhead_t), intent(inout) :: ah !< matrix
      integer, intent(in) :: m               !< blocks
      integer, intent(in) :: nj              !< junction unknowns
      if (allocated(ah%blocks)) deallocate (ah%blocks, ah%offset, ah%c, ah%s, ah%ipiv)
      allocate (ah%blocks(m), ah%offset(m + 1), ah%c(nj, nj), ah%s(nj, nj), ah%ipiv(nj))
      ah%nj = nj
      ah%offset = 0
      ah%c = 0.0_wp
      ah%factored = .false.
   end subroutine arrowhead_init

   !> Block i: n unknowns in a band of half-bandwidth hb, coupled to the junction
   !> unknowns junctions (E, F = 0); blocks must be set in order 1, 2, ... (offsets).
   subroutine arrowhead_block_init(ah, i, n, hb, junctions, pivoting)
      type(arrowhead_t), intent(inout) :: ah  !< matrix
      integer, intent(in) :: i                !< block
      integer, intent(in) :: n                !< its unknowns
      integer, intent(in) :: hb               !< its half-bandwidth
      integer, intent(in) :: junctions(:)     !< junction unknowns it couples to
      logical, intent(in), optional :: pivoting !< the band's LU with pivoting (default)
      integer :: k
      k = size(junctions)
      associate (b => ah%blocks(i))
         if (present(pivoting)) b%a%pivoting = pivoting   ! banded_init sizes for it
         call banded_init(b%a, n, hb)
         b%junctions = junctions
         allocate (b%e(n, k), b%f(k, n), b%w(n, k))
         b%e = 0.0_wp
         b%f = 0.0_wp
      end associate
      ah%offset(i + 1) = ah%offset(i) + n
      if (i < size(ah%blocks)) ah%offset(i + 2:) = ah%offset(i + 1)
      ah%factored = .false.
   end subroutine arrowhead_block_init

   !> Order of the whole matrix: the blocks' unknowns and the junctions.
   pure integer function arrowhead_size(ah)
      type(arrowhead_t), intent(in) :: ah !< matrix
      arrowhead_size = ah%offset(size(ah%blocks) + 1) + ah%nj
   end function arrowhead_size

   !> Factorise: each band, W_i = A_i^-1 E_i, and the Schur complement S (header).
   subroutine arrowhead_factor(ah, err)
      type(arrowhead_t), intent(inout) :: ah !< matrix, then its factors
      type(error_t), intent(inout) :: err    !< status
      integer :: i, c
      if (has_error(err)) return
      ah%s = ah%c
      do i = 1, size(ah%blocks)
         associate (b => ah%blocks(i))
            call banded_factor(b%a, err)
            if (has_error(err)) return
            b%w = b%e
            do c = 1, size(b%junctions)
               call banded_solve(b%a, b%w(:, c), err)
            end do
            if (has_error(err)) return
            ah%s(b%junctions, b%junctions) = ah%s(b%junctions, b%junctions) - matmul(b%f, b%w)
         end associate
      end do
      call dense_factor(ah%s, ah%ipiv, err)
      ah%factored = .not. has_error(err)
   end subroutine arrowhead_factor

   !> Solve in place: x holds (f_1, ..., f_m, g) and is replaced by (x_1, ..., x_m, y).
   subroutine arrowhead_solve(ah, x, err)
      type(arrowhead_t), intent(in) :: ah  !< factorised matrix
      real(wp), intent(inout) :: x(:)      !< right-hand side, then solution
      type(error_t), intent(inout) :: err  !< status
      real(wp) :: y(ah%nj, 1)
      integer :: i, o
      if (has_error(err)) return
      o = ah%offset(size(ah%blocks) + 1)
      y(:, 1) = x(o + 1:o + ah%nj)
      do i = 1, size(ah%blocks)
         associate (b => ah%blocks(i), xi => x(ah%offset(i) + 1:ah%offset(i + 1)))
            call banded_solve(b%a, xi, err)
            y(b%junctions, 1) = y(b%junctions, 1) - matmul(b%f, xi)
         end associate
      end do
      if (has_error(err)) return
      call dense_solve(ah%s, ah%ipiv, y, err)
      do i = 1, size(ah%blocks)
         associate (b => ah%blocks(i), xi => x(ah%offset(i) + 1:ah%offset(i + 1)))
            xi = xi - matmul(b%w, y(b%junctions, 1))
         end associate
      end do
      x(o + 1:o + ah%nj) = y(:, 1)
   end subroutine arrowhead_solve

   !> r = M x with the matrix before arrowhead_factor (bands not factorised).
   subroutine arrowhead_matvec(ah, x, r)
      type(arrowhead_t), intent(in) :: ah  !< matrix
      real(wp), intent(in) :: x(:)         !< vector
      real(wp), intent(out) :: r(:)        !< product
      integer :: i, o
      o = ah%offset(size(ah%blocks) + 1)
      r(o + 1:o + ah%nj) = matmul(ah%c, x(o + 1:o + ah%nj))
      do i = 1, size(ah%blocks)
         associate (b => ah%blocks(i), xi => x(ah%offset(i) + 1:ah%offset(i + 1)))
            call banded_matvec(b%a, xi, r(ah%offset(i) + 1:ah%offset(i + 1)))
            r(ah%offset(i) + 1:ah%offset(i + 1)) = r(ah%offset(i) + 1:ah%offset(i + 1)) &
                                                  + matmul(b%e, x(o + b%junctions))
            r(o + b%junctions) = r(o + b%junctions) + matmul(b%f, xi)
         end associate
      end do
   end subroutine arrowhead_matvec
end module rodyn_arrowhead
