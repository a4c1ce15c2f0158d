!> Linear (Airy) wave kinematics (docs/waves.md; docs/theory.md section 11, eqs.
!> (82)-(93)): a sea of components i, each of
!> amplitude A_i = H_i/2, angular frequency omega_i, heading beta_i and phase phi_i, on
!> water of constant depth d below the still water level z_s. With z' = z - z_s and
!>   theta_i = k_i (x cos beta_i + y sin beta_i) - omega_i t + phi_i,
!> the elevation, horizontal (along beta_i) and vertical velocity and acceleration are
!> (Dean & Dalrymple, "Water Wave Mechanics for Engineers and Scientists", 1991, ch. 4;
!> DNV-RP-C205, 2021, section 3.2, table 3-1)
!>   eta = sum A_i cos theta_i
!>   u_h = sum A_i omega_i C_i(s) cos theta_i,    w = sum A_i omega_i S_i(s) sin theta_i
!>   a_h = sum A_i omega_i^2 C_i(s) sin theta_i,  a_z = -sum A_i omega_i^2 S_i(s) cos theta_i
!>   C_i(s) = cosh(k_i (s + d))/sinh(k_i d),      S_i(s) = sinh(k_i (s + d))/sinh(k_i d)
!>   p_d = rho_w sum A_i (omega_i^2/k_i) C_i(s) cos theta_i
!>       = rho_w g sum A_i cosh(k_i (s + d))/cosh(k_i d) cos theta_i   (dynamic pressure)
!> with k_i from the dispersion relation omega^2 = g k tanh(k d) (wave_number) and s the
!> level the profile is evaluated at. Below the mean surface s = z'; above it, up to eta,
!> the stretching named in the deck (DNV-RP-C205 section 3.2.3):
!>   WHEELER        s = (z' - eta) d/(d + eta), for every z' (eta maps to 0, -d to -d)
!>   VERTICAL       s = min(z', 0): the values at the mean surface carried up
!>   EXTRAPOLATION  C(z') = C(0) + z' k S(0), S(z') = S(0) + z' k C(0) for z' > 0
!>   NONE           s = z': the linear profile carried up as it is
!> Below the mean surface -grad p_d = rho_w a exactly (linear theory): the
!> Froude-Krylov load rho_w A a_w is the gradient of this pressure, which the tension
!> relation uses (rodyn_hydro, sea_pressure). With WHEELER the total pressure
!> rho_w g (z_s - z) + p_d vanishes at the surface z' = eta.
!> Above eta the water has no velocity. A ramp r(t) = (1 - cos(pi t/T))/2 multiplies the
!> elevation, the velocity and p_d; the acceleration is r a + r' u. The acceleration is the
!> local one of linear theory at the stretched level (the stretch's own rate is not
!> differentiated, as is usual). The per-component factors (k cos beta, k sin beta,
!> A omega, A omega^2, the depth terms) are formed once by waves_build.
!>
!> Irregular seas (sea_components): the spectrum S(omega) between omega_min and
!> omega_max is cut into N bins of equal width d omega; component i takes a frequency
!> drawn uniformly within bin i, the amplitude A_i = sqrt(2 S(omega_i) d omega) and a
!> phase drawn uniformly in [0, 2 pi), from the seed by L'Ecuyer's combined generator
!> (Commun. ACM 31, 1988, 742-751), so that a seed gives the same sea bit for bit on
!> any machine. The random frequencies are incommensurate: the sea does not repeat
!> (components on a regular grid of spacing d omega would repeat after 2 pi/d omega).
!> Spectra (DNV-RP-C205, 2021, section 3.5.5), omega_p = 2 pi/T_p:
!>   Pierson-Moskowitz  S_PM = 5/16 Hs^2 omega_p^4 omega^-5 exp(-5/4 (omega/omega_p)^-4)
!>   JONSWAP            S_J = (1 - 0.287 ln gamma) S_PM gamma^exp(-(omega - omega_p)^2
!>                      /(2 sigma^2 omega_p^2)), sigma = 0.07 (omega <= omega_p), 0.09
!>   default gamma      5 for T_p/sqrt(Hs) <= 3.6, exp(5.75 - 1.15 T_p/sqrt(Hs)) below 5,
!>                      1 from 5 (T_p in s, Hs in m)
!>   table              linear between the points of the table, 0 outside it.
!> Directional spreading (optional; Longuet-Higgins et al. 1963, DNV-RP-C205, 2021,
!> section 3.5.8): the cos-2s distribution about the mean heading beta,
!>   D(theta) = Gamma(s + 1)/(2 sqrt(pi) Gamma(s + 1/2)) cos^(2s)((theta - beta)/2),
!> |theta - beta| <= pi, whose circular moments are E cos(theta - beta) = s/(s + 1),
!> E cos 2(theta - beta) = s (s - 1)/((s + 1)(s + 2)). It is cut into M directions of
!> equal energy at its quantiles, each keeping its bin's mean cosine (so the spread
!> is kept; spreading_directions), the same for every seed; each frequency bin i then has M
!> components (i, j), each with its own frequency drawn within the bin, amplitude
!> sqrt(2 S(omega_ij) d omega/M) and phase: N M components, no two at one frequency,
!> so the sea stays ergodic (a record at one point has the directional sea's variance).
module rodyn_waves
   use rodyn_kinds, only: wp, i8, pi, two_pi
   use rodyn_model, only: waves_t, stretch_wheeler, stretch_vertical, &
                          stretch_extrapolation, stretch_none, sea_airy, sea_jonswap, &
                          sea_pm, sea_table, sea_record
   use rodyn_fft, only: dft_real
   implicit none
   private
   public :: wave_field_t, wave_number, waves_build, wave_elevation, wave_kinematics
   public :: wave_ramp, wave_spectrum, jonswap_gamma, sea_components, spreading_directions
   public :: record_components

   real(wp), parameter :: kd_exp = 20.0_wp !< above k d the depth terms use exponentials

   !> The sea of a run, ready for evaluation (fixed after waves_build).
   type :: wave_field_t
      integer :: n = 0                        !< components
      integer :: stretching = stretch_wheeler !< stretch_* constant
      real(wp) :: depth = 0.0_wp              !< d [m]
      real(wp) :: surface = 0.0_wp            !< z_s [m]
      real(wp) :: ramp = 0.0_wp               !< ramp-in duration [s]
      real(wp), allocatable :: amp(:)    !< (n) A [m]
      real(wp), allocatable :: omega(:)  !< (n) [rad/s]
      real(wp), allocatable :: k(:)      !< (n) wave number [1/m]
      real(wp), allocatable :: kx(:)     !< (n) k cos beta [1/m]
      real(wp), allocatable :: ky(:)     !< (n) k sin beta [1/m]
      real(wp), allocatable :: cb(:)     !< (n) cos beta [-]
      real(wp), allocatable :: sb(:)     !< (n) sin beta [-]
      real(wp), allocatable :: phase(:)  !< (n) phi [rad]
      real(wp), allocatable :: aw(:)     !< (n) A omega [m/s]
      real(wp), allocatable :: aw2(:)    !< (n) A omega^2 [m/s2]
      real(wp), allocatable :: rsh(:)    !< (n) 1/sinh(k d) (k d < kd_exp) [-]
      real(wp), allocatable :: qd(:)     !< (n) 1/(1 - e^{-2 k d}) (k d >= kd_exp) [-]
      logical, allocatable :: deep(:)    !< (n) k d >= kd_exp: exponential forms
   end type wave_field_t

contains

   !> Wave number k of angular frequency omega in water of depth d: the root of the
   !> dispersion relation omega^2 = g k tanh(k d), written y tanh y = x with y = k d,
   !> x = omega^2 d/g, by Newton's method from Eckart's approximation
   !> y0 = x/sqrt(tanh x) (Eckart 1952; within 5 %), to round-off (the step below
   !> 2 eps y). Deep water (x large): y = x, k = omega^2/g; shallow (x small):
   !> y = sqrt(x), k = omega/sqrt(g d).
   !> docs/theory.md eq. (82).
   pure real(wp) function wave_number(omega, depth, g) result(k)
      real(wp), intent(in) :: omega  !< angular frequency [rad/s], > 0
      real(wp), intent(in) :: depth  !< water depth [m], > 0
      real(wp), intent(in) :: g      !< gravity [m/s2], > 0
      real(wp) :: x, y, th, dy
      integer :: it
      x = omega**2*depth/g
      y = x/sqrt(tanh(x))
      do it = 1, 60
         th = tanh(y)
         dy = (y*th - x)/(th + y*(1.0_wp - th**2))
         y = y - dy
         if (abs(dy) <= 2.0_wp*epsilon(1.0_wp)*y) exit
      end do
      k = y/depth
   end function wave_number

   !> The field of the deck's sea: per component k (wave_number), k cos beta,
   !> k sin beta, A omega, A omega^2 and 1/sinh(k d) (module header).
   !> docs/theory.md eqs. (82), (85).
   pure subroutine waves_build(waves, depth, surface, g, field)
      type(waves_t), intent(in) :: waves        !< the deck's waves
      real(wp), intent(in) :: depth             !< water depth d [m]
      real(wp), intent(in) :: surface           !< still water level z_s [m]
      real(wp), intent(in) :: g                 !< |gravity| [m/s2]
      type(wave_field_t), intent(out) :: field  !< the field
      integer :: i, n
      n = 0
      if (waves%present) n = size(waves%height)
      field%n = n
      field%stretching = waves%stretching
      field%depth = depth
      field%surface = surface
      field%ramp = waves%ramp
      allocate (field%amp(n), field%omega(n), field%k(n), field%kx(n), field%ky(n), &
                field%cb(n), field%sb(n), field%phase(n), field%aw(n), field%aw2(n), &
                field%rsh(n), field%qd(n), field%deep(n))
      do i = 1, n
         field%amp(i) = 0.5_wp*waves%height(i)
         field%omega(i) = two_pi/waves%period(i)
         field%k(i) = wave_number(field%omega(i), depth, g)
         field%cb(i) = cos(waves%heading(i))
         field%sb(i) = sin(waves%heading(i))
         field%kx(i) = field%k(i)*field%cb(i)
         field%ky(i) = field%k(i)*field%sb(i)
         field%phase(i) = waves%phase(i) - (field%kx(i)*waves%point(1) &
                                            + field%ky(i)*waves%point(2))
         field%aw(i) = field%amp(i)*field%omega(i)
         field%aw2(i) = field%aw(i)*field%omega(i)
         field%deep(i) = field%k(i)*depth >= kd_exp
         field%rsh(i) = 0.0_wp
         if (.not. field%deep(i)) field%rsh(i) = 1.0_wp/sinh(field%k(i)*depth)
         field%qd(i) = 1.0_wp/(1.0_wp - exp(-2.0_wp*field%k(i)*depth))
      end do
   end subroutine waves_build

   !> Ramp factor r(t) = (1 - cos(pi t/T))/2 for 0 < t < T (0 before, 1 after; 1 when
   !> T = 0) and its rate r'(t) = pi/(2T) sin(pi t/T).
   !> docs/theory.md eqs. (81), (87).
   pure subroutine wave_ramp(ramp, t, r, dr)
      real(wp), intent(in) :: ramp  !< T [s]
      real(wp), intent(in) :: t     !< time [s]
      real(wp), intent(out) :: r    !< r(t) [-]
      real(wp), intent(out) :: dr   !< r'(t) [1/s]
      r = 1.0_wp
      dr = 0.0_wp
      if (ramp <= 0.0_wp .or. t >= ramp) return
      if (t <= 0.0_wp) then
         r = 0.0_wp
         return
      end if
      r = 0.5_wp*(1.0_wp - cos(pi*t/ramp))
      dr = 0.5_wp*pi/ramp*sin(pi*t/ramp)
   end subroutine wave_ramp

   !> Elevation eta of the surface above the still water level at (x, y), time t, ramp
   !> included [m] (module header).
   !> docs/theory.md eq. (83).
   pure real(wp) function wave_elevation(field, x, y, t) result(eta)
      type(wave_field_t), intent(in) :: field !< the sea
      real(wp), intent(in) :: x               !< [m]
      real(wp), intent(in) :: y               !< [m]
      real(wp), intent(in) :: t               !< time [s]
      real(wp) :: r, dr
      integer :: i
      eta = 0.0_wp
      do i = 1, field%n
         eta = eta + field%amp(i)*cos(field%kx(i)*x + field%ky(i)*y - field%omega(i)*t &
                                      + field%phase(i))
      end do
      call wave_ramp(field%ramp, t, r, dr)
      eta = r*eta
   end function wave_elevation

   !> Elevation eta above (x, y), water velocity u and acceleration a at point x and
   !> time t, and the wave's dynamic pressure over the water's density (module header:
   !> linear theory, the stretching above the mean surface, ramp included; zero above
   !> the surface).
   !> docs/theory.md eqs. (83)-(87), (122).
   pure subroutine wave_kinematics(field, x, t, eta, u, a, pd)
      type(wave_field_t), intent(in) :: field !< the sea
      real(wp), intent(in) :: x(3)            !< point [m]
      real(wp), intent(in) :: t               !< time [s]
      real(wp), intent(out) :: eta            !< surface elevation above z_s [m]
      real(wp), intent(out) :: u(3)           !< water velocity [m/s]
      real(wp), intent(out) :: a(3)           !< water acceleration [m/s2]
      real(wp), intent(out), optional :: pd   !< dynamic pressure / rho_w [m2/s2]
      real(wp) :: r, dr, zp, s, ch, sh, c, uh, ah, w, az, d, ext, th, q
      real(wp) :: cs(field%n), sn(field%n)
      integer :: i
      u = 0.0_wp
      a = 0.0_wp
      q = 0.0_wp
      if (present(pd)) pd = 0.0_wp
      ! the phases once: their cosines make eta, and serve the kinematics below
      eta = 0.0_wp
      do i = 1, field%n
         th = field%kx(i)*x(1) + field%ky(i)*x(2) - field%omega(i)*t + field%phase(i)
         cs(i) = cos(th)
         sn(i) = sin(th)
         eta = eta + field%amp(i)*cs(i)
      end do
      call wave_ramp(field%ramp, t, r, dr)
      eta = r*eta
      if (field%n == 0) return
      zp = x(3) - field%surface
      if (zp > eta) return
      if (r == 0.0_wp) return
      d = field%depth
      ext = 0.0_wp
      select case (field%stretching)
      case (stretch_wheeler)
         s = (zp - eta)*d/(d + eta)
      case (stretch_vertical)
         s = min(zp, 0.0_wp)
      case (stretch_extrapolation)
         s = min(zp, 0.0_wp)
         ext = max(zp, 0.0_wp)
      case default
         s = zp
      end select
      do i = 1, field%n
         call depth_terms(field, i, s, ch, sh)
         if (ext > 0.0_wp) then
            ! C(z') = C(0) + z' k S(0), S(z') = S(0) + z' k C(0)
            c = ch
            ch = ch + ext*field%k(i)*sh
            sh = sh + ext*field%k(i)*c
         end if
         uh = field%aw(i)*ch*cs(i)
         ! p_d/rho = g eta_i cosh(k (s + d))/cosh(k d) = (A omega^2/k) C cos theta
         q = q + field%aw2(i)/field%k(i)*ch*cs(i)
         w = field%aw(i)*sh*sn(i)
         ah = field%aw2(i)*ch*sn(i)
         az = -field%aw2(i)*sh*cs(i)
         u(1) = u(1) + uh*field%cb(i)
         u(2) = u(2) + uh*field%sb(i)
         u(3) = u(3) + w
         a(1) = a(1) + ah*field%cb(i)
         a(2) = a(2) + ah*field%sb(i)
         a(3) = a(3) + az
      end do
      a = r*a + dr*u
      u = r*u
      if (present(pd)) pd = r*q
   end subroutine wave_kinematics

   !> C = cosh(k (s + d))/sinh(k d) and S = sinh(k (s + d))/sinh(k d) of component i,
   !> from one exponential E = e^{k (s + d)}: (E +- 1/E)/(2 sinh(k d)); for k d >= kd_exp
   !> (e^{k s} +- e^{-k (s + 2 d)})/(1 - e^{-2 k d}), which neither overflows nor loses
   !> digits in deep water.
   !> docs/theory.md eq. (85).
   pure subroutine depth_terms(field, i, s, ch, sh)
      type(wave_field_t), intent(in) :: field !< the sea
      integer, intent(in) :: i                !< component
      real(wp), intent(in) :: s               !< level below the mean surface [m]
      real(wp), intent(out) :: ch             !< C [-]
      real(wp), intent(out) :: sh             !< S [-]
      real(wp) :: e1, e2
      if (field%deep(i)) then
         e1 = exp(field%k(i)*s)
         e2 = exp(-field%k(i)*(s + 2.0_wp*field%depth))
         ch = (e1 + e2)*field%qd(i)
         sh = (e1 - e2)*field%qd(i)
      else
         e1 = exp(field%k(i)*(s + field%depth))
         e2 = 1.0_wp/e1
         ch = 0.5_wp*(e1 + e2)*field%rsh(i)
         sh = 0.5_wp*(e1 - e2)*field%rsh(i)
      end if
   end subroutine depth_terms

   !> DNV-RP-C205's default JONSWAP peak enhancement gamma for Hs and T_p (header).
   !> docs/theory.md eq. (91).
   pure real(wp) function jonswap_gamma(hs, tp) result(gamma)
      real(wp), intent(in) :: hs  !< significant wave height [m]
      real(wp), intent(in) :: tp  !< peak period [s]
      real(wp) :: r
      r = tp/sqrt(hs)
      if (r <= 3.6_wp) then
         gamma = 5.0_wp
      else if (r < 5.0_wp) then
         gamma = exp(5.75_wp - 1.15_wp*r)
      else
         gamma = 1.0_wp
      end if
   end function jonswap_gamma

   !> Spectral density S(omega) of the sea (module header) [m2 s/rad].
   !> docs/theory.md eqs. (89)-(90).
   pure real(wp) function wave_spectrum(waves, omega) result(s)
      type(waves_t), intent(in) :: waves  !< the sea (kind, Hs, Tp, gamma or table)
      real(wp), intent(in) :: omega       !< frequency [rad/s], > 0
      real(wp) :: wpk, sigma, f
      integer :: j, n
      s = 0.0_wp
      select case (waves%kind)
      case (sea_jonswap, sea_pm)
         wpk = two_pi/waves%tp
         s = 5.0_wp/16.0_wp*waves%hs**2*wpk**4/omega**5*exp(-1.25_wp*(wpk/omega)**4)
         if (waves%kind == sea_jonswap .and. waves%gamma /= 1.0_wp) then
            sigma = 0.09_wp
            if (omega <= wpk) sigma = 0.07_wp
            s = s*(1.0_wp - 0.287_wp*log(waves%gamma)) &
                *waves%gamma**exp(-0.5_wp*((omega - wpk)/(sigma*wpk))**2)
         end if
      case (sea_table)
         n = size(waves%tab_omega)
         if (omega < waves%tab_omega(1) .or. omega > waves%tab_omega(n)) return
         do j = 1, n - 1
            if (omega <= waves%tab_omega(j + 1)) exit
         end do
         j = min(j, n - 1)
         f = (omega - waves%tab_omega(j))/(waves%tab_omega(j + 1) - waves%tab_omega(j))
         s = waves%tab_s(j) + f*(waves%tab_s(j + 1) - waves%tab_s(j))
      end select
   end function wave_spectrum

   !> The components of an irregular sea (module header): height H_i = 2 A_i, period,
   !> phase and heading, into waves%height, period, phase, heading (n =
   !> waves%components x waves%directions, bin by bin, the directions within a bin
   !> innermost; one direction: the long-crested sea). A regular wave (sea_airy) is left
   !> as it is.
   !> docs/theory.md eq. (88).
   pure subroutine sea_components(waves)
      type(waves_t), intent(inout) :: waves !< the sea; its components set
      integer(i8) :: s1, s2
      real(wp) :: dw, om, beta, u
      real(wp), allocatable :: theta(:)
      integer :: i, j, n, m, ic
      if (waves%kind == sea_airy .or. waves%kind == sea_record) return
      n = waves%components
      m = max(waves%directions, 1)
      beta = 0.0_wp
      if (allocated(waves%heading)) then
         if (size(waves%heading) > 0) beta = waves%heading(1)
      end if
      allocate (theta(m))
      theta = 0.0_wp
      if (m > 1 .and. waves%spreading > 0.0_wp) &
         call spreading_directions(waves%spreading, m, theta)
      ! the generator's two states from the seed (L'Ecuyer's ranges 1..m - 1)
      s1 = 1_i8 + modulo(int(waves%seed, i8), 2147483562_i8)
      s2 = 1_i8 + modulo(int(waves%seed, i8)*7919_i8 + 12345_i8, 2147483398_i8)
      dw = (waves%omega_max - waves%omega_min)/real(n, wp)
      if (allocated(waves%height)) deallocate (waves%height)
      if (allocated(waves%period)) deallocate (waves%period)
      if (allocated(waves%phase)) deallocate (waves%phase)
      if (allocated(waves%heading)) deallocate (waves%heading)
      allocate (waves%height(n*m), waves%period(n*m), waves%phase(n*m), &
                waves%heading(n*m))
      ic = 0
      do i = 1, n
         do j = 1, m
            ic = ic + 1
            call lecuyer_next(s1, s2, u)
            om = waves%omega_min + dw*(real(i - 1, wp) + u)
            waves%period(ic) = two_pi/om
            waves%height(ic) = 2.0_wp*sqrt(2.0_wp*wave_spectrum(waves, om)*dw/real(m, wp))
            call lecuyer_next(s1, s2, u)
            waves%phase(ic) = two_pi*u
            waves%heading(ic) = beta + theta(j)
         end do
      end do
   end subroutine sea_components

   !> The M directions of equal energy of the cos-2s distribution (module header),
   !> relative to the mean heading [rad]: the distribution cut at its quantiles
   !> F^-1(j/M), j = 1..M-1, each bin j taking the angle whose cosine is the bin's mean
   !> cosine, theta_j = acos(E[cos x | bin j]) (in the bin, as cos is monotonic there),
   !> so that sum cos(theta_j)/M = E cos x = s/(s + 1): the first circular moment, and
   !> with it the spread sqrt(2 (1 - E cos x)), kept (the middle bin of an odd M at 0 by
   !> symmetry, a departure of a few 1e-4 of the variance). F and the integrals by the
   !> trapezoidal rule of cos^(2s)(x/2) and its product with cos x on ng intervals of
   !> [0, x_max] (x_max = pi, or where the density is below e^-80 of its peak), linear
   !> within an interval. theta_j = -theta_(M+1-j) exactly.
   !> docs/theory.md eq. (92).
   pure subroutine spreading_directions(s, m, theta)
      real(wp), intent(in) :: s          !< spreading exponent, > 0 [-]
      integer, intent(in) :: m           !< number of directions, >= 1
      real(wp), intent(out) :: theta(m)  !< directions relative to the mean [rad]
      integer, parameter :: ng = 20000
      real(wp), allocatable :: cum(:), cumc(:)
      real(wp) :: f0, f1, h, xmax, clo, chi, elo, ehi
      integer :: j, k
      theta = 0.0_wp
      xmax = min(pi, 2.0_wp*acos(exp(-40.0_wp/s)))
      if (.not. xmax > 0.0_wp) return  ! s so large that the spread is below round-off
      allocate (cum(0:ng), cumc(0:ng))
      h = xmax/real(ng, wp)
      cum(0) = 0.0_wp
      cumc(0) = 0.0_wp
      f0 = 1.0_wp
      do k = 1, ng
         f1 = density(h*real(k, wp))
         cum(k) = cum(k - 1) + 0.5_wp*h*(f0 + f1)
         cumc(k) = cumc(k - 1) + 0.5_wp*h*(f0*cos(h*real(k - 1, wp)) + f1*cos(h*real(k, wp)))
         f0 = f1
      end do
      cumc = cumc/cum(ng)
      cum = cum/cum(ng)
      ! the upper half: bin j holds the probabilities [(j - 1)/M, j/M], that is
      ! [2 (j - 1)/M - 1, 2 j/M - 1] of [0, pi]; mirrored below
      do j = m/2 + 1 + modulo(m, 2), m
         call cut(max(0.0_wp, 2.0_wp*real(j - 1, wp)/real(m, wp) - 1.0_wp), clo, elo)
         call cut(2.0_wp*real(j, wp)/real(m, wp) - 1.0_wp, chi, ehi)
         theta(j) = acos(min(1.0_wp, (ehi - elo)/(chi - clo)))
         theta(m + 1 - j) = -theta(j)
      end do
   contains
      !> cos^(2s)(x/2), 0 where it underflows.
      pure real(wp) function density(x)
         real(wp), intent(in) :: x !< angle [rad]
         real(wp) :: c
         density = 0.0_wp
         c = cos(0.5_wp*x)
         if (c <= 0.0_wp) return
         density = exp(2.0_wp*s*log(c))
      end function density
      !> The grid's F = p and the integral of f cos x up to the same point.
      pure subroutine cut(p, c, e)
         real(wp), intent(in) :: p   !< probability within [0, pi]
         real(wp), intent(out) :: c  !< F there (p, up to the grid's resolution)
         real(wp), intent(out) :: e  !< integral of f cos x up to there (normalised)
         real(wp) :: r
         integer :: kk
         kk = 1
         do while (kk < ng .and. cum(kk) < p)
            kk = kk + 1
         end do
         r = 0.0_wp
         if (cum(kk) > cum(kk - 1)) r = min(1.0_wp, max(0.0_wp, &
                                             (p - cum(kk - 1))/(cum(kk) - cum(kk - 1))))
         c = cum(kk - 1) + r*(cum(kk) - cum(kk - 1))
         e = cumc(kk - 1) + r*(cumc(kk) - cumc(kk - 1))
      end subroutine cut
   end subroutine spreading_directions

   !> The Airy components of an elevation record eta(t_m), t_m = t_0 + m dt, m = 0..n-1
   !> (module header; docs/waves.md): with X_k its DFT (rodyn_fft), the record's Fourier
   !> series eta_m = X_0/n + sum_k (2|X_k|/n) cos(omega_k (t_m - t_0) + arg X_k),
   !> omega_k = 2 pi k/(n dt), k = 1..(n-1)/2, and for an even n the last term
   !> (|X_{n/2}|/n) cos(pi m + arg X_{n/2}). Component k: H = 2 A_k, T = 2 pi/omega_k,
   !> phase phi_k = omega_k t_0 - arg X_k (so that -omega t + phi is the series' angle at
   !> the record's point, waves%point, where waves_build refers the phases to), heading
   !> the sea's. The mean X_0/n is not a wave: it is kept in waves%mean and left out.
   !> docs/theory.md eq. (93).
   pure subroutine record_components(t0, dt, eta, waves)
      real(wp), intent(in) :: t0             !< time of the first sample [s]
      real(wp), intent(in) :: dt             !< sampling interval [s], > 0
      real(wp), intent(in) :: eta(:)         !< (n >= 2) the record [m]
      type(waves_t), intent(inout) :: waves  !< the sea: its components set
      complex(wp), allocatable :: xk(:)
      real(wp) :: beta, om, a
      integer :: n, nc, k
      n = size(eta)
      beta = 0.0_wp
      if (allocated(waves%heading)) then
         if (size(waves%heading) > 0) beta = waves%heading(1)
      end if
      allocate (xk(0:n - 1))
      call dft_real(eta, xk)
      nc = n/2
      if (allocated(waves%height)) deallocate (waves%height)
      if (allocated(waves%period)) deallocate (waves%period)
      if (allocated(waves%phase)) deallocate (waves%phase)
      if (allocated(waves%heading)) deallocate (waves%heading)
      allocate (waves%height(nc), waves%period(nc), waves%phase(nc), waves%heading(nc))
      waves%mean = real(xk(0), wp)/real(n, wp)
      do k = 1, nc
         om = two_pi*real(k, wp)/(real(n, wp)*dt)
         a = 2.0_wp*abs(xk(k))/real(n, wp)
         if (2*k == n) a = 0.5_wp*a
         waves%height(k) = 2.0_wp*a
         waves%period(k) = two_pi/om
         waves%phase(k) = om*t0 - atan2(aimag(xk(k)), real(xk(k), wp))
         waves%heading(k) = beta
      end do
      waves%components = nc
   end subroutine record_components

   !> Next number u in (0, 1) of L'Ecuyer's combined generator (1988): two
   !> multiplicative congruential generators, s1 = 40014 s1 mod 2147483563,
   !> s2 = 40692 s2 mod 2147483399, z = (s1 - s2) mod 2147483562; products below 2^47,
   !> exact in 64-bit integers.
   !> docs/theory.md section 11 (irregular seas).
   pure subroutine lecuyer_next(s1, s2, u)
      integer(i8), intent(inout) :: s1 !< state of the first generator
      integer(i8), intent(inout) :: s2 !< state of the second generator
      real(wp), intent(out) :: u       !< the number [-]
      integer(i8) :: z
      s1 = modulo(40014_i8*s1, 2147483563_i8)
      s2 = modulo(40692_i8*s2, 2147483399_i8)
      z = modulo(s1 - s2, 2147483562_i8)
      if (z == 0_i8) z = 2147483562_i8
      u = real(z, wp)/2147483563.0_wp
   end subroutine lecuyer_next
end module rodyn_waves
