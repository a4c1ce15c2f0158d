!> Cross-section properties: the constitutive matrix of the rod (docs/theory.md eq. (6))
!> and the defaults derived from the deck's values (eq. (10)).
module rodyn_section
   use rodyn_kinds, only: wp
   use rodyn_model, only: section_t
   implicit none
   private
   public :: section_stiffness, section_default_rotary_inertia, section_damping

contains

   !> Diagonal of C = diag(GA1, GA2, EA, EI1, EI2, GJ), W = 1/2 (eps - eps0).C(eps - eps0).
   !> docs/theory.md eqs. (6)-(7).
   pure function section_stiffness(sec) result(c)
      type(section_t), intent(in) :: sec !< section with its defaults resolved
      real(wp) :: c(6)
      c = [sec%ga1, sec%ga2, sec%ea, sec%ei1, sec%ei2, sec%gj]
   end function section_stiffness

   !> Structural damping coefficients of an element of the section, (C_a, C_b, C_b):
   !> axial [N s] and bending about d1 and d2 [N m2 s]. AXIAL DAMPING RATIO zeta gives
   !> C_a = zeta h sqrt(EA m) (MoorDyn's negative BA with h its segment length, here the
   !> node spacing le/p): zeta times the critical damping of the free-free axial mode of
   !> one segment of length h with its lumped end masses m h/2.
   !> docs/theory.md eq. (118).
   pure function section_damping(sec, mass, h) result(cd)
      type(section_t), intent(in) :: sec !< section
      real(wp), intent(in) :: mass       !< mass per length, structure and contents [kg/m]
      real(wp), intent(in) :: h          !< node spacing le/p [m]
      real(wp) :: cd(3)
      cd(1) = sec%axial_damping + sec%axial_damping_ratio*h*sqrt(sec%ea*mass)
      cd(2:3) = sec%bending_damping
   end function section_damping

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
