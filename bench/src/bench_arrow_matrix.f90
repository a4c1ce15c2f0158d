!> The test matrix of the solver benchmarks (bench/arrowhead_scaling.py,
!> bench/sparse_direct.py): m lines of n unknowns each, concatenated in one band of
!> half-bandwidth hb (no line coupled to another), their first and last 6 unknowns
!> coupled to a point's 3 junction unknowns (one point per three lines) and to a shared
!> body's 6, the entries from a formula and the band diagonally dominant (factorised
!> without pivoting); and a right-hand side from a known solution.
module bench_arrow_matrix
   use rodyn_kinds, only: wp
   use rodyn_banded, only: banded_t, banded_init, banded_set_pivoting
   use rodyn_error, only: error_t, has_error
   use rodyn_arrowhead, only: arrowhead_t, arrowhead_init, arrowhead_block_init, &
                              arrowhead_matvec, arrowhead_factor, arrowhead_solve
   implicit none
   private
   public :: arrow_problem, bench_args, time_arrowhead

contains

   !> The matrix (band and arrowhead) and the right-hand side (bx, by) of the solution xt.
   subroutine arrow_problem(m, n, hb, ah, band, bx, by, xt)
      integer, intent(in) :: m                 !< lines
      integer, intent(in) :: n                 !< unknowns a line
      integer, intent(in) :: hb                !< half-bandwidth
      type(arrowhead_t), intent(out) :: ah     !< couplings
      type(banded_t), intent(out) :: band      !< band of all lines
      real(wp), allocatable, intent(out) :: bx(:), by(:), xt(:) !< right-hand side, solution
      integer :: np, nj, nb, i, o, c, r, k
      np = max(1, m/3)
      nj = 3*np + 6
      nb = m*n
      call banded_init(band, nb, hb)
      call banded_set_pivoting(band, .false.)
      call arrowhead_init(ah, m, nj)
      do i = 1, m
         o = (i - 1)*n
         call arrowhead_block_init(ah, i, o + 1, o + n, [3*mod(i - 1, np) + [1, 2, 3], &
                                   3*np + [1, 2, 3, 4, 5, 6]])
         do c = 1, n
            do r = max(1, c - hb), min(n, c + hb)
               band%ab(band%kv + r - c, o + c) = val(r, c, i)
            end do
            band%ab(band%kv, o + c) = 4.0_wp*real(hb, wp)
         end do
         associate (bl => ah%blocks(i))
            do k = 1, size(bl%junctions)
               do r = 1, n
                  if (r > 6 .and. r <= n - 6) cycle
                  bl%e(r, k) = val(r, k, i + 7)
                  bl%f(k, r) = val(k, r, i + 11)
               end do
            end do
         end associate
      end do
      do c = 1, nj
         ah%c(c, c) = 8.0_wp*real(m, wp)
      end do
      allocate (bx(nb), by(nj), xt(nb + nj))
      do r = 1, nb + nj
         xt(r) = val(r, 5, 3)
      end do
      call arrowhead_matvec(ah, band, xt(:nb), xt(nb + 1:), bx, by)
   end subroutine arrow_problem

   !> The shortest wall times [s] of `reps` factorisations (tf) and solves (ts) of the
   !> arrowhead, each from a fresh copy of band, and the solution (x, y) of (bx, by).
   subroutine time_arrowhead(ah, band, bx, by, reps, tf, ts, x, y)
      type(arrowhead_t), intent(inout) :: ah   !< couplings (and their factors)
      type(banded_t), intent(in) :: band       !< band of all lines
      real(wp), intent(in) :: bx(:), by(:)     !< right-hand side
      integer, intent(in) :: reps              !< repetitions
      real(wp), intent(out) :: tf, ts          !< shortest factorisation and solve [s]
      real(wp), intent(out) :: x(:), y(:)      !< the solution
      type(banded_t) :: bm
      type(error_t) :: err
      integer(kind=8) :: t0, t1, t2, rate
      integer :: rep
      call system_clock(count_rate=rate)
      tf = huge(1.0_wp)
      ts = huge(1.0_wp)
      do rep = 1, reps
         bm = band
         call system_clock(t0)
         call arrowhead_factor(ah, bm, err)
         call system_clock(t1)
         x = bx
         y = by
         call arrowhead_solve(ah, bm, x, y, err)
         call system_clock(t2)
         tf = min(tf, real(t1 - t0, wp)/real(rate, wp))
         ts = min(ts, real(t2 - t1, wp)/real(rate, wp))
      end do
      if (has_error(err)) error stop 'bench: the arrowhead factorisation or solve failed'
   end subroutine time_arrowhead

   !> The drivers' arguments M N HB REPS.
   subroutine bench_args(m, n, hb, reps)
      integer, intent(out) :: m, n, hb, reps !< lines, unknowns a line, half-bandwidth, runs
      character(len=32) :: arg
      call get_command_argument(1, arg)
      read (arg, *) m
      call get_command_argument(2, arg)
      read (arg, *) n
      call get_command_argument(3, arg)
      read (arg, *) hb
      call get_command_argument(4, arg)
      read (arg, *) reps
   end subroutine bench_args

   !> The entries' formula.
   pure real(wp) function val(i, j, k)
      integer, intent(in) :: i, j, k
      val = sin(1.7_wp*real(i, wp) + 3.1_wp*real(j, wp) + 0.37_wp*real(k, wp)) &
            *cos(0.41_wp*real(i*j + k, wp))
   end function val
end module bench_arrow_matrix
