!> Results of a solved configuration, per line: node positions, stress resultants and
!> curvatures at the reduced integration points (rod_element_resultants), and the
!> support reactions at the ends (R = f_int - f_ext at a held node).
!> docs/theory.md eqs. (30)-(31), (77)-(79).
module rodyn_recovery
   use rodyn_kinds, only: wp, pi
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, end_a, end_b, body_free
   use rodyn_mesh, only: mesh_t, mesh_node
   use rodyn_statics, only: static_problem_t
   use rodyn_state, only: state_t, state_gather
   use rodyn_rod_element, only: rod_element_resultants, max_points
   use rodyn_cable_element, only: cable_element_tension
   use rodyn_shape, only: max_order, max_nen
   use rodyn_results, only: line_result_t, system_result_t
   use rodyn_bodies, only: body_transfer
   use rodyn_junctions, only: junctions_stiffness
   use rodyn_rotation, only: cross, skew, rotation_log
   use rodyn_banded, only: dense_sym_eigen, dense_factor, dense_solve
   use rodyn_water, only: water_loads_t
   use rodyn_hydro, only: water_point_load, part_seabed, sea_pressure
   use rodyn_waves, only: wave_kinematics
   use rodyn_body_mass, only: body_added_mass_g, added_mass_global
   implicit none
   private
   public :: recover_static, recover_state, touchdown_root, recover_system

contains

   !> Fill one line_result_t per line from the static problem's configuration.
   subroutine recover_static(model, prob, lines)
      type(model_t), intent(in) :: model                 !< model
      type(static_problem_t), intent(inout) :: prob      !< solved problem
      type(line_result_t), allocatable, intent(out) :: lines(:) !< results
      type(error_t) :: err
      call prob%evaluate(.false., err)      ! refresh f_int and the reactions
      call recover_state(model, prob%mesh, prob%state, prob%lam, prob%r, prob%sup%held, lines, &
                         prob%water)
   end subroutine recover_static

   !> The system's results at the static equilibrium (prob solved to lambda = 1): each
   !> body's position, rotation and the force of its lines, and the stiffness at the FREE
   !> points and bodies, of everything and of the lines alone, from the consistent tangent
   !> condensed onto them (rodyn_junctions' junctions_stiffness), a body's taken to its
   !> reference point R (system_stiffness_at_r).
   subroutine recover_system(model, prob, sys, err)
      type(model_t), intent(in) :: model                 !< model
      type(static_problem_t), intent(inout) :: prob      !< solved problem
      type(system_result_t), intent(out) :: sys          !< results
      type(error_t), intent(inout) :: err                !< status
      integer :: k, nb, np, nj
      np = count(prob%mesh%point_node > 0)
      nb = size(prob%mesh%body_node)
      allocate (sys%kind(np + nb), sys%index(np + nb), sys%body_x(3, nb), &
                sys%body_rot(3, nb), sys%body_force(6, nb))
      nj = prob%jn%nj
      allocate (sys%stiffness(nj, nj), sys%lines_stiffness(nj, nj))
      if (np + nb == 0) return
      sys%kind = [(1, k=1, np), (2, k=1, nb)]
      sys%index = [pack([(k, k=1, size(model%points))], prob%mesh%point_node > 0), &
                   (k, k=1, nb)]
      call prob%evaluate(.false., err)
      call body_results(model, prob, sys)
      prob%jn%free_all = .true.
      call prob%evaluate(.true., err)
      call junctions_stiffness(prob%jn, prob%bm, sys%stiffness, err)
      prob%bl%off = .true.
      call prob%evaluate(.true., err)
      call junctions_stiffness(prob%jn, prob%bm, sys%lines_stiffness, err)
      prob%bl%off = .false.
      prob%jn%free_all = .false.
      call prob%evaluate(.false., err)
      if (has_error(err)) then
         deallocate (sys%stiffness, sys%lines_stiffness)
         return
      end if
      call stiffness_at_r(prob, sys)
      call body_periods(model, prob, sys, err)
   end subroutine recover_system

   !> Each FREE body's natural periods and modes as a rigid body on its moorings (docs/
   !> theory.md eq. (144)): K_b the stiffness of everything at R condensed onto the body
   !> (every other FREE point and body relaxed), made symmetric; M_R = T^T (diag(m I,
   !> D (J + A_r) D^T) + A^) T the mass about R (T = [I, -skew(g); 0, I], g = G - R; A_r
   !> the diagonal form's rotational added mass, A^ the added mass at G, eq. (153));
   !> K_b v = omega^2 M_R v (dense_sym_eigen).
   subroutine body_periods(model, prob, sys, err)
      type(model_t), intent(in) :: model                 !< model
      type(static_problem_t), intent(in) :: prob         !< problem (state, junctions)
      type(system_result_t), intent(inout) :: sys        !< periods and modes set
      type(error_t), intent(inout) :: err                !< status
      real(wp) :: kb(6, 6), mr(6, 6), mg(6, 6), t(6, 6), lam(6), g(3), d(3, 3)
      integer :: m, b, j0, i, nb
      nb = size(prob%mesh%body_node)
      allocate (sys%body_periods(6, nb), sys%body_modes(6, 6, nb))
      sys%body_periods = 0.0_wp
      sys%body_modes = 0.0_wp
      do m = 1, prob%jn%nm
         if (sys%kind(m) /= 2) cycle
         b = sys%index(m)
         if (model%bodies(b)%kind /= body_free) cycle
         j0 = prob%jn%m_j0(m)
         call condensed_block(sys%stiffness, j0, kb, err)
         if (has_error(err)) return
         kb = 0.5_wp*(kb + transpose(kb))
         d = prob%state%d(:, :, prob%mesh%body_node(b))
         g = prob%state%x(:, prob%mesh%body_node(b)) - sys%body_x(:, b)
         mg = 0.0_wp
         associate (bd => model%bodies(b))
            do i = 1, 3
               mg(i, i) = bd%mass
            end do
            mg(4:6, 4:6) = matmul(d, matmul(diagonal(bd%inertia + bd%added_mass(4:6)), &
                                            transpose(d)))
            mg = mg + added_mass_global(body_added_mass_g(bd), d)
         end associate
         t = body_transfer(g)
         mr = matmul(transpose(t), matmul(mg, t))
         call dense_sym_eigen(kb, mr, lam, err)
         if (has_error(err)) return
         do i = 1, 6
            if (lam(i) > 0.0_wp) sys%body_periods(i, b) = 2.0_wp*pi/sqrt(lam(i))
            sys%body_modes(:, i, b) = kb(:, i)/maxval(abs(kb(:, i)))
         end do
      end do
   contains
      pure function diagonal(v) result(a)
         real(wp), intent(in) :: v(3)
         real(wp) :: a(3, 3)
         a = 0.0_wp
         a(1, 1) = v(1)
         a(2, 2) = v(2)
         a(3, 3) = v(3)
      end function diagonal
   end subroutine body_periods

   !> The 6 x 6 block of k at rows and columns j0 + 1 .. j0 + 6 with every other unknown
   !> of k relaxed: k_bb - k_bo k_oo^-1 k_ob.
   subroutine condensed_block(k, j0, kb, err)
      real(wp), intent(in) :: k(:, :)     !< (n, n) the system's stiffness
      integer, intent(in) :: j0           !< the block's first unknown - 1
      real(wp), intent(out) :: kb(6, 6)   !< the condensed block
      type(error_t), intent(inout) :: err !< status
      real(wp), allocatable :: koo(:, :), kob(:, :)
      integer, allocatable :: o(:), ipiv(:)
      integer :: n, i
      n = size(k, 1)
      kb = k(j0 + 1:j0 + 6, j0 + 1:j0 + 6)
      if (n == 6) return
      o = [(i, i=1, j0), (i, i=j0 + 7, n)]
      koo = k(o, o)
      kob = k(o, j0 + 1:j0 + 6)
      allocate (ipiv(size(o)))
      call dense_factor(koo, ipiv, err)
      call dense_solve(koo, ipiv, kob, err)
      if (has_error(err)) return
      kb = kb - matmul(k(j0 + 1:j0 + 6, o), kob)
   end subroutine condensed_block

   !> Each body's reference point, rotation vector and the force and moment about R of its
   !> lines: minus the sum of the residuals at the line ends on it (before they are moved
   !> onto the body; rodyn_junctions).
   subroutine body_results(model, prob, sys)
      type(model_t), intent(in) :: model                 !< model
      type(static_problem_t), intent(in) :: prob         !< evaluated problem
      type(system_result_t), intent(inout) :: sys        !< body results set
      integer :: b, n, l, k, e
      real(wp) :: xr(3), fe(3)
      do b = 1, size(prob%mesh%body_node)
         n = prob%mesh%body_node(b)
         associate (d => prob%state%d(:, :, n))
            xr = prob%state%x(:, n) + matmul(d, -model%bodies(b)%cog)
            sys%body_x(:, b) = xr
            sys%body_rot(:, b) = rotation_log(d)
         end associate
         sys%body_force(:, b) = 0.0_wp
         do l = 1, prob%mesh%n_lines
            do k = 1, 2
               if (prob%mesh%end_point_node(k, l) /= n) cycle
               e = mesh_node(prob%mesh, l, merge(end_a, end_b, k == 1))
               fe = -prob%r(1:3, e)
               sys%body_force(1:3, b) = sys%body_force(1:3, b) + fe
               sys%body_force(4:6, b) = sys%body_force(4:6, b) + &
                                        cross(prob%state%x(:, e) - xr, fe)
            end do
         end do
      end do
   end subroutine body_results

   !> The stiffness with each body's rows and columns taken from G (its node) to its
   !> reference point R: K_R = T^T K_G T, T = [I, -skew(g); 0, I] on the body's unknowns
   !> (g = G - R, global), less (g F^T - (g . F) I) on its rotations, F the force on it
   !> that the matrix is of (its lines' for the lines' stiffness; none of everything for
   !> a FREE body in equilibrium, its lines' for a FIXED one).
   subroutine stiffness_at_r(prob, sys)
      type(static_problem_t), intent(in) :: prob         !< problem
      type(system_result_t), intent(inout) :: sys        !< stiffness transformed
      real(wp) :: t(size(sys%stiffness, 1), size(sys%stiffness, 1)), g(3), f(3)
      integer :: m, j0, i, b
      t = 0.0_wp
      do i = 1, size(t, 1)
         t(i, i) = 1.0_wp
      end do
      do m = 1, prob%jn%nm
         if (sys%kind(m) /= 2) cycle
         b = sys%index(m)
         j0 = prob%jn%m_j0(m)
         g = prob%state%x(:, prob%mesh%body_node(b)) - sys%body_x(:, b)
         t(j0 + 1:j0 + 3, j0 + 4:j0 + 6) = -skew(g)
      end do
      sys%stiffness = matmul(transpose(t), matmul(sys%stiffness, t))
      sys%lines_stiffness = matmul(transpose(t), matmul(sys%lines_stiffness, t))
      do m = 1, prob%jn%nm
         if (sys%kind(m) /= 2) cycle
         b = sys%index(m)
         j0 = prob%jn%m_j0(m)
         g = prob%state%x(:, prob%mesh%body_node(b)) - sys%body_x(:, b)
         f = sys%body_force(1:3, b)
         call less_moment_tangent(sys%lines_stiffness(j0 + 4:j0 + 6, j0 + 4:j0 + 6), g, f)
         if (prob%jn%held(j0 + 1)) &
            call less_moment_tangent(sys%stiffness(j0 + 4:j0 + 6, j0 + 4:j0 + 6), g, f)
      end do
   contains
      pure subroutine less_moment_tangent(k, a, force)
         real(wp), intent(inout) :: k(3, 3)
         real(wp), intent(in) :: a(3), force(3)
         integer :: i
         do i = 1, 3
            k(:, i) = k(:, i) - a*force(i)
            k(i, i) = k(i, i) + dot_product(a, force)
         end do
      end subroutine less_moment_tangent
   end subroutine stiffness_at_r

   !> Results of a configuration: node positions, resultants at the reduced points (with
   !> stress-free strains scaled by eps0_scale), and end reactions r(:, node) where held.
   !> In water (docs/water.md; docs/theory.md eqs. (77)-(79), where the sign convention
   !> is discussed): the wall tension T_w = T_eff - p_o A_o + p_i A_i at the
   !> points, p_o the sea pressure there (rodyn_hydro's sea_pressure: hydrostatic, and
   !> in waves with the wave's dynamic pressure at time t, eqs. (122)-(123); 0 above the
   !> surface), p_i = p_ref + rho_i g (z_ref - z); the seabed's normal and friction
   !> force per length at the nodes (the
   !> point law at the node, tangent d3); the touchdown (touchdown_root), the largest arc
   !> length where the line is in contact, with the nodes' effective penetration
   !> pen = -gap - (c/k) v.n (N = D k max(0, pen), docs/water.md; pen = -gap in statics).
   subroutine recover_state(model, mesh, state, eps0_scale, r, held, lines, water, t)
      type(model_t), intent(in) :: model                 !< model
      type(mesh_t), intent(in) :: mesh                   !< mesh
      type(state_t), intent(in) :: state                 !< configuration
      real(wp), intent(in) :: eps0_scale                 !< factor on eps0 (1 but in statics)
      real(wp), intent(in) :: r(:, :)                    !< (6, nn) support forces at held nodes
      logical, intent(in) :: held(:, :)                  !< (6, nn) held dofs
      type(line_result_t), allocatable, intent(inout) :: lines(:) !< results (reused)
      type(water_loads_t), intent(in), optional :: water !< loads of a scene in water
      real(wp), intent(in), optional :: t                !< time of the state, in waves [s]
      real(wp) :: xig(max_order), res(6, max_order), tens(max_order), curv(3, max_order)
      real(wp) :: xe(3, max_nen), de(3, 3, max_nen), e0(6, max_points), tg(3, max_order)
      integer :: l, p, ne, el, e, g, ig, n0, nn, k, node
      if (.not. allocated(lines)) allocate (lines(mesh%n_lines))
      do l = 1, mesh%n_lines
         p = mesh%line_order(l)
         ne = model%lines(l)%n_elements
         nn = mesh%line_n_nodes(l)
         n0 = mesh%line_first_node(l)
         lines(l)%name = model%lines(l)%name
         lines(l)%node_s = mesh%node_s(n0:n0 + nn - 1)
         lines(l)%node_x = state%x(:, n0:n0 + nn - 1)
         if (.not. allocated(lines(l)%gp_s)) allocate (lines(l)%gp_element(ne*p), &
            lines(l)%gp_point(ne*p), lines(l)%gp_s(ne*p), lines(l)%tension(ne*p), &
            lines(l)%shear(2, ne*p), lines(l)%moment(2, ne*p), lines(l)%torque(ne*p), &
            lines(l)%curvature(3, ne*p), lines(l)%wall_tension(ne*p))
         if (.not. allocated(lines(l)%seabed_normal)) allocate (lines(l)%seabed_normal(nn), &
            lines(l)%seabed_friction(nn))
         lines(l)%seabed_normal = 0.0_wp
         lines(l)%seabed_friction = 0.0_wp
         lines(l)%touchdown_s = -1.0_wp
         do el = 1, ne
            e = mesh%line_first_elem(l) + el - 1
            call state_gather(state, mesh%elem_nodes(1:p + 1, e), xe, de)
            if (mesh%elem_cable(e)) then
               ! a cable: tension only (no shear, moment or curvature of its own)
               call cable_element_tension(p, mesh%elem_le(e), mesh%elem_c(3, e), &
                                          xe(:, 1:p + 1), mesh%rules(p), tens(1:p), tg(:, 1:p))
               res(:, 1:p) = 0.0_wp
               curv(:, 1:p) = 0.0_wp
               xig(1:p) = mesh%rules(p)%xi(1:p)
            else
               e0 = eps0_scale*mesh%eps0(:, :, e)
               call rod_element_resultants(p, mesh%elem_le(e), mesh%elem_c(:, e), e0, &
                                           xe(:, 1:p + 1), de(:, :, 1:p + 1), res(:, 1:p), &
                                           tens(1:p), curv(:, 1:p), xig(1:p), mesh%rules(p))
            end if
            do g = 1, p
               ig = (el - 1)*p + g
               lines(l)%gp_element(ig) = el
               lines(l)%gp_point(ig) = g
               lines(l)%gp_s(ig) = mesh%elem_s0(e) + 0.5_wp*mesh%elem_le(e)*(xig(g) + 1.0_wp)
               lines(l)%shear(:, ig) = res(1:2, g)
               lines(l)%tension(ig) = tens(g)
               lines(l)%wall_tension(ig) = tens(g)
               if (present(water)) then
                  if (water%active) lines(l)%wall_tension(ig) = tens(g) + &
                                                                pressure_term(e, g)
               end if
               lines(l)%moment(:, ig) = res(4:5, g)
               lines(l)%torque(ig) = res(6, g)
               lines(l)%curvature(:, ig) = curv(:, g)
            end do
         end do
         if (present(water)) then
            if (water%active .and. water%env%seabed) call seabed_results(l)
         end if
         do k = 1, 2
            node = mesh_node(mesh, l, merge(end_a, end_b, k == 1))
            e = mesh%line_first_elem(l) + merge(0, ne - 1, k == 1)
            ! (the rotation unknowns of a cable's end are always held: only its position
            ! counts)
            ! (an end on a FREE point: the point's force on it, as a support's)
            lines(l)%end_held(k) = any(held(1:3, node)) .or. &
                                   (any(held(4:6, node)) .and. .not. mesh%elem_cable(e)) .or. &
                                   mesh%end_point_node(k, l) > 0
            lines(l)%reaction(:, k) = 0.0_wp
            if (lines(l)%end_held(k)) lines(l)%reaction(:, k) = r(:, node)
         end do
      end do
   contains
      !> p_i A_i - p_o A_o at reduced point g of element e (order p, nodes xe) [N], the
      !> wall tension less the effective (docs/theory.md (77)-(79), (123)): the point
      !> with the rule's shape functions there (both resultant routines give the rule's
      !> first p points; no shape_lagrange call and no heap temporary per point); in
      !> waves the sea pressure at time t has the wave's dynamic pressure there
      real(wp) function pressure_term(e, g)
         integer, intent(in) :: e, g
         real(wp) :: xg(3), gm, po, pi_, eta, pd, uw(3), aw(3)
         integer :: a
         xg = 0.0_wp
         do a = 1, p + 1
            xg = xg + mesh%rules(p)%n(a, g)*xe(:, a)
         end do
         gm = norm2(model%gravity)
         eta = 0.0_wp
         pd = 0.0_wp
         if (present(t)) then
            if (water%field%n > 0) call wave_kinematics(water%field, xg, t, eta, uw, aw, pd)
         end if
         associate (sec => model%sections(mesh%elem_sec(e)))
            po = sea_pressure(model%water%density, gm, model%water%surface, xg(3), eta, pd)
            pi_ = sec%p_i + sec%rho_i*gm*(sec%z_pi - xg(3))
            pressure_term = pi_*0.25_wp*pi*sec%id**2 - po*0.25_wp*pi*max(sec%db, 0.0_wp)**2
         end associate
      end function pressure_term
      !> Seabed force per length at the nodes of line l and its touchdown.
      subroutine seabed_results(l)
         integer, intent(in) :: l
         real(wp) :: fh(3), fs(3), k1(3, 3), k2(3, 3), k3(3, 3), k4(3, 3), fn, zero3(3)
         integer :: k, node, e, isec
         zero3 = 0.0_wp
         e = mesh%line_first_elem(l)
         do k = 1, mesh%line_n_nodes(l)
            node = mesh%line_first_node(l) + k - 1
            do while (e < mesh%line_first_elem(l) + model%lines(l)%n_elements - 1 .and. &
                      mesh%elem_s0(e) + mesh%elem_le(e) < mesh%node_s(node))
               e = e + 1
            end do
            isec = mesh%elem_sec(e)
            call water_point_load(water%env, water%sec(isec), state%x(:, node), &
                                  state%d(:, 3, node), state%v(:, node), zero3, fh, fs, &
                                  k1, k2, k3, k4, .false., part_seabed)
            fn = dot_product(fs, water%env%n)
            lines(l)%seabed_normal(k) = fn
            lines(l)%seabed_friction(k) = norm2(fs - fn*water%env%n)
         end do
         lines(l)%touchdown_s = touchdown_root(lines(l)%node_s, contact_pen(l))
      end subroutine seabed_results
      !> The effective penetration pen = -gap - (c/k) v.n of the seabed at the nodes of
      !> line l (c = 0 in statics): positive where the seabed pushes (N = D k pen > 0),
      !> and taken as 0 where it does not (a section of no contact width, or round-off).
      function contact_pen(l) result(pen)
         integer, intent(in) :: l
         real(wp) :: pen(mesh%line_n_nodes(l))
         integer :: k, node
         do k = 1, size(pen)
            node = mesh%line_first_node(l) + k - 1
            pen(k) = -(dot_product(water%env%n, state%x(:, node)) - water%env%c0)
            if (water%env%dynamic .and. water%env%k > 0.0_wp) pen(k) = pen(k) &
               - water%env%c/water%env%k*dot_product(water%env%n, state%v(:, node))
            if (.not. lines(l)%seabed_normal(k) > 0.0_wp) pen(k) = min(pen(k), 0.0_wp)
            if (lines(l)%seabed_normal(k) > 0.0_wp) pen(k) = max(pen(k), tiny(1.0_wp))
         end do
      end function contact_pen
   end subroutine recover_state

   !> The touchdown of a line: the largest arc length in contact with the seabed, from
   !> the nodes' arc lengths s and a contact measure pen (> 0: in contact; the effective
   !> penetration). The last node in contact, k, and the node after it bracket the
   !> touchdown; it is the root of pen interpolated linearly between them,
   !>   s_td = s_k + (s_{k+1} - s_k) pen_k / (pen_k - pen_{k+1}),
   !> always within [s_k, s_{k+1}] (pen_k > 0 >= pen_{k+1}). s_n when the last node is in
   !> contact (grounded to its end); -1 when no node is.
   pure real(wp) function touchdown_root(s, pen) result(s_td)
      real(wp), intent(in) :: s(:)     !< arc lengths of the nodes, increasing [m]
      real(wp), intent(in) :: pen(:)   !< contact measure at the nodes (> 0: contact) [m]
      integer :: k, n
      n = size(s)
      s_td = -1.0_wp
      do k = n, 1, -1
         if (pen(k) > 0.0_wp) exit
      end do
      if (k < 1) return
      if (k == n) then
         s_td = s(n)
         return
      end if
      s_td = s(k) + (s(k + 1) - s(k))*pen(k)/(pen(k) - pen(k + 1))
      s_td = min(max(s_td, s(k)), s(k + 1))
   end function touchdown_root
end module rodyn_recovery
