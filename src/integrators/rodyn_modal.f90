!> Modal analysis of a system about its static equilibrium (*MODAL; docs/theory.md
!> section 18, eqs. (145)-(148)).
!>
!> The unknowns are those of the Newton step of the statics, reduced (145): the band's
!> rows that are neither held (supports), nor a line end's translation on a FREE point
!> or body (eliminated onto it, rodyn_junctions), nor a master's own band row, followed
!> by the junction unknowns of the FREE points and bodies. K is the consistent tangent of
!> the statics at the equilibrium (its band and arrowhead, made symmetric); M (146) the
!> lumped inertia of the integrators (rodyn_inertia: m I on the translations, sum_i E_i
!> (I - d_i d_i^T) on a node's rotations), the water's added mass (the acceleration
!> tangent of rodyn_water, C_an P + C_aa t t per unit length) and the bodies' added
!> mass, assembled in the same band and condensed onto the masters with the same
!> transfer matrices T as K (132). Both reduced matrices are formed column by column from
!> products with unit vectors, and
!>
!>   M phi = mu K phi,   mu = 1 / omega^2                                       (147)
!>
!> is solved by LAPACK's dsygv (K positive definite at a stable equilibrium; M may be
!> singular: a massless unknown has mu = 0, an infinite frequency, and is not a mode).
!> The modes are the largest mu, longest period first; each shape is expanded to every
!> node (an end on a master moves with it, T q_m) and scaled to a largest translation of
!> 1 m; the kinetic energy phi^T M phi is split by rows among the lines and masters
!> (148).
module rodyn_modal
   use rodyn_kinds, only: wp, pi
   use rodyn_error, only: error_t, has_error, set_error, stat_numerical
   use rodyn_model, only: model_t, modal_auto, modal_dense, modal_lanczos, &
                          modal_solver_names
   use rodyn_mesh, only: mesh_t
   use rodyn_statics, only: static_problem_t
   use rodyn_results, only: system_result_t
   use rodyn_inertia, only: inertia_t, inertia_build
   use rodyn_assembly, only: supports_t, add_node_block, assemble_water
   use rodyn_banded, only: banded_t, banded_init, banded_matvec, dense_sym_eigen
   use rodyn_junctions, only: junctions_t, junctions_condense
   use rodyn_rod_problem, only: rod_factor, rod_back_solve
   use rodyn_lanczos, only: eigen_operator_t, lanczos_modes
   use rodyn_arrowhead, only: arrowhead_matvec
   use rodyn_water, only: water_loads_t
   use rodyn_rotation, only: cross
   use rodyn_body_mass, only: added_mass_global
   use rodyn_hydro, only: outer
   implicit none
   private
   public :: modal_analysis, modal_max_unknowns, modal_dense_limit

   !> The largest reduced system the dense eigensolver takes (two matrices of 290 MB)
   integer, parameter :: modal_max_unknowns = 6000
   !> SOLVER=AUTO: dense up to this many reduced unknowns, Lanczos above
   integer, parameter :: modal_dense_limit = 100

   !> The reduced unknowns (145): free band rows, then junction unknowns not held.
   type :: reduced_t
      integer :: n = 0                    !< reduced unknowns
      integer :: nb = 0                   !< of them in the band
      integer, allocatable :: band(:)     !< (nb) the band dof of each
      integer, allocatable :: junc(:)     !< (n - nb) the junction unknown of each
   end type reduced_t

   !> An operator in the band and junction layout: the band and, with junctions, the
   !> arrowhead couplings of a junctions_t condensed with it.
   type :: operator_t
      type(banded_t) :: bm                !< band
      type(junctions_t) :: jn             !< junctions (E, F, C in jn%ah)
   end type operator_t

   !> The eigenproblem's operations with their context (rodyn_lanczos).
   type, extends(eigen_operator_t) :: system_operator_t
      type(static_problem_t), pointer :: prob => null() !< statics, K factorised
      type(operator_t), pointer :: mass => null()       !< the mass
      type(reduced_t), pointer :: red => null()         !< reduced unknowns
      real(wp), allocatable :: x(:), rx(:)              !< (n_dof) scratch, band layout
      real(wp), allocatable :: y(:), ry(:)              !< (nj) scratch, junctions
   contains
      procedure :: solve_k => system_solve_k
      procedure :: apply_m => system_apply_m
   end type system_operator_t

contains

   !> The modal analysis of model%modal into sys (nothing without *MODAL): prob solved
   !> to its equilibrium (lambda = 1). The eigensolver: DENSE, LANCZOS, or AUTO (dense up
   !> to modal_dense_limit reduced unknowns, docs/benchmarks.md "Modal analysis").
   subroutine modal_analysis(model, prob, sys, err)
      type(model_t), intent(in) :: model                   !< model (*MODAL, inertia)
      type(static_problem_t), intent(inout), target :: prob !< solved statics
      type(system_result_t), intent(inout) :: sys          !< modal results set
      type(error_t), intent(inout) :: err                  !< status
      type(reduced_t), target :: red
      type(operator_t), target :: mass
      real(wp), allocatable :: v(:, :), mu(:)
      integer :: nev, solver
      if (.not. model%modal%requested .or. has_error(err)) return
      call prob%evaluate(.true., err)
      if (has_error(err)) return
      call reduced_build(prob%sup, prob%jn, red)
      call mass_build(model, prob, mass)
      sys%modal_asymmetry = asymmetry(prob%bm, prob%jn, red)
      call symmetric_part(prob%bm, prob%jn)
      nev = min(model%modal%modes, red%n - 1)
      solver = model%modal%solver
      if (solver == modal_auto) solver = merge(modal_dense, modal_lanczos, &
                                               red%n <= modal_dense_limit)
      if (nev < 1) solver = modal_dense
      sys%modal_solver = modal_solver_names(solver)
      if (solver == modal_dense) then
         call dense_modes(prob, mass, red, model%modal%modes, v, mu, err)
      else
         call lanczos_path(prob, mass, red, nev, v, mu, err)
      end if
      if (has_error(err)) then
         call set_error(err, stat_numerical, '*MODAL: '//err%message)
         return
      end if
      call modes_store(prob, mass, red, v, mu, sys)
   end subroutine modal_analysis

   !> The modes by LAPACK's dense dsygv on the reduced matrices (147), the largest mu
   !> (at most `modes` of them, those with mass).
   subroutine dense_modes(prob, mass, red, modes, v, mu, err)
      type(static_problem_t), intent(inout) :: prob   !< solved statics, K formed
      type(operator_t), intent(in) :: mass            !< the mass
      type(reduced_t), intent(in) :: red              !< reduced unknowns
      integer, intent(in) :: modes                    !< modes wanted
      real(wp), allocatable, intent(out) :: v(:, :)   !< (n, nm) modes
      real(wp), allocatable, intent(out) :: mu(:)     !< (nm) 1/omega^2, descending [s2]
      type(error_t), intent(inout) :: err             !< status
      real(wp), allocatable :: kr(:, :), mr(:, :), all(:)
      character(len=160) :: msg
      integer :: nm
      if (red%n > modal_max_unknowns) then
         write (msg, '(a,i0,a,i0,a)') 'the system has ', red%n, ' unknowns, more than '// &
            'the dense eigensolver takes (', modal_max_unknowns, '): use SOLVER=LANCZOS'
         call set_error(err, stat_numerical, trim(msg))
         return
      end if
      allocate (kr(red%n, red%n), mr(red%n, red%n), all(red%n))
      call dense_of(prob%bm, prob%jn, red, kr)
      call dense_of(mass%bm, mass%jn, red, mr)
      kr = 0.5_wp*(kr + transpose(kr))
      mr = 0.5_wp*(mr + transpose(mr))
      call dense_sym_eigen(mr, kr, all, err)
      if (has_error(err)) then
         err%message = 'the stiffness about the equilibrium is not positive definite (a '// &
                       'motion without restoring, or an unstable equilibrium): '//err%message
         return
      end if
      nm = min(modes, count(all > 1.0e-12_wp*maxval(all)))
      mu = all(red%n:red%n - nm + 1:-1)
      v = mr(:, red%n:red%n - nm + 1:-1)
   end subroutine dense_modes

   !> The nev modes by ARPACK's shift-invert Lanczos (rodyn_lanczos) with the statics'
   !> factorised tangent.
   subroutine lanczos_path(prob, mass, red, nev, v, mu, err)
      type(static_problem_t), intent(inout), target :: prob !< solved statics, K formed
      type(operator_t), intent(inout), target :: mass      !< the mass
      type(reduced_t), intent(in), target :: red           !< reduced unknowns
      integer, intent(in) :: nev                           !< modes wanted (< red%n)
      real(wp), allocatable, intent(out) :: v(:, :)        !< (n, nev) modes
      real(wp), allocatable, intent(out) :: mu(:)          !< (nev) 1/omega^2 [s2]
      type(error_t), intent(inout) :: err                  !< status
      type(system_operator_t) :: op
      call rod_factor(prob, err)
      if (has_error(err)) then
         err%message = 'the stiffness about the equilibrium is singular: '//err%message
         return
      end if
      op%prob => prob
      op%mass => mass
      op%red => red
      allocate (op%x(prob%sup%n_dof), op%rx(prob%sup%n_dof), op%y(prob%jn%nj), &
                op%ry(prob%jn%nj))
      allocate (v(red%n, nev), mu(nev))
      call lanczos_modes(op, red%n, nev, mu, v, err)
   end subroutine lanczos_path

   !> y = K^-1 x in the reduced unknowns (the factorised tangent of the statics).
   subroutine system_solve_k(this, x, y, err)
      class(system_operator_t), intent(inout) :: this !< context
      real(wp), intent(in) :: x(:)                    !< (n) right-hand side
      real(wp), intent(out) :: y(:)                   !< (n) solution
      type(error_t), intent(inout) :: err             !< status
      associate (red => this%red, p => this%prob)
         this%x = 0.0_wp
         this%x(red%band) = x(1:red%nb)
         if (size(red%junc) > 0) this%x(p%jn%jdof(red%junc)) = x(red%nb + 1:)
         call rod_back_solve(p, this%x, err)
         y(1:red%nb) = this%x(red%band)
         if (size(red%junc) > 0) y(red%nb + 1:) = this%x(p%jn%jdof(red%junc))
      end associate
   end subroutine system_solve_k

   !> y = M x in the reduced unknowns.
   subroutine system_apply_m(this, x, y)
      class(system_operator_t), intent(inout) :: this !< context
      real(wp), intent(in) :: x(:)                    !< (n) vector
      real(wp), intent(out) :: y(:)                   !< (n) product
      associate (red => this%red)
         this%x = 0.0_wp
         this%y = 0.0_wp
         this%x(red%band) = x(1:red%nb)
         this%y(red%junc) = x(red%nb + 1:)
         call apply(this%mass%bm, this%mass%jn, this%x, this%y, this%rx, this%ry)
         y(1:red%nb) = this%rx(red%band)
         y(red%nb + 1:) = this%ry(red%junc)
      end associate
   end subroutine system_apply_m

   !> K <- (K + K^T)/2 in place: the band, the arrowhead's E and F^T, and C (eq. (147):
   !> the modes of the symmetric part of the tangent).
   subroutine symmetric_part(bm, jn)
      type(banded_t), intent(inout) :: bm     !< band (not factorised)
      type(junctions_t), intent(inout) :: jn  !< junctions condensed with it
      real(wp) :: a
      integer :: i, j, b
      do j = 1, bm%n
         do i = j + 1, min(bm%n, j + min(bm%kl, bm%ku))
            a = 0.5_wp*(bm%ab(bm%kv + i - j, j) + bm%ab(bm%kv + j - i, i))
            bm%ab(bm%kv + i - j, j) = a
            bm%ab(bm%kv + j - i, i) = a
         end do
      end do
      if (jn%nj == 0) return
      jn%ah%c = 0.5_wp*(jn%ah%c + transpose(jn%ah%c))
      do b = 1, size(jn%ah%blocks)
         associate (blk => jn%ah%blocks(b))
            blk%e = 0.5_wp*(blk%e + transpose(blk%f))
            blk%f = transpose(blk%e)
         end associate
      end do
   end subroutine symmetric_part

   !> An estimate of |K - K^T| / |K| from two fixed vectors a, b of the reduced unknowns:
   !> |a^T K b - b^T K a| / (|K a| |b|), K before its factorisation.
   function asymmetry(bm, jn, red) result(r)
      type(banded_t), intent(in) :: bm        !< tangent
      type(junctions_t), intent(in) :: jn     !< junctions condensed with it
      type(reduced_t), intent(in) :: red      !< reduced unknowns
      real(wp) :: r
      real(wp), allocatable :: a(:), b(:), ka(:), kb(:), x(:), y(:), rx(:), ry(:)
      integer :: i
      allocate (x(bm%n), rx(bm%n), y(jn%nj), ry(jn%nj))
      a = [(sin(1.0_wp + 0.7_wp*i), i=1, red%n)]
      b = [(cos(2.0_wp + 1.3_wp*i), i=1, red%n)]
      allocate (ka(red%n), kb(red%n))
      call product(a, ka)
      call product(b, kb)
      r = abs(dot_product(b, ka) - dot_product(a, kb))/max(norm2(ka)*norm2(b), tiny(1.0_wp))
   contains
      subroutine product(u, ku)
         real(wp), intent(in) :: u(:)
         real(wp), intent(out) :: ku(:)
         x = 0.0_wp
         y = 0.0_wp
         x(red%band) = u(1:red%nb)
         y(red%junc) = u(red%nb + 1:)
         call apply(bm, jn, x, y, rx, ry)
         ku(1:red%nb) = rx(red%band)
         ku(red%nb + 1:) = ry(red%junc)
      end subroutine product
   end function asymmetry

   !> The reduced unknowns of the statics' Newton step (145).
   subroutine reduced_build(sup, jn, red)
      type(supports_t), intent(in) :: sup     !< dof map and held dofs
      type(junctions_t), intent(in) :: jn     !< junctions
      type(reduced_t), intent(out) :: red     !< reduced unknowns
      logical, allocatable :: fixed(:)
      integer :: s, i, j
      allocate (fixed(sup%n_dof))
      fixed = .false.
      fixed(sup%held_dof(1:sup%n_held)) = .true.
      do s = 1, jn%ns
         if (.not. jn%s_on(s)) cycle
         i = sup%first(jn%s_node(s))
         fixed(i:i + jn%s_ne(s) - 1) = .true.
      end do
      if (jn%nj > 0) fixed(jn%jdof) = .true.
      red%band = pack([(i, i=1, sup%n_dof)], .not. fixed)
      red%nb = size(red%band)
      if (jn%nj > 0) then
         red%junc = pack([(j, j=1, jn%nj)], .not. jn%held)
      else
         allocate (red%junc(0))
      end if
      red%n = red%nb + size(red%junc)
   end subroutine reduced_build

   !> The mass (146) in the statics' band and junction layout: the lumped inertia of
   !> every node, the water's added mass, the bodies' added mass at G (153), condensed
   !> onto the masters as the tangent is.
   subroutine mass_build(model, prob, mass)
      type(model_t), intent(in) :: model              !< model
      type(static_problem_t), intent(in) :: prob      !< solved statics
      type(operator_t), intent(out) :: mass           !< the mass
      type(inertia_t) :: inert
      type(water_loads_t) :: wl
      real(wp) :: kb(6, 6), d(3, 3)
      real(wp), allocatable :: fint(:, :), rhs(:)
      integer :: node, i, k
      associate (mesh => prob%mesh, sup => prob%sup, st => prob%state)
         call banded_init(mass%bm, sup%n_dof, sup%half_bw)
         call inertia_build(model, mesh, inert)
         do node = 1, mesh%n_nodes
            kb = 0.0_wp
            d = st%d(:, :, node)
            do i = 1, 3
               kb(i, i) = inert%m(node)
               kb(4:6, 4:6) = kb(4:6, 4:6) - inert%md(i, node)*outer(d(:, i), d(:, i))
               kb(3 + i, 3 + i) = kb(3 + i, 3 + i) + sum(inert%md(:, node))
            end do
            k = findloc(inert%ma_node, node, dim=1)
            if (k > 0) kb = kb + added_mass_global(inert%ma(:, :, k), d)
            call add_node_block(sup, node, kb, mass%bm)
         end do
         if (prob%water%active) then
            wl = prob%water
            allocate (fint(6, mesh%n_nodes))
            fint = 0.0_wp
            call assemble_water(wl, mesh, sup, st%x, prob%zero3, prob%zero3, 0.0_wp, &
                                0.0_wp, 1.0_wp, fint, mass%bm, .true.)
         end if
         mass%jn = prob%jn
         if (mass%jn%nj > 0) then
            allocate (rhs(sup%n_dof))
            rhs = 0.0_wp
            call junctions_condense(mass%jn, sup, rhs, mass%bm, .true., st%d, st%d, 1.0_wp)
         end if
      end associate
   end subroutine mass_build

   !> The reduced dense matrix of an operator: column c its product with unit vector c.
   subroutine dense_of(bm, jn, red, a)
      type(banded_t), intent(in) :: bm        !< band (not factorised)
      type(junctions_t), intent(in) :: jn     !< junctions condensed with it
      type(reduced_t), intent(in) :: red      !< reduced unknowns
      real(wp), intent(out) :: a(:, :)        !< (n, n) the matrix
      real(wp), allocatable :: x(:), y(:), rx(:), ry(:)
      integer :: c
      allocate (x(bm%n), rx(bm%n), y(jn%nj), ry(jn%nj))
      x = 0.0_wp
      y = 0.0_wp
      do c = 1, red%n
         call unit_vector(red, c, 1.0_wp, x, y)
         call apply(bm, jn, x, y, rx, ry)
         a(1:red%nb, c) = rx(red%band)
         a(red%nb + 1:, c) = ry(red%junc)
         call unit_vector(red, c, 0.0_wp, x, y)
      end do
   end subroutine dense_of

   !> Entry c of the reduced vector set to v in the band and junction layout (x, y).
   pure subroutine unit_vector(red, c, v, x, y)
      type(reduced_t), intent(in) :: red      !< reduced unknowns
      integer, intent(in) :: c                !< reduced unknown
      real(wp), intent(in) :: v               !< value
      real(wp), intent(inout) :: x(:), y(:)   !< band and junction parts
      if (c <= red%nb) then
         x(red%band(c)) = v
      else
         y(red%junc(c - red%nb)) = v
      end if
   end subroutine unit_vector

   !> (rx, ry) = A (x, y): the band's product, with the arrowhead's couplings if any.
   subroutine apply(bm, jn, x, y, rx, ry)
      type(banded_t), intent(in) :: bm        !< band
      type(junctions_t), intent(in) :: jn     !< junctions
      real(wp), intent(in) :: x(:), y(:)      !< vector
      real(wp), intent(out) :: rx(:), ry(:)   !< product
      if (jn%nj > 0) then
         call arrowhead_matvec(jn%ah, bm, x, y, rx, ry)
      else
         call banded_matvec(bm, x, rx)
      end if
   end subroutine apply

   !> The nm modes (columns of v, reduced; mu = 1/omega^2) into sys: periods, node and
   !> body motions (largest translation 1 m, its largest component positive) and the
   !> shares of kinetic energy (148).
   subroutine modes_store(prob, mass, red, v, mu, sys)
      type(static_problem_t), intent(in) :: prob      !< solved statics
      type(operator_t), intent(in) :: mass            !< the mass
      type(reduced_t), intent(in) :: red              !< reduced unknowns
      real(wp), intent(in) :: v(:, :)                 !< (n, nm) modes
      real(wp), intent(in) :: mu(:)                   !< (nm) 1/omega^2 [s2]
      type(system_result_t), intent(inout) :: sys     !< modal results set
      real(wp), allocatable :: x(:), y(:), rx(:), ry(:)
      real(wp) :: scale, big
      integer :: k, nm, nn, i, b, m
      nm = size(mu)
      nn = prob%mesh%n_nodes
      allocate (sys%modal_period(nm), sys%modal_shape(6, nn, nm), &
                sys%modal_master(6, prob%jn%nm, nm), &
                sys%modal_share(prob%mesh%n_lines + prob%jn%nm, nm))
      allocate (x(prob%sup%n_dof), rx(prob%sup%n_dof), y(prob%jn%nj), ry(prob%jn%nj))
      do k = 1, nm
         sys%modal_period(k) = 2.0_wp*pi*sqrt(mu(k))
         x = 0.0_wp
         y = 0.0_wp
         x(red%band) = v(1:red%nb, k)
         y(red%junc) = v(red%nb + 1:, k)
         call apply(mass%bm, mass%jn, x, y, rx, ry)
         call energy_shares(prob, x, y, rx, ry, sys%modal_share(:, k))
         call node_motion(prob, x, y, sys%modal_shape(:, :, k))
         do m = 1, prob%jn%nm
            i = prob%jn%m_node(m)
            sys%modal_master(:, m, k) = sys%modal_shape(:, i, k)
            if (sys%kind(m) /= 2) cycle
            b = sys%index(m)
            sys%modal_master(1:3, m, k) = sys%modal_shape(1:3, i, k) + &
               cross(sys%modal_shape(4:6, i, k), sys%body_x(:, b) - prob%state%x(:, i))
         end do
         big = largest(sys%modal_shape(1:3, :, k))
         if (big == 0.0_wp) big = largest(sys%modal_shape(4:6, :, k))
         scale = 1.0_wp/big
         ! (+ 0: no negative zeros in the tables)
         sys%modal_shape(:, :, k) = scale*sys%modal_shape(:, :, k) + 0.0_wp
         sys%modal_master(:, :, k) = scale*sys%modal_master(:, :, k) + 0.0_wp
      end do
   contains
      !> The entry of largest magnitude, with its sign.
      pure real(wp) function largest(a)
         real(wp), intent(in) :: a(:, :)
         integer :: ij(2)
         ij = maxloc(abs(a))
         largest = a(ij(1), ij(2))
      end function largest
   end subroutine modes_store

   !> Every node's motion (6, nn) of a mode in the band and junction layout: translations
   !> global, a rotated node's rotation taken to global axes (T theta), an end on a master
   !> moving with it (T_k q_m, eq. (135)), a master's node its junction unknowns.
   subroutine node_motion(prob, x, y, u)
      type(static_problem_t), intent(in) :: prob      !< solved statics
      real(wp), intent(in) :: x(:), y(:)              !< mode (band, junctions)
      real(wp), intent(out) :: u(:, :)                !< (6, nn) node motions
      integer :: node, k, s, m, j0, nmj
      u = 0.0_wp
      associate (sup => prob%sup, jn => prob%jn)
         do node = 1, prob%mesh%n_nodes
            k = sup%first(node) - 1
            u(1:sup%ndof(node), node) = x(k + 1:k + sup%ndof(node))
            if (sup%ndof(node) == 6 .and. sup%rotated(node)) &
               u(4:6, node) = matmul(sup%basis(:, :, node), u(4:6, node))
         end do
         do m = 1, jn%nm
            j0 = jn%m_j0(m)
            u(1:jn%m_n(m), jn%m_node(m)) = y(j0 + 1:j0 + jn%m_n(m))
         end do
         do s = 1, jn%ns
            if (.not. jn%s_on(s)) cycle
            m = jn%s_m(s)
            j0 = jn%m_j0(m)
            nmj = jn%m_n(m)
            u(1:jn%s_ne(s), jn%s_node(s)) = matmul(jn%tk(1:jn%s_ne(s), 1:nmj, s), &
                                                   y(j0 + 1:j0 + nmj))
         end do
      end associate
   end subroutine node_motion

   !> Each line's and master's share of phi^T M phi, by rows (148).
   subroutine energy_shares(prob, x, y, rx, ry, share)
      type(static_problem_t), intent(in) :: prob      !< solved statics
      real(wp), intent(in) :: x(:), y(:)              !< mode
      real(wp), intent(in) :: rx(:), ry(:)            !< M times the mode
      real(wp), intent(out) :: share(:)               !< (nl + nm) shares [-]
      integer :: node, k, l, m, j0
      real(wp) :: total
      share = 0.0_wp
      associate (sup => prob%sup, jn => prob%jn, mesh => prob%mesh)
         do node = 1, mesh%n_nodes
            l = mesh%node_line(node)
            if (l <= 0) cycle
            k = sup%first(node) - 1
            share(l) = share(l) + dot_product(x(k + 1:k + sup%ndof(node)), &
                                              rx(k + 1:k + sup%ndof(node)))
         end do
         do m = 1, jn%nm
            j0 = jn%m_j0(m)
            share(mesh%n_lines + m) = dot_product(y(j0 + 1:j0 + jn%m_n(m)), &
                                                  ry(j0 + 1:j0 + jn%m_n(m)))
         end do
      end associate
      total = sum(share)
      if (total > 0.0_wp) share = share/total
   end subroutine energy_shares
end module rodyn_modal
