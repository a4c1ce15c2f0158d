!> Distributed loads of the water and the seabed at one point of a line (docs/water.md;
!> docs/theory.md eqs. (67)-(71), (96)-(97)), per unit UNSTRETCHED length, with their
!> derivatives for the Newton tangent.
!>
!> With t = x'/|x'| the unit tangent, lambda = |x'| the stretch, u the water velocity,
!> a_w its acceleration, v and a the line's velocity and acceleration, u_r = u - v:
!>   buoyancy     f_b = rho_w g A_b phi(h) e_z,   h = z_s - z the depth of the centre,
!>                phi(h) = 1 - [acos(h/r) - (h/r) sqrt(1 - (h/r)^2)]/pi  (|h| < r = D_b/2)
!>                the submerged fraction of a horizontal circular section (1 below, 0 above)
!>   drag         f_d = 1/2 rho_w C_dn D_d lambda |u_n| u_n + 1/2 rho_w C_da pi D_d lambda
!>                |u_t| u_t,   u_t = (u_r.t) t, u_n = u_r - u_t  (drag on the stretched
!>                length; the axial coefficient acts on the surface, pi D_d, as in MoorDyn)
!>   inertia      f_a = rho_w A_b [(1 + C_an) P + (1 + C_aa) t t] a_w - rho_w A_b [C_an P
!>                + C_aa t t] a,   P = I - t t: the Froude-Krylov force rho_w A_b a_w =
!>                -A_b grad p_d of the wave's pressure (all three components, as the
!>                buoyancy is the whole hydrostatic gradient) and the added mass on the
!>                relative acceleration a_w - a (a steady current has a_w = 0)
!>   seabed       f_s = N n,  N = max(0, (k pen - c v.n) D_b),  pen = -gap
!>   friction     f_f = -mu_ax N v_ax / max(|v_ax|, v_mob) - mu_lat N v_lat /
!>                max(|v_lat|, v_mob), v_ax, v_lat the axial and lateral parts of the
!>                velocity in the seabed plane (dynamics only)
!> In a wave (env%wave, and the argument wk) the wave's water velocity and acceleration
!> are added to the current's and the surface is the instantaneous one, z_s + eta: all
!> given per point, interpolated from the nodes where they were evaluated once per step
!> (rodyn_water), and held fixed within the step (no derivative in x).
!> A_b = pi D_b^2/4. Buoyancy and added mass act per unstretched length (the volume of
!> the line is taken as conserved when it stretches).
!> These loads are the whole gradient of the sea pressure p = rho_w g (z_s - z) + p_d
!> (sea_pressure, zero above the instantaneous surface z_s + eta): the line's tension
!> is then the effective tension T_e, and the wall tension is T_w = T_e - p A_b + p_i A_i
!> with this p (docs/theory.md eqs. (77)-(79), (122)-(123)).
module rodyn_hydro
   use rodyn_kinds, only: wp, pi
   use rodyn_model, only: water_t
   use rodyn_environment, only: fluid_kinematics
   use rodyn_rotation, only: norm3
   implicit none
   private
   public :: water_section_t, water_env_t, water_point_load, submerged_fraction
   public :: part_water, part_seabed, seabed_normal_force, sea_pressure
   public :: n_wk, outer

   !> Values per point of a wave's state (wkin): velocity (1:3) [m/s], acceleration
   !> (4:6) [m/s2], elevation eta (7) [m]
   integer, parameter :: n_wk = 7

   integer, parameter :: part_water = 1   !< water_point_load: buoyancy, drag, inertia
   integer, parameter :: part_seabed = 2  !< water_point_load: seabed contact and friction
   real(wp), parameter :: eye(3, 3) = reshape([1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, &
                                               0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [3, 3])

   !> Per section: the constants of the laws above.
   type :: water_section_t
      real(wp) :: fb = 0.0_wp   !< rho_w g A_b [N/m]
      real(wp) :: rb = 0.0_wp   !< D_b / 2 [m]
      real(wp) :: cn = 0.0_wp   !< 1/2 rho_w C_dn D_d [kg/m2]
      real(wp) :: ct = 0.0_wp   !< 1/2 rho_w C_da pi D_d [kg/m2]
      real(wp) :: man = 0.0_wp  !< rho_w A_b C_an [kg/m]
      real(wp) :: maa = 0.0_wp  !< rho_w A_b C_aa [kg/m]
      real(wp) :: mw = 0.0_wp   !< rho_w A_b [kg/m]
      real(wp) :: dc = 0.0_wp   !< contact width D_b [m]
   end type water_section_t

   !> The water and seabed as the point law needs them, with the state of the step.
   type :: water_env_t
      type(water_t) :: water             !< water and current profile
      real(wp) :: r_current = 1.0_wp     !< current ramp factor at the force time [-]
      real(wp) :: gmag = 0.0_wp          !< |g| [m/s2]
      logical :: dynamic = .false.       !< seabed damping and friction (not in statics)
      logical :: seabed = .false.        !< a seabed is present
      real(wp) :: n(3) = [0.0_wp, 0.0_wp, 1.0_wp] !< seabed outward normal
      real(wp) :: c0 = 0.0_wp            !< seabed plane: gap = n.x - c0 [m]
      real(wp) :: k = 0.0_wp             !< normal stiffness per contact area [Pa/m]
      real(wp) :: c = 0.0_wp             !< normal damping per contact area [Pa s/m]
      real(wp) :: mu_ax = 0.0_wp         !< axial friction coefficient [-]
      real(wp) :: mu_lat = 0.0_wp        !< lateral friction coefficient [-]
      real(wp) :: v_mob = 0.01_wp        !< mobilisation velocity [m/s]
      logical :: wave = .false.          !< the step has waves: wk of water_point_load used
   end type water_env_t

   !> The line at a point: its motion and direction (line_point).
   type :: line_point_t
      real(wp) :: x(3)        !< position [m]
      real(wp) :: v(3)        !< velocity [m/s]
      real(wp) :: acc(3)      !< acceleration [m/s2]
      real(wp) :: lam         !< stretch |x'| [-]
      real(wp) :: t(3)        !< unit tangent x'/|x'| [-]
      real(wp) :: tt(3, 3)    !< t t^T (with the derivatives only) [-]
      real(wp) :: pm(3, 3)    !< P = I - t t^T (with the derivatives only) [-]
   end type line_point_t

   !> A force per unstretched length at a point and its derivatives with respect to the
   !> position x, the tangent x', the velocity v and the acceleration a of the line.
   type :: point_force_t
      real(wp) :: f(3)        !< force [N/m]
      real(wp) :: kx(3, 3)    !< df/dx [N/m2]
      real(wp) :: kxp(3, 3)   !< df/dx' [N/m]
      real(wp) :: kv(3, 3)    !< df/dv [N s/m2]
      real(wp) :: ka(3, 3)    !< df/da [kg/m]
   end type point_force_t

   !> The seabed's normal force at a point in contact (water_point_load).
   type :: seabed_contact_t
      real(wp) :: vn          !< velocity along the seabed normal [m/s]
      real(wp) :: nf          !< normal force N [N/m]
      real(wp) :: dnx         !< dN/dgap [N/m2]
      real(wp) :: dnv         !< dN/dvn [N s/m2]
   end type seabed_contact_t

contains

   !> The sea pressure at height z [Pa]: hydrostatic below the still water level z_s
   !> plus the wave's dynamic pressure p_d = rho_w pd (rodyn_waves, wave_kinematics),
   !> zero above the instantaneous surface z_s + eta. The one pressure of the sea: its
   !> gradient is the buoyancy and the Froude-Krylov load of water_point_load, and it is
   !> the outer pressure of the wall tension (rodyn_recovery).
   !> docs/theory.md eqs. (122)-(123).
   pure real(wp) function sea_pressure(rho, gmag, zs, z, eta, pd) result(p)
      real(wp), intent(in) :: rho   !< water density [kg/m3]
      real(wp), intent(in) :: gmag  !< |g| [m/s2]
      real(wp), intent(in) :: zs    !< still water level [m]
      real(wp), intent(in) :: z     !< height of the point [m]
      real(wp), intent(in) :: eta   !< surface elevation above z_s there [m]
      real(wp), intent(in) :: pd    !< dynamic pressure over density [m2/s2]
      p = 0.0_wp
      if (z > zs + eta) return
      p = max(rho*(gmag*(zs - z) + pd), 0.0_wp)
   end function sea_pressure

   !> Submerged fraction phi(h) of a circle of radius r whose centre is h below the
   !> surface, and dphi/dh (module header; docs/theory.md eq. (69)).
   pure subroutine submerged_fraction(h, r, phi, dphi)
      real(wp), intent(in) :: h     !< depth of the centre below the surface [m]
      real(wp), intent(in) :: r     !< radius [m]
      real(wp), intent(out) :: phi  !< fraction [-]
      real(wp), intent(out) :: dphi !< dphi/dh [1/m]
      real(wp) :: q
      dphi = 0.0_wp
      if (h >= r) then
         phi = 1.0_wp
         if (h == 0.0_wp) phi = 0.5_wp
      else if (h <= -r) then
         phi = 0.0_wp
      else
         q = h/r
         phi = 1.0_wp - (acos(q) - q*sqrt(1.0_wp - q**2))/pi
         dphi = 2.0_wp*sqrt(1.0_wp - q**2)/(pi*r)
      end if
   end subroutine submerged_fraction

   !> Water and seabed force per unstretched length at a point (module header): fh from
   !> the water, fs from the seabed; with want_k their derivatives with respect to the
   !> position x, the tangent x', the velocity v and the acceleration a of the line.
   !> docs/theory.md eqs. (68)-(71), (96)-(97).
   pure subroutine water_point_load(env, ws, x, xp, v, acc, fh, fs, kx, kxp, kv, ka, want_k, &
                                    parts, wk)
      type(water_env_t), intent(in) :: env      !< environment
      type(water_section_t), intent(in) :: ws   !< section constants
      real(wp), intent(in) :: x(3)              !< position [m]
      real(wp), intent(in) :: xp(3)             !< x' = dx/dS [-]
      real(wp), intent(in) :: v(3)              !< velocity [m/s]
      real(wp), intent(in) :: acc(3)            !< acceleration [m/s2]
      real(wp), intent(out) :: fh(3)            !< water force [N/m]
      real(wp), intent(out) :: fs(3)            !< seabed force [N/m]
      real(wp), intent(out) :: kx(3, 3)         !< d(fh + fs)/dx [N/m2]
      real(wp), intent(out) :: kxp(3, 3)        !< d(fh + fs)/dx' [N/m]
      real(wp), intent(out) :: kv(3, 3)         !< d(fh + fs)/dv [N s/m2]
      real(wp), intent(out) :: ka(3, 3)         !< d(fh + fs)/da [kg/m]
      logical, intent(in) :: want_k             !< form the derivatives
      integer, intent(in) :: parts              !< part_water, part_seabed or both (sum)
      real(wp), intent(in), optional :: wk(n_wk) !< wave velocity [m/s], acceleration
                                                 !< [m/s2] and elevation eta [m]
      type(line_point_t) :: lp
      type(seabed_contact_t) :: sc
      logical :: wave
      real(wp) :: gap
      fh = 0.0_wp
      fs = 0.0_wp
      if (want_k) then
         kx = 0.0_wp
         kxp = 0.0_wp
         kv = 0.0_wp
         ka = 0.0_wp
      end if
      wave = .false.
      if (present(wk)) wave = env%wave
      call line_point(x, xp, v, acc, want_k, lp)
      if (iand(parts, part_water) /= 0) &
         call water_load(env, ws, lp, want_k, wave, fh, kx, kxp, kv, ka, wk)
      ! seabed: the normal force (docs/theory.md eq. (96))
      if (iand(parts, part_seabed) == 0 .or. .not. env%seabed) return
      gap = dot_product(env%n, x) - env%c0
      sc%vn = dot_product(v, env%n)
      call seabed_normal_force(env, ws%dc, gap, sc%vn, sc%nf, sc%dnx, sc%dnv)
      if (sc%nf <= 0.0_wp) return
      fs = sc%nf*env%n
      if (want_k) then
         kx = kx + outer(env%n, sc%dnx*env%n)
         kv = kv + outer(env%n, sc%dnv*env%n)
      end if
      ! regularised Coulomb friction in the seabed plane (module header), dynamics only
      if (.not. env%dynamic .or. (env%mu_ax <= 0.0_wp .and. env%mu_lat <= 0.0_wp)) return
      call seabed_friction(env, lp, sc, want_k, fs, kx, kxp, kv)
   end subroutine water_point_load

   !> The line at a point: position, velocity and acceleration, stretch, unit tangent,
   !> and with want_k the projections t t^T and P = I - t t^T. These enter the
   !> derivatives only: the forces are formed from vectors (a residual without its
   !> tangent: 4 iterations in 5 of a step with reused tangents). docs/theory.md section
   !> 9 (notation).
   pure subroutine line_point(x, xp, v, acc, want_k, lp)
      real(wp), intent(in) :: x(3)              !< position [m]
      real(wp), intent(in) :: xp(3)             !< x' = dx/dS [-]
      real(wp), intent(in) :: v(3)              !< velocity [m/s]
      real(wp), intent(in) :: acc(3)            !< acceleration [m/s2]
      logical, intent(in) :: want_k             !< form the projections
      type(line_point_t), intent(out) :: lp     !< the line there
      integer :: i
      lp%x = x
      lp%v = v
      lp%acc = acc
      lp%lam = norm3(xp)
      lp%t = xp/lp%lam
      if (want_k) then
         do i = 1, 3
            lp%tt(:, i) = lp%t*lp%t(i)
            lp%pm(:, i) = eye(:, i) - lp%tt(:, i)
         end do
      end if
   end subroutine line_point

   !> The water's part of water_point_load, added to fh and its derivatives: buoyancy
   !> (docs/theory.md eqs. (68)-(69)), and on the submerged fraction drag (70), added
   !> mass and Froude-Krylov (71).
   pure subroutine water_load(env, ws, lp, want_k, wave, fh, kx, kxp, kv, ka, wk)
      type(water_env_t), intent(in) :: env       !< environment
      type(water_section_t), intent(in) :: ws    !< section constants
      type(line_point_t), intent(in) :: lp       !< the line at the point
      logical, intent(in) :: want_k              !< form the derivatives
      logical, intent(in) :: wave                !< wk holds the wave's state
      real(wp), intent(inout) :: fh(3)           !< water force [N/m]
      real(wp), intent(inout) :: kx(3, 3)        !< dfh/dx [N/m2]
      real(wp), intent(inout) :: kxp(3, 3)       !< dfh/dx' [N/m]
      real(wp), intent(inout) :: kv(3, 3)        !< dfh/dv [N s/m2]
      real(wp), intent(inout) :: ka(3, 3)        !< dfh/da [kg/m]
      real(wp), intent(in), optional :: wk(n_wk) !< wave velocity [m/s], acceleration
                                                 !< [m/s2] and elevation eta [m]
      type(point_force_t) :: fd
      real(wp) :: h, phi, dphi
      ! buoyancy; drag and inertia act on the submerged fraction too
      h = env%water%surface - lp%x(3)
      if (wave) h = h + wk(7)
      call submerged_fraction(h, ws%rb, phi, dphi)
      if (ws%fb > 0.0_wp) then
         fh(3) = ws%fb*phi
         if (want_k) kx(3, 3) = -ws%fb*dphi
      end if
      if (.not. (phi > 0.0_wp)) return
      fd%f = 0.0_wp
      if (want_k) then
         fd%kx = 0.0_wp
         fd%kxp = 0.0_wp
         fd%kv = 0.0_wp
         fd%ka = 0.0_wp
      end if
      if (ws%cn > 0.0_wp .or. ws%ct > 0.0_wp) &
         call drag_load(env, ws, lp, want_k, wave, fd, wk)
      if (ws%man > 0.0_wp .or. ws%maa > 0.0_wp) call added_mass_load(ws, lp, want_k, fd)
      if (wave) call froude_krylov_load(ws, wk(4:6), lp, want_k, fd)
      fh = fh + phi*fd%f
      if (want_k) then
         kx = kx + phi*fd%kx
         kx(:, 3) = kx(:, 3) - dphi*fd%f
         kxp = kxp + phi*fd%kxp
         kv = kv + phi*fd%kv
         ka = ka + phi*fd%ka
      end if
   end subroutine water_load

   !> Morison drag on the stretched length into fd (its force and derivatives set), with
   !> the wave's velocity added to the current's. docs/theory.md eq. (70).
   pure subroutine drag_load(env, ws, lp, want_k, wave, fd, wk)
      type(water_env_t), intent(in) :: env       !< environment
      type(water_section_t), intent(in) :: ws    !< section constants
      type(line_point_t), intent(in) :: lp       !< the line at the point
      logical, intent(in) :: want_k              !< form the derivatives
      logical, intent(in) :: wave                !< wk holds the wave's state
      type(point_force_t), intent(inout) :: fd   !< drag [N/m] and its derivatives
      real(wp), intent(in), optional :: wk(n_wk) !< wave velocity [m/s], acceleration
                                                 !< [m/s2] and elevation eta [m]
      real(wp) :: u(3), dudx(3, 3), aw(3), ur(3), s, un(3), unm, g(3, 3), gn(3, 3), m(3, 3)
      call fluid_kinematics(env%water, env%r_current, lp%x, u, dudx, aw)
      if (wave) u = u + wk(1:3)
      ur = u - lp%v
      s = dot_product(ur, lp%t)
      un = ur - s*lp%t
      unm = norm3(un)
      fd%f = ws%cn*lp%lam*unm*un + ws%ct*lp%lam*abs(s)*s*lp%t
      if (.not. want_k) return
      ! g = d f_d / d u_r
      gn = unm*eye
      if (unm > 0.0_wp) gn = gn + outer(un, un)/unm
      g = ws%cn*lp%lam*mm3(gn, lp%pm) + 2.0_wp*ws%ct*lp%lam*abs(s)*lp%tt
      fd%kv = -g
      fd%kx = mm3(g, dudx)
      ! (named 3 x 3 locals: matmul of array expressions would take heap
      ! temporaries at every point)
      m = outer(lp%t, ur)
      fd%kxp = ws%cn*(unm*outer(un, lp%t) - mm3(mm3(gn, m + s*eye), lp%pm)) &
               + ws%ct*(abs(s)*s*lp%tt + mm3(2.0_wp*abs(s)*m + abs(s)*s*eye, lp%pm))
   end subroutine drag_load

   !> The added mass's force on the line's acceleration, -rho A [C_an P + C_aa t t] a,
   !> added to fd. docs/theory.md eq. (71).
   pure subroutine added_mass_load(ws, lp, want_k, fd)
      type(water_section_t), intent(in) :: ws    !< section constants
      type(line_point_t), intent(in) :: lp       !< the line at the point
      logical, intent(in) :: want_k              !< form the derivatives
      type(point_force_t), intent(inout) :: fd   !< force [N/m] and its derivatives
      real(wp) :: ta, m(3, 3)
      ! [C_an P + C_aa t t] a = C_an a + (C_aa - C_an) (t.a) t
      ta = dot_product(lp%t, lp%acc)
      fd%f = fd%f - ws%man*lp%acc - (ws%maa - ws%man)*ta*lp%t
      if (.not. want_k) return
      fd%ka = -(ws%man*lp%pm + ws%maa*lp%tt)
      m = outer(lp%t, lp%acc) + ta*eye     ! (a local: no heap temporary)
      fd%kxp = fd%kxp - (ws%maa - ws%man)*mm3(m, lp%pm)/lp%lam
   end subroutine added_mass_load

   !> The wave's Froude-Krylov and added-mass force on the water's acceleration a_w,
   !> rho A [(1 + C_an) P + (1 + C_aa) t t] a_w, added to fd. docs/theory.md eq. (71).
   pure subroutine froude_krylov_load(ws, aw, lp, want_k, fd)
      type(water_section_t), intent(in) :: ws    !< section constants
      real(wp), intent(in) :: aw(3)              !< water acceleration [m/s2]
      type(line_point_t), intent(in) :: lp       !< the line at the point
      logical, intent(in) :: want_k              !< form the derivatives
      type(point_force_t), intent(inout) :: fd   !< force [N/m] and its derivatives
      real(wp) :: ta, m(3, 3)
      ! rho A [(1 + C_an) P + (1 + C_aa) t t] a_w = c1 a_w + (c2 - c1) (t.a_w) t
      ta = dot_product(lp%t, aw)
      fd%f = fd%f + (ws%mw + ws%man)*aw + (ws%maa - ws%man)*ta*lp%t
      if (.not. want_k) return
      m = outer(lp%t, aw) + ta*eye
      fd%kxp = fd%kxp + (ws%maa - ws%man)*mm3(m, lp%pm)/lp%lam
   end subroutine froude_krylov_load

   !> Regularised Coulomb friction in the seabed plane, axial and lateral (module
   !> header), added to fs, and its derivatives: through N, through the velocity in the
   !> plane, and through the orientation of the axial direction t_s = P_n t/|P_n t|.
   !> docs/theory.md eq. (97).
   pure subroutine seabed_friction(env, lp, sc, want_k, fs, kx, kxp, kv)
      type(water_env_t), intent(in) :: env       !< environment
      type(line_point_t), intent(in) :: lp       !< the line at the point
      type(seabed_contact_t), intent(in) :: sc   !< normal force, in contact
      logical, intent(in) :: want_k              !< form the derivatives
      real(wp), intent(inout) :: fs(3)           !< seabed force [N/m]
      real(wp), intent(inout) :: kx(3, 3)        !< dfs/dx added [N/m2]
      real(wp), intent(inout) :: kxp(3, 3)       !< dfs/dx' added [N/m]
      real(wp), intent(inout) :: kv(3, 3)        !< dfs/dv added [N s/m2]
      real(wp) :: vt(3), ts(3), tsn, va, vl(3), vlm, ff(3), pl(3, 3), gl(3, 3), dts(3, 3)
      vt = lp%v - sc%vn*env%n
      ts = lp%t - dot_product(lp%t, env%n)*env%n
      tsn = norm3(ts)
      if (tsn > 0.0_wp) then
         ts = ts/tsn
      else
         ts = 0.0_wp
      end if
      va = dot_product(vt, ts)
      vl = vt - va*ts
      vlm = norm3(vl)
      ff = -env%mu_ax*sc%nf*va/max(abs(va), env%v_mob)*ts &
           - env%mu_lat*sc%nf*vl/max(vlm, env%v_mob)
      fs = fs + ff
      if (.not. want_k) return
      ! through N: dN/dx = dnx n, dN/dv = dnv n
      kx = kx + outer(ff/sc%nf, sc%dnx*env%n)
      kv = kv + outer(ff/sc%nf, sc%dnv*env%n)
      if (abs(va) < env%v_mob) kv = kv - env%mu_ax*sc%nf/env%v_mob*outer(ts, ts)
      pl = eye - outer(env%n, env%n) - outer(ts, ts)
      ! dF_lat/dv_lat (gl) and dF_ax/dt_s, dF_lat/dt_s (orientation of the axial direction)
      if (vlm < env%v_mob) then
         gl = -env%mu_lat*sc%nf/env%v_mob*eye
      else
         gl = -env%mu_lat*sc%nf/vlm*(eye - outer(vl, vl)/vlm**2)
      end if
      kv = kv + mm3(gl, pl)
      if (tsn <= 0.0_wp) return
      pl = outer(ts, vt)
      dts = -env%mu_ax*sc%nf*va/max(abs(va), env%v_mob)*eye - mm3(gl, pl + va*eye)
      if (abs(va) < env%v_mob) dts = dts - env%mu_ax*sc%nf/env%v_mob*pl
      ! t_s = P_n t/|P_n t|, t = x'/|x'|
      gl = eye - outer(ts, ts)
      pl = eye - outer(env%n, env%n)
      kxp = kxp + mm3(mm3(dts, gl), mm3(pl, lp%pm))/(tsn*lp%lam)
   end subroutine seabed_friction

   !> Seabed normal force per unstretched length N = D (k pen - c v.n), pen = -gap
   !> (c = 0 in statics), wherever it is positive, and its derivatives in the gap and in
   !> v.n; N <= 0: no contact (docs/theory.md eq. (96)). A line coming down at v.n < 0
   !> meets the damper c/k |v.n| above the plane (0.1 s times the speed with the
   !> defaults), so that N grows from 0 without a jump: a damper engaged only below the
   !> plane would make N jump from 0 to c |v.n| D at the plane, many times the weight of a
   !> landing line, and the steps of an inclined line touching down would fail
   !> (tests/verification/test_water_dynamics.pf).
   pure subroutine seabed_normal_force(env, dc, gap, vn, nf, dn_dgap, dn_dvn)
      type(water_env_t), intent(in) :: env !< environment
      real(wp), intent(in) :: dc           !< contact width D [m]
      real(wp), intent(in) :: gap          !< distance above the seabed [m]
      real(wp), intent(in) :: vn           !< velocity along the seabed normal [m/s]
      real(wp), intent(out) :: nf          !< normal force per length [N/m]
      real(wp), intent(out) :: dn_dgap     !< dN/dgap [N/m2]
      real(wp), intent(out) :: dn_dvn      !< dN/dvn [N s/m2]
      real(wp) :: c
      nf = 0.0_wp
      dn_dgap = 0.0_wp
      dn_dvn = 0.0_wp
      if (dc <= 0.0_wp) return
      c = 0.0_wp
      if (env%dynamic) c = env%c
      nf = dc*(-env%k*gap - c*vn)
      if (nf <= 0.0_wp) then
         nf = 0.0_wp
         return
      end if
      dn_dgap = -dc*env%k
      dn_dvn = -dc*c
   end subroutine seabed_normal_force

   !> The product a b of two 3 x 3 matrices.
   pure function mm3(a, b) result(c)
      real(wp), intent(in) :: a(3, 3) !< left
      real(wp), intent(in) :: b(3, 3) !< right
      real(wp) :: c(3, 3)
      integer :: j
      do j = 1, 3
         c(:, j) = a(:, 1)*b(1, j) + a(:, 2)*b(2, j) + a(:, 3)*b(3, j)
      end do
   end function mm3

   !> a b^T.
   pure function outer(a, b) result(m)
      real(wp), intent(in) :: a(3) !< column
      real(wp), intent(in) :: b(3) !< row
      real(wp) :: m(3, 3)
      integer :: j
      do j = 1, 3
         m(:, j) = a*b(j)
      end do
   end function outer
end module rodyn_hydro
