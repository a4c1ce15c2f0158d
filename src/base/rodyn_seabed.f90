!> The seabed plane (docs/water.md; docs/theory.md eqs. (94)-(95)), a fact of the model
!> that the mesh (a line started grounded), the loads (contact) and the deck's checks
!> read alike:
!>   z_bed(x, y) = z_s - h + tan(alpha) (x cos(beta) + y sin(beta)),
!>   n = (-tan(alpha) cos(beta), -tan(alpha) sin(beta), 1) / sqrt(1 + tan^2(alpha)),
!>   g(x) = (x - x_bed) . n, the distance above the plane (negative: penetration).
module rodyn_seabed
   use rodyn_kinds, only: wp
   use rodyn_model, only: model_t, seabed_t
   implicit none
   private
   public :: seabed_z, seabed_normal, seabed_gap

contains

   !> Height of the seabed plane under (x, y) [m].
   !> docs/theory.md eq. (94).
   pure real(wp) function seabed_z(model, x, y)
      type(model_t), intent(in) :: model !< model (water and seabed)
      real(wp), intent(in) :: x          !< [m]
      real(wp), intent(in) :: y          !< [m]
      associate (sb => model%seabed)
         seabed_z = model%water%surface - model%water%depth &
                    + tan(sb%slope)*(x*cos(sb%slope_dir) + y*sin(sb%slope_dir))
      end associate
   end function seabed_z

   !> Outward (upward) unit normal of the seabed plane.
   !> docs/theory.md eq. (94).
   pure function seabed_normal(sb) result(n)
      type(seabed_t), intent(in) :: sb !< seabed
      real(wp) :: n(3)
      real(wp) :: ts
      ts = tan(sb%slope)
      n = [-ts*cos(sb%slope_dir), -ts*sin(sb%slope_dir), 1.0_wp]/sqrt(1.0_wp + ts**2)
   end function seabed_normal

   !> Distance of x above the seabed plane, along its normal [m] (< 0: penetration).
   !> docs/theory.md eq. (95).
   pure real(wp) function seabed_gap(model, n, x)
      type(model_t), intent(in) :: model !< model
      real(wp), intent(in) :: n(3)       !< seabed_normal
      real(wp), intent(in) :: x(3)       !< point [m]
      seabed_gap = n(3)*(x(3) - seabed_z(model, 0.0_wp, 0.0_wp)) + n(1)*x(1) + n(2)*x(2)
   end function seabed_gap
end module rodyn_seabed
