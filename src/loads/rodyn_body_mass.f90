!> A body's added mass as one 6 x 6 matrix at its centre of gravity G in its axes (docs/
!> theory.md eqs. (142), (152)-(153)): the matrix form of *BODY ADDED MASS moved from R to
!> G, or the translational part of the diagonal form (whose rotational part adds to the
!> body's principal moments instead), and the same turned to the global axes.
module rodyn_body_mass
   use rodyn_kinds, only: wp
   use rodyn_model, only: body_t
   use rodyn_rotation, only: skew
   implicit none
   private
   public :: body_added_mass_g, added_mass_global

contains

   !> The added mass at G in body axes, A_G = T_R^T A_R T_R with T_R = [I, -skew(a_R);
   !> 0, I], a_R = R - G = -cog (the velocity of R is v_G + omega x a_R), eq. (152); for
   !> the diagonal form diag(A11, A22, A33, 0, 0, 0) (eq. (142)).
   pure function body_added_mass_g(bd) result(a)
      type(body_t), intent(in) :: bd   !< the body
      real(wp) :: a(6, 6)              !< [kg, kg m, kg m2]
      real(wp) :: t(6, 6)
      integer :: i
      a = 0.0_wp
      if (any(bd%added_matrix /= 0.0_wp)) then
         t = 0.0_wp
         do i = 1, 6
            t(i, i) = 1.0_wp
         end do
         t(1:3, 4:6) = skew(bd%cog)
         a = matmul(transpose(t), matmul(bd%added_matrix, t))
      else
         do i = 1, 3
            a(i, i) = bd%added_mass(i)
         end do
      end if
   end function body_added_mass_g

   !> The added mass at G in the global axes, blkdiag(D, D) A_G blkdiag(D, D)^T, with the
   !> body's directors D (eq. (153)).
   pure function added_mass_global(ag, d) result(a)
      real(wp), intent(in) :: ag(6, 6)  !< at G, body axes
      real(wp), intent(in) :: d(3, 3)   !< directors (columns)
      real(wp) :: a(6, 6)
      real(wp) :: r(6, 6)
      r = 0.0_wp
      r(1:3, 1:3) = d
      r(4:6, 4:6) = d
      a = matmul(r, matmul(ag, transpose(r)))
   end function added_mass_global
end module rodyn_body_mass
