!> Lumped inertia of the director rod (docs/theory.md eqs. (9), (29), (41)-(42)): kinetic energy
!> T = 1/2 sum_a [m_a |v_a|^2 + M1_a |d1dot_a|^2 + M2_a |d2dot_a|^2], row-sum lumped from
!> rhoA and the director inertias E11 = rhoI2 (for d1), E22 = rhoI1 (for d2); d3 carries
!> none. The mass matrix is constant: all nonlinearity is in the stiffness.
module rodyn_inertia
   use rodyn_kinds, only: wp
   use rodyn_model, only: model_t, body_free
   use rodyn_mesh, only: mesh_t
   use rodyn_state, only: state_t
   use rodyn_rod_element, only: rod_element_lumped_mass
   use rodyn_rotation, only: cross
   use rodyn_shape, only: max_nen
   use rodyn_body_mass, only: body_added_mass_g
   implicit none
   private
   public :: inertia_t, inertia_build, kinetic_energy, linear_momentum, angular_momentum
   public :: added_momentum, body_velocity6

   !> Nodal lumped inertia.
   type :: inertia_t
      real(wp), allocatable :: m(:)       !< (nn) translational mass [kg]
      real(wp), allocatable :: md(:, :)   !< (3, nn) inertia of d1, d2, d3 [kg m2] (d3: 0 but
                                          !< at a body's node: its Euler tensor)
      !> bodies with an added mass acting on their accelerations (theory.md (142), (152)):
      !> node and the added mass at G in body axes [kg, kg m, kg m2]
      integer, allocatable :: ma_node(:)  !< (nma)
      real(wp), allocatable :: ma(:, :, :) !< (6, 6, nma)
      !> (nma) translational only: no rotational or coupling terms (EMC's exact form, (151))
      logical, allocatable :: ma_trans(:)
   end type inertia_t

contains

   !> Lump rhoA, E11 = rhoI2 and E22 = rhoI1 element by element.
   !> docs/theory.md eqs. (29), (75).
   subroutine inertia_build(model, mesh, inert)
      type(model_t), intent(in) :: model     !< model (sections)
      type(mesh_t), intent(in) :: mesh       !< mesh
      type(inertia_t), intent(out) :: inert  !< lumped inertia
      real(wp) :: ma(max_nen), m1(max_nen), m2(max_nen), ag(6, 6)
      integer :: e, l, p, a, node
      allocate (inert%m(mesh%n_nodes), inert%md(3, mesh%n_nodes))
      inert%m = 0.0_wp
      inert%md = 0.0_wp
      do e = 1, mesh%n_elements
         l = mesh%elem_line(e)
         p = mesh%line_order(l)
         associate (sec => model%sections(mesh%elem_sec(e)))
            call rod_element_lumped_mass(p, mesh%elem_le(e), mesh%elem_mass(e), ma(1:p + 1))
            call rod_element_lumped_mass(p, mesh%elem_le(e), sec%rhoi2, m1(1:p + 1))
            call rod_element_lumped_mass(p, mesh%elem_le(e), sec%rhoi1, m2(1:p + 1))
         end associate
         do a = 1, p + 1
            node = mesh%elem_nodes(a, e)
            inert%m(node) = inert%m(node) + ma(a)
            ! a cable element has no directors, so no rotary inertia
            if (mesh%elem_cable(e)) cycle
            inert%md(1, node) = inert%md(1, node) + m1(a)
            inert%md(2, node) = inert%md(2, node) + m2(a)
         end do
      end do
      ! a FREE body: its mass at G and its Euler tensor on its directors (principal
      ! axes): E_1 = (J_2 + J_3 - J_1)/2, ... (T_rot = 1/2 sum_i E_i |d_i dot|^2)
      do e = 1, size(mesh%body_node)
         node = mesh%body_node(e)
         if (model%bodies(e)%kind /= body_free) cycle
         associate (j => model%bodies(e)%inertia + model%bodies(e)%added_mass(4:6))
            inert%m(node) = inert%m(node) + model%bodies(e)%mass
            inert%md(:, node) = inert%md(:, node) + 0.5_wp*(sum(j) - 2.0_wp*j)
         end associate
      end do
      allocate (inert%ma_node(0), inert%ma(6, 6, 0), inert%ma_trans(0))
      do e = 1, size(mesh%body_node)
         if (model%bodies(e)%kind /= body_free) cycle
         ag = body_added_mass_g(model%bodies(e))
         if (all(ag == 0.0_wp)) cycle
         inert%ma_node = [inert%ma_node, mesh%body_node(e)]
         inert%ma = reshape([inert%ma, ag], [6, 6, size(inert%ma_node)])
         inert%ma_trans = [inert%ma_trans, all(ag(:, 4:6) == 0.0_wp)]
      end do
      ! attachments: their mass and the isotropic added mass Ca rho_w V at their node
      if (.not. allocated(model%attachments)) return
      do e = 1, size(model%attachments)
         associate (at => model%attachments(e))
            node = mesh%att_node(e)
            inert%m(node) = inert%m(node) + at%mass + at%ca*model%water%density*at%volume
         end associate
      end do
   end subroutine inertia_build

   !> Kinetic energy [J].
   !> docs/theory.md eq. (41).
   pure function kinetic_energy(inert, state) result(t)
      type(inertia_t), intent(in) :: inert !< lumped inertia
      type(state_t), intent(in) :: state   !< velocities
      real(wp) :: t, nu(6)
      integer :: a, i
      t = 0.0_wp
      do a = 1, size(inert%m)
         t = t + inert%m(a)*dot_product(state%v(:, a), state%v(:, a))
         do i = 1, 3
            t = t + inert%md(i, a)*dot_product(state%dd(:, i, a), state%dd(:, i, a))
         end do
      end do
      do i = 1, size(inert%ma_node)          ! a body's added mass, in its axes
         a = inert%ma_node(i)
         nu = body_velocity6(state%d(:, :, a), state%v(:, a), state%dd(:, :, a))
         t = t + dot_product(nu, matmul(inert%ma(:, :, i), nu))
      end do
      t = 0.5_wp*t
   end function kinetic_energy

   !> Total linear momentum sum m v [kg m/s].
   !> docs/theory.md eq. (42).
   pure function linear_momentum(inert, state) result(p)
      type(inertia_t), intent(in) :: inert !< lumped inertia
      type(state_t), intent(in) :: state   !< velocities
      real(wp) :: p(3)
      integer :: a, i
      p = 0.0_wp
      do a = 1, size(inert%m)
         p = p + inert%m(a)*state%v(:, a)
      end do
      do i = 1, size(inert%ma_node)
         a = inert%ma_node(i)
         p = p + added_momentum(inert%ma(:, :, i), state%d(:, :, a), state%v(:, a), &
                                state%dd(:, :, a), 1)
      end do
   end function linear_momentum

   !> Total angular momentum about the origin, J = sum x x m v + sum_i d_i x M_i d_i_dot
   !> (docs/theory.md eq. (42): what the EMC scheme conserves) [kg m2/s].
   pure function angular_momentum(inert, state) result(j)
      type(inertia_t), intent(in) :: inert !< lumped inertia
      type(state_t), intent(in) :: state   !< configuration and velocities
      real(wp) :: j(3), pa(3)
      integer :: a, i
      j = 0.0_wp
      do a = 1, size(inert%m)
         j = j + inert%m(a)*cross(state%x(:, a), state%v(:, a))
         do i = 1, 3
            j = j + inert%md(i, a)*cross(state%d(:, i, a), state%dd(:, i, a))
         end do
      end do
      do i = 1, size(inert%ma_node)
         a = inert%ma_node(i)
         pa = added_momentum(inert%ma(:, :, i), state%d(:, :, a), state%v(:, a), &
                             state%dd(:, :, a), 1)
         j = j + cross(state%x(:, a), pa) + added_momentum(inert%ma(:, :, i), &
                                                           state%d(:, :, a), state%v(:, a), &
                                                           state%dd(:, :, a), 2)
      end do
   end function angular_momentum

   !> The momentum of a body's added mass A_G (at G, body axes): part 1, D (A_G nu)(1:3)
   !> [kg m/s]; part 2, its moment about G, D (A_G nu)(4:6) [kg m2/s] (nu: body_velocity6).
   pure function added_momentum(ma, d, v, dd, part) result(p)
      real(wp), intent(in) :: ma(6, 6)   !< added mass at G, body axes
      real(wp), intent(in) :: d(3, 3)    !< the body's directors
      real(wp), intent(in) :: v(3)       !< velocity of G [m/s]
      real(wp), intent(in) :: dd(3, 3)   !< the directors' velocities [1/s]
      integer, intent(in) :: part        !< 1: momentum, 2: its moment about G
      real(wp) :: p(3)
      real(wp) :: q(6)
      q = matmul(ma, body_velocity6(d, v, dd))
      p = matmul(d, q(3*part - 2:3*part))
   end function added_momentum

   !> A body's velocity in its axes, (D^T v, D^T omega), omega = 1/2 sum_i d_i x d_i_dot
   !> its angular velocity (docs/theory.md eq. (153)).
   pure function body_velocity6(d, v, dd) result(nu)
      real(wp), intent(in) :: d(3, 3)    !< directors
      real(wp), intent(in) :: v(3)       !< velocity of G [m/s]
      real(wp), intent(in) :: dd(3, 3)   !< the directors' velocities [1/s]
      real(wp) :: nu(6)
      real(wp) :: om(3)
      om = 0.5_wp*(cross(d(:, 1), dd(:, 1)) + cross(d(:, 2), dd(:, 2)) + &
                   cross(d(:, 3), dd(:, 3)))
      nu(1:3) = matmul(transpose(d), v)
      nu(4:6) = matmul(transpose(d), om)
   end function body_velocity6
end module rodyn_inertia
