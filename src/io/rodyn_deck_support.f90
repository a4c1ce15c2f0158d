!> Deck reader support: what the keyword readers remember for the validation pass
!> (pending_t: names referred to, the card of each item, the first card of keywords
!> allowed once), what a reader works on (reading_t: the cards, the card read and those
!> records) and the checks they share: parameters in a range, a pair set together,
!> END=/NODE=, the NAME= of an item a card defines, a name among those defined, a line
!> name resolved with its node number, a node given once, error locations. Used by all
!> the keyword readers (rodyn_deck and the rodyn_deck_* modules).
module rodyn_deck_support
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, line_def_t, end_a, end_b
   use rodyn_deck_lexer, only: deck_t
   use rodyn_deck_card, only: card_t, card_find_param, card_error, card_param_error, &
                              card_data_error, card_check_params, card_check_data
   use rodyn_deck_card_values, only: card_get_real, card_get_int, card_get_choice, card_get_name
   use rodyn_deck_numbers, only: real_str, int_str
   implicit none
   private
   public :: ref_t, pending_t, reading_t, max_cutbacks, max_elements, body_subcards, &
             sub_drag, sub_wave
   public :: max_gravity, max_frequency, max_distance, max_increments, max_iterations
   public :: get_lumped_body
   public :: check_card, check_once, get_node, get_bounded, check_at_most, get_tolerance, data_check
   public :: get_int_range, param_fail, get_pair
   public :: location, resolve_line, resolve_section, node_count, node_number, node_label
   public :: check_node_once, get_item_name, find_named, refuse, get_host

   integer, parameter :: max_cutbacks = 30             !< most cutbacks allowed
   integer, parameter :: max_elements = 10000000       !< most elements in one line
   ! Physically absurd magnitudes, refused at reading (docs/deck.md, "Bounds"):
   real(wp), parameter :: max_gravity = 1000.0_wp      !< |g| at most 100 g [m/s2]
   real(wp), parameter :: max_frequency = 1000.0_wp    !< a prescribed motion's [Hz]
   real(wp), parameter :: max_distance = 1.0e7_wp      !< LENGTH, coordinates [m]
   integer, parameter :: max_increments = 100000       !< *STATIC INCREMENTS
   integer, parameter :: max_iterations = 1000         !< MAX ITERATIONS (Newton)

   !> The keywords of the cards that belong to a body (BODY=name), one of each per body;
   !> sub_drag and sub_wave index *BODY DRAG and *BODY WAVE LOAD.
   character(len=*), parameter :: body_subcards(5) = [character(len=17) :: &
      'BODY HYDROSTATICS', 'BODY DAMPING', 'BODY ADDED MASS', 'BODY DRAG', 'BODY WAVE LOAD']
   integer, parameter :: sub_drag = 4, sub_wave = 5  !< indices in body_subcards

   !> A reference by name from one card to a section, line or amplitude, resolved after
   !> all cards are read.
   type :: ref_t
      character(len=:), allocatable :: name  !< name referred to, upper case
      integer :: card = 0                    !< index of the referring card
   end type ref_t

   !> What the readers remember for the validation pass (not part of the model).
   type :: pending_t
      type(ref_t), allocatable :: line_section(:) !< per line: its SECTION= ('' if none)
      type(ref_t), allocatable :: bc_line(:)      !< per constraint: its LINE=
      type(ref_t), allocatable :: load_line(:)    !< per load: its LINE=
      type(ref_t), allocatable :: load_amp(:)     !< per load: its AMPLITUDE= ('' if none)
      type(ref_t), allocatable :: motion_line(:)  !< per motion: its LINE= (or BODY=)
      logical, allocatable :: motion_body(:)      !< per motion: BODY= given (not LINE=)
      logical, allocatable :: motion_point(:)     !< per motion: POINT= given
      type(ref_t), allocatable :: motion_vessel(:) !< per motion: its VESSEL= ('' if none)
      integer, allocatable :: vessel_card(:)      !< per vessel: card index
      type(ref_t), allocatable :: iv_line(:)      !< per initial velocity: its LINE= (or BODY=)
      logical, allocatable :: iv_body(:)          !< per initial velocity: BODY= given
      type(ref_t), allocatable :: seg_line(:)     !< per *SEGMENT: its LINE=
      type(ref_t), allocatable :: seg_section(:)  !< per *SEGMENT: its SECTION=
      real(wp), allocatable :: seg_length(:)      !< per *SEGMENT: LENGTH [m]
      integer, allocatable :: seg_elements(:)     !< per *SEGMENT: ELEMENTS
      type(ref_t), allocatable :: att_line(:)     !< per attachment: its LINE=
      type(ref_t), allocatable :: line_point_a(:) !< per line: its POINT A= ('' if none)
      type(ref_t), allocatable :: line_point_b(:) !< per line: its POINT B= ('' if none)
      type(ref_t), allocatable :: load_point(:)   !< per load: its POINT= ('' if on a line)
      integer, allocatable :: point_card(:)       !< per point: card index
      type(ref_t), allocatable :: point_body(:)   !< per point: its BODY= ('' if none)
      type(ref_t), allocatable :: load_body(:)    !< per load: its BODY= ('' if none)
      integer, allocatable :: body_card(:)        !< per body: card index
      integer, allocatable :: body_sub(:, :)      !< (k, body): its body_subcards(k) card
      type(ref_t), allocatable :: failure_line(:) !< per *FAILURE: its LINE=
      type(ref_t) :: offset_body                  !< *OFFSET CURVE's BODY=
      integer, allocatable :: section_card(:)     !< per section: card index
      integer, allocatable :: amplitude_card(:)   !< per amplitude: card index
      integer :: n_sections = 0     !< sections read so far
      integer :: n_lines = 0        !< lines read so far
      integer :: n_constraints = 0  !< constraints read so far
      integer :: n_loads = 0        !< loads read so far
      integer :: n_amplitudes = 0   !< amplitudes read so far
      integer :: n_motions = 0      !< motions read so far
      integer :: n_vessels = 0      !< vessels read so far
      integer :: n_ivs = 0          !< initial velocities read so far
      integer :: n_segments = 0     !< segments read so far
      integer :: n_attachments = 0  !< attachments read so far
      integer :: n_points = 0       !< points read so far
      integer :: n_bodies = 0       !< bodies read so far
      integer :: n_failures = 0     !< failures read so far
      integer :: heading = 0   !< card of the first *HEADING (0: none yet)
      integer :: gravity = 0   !< card of the first *GRAVITY
      integer :: static = 0    !< card of the first *STATIC
      integer :: output = 0    !< card of the first *OUTPUT
      integer :: dynamic = 0   !< card of the first *DYNAMIC
      integer :: damping = 0   !< card of the first *DAMPING
      integer :: water = 0     !< card of the first *WATER
      integer :: current = 0   !< card of the first *CURRENT
      integer :: seabed = 0    !< card of the first *SEABED
      integer :: offset_card = 0 !< card of the first *OFFSET CURVE
      integer :: modal_card = 0  !< card of the first *MODAL
   end type pending_t

   !> What a keyword reader works on: all cards, the index of the card it reads, and the
   !> readers' records (one for the whole reading of a deck, deck_read).
   type :: reading_t
      type(deck_t) :: deck      !< all cards
      integer :: ic = 0         !< index of the card being read
      type(pending_t) :: pend   !< what the readers remember for the validation pass
   end type reading_t

contains

   !> The form of card ic: only the parameters `allowed`, between nmin and nmax data lines
   !> (card_check_data, `what` naming a line's values), and, given `first`, the only card
   !> of its keyword (check_once, checked first). Stops at the first error.
   subroutine check_card(deck, ic, allowed, nmin, nmax, err, first, what)
      type(deck_t), intent(in) :: deck               !< all cards
      integer, intent(in) :: ic                      !< index of the card
      character(len=*), intent(in) :: allowed(:)     !< allowed parameters, upper case
      integer, intent(in) :: nmin                    !< fewest data lines needed
      integer, intent(in) :: nmax                    !< most data lines allowed, < 0: any
      type(error_t), intent(inout) :: err            !< status
      integer, intent(inout), optional :: first      !< first card of the keyword (0: none)
      character(len=*), intent(in), optional :: what !< names of a data line's values
      if (present(first)) call check_once(deck, ic, first, err)
      call card_check_params(deck%cards(ic), allowed, err)
      call card_check_data(deck%cards(ic), nmin, nmax, err, what)
   end subroutine check_card

   !> Refuse a second card of a keyword allowed once; `first` remembers the first.
   subroutine check_once(deck, ic, first, err)
      type(deck_t), intent(in) :: deck     !< all cards
      integer, intent(in) :: ic            !< index of this card
      integer, intent(inout) :: first      !< index of the first such card (0: none)
      type(error_t), intent(inout) :: err  !< status
      if (has_error(err)) return
      if (first == 0) then
         first = ic
      else
         call card_error(deck%cards(ic), 'given twice (first at '// &
                         location(deck, first)//')', err)
      end if
   end subroutine check_once

   !> Read END=A|B or NODE=k (exactly one of them) into a node number: end_a, end_b
   !> or k >= 1. The upper bound of k is checked once the line is known.
   subroutine get_node(card, node, err)
      type(card_t), intent(in) :: card     !< a *BOUNDARY, *LOAD or *MOTION card
      integer, intent(out) :: node         !< end_a, end_b or the node number
      type(error_t), intent(inout) :: err  !< status
      integer :: which

      node = end_a
      if (has_error(err)) return
      if (card_find_param(card, 'END') > 0 .and. card_find_param(card, 'NODE') > 0) then
         call card_error(card, 'give END or NODE, not both', err)
         return
      end if
      if (card_find_param(card, 'END') > 0) then
         which = 0
         call card_get_choice(card, 'END', [character(len=1) :: 'A', 'B'], which, err)
         if (has_error(err)) return
         node = merge(end_a, end_b, which == 1)
      else if (card_find_param(card, 'NODE') > 0) then
         call card_get_int(card, 'NODE', node, err)
         if (has_error(err)) return
         if (node < 1) then
            call param_fail(card, 'NODE', 'NODE must be >= 1, got '//int_str(node), err)
         end if
      else
         call card_error(card, 'missing parameter END or NODE', err)
      end if
   end subroutine get_node

   !> A real parameter, optional unless `required`, that must be >= 0 (or > 0 when
   !> `strict`); `hint` ends the message of a value out of bounds.
   subroutine get_bounded(card, name, value, strict, err, required, hint)
      type(card_t), intent(in) :: card     !< the card
      character(len=*), intent(in) :: name !< parameter name
      real(wp), intent(inout) :: value     !< the value (unchanged if absent)
      logical, intent(in) :: strict        !< require > 0 rather than >= 0
      type(error_t), intent(inout) :: err  !< status
      logical, intent(in), optional :: required !< absence is an error
      character(len=*), intent(in), optional :: hint !< ends the message of a bad value
      character(len=:), allocatable :: msg
      logical :: found

      call card_get_real(card, name, value, err, found, required)
      if (has_error(err) .or. .not. found) return
      msg = sign_problem(name, value, strict)
      if (len(msg) > 0 .and. present(hint)) msg = msg//hint
      if (len(msg) > 0) call param_fail(card, name, msg, err)
   end subroutine get_bounded

   !> '' when value > 0 (strict) or value >= 0, else 'NAME must be > 0, got VALUE' (or
   !> '>= 0').
   function sign_problem(name, value, strict) result(msg)
      character(len=*), intent(in) :: name  !< name of the value
      real(wp), intent(in) :: value         !< the value
      logical, intent(in) :: strict         !< require > 0 rather than >= 0
      character(len=:), allocatable :: msg  !< '' or what is wrong
      msg = ''
      if (strict .and. .not. value > 0.0_wp) then
         msg = name//' must be > 0, got '//real_str(value)
      else if (.not. value >= 0.0_wp) then
         msg = name//' must be >= 0, got '//real_str(value)
      end if
   end function sign_problem

   !> Two values set by parameters n1 and n2, or both by `name` (GA sets GA1 and GA2):
   !> `name` with n1 or n2 is an error. Each >= 0 (> 0 when strict); unchanged if absent.
   subroutine get_pair(card, name, n1, n2, v1, v2, strict, err)
      type(card_t), intent(in) :: card     !< the card
      character(len=*), intent(in) :: name !< the parameter setting both
      character(len=*), intent(in) :: n1   !< the parameter of value 1
      character(len=*), intent(in) :: n2   !< the parameter of value 2
      real(wp), intent(inout) :: v1        !< value 1 (unchanged if not given)
      real(wp), intent(inout) :: v2        !< value 2 (unchanged if not given)
      logical, intent(in) :: strict        !< require > 0 rather than >= 0
      type(error_t), intent(inout) :: err  !< status
      real(wp) :: both

      if (has_error(err)) return
      if (card_find_param(card, name) == 0) then
         call get_bounded(card, n1, v1, strict, err)
         call get_bounded(card, n2, v2, strict, err)
      else if (card_find_param(card, n1) > 0 .or. card_find_param(card, n2) > 0) then
         call param_fail(card, name, 'give '//name//' or '//n1//'/'//n2//', not both', err)
      else
         both = -1.0_wp
         call get_bounded(card, name, both, strict, err)
         if (has_error(err)) return
         v1 = both
         v2 = both
      end if
   end subroutine get_pair

   !> An integer parameter, optional unless `required`, with lo <= value <= hi (hi = huge:
   !> no upper bound); a value left unchanged is checked too.
   subroutine get_int_range(card, name, lo, hi, value, err, required)
      type(card_t), intent(in) :: card     !< the card
      character(len=*), intent(in) :: name !< parameter name
      integer, intent(in) :: lo            !< smallest value allowed
      integer, intent(in) :: hi            !< largest value allowed
      integer, intent(inout) :: value      !< the value (unchanged if absent)
      type(error_t), intent(inout) :: err  !< status
      logical, intent(in), optional :: required !< absence is an error

      if (has_error(err)) return
      call card_get_int(card, name, value, err, required=required)
      if (has_error(err)) return
      if (value >= lo .and. value <= hi) return
      if (hi == huge(hi)) then
         call param_fail(card, name, name//' must be >= '//int_str(lo)//', got '// &
                         int_str(value), err)
      else
         call param_fail(card, name, name//' must be between '//int_str(lo)//' and '// &
                         int_str(hi)//', got '//int_str(value), err)
      end if
   end subroutine get_int_range

   !> MASS=, VOLUME=, CDA=, CA= of a lumped body (*ATTACHMENT, a FREE *POINT): each >= 0
   !> (unchanged if absent), and CA > 0 only with VOLUME > 0 (the added mass is
   !> CA rho_w VOLUME).
   subroutine get_lumped_body(card, mass, volume, cda_area, ca, err)
      type(card_t), intent(in) :: card       !< the card
      real(wp), intent(inout) :: mass        !< MASS [kg]
      real(wp), intent(inout) :: volume      !< VOLUME [m3]
      real(wp), intent(inout) :: cda_area    !< CDA [m2]
      real(wp), intent(inout) :: ca          !< CA [-]
      type(error_t), intent(inout) :: err    !< status
      call get_bounded(card, 'MASS', mass, .false., err)
      call get_bounded(card, 'VOLUME', volume, .false., err)
      call get_bounded(card, 'CDA', cda_area, .false., err)
      call get_bounded(card, 'CA', ca, .false., err)
      if (has_error(err)) return
      if (ca > 0.0_wp .and. .not. volume > 0.0_wp) &
         call param_fail(card, 'CA', 'CA > 0 needs VOLUME > 0 (the added mass is'// &
                         ' CA rho_w VOLUME)', err)
   end subroutine get_lumped_body

   !> An error at the first of `names` the card gives: 'NAME'//why (why: ' is only
   !> allowed with TYPE=TABLE', ...).
   subroutine refuse(card, names, why, err)
      type(card_t), intent(in) :: card          !< the card
      character(len=*), intent(in) :: names(:)  !< parameters the card may not give
      character(len=*), intent(in) :: why       !< why, following the name in the message
      type(error_t), intent(inout) :: err       !< status
      integer :: j
      if (has_error(err)) return
      do j = 1, size(names)
         if (card_find_param(card, trim(names(j))) == 0) cycle
         call param_fail(card, trim(names(j)), trim(names(j))//why, err)
         return
      end do
   end subroutine refuse

   !> A value no physical model has: refused when above vmax, with `why` (the physical
   !> meaning of the bound, ending the message).
   subroutine check_at_most(card, name, value, vmax, unit, why, err)
      type(card_t), intent(in) :: card     !< the card
      character(len=*), intent(in) :: name !< parameter name
      real(wp), intent(in) :: value        !< its value
      real(wp), intent(in) :: vmax         !< largest value accepted
      character(len=*), intent(in) :: unit !< unit of value and vmax ('' when none)
      character(len=*), intent(in) :: why  !< why no larger value is meaningful
      type(error_t), intent(inout) :: err  !< status

      if (has_error(err)) return
      if (value > vmax) then
         call param_fail(card, name, name//' = '//real_str(value)//unit//' is beyond '// &
                         real_str(vmax)//unit//': '//why, err)
      end if
   end subroutine check_at_most

   !> Optional tolerance parameter, 0 < value < 1.
   subroutine get_tolerance(card, name, value, err)
      type(card_t), intent(in) :: card     !< the *STATIC or *DYNAMIC card
      character(len=*), intent(in) :: name !< parameter name
      real(wp), intent(inout) :: value     !< the tolerance [-] (unchanged if absent)
      type(error_t), intent(inout) :: err  !< status
      logical :: found

      if (has_error(err)) return
      call card_get_real(card, name, value, err, found)
      if (has_error(err) .or. .not. found) return
      if (.not. (value > 0.0_wp .and. value < 1.0_wp)) then
         call param_fail(card, name, name//' must be > 0 and < 1, got '// &
                         real_str(value), err)
      end if
   end subroutine get_tolerance

   !> Check a value of data line `id`: > 0 when strict, else >= 0.
   subroutine data_check(card, id, name, value, strict, err)
      type(card_t), intent(in) :: card     !< the card
      integer, intent(in) :: id            !< index of the data line
      character(len=*), intent(in) :: name !< name of the value
      real(wp), intent(in) :: value        !< the value
      logical, intent(in) :: strict        !< require > 0 rather than >= 0
      type(error_t), intent(inout) :: err  !< status
      if (len(sign_problem(name, value, strict)) > 0) &
         call card_data_error(card, id, sign_problem(name, value, strict), err)
   end subroutine data_check

   !> Report an error at the line of parameter `name` (keyword line if absent).
   subroutine param_fail(card, name, message, err)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name
      character(len=*), intent(in) :: message !< what is wrong
      type(error_t), intent(inout) :: err     !< status
      integer :: ip
      ip = card_find_param(card, name)
      if (ip > 0) then
         call card_param_error(card, ip, message, err)
      else
         call card_error(card, message, err)
      end if
   end subroutine param_fail

   !> HOST=YES|NO of a *POINT or *BODY (default NO): a host program moves it through
   !> librodyn (docs/capi.md); only a FIXED one (held where it is in a run of the deck).
   subroutine get_host(card, fixed, what, host, err)
      use rodyn_deck_card_values, only: card_get_yesno
      type(card_t), intent(in) :: card        !< the *POINT or *BODY card
      logical, intent(in) :: fixed            !< TYPE=FIXED
      character(len=*), intent(in) :: what    !< 'point' or 'body'
      logical, intent(out) :: host            !< HOST=YES
      type(error_t), intent(inout) :: err     !< status
      host = .false.
      call card_get_yesno(card, 'HOST', host, err)
      if (has_error(err) .or. .not. host .or. fixed) return
      call param_fail(card, 'HOST', 'HOST=YES is for a FIXED '//what//': a host program '// &
                      'moves a held '//what//', not one the lines carry', err)
   end subroutine get_host

   !> 'FILE:LINE' of card ic, to point at an earlier definition.
   function location(deck, ic) result(s)
      type(deck_t), intent(in) :: deck    !< all cards
      integer, intent(in) :: ic           !< card index
      character(len=:), allocatable :: s  !< 'FILE:LINE'
      s = deck%cards(ic)%file//':'//int_str(deck%cards(ic)%line)
   end function location

   !> Find the line named by LINE= of a *BOUNDARY, *LOAD, *MOTION or *INITIAL VELOCITY
   !> card and check its node.
   subroutine resolve_line(card, name, model, iline, node, err)
      type(card_t), intent(in) :: card      !< the card naming the line
      character(len=*), intent(in) :: name  !< line name, upper case
      type(model_t), intent(in) :: model    !< model with all lines
      integer, intent(out) :: iline         !< index of the line
      integer, intent(in) :: node           !< end_a, end_b or node number
      type(error_t), intent(inout) :: err   !< status
      integer :: nn

      call find_named(card, 'LINE', name, model%lines%name, 'LINE', iline, err)
      if (iline == 0) return
      nn = node_count(model%lines(iline))
      if (node > nn) then
         call param_fail(card, 'NODE', 'NODE '//int_str(node)//' is beyond the last node'// &
                         ' of line '//trim(name)//' ('//int_str(nn)//')', err)
      end if
   end subroutine resolve_line

   !> Find the section named by SECTION= of a *LINE or *SEGMENT card.
   subroutine resolve_section(card, name, model, isec, err)
      type(card_t), intent(in) :: card      !< the card naming the section
      character(len=*), intent(in) :: name  !< section name, upper case
      type(model_t), intent(in) :: model    !< model with all sections
      integer, intent(out) :: isec          !< index of the section (0 if not found)
      type(error_t), intent(inout) :: err   !< status
      call find_named(card, 'SECTION', name, model%sections%name, 'SECTION', isec, err)
   end subroutine resolve_section

   !> Index of `name` among `names`; 0 if absent, an error at parameter param: "PARAM
   !> 'NAME' is not defined (no *KEYWORD with NAME=NAME in the deck)".
   subroutine find_named(card, param, name, names, keyword, k, err)
      type(card_t), intent(in) :: card          !< the card naming it
      character(len=*), intent(in) :: param     !< the parameter naming it
      character(len=*), intent(in) :: name      !< the name, upper case
      character(len=*), intent(in) :: names(:)  !< the names defined
      character(len=*), intent(in) :: keyword   !< the keyword defining them
      integer, intent(out) :: k                 !< index of the name in names (0: none)
      type(error_t), intent(inout) :: err       !< status
      k = findloc(names == name, .true., dim=1)
      if (k == 0) call param_fail(card, param, param//" '"//name//"' is not defined (no *"// &
                                  keyword//' with NAME='//name//' in the deck)', err)
   end subroutine find_named

   !> NAME= of card ic, which defines a named item (a section, line, amplitude, body or
   !> point): required, and not the name of an earlier item of its kind ("<what> 'NAME' is
   !> already defined (at FILE:LINE)", at the NAME= parameter when at_name is given).
   subroutine get_item_name(deck, ic, names, cards, what, name, err, at_name)
      type(deck_t), intent(in) :: deck         !< all cards
      integer, intent(in) :: ic                !< index of the card
      character(len=*), intent(in) :: names(:) !< the names of the earlier items
      integer, intent(in) :: cards(:)          !< the card of each earlier item
      character(len=*), intent(in) :: what     !< the kind of item, 'section', ...
      character(len=:), allocatable, intent(inout) :: name !< the name, upper case
      type(error_t), intent(inout) :: err      !< status
      logical, intent(in), optional :: at_name !< report at NAME= (else the keyword line)
      integer :: j
      call card_get_name(deck%cards(ic), 'NAME', name, err, required=.true.)
      if (has_error(err)) return
      j = findloc(names == name, .true., dim=1)
      if (j == 0) return
      if (present(at_name)) then
         call param_fail(deck%cards(ic), 'NAME', what//" '"//name//"' is already defined"// &
                         ' (at '//location(deck, cards(j))//')', err)
      else
         call card_error(deck%cards(ic), what//" '"//name//"' is already defined (at "// &
                         location(deck, cards(j))//')', err)
      end if
   end subroutine get_item_name

   !> Refuse item k of a list of node items (*BOUNDARY, *MOTION) at the node of an
   !> earlier item on the same line: 'line L node N already has a *KEYWORD (at ...)'.
   subroutine check_node_once(deck, model, lines, nodes, cards, k, keyword, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(model_t), intent(in) :: model      !< model with the lines
      integer, intent(in) :: lines(:)         !< line of each item (0: on no line)
      integer, intent(in) :: nodes(:)         !< stored node of each item (end_a, end_b, k)
      integer, intent(in) :: cards(:)         !< card of each item
      integer, intent(in) :: k                !< item to check
      character(len=*), intent(in) :: keyword !< keyword of the items
      type(error_t), intent(inout) :: err     !< status
      integer :: j, nn, node

      if (lines(k) == 0) return
      nn = node_count(model%lines(lines(k)))
      node = node_number(nodes(k), nn)
      do j = 1, k - 1
         if (lines(j) /= lines(k) .or. node_number(nodes(j), nn) /= node) cycle
         call card_error(deck%cards(cards(k)), 'line '//trim(model%lines(lines(k))%name)// &
                         ' '//node_label(node, nn)//' already has a *'//keyword//' (at '// &
                         location(deck, cards(j))//')', err)
         return
      end do
   end subroutine check_node_once

   !> Number of nodes of a line: ELEMENTS*ORDER + 1.
   pure integer function node_count(line) result(nn)
      type(line_def_t), intent(in) :: line  !< the line
      nn = line%n_elements*line%order + 1
   end function node_count

   !> Node number 1..nn of a stored node (end_a, end_b or k).
   pure integer function node_number(node, nn) result(k)
      integer, intent(in) :: node  !< end_a, end_b or a node number
      integer, intent(in) :: nn    !< number of nodes of the line
      if (node == end_b) then
         k = nn
      else
         k = node     ! end_a is node 1
      end if
   end function node_number

   !> 'node 1 (end A)', 'node 31 (end B)' or 'node 7'.
   function node_label(node, nn) result(s)
      integer, intent(in) :: node         !< node number 1..nn
      integer, intent(in) :: nn           !< number of nodes of the line
      character(len=:), allocatable :: s  !< the label
      s = 'node '//int_str(node)
      if (node == 1) s = s//' (end A)'
      if (node == nn) s = s//' (end B)'
   end function node_label

end module rodyn_deck_support
