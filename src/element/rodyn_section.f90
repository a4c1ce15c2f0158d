!> Cross-section properties: the constitutive matrix of the rod (docs/theory.md eq. (6))
!> and the defaults derived from the deck's values (eq. (10)).
module rodyn_section
   use rodyn_kinds, only: wp
   use rodyn_model, only: section_t
   implicit none
   private
   public :: section_stiffness, section_default_rotary_inertia

contains

   !> Diagonal of C = diag(GA1, GA2, EA, EI1, EI2, GJ), W = 1/2 (eps - eps0).C(eps - eps0).
   !> docs/theory.md eqs. (6)-(7).
   pure function section_stiffness(sec) result(c)
      type(section_t), intent(in) :: sec !< section with its defaults resolved
      real(wp) :: c(6)
      c = [sec%ga1, sec%ga2, sec%ea, sec%ei1, sec%ei2, sec%gj]
   end function section_stiffness

   !> Rotary inertia per length about a diameter of a solid circular section,
   !> rho I = m D^2 / 16 [kg m] (0 when no outer diameter is given).
   !> docs/theory.md eq. (10).
   pure function section_default_rotary_inertia(mass, od) result(rhoi)
      real(wp), intent(in) :: mass !< mass per length [kg/m]
      real(wp), intent(in) :: od   !< outer diameter [m]
      real(wp) :: rhoi
      rhoi = mass*od**2/16.0_wp
   end function section_default_rotary_inertia
end module rodyn_section
