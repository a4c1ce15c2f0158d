!> Internal force of the director rod over a time step (docs/theory.md eqs. (35)-(36),
!> (44), (54)-(57)),
!> projected with the midpoint directors d^{n+1/2} = (d^n + d^{n+1})/2, and its tangent
!> with respect to the unknowns at n+1 (dx, dtheta; dd^{n+1} = dtheta x d^{n+1}):
!>   EMC          S = C ((eps(q^n) + eps(q^{n+1}))/2 - eps0), B at q^{n+1/2}
!>   MIDPOINT     S = C (eps(q^{n+1/2}) - eps0),                B at q^{n+1/2}
!>   TRAPEZOIDAL  f = (f(q^n) + f(q^{n+1}))/2
!>   ALPHA        S = C (eps(q_f) - eps0), B at q_f = (1 - w) q^n + w q^{n+1}, w = 1 - alpha_f
!>                (generalized-alpha; the projection uses the directors of q_f too)
!> With the EMC choice the work of the internal force over the step equals the change of
!> stored energy exactly (strains quadratic in q), the root of energy conservation.
!>
!> Stresses of the EMC tangent (argument xb, db: Newton's base, the iterate q^k that the
!> last correction started from). A correction is linear in q, the strains are not: an
!> iterate q^{k+1} carries besides the strain change B(q^k) dq the second-order part of
!> it, and with EA >> tension that part sets the stress: an early iterate's axial
!> strain can be orders of magnitude above the converged one. A tangent formed there
!> has stress terms far off, and the reused-tangent iterations after it contract
!> slowly. With the base given, every stress term of the tangent (the geometric
!> sums and the projection's q-forces) takes instead the stress of the strain linearized
!> from the base,
!>   eps_lin = eps(q^k) + B(q^k) (q^{k+1} - q^k)_lin = eps(q_l) - eps2(dq_l) (+ e3),
!>   q_l = q^k + dq_l,  dq_l = (x^{k+1} - x^k,  theta x d^k),  theta = cay^-1(d^{k+1} d^k^T),
!> with eps2 the strains' quadratic part of the increment fields alone (the strains are
!> bilinear in x', d_i, d_i'): S_lin = C ((eps(q^n) + eps_lin)/2 - eps0). This is the
!> stress Newton's iteration of the mixed (Hellinger-Reissner) form carries, the
!> point stresses being unknowns of their own: eliminated point by point, that
!> iteration has the same residual and the same material part as this one and differs
!> only in the stress of the stress terms. The converged step does not change (the
!> residual is untouched); only the iterates do, and in fewer iterations
!> (docs/theory.md eq. (44)).
module rodyn_rod_dynamic
   use rodyn_kinds, only: wp
   use rodyn_schemes, only: scheme_emc, scheme_midpoint, scheme_trapezoidal, scheme_alpha
   use rodyn_shape, only: max_nen
   use rodyn_rotation, only: skew, cross, rotation_cayley_inverse, relative_rotation
   use rodyn_rod_element, only: rod_gp_t, rod_gp_kinematics, rod_strains, rod_gp_qforce, &
                                rod_gp_jacobian_row, rod_project_qforce, &
                                rod_rotation_geometric, rod_rule_t, max_points, &
                                rod_gp_kinematics_shear, rod_strains_shear, &
                                rod_gp_qforce_shear
   implicit none
   private
   public :: rod_element_dynamic

   !> What the points of one element share in a step (rod_element_dynamic).
   type :: element_step_t
      integer :: nen                   !< nodes of the element
      integer :: scheme                !< scheme_* constant
      logical :: want_k                !< form the tangent
      logical :: have0                 !< q^n's fields and strains given (gp0, epsn)
      logical :: lin                   !< the tangent's stresses linearized from the base
      real(wp) :: wq                   !< weight of q^{n+1} in the evaluation point [-]
      real(wp) :: xm(3, max_nen)       !< positions at the evaluation point [m]
      real(wp) :: dm(3, 3, max_nen)    !< directors at the evaluation point
      real(wp) :: dxl(3, max_nen)      !< position increment from the base [m]
      real(wp) :: ddl(3, 3, max_nen)   !< linearized director increment from the base
      real(wp) :: dl(3, 3, max_nen)    !< base directors plus ddl
   end type element_step_t

   !> The sums over the points of one element (rod_element_dynamic): the q-forces, and
   !> for the tangent the material part's rows of all points (add_material: force
   !> strains (Gamma) in blt/cr(1:nf), curvatures (K: no x columns; blc holds the
   !> rotation entries only) in blc/crc(1:nc)) and the stress part per node pair
   !> (add_geometric).
   type :: element_sums_t
      real(wp) :: fq(3, 4, max_nen)              !< q-forces of the stresses [N, N m]
      real(wp) :: fql(3, 4, max_nen)             !< q-forces of the linearized stresses
      real(wp) :: blt(6*max_nen, 3*max_points)   !< force-strain rows, test side
      real(wp) :: cr(3*max_points, 6*max_nen)    !< force-strain rows, increment side
      real(wp) :: blc(3*max_nen, 3*max_points)   !< curvature rows, test side
      real(wp) :: crc(3*max_points, 6*max_nen)   !< curvature rows, increment side
      integer :: nf                              !< force-strain rows used
      integer :: nc                              !< curvature rows used
      real(wp) :: pg(3, max_nen, max_nen)        !< force sums of the stress part
      real(wp) :: mg(3, max_nen, max_nen)        !< moment sums of the stress part
   end type element_sums_t

   !> One quadrature point of an element in a step (point_setup, point_fields).
   type :: step_point_t
      integer :: g                  !< point number
      logical :: shear              !< a shear-only point (Gamma1 and Gamma2 alone)
      real(wp) :: n(max_nen)        !< shape functions
      real(wp) :: dn(max_nen)       !< dN/dS [1/m]
      real(wp) :: wj                !< Gauss weight times Jacobian [m]
      real(wp) :: mask(6)           !< strains integrated here (1) or not (0), with off
      real(wp) :: cg(6)             !< stiffness of the strains integrated here
      real(wp) :: eps0(6)           !< stress-free strains
      real(wp) :: off(6)            !< offset of the numerical stress [N, N m]
      type(rod_gp_t) :: k0          !< fields of q^n (EMC, TRAPEZOIDAL)
      type(rod_gp_t) :: k1          !< fields of q^{n+1}
      type(rod_gp_t) :: km          !< fields where B is evaluated (MIDPOINT, ALPHA, EMC)
      real(wp) :: e0(6)             !< strains of q^n (EMC, TRAPEZOIDAL)
   end type step_point_t

contains

   !> Step internal force fe (6, p+1) and tangent ke of one element for a scheme: the
   !> sums over the points (midpoint_terms, trapezoidal_terms, emc_terms) projected with
   !> the nodal directors of the evaluation point. docs/theory.md eqs. (35), (44),
   !> (54)-(57).
   pure subroutine rod_element_dynamic(p, le, c, eps0, x0, d0, x1, d1, scheme, wf, fe, ke, &
                                       want_k, rule, gp0, epsn, xb, db, kd, off)
      integer, intent(in) :: p                    !< element order
      real(wp), intent(in) :: le                  !< unstretched element length [m]
      real(wp), intent(in) :: c(6)                !< diag(GA1,GA2,EA,EI1,EI2,GJ)
      real(wp), intent(in) :: eps0(6, max_points) !< stress-free strains
      real(wp), intent(in) :: x0(3, p + 1)        !< positions at t_n [m]
      real(wp), intent(in) :: d0(3, 3, p + 1)     !< directors at t_n
      real(wp), intent(in) :: x1(3, p + 1)        !< positions at t_n+1 [m]
      real(wp), intent(in) :: d1(3, 3, p + 1)     !< directors at t_n+1
      integer, intent(in) :: scheme               !< scheme_* constant
      real(wp), intent(in) :: wf                  !< ALPHA: weight of q^{n+1} in q_f [-]
      real(wp), intent(out) :: fe(6, p + 1)       !< projected internal force [N, N m]
      real(wp), intent(out) :: ke(:, :)           !< (6(p+1), 6(p+1)) tangent, if want_k
      logical, intent(in) :: want_k               !< form the tangent
      type(rod_rule_t), intent(in) :: rule        !< rod_rule(p): points, shape functions
      !> EMC, TRAPEZOIDAL: the fields and strains of q^n at the points (rod_element_fields),
      !> constant over a step; computed here if absent
      type(rod_gp_t), intent(in), optional :: gp0(max_points)
      real(wp), intent(in), optional :: epsn(6, max_points)
      !> EMC: Newton's base, the iterate that the last correction started from (header:
      !> the tangent's stresses are then those of the strains linearized from it)
      real(wp), intent(in), optional :: xb(3, p + 1), db(3, 3, p + 1)
      !> EMC with RHO INF < 1 (docs/theory.md eq. (126)): the numerical stress
      !> kd (eps^{n+1} - eps^n) - off at each point, kd = K0 (c1 + 2 c2) [N, N m2]
      real(wp), intent(in), optional :: kd(6), off(6, max_points)
      type(element_step_t) :: es
      type(element_sums_t) :: sums
      type(step_point_t) :: pt
      integer :: g, nen, nd
      nen = p + 1
      nd = 6*nen
      es%nen = nen
      es%scheme = scheme
      es%want_k = want_k
      es%have0 = present(gp0) .and. present(epsn)
      ! evaluation point: the midpoint, or q_f for the generalized-alpha scheme
      es%wq = 0.5_wp
      if (scheme == scheme_alpha) es%wq = wf
      es%xm(:, 1:nen) = (1.0_wp - es%wq)*x0 + es%wq*x1
      es%dm(:, :, 1:nen) = (1.0_wp - es%wq)*d0 + es%wq*d1
      sums%fq(:, :, 1:nen) = 0.0_wp
      es%lin = want_k .and. present(xb) .and. present(db) .and. scheme == scheme_emc
      if (es%lin) then
         call linear_increment(nen, x1, d1, xb, db, es%dxl, es%ddl, es%dl, es%lin)
         sums%fql(:, :, 1:nen) = 0.0_wp
      end if
      if (want_k) ke(1:nd, 1:nd) = 0.0_wp
      sums%nf = 0
      sums%nc = 0
      if (want_k) then
         sums%pg(:, 1:nen, 1:nen) = 0.0_wp
         sums%mg(:, 1:nen, 1:nen) = 0.0_wp
      end if
      do g = 1, rule%np
         call point_setup(rule, g, le, c, eps0, nen, pt, off)
         call point_fields(es, x0, d0, x1, d1, pt, gp0, epsn)
         select case (scheme)
         case (scheme_midpoint, scheme_alpha)
            call midpoint_terms(es, pt, d1, sums)
         case (scheme_trapezoidal)
            call trapezoidal_terms(es, pt, d1, sums)
         case default ! scheme_emc
            call emc_terms(es, pt, x1, d1, sums, kd)
         end select
      end do
      call rod_project_qforce(nen, sums%fq(:, :, 1:nen), es%dm(:, :, 1:nen), fe)
      if (.not. want_k) return
      call material_update(nen, sums%blt, sums%cr, sums%nf, sums%blc, sums%crc, sums%nc, &
                           ke(1:nd, 1:nd))
      call geometric_update(nen, sums%pg, sums%mg, es%dm(:, :, 1:nen), d1, ke(1:nd, 1:nd))
      if (es%lin) then
         call rod_rotation_geometric(nen, sums%fql(:, :, 1:nen), d1, es%wq, ke(1:nd, 1:nd))
      else
         call rod_rotation_geometric(nen, sums%fq(:, :, 1:nen), d1, es%wq, ke(1:nd, 1:nd))
      end if
   end subroutine rod_element_dynamic

   !> Point g of the rule on an element of length le: shape functions and their
   !> derivatives in S, weight, and the stiffness and stress-free strains of the strains
   !> integrated there (docs/theory.md eqs. (19)-(21)).
   pure subroutine point_setup(rule, g, le, c, eps0, nen, pt, off)
      type(rod_rule_t), intent(in) :: rule          !< points, shape functions
      integer, intent(in) :: g                      !< point number
      real(wp), intent(in) :: le                    !< unstretched element length [m]
      real(wp), intent(in) :: c(6)                  !< diag(GA1,GA2,EA,EI1,EI2,GJ)
      real(wp), intent(in) :: eps0(6, max_points)   !< stress-free strains
      integer, intent(in) :: nen                    !< nodes of the element
      type(step_point_t), intent(inout) :: pt       !< the point (fields kept)
      !> offset of the numerical stress at the points (rod_element_dynamic; with it the
      !> point's mask) [N, N m]
      real(wp), intent(in), optional :: off(6, max_points)
      pt%g = g
      pt%shear = rule%shear_only(g)
      pt%n(1:nen) = rule%n(1:nen, g)
      pt%dn(1:nen) = rule%dn(1:nen, g)*2.0_wp/le
      pt%wj = rule%w(g)*0.5_wp*le
      pt%cg = c*rule%mask(:, g)
      pt%eps0 = eps0(:, g)
      if (.not. present(off)) return
      pt%mask = rule%mask(:, g)
      pt%off = off(:, g)
   end subroutine point_setup

   !> The fields at the point of q^{n+1} and, for EMC and TRAPEZOIDAL, of q^n with its
   !> strains (given, or computed here). docs/theory.md eqs. (4)-(5), (22).
   pure subroutine point_fields(es, x0, d0, x1, d1, pt, gp0, epsn)
      type(element_step_t), intent(in) :: es        !< the element's step
      real(wp), intent(in) :: x0(3, es%nen)         !< positions at t_n [m]
      real(wp), intent(in) :: d0(3, 3, es%nen)      !< directors at t_n
      real(wp), intent(in) :: x1(3, es%nen)         !< positions at t_n+1 [m]
      real(wp), intent(in) :: d1(3, 3, es%nen)      !< directors at t_n+1
      type(step_point_t), intent(inout) :: pt       !< k1, and k0, e0 set
      type(rod_gp_t), intent(in), optional :: gp0(max_points) !< fields of q^n
      real(wp), intent(in), optional :: epsn(6, max_points)   !< strains of q^n
      integer :: nen
      nen = es%nen
      call point_kinematics(nen, pt%shear, pt%n(1:nen), pt%dn(1:nen), x1, d1, pt%k1)
      if (es%scheme /= scheme_emc .and. es%scheme /= scheme_trapezoidal) return
      if (es%have0) then   ! q^n's fields and strains, given or computed
         pt%k0 = gp0(pt%g)
         if (pt%shear) then
            pt%e0(1:2) = epsn(1:2, pt%g)
         else
            pt%e0 = epsn(:, pt%g)
         end if
      else
         call point_kinematics(nen, pt%shear, pt%n(1:nen), pt%dn(1:nen), x0, d0, pt%k0)
         pt%e0 = point_strains(pt, pt%k0)
      end if
   end subroutine point_fields

   !> MIDPOINT and ALPHA: S = C (eps(q_e) - eps0) and B at the evaluation point q_e (the
   !> midpoint, or q_f). docs/theory.md eqs. (54), (56).
   pure subroutine midpoint_terms(es, pt, d1, sums)
      type(element_step_t), intent(in) :: es        !< the element's step
      type(step_point_t), intent(inout) :: pt       !< the point (km set)
      real(wp), intent(in) :: d1(3, 3, es%nen)      !< directors at t_n+1
      type(element_sums_t), intent(inout) :: sums   !< the element's sums
      real(wp) :: s(6)
      integer :: nen
      nen = es%nen
      call point_kinematics(nen, pt%shear, pt%n(1:nen), pt%dn(1:nen), es%xm(:, 1:nen), &
                            es%dm(:, :, 1:nen), pt%km)
      s = elastic_stress(pt, point_strains(pt, pt%km))
      call add_qforce(nen, pt, pt%km, s, pt%wj, sums%fq(:, :, 1:nen))
      if (.not. es%want_k) return
      call add_material(nen, pt, pt%km, es%dm(:, :, 1:nen), pt%km, d1, pt%cg, es%wq*pt%wj, sums)
      call add_geometric(nen, pt, s, es%wq*pt%wj, sums)
   end subroutine midpoint_terms

   !> TRAPEZOIDAL: the mean of the forces of q^n and q^{n+1}. docs/theory.md eq. (55).
   pure subroutine trapezoidal_terms(es, pt, d1, sums)
      type(element_step_t), intent(in) :: es        !< the element's step
      type(step_point_t), intent(in) :: pt          !< the point (k0, e0 set)
      real(wp), intent(in) :: d1(3, 3, es%nen)      !< directors at t_n+1
      type(element_sums_t), intent(inout) :: sums   !< the element's sums
      real(wp) :: s(6), s1(6)
      integer :: nen
      nen = es%nen
      s = elastic_stress(pt, pt%e0)
      s1 = elastic_stress(pt, point_strains(pt, pt%k1))
      call add_qforce(nen, pt, pt%k0, s, 0.5_wp*pt%wj, sums%fq(:, :, 1:nen))
      call add_qforce(nen, pt, pt%k1, s1, 0.5_wp*pt%wj, sums%fq(:, :, 1:nen))
      if (.not. es%want_k) return
      call add_material(nen, pt, pt%k1, es%dm(:, :, 1:nen), pt%k1, d1, pt%cg, 0.5_wp*pt%wj, &
                        sums)
      call add_geometric(nen, pt, s1, 0.5_wp*pt%wj, sums)
   end subroutine trapezoidal_terms

   !> EMC: S = C ((eps(q^n) + eps(q^{n+1}))/2 - eps0) (with RHO INF < 1 the numerical
   !> stress added) and B at the midpoint; the tangent's stress terms those of the strains
   !> linearized from Newton's base (es%lin; module header).
   !> docs/theory.md eqs. (35), (44), (126).
   pure subroutine emc_terms(es, pt, x1, d1, sums, kd)
      type(element_step_t), intent(in) :: es        !< the element's step
      type(step_point_t), intent(inout) :: pt       !< the point (k0, e0 set; km set)
      real(wp), intent(in) :: x1(3, es%nen)         !< positions at t_n+1 [m]
      real(wp), intent(in) :: d1(3, 3, es%nen)      !< directors at t_n+1
      type(element_sums_t), intent(inout) :: sums   !< the element's sums
      real(wp), intent(in), optional :: kd(6)       !< numerical stiffness [N, N m2]
      real(wp) :: s(6), cgt(6), sl(6)
      integer :: nen
      nen = es%nen
      ! the fields are linear in the nodal values: midpoint = mean of the ends
      pt%km%xp = 0.5_wp*(pt%k0%xp + pt%k1%xp)
      if (pt%shear) then
         pt%km%d(:, 1:2) = 0.5_wp*(pt%k0%d(:, 1:2) + pt%k1%d(:, 1:2))
      else
         pt%km%d = 0.5_wp*(pt%k0%d + pt%k1%d)
         pt%km%dp = 0.5_wp*(pt%k0%dp + pt%k1%dp)
      end if
      s = emc_stress(pt, point_strains(pt, pt%k1), kd)
      cgt = pt%cg
      if (present(kd)) cgt = pt%cg + 2.0_wp*kd*pt%mask
      call add_qforce(nen, pt, pt%km, s, pt%wj, sums%fq(:, :, 1:nen))
      if (.not. es%want_k) return
      call add_material(nen, pt, pt%km, es%dm(:, :, 1:nen), pt%k1, d1, cgt, 0.5_wp*pt%wj, sums)
      if (es%lin) then
         sl = linearized_strains(nen, pt%n(1:nen), pt%dn(1:nen), x1, es%dl(:, :, 1:nen), &
                                 es%dxl(:, 1:nen), es%ddl(:, :, 1:nen))
         s = emc_stress(pt, sl, kd)
         call add_qforce(nen, pt, pt%km, s, pt%wj, sums%fql(:, :, 1:nen))
      end if
      call add_geometric(nen, pt, s, 0.5_wp*pt%wj, sums)
   end subroutine emc_terms

   !> The fields at a point of nodal positions x and directors d (rod_gp_kinematics); at
   !> a shear-only point (Gamma1 and Gamma2 alone: the extra points of order 3) only x',
   !> d1 and d2, which the shear strains need. docs/theory.md eq. (22).
   pure subroutine point_kinematics(nen, shear, n, dn, x, d, kin)
      integer, intent(in) :: nen                    !< nodes of the element
      logical, intent(in) :: shear                  !< a shear-only point
      real(wp), intent(in) :: n(nen)                !< shape functions
      real(wp), intent(in) :: dn(nen)               !< dN/dS [1/m]
      real(wp), intent(in) :: x(3, nen)             !< nodal positions [m]
      real(wp), intent(in) :: d(3, 3, nen)          !< nodal directors
      type(rod_gp_t), intent(inout) :: kin          !< fields at the point
      if (shear) then
         call rod_gp_kinematics_shear(nen, n, dn, x, d, kin)
      else
         call rod_gp_kinematics(nen, n, dn, x, d, kin)
      end if
   end subroutine point_kinematics

   !> The strains at the point of the fields kin (at a shear-only point Gamma1 and
   !> Gamma2, the others 0). docs/theory.md eqs. (4)-(5).
   pure function point_strains(pt, kin) result(e)
      type(step_point_t), intent(in) :: pt          !< the point
      type(rod_gp_t), intent(in) :: kin             !< fields at the point
      real(wp) :: e(6)                              !< strains [-, 1/m]
      if (pt%shear) then
         e = 0.0_wp
         e(1:2) = rod_strains_shear(kin)
      else
         e = rod_strains(kin)
      end if
   end function point_strains

   !> Stress S = C (e - eps0) of the strains e integrated at the point [N, N m].
   !> docs/theory.md eq. (6).
   pure function elastic_stress(pt, e) result(s)
      type(step_point_t), intent(in) :: pt          !< the point
      real(wp), intent(in) :: e(6)                  !< strains [-, 1/m]
      real(wp) :: s(6)                              !< stress resultants [N, N m]
      if (pt%shear) then
         s = 0.0_wp
         s(1:2) = pt%cg(1:2)*(e(1:2) - pt%eps0(1:2))
      else
         s = pt%cg*(e - pt%eps0)
      end if
   end function elastic_stress

   !> EMC's stress with q^{n+1}'s strains e, S = C ((e0 + e)/2 - eps0), and with RHO
   !> INF < 1 the numerical stress kd (e - e0) - off [N, N m]. docs/theory.md eqs.
   !> (35), (126).
   pure function emc_stress(pt, e, kd) result(s)
      type(step_point_t), intent(in) :: pt          !< the point (e0 set)
      real(wp), intent(in) :: e(6)                  !< strains of q^{n+1} [-, 1/m]
      real(wp), intent(in), optional :: kd(6)       !< numerical stiffness [N, N m2]
      real(wp) :: s(6)                              !< stress resultants [N, N m]
      if (pt%shear) then
         s = 0.0_wp
         s(1:2) = pt%cg(1:2)*(0.5_wp*(pt%e0(1:2) + e(1:2)) - pt%eps0(1:2))
         if (present(kd)) s(1:2) = s(1:2) + pt%mask(1:2)* &
                                   (kd(1:2)*(e(1:2) - pt%e0(1:2)) - pt%off(1:2))
      else
         s = pt%cg*(0.5_wp*(pt%e0 + e) - pt%eps0)
         if (present(kd)) s = s + pt%mask*(kd*(e - pt%e0) - pt%off)
      end if
   end function emc_stress

   !> Add f B(kin)^T s to the q-forces (rod_gp_qforce; at a shear-only point
   !> rod_gp_qforce_shear of s(1:2)). docs/theory.md eqs. (22)-(23).
   pure subroutine add_qforce(nen, pt, kin, s, f, fq)
      integer, intent(in) :: nen                    !< nodes of the element
      type(step_point_t), intent(in) :: pt          !< the point
      type(rod_gp_t), intent(in) :: kin             !< fields where B is evaluated
      real(wp), intent(in) :: s(6)                  !< stress resultants [N, N m]
      real(wp), intent(in) :: f                     !< weight (Gauss weight, Jacobian) [m]
      real(wp), intent(inout) :: fq(3, 4, nen)      !< q-forces
      if (pt%shear) then
         call rod_gp_qforce_shear(nen, pt%n(1:nen), pt%dn(1:nen), kin, s(1:2), f, fq)
      else
         call rod_gp_qforce(nen, pt%n(1:nen), pt%dn(1:nen), kin, s, f, fq)
      end if
   end subroutine add_qforce

   !> The correction from Newton's base (xb, db) to the iterate (x1, d1), linearized:
   !> dxl = x1 - xb, ddl_i = theta x db_i with theta = cay^-1(d1 db^T) (the Cayley
   !> parameter of the director update), and dl = db + ddl, per node. Not ok where a
   !> node turned by 120 degrees or more (1 + tr R <= 1; cay^-1 is singular at 180): such
   !> an iterate is far from this tangent's purpose, which then keeps its own stresses.
   !> docs/theory.md eq. (44).
   pure subroutine linear_increment(nen, x1, d1, xb, db, dxl, ddl, dl, ok)
      integer, intent(in) :: nen                 !< nodes of the element
      real(wp), intent(in) :: x1(3, nen)         !< iterate positions [m]
      real(wp), intent(in) :: d1(3, 3, nen)      !< iterate directors
      real(wp), intent(in) :: xb(3, nen)         !< base positions [m]
      real(wp), intent(in) :: db(3, 3, nen)      !< base directors
      real(wp), intent(out) :: dxl(:, :)         !< (3, >= nen) position increment [m]
      real(wp), intent(out) :: ddl(:, :, :)      !< (3, 3, >= nen) linearized director increment
      real(wp), intent(out) :: dl(:, :, :)       !< (3, 3, >= nen) db + ddl
      logical, intent(out) :: ok                 !< every node turned by less than 120 deg
      real(wp) :: th(3), r(3, 3)
      integer :: a, i
      ok = .true.
      do a = 1, nen
         r = relative_rotation(d1(:, :, a), db(:, :, a))
         if (1.0_wp + r(1, 1) + r(2, 2) + r(3, 3) <= 1.0_wp) then
            ok = .false.
            return
         end if
         th = rotation_cayley_inverse(r)
         do i = 1, 3
            ddl(:, i, a) = cross(th, db(:, i, a))
         end do
         dl(:, :, a) = db(:, :, a) + ddl(:, :, a)
         dxl(:, a) = x1(:, a) - xb(:, a)
      end do
   end subroutine linear_increment

   !> The strains at a point linearized from the base (module header): eps of the fields
   !> of (x1, dl) less the quadratic part eps2 of the increment fields (dxl, ddl) alone;
   !> rod_strains of the increment fields is eps2 with -1 in its axial strain.
   !> docs/theory.md eq. (44).
   pure function linearized_strains(nen, n, dn, x1, dl, dxl, ddl) result(eps)
      integer, intent(in) :: nen                 !< nodes of the element
      real(wp), intent(in) :: n(nen)             !< shape functions
      real(wp), intent(in) :: dn(nen)            !< dN/dS [1/m]
      real(wp), intent(in) :: x1(3, nen)         !< iterate positions [m]
      real(wp), intent(in) :: dl(3, 3, nen)      !< base directors plus their increment
      real(wp), intent(in) :: dxl(3, nen)        !< position increment [m]
      real(wp), intent(in) :: ddl(3, 3, nen)     !< linearized director increment
      real(wp) :: eps(6)
      type(rod_gp_t) :: kl, kd
      call rod_gp_kinematics(nen, n, dn, x1, dl, kl)
      call rod_gp_kinematics(nen, n, dn, dxl, ddl, kd)
      eps = rod_strains(kl) - rod_strains(kd)
      eps(3) = eps(3) - 1.0_wp
   end function linearized_strains

   !> The stress (geometric) stiffness of one point, rod_rod_element's rod_gp_geometric,
   !> summed over the points before it is formed: with the nodal directors the same at
   !> every point, its blocks are linear in
   !>   pg(k, a, b) = sum_g f dN_a N_b s_k          (k = 1..3, contact forces)
   !>   mg(:, a, b) = sum_g f (dN_a N_b - N_a dN_b)/2 (s_4, s_5, s_6)   (moments)
   !> (geometric_update forms them once per element, not once per point).
   !> docs/theory.md eq. (27).
   pure subroutine add_geometric(nen, pt, s, f, sums)
      integer, intent(in) :: nen                     !< nodes of the element
      type(step_point_t), intent(in) :: pt           !< the point (shape functions)
      real(wp), intent(in) :: s(6)                   !< stress resultants [N, N m]
      real(wp), intent(in) :: f                      !< weight (Gauss weight, Jacobian)
      type(element_sums_t), intent(inout) :: sums    !< force and moment sums pg, mg
      real(wp) :: h
      integer :: a, b
      do b = 1, nen
         do a = 1, nen
            sums%pg(:, a, b) = sums%pg(:, a, b) + (f*pt%dn(a)*pt%n(b))*s(1:3)
            if (a == b) cycle
            h = 0.5_wp*f*(pt%dn(a)*pt%n(b) - pt%n(a)*pt%dn(b))
            sums%mg(:, a, b) = sums%mg(:, a, b) + h*s(4:6)
         end do
      end do
   end subroutine add_geometric

   !> Add the stress stiffness of the sums of add_geometric to ke (P(d) = -skew(d), as
   !> in rod_gp_geometric):
   !>   x_a - theta_b:      -skew(sum_k pg(k, a, b) dr_kb)
   !>   theta_a - x_b:       skew(sum_k pg(k, b, a) dl_ka)
   !>   theta_a - theta_b:   tr(M) I - M,  M = Dr_b skew(mg(:, a, b)) Dl_a^T
   !> (Dl_a, Dr_b: the nodal directors as columns, test side and increment side).
   !> docs/theory.md eq. (27).
   pure subroutine geometric_update(nen, pg, mg, dl, dr, ke)
      integer, intent(in) :: nen                  !< nodes of the element
      real(wp), intent(in) :: pg(:, :, :)         !< force sums (add_geometric)
      real(wp), intent(in) :: mg(:, :, :)         !< moment sums (add_geometric)
      real(wp), intent(in) :: dl(3, 3, nen)       !< nodal directors, test side
      real(wp), intent(in) :: dr(3, 3, nen)       !< nodal directors, increment side
      real(wp), intent(inout) :: ke(:, :)         !< element matrix (6 nen square)
      real(wp) :: v(3), st(3, 3), w(3, 3), m(3, 3), tr
      integer :: a, b, ra, rb, i, j
      do b = 1, nen
         rb = 6*(b - 1)
         do a = 1, nen
            ra = 6*(a - 1)
            v = pg(1, a, b)*dr(:, 1, b) + pg(2, a, b)*dr(:, 2, b) + pg(3, a, b)*dr(:, 3, b)
            ke(ra + 1:ra + 3, rb + 4:rb + 6) = ke(ra + 1:ra + 3, rb + 4:rb + 6) - skew(v)
            v = pg(1, b, a)*dl(:, 1, a) + pg(2, b, a)*dl(:, 2, a) + pg(3, b, a)*dl(:, 3, a)
            ke(ra + 4:ra + 6, rb + 1:rb + 3) = ke(ra + 4:ra + 6, rb + 1:rb + 3) + skew(v)
            if (a == b) cycle
            st = skew(mg(:, a, b))
            ! w = st Dl_a^T, m = Dr_b w
            do j = 1, 3
               w(:, j) = st(:, 1)*dl(j, 1, a) + st(:, 2)*dl(j, 2, a) + st(:, 3)*dl(j, 3, a)
            end do
            do j = 1, 3
               m(:, j) = dr(:, 1, b)*w(1, j) + dr(:, 2, b)*w(2, j) + dr(:, 3, b)*w(3, j)
            end do
            tr = m(1, 1) + m(2, 2) + m(3, 3)
            do j = 1, 3
               do i = 1, 3
                  ke(ra + 3 + i, rb + 3 + j) = ke(ra + 3 + i, rb + 3 + j) - m(i, j)
               end do
               ke(ra + 3 + j, rb + 3 + j) = ke(ra + 3 + j, rb + 3 + j) + tr
            end do
         end do
      end do
   end subroutine geometric_update

   !> Append the point's material part f bl^T diag(cg) br, over the strains integrated
   !> here (cg /= 0), to the rows of the element (material_update adds them to ke):
   !> row k of bl (the strain Jacobian of the test side: fields kl, nodal directors dl)
   !> as column nf of blt (force strains) or, its rotation entries only (3 a - 2 .. 3 a
   !> for node a), as column nc of blc (curvatures); f cg(k) times row k of br (the
   !> increment side: kr, dr) as row nf of cr or nc of crc. Only the rows used are formed
   !> (rod_gp_jacobian_row): at a full point of order 3 Gamma3 and the curvatures, at a
   !> shear-only point Gamma1 and Gamma2.
   !> docs/theory.md eq. (26).
   pure subroutine add_material(nen, pt, kl, dl, kr, dr, cg, f, sums)
      integer, intent(in) :: nen                 !< nodes of the element
      type(step_point_t), intent(in) :: pt       !< the point (shape functions)
      type(rod_gp_t), intent(in) :: kl, kr       !< fields of the test and increment sides
      real(wp), intent(in) :: dl(3, 3, nen)      !< nodal directors, test side
      real(wp), intent(in) :: dr(3, 3, nen)      !< nodal directors, increment side
      real(wp), intent(in) :: cg(6)              !< stiffness of the strains integrated here
      real(wp), intent(in) :: f                  !< weight
      type(element_sums_t), intent(inout) :: sums !< rows blt, cr (nf) and blc, crc (nc)
      real(wp) :: row(6*max_nen)
      integer :: k, nd, a
      nd = 6*nen
      do k = 1, 6
         if (cg(k) == 0.0_wp) cycle
         call rod_gp_jacobian_row(nen, pt%n(1:nen), pt%dn(1:nen), kr, dr, k, row(1:nd))
         if (k <= 3) then
            sums%nf = sums%nf + 1
            call rod_gp_jacobian_row(nen, pt%n(1:nen), pt%dn(1:nen), kl, dl, k, &
                                     sums%blt(1:nd, sums%nf))
            sums%cr(sums%nf, 1:nd) = (f*cg(k))*row(1:nd)
         else
            sums%nc = sums%nc + 1
            sums%crc(sums%nc, 1:nd) = (f*cg(k))*row(1:nd)
            call rod_gp_jacobian_row(nen, pt%n(1:nen), pt%dn(1:nen), kl, dl, k, row(1:nd))
            do a = 1, nen                  ! the rotation entries only
               sums%blc(3*a - 2:3*a, sums%nc) = row(6*a - 2:6*a)
            end do
         end if
      end do
   end subroutine add_material

   !> ke += blt(:, 1:nf) cr(1:nf, :) + blc(:, 1:nc) crc(1:nc, :), column by column and
   !> row by row down a column (the loop the compiler vectorizes). The curvatures do not
   !> depend on the positions: blc holds their rotation rows only, and a rotation column
   !> of ke takes them through its rotation rows gathered into one vector.
   pure subroutine material_update(nen, blt, cr, nf, blc, crc, nc, ke)
      integer, intent(in) :: nen                      !< nodes of the element
      real(wp), intent(in) :: blt(6*max_nen, 3*max_points), cr(3*max_points, 6*max_nen)
      integer, intent(in) :: nf                       !< force-strain rows
      real(wp), intent(in) :: blc(3*max_nen, 3*max_points), crc(3*max_points, 6*max_nen)
      integer, intent(in) :: nc                       !< curvature rows
      real(wp), intent(inout) :: ke(:, :)             !< element matrix (6 nen square)
      real(wp) :: c, kr(3*max_nen)
      integer :: j, i, k, a
      do j = 1, 6*nen
         do k = 1, nf
            c = cr(k, j)
            do i = 1, 6*nen
               ke(i, j) = ke(i, j) + c*blt(i, k)
            end do
         end do
         if (mod(j - 1, 6) < 3) cycle       ! an x column: no curvature terms
         do a = 1, nen
            kr(3*a - 2:3*a) = ke(6*a - 2:6*a, j)
         end do
         do k = 1, nc
            c = crc(k, j)
            do i = 1, 3*nen
               kr(i) = kr(i) + c*blc(i, k)
            end do
         end do
         do a = 1, nen
            ke(6*a - 2:6*a, j) = kr(3*a - 2:3*a)
         end do
      end do
   end subroutine material_update
end module rodyn_rod_dynamic
