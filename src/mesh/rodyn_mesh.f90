!> Finite element mesh of the lines: nodes, elements, arc lengths, section stiffness,
!> the stress-free strains at the integration points and the initial configuration
!> (docs/theory.md eqs. (8), (19)-(21); section 14, eqs. (112)-(115), for the catenary
!> start).
!>
!> Nodes of all lines are numbered consecutively, line after line, each line from
!> end A (S = 0) to end B (S = L); an element of order p has p+1 equally spaced nodes.
module rodyn_mesh
   use rodyn_kinds, only: wp, pi
   use rodyn_error, only: error_t, set_error, stat_input, has_error
   use rodyn_section, only: section_stiffness, section_damping
   use rodyn_model, only: model_t, bc_free, bc_pinned, bc_hinged, bc_clamped, &
                          bc_position, end_a, end_b, element_cable, scheme_alpha, point_free, &
                          point_body, body_free
   use rodyn_state, only: state_t, state_allocate
   use rodyn_rotation, only: rotation_exp, rotation_frame, cross, skew
   use rodyn_catenary, only: catenary_t, catenary_solve, catenary_point, catenary_grounded
   use rodyn_seabed, only: seabed_z
   use rodyn_rod_element, only: rod_element_strains, max_points, rod_rule_t, rod_rule, &
                                rod_hidden_shear
   use rodyn_shape, only: max_nen, max_order
   use rodyn_memory, only: memory_estimate, memory_physical, memory_text
   implicit none
   private
   public :: line_mean_weight
   public :: mesh_t, mesh_build, mesh_node

   !> The discretised model.
   type :: mesh_t
      integer :: n_lines = 0
      integer :: n_nodes = 0
      integer :: n_elements = 0
      integer :: max_nen = 2                   !< most nodes in one element
      type(rod_rule_t) :: rules(max_order)     !< quadrature and shape functions per order
      ! per line
      integer, allocatable :: line_first_node(:)  !< (nl) global number of node A
      integer, allocatable :: line_n_nodes(:)     !< (nl)
      integer, allocatable :: line_first_elem(:)  !< (nl)
      integer, allocatable :: line_order(:)       !< (nl) element order p
      logical, allocatable :: line_catenary(:)    !< (nl) started as a catenary (held at both ends)
      logical, allocatable :: line_cable(:)       !< (nl) only cable elements
      ! per element
      integer, allocatable :: elem_line(:)        !< (ne)
      integer, allocatable :: elem_sec(:)         !< (ne) section (model%sections index)
      logical, allocatable :: elem_cable(:)       !< (ne) a cable element (else a rod)
      integer :: n_cable = 0                      !< how many elements are cables
      real(wp), allocatable :: elem_c(:, :)       !< (6, ne) diag(GA1,GA2,EA,EI1,EI2,GJ)
      real(wp), allocatable :: elem_mass(:)       !< (ne) mass per length, structure and
                                                  !< contents rho_i pi ID^2/4 [kg/m]
      !> (3, ne) structural damping (C_a, C_b1, C_b2) [N s, N m2 s, N m2 s] (section_damping)
      real(wp), allocatable :: elem_damp(:, :)
      logical :: damped = .false.                 !< some element has structural damping
      integer, allocatable :: elem_nodes(:, :)    !< (max_nen, ne) global node numbers
      real(wp), allocatable :: elem_le(:)         !< (ne) unstretched length [m]
      real(wp), allocatable :: elem_s0(:)         !< (ne) arc length of its first node [m]
      real(wp), allocatable :: eps0(:, :, :)      !< (6, max_points, ne) stress-free strains
      ! per node
      integer, allocatable :: node_line(:)        !< (nn)
      real(wp), allocatable :: node_s(:)          !< (nn) unstretched arc length [m]
      ! per attachment (*ATTACHMENT, and a FREE point's own: its point's node)
      integer, allocatable :: att_node(:)         !< (na) node nearest to its arc length
      ! the points of a system (*POINT): a FREE point is a node of its own after the
      ! lines' nodes (node_line 0, no element: 3 unknowns); the line ends on it share
      ! its position (rodyn_junctions)
      integer :: n_line_nodes = 0                 !< nodes on lines (the first ones)
      integer, allocatable :: point_node(:)       !< (np) node of each FREE point, else 0
      !> (nb) node of each body (after the points' nodes; at its centre of gravity G, its
      !> directors the body's axes: 6 unknowns, held for a FIXED body)
      integer, allocatable :: body_node(:)
      !> (2, nl) the node that ends A, B move with: a FREE point's or a FREE body's (0: none)
      integer, allocatable :: end_point_node(:, :)
      !> (3, 2, nl) where the end is on its body: body axes, from G [m] (0 on a point)
      real(wp), allocatable :: end_offset(:, :, :)
      !> (2, nl) the end is clamped to its body (a rod's end: it turns with the body)
      logical, allocatable :: end_clamped(:, :)
   end type mesh_t

   !> The chord of a line and its weight, as its start shape needs them (line_chord).
   type :: line_chord_t
      real(wp) :: chord(3)    !< end B - end A [m]
      real(wp) :: dist        !< |chord| [m]
      real(wp) :: up(3)       !< unit vector against gravity [-]
      real(wp) :: eh(3)       !< horizontal part of the chord [m]
      real(wp) :: span        !< |eh| [m]
      real(wp) :: rise        !< height of end B above end A [m]
      real(wp) :: w           !< mean weight per length (in water: submerged) [N/m]
      real(wp) :: ea          !< mean axial stiffness [N]
   end type line_chord_t

   !> The catenary a line starts from, in the vertical plane of its chord
   !> (start_catenary).
   type :: start_catenary_t
      type(line_chord_t) :: lc         !< the chord
      type(catenary_t) :: cat          !< the catenary
      logical :: grounded = .false.    !< with a grounded length at its lower end
      logical :: b_low = .false.       !< grounded at end B: arc length L - s from B
   end type start_catenary_t

contains

   !> Global node number of node k (or end_a / end_b) of line l.
   pure integer function mesh_node(mesh, l, k)
      type(mesh_t), intent(in) :: mesh !< mesh
      integer, intent(in) :: l         !< line index
      integer, intent(in) :: k         !< node along the line, or end_a / end_b
      if (k == end_b) then
         mesh_node = mesh%line_first_node(l) + mesh%line_n_nodes(l) - 1
      else
         mesh_node = mesh%line_first_node(l) + k - 1
      end if
   end function mesh_node

   !> Global number of the node of line l nearest to unstretched arc length s.
   pure integer function mesh_nearest_node(mesh, l, s)
      type(mesh_t), intent(in) :: mesh !< mesh
      integer, intent(in) :: l         !< line index
      real(wp), intent(in) :: s        !< arc length from end A [m]
      integer :: n0
      n0 = mesh%line_first_node(l)
      mesh_nearest_node = n0 - 1 + minloc(abs(mesh%node_s(n0:n0 + mesh%line_n_nodes(l) - 1) - s), &
                                          dim=1)
   end function mesh_nearest_node

   !> Build the mesh and the initial configuration from the model. First the memory the
   !> run needs is estimated (rodyn_memory): more than the machine's physical memory is
   !> refused (stat_input, at the *LINE card with most elements) before any allocation.
   !> With initial_shape false (rodyn --check, which computes nothing) the lines' starting
   !> catenaries are not solved: the state is left at zero, only the checks that need no
   !> computing (a slack line that cannot hang) are made.
   subroutine mesh_build(model, mesh, state, err, initial_shape)
      type(model_t), intent(in) :: model     !< validated model
      type(mesh_t), intent(out) :: mesh      !< mesh
      type(state_t), intent(inout) :: state  !< initial configuration
      type(error_t), intent(inout) :: err    !< status
      logical, intent(in), optional :: initial_shape !< solve the starting shape (default)
      integer :: l, nl, nn, ne, p, k
      logical :: shape
      real(wp) :: need, have
      integer :: largest
      shape = .true.
      if (present(initial_shape)) shape = initial_shape
      call memory_estimate(model, need, largest)
      have = memory_physical()
      if (have > 0.0_wp .and. need > have .and. largest > 0) then
         associate (ld => model%lines(largest))
            call set_error(err, stat_input, line_at(model, largest)//': error: *LINE: '// &
                           'the model needs about '//memory_text(need)//' of memory '// &
                           '(line '//trim(ld%name)//': '//int_text(ld%n_elements)// &
                           ' elements of order '//int_text(ld%order)//'), more than the '// &
                           memory_text(have)//' of this machine: use fewer elements')
         end associate
         return
      end if
      do p = 1, max_order
         mesh%rules(p) = rod_rule(p)
      end do
      nl = size(model%lines)
      mesh%n_lines = nl
      allocate (mesh%line_first_node(nl), mesh%line_n_nodes(nl), mesh%line_first_elem(nl), &
                mesh%line_order(nl), mesh%line_catenary(nl), mesh%line_cable(nl))
      nn = 0
      ne = 0
      mesh%max_nen = 2
      do l = 1, nl
         p = model%lines(l)%order
         mesh%line_order(l) = p
         mesh%line_first_node(l) = nn + 1
         mesh%line_first_elem(l) = ne + 1
         mesh%line_n_nodes(l) = model%lines(l)%n_elements*p + 1
         mesh%line_catenary(l) = held_in_position(model, l, end_a) .and. &
                                 held_in_position(model, l, end_b)
         nn = nn + mesh%line_n_nodes(l)
         ne = ne + model%lines(l)%n_elements
         mesh%max_nen = max(mesh%max_nen, p + 1)
      end do
      mesh%n_line_nodes = nn
      call point_nodes(model, mesh, nn)
      mesh%n_nodes = nn
      mesh%n_elements = ne
      allocate (mesh%elem_line(ne), mesh%elem_nodes(mesh%max_nen, ne), mesh%elem_le(ne), &
                mesh%elem_s0(ne), mesh%eps0(6, max_points, ne), mesh%node_line(nn), &
                mesh%node_s(nn), mesh%elem_sec(ne), mesh%elem_c(6, ne), mesh%elem_mass(ne), &
                mesh%elem_cable(ne), mesh%elem_damp(3, ne))
      mesh%elem_nodes = 0
      mesh%eps0 = 0.0_wp
      ! the accelerations only for the generalized-alpha scheme (rodyn_state)
      call state_allocate(state, nn, model%dynamic%scheme == scheme_alpha)
      do l = 1, nl
         p = mesh%line_order(l)
         call line_elements(model, mesh, l)
         associate (e1 => mesh%line_first_elem(l))
            mesh%line_cable(l) = all(mesh%elem_cable(e1:e1 + model%lines(l)%n_elements - 1))
         end associate
         call line_stress_free_strains(model, mesh, l)
         call line_initial_shape(model, mesh, l, state, shape, err)
         if (has_error(err)) return
      end do
      call place_point_nodes(model, mesh, state)
      ! the line ends on FREE points and bodies where their points are
      do l = 1, nl
         do k = 1, 2
            if (mesh%end_point_node(k, l) == 0) cycle
            state%x(:, mesh_node(mesh, l, merge(end_a, end_b, k == 1))) = &
               state%x(:, mesh%end_point_node(k, l)) + mesh%end_offset(:, k, l)
         end do
      end do
      call clamp_axes(model, mesh, state)
      mesh%n_cable = count(mesh%elem_cable)
      mesh%damped = any(mesh%elem_damp > 0.0_wp)
      allocate (mesh%att_node(0))
      if (allocated(model%attachments)) mesh%att_node = [(attachment_node(k), &
                                                          k=1, size(model%attachments))]
   contains
      integer function attachment_node(i)
         integer, intent(in) :: i
         associate (at => model%attachments(i))
            if (at%point > 0) then
               attachment_node = mesh%point_node(at%point)
            else
               attachment_node = mesh_nearest_node(mesh, at%line, at%s)
            end if
         end associate
      end function attachment_node
   end subroutine mesh_build

   !> The FREE points' and the bodies' nodes, numbered after the lines' nn nodes (nn
   !> counts them on return), and the node each line end moves with, with its offset.
   pure subroutine point_nodes(model, mesh, nn)
      type(model_t), intent(in) :: model   !< model
      type(mesh_t), intent(inout) :: mesh  !< point_node, body_node, end_* set
      integer, intent(inout) :: nn         !< nodes so far
      integer :: np, nb, k, l, ip
      np = 0
      nb = 0
      if (allocated(model%points)) np = size(model%points)
      if (allocated(model%bodies)) nb = size(model%bodies)
      allocate (mesh%point_node(np), mesh%body_node(nb), mesh%end_point_node(2, mesh%n_lines), &
                mesh%end_offset(3, 2, mesh%n_lines), mesh%end_clamped(2, mesh%n_lines))
      mesh%point_node = 0
      mesh%body_node = 0
      do k = 1, np
         if (model%points(k)%kind /= point_free) cycle
         nn = nn + 1
         mesh%point_node(k) = nn
      end do
      do k = 1, nb              ! (a FIXED body too: its unknowns are held)
         nn = nn + 1
         mesh%body_node(k) = nn
      end do
      mesh%end_point_node = 0
      mesh%end_offset = 0.0_wp
      mesh%end_clamped = .false.
      do l = 1, mesh%n_lines
         do k = 1, 2
            ip = merge(model%lines(l)%point_a, model%lines(l)%point_b, k == 1)
            if (ip == 0) cycle
            if (model%points(ip)%kind == point_free) then
               mesh%end_point_node(k, l) = mesh%point_node(ip)
            else if (model%points(ip)%kind == point_body) then
               mesh%end_point_node(k, l) = mesh%body_node(model%points(ip)%body)
               mesh%end_offset(:, k, l) = model%points(ip)%position - &
                                          model%bodies(model%points(ip)%body)%cog
               mesh%end_clamped(k, l) = model%points(ip)%clamped
            end if
         end do
      end do
   end subroutine point_nodes

   !> A line end clamped to a point with an axis (*POINT, CONNECTION=CLAMPED, its second
   !> data line a, body axes; the global axes at the start) starts with its directors
   !> turned, by the least rotation, to d3 = a/|a| at end A (the line leaves along a) and
   !> d3 = -a/|a| at end B (it arrives against a); the clamp holds that attitude
   !> (rodyn_junctions: junctions_clamp). Its positions are the starting shape's: the
   !> statics bend the line to it.
   pure subroutine clamp_axes(model, mesh, state)
      type(model_t), intent(in) :: model     !< model
      type(mesh_t), intent(in) :: mesh       !< mesh
      type(state_t), intent(inout) :: state  !< the ends' directors turned
      real(wp) :: t(3), c(3), s, co
      integer :: l, k, ip, n
      do l = 1, mesh%n_lines
         do k = 1, 2
            ip = merge(model%lines(l)%point_a, model%lines(l)%point_b, k == 1)
            if (ip == 0) cycle
            if (.not. (model%points(ip)%clamped .and. &
                       norm2(model%points(ip)%clamp_axis) > 0.0_wp)) cycle
            t = model%points(ip)%clamp_axis/norm2(model%points(ip)%clamp_axis)
            if (k == 2) t = -t
            n = mesh_node(mesh, l, merge(end_a, end_b, k == 1))
            c = cross(state%d(:, 3, n), t)
            s = norm2(c)
            co = dot_product(state%d(:, 3, n), t)
            if (s > 0.0_wp) then
               state%d(:, :, n) = matmul(rotation_exp(c/s*atan2(s, co)), state%d(:, :, n))
            else if (co < 0.0_wp) then          ! opposite: half a turn about d1
               state%d(:, :, n) = matmul(rotation_exp(pi*state%d(:, 1, n)), state%d(:, :, n))
            end if
         end do
      end do
   end subroutine clamp_axes

   !> The FREE points' and bodies' nodes at the start: a point where it is, its directors
   !> the global axes; a body at its centre of gravity R + G, its directors the body's
   !> axes (the global axes at the start).
   pure subroutine place_point_nodes(model, mesh, state)
      type(model_t), intent(in) :: model     !< model
      type(mesh_t), intent(inout) :: mesh    !< node_line, node_s of the nodes set
      type(state_t), intent(inout) :: state  !< their positions and directors
      real(wp), parameter :: eye(3, 3) = reshape([1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, &
                                                  0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [3, 3])
      integer :: k, n
      do k = 1, size(mesh%point_node)
         n = mesh%point_node(k)
         if (n == 0) cycle
         mesh%node_line(n) = 0
         mesh%node_s(n) = 0.0_wp
         state%x(:, n) = model%points(k)%position
         state%d(:, :, n) = eye
      end do
      do k = 1, size(mesh%body_node)
         n = mesh%body_node(k)
         if (n == 0) cycle
         mesh%node_line(n) = 0
         mesh%node_s(n) = 0.0_wp
         state%x(:, n) = model%bodies(k)%position + model%bodies(k)%cog
         state%d(:, :, n) = eye
      end do
   end subroutine place_point_nodes

   !> Elements and nodes of line l, segment after segment from end A: each element of a
   !> segment has the segment's section and length / elements; nodes equally spaced in
   !> each element. Mass per length includes the contents, rho_i pi ID^2/4.
   subroutine line_elements(model, mesh, l)
      type(model_t), intent(in) :: model   !< model
      type(mesh_t), intent(inout) :: mesh  !< mesh (line l's elements and nodes filled)
      integer, intent(in) :: l             !< line index
      real(wp) :: s0, seg_len
      integer :: p, el, e, a, iseg, k, node, nseg, isec, nel
      p = mesh%line_order(l)
      associate (ld => model%lines(l))
         el = 0
         s0 = 0.0_wp
         nseg = 1
         if (allocated(ld%seg_section)) nseg = size(ld%seg_section)
         do iseg = 1, nseg
            ! a line without segment arrays (built in code) is one segment
            isec = ld%section
            seg_len = ld%length
            nel = ld%n_elements
            if (allocated(ld%seg_section)) then
               isec = ld%seg_section(iseg)
               seg_len = ld%seg_length(iseg)
               nel = ld%seg_elements(iseg)
            end if
            associate (sec => model%sections(isec))
               do k = 1, nel
                  el = el + 1
                  e = mesh%line_first_elem(l) + el - 1
                  mesh%elem_line(e) = l
                  mesh%elem_sec(e) = isec
                  ! the line's ELEMENT= if given, else the section's
                  if (ld%element /= 0) then
                     mesh%elem_cable(e) = ld%element == element_cable
                  else
                     mesh%elem_cable(e) = sec%element == element_cable
                  end if
                  mesh%elem_c(:, e) = section_stiffness(sec)
                  mesh%elem_mass(e) = sec%mass + sec%rho_i*0.25_wp*pi*sec%id**2
                  mesh%elem_le(e) = seg_len/real(nel, wp)
                  mesh%elem_damp(:, e) = section_damping(sec, mesh%elem_mass(e), &
                                                         mesh%elem_le(e)/real(p, wp))
                  if (mesh%elem_cable(e)) mesh%elem_damp(2:3, e) = 0.0_wp
                  mesh%elem_s0(e) = s0 + mesh%elem_le(e)*real(k - 1, wp)
                  do a = 1, p + 1
                     node = mesh%line_first_node(l) + (el - 1)*p + a - 1
                     mesh%elem_nodes(a, e) = node
                     mesh%node_line(node) = l
                     mesh%node_s(node) = mesh%elem_s0(e) + mesh%elem_le(e)*real(a - 1, wp) &
                                         /real(p, wp)
                  end do
               end do
            end associate
            s0 = s0 + seg_len
         end do
         ! the last node at the line's length exactly (no round-off of the sums)
         mesh%node_s(mesh%line_first_node(l) + mesh%line_n_nodes(l) - 1) = ld%length
      end associate
   end subroutine line_elements

   !> Length-weighted mean weight per unstretched length of line l for its starting
   !> catenary, in water the submerged weight (m - rho_w pi D_b^2/4) g, and mean EA.
   subroutine line_mean_weight(model, mesh, l, w, ea)
      type(model_t), intent(in) :: model !< model
      type(mesh_t), intent(in) :: mesh   !< mesh
      integer, intent(in) :: l           !< line index
      real(wp), intent(out) :: w         !< mean weight per length [N/m]
      real(wp), intent(out) :: ea        !< mean axial stiffness [N]
      real(wp) :: m
      integer :: e
      w = 0.0_wp
      ea = 0.0_wp
      do e = mesh%line_first_elem(l), mesh%line_first_elem(l) + model%lines(l)%n_elements - 1
         m = mesh%elem_mass(e)
         if (model%water%present) m = m - model%water%density*0.25_wp*pi* &
                                      max(model%sections(mesh%elem_sec(e))%db, 0.0_wp)**2
         w = w + m*mesh%elem_le(e)
         ea = ea + mesh%elem_c(3, e)*mesh%elem_le(e)
      end do
      w = w*norm2(model%gravity)/model%lines(l)%length
      ea = ea/model%lines(l)%length
   end subroutine line_mean_weight

   !> An integer as text.
   pure function int_text(i) result(s)
      integer, intent(in) :: i           !< the integer
      character(len=:), allocatable :: s !< its decimal text
      character(len=12) :: buf
      write (buf, '(i0)') i
      s = trim(buf)
   end function int_text

   !> 'FILE:LINE' of the *LINE card of line l (the deck's name for a line built in code).
   pure function line_at(model, l) result(at)
      type(model_t), intent(in) :: model  !< model
      integer, intent(in) :: l            !< line index
      character(len=:), allocatable :: at !< location
      if (allocated(model%lines(l)%card_at)) then
         at = model%lines(l)%card_at
      else if (allocated(model%deck_file)) then
         at = model%deck_file
      else
         at = 'rodyn'
      end if
   end function line_at

   !> True when node k of line l is held in position by a *BOUNDARY.
   pure logical function held_in_position(model, l, k)
      type(model_t), intent(in) :: model !< model
      integer, intent(in) :: l           !< line index
      integer, intent(in) :: k           !< end_a or end_b
      integer :: i, nn
      ! an end on a point is where its point is (held, or moved with the point)
      held_in_position = merge(model%lines(l)%point_a, model%lines(l)%point_b, k == end_a) > 0
      if (held_in_position .or. .not. allocated(model%constraints)) return
      nn = model%lines(l)%n_elements*model%lines(l)%order + 1
      do i = 1, size(model%constraints)
         associate (c => model%constraints(i))
            if (c%line /= l) cycle
            if (.not. same_node(c%node, k, nn)) cycle
            held_in_position = any(c%kind == [bc_pinned, bc_hinged, bc_clamped, bc_position])
         end associate
      end do
   end function held_in_position

   !> Same node of a line with nn nodes, allowing for the end_a / end_b aliases.
   pure logical function same_node(k1, k2, nn)
      integer, intent(in) :: k1 !< node or alias
      integer, intent(in) :: k2 !< node or alias
      integer, intent(in) :: nn !< nodes on the line
      same_node = resolve(k1) == resolve(k2)
   contains
      pure integer function resolve(k)
         integer, intent(in) :: k
         resolve = k
         if (k == end_b) resolve = nn
      end function resolve
   end function same_node

   !> Strains of the discrete stress-free shape at the integration points: the rod
   !> with constant material curvature kappa0, R(S) = exp(S skew(kappa0)),
   !> x(S) = int_0^S R e3 dS, interpolated exactly as the deformed rod is. A rigid
   !> motion of this shape then stores no energy.
   subroutine line_stress_free_strains(model, mesh, l)
      type(model_t), intent(in) :: model   !< model
      type(mesh_t), intent(inout) :: mesh  !< mesh (eps0 filled for line l)
      integer, intent(in) :: l             !< line index
      real(wp) :: kap(3), xe(3, max_nen), de(3, 3, max_nen), xig(max_points), s, k
      real(wp) :: kk(3, 3), r(3, 3), integral(3, 3)
      integer :: e, el, a, p, i
      p = mesh%line_order(l)
      do el = 1, model%lines(l)%n_elements
         e = mesh%line_first_elem(l) + el - 1
         kap = model%sections(mesh%elem_sec(e))%kappa0
         if (all(kap == 0.0_wp) .or. mesh%elem_cable(e)) cycle
         kk = skew(kap)
         k = norm2(kap)
         do a = 1, p + 1
            s = mesh%elem_s0(e) + mesh%elem_le(e)*real(a - 1, wp)/real(p, wp)
            r = rotation_exp(s*kap)
            ! int_0^s exp(t K) dt = s I + (1 - cos ks)/k^2 K + (ks - sin ks)/k^3 K^2
            integral = (1.0_wp - cos(k*s))/k**2*kk + (k*s - sin(k*s))/k**3*matmul(kk, kk)
            do i = 1, 3
               integral(i, i) = integral(i, i) + s
            end do
            xe(:, a) = integral(:, 3)
            de(:, :, a) = r
         end do
         call rod_element_strains(p, mesh%elem_le(e), xe(:, 1:p + 1), de(:, :, 1:p + 1), &
                                  mesh%eps0(:, :, e), xig)
      end do
   end subroutine line_stress_free_strains

   !> Initial configuration of line l: the elastic catenary when both ends are held in
   !> position and the line is slack with a weight in water (ends not vertically
   !> aligned): hanging for a weight > 0, floating up (the catenary turned upside down:
   !> gravity's direction reversed) for a buoyant line; else the straight line from A
   !> towards B.
   subroutine line_initial_shape(model, mesh, l, state, shape, err)
      type(model_t), intent(in) :: model     !< model
      type(mesh_t), intent(in) :: mesh       !< mesh
      integer, intent(in) :: l               !< line index
      type(state_t), intent(inout) :: state  !< configuration (line l filled)
      logical, intent(in) :: shape           !< solve the shape (else only check the line)
      type(error_t), intent(inout) :: err    !< status
      type(line_chord_t) :: lc
      type(start_catenary_t) :: sc
      real(wp) :: t(3), n2(3), stretch
      integer :: k, node
      call line_chord(model, mesh, l, lc)
      call check_slack_line(model, mesh, l, lc, err)
      if (has_error(err)) return
      if (.not. shape) return
      if (lc%w < 0.0_wp) then       ! a buoyant line: the catenary hung from gravity reversed
         lc%up = -lc%up
         lc%rise = -lc%rise
         lc%w = -lc%w
      end if
      if (mesh%line_catenary(l) .and. lc%w > 0.0_wp .and. &
          lc%span >= 1.0e-9_wp*model%lines(l)%length) then
         call start_catenary(model, mesh, l, lc, sc, err)
         if (has_error(err)) return
         call place_catenary(model, mesh, l, sc, state)
         return
      end if
      ! the straight line from end A towards end B, stretched uniformly to reach it when
      ! the ends are farther apart than LENGTH (a taut line)
      t = lc%chord/lc%dist
      stretch = max(1.0_wp, lc%dist/model%lines(l)%length)
      n2 = cross(lc%up, t)
      if (norm2(n2) < 1.0e-6_wp) n2 = [0.0_wp, 1.0_wp, 0.0_wp]
      do k = 1, mesh%line_n_nodes(l)
         node = mesh%line_first_node(l) + k - 1
         state%x(:, node) = model%lines(l)%end_a + stretch*mesh%node_s(node)*t
         state%d(:, :, node) = line_frame(model, l, t, n2)
      end do
   end subroutine line_initial_shape

   !> The chord of line l from end A to end B against the vertical (the direction
   !> opposite to gravity, else z), and the line's mean weight and axial stiffness
   !> (line_mean_weight).
   subroutine line_chord(model, mesh, l, lc)
      type(model_t), intent(in) :: model          !< model
      type(mesh_t), intent(in) :: mesh            !< mesh
      integer, intent(in) :: l                    !< line index
      type(line_chord_t), intent(out) :: lc       !< the chord
      real(wp) :: gmag
      associate (ld => model%lines(l))
         lc%chord = ld%end_b - ld%end_a
         lc%dist = norm2(lc%chord)
         gmag = norm2(model%gravity)
         if (gmag > 0.0_wp) then
            lc%up = -model%gravity/gmag
         else
            lc%up = [0.0_wp, 0.0_wp, 1.0_wp]
         end if
         lc%eh = lc%chord - dot_product(lc%chord, lc%up)*lc%up
         lc%span = norm2(lc%eh)
         lc%rise = dot_product(lc%chord, lc%up)
      end associate
      call line_mean_weight(model, mesh, l, lc%w, lc%ea)
   end subroutine line_chord

   !> A slack line held at both ends needs a weight in water (or a buoyancy) and a
   !> horizontal span to hang: the error naming what it lacks when it has not.
   subroutine check_slack_line(model, mesh, l, lc, err)
      type(model_t), intent(in) :: model          !< model
      type(mesh_t), intent(in) :: mesh            !< mesh
      integer, intent(in) :: l                    !< line index
      type(line_chord_t), intent(in) :: lc        !< its chord
      type(error_t), intent(inout) :: err         !< status
      character(len=320) :: msg
      associate (ld => model%lines(l))
         if (.not. (mesh%line_catenary(l) .and. &
                    lc%dist < ld%length*(1.0_wp - 1.0e-12_wp))) return
         if (.not. (lc%w == 0.0_wp .or. lc%span < 1.0e-9_wp*ld%length)) return
         if (lc%w == 0.0_wp) then
            write (msg, '(3a)') 'line ', trim(ld%name), ' is slack between its'// &
               ' held ends but weightless (no mass, no gravity, or a weight balanced'// &
               ' exactly by buoyancy): no hanging catenary to start from'
         else
            write (msg, '(3a)') 'line ', trim(ld%name), ' is slack between its'// &
               ' held ends, which are vertically above each other: no catenary'// &
               ' to start from'
         end if
         call set_error(err, stat_input, line_at(model, l)//': error: *LINE: '// &
                        trim(msg))
      end associate
   end subroutine check_slack_line

   !> The elastic catenary line l starts from (docs/theory.md eqs. (112)-(114)); with
   !> its lower end on the seabed, the catenary with a grounded length if it touches
   !> (eq. (115)), its touchdown moved to an element boundary (snap_touchdown).
   subroutine start_catenary(model, mesh, l, lc, sc, err)
      type(model_t), intent(in) :: model          !< model
      type(mesh_t), intent(in) :: mesh            !< mesh
      integer, intent(in) :: l                    !< line index
      type(line_chord_t), intent(in) :: lc        !< its chord
      type(start_catenary_t), intent(out) :: sc   !< the catenary
      type(error_t), intent(inout) :: err         !< status
      real(wp) :: z_lo, xy(3)
      sc%lc = lc
      associate (ld => model%lines(l))
         sc%grounded = .false.
         sc%b_low = lc%rise < 0.0_wp
         if (model%seabed%present .and. abs(lc%rise) > 1.0e-9_wp*ld%length .and. &
             dot_product(lc%up, model%gravity) < 0.0_wp) then
            xy = merge(ld%end_b, ld%end_a, sc%b_low)
            z_lo = seabed_z(model, xy(1), xy(2))
            if (xy(3) - z_lo < 1.0e-6_wp*ld%length + 1.0e-9_wp) &
               call catenary_grounded(lc%w, lc%ea, ld%length, lc%span, abs(lc%rise), &
                                      sc%cat, sc%grounded)
         end if
         if (sc%grounded) call snap_touchdown(model, mesh, l, sc)
         if (.not. sc%grounded) then
            sc%b_low = .false.
            call catenary_solve(lc%w, lc%ea, ld%length, lc%span, lc%rise, sc%cat, err)
            if (has_error(err)) then
               err%message = line_at(model, l)//': error: *LINE: line '//trim(ld%name)// &
                             ': '//err%message
               return
            end if
         end if
      end associate
   end subroutine start_catenary

   !> Touchdown moved to the element boundary nearest to it, for the statics: the
   !> grounded catenary with that grounded length (V_F = w (L - L_B)) and H fitting the
   !> span, its upper end then off its deck position by a little, where the statics
   !> moves it
   !> (supports_build). With the touchdown inside an element the jump of curvature
   !> there makes the interpolated x' miss the nodal tangents by ~1e-2, which the
   !> shear and axial stiffness turn into large start forces; the homotopy of the
   !> statics can then drive the line on the seabed into compression and fail to
   !> converge on meshes whose nodes fall away from the touchdown.
   !> docs/theory.md eq. (115).
   subroutine snap_touchdown(model, mesh, l, sc)
      type(model_t), intent(in) :: model          !< model
      type(mesh_t), intent(in) :: mesh            !< mesh
      integer, intent(in) :: l                    !< line index
      type(start_catenary_t), intent(inout) :: sc !< the grounded catenary
      real(wp) :: lbn, sn, vf, h, lo, hi, f
      integer :: kk, it
      if (.not. (model%static%requested .or. (model%dynamic%requested .and. &
                                               model%dynamic%start_static))) return
      associate (w => sc%lc%w, ea => sc%lc%ea, span => sc%lc%span, &
                 length => model%lines(l)%length)
         lbn = -1.0_wp
         do kk = 1, mesh%line_n_nodes(l), mesh%line_order(l)
            sn = mesh%node_s(mesh%line_first_node(l) + kk - 1)
            if (sc%b_low) sn = length - sn
            if (lbn < 0.0_wp .or. abs(sn - sc%cat%lb) < abs(lbn - sc%cat%lb)) lbn = sn
         end do
         if (lbn <= 0.0_wp .or. lbn >= length .or. lbn >= span) return
         ! X(H) = L_B + H/w asinh(V_F/H) + H L/EA grows with H: bisection for X(H) = span
         vf = w*(length - lbn)
         lo = 1.0e-9_wp*w*length
         hi = max(sc%cat%h, lo)
         do it = 1, 200
            if (lbn + hi/w*asinh(vf/hi) + hi*length/ea > span) exit
            hi = 2.0_wp*hi
         end do
         do it = 1, 200
            h = 0.5_wp*(lo + hi)
            f = lbn + h/w*asinh(vf/h) + h*length/ea - span
            if (f > 0.0_wp) then
               hi = h
            else
               lo = h
            end if
         end do
         sc%cat%h = 0.5_wp*(lo + hi)
         sc%cat%v0 = 0.0_wp
         sc%cat%lb = lbn
      end associate
   end subroutine snap_touchdown

   !> The nodes of line l on its catenary (docs/theory.md eqs. (112)-(113)), from the
   !> lower end when grounded at B (arc length L - s, span reversed); the grounded part
   !> sunk to the penetration that carries its weight, w / (k D), so that it starts in
   !> contact, in equilibrium.
   subroutine place_catenary(model, mesh, l, sc, state)
      type(model_t), intent(in) :: model          !< model
      type(mesh_t), intent(in) :: mesh            !< mesh
      integer, intent(in) :: l                    !< line index
      type(start_catenary_t), intent(in) :: sc    !< its catenary
      type(state_t), intent(inout) :: state       !< configuration (line l filled)
      real(wp) :: eh(3), xz(2), tg(2), tens, t(3), sk
      integer :: k, node
      associate (ld => model%lines(l), up => sc%lc%up)
         eh = sc%lc%eh/sc%lc%span
         do k = 1, mesh%line_n_nodes(l)
            node = mesh%line_first_node(l) + k - 1
            sk = mesh%node_s(node)
            if (sc%b_low) sk = ld%length - sk
            call catenary_point(sc%cat, sk, xz, tg, tens)
            if (sc%b_low) then
               state%x(:, node) = ld%end_b - xz(1)*eh + xz(2)*up
               t = tg(1)*eh - tg(2)*up
            else
               state%x(:, node) = ld%end_a + xz(1)*eh + xz(2)*up
               t = tg(1)*eh + tg(2)*up
            end if
            if (sc%grounded .and. sk <= sc%cat%lb) state%x(:, node) = state%x(:, node) &
               - sc%lc%w/(model%seabed%stiffness*model%sections(ld%section)%db)*up
            state%d(:, :, node) = line_frame(model, l, t, cross(up, eh))
         end do
      end associate
   end subroutine place_catenary

   !> Frame of a node of line l with d3 = tt; d1 towards the deck's hint if given, else
   !> d2 = n2.
   pure function line_frame(model, l, tt, n2) result(d)
      type(model_t), intent(in) :: model !< model
      integer, intent(in) :: l           !< line index
      real(wp), intent(in) :: tt(3)      !< unit tangent
      real(wp), intent(in) :: n2(3)      !< default d2 direction (normal to tt)
      real(wp) :: d(3, 3)                !< the directors as columns
      real(wp) :: hint(3)
      if (model%lines(l)%has_d1_hint) then
         hint = model%lines(l)%d1_hint
         if (norm2(cross(hint, tt)) < 1.0e-6_wp) hint = cross(n2, tt)
      else
         hint = cross(n2, tt)
      end if
      d = rotation_frame(tt, hint)
   end function line_frame
end module rodyn_mesh
