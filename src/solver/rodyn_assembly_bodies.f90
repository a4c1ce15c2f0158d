!> The turning loads of the FREE bodies (rodyn_bodies: buoyancy at B, waterplane
!> restoring, the moment of a load given at R, the wave load; in dynamics the damping and
!> drag, in statics the current's drag) added to the internal forces and the tangent, as
!> the water's are (docs/theory.md eqs. (137)-(139), (141), (149)-(150)).
module rodyn_assembly_bodies
   use rodyn_kinds, only: wp
   use rodyn_bodies, only: body_loads_t, body_force, body_damping, body_current_drag
   use rodyn_rotation, only: rotation_cayley_inverse, relative_rotation
   use rodyn_assembly, only: supports_t, add_node_block
   use rodyn_banded, only: banded_t
   implicit none
   private
   public :: assemble_bodies

contains

   !> fint -= f of each body at the force point, and the tangent -df/dq (want_k). The
   !> force of the loads given at R is the node's external force less its weight.
   subroutine assemble_bodies(bl, sup, x0, x1, d0, d1, w, fext, grav, fint, bm, want_k, dt)
      type(body_loads_t), intent(inout) :: bl !< bodies' loads (their last forces kept)
      type(supports_t), intent(in) :: sup     !< supports (dof map)
      real(wp), intent(in) :: x0(:, :)        !< (3, nn) positions at t_n [m]
      real(wp), intent(in) :: x1(:, :)        !< (3, nn) positions now [m]
      real(wp), intent(in) :: d0(:, :, :)     !< (3, 3, nn) directors at t_n
      real(wp), intent(in) :: d1(:, :, :)     !< (3, 3, nn) directors now
      real(wp), intent(in) :: w               !< weight of t_n+1 at the force point
      real(wp), intent(in) :: fext(:, :)      !< (6, nn) external forces (point loads, weight)
      real(wp), intent(in) :: grav(:, :)      !< (3, nn) the weight [N]
      real(wp), intent(inout) :: fint(:, :)   !< (6, nn) internal forces
      type(banded_t), intent(inout) :: bm     !< tangent
      logical, intent(in) :: want_k           !< form the tangent
      real(wp), intent(in), optional :: dt    !< time step [s] (dynamics: the damping)
      real(wp) :: f(6), kb(6, 6), th(3)
      integer :: k, n
      if (bl%off) return
      do k = 1, bl%nb
         n = bl%node(k)
         call body_force(bl, k, x0(:, n), x1(:, n), d0(:, :, n), d1(:, :, n), w, &
                         fext(1:3, n) - grav(:, n), f, kb)
         fint(:, n) = fint(:, n) - f
         if (want_k) call add_node_block(sup, n, -kb, bm)
         if (.not. present(dt)) then
            ! statics: the current's steady drag on a body with a drag (eq. (149))
            if (.not. any(bl%uw(:, k) /= 0.0_wp)) cycle
            call body_current_drag(bl, k, d1(:, :, n), f, kb)
            fint(:, n) = fint(:, n) - f
            if (want_k) call add_node_block(sup, n, -kb, bm)
            cycle
         end if
         if (.not. (any(bl%b(:, :, k) /= 0.0_wp) .or. any(bl%q(:, k) > 0.0_wp))) cycle
         th = rotation_cayley_inverse(relative_rotation(d1(:, :, n), d0(:, :, n)))
         call body_damping(bl, k, x0(:, n), x1(:, n), d0(:, :, n), d1(:, :, n), w, dt, th, &
                           f, kb)
         fint(:, n) = fint(:, n) - f
         if (want_k) call add_node_block(sup, n, -kb, bm)
      end do
   end subroutine assemble_bodies
end module rodyn_assembly_bodies
