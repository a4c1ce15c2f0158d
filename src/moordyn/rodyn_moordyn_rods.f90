!> MoorDyn's rods that rodyn reads (docs/moordyn.md, "Rods"): a rod fixed to the ground
!> (Fixed, Fix, Anchor) or moved by a host (Coupled, Vessel: held at its start, as a
!> coupled point) is a FIXED *BODY R<ID> from its end A, and each of its ends a line is
!> attached to (R<ID>A, R<ID>B in LINES) a *POINT on it, where the line is pinned; a line
!> with bending stiffness (EI > 0) is clamped there along the rod's axis, as MoorDyn
!> clamps it (CONNECTION=CLAMPED with the axis the end leaves along). A rod that moves
!> with the lines (Free, Pinned, Body<n>) is refused: rodyn has no rigid cylinder with its
!> own hydrodynamics.
module rodyn_moordyn_rods
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_deck_numbers, only: real_str, int_str, parse_int
   use rodyn_deck_params, only: upper_case
   use rodyn_moordyn_file, only: md_file_t, md_row_t, md_rod_types, md_rods, md_lines, &
                                 md_line_types
   use rodyn_moordyn_out, only: md_deck_t, put, note, md_real, md_columns, md_fail, word
   implicit none
   private
   public :: rods, rod_end

   character(len=*), parameter :: rod_cols = 'ID RodType Attachment Xa Ya Za Xb Yb Zb '// &
                                             'NumSegs RodOutputs'
   character(len=*), parameter :: type_cols = 'TypeName Diam Mass/m Cd Ca CdEnd CaEnd'

contains

   !> The rods of the file as FIXED bodies with the points of their ends that lines use.
   subroutine rods(md, d, err)
      type(md_file_t), intent(in) :: md     !< the MoorDyn file
      type(md_deck_t), intent(inout) :: d   !< the deck
      type(error_t), intent(inout) :: err   !< status
      real(wp) :: v(7)
      integer :: k, j
      do k = 1, md%sec(md_rod_types)%n
         call md_columns(d, md_rod_types, md%sec(md_rod_types)%rows(k), type_cols, 7, err)
         do j = 2, 7
            call md_real(d, md_rod_types, md%sec(md_rod_types)%rows(k), j, &
                         word(type_cols, j), v(j), err)
         end do
      end do
      do k = 1, md%sec(md_rods)%n
         call rod(md, d, md%sec(md_rods)%rows(k), k, err)
      end do
   end subroutine rods

   !> One RODS row.
   subroutine rod(md, d, row, id, err)
      type(md_file_t), intent(in) :: md     !< the MoorDyn file
      type(md_deck_t), intent(inout) :: d   !< the deck
      type(md_row_t), intent(in) :: row     !< the row
      integer, intent(in) :: id             !< its place in RODS (its ID)
      type(error_t), intent(inout) :: err   !< status
      real(wp) :: a(3), b(3)
      character(len=:), allocatable :: att, msg, name
      integer :: j, n, e
      if (has_error(err)) return
      call md_columns(d, md_rods, row, rod_cols, 11, err)
      if (has_error(err)) return
      call parse_int(row%f(1)%s, n, msg)
      if (len(msg) > 0 .or. n /= id) call md_fail(d, md_rods, row, 'column ID: "'// &
         row%f(1)%s//'" where '//int_str(id)//' is due (IDs run 1, 2, ... in the order '// &
         'of the rows)', err)
      if (.not. any([(md%sec(md_rod_types)%rows(j)%f(1)%s == row%f(2)%s, &
                      j = 1, md%sec(md_rod_types)%n)])) call md_fail(d, md_rods, row, &
         'column RodType: no rod type "'//row%f(2)%s//'" in ROD TYPES', err)
      do j = 1, 3
         call md_real(d, md_rods, row, 3 + j, word(rod_cols, 3 + j), a(j), err)
         call md_real(d, md_rods, row, 6 + j, word(rod_cols, 6 + j), b(j), err)
      end do
      if (has_error(err)) return
      ! (its nodes, NumSegs + 1: the places of MoorDyn's external water kinematics)
      call parse_int(row%f(10)%s, n, msg)
      if (len(msg) > 0 .or. n < 1) call md_fail(d, md_rods, row, 'column NumSegs: "'// &
         row%f(10)%s//'" is not a whole number above 0', err)
      if (has_error(err)) return
      d%info%rod_nodes = [d%info%rod_nodes, n + 1]
      d%info%rod_ends = reshape([d%info%rod_ends, a, b], [6, size(d%info%rod_nodes)])
      att = upper_case(row%f(3)%s)
      select case (att)
      case ('FIXED', 'FIX', 'ANCHOR')
      case ('COUPLED', 'VESSEL', 'VES', 'CPLD')
         d%info%coupled_rods = [d%info%coupled_rods, id]
         call note(d, row%line, 'RODS: rod '//row%f(1)%s//' ('//row%f(3)%s//') is held '// &
                   'at its start: it moves when a host program moves it')
      case default
         call md_fail(d, md_rods, row, 'column Attachment: "'//row%f(3)%s//'": a rod that '// &
                      'moves with the lines (Free, Pinned, Body<n>) is not read: rodyn has '// &
                      'no rigid cylinder; Fixed and Coupled rods are (docs/moordyn.md)', err)
         return
      end select
      name = 'R'//row%f(1)%s
      call put(d, '*BODY, NAME='//name//', TYPE=FIXED', row%line)
      call put(d, row%f(4)%s//', '//row%f(5)%s//', '//row%f(6)%s, row%line)
      call put(d, '0.0, 0.0, 0.0', row%line)
      call put(d, '0.0, 0.0, 0.0', row%line)
      call put(d, '0.0, 0.0, 0.0', row%line)
      do e = 1, 2
         call end_point(md, d, row, id, e, merge(a, b, e == 1) - a, b - a, err)
      end do
   end subroutine rod

   !> The point of end e (1 A, 2 B) of rod id at r (body axes from end A), when a line
   !> is on it; a line that bends (its type's EI > 0) refused there.
   subroutine end_point(md, d, row, id, e, r, ab, err)
      type(md_file_t), intent(in) :: md     !< the MoorDyn file
      type(md_deck_t), intent(inout) :: d   !< the deck
      type(md_row_t), intent(in) :: row     !< the rod's row
      integer, intent(in) :: id             !< the rod
      integer, intent(in) :: e              !< its end
      real(wp), intent(in) :: r(3)          !< where
      real(wp), intent(in) :: ab(3)         !< the rod from end A to end B [m]
      type(error_t), intent(inout) :: err   !< status
      character(len=:), allocatable :: pname
      real(wp) :: axis(3)
      logical :: used, bends, pins
      integer :: k, j, n, ee, t
      if (has_error(err)) return
      used = .false.
      bends = .false.
      pins = .false.
      do k = 1, md%sec(md_lines)%n
         associate (lr => md%sec(md_lines)%rows(k))
            if (size(lr%f) < 4) cycle
            do j = 3, 4
               call rod_end(lr%f(j)%s, n, ee)
               if (n /= id .or. ee /= e) cycle
               used = .true.
               do t = 1, md%sec(md_line_types)%n
                  associate (tr => md%sec(md_line_types)%rows(t))
                     if (tr%f(1)%s /= lr%f(2)%s .or. size(tr%f) < 6) cycle
                     if (verify(tr%f(6)%s, '0.+-eE') /= 0) then
                        bends = .true.
                     else
                        pins = .true.
                     end if
                  end associate
               end do
               if (bends .and. pins) then
                  call md_fail(d, md_lines, lr, 'column '//merge('AttachA', 'AttachB', j == 3)// &
                               ': "'//lr%f(j)%s//'": lines with and without bending '// &
                               'stiffness on one rod end are not read (the first clamped '// &
                               'along the rod''s axis, the others pinned); give each its end', &
                               err)
                  return
               end if
            end do
         end associate
      end do
      if (.not. used) return
      pname = 'R'//int_str(id)//merge('A', 'B', e == 1)
      if (.not. bends) then
         call put(d, '*POINT, NAME='//pname//', TYPE=BODY, BODY=R'//int_str(id), row%line)
         call put(d, real_str(r(1))//', '//real_str(r(2))//', '//real_str(r(3)), row%line)
         return
      end if
      ! a line that bends is clamped along the rod's axis, leaving the end outwards (MoorDyn's
      ! Line::setEndOrientation): from end B along A to B, from end A along B to A
      axis = merge(-ab, ab, e == 1)
      call put(d, '*POINT, NAME='//pname//', TYPE=BODY, BODY=R'//int_str(id)// &
               ', CONNECTION=CLAMPED', row%line)
      call put(d, real_str(r(1))//', '//real_str(r(2))//', '//real_str(r(3)), row%line)
      call put(d, real_str(axis(1))//', '//real_str(axis(2))//', '//real_str(axis(3)), &
               row%line)
   end subroutine end_point

   !> A line's end on a rod, as LINES writes it (R1A, Rod2B, any case): the rod and its
   !> end (1 A, 2 B); n = 0 when it is not a rod's end, e = 0 when the end is missing.
   pure subroutine rod_end(s, n, e)
      character(len=*), intent(in) :: s     !< AttachA or AttachB
      integer, intent(out) :: n             !< the rod (0: not a rod's end)
      integer, intent(out) :: e             !< its end (0: not given)
      character(len=:), allocatable :: u
      integer :: k, j
      n = 0
      e = 0
      u = upper_case(s)
      k = 0
      if (len(u) >= 2) then
         if (u(1:1) == 'R' .and. scan(u(2:2), '0123456789') == 1) k = 2
      end if
      if (len(u) >= 4) then
         if (u(1:3) == 'ROD' .and. scan(u(4:4), '0123456789') == 1) k = 4
      end if
      if (k == 0) return
      j = verify(u(k:), '0123456789')
      if (j == 0) then
         read (u(k:), *) n
         return
      end if
      read (u(k:k + j - 2), *) n
      if (u(k + j - 1:) == 'A') e = 1
      if (u(k + j - 1:) == 'B') e = 2
   end subroutine rod_end

end module rodyn_moordyn_rods
