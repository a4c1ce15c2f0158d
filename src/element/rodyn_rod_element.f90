!> The director rod element (docs/theory.md sections 2 and 4, eqs. (4)-(31); Betsch &
!> Steinmann 2002).
!>
!> Per node a the configuration is q_a = (x_a, d1_a, d2_a, d3_a) and the unknown is
!> u_a = (dx_a, dtheta_a) with d_i <- cay(dtheta) d_i. Everything is interpolated with
!> the same Lagrange functions; strains at the p reduced Gauss points are
!>   Gamma_k = x'.d_k - delta_k3                               (shear, extension)
!>   K1 = (d2'.d3 - d3'.d2)/2, K2 = (d3'.d1 - d1'.d3)/2, K3 = (d1'.d2 - d2'.d1)/2
!> and the stored energy is W = 1/2 (eps - eps0)^T C (eps - eps0),
!> C = diag(GA1, GA2, EA, EI1, EI2, GJ), eps = (Gamma1, Gamma2, Gamma3, K1, K2, K3).
!>
!> Quadrature (rod_quadrature): orders 1 and 2 integrate every strain at the p reduced
!> Gauss points. Order 3 integrates extension, bending and torsion at 3 points and the
!> shear strains Gamma1, Gamma2 at 4 points: at 3 points one director pattern per
!> element (a wiggle vanishing at the points) is held by EI alone, and on a
!> cable-dominated line (EI << T le^2) Newton then ping-pongs and fails; the 4 shear
!> points remove that pattern (docs/element.md; docs/theory.md eq. (21)).
!>
!> Forces are first formed as gradients with respect to q ("q-forces", 12 per node) and
!> then projected onto the 6 unknowns with the null-space matrix P(d):
!>   r_x = f_x,   r_theta = sum_i d_i x f_di.
module rodyn_rod_element
   use rodyn_kinds, only: wp
   use rodyn_rotation, only: cross, skew
   use rodyn_shape, only: shape_lagrange, gauss_rule, max_nen
   implicit none
   private
   public :: rod_gp_t, rod_gp_kinematics, rod_strains, rod_gp_qforce, rod_gp_jacobian
   public :: rod_gp_geometric, rod_project_qforce, rod_rotation_geometric
   public :: rod_element_static, rod_element_strains, rod_element_energy
   public :: rod_element_energy_scale, rod_element_fields, rod_energy_of_strains
   public :: rod_element_line_load, rod_element_lumped_mass, rod_quadrature, max_points
   public :: rod_element_resultants, rod_rule_t, rod_rule, rod_hidden_shear
   public :: rod_gp_kinematics_shear, rod_strains_shear, rod_gp_qforce_shear, rod_gp_jacobian_row

   integer, parameter :: max_points = 7  !< most quadrature points of one element

   !> Centreline and director fields at one point of an element.
   type :: rod_gp_t
      real(wp) :: xp(3) = 0.0_wp       !< x' (derivative in S) [-]
      real(wp) :: d(3, 3) = 0.0_wp     !< d(:, i): interpolated director d_i [-]
      real(wp) :: dp(3, 3) = 0.0_wp    !< d(:, i)': derivative of director d_i [1/m]
   end type rod_gp_t

   !> The quadrature of an element order with its shape functions at the points,
   !> formed once per mesh (mesh_t%rules) rather than once per element.
   type :: rod_rule_t
      integer :: p = 0                            !< element order
      integer :: np = 0                           !< number of points
      real(wp) :: xi(max_points) = 0.0_wp         !< parent coordinates
      real(wp) :: w(max_points) = 0.0_wp          !< weights
      real(wp) :: mask(6, max_points) = 0.0_wp    !< strains integrated at each point
      logical :: shear_only(max_points) = .false. !< only Gamma1, Gamma2 integrated there
      real(wp) :: n(max_nen, max_points) = 0.0_wp !< N_a at the points
      real(wp) :: dn(max_nen, max_points) = 0.0_wp !< dN_a/dxi at the points
   end type rod_rule_t

contains

   !> Quadrature and shape functions of order p (rod_quadrature, shape_lagrange).
   !> docs/theory.md eqs. (19), (21).
   pure function rod_rule(p) result(rule)
      integer, intent(in) :: p !< element order
      type(rod_rule_t) :: rule
      integer :: g
      rule%p = p
      call rod_quadrature(p, rule%np, rule%xi, rule%w, rule%mask)
      do g = 1, rule%np
         rule%shear_only(g) = all(rule%mask(3:6, g) == 0.0_wp)
         call shape_lagrange(p, rule%xi(g), rule%n(1:p + 1, g), rule%dn(1:p + 1, g))
      end do
   end function rod_rule

   !> Quadrature of the stored energy of an element of order p: np points, parent
   !> coordinates xi, weights w, and mask(k, g) = 1 where strain k is integrated at
   !> point g. The first p points are the reduced Gauss points where results are given.
   !> docs/theory.md eq. (21).
   pure subroutine rod_quadrature(p, np, xi, w, mask)
      integer, intent(in) :: p                   !< element order
      integer, intent(out) :: np                 !< number of points
      real(wp), intent(out) :: xi(max_points)    !< parent coordinates
      real(wp), intent(out) :: w(max_points)     !< weights
      real(wp), intent(out) :: mask(6, max_points) !< strains integrated at each point
      xi = 0.0_wp
      w = 0.0_wp
      mask = 0.0_wp
      call gauss_rule(p, xi(1:p), w(1:p))
      mask(:, 1:p) = 1.0_wp
      np = p
      if (p == 3) then
         mask(1:2, 1:p) = 0.0_wp
         call gauss_rule(p + 1, xi(p + 1:2*p + 1), w(p + 1:2*p + 1))
         mask(1:2, p + 1:2*p + 1) = 1.0_wp
         np = 2*p + 1
      end if
   end subroutine rod_quadrature

   !> Interpolate x', d_i, d_i' at a point from nodal values.
   !> docs/theory.md eq. (20).
   pure subroutine rod_gp_kinematics(nen, n, dn, xe, de, kin)
      integer, intent(in) :: nen              !< nodes of the element
      real(wp), intent(in) :: n(nen)          !< shape functions
      real(wp), intent(in) :: dn(nen)         !< shape function derivatives dN/dS [1/m]
      real(wp), intent(in) :: xe(3, nen)      !< nodal positions [m]
      real(wp), intent(in) :: de(3, 3, nen)   !< nodal directors de(:, i, a)
      type(rod_gp_t), intent(out) :: kin      !< interpolated fields
      integer :: a
      kin%xp = 0.0_wp
      kin%d = 0.0_wp
      kin%dp = 0.0_wp
      do a = 1, nen
         kin%xp = kin%xp + dn(a)*xe(:, a)
         kin%d = kin%d + n(a)*de(:, :, a)
         kin%dp = kin%dp + dn(a)*de(:, :, a)
      end do
   end subroutine rod_gp_kinematics

   !> The fields of a shear-only point (rule%shear_only): x', d_1 and d_2 (kin%d(:, 3)
   !> and kin%dp are left as they were). The shear strains Gamma_k = x'.d_k (k = 1, 2)
   !> need no more.
   pure subroutine rod_gp_kinematics_shear(nen, n, dn, xe, de, kin)
      integer, intent(in) :: nen              !< nodes of the element
      real(wp), intent(in) :: n(nen)          !< shape functions
      real(wp), intent(in) :: dn(nen)         !< shape function derivatives dN/dS [1/m]
      real(wp), intent(in) :: xe(3, nen)      !< nodal positions [m]
      real(wp), intent(in) :: de(3, 3, nen)   !< nodal directors de(:, i, a)
      type(rod_gp_t), intent(inout) :: kin    !< xp, d(:, 1:2) set
      integer :: a
      kin%xp = 0.0_wp
      kin%d(:, 1:2) = 0.0_wp
      do a = 1, nen
         kin%xp = kin%xp + dn(a)*xe(:, a)
         kin%d(:, 1:2) = kin%d(:, 1:2) + n(a)*de(:, 1:2, a)
      end do
   end subroutine rod_gp_kinematics_shear

   !> Shear strains (Gamma1, Gamma2) of a shear-only point.
   !> docs/theory.md eq. (4).
   pure function rod_strains_shear(kin) result(eps)
      type(rod_gp_t), intent(in) :: kin !< fields at the point (rod_gp_kinematics_shear)
      real(wp) :: eps(2)
      eps(1) = dot_product(kin%xp, kin%d(:, 1))
      eps(2) = dot_product(kin%xp, kin%d(:, 2))
   end function rod_strains_shear

   !> rod_gp_qforce for stresses (N1, N2, 0, 0, 0, 0): on x_a wj dN_a (N1 d_1 + N2 d_2),
   !> on d_ka wj N_a N_k x' (k = 1, 2), nothing on d_3a.
   !> docs/theory.md eqs. (22)-(23).
   pure subroutine rod_gp_qforce_shear(nen, n, dn, kin, s, wj, fq)
      integer, intent(in) :: nen              !< nodes of the element
      real(wp), intent(in) :: n(nen)          !< shape functions
      real(wp), intent(in) :: dn(nen)         !< dN/dS [1/m]
      type(rod_gp_t), intent(in) :: kin       !< fields where B is evaluated
      real(wp), intent(in) :: s(2)            !< shear forces (N1, N2) [N]
      real(wp), intent(in) :: wj              !< Gauss weight times Jacobian [m]
      real(wp), intent(inout) :: fq(3, 4, nen) !< q-forces
      real(wp) :: nsp(3), c1(3), c2(3)
      integer :: a
      nsp = wj*(s(1)*kin%d(:, 1) + s(2)*kin%d(:, 2))
      c1 = (wj*s(1))*kin%xp
      c2 = (wj*s(2))*kin%xp
      do a = 1, nen
         fq(:, 1, a) = fq(:, 1, a) + dn(a)*nsp
         fq(:, 2, a) = fq(:, 2, a) + n(a)*c1
         fq(:, 3, a) = fq(:, 3, a) + n(a)*c2
      end do
   end subroutine rod_gp_qforce_shear


   !> Material strains eps = (Gamma1, Gamma2, Gamma3, K1, K2, K3), docs/theory.md
   !> eqs. (4)-(5).
   pure function rod_strains(kin) result(eps)
      type(rod_gp_t), intent(in) :: kin !< fields at the point
      real(wp) :: eps(6)
      eps(1) = dot_product(kin%xp, kin%d(:, 1))
      eps(2) = dot_product(kin%xp, kin%d(:, 2))
      eps(3) = dot_product(kin%xp, kin%d(:, 3)) - 1.0_wp
      eps(4) = 0.5_wp*(dot_product(kin%dp(:, 2), kin%d(:, 3)) &
                       - dot_product(kin%dp(:, 3), kin%d(:, 2)))
      eps(5) = 0.5_wp*(dot_product(kin%dp(:, 3), kin%d(:, 1)) &
                       - dot_product(kin%dp(:, 1), kin%d(:, 3)))
      eps(6) = 0.5_wp*(dot_product(kin%dp(:, 1), kin%d(:, 2)) &
                       - dot_product(kin%dp(:, 2), kin%d(:, 1)))
   end function rod_strains

   !> Add wj * B(q)^T s to the q-forces: the gradient of wj s.eps with respect to the
   !> nodal x_a and d_ia, with B = d eps / d q evaluated at kin (docs/theory.md eqs.
   !> (22)-(23)).
   pure subroutine rod_gp_qforce(nen, n, dn, kin, s, wj, fq)
      integer, intent(in) :: nen              !< nodes of the element
      real(wp), intent(in) :: n(nen)          !< shape functions
      real(wp), intent(in) :: dn(nen)         !< dN/dS [1/m]
      type(rod_gp_t), intent(in) :: kin       !< fields where B is evaluated
      real(wp), intent(in) :: s(6)            !< stress resultants (N1,N2,N3,M1,M2,M3) [N, N m]
      real(wp), intent(in) :: wj              !< Gauss weight times Jacobian [m]
      real(wp), intent(inout) :: fq(3, 4, nen) !< q-forces: (:,1,a) on x_a, (:,1+i,a) on d_ia
      real(wp) :: nsp(3), c(3, 3), e(3, 3)
      integer :: a, i
      associate (d => kin%d, dp => kin%dp)
         nsp = s(1)*d(:, 1) + s(2)*d(:, 2) + s(3)*d(:, 3)   ! spatial contact force
         ! curvature terms: c_i multiplies N_a, e_i multiplies dN_a (see module header)
         c(:, 1) = 0.5_wp*(s(5)*dp(:, 3) - s(6)*dp(:, 2))
         e(:, 1) = 0.5_wp*(s(6)*d(:, 2) - s(5)*d(:, 3))
         c(:, 2) = 0.5_wp*(s(6)*dp(:, 1) - s(4)*dp(:, 3))
         e(:, 2) = 0.5_wp*(s(4)*d(:, 3) - s(6)*d(:, 1))
         c(:, 3) = 0.5_wp*(s(4)*dp(:, 2) - s(5)*dp(:, 1))
         e(:, 3) = 0.5_wp*(s(5)*d(:, 1) - s(4)*d(:, 2))
         do i = 1, 3
            c(:, i) = c(:, i) + s(i)*kin%xp
         end do
         do a = 1, nen
            fq(:, 1, a) = fq(:, 1, a) + wj*dn(a)*nsp
            do i = 1, 3
               fq(:, 1 + i, a) = fq(:, 1 + i, a) + wj*(n(a)*c(:, i) + dn(a)*e(:, i))
            end do
         end do
      end associate
   end subroutine rod_gp_qforce

   !> Projected strain Jacobian bt = B P(dnode) (docs/theory.md eq. (25)): the change of
   !> eps at the point for
   !> u_b = (dx_b, dtheta_b), with nodal directors varied as dd_ib = dtheta_b x dnode_ib
   !> (rod_gp_jacobian_row, row by row).
   pure subroutine rod_gp_jacobian(nen, n, dn, kin, dnode, bt)
      integer, intent(in) :: nen               !< nodes of the element
      real(wp), intent(in) :: n(nen)           !< shape functions
      real(wp), intent(in) :: dn(nen)          !< dN/dS [1/m]
      type(rod_gp_t), intent(in) :: kin        !< fields where B is evaluated
      real(wp), intent(in) :: dnode(3, 3, nen) !< nodal directors defining the rotation
      real(wp), intent(out) :: bt(6, 6*nen)    !< d eps_k / d u_(j,b): bt(k, 6 (b - 1) + j)
      real(wp) :: row(6*max_nen)
      integer :: k
      do k = 1, 6
         call rod_gp_jacobian_row(nen, n, dn, kin, dnode, k, row(1:6*nen))
         bt(k, :) = row(1:6*nen)
      end do
   end subroutine rod_gp_jacobian

   !> Row k of the projected strain Jacobian B P(dnode), entry 6 (b - 1) + j for
   !> u_b = (dx_b, dtheta_b) (dd_ib = dtheta_b x dnode_ib):
   !>   Gamma_k (k = 1..3):  dx_b: dN_b d_k,   dtheta_b: N_b dnode_kb x x'
   !>   K_k (k = 4..6, (i, j) = (2, 3), (3, 1), (1, 2)): dx_b: 0,
   !>     dtheta_b: dnode_ib x g_i + dnode_jb x g_j,
   !>     g_i = (dN_b d_j - N_b d_j')/2,  g_j = (N_b d_i' - dN_b d_i)/2.
   !> A shear row (k = 1, 2) reads x' and d_1, d_2 only (rod_gp_kinematics_shear).
   !> docs/theory.md eq. (25).
   pure subroutine rod_gp_jacobian_row(nen, n, dn, kin, dnode, k, row)
      integer, intent(in) :: nen               !< nodes of the element
      real(wp), intent(in) :: n(nen)           !< shape functions
      real(wp), intent(in) :: dn(nen)          !< dN/dS [1/m]
      type(rod_gp_t), intent(in) :: kin        !< fields where B is evaluated
      real(wp), intent(in) :: dnode(3, 3, nen) !< nodal directors defining the rotation
      integer, intent(in) :: k                 !< strain (1..6)
      real(wp), intent(out) :: row(6, nen)     !< row(j, b)
      real(wp) :: gi(3), gj(3)
      integer :: b, i, j
      associate (d => kin%d, dp => kin%dp, xp => kin%xp)
         if (k <= 3) then
            do b = 1, nen
               row(1:3, b) = dn(b)*d(:, k)
               row(4:6, b) = n(b)*cross(dnode(:, k, b), xp)
            end do
            return
         end if
         i = mod(k - 3, 3) + 1
         j = mod(k - 2, 3) + 1
         do b = 1, nen
            gi = 0.5_wp*(dn(b)*d(:, j) - n(b)*dp(:, j))
            gj = 0.5_wp*(n(b)*dp(:, i) - dn(b)*d(:, i))
            row(1:3, b) = 0.0_wp
            row(4:6, b) = cross(dnode(:, i, b), gi) + cross(dnode(:, j, b), gj)
         end do
      end associate
   end subroutine rod_gp_jacobian_row

   !> Add wj * P(dl)^T [sum_k s_k d2 eps_k / dq dq] P(dr) to ke: the stress (geometric)
   !> stiffness at one point (docs/theory.md eq. (27)). The strains are quadratic, so the
   !> second derivatives are constant blocks (identity times shape-function products). With
   !> P(d) = -skew(d):
   !>   x_a - theta_b:      -dN_a N_b skew(sum_k s_k dr_kb)
   !>   theta_a - x_b:       N_a dN_b skew(sum_k s_k dl_ka)
   !>   theta_a - theta_b:  (dN_a N_b - N_a dN_b)/2 (tr(M) I - M),  M = Dr_b S^T Dl_a^T
   !> where Dl_a, Dr_b hold the directors as columns and S is the skew matrix of the
   !> moments, S_23 = M1, S_31 = M2, S_12 = M3 (sum over the pairs of P(u)^T P(v) =
   !> (u.v) I - v u^T of the curvature terms).
   pure subroutine rod_gp_geometric(nen, n, dn, s, dl, dr, wj, ke)
      integer, intent(in) :: nen                 !< nodes of the element
      real(wp), intent(in) :: n(nen)             !< shape functions
      real(wp), intent(in) :: dn(nen)            !< dN/dS [1/m]
      real(wp), intent(in) :: s(6)               !< stress resultants [N, N m]
      real(wp), intent(in) :: dl(3, 3, nen)      !< nodal directors of the test side (rows)
      real(wp), intent(in) :: dr(3, 3, nen)      !< nodal directors of the increment (cols)
      real(wp), intent(in) :: wj                 !< Gauss weight times Jacobian [m]
      real(wp), intent(inout) :: ke(:, :)         !< element matrix (6 nen square)
      ! (fixed sizes: automatic arrays sized by nen are heap ones; bench/alloc_check.sh)
      real(wp) :: skl(3, 3, max_nen), skr(3, 3, max_nen), wr(3, 3, max_nen), st(3, 3), m(3, 3)
      real(wp) :: h, tr, f
      integer :: a, b, i, j, ra, rb
      logical :: forces, moments
      forces = any(s(1:3) /= 0.0_wp)
      moments = any(s(4:6) /= 0.0_wp)
      if (forces) then
         do a = 1, nen
            skl(:, :, a) = skew(s(1)*dl(:, 1, a) + s(2)*dl(:, 2, a) + s(3)*dl(:, 3, a))
            skr(:, :, a) = skew(s(1)*dr(:, 1, a) + s(2)*dr(:, 2, a) + s(3)*dr(:, 3, a))
         end do
      end if
      if (moments) then
         st = skew(s(4:6))   ! S^T, S skew with S_23 = M1, S_31 = M2, S_12 = M3
         do b = 1, nen
            do j = 1, 3
               do i = 1, 3
                  wr(i, j, b) = dr(i, 1, b)*st(1, j) + dr(i, 2, b)*st(2, j) &
                                + dr(i, 3, b)*st(3, j)
               end do
            end do
         end do
      end if
      do b = 1, nen
         rb = 6*(b - 1)
         do a = 1, nen
            ra = 6*(a - 1)
            if (forces) then
               f = -wj*dn(a)*n(b)
               ke(ra + 1:ra + 3, rb + 4:rb + 6) = ke(ra + 1:ra + 3, rb + 4:rb + 6) &
                                                   + f*skr(:, :, b)
               f = wj*n(a)*dn(b)
               ke(ra + 4:ra + 6, rb + 1:rb + 3) = ke(ra + 4:ra + 6, rb + 1:rb + 3) &
                                                   + f*skl(:, :, a)
            end if
            h = 0.5_wp*wj*(dn(a)*n(b) - n(a)*dn(b))
            if (.not. moments .or. h == 0.0_wp) cycle
            do j = 1, 3
               do i = 1, 3
                  m(i, j) = wr(i, 1, b)*dl(j, 1, a) + wr(i, 2, b)*dl(j, 2, a) &
                            + wr(i, 3, b)*dl(j, 3, a)
               end do
            end do
            tr = m(1, 1) + m(2, 2) + m(3, 3)
            do j = 1, 3
               do i = 1, 3
                  ke(ra + 3 + i, rb + 3 + j) = ke(ra + 3 + i, rb + 3 + j) - h*m(i, j)
               end do
               ke(ra + 3 + j, rb + 3 + j) = ke(ra + 3 + j, rb + 3 + j) + h*tr
            end do
         end do
      end do
   end subroutine rod_gp_geometric

   !> Project q-forces onto the unknowns: r_x = f_x, r_theta = sum_i d_i x f_di
   !> (docs/theory.md eqs. (12), (24)).
   pure subroutine rod_project_qforce(nen, fq, dnode, fe)
      integer, intent(in) :: nen               !< nodes of the element
      real(wp), intent(in) :: fq(3, 4, nen)    !< q-forces
      real(wp), intent(in) :: dnode(3, 3, nen) !< nodal directors of the projection
      real(wp), intent(out) :: fe(6, nen)      !< projected forces (force, moment) [N, N m]
      integer :: a
      do a = 1, nen
         fe(1:3, a) = fq(:, 1, a)
         fe(4:6, a) = cross(dnode(:, 1, a), fq(:, 2, a)) + cross(dnode(:, 2, a), fq(:, 3, a)) &
                      + cross(dnode(:, 3, a), fq(:, 4, a))
      end do
   end subroutine rod_project_qforce

   !> Add scale * sum_i [d_i f_di^T - (f_di . d_i) I] to the rotation diagonal blocks:
   !> the change of the projection d_i x f_di when d_i rotates with the increment
   !> (docs/theory.md eq. (26), last term).
   pure subroutine rod_rotation_geometric(nen, fq, dnode, scale, ke)
      integer, intent(in) :: nen                 !< nodes of the element
      real(wp), intent(in) :: fq(3, 4, nen)      !< q-forces
      real(wp), intent(in) :: dnode(3, 3, nen)   !< directors being rotated
      real(wp), intent(in) :: scale              !< factor (1 in statics)
      real(wp), intent(inout) :: ke(:, :)         !< element matrix (6 nen square)
      real(wp) :: blk(3, 3), fd
      integer :: a, i, j, k, r
      do a = 1, nen
         blk = 0.0_wp
         do i = 1, 3
            fd = dot_product(fq(:, 1 + i, a), dnode(:, i, a))
            do k = 1, 3
               do j = 1, 3
                  blk(j, k) = blk(j, k) + dnode(j, i, a)*fq(k, 1 + i, a)
               end do
               blk(k, k) = blk(k, k) - fd
            end do
         end do
         r = 6*(a - 1) + 3
         ke(r + 1:r + 3, r + 1:r + 3) = ke(r + 1:r + 3, r + 1:r + 3) + scale*blk
      end do
   end subroutine rod_rotation_geometric

   !> Internal force and consistent tangent of one element in statics: the projected
   !> gradient of the stored energy and its derivative (docs/theory.md eqs. (21)-(27)).
   pure subroutine rod_element_static(p, le, c, eps0, xe, de, fe, ke, want_k, rule)
      integer, intent(in) :: p                     !< element order
      real(wp), intent(in) :: le                   !< unstretched element length [m]
      real(wp), intent(in) :: c(6)                 !< diag(GA1,GA2,EA,EI1,EI2,GJ)
      real(wp), intent(in) :: eps0(6, max_points)  !< stress-free strains at the points
      real(wp), intent(in) :: xe(3, p + 1)         !< nodal positions [m]
      real(wp), intent(in) :: de(3, 3, p + 1)      !< nodal directors
      real(wp), intent(out) :: fe(6, p + 1)        !< internal force and moment [N, N m]
      real(wp), intent(out) :: ke(:, :)            !< (6(p+1), 6(p+1)) tangent (if want_k)
      logical, intent(in) :: want_k                !< form the tangent
      type(rod_rule_t), intent(in) :: rule         !< rod_rule(p): points, shape functions
      ! fixed-size work arrays: nothing is allocated per call
      real(wp) :: n(max_nen), dn(max_nen), s(6), wj, cg(6), acc
      real(wp) :: fq(3, 4, max_nen), bt(6, 6*max_nen), cb(6, 6*max_nen)
      type(rod_gp_t) :: kin
      integer :: g, nen, nd, k, np, i, j, nk, rows(6)
      nen = p + 1
      nd = 6*nen
      np = rule%np
      fq(:, :, 1:nen) = 0.0_wp
      if (want_k) ke(1:nd, 1:nd) = 0.0_wp
      do g = 1, np
         n(1:nen) = rule%n(1:nen, g)
         dn(1:nen) = rule%dn(1:nen, g)*2.0_wp/le
         wj = rule%w(g)*0.5_wp*le
         cg = c*rule%mask(:, g)
         call rod_gp_kinematics(nen, n(1:nen), dn(1:nen), xe, de, kin)
         s = cg*(rod_strains(kin) - eps0(:, g))
         call rod_gp_qforce(nen, n(1:nen), dn(1:nen), kin, s, wj, fq(:, :, 1:nen))
         if (.not. want_k) cycle
         call rod_gp_jacobian(nen, n(1:nen), dn(1:nen), kin, de, bt(:, 1:nd))
         ! material part B^T C B over the strains integrated at this point only
         nk = 0
         do k = 1, 6
            if (cg(k) == 0.0_wp) cycle
            nk = nk + 1
            rows(nk) = k
            cb(k, 1:nd) = (wj*cg(k))*bt(k, 1:nd)
         end do
         do j = 1, nd
            do i = 1, nd
               acc = 0.0_wp
               do k = 1, nk
                  acc = acc + bt(rows(k), i)*cb(rows(k), j)
               end do
               ke(i, j) = ke(i, j) + acc
            end do
         end do
         call rod_gp_geometric(nen, n(1:nen), dn(1:nen), s, de, de, wj, ke(1:nd, 1:nd))
      end do
      call rod_project_qforce(nen, fq(:, :, 1:nen), de, fe)
      if (want_k) call rod_rotation_geometric(nen, fq(:, :, 1:nen), de, 1.0_wp, ke(1:nd, 1:nd))
   end subroutine rod_element_static

   !> Strains at the quadrature points of one element (the first p are the reduced
   !> Gauss points where results are reported); also used for the stress-free eps0.
   !> docs/theory.md eqs. (4)-(5), (8).
   pure subroutine rod_element_strains(p, le, xe, de, eps, xig)
      integer, intent(in) :: p                    !< element order
      real(wp), intent(in) :: le                  !< unstretched element length [m]
      real(wp), intent(in) :: xe(3, p + 1)        !< nodal positions [m]
      real(wp), intent(in) :: de(3, 3, p + 1)     !< nodal directors
      real(wp), intent(out) :: eps(6, max_points) !< strains at the points (0 beyond np)
      real(wp), intent(out) :: xig(max_points)    !< parent coordinates of the points
      real(wp) :: w(max_points), mask(6, max_points)
      integer :: g, np
      call rod_quadrature(p, np, xig, w, mask)
      eps = 0.0_wp
      do g = 1, np
         eps(:, g) = rod_point_strains(p, le, xe, de, xig(g))
      end do
   end subroutine rod_element_strains

   !> Strains (Gamma, K) at the parent coordinate xi of an element.
   pure function rod_point_strains(p, le, xe, de, xi) result(eps)
      integer, intent(in) :: p                    !< element order
      real(wp), intent(in) :: le                  !< unstretched element length [m]
      real(wp), intent(in) :: xe(3, p + 1)        !< nodal positions [m]
      real(wp), intent(in) :: de(3, 3, p + 1)     !< nodal directors
      real(wp), intent(in) :: xi                  !< parent coordinate [-]
      real(wp) :: eps(6)
      real(wp) :: n(max_nen), dn(max_nen)
      type(rod_gp_t) :: kin
      call shape_lagrange(p, xi, n(1:p + 1), dn(1:p + 1))
      dn = dn*2.0_wp/le
      call rod_gp_kinematics(p + 1, n(1:p + 1), dn(1:p + 1), xe, de, kin)
      eps = rod_strains(kin)
   end function rod_point_strains

   !> The shear an element of order 3 hides from its quadrature: the largest |Gamma_1|,
   !> |Gamma_2| (less the stress-free ones) at the p extension points, where shear is not
   !> integrated (hidden), and, when hidden exceeds limit, at the p + 1 shear points,
   !> where it is (seen; else 0). A shape of the selective rule's spurious mode
   !> (docs/element.md, "Known limits") has shear of order 1 at the former and almost
   !> none at the latter; a true shape, about the same shear at both. Orders 1 and 2
   !> sample every strain at the same points: hidden = 0.
   pure subroutine rod_hidden_shear(p, le, xe, de, eps0, limit, hidden, seen, rule)
      integer, intent(in) :: p                    !< element order
      real(wp), intent(in) :: le                  !< unstretched element length [m]
      real(wp), intent(in) :: xe(3, p + 1)        !< nodal positions [m]
      real(wp), intent(in) :: de(3, 3, p + 1)     !< nodal directors
      real(wp), intent(in) :: eps0(6, max_points) !< stress-free strains
      real(wp), intent(in) :: limit               !< hidden shear worth a look at seen [-]
      real(wp), intent(out) :: hidden             !< largest shear at the extension points
      real(wp), intent(out) :: seen               !< largest shear at the shear points
      type(rod_rule_t), intent(in) :: rule        !< rod_rule(p): points, shape functions
      real(wp) :: dn(max_nen), e(2)
      type(rod_gp_t) :: kin
      integer :: g
      hidden = 0.0_wp
      seen = 0.0_wp
      if (rule%np == p) return
      do g = 1, rule%np
         if (g == p + 1 .and. hidden <= limit) return
         dn(1:p + 1) = rule%dn(1:p + 1, g)*2.0_wp/le
         call rod_gp_kinematics_shear(p + 1, rule%n(1:p + 1, g), dn(1:p + 1), xe, de, kin)
         e = rod_strains_shear(kin)
         if (g <= p) then
            hidden = max(hidden, abs(e(1) - eps0(1, g)), abs(e(2) - eps0(2, g)))
         else
            seen = max(seen, abs(e(1) - eps0(1, g)), abs(e(2) - eps0(2, g)))
         end if
      end do
   end subroutine rod_hidden_shear

   !> Stress resultants at the p reduced Gauss points (where results are reported;
   !> docs/theory.md eq. (30)):
   !> res = (N1, N2, N3, M1, M2, M3) with N = C (eps - eps0); for order 3 the shear
   !> forces N1, N2 are interpolated from the 4 points where shear is integrated. The
   !> effective tension is the spatial contact force n = N_i d_i along the centreline
   !> tangent, n . x'/|x'|; curv holds the curvatures (K1, K2, K3).
   pure subroutine rod_element_resultants(p, le, c, eps0, xe, de, res, tension, curv, xig, &
                                          rule)
      integer, intent(in) :: p                    !< element order
      real(wp), intent(in) :: le                  !< unstretched element length [m]
      real(wp), intent(in) :: c(6)                !< diag(GA1,GA2,EA,EI1,EI2,GJ)
      real(wp), intent(in) :: eps0(6, max_points) !< stress-free strains
      real(wp), intent(in) :: xe(3, p + 1)        !< nodal positions [m]
      real(wp), intent(in) :: de(3, 3, p + 1)     !< nodal directors
      real(wp), intent(out) :: res(6, p)          !< resultants [N, N m]
      real(wp), intent(out) :: tension(p)         !< effective tension [N]
      real(wp), intent(out) :: curv(3, p)         !< curvatures [1/m]
      real(wp), intent(out) :: xig(p)             !< parent coordinates of the points
      type(rod_rule_t), intent(in) :: rule        !< rod_rule(p): points, shape functions
      real(wp) :: eps(6), xq(max_points), lq(max_nen), nsp(3), sq(6, max_points)
      real(wp) :: dn(max_nen)
      type(rod_gp_t) :: kin(max_points)
      integer :: g, np, k
      np = rule%np
      xq = rule%xi
      do g = 1, np
         dn(1:p + 1) = rule%dn(1:p + 1, g)*2.0_wp/le
         call rod_gp_kinematics(p + 1, rule%n(1:p + 1, g), dn(1:p + 1), xe, de, kin(g))
         eps = rod_strains(kin(g))
         sq(:, g) = c*(eps - eps0(:, g))
         if (g <= p) curv(:, g) = eps(4:6)
      end do
      xig = xq(1:p)
      do g = 1, p
         res(:, g) = sq(:, g)
         if (np > p) then
            ! shear from the p+1 shear points: Lagrange interpolation through them
            call lagrange_through(p + 1, xq(p + 1:np), xq(g), lq(1:p + 1))
            res(1:2, g) = 0.0_wp
            do k = 1, p + 1
               res(1:2, g) = res(1:2, g) + lq(k)*sq(1:2, p + k)
            end do
         end if
         nsp = res(1, g)*kin(g)%d(:, 1) + res(2, g)*kin(g)%d(:, 2) + res(3, g)*kin(g)%d(:, 3)
         tension(g) = dot_product(nsp, kin(g)%xp)/norm2(kin(g)%xp)
      end do
   contains
      !> Lagrange basis through the m points t evaluated at x.
      pure subroutine lagrange_through(m, t, x, l)
         integer, intent(in) :: m
         real(wp), intent(in) :: t(m), x
         real(wp), intent(out) :: l(m)
         integer :: i, j
         do i = 1, m
            l(i) = 1.0_wp
            do j = 1, m
               if (j /= i) l(i) = l(i)*(x - t(j))/(t(i) - t(j))
            end do
         end do
      end subroutine lagrange_through
   end subroutine rod_element_resultants

   !> Stored energy of one element, sum over points of wj/2 (eps-eps0).C(eps-eps0) [J].
   !> docs/theory.md eq. (21).
   pure function rod_element_energy(p, le, c, eps0, xe, de) result(energy)
      integer, intent(in) :: p                    !< element order
      real(wp), intent(in) :: le                  !< unstretched element length [m]
      real(wp), intent(in) :: c(6)                !< diag(GA1,GA2,EA,EI1,EI2,GJ)
      real(wp), intent(in) :: eps0(6, max_points) !< stress-free strains
      real(wp), intent(in) :: xe(3, p + 1)        !< nodal positions [m]
      real(wp), intent(in) :: de(3, 3, p + 1)     !< nodal directors
      real(wp) :: energy
      real(wp) :: scale
      call rod_element_energy_scale(p, le, c, eps0, xe, de, energy, scale, rod_rule(p))
   end function rod_element_energy

   !> The stored energy (as rod_element_energy) and its round-off scale [J]: sum over
   !> points of wj sum_k |S_k|, the
   !> resultants S = C (eps - eps0) times a unit strain. A strain is a difference of
   !> numbers of order 1 (x'.d3 - 1), so each carries an absolute round-off of order
   !> epsilon, and the energy one of order epsilon times this scale: under a large
   !> prestress far above epsilon times the energy itself.
   pure subroutine rod_element_energy_scale(p, le, c, eps0, xe, de, energy, scale, rule)
      integer, intent(in) :: p                    !< element order
      real(wp), intent(in) :: le                  !< unstretched element length [m]
      real(wp), intent(in) :: c(6)                !< diag(GA1,GA2,EA,EI1,EI2,GJ)
      real(wp), intent(in) :: eps0(6, max_points) !< stress-free strains
      real(wp), intent(in) :: xe(3, p + 1)        !< nodal positions [m]
      real(wp), intent(in) :: de(3, 3, p + 1)     !< nodal directors
      real(wp), intent(out) :: energy             !< stored energy (rod_element_energy) [J]
      real(wp), intent(out) :: scale              !< its round-off scale [J]
      type(rod_rule_t), intent(in) :: rule        !< rod_rule(p)
      real(wp) :: eps(6, max_points)
      type(rod_gp_t) :: kin(max_points)
      call rod_element_fields(p, le, xe, de, rule, kin, eps)
      call rod_energy_of_strains(le, c, eps0, eps, rule, energy, scale)
   end subroutine rod_element_energy_scale

   !> The stored energy W = 1/2 sum_g w_g (le/2) (eps - eps0)^T C (eps - eps0) of an
   !> element from its strains at the points (rod_element_fields), and its round-off
   !> scale sum_g w_g (le/2) |C (eps - eps0)| (rod_element_energy_scale).
   !> docs/theory.md eq. (21).
   pure subroutine rod_energy_of_strains(le, c, eps0, eps, rule, energy, scale)
      real(wp), intent(in) :: le                  !< unstretched element length [m]
      real(wp), intent(in) :: c(6)                !< diag(GA1,GA2,EA,EI1,EI2,GJ)
      real(wp), intent(in) :: eps0(6, max_points) !< stress-free strains
      real(wp), intent(in) :: eps(6, max_points)  !< strains at the points
      type(rod_rule_t), intent(in) :: rule        !< rod_rule(p)
      real(wp), intent(out) :: energy             !< stored energy [J]
      real(wp), intent(out) :: scale              !< its round-off scale [J]
      real(wp) :: s(6)
      integer :: g
      energy = 0.0_wp
      scale = 0.0_wp
      do g = 1, rule%np
         s = rule%mask(:, g)*c*(eps(:, g) - eps0(:, g))
         energy = energy + 0.25_wp*le*rule%w(g)*sum(s*(eps(:, g) - eps0(:, g)))
         scale = scale + 0.5_wp*le*rule%w(g)*sum(abs(s))
      end do
   end subroutine rod_energy_of_strains

   !> The fields and strains of one element's configuration (x0, d0) at its points: full
   !> fields at the full points, x', d1, d2 at the shear-only points. rod_element_dynamic
   !> takes those of q^n from here once per step (not once per Newton iteration); the
   !> stored energy uses them too.
   pure subroutine rod_element_fields(p, le, x0, d0, rule, gp0, epsn)
      integer, intent(in) :: p                       !< element order
      real(wp), intent(in) :: le                     !< unstretched element length [m]
      real(wp), intent(in) :: x0(3, p + 1)           !< nodal positions [m]
      real(wp), intent(in) :: d0(3, 3, p + 1)        !< nodal directors
      type(rod_rule_t), intent(in) :: rule           !< rod_rule(p)
      type(rod_gp_t), intent(out) :: gp0(max_points) !< fields at the points
      real(wp), intent(out) :: epsn(6, max_points)   !< strains at the points
      real(wp) :: n(max_nen), dn(max_nen)
      integer :: g, nen
      nen = p + 1
      epsn = 0.0_wp
      do g = 1, rule%np
         n(1:nen) = rule%n(1:nen, g)
         dn(1:nen) = rule%dn(1:nen, g)*2.0_wp/le
         if (rule%shear_only(g)) then
            call rod_gp_kinematics_shear(nen, n(1:nen), dn(1:nen), x0, d0, gp0(g))
            epsn(1:2, g) = rod_strains_shear(gp0(g))
         else
            call rod_gp_kinematics(nen, n(1:nen), dn(1:nen), x0, d0, gp0(g))
            epsn(:, g) = rod_strains(gp0(g))
         end if
      end do
   end subroutine rod_element_fields

   !> Consistent nodal forces of a uniform line load q [N/m] (docs/theory.md eq. (28)):
   !> f_a = q int N_a dS,
   !> integrated exactly with p+1 Gauss points.
   pure subroutine rod_element_line_load(p, le, q, fa)
      integer, intent(in) :: p              !< element order
      real(wp), intent(in) :: le            !< unstretched element length [m]
      real(wp), intent(in) :: q(3)          !< load per unit unstretched length [N/m]
      real(wp), intent(out) :: fa(3, p + 1) !< nodal forces [N]
      real(wp) :: xi(max_nen), w(max_nen), n(max_nen), dn(max_nen)
      integer :: g, a
      call gauss_rule(p + 1, xi(1:p + 1), w(1:p + 1))
      fa = 0.0_wp
      do g = 1, p + 1
         call shape_lagrange(p, xi(g), n(1:p + 1), dn(1:p + 1))
         do a = 1, p + 1
            fa(:, a) = fa(:, a) + 0.5_wp*le*w(g)*n(a)*q
         end do
      end do
   end subroutine rod_element_line_load

   !> Row-sum lumped translational mass of one element: m_a = rhoA int N_a dS
   !> (docs/theory.md eq. (29)). The same weights serve the director inertias E11, E22.
   pure subroutine rod_element_lumped_mass(p, le, rhoa, ma)
      integer, intent(in) :: p              !< element order
      real(wp), intent(in) :: le            !< unstretched element length [m]
      real(wp), intent(in) :: rhoa          !< mass (or inertia) per unit length
      real(wp), intent(out) :: ma(p + 1)    !< nodal lumped values
      real(wp) :: fa(3, max_nen)
      call rod_element_line_load(p, le, [rhoa, 0.0_wp, 0.0_wp], fa(:, 1:p + 1))
      ma = fa(1, 1:p + 1)
   end subroutine rod_element_lumped_mass
end module rodyn_rod_element
