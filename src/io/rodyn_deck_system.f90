!> Deck reader of the mooring-system keywords (*POINT) and the whole-deck checks of a
!> system (docs/deck.md, *POINT; docs/systems.md): the points named by *LINE (POINT A=,
!> POINT B=) and *LOAD (POINT=) exist, every point has a line, no *BOUNDARY sits on an
!> end that is on a point, a FREE point's water properties need *WATER. Then the
!> system is put in the terms the analyses use: a line end on a FIXED point is pinned
!> there (a constraint of its own), a FREE point's mass, volume, drag and added mass are
!> an attachment at the point's node.
module rodyn_deck_system
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, point_t, constraint_t, attachment_t, failure_t, point_fixed, &
                          point_free, point_body, point_kind_names, bc_pinned, bc_free, &
                          end_a, end_b, body_fixed, element_rod, element_cable
   use rodyn_deck_lexer, only: deck_t
   use rodyn_deck_card, only: card_t, card_check_params, card_find_param, card_error, &
                              card_check_data, card_data_error, param_len
   use rodyn_deck_card_values, only: card_get_name, card_get_choice, card_data_reals, card_get_real
   use rodyn_deck_numbers, only: real_str, int_str
   use rodyn_deck_support, only: ref_t, pending_t, reading_t, get_item_name, &
                                 max_distance, get_lumped_body, param_fail, find_named, &
                                 get_bounded, check_card, get_host, &
                                 location, node_count, node_number
   implicit none
   private
   public :: read_point_card, resolve_line_points, resolve_load_points, check_point_ends
   public :: check_clamped_ends
   public :: find_point
   public :: system_complete, point_held, point_junction, read_failure_card, check_failures

contains

   !> *POINT, NAME=, TYPE=FIXED|FREE|BODY [, BODY=] [, MASS=] [, VOLUME=] [, CDA=] [, CA=]
   !> [, CONNECTION=] [, HOST=]; data line x, y, z (the position at the start; on a body,
   !> in its axes from its reference point). MASS, VOLUME, CDA and CA only for a FREE
   !> point, BODY= only (and always) for a BODY point, HOST=YES only for a FIXED one.
   subroutine read_point_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: one point appended
      type(error_t), intent(inout) :: err     !< status
      character(len=*), parameter :: what = 'x, y, z'
      character(len=6), parameter :: props(4) = [character(len=6) :: 'MASS', 'VOLUME', &
                                                 'CDA', 'CA']
      type(point_t) :: pt
      character(len=:), allocatable :: name, body
      integer :: k

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call card_check_params(card, [character(len=param_len) :: 'NAME', 'TYPE', 'MASS', &
                                'VOLUME', 'CDA', 'CA', 'BODY', 'CONNECTION', 'HOST'], err)
         call get_item_name(deck, ic, model%points(1:pend%n_points)%name, &
                            pend%point_card(1:pend%n_points), 'point', name, err, &
                            at_name=.true.)
         if (has_error(err)) return
         pt%name = name
         pt%card_at = card%file//':'//int_str(card%line)
         call card_get_choice(card, 'TYPE', point_kind_names, pt%kind, err, listed=.true.)
         call get_host(card, pt%kind == point_fixed, 'point', pt%host, err)
         if (has_error(err)) return
         if (pt%kind /= point_free) then
            do k = 1, size(props)
               if (card_find_param(card, trim(props(k))) == 0) cycle
               call param_fail(card, trim(props(k)), trim(props(k))//' is for a FREE '// &
                               'point: a '//trim(point_kind_names(pt%kind))// &
                               ' point has no mass or water load of its own', err)
               return
            end do
         end if
         body = ''
         call card_get_name(card, 'BODY', body, err, required=pt%kind == point_body)
         if (has_error(err)) return
         if (pt%kind /= point_body .and. len(body) > 0) then
            call param_fail(card, 'BODY', 'BODY= is for TYPE=BODY', err)
            return
         end if
         k = 1
         call card_get_choice(card, 'CONNECTION', [character(len=8) :: 'PINNED', 'CLAMPED'], &
                              k, err)
         if (has_error(err)) return
         pt%clamped = k == 2
         if (pt%clamped .and. pt%kind /= point_body) then
            call param_fail(card, 'CONNECTION', 'CONNECTION=CLAMPED is for TYPE=BODY: a '// &
                            trim(point_kind_names(pt%kind))//' point has no rotation to'// &
                            ' clamp an end to', err)
            return
         end if
         call get_lumped_body(card, pt%mass, pt%volume, pt%cda_area, pt%ca, err)
         if (.not. pt%clamped .and. card%n_data == 2) then
            call card_data_error(card, 2, 'a second data line (the axis a clamped end '// &
                                 'leaves the point along) is for CONNECTION=CLAMPED', err)
            return
         end if
         call card_check_data(card, 1, merge(2, 1, pt%clamped), err, what)
         call card_data_reals(card, 1, 3, pt%position, err, what)
         if (card%n_data == 2) call card_data_reals(card, 2, 3, pt%clamp_axis, err, &
                                                    'ax, ay, az')
         if (has_error(err)) return
         if (card%n_data == 2 .and. .not. norm2(pt%clamp_axis) > 0.0_wp) then
            call card_data_error(card, 2, 'the axis a clamped end leaves the point along '// &
                                 'is 0: give a direction, or no second line', err)
            return
         end if
         if (maxval(abs(pt%position)) > max_distance) then
            call card_error(card, 'a coordinate of '//real_str(maxval(abs(pt%position)))// &
                            ' m is not physical: a point must lie within '// &
                            real_str(max_distance)//' m of the origin', err)
            return
         end if
         pt%global = pt%position
         pend%n_points = pend%n_points + 1
         model%points(pend%n_points) = pt
         pend%point_card(pend%n_points) = ic
         pend%point_body(pend%n_points) = ref_t(body, ic)
      end associate
   end subroutine read_point_card

   !> The points of each line's ends (POINT A=, POINT B=): they exist, and the end takes
   !> the point's position. Before the lines' geometry is checked.
   subroutine resolve_line_points(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< POINT A=, POINT B= of each line
      type(model_t), intent(inout) :: model   !< lines get their points and end positions
      type(error_t), intent(inout) :: err     !< status
      integer :: il
      do il = 1, size(model%lines)
         associate (line => model%lines(il))
            call find_point(deck%cards(pend%line_point_a(il)%card), 'POINT A', &
                            pend%line_point_a(il)%name, model, line%point_a, err)
            if (has_error(err)) return
            call find_point(deck%cards(pend%line_point_b(il)%card), 'POINT B', &
                            pend%line_point_b(il)%name, model, line%point_b, err)
            if (has_error(err)) return
            if (line%point_a > 0) line%end_a = model%points(line%point_a)%global
            if (line%point_b > 0) line%end_b = model%points(line%point_b)%global
         end associate
      end do
   end subroutine resolve_line_points

   !> A line end on a CONNECTION=CLAMPED point is a rod's (a cable's end has no rotation
   !> to clamp). After the lines' segments are resolved.
   subroutine check_clamped_ends(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< the lines' cards
      type(model_t), intent(inout) :: model      !< model
      type(error_t), intent(inout) :: err     !< status
      integer :: il, k, ip, is
      do il = 1, size(model%lines)
         associate (line => model%lines(il))
            do k = 1, 2
               ip = merge(line%point_a, line%point_b, k == 1)
               if (ip == 0) cycle
               if (.not. model%points(ip)%clamped) cycle
               is = line%section
               if (allocated(line%seg_section)) is = line%seg_section(merge(1, &
                                                      size(line%seg_section), k == 1))
               if (line%element == element_rod) cycle
               if (line%element == 0 .and. model%sections(is)%element /= element_cable) cycle
               call card_error(deck%cards(pend%line_section(il)%card), 'line '// &
                               trim(line%name)//"'s end "//merge('A', 'B', k == 1)// &
                               ' is on point '//trim(model%points(ip)%name)//', CONNECTION'// &
                               '=CLAMPED, but is a cable element''s: it has no rotation to'// &
                               ' clamp (make the line, or its end segment, a rod)', err)
               return
            end do
         end associate
      end do
   end subroutine check_clamped_ends

   !> The point of a *LOAD given with POINT= (instead of LINE=): it exists and is FREE
   !> (a FIXED point's load would act on nothing).
   subroutine resolve_load_points(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< POINT= of each load ('' if on a line)
      type(model_t), intent(inout) :: model   !< loads get their point
      type(error_t), intent(inout) :: err     !< status
      integer :: k
      do k = 1, size(model%loads)
         associate (card => deck%cards(pend%load_point(k)%card))
            call find_point(card, 'POINT', pend%load_point(k)%name, model, &
                            model%loads(k)%point, err)
            if (has_error(err)) return
            if (model%loads(k)%point == 0) cycle
            if (model%points(model%loads(k)%point)%kind /= point_free) then
               call param_fail(card, 'POINT', "point '"//pend%load_point(k)%name// &
                               "' is FIXED: a load on it acts on nothing (load a FREE"// &
                               ' point, or a line)', err)
               return
            end if
            if (any(model%loads(k)%moment /= 0.0_wp)) then
               call card_error(card, "a point takes no moment: give Fx, Fy, Fz only", err)
               return
            end if
         end associate
      end do
   end subroutine resolve_load_points

   !> Point ip named `name` by parameter `param` of `card` ('' : none, ip = 0).
   subroutine find_point(card, param, name, model, ip, err)
      type(card_t), intent(in) :: card      !< the referring card
      character(len=*), intent(in) :: param !< its parameter
      character(len=*), intent(in) :: name  !< point name ('' for none)
      type(model_t), intent(in) :: model    !< model with its points
      integer, intent(out) :: ip            !< the point's index (0: none)
      type(error_t), intent(inout) :: err   !< status
      ip = 0
      if (len(name) > 0) call find_named(card, param, name, model%points%name, 'POINT', ip, err)
   end subroutine find_point

   !> No *BOUNDARY on a line end that is on a point (the point holds it, or moves it),
   !> and every point has a line. Then each end on a FIXED point gets its constraint:
   !> pinned at the point's position.
   subroutine check_point_ends(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< card of each constraint
      type(model_t), intent(inout) :: model   !< constraints appended
      type(error_t), intent(inout) :: err     !< status
      integer :: ib, ip, il, node, nn
      character(len=1) :: which
      do ib = 1, pend%n_constraints
         associate (b => model%constraints(ib))
            nn = node_count(model%lines(b%line))
            node = node_number(b%node, nn)
            ip = 0
            if (node == 1) ip = model%lines(b%line)%point_a
            if (node == nn .and. ip == 0) ip = model%lines(b%line)%point_b
            if (ip == 0) cycle
            which = merge('A', 'B', node == 1 .and. model%lines(b%line)%point_a == ip)
            call card_error(deck%cards(pend%bc_line(ib)%card), 'end '//which//' of line '// &
                            trim(model%lines(b%line)%name)//" is on point '"// &
                            trim(model%points(ip)%name)//"' (*POINT at "// &
                            location(deck, pend%point_card(ip))//'): the point holds'// &
                            ' it, a *BOUNDARY cannot', err)
            return
         end associate
      end do
      do ip = 1, size(model%points)
         if (any(model%lines%point_a == ip .or. model%lines%point_b == ip)) cycle
         call card_error(deck%cards(pend%point_card(ip)), "no line has an end on point '"// &
                         trim(model%points(ip)%name)//"' (give POINT A= or POINT B= on"// &
                         ' a *LINE)', err)
         return
      end do
      do il = 1, size(model%lines)
         call pin_end(il, model%lines(il)%point_a, end_a)
         call pin_end(il, model%lines(il)%point_b, end_b)
      end do
   contains
      subroutine pin_end(l, p, k)
         integer, intent(in) :: l, p, k
         if (p == 0) return
         if (model%points(p)%kind /= point_fixed) return
         model%constraints = [model%constraints, constraint_t(line=l, node=k, kind=bc_pinned)]
      end subroutine pin_end
   end subroutine check_point_ends

   !> Whether point ip holds its line ends in place: a FIXED point, a point on a FIXED body.
   pure logical function point_held(model, ip)
      type(model_t), intent(in) :: model  !< model, points' bodies resolved
      integer, intent(in) :: ip           !< point
      point_held = model%points(ip)%kind == point_fixed
      if (model%points(ip)%kind == point_body) &
         point_held = model%bodies(model%points(ip)%body)%kind == body_fixed
   end function point_held

   !> The junction that line ends on point ip move with (0: none, a FIXED point pins
   !> them): ip itself for a FREE point, size(points) + the body for a point on a body
   !> (FIXED or FREE: a FIXED body is a junction whose unknowns are held).
   pure integer function point_junction(model, ip)
      type(model_t), intent(in) :: model  !< model, points' bodies resolved
      integer, intent(in) :: ip           !< point
      point_junction = 0
      if (model%points(ip)%kind == point_fixed) return
      point_junction = ip
      if (model%points(ip)%kind == point_body) &
         point_junction = size(model%points) + model%points(ip)%body
   end function point_junction

   !> A FREE point's VOLUME, CDA and CA need *WATER; its mass, volume, drag and added
   !> mass become an attachment at the point (rodyn_mesh puts it on the point's node).
   subroutine system_complete(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< card of each point
      type(model_t), intent(inout) :: model   !< attachments appended
      type(error_t), intent(inout) :: err     !< status
      character(len=*), parameter :: no_water = ' needs *WATER (no *WATER in the deck)'
      integer :: ip
      do ip = 1, size(model%points)
         associate (pt => model%points(ip), card => deck%cards(pend%point_card(ip)))
            if (pt%kind /= point_free) cycle
            if (.not. model%water%present) then
               if (pt%volume > 0.0_wp) call param_fail(card, 'VOLUME', 'VOLUME > 0'// &
                                                       no_water, err)
               if (pt%cda_area > 0.0_wp .and. .not. has_error(err)) &
                  call param_fail(card, 'CDA', 'CDA > 0'//no_water, err)
               if (has_error(err)) return
            end if
            if (pt%mass == 0.0_wp .and. pt%volume == 0.0_wp .and. pt%cda_area == 0.0_wp) cycle
            model%attachments = [model%attachments, attachment_t(line=0, point=ip, &
                                 mass=pt%mass, volume=pt%volume, cda_area=pt%cda_area, &
                                 ca=pt%ca)]
         end associate
      end do
   end subroutine system_complete

   !> *FAILURE, LINE=name, END=A|B [, TIME=t] [, BREAK LOAD=T]: that end is released at
   !> time t or when its force first reaches T, whichever comes first (one of them given).
   subroutine read_failure_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< one failure appended
      type(error_t), intent(inout) :: err     !< status
      type(failure_t) :: f
      character(len=:), allocatable :: line
      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call check_card(deck, ic, [character(len=param_len) :: 'LINE', 'END', 'TIME', &
                         'BREAK LOAD'], 0, 0, err)
         call card_get_name(card, 'LINE', line, err, required=.true.)
         if (has_error(err)) return
         if (card_find_param(card, 'END') == 0) then
            call card_error(card, 'missing parameter END (A or B)', err)
            return
         end if
         call card_get_choice(card, 'END', [character(len=1) :: 'A', 'B'], f%end, err)
         if (has_error(err)) return
         if (card_find_param(card, 'TIME') == 0 .and. card_find_param(card, 'BREAK LOAD') == 0) then
            call card_error(card, 'give TIME= or BREAK LOAD= (or both): when the end is'// &
                            ' released', err)
            return
         end if
         call get_bounded(card, 'TIME', f%time, .false., err)
         call get_bounded(card, 'BREAK LOAD', f%break_load, .true., err)
         if (has_error(err)) return
         pend%n_failures = pend%n_failures + 1
         model%failures(pend%n_failures) = f
         pend%failure_line(pend%n_failures) = ref_t(line, ic)
      end associate
   end subroutine read_failure_card

   !> Each *FAILURE: its line exists, the end is held or on a point (else nothing holds
   !> it to release), one per end, the deck has *DYNAMIC, and no CHECKPOINT (a checkpoint
   !> does not hold which ends were released).
   subroutine check_failures(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< LINE= of each failure
      type(model_t), intent(inout) :: model   !< failures get their line
      type(error_t), intent(inout) :: err     !< status
      integer :: k, j, il, ib, nn
      logical :: held
      do k = 1, size(model%failures)
         associate (card => deck%cards(pend%failure_line(k)%card), f => model%failures(k))
            do il = 1, size(model%lines)
               if (model%lines(il)%name == pend%failure_line(k)%name) exit
            end do
            if (il > size(model%lines)) then
               call param_fail(card, 'LINE', "LINE '"//pend%failure_line(k)%name// &
                               "' is not defined (no *LINE with NAME="// &
                               pend%failure_line(k)%name//' in the deck)', err)
               return
            end if
            f%line = il
            held = merge(model%lines(il)%point_a, model%lines(il)%point_b, f%end == 1) > 0
            nn = node_count(model%lines(il))
            do ib = 1, size(model%constraints)
               if (model%constraints(ib)%line /= il .or. &
                   model%constraints(ib)%kind == bc_free) cycle
               if (node_number(model%constraints(ib)%node, nn) == merge(1, nn, f%end == 1)) &
                  held = .true.
            end do
            if (.not. held) then
               call param_fail(card, 'END', 'end '//merge('A', 'B', f%end == 1)// &
                               ' of line '//trim(model%lines(il)%name)//' is free: there is'// &
                               ' nothing to release it from', err)
               return
            end if
            do j = 1, k - 1
               if (model%failures(j)%line /= il .or. model%failures(j)%end /= f%end) cycle
               call card_error(card, 'end '//merge('A', 'B', f%end == 1)//' of line '// &
                               trim(model%lines(il)%name)//' already has a *FAILURE (at '// &
                               location(deck, pend%failure_line(j)%card)//')', err)
               return
            end do
            if (.not. model%dynamic%requested) then
               call card_error(card, 'a failure happens in a dynamic analysis: the deck'// &
                               ' has no *DYNAMIC', err)
               return
            end if
            if (model%dynamic%checkpoint > 0.0_wp) then
               call card_error(card, 'not with *DYNAMIC CHECKPOINT: a checkpoint does not'// &
                               ' hold which ends were released', err)
               return
            end if
         end associate
      end do
   end subroutine check_failures
end module rodyn_deck_system
