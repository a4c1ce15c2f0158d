!> Deck reader of the rigid bodies of a mooring system (*BODY, *BODY HYDROSTATICS) and
!> their whole-deck checks: the points on a body (*POINT, TYPE=BODY) and the loads on it
!> (*LOAD, BODY=) name a body of the deck, a point sits within reach of its body, a
!> FREE body has mass and inertia, its volume needs *WATER (docs/deck.md, *BODY;
!> docs/systems.md).
module rodyn_deck_body
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, body_t, body_fixed, body_free, body_kind_names, &
                          point_body, modal_solver_names
   use rodyn_deck_lexer, only: deck_t
   use rodyn_deck_card, only: card_t, card_check_params, card_find_param, card_error, &
                              card_data_error, card_check_data, param_len
   use rodyn_deck_card_values, only: card_get_name, card_get_choice, card_data_reals, &
                                     card_get_real, card_get_int
   use rodyn_deck_numbers, only: real_str, int_str
   use rodyn_banded, only: dense_sym_eigen
   use rodyn_deck_support, only: ref_t, pending_t, reading_t, get_item_name, &
                                 body_subcards, sub_drag, max_distance, &
                                 get_bounded, param_fail, location, check_card, get_int_range, &
                                 get_host, &
                                 find_named
   implicit none
   private
   public :: read_body_card, read_body_hydrostatics_card, read_body_added_mass_card
   public :: read_offset_curve_card, resolve_offset_curve, read_modal_card, check_modal
   public :: find_body, body_of_card, body_card_once
   public :: resolve_point_bodies, &
             resolve_load_bodies, check_bodies

   !> a point farther from its body's reference point than this many radii of gyration
   !> (sqrt(I_max / MASS)) is taken for a mistake (a global position given in body axes)
   real(wp), parameter :: reach_radii = 50.0_wp

contains

   !> *BODY, NAME=, TYPE=FIXED|FREE [, MASS=] [, VOLUME=] [, HOST=]; four data lines of 3
   !> values: the reference point R at the start (global), G and B (body axes from R), and
   !> the inertia Ixx, Iyy, Izz about G (body axes). A FREE body needs MASS > 0 and
   !> inertia; HOST=YES only a FIXED one.
   subroutine read_body_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model: one body appended
      type(error_t), intent(inout) :: err     !< status
      character(len=*), parameter :: what(4) = [character(len=40) :: 'xR, yR, zR', &
         'xG, yG, zG (body axes from R)', 'xB, yB, zB (body axes from R)', 'Ixx, Iyy, Izz']
      type(body_t) :: b
      character(len=:), allocatable :: name
      real(wp) :: v(3, 4)
      integer :: k

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         call card_check_params(card, [character(len=param_len) :: 'NAME', 'TYPE', 'MASS', &
                                'VOLUME', 'HOST'], err)
         call get_item_name(deck, ic, model%bodies(1:pend%n_bodies)%name, &
                            pend%body_card(1:pend%n_bodies), 'body', name, err)
         if (has_error(err)) return
         b%name = name
         b%card_at = card%file//':'//int_str(card%line)
         call card_get_choice(card, 'TYPE', body_kind_names, b%kind, err, listed=.true.)
         call get_host(card, b%kind == body_fixed, 'body', b%host, err)
         call get_bounded(card, 'MASS', b%mass, .false., err)
         call get_bounded(card, 'VOLUME', b%volume, .false., err)
         call card_check_data(card, 4, 4, err, trim(what(min(card%n_data + 1, 4))))
         if (has_error(err)) return
         do k = 1, 4
            call card_data_reals(card, k, 3, v(:, k), err, trim(what(k)))
            if (has_error(err)) return
         end do
         if (maxval(abs(v(:, 1:3))) > max_distance) then
            call card_error(card, 'a coordinate of '//real_str(maxval(abs(v(:, 1:3))))// &
                            ' m is not physical: within '//real_str(max_distance)// &
                            ' m of the origin', err)
            return
         end if
         b%position = v(:, 1)
         b%cog = v(:, 2)
         b%cob = v(:, 3)
         b%inertia = v(:, 4)
         if (b%kind == body_free) call check_free_body(card, b, err)
         if (has_error(err)) return
         pend%n_bodies = pend%n_bodies + 1
         model%bodies(pend%n_bodies) = b
         pend%body_card(pend%n_bodies) = ic
         pend%body_sub(:, pend%n_bodies) = 0
      end associate
   end subroutine read_body_card

   !> A FREE body has inertia: MASS > 0, Ixx, Iyy, Izz > 0, each at most the sum of the
   !> other two (the inertia of a real body).
   subroutine check_free_body(card, b, err)
      type(card_t), intent(in) :: card      !< the *BODY card
      type(body_t), intent(in) :: b         !< the body
      type(error_t), intent(inout) :: err   !< status
      integer :: i
      if (.not. b%mass > 0.0_wp) then
         call card_error(card, 'a FREE body needs MASS > 0 (its inertia), got '// &
                         real_str(b%mass), err)
         return
      end if
      if (.not. all(b%inertia > 0.0_wp)) then
         call card_data_error(card, 4, 'a FREE body needs Ixx, Iyy, Izz > 0', err)
         return
      end if
      do i = 1, 3
         if (b%inertia(i) <= (sum(b%inertia) - b%inertia(i))*(1.0_wp + 1.0e-12_wp)) cycle
         call card_data_error(card, 4, 'no body has these inertias: each of Ixx, Iyy, '// &
                              'Izz is at most the sum of the other two', err)
         return
      end do
   end subroutine check_free_body

   !> *BODY HYDROSTATICS, BODY=name: 6 data lines of 6 values, the waterplane restoring
   !> matrix C about the body's reference point (rows: force x, y, z and moment x, y, z;
   !> columns: x, y, z and rotations x, y, z of R) [N/m, N, N m/m, N m/rad]; *BODY
   !> DAMPING, BODY=name: the linear damping matrix B about R likewise, on R's velocity
   !> and the angular velocity [N s/m, N s, N m s/m, N m s/rad]. After the *BODY card;
   !> one of each per body.
   subroutine read_body_hydrostatics_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< the body's matrix set
      type(error_t), intent(inout) :: err     !< status
      character(len=:), allocatable :: name
      real(wp) :: mat(6, 6)
      integer :: ib

      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend)
         call body_of_card(deck, ic, model, pend, [character(len=param_len) :: 'BODY'], name, &
                           ib, err)
         if (has_error(err)) return         ! (name is not set)
         call body_card_once(deck, ic, pend, name, ib, err)
         call read_matrix6(deck%cards(ic), 'C(k,1), ..., C(k,6)', mat, err)
         if (has_error(err)) return
         if (deck%cards(ic)%keyword == 'BODY DAMPING') model%bodies(ib)%damping = mat
         if (deck%cards(ic)%keyword /= 'BODY DAMPING') model%bodies(ib)%hydrostatic = mat
      end associate
   end subroutine read_body_hydrostatics_card

   !> *BODY ADDED MASS, BODY=name: one data line A11, A22, A33 [kg] (translations of G),
   !> A44, A55, A66 [kg m2] (rotations about G), body axes, each >= 0. After the *BODY
   !> card; one per body.
   subroutine read_body_added_mass_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< the body's added mass or drag set
      type(error_t), intent(inout) :: err     !< status
      character(len=:), allocatable :: name, what
      real(wp) :: a(6)
      integer :: ib, form
      logical :: drag
      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic))
         drag = card%keyword == 'BODY DRAG'
         what = merge('CdA1, CdA2, CdA3, Cr1, Cr2, Cr3', 'A11, A22, A33, A44, A55, A66   ', &
                      drag)
         what = trim(what)
         call body_of_card(deck, ic, model, pend, [character(len=param_len) :: 'BODY', &
                           merge('BODY', 'FORM', drag)], name, ib, err)
         if (has_error(err)) return         ! (name is not set)
         form = 1
         if (.not. drag) call card_get_choice(card, 'FORM', [character(len=8) :: &
                                              'DIAGONAL', 'MATRIX'], form, err)
         call body_card_once(deck, ic, pend, name, ib, err)
         if (has_error(err)) return
         if (form == 2) then
            call read_added_matrix(card, model%bodies(ib)%added_matrix, err)
            return
         end if
         call card_check_data(card, 1, 1, err, what)
         call card_data_reals(card, 1, 6, a, err, what)
         if (has_error(err)) return
         if (.not. all(a >= 0.0_wp)) then
            call card_data_error(card, 1, merge('a drag coefficient is negative         ', &
                                                'an added mass or inertia is negative   ', &
                                                drag), err)
            err%message = trim(err%message)
            return
         end if
         if (drag) model%bodies(ib)%drag = a
         if (.not. drag) model%bodies(ib)%added_mass = a
      end associate
   end subroutine read_body_added_mass_card

   !> *BODY ADDED MASS, FORM=MATRIX: 6 data lines of 6 values, the added mass about R in
   !> body axes (docs/theory.md eq. (152)); symmetric to 1e-9 of its largest entry and
   !> positive semi-definite (its eigenvalues above -1e-9 of the largest, dense_sym_eigen).
   subroutine read_added_matrix(card, a, err)
      type(card_t), intent(in) :: card        !< the card
      real(wp), intent(out) :: a(6, 6)        !< the matrix [kg, kg m, kg m2]
      type(error_t), intent(inout) :: err     !< status
      real(wp) :: k(6, 6), m(6, 6), lam(6), big
      integer :: i, j
      call read_matrix6(card, 'A(i,1), ..., A(i,6)', a, err)
      if (has_error(err)) return
      big = maxval(abs(a))
      do i = 2, 6
         do j = 1, i - 1
            if (abs(a(i, j) - a(j, i)) <= 1.0e-9_wp*big) cycle
            call card_data_error(card, i, 'the added mass is not symmetric: A('// &
                                 int_str(i)//','//int_str(j)//') = '//real_str(a(i, j))// &
                                 ', A('//int_str(j)//','//int_str(i)//') = '// &
                                 real_str(a(j, i)), err)
            return
         end do
      end do
      k = 0.5_wp*(a + transpose(a))
      m = 0.0_wp
      do i = 1, 6
         m(i, i) = 1.0_wp
      end do
      call dense_sym_eigen(k, m, lam, err)
      if (has_error(err)) return
      if (minval(lam) < -1.0e-9_wp*max(maxval(abs(lam)), tiny(1.0_wp))) &
         call card_error(card, 'the added mass is not positive semi-definite (an '// &
                         'eigenvalue '//real_str(minval(lam))//'): a motion would lower '// &
                         'the kinetic energy', err)
   end subroutine read_added_matrix

   !> A 6 x 6 matrix as the card's 6 data lines of 6 values (0 on an error).
   subroutine read_matrix6(card, what, mat, err)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: what    !< names of a row's values
      real(wp), intent(out) :: mat(6, 6)      !< the matrix, by rows
      type(error_t), intent(inout) :: err     !< status
      real(wp) :: row(6)
      integer :: i
      mat = 0.0_wp
      call card_check_data(card, 6, 6, err, 'row of 6 values')
      if (has_error(err)) return
      do i = 1, 6
         call card_data_reals(card, i, 6, row, err, what)
         if (has_error(err)) return
         mat(i, :) = row
      end do
   end subroutine read_matrix6

   !> *OFFSET CURVE, BODY=name, FORCE=F [, HEADING=deg] [, STEPS=n]: after the statics, a
   !> horizontal force at the body's R towards HEADING raised to F in n steps (1 to 1000,
   !> default 10). At most one; the body is resolved with the whole deck.
   subroutine read_offset_curve_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< the curve's parameters set
      type(error_t), intent(inout) :: err     !< status
      character(len=:), allocatable :: name
      real(wp) :: deg
      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic), oc => model%offset_curve)
         call check_card(deck, ic, [character(len=param_len) :: 'BODY', 'FORCE', 'HEADING', &
                         'STEPS'], 0, 0, err, first=pend%offset_card)
         call card_get_name(card, 'BODY', name, err, required=.true.)
         call get_bounded(card, 'FORCE', oc%force, .true., err, required=.true.)
         if (has_error(err)) return
         deg = 0.0_wp
         call card_get_real(card, 'HEADING', deg, err)
         oc%heading = deg*acos(-1.0_wp)/180.0_wp
         call get_int_range(card, 'STEPS', 1, 1000, oc%steps, err)
         if (has_error(err)) return
         pend%offset_body = ref_t(name, ic)
      end associate
   end subroutine read_offset_curve_card

   !> The body of *OFFSET CURVE: it exists and is FREE.
   subroutine resolve_offset_curve(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< its card and BODY=
      type(model_t), intent(inout) :: model   !< the curve's body set
      type(error_t), intent(inout) :: err     !< status
      if (pend%offset_card == 0) return
      associate (card => deck%cards(pend%offset_card))
         call find_body(card, 'BODY', pend%offset_body%name, model, &
                        model%offset_curve%body, err)
         if (has_error(err)) return
         if (model%bodies(model%offset_curve%body)%kind /= body_free) &
            call param_fail(card, 'BODY', "body '"//pend%offset_body%name//"' is FIXED: it"// &
                            ' has no offset', err)
      end associate
   end subroutine resolve_offset_curve

   !> The body of a card that belongs to one (BODY=name, keyword in body_subcards): only
   !> the parameters `allowed`, and a body defined above the card.
   subroutine body_of_card(deck, ic, model, pend, allowed, name, ib, err)
      type(deck_t), intent(in) :: deck           !< all cards
      integer, intent(in) :: ic                  !< index of the card
      type(model_t), intent(in) :: model         !< model with the bodies read so far
      type(pending_t), intent(in) :: pend        !< how many
      character(len=*), intent(in) :: allowed(:) !< allowed parameters, upper case
      character(len=:), allocatable, intent(out) :: name !< the body's name
      integer, intent(out) :: ib                 !< the body's index
      type(error_t), intent(inout) :: err        !< status
      ib = 0
      call card_check_params(deck%cards(ic), allowed, err)
      call card_get_name(deck%cards(ic), 'BODY', name, err, required=.true.)
      if (has_error(err)) return
      do ib = 1, pend%n_bodies
         if (model%bodies(ib)%name == name) return
      end do
      call param_fail(deck%cards(ic), 'BODY', "BODY '"//name//"' is not defined above (a"// &
                      ' *BODY card with NAME='//name//' comes first)', err)
   end subroutine body_of_card

   !> Refuse a second card of the same keyword (in body_subcards) for body ib; remember
   !> card ic as the body's.
   subroutine body_card_once(deck, ic, pend, name, ib, err)
      type(deck_t), intent(in) :: deck        !< all cards
      integer, intent(in) :: ic               !< index of the card
      type(pending_t), intent(inout) :: pend  !< the card of each body's keyword
      character(len=*), intent(in) :: name    !< the body's name
      integer, intent(in) :: ib               !< the body's index
      type(error_t), intent(inout) :: err     !< status
      integer :: k
      if (has_error(err)) return
      k = findloc(body_subcards == deck%cards(ic)%keyword, .true., dim=1)
      if (pend%body_sub(k, ib) > 0) then
         call card_error(deck%cards(ic), "body '"//name//"' already has its *"// &
                         deck%cards(ic)%keyword//' (at '//location(deck, pend%body_sub(k, ib))// &
                         ')', err)
         return
      end if
      pend%body_sub(k, ib) = ic
   end subroutine body_card_once
   !> The body of each BODY point: it exists; the point lies within reach of it
   !> (reach_radii radii of gyration); its global position at the start is R + offset.
   subroutine resolve_point_bodies(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< BODY= of each point
      type(model_t), intent(inout) :: model   !< points get their body and position
      type(error_t), intent(inout) :: err     !< status
      integer :: ip, ib
      real(wp) :: radius
      do ip = 1, size(model%points)
         associate (pt => model%points(ip), card => deck%cards(pend%point_card(ip)))
            if (pt%kind /= point_body) cycle
            call find_body(card, 'BODY', pend%point_body(ip)%name, model, ib, err)
            if (has_error(err)) return
            pt%body = ib
            pt%global = model%bodies(ib)%position + pt%position
            associate (b => model%bodies(ib))
               if (b%kind /= body_free) cycle
               radius = sqrt(maxval(b%inertia)/b%mass)
               if (norm2(pt%position - b%cog) <= reach_radii*radius) cycle
               call card_data_error(card, 1, 'the point is '// &
                                    real_str(norm2(pt%position - b%cog))//' m from the'// &
                                    ' centre of gravity of body '//trim(b%name)//', '// &
                                    'more than 50 radii of gyration ('// &
                                    real_str(reach_radii*radius)//' m): give it in the'// &
                                    " body's axes, from its reference point", err)
               return
            end associate
         end associate
      end do
   end subroutine resolve_point_bodies

   !> The body of a *LOAD given with BODY=: it exists and is FREE.
   subroutine resolve_load_bodies(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< BODY= of each load ('' if none)
      type(model_t), intent(inout) :: model   !< loads get their body
      type(error_t), intent(inout) :: err     !< status
      integer :: k
      do k = 1, size(model%loads)
         associate (card => deck%cards(pend%load_body(k)%card))
            if (len(pend%load_body(k)%name) == 0) cycle
            call find_body(card, 'BODY', pend%load_body(k)%name, model, &
                           model%loads(k)%body, err)
            if (has_error(err)) return
            if (model%bodies(model%loads(k)%body)%kind == body_free) cycle
            call param_fail(card, 'BODY', "body '"//pend%load_body(k)%name//"' is FIXED: "// &
                            'a load on it acts on nothing', err)
            return
         end associate
      end do
   end subroutine resolve_load_bodies

   !> Body ib named `name` by parameter `param` of `card`.
   subroutine find_body(card, param, name, model, ib, err)
      type(card_t), intent(in) :: card      !< the referring card
      character(len=*), intent(in) :: param !< its parameter
      character(len=*), intent(in) :: name  !< body name
      type(model_t), intent(in) :: model    !< model with its bodies
      integer, intent(out) :: ib            !< the body's index
      type(error_t), intent(inout) :: err   !< status
      call find_named(card, param, name, model%bodies%name, 'BODY', ib, err)
   end subroutine find_body

   !> A body's VOLUME and its *BODY DRAG need *WATER.
   subroutine check_bodies(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< card of each body
      type(model_t), intent(inout) :: model      !< model
      type(error_t), intent(inout) :: err     !< status
      integer :: ib
      if (model%water%present) return
      do ib = 1, size(model%bodies)
         if (pend%body_sub(sub_drag, ib) > 0) then
            call card_error(deck%cards(pend%body_sub(sub_drag, ib)), 'a body''s drag needs'// &
                            ' *WATER (no *WATER in the deck)', err)
            return
         end if
         if (.not. model%bodies(ib)%volume > 0.0_wp) cycle
         call param_fail(deck%cards(pend%body_card(ib)), 'VOLUME', 'VOLUME > 0 needs'// &
                         ' *WATER (no *WATER in the deck)', err)
         return
      end do
   end subroutine check_bodies

   !> *MODAL [, MODES=n] [, SOLVER=AUTO|DENSE|LANCZOS]: after the statics, the n (1 to
   !> 1000, default 10) longest natural periods of the whole system about its equilibrium
   !> and their shapes. At most one.
   subroutine read_modal_card(rd, model, err)
      type(reading_t), intent(inout) :: rd    !< the cards, the card read, the records
      type(model_t), intent(inout) :: model   !< model%modal set
      type(error_t), intent(inout) :: err     !< status
      integer :: k
      associate (deck => rd%deck, ic => rd%ic, pend => rd%pend, &
                 card => rd%deck%cards(rd%ic), mo => model%modal)
         call check_card(deck, ic, [character(len=param_len) :: 'MODES', 'SOLVER'], 0, 0, err, &
                         first=pend%modal_card)
         call get_int_range(card, 'MODES', 1, 1000, mo%modes, err)
         if (has_error(err)) return
         k = mo%solver + 1              ! (choices from 1; the names from 0)
         call card_get_choice(card, 'SOLVER', modal_solver_names, k, err)
         if (has_error(err)) return
         mo%solver = k - 1
         mo%requested = .true.
      end associate
   end subroutine read_modal_card

   !> *MODAL is about the static equilibrium: a deck whose dynamics start from the
   !> defined shape without *STATIC has none.
   subroutine check_modal(deck, pend, model, err)
      type(deck_t), intent(in) :: deck        !< all cards
      type(pending_t), intent(in) :: pend     !< the card of *MODAL
      type(model_t), intent(inout) :: model      !< model
      type(error_t), intent(inout) :: err     !< status
      if (pend%modal_card == 0) return
      if (model%dynamic%requested .and. .not. model%dynamic%start_static .and. &
          .not. model%static%requested) &
         call card_error(deck%cards(pend%modal_card), 'the modal analysis needs the '// &
                        'static equilibrium, and the dynamics start from the defined shape '// &
                        'without *STATIC: add *STATIC or START=STATIC', err)
   end subroutine check_modal
end module rodyn_deck_body
