!> Deck reader of *LINE and the whole-deck checks of each line: its elements, its
!> geometry with the total length (ends apart, not beyond LENGTH, the d1 hint), that it
!> is held (through its points too) when a static analysis runs, and that a line not
!> held at both ends starts straight (docs/deck.md, *LINE).
module rodyn_deck_line
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, line_def_t, bc_free, element_names, element_cable, &
                          element_rod, point_body
   use rodyn_deck_lexer, only: deck_t
   use rodyn_deck_card, only: card_t, card_check_params, card_find_param, card_error, &
                              card_data_error, card_check_data, param_len
   use rodyn_deck_card_values, only: card_get_real, card_get_int, card_get_name, card_get_choice, &
                                     card_data_reals
   use rodyn_deck_numbers, only: real_str, int_str
   use rodyn_deck_support, only: ref_t, pending_t, reading_t, get_item_name, &
                                 max_elements, max_distance, param_fail, &
                                 location, node_count, node_number, get_bounded
   use rodyn_deck_system, only: point_junction, point_held
   implicit none
   private
   public :: read_line_card, all_cable, check_line_element, check_line_geometry
   public :: static_analysis_runs, check_supported, check_straight_start

   real(wp), parameter :: coincide_tol = 1.0e-9_wp     !< ends coincide below tol*LENGTH
   !> a taut line starts straight and stretched uniformly; a start stretched more than this
   !> is taken for a mistake (nylon, the most extensible rope, breaks near 20 %)
   real(wp), parameter :: max_start_stretch = 0.2_wp
   real(wp), parameter :: straight_tol = 1.0e-9_wp     !< relative tolerance, free lines
   real(wp), parameter :: parallel_tol = 1.0e-6_wp     !< d1 hint parallel to the chord

contains

   !> *LINE: a rod between end A and end B; data line xA, yA, zA, xB, yB, zB and an
   !> optional line v1x, v1y, v1z (direction d1 should point to). SECTION=, LENGTH= and
   !> ELEMENTS= are required together; without SECTION= the line is made of *SEGMENT
   !> cards, and LENGTH= and ELEMENTS= are optional (checked against the segments).
   !> An end on a *POINT (POINT A=, POINT B=) takes the point's position, so the first
   !> data line gives only the other end's (3 values), or nothing when both are on points
   !> (read_line_data). The geometry that depends on the length is checked by
   !> check_line_geometry.
   subroutine read_line_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: one line appended
      type(error_t), intent(inout) :: err     !< status
      type(line_def_t) :: line
      character(len=:), allocatable :: name, section, pa, pb
      logical :: plain

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call card_check_params(card, [character(len=param_len) :: 'NAME', 'SECTION', &
                                'LENGTH', 'ELEMENTS', 'ORDER', 'ELEMENT', 'POINT A', &
                                'POINT B'], err)
         call get_item_name(deck, ic, model%lines(1:pend%n_lines)%name, &
                            pend%line_section(1:pend%n_lines)%card, 'line', name, err)
         if (has_error(err)) return
         line%name = name
         line%card_at = card%file//':'//int_str(card%line)
         section = ''
         call card_get_name(card, 'SECTION', section, err)
         if (has_error(err)) return
         plain = len(section) > 0     ! else segmented: LENGTH, ELEMENTS optional

         call get_bounded(card, 'LENGTH', line%length, .true., err, required=plain)
         if (has_error(err)) return
         if (line%length > max_distance) then
            call param_fail(card, 'LENGTH', 'LENGTH must be at most '// &
                            real_str(max_distance)//' m, got '//real_str(line%length), err)
            return
         end if
         call card_get_int(card, 'ELEMENTS', line%n_elements, err, required=plain)
         if (has_error(err)) return
         if (card_find_param(card, 'ELEMENTS') > 0 .and. &
             (line%n_elements < 1 .or. line%n_elements > max_elements)) then
            call param_fail(card, 'ELEMENTS', 'ELEMENTS must be between 1 and '// &
                            int_str(max_elements)//', got '//int_str(line%n_elements), err)
            return
         end if
         call card_get_int(card, 'ORDER', line%order, err)
         if (has_error(err)) return
         if (line%order < 1 .or. line%order > 3) then
            call param_fail(card, 'ORDER', 'ORDER must be 1, 2 or 3, got '// &
                            int_str(line%order), err)
            return
         end if

         call card_get_choice(card, 'ELEMENT', element_names, line%element, err)

         pa = ''
         pb = ''
         call card_get_name(card, 'POINT A', pa, err)
         call card_get_name(card, 'POINT B', pb, err)
         if (has_error(err)) return
         if (len(pa) > 0 .and. pa == pb) then
            call param_fail(card, 'POINT B', 'both ends of line '//trim(line%name)// &
                            " are on point '"//pa//"': a line joins two points", err)
            return
         end if
         call read_line_data(card, len(pa) > 0, len(pb) > 0, line, err)
         if (has_error(err)) return
         pend%n_lines = pend%n_lines + 1
         model%lines(pend%n_lines) = line
         pend%line_section(pend%n_lines) = ref_t(section, ic)
         pend%line_point_a(pend%n_lines) = ref_t(pa, ic)
         pend%line_point_b(pend%n_lines) = ref_t(pb, ic)
      end associate
   end subroutine read_line_card

   !> The data lines of *LINE: the positions of the ends not on a point (6, 3 or no
   !> values: xA, yA, zA, xB, yB, zB; the other end's; none), then optionally the d1
   !> direction v1x, v1y, v1z. An end on a point gets its position when the points are
   !> resolved (rodyn_deck_system).
   subroutine read_line_data(card, on_a, on_b, line, err)
      type(card_t), intent(in) :: card          !< the *LINE card
      logical, intent(in) :: on_a               !< end A is on a point
      logical, intent(in) :: on_b               !< end B is on a point
      type(line_def_t), intent(inout) :: line   !< ends and d1 hint set
      type(error_t), intent(inout) :: err       !< status
      character(len=*), parameter :: what2 = 'v1x, v1y, v1z'
      character(len=:), allocatable :: what1
      real(wp) :: x(6), v(3), vn
      integer :: nx, id1
      nx = 3*(merge(0, 1, on_a) + merge(0, 1, on_b))
      if (nx == 6) then
         what1 = 'xA, yA, zA, xB, yB, zB'
      else if (on_a) then
         what1 = 'xB, yB, zB (end A is on a point)'
      else
         what1 = 'xA, yA, zA (end B is on a point)'
      end if
      if (nx == 0) then
         call card_check_data(card, 0, 1, err, what2//' (both ends are on points)')
      else
         call card_check_data(card, 1, 2, err, what1)
      end if
      if (has_error(err)) return
      id1 = 1
      if (nx > 0) then
         id1 = 2
         call card_data_reals(card, 1, nx, x(1:nx), err, what1)
         if (has_error(err)) return
         if (maxval(abs(x(1:nx))) > max_distance) then
            call card_data_error(card, 1, 'a coordinate of '// &
                                 real_str(maxval(abs(x(1:nx))))//' m is not physical: '// &
                                 'the ends must lie within '//real_str(max_distance)// &
                                 ' m of the origin', err)
            return
         end if
         if (.not. on_a) line%end_a = x(1:3)
         if (.not. on_b) line%end_b = x(nx - 2:nx)
      end if
      if (card%n_data >= id1) then
         call card_data_reals(card, id1, 3, v, err, what2)
         if (has_error(err)) return
         vn = norm2(v)
         if (.not. vn > 0.0_wp) then
            call card_data_error(card, id1, 'the d1 direction v1x, v1y, v1z is zero', err)
            return
         end if
         line%has_d1_hint = .true.
         line%d1_hint = v/vn
      end if
   end subroutine read_line_data

   !> Whether line il is made of cable elements only: its ELEMENT=, else its sections'.
   pure logical function all_cable(model, il)
      type(model_t), intent(in) :: model !< model, segments resolved
      integer, intent(in) :: il          !< line
      associate (line => model%lines(il))
         if (line%element /= 0) then
            all_cable = line%element == element_cable
         else if (allocated(line%seg_section)) then
            all_cable = all(model%sections(line%seg_section)%element == element_cable)
         else
            all_cable = model%sections(line%section)%element == element_cable
         end if
      end associate
   end function all_cable

   !> ELEMENT=ROD on a line needs rod sections: a section of EI1 = EI2 = GJ = 0 (or
   !> ELEMENT=CABLE) cannot be a rod.
   subroutine check_line_element(card, model, il, err)
      type(card_t), intent(in) :: card       !< the *LINE card
      type(model_t), intent(in) :: model     !< model, segments resolved
      integer, intent(in) :: il              !< line
      type(error_t), intent(inout) :: err    !< status
      integer :: k, is
      if (model%lines(il)%element /= element_rod) return
      do k = 1, max(1, merge(size(model%lines(il)%seg_section), 0, &
                             allocated(model%lines(il)%seg_section)))
         is = model%lines(il)%section
         if (allocated(model%lines(il)%seg_section)) is = model%lines(il)%seg_section(k)
         if (model%sections(is)%element == element_cable) then
            call param_fail(card, 'ELEMENT', 'ELEMENT=ROD, but section '// &
                            trim(model%sections(is)%name)//' is a cable section '// &
                            '(ELEMENT=CABLE, or EI1 = EI2 = GJ = 0)', err)
            return
         end if
      end do
   end subroutine check_line_element

   !> The geometry of a line with its total length (segments resolved): the ends do not
   !> coincide, are not farther apart than the length, and the d1 hint is not parallel
   !> to the chord. Reported at the *LINE card's data lines.
   subroutine check_line_geometry(card, line, err)
      type(card_t), intent(in) :: card       !< the *LINE card
      type(line_def_t), intent(in) :: line   !< the line, length resolved
      type(error_t), intent(inout) :: err    !< status
      real(wp) :: chord(3), dist
      integer :: id1
      logical :: on_points

      on_points = line%point_a > 0 .or. line%point_b > 0
      id1 = merge(1, 2, line%point_a > 0 .and. line%point_b > 0)
      chord = line%end_b - line%end_a
      dist = norm2(chord)
      if (dist < coincide_tol*line%length) then
         if (on_points) then
            call card_error(card, 'ends A and B coincide (where their points are)', err)
         else
            call card_data_error(card, 1, 'ends A and B coincide', err)
         end if
         return
      end if
      if (dist > line%length*(1.0_wp + max_start_stretch)) then
         if (on_points) then
            call card_error(card, 'the distance between ends A and B ('//real_str(dist)// &
                            ' m, where their points are) is more than 20 % over LENGTH ('// &
                            real_str(line%length)//' m): no line stretches so far', err)
         else
            call card_data_error(card, 1, 'the distance between ends A and B ('// &
                                 real_str(dist)//' m) is more than 20 % over LENGTH ('// &
                                 real_str(line%length)//' m): no line stretches so far', err)
         end if
         return
      end if
      if (.not. line%has_d1_hint) return
      if (norm2(cross(line%d1_hint, chord/dist)) < parallel_tol) then
         call card_data_error(card, id1, 'the d1 direction v1x, v1y, v1z is parallel '// &
                              'to the chord from end A to end B', err)
      end if
   end subroutine check_line_geometry

   !> True unless the deck asks only for a dynamic analysis from the defined shape
   !> (*DYNAMIC with START=DEFINED and no *STATIC): a static analysis then never runs.
   pure logical function static_analysis_runs(model)
      type(model_t), intent(in) :: model  !< model with its analysis options read
      static_analysis_runs = .not. (model%dynamic%requested .and. &
                                    .not. model%dynamic%start_static .and. &
                                    .not. model%static%requested)
   end function static_analysis_runs

   !> A line with no node held in position is a free body: it has no static solution
   !> (checked only when a static analysis runs, see static_analysis_runs). A line whose
   !> end is on a FREE point is held through it when another line on that point is held
   !> (the points' connections followed until nothing changes); an end on a FIXED point
   !> is pinned (rodyn_deck_system gave it its constraint).
   subroutine check_supported(card, model, il, err)
      type(card_t), intent(in) :: card      !< the *LINE card
      type(model_t), intent(in) :: model    !< model with resolved constraints
      integer, intent(in) :: il             !< line to check
      type(error_t), intent(inout) :: err   !< status
      logical :: held(size(model%lines)), any_held, changed
      integer :: ib, ij, l, nj
      held = .false.
      do ib = 1, size(model%constraints)
         if (model%constraints(ib)%kind /= bc_free) held(model%constraints(ib)%line) = .true.
      end do
      do l = 1, size(model%lines)          ! an end on a FIXED body, or on a body with
         if (model%lines(l)%point_a > 0) held(l) = held(l) .or. &      ! a waterplane, is held
                                                  point_held(model, model%lines(l)%point_a) &
                                                  .or. restored(model%lines(l)%point_a)
         if (model%lines(l)%point_b > 0) held(l) = held(l) .or. &
                                                  point_held(model, model%lines(l)%point_b) &
                                                  .or. restored(model%lines(l)%point_b)
      end do
      ! junctions: FREE points, then bodies (rodyn_deck_system's point_junction)
      nj = size(model%points)
      if (allocated(model%bodies)) nj = nj + size(model%bodies)
      changed = .true.
      do while (changed .and. .not. held(il))
         changed = .false.
         do ij = 1, nj
            any_held = .false.
            do l = 1, size(model%lines)
               if (on_junction(l, ij)) any_held = any_held .or. held(l)
            end do
            if (.not. any_held) cycle
            do l = 1, size(model%lines)
               if (.not. on_junction(l, ij) .or. held(l)) cycle
               held(l) = .true.
               changed = .true.
            end do
         end do
      end do
      if (held(il)) return
      if (model%lines(il)%point_a > 0 .or. model%lines(il)%point_b > 0) then
         call card_error(card, 'nothing holds line '//trim(model%lines(il)%name)// &
                         ' in position, nor any line joined to it through its points: a'// &
                         ' static analysis needs a FIXED *POINT or a *BOUNDARY of TYPE'// &
                         ' PINNED, HINGED, CLAMPED or POSITION in each connected group', err)
         return
      end if
      call card_error(card, 'nothing holds line '//trim(model%lines(il)%name)// &
                      ' in position: a static analysis needs at least one *BOUNDARY of'// &
                      ' TYPE PINNED, HINGED, CLAMPED or POSITION on it', err)
   contains
      logical function restored(ip)
         integer, intent(in) :: ip
         restored = .false.
         if (model%points(ip)%kind /= point_body) return
         restored = any(model%bodies(model%points(ip)%body)%hydrostatic /= 0.0_wp)
      end function restored
      logical function on_junction(l, ij)
         integer, intent(in) :: l, ij
         on_junction = .false.
         if (model%lines(l)%point_a > 0) on_junction = &
            point_junction(model, model%lines(l)%point_a) == ij
         if (model%lines(l)%point_b > 0) on_junction = on_junction .or. &
            point_junction(model, model%lines(l)%point_b) == ij
      end function on_junction
   end subroutine check_supported


   !> A line not held in position at both ends (PINNED, HINGED, CLAMPED or POSITION, or
   !> on a point) starts straight from A towards B, so its end distance must equal LENGTH.
   subroutine check_straight_start(card, model, il, err)
      type(card_t), intent(in) :: card      !< the *LINE card
      type(model_t), intent(in) :: model    !< model with resolved constraints
      integer, intent(in) :: il             !< line to check
      type(error_t), intent(inout) :: err   !< status
      logical :: held_a, held_b
      integer :: ib, nn, node
      real(wp) :: dist
      character(len=:), allocatable :: which

      associate (line => model%lines(il))
         nn = node_count(line)
         held_a = line%point_a > 0
         held_b = line%point_b > 0
         do ib = 1, size(model%constraints)
            associate (b => model%constraints(ib))
               if (b%line /= il .or. b%kind == bc_free) cycle
               node = node_number(b%node, nn)
               if (node == 1) held_a = .true.
               if (node == nn) held_b = .true.
            end associate
         end do
         if (held_a .and. held_b) return
         dist = norm2(line%end_b - line%end_a)
         if (abs(dist - line%length) <= straight_tol*line%length) return
         if (.not. held_a .and. .not. held_b) then
            which = 'ends A and B are free'
         else if (.not. held_a) then
            which = 'end A is free'
         else
            which = 'end B is free'
         end if
         call card_error(card, which//', so line '//trim(line%name)//' starts straight'// &
                         ' from A towards B: the distance between its ends ('// &
                         real_str(dist)//' m) must equal LENGTH ('//real_str(line%length)// &
                         ' m)', err)
      end associate
   end subroutine check_straight_start

   !> Cross product a x b.
   pure function cross(a, b) result(c)
      real(wp), intent(in) :: a(3)  !< first vector
      real(wp), intent(in) :: b(3)  !< second vector
      real(wp) :: c(3)              !< a x b
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross
end module rodyn_deck_line
