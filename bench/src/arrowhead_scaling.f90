!> Cost of rodyn_arrowhead against the number of lines (bench/arrowhead_scaling.py): m
!> lines of n unknowns each, concatenated in one band of half-bandwidth hb (a line of
!> cubic rod elements: 6 unknowns a node, hb = 23; no line coupled to another), their
!> first and last 6 unknowns coupled to a point's 3 junction unknowns (one point per
!> three lines) and to a shared body's 6, the entries from a formula and the band
!> diagonally dominant (factorised without pivoting). Prints, for `reps` repetitions
!> of factor + solve: the order, the junctions, the shortest wall time [s] of factor
!> and of solve, and the relative residual of the last solve.
!>
!> usage: bench_arrowhead M N HB REPS
program arrowhead_scaling
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_banded, only: banded_t, banded_init, banded_set_pivoting
   use rodyn_arrowhead, only: arrowhead_t, arrowhead_init, arrowhead_block_init, &
                              arrowhead_factor, arrowhead_solve, arrowhead_matvec
   implicit none
   type(arrowhead_t) :: ah
   type(banded_t) :: bm, fresh
   type(error_t) :: err
   integer :: m, n, hb, reps, np, nj, i, r, c, k, rep, nb, o
   integer(kind=8) :: t0, t1, t2, rate
   real(wp), allocatable :: bx(:), by(:), x(:), y(:), xt(:), rx(:), ry(:), tf(:), ts(:)
   character(len=32) :: arg
   call get_command_argument(1, arg)
   read (arg, *) m
   call get_command_argument(2, arg)
   read (arg, *) n
   call get_command_argument(3, arg)
   read (arg, *) hb
   call get_command_argument(4, arg)
   read (arg, *) reps
   np = max(1, m/3)
   nj = 3*np + 6
   nb = m*n
   call banded_init(fresh, nb, hb)
   call banded_set_pivoting(fresh, .false.)
   call arrowhead_init(ah, m, nj)
   do i = 1, m
      o = (i - 1)*n
      call arrowhead_block_init(ah, i, o + 1, o + n, [3*mod(i - 1, np) + [1, 2, 3], &
                                3*np + [1, 2, 3, 4, 5, 6]])
      do c = 1, n
         do r = max(1, c - hb), min(n, c + hb)
            fresh%ab(fresh%kv + r - c, o + c) = val(r, c, i)
         end do
         fresh%ab(fresh%kv, o + c) = 4.0_wp*real(hb, wp)
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
   allocate (bx(nb), by(nj), x(nb), y(nj), xt(nb + nj), rx(nb), ry(nj), tf(reps), ts(reps))
   do r = 1, nb + nj
      xt(r) = val(r, 5, 3)
   end do
   call arrowhead_matvec(ah, fresh, xt(:nb), xt(nb + 1:), bx, by)
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
contains
   pure real(wp) function val(i, j, k)
      integer, intent(in) :: i, j, k
      val = sin(1.7_wp*real(i, wp) + 3.1_wp*real(j, wp) + 0.37_wp*real(k, wp)) &
            *cos(0.41_wp*real(i*j + k, wp))
   end function val
end program arrowhead_scaling
