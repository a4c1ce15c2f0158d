!> Lagrange shape functions of order 1-3 on equally spaced nodes in xi in [-1, 1], and
!> Gauss-Legendre rules (docs/theory.md eqs. (19)-(21)). Element nodes are numbered along
!> the line: node 1 at xi = -1, node p+1 at xi = +1.
module rodyn_shape
   use rodyn_kinds, only: wp
   implicit none
   private
   public :: shape_lagrange, gauss_rule, max_order, max_nen

   integer, parameter :: max_order = 3            !< highest element order
   integer, parameter :: max_nen = max_order + 1  !< most nodes per element

contains

   !> Lagrange polynomials N_a(xi) and dN_a/dxi for an element of order p.
   !> docs/theory.md eq. (19).
   pure subroutine shape_lagrange(p, xi, n, dn)
      integer, intent(in) :: p            !< element order (1, 2 or 3)
      real(wp), intent(in) :: xi          !< parent coordinate in [-1, 1]
      real(wp), intent(out) :: n(p + 1)   !< shape functions
      real(wp), intent(out) :: dn(p + 1)  !< derivatives with respect to xi
      real(wp) :: xa(max_nen), prod, dsum, term
      integer :: a, b, c
      do a = 1, p + 1
         xa(a) = -1.0_wp + 2.0_wp*real(a - 1, wp)/real(p, wp)
      end do
      do a = 1, p + 1
         prod = 1.0_wp
         dsum = 0.0_wp
         do b = 1, p + 1
            if (b == a) cycle
            prod = prod*(xi - xa(b))/(xa(a) - xa(b))
            term = 1.0_wp/(xa(a) - xa(b))
            do c = 1, p + 1
               if (c == a .or. c == b) cycle
               term = term*(xi - xa(c))/(xa(a) - xa(c))
            end do
            dsum = dsum + term
         end do
         n(a) = prod
         dn(a) = dsum
      end do
   end subroutine shape_lagrange

   !> Gauss-Legendre points and weights on [-1, 1], 1 to 4 points.
   !> docs/theory.md eq. (21).
   pure subroutine gauss_rule(ng, xi, w)
      integer, intent(in) :: ng          !< number of points (1..4)
      real(wp), intent(out) :: xi(ng)    !< abscissae
      real(wp), intent(out) :: w(ng)     !< weights (sum 2)
      real(wp) :: a, b
      select case (ng)
      case (1)
         xi = 0.0_wp
         w = 2.0_wp
      case (2)
         xi = [-1.0_wp, 1.0_wp]/sqrt(3.0_wp)
         w = 1.0_wp
      case (3)
         xi = [-sqrt(0.6_wp), 0.0_wp, sqrt(0.6_wp)]
         w = [5.0_wp, 8.0_wp, 5.0_wp]/9.0_wp
      case default
         a = sqrt(3.0_wp/7.0_wp - 2.0_wp/7.0_wp*sqrt(1.2_wp))
         b = sqrt(3.0_wp/7.0_wp + 2.0_wp/7.0_wp*sqrt(1.2_wp))
         xi = [-b, -a, a, b]
         w = [(18.0_wp - sqrt(30.0_wp))/36.0_wp, (18.0_wp + sqrt(30.0_wp))/36.0_wp, &
              (18.0_wp + sqrt(30.0_wp))/36.0_wp, (18.0_wp - sqrt(30.0_wp))/36.0_wp]
      end select
   end subroutine gauss_rule
end module rodyn_shape
