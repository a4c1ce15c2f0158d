!> Deck lexer, the values of a card, the readers' toolkit: a parameter as a real, an
!> integer, a name, a text, a file path, a choice from a list or YES/NO; the reals of a
!> data line. Each helper reports its own errors, located at the parameter or data line
!> (rodyn_deck_card), and leaves the value unchanged when the parameter is absent. A
!> helper called with an error already in err does nothing: a reader's calls chain, and
!> the first error stands.
module rodyn_deck_card_values
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: name_len
   use rodyn_deck_params, only: upper_case
   use rodyn_deck_numbers, only: parse_real, parse_int, int_str, fields_reals, field_real
   use rodyn_deck_files, only: dir_of
   use rodyn_deck_card, only: card_t, card_find_param, card_error, card_param_error, &
                              card_data_error, card_data_count
   implicit none
   private
   public :: card_get_real, card_get_int, card_get_name, card_get_text, card_get_file
   public :: card_get_choice, card_get_yesno, card_data_reals, card_data_real

contains

   !> Find parameter `name` and check it has a value. ip = 0 when absent (an error if
   !> required), when it has no value (always an error) or when err holds an error.
   subroutine find_valued(card, name, ip, err, required, found)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name, upper case
      integer, intent(out) :: ip              !< index of the parameter, 0 if unusable
      type(error_t), intent(inout) :: err     !< status
      logical, intent(in), optional :: required !< absence is an error
      logical, intent(out), optional :: found !< set .false. (the getter sets it .true.)
      ip = 0
      if (present(found)) found = .false.
      if (has_error(err)) return
      ip = card_find_param(card, name)
      if (ip == 0) then
         if (present(required)) then
            if (required) call card_error(card, 'missing parameter '//name, err)
         end if
      else if (.not. card%params(ip)%has_value) then
         call card_param_error(card, ip, 'parameter '//name//' needs a value ('// &
                               name//'=...)', err)
         ip = 0
      end if
   end subroutine find_valued

   !> Get a real parameter. Left unchanged when absent.
   subroutine card_get_real(card, name, value, err, found, required)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name, upper case
      real(wp), intent(inout) :: value        !< the value (unchanged if absent)
      type(error_t), intent(inout) :: err     !< status
      logical, intent(out), optional :: found !< the parameter was given
      logical, intent(in), optional :: required !< absence is an error
      call get_number(card, name, err, found, required, r=value)
   end subroutine card_get_real

   !> Get an integer parameter ('10.5' and '1e3' are refused). Unchanged when absent.
   subroutine card_get_int(card, name, value, err, found, required)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name, upper case
      integer, intent(inout) :: value         !< the value (unchanged if absent)
      type(error_t), intent(inout) :: err     !< status
      logical, intent(out), optional :: found !< the parameter was given
      logical, intent(in), optional :: required !< absence is an error
      call get_number(card, name, err, found, required, i=value)
   end subroutine card_get_int

   !> Get a number parameter: a real into r, or an integer into i. Unchanged when absent.
   subroutine get_number(card, name, err, found, required, r, i)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name, upper case
      type(error_t), intent(inout) :: err     !< status
      logical, intent(out), optional :: found !< the parameter was given
      logical, intent(in), optional :: required !< absence is an error
      real(wp), intent(inout), optional :: r  !< the real (unchanged if absent)
      integer, intent(inout), optional :: i   !< the integer (unchanged if absent)
      character(len=:), allocatable :: msg
      real(wp) :: x
      integer :: ip, k

      call find_valued(card, name, ip, err, required, found)
      if (ip == 0) return
      if (present(r)) call parse_real(card%params(ip)%value, x, msg)
      if (present(i)) call parse_int(card%params(ip)%value, k, msg)
      if (len(msg) > 0) then
         call card_param_error(card, ip, name//': '//msg, err)
         return
      end if
      if (present(r)) r = x
      if (present(i)) i = k
      if (present(found)) found = .true.
   end subroutine get_number

   !> Get the raw text of a parameter (case kept), e.g. a file path. Unchanged if absent.
   subroutine card_get_text(card, name, value, err, found, required)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name, upper case
      character(len=:), allocatable, intent(inout) :: value !< the text
      type(error_t), intent(inout) :: err     !< status
      logical, intent(out), optional :: found !< the parameter was given
      logical, intent(in), optional :: required !< absence is an error
      integer :: ip

      call find_valued(card, name, ip, err, required, found)
      if (ip == 0) return
      value = card%params(ip)%value
      if (present(found)) found = .true.
   end subroutine card_get_text

   !> Get a file path (INPUT=path): double quotes around it are dropped, and a relative
   !> path is taken from the folder of the file holding the card. Unchanged when absent.
   subroutine card_get_file(card, name, path, err, found, required)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name, upper case
      character(len=:), allocatable, intent(inout) :: path !< the path to open
      type(error_t), intent(inout) :: err     !< status
      logical, intent(out), optional :: found !< the parameter was given
      logical, intent(in), optional :: required !< absence is an error
      character(len=:), allocatable :: v
      logical :: given

      if (present(found)) found = .false.
      call card_get_text(card, name, v, err, given, required)
      if (.not. given) return
      if (len(v) >= 2) then          ! INPUT="path" : quotes are not part of the path
         if (v(1:1) == '"' .and. v(len(v):len(v)) == '"') v = v(2:len(v) - 1)
      end if
      if (len(v) == 0) then
         call card_param_error(card, card_find_param(card, name), 'parameter '//name// &
                               ' needs a value ('//name//'=...)', err)
         return
      end if
      if (v(1:1) == '/') then
         path = v
      else
         path = dir_of(card%file)//v
      end if
      if (present(found)) found = .true.
   end subroutine card_get_file

   !> Get a name (of a section or line): upper-cased, at most name_len characters of
   !> letters, digits, '_', '-' and '.'. Unchanged when absent.
   subroutine card_get_name(card, name, value, err, found, required)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name, upper case
      character(len=:), allocatable, intent(inout) :: value !< the name, upper case
      type(error_t), intent(inout) :: err     !< status
      logical, intent(out), optional :: found !< the parameter was given
      logical, intent(in), optional :: required !< absence is an error
      character(len=:), allocatable :: v
      integer :: ip

      call find_valued(card, name, ip, err, required, found)
      if (ip == 0) return
      v = upper_case(card%params(ip)%value)
      if (len(v) > name_len) then
         call card_param_error(card, ip, name//" '"//v//"' is longer than "// &
                               int_str(name_len)//' characters', err)
         return
      end if
      if (verify(v, 'ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.') /= 0) then
         call card_param_error(card, ip, name//" '"//v//"' may contain only letters, "// &
                               "digits, '_', '-' and '.'", err)
         return
      end if
      value = v
      if (present(found)) found = .true.
   end subroutine card_get_name

   !> Get a parameter whose value is one of `choices` (case-insensitive).
   !> index = position in choices; unchanged when absent. With `listed`, a missing
   !> parameter is an error naming the choices.
   subroutine card_get_choice(card, name, choices, index, err, found, required, listed)
      type(card_t), intent(in) :: card          !< the card
      character(len=*), intent(in) :: name      !< parameter name, upper case
      character(len=*), intent(in) :: choices(:) !< allowed values, upper case
      integer, intent(inout) :: index           !< position of the value in choices
      type(error_t), intent(inout) :: err       !< status
      logical, intent(out), optional :: found   !< the parameter was given
      logical, intent(in), optional :: required !< absence is an error
      logical, intent(in), optional :: listed   !< absence is an error naming the choices
      character(len=:), allocatable :: v
      integer :: ip, k

      if (present(listed) .and. card_find_param(card, name) == 0 .and. .not. has_error(err)) &
         call card_error(card, 'missing parameter '//name//' ('//list()//')', err)
      call find_valued(card, name, ip, err, required, found)
      if (ip == 0) return
      v = upper_case(card%params(ip)%value)
      do k = 1, size(choices)
         if (choices(k) == v) then
            index = k
            if (present(found)) found = .true.
            return
         end if
      end do
      call card_param_error(card, ip, name//' must be '//list()//", got '"// &
                            card%params(ip)%value//"'", err)
   contains
      !> The choices as 'A, B or C' (formed only for a message).
      function list() result(s)
         character(len=:), allocatable :: s  !< the list
         integer :: j
         s = trim(choices(1))
         do j = 2, size(choices) - 1
            s = s//', '//trim(choices(j))
         end do
         if (size(choices) > 1) s = s//' or '//trim(choices(size(choices)))
      end function list
   end subroutine card_get_choice

   !> Get a YES/NO parameter. Unchanged when absent.
   subroutine card_get_yesno(card, name, value, err, found)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name, upper case
      logical, intent(inout) :: value         !< .true. for YES
      type(error_t), intent(inout) :: err     !< status
      logical, intent(out), optional :: found !< the parameter was given
      integer :: k
      logical :: given

      k = 0
      call card_get_choice(card, name, [character(len=3) :: 'YES', 'NO'], k, err, given)
      if (given) value = k == 1
      if (present(found)) found = given
   end subroutine card_get_yesno

   !> Parse exactly n reals from data line `id`. `what` names the values,
   !> comma-separated (e.g. 'EA, EI1, EI2, GJ, MASS'), for the messages.
   subroutine card_data_reals(card, id, n, values, err, what)
      type(card_t), intent(in) :: card        !< the card
      integer, intent(in) :: id               !< index of the data line
      integer, intent(in) :: n                !< number of values expected
      real(wp), intent(out) :: values(n)      !< the values
      type(error_t), intent(inout) :: err     !< status
      character(len=*), intent(in), optional :: what !< names of the values
      character(len=:), allocatable :: msg, names

      if (has_error(err)) return
      names = ''
      if (present(what)) names = what
      call fields_reals(card%data(id)%fields, values, names, msg)
      if (len(msg) > 0) call card_data_error(card, id, msg, err)
   end subroutine card_data_reals

   !> Parse value k of data line `id` as a real (the line may hold other kinds of
   !> values; its number of values is checked by the caller).
   subroutine card_data_real(card, id, k, value, err, what)
      type(card_t), intent(in) :: card        !< the card
      integer, intent(in) :: id               !< index of the data line
      integer, intent(in) :: k                !< which value of the line
      real(wp), intent(out) :: value          !< the value
      type(error_t), intent(inout) :: err     !< status
      character(len=*), intent(in), optional :: what !< names of the values of the line
      character(len=:), allocatable :: msg, names

      if (has_error(err)) return
      names = ''
      if (present(what)) names = what
      call field_real(card%data(id)%fields(k)%s, k, card_data_count(card, id), names, &
                      value, msg)
      if (len(msg) > 0) call card_data_error(card, id, msg, err)
   end subroutine card_data_real

end module rodyn_deck_card_values
