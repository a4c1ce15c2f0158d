!> Cost of rodyn_arrowhead against the number of lines (bench/arrowhead_scaling.py), on
!> the matrix of bench_arrow_matrix (m lines of n unknowns, half-bandwidth hb: a line of
!> cubic rod elements has 6 unknowns a node, hb = 23). Prints, for `reps` repetitions
!> of factor + solve: the lines, the order, the junctions, the shortest wall time [s] of
!> factor and of solve, and the relative residual of the last solve.
!>
!> usage: bench_arrowhead M N HB REPS
program arrowhead_scaling
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_banded, only: banded_t
   use rodyn_arrowhead, only: arrowhead_t, arrowhead_factor, arrowhead_solve, &
                              arrowhead_matvec
   use bench_arrow_matrix, only: arrow_problem, bench_args
   implicit none
   type(arrowhead_t) :: ah
   type(banded_t) :: bm, fresh
   type(error_t) :: err
   integer :: m, n, hb, reps, rep, nb, nj
   integer(kind=8) :: t0, t1, t2, rate
   real(wp), allocatable :: bx(:), by(:), x(:), y(:), xt(:), rx(:), ry(:), tf(:), ts(:)
   call bench_args(m, n, hb, reps)
   call arrow_problem(m, n, hb, ah, fresh, bx, by, xt)
   nb = size(bx)
   nj = size(by)
   allocate (x(nb), y(nj), rx(nb), ry(nj), tf(reps), ts(reps))
   call system_clock(count_rate=rate)
   do rep = 1, reps
      bm = fresh
      call system_clock(t0)
      call arrowhead_factor(ah, bm, err)
      call system_clock(t1)
      x = bx
      y = by
      call arrowhead_solve(ah, bm, x, y, err)
      call system_clock(t2)
      tf(rep) = real(t1 - t0, wp)/real(rate, wp)
      ts(rep) = real(t2 - t1, wp)/real(rate, wp)
   end do
   if (has_error(err)) error stop 'bench_arrowhead: factor or solve failed'
   call arrowhead_matvec(ah, fresh, x, y, rx, ry)
   print '(i0,1x,i0,1x,i0,1x,es12.5,1x,es12.5,1x,es10.3)', m, nb + nj, nj, minval(tf), &
      minval(ts), max(maxval(abs(rx - bx)), maxval(abs(ry - by))) &
      /max(maxval(abs(bx)), maxval(abs(by)))
end program arrowhead_scaling
