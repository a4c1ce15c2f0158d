!> Assembly of the sections' structural damping over a time step (rodyn_section_damping;
!> docs/theory.md eqs. (116)-(121)): a pass over the damped elements after the step's
!> internal force, adding the damping forces to fint and to fdamp (whose work over the
!> step the energy log books as damping work) and their tangent to the banded matrix.
!> A run without structural damping never calls it, so its results do not change.
module rodyn_assembly_damping
   use rodyn_kinds, only: wp
   use rodyn_mesh, only: mesh_t
   use rodyn_state, only: state_t, state_gather
   use rodyn_banded, only: banded_t
   use rodyn_shape, only: max_nen
   use rodyn_assembly, only: supports_t, scatter_element, scatter_cable
   use rodyn_section_damping, only: rod_section_damping, cable_section_damping
   implicit none
   private
   public :: section_damping_rates, assemble_section_damping

contains

   !> The constant part g of the nodal rates u = cv (q^{n+1} - q^n) + g at the force point
   !> of generalized-alpha, the velocity at t_{n+1-alpha_f} of the Newmark update:
   !>   g = v^n + (1 - af) dt ((1 - gm) a^n - gm (v^n/(b dt) + (1/2 - b)/b a^n)),
   !>   cv = (1 - af) gm/(b dt),
   !> for the positions (g(:, 1, a)) and the three directors (g(:, 1 + i, a)).
   !> docs/theory.md eq. (117).
   pure subroutine section_damping_rates(s0, af, gm, b, dt, g, cv)
      type(state_t), intent(in) :: s0          !< state at t_n (with accelerations)
      real(wp), intent(in) :: af               !< generalized-alpha alpha_f [-]
      real(wp), intent(in) :: gm               !< Newmark gamma [-]
      real(wp), intent(in) :: b                !< Newmark beta [-]
      real(wp), intent(in) :: dt               !< step [s]
      real(wp), intent(out) :: g(:, :, :)      !< (3, 4, nn) constant part [m/s, 1/s]
      real(wp), intent(out) :: cv              !< d(rate)/d(q^{n+1}) [1/s]
      integer :: node, i
      do node = 1, size(g, 3)
         g(:, 1, node) = rate0(s0%v(:, node), s0%a(:, node))
         do i = 1, 3
            g(:, 1 + i, node) = rate0(s0%dd(:, i, node), s0%ad(:, i, node))
         end do
      end do
      cv = (1.0_wp - af)*gm/(b*dt)
   contains
      pure function rate0(v0, a0) result(r)
         real(wp), intent(in) :: v0(3), a0(3)
         real(wp) :: r(3)
         r = v0 + (1.0_wp - af)*dt*((1.0_wp - gm)*a0 - gm*(v0/(b*dt) + (0.5_wp - b)/b*a0))
      end function rate0
   end subroutine section_damping_rates

   !> Add the structural damping of every damped element to fint and fdamp and, if
   !> want_k, its tangent to bm (after assemble_dynamic and assemble_dynamic_cables).
   !> docs/theory.md eqs. (116)-(121).
   subroutine assemble_section_damping(mesh, sup, s0, s1, g, cv, wq, scheme, fint, fdamp, &
                                       bm, want_k)
      type(mesh_t), intent(in) :: mesh        !< mesh (elem_damp)
      type(supports_t), intent(in) :: sup     !< supports (dof map, node bases)
      type(state_t), intent(in) :: s0         !< state at t_n
      type(state_t), intent(in) :: s1         !< state at t_n+1 (current iterate)
      real(wp), intent(in) :: g(:, :, :)      !< (3, 4, nn) rates' constant part
      real(wp), intent(in) :: cv              !< d(rate)/d(q^{n+1}) [1/s]
      real(wp), intent(in) :: wq              !< weight of t_n+1 in the force point [-]
      integer, intent(in) :: scheme           !< scheme_* constant
      real(wp), intent(inout) :: fint(:, :)   !< (6, nn) internal forces [N, N m]
      real(wp), intent(inout) :: fdamp(:, :)  !< (6, nn) damping forces [N, N m]
      type(banded_t), intent(inout) :: bm     !< tangent
      logical, intent(in) :: want_k           !< form the tangent
      real(wp) :: x0(3, max_nen), x1(3, max_nen), d0(3, 3, max_nen), d1(3, 3, max_nen)
      real(wp) :: ge(3, 4, max_nen), fe(6, max_nen), ke(6*max_nen, 6*max_nen)
      real(wp) :: fc(3, max_nen), kc(3*max_nen, 3*max_nen)
      integer :: e, p, nen, a
      do e = 1, mesh%n_elements
         if (all(mesh%elem_damp(:, e) == 0.0_wp)) cycle
         p = mesh%line_order(mesh%elem_line(e))
         nen = p + 1
         associate (nodes => mesh%elem_nodes(1:nen, e))
            do a = 1, nen
               ge(:, :, a) = g(:, :, nodes(a))
            end do
            if (mesh%elem_cable(e)) then
               do a = 1, nen
                  x0(:, a) = s0%x(:, nodes(a))
                  x1(:, a) = s1%x(:, nodes(a))
               end do
               call cable_section_damping(p, mesh%elem_le(e), mesh%elem_damp(1, e), &
                                          x0(:, 1:nen), x1(:, 1:nen), ge(:, 1, 1:nen), cv, &
                                          wq, scheme, fc(:, 1:nen), kc(1:3*nen, 1:3*nen), &
                                          want_k, mesh%rules(p))
               do a = 1, nen
                  fdamp(1:3, nodes(a)) = fdamp(1:3, nodes(a)) + fc(:, a)
               end do
               call scatter_cable(sup, nodes, fc(:, 1:nen), kc(1:3*nen, 1:3*nen), fint, bm, &
                                  want_k)
            else
               call state_gather(s0, nodes, x0, d0)
               call state_gather(s1, nodes, x1, d1)
               call rod_section_damping(p, mesh%elem_le(e), &
                                        [0.0_wp, 0.0_wp, mesh%elem_damp(:, e), 0.0_wp], &
                                        x0(:, 1:nen), d0(:, :, 1:nen), x1(:, 1:nen), &
                                        d1(:, :, 1:nen), ge(:, :, 1:nen), cv, wq, &
                                        fe(:, 1:nen), ke(1:6*nen, 1:6*nen), want_k, &
                                        mesh%rules(p))
               do a = 1, nen
                  fdamp(:, nodes(a)) = fdamp(:, nodes(a)) + fe(:, a)
               end do
               call scatter_element(sup, nodes, fe(:, 1:nen), ke(1:6*nen, 1:6*nen), fint, &
                                    bm, want_k)
            end if
         end associate
      end do
   end subroutine assemble_section_damping
end module rodyn_assembly_damping
