!> Global assembly of internal forces and tangents over all elements, the external load
!> vectors, and the node constraints (held, hinged about an axis, prescribed position).
!>
!> Unknowns: 6 per node, dof first(a)+j-1: j = 1..3 translation, 4..6 spatial rotation;
!> a node with cable elements only has the 3 translations (supports_t's dof map).
!> A hinged node has its rotation unknowns expressed in the basis (axis, b, c) by an
!> orthogonal T (columns), so that the b and c components can be held: K' = T^T K T
!> (docs/theory.md eqs. (47)-(48)).
module rodyn_assembly
   use rodyn_kinds, only: wp
   use rodyn_model, only: model_t, amplitude_t, bc_free, bc_pinned, bc_hinged, bc_clamped, &
                          bc_position, end_a, end_b, body_fixed, body_free
   use rodyn_mesh, only: mesh_t, mesh_node
   use rodyn_water, only: water_loads_t, water_element, water_attachment
   use rodyn_hydro, only: water_section_t
   use rodyn_state, only: state_t, state_gather, copy_values
   use rodyn_banded, only: banded_t, banded_add, banded_fix_dof, banded_keep_column, &
                           banded_kept_axpy, banded_zero
   use rodyn_rod_element, only: rod_element_static, rod_element_line_load, max_points, rod_gp_t
   use rodyn_rod_dynamic, only: rod_element_dynamic
   use rodyn_cable_element, only: cable_element_static, cable_element_dynamic
   use rodyn_rotation, only: cross, rotation_cayley_inverse, relative_rotation
   use rodyn_motion, only: amplitude_value
   use rodyn_shape, only: max_nen
   implicit none
   private
   public :: supports_t, loads_t, supports_build, loads_build, supports_held_lists
   public :: assemble_static, assemble_dynamic, assemble_dynamic_cables, apply_supports
   public :: external_force
   public :: add_node_block, assemble_water, dof_map, dof_reach, scatter_element, &
             scatter_cable

   !> Node constraints, fixed for the run.
   type :: supports_t
      logical, allocatable :: held(:, :)       !< (6, nn) dof held (in the node's basis)
      logical, allocatable :: rotated(:)       !< (nn) node uses a rotation basis T
      real(wp), allocatable :: basis(:, :, :)  !< (3, 3, nn) T for rotated nodes
      logical, allocatable :: moved(:)         !< (nn) node has a prescribed position
      real(wp), allocatable :: x_start(:, :)   !< (3, nn) position at load factor 0 [m]
      real(wp), allocatable :: x_target(:, :)  !< (3, nn) position at load factor 1 [m]
      integer, allocatable :: first(:)         !< (nn) first dof of each node
      integer, allocatable :: ndof(:)          !< (nn) its unknowns: 6, or 3 (cable only)
      integer :: n_dof = 0                     !< unknowns of the linear system
      integer :: half_bw = 0                   !< its half bandwidth
      logical :: uniform = .true.              !< 6 unknowns at every node: first = 6(a-1)+1
      integer :: n_held = 0                    !< held unknowns of the linear system
      integer, allocatable :: held_dof(:)      !< (n_held) each one's dof
      integer, allocatable :: held_node(:)     !< (n_held) its node
      integer, allocatable :: held_j(:)        !< (n_held) and the node's dof j (1..6)
   end type supports_t

   !> External loads given by the deck, global axes: the weight, and the point loads with
   !> the amplitudes that scale them in time (one path for statics and dynamics).
   type :: loads_t
      real(wp), allocatable :: gravity(:, :)   !< (3, nn) consistent self-weight [N]
      integer, allocatable :: pt_node(:)       !< (np) node of each point load
      integer, allocatable :: pt_amp(:)        !< (np) its amplitude (0: constant)
      real(wp), allocatable :: pt_fm(:, :)     !< (6, np) force and moment [N, N m]
      type(amplitude_t), allocatable :: amps(:) !< the deck's amplitudes
   end type loads_t

contains

   !> Supports from the model's *BOUNDARY cards and the initial configuration.
   subroutine supports_build(model, mesh, state, sup)
      type(model_t), intent(in) :: model    !< model
      type(mesh_t), intent(in) :: mesh      !< mesh
      type(state_t), intent(in) :: state    !< initial configuration
      type(supports_t), intent(out) :: sup  !< supports
      integer :: i, node, nn, l, k, nen
      real(wp) :: ends(3)
      nn = mesh%n_nodes
      allocate (sup%held(6, nn), sup%rotated(nn), sup%basis(3, 3, nn), sup%moved(nn), &
                sup%x_start(3, nn), sup%x_target(3, nn))
      sup%held = .false.
      sup%rotated = .false.
      sup%moved = .false.
      sup%basis = 0.0_wp
      sup%x_start = state%x
      sup%x_target = state%x
      ! a node with cable elements only has no rotations: its rotation unknowns are held
      sup%held(4:6, :) = .true.
      do i = 1, mesh%n_elements
         if (mesh%elem_cable(i)) cycle
         nen = mesh%line_order(mesh%elem_line(i)) + 1
         sup%held(4:6, mesh%elem_nodes(1:nen, i)) = .false.
      end do
      ! a body turns: its node's rotations are unknowns (held for a FIXED body)
      do i = 1, size(mesh%body_node)
         sup%held(4:6, mesh%body_node(i)) = model%bodies(i)%kind == body_fixed
         if (model%bodies(i)%kind == body_fixed) sup%held(1:3, mesh%body_node(i)) = .true.
      end do
      ! ... and no rotation unknowns in the linear system: 3 dofs, not 6
      call dof_map(mesh, sup%first, sup%ndof, sup%n_dof, sup%half_bw)
      sup%uniform = all(sup%ndof == 6)
      if (allocated(model%constraints)) call constraints_apply(model, mesh, sup)
      ! a held end that the starting shape put off its deck position (a grounded catenary
      ! with its touchdown on a node, rodyn_mesh) is moved there by the statics
      do l = 1, mesh%n_lines
         do k = 1, 2
            node = mesh_node(mesh, l, merge(end_a, end_b, k == 1))
            ends = merge(model%lines(l)%end_a, model%lines(l)%end_b, k == 1)
            if (.not. sup%held(1, node) .or. sup%moved(node)) cycle
            if (norm2(state%x(:, node) - ends) <= 1.0e-12_wp*model%lines(l)%length) cycle
            sup%moved(node) = .true.
            sup%x_target(:, node) = ends
         end do
      end do
      call supports_held_lists(sup)
   end subroutine supports_build

   !> The held unknowns of the linear system, listed from sup%held (apply_supports); again
   !> when an end is released (a line failure, rodyn_system_dynamics).
   subroutine supports_held_lists(sup)
      type(supports_t), intent(inout) :: sup !< supports: held_* set
      integer :: node, k, i
      if (allocated(sup%held_dof)) deallocate (sup%held_dof, sup%held_node, sup%held_j)
      sup%n_held = 0
      do node = 1, size(sup%ndof)
         sup%n_held = sup%n_held + count(sup%held(1:sup%ndof(node), node))
      end do
      allocate (sup%held_dof(sup%n_held), sup%held_node(sup%n_held), sup%held_j(sup%n_held))
      i = 0
      do node = 1, size(sup%ndof)
         do k = 1, sup%ndof(node)
            if (.not. sup%held(k, node)) cycle
            i = i + 1
            sup%held_dof(i) = sup%first(node) + k - 1
            sup%held_node(i) = node
            sup%held_j(i) = k
         end do
      end do
   end subroutine supports_held_lists

   !> The *BOUNDARY cards' constraints into sup (supports_build).
   subroutine constraints_apply(model, mesh, sup)
      type(model_t), intent(in) :: model     !< model
      type(mesh_t), intent(in) :: mesh       !< mesh
      type(supports_t), intent(inout) :: sup !< supports
      integer :: i, node
      real(wp) :: ax(3), b(3)
      do i = 1, size(model%constraints)
         associate (c => model%constraints(i))
            node = mesh_node(mesh, c%line, c%node)
            select case (c%kind)
            case (bc_pinned)
               sup%held(1:3, node) = .true.
            case (bc_clamped)
               sup%held(:, node) = .true.
            case (bc_hinged)
               sup%held(1:3, node) = .true.
               sup%held(5:6, node) = .true.
               ax = c%axis/norm2(c%axis)
               b = cross(ax, [1.0_wp, 0.0_wp, 0.0_wp])
               if (norm2(b) < 0.5_wp) b = cross(ax, [0.0_wp, 1.0_wp, 0.0_wp])
               b = b/norm2(b)
               sup%rotated(node) = .true.
               sup%basis(:, 1, node) = ax
               sup%basis(:, 2, node) = b
               sup%basis(:, 3, node) = cross(ax, b)
            case (bc_position)
               sup%held(1:3, node) = .true.
               sup%moved(node) = .true.
               sup%x_target(:, node) = c%position
            case (bc_free)
            end select
         end associate
      end do
   end subroutine constraints_apply

   !> The unknowns of the linear system: 6 at a node with a rod element and at a body's,
   !> 3 (the translations) at a node with cable elements only and at a FREE point's; node
   !> after node, so that the half bandwidth is the largest span of one element's unknowns.
   subroutine dof_map(mesh, first, ndof, n_dof, half_bw)
      type(mesh_t), intent(in) :: mesh                !< mesh
      integer, allocatable, intent(out) :: first(:)   !< (nn) first dof of each node
      integer, allocatable, intent(out) :: ndof(:)    !< (nn) its unknowns
      integer, intent(out) :: n_dof                   !< unknowns
      integer, intent(out) :: half_bw                 !< half bandwidth
      integer :: e, nen, node
      allocate (first(mesh%n_nodes), ndof(mesh%n_nodes))
      ndof = 3
      do e = 1, mesh%n_elements
         if (mesh%elem_cable(e)) cycle
         nen = mesh%line_order(mesh%elem_line(e)) + 1
         ndof(mesh%elem_nodes(1:nen, e)) = 6
      end do
      do e = 1, size(mesh%body_node)       ! a body's node: 6
         ndof(mesh%body_node(e)) = 6
      end do
      n_dof = 0
      do node = 1, mesh%n_nodes
         first(node) = n_dof + 1
         n_dof = n_dof + ndof(node)
      end do
      half_bw = 0
      do e = 1, mesh%n_elements
         nen = mesh%line_order(mesh%elem_line(e)) + 1
         associate (nodes => mesh%elem_nodes(1:nen, e))
            half_bw = max(half_bw, maxval(first(nodes) + ndof(nodes)) - 1 - minval(first(nodes)))
         end associate
      end do
   end subroutine dof_map

   !> The envelope of the linear system (rodyn_banded): reach(k), the last unknown that
   !> unknown k shares an element with (every matrix entry is an element's or a node's).
   pure subroutine dof_reach(mesh, sup, reach)
      type(mesh_t), intent(in) :: mesh       !< mesh
      type(supports_t), intent(in) :: sup    !< supports with their dof map
      integer, intent(out) :: reach(:)       !< (n_dof) last unknown coupled to each one
      integer :: e, nen, a, k, last
      do k = 1, sup%n_dof
         reach(k) = k
      end do
      do e = 1, mesh%n_elements
         nen = mesh%line_order(mesh%elem_line(e)) + 1
         associate (nodes => mesh%elem_nodes(1:nen, e))
            last = maxval(sup%first(nodes) + sup%ndof(nodes)) - 1
            do a = 1, nen
               do k = sup%first(nodes(a)), sup%first(nodes(a)) + sup%ndof(nodes(a)) - 1
                  reach(k) = max(reach(k), last)
               end do
            end do
         end associate
      end do
      do a = 1, mesh%n_nodes   ! a node's own block (inertia, supports, attachments)
         last = sup%first(a) + sup%ndof(a) - 1
         reach(sup%first(a):last) = max(reach(sup%first(a):last), last)
      end do
   end subroutine dof_reach

   !> Load vectors: consistent self-weight m g int N_a dS (m with the contents) plus the
   !> weight of the attachments at their nodes, and the point loads with their amplitudes.
   !> docs/theory.md eq. (28).
   subroutine loads_build(model, mesh, loads)
      type(model_t), intent(in) :: model  !< model
      type(mesh_t), intent(in) :: mesh    !< mesh
      type(loads_t), intent(out) :: loads !< loads
      real(wp) :: fa(3, max_nen)
      integer :: e, l, p, a, node, i, np
      allocate (loads%gravity(3, mesh%n_nodes))
      loads%gravity = 0.0_wp
      do e = 1, mesh%n_elements
         l = mesh%elem_line(e)
         p = mesh%line_order(l)
         call rod_element_line_load(p, mesh%elem_le(e), mesh%elem_mass(e)*model%gravity, &
                                    fa(:, 1:p + 1))
         do a = 1, p + 1
            node = mesh%elem_nodes(a, e)
            loads%gravity(:, node) = loads%gravity(:, node) + fa(:, a)
         end do
      end do
      if (allocated(model%bodies)) then        ! a FREE body's weight at its node, G
         do i = 1, size(model%bodies)
            node = mesh%body_node(i)
            if (model%bodies(i)%kind == body_free) loads%gravity(:, node) = &
               loads%gravity(:, node) + model%bodies(i)%mass*model%gravity
         end do
      end if
      if (allocated(model%attachments)) then
         do i = 1, size(model%attachments)
            node = mesh%att_node(i)
            loads%gravity(:, node) = loads%gravity(:, node) + model%attachments(i)%mass* &
                                     model%gravity
         end do
      end if
      np = 0
      if (allocated(model%loads)) np = size(model%loads)
      allocate (loads%pt_node(np), loads%pt_amp(np), loads%pt_fm(6, np))
      do i = 1, np
         if (model%loads(i)%point > 0) then        ! on a FREE point: its node
            loads%pt_node(i) = mesh%point_node(model%loads(i)%point)
         else if (model%loads(i)%body > 0) then    ! on a FREE body: its node (at G)
            loads%pt_node(i) = mesh%body_node(model%loads(i)%body)
         else
            loads%pt_node(i) = mesh_node(mesh, model%loads(i)%line, model%loads(i)%node)
         end if
         loads%pt_amp(i) = model%loads(i)%amplitude
         loads%pt_fm(1:3, i) = model%loads(i)%force
         loads%pt_fm(4:6, i) = model%loads(i)%moment
      end do
      if (allocated(model%amplitudes)) then
         loads%amps = model%amplitudes
      else
         allocate (loads%amps(0))
      end if
   end subroutine loads_build

   !> External force at time t and load factor lam: gravity scaled per line by
   !> gfac(line), point loads by lam a(t) (a their amplitude, 1 without). Statics is
   !> t = 0; a time step passes its force time and lam = gfac = 1.
   !> docs/theory.md eqs. (28), (106), (109).
   pure subroutine external_force(mesh, loads, gfac, lam, t, fext)
      type(mesh_t), intent(in) :: mesh        !< mesh
      type(loads_t), intent(in) :: loads      !< loads
      real(wp), intent(in) :: gfac(0:)        !< (0:nl) gravity factor of each line, 0: points
      real(wp), intent(in) :: lam             !< load factor of the point loads
      real(wp), intent(in) :: t               !< time [s]
      real(wp), intent(out) :: fext(:, :)     !< (6, nn) external force [N, N m]
      real(wp) :: fac
      integer :: node, i
      do node = 1, mesh%n_nodes
         fext(1:3, node) = gfac(mesh%node_line(node))*loads%gravity(:, node)
         fext(4:6, node) = 0.0_wp
      end do
      do i = 1, size(loads%pt_node)
         fac = lam
         if (loads%pt_amp(i) > 0) fac = lam*amplitude_value(loads%amps(loads%pt_amp(i)), t)
         node = loads%pt_node(i)
         fext(:, node) = fext(:, node) + fac*loads%pt_fm(:, i)
      end do
   end subroutine external_force

   !> The water's and seabed's loads (rodyn_water) subtracted from fint, their tangent
   !> from the matrix; xf, vf, af the nodes' positions, velocities and accelerations at
   !> the force point, moving with the unknowns by cx, cv, ca. The nodal forces are kept
   !> in wl%fh (water) and wl%fs (seabed).
   !> docs/theory.md eq. (73).
   subroutine assemble_water(wl, mesh, sup, xf, vf, af, cx, cv, ca, fint, bm, want_k)
      type(water_loads_t), intent(inout) :: wl !< loads (nodal forces updated)
      type(mesh_t), intent(in) :: mesh         !< mesh
      type(supports_t), intent(in) :: sup      !< supports (dof map)
      real(wp), intent(in) :: xf(:, :)         !< (3, nn) positions [m]
      real(wp), intent(in) :: vf(:, :)         !< (3, nn) velocities [m/s]
      real(wp), intent(in) :: af(:, :)         !< (3, nn) accelerations [m/s2]
      real(wp), intent(in) :: cx               !< d x_f / d x^{n+1} [-]
      real(wp), intent(in) :: cv               !< d v_f / d x^{n+1} [1/s]
      real(wp), intent(in) :: ca               !< d a_f / d x^{n+1} [1/s2]
      real(wp), intent(inout) :: fint(:, :)    !< (6, nn) internal forces [N]
      type(banded_t), intent(inout) :: bm      !< tangent
      logical, intent(in) :: want_k            !< add the tangent
      real(wp) :: fh(3, max_nen), fs(3, max_nen), ke(3*max_nen, 3*max_nen), f(3), k(3, 3)
      type(water_section_t) :: ws
      real(wp) :: qe(9, max_nen), we(7, max_nen)
      integer :: e, p, nen, a, j, node, dofs(3*max_nen), i
      wl%fh = 0.0_wp
      wl%fs = 0.0_wp
      do e = 1, mesh%n_elements
         p = mesh%line_order(mesh%elem_line(e))
         nen = p + 1
         associate (nodes => mesh%elem_nodes(1:nen, e))
            do a = 1, nen          ! (rodyn_water: a node's x, v and a as one column)
               qe(1:3, a) = xf(:, nodes(a))
               qe(4:6, a) = vf(:, nodes(a))
               qe(7:9, a) = af(:, nodes(a))
            end do
            if (wl%wave_on) then
               do a = 1, nen
                  we(:, a) = wl%wkin(:, nodes(a))
               end do
            end if
            ws = wl%sec(mesh%elem_sec(e))
            if (allocated(wl%bfac)) ws%fb = wl%bfac(mesh%elem_line(e))*ws%fb ! (statics)
            call water_element(wl, ws, p, mesh%elem_le(e), qe(:, 1:nen), cx, cv, ca, &
                               fh(:, 1:nen), fs(:, 1:nen), ke(1:3*nen, 1:3*nen), want_k, &
                               we(:, 1:nen))
            do a = 1, nen
               fint(1:3, nodes(a)) = fint(1:3, nodes(a)) - fh(:, a) - fs(:, a)
               wl%fh(:, nodes(a)) = wl%fh(:, nodes(a)) + fh(:, a)
               wl%fs(:, nodes(a)) = wl%fs(:, nodes(a)) + fs(:, a)
               do j = 1, 3
                  dofs(3*(a - 1) + j) = sup%first(nodes(a)) + j - 1
               end do
            end do
            if (want_k) call banded_add(bm, dofs(1:3*nen), -ke(1:3*nen, 1:3*nen))
         end associate
      end do
      do i = 1, size(wl%att_node)
         node = wl%att_node(i)
         if (wl%wave_on) then
            call water_attachment(wl, wl%att_volume(i), wl%att_cda(i), xf(:, node), &
                                  vf(:, node), cx, cv, f, k, want_k, wl%wkin(:, node), &
                                  wl%att_ca(i))
         else if (allocated(wl%bfac)) then
            call water_attachment(wl, wl%att_volume(i), wl%att_cda(i), xf(:, node), &
                                  vf(:, node), cx, cv, f, k, want_k, &
                                  bf=wl%bfac(mesh%node_line(node)))
         else
            call water_attachment(wl, wl%att_volume(i), wl%att_cda(i), xf(:, node), &
                                  vf(:, node), cx, cv, f, k, want_k)
         end if
         fint(1:3, node) = fint(1:3, node) - f
         wl%fh(:, node) = wl%fh(:, node) + f
         if (want_k) call banded_add(bm, [(sup%first(node) + j - 1, j=1, 3)], -k)
      end do
   end subroutine assemble_water

   !> Internal force fint (6, nn) in global axes and, if want_k, the tangent assembled
   !> into bm with the rotated nodes' bases applied (docs/theory.md eqs. (21)-(27)). The
   !> stress-free strains enter scaled by eps0_scale (the static load factor, so that a
   !> built-in curvature is applied gradually; 1 at the end of the analysis).
   subroutine assemble_static(mesh, sup, state, eps0_scale, fint, bm, want_k)
      type(mesh_t), intent(in) :: mesh        !< mesh
      type(supports_t), intent(in) :: sup    !< supports (for the node bases)
      type(state_t), intent(in) :: state      !< configuration
      real(wp), intent(in) :: eps0_scale      !< factor on the stress-free strains [-]
      real(wp), intent(out) :: fint(:, :)     !< (6, nn) internal forces [N, N m]
      type(banded_t), intent(inout) :: bm     !< tangent (zeroed here if want_k)
      logical, intent(in) :: want_k           !< form the tangent
      real(wp) :: fe(6, max_nen), ke(6*max_nen, 6*max_nen), xe(3, max_nen)
      real(wp) :: de(3, 3, max_nen), e0(6, max_points), fc(3, max_nen)
      real(wp) :: kc(3*max_nen, 3*max_nen)
      integer :: e, l, p, nen
      fint = 0.0_wp
      if (want_k) call banded_zero(bm)
      do e = 1, mesh%n_elements
         l = mesh%elem_line(e)
         p = mesh%line_order(l)
         nen = p + 1
         associate (nodes => mesh%elem_nodes(1:nen, e))
            call state_gather(state, nodes, xe, de)
            if (mesh%elem_cable(e)) then
               call cable_element_static(p, mesh%elem_le(e), mesh%elem_c(3, e), xe(:, 1:nen), &
                                         fc(:, 1:nen), kc(1:3*nen, 1:3*nen), want_k, &
                                         mesh%rules(p), slack_axial=.true.)
               call scatter_cable(sup, nodes, fc(:, 1:nen), kc(1:3*nen, 1:3*nen), fint, bm, &
                                  want_k)
            else
               e0 = eps0_scale*mesh%eps0(:, :, e)
               call rod_element_static(p, mesh%elem_le(e), mesh%elem_c(:, e), e0, &
                                       xe(:, 1:nen), de(:, :, 1:nen), fe(:, 1:nen), &
                                       ke(1:6*nen, 1:6*nen), want_k, mesh%rules(p))
               call scatter_element(sup, nodes, fe(:, 1:nen), ke(1:6*nen, 1:6*nen), fint, &
                                    bm, want_k)
            end if
         end associate
      end do
   end subroutine assemble_static

   !> Add a rod element's forces to fint and, if want_k, its matrix (in the node bases of
   !> rotated nodes) to the banded tangent (its nodes all have 6 unknowns).
   subroutine scatter_element(sup, nodes, fe, ke, fint, bm, want_k)
      type(supports_t), intent(in) :: sup   !< supports (node bases)
      integer, intent(in) :: nodes(:)       !< (nen) global nodes of the element
      real(wp), intent(in) :: fe(:, :)      !< (6, nen) element forces
      real(wp), intent(inout) :: ke(:, :)   !< (6 nen, 6 nen) element matrix (rotated here)
      real(wp), intent(inout) :: fint(:, :) !< (6, nn) global forces
      type(banded_t), intent(inout) :: bm   !< tangent
      logical, intent(in) :: want_k         !< add the matrix
      integer :: dofs(6*max_nen), a, j, nen
      nen = size(nodes)
      do a = 1, nen
         fint(:, nodes(a)) = fint(:, nodes(a)) + fe(:, a)
      end do
      if (.not. want_k) return
      do a = 1, nen
         do j = 1, 6
            dofs(6*(a - 1) + j) = sup%first(nodes(a)) + j - 1
         end do
         if (sup%rotated(nodes(a))) call rotate_rows_cols(ke, a, sup%basis(:, :, nodes(a)))
      end do
      call banded_add(bm, dofs(1:6*nen), ke)
   end subroutine scatter_element

   !> Step internal force fint (6, nn) of a time-integration scheme between the states
   !> s0 (t_n) and s1 (t_n+1) and, if want_k, its tangent with respect to the unknowns at
   !> t_n+1 (rodyn_rod_dynamic), assembled as in assemble_static.
   !> Stiffness-proportional Rayleigh damping (beta > 0; docs/theory.md eq. (40)) adds,
   !> element by element,
   !> f_d = beta/dt K_e(q^{n+1/2}) du_e, du = (x^{n+1} - x^n, theta) with theta the rotation
   !> of the step (inverse Cayley of d^{n+1} d^n^T), K_e the element tangent at the
   !> midpoint; its tangent is taken as beta/dt K_e (the change of K_e is neglected).
   !> The damping forces are also returned in fdamp (for the energy log).
   subroutine assemble_dynamic(mesh, sup, s0, s1, scheme, wf, beta, dt, fint, fdamp, bm, &
                               want_k, gp0, epsn, x_base, d_base, nd_fac, nd_off)
      type(mesh_t), intent(in) :: mesh        !< mesh
      type(supports_t), intent(in) :: sup    !< supports (for the node bases)
      type(state_t), intent(in) :: s0         !< state at t_n
      type(state_t), intent(in) :: s1         !< state at t_n+1 (current iterate)
      integer, intent(in) :: scheme           !< scheme_* constant
      real(wp), intent(in) :: wf              !< ALPHA: weight of t_n+1 in the force point
      real(wp), intent(in) :: beta            !< stiffness-proportional damping [s]
      real(wp), intent(in) :: dt              !< step [s]
      real(wp), intent(out) :: fint(:, :)     !< (6, nn) internal forces [N, N m]
      real(wp), intent(out) :: fdamp(:, :)    !< (6, nn) damping forces (in fint) [N, N m]
      type(banded_t), intent(inout) :: bm     !< tangent (zeroed here if want_k)
      logical, intent(in) :: want_k           !< form the tangent
      !> (max_points, ne), (6, max_points, ne): the rods' fields and strains of s0 at
      !> their points for EMC and TRAPEZOIDAL (rod_element_fields), if formed for the step
      type(rod_gp_t), intent(in), optional :: gp0(:, :)
      real(wp), intent(in), optional :: epsn(:, :, :)
      !> (3, nn), (3, 3, nn): Newton's base, for the stresses of an EMC tangent
      !> (rodyn_rod_dynamic's header); with gp0 and epsn only
      real(wp), intent(in), optional :: x_base(:, :), d_base(:, :, :)
      !> EMC with RHO INF < 1 (rodyn_numerical_dissipation): c1 + 2 c2, and the history
      !> stress of each point (6, max_points, ne) [N, N m] (docs/theory.md eq. (126))
      real(wp), intent(in), optional :: nd_fac, nd_off(:, :, :)
      ! the element's numerical stress (pointers: disassociated, they are absent there;
      ! no allocation inside the Newton loop)
      real(wp), target :: kd6(6), off6(6, max_points)
      real(wp), pointer :: kde(:), offe(:, :)   ! (no initialiser: it would imply save)
      real(wp) :: xb(3, max_nen), db(3, 3, max_nen)
      real(wp) :: fe(6, max_nen), ke(6*max_nen, 6*max_nen), x0(3, max_nen), x1(3, max_nen)
      real(wp) :: d0(3, 3, max_nen), d1(3, 3, max_nen)
      integer :: e, l, p, nen, a, nd
      fint = 0.0_wp
      fdamp = 0.0_wp
      nullify (kde, offe)
      if (present(nd_fac) .and. present(nd_off)) then
         kde => kd6
         offe => off6
      end if
      if (want_k) call banded_zero(bm)
      do e = 1, mesh%n_elements
         l = mesh%elem_line(e)
         if (mesh%elem_cable(e)) cycle     ! assemble_dynamic_cables
         p = mesh%line_order(l)
         nen = p + 1
         associate (nodes => mesh%elem_nodes(1:nen, e))
            call state_gather(s0, nodes, x0, d0)
            call state_gather(s1, nodes, x1, d1)
            if (associated(kde)) then
               kd6 = nd_fac*mesh%elem_c(:, e)
               off6 = nd_off(:, :, e)
            end if
            if (want_k .and. present(x_base) .and. present(d_base) .and. present(gp0) &
                .and. present(epsn)) then
               do a = 1, nen
                  xb(:, a) = x_base(:, nodes(a))
                  db(:, :, a) = d_base(:, :, nodes(a))
               end do
               call rod_element_dynamic(p, mesh%elem_le(e), mesh%elem_c(:, e), &
                                        mesh%eps0(:, :, e), x0(:, 1:nen), d0(:, :, 1:nen), &
                                        x1(:, 1:nen), d1(:, :, 1:nen), scheme, wf, &
                                        fe(:, 1:nen), ke(1:6*nen, 1:6*nen), want_k, &
                                        mesh%rules(p), gp0(:, e), epsn(:, :, e), &
                                        xb(:, 1:nen), db(:, :, 1:nen), kde, offe)
            else if (present(gp0) .and. present(epsn)) then
               call rod_element_dynamic(p, mesh%elem_le(e), mesh%elem_c(:, e), &
                                        mesh%eps0(:, :, e), x0(:, 1:nen), d0(:, :, 1:nen), &
                                        x1(:, 1:nen), d1(:, :, 1:nen), scheme, wf, &
                                        fe(:, 1:nen), ke(1:6*nen, 1:6*nen), want_k, &
                                        mesh%rules(p), gp0(:, e), epsn(:, :, e), kd=kde, &
                                        off=offe)
            else
               call rod_element_dynamic(p, mesh%elem_le(e), mesh%elem_c(:, e), &
                                        mesh%eps0(:, :, e), x0(:, 1:nen), d0(:, :, 1:nen), &
                                        x1(:, 1:nen), d1(:, :, 1:nen), scheme, wf, &
                                        fe(:, 1:nen), ke(1:6*nen, 1:6*nen), want_k, &
                                        mesh%rules(p), kd=kde, off=offe)
            end if
            nd = 6*nen
            if (beta > 0.0_wp) call rayleigh_rod(mesh, e, p, nen, beta/dt, x0, x1, d0, d1, &
                                                 nodes, fint, fdamp, ke(1:nd, 1:nd), want_k)
            call scatter_element(sup, nodes, fe(:, 1:nen), ke(1:nd, 1:nd), fint, bm, want_k)
         end associate
      end do
   end subroutine assemble_dynamic

   !> A rod element's stiffness-proportional damping (docs/theory.md eq. (40)): f_d = c
   !> K_e(q^{n+1/2}) du_e, c = beta/dt, added to fint and fdamp, and c K_e to ke if want_k
   !> (assemble_dynamic's header).
   subroutine rayleigh_rod(mesh, e, p, nen, c, x0, x1, d0, d1, nodes, fint, fdamp, ke, want_k)
      type(mesh_t), intent(in) :: mesh             !< mesh
      integer, intent(in) :: e, p, nen             !< element, its order and nodes
      real(wp), intent(in) :: c                    !< beta/dt [-]
      real(wp), intent(in) :: x0(:, :), x1(:, :)   !< (3, >= nen) positions at t_n, t_n+1
      real(wp), intent(in) :: d0(:, :, :), d1(:, :, :) !< (3, 3, >= nen) directors
      integer, intent(in) :: nodes(:)              !< (nen) its global nodes
      real(wp), intent(inout) :: fint(:, :)        !< (6, nn) internal forces
      real(wp), intent(inout) :: fdamp(:, :)       !< (6, nn) damping forces
      real(wp), intent(inout) :: ke(:, :)          !< (6 nen, 6 nen) element tangent
      logical, intent(in) :: want_k                !< add to the tangent
      real(wp) :: xm(3, max_nen), dm(3, 3, max_nen), ks(6*max_nen, 6*max_nen)
      real(wp) :: fs(6, max_nen), du(6*max_nen), fd(6*max_nen)
      integer :: a, j, nd
      nd = 6*nen
      do a = 1, nen
         xm(:, a) = 0.5_wp*(x0(:, a) + x1(:, a))
         dm(:, :, a) = 0.5_wp*(d0(:, :, a) + d1(:, :, a))
         du(6*a - 5:6*a - 3) = x1(:, a) - x0(:, a)
         du(6*a - 2:6*a) = rotation_cayley_inverse(relative_rotation(d1(:, :, a), d0(:, :, a)))
      end do
      call rod_element_static(p, mesh%elem_le(e), mesh%elem_c(:, e), mesh%eps0(:, :, e), &
                              xm(:, 1:nen), dm(:, :, 1:nen), fs(:, 1:nen), ks(1:nd, 1:nd), &
                              .true., mesh%rules(p))
      do j = 1, nd
         fd(j) = c*dot_product(ks(j, 1:nd), du(1:nd))
      end do
      do a = 1, nen
         fint(:, nodes(a)) = fint(:, nodes(a)) + fd(6*a - 5:6*a)
         fdamp(:, nodes(a)) = fdamp(:, nodes(a)) + fd(6*a - 5:6*a)
      end do
      if (want_k) ke = ke + c*ks(1:nd, 1:nd)
   end subroutine rayleigh_rod

   !> The cable elements' part of assemble_dynamic (same arguments; fint, fdamp and bm
   !> added to, after assemble_dynamic): a separate pass, so that the rod's element keeps
   !> being inlined into assemble_dynamic's loop (with the cable inside it, the compiler
   !> does not inline it).
   subroutine assemble_dynamic_cables(mesh, sup, s0, s1, scheme, wf, beta, dt, fint, fdamp, &
                                      bm, want_k, nd_fac, nd_off)
      type(mesh_t), intent(in) :: mesh        !< mesh
      type(supports_t), intent(in) :: sup     !< supports
      type(state_t), intent(in) :: s0, s1     !< states at t_n and t_n+1
      integer, intent(in) :: scheme           !< scheme_* constant
      real(wp), intent(in) :: wf, beta, dt    !< as assemble_dynamic
      real(wp), intent(inout) :: fint(:, :)   !< (6, nn) internal forces [N]
      real(wp), intent(inout) :: fdamp(:, :)  !< (6, nn) damping forces [N]
      type(banded_t), intent(inout) :: bm     !< tangent
      logical, intent(in) :: want_k           !< form the tangent
      real(wp), intent(in), optional :: nd_fac, nd_off(:, :, :) !< as assemble_dynamic
      real(wp), target :: kd1, off1(max_points)  ! as assemble_dynamic's kd6, off6
      real(wp), pointer :: kde, offe(:)   ! (no initialiser: it would imply save)
      real(wp) :: x0(3, max_nen), x1(3, max_nen)
      real(wp) :: fc(3, max_nen), kc(3*max_nen, 3*max_nen), fs(3, max_nen)
      real(wp) :: ks(3*max_nen, 3*max_nen), du(3*max_nen), fd(3*max_nen)
      integer :: e, p, nen, a, j, nc
      nullify (kde, offe)
      if (present(nd_fac) .and. present(nd_off)) then
         kde => kd1
         offe => off1
      end if
      do e = 1, mesh%n_elements
         if (.not. mesh%elem_cable(e)) cycle
         p = mesh%line_order(mesh%elem_line(e))
         nen = p + 1
         nc = 3*nen
         associate (nodes => mesh%elem_nodes(1:nen, e))
            do a = 1, nen                 ! positions only: a cable has no directors
               x0(:, a) = s0%x(:, nodes(a))
               x1(:, a) = s1%x(:, nodes(a))
            end do
            if (associated(kde)) then
               kd1 = nd_fac*mesh%elem_c(3, e)
               off1 = nd_off(3, :, e)
            end if
            call cable_element_dynamic(p, mesh%elem_le(e), mesh%elem_c(3, e), x0(:, 1:nen), &
                                       x1(:, 1:nen), scheme, wf, fc(:, 1:nen), &
                                       kc(1:nc, 1:nc), want_k, mesh%rules(p), kde, offe)
            ! Rayleigh damping f_d = beta/dt K_e(x^{n+1/2}) (x^{n+1} - x^n)
            if (beta > 0.0_wp) then
               call cable_element_static(p, mesh%elem_le(e), mesh%elem_c(3, e), &
                                         0.5_wp*(x0(:, 1:nen) + x1(:, 1:nen)), fs(:, 1:nen), &
                                         ks(1:nc, 1:nc), .true., mesh%rules(p))
               du(1:nc) = reshape(x1(:, 1:nen) - x0(:, 1:nen), [nc])
               do j = 1, nc
                  fd(j) = beta/dt*dot_product(ks(j, 1:nc), du(1:nc))
               end do
               fc(:, 1:nen) = fc(:, 1:nen) + reshape(fd(1:nc), [3, nen])
               do a = 1, nen
                  fdamp(1:3, nodes(a)) = fdamp(1:3, nodes(a)) + fd(3*a - 2:3*a)
               end do
               if (want_k) kc(1:nc, 1:nc) = kc(1:nc, 1:nc) + beta/dt*ks(1:nc, 1:nc)
            end if
            call scatter_cable(sup, nodes, fc(:, 1:nen), kc(1:nc, 1:nc), fint, bm, want_k)
         end associate
      end do
   end subroutine assemble_dynamic_cables

   !> Add a cable element's forces (3, nen) to fint and, if want_k, its matrix
   !> (3 nen, 3 nen) to the tangent on its nodes' translation unknowns (a node shared
   !> with a rod keeps its rotations, which the cable does not touch).
   subroutine scatter_cable(sup, nodes, fc, kc, fint, bm, want_k)
      type(supports_t), intent(in) :: sup   !< supports (dof map)
      integer, intent(in) :: nodes(:)       !< (nen) global nodes of the element
      real(wp), intent(in) :: fc(:, :)      !< (3, nen) element forces [N]
      real(wp), intent(in) :: kc(:, :)      !< (3 nen, 3 nen) element matrix
      real(wp), intent(inout) :: fint(:, :) !< (6, nn) global forces
      type(banded_t), intent(inout) :: bm   !< tangent
      logical, intent(in) :: want_k         !< add the matrix
      integer :: dofs(3*max_nen), a, j, nen
      nen = size(nodes)
      do a = 1, nen
         fint(1:3, nodes(a)) = fint(1:3, nodes(a)) + fc(:, a)
      end do
      if (.not. want_k) return
      do a = 1, nen
         do j = 1, 3
            dofs(3*(a - 1) + j) = sup%first(nodes(a)) + j - 1
         end do
      end do
      call banded_add(bm, dofs(1:3*nen), kc)
   end subroutine scatter_cable

   !> Add a 6x6 block (force/moment of one node against its own unknowns) to the
   !> tangent, in the node's basis if it has one (the 3x3 translation block only at a
   !> node without rotation unknowns).
   subroutine add_node_block(sup, node, kb, bm)
      type(supports_t), intent(in) :: sup   !< supports (node bases)
      integer, intent(in) :: node           !< global node
      real(wp), intent(in) :: kb(6, 6)      !< block, global axes
      type(banded_t), intent(inout) :: bm   !< tangent
      real(wp) :: k(6, 6)
      integer :: j, dofs(6), nd
      nd = sup%ndof(node)
      do j = 1, 6                  ! (a loop: an array constructor allocates)
         dofs(j) = sup%first(node) + j - 1
      end do
      if (nd == 3) then            ! no rotation unknowns: the translation block only
         call banded_add(bm, dofs(1:3), kb(1:3, 1:3))
         return
      end if
      k = kb
      if (sup%rotated(node)) call rotate_rows_cols(k, 1, sup%basis(:, :, node))
      call banded_add(bm, dofs, k)
   end subroutine add_node_block

   !> k <- T^T k T on the rotation rows and columns of element node a.
   !> docs/theory.md eq. (48).
   pure subroutine rotate_rows_cols(k, a, t)
      real(wp), intent(inout) :: k(:, :) !< element matrix
      integer, intent(in) :: a           !< element node
      real(wp), intent(in) :: t(3, 3)    !< basis (columns)
      real(wp) :: rows(3, 6*max_nen), cols(6*max_nen, 3)
      integer :: r, n, i, j
      r = 6*(a - 1) + 3
      n = size(k, 1)
      rows(:, 1:n) = k(r + 1:r + 3, :)
      do j = 1, n
         do i = 1, 3
            k(r + i, j) = t(1, i)*rows(1, j) + t(2, i)*rows(2, j) + t(3, i)*rows(3, j)
         end do
      end do
      cols(1:n, :) = k(:, r + 1:r + 3)
      do j = 1, 3
         k(:, r + j) = cols(1:n, 1)*t(1, j) + cols(1:n, 2)*t(2, j) + cols(1:n, 3)*t(3, j)
      end do
   end subroutine rotate_rows_cols

   !> Right-hand side for the Newton step K du = -rhs: the residual in the node bases;
   !> at a held dof k, rhs_k = -gap_k so that du_k = gap_k (the distance still to go to
   !> a prescribed position), and K_fk gap_k moved to the free rows before the held rows
   !> and columns of the tangent are replaced by the identity:
   !>   K_ff du_f = -(r_f + K_fk gap_k).
   !> The columns K_fk of moved nodes are kept when the tangent is formed (want_k), so
   !> that a later residual-only evaluation, solved with a reused tangent, moves its gaps
   !> the same way.
   !> docs/theory.md eq. (47).
   subroutine apply_supports(sup, r, gap, rhs, bm, want_k)
      type(supports_t), intent(in) :: sup   !< supports
      real(wp), intent(in) :: r(:, :)       !< (6, nn) residual fint - fext, global axes
      real(wp), intent(in) :: gap(:, :)     !< (3, nn) prescribed position - position [m]
      real(wp), intent(out) :: rhs(:)       !< (n_dof) right-hand side
      type(banded_t), intent(inout) :: bm   !< tangent
      logical, intent(in) :: want_k         !< the tangent was formed: fix its held dofs
      integer :: node, j, k, i
      logical :: uni
      uni = sup%uniform
      ! 6 unknowns a node unless the map says otherwise: then rhs is r as one sequence
      ! (copy_values: one vector move instead of a node by node copy)
      if (uni) call copy_values(size(r), r, rhs)
      do node = 1, size(r, 2)
         k = 6*(node - 1)
         if (.not. uni) then
            k = sup%first(node) - 1
            if (sup%ndof(node) == 3) then
               rhs(k + 1:k + 3) = r(1:3, node)
               cycle
            end if
            rhs(k + 1:k + 6) = r(:, node)
         end if
         if (sup%rotated(node)) rhs(k + 4:k + 6) = matmul(transpose(sup%basis(:, :, node)), &
                                                          r(4:6, node))
      end do
      do node = 1, size(r, 2)
         if (.not. sup%moved(node)) cycle
         k = sup%first(node) - 1
         do j = 1, 3
            if (want_k) call banded_keep_column(bm, k + j)
            if (gap(j, node) /= 0.0_wp) call banded_kept_axpy(bm, k + j, gap(j, node), rhs)
         end do
      end do
      do i = 1, sup%n_held
         k = sup%held_dof(i)
         j = sup%held_j(i)
         rhs(k) = 0.0_wp
         if (j <= 3) rhs(k) = -gap(j, sup%held_node(i))
         if (want_k) call banded_fix_dof(bm, k)
      end do
   end subroutine apply_supports
end module rodyn_assembly
