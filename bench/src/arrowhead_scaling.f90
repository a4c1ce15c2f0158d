!> Cost of rodyn_arrowhead against the number of lines (bench/arrowhead_scaling.py), on
!> the matrix of bench_arrow_matrix (m lines of n unknowns, half-bandwidth hb: a line of
!> cubic rod elements has 6 unknowns a node, hb = 23). Prints, for `reps` repetitions
!> of factor + solve: the lines, the order, the junctions, the shortest wall time [s] of
!> factor and of solve, and the relative residual of the last solve.
!>
!> usage: bench_arrowhead M N HB REPS
program arrowhead_scaling
   use rodyn_kinds, only: wp
   use rodyn_banded, only: banded_t
   use rodyn_arrowhead, only: arrowhead_t, arrowhead_matvec
   use bench_arrow_matrix, only: arrow_problem, bench_args, time_arrowhead
   implicit none
   type(arrowhead_t) :: ah
   type(banded_t) :: fresh
   integer :: m, n, hb, reps, nb, nj
   real(wp), allocatable :: bx(:), by(:), x(:), y(:), xt(:), rx(:), ry(:)
   real(wp) :: tf, ts
   call bench_args(m, n, hb, reps)
   call arrow_problem(m, n, hb, ah, fresh, bx, by, xt)
   nb = size(bx)
   nj = size(by)
   allocate (x(nb), y(nj), rx(nb), ry(nj))
   call time_arrowhead(ah, fresh, bx, by, reps, tf, ts, x, y)
   call arrowhead_matvec(ah, fresh, x, y, rx, ry)
   print '(i0,1x,i0,1x,i0,1x,es12.5,1x,es12.5,1x,es10.3)', m, nb + nj, nj, tf, ts, max(maxval(abs(rx - bx)), maxval(abs(ry - by))) &
      /max(maxval(abs(bx)), maxval(abs(by)))
end program arrowhead_scaling
