!> Working precision and physical constants used across rodyn.
module rodyn_kinds
   use, intrinsic :: iso_fortran_env, only: real64, int32, int64
   implicit none
   private
   public :: wp, i8, pi, two_pi, g_standard, rodyn_version

   integer, parameter :: wp = real64          !< working real kind
   integer, parameter :: i8 = int64           !< long integer kind (counters)
   real(wp), parameter :: pi = 3.14159265358979323846264338327950288_wp
   real(wp), parameter :: two_pi = 2.0_wp*pi
   real(wp), parameter :: g_standard = 9.80665_wp   !< standard gravity [m/s2] (ISO 80000-3)
   character(len=*), parameter :: rodyn_version = '0.1.0'
end module rodyn_kinds
