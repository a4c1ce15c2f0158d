!> Deck lexer, a card: one keyword line (`*KEYWORD, PARAM=value, ...`) with its
!> parameters and the data lines that follow it, each remembering the file and line it
!> came from (card_t); the located messages of the readers, 'FILE:LINE: error:
!> *KEYWORD: message' (card_error, card_param_error, card_data_error, card_file_error);
!> the checks of a card's parameter names and number of data lines.
module rodyn_deck_card
   use rodyn_error, only: error_t, set_error, stat_input, has_error
   use rodyn_deck_text, only: field_t
   use rodyn_deck_numbers, only: int_str
   implicit none
   private
   public :: param_t, data_line_t, card_t, param_len
   public :: card_where, card_error, card_param_error, card_data_error, card_file_error
   public :: card_check_params, card_find_param, card_check_data, card_data_count

   integer, parameter :: param_len = 24         !< length for lists of parameter names

   !> One `NAME=value` parameter of a keyword line.
   type :: param_t
      character(len=:), allocatable :: name  !< upper case, blanks collapsed
      character(len=:), allocatable :: value !< text after '=', trimmed ('' if none)
      logical :: has_value = .false.         !< a non-empty value was given
      integer :: line = 0                    !< line number in the card's file
   end type param_t

   !> One data line, split at commas.
   type :: data_line_t
      integer :: line = 0                       !< line number in the card's file
      character(len=:), allocatable :: text     !< the whole line, trimmed
      type(field_t), allocatable :: fields(:)   !< comma-separated fields, trimmed
   end type data_line_t

   !> One keyword line with its parameters and data lines.
   type :: card_t
      character(len=:), allocatable :: keyword  !< upper case, without the '*'
      character(len=:), allocatable :: file     !< path the file was opened with
      integer :: line = 0                       !< line number of the keyword line
      type(param_t), allocatable :: params(:)   !< parameters, in the order given
      integer :: n_data = 0                     !< number of data lines
      type(data_line_t), allocatable :: data(:) !< data lines 1..n_data (capacity may exceed)
   end type card_t

contains

   !> Location prefix of a message: 'FILE:LINE: error: *KEYWORD: '.
   pure function card_where(card, line) result(s)
      type(card_t), intent(in) :: card   !< the card
      integer, intent(in) :: line        !< line number to name
      character(len=:), allocatable :: s !< the prefix
      s = card%file//':'//int_str(line)//': error: *'//card%keyword//': '
   end function card_where

   !> Report an error located at the card's keyword line.
   subroutine card_error(card, message, err)
      type(card_t), intent(in) :: card      !< the card
      character(len=*), intent(in) :: message !< what is wrong
      type(error_t), intent(inout) :: err   !< status to fill
      call set_error(err, stat_input, card_where(card, card%line)//message)
   end subroutine card_error

   !> Report an error located at the line of parameter `ip`.
   subroutine card_param_error(card, ip, message, err)
      type(card_t), intent(in) :: card      !< the card
      integer, intent(in) :: ip             !< index of the parameter
      character(len=*), intent(in) :: message !< what is wrong
      type(error_t), intent(inout) :: err   !< status to fill
      call set_error(err, stat_input, card_where(card, card%params(ip)%line)//message)
   end subroutine card_param_error

   !> Report an error located at data line `id` of the card.
   subroutine card_data_error(card, id, message, err)
      type(card_t), intent(in) :: card      !< the card
      integer, intent(in) :: id             !< index of the data line
      character(len=*), intent(in) :: message !< what is wrong
      type(error_t), intent(inout) :: err   !< status to fill
      call set_error(err, stat_input, card_where(card, card%data(id)%line)//message)
   end subroutine card_data_error

   !> Report an error located at line `line` of another file read for the card (a table
   !> file): 'FILE:LINE: error: *KEYWORD: message'.
   subroutine card_file_error(card, file, line, message, err)
      type(card_t), intent(in) :: card        !< the card that reads the file
      character(len=*), intent(in) :: file    !< the file, as opened
      integer, intent(in) :: line             !< line number in that file
      character(len=*), intent(in) :: message !< what is wrong
      type(error_t), intent(inout) :: err     !< status to fill
      call set_error(err, stat_input, file//':'//int_str(line)//': error: *'// &
                     card%keyword//': '//message)
   end subroutine card_file_error

   !> Check the parameter names: each must be in `allowed`, and given only once.
   subroutine card_check_params(card, allowed, err)
      type(card_t), intent(in) :: card                 !< the card
      character(len=*), intent(in) :: allowed(:)       !< allowed names, upper case
      type(error_t), intent(inout) :: err              !< status
      character(len=:), allocatable :: list
      integer :: ip, jp, k

      if (has_error(err)) return
      do ip = 1, size(card%params)
         if (.not. any(allowed == card%params(ip)%name)) then
            if (size(allowed) == 0) then
               list = '*'//card%keyword//' takes no parameters'
            else
               list = 'allowed: '//trim(allowed(1))
               do k = 2, size(allowed)
                  list = list//', '//trim(allowed(k))
               end do
            end if
            call card_param_error(card, ip, 'unknown parameter '//card%params(ip)%name// &
                                  ' ('//list//')', err)
            return
         end if
         do jp = 1, ip - 1
            if (card%params(jp)%name == card%params(ip)%name) then
               call card_param_error(card, ip, 'parameter '//card%params(ip)%name// &
                                     ' given twice', err)
               return
            end if
         end do
      end do
   end subroutine card_check_params

   !> Index of parameter `name` in the card, 0 if not given.
   pure integer function card_find_param(card, name) result(ip)
      type(card_t), intent(in) :: card       !< the card
      character(len=*), intent(in) :: name   !< parameter name, upper case
      do ip = 1, size(card%params)
         if (card%params(ip)%name == name) return
      end do
      ip = 0
   end function card_find_param

   !> Check the number of data lines: at least nmin, at most nmax (nmax < 0: no limit).
   subroutine card_check_data(card, nmin, nmax, err, what)
      type(card_t), intent(in) :: card        !< the card
      integer, intent(in) :: nmin             !< fewest data lines needed
      integer, intent(in) :: nmax             !< most data lines allowed, < 0: any
      type(error_t), intent(inout) :: err     !< status
      character(len=*), intent(in), optional :: what !< what the missing line holds
      if (has_error(err)) return
      if (card%n_data < nmin) then
         if (present(what)) then
            call card_error(card, 'missing data line ('//what//')', err)
         else
            call card_error(card, 'missing data line', err)
         end if
      else if (nmax >= 0 .and. card%n_data > nmax) then
         if (nmax == 0) then
            call card_data_error(card, 1, 'data lines are not allowed', err)
         else
            call card_data_error(card, nmax + 1, 'too many data lines (at most '// &
                                 int_str(nmax)//')', err)
         end if
      end if
   end subroutine card_check_data

   !> Number of values on data line `id`.
   pure integer function card_data_count(card, id) result(n)
      type(card_t), intent(in) :: card  !< the card
      integer, intent(in) :: id         !< index of the data line
      n = size(card%data(id)%fields)
   end function card_data_count

end module rodyn_deck_card
