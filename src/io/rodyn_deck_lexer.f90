!> Keyword-deck lexer: turns an Abaqus/Flexcom-style input deck into a list of cards.
!>
!> A card is one keyword line (`*KEYWORD, PARAM=value, ...`) and the data lines that
!> follow it up to the next keyword line. Every card, parameter and data line remembers
!> the file (as the path used to open it) and the line number it came from, so that the
!> keyword readers can report `FILE:LINE: error: *KEYWORD: message`.
!>
!> The lexer handles the general syntax of docs/deck.md: `**` comments, blank lines,
!> case-insensitive names (stored upper case, runs of blanks collapsed to one),
!> trailing commas, blanks around `=` and `,`, and `*INCLUDE, INPUT=path` (path relative
!> to the including file's folder, nested up to max_include_depth levels, cycles
!> refused). It also keeps the full text read for the record (model%deck_text).
!>
!> Deck parameters (rodyn_deck_params): the data lines of a `*PARAMETER` card define
!> `NAME = value` (the card itself is not kept), and every `<NAME>` in a later line (a
!> keyword line, a data line, an *INCLUDE path, a line of an included file) is replaced
!> by the parameter's text before the line is read, so that the readers see plain text.
!> A value given with --set (deck_lex's `overrides`) replaces the definition's value.
!> Parameters never referred to give a warning (deck%warnings).
!>
!> The card_* helpers below are the readers' toolkit: get a parameter as a real, an
!> integer, a name, a choice from a list, YES/NO, a file path; check the number of data
!> lines; parse the reals on a data line; read a table of numbers from the data lines or
!> from a file (*AMPLITUDE, *MOTION). Each helper reports its own errors, already located
!> (an error in a table file names that file and its line).
module rodyn_deck_lexer
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
   use rodyn_kinds, only: wp, i8
   use rodyn_error, only: error_t, set_error, has_error, stat_input
   use rodyn_model, only: name_len
   use rodyn_deck_params, only: param_table_t, param_override_t, deck_param_t, param_find, &
                                param_add, param_split_definition, param_value, &
                                param_substitute, upper_case
   implicit none
   private
   public :: field_t, param_t, data_line_t, card_t, deck_t, table_t
   public :: deck_lex
   public :: card_check_params, card_find_param, card_where
   public :: card_error, card_param_error, card_data_error, card_file_error
   public :: card_get_real, card_get_int, card_get_name, card_get_text, card_get_file
   public :: card_get_choice, card_get_yesno
   public :: card_check_data, card_data_count, card_data_reals, card_data_real
   public :: card_data_table, card_get_table
   public :: parse_real, parse_int, real_str, int_str, upper_case
   public :: max_include_depth, param_len

   integer, parameter :: max_include_depth = 10 !< deepest *INCLUDE nesting allowed
   integer, parameter :: param_len = 24         !< length for lists of parameter names
   integer, parameter :: max_exponent10 = 100   !< numbers are below 10**max_exponent10
   integer, parameter :: min_exponent10 = -100  !< non-zero numbers are at least 10**min_..
   character(len=1), parameter :: lf = achar(10), cr = achar(13), tab = achar(9)
   !> the UTF-8 byte-order mark, EF BB BF
   character(len=3), parameter :: utf8_bom = char(239)//char(187)//char(191)

   !> A string of any length (one field of a data line, one line of a file).
   type :: field_t
      character(len=:), allocatable :: s !< the text, trimmed
   end type field_t

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

   !> A table of numbers, one row per data line or per line of a table file
   !> (card_data_table, card_get_table).
   type :: table_t
      character(len=:), allocatable :: path     !< file the rows are in (as opened)
      character(len=:), allocatable :: text     !< the table file's text ('' for data lines)
      integer :: n_rows = 0                     !< number of rows
      real(wp), allocatable :: values(:, :)     !< (columns, rows 1..n_rows)
      integer, allocatable :: line(:)           !< line number of each row in path
   end type table_t

   !> The deck: all cards of the main file and its includes, in reading order.
   type :: deck_t
      character(len=:), allocatable :: main_file !< path of the main deck
      character(len=:), allocatable :: text      !< full text read, each file headed
      integer :: n_cards = 0                     !< number of cards
      type(card_t), allocatable :: cards(:)      !< cards 1..n_cards (capacity may exceed)
      type(param_table_t) :: params              !< *PARAMETER definitions, in order
      type(param_override_t), allocatable :: overrides(:) !< values given with --set
      type(field_t), allocatable :: warnings(:)  !< 'FILE:LINE: warning: ...' messages
   end type deck_t

contains

   ! ======================================================================= lexing

   !> Read the deck file `path` and its includes into a list of cards.
   !> A file that cannot be read gives 'PATH: error: cannot open deck'; a value of
   !> `overrides` whose name no *PARAMETER defines, 'rodyn: error: --set NAME: no
   !> *PARAMETER NAME in PATH'. Parameters never used are listed in deck%warnings.
   subroutine deck_lex(path, deck, err, overrides)
      character(len=*), intent(in) :: path   !< path of the main deck file
      type(deck_t), intent(out) :: deck      !< the cards read
      type(error_t), intent(inout) :: err    !< status (stat_input on error)
      type(param_override_t), intent(in), optional :: overrides(:) !< --set values
      character(len=:), allocatable :: text
      type(field_t) :: stack(0:max_include_depth)
      logical :: ok
      integer :: k

      deck%main_file = path
      deck%text = ''
      deck%n_cards = 0
      allocate (deck%cards(16))
      allocate (deck%warnings(0))
      if (present(overrides)) then
         deck%overrides = overrides
      else
         allocate (deck%overrides(0))
      end if
      call read_file_text(path, text, ok)
      if (.not. ok) then
         call set_error(err, stat_input, path//': error: cannot open deck')
         return
      end if
      stack(0)%s = path_normalise(path)
      call lex_text(path, text, 0, stack, deck, err)
      if (has_error(err)) return
      do k = 1, size(deck%overrides)
         if (.not. deck%overrides(k)%matched) then
            call set_error(err, stat_input, 'rodyn: error: --set '//deck%overrides(k)%name// &
                           ': no *PARAMETER '//deck%overrides(k)%name//' in '//path)
            return
         end if
      end do
      do k = 1, deck%params%n
         associate (p => deck%params%p(k))
            if (.not. p%used) deck%warnings = [deck%warnings, field_t(p%file//':'// &
               int_str(p%line)//': warning: *PARAMETER '//p%name//' is never used')]
         end associate
      end do
   end subroutine deck_lex

   !> Split the text of one file into lines and turn them into cards; recurse into
   !> *INCLUDE files. `depth` is 0 for the main file.
   recursive subroutine lex_text(path, text, depth, stack, deck, err)
      character(len=*), intent(in) :: path       !< path the file was opened with
      character(len=*), intent(in) :: text       !< the file's contents
      integer, intent(in) :: depth               !< include depth of this file
      type(field_t), intent(inout) :: stack(0:)  !< normalised paths of the open files
      type(deck_t), intent(inout) :: deck        !< cards read so far
      type(error_t), intent(inout) :: err        !< status
      integer :: first, last, line_no, cur
      character(len=:), allocatable :: s, t
      type(card_t) :: card
      type(error_t) :: perr

      s = encoding_problem(text)
      if (len(s) > 0) then
         call set_error(err, stat_input, path//':1: error: '//s)
         return
      end if
      deck%text = deck%text//'** ---- file: '//path//lf//without_cr(text)
      if (len(text) > 0) then
         if (text(len(text):len(text)) /= lf) deck%text = deck%text//lf
      end if

      cur = 0        ! card of the data lines: 0 none yet, -1 *INCLUDE, -2 *PARAMETER
      line_no = 0
      first = 1
      do while (first <= len(text))
         last = index(text(first:), lf)
         if (last == 0) then
            last = len(text) + 1
         else
            last = first + last - 1
         end if
         line_no = line_no + 1
         s = clean_line(text(first:last - 1))
         first = last + 1

         if (len(s) == 0) cycle
         if (len(s) >= 2) then
            if (s(1:2) == '**') cycle
         end if
         if (index(s, '<') > 0) then             ! <NAME> references: plain text from here
            call param_substitute(s, deck%params, t, perr)
            if (has_error(perr)) then
               call set_error(err, stat_input, path//':'//int_str(line_no)//': error: '// &
                              line_keyword(s, cur, deck)//perr%message)
               return
            end if
            s = trim(adjustl(t))
            if (len(s) == 0) cycle
         end if
         if (s(1:1) == '*') then
            call parse_keyword_line(path, line_no, s, card, err)
            if (has_error(err)) return
            if (card%keyword == 'INCLUDE') then
               call lex_include(card, depth, stack, deck, err)
               if (has_error(err)) return
               cur = -1
            else if (card%keyword == 'PARAMETER') then
               call card_check_params(card, [character(len=param_len) ::], err)
               if (has_error(err)) return
               cur = -2
            else
               call append_card(deck, card)
               cur = deck%n_cards
            end if
         else if (cur == 0) then
            call set_error(err, stat_input, path//':'//int_str(line_no)// &
                           ': error: data line before the first keyword line')
            return
         else if (cur == -1) then
            call set_error(err, stat_input, path//':'//int_str(line_no)// &
                           ': error: *INCLUDE: data lines are not allowed')
            return
         else if (cur == -2) then
            call define_parameter(path, line_no, s, deck, err)
            if (has_error(err)) return
         else
            call append_data_line(deck%cards(cur), line_no, s)
         end if
      end do
   end subroutine lex_text

   !> Keyword of a line for a message, as '*KEYWORD: ': the line's own for a keyword
   !> line, else that of the card the line belongs to ('' before the first card).
   pure function line_keyword(s, cur, deck) result(kw)
      character(len=*), intent(in) :: s   !< the line, starting with '*' if a keyword line
      integer, intent(in) :: cur          !< card of the data lines (as in lex_text)
      type(deck_t), intent(in) :: deck    !< cards read so far
      character(len=:), allocatable :: kw !< '*KEYWORD: ' or ''
      integer :: last
      kw = ''
      if (s(1:1) == '*') then
         last = scan(s(2:)//',', ',<')
         kw = '*'//normalise_name(s(2:last))//': '
      else if (cur > 0) then
         kw = '*'//deck%cards(cur)%keyword//': '
      else if (cur == -1) then
         kw = '*INCLUDE: '
      else if (cur == -2) then
         kw = '*PARAMETER: '
      end if
   end function line_keyword

   !> A data line of *PARAMETER: `NAME = value` (rodyn_deck_params). The value of a
   !> --set NAME=VALUE replaces the one written. Errors: a malformed line, a name
   !> defined twice, a bad value (located at this line; naming --set for its value).
   subroutine define_parameter(path, line_no, s, deck, err)
      character(len=*), intent(in) :: path    !< file the line is in
      integer, intent(in) :: line_no          !< line number
      character(len=*), intent(in) :: s       !< the line, cleaned and substituted
      type(deck_t), intent(inout) :: deck     !< gets the parameter
      type(error_t), intent(inout) :: err     !< status
      character(len=:), allocatable :: name, text, where
      type(deck_param_t) :: p
      type(error_t) :: perr
      integer :: k, io

      where = path//':'//int_str(line_no)//': error: *PARAMETER: '
      call param_split_definition(s, name, text, perr)
      if (has_error(perr)) then
         call set_error(err, stat_input, where//perr%message)
         return
      end if
      k = param_find(deck%params, name)
      if (k > 0) then
         call set_error(err, stat_input, where//name//' is already defined (at '// &
                        deck%params%p(k)%file//':'//int_str(deck%params%p(k)%line)//')')
         return
      end if
      p%name = name
      p%file = path
      p%line = line_no
      do io = 1, size(deck%overrides)
         if (deck%overrides(io)%name == name) then
            deck%overrides(io)%matched = .true.
            p%overridden = .true.
            text = deck%overrides(io)%text
            where = where//name//': --set '//name//'='//text//': '
         end if
      end do
      if (.not. p%overridden) where = where//name//': '
      call param_value(text, deck%params, p, perr)
      if (has_error(perr)) then
         call set_error(err, stat_input, where//perr%message)
         return
      end if
      call param_add(deck%params, p)
   end subroutine define_parameter

   !> Process one *INCLUDE card: check it, open the file relative to the including
   !> file's folder, refuse cycles and nesting deeper than max_include_depth, recurse.
   recursive subroutine lex_include(card, depth, stack, deck, err)
      type(card_t), intent(in) :: card           !< the *INCLUDE card
      integer, intent(in) :: depth               !< include depth of the including file
      type(field_t), intent(inout) :: stack(0:)  !< normalised paths of the open files
      type(deck_t), intent(inout) :: deck        !< cards read so far
      type(error_t), intent(inout) :: err        !< status
      character(len=:), allocatable :: path, text, norm
      integer :: k
      logical :: ok

      call card_check_params(card, [character(len=param_len) :: 'INPUT'], err)
      if (has_error(err)) return
      call card_get_file(card, 'INPUT', path, err, required=.true.)
      if (has_error(err)) return
      norm = path_normalise(path)
      do k = 0, depth
         if (stack(k)%s == norm) then
            call card_error(card, "'"//path//"' is already being read (include cycle)", err)
            return
         end if
      end do
      if (depth + 1 > max_include_depth) then
         call card_error(card, 'includes nested deeper than '// &
                         int_str(max_include_depth)//' levels', err)
         return
      end if
      call read_file_text(path, text, ok)
      if (.not. ok) then
         call card_error(card, "cannot open '"//path//"'", err)
         return
      end if
      stack(depth + 1)%s = norm
      call lex_text(path, text, depth + 1, stack, deck, err)
   end subroutine lex_include

   !> Parse a keyword line `*KEYWORD, NAME=value, ...` (s starts with '*').
   subroutine parse_keyword_line(path, line_no, s, card, err)
      character(len=*), intent(in) :: path    !< file the line is in
      integer, intent(in) :: line_no          !< line number
      character(len=*), intent(in) :: s       !< the line, cleaned, starting with '*'
      type(card_t), intent(out) :: card       !< the card started by this line
      type(error_t), intent(inout) :: err     !< status
      type(field_t), allocatable :: pieces(:)
      integer :: n, k, eq

      card%file = path
      card%line = line_no
      card%n_data = 0
      call split_commas(s(2:), pieces)
      n = size(pieces)
      card%keyword = normalise_name(pieces(1)%s)
      if (len(card%keyword) == 0) then
         call set_error(err, stat_input, path//':'//int_str(line_no)// &
                        ": error: keyword name missing after '*'")
         return
      end if
      if (n > 1) then
         if (len(pieces(n)%s) == 0) n = n - 1      ! trailing comma
      end if
      allocate (card%params(n - 1))
      do k = 2, n
         associate (p => card%params(k - 1))
            p%line = line_no
            if (len(pieces(k)%s) == 0) then
               call card_error(card, 'empty parameter between two commas', err)
               return
            end if
            eq = index(pieces(k)%s, '=')
            if (eq == 0) then
               p%name = normalise_name(pieces(k)%s)
               p%value = ''
            else
               p%name = normalise_name(pieces(k)%s(:eq - 1))
               p%value = trim(adjustl(pieces(k)%s(eq + 1:)))
            end if
            p%has_value = len(p%value) > 0
            if (len(p%name) == 0) then
               call card_error(card, "parameter name missing before '='", err)
               return
            end if
         end associate
      end do
   end subroutine parse_keyword_line

   !> Append a card to the deck, growing the list when full.
   subroutine append_card(deck, card)
      type(deck_t), intent(inout) :: deck  !< deck to extend
      type(card_t), intent(in) :: card     !< card to append
      type(card_t), allocatable :: tmp(:)
      integer :: k

      if (deck%n_cards == size(deck%cards)) then
         allocate (tmp(2*size(deck%cards)))
         do k = 1, deck%n_cards
            call move_card(deck%cards(k), tmp(k))
         end do
         call move_alloc(tmp, deck%cards)
      end if
      deck%n_cards = deck%n_cards + 1
      deck%cards(deck%n_cards) = card
   end subroutine append_card

   !> Move a card's contents to another (cheap: allocatable components are moved).
   subroutine move_card(from, to)
      type(card_t), intent(inout) :: from  !< source, left empty
      type(card_t), intent(inout) :: to    !< destination
      call move_alloc(from%keyword, to%keyword)
      call move_alloc(from%file, to%file)
      to%line = from%line
      call move_alloc(from%params, to%params)
      to%n_data = from%n_data
      call move_alloc(from%data, to%data)
   end subroutine move_card

   !> Append a data line to a card, splitting it at commas (a trailing comma dropped).
   subroutine append_data_line(card, line_no, s)
      type(card_t), intent(inout) :: card  !< card the line belongs to
      integer, intent(in) :: line_no       !< line number
      character(len=*), intent(in) :: s    !< the line, cleaned
      type(data_line_t), allocatable :: tmp(:)
      type(field_t), allocatable :: pieces(:)
      integer :: k, n

      if (.not. allocated(card%data)) allocate (card%data(2))
      if (card%n_data == size(card%data)) then
         allocate (tmp(2*size(card%data)))
         do k = 1, card%n_data
            tmp(k)%line = card%data(k)%line
            call move_alloc(card%data(k)%text, tmp(k)%text)
            call move_alloc(card%data(k)%fields, tmp(k)%fields)
         end do
         call move_alloc(tmp, card%data)
      end if
      card%n_data = card%n_data + 1
      call split_commas(s, pieces)
      n = size(pieces)
      if (n > 1) then
         if (len(pieces(n)%s) == 0) n = n - 1      ! trailing comma
      end if
      associate (d => card%data(card%n_data))
         d%line = line_no
         d%text = s
         allocate (d%fields(n))
         do k = 1, n
            call move_alloc(pieces(k)%s, d%fields(k)%s)
         end do
      end associate
   end subroutine append_data_line

   ! ================================================================ card helpers

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

   !> Find parameter `name` and check it has a value. ip = 0 when absent (an error if
   !> required) or when it has no value (always an error).
   subroutine find_valued(card, name, ip, err, required)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name, upper case
      integer, intent(out) :: ip              !< index of the parameter, 0 if unusable
      type(error_t), intent(inout) :: err     !< status
      logical, intent(in), optional :: required !< absence is an error
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
      character(len=:), allocatable :: msg
      real(wp) :: x
      integer :: ip

      if (present(found)) found = .false.
      call find_valued(card, name, ip, err, required)
      if (ip == 0) return
      call parse_real(card%params(ip)%value, x, msg)
      if (len(msg) > 0) then
         call card_param_error(card, ip, name//': '//msg, err)
         return
      end if
      value = x
      if (present(found)) found = .true.
   end subroutine card_get_real

   !> Get an integer parameter ('10.5' and '1e3' are refused). Unchanged when absent.
   subroutine card_get_int(card, name, value, err, found, required)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name, upper case
      integer, intent(inout) :: value         !< the value (unchanged if absent)
      type(error_t), intent(inout) :: err     !< status
      logical, intent(out), optional :: found !< the parameter was given
      logical, intent(in), optional :: required !< absence is an error
      character(len=:), allocatable :: msg
      integer :: ip, i

      if (present(found)) found = .false.
      call find_valued(card, name, ip, err, required)
      if (ip == 0) return
      call parse_int(card%params(ip)%value, i, msg)
      if (len(msg) > 0) then
         call card_param_error(card, ip, name//': '//msg, err)
         return
      end if
      value = i
      if (present(found)) found = .true.
   end subroutine card_get_int

   !> Get the raw text of a parameter (case kept), e.g. a file path. Unchanged if absent.
   subroutine card_get_text(card, name, value, err, found, required)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter name, upper case
      character(len=:), allocatable, intent(inout) :: value !< the text
      type(error_t), intent(inout) :: err     !< status
      logical, intent(out), optional :: found !< the parameter was given
      logical, intent(in), optional :: required !< absence is an error
      integer :: ip

      if (present(found)) found = .false.
      call find_valued(card, name, ip, err, required)
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

      if (present(found)) found = .false.
      call find_valued(card, name, ip, err, required)
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
   !> index = position in choices; unchanged when absent.
   subroutine card_get_choice(card, name, choices, index, err, found, required)
      type(card_t), intent(in) :: card          !< the card
      character(len=*), intent(in) :: name      !< parameter name, upper case
      character(len=*), intent(in) :: choices(:) !< allowed values, upper case
      integer, intent(inout) :: index           !< position of the value in choices
      type(error_t), intent(inout) :: err       !< status
      logical, intent(out), optional :: found   !< the parameter was given
      logical, intent(in), optional :: required !< absence is an error
      character(len=:), allocatable :: v, list
      integer :: ip, k

      if (present(found)) found = .false.
      call find_valued(card, name, ip, err, required)
      if (ip == 0) return
      v = upper_case(card%params(ip)%value)
      do k = 1, size(choices)
         if (choices(k) == v) then
            index = k
            if (present(found)) found = .true.
            return
         end if
      end do
      list = trim(choices(1))
      do k = 2, size(choices) - 1
         list = list//', '//trim(choices(k))
      end do
      if (size(choices) > 1) list = list//' or '//trim(choices(size(choices)))
      call card_param_error(card, ip, name//' must be '//list//", got '"// &
                            card%params(ip)%value//"'", err)
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

   !> Check the number of data lines: at least nmin, at most nmax (nmax < 0: no limit).
   subroutine card_check_data(card, nmin, nmax, err, what)
      type(card_t), intent(in) :: card        !< the card
      integer, intent(in) :: nmin             !< fewest data lines needed
      integer, intent(in) :: nmax             !< most data lines allowed, < 0: any
      type(error_t), intent(inout) :: err     !< status
      character(len=*), intent(in), optional :: what !< what the missing line holds
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

      names = ''
      if (present(what)) names = what
      call field_real(card%data(id)%fields(k)%s, k, card_data_count(card, id), names, &
                      value, msg)
      if (len(msg) > 0) call card_data_error(card, id, msg, err)
   end subroutine card_data_real

   !> The data lines as a table: each line one row of exactly ncol reals (`what` names
   !> the columns). table%path is the card's file, table%line the data lines' numbers.
   subroutine card_data_table(card, ncol, what, table, err)
      type(card_t), intent(in) :: card        !< the card
      integer, intent(in) :: ncol             !< number of values on each line
      character(len=*), intent(in) :: what    !< names of the columns
      type(table_t), intent(out) :: table     !< the rows
      type(error_t), intent(inout) :: err     !< status
      integer :: id

      table%path = card%file
      table%text = ''
      table%n_rows = card%n_data
      allocate (table%values(ncol, card%n_data), table%line(card%n_data))
      do id = 1, card%n_data
         table%line(id) = card%data(id)%line
         call card_data_reals(card, id, ncol, table%values(:, id), err, what)
         if (has_error(err)) return
      end do
   end subroutine card_data_table

   !> Read a table of numbers from the file given by parameter `name` (INPUT=path, see
   !> card_get_file): one row of exactly ncol reals per line, separated by commas or
   !> blanks. Blank lines and comment lines (first character '#', or '**') are skipped,
   !> and so is the first other line when none of its values is a number (a header).
   !> Errors in the file name the file and its line. found = .false. when the parameter
   !> is absent (table left empty).
   subroutine card_get_table(card, name, ncol, what, table, err, found, required)
      type(card_t), intent(in) :: card        !< the card
      character(len=*), intent(in) :: name    !< parameter holding the path, upper case
      integer, intent(in) :: ncol             !< number of values on each row
      character(len=*), intent(in) :: what    !< names of the columns
      type(table_t), intent(out) :: table     !< the rows read
      type(error_t), intent(inout) :: err     !< status
      logical, intent(out), optional :: found !< the parameter was given
      logical, intent(in), optional :: required !< absence is an error
      character(len=:), allocatable :: text, s, msg
      type(field_t), allocatable :: fields(:)
      real(wp) :: row(ncol)
      logical :: given, ok, header_allowed
      integer :: first, last, line_no

      if (present(found)) found = .false.
      table%n_rows = 0
      allocate (table%values(ncol, 16), table%line(16))
      call card_get_file(card, name, table%path, err, given, required)
      if (.not. given) return
      if (present(found)) found = .true.
      call read_file_text(table%path, text, ok)
      if (.not. ok) then
         call card_param_error(card, card_find_param(card, name), "cannot open '"// &
                               table%path//"'", err)
         return
      end if
      s = encoding_problem(text)
      if (len(s) > 0) then
         call card_file_error(card, table%path, 1, s, err)
         return
      end if
      table%text = without_cr(text)
      if (len(table%text) > 0) then
         if (table%text(len(table%text):len(table%text)) /= lf) table%text = table%text//lf
      end if

      header_allowed = .true.
      line_no = 0
      first = 1
      do while (first <= len(table%text))
         last = first + index(table%text(first:), lf) - 1
         line_no = line_no + 1
         s = clean_line(table%text(first:last - 1))
         first = last + 1
         if (len(s) == 0) cycle
         if (s(1:1) == '#') cycle
         if (len(s) >= 2) then
            if (s(1:2) == '**') cycle
         end if
         call split_table_line(s, fields)
         if (header_allowed) then
            header_allowed = .false.
            if (.not. any_number(fields)) cycle
         end if
         call fields_reals(fields, row, what, msg)
         if (len(msg) > 0) then
            call card_file_error(card, table%path, line_no, msg, err)
            return
         end if
         call append_row(table, row, line_no)
      end do
   end subroutine card_get_table

   !> Append one row to a table, growing its arrays when full.
   subroutine append_row(table, row, line_no)
      type(table_t), intent(inout) :: table  !< table to extend
      real(wp), intent(in) :: row(:)         !< the row's values
      integer, intent(in) :: line_no         !< its line number
      real(wp), allocatable :: v(:, :)
      integer, allocatable :: l(:)

      if (table%n_rows == size(table%line)) then
         allocate (v(size(row), 2*table%n_rows), l(2*table%n_rows))
         v(:, 1:table%n_rows) = table%values(:, 1:table%n_rows)
         l(1:table%n_rows) = table%line(1:table%n_rows)
         call move_alloc(v, table%values)
         call move_alloc(l, table%line)
      end if
      table%n_rows = table%n_rows + 1
      table%values(:, table%n_rows) = row
      table%line(table%n_rows) = line_no
   end subroutine append_row

   !> Split a line of a table file at commas and at runs of blanks. An empty value
   !> between two commas is kept (as '') so that it is reported; a trailing comma is not.
   pure subroutine split_table_line(s, fields)
      character(len=*), intent(in) :: s                    !< the line, cleaned
      type(field_t), allocatable, intent(out) :: fields(:) !< its values
      type(field_t), allocatable :: pieces(:)
      type(field_t) :: buf(len(s) + 1)
      integer :: n, k, np, p, q

      call split_commas(s, pieces)
      np = size(pieces)
      if (np > 1) then
         if (len(pieces(np)%s) == 0) np = np - 1      ! trailing comma
      end if
      n = 0
      do k = 1, np
         associate (t => pieces(k)%s)
            if (len(t) == 0) then
               n = n + 1
               buf(n)%s = ''
               cycle
            end if
            p = 1
            do while (p <= len(t))
               if (t(p:p) == ' ') then
                  p = p + 1
                  cycle
               end if
               q = index(t(p:), ' ')
               if (q == 0) then
                  q = len(t) + 1
               else
                  q = p + q - 1
               end if
               n = n + 1
               buf(n)%s = t(p:q - 1)
               p = q + 1
            end do
         end associate
      end do
      allocate (fields(n))
      do k = 1, n
         call move_alloc(buf(k)%s, fields(k)%s)
      end do
   end subroutine split_table_line

   !> True when at least one of the fields is a number.
   logical function any_number(fields)
      type(field_t), intent(in) :: fields(:)  !< values of a line
      character(len=:), allocatable :: msg
      real(wp) :: x
      integer :: k
      any_number = .false.
      do k = 1, size(fields)
         call parse_real(fields(k)%s, x, msg)
         if (len(msg) == 0) any_number = .true.
      end do
   end function any_number

   !> Parse fields as exactly size(values) reals. msg = '' on success, else what is
   !> wrong, naming the value by `what` (comma-separated names) and position.
   subroutine fields_reals(fields, values, what, msg)
      type(field_t), intent(in) :: fields(:)          !< the values as text
      real(wp), intent(out) :: values(:)              !< the numbers
      character(len=*), intent(in) :: what            !< names of the values ('' if none)
      character(len=:), allocatable, intent(out) :: msg !< '' or the problem
      integer :: k, n, nf

      values = 0.0_wp
      msg = ''
      n = size(values)
      nf = size(fields)
      if (nf /= n) then
         msg = 'expected '//int_str(n)//' value'
         if (n /= 1) msg = msg//'s'
         msg = msg//', got '//int_str(nf)
         if (len(what) > 0) msg = msg//' ('//what//')'
         return
      end if
      do k = 1, n
         call field_real(fields(k)%s, k, n, what, values(k), msg)
         if (len(msg) > 0) return
      end do
   end subroutine fields_reals

   !> Parse value k of n of a line as a real; msg = '' or the problem, ending with a
   !> label '(NAME, value k of n)' (NAME the k-th item of `what`).
   subroutine field_real(f, k, n, what, value, msg)
      character(len=*), intent(in) :: f               !< the value as text, trimmed
      integer, intent(in) :: k                        !< its position on the line
      integer, intent(in) :: n                        !< number of values of the line
      character(len=*), intent(in) :: what            !< names of the values ('' if none)
      real(wp), intent(out) :: value                  !< the number
      character(len=:), allocatable, intent(out) :: msg !< '' or the problem
      character(len=:), allocatable :: label

      value = 0.0_wp
      label = item_of(what, k)
      if (len(label) > 0) label = label//', '
      label = '('//label//'value '//int_str(k)//' of '//int_str(n)//')'
      if (len(f) == 0) then
         msg = 'empty value '//label
         return
      end if
      call parse_real(f, value, msg)
      if (len(msg) > 0) msg = msg//' '//label
   end subroutine field_real

   ! ================================================================== numbers

   !> Parse a real written Fortran/C style: [sign] digits [. digits] [e|E|d|D [sign]
   !> digits], at least one digit in the mantissa. Anything else (nan, inf, 1.2.3, ...)
   !> is refused, and so is a magnitude outside [1e-100, 1e100) other than zero (so that
   !> products of a few input values cannot overflow). The token is checked character by
   !> character before it is converted, so that bad text cannot raise a floating-point
   !> exception.
   subroutine parse_real(token, value, msg)
      character(len=*), intent(in) :: token           !< text to convert, trimmed
      real(wp), intent(out) :: value                  !< the number
      character(len=:), allocatable, intent(out) :: msg !< '' on success, else why not
      integer :: n, p, n_int, n_frac, lead, ios
      integer(i8) :: e_val, e_sign, mag
      logical :: nonzero

      value = 0.0_wp
      msg = ''
      n = len(token)
      p = 1
      if (n > 0) then
         if (token(1:1) == '+' .or. token(1:1) == '-') p = 2
      end if
      n_int = 0
      n_frac = 0
      lead = 0            ! decimal exponent of the first non-zero digit (before e)
      nonzero = .false.
      do while (p <= n)
         if (.not. is_digit(token(p:p))) exit
         if (.not. nonzero .and. token(p:p) /= '0') then
            nonzero = .true.
            lead = -n_int    ! fixed below once the number of integer digits is known
         end if
         n_int = n_int + 1
         p = p + 1
      end do
      if (nonzero) lead = lead + n_int - 1
      if (p <= n) then
         if (token(p:p) == '.') then
            p = p + 1
            do while (p <= n)
               if (.not. is_digit(token(p:p))) exit
               n_frac = n_frac + 1
               if (.not. nonzero .and. token(p:p) /= '0') then
                  nonzero = .true.
                  lead = -n_frac
               end if
               p = p + 1
            end do
         end if
      end if
      if (n_int + n_frac == 0) then
         msg = "'"//token//"' is not a number"
         return
      end if
      e_val = 0
      e_sign = 1
      if (p <= n) then
         if (index('eEdD', token(p:p)) > 0) then
            p = p + 1
            if (p <= n) then
               if (token(p:p) == '+' .or. token(p:p) == '-') then
                  if (token(p:p) == '-') e_sign = -1
                  p = p + 1
               end if
            end if
            if (p > n) then
               msg = "'"//token//"' is not a number"
               return
            end if
            do while (p <= n)
               if (.not. is_digit(token(p:p))) exit
               if (e_val < 100000_i8) e_val = 10_i8*e_val + (iachar(token(p:p)) - iachar('0'))
               p = p + 1
            end do
         end if
      end if
      if (p /= n + 1) then
         msg = "'"//token//"' is not a number"
         return
      end if
      if (nonzero) then
         mag = lead + e_sign*e_val
         if (mag >= max_exponent10 .or. mag < min_exponent10) then
            msg = "'"//token//"' is out of range: its magnitude must be between 1e"// &
                  int_str(min_exponent10)//' and 1e'//int_str(max_exponent10)//' (or zero)'
            return
         end if
      end if
      read (token, *, iostat=ios) value
      if (ios /= 0) then
         value = 0.0_wp
         msg = "'"//token//"' is not a number"
      end if
   end subroutine parse_real

   !> Parse an integer: [sign] digits, nothing else ('10.5', '1e3' refused).
   subroutine parse_int(token, value, msg)
      character(len=*), intent(in) :: token           !< text to convert, trimmed
      integer, intent(out) :: value                   !< the number
      character(len=:), allocatable, intent(out) :: msg !< '' on success, else why not
      integer :: p, ios
      integer(i8) :: v8

      value = 0
      msg = ''
      p = 1
      if (len(token) > 0) then
         if (token(1:1) == '+' .or. token(1:1) == '-') p = 2
      end if
      if (p > len(token)) then
         msg = "'"//token//"' is not an integer"
         return
      end if
      if (verify(token(p:), '0123456789') /= 0) then
         msg = "'"//token//"' is not an integer"
         return
      end if
      if (len(token(p:)) - (verify(token(p:), '0') - 1) > 18 .and. &
          verify(token(p:), '0') > 0) then
         msg = "'"//token//"' is out of range"
         return
      end if
      read (token, *, iostat=ios) v8
      if (ios /= 0 .or. abs(v8) > int(huge(value), i8)) then
         msg = "'"//token//"' is out of range"
         return
      end if
      value = int(v8)
   end subroutine parse_int

   !> Shortest text that reads back as x exactly: '10', '9.5', '0.001', '7.96e8'.
   function real_str(x) result(s)
      real(wp), intent(in) :: x           !< the number
      character(len=:), allocatable :: s  !< its text
      character(len=40) :: buf, fmt
      character(len=:), allocatable :: mant, digits
      real(wp) :: y
      integer :: p, ios, epos, e, k

      if (ieee_is_nan(x)) then      ! not produced by the reader, but be safe
         s = 'NaN'
         return
      end if
      if (.not. ieee_is_finite(x)) then
         s = 'Infinity'
         if (x < 0.0_wp) s = '-'//s
         return
      end if
      if (abs(x) < tiny(x)) then
         s = '0'
         return
      end if
      do p = 1, 17
         write (fmt, '(a,i0,a)') '(es40.', p - 1, 'e3)'
         write (buf, fmt) x
         if (abs(x) > 1.0e300_wp) cycle   ! rounding up could overflow on reading back
         read (buf, *, iostat=ios) y
         if (ios == 0) then
            if (transfer(y, 0_i8) == transfer(x, 0_i8)) exit
         end if
      end do
      buf = adjustl(buf)
      epos = index(buf, 'E')
      mant = buf(:epos - 1)
      read (buf(epos + 1:), *) e
      digits = ''
      do k = 1, len(mant)
         if (is_digit(mant(k:k))) digits = digits//mant(k:k)
      end do
      do while (len(digits) > 1)
         if (digits(len(digits):len(digits)) /= '0') exit
         digits = digits(:len(digits) - 1)
      end do
      if (e >= 0 .and. e < 7) then
         if (len(digits) <= e + 1) then
            s = digits//repeat('0', e + 1 - len(digits))
         else
            s = digits(:e + 1)//'.'//digits(e + 2:)
         end if
      else if (e < 0 .and. e >= -4) then
         s = '0.'//repeat('0', -e - 1)//digits
      else
         s = digits(1:1)
         if (len(digits) > 1) s = s//'.'//digits(2:)
         s = s//'e'//int_str(e)
      end if
      if (x < 0.0_wp) s = '-'//s
   end function real_str

   !> Integer as text without blanks.
   pure function int_str(i) result(s)
      integer, intent(in) :: i            !< the number
      character(len=:), allocatable :: s  !< its text
      character(len=24) :: buf
      write (buf, '(i0)') i
      s = trim(buf)
   end function int_str

   ! =================================================================== strings


   !> A keyword or parameter name: trimmed, upper case, runs of blanks made one blank.
   !> One pass into a buffer of the name's length (time linear in the length: growing
   !> the result a character at a time took 17 s for a keyword of 200 000 characters).
   pure function normalise_name(s) result(n)
      character(len=*), intent(in) :: s   !< name as written
      character(len=:), allocatable :: n  !< normalised name
      character(len=:), allocatable :: t
      integer :: k, m
      t = upper_case(trim(adjustl(s)))
      allocate (character(len=len(t)) :: n)
      m = 0
      do k = 1, len(t)
         if (t(k:k) == ' ' .and. m > 0) then
            if (n(m:m) == ' ') cycle
         end if
         m = m + 1
         n(m:m) = t(k:k)
      end do
      n = n(:m)
   end function normalise_name

   !> A line of a file with tabs made blanks, a trailing carriage return dropped,
   !> and leading and trailing blanks removed.
   pure function clean_line(raw) result(s)
      character(len=*), intent(in) :: raw !< the line as read
      character(len=:), allocatable :: s  !< the cleaned line
      integer :: k
      s = raw
      if (len(s) > 0) then
         if (s(len(s):len(s)) == cr) s = s(:len(s) - 1)
      end if
      do k = 1, len(s)
         if (s(k:k) == tab) s(k:k) = ' '
      end do
      s = trim(adjustl(s))
   end function clean_line

   !> Text with the carriage return of each CR LF line end removed (one pass).
   pure function without_cr(text) result(t)
      character(len=*), intent(in) :: text !< text with any line ends
      character(len=:), allocatable :: t   !< the text with LF line ends only
      integer :: k, n
      allocate (character(len=len(text)) :: t)
      n = 0
      do k = 1, len(text)
         if (text(k:k) == cr .and. k < len(text)) then
            if (text(k + 1:k + 1) == lf) cycle
         end if
         n = n + 1
         t(n:n) = text(k:k)
      end do
      t = t(:n)
   end function without_cr

   !> Split s at commas into trimmed pieces (at least one piece).
   pure subroutine split_commas(s, pieces)
      character(len=*), intent(in) :: s                    !< text to split
      type(field_t), allocatable, intent(out) :: pieces(:) !< the pieces, trimmed
      integer :: n, k, first, last
      n = 1
      do k = 1, len(s)
         if (s(k:k) == ',') n = n + 1
      end do
      allocate (pieces(n))
      first = 1
      do k = 1, n
         last = index(s(first:), ',')
         if (last == 0) then
            last = len(s) + 1
         else
            last = first + last - 1
         end if
         pieces(k)%s = trim(adjustl(s(first:last - 1)))
         first = last + 1
      end do
   end subroutine split_commas

   !> The k-th comma-separated item of list, trimmed ('' if there is none).
   pure function item_of(list, k) result(item)
      character(len=*), intent(in) :: list  !< comma-separated list
      integer, intent(in) :: k              !< which item
      character(len=:), allocatable :: item !< the item
      type(field_t), allocatable :: pieces(:)
      item = ''
      if (len_trim(list) == 0) return
      call split_commas(list, pieces)
      if (k <= size(pieces)) item = pieces(k)%s
   end function item_of

   !> True for '0'..'9'.
   elemental logical function is_digit(c)
      character(len=1), intent(in) :: c  !< character to test
      is_digit = c >= '0' .and. c <= '9'
   end function is_digit

   ! ===================================================================== files

   !> Read a whole file into a string, without a leading UTF-8 byte-order mark. ok =
   !> .false. if it cannot be opened or read.
   subroutine read_file_text(path, text, ok)
      character(len=*), intent(in) :: path                !< file to read
      character(len=:), allocatable, intent(out) :: text  !< its contents
      logical, intent(out) :: ok                          !< the file was read
      integer :: u, ios
      integer(i8) :: n

      ok = .false.
      text = ''
      if (len_trim(path) == 0) return
      open (newunit=u, file=path, access='stream', form='unformatted', status='old', &
            action='read', iostat=ios)
      if (ios /= 0) return
      inquire (unit=u, size=n)
      if (n < 0_i8) then
         close (u)
         return
      end if
      deallocate (text)
      allocate (character(len=n) :: text)
      if (n > 0_i8) then
         read (u, iostat=ios) text
         if (ios /= 0) then
            close (u)
            text = ''
            return
         end if
      end if
      close (u)
      ! a UTF-8 byte-order mark (Windows editors write one) is no part of the text
      if (len(text) >= 3) then
         if (text(1:3) == utf8_bom) text = text(4:)
      end if
      ! carriage returns alone end the lines of old Mac files: made line feeds
      if (index(text, lf) == 0 .and. index(text, cr) > 0) then
         do n = 1_i8, int(len(text), i8)
            if (text(n:n) == cr) text(n:n) = lf
         end do
      end if
      ok = .true.
   end subroutine read_file_text

   !> Why a file's text cannot be a deck or table in this encoding ('' if it can): a
   !> UTF-16 byte-order mark, or NUL bytes in the first line (UTF-16 without one).
   pure function encoding_problem(text) result(msg)
      character(len=*), intent(in) :: text !< the file's contents
      character(len=:), allocatable :: msg !< '' or the problem
      integer :: eol
      msg = ''
      if (len(text) >= 2) then
         if (text(1:2) == char(255)//char(254) .or. text(1:2) == char(254)//char(255)) &
            then
            msg = 'the file is UTF-16 (it starts with a UTF-16 byte-order mark): save it'// &
                  ' as UTF-8 or ASCII'
            return
         end if
      end if
      eol = index(text, lf)
      if (eol == 0) eol = len(text) + 1
      if (index(text(:eol - 1), achar(0)) > 0) msg = 'the first line holds NUL bytes (a'// &
         ' UTF-16 or binary file?): save the file as UTF-8 or ASCII'
   end function encoding_problem

   !> Folder part of a path, with its trailing '/' ('' for a bare file name).
   pure function dir_of(path) result(d)
      character(len=*), intent(in) :: path !< a file path
      character(len=:), allocatable :: d   !< its folder
      d = path(:index(path, '/', back=.true.))
   end function dir_of

   !> Path with '.' and empty segments removed and 'x/..' collapsed, as text: used only
   !> to recognise a file that is already open (include cycles).
   pure function path_normalise(path) result(norm)
      character(len=*), intent(in) :: path  !< a file path
      character(len=:), allocatable :: norm !< normalised path
      character(len=len(path)) :: seg(len(path) + 1)
      integer :: n, first, last
      logical :: absolute

      absolute = .false.
      if (len(path) > 0) absolute = path(1:1) == '/'
      n = 0
      first = 1
      do while (first <= len(path) + 1)
         last = index(path(first:)//'/', '/') + first - 1
         if (last > first) then
            associate (s => path(first:last - 1))
               if (s == '.') then
                  continue
               else if (s == '..' .and. n > 0) then
                  if (seg(n) /= '..') then
                     n = n - 1
                  else
                     n = n + 1
                     seg(n) = s
                  end if
               else
                  n = n + 1
                  seg(n) = s
               end if
            end associate
         end if
         first = last + 1
      end do
      norm = ''
      if (absolute) norm = '/'
      do first = 1, n
         if (first > 1) norm = norm//'/'
         norm = norm//trim(seg(first))
      end do
   end function path_normalise

end module rodyn_deck_lexer
