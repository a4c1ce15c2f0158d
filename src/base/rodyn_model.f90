!> The analysis model as read from the deck: parameters fixed for the whole run.
!> Everything here has a documented default; the deck reader fills it, the mesh and
!> solvers read it and never change it (data separated by lifetime, as in BeamDyn;
!> docs/architecture.md). The symbols of its components are those of docs/theory.md.
module rodyn_model
   use rodyn_kinds, only: wp, g_standard
   use rodyn_schemes, only: scheme_emc, scheme_midpoint, scheme_trapezoidal, scheme_alpha, &
                            scheme_names, edmc_rho_min, rho_inf_emc_water
   implicit none
   private
   public :: section_t, line_def_t, constraint_t, point_load_t, static_options_t
   public :: output_options_t, model_t, parameter_value_t
   public :: dynamic_options_t, motion_t, amplitude_t, initial_velocity_t
   public :: water_t, seabed_t, attachment_t, rho_water_default
   public :: waves_t, stretch_wheeler, stretch_vertical, stretch_extrapolation, stretch_none
   public :: stretch_names, sea_airy, sea_jonswap, sea_pm, sea_table, sea_record, sea_names
   public :: element_rod, element_cable, element_names
   public :: edmc_rho_min, rho_inf_emc_water
   public :: scheme_emc, scheme_midpoint, scheme_trapezoidal, scheme_alpha, scheme_names
   public :: motion_harmonic, motion_table, motion_vessel
   public :: vessel_t, vessel_rao_t, vessel_from_rao, vessel_from_table
   public :: model_ramp
   public :: rao_interp_complex, rao_interp_polar
   public :: bc_free, bc_pinned, bc_hinged, bc_clamped, bc_position, bc_names
   public :: end_a, end_b, name_len
   public :: point_t, point_fixed, point_free, point_body, point_kind_names
   public :: body_t, body_fixed, body_free, body_kind_names, failure_t, offset_curve_t, modal_t

   integer, parameter :: name_len = 32     !< longest name of a section or line
   real(wp), parameter :: rho_water_default = 1025.0_wp !< sea water density [kg/m3]

   ! Kinds of node constraint (*BOUNDARY, TYPE=...)
   integer, parameter :: bc_free = 0       !< no constraint
   integer, parameter :: bc_pinned = 1     !< ball joint: position held, rotation free
   integer, parameter :: bc_hinged = 2     !< position held, rotation free about one axis only
   integer, parameter :: bc_clamped = 3    !< position and rotation held
   integer, parameter :: bc_position = 4   !< moved to a prescribed position, rotation free
   character(len=8), parameter :: bc_names(0:4) = &
      [character(len=8) :: 'FREE', 'PINNED', 'HINGED', 'CLAMPED', 'POSITION']

   ! Element of a line (*LINE, ELEMENT=...)
   integer, parameter :: element_rod = 1         !< geometrically exact rod (the paper's)
   integer, parameter :: element_cable = 2       !< axial stiffness only, no compression
   character(len=8), parameter :: element_names(2) = [character(len=8) :: 'ROD', 'CABLE']


   ! Kinds of prescribed motion (*MOTION, TYPE=...)
   integer, parameter :: motion_harmonic = 1     !< sum of sines per direction
   integer, parameter :: motion_table = 2        !< displacement time series from a file
   integer, parameter :: motion_vessel = 3       !< a point of a vessel (*VESSEL)

   ! Kinds of vessel motion (*VESSEL, TYPE=...)
   integer, parameter :: vessel_from_rao = 1     !< displacement RAOs in the deck's sea
   integer, parameter :: vessel_from_table = 2   !< 6-DOF time series from a file
   ! Interpolation of an RAO table (*VESSEL, INTERPOLATION=...)
   integer, parameter :: rao_interp_complex = 1  !< real and imaginary parts
   integer, parameter :: rao_interp_polar = 2    !< amplitude, and phase on the shorter arc

   ! Kinds of point (*POINT, TYPE=...)
   integer, parameter :: point_fixed = 1   !< held in place: the line ends on it are pinned
   integer, parameter :: point_free = 2    !< moves with the lines: 3 unknowns of its own
   integer, parameter :: point_body = 3    !< fixed on a body (*BODY), moves with it
   character(len=5), parameter :: point_kind_names(3) = [character(len=5) :: 'FIXED', 'FREE', &
                                                         'BODY']

   ! Kinds of body (*BODY, TYPE=...)
   integer, parameter :: body_fixed = 1    !< held in place: its points are FIXED points
   integer, parameter :: body_free = 2     !< six degrees of freedom of its own
   character(len=5), parameter :: body_kind_names(2) = [character(len=5) :: 'FIXED', 'FREE']

   ! Symbolic node numbers for the two ends of a line (resolved by the mesh)
   integer, parameter :: end_a = 1         !< first node of a line (S = 0)
   integer, parameter :: end_b = -1        !< last node of a line (S = L)

   !> Cross-section properties (*SECTION). Section frame: d3 along the centreline,
   !> d1 and d2 the principal axes; EI1 resists bending about d1.
   type :: section_t
      character(len=name_len) :: name = ''
      real(wp) :: ea = 0.0_wp       !< axial stiffness [N]
      real(wp) :: ga1 = -1.0_wp     !< shear stiffness along d1 [N]; < 0: default EA
      real(wp) :: ga2 = -1.0_wp     !< shear stiffness along d2 [N]; < 0: default EA
      real(wp) :: ei1 = 0.0_wp      !< bending stiffness about d1 [N m2]
      real(wp) :: ei2 = 0.0_wp      !< bending stiffness about d2 [N m2]
      real(wp) :: gj = 0.0_wp       !< torsional stiffness [N m2/rad]
      real(wp) :: mass = 0.0_wp     !< mass per unit length [kg/m]
      real(wp) :: od = 0.0_wp       !< outer diameter [m] (0: not given)
      real(wp) :: rhoi1 = -1.0_wp   !< rotary inertia per length about d1 [kg m]; < 0: default
      real(wp) :: rhoi2 = -1.0_wp   !< rotary inertia per length about d2 [kg m]; < 0: default
      real(wp) :: kappa0(3) = 0.0_wp !< stress-free curvature (K1, K2, K3) [1/m]
      integer :: element = element_rod !< element_rod or element_cable (EI = GJ = 0)
      ! structural (material) damping, dynamics only (docs/theory.md eqs. (116)-(121))
      real(wp) :: axial_damping = 0.0_wp       !< C_a: axial force per axial strain rate [N s]
      real(wp) :: axial_damping_ratio = 0.0_wp !< zeta of a segment's axial mode [-]
      real(wp) :: bending_damping = 0.0_wp     !< C_b: moment per curvature rate [N m2 s]
      ! hydrodynamics and contents (used only when the deck has *WATER); docs/water.md
      real(wp) :: db = -1.0_wp      !< buoyancy (displacement) diameter [m]; < 0: OD
      real(wp) :: dd = -1.0_wp      !< drag diameter [m]; < 0: the buoyancy diameter
      real(wp) :: cdn = 1.2_wp      !< normal drag coefficient, on dd [-]
      real(wp) :: cda = 0.008_wp    !< axial drag coefficient, on pi dd (skin) [-]
      real(wp) :: can = 1.0_wp      !< normal added-mass coefficient, on pi db^2/4 [-]
      real(wp) :: caa = 0.0_wp      !< axial added-mass coefficient, on pi db^2/4 [-]
      real(wp) :: id = 0.0_wp       !< internal (contents) diameter [m]
      real(wp) :: rho_i = 0.0_wp    !< contents density [kg/m3]
      real(wp) :: p_i = 0.0_wp      !< contents gauge pressure at z = z_pi [Pa]
      real(wp) :: z_pi = 0.0_wp     !< reference level of the contents pressure [m]
   end type section_t

   !> One line (*LINE): a rod of given unstretched length between end A and end B.
   type :: line_def_t
      character(len=name_len) :: name = ''
      integer :: section = 0        !< index into model%sections
      real(wp) :: length = 0.0_wp   !< unstretched length [m]
      integer :: n_elements = 0     !< number of elements
      integer :: order = 3          !< Lagrange order of the elements (1, 2 or 3)
      integer :: element = 0        !< element_rod or element_cable; 0: the sections'
      real(wp) :: end_a(3) = 0.0_wp !< position of end A (S = 0) [m]
      real(wp) :: end_b(3) = 0.0_wp !< position of end B (S = L) [m]
      logical :: has_d1_hint = .false.
      real(wp) :: d1_hint(3) = 0.0_wp !< direction d1 should point to (projected) [-]
      ! segments in order from end A (*SEGMENT cards; one segment when the *LINE card
      ! gives SECTION=, LENGTH=, ELEMENTS=): section, length and n_elements above are
      ! then those of the first segment's section and the line's totals
      integer, allocatable :: seg_section(:)    !< (nseg) index into model%sections
      real(wp), allocatable :: seg_length(:)    !< (nseg) unstretched length [m]
      integer, allocatable :: seg_elements(:)   !< (nseg) number of elements
      character(len=:), allocatable :: card_at  !< 'FILE:LINE' of its *LINE card (unset
                                                !< for a line built in code)
      integer :: point_a = 0        !< point end A is attached to (model%points; 0: none)
      integer :: point_b = 0        !< point end B is attached to (0: none)
   end type line_def_t

   !> A point of a mooring system (*POINT): where line ends meet (pinned). A FIXED point
   !> holds them (an anchor, a fairlead on a fixed structure); a FREE point is a body of
   !> its own with three translations (a connector, a clump weight, a subsea buoy): its
   !> weight MASS g less the buoyancy of VOLUME (as an *ATTACHMENT's), the drag
   !> 1/2 rho_w CDA |u| u on the velocity of the water relative to it, and the inertia
   !> MASS + CA rho_w VOLUME (docs/systems.md).
   type :: point_t
      character(len=name_len) :: name = ''
      integer :: kind = point_fixed     !< point_fixed, point_free or point_body
      !> position at the start [m]; a BODY point's: in the body's axes from its reference
      !> point (its global position at the start is then in `global`)
      real(wp) :: position(3) = 0.0_wp
      integer :: body = 0               !< the body of a BODY point (model%bodies)
      real(wp) :: global(3) = 0.0_wp   !< position at the start, global axes [m]
      real(wp) :: mass = 0.0_wp         !< mass [kg]
      real(wp) :: volume = 0.0_wp       !< displaced volume [m3]
      real(wp) :: cda_area = 0.0_wp     !< drag coefficient times area, Cd A [m2]
      real(wp) :: ca = 0.0_wp           !< added-mass coefficient on rho_w volume [-]
      !> a BODY point's rod ends clamped to the body (CONNECTION=CLAMPED): they turn with
      !> it; pinned otherwise
      logical :: clamped = .false.
      !> the direction, in body axes, a clamped end leaves the point along (its second
      !> data line; 0: the end keeps the attitude of its line's starting shape)
      real(wp) :: clamp_axis(3) = 0.0_wp
      !> a FIXED point a host program moves through librodyn (HOST=YES: a coupled point of
      !> MoorDyn's C API); held where it is in a run of the deck itself
      logical :: host = .false.
      character(len=:), allocatable :: card_at !< 'FILE:LINE' of its *POINT card
   end type point_t

   !> An RAO table (rodyn_vessel): 6 complex values per wave period and heading relative
   !> to the vessel or body, H = R exp(-i eps) for a phase lag eps. A vessel's gives its
   !> motion per metre of wave amplitude [m/m, rad/m]; a body's (*BODY WAVE LOAD) the
   !> force and moment at its reference point [N/m, N m/m].
   type :: vessel_rao_t
      real(wp), allocatable :: period(:)      !< (np) increasing wave periods [s]
      real(wp), allocatable :: heading(:)     !< (nh) increasing relative headings [rad], [0, 2 pi)
      complex(wp), allocatable :: h(:, :, :)  !< (6, np, nh) per metre of wave amplitude
      integer :: interp = rao_interp_complex  !< rao_interp_* constant
   end type vessel_rao_t

   !> A rigid body (*BODY): a floating platform, a buoy, a vessel. Six degrees of freedom
   !> (FREE) or held (FIXED); its points (*POINT, TYPE=BODY) carry line ends. Its loads:
   !> the weight MASS g at G, the buoyancy rho_w g VOLUME at B, a linear waterplane
   !> restoring about the reference point R (*BODY HYDROSTATICS), *LOAD, BODY=. Body axes
   !> are the global axes at the start; G, B and the points are given in them, from R
   !> (docs/systems.md; docs/theory.md section 17).
   type :: body_t
      character(len=name_len) :: name = ''
      integer :: kind = body_free         !< body_fixed or body_free
      real(wp) :: mass = 0.0_wp           !< mass [kg]
      real(wp) :: volume = 0.0_wp         !< displaced volume [m3]
      real(wp) :: position(3) = 0.0_wp    !< reference point R at the start, global [m]
      real(wp) :: cog(3) = 0.0_wp         !< centre of gravity G, body axes from R [m]
      real(wp) :: cob(3) = 0.0_wp         !< centre of buoyancy B, body axes from R [m]
      real(wp) :: inertia(3) = 0.0_wp     !< Ixx, Iyy, Izz about G, body axes [kg m2]
      !> linear waterplane restoring about R: force and moment -C (x_R - x_R0, theta) [N/m,
      !> N, N m/m, N m/rad]; the weight and buoyancy are forces of their own (not in C)
      real(wp) :: hydrostatic(6, 6) = 0.0_wp
      !> linear damping about R (*BODY DAMPING): force and moment -B (v_R, omega) [N s/m,
      !> N s, N m s/m, N m s/rad], dynamics only
      real(wp) :: damping(6, 6) = 0.0_wp
      !> added mass (*BODY ADDED MASS): A11, A22, A33 at G [kg] and A44, A55, A66 about G
      !> [kg m2], body axes
      real(wp) :: added_mass(6) = 0.0_wp
      !> quadratic drag (*BODY DRAG), dynamics only: CdA_1..3 [m2], the force -1/2 rho_w
      !> CdA_i |u_i| u_i along body axis i at R (u the velocity of R in body axes, still
      !> water), and C_r1..3 [N m s2], the moment -C_ri |w_i| w_i (w the angular velocity)
      real(wp) :: drag(6) = 0.0_wp
      character(len=:), allocatable :: card_at !< 'FILE:LINE' of its *BODY card
      !> a FIXED body a host program moves through librodyn (HOST=YES: a coupled body of
      !> MoorDyn's C API); held where it is in a run of the deck itself
      logical :: host = .false.
      !> first-order wave load (*BODY WAVE LOAD), dynamics only: force and moment at R
      !> per metre of wave amplitude, by wave period and heading relative to the body's x
      !> axis (period unallocated: none)
      type(vessel_rao_t) :: wave_load
      character(len=:), allocatable :: wave_load_at !< 'FILE:LINE' of its *BODY WAVE LOAD

      !> added mass about R in body axes (*BODY ADDED MASS, FORM=MATRIX), rows and columns
      !> x, y, z, rx, ry, rz [kg, kg m, kg m2]; symmetric, positive semi-definite
      real(wp) :: added_matrix(6, 6) = 0.0_wp
   end type body_t

   !> The offset-restoring-force curve of a body (*OFFSET CURVE): after the statics, a
   !> horizontal force at R towards `heading` raised to `force` in `steps` equal steps,
   !> each a static solution.
   type :: offset_curve_t
      integer :: body = 0               !< model%bodies index (0: none)
      real(wp) :: heading = 0.0_wp      !< direction of the force, from +x to +y [rad]
      real(wp) :: force = 0.0_wp        !< largest force [N]
      integer :: steps = 10             !< steps to it
   end type offset_curve_t

   !> *MODAL's eigensolver: by the size of the system, LAPACK's dense dsygv, ARPACK's
   !> shift-invert Lanczos
   integer, parameter, public :: modal_auto = 0, modal_dense = 1, modal_lanczos = 2
   character(len=*), parameter, public :: modal_solver_names(0:2) = &
      [character(len=7) :: 'AUTO', 'DENSE', 'LANCZOS']

   !> The modal analysis of the system about its static equilibrium (*MODAL): the
   !> `modes` longest natural periods and their shapes (docs/theory.md eqs. (145)-(148)).
   type :: modal_t
      logical :: requested = .false.    !< *MODAL given
      integer :: modes = 10             !< modes wanted (fewer if the system has fewer)
      integer :: solver = modal_auto    !< modal_auto, modal_dense or modal_lanczos
   end type modal_t

   !> A line end that fails (*FAILURE): released from its support, point or body at a
   !> time or when its force first reaches a break load, whichever comes first.
   type :: failure_t
      integer :: line = 0               !< index into model%lines
      integer :: end = 1                !< 1: end A, 2: end B
      real(wp) :: time = -1.0_wp        !< release time [s] (< 0: none)
      real(wp) :: break_load = -1.0_wp  !< force that releases it [N] (<= 0: none)
   end type failure_t

   !> A point attachment on a line (*ATTACHMENT): a clump weight or a buoy at an
   !> unstretched arc length S from end A, applied at the node nearest to S (the mesh
   !> reports the distance). Force: (mass g - rho_w g volume submerged) plus Morison drag
   !> 1/2 rho_w cda_area |u| u on the relative velocity; inertia mass + ca rho_w volume.
   type :: attachment_t
      integer :: line = 0           !< index into model%lines (0: on a point)
      integer :: point = 0          !< a FREE point's own load (model%points; 0: on a line)
      real(wp) :: s = 0.0_wp        !< arc length from end A [m]
      real(wp) :: mass = 0.0_wp     !< mass [kg]
      real(wp) :: volume = 0.0_wp   !< displaced volume [m3]
      real(wp) :: cda_area = 0.0_wp !< drag coefficient times area, Cd A [m2]
      real(wp) :: ca = 0.0_wp       !< added-mass coefficient on rho_w volume [-]
   end type attachment_t

   !> The sea (*WATER, *CURRENT): still water level, depth, density and a steady current
   !> profile (speed and heading at levels z, linear between, constant beyond).
   type :: water_t
      logical :: present = .false.     !< the deck has *WATER (else a dry scene)
      real(wp) :: surface = 0.0_wp     !< z of the still water level [m]
      real(wp) :: depth = 0.0_wp       !< water depth at x = y = 0 [m] (seabed below)
      real(wp) :: density = rho_water_default !< [kg/m3]
      real(wp), allocatable :: cur_z(:)       !< (nc) levels, increasing [m]
      real(wp), allocatable :: cur_speed(:)   !< (nc) current speed [m/s]
      real(wp), allocatable :: cur_heading(:) !< (nc) direction it flows towards,
                                              !< from +x towards +y [rad] (deg in the deck)
      real(wp) :: cur_ramp = 0.0_wp    !< ramp-in duration of the current in dynamics [s]
   end type water_t

   !> The seabed (*SEABED): a plane through (0, 0, surface - depth) rising at angle
   !> slope towards the horizontal direction slope_dir. Contact per unit length of line:
   !> normal force (k pen + c pen_rate) D, D the buoyancy diameter (MoorDyn's kbot/cbot
   !> convention); Coulomb friction mu N with separate axial and lateral coefficients,
   !> regularised linearly below the mobilisation velocity v_mob (dynamics only).
   type :: seabed_t
      logical :: present = .false.     !< a seabed under the water
      real(wp) :: slope = 0.0_wp       !< angle [rad] (deg in the deck)
      real(wp) :: slope_dir = 0.0_wp   !< heading of steepest ascent [rad] (deg in the deck)
      real(wp) :: stiffness = 3.0e6_wp !< normal stiffness per contact area [N/m3 = Pa/m]
      real(wp) :: damping = 3.0e5_wp   !< normal damping per contact area [Pa s/m]
      real(wp) :: mu_axial = 0.0_wp    !< axial friction coefficient [-]
      real(wp) :: mu_lateral = 0.0_wp  !< lateral friction coefficient [-]
      real(wp) :: v_mob = 0.01_wp      !< friction mobilisation velocity [m/s]
   end type seabed_t

   ! Kinematics above the mean surface (*WAVE, STRETCHING=); docs/waves.md
   integer, parameter :: stretch_wheeler = 1       !< Wheeler: z mapped onto [-d, 0]
   integer, parameter :: stretch_vertical = 2      !< the values at z = 0 carried up
   integer, parameter :: stretch_extrapolation = 3 !< linear extrapolation from z = 0
   integer, parameter :: stretch_none = 4          !< linear theory's profile carried up
   character(len=13), parameter :: stretch_names(4) = [character(len=13) :: 'WHEELER', &
                                                       'VERTICAL', 'EXTRAPOLATION', 'NONE']

   ! Kinds of sea (*WAVE, TYPE=); docs/waves.md
   integer, parameter :: sea_airy = 1      !< one regular wave
   integer, parameter :: sea_jonswap = 2   !< JONSWAP spectrum (Hs, Tp, gamma)
   integer, parameter :: sea_pm = 3        !< Pierson-Moskowitz spectrum (Hs, Tp)
   integer, parameter :: sea_table = 4     !< a spectrum given as a table
   integer, parameter :: sea_record = 5    !< an elevation record, decomposed (FFT)
   character(len=8), parameter :: sea_names(5) = [character(len=8) :: 'AIRY', 'JONSWAP', &
                                                  'PM', 'SPECTRUM', 'RECORD']

   !> The sea state (*WAVE): a sum of Airy components, the elevation above the still
   !> water level eta = sum_i (H_i/2) cos(k_i (x cos beta_i + y sin beta_i) - omega_i t
   !> + phi_i), k_i from the finite-depth dispersion relation at the water depth; all
   !> multiplied by the ramp-in (1 - cos(pi t/T))/2 in dynamics, absent in statics. An
   !> irregular sea is the spectrum's components drawn from the seed (rodyn_waves,
   !> sea_components) into height, period and phase when the deck is read.
   type :: waves_t
      logical :: present = .false.       !< the deck has *WAVE
      integer :: kind = sea_airy         !< sea_* constant
      real(wp) :: hs = 0.0_wp            !< significant wave height [m] (spectra)
      real(wp) :: tp = 0.0_wp            !< peak period [s] (JONSWAP, PM)
      real(wp) :: gamma = 0.0_wp         !< JONSWAP peak enhancement [-]
      integer :: components = 200        !< number of components (spectra)
      integer :: seed = 1                !< seed of the frequencies and phases
      real(wp) :: omega_min = 0.0_wp     !< lowest frequency of the components [rad/s]
      real(wp) :: omega_max = 0.0_wp     !< highest [rad/s]
      real(wp) :: spreading = 0.0_wp     !< cos-2s exponent s [-]; 0: long-crested
      integer :: directions = 1          !< directions per frequency bin (spreading)
      real(wp) :: point(2) = 0.0_wp      !< x, y where the phases are given (RECORD) [m]
      real(wp) :: mean = 0.0_wp          !< the record's mean elevation, removed [m]
      real(wp), allocatable :: tab_omega(:) !< (nt) SPECTRUM table: frequencies [rad/s]
      real(wp), allocatable :: tab_s(:)     !< (nt) spectral density [m2 s/rad]
      integer :: stretching = stretch_wheeler !< stretch_* constant
      real(wp) :: ramp = 0.0_wp          !< ramp-in duration [s]; 0: none
      real(wp), allocatable :: height(:)  !< (nw) wave height H = 2 x amplitude [m]
      real(wp), allocatable :: period(:)  !< (nw) period [s]
      real(wp), allocatable :: heading(:) !< (nw) direction of travel, from +x towards +y
                                          !< [rad] (deg in the deck)
      real(wp), allocatable :: phase(:)   !< (nw) phase phi [rad] (deg in the deck)
      !> wave probes (*WAVE PROBE): points whose elevation is written with the frames
      !> and every step (docs/output.md, dynamic_waves.csv)
      character(len=name_len), allocatable :: probe_name(:) !< (np) names
      real(wp), allocatable :: probe_xy(:, :)  !< (2, np) x, y of each probe, global [m]
   end type waves_t

   !> A node constraint (*BOUNDARY).
   type :: constraint_t
      integer :: line = 0           !< index into model%lines
      integer :: node = end_a       !< node number along the line, or end_a / end_b
      integer :: kind = bc_free     !< bc_* constant
      real(wp) :: axis(3) = 0.0_wp  !< hinge axis (bc_hinged), unit vector [-]
      real(wp) :: position(3) = 0.0_wp !< prescribed position (bc_position) [m]
   end type constraint_t

   !> A point force and moment at a node (*LOAD), fixed in space.
   type :: point_load_t
      integer :: line = 0           !< index into model%lines (0: on a point)
      integer :: point = 0          !< index into model%points of a FREE point (0: on a line)
      integer :: body = 0           !< index into model%bodies: force and moment at its R
      integer :: node = end_a       !< node number along the line, or end_a / end_b
      real(wp) :: force(3) = 0.0_wp !< force [N]
      real(wp) :: moment(3) = 0.0_wp !< moment [N m]
      integer :: amplitude = 0      !< index into model%amplitudes (0: constant in time)
      character(len=:), allocatable :: card_at !< 'FILE:LINE' of its *LOAD card (unset for
                                               !< a load set in code)
   end type point_load_t

   !> Static analysis controls (*STATIC).
   type :: static_options_t
      logical :: requested = .false. !< a *STATIC card was given
      integer :: increments = 1      !< initial number of load increments
      integer :: max_cutbacks = 10   !< how many times an increment may be halved
      integer :: max_iterations = 30 !< Newton iterations per increment
      real(wp) :: force_tol = 1.0e-8_wp  !< residual / reference force [-]
      real(wp) :: disp_tol = 1.0e-8_wp   !< correction / reference length (and rad) [-]
      logical :: line_search = .false.   !< energy line search (Crisfield) along each step
   end type static_options_t

   !> A piecewise-linear function of time (*AMPLITUDE): value(t) interpolated in
   !> (time, value), constant beyond the ends.
   type :: amplitude_t
      character(len=name_len) :: name = ''
      real(wp), allocatable :: time(:)   !< (n) increasing times [s]
      real(wp), allocatable :: value(:)  !< (n) values [-]
   end type amplitude_t

   !> A vessel (*VESSEL): its reference point at rest, heading, and motion xi = (surge,
   !> sway, heave, roll, pitch, yaw) of the reference point in vessel axes (rodyn_vessel).
   type :: vessel_t
      character(len=name_len) :: name = ''
      real(wp) :: origin(3) = 0.0_wp          !< reference point at rest, global [m]
      real(wp) :: heading = 0.0_wp            !< heading at rest, about global z [rad]
      integer :: kind = vessel_from_table     !< vessel_from_* constant
      type(vessel_rao_t) :: rao               !< RAO table (vessel_from_rao)
      character(len=:), allocatable :: file   !< the file a table was read from
      real(wp), allocatable :: time(:)        !< (n) times of a motion table [s]
      real(wp), allocatable :: motion(:, :)   !< (6, n) xi at those times [m, rad]
      !> the sea's components as the vessel's motion needs them (rodyn_vessel's
      !> vessel_coefficients), set up before the dynamic analysis
      complex(wp), allocatable :: coef(:, :)  !< (6, nc) complex response factors
      real(wp), allocatable :: omega(:)       !< (nc) angular frequencies [rad/s]
      real(wp) :: sea_ramp = 0.0_wp           !< ramp-in of the sea [s] (0: none)
      !> slow motion of the reference point, global: a static offset and a drift,
      !> harmonic or from a table (rodyn_motion's vessel_slow_motion)
      real(wp) :: offset(4) = 0.0_wp          !< x, y, z [m], heading [rad]
      real(wp) :: drift(4) = 0.0_wp           !< amplitudes x, y [m], 0, yaw [rad]
      real(wp) :: drift_period = 0.0_wp       !< [s]; 0: no drift
      real(wp) :: drift_phase = 0.0_wp        !< [rad]
      real(wp), allocatable :: drift_time(:)  !< (nd) times of a drift table [s]
      real(wp), allocatable :: drift_table(:, :) !< (4, nd) x, y, z [m], heading [rad]
      !> OFFSET START=STATIC (default): the static analysis puts the vessel at its offset
      !> and a dynamics started from it does not ramp the offset in; DYNAMIC: statics at
      !> rest at O, the offset ramped in with the dynamics (rodyn_motion's
      !> vessel_offset_rest)
      logical :: offset_static = .true.
   end type vessel_t

   !> Prescribed motion of a held node (*MOTION): a displacement added to the position
   !> the node has at the start of the dynamic analysis, multiplied by the ramp
   !> r(t) = (1 - cos(pi t / ramp))/2 for t < ramp, 1 after (ramp = 0: no ramp).
   type :: motion_t
      integer :: line = 0                 !< index into model%lines (0: a body's motion)
      integer :: body = 0                 !< a FIXED body moved (model%bodies; 0: a line's)
      integer :: point = 0                !< a FIXED point moved: its line ends (model%points)
      integer :: node = end_a             !< node number along the line, or end_a / end_b
      integer :: kind = motion_harmonic   !< motion_* constant
      real(wp) :: ramp = 3.0_wp           !< ramp-in duration [s]
      ! harmonic: u_j(t) = amplitude_j sin(2 pi frequency_j t + phase_j), j = x, y, z
      real(wp) :: amplitude(3) = 0.0_wp   !< [m]
      real(wp) :: frequency(3) = 0.0_wp   !< [Hz]
      real(wp) :: phase(3) = 0.0_wp       !< [rad] (given in degrees in the deck)
      ! table: displacement (ux, uy, uz) at times t, linear interpolation
      character(len=:), allocatable :: file !< the file the table was read from
      real(wp), allocatable :: time(:)      !< (n) [s]
      real(wp), allocatable :: disp(:, :)   !< (3, n) [m]
      ! vessel: the node is fixed to vessel model%vessels(vessel) at the point where it
      ! is at the start of the dynamic analysis (the vessel at rest)
      integer :: vessel = 0                 !< index into model%vessels
   end type motion_t

   !> Initial velocity of a whole line as a rigid body (*INITIAL VELOCITY): each node
   !> gets v + omega x (x - centre), each director omega x d.
   type :: initial_velocity_t
      integer :: line = 0                 !< index into model%lines (0: a body's)
      integer :: body = 0                 !< a FREE body thrown (model%bodies; 0: a line)
      real(wp) :: velocity(3) = 0.0_wp    !< translational velocity [m/s]
      real(wp) :: omega(3) = 0.0_wp       !< angular velocity [rad/s]
      logical :: has_centre = .false.     !< centre given (else the mean of the nodes)
      real(wp) :: centre(3) = 0.0_wp      !< centre of the rotation [m]
   end type initial_velocity_t

   !> Dynamic analysis controls (*DYNAMIC, *DAMPING).
   type :: dynamic_options_t
      logical :: requested = .false.      !< a *DYNAMIC card was given
      integer :: scheme = scheme_emc      !< scheme_* constant
      !> spectral radius at infinite frequency (ALPHA; EMC below 1: the dissipative EMC) [-]
      real(wp) :: rho_inf = 1.0_wp
      logical :: rho_inf_given = .false.  !< RHO INF was on the card (else the default)
      real(wp) :: dt = 0.0_wp             !< time step [s]
      real(wp) :: duration = 0.0_wp       !< simulated time [s]
      real(wp) :: output_interval = 0.0_wp !< time between outputs [s]; 0: every step
      real(wp) :: checkpoint = 0.0_wp     !< simulated time between checkpoints [s]; 0: none
      logical :: start_static = .true.    !< start from the static solution (else as defined)
      integer :: max_iterations = 20      !< Newton iterations per step
      integer :: max_cutbacks = 6         !< halvings of a step
      real(wp) :: force_tol = 1.0e-8_wp   !< residual / reference force [-]
      real(wp) :: disp_tol = 1.0e-8_wp    !< correction / reference length [-]
      logical :: reuse_tangent = .true.   !< TANGENT=REUSE: modified Newton (rodyn_newton)
      real(wp) :: rayleigh_alpha = 0.0_wp !< mass-proportional damping [1/s]
      real(wp) :: rayleigh_beta = 0.0_wp  !< stiffness-proportional damping [s]
      character(len=:), allocatable :: damping_at !< 'FILE:LINE' of *DAMPING (unset: none)
   end type dynamic_options_t

   !> A deck parameter as used (*PARAMETER, after any --set), echoed into the output.
   type :: parameter_value_t
      character(len=:), allocatable :: name  !< upper case
      character(len=:), allocatable :: text  !< text substituted for <NAME>
      logical :: is_number = .false.         !< a number (else a string)
      real(wp) :: value = 0.0_wp             !< the number (0 for a string)
   end type parameter_value_t

   !> What to write (*OUTPUT).
   type :: output_options_t
      logical :: csv = .true.        !< CSV tables
      logical :: hdf5 = .true.       !< the HDF5 file
   end type output_options_t

   !> The whole model.
   type :: model_t
      character(len=:), allocatable :: title      !< *HEADING text
      character(len=:), allocatable :: deck_file  !< path of the main deck
      character(len=:), allocatable :: deck_text  !< full text read, includes expanded
      real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -g_standard] !< [m/s2]
      type(section_t), allocatable :: sections(:)
      type(line_def_t), allocatable :: lines(:)
      type(constraint_t), allocatable :: constraints(:)
      type(point_load_t), allocatable :: loads(:)
      type(amplitude_t), allocatable :: amplitudes(:)
      type(motion_t), allocatable :: motions(:)
      type(vessel_t), allocatable :: vessels(:)
      type(initial_velocity_t), allocatable :: initial_velocities(:)
      type(attachment_t), allocatable :: attachments(:)
      type(point_t), allocatable :: points(:)        !< *POINT, in deck order
      type(body_t), allocatable :: bodies(:)         !< *BODY, in deck order
      type(failure_t), allocatable :: failures(:)    !< *FAILURE, in deck order
      type(offset_curve_t) :: offset_curve           !< *OFFSET CURVE (body 0: none)
      type(modal_t) :: modal                         !< *MODAL
      type(water_t) :: water
      type(seabed_t) :: seabed
      type(waves_t) :: waves
      type(static_options_t) :: static
      type(dynamic_options_t) :: dynamic
      type(output_options_t) :: output
      type(parameter_value_t), allocatable :: parameters(:) !< *PARAMETER values, in order
   end type model_t

contains

   !> The longest ramp-in of what drives the dynamics [s]: harmonic and table *MOTIONs,
   !> the waves and the current (0 when nothing ramps). Results before its end hold the
   !> start-up, not the steady response (the default window of range graphs starts here).
   pure function model_ramp(model) result(ramp)
      type(model_t), intent(in) :: model  !< the model
      real(wp) :: ramp                    !< [s]
      integer :: i
      ramp = 0.0_wp
      if (allocated(model%motions)) then
         do i = 1, size(model%motions)
            ramp = max(ramp, model%motions(i)%ramp)
         end do
      end if
      if (model%waves%present) ramp = max(ramp, model%waves%ramp)
      if (model%water%present) ramp = max(ramp, model%water%cur_ramp)
   end function model_ramp
end module rodyn_model
