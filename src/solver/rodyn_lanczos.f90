!> The few longest-period modes of K phi = omega^2 M phi (K symmetric positive
!> definite, M symmetric positive semi-definite) by ARPACK's implicitly restarted Lanczos
!> method in shift-invert mode about 0 (dsaupd / dseupd, mode 3: OP = K^-1 M, inner
!> product of M; docs/theory.md eq. (147)). The caller gives the two operations as an
!> extension of eigen_operator_t (its context: the factorised K and the mass): solve_k
!> y = K^-1 x and apply_m y = M x. Cost per iteration: one solve and one product, so
!> linear in the unknowns for a banded K; the Lanczos basis holds ncv = max(2 nev + 1,
!> 20) vectors.
!>
!> R. B. Lehoucq, D. C. Sorensen, C. Yang, ARPACK Users' Guide, SIAM, 1998, sec. 3.2.
module rodyn_lanczos
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error, set_error, stat_numerical
   use rodyn_sort, only: sorted_order
   implicit none
   private
   public :: eigen_operator_t, lanczos_modes

   !> The operations of the eigenproblem, with their context in the extension.
   type, abstract :: eigen_operator_t
   contains
      procedure(op_solve), deferred :: solve_k
      procedure(op_apply), deferred :: apply_m
   end type eigen_operator_t

   abstract interface
      !> y = K^-1 x.
      subroutine op_solve(this, x, y, err)
         import :: eigen_operator_t, wp, error_t
         class(eigen_operator_t), intent(inout) :: this
         real(wp), intent(in) :: x(:)
         real(wp), intent(out) :: y(:)
         type(error_t), intent(inout) :: err
      end subroutine op_solve
      !> y = M x.
      subroutine op_apply(this, x, y)
         import :: eigen_operator_t, wp
         class(eigen_operator_t), intent(inout) :: this
         real(wp), intent(in) :: x(:)
         real(wp), intent(out) :: y(:)
      end subroutine op_apply
   end interface

   interface
      subroutine dsaupd(ido, bmat, n, which, nev, tol, resid, ncv, v, ldv, iparam, ipntr, &
                        workd, workl, lworkl, info)
         import :: wp
         integer, intent(inout) :: ido
         character(len=1), intent(in) :: bmat
         integer, intent(in) :: n, nev, ncv, ldv, lworkl
         character(len=2), intent(in) :: which
         real(wp), intent(inout) :: tol         ! (set to the machine precision when <= 0)
         real(wp), intent(inout) :: resid(n), v(ldv, ncv), workd(3*n), workl(lworkl)
         integer, intent(inout) :: iparam(11), ipntr(11), info
      end subroutine dsaupd
      subroutine dseupd(rvec, howmny, select, d, z, ldz, sigma, bmat, n, which, nev, tol, &
                        resid, ncv, v, ldv, iparam, ipntr, workd, workl, lworkl, info)
         import :: wp
         logical, intent(in) :: rvec
         character(len=1), intent(in) :: howmny, bmat
         integer, intent(in) :: ldz, n, nev, ncv, ldv, lworkl
         logical, intent(inout) :: select(ncv)
         real(wp), intent(out) :: d(nev), z(ldz, nev)
         real(wp), intent(in) :: sigma
         real(wp), intent(inout) :: tol
         character(len=2), intent(in) :: which
         real(wp), intent(inout) :: resid(n), v(ldv, ncv), workd(3*n), workl(lworkl)
         integer, intent(inout) :: iparam(11), ipntr(11), info
      end subroutine dseupd
   end interface

contains

   !> The nev modes of longest period: mu (nev) = 1/omega^2, descending [s2], and their
   !> vectors v (n, nev), M-orthonormal. nev < n.
   subroutine lanczos_modes(op, n, nev, mu, v, err)
      class(eigen_operator_t), intent(inout) :: op !< K^-1 and M
      integer, intent(in) :: n                     !< unknowns
      integer, intent(in) :: nev                   !< modes wanted
      real(wp), intent(out) :: mu(:)               !< (nev) 1/omega^2 [s2]
      real(wp), intent(out) :: v(:, :)             !< (n, nev) modes
      type(error_t), intent(inout) :: err          !< status
      real(wp), allocatable :: resid(:), basis(:, :), workd(:), workl(:), d(:), mx(:)
      integer :: iparam(11), ipntr(11), ido, info, ncv, lworkl
      integer, allocatable :: order(:)
      logical, allocatable :: sel(:)
      character(len=120) :: msg
      real(wp) :: tol
      tol = 0.0_wp             ! the machine precision (ARPACK writes it here)
      ncv = min(n, max(2*nev + 1, 20))
      lworkl = ncv*(ncv + 8)
      allocate (resid(n), basis(n, ncv), workd(3*n), workl(lworkl), sel(ncv), d(nev), mx(n))
      iparam = 0
      iparam(1) = 1            ! exact shifts
      iparam(3) = 1000         ! restarts at most
      iparam(7) = 3            ! shift-invert: OP = (K - sigma M)^-1 M, B = M
      ipntr = 0
      ido = 0
      info = 0
      do
         call dsaupd(ido, 'G', n, 'LM', nev, tol, resid, ncv, basis, n, iparam, ipntr, &
                     workd, workl, lworkl, info)
         select case (ido)
         case (-1)
            call op%apply_m(workd(ipntr(1):ipntr(1) + n - 1), mx)
            call op%solve_k(mx, workd(ipntr(2):ipntr(2) + n - 1), err)
         case (1)
            call op%solve_k(workd(ipntr(3):ipntr(3) + n - 1), &
                            workd(ipntr(2):ipntr(2) + n - 1), err)
         case (2)
            call op%apply_m(workd(ipntr(1):ipntr(1) + n - 1), workd(ipntr(2):ipntr(2) + n - 1))
         case default
            exit
         end select
         if (has_error(err)) return
      end do
      if (info < 0 .or. info == 1) then
         write (msg, '(a,i0,a,i0,a)') 'lanczos_modes: dsaupd info = ', info, ' (', &
            iparam(5), ' modes converged)'
         call set_error(err, stat_numerical, trim(msg))
         return
      end if
      call dseupd(.true., 'A', sel, d, v, n, 0.0_wp, 'G', n, 'LM', nev, tol, resid, ncv, &
                  basis, n, iparam, ipntr, workd, workl, lworkl, info)
      if (info /= 0) then
         write (msg, '(a,i0)') 'lanczos_modes: dseupd info = ', info
         call set_error(err, stat_numerical, trim(msg))
         return
      end if
      ! d: omega^2 of the original problem; longest period first
      order = sorted_order(d)
      mu = 1.0_wp/d(order)
      v(:, 1:nev) = v(:, order)
      if (any(d <= 0.0_wp)) call set_error(err, stat_numerical, 'lanczos_modes: an '// &
         'eigenvalue omega^2 <= 0 (the stiffness is not positive definite)')
   end subroutine lanczos_modes
end module rodyn_lanczos
