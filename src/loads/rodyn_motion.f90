!> Time functions of a dynamic run: prescribed motions of held nodes (harmonic per
!> direction or a displacement table, times a smooth ramp-in) and load amplitudes
!> (docs/theory.md eqs. (81), (102)-(106)).
module rodyn_motion
   use rodyn_kinds, only: wp, pi, two_pi
   use rodyn_model, only: motion_t, amplitude_t, motion_harmonic, motion_table, &
                          motion_vessel, vessel_t, vessel_from_rao
   use rodyn_vessel, only: vessel_point_position, vessel_harmonic_motion, vessel_local_point, &
                           vessel_rotation
   implicit none
   private
   public :: motion_displacement, amplitude_value, ramp_factor, vessel_motion
   public :: vessel_slow_motion, motion_rotation, vessel_offset_rest, vessel_offset_point
   public :: rotation_z, vessel_pose

contains

   !> Ramp-in r(t) = (1 - cos(pi t / T))/2 for t < T, 1 after; r = 1 when T = 0.
   !> r(0) = r'(0) = 0, so a motion multiplied by it starts from rest.
   !> docs/theory.md eq. (81).
   pure real(wp) function ramp_factor(t, ramp)
      real(wp), intent(in) :: t     !< time [s]
      real(wp), intent(in) :: ramp  !< ramp duration T [s]
      if (ramp <= 0.0_wp .or. t >= ramp) then
         ramp_factor = 1.0_wp
      else if (t <= 0.0_wp) then
         ramp_factor = 0.0_wp
      else
         ramp_factor = 0.5_wp*(1.0_wp - cos(pi*t/ramp))
      end if
   end function ramp_factor

   !> Displacement of a moved node at time t, from its position x0 at t = 0 [m]. A point
   !> of a vessel: u = X(r xi(t)) - x0, X the position of the vessel's point p at x0 for
   !> the vessel motion xi (rodyn_vessel; X = x0 for xi = 0), r the ramp: the rotations
   !> stay exact while they are ramped in. The vessel's slow motion (offset and drift,
   !> vessel_slow_motion) moves its reference point to O + r d(t) and turns it to
   !> psi0 + r d_psi(t), the wave-frequency motion xi acting about them:
   !>   X = O + r d + Rz(psi0 + r d_psi) (r xi_1:3 + Rv(r xi_4:6) p).
   !> docs/theory.md eqs. (102), (104).
   pure function motion_displacement(mo, t, vessels, x0) result(u)
      type(motion_t), intent(in) :: mo !< motion
      real(wp), intent(in) :: t        !< time [s]
      type(vessel_t), intent(in), optional :: vessels(:) !< the model's (motion_vessel)
      real(wp), intent(in), optional :: x0(3) !< the node at t = 0 (motion_vessel) [m]
      real(wp) :: u(3)
      real(wp) :: xi(6), p(3), sl(4), r
      integer :: j
      if (mo%kind == motion_vessel) then
         u = 0.0_wp
         if (.not. (present(vessels) .and. present(x0))) return
         associate (ve => vessels(mo%vessel))
            r = ramp_factor(t, mo%ramp)
            xi = r*vessel_motion(ve, t)
            sl = r*vessel_slow_motion(ve, t)
            p = vessel_local_point(ve%origin, ve%heading, x0)
            u = vessel_point_position(ve%origin + sl(1:3), ve%heading + sl(4), xi, p) - x0
         end associate
         return
      end if
      select case (mo%kind)
      case (motion_harmonic)
         do j = 1, 3
            u(j) = mo%amplitude(j)*sin(two_pi*mo%frequency(j)*t + mo%phase(j))
         end do
      case (motion_table)
         u = interpolate_rows(mo%time, mo%disp(1:3, :), t)
      case default
         u = 0.0_wp
      end select
      u = ramp_factor(t, mo%ramp)*u
   end function motion_displacement

   !> Rotation Q(t) of a moved node's directors from their start: d_i(t) = Q d_i(0). A
   !> point of a vessel turns with it (the directors fixed to the vessel at rest):
   !>   Q = Rz(psi0 + r d_psi) Rv(r xi_4:6) Rz(psi0)^T,
   !> the vessel's rotation (as in motion_displacement: ramp r, slow heading d_psi, motion
   !> xi, composed exactly) times the transpose of its rotation at rest; Q = I when the
   !> vessel is at rest. The identity for the other motions (translations only).
   !> docs/theory.md eq. (105).
   pure function motion_rotation(mo, t, vessels) result(q)
      type(motion_t), intent(in) :: mo !< motion
      real(wp), intent(in) :: t        !< time [s]
      type(vessel_t), intent(in), optional :: vessels(:) !< the model's (motion_vessel)
      real(wp) :: q(3, 3)
      real(wp) :: r, xi(6), sl(4)
      q = reshape([1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], &
                  [3, 3])
      if (mo%kind /= motion_vessel .or. .not. present(vessels)) return
      associate (ve => vessels(mo%vessel))
         r = ramp_factor(t, mo%ramp)
         xi = r*vessel_motion(ve, t)
         sl = r*vessel_slow_motion(ve, t)
         q = matmul(matmul(rotation_z(ve%heading + sl(4)), vessel_rotation(xi(4:6))), &
                    transpose(rotation_z(ve%heading)))
      end associate
   end function motion_rotation

   !> The vessel whose rest pose is its static offset (OFFSET START=STATIC, when the
   !> dynamics starts from the static solution): reference point O + offset_1:3, heading
   !> psi0 + offset_psi, offset 0; its wave-frequency motion (RAO factors, table) and
   !> drift unchanged. motion_displacement and motion_rotation with it give, after the
   !> ramp, the positions and turns of the vessel itself, and none at t = 0.
   pure function vessel_offset_rest(ve) result(vo)
      type(vessel_t), intent(in) :: ve !< vessel
      type(vessel_t) :: vo
      vo = ve
      vo%origin = ve%origin + ve%offset(1:3)
      vo%heading = ve%heading + ve%offset(4)
      vo%offset = 0.0_wp
   end function vessel_offset_rest

   !> Where the vessel point at x (the vessel at rest) is with the vessel at its static
   !> offset, lam of it (statics' load factor):
   !>   X = O + lam offset_1:3 + Rz(psi0 + lam offset_psi) p,  p = Rz(psi0)^T (x - O).
   !> docs/theory.md eq. (103).
   pure function vessel_offset_point(ve, x, lam) result(xo)
      type(vessel_t), intent(in) :: ve !< vessel
      real(wp), intent(in) :: x(3)     !< position at rest [m]
      real(wp), intent(in) :: lam      !< fraction of the offset [-]
      real(wp) :: xo(3)
      real(wp) :: p(3)
      p = vessel_local_point(ve%origin, ve%heading, x)
      xo = vessel_point_position(ve%origin + lam*ve%offset(1:3), ve%heading + &
                                 lam*ve%offset(4), [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, &
                                                    0.0_wp], p)
   end function vessel_offset_point

   !> Rotation by a about global z: Rz(a) = [cos a, -sin a, 0; sin a, cos a, 0; 0, 0, 1]
   !> (the turn of a clamped end on a vessel turned by a static offset heading a).
   pure function rotation_z(a) result(m)
      real(wp), intent(in) :: a !< angle [rad]
      real(wp) :: m(3, 3)
      m = reshape([cos(a), sin(a), 0.0_wp, -sin(a), cos(a), 0.0_wp, 0.0_wp, 0.0_wp, &
                   1.0_wp], [3, 3])
   end function rotation_z

   !> Motion xi(t) = (surge, sway, heave [m], roll, pitch, yaw [rad]) of a vessel's
   !> reference point, in vessel axes: from its RAOs in the sea (the response factors
   !> set up before the run, times the sea's ramp), or its table (linear interpolation,
   !> constant beyond the ends).
   !> docs/theory.md eq. (100).
   pure function vessel_motion(ve, t) result(xi)
      type(vessel_t), intent(in) :: ve !< vessel
      real(wp), intent(in) :: t        !< time [s]
      real(wp) :: xi(6)
      xi = 0.0_wp
      if (ve%kind == vessel_from_rao) then
         if (allocated(ve%coef)) xi = ramp_factor(t, ve%sea_ramp)* &
                                      vessel_harmonic_motion(ve%coef, ve%omega, t)
         return
      end if
      xi = interpolate_rows(ve%time, ve%motion(1:6, :), t)
   end function vessel_motion

   !> Slow motion of a vessel's reference point, global: its static offset plus its
   !> drift, harmonic d(t) = offset + a sin(2 pi t/T_d + phi_d) (x, y [m], z [m], heading
   !> [rad]; a = 0 in z; none when T_d = 0) or from its table (linear interpolation,
   !> constant beyond the ends).
   !> docs/theory.md eq. (101).
   pure function vessel_slow_motion(ve, t) result(d)
      type(vessel_t), intent(in) :: ve !< vessel
      real(wp), intent(in) :: t        !< time [s]
      real(wp) :: d(4)
      d = ve%offset
      if (ve%drift_period > 0.0_wp) &
         d = d + ve%drift*sin(two_pi*t/ve%drift_period + ve%drift_phase)
      if (allocated(ve%drift_time)) &
         d = d + interpolate_rows(ve%drift_time, ve%drift_table(1:4, :), t)
   end function vessel_slow_motion

   !> Pose of a vessel at time t, as motion_displacement moves its points with ramp r
   !> (the ramp of a *MOTION on it): the reference point X = O + r d_1:3 + Rz(psi) r xi_1:3,
   !> global, the angles r xi_4:6 of Rv = Rz(yaw) Ry(pitch) Rx(roll) and the heading
   !> psi = psi0 + r d_psi of the mean axes, so that a point p of vessel axes is at
   !> X + Rz(psi) Rv p. pose = (x, y, z [m], roll, pitch, yaw, psi [rad]).
   pure function vessel_pose(ve, t, ramp) result(pose)
      type(vessel_t), intent(in) :: ve !< vessel
      real(wp), intent(in) :: t        !< time [s]
      real(wp), intent(in) :: ramp     !< ramp duration of its *MOTION [s] (0: none)
      real(wp) :: pose(7)
      real(wp) :: xi(6), sl(4), r, psi
      r = ramp_factor(t, ramp)
      xi = r*vessel_motion(ve, t)
      sl = r*vessel_slow_motion(ve, t)
      psi = ve%heading + sl(4)
      pose(1:3) = vessel_point_position(ve%origin + sl(1:3), psi, xi, [0.0_wp, 0.0_wp, 0.0_wp])
      pose(4:6) = xi(4:6)
      pose(7) = psi
   end function vessel_pose

   !> Value of an amplitude at time t (linear interpolation, constant beyond the ends).
   !> docs/theory.md eq. (106).
   pure real(wp) function amplitude_value(amp, t)
      type(amplitude_t), intent(in) :: amp !< amplitude table
      real(wp), intent(in) :: t            !< time [s]
      amplitude_value = interpolate(amp%time, amp%value, t)
   end function amplitude_value

   !> interpolate of each row of a table: y(k) from (tt, table(k, :)).
   pure function interpolate_rows(tt, table, t) result(y)
      real(wp), intent(in) :: tt(:)        !< increasing abscissae
      real(wp), intent(in) :: table(:, :)  !< (rows, size(tt)) values
      real(wp), intent(in) :: t            !< where
      real(wp) :: y(size(table, 1))        !< the rows' values at t
      integer :: k
      do k = 1, size(table, 1)
         y(k) = interpolate(tt, table(k, :), t)
      end do
   end function interpolate_rows

   !> Piecewise-linear interpolation in (tt, yy), constant beyond the ends.
   pure real(wp) function interpolate(tt, yy, t)
      real(wp), intent(in) :: tt(:) !< increasing abscissae
      real(wp), intent(in) :: yy(:) !< values
      real(wp), intent(in) :: t     !< where
      integer :: lo, hi, mid
      if (t <= tt(1)) then
         interpolate = yy(1)
         return
      end if
      if (t >= tt(size(tt))) then
         interpolate = yy(size(tt))
         return
      end if
      lo = 1
      hi = size(tt)
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         if (tt(mid) <= t) then
            lo = mid
         else
            hi = mid
         end if
      end do
      interpolate = yy(lo) + (yy(hi) - yy(lo))*(t - tt(lo))/(tt(hi) - tt(lo))
   end function interpolate
end module rodyn_motion
