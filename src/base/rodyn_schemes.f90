!> The time integration schemes of *DYNAMIC, SCHEME= (docs/dynamics.md, "Schemes"): their
!> numbers and names and the bounds and defaults of RHO INF. The element kernels take a
!> scheme by these numbers; rodyn_model re-exports them with the options that hold them.
module rodyn_schemes
   use rodyn_kinds, only: wp
   implicit none
   private
   public :: scheme_emc, scheme_midpoint, scheme_trapezoidal, scheme_alpha, scheme_names
   public :: edmc_rho_min, rho_inf_emc_water

   integer, parameter :: scheme_emc = 1          !< energy-momentum conserving (the paper's)
   !> the lowest RHO INF of the dissipative EMC (rodyn_numerical_dissipation, eq. (129))
   real(wp), parameter :: edmc_rho_min = 0.52_wp
   !> RHO INF of EMC in a deck with *WATER unless given (docs/dynamics.md, "Choosing the
   !> scheme"); 1 in a dry deck
   real(wp), parameter :: rho_inf_emc_water = 0.8_wp
   integer, parameter :: scheme_midpoint = 2     !< midpoint rule, stress at the midpoint
   integer, parameter :: scheme_trapezoidal = 3  !< trapezoidal rule, averaged end forces
   integer, parameter :: scheme_alpha = 4        !< dissipative, spectral radius rho_inf
   character(len=12), parameter :: scheme_names(4) = &
      [character(len=12) :: 'EMC', 'MIDPOINT', 'TRAPEZOIDAL', 'ALPHA']
end module rodyn_schemes
