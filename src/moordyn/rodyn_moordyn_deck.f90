!> A MoorDyn v2 input file as a rodyn deck (docs/moordyn.md): one keyword a MoorDyn
!> entry, each deck line located at the MoorDyn line it comes from, so that the deck
!> reader's checks report 'FILE:LINE: error:' in the MoorDyn file. MoorDyn's conventions
!> and what each column becomes are in docs/moordyn.md, "What each entry becomes":
!> - LINE TYPES -> *SECTION (Diam -> OD, Cd -> CDN, Ca -> CAN, CdAx -> CDA on pi d,
!>   CaAx -> CAA, BA -> AXIAL DAMPING, a negative BA -> AXIAL DAMPING RATIO);
!> - POINTS -> *POINT (Fixed, Free; Coupled and Vessel held at their start, as MoorDyn
!>   holds them until its host moves them; Body# on *BODY B#);
!> - LINES -> *LINE, NumSegs linear elements (MoorDyn's nodes);
!> - BODIES -> *BODY, *BODY DRAG, *BODY ADDED MASS;
!> - OPTIONS -> *GRAVITY, *WATER, *SEABED; the time-stepping and initial-condition
!>   options of an explicit program are noted as ignored.
!> The deck ends with *STATIC (MoorDyn's initial condition is the static equilibrium).
module rodyn_moordyn_deck
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_deck_numbers, only: real_str, int_str, parse_int, parse_real
   use rodyn_deck_params, only: upper_case
   use rodyn_moordyn_file, only: md_file_t, md_row_t, md_line_types, md_rod_types, &
                                 md_bodies, md_rods, md_points, md_lines, md_failure, &
                                 md_options, md_outputs
   use rodyn_moordyn_out, only: md_deck_t, put, note, md_real, md_columns, md_fail
   use rodyn_moordyn_options, only: md_env_t, read_options
   use rodyn_moordyn_rods, only: rods, rod_end
   implicit none
   private
   public :: md_to_deck

   character(len=*), parameter :: point_cols = 'ID Attachment X Y Z Mass Volume CdA Ca'
   character(len=*), parameter :: type_cols = 'TypeName Diam Mass/m EA BA/-zeta EI Cd '// &
                                              'Ca CdAx CaAx'
   character(len=*), parameter :: line_cols = 'ID LineType AttachA AttachB UnstrLen NumSegs'
   character(len=*), parameter :: body_cols = 'ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* '// &
                                              'Volume CdA* Ca*'

contains

   !> Write the rodyn deck of the MoorDyn file md into d (its text and line map, the
   !> notes). Errors: 'FILE:LINE: error: SECTION: ...' (stat_input).
   subroutine md_to_deck(md, d, err, host)
      type(md_file_t), intent(in) :: md     !< the MoorDyn file, in sections
      type(md_deck_t), intent(out) :: d     !< the deck
      type(error_t), intent(inout) :: err   !< status
      !> for a host program's steps (librodyn): a *DYNAMIC whose DT the host's coupling
      !> step replaces, run until the host stops
      logical, intent(in), optional :: host
      type(md_env_t) :: env
      integer :: k

      d%path = md%path
      d%notes = ''
      allocate (d%info%coupled_rods(0), &
                d%info%rod_nodes(0), d%info%rod_ends(6, 0))
      call put(d, '** rodyn deck of the MoorDyn file '//md%path//' (rodyn --to-deck);', 0)
      call put(d, '** each keyword stands for the MoorDyn entry on the line it names', 0)
      call put(d, '*HEADING', 0)
      if (len(md%title) > 0 .and. md%title(1:1) /= '*') then
         call put(d, md%title, 1)
      else
         call put(d, 'MoorDyn file '//md%path, 0)
      end if
      if (md%sec(md_failure)%n > 0) call md_fail(d, md_failure, md%sec(md_failure)%rows(1), &
         'a MoorDyn FAILURE entry is written as *FAILURE by hand (docs/moordyn.md)', err)
      if (has_error(err)) return
      call read_options(md, d, env, err)
      if (has_error(err)) return
      call raise_depth(md, d, env, err)
      if (has_error(err)) return
      call put(d, '*GRAVITY', md%sec(md_options)%line)
      call put(d, '0.0, 0.0, '//real_str(-env%g), env%g_line)
      if (env%rho > 0.0_wp) then
         call put(d, '*WATER, DEPTH='//real_str(env%depth)//', DENSITY='// &
                  real_str(env%rho), env%depth_line)
         call put(d, '*SEABED, STIFFNESS='//real_str(env%kbot)//', DAMPING='// &
                  real_str(env%cbot)//env%friction, env%kbot_line)
      end if
      do k = 1, md%sec(md_line_types)%n
         call line_type(d, md%sec(md_line_types)%rows(k), err)
      end do
      do k = 1, md%sec(md_bodies)%n
         call body(d, md%sec(md_bodies)%rows(k), k, env, err)
         if (d%info%external_waves .and. upper_case(md%sec(md_bodies)%rows(k)%f(2)%s) == &
             'FREE') call md_fail(d, md_bodies, md%sec(md_bodies)%rows(k), 'a Free body '// &
            'with WaveKin 1 (line '//int_str(env%wave_kin_line)//'): the water '// &
            'kinematics a host gives are used on the lines and points, not yet on a body', &
            err)
      end do
      do k = 1, md%sec(md_points)%n
         call point(d, md%sec(md_points)%rows(k), k, md%sec(md_bodies)%n, err)
      end do
      d%info%n_points = md%sec(md_points)%n
      d%info%n_bodies = md%sec(md_bodies)%n
      call rods(md, d, err)             ! their bodies after the bodies, points after the points
      do k = 1, md%sec(md_lines)%n
         call line(d, md, md%sec(md_lines)%rows(k), k, err)
      end do
      if (has_error(err)) return
      call collect_outputs(md, d)
      d%info%write_units = env%write_units
      if (md%sec(md_outputs)%n > 0) call note(d, md%sec(md_outputs)%line, 'OUTPUTS: '// &
         '`rodyn FILE` writes every line''s nodes and tensions, every point and body '// &
         '(docs/output.md); librodyn writes the channels to FILE.out (docs/capi.md)')
      call put(d, '*STATIC, INCREMENTS=20', 0)
      if (present(host)) then
         if (host) call put(d, '*DYNAMIC, DT=1.0, TIME=1.0e7, OUTPUT INTERVAL=1.0e7', 0)
      end if
      call put(d, '*OUTPUT, CSV=YES, HDF5=YES', 0)
   end subroutine md_to_deck

   !> The channels of OUTPUTS, several a row (MoorDyn2.cpp reads them so), with their
   !> lines.
   subroutine collect_outputs(md, d)
      type(md_file_t), intent(in) :: md     !< the MoorDyn file
      type(md_deck_t), intent(inout) :: d   !< the deck (outputs set)
      integer :: k, j, n
      n = 0
      do k = 1, md%sec(md_outputs)%n
         n = n + size(md%sec(md_outputs)%rows(k)%f)
      end do
      allocate (d%info%outputs(n), d%info%output_line(n))
      n = 0
      do k = 1, md%sec(md_outputs)%n
         do j = 1, size(md%sec(md_outputs)%rows(k)%f)
            n = n + 1
            d%info%outputs(n)%s = md%sec(md_outputs)%rows(k)%f(j)%s
            d%info%output_line(n) = md%sec(md_outputs)%rows(k)%line
         end do
      end do
   end subroutine collect_outputs

   !> MoorDyn's water depth is at least the depth of its deepest point in global axes
   !> (MoorDyn2.cpp: a point below the seabed lowers the seabed to it, with a warning).
   subroutine raise_depth(md, d, env, err)
      type(md_file_t), intent(in) :: md     !< the MoorDyn file
      type(md_deck_t), intent(inout) :: d   !< the deck (its notes)
      type(md_env_t), intent(inout) :: env  !< the environment
      type(error_t), intent(inout) :: err   !< status
      character(len=:), allocatable :: word
      real(wp) :: z
      integer :: k, ib
      do k = 1, md%sec(md_points)%n
         associate (row => md%sec(md_points)%rows(k))
            if (size(row%f) < 5) cycle
            call attachment(row%f(2)%s, word, ib)
            if (word == 'BODY') cycle
            call md_real(d, md_points, row, 5, 'Z', z, err)
            if (has_error(err)) return
            if (-z <= env%depth) cycle
            env%depth = -z
            env%depth_line = row%line
            call note(d, row%line, 'POINTS: point '//row%f(1)%s//' at z = '//row%f(5)%s// &
                      ' is below the water depth: the depth is '//real_str(-z)// &
                      ' m (as in MoorDyn)')
         end associate
      end do
   end subroutine raise_depth

   !> LINE TYPES row -> *SECTION. EA, BA and EI as numbers (MoorDyn's tables of
   !> nonlinear stiffness by file name are refused: rodyn's sections are linear).
   subroutine line_type(d, row, err)
      type(md_deck_t), intent(inout) :: d   !< the deck
      type(md_row_t), intent(in) :: row     !< TypeName Diam Mass/m EA BA EI Cd Ca CdAx CaAx
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: cols(2:10) = [character(len=8) :: 'Diam', 'Mass/m', &
         'EA', 'BA/-zeta', 'EI', 'Cd', 'Ca', 'CdAx', 'CaAx']
      real(wp) :: v(2:10)
      character(len=:), allocatable :: card, damp
      integer :: k
      if (has_error(err)) return
      call md_columns(d, md_line_types, row, type_cols, 10, err)
      if (size(row%f) == 12 .or. size(row%f) > 13) call md_fail(d, md_line_types, row, &
         int_str(size(row%f))//' values: a line type has 10, 11 (with Cl) or 13 (with Cl, '// &
         'dF, cF)', err)
      do k = 2, 10
         if (k == 4 .or. k == 5 .or. k == 6) call not_a_curve(d, row, k, trim(cols(k)), err)
         call md_real(d, md_line_types, row, k, trim(cols(k)), v(k), err)
      end do
      if (has_error(err)) return
      if (size(row%f) > 10) then
         call md_real(d, md_line_types, row, 11, 'Cl', v(2), err)
         if (v(2) /= 0.0_wp) call md_fail(d, md_line_types, row, 'column Cl: a vortex-'// &
            'induced lift (Cl > 0) is not in rodyn (docs/moordyn.md, "What is not read")', err)
         if (has_error(err)) return
         call md_real(d, md_line_types, row, 2, 'Diam', v(2), err)
      end if
      damp = ''
      if (v(5) < 0.0_wp) damp = ', AXIAL DAMPING RATIO='//real_str(-v(5))
      if (v(5) > 0.0_wp) damp = ', AXIAL DAMPING='//row%f(5)%s
      card = '*SECTION, NAME='//row%f(1)%s//', OD='//row%f(2)%s
      if (v(2) == 0.0_wp) card = card//', BUOYANCY DIAMETER=0'
      card = card//', CDN='//row%f(7)%s//', CAN='//row%f(8)%s//', CDA='//row%f(9)%s// &
             ', CAA='//row%f(10)%s//damp
      if (v(6) > 0.0_wp) card = card//', ELEMENT=ROD'
      call put(d, card, row%line)
      if (v(6) > 0.0_wp) then      ! a bending line: torsion free of load, GJ = EI
         call put(d, row%f(4)%s//', '//row%f(6)%s//', '//row%f(6)%s//', '//row%f(6)%s// &
                  ', '//row%f(3)%s, row%line)
      else
         call put(d, row%f(4)%s//', 0.0, 0.0, 0.0, '//row%f(3)%s, row%line)
      end if
   end subroutine line_type

   !> A column that MoorDyn also takes as the name of a file of a nonlinear curve.
   subroutine not_a_curve(d, row, k, name, err)
      type(md_deck_t), intent(in) :: d      !< the deck
      type(md_row_t), intent(in) :: row     !< the row
      integer, intent(in) :: k              !< the column
      character(len=*), intent(in) :: name  !< its name
      type(error_t), intent(inout) :: err   !< status
      if (has_error(err)) return
      if (index(row%f(k)%s, '|') > 0) then
         call md_fail(d, md_line_types, row, 'column '//name//': "'//row%f(k)%s// &
                      '": MoorDyn''s viscoelastic line (a|b values) is not in rodyn', err)
         return
      end if
      if (verify(row%f(k)%s(1:1), '0123456789+-.') == 0) return
      call md_fail(d, md_line_types, row, 'column '//name//': "'//row%f(k)%s// &
                   '": a nonlinear '//name//' curve from a file is not in rodyn (its '// &
                   'sections are linear); give a number', err)
   end subroutine not_a_curve

   !> POINTS row -> *POINT P<ID>. Columns ID Attachment X Y Z Mass Volume CdA Ca (9 to
   !> 11 values), or with 12 or more MoorDyn v1's ID Attachment X Y Z M V FX FY FZ CdA Ca
   !> (a steady force, *LOAD). Attachment (any case): Fixed, Fix, Anchor; Free, Point,
   !> Connect, Con; Coupled, Vessel, Ves, Cpld, Fairlead (held at the start: a host moves
   !> it); Body<n> (x, y, z in the body's axes from its reference point).
   subroutine point(d, row, id, n_bodies, err)
      type(md_deck_t), intent(inout) :: d   !< the deck
      type(md_row_t), intent(in) :: row     !< the row
      integer, intent(in) :: id             !< its place in POINTS (its ID)
      integer, intent(in) :: n_bodies       !< bodies in BODIES
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: cols(3:12) = [character(len=6) :: 'X', 'Y', 'Z', &
         'Mass', 'Volume', 'FX', 'FY', 'FZ', 'CdA', 'Ca']
      real(wp) :: v(3:12)
      character(len=:), allocatable :: name, kind, word, card
      integer :: k, ib, icda
      if (has_error(err)) return
      call md_columns(d, md_points, row, point_cols, 9, err)
      call md_id(d, md_points, row, id, err)
      icda = 8
      if (size(row%f) >= 12) icda = 11
      v = 0.0_wp
      do k = 3, 7
         call md_real(d, md_points, row, k, trim(cols(k)), v(k), err)
      end do
      if (icda == 11) then
         do k = 8, 10
            call md_real(d, md_points, row, k, trim(cols(k)), v(k), err)
         end do
      end if
      call md_real(d, md_points, row, icda, 'CdA', v(11), err)
      call md_real(d, md_points, row, icda + 1, 'Ca', v(12), err)
      if (has_error(err)) return
      name = 'P'//row%f(1)%s
      call attachment(row%f(2)%s, word, ib)
      select case (word)
      case ('FIXED', 'FIX', 'ANCHOR')
         kind = 'FIXED'
      case ('FREE', 'POINT', 'CONNECT', 'CON')
         kind = 'FREE'
      case ('COUPLED', 'VESSEL', 'VES', 'CPLD', 'FAIRLEAD')
         kind = 'HOST'
         call note(d, row%line, 'POINTS: point '//row%f(1)%s//' ('//row%f(2)%s//') is '// &
                   'held at its start: it moves when a host program moves it')
      case ('BODY')
         if (ib < 1 .or. ib > n_bodies) then
            call md_fail(d, md_points, row, 'column Attachment: "'//row%f(2)%s//'": '// &
                         'no body '//int_str(ib)//' in BODIES (Body<n>, n from 1 to '// &
                         int_str(n_bodies)//')', err)
            return
         end if
         call put(d, '*POINT, NAME='//name//', TYPE=BODY, BODY=B'//int_str(ib), row%line)
         call put(d, row%f(3)%s//', '//row%f(4)%s//', '//row%f(5)%s, row%line)
         return
      case default
         call md_fail(d, md_points, row, 'column Attachment: "'//row%f(2)%s//'" is not '// &
                      'Fixed, Free, Coupled, Vessel or Body<n>', err)
         return
      end select
      if (kind == 'FREE') then
         card = '*POINT, NAME='//name//', TYPE=FREE, MASS='//real_str(v(6))// &
                 ', VOLUME='//real_str(v(7))//', CDA='//real_str(v(11))
         if (v(7) > 0.0_wp) card = card//', CA='//real_str(v(12))
         call put(d, card, row%line)
      else if (kind == 'HOST') then
         call put(d, '*POINT, NAME='//name//', TYPE=FIXED, HOST=YES', row%line)
      else
         call put(d, '*POINT, NAME='//name//', TYPE=FIXED', row%line)
      end if
      call put(d, row%f(3)%s//', '//row%f(4)%s//', '//row%f(5)%s, row%line)
      if (kind == 'FREE' .and. any(v(8:10) /= 0.0_wp)) then
         call put(d, '*LOAD, POINT='//name, row%line)
         call put(d, triple(v(8:10)), row%line)
      end if
   end subroutine point

   !> The word and number of an attachment (MoorDyn's decomposeString): 'Body2' -> 'BODY',
   !> 2; 'Fixed' -> 'FIXED', 0; a word with more after its number -> that whole text.
   pure subroutine attachment(s, word, n)
      character(len=*), intent(in) :: s     !< as written
      character(len=:), allocatable, intent(out) :: word !< upper case
      integer, intent(out) :: n             !< its number (0: none)
      integer :: k, j
      word = upper_case(s)
      n = 0
      k = scan(word, '0123456789')
      if (k == 0) return
      j = verify(word(k:), '0123456789')
      if (j /= 0 .or. k == 1) return
      read (word(k:), *) n
      word = word(1:k - 1)
   end subroutine attachment

   !> LINES row -> *LINE L<ID>: NumSegs linear elements (MoorDyn's nodes) between the
   !> points AttachA and AttachB (a point's ID, or C, Con, P, Point and its ID). A
   !> negative UnstrLen is that many times the distance between the ends (MoorDyn's
   !> Line::initialize).
   subroutine line(d, md, row, id, err)
      type(md_deck_t), intent(inout) :: d   !< the deck
      type(md_file_t), intent(in) :: md     !< the MoorDyn file (its points and types)
      type(md_row_t), intent(in) :: row     !< ID LineType AttachA AttachB UnstrLen NumSegs
      integer, intent(in) :: id             !< its place in LINES (its ID)
      type(error_t), intent(inout) :: err   !< status
      real(wp) :: length, ends_at(3, 2)
      integer :: k, n, ends(2), it, n_rod, e_rod
      character(len=:), allocatable :: msg, word, len_text
      character(len=16) :: ends_name(2)
      if (has_error(err)) return
      call md_columns(d, md_lines, row, line_cols//' LineOutputs', 7, err)
      call md_id(d, md_lines, row, id, err)
      call md_real(d, md_lines, row, 5, 'UnstrLen', length, err)
      if (has_error(err)) return
      call parse_int(row%f(6)%s, n, msg)
      if (len(msg) > 0) then
         call md_fail(d, md_lines, row, 'column NumSegs: "'//row%f(6)%s//'" is not a '// &
                      'whole number', err)
         return
      end if
      it = find_row(md%sec(md_line_types)%rows(1:md%sec(md_line_types)%n), row%f(2)%s)
      if (it == 0) then
         call md_fail(d, md_lines, row, 'column LineType: no line type "'//row%f(2)%s// &
                      '" in LINE TYPES', err)
         return
      end if
      do k = 1, 2
         ends_name(k) = ''
         call rod_end(row%f(2 + k)%s, n_rod, e_rod)
         if (n_rod > 0) then
            if (e_rod > 0 .and. n_rod <= md%sec(md_rods)%n) then
               ends_name(k) = 'R'//int_str(n_rod)//merge('A', 'B', e_rod == 1)
               ends(k) = -n_rod
               cycle
            end if
            call md_fail(d, md_lines, row, 'column '//merge('AttachA', 'AttachB', k == 1)// &
                         ': "'//row%f(2 + k)%s//'" is not the end A or B of a rod of RODS '// &
                         '(R<n>A, R<n>B, n from 1 to '//int_str(md%sec(md_rods)%n)//')', err)
            return
         end if
         call attachment(row%f(2 + k)%s, word, ends(k))
         if (word == upper_case(row%f(2 + k)%s)) then
            call parse_int(row%f(2 + k)%s, ends(k), msg)
            if (len(msg) > 0) ends(k) = -1
         else if (word /= 'C' .and. word /= 'CON' .and. word /= 'P' .and. word /= 'POINT') then
            ends(k) = -1
         end if
         ends_name(k) = 'P'//int_str(ends(k))
         if (ends(k) >= 1 .and. ends(k) <= md%sec(md_points)%n) cycle
         call md_fail(d, md_lines, row, 'column '//merge('AttachA', 'AttachB', k == 1)// &
                      ': no point "'//row%f(2 + k)%s//'" in POINTS (a line''s ends are '// &
                      'on points, by their ID from 1 to '//int_str(md%sec(md_points)%n)// &
                      ', or on rods'' ends, R<n>A and R<n>B)', err)
         return
      end do
      len_text = row%f(5)%s
      if (length < 0.0_wp .and. any(ends < 0)) then
         call md_fail(d, md_lines, row, 'column UnstrLen: a negative UnstrLen (a multiple '// &
                      'of the distance of the ends) on a rod''s end is not read', err)
         return
      end if
      if (length < 0.0_wp) then
         do k = 1, 2
            call point_at(md, ends(k), ends_at(:, k), err)
         end do
         length = -length*norm2(ends_at(:, 2) - ends_at(:, 1))
         len_text = real_str(length)
         call note(d, row%line, 'LINES: line '//row%f(1)%s//': UnstrLen '//row%f(5)%s// &
                   ' times the distance between its ends is '//len_text//' m')
      end if
      call put(d, '*LINE, NAME=L'//row%f(1)%s//', SECTION='//row%f(2)%s//', LENGTH='// &
               len_text//', ELEMENTS='//row%f(6)%s//', ORDER=1, POINT A='// &
               trim(ends_name(1))//', POINT B='//trim(ends_name(2)), row%line)
      if (row%f(7)%s /= '-') call note(d, row%line, 'LINES: LineOutputs "'//row%f(7)%s// &
         '": rodyn writes every node''s position, velocity and tension (docs/output.md)')
   end subroutine line

   !> Where point k starts, in global axes (a body's point: from the body's start).
   subroutine point_at(md, k, x, err)
      type(md_file_t), intent(in) :: md     !< the MoorDyn file
      integer, intent(in) :: k              !< the point
      real(wp), intent(out) :: x(3)         !< its position
      type(error_t), intent(inout) :: err   !< status
      character(len=:), allocatable :: word, msg
      real(wp) :: r
      integer :: j, ib
      x = 0.0_wp
      if (has_error(err)) return
      associate (row => md%sec(md_points)%rows(k))
         do j = 1, 3
            call parse_real(row%f(2 + j)%s, x(j), msg)
         end do
         call attachment(row%f(2)%s, word, ib)
         if (word /= 'BODY') return
         do j = 1, 3
            call parse_real(md%sec(md_bodies)%rows(ib)%f(2 + j)%s, r, msg)
            x(j) = x(j) + r
         end do
      end associate
   end subroutine point_at

   !> BODIES row -> *BODY B<ID> with its drag and added mass. Columns ID Attachment X0
   !> Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca; CG one value (z) or x|y|z, I one value or
   !> Ixx|Iyy|Izz about CG, CdA one value, t|r, or per axis (3 or 6 values), Ca one value
   !> or per axis. MoorDyn's buoyancy acts at CG (B = G); its added mass V rho Ca acts at
   !> the reference point (FORM=MATRIX about R). Attachment: Free; Fixed, Fix, Anchor;
   !> Coupled, Vessel, Ves, Cpld (held at the start: a host moves it).
   subroutine body(d, row, id, env, err)
      type(md_deck_t), intent(inout) :: d   !< the deck
      type(md_row_t), intent(in) :: row     !< the row
      integer, intent(in) :: id             !< its place in BODIES (its ID)
      type(md_env_t), intent(in) :: env     !< the environment (water density)
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: cols(3:9) = [character(len=4) :: 'X0', 'Y0', 'Z0', &
                                                  'r0', 'p0', 'y0', 'Mass']
      real(wp) :: v(3:12), cg(3), inertia(3), cda(6), ca(3), a(6, 6)
      character(len=:), allocatable :: word, kind, name
      integer :: k, ib
      if (has_error(err)) return
      call md_columns(d, md_bodies, row, body_cols, 14, err)
      call md_id(d, md_bodies, row, id, err)
      do k = 3, 9
         call md_real(d, md_bodies, row, k, trim(cols(k)), v(k), err)
      end do
      call md_values(d, md_bodies, row, 10, 'CG', [1, 3], cg, err)
      if (index(row%f(10)%s, '|') == 0) cg = [0.0_wp, 0.0_wp, cg(1)]
      call md_values(d, md_bodies, row, 11, 'I', [1, 3], inertia, err)
      call md_real(d, md_bodies, row, 12, 'Volume', v(12), err)
      call md_values(d, md_bodies, row, 13, 'CdA', [1, 2, 3, 6], cda, err)
      call md_values(d, md_bodies, row, 14, 'Ca', [1, 3], ca, err)
      if (has_error(err)) return
      if (any(v(6:8) /= 0.0_wp)) then
         call md_fail(d, md_bodies, row, 'columns r0, p0, y0: a body turned at the start '// &
                      'is not read: rodyn''s bodies start with the global axes', err)
         return
      end if
      name = 'B'//row%f(1)%s
      call attachment(row%f(2)%s, word, ib)
      select case (word)
      case ('FREE')
         kind = 'FREE'
      case ('FIXED', 'FIX', 'ANCHOR')
         kind = 'FIXED'
      case ('COUPLED', 'VESSEL', 'VES', 'CPLD')
         kind = 'HOST'
         call note(d, row%line, 'BODIES: body '//row%f(1)%s//' ('//row%f(2)%s//') is '// &
                   'held at its start: it moves when a host program moves it')
      case default
         call md_fail(d, md_bodies, row, 'column Attachment: "'//row%f(2)%s//'" is not '// &
                      'Free, Fixed, Coupled or Vessel (MoorDyn takes any other word for '// &
                      'Free; its pinned coupling is not in rodyn)', err)
         return
      end select
      if (kind == 'FIXED') then
         call put(d, '*BODY, NAME='//name//', TYPE=FIXED', row%line)
      else if (kind == 'HOST') then
         call put(d, '*BODY, NAME='//name//', TYPE=FIXED, HOST=YES', row%line)
      else
         call put(d, '*BODY, NAME='//name//', TYPE=FREE, MASS='//row%f(9)%s// &
                  ', VOLUME='//row%f(12)%s, row%line)
      end if
      call put(d, row%f(3)%s//', '//row%f(4)%s//', '//row%f(5)%s, row%line)
      call put(d, triple(cg), row%line)
      call put(d, triple(cg), row%line)
      call put(d, triple(inertia), row%line)
      if (kind == 'FIXED') return
      if (any(cda /= 0.0_wp)) then
         call put(d, '*BODY DRAG, BODY='//name, row%line)
         call put(d, triple(cda(1:3))//', '//triple(0.5_wp*env%rho*cda(4:6)), row%line)
      end if
      if (any(ca /= 0.0_wp) .and. v(12) > 0.0_wp) then
         a = 0.0_wp
         do k = 1, 3
            a(k, k) = ca(k)*env%rho*v(12)
         end do
         call put(d, '*BODY ADDED MASS, BODY='//name//', FORM=MATRIX', row%line)
         do k = 1, 6
            call put(d, triple(a(k, 1:3))//', '//triple(a(k, 4:6)), row%line)
         end do
      end if
   end subroutine body

   !> Column k as 1, 2, 3 or 6 values a|b|...: one value for all of x; t|r for the
   !> first and second halves of x (CdA); the counts allowed are `counts`.
   subroutine md_values(d, sec, row, k, name, counts, x, err)
      type(md_deck_t), intent(in) :: d      !< the deck
      integer, intent(in) :: sec            !< the section
      type(md_row_t), intent(in) :: row     !< the row
      integer, intent(in) :: k              !< the column
      character(len=*), intent(in) :: name  !< its name
      integer, intent(in) :: counts(:)      !< the numbers of values allowed
      real(wp), intent(out) :: x(:)         !< the values
      type(error_t), intent(inout) :: err   !< status
      real(wp) :: y(6)
      character(len=:), allocatable :: s, msg
      integer :: n, p, q
      x = 0.0_wp
      if (has_error(err)) return
      s = row%f(k)%s//'|'
      n = 0
      p = 1
      msg = ''
      do while (p <= len(s) .and. n < 6)
         q = index(s(p:), '|')
         n = n + 1
         call parse_real(s(p:p + q - 2), y(n), msg)
         if (len(msg) > 0) exit
         p = p + q
      end do
      if (len(msg) == 0 .and. (p <= len(s) .or. .not. any(counts == n))) &
         msg = 'it has '//int_str(n)//' values'
      if (len(msg) > 0) then
         call md_fail(d, sec, row, 'column '//name//': "'//row%f(k)%s//'" is not '// &
                      counts_text(counts)//' numbers a|b|... ('//msg//')', err)
         return
      end if
      if (n == 1) x = y(1)
      if (n == 2) x = [y(1), y(1), y(1), y(2), y(2), y(2)]
      if (n == 3) x = [y(1:3), y(1:3)]
      if (n == size(x)) x = y(1:n)
   contains
      function counts_text(c) result(t)
         integer, intent(in) :: c(:)
         character(len=:), allocatable :: t
         integer :: j
         t = int_str(c(1))
         do j = 2, size(c)
            if (j < size(c)) t = t//', '//int_str(c(j))
            if (j == size(c)) t = t//' or '//int_str(c(j))
         end do
      end function counts_text
   end subroutine md_values

   !> Column ID of a row: the row's place in its section (MoorDyn's IDs run from 1 in
   !> the file's order).
   subroutine md_id(d, sec, row, place, err)
      type(md_deck_t), intent(in) :: d      !< the deck
      integer, intent(in) :: sec            !< the section
      type(md_row_t), intent(in) :: row     !< the row
      integer, intent(in) :: place          !< its place in the section
      type(error_t), intent(inout) :: err   !< status
      character(len=:), allocatable :: msg
      integer :: id
      if (has_error(err)) return
      call parse_int(row%f(1)%s, id, msg)
      if (len(msg) > 0 .or. id /= place) call md_fail(d, sec, row, 'column ID: "'// &
         row%f(1)%s//'" where '//int_str(place)//' is due (IDs run 1, 2, ... in the '// &
         'order of the rows)', err)
   end subroutine md_id

   !> The row whose first field is `id` (0: none).
   pure integer function find_row(rows, id) result(k)
      type(md_row_t), intent(in) :: rows(:) !< the rows
      character(len=*), intent(in) :: id    !< the ID or name sought
      do k = 1, size(rows)
         if (size(rows(k)%f) == 0) cycle
         if (rows(k)%f(1)%s == id) return
      end do
      k = 0
   end function find_row

   !> 'a, b, c'.
   function triple(x) result(s)
      real(wp), intent(in) :: x(3)          !< the values
      character(len=:), allocatable :: s
      s = real_str(x(1))//', '//real_str(x(2))//', '//real_str(x(3))
   end function triple

   !> Whether s starts with p.
   pure logical function starts(s, p)
      character(len=*), intent(in) :: s, p  !< the text, the start sought
      starts = .false.
      if (len(s) >= len(p)) starts = s(1:len(p)) == p
   end function starts
end module rodyn_moordyn_deck
