!> The OUTPUTS channels of a MoorDyn file, written by librodyn as MoorDyn writes them
!> (docs/capi.md, "The .out file"): FILE.out beside the input file (its name without its
!> extension), a row of names (Time in 10 characters, each channel in 20), a row of
!> units (WriteUnits > 0), then a row at t = 0 (MoorDyn_Init) and at the end of every
!> MoorDyn_Step: the time with 4 decimals in 10 characters, each value as C's
!> scientific with 7 digits in 20 (MoorDyn2.cpp, Init and WriteOutputs).
!>
!> Channels (any case; MoorDyn's decomposeString): FairTen<n> and AnchTen<n> (the tension
!> at end B and end A of line n); L<n>N<k><Q> with node k from 0, L<n>NA<Q> (node 0),
!> L<n>NB<Q> (the last node) and L<n><Q> (node 0), Q one of PX PY PZ (position), VX VY VZ
!> (velocity), T or TEN (MoorDyn's node tension, system_node_tension); P<n><Q> of point
!> n with Q one of PX PY PZ, FX FY FZ (the lines' force on a coupled point) and T (its
!> size); B<n><Q> of body n with Q one of PX PY PZ (its reference point), RX RY RZ
!> (MoorDyn's angles, degrees), VX VY VZ, RVX RVY RVZ (degrees a second). A channel of a
!> rod, of a body's acceleration or force, of a line node's forces, or a name MoorDyn does
!> not know is refused at its line.
module rodyn_capi_outputs
   use rodyn_kinds, only: wp, pi
   use rodyn_error, only: error_t, has_error, set_error, stat_input
   use rodyn_deck_text, only: field_t
   use rodyn_deck_numbers, only: int_str
   use rodyn_deck_params, only: upper_case
   use rodyn_outfile, only: out_file_t, outfile_create, outfile_put, outfile_flush, &
                            outfile_close
   use rodyn_mesh, only: mesh_node
   use rodyn_capi_system, only: md_system_t, system_node_x, system_node_tension, &
                                system_forces, system_ndof, system_body_state, &
                                system_point_x
   implicit none
   private
   public :: channel_t, channels_parse, out_open, out_row, out_close

   !> One channel: what it reads.
   type :: channel_t
      character(len=:), allocatable :: name  !< as written in OUTPUTS
      integer :: obj = 0                     !< 1 a line node, 2 a point, 3 a body
      integer :: index = 0                   !< the line or point, from 1
      integer :: node = 0                    !< the node, from 0 (-1: the last)
      character(len=3) :: q = ''             !< PX ... VZ, T, FX ... FZ
   end type channel_t

contains

   !> The channels of names (at lines of path), checked against sys's lines and points.
   subroutine channels_parse(sys, path, names, lines, ch, err)
      type(md_system_t), intent(in) :: sys  !< the system
      character(len=*), intent(in) :: path  !< the MoorDyn file
      type(field_t), intent(in) :: names(:) !< the channels' names
      integer, intent(in) :: lines(:)       !< their lines
      type(channel_t), allocatable, intent(out) :: ch(:) !< the channels
      type(error_t), intent(inout) :: err   !< status
      character(len=:), allocatable :: u, why
      integer :: k
      allocate (ch(size(names)))
      do k = 1, size(names)
         ch(k)%name = names(k)%s
         u = upper_case(names(k)%s)
         call parse_one(u, ch(k), why)
         if (len(why) == 0) call check_range(sys, ch(k), why)
         if (len(why) > 0) then
            call set_error(err, stat_input, path//':'//int_str(lines(k))//': error: '// &
                           'OUTPUTS: "'//names(k)%s//'": '//why)
            return
         end if
      end do
   end subroutine channels_parse

   !> A channel's name read into c; why = '' or what is wrong.
   subroutine parse_one(u, c, why)
      character(len=*), intent(in) :: u     !< the name, upper case
      type(channel_t), intent(inout) :: c   !< its object, index, node, quantity
      character(len=:), allocatable, intent(out) :: why
      character(len=:), allocatable :: obj, rest
      integer :: p, q
      why = ''
      if (index(u, 'FAIRTEN') == 1 .or. index(u, 'ANCHTEN') == 1) then
         c%obj = 1
         c%q = 'T'
         c%node = merge(-1, 0, u(1:1) == 'F')
         c%index = whole(u(8:))
         if (c%index < 1) why = 'FairTen and AnchTen take a line''s number'
         return
      end if
      p = scan(u, '0123456789')
      if (p < 2) then
         why = 'not a channel: L<n>..., P<n>..., FairTen<n>, AnchTen<n>'
         return
      end if
      obj = u(1:p - 1)
      q = verify(u(p:), '0123456789')
      if (q == 0) then
         why = 'no quantity after the number'
         return
      end if
      c%index = whole(u(p:p + q - 2))
      rest = u(p + q - 1:)
      select case (obj)
      case ('L', 'LINE')
         c%obj = 1
         call line_node(rest, c, why)
      case ('P', 'POINT')
         c%obj = 2
         c%q = rest
         if (.not. any(rest == [character(len=3) :: 'PX', 'PY', 'PZ', 'FX', 'FY', 'FZ', &
                                'T', 'TEN'])) why = 'a point''s quantity is PX, PY, PZ, '// &
                                                    'FX, FY, FZ or T in librodyn'
         if (rest == 'TEN') c%q = 'T'
      case ('B', 'BODY')
         c%obj = 3
         c%q = rest
         if (.not. any(rest == [character(len=3) :: 'PX', 'PY', 'PZ', 'RX', 'RY', 'RZ', &
                                'VX', 'VY', 'VZ', 'RVX', 'RVY', 'RVZ'])) why = 'a body''s '// &
            'quantity is PX, PY, PZ, RX, RY, RZ, VX, VY, VZ, RVX, RVY or RVZ in librodyn'
      case ('R', 'ROD')
         why = 'the channels of rods are not written by librodyn (docs/capi.md)'
      case default
         why = 'not a channel: L<n>..., P<n>..., FairTen<n>, AnchTen<n>'
      end select
   end subroutine parse_one

   !> The node and quantity of a line channel after its number: N<k><Q>, NA<Q>, NB<Q>, <Q>.
   subroutine line_node(rest, c, why)
      character(len=*), intent(in) :: rest  !< after the line's number
      type(channel_t), intent(inout) :: c   !< node and quantity set
      character(len=:), allocatable, intent(inout) :: why
      character(len=:), allocatable :: qq
      integer :: q
      qq = rest
      c%node = 0
      if (len(rest) >= 2) then
         if (rest(1:1) == 'N' .and. scan(rest(2:2), '0123456789') == 1) then
            q = verify(rest(2:), '0123456789')
            if (q == 0) then
               why = 'no quantity after the node'
               return
            end if
            c%node = whole(rest(2:q))
            qq = rest(q + 1:)
         else if (rest(1:2) == 'NA' .or. rest(1:2) == 'NB') then
            c%node = merge(0, -1, rest(1:2) == 'NA')
            qq = rest(3:)
         end if
      end if
      if (qq == 'TEN') qq = 'T'
      c%q = qq
      if (.not. any(qq == [character(len=3) :: 'PX', 'PY', 'PZ', 'VX', 'VY', 'VZ', 'T'])) &
         why = 'a line node''s quantity is PX, PY, PZ, VX, VY, VZ or T in librodyn'
   end subroutine line_node

   !> The channel's line, node or point exists.
   subroutine check_range(sys, c, why)
      type(md_system_t), intent(in) :: sys  !< the system
      type(channel_t), intent(in) :: c      !< the channel
      character(len=:), allocatable, intent(inout) :: why
      integer :: nn
      if (c%obj == 1) then
         if (c%index < 1 .or. c%index > size(sys%model%lines)) then
            why = 'no line '//int_str(c%index)
            return
         end if
         nn = sys%model%lines(c%index)%n_elements*sys%model%lines(c%index)%order
         if (c%node > nn) why = 'no node '//int_str(c%node)//' on line '// &
                                int_str(c%index)//' (0 to '//int_str(nn)//')'
      else if (c%obj == 3) then
         if (c%index < 1 .or. c%index > sys%n_bodies) why = 'no body '//int_str(c%index)
      else if (c%index < 1 .or. c%index > sys%n_points) then
         why = 'no point '//int_str(c%index)
      end if
   end subroutine check_range

   !> A whole number (-1 when not one).
   pure integer function whole(s)
      character(len=*), intent(in) :: s
      integer :: ios
      whole = -1
      if (len(s) == 0) return
      if (verify(s, '0123456789') /= 0) return
      read (s, *, iostat=ios) whole
      if (ios /= 0) whole = -1
   end function whole

   !> FILE.out created beside path, its heads written.
   subroutine out_open(f, path, ch, units, err)
      type(out_file_t), intent(out) :: f    !< the file
      character(len=*), intent(in) :: path  !< the MoorDyn file
      type(channel_t), intent(in) :: ch(:)  !< the channels
      logical, intent(in) :: units          !< write the units row
      type(error_t), intent(inout) :: err   !< status
      character(len=:), allocatable :: dir, base, head, unit
      character(len=20) :: cell
      integer :: k, slash, dot
      slash = index(path, '/', back=.true.)
      dir = '.'
      if (slash > 0) dir = path(1:slash - 1)
      base = path(slash + 1:)
      dot = index(base, '.', back=.true.)
      if (dot > 1) base = base(1:dot - 1)
      call outfile_create(f, dir, base//'.out', err, live=.true.)
      if (has_error(err)) return
      write (cell(1:10), '(a10)') 'Time'
      head = cell(1:10)
      unit = '       (s)'
      do k = 1, size(ch)
         write (cell, '(a20)') ch(k)%name
         head = head//cell
         select case (ch(k)%q(1:2))
         case ('PX', 'PY', 'PZ')
            write (cell, '(a20)') 'm'
         case ('VX', 'VY', 'VZ')
            write (cell, '(a20)') 'm/s'
         case ('RX', 'RY', 'RZ')
            write (cell, '(a20)') 'deg'
         case ('RV')
            write (cell, '(a20)') 'deg/s'
         case default
            write (cell, '(a20)') 'N'
         end select
         unit = unit//cell
      end do
      call outfile_put(f, head)
      if (units) call outfile_put(f, unit)
   end subroutine out_open

   !> The row of the channels at sys%t.
   subroutine out_row(f, sys, ch, err)
      type(out_file_t), intent(inout) :: f  !< the file
      type(md_system_t), intent(in) :: sys  !< the system
      type(channel_t), intent(in) :: ch(:)  !< the channels
      type(error_t), intent(inout) :: err   !< status
      character(len=:), allocatable :: row
      character(len=20) :: cell
      real(wp), allocatable :: fc(:)
      integer :: k
      allocate (fc(system_ndof(sys)))
      call system_forces(sys, fc)
      fc = fc(6*size(sys%cbody) + 1:)     ! the points' (after the bodies' 6 DOFs)
      write (cell(1:10), '(f10.4)') sys%t
      row = cell(1:10)
      do k = 1, size(ch)
         write (cell, '(es20.7e2)') value_of(sys, ch(k), fc)
         row = row//lower_e(cell)
      end do
      call outfile_put(f, row)
      call outfile_flush(f, err)
   end subroutine out_row

   !> A number's text with C's lower-case exponent letter.
   pure function lower_e(s) result(t)
      character(len=*), intent(in) :: s
      character(len=len(s)) :: t
      integer :: k
      t = s
      k = index(t, 'E')
      if (k > 0) t(k:k) = 'e'
   end function lower_e

   !> The value of a channel now.
   real(wp) function value_of(sys, c, fc) result(v)
      type(md_system_t), intent(in) :: sys  !< the system
      type(channel_t), intent(in) :: c      !< the channel
      real(wp), intent(in) :: fc(:)         !< the forces on the coupled points
      real(wp) :: x(3), r(6), rd(6)
      integer :: node, k, j
      j = index('XYZ', c%q(len_trim(c%q):len_trim(c%q)))
      if (c%obj == 1) then
         node = c%node
         if (node < 0) node = sys%mesh%line_n_nodes(c%index) - 1
         select case (c%q(1:1))
         case ('P')
            x = system_node_x(sys, c%index, node)
         case ('V')
            x = sys%state%v(:, mesh_node(sys%mesh, c%index, node + 1))
         case default
            x = system_node_tension(sys, c%index, node)
         end select
      else if (c%obj == 3) then          ! MoorDyn's angles and their rates in degrees
         call system_body_state(sys, c%index, r, rd)
         select case (c%q(1:2))
         case ('PX', 'PY', 'PZ')
            x = r(1:3)
         case ('RX', 'RY', 'RZ')
            x = r(4:6)*180.0_wp/pi
         case ('VX', 'VY', 'VZ')
            x = rd(1:3)
         case default
            x = rd(4:6)*180.0_wp/pi
         end select
      else
         k = findloc(sys%coupled, c%index, dim=1)
         if (c%q(1:1) == 'F' .or. c%q(1:1) == 'T') then
            x = 0.0_wp
            if (k > 0) x = fc(3*k - 2:3*k)
         else
            x = system_point_x(sys, c%index)
         end if
      end if
      if (j > 0) then
         v = x(j)
      else
         v = norm2(x)
      end if
   end function value_of


   !> The file closed.
   subroutine out_close(f, err)
      type(out_file_t), intent(inout) :: f  !< the file
      type(error_t), intent(inout) :: err   !< status
      call outfile_close(f, err)
   end subroutine out_close
end module rodyn_capi_outputs
