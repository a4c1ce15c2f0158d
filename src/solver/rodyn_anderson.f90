!> Anderson acceleration of the chord (reused-tangent) Newton iteration (docs/theory.md
!> eq. (53)).
!>
!> With a tangent K0 held from an earlier iterate, each Newton iteration takes the chord
!> step f_k = -K0^{-1} r(u_k): a fixed-point iteration u <- u + f(u) that converges only
!> linearly. Anderson's mixing (type II with mixing parameter 1; Walker and Ni, "Anderson
!> acceleration for fixed-point iterations", SIAM J. Numer. Anal. 49(4), 2011, eq. 2.1)
!> takes instead
!>
!>   s_k = f_k - (S + dF) gamma,   gamma = argmin | f_k - dF gamma |_2
!>
!> where the m <= depth columns of S are the last corrections applied, s_j = u_{j+1} - u_j,
!> and those of dF the changes of the chord step between them, f_{j+1} - f_j. On a linear
!> problem this is GMRES preconditioned by K0 (Walker and Ni, section 4), so the
!> directions in which the held tangent has gone stale (on a rod: the stiff axial
!> direction turning with the line) are corrected from the history instead of by a new
!> tangent. The rotation unknowns are increments about the current directors (Cayley
!> updates): their differences are taken as vectors, an error of second order in the
!> corrections, which shrink as the iteration converges.
!>
!> gamma comes from the normal equations dF^T dF gamma = dF^T f_k (m <= 8 unknowns); a
!> history whose columns have become dependent (a pivot below 1e-12 of the largest
!> diagonal) is dropped and the plain chord step taken. The history is cleared whenever
!> the fixed-point map changes: a new tangent, or a new Newton solve (a new time step).
!>
!> It trades a few more iterations for fewer tangents, with the tolerances and the
!> accuracy of a run unchanged (figures in docs/benchmarks.md).
module rodyn_anderson
   use rodyn_kinds, only: wp
   implicit none
   private
   public :: anderson_t, anderson_init, anderson_clear, anderson_step

   !> The history of one Newton problem (allocated once, outside the Newton loop): depth
   !> slots of (s, df), each either a column held or the pending pair (the last correction
   !> applied, and in df the chord step it came from, until the next step completes it).
   type :: anderson_t
      integer :: depth = 0                    !< slots (0: no acceleration)
      integer :: m = 0                        !< columns held
      integer :: cols(8) = 0                  !< their slots, oldest first
      integer :: pend = 0                     !< slot of the pending pair (0: none)
      real(wp) :: g(8, 8) = 0.0_wp            !< Gram matrix df_a . df_b of the slots held
      real(wp), allocatable :: s(:, :)        !< (n, depth) corrections applied
      real(wp), allocatable :: df(:, :)       !< (n, depth) changes of the chord step
   end type anderson_t

contains

   !> Allocate the history for n unknowns and `depth` slots (depth 0: none kept).
   subroutine anderson_init(aa, n, depth)
      type(anderson_t), intent(inout) :: aa !< history
      integer, intent(in) :: n              !< unknowns
      integer, intent(in) :: depth          !< slots (0..8)
      aa%depth = max(0, min(depth, 8))
      if (allocated(aa%s)) deallocate (aa%s, aa%df)
      if (aa%depth == 0) return
      allocate (aa%s(n, aa%depth), aa%df(n, aa%depth))
      call anderson_clear(aa)
   end subroutine anderson_init

   !> Forget the history (the fixed-point map changed: new tangent or new solve).
   pure subroutine anderson_clear(aa)
      type(anderson_t), intent(inout) :: aa !< history
      aa%m = 0
      aa%pend = 0
   end subroutine anderson_clear

   !> Replace the chord step f (in) by the accelerated correction s_k (out), and record
   !> the pair for the next iteration. The caller applies f in full (no line search).
   !> Only the new column's Gram row is computed; the others are kept.
   !> docs/theory.md eq. (53).
   pure subroutine anderson_step(aa, f)
      type(anderson_t), intent(inout) :: aa !< history
      real(wp), intent(inout) :: f(:)       !< chord step in, correction out
      real(wp) :: a(64), gam(8), fi, g1   ! a: the m x m Gram matrix, column by column
      integer :: i, j, p, q, m, cj
      logical :: ok, drop
      if (aa%depth == 0) return
      m = 0
      if (aa%pend > 0) then
         ! complete the pending column: df = f_k - f_{k-1} (f_{k-1} was kept in df)
         p = aa%pend
         aa%df(:, p) = f - aa%df(:, p)
         aa%m = aa%m + 1
         aa%cols(aa%m) = p
         m = aa%m
         do j = 1, m
            cj = aa%cols(j)
            aa%g(p, cj) = dot_product(aa%df(:, p), aa%df(:, cj))
            aa%g(cj, p) = aa%g(p, cj)
            gam(j) = dot_product(aa%df(:, cj), f)
         end do
         do j = 1, m      ! (contiguous: a section of an 8 x 8 array was copied to the heap)
            do i = 1, m
               a(i + m*(j - 1)) = aa%g(aa%cols(i), aa%cols(j))
            end do
         end do
         call solve_gram(m, a(1:m*m), gam(1:m), ok)
         if (.not. ok) then             ! dependent columns: the plain step, history anew
            aa%m = 0
            m = 0
         end if
      end if
      ! the slot of the new pending pair: a free one, or the oldest column's, dropped
      ! once this update has used it
      drop = m == aa%depth
      if (drop) then
         q = aa%cols(1)
         g1 = gam(1)
         do i = 1, size(f)
            fi = f(i)
            f(i) = fi - g1*(aa%s(i, q) + aa%df(i, q))
            aa%df(i, q) = fi
         end do
         do j = 1, m - 1         ! (a loop: the overlapping section copies made heap
            aa%cols(j) = aa%cols(j + 1)  ! temporaries, bench/alloc_check.sh)
            gam(j) = gam(j + 1)
         end do
         aa%m = m - 1
         m = m - 1
      else
         q = free_slot()
         aa%df(:, q) = f
      end if
      do j = 1, m
         cj = aa%cols(j)
         f = f - gam(j)*(aa%s(:, cj) + aa%df(:, cj))
      end do
      aa%s(:, q) = f
      aa%pend = q
   contains
      !> A slot neither held nor pending (there is one while m < depth).
      pure integer function free_slot()
         integer :: k
         do k = 1, aa%depth
            if (any(aa%cols(1:aa%m) == k)) cycle
            free_slot = k
            return
         end do
         free_slot = 1
      end function free_slot
   end subroutine anderson_step

   !> Solve the Gram system g x = b in place by elimination without pivoting (g is
   !> symmetric positive semi-definite); ok false when a pivot falls below 1e-12 of the
   !> largest diagonal entry (dependent columns).
   pure subroutine solve_gram(m, g, b, ok)
      integer, intent(in) :: m              !< order
      real(wp), intent(inout) :: g(m, m)    !< Gram matrix, destroyed
      real(wp), intent(inout) :: b(m)       !< right-hand side in, solution out
      logical, intent(out) :: ok            !< solved
      real(wp) :: gmax, fct
      integer :: i, k
      gmax = 0.0_wp
      do i = 1, m
         gmax = max(gmax, g(i, i))
      end do
      ok = .false.
      do k = 1, m
         if (.not. g(k, k) > 1.0e-12_wp*gmax) return
         do i = k + 1, m
            fct = g(i, k)/g(k, k)
            g(i, k + 1:m) = g(i, k + 1:m) - fct*g(k, k + 1:m)
            b(i) = b(i) - fct*b(k)
         end do
      end do
      do k = m, 1, -1
         b(k) = (b(k) - dot_product(g(k, k + 1:m), b(k + 1:m)))/g(k, k)
      end do
      ok = .true.
   end subroutine solve_gram
end module rodyn_anderson
