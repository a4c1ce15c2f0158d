!> librodyn's settings of a run (MoorDyn v2's MoorDyn2.h; docs/capi.md): the time step,
!> the CFL number and the time scheme as a host sets and reads them, and the log.
!> rodyn integrates with its own implicit scheme (docs/theory.md): a MoorDyn scheme's
!> name is checked and noted, not used; a step set by the host bounds rodyn's steps.
module rodyn_capi_settings
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_double, c_char, c_size_t, &
                                          c_associated, c_f_pointer, c_null_ptr
   use, intrinsic :: iso_fortran_env, only: error_unit
   use rodyn_kinds, only: wp
   use rodyn_model, only: scheme_names
   use rodyn_deck_params, only: upper_case
   use rodyn_waves, only: wave_number
   use rodyn_capi_handles, only: capi_system_t, system_of, f_string, md_success, &
                                 md_invalid_value
   implicit none
   private

   !> MoorDyn's log levels: warnings and errors are written (on stderr)
   integer(c_int), parameter :: md_wrn_level = 2

contains

   !> MoorDyn_GetDt: the largest step rodyn takes: the one the host set, else the last
   !> coupling step (the file's dtM before the first step) [s].
   function md_get_dt(h, dt) result(code) bind(c, name='MoorDyn_GetDt')
      type(c_ptr), value :: h               !< system
      real(c_double), intent(out) :: dt     !< step [s]
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      dt = 0.0_c_double
      dt = real(cs%s%model%dynamic%dt, c_double)
      if (cs%s%dt_max > 0.0_wp) dt = real(cs%s%dt_max, c_double)
      code = md_success
   end function md_get_dt

   !> MoorDyn_SetDt: rodyn's steps no longer than dt: a coupling step is then the fewest
   !> equal steps that are not (one step a coupling step otherwise).
   function md_set_dt(h, dt) result(code) bind(c, name='MoorDyn_SetDt')
      type(c_ptr), value :: h               !< system
      real(c_double), value :: dt           !< step [s]
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      if (.not. dt > 0.0_c_double) return
      cs%s%dt_max = real(dt, wp)
      code = md_success
   end function md_set_dt

   !> MoorDyn_GetCFL, MoorDyn_SetCFL: the value kept and given back; an implicit step
   !> has no stability limit to set the step by, so it is not used (noted on stderr).
   function md_get_cfl(h, cfl) result(code) bind(c, name='MoorDyn_GetCFL')
      type(c_ptr), value :: h               !< system
      real(c_double), intent(out) :: cfl    !< CFL number
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      cfl = 0.0_c_double
      cfl = cs%cfl
      code = md_success
   end function md_get_cfl

   function md_set_cfl(h, cfl) result(code) bind(c, name='MoorDyn_SetCFL')
      type(c_ptr), value :: h               !< system
      real(c_double), value :: cfl          !< CFL number
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      if (.not. cfl > 0.0_c_double) return
      cs%cfl = cfl
      write (error_unit, '(a)') 'rodyn: note: MoorDyn_SetCFL: not used (rodyn''s implicit '// &
         'steps are the coupling steps, or those of MoorDyn_SetDt)'
      code = md_success
   end function md_set_cfl

   !> MoorDyn_GetTimeScheme: the name of rodyn's scheme (EMC, MIDPOINT, TRAPEZOIDAL or
   !> ALPHA); name_len its length with the terminating NUL. Either may be NULL.
   function md_get_scheme(h, name, name_len) result(code) bind(c, name='MoorDyn_GetTimeScheme')
      type(c_ptr), value :: h               !< system
      type(c_ptr), value :: name            !< char*, room for name_len
      type(c_ptr), value :: name_len        !< size_t*
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      character(kind=c_char), pointer :: c(:)
      integer(c_size_t), pointer :: n
      character(len=:), allocatable :: s
      integer :: k
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      s = trim(scheme_names(cs%s%model%dynamic%scheme))
      if (c_associated(name_len)) then
         call c_f_pointer(name_len, n)
         n = int(len(s) + 1, c_size_t)
      end if
      if (c_associated(name)) then
         call c_f_pointer(name, c, [len(s) + 1])
         do k = 1, len(s)
            c(k) = s(k:k)
         end do
         c(len(s) + 1) = achar(0)
      end if
      code = md_success
   end function md_get_scheme

   !> MoorDyn_SetTimeScheme: a name of MoorDyn's schemes (Euler, LEuler, Heun, RK2, RK4,
   !> AB2-4, LAB2-4, BEuler<n>, Midpoint<n>, ACA<n>, Wilson<n>) is accepted and noted on
   !> stderr, and rodyn keeps its own scheme; another name: MOORDYN_INVALID_VALUE, as
   !> MoorDyn's.
   function md_set_scheme(h, name) result(code) bind(c, name='MoorDyn_SetTimeScheme')
      type(c_ptr), value :: h               !< system
      type(c_ptr), value :: name            !< const char*
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      character(len=:), allocatable :: s
      cs => system_of(h)
      code = md_invalid_value
      if (.not. associated(cs)) return
      s = upper_case(f_string(name))
      if (.not. moordyn_scheme(s)) then
         write (error_unit, '(a)') 'rodyn: error: MoorDyn_SetTimeScheme: unknown time '// &
            'scheme '''//f_string(name)//''''
         return
      end if
      write (error_unit, '(a)') 'rodyn: note: MoorDyn_SetTimeScheme('//f_string(name)// &
         '): rodyn keeps its implicit scheme, '// &
         trim(scheme_names(cs%s%model%dynamic%scheme))
      code = md_success
   end function md_set_scheme

   !> Whether s (upper case) names one of MoorDyn's time schemes.
   pure logical function moordyn_scheme(s) result(yes)
      character(len=*), intent(in) :: s     !< the name
      character(len=8), parameter :: fixed(11) = [character(len=8) :: 'EULER', 'LEULER', &
         'HEUN', 'RK2', 'RK4', 'AB2', 'AB3', 'AB4', 'LAB2', 'LAB3', 'LAB4']
      character(len=8), parameter :: iterated(4) = [character(len=8) :: 'BEULER', &
         'MIDPOINT', 'ACA', 'WILSON']
      integer :: k, n
      yes = any(fixed == s)
      do k = 1, size(iterated)
         n = len_trim(iterated(k))
         if (len(s) <= n) cycle
         if (s(1:n) /= iterated(k)(1:n)) cycle
         if (verify(s(n + 1:), '0123456789') == 0) yes = .true.
      end do
   end function moordyn_scheme

   !> MoorDyn_SetLogFile: accepted; librodyn's messages go to stderr (noted there).
   function md_set_log_file(h, path) result(code) bind(c, name='MoorDyn_SetLogFile')
      type(c_ptr), value :: h               !< system
      type(c_ptr), value :: path            !< const char*
      integer(c_int) :: code
      code = md_invalid_value
      if (.not. associated(system_of(h))) return
      write (error_unit, '(a)') 'rodyn: note: MoorDyn_SetLogFile('//f_string(path)// &
         '): librodyn writes its messages on stderr'
      code = md_success
   end function md_set_log_file

   !> MoorDyn_Log: the host's message on stderr when it is a warning or an error.
   function md_log(h, level, msg) result(code) bind(c, name='MoorDyn_Log')
      type(c_ptr), value :: h               !< system
      integer(c_int), value :: level        !< MoorDyn's level
      type(c_ptr), value :: msg             !< const char*
      integer(c_int) :: code
      code = md_invalid_value
      if (.not. associated(system_of(h))) return
      if (level >= md_wrn_level) write (error_unit, '(a)') f_string(msg)
      code = md_success
   end function md_log

   !> MoorDyn_GetSeafloor: NULL, as MoorDyn's without a SeafloorFile (rodyn's seabed is
   !> flat, at WtrDpth: docs/moordyn.md); the depth getters, given no seafloor,
   !> MOORDYN_INVALID_VALUE, as MoorDyn's.
   type(c_ptr) function md_get_seafloor(h) bind(c, name='MoorDyn_GetSeafloor')
      type(c_ptr), value :: h               !< system
      md_get_seafloor = c_null_ptr
   end function md_get_seafloor

   integer(c_int) function md_depth_at(sf, x, y, depth) bind(c, name='MoorDyn_GetDepthAt')
      type(c_ptr), value :: sf              !< seafloor
      real(c_double), value :: x, y         !< where [m]
      real(c_double), intent(out) :: depth  !< depth [m]
      depth = 0.0_c_double
      md_depth_at = md_invalid_value
   end function md_depth_at

   integer(c_int) function md_depth_mean(sf, depth) bind(c, name='MoorDyn_GetAverageDepth')
      type(c_ptr), value :: sf              !< seafloor
      real(c_double), intent(out) :: depth  !< depth [m]
      depth = 0.0_c_double
      md_depth_mean = md_invalid_value
   end function md_depth_mean

   integer(c_int) function md_depth_min(sf, depth) bind(c, name='MoorDyn_GetMinDepth')
      type(c_ptr), value :: sf              !< seafloor
      real(c_double), intent(out) :: depth  !< depth [m]
      depth = 0.0_c_double
      md_depth_min = md_invalid_value
   end function md_depth_min

   !> WaveNumber (MoorDyn's Waves.h): the root k of omega^2 = g k tanh(k h), rodyn's
   !> wave_number (docs/theory.md eq. (82)); 0 for omega = 0 or a g or h not positive.
   real(c_double) function md_wave_number(omega, g, h) bind(c, name='WaveNumber')
      real(c_double), value :: omega        !< angular frequency [rad/s]
      real(c_double), value :: g            !< gravity [m/s2]
      real(c_double), value :: h            !< depth [m]
      md_wave_number = 0.0_c_double
      if (omega == 0.0_c_double .or. .not. (g > 0.0_c_double .and. h > 0.0_c_double)) return
      md_wave_number = real(wave_number(abs(real(omega, wp)), real(h, wp), real(g, wp)), &
                            c_double)
   end function md_wave_number

end module rodyn_capi_settings
