!> rodyn's arrowhead solver against SuiteSparse's UMFPACK and KLU on the matrix of
!> bench_arrow_matrix (bench/sparse_direct.py): the whole matrix (band, couplings and
!> junction block) in compressed columns for the sparse solvers. Prints one line per
!> solver: its name, the order, the nonzeros, the shortest wall time [s] of the symbolic
!> analysis (0 for the arrowhead: its structure is given), of the factorisation and of
!> the solve over `reps` repetitions, and the relative residual of the last solution.
!>
!> usage: bench_sparse M N HB REPS
program sparse_direct
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use rodyn_kinds, only: wp
   use rodyn_banded, only: banded_t
   use rodyn_arrowhead, only: arrowhead_t, arrowhead_matvec
   use bench_arrow_matrix, only: arrow_problem, bench_args, time_arrowhead
   implicit none
   interface
      integer(c_int) function bench_umfpack(n, ap, ai, ax, b, x, reps, times) &
         bind(C, name='rodyn_bench_umfpack')
         import :: c_int, c_double
         integer(c_int), value :: n, reps
         integer(c_int), intent(in) :: ap(*), ai(*)
         real(c_double), intent(in) :: ax(*), b(*)
         real(c_double), intent(out) :: x(*), times(3)
      end function bench_umfpack
      integer(c_int) function bench_klu(n, ap, ai, ax, b, x, reps, times) &
         bind(C, name='rodyn_bench_klu')
         import :: c_int, c_double
         integer(c_int), value :: n, reps
         integer(c_int), intent(in) :: ap(*), ai(*)
         real(c_double), intent(in) :: ax(*), b(*)
         real(c_double), intent(out) :: x(*), times(3)
      end function bench_klu
   end interface
   type(arrowhead_t) :: ah
   type(banded_t) :: band
   integer :: m, n, hb, reps, nb, nj, nt
   integer(c_int), allocatable :: ap(:), ai(:)
   real(c_double), allocatable :: ax(:), b(:), x(:)
   real(c_double) :: times(3)
   real(wp), allocatable :: bx(:), by(:), xt(:), xa(:), ya(:), rx(:), ry(:)
   real(wp) :: tf, ts
   call bench_args(m, n, hb, reps)
   call arrow_problem(m, n, hb, ah, band, bx, by, xt)
   nb = size(bx)
   nj = size(by)
   nt = nb + nj
   call to_csc(ah, band, ap, ai, ax)
   allocate (b(nt), x(nt), xa(nb), ya(nj), rx(nb), ry(nj))
   b(:nb) = bx
   b(nb + 1:) = by
   ! the arrowhead
   call time_arrowhead(ah, band, bx, by, reps, tf, ts, xa, ya)
   call report('arrowhead', [0.0_wp, tf, ts], [xa, ya])
   if (bench_umfpack(nt, ap, ai, ax, b, x, reps, times) /= 0) error stop 'UMFPACK failed'
   call report('umfpack', times, x)
   if (bench_klu(nt, ap, ai, ax, b, x, reps, times) /= 0) error stop 'KLU failed'
   call report('klu', times, x)
contains
   !> One line of results, with the residual of solution s against the matrix.
   subroutine report(name, t, s)
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: t(3)
      real(wp), intent(in) :: s(:)
      call arrowhead_matvec(ah, band, s(:nb), s(nb + 1:), rx, ry)
      print '(a,1x,i0,1x,i0,3(1x,es12.5),1x,es10.3)', name, nt, size(ax), t, &
         max(maxval(abs(rx - bx)), maxval(abs(ry - by)))/max(maxval(abs(bx)), &
                                                             maxval(abs(by)))
   end subroutine report

   !> The whole matrix in compressed columns (0-based, rows increasing in a column): a
   !> counting pass, then a filling pass over the same columns.
   subroutine to_csc(ah, band, ap, ai, ax)
      type(arrowhead_t), intent(in) :: ah
      type(banded_t), intent(in) :: band
      integer(c_int), allocatable, intent(out) :: ap(:), ai(:)
      real(c_double), allocatable, intent(out) :: ax(:)
      real(wp), allocatable :: col(:)
      integer :: c, r, pass, nz
      allocate (ap(nt + 1), col(nt))
      do pass = 1, 2
         nz = 0
         ap(1) = 0
         do c = 1, nt
            call column(ah, band, c, col)
            do r = 1, nt
               if (col(r) == 0.0_wp) cycle
               nz = nz + 1
               if (pass == 2) then
                  ai(nz) = int(r - 1, c_int)
                  ax(nz) = col(r)
               end if
            end do
            ap(c + 1) = nz
         end do
         if (pass == 1) allocate (ai(nz), ax(nz))
      end do
   end subroutine to_csc

   !> Column c of the whole matrix.
   subroutine column(ah, band, c, col)
      type(arrowhead_t), intent(in) :: ah
      type(banded_t), intent(in) :: band
      integer, intent(in) :: c
      real(wp), intent(out) :: col(:)
      integer :: r, i, k, j
      col = 0.0_wp
      if (c <= nb) then
         do r = max(1, c - band%ku), min(nb, c + band%kl)
            col(r) = band%ab(band%kv + r - c, c)
         end do
         do i = 1, size(ah%blocks)
            associate (bl => ah%blocks(i))
               if (c < bl%lo .or. c > bl%hi) cycle
               do k = 1, size(bl%junctions)
                  col(nb + bl%junctions(k)) = bl%f(k, c - bl%lo + 1)
               end do
            end associate
         end do
      else
         j = c - nb
         do i = 1, size(ah%blocks)
            associate (bl => ah%blocks(i))
               do k = 1, size(bl%junctions)
                  if (bl%junctions(k) == j) col(bl%lo:bl%hi) = bl%e(:, k)
               end do
            end associate
         end do
         col(nb + 1:) = ah%c(:, j)
      end if
   end subroutine column
end program sparse_direct
