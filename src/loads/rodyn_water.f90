!> The water's and the seabed's loads on the whole mesh (docs/water.md; docs/theory.md
!> eqs. (72)-(75), (98)): the point law
!> of rodyn_hydro integrated over each element with Gauss rules of p + 1 points, and the
!> forces of the point attachments (buoyancy of their volume, drag on Cd A). One path
!> for statics and dynamics: the caller gives the configuration at the force point and
!> how it moves with the unknowns x^{n+1},
!>   x_f = x^n + c_x dx,  d v_f / d x^{n+1} = c_v,  d a_f / d x^{n+1} = c_a,
!> (statics: x_f = x, v_f = a_f = 0, c_x = 1, c_v = c_a = 0), and receives the element
!> force vectors f_a = int N_a f(S) dS and their tangents
!>   K_ab = int N_a [c_x (N_b df/dx + N_b' df/dx') + c_v N_b df/dv + c_a N_b df/da] dS.
!> The seabed contact is integrated apart, exactly over the parts of an element where
!> the normal force N = (k pen - c v.n) D is positive: gap + c/k v.n is a polynomial of
!> degree p in xi; its roots in the element are found (sampling and bisection) and each
!> part in contact is integrated with 4 Gauss points, exact for N N_a up to cubic
!> elements (with the p + 1 rule alone the touchdown jumps from point to point, and the
!> fairlead tension with it). N vanishes at the roots, so their motion adds nothing to
!> the tangent.
!> Only translational unknowns are loaded. A scene without *WATER builds nothing here.
!> Waves (rodyn_waves, docs/waves.md): at the start of each time step the wave's
!> elevation, velocity and acceleration are evaluated once per node, at the node's
!> predicted force point x^n + w dt v^n and the force time (water_set_time), and
!> interpolated with the shape functions to the load points; within the step they are
!> held fixed (the tangent has no derivative of them). Statics has no waves.
module rodyn_water
   use rodyn_kinds, only: wp, pi
   use rodyn_model, only: model_t
   use rodyn_mesh, only: mesh_t
   use rodyn_shape, only: shape_lagrange, gauss_rule, max_order, max_nen
   use rodyn_environment, only: fluid_kinematics, current_factor
   use rodyn_seabed, only: seabed_normal, seabed_z
   use rodyn_hydro, only: water_section_t, water_env_t, water_point_load, submerged_fraction, &
                          part_water, part_seabed, n_wk
   use rodyn_waves, only: wave_field_t, waves_build, wave_kinematics
   implicit none
   private
   public :: water_loads_t, water_loads_build, water_element, water_attachment
   public :: water_set_time, contact_parts, water_set_external

   integer, parameter :: max_wp = max_order + 1 !< most load points per element

   !> The distributed loads of a scene in water, fixed for the run, and the last
   !> nodal forces evaluated (for the work and the results).
   type :: water_loads_t
      logical :: active = .false.                  !< the scene has water
      type(water_env_t) :: env                     !< environment of the point law
      type(water_section_t), allocatable :: sec(:) !< per model section
      integer :: ng(max_order) = 0                 !< load points per element order
      real(wp) :: w(max_wp, max_order) = 0.0_wp    !< Gauss weights
      real(wp) :: xi(max_wp, max_order) = 0.0_wp   !< Gauss points
      real(wp) :: n(max_nen, max_wp, max_order) = 0.0_wp  !< N_a at the points
      real(wp) :: dn(max_nen, max_wp, max_order) = 0.0_wp !< dN_a/dxi at the points
      real(wp) :: ws4(4) = 0.0_wp                  !< the seabed's 4-point Gauss rule
      real(wp) :: xs4(4) = 0.0_wp
      real(wp) :: ns4(max_nen, 4, max_order) = 0.0_wp  !< N_a there (a whole element)
      real(wp) :: dns4(max_nen, 4, max_order) = 0.0_wp !< dN_a/dxi there
      integer, allocatable :: att_node(:)          !< (na) node of each attachment
      real(wp), allocatable :: att_volume(:)       !< (na) displaced volume [m3]
      real(wp), allocatable :: att_cda(:)          !< (na) drag coefficient x area [m2]
      real(wp), allocatable :: att_ca(:)           !< (na) added-mass coefficient [-]
      type(wave_field_t) :: field                  !< the waves (field%n = 0: none)
      !> the water's velocity and acceleration at the nodes given by a host program
      !> (water_set_external; MoorDyn's external kinematics), held in wkin instead of
      !> the waves'
      logical :: external = .false.
      logical :: wave_on = .false.                 !< wkin holds this step's kinematics
      real(wp), allocatable :: wkin(:, :)          !< (7, nn) per node: wave velocity
                                                   !< [m/s], acceleration [m/s2], eta [m]
      real(wp), allocatable :: fh(:, :)            !< (3, nn) water force on the nodes [N]
      real(wp), allocatable :: fs(:, :)            !< (3, nn) seabed force on the nodes [N]
      !> (nl) factor on the buoyancy of each line's sections and attachments: statics
      !> ramps it with the line's weight (rodyn_statics); unallocated: 1 (dynamics)
      real(wp), allocatable :: bfac(:)
   end type water_loads_t

contains

   !> Section constants, Gauss rules and attachment nodes of a scene in water.
   !> docs/theory.md eq. (67).
   subroutine water_loads_build(model, mesh, wl)
      type(model_t), intent(in) :: model      !< model
      type(mesh_t), intent(in) :: mesh        !< mesh
      type(water_loads_t), intent(out) :: wl  !< loads
      real(wp) :: rho, gmag, ab, dd
      integer :: i, p, g
      wl%active = model%water%present
      if (.not. wl%active) return
      rho = model%water%density
      gmag = norm2(model%gravity)
      wl%env%water = model%water
      wl%env%gmag = gmag
      wl%env%r_current = current_factor(model%water, 0.0_wp)
      wl%env%seabed = model%seabed%present
      if (wl%env%seabed) then
         wl%env%n = seabed_normal(model%seabed)
         wl%env%c0 = wl%env%n(3)*seabed_z(model, 0.0_wp, 0.0_wp)
         wl%env%k = model%seabed%stiffness
         wl%env%c = model%seabed%damping
         wl%env%mu_ax = model%seabed%mu_axial
         wl%env%mu_lat = model%seabed%mu_lateral
         wl%env%v_mob = model%seabed%v_mob
      end if
      allocate (wl%sec(size(model%sections)))
      do i = 1, size(model%sections)
         associate (s => model%sections(i), ws => wl%sec(i))
            ab = 0.25_wp*pi*max(s%db, 0.0_wp)**2
            dd = max(s%dd, 0.0_wp)
            ws%fb = rho*gmag*ab
            ws%rb = 0.5_wp*max(s%db, 0.0_wp)
            ws%cn = 0.5_wp*rho*s%cdn*dd
            ws%ct = 0.5_wp*rho*s%cda*pi*dd
            ws%man = rho*ab*s%can
            ws%maa = rho*ab*s%caa
            ws%mw = rho*ab
            ws%dc = max(s%db, 0.0_wp)
         end associate
      end do
      call gauss_rule(4, wl%xs4, wl%ws4)
      do p = 1, max_order
         wl%ng(p) = p + 1
         call gauss_rule(p + 1, wl%xi(1:p + 1, p), wl%w(1:p + 1, p))
         do g = 1, p + 1
            call shape_lagrange(p, wl%xi(g, p), wl%n(1:p + 1, g, p), wl%dn(1:p + 1, g, p))
         end do
         do g = 1, 4
            call shape_lagrange(p, wl%xs4(g), wl%ns4(1:p + 1, g, p), wl%dns4(1:p + 1, g, p))
         end do
      end do
      allocate (wl%att_node(0), wl%att_volume(0), wl%att_cda(0), wl%att_ca(0))
      if (allocated(model%attachments)) then
         wl%att_node = mesh%att_node
         wl%att_volume = model%attachments%volume
         wl%att_cda = model%attachments%cda_area
         wl%att_ca = model%attachments%ca
      end if
      call waves_build(model%waves, model%water%depth, model%water%surface, gmag, wl%field)
      if (wl%field%n > 0) then
         allocate (wl%wkin(n_wk, mesh%n_nodes))
         wl%wkin = 0.0_wp
      end if
      allocate (wl%fh(3, mesh%n_nodes), wl%fs(3, mesh%n_nodes))
      wl%fh = 0.0_wp
      wl%fs = 0.0_wp
   end subroutine water_loads_build

   !> The state of the water at the force time of a step: current ramp; seabed damping
   !> and friction on in dynamics; with waves and the nodes' x and v at the start of the
   !> step, the wave kinematics at each node's predicted force point x + h v (module
   !> header), once per node and step.
   !> docs/theory.md eq. (73).
   subroutine water_set_time(wl, t, dynamic, x, v, h)
      type(water_loads_t), intent(inout) :: wl   !< loads
      real(wp), intent(in) :: t                  !< force time [s]
      logical, intent(in) :: dynamic             !< a time step (not statics)
      real(wp), intent(in), optional :: x(:, :)  !< (3, nn) positions at t_n [m]
      real(wp), intent(in), optional :: v(:, :)  !< (3, nn) velocities at t_n [m/s]
      real(wp), intent(in), optional :: h        !< time from t_n to the force point [s]
      integer :: node
      wl%env%r_current = current_factor(wl%env%water, t)
      wl%env%dynamic = dynamic
      wl%wave_on = (wl%field%n > 0 .or. wl%external) .and. present(x) .and. present(v) &
                   .and. present(h)
      wl%env%wave = wl%wave_on
      if (.not. wl%wave_on) return
      if (wl%external) return          ! a host's, in wkin (water_set_external)
      do node = 1, size(wl%wkin, 2)
         call wave_kinematics(wl%field, x(:, node) + h*v(:, node), t, wl%wkin(7, node), &
                              wl%wkin(1:3, node), wl%wkin(4:6, node))
      end do
   end subroutine water_set_time

   !> The water's velocity and acceleration at every node given by a host program from the
   !> next step on, in place of the waves (ext: (6, nn)). The
   !> wave elevation is then 0, the dynamic pressure too (MoorDyn's external kinematics).
   subroutine water_set_external(wl, ext)
      type(water_loads_t), intent(inout) :: wl       !< loads
      real(wp), intent(in) :: ext(:, :)              !< (6, nn) [m/s, m/s2]
      wl%external = .true.
      if (.not. allocated(wl%wkin)) allocate (wl%wkin(n_wk, size(ext, 2)))
      wl%wkin(1:6, :) = ext            ! held over the steps, at the still level
      wl%wkin(7, :) = 0.0_wp
   end subroutine water_set_external

   !> Element forces fh (water) and fs (seabed) on the p + 1 nodes and, if want_k, the
   !> tangent of their sum with respect to x^{n+1} (module header).
   !> docs/theory.md eqs. (72)-(73), (98).
   pure subroutine water_element(wl, ws, p, le, q, cx, cv, ca, fh, fs, ke, want_k, we)
      type(water_loads_t), intent(in) :: wl    !< loads
      type(water_section_t), intent(in) :: ws  !< section constants
      integer, intent(in) :: p                 !< element order
      real(wp), intent(in) :: le               !< unstretched length [m]
      !> (9, p+1) each node's position [m], velocity [m/s] and acceleration [m/s2] at the
      !> force point, one column a node: interpolated to a point as one 9-vector
      !> (contiguous: the callers pass whole columns of fixed-size arrays; declared so,
      !> the loops over nodes compile without strides)
      real(wp), intent(in), contiguous :: q(:, :)
      real(wp), intent(in) :: cx               !< d x_f / d x^{n+1} [-]
      real(wp), intent(in) :: cv               !< d v_f / d x^{n+1} [1/s]
      real(wp), intent(in) :: ca               !< d a_f / d x^{n+1} [1/s2]
      real(wp), intent(out), contiguous :: fh(:, :)        !< (3, p+1) water forces [N]
      real(wp), intent(out), contiguous :: fs(:, :)        !< (3, p+1) seabed forces [N]
      real(wp), intent(out) :: ke(:, :)        !< (3(p+1), 3(p+1)) d(fh + fs)/dx^{n+1} [N/m]
      logical, intent(in) :: want_k            !< form ke
      !> (7, p+1) nodal wave kinematics (wkin); needed, and read, when wl%wave_on
      real(wp), intent(in), optional, contiguous :: we(:, :)
      real(wp) :: wj, nn(max_nen), ds(max_nen), gapn(max_nen), gcon(max_nen), bc(max_nen)
      real(wp) :: lo(max_order + 1), hi(max_order + 1), xi
      integer :: g, a, nen, nparts, k
      logical :: whole
      nen = p + 1
      fh = 0.0_wp
      fs = 0.0_wp
      if (want_k) ke = 0.0_wp
      ! the seabed's parts of the element in contact (module header)
      nparts = 0
      whole = .false.
      if (wl%env%seabed) then
         do a = 1, nen     ! (loops, not array constructors: those allocate)
            gapn(a) = dot_product(wl%env%n, q(1:3, a)) - wl%env%c0
            gcon(a) = gapn(a)
            if (wl%env%dynamic) gcon(a) = gcon(a) + wl%env%c/wl%env%k* &
                                          dot_product(wl%env%n, q(4:6, a))
         end do
         if (minval(gcon(1:nen)) <= 0.1_wp*le) then
            ! the polynomial lies between its least and largest Bernstein coefficients:
            ! all of one sign decides the element without the root search
            call bernstein_of_nodal(p, gcon(1:nen), bc(1:nen))
            if (maxval(bc(1:nen)) < 0.0_wp) then
               nparts = 1
               lo(1) = -1.0_wp
               hi(1) = 1.0_wp
            else if (minval(bc(1:nen)) <= 0.0_wp) then
               call contact_parts(p, gcon(1:nen), nparts, lo, hi)
            end if
         end if
         whole = nparts == 1
         if (whole) whole = lo(1) == -1.0_wp .and. hi(1) == 1.0_wp
      end if
      ! a cubic element grounded over its whole length: its water rule (p + 1 = 4 Gauss
      ! points) is the seabed's, so water and seabed are taken together at each point
      ! (one point law, one interpolation)
      if (whole .and. wl%ng(p) == 4) then
         do g = 1, 4
            nn(1:nen) = wl%n(1:nen, g, p)
            ds(1:nen) = wl%dn(1:nen, g, p)*2.0_wp/le
            wj = wl%w(g, p)*0.5_wp*le
            call water_add_point(wl, ws, nen, q, cx, cv, ca, nn, ds, wj, &
                                 ior(part_water, part_seabed), fh, fs, ke, want_k, we)
         end do
         return
      end if
      do g = 1, wl%ng(p)
         nn(1:nen) = wl%n(1:nen, g, p)
         ds(1:nen) = wl%dn(1:nen, g, p)*2.0_wp/le
         wj = wl%w(g, p)*0.5_wp*le
         call water_add_point(wl, ws, nen, q, cx, cv, ca, nn, ds, wj, part_water, &
                              fh, fs, ke, want_k, we)
      end do
      do k = 1, nparts
         do g = 1, 4
            if (lo(k) == -1.0_wp .and. hi(k) == 1.0_wp) then
               ! the whole element in contact (a grounded stretch): the stored functions
               nn(1:nen) = wl%ns4(1:nen, g, p)
               ds(1:nen) = wl%dns4(1:nen, g, p)*2.0_wp/le
            else
               xi = 0.5_wp*(lo(k) + hi(k)) + 0.5_wp*(hi(k) - lo(k))*wl%xs4(g)
               call shape_lagrange(p, xi, nn(1:nen), ds(1:nen))
               ds(1:nen) = ds(1:nen)*2.0_wp/le
            end if
            wj = wl%ws4(g)*0.5_wp*(hi(k) - lo(k))*0.5_wp*le
            call water_add_point(wl, ws, nen, q, cx, cv, ca, nn, ds, wj, &
                                 part_seabed, fh, fs, ke, want_k)
         end do
      end do
   end subroutine water_element

   !> Add the load at one point (shape functions nn, their S-derivatives ds, weight wj)
   !> to the element vectors and matrix (module header).
   !> docs/theory.md eq. (73).
   pure subroutine water_add_point(wl, ws, nen, q, cx, cv, ca, nn, ds, wj, parts, &
                                   fh, fs, ke, want_k, we)
      type(water_loads_t), intent(in) :: wl    !< loads
      type(water_section_t), intent(in) :: ws  !< section constants
      integer, intent(in) :: nen               !< nodes of the element
      real(wp), intent(in), contiguous :: q(:, :)   !< (9, nen) positions [m], velocities
                                                    !< [m/s], accelerations [m/s2]
      real(wp), intent(in) :: cx, cv, ca       !< derivatives of x_f, v_f, a_f in x^{n+1}
      real(wp), intent(in), contiguous :: nn(:)            !< (>= nen) shape functions
      real(wp), intent(in), contiguous :: ds(:)            !< (>= nen) their derivatives in S [1/m]
      real(wp), intent(in) :: wj               !< weight times Jacobian [m]
      integer, intent(in) :: parts             !< part_water or part_seabed
      real(wp), intent(inout), contiguous :: fh(:, :)      !< (3, nen) water forces [N]
      real(wp), intent(inout), contiguous :: fs(:, :)      !< (3, nen) seabed forces [N]
      real(wp), intent(inout) :: ke(:, :)      !< (3 nen, 3 nen) tangent [N/m]
      logical, intent(in) :: want_k            !< form the tangent
      real(wp), intent(in), optional, contiguous :: we(:, :) !< (7, nen) nodal wave kinematics (read
                                                 !< when wl%wave_on)
      real(wp) :: wk(n_wk), y(9)
      real(wp) :: x(3), xp(3), v(3), acc(3), gh(3), gs(3), kx(3, 3), kxp(3, 3), kv(3, 3)
      real(wp) :: ka(3, 3), kn(3, 3), kd(3, 3), kb(3, 3), c
      integer :: i, j, a
      ! x, x', v and a at the point, in one pass over the nodes (x, v, a as one 9-vector)
      y = 0.0_wp
      xp = 0.0_wp
      do a = 1, nen
         y = y + nn(a)*q(:, a)
         xp = xp + ds(a)*q(1:3, a)
      end do
      x = y(1:3)
      v = y(4:6)
      acc = y(7:9)
      ! (one call, so that this routine and water_element stay inlined into
      ! assemble_water; wk is read only when env%wave, and only by the water's part)
      if (wl%env%wave .and. iand(parts, part_water) /= 0) then
         wk = 0.0_wp
         do a = 1, nen
            wk = wk + nn(a)*we(:, a)
         end do
      end if
      call water_point_load(wl%env, ws, x, xp, v, acc, gh, gs, kx, kxp, kv, ka, want_k, &
                            parts, wk)
      if (iand(parts, part_water) /= 0) then
         do i = 1, nen
            fh(:, i) = fh(:, i) + (wj*nn(i))*gh
         end do
      end if
      if (iand(parts, part_seabed) /= 0) then
         do i = 1, nen
            fs(:, i) = fs(:, i) + (wj*nn(i))*gs
         end do
      end if
      if (.not. want_k) return
      ! K_ij += wj N_i (N_j kn + N_j' kd), kn = c_x df/dx + c_v df/dv + c_a df/da,
      ! kd = c_x df/dx'
      kn = cx*kx + cv*kv + ca*ka
      kd = cx*kxp
      do j = 1, nen
         kb = nn(j)*kn + ds(j)*kd
         do i = 1, nen
            c = wj*nn(i)
            ke(3*i - 2:3*i, 3*j - 2:3*j) = ke(3*i - 2:3*i, 3*j - 2:3*j) + c*kb
         end do
      end do
   end subroutine water_add_point

   !> Bernstein coefficients b_0..b_p on [-1, 1] of the polynomial of degree p (<= 3)
   !> through the values g at the p + 1 equally spaced nodes:
   !>   p = 1: b = g;   p = 2: b_1 = (4 g_2 - g_1 - g_3)/2;
   !>   p = 3: b_1 = (-5 g_1 + 18 g_2 - 9 g_3 + 2 g_4)/6, b_2 = (2 g_1 - 9 g_2 + 18 g_3 - 5 g_4)/6;
   !> b_0 = g_1 and b_p = g_(p+1). The polynomial lies between min b and max b on [-1, 1]
   !> (Farin, "Curves and Surfaces for CAGD", 5th ed., 2002, section 5.1: convex hull).
   !> docs/theory.md eq. (98).
   pure subroutine bernstein_of_nodal(p, g, b)
      integer, intent(in) :: p          !< order (1 to 3)
      real(wp), intent(in) :: g(:)      !< (p+1) nodal values
      real(wp), intent(out) :: b(:)     !< (p+1) Bernstein coefficients
      b(1:p + 1) = g(1:p + 1)
      select case (p)
      case (2)
         b(2) = (4.0_wp*g(2) - g(1) - g(3))/2.0_wp
      case (3)
         b(2) = (-5.0_wp*g(1) + 18.0_wp*g(2) - 9.0_wp*g(3) + 2.0_wp*g(4))/6.0_wp
         b(3) = (2.0_wp*g(1) - 9.0_wp*g(2) + 18.0_wp*g(3) - 5.0_wp*g(4))/6.0_wp
      end select
   end subroutine bernstein_of_nodal

   !> The intervals [lo, hi] of xi in [-1, 1] where the polynomial sum N_a(xi) g_a is
   !> negative. Between its critical points (the roots of its derivative, of degree
   !> p - 1 <= 2, in closed form) the polynomial is monotone, so each piece holds at most
   !> one root, found by bisection: a part in contact as narrow as it may be is found,
   !> and the parts change continuously with the nodal values. docs/theory.md eq. (98).
   pure subroutine contact_parts(p, gn, nparts, lo, hi)
      integer, intent(in) :: p              !< element order
      real(wp), intent(in) :: gn(:)         !< (p+1) nodal values [m]
      integer, intent(out) :: nparts        !< intervals found
      real(wp), intent(out) :: lo(:)        !< (>= p+1) their starts
      real(wp), intent(out) :: hi(:)        !< (>= p+1) their ends
      real(wp) :: x0, x1, g1, xm, root, xa(max_nen), dd(max_order + 2), brk(max_order + 1)
      integer :: i, it, j, nb
      logical :: inside
      ! the polynomial in Newton's form through the nodes (divided differences): each
      ! value then costs p multiplications, not a set of shape functions
      do i = 1, p + 1
         xa(i) = -1.0_wp + 2.0_wp*real(i - 1, wp)/real(p, wp)
      end do
      dd = 0.0_wp
      dd(1:p + 1) = gn(1:p + 1)
      do j = 1, p
         do i = p + 1, j + 1, -1
            dd(i) = (dd(i) - dd(i - 1))/(xa(i) - xa(i - j))
         end do
      end do
      call critical_points(p, xa, dd, nb, brk)
      nparts = 0
      x0 = -1.0_wp
      inside = value_at(x0) < 0.0_wp
      if (inside) then
         nparts = 1
         lo(1) = -1.0_wp
      end if
      do i = 1, nb + 1
         x1 = 1.0_wp
         if (i <= nb) x1 = brk(i)
         g1 = value_at(x1)
         if ((g1 < 0.0_wp) .neqv. inside) then
            xm = x0
            root = x1
            do it = 1, 60
               ! (bracket down to adjacent doubles: then the midpoint is an end, and the
               ! halvings left would change nothing)
               if (0.5_wp*(xm + root) == xm .or. 0.5_wp*(xm + root) == root) exit
               if ((value_at(0.5_wp*(xm + root)) < 0.0_wp) .eqv. inside) then
                  xm = 0.5_wp*(xm + root)
               else
                  root = 0.5_wp*(xm + root)
               end if
            end do
            root = 0.5_wp*(xm + root)
            if (inside) then
               hi(nparts) = root
            else if (nparts < size(lo)) then
               nparts = nparts + 1
               lo(nparts) = root
            end if
            inside = .not. inside
         end if
         x0 = x1
      end do
      if (inside) hi(nparts) = 1.0_wp
   contains
      pure real(wp) function value_at(xi)
         real(wp), intent(in) :: xi
         integer :: k
         value_at = dd(p + 1)
         do k = p, 1, -1
            value_at = value_at*(xi - xa(k)) + dd(k)
         end do
      end function value_at
   end subroutine contact_parts

   !> The critical points in (-1, 1), ascending, of the polynomial of degree p <= 3 in
   !> Newton's form dd(1) + dd(2) (xi - x1) + dd(3) (xi - x1)(xi - x2) + dd(4) (xi - x1)
   !> (xi - x2)(xi - x3): the roots of its derivative a xi^2 + b xi + c.
   pure subroutine critical_points(p, xa, dd, nb, brk)
      integer, intent(in) :: p              !< degree
      real(wp), intent(in) :: xa(:)         !< (p+1) nodes
      real(wp), intent(in) :: dd(:)         !< (4) divided differences, 0 past p + 1
      integer, intent(out) :: nb            !< critical points found
      real(wp), intent(out) :: brk(:)       !< (>= 2) the points
      real(wp) :: a, b, c, disc, q, r(2), s1, s2
      integer :: k, nr
      nb = 0
      if (p < 2) return
      s1 = xa(1) + xa(2)
      s2 = 0.0_wp
      a = 0.0_wp
      if (p == 3) then
         s1 = xa(1) + xa(2) + xa(3)
         s2 = xa(1)*xa(2) + xa(1)*xa(3) + xa(2)*xa(3)
         a = 3.0_wp*dd(4)
      end if
      b = 2.0_wp*dd(3) - 2.0_wp*dd(4)*s1
      c = dd(2) - dd(3)*(xa(1) + xa(2)) + dd(4)*s2
      if (a == 0.0_wp) then
         if (b == 0.0_wp) return
         r(1) = -c/b
         nr = 1
      else
         disc = b*b - 4.0_wp*a*c
         if (disc <= 0.0_wp) return
         q = -0.5_wp*(b + sign(sqrt(disc), b))   ! (the stable pair of roots)
         r(1) = q/a
         r(2) = r(1)
         if (q /= 0.0_wp) r(2) = c/q
         nr = 2
      end if
      do k = 1, nr
         if (.not. (abs(r(k)) < 1.0_wp)) cycle
         nb = nb + 1
         brk(nb) = r(k)
      end do
      if (nb == 2) then
         if (brk(1) > brk(2)) brk(1:2) = [brk(2), brk(1)]
      end if
   end subroutine critical_points

   !> Water force on a point attachment (*ATTACHMENT; docs/theory.md eq. (74)): buoyancy
   !> rho_w g V of the
   !> submerged fraction of a sphere of that volume, drag 1/2 rho_w Cd A |u_r| u_r; and
   !> with want_k its derivative with respect to x^{n+1} (c_x, c_v as in water_element).
   !> Its weight is in the gravity loads and its added mass in the inertia. In a wave
   !> (we: the node's wkin) the wave's velocity is added to the current's, the surface
   !> is z_s + eta, and the water's acceleration a_w adds (1 + C_a) rho_w V a_w.
   pure subroutine water_attachment(wl, volume, cda_area, x, v, cx, cv, f, k, want_k, we, ca, &
                                    bf)
      type(water_loads_t), intent(in) :: wl !< loads
      real(wp), intent(in) :: volume        !< displaced volume [m3]
      real(wp), intent(in) :: cda_area      !< Cd A [m2]
      real(wp), intent(in) :: x(3)          !< position [m]
      real(wp), intent(in) :: v(3)          !< velocity [m/s]
      real(wp), intent(in) :: cx            !< d x_f / d x^{n+1} [-]
      real(wp), intent(in) :: cv            !< d v_f / d x^{n+1} [1/s]
      real(wp), intent(out) :: f(3)         !< force [N]
      real(wp), intent(out) :: k(3, 3)      !< df/dx^{n+1} [N/m]
      logical, intent(in) :: want_k         !< form k
      real(wp), intent(in), optional :: we(n_wk) !< the node's wave kinematics (wkin)
      real(wp), intent(in), optional :: ca    !< added-mass coefficient, with we [-]
      real(wp), intent(in), optional :: bf    !< factor on the buoyancy (bfac) [-]
      real(wp) :: rho, gmag, r, phi, dphi, u(3), dudx(3, 3), aw(3), ur(3), urm, g(3, 3)
      integer :: i
      rho = wl%env%water%density
      gmag = wl%env%gmag
      r = 0.5_wp*(6.0_wp*volume/pi)**(1.0_wp/3.0_wp)
      if (present(we)) then
         call submerged_fraction(wl%env%water%surface + we(7) - x(3), r, phi, dphi)
      else
         call submerged_fraction(wl%env%water%surface - x(3), r, phi, dphi)
      end if
      f = 0.0_wp
      k = 0.0_wp
      f(3) = rho*gmag*volume*phi
      if (want_k) k(3, 3) = -cx*rho*gmag*volume*dphi
      if (present(bf)) then
         f(3) = bf*f(3)
         k(3, 3) = bf*k(3, 3)
      end if
      if (present(we) .and. present(ca)) then
         f = f + phi*(1.0_wp + ca)*rho*volume*we(4:6)
         if (want_k) k(:, 3) = k(:, 3) - cx*dphi*(1.0_wp + ca)*rho*volume*we(4:6)
      end if
      if (cda_area <= 0.0_wp .or. phi <= 0.0_wp) return
      call fluid_kinematics(wl%env%water, wl%env%r_current, x, u, dudx, aw)
      if (present(we)) u = u + we(1:3)
      ur = u - v
      urm = norm2(ur)
      f = f + phi*0.5_wp*rho*cda_area*urm*ur
      if (.not. want_k) return
      g = 0.0_wp
      do i = 1, 3
         g(i, i) = urm
         if (urm > 0.0_wp) g(:, i) = g(:, i) + ur*ur(i)/urm
      end do
      g = phi*0.5_wp*rho*cda_area*g
      k = k - cv*g + cx*matmul(g, dudx)
      k(:, 3) = k(:, 3) - cx*dphi*0.5_wp*rho*cda_area*urm*ur
   end subroutine water_attachment
end module rodyn_water
