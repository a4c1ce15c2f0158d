!> Results handed from the solvers to the output writers: plain arrays per line,
!> in SI units, with nothing the writers have to recompute (resultants, effective and
!> wall tension: docs/theory.md eqs. (30)-(31), (77)-(79)).
module rodyn_results
   use rodyn_kinds, only: wp
   use rodyn_model, only: name_len
   implicit none
   private
   public :: line_result_t, run_summary_t, step_log_t, system_result_t

   !> Static results of one line.
   type :: line_result_t
      character(len=name_len) :: name = ''
      ! nodes
      real(wp), allocatable :: node_s(:)       !< (nn) unstretched arc length [m]
      real(wp), allocatable :: node_x(:, :)    !< (3, nn) position x, y, z [m]
      ! integration points of the stiffness (p per element, ordered along the line)
      integer, allocatable :: gp_element(:)    !< (ng) element number along the line
      integer, allocatable :: gp_point(:)      !< (ng) point number within the element
      real(wp), allocatable :: gp_s(:)         !< (ng) unstretched arc length [m]
      real(wp), allocatable :: tension(:)      !< (ng) effective tension N3 [N]
      real(wp), allocatable :: wall_tension(:) !< (ng) wall (true) tension
                                               !< T_eff + p_o A_o - p_i A_i [N] (docs/water.md)
      real(wp), allocatable :: shear(:, :)     !< (2, ng) shear forces N1, N2 [N]
      real(wp), allocatable :: moment(:, :)    !< (2, ng) bending moments M1, M2 [N m]
      real(wp), allocatable :: torque(:)       !< (ng) torsional moment M3 [N m]
      real(wp), allocatable :: curvature(:, :) !< (3, ng) K1, K2 bending, K3 twist [1/m]
      ! seabed contact at the nodes (0 without a seabed)
      real(wp), allocatable :: seabed_normal(:)   !< (nn) normal force per length [N/m]
      real(wp), allocatable :: seabed_friction(:) !< (nn) friction force per length [N/m]
      real(wp) :: touchdown_s = -1.0_wp        !< largest arc length in contact [m]; < 0: none
      ! ends: force and moment the support exerts on the line, global axes
      real(wp) :: reaction(6, 2) = 0.0_wp      !< (Fx,Fy,Fz,Mx,My,Mz) at end A, end B [N, N m]
      logical :: end_held(2) = .false.         !< end A / end B carries a support
   end type line_result_t

   !> Static results of a mooring system beyond its lines (docs/systems.md): its bodies
   !> and its stiffness at its FREE points and bodies.
   type :: system_result_t
      !> the masters, in the order of the unknowns: each FREE point (3 unknowns), then each
      !> body (6): kind 1 a point, 2 a body, and its model%points / model%bodies index
      integer, allocatable :: kind(:)
      integer, allocatable :: index(:)
      !> (n, n) K = -dF/dq, F the force (and moment about each body's reference point R)
      !> on the masters, q their positions (and R's position and the rotation vector), every
      !> other unknown in equilibrium [N/m, N/rad, N m/m, N m/rad]: of everything
      real(wp), allocatable :: stiffness(:, :)
      !> (n, n) the same of the lines alone (the mooring stiffness: no body's own load)
      real(wp), allocatable :: lines_stiffness(:, :)
      ! per body (model%bodies order)
      real(wp), allocatable :: body_x(:, :)      !< (3, nb) position of R [m]
      real(wp), allocatable :: body_rot(:, :)    !< (3, nb) rotation vector from the start [rad]
      real(wp), allocatable :: body_force(:, :)  !< (6, nb) force and moment about R of its
                                                 !< lines [N, N m]
      !> (6, nb) each FREE body's natural periods as a rigid body on its moorings (its
      !> stiffness of everything at R, the lines quasi-static; its mass, inertia and added
      !> mass), ascending [s]; 0 where the stiffness is not positive (no oscillation)
      real(wp), allocatable :: body_periods(:, :)
      real(wp), allocatable :: body_modes(:, :, :) !< (6, 6, nb) the modes (columns), largest
                                                   !< entry 1 (x, y, z [m], rx, ry, rz [rad])
      !> (9, 0:steps) the offset curve (*OFFSET CURVE): force [N], offset of R along the
      !> force from the equilibrium [m], R's x, y, z [m], rotation vector [rad], the
      !> largest force on a line end on the body [N]; unallocated: none
      real(wp), allocatable :: curve(:, :)
      ! the modal analysis (*MODAL; docs/theory.md eqs. (145)-(148)); unallocated: none
      real(wp), allocatable :: modal_period(:)       !< (nm) natural periods, longest first [s]
      !> (6, nn, nm) each mode's motion of every node (translation [m], rotation [rad];
      !> a body's node is its G), the largest translation 1 m
      real(wp), allocatable :: modal_shape(:, :, :)
      !> (6, nmaster, nm) the motion of each master (kind, index above): a point's
      !> translation, a body's at its R and its rotation
      real(wp), allocatable :: modal_master(:, :, :)
      !> (no, nm) each object's share of the mode's kinetic energy, objects the lines (deck
      !> order) then the masters (kind, index above)
      real(wp), allocatable :: modal_share(:, :)
      real(wp) :: modal_asymmetry = 0.0_wp !< |K - K^T| / |K| of the tangent, estimated [-]
      character(len=7) :: modal_solver = ''  !< the eigensolver used: DENSE or LANCZOS
   end type system_result_t

   !> One time step of a dynamic run: solver effort and the balance of energy and
   !> momentum (docs/theory.md eqs. (41)-(43): what the EMC scheme conserves).
   type :: step_log_t
      integer :: step = 0                       !< step number (1, 2, ...)
      real(wp) :: time = 0.0_wp                 !< time at the end of the step [s]
      real(wp) :: dt = 0.0_wp                   !< step length used [s]
      integer :: iterations = 0                 !< Newton iterations of the step
      integer :: tangents = 0                   !< tangents formed in the step (summary only)
      integer :: cutbacks = 0                   !< halvings needed by the step
      real(wp) :: kinetic = 0.0_wp              !< kinetic energy [J]
      real(wp) :: strain = 0.0_wp               !< stored (strain) energy [J]
      real(wp) :: strain_scale = 0.0_wp         !< its round-off scale (energy identity
                                                !< check only; not written) [J]
      real(wp) :: gravity = 0.0_wp              !< potential of the weight, -sum f_g . x [J]
      real(wp) :: external_work = 0.0_wp        !< work done on the line since t = 0 by
                                                !< prescribed motions and loads [J]
      real(wp) :: damping_work = 0.0_wp         !< energy taken out by damping since t = 0 [J]
      real(wp) :: hydro_work = 0.0_wp           !< work done on the line since t = 0 by the
                                                !< water: buoyancy, drag, added mass [J]
      real(wp) :: seabed_work = 0.0_wp          !< work done on the line since t = 0 by the
                                                !< seabed: contact, damping, friction [J]
      !> the dissipative EMC (RHO INF < 1): work of its numerical stress since t = 0 and
      !> its numerical energy N at the end of the step (docs/theory.md eq. (128)) [J]
      real(wp) :: numerical_work = 0.0_wp
      real(wp) :: numerical_energy = 0.0_wp
      real(wp) :: total = 0.0_wp                !< kinetic + strain + gravity [J]
      real(wp) :: momentum(3) = 0.0_wp          !< total linear momentum [kg m/s]
      real(wp) :: angular_momentum(3) = 0.0_wp  !< about the origin [kg m2/s]
   end type step_log_t

   !> How the run went: written with the results so a reader knows how far it got.
   type :: run_summary_t
      logical :: complete = .false.            !< the analysis reached its end
      character(len=:), allocatable :: status  !< one line: 'complete' or what failed
      real(wp) :: load_factor = 0.0_wp         !< static load factor reached [-]
      integer :: increments = 0                !< load increments converged
      integer :: iterations = 0                !< Newton iterations in total
      integer :: cutbacks = 0                  !< increment halvings
      real(wp) :: wall_time = 0.0_wp           !< solve wall time [s]
      ! dynamic analysis
      logical :: dynamic = .false.             !< a dynamic analysis was run
      real(wp) :: time_reached = 0.0_wp        !< last time reached [s]
      integer :: steps = 0                     !< time steps completed
      integer :: frames = 0                    !< output frames the files hold
      integer :: step_cutbacks = 0             !< step halvings in total
      integer :: step_iterations = 0           !< Newton iterations over all steps
      integer :: step_tangents = 0             !< tangents formed and factorised, all steps
   end type run_summary_t
end module rodyn_results
