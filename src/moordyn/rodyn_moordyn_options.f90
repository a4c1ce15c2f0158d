!> The OPTIONS of a MoorDyn v2 file (docs/moordyn.md, "Options"): rows `value name
!> [comment]`, names in any case (MoorDyn2.cpp, readOptionsLine). The environment's
!> options become rodyn's *GRAVITY, *WATER and *SEABED with MoorDyn's defaults (g
!> 9.80665 m/s2, 1025 kg/m3, kBot 3e6 Pa/m, cBot 3e5 Pa s/m); the options of an explicit
!> time integrator and of its initial-condition generator have no meaning for rodyn's
!> implicit steps and Newton statics and are noted as ignored, with why; the options of
!> what rodyn does not read (external wave and current kinematics, a seabed from a file)
!> and names MoorDyn v2 does not know are refused.
module rodyn_moordyn_options
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_deck_numbers, only: real_str
   use rodyn_deck_params, only: upper_case
   use rodyn_deck_text, only: field_t
   use rodyn_moordyn_file, only: md_file_t, md_row_t, md_options
   use rodyn_moordyn_out, only: md_deck_t, note, md_real, md_fail
   implicit none
   private
   public :: md_env_t, read_options

   !> The environment the options set, and the lines that set it (0: the default).
   type :: md_env_t
      real(wp) :: g = 9.80665_wp       !< gravity [m/s2] (MoorDyn's default)
      real(wp) :: rho = 1025.0_wp      !< water density [kg/m3]
      real(wp) :: depth = 0.0_wp       !< water depth [m] (raised to the deepest point)
      real(wp) :: kbot = 3.0e6_wp      !< seabed stiffness [Pa/m]
      real(wp) :: cbot = 3.0e5_wp      !< seabed damping [Pa s/m]
      real(wp) :: mu = 0.0_wp          !< seabed friction coefficient
      integer :: g_line = 0, depth_line = 0, kbot_line = 0
      integer :: wave_kin_line = 0     !< line of WaveKin 1 (external kinematics)
      character(len=:), allocatable :: friction !< ', FRICTION=mu' or ''
      logical :: write_units = .true.  !< a units row in the .out file (WriteUnits > 0)
      !> the options ignored, by reason (time step, initial condition, output files),
      !> and the line of the first of each
      type(field_t) :: ignored(3)
      integer :: ignored_line(3) = 0
   end type md_env_t

   !> Why each group of options is ignored.
   character(len=*), parameter :: why(3) = [character(len=110) :: &
      'the time step of an explicit integrator; rodyn''s implicit step is the host''s '// &
      'coupling step or *DYNAMIC, DT=', &
      'rodyn''s initial condition is the static equilibrium, solved by Newton', &
      '`rodyn FILE` writes rodyn''s own tables (docs/output.md)']

   !> Options that are noted as ignored: an explicit integrator's and its initial
   !> condition's, and the outputs of MoorDyn's own files.
   character(len=*), parameter :: step_options(5) = [character(len=8) :: 'DTM', 'DT', &
      'CFL', 'TSCHEME', 'DTWAVE']
   character(len=*), parameter :: ic_options(12) = [character(len=12) :: 'DTIC', 'ICDT', &
      'TMAXIC', 'ICTMAX', 'CDSCALEIC', 'ICDFAC', 'THRESHIC', 'ICTHRESH', 'ICGENDYNAMIC', &
      'GENDYNAMICIC', 'FILEIC', 'ICFILE']
   character(len=*), parameter :: out_options(4) = [character(len=14) :: &
      'DTOUT', 'DISABLEOUTPUT', 'DISABLEOUTTIME', 'WRITELOG']

contains

   !> Read the OPTIONS rows into env; note the ignored ones; refuse the others.
   subroutine read_options(md, d, env, err)
      type(md_file_t), intent(in) :: md     !< the MoorDyn file
      type(md_deck_t), intent(inout) :: d   !< the deck (its notes)
      type(md_env_t), intent(out) :: env    !< the environment
      type(error_t), intent(inout) :: err   !< status
      integer :: k
      env%friction = ''
      do k = 1, 3
         env%ignored(k)%s = ''
      end do
      do k = 1, md%sec(md_options)%n
         call read_option(md%sec(md_options)%rows(k), d, env, err)
         if (has_error(err)) return
      end do
      do k = 1, 3
         if (env%ignored_line(k) > 0) call note(d, env%ignored_line(k), 'OPTIONS '// &
            env%ignored(k)%s//' ignored: '//trim(why(k)))
      end do
      if (env%mu > 0.0_wp) env%friction = ', FRICTION='//real_str(env%mu)
   end subroutine read_options

   !> One OPTIONS row.
   subroutine read_option(row, d, env, err)
      type(md_row_t), intent(in) :: row     !< value name [comment]
      type(md_deck_t), intent(inout) :: d   !< the deck (its notes)
      type(md_env_t), intent(inout) :: env  !< the environment
      type(error_t), intent(inout) :: err   !< status
      character(len=:), allocatable :: name
      real(wp) :: x
      if (size(row%f) < 2) then
         call md_fail(d, md_options, row, 'a row is `value name`: the name is missing', err)
         return
      end if
      name = upper_case(row%f(2)%s)
      select case (name)
      case ('G', 'GRAVITY')
         call md_real(d, md_options, row, 1, row%f(2)%s, env%g, err)
         if (env%g < 0.0_wp) call md_fail(d, md_options, row, row%f(2)%s//': '// &
                                          'a gravity below 0', err)
         env%g_line = row%line
      case ('RHO', 'WTRDNSTY')
         call md_real(d, md_options, row, 1, row%f(2)%s, env%rho, err)
         if (env%rho < 0.0_wp) call md_fail(d, md_options, row, row%f(2)%s//': '// &
                                            'a density below 0', err)
         if (env%rho == 0.0_wp .and. .not. has_error(err)) call note(d, row%line, &
            row%f(2)%s//' 0: a model in vacuum, without water or seabed (no *WATER)')
         if (env%depth_line == 0) env%depth_line = row%line
      case ('WTRDPTH')
         call positive(env%depth)
         env%depth_line = row%line
      case ('KBOT', 'KB')
         call positive(env%kbot)
         env%kbot_line = row%line
      case ('CBOT', 'CB')
         call md_real(d, md_options, row, 1, row%f(2)%s, env%cbot, err)
         if (env%cbot < 0.0_wp) call md_fail(d, md_options, row, row%f(2)%s//': '// &
                                             'a damping below 0', err)
      case ('FRICTIONCOEFFICIENT')
         call md_real(d, md_options, row, 1, row%f(2)%s, env%mu, err)
         if (env%mu < 0.0_wp) call md_fail(d, md_options, row, row%f(2)%s//': '// &
                                           'a friction coefficient below 0', err)
      case ('FRICDAMP', 'STATDYNFRICSCALE')
         call md_real(d, md_options, row, 1, row%f(2)%s, x, err)
         call note(d, row%line, 'option '//row%f(2)%s//' ignored: rodyn''s seabed '// &
                   'friction rises linearly to mu N over its mobilisation velocity (0.01 '// &
                   'm/s) and has one coefficient (docs/moordyn.md, "Seabed")')
      case ('WAVEKIN', 'CURRENTS')
         call md_real(d, md_options, row, 1, row%f(2)%s, x, err)
         if (x == 1.0_wp .and. name == 'WAVEKIN') then
            d%info%external_waves = .true.
            env%wave_kin_line = row%line
            call note(d, row%line, row%f(2)%s//' 1: the water''s velocity and '// &
               'acceleration at the nodes come from the host in the dynamics '// &
               '(MoorDyn_ExternalWaveKinSet, docs/capi.md); the statics are in still '// &
               'water, as MoorDyn''s initial condition')
         else if (x /= 0.0_wp) then
            call md_fail(d, md_options, row, row%f(2)%s//' '//row%f(1)%s// &
            ': MoorDyn''s water kinematics from files are not read; rodyn''s own *WAVE '// &
            'and *CURRENT give waves and current (docs/moordyn.md, "What is not read")', err)
         end if
      case ('SEAFLOORFILE')
         call md_fail(d, md_options, row, 'SeafloorFile: a seabed from a file is not '// &
                      'read; rodyn''s seabed is a plane (*SEABED, SLOPE=)', err)
      case ('WRITEUNITS')
         call md_real(d, md_options, row, 1, row%f(2)%s, x, err)
         env%write_units = x > 0.0_wp
      case ('UNIFYCURRENTGRID')
         call note(d, row%line, 'option '//row%f(2)%s//' ignored: no current grid is read')
      case default
         call other(name)
      end select
   contains
      !> The value as a real > 0.
      subroutine positive(v)
         real(wp), intent(inout) :: v
         call md_real(d, md_options, row, 1, row%f(2)%s, v, err)
         if (.not. has_error(err) .and. .not. v > 0.0_wp) call md_fail(d, md_options, row, &
            row%f(2)%s//': '//row%f(1)%s//' is not above 0', err)
      end subroutine positive
      !> An option ignored with why, or a name MoorDyn v2 does not know.
      subroutine other(name)
         character(len=*), intent(in) :: name
         if (any(step_options == name)) then
            call ignore(1)
         else if (any(ic_options == name)) then
            call ignore(2)
         else if (any(out_options == name)) then
            call ignore(3)
         else if (name == 'RHOW' .or. name == 'DEPTH') then
            call md_fail(d, md_options, row, row%f(2)%s//': not an option of MoorDyn v2 '// &
                         '(which ignores it): the water density is rho or WtrDnsty, the '// &
                         'depth WtrDpth', err)
         else
            call md_fail(d, md_options, row, 'no option "'//row%f(2)%s//'" in MoorDyn v2 '// &
                         '(docs/moordyn.md, "Options")', err)
         end if
      end subroutine other
      !> Add the option to the ignored ones of group k.
      subroutine ignore(k)
         integer, intent(in) :: k
         if (env%ignored_line(k) == 0) then
            env%ignored_line(k) = row%line
            env%ignored(k)%s = row%f(2)%s
         else
            env%ignored(k)%s = env%ignored(k)%s//', '//row%f(2)%s
         end if
      end subroutine ignore
   end subroutine read_option
end module rodyn_moordyn_options
