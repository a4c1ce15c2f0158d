!> Keyword-deck lexer: turns an Abaqus/Flexcom-style input deck into a list of cards.
!>
!> A card is one keyword line (`*KEYWORD, PARAM=value, ...`) and the data lines that
!> follow it up to the next keyword line (rodyn_deck_card). Every card, parameter and
!> data line remembers the file (as the path used to open it) and the line number it
!> came from, so that the keyword readers can report `FILE:LINE: error: *KEYWORD:
!> message`.
!>
!> The lexer handles the general syntax of docs/deck.md: `**` comments, blank lines,
!> case-insensitive names (stored upper case, runs of blanks collapsed to one),
!> trailing commas, blanks around `=` and `,`, and `*INCLUDE, INPUT=path`
!> (rodyn_deck_include). It also keeps the full text read for the record
!> (model%deck_text).
!>
!> Deck parameters (rodyn_deck_params): the data lines of a `*PARAMETER` card define
!> `NAME = value` (the card itself is not kept), and every `<NAME>` in a later line (a
!> keyword line, a data line, an *INCLUDE path, a line of an included file) is replaced
!> by the parameter's text before the line is read, so that the readers see plain text.
!> A value given with --set (deck_lex's `overrides`) replaces the definition's value.
!> Parameters never referred to give a warning (deck%warnings).
!>
!> The readers take a card's values with rodyn_deck_card_values and its tables with
!> rodyn_deck_table.
module rodyn_deck_lexer
   use rodyn_error, only: error_t, set_error, has_error, stat_input
   use rodyn_deck_params, only: param_table_t, param_override_t, deck_param_t, param_find, &
                                param_add, param_split_definition, param_value, &
                                param_substitute
   use rodyn_deck_text, only: field_t, normalise_name, next_line, without_cr, split_commas, &
                              lf
   use rodyn_deck_numbers, only: int_str
   use rodyn_deck_files, only: read_file_text, encoding_problem, path_normalise
   use rodyn_deck_card, only: card_t, data_line_t, card_error, card_check_params, param_len
   use rodyn_deck_include, only: include_open, max_include_depth
   implicit none
   private
   public :: deck_t, deck_source_t, deck_lex, keyword_count, last_card

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

   !> A deck made by a program rather than read from `path` (a MoorDyn input file
   !> translated, rodyn_moordyn_deck): its text, and for each of its lines the line of
   !> `path` it stands for, where its messages point (0: a line of its own, reported as
   !> line 1 of path).
   type :: deck_source_t
      character(len=:), allocatable :: text      !< the deck's text, lines ended by LF
      integer, allocatable :: line_map(:)        !< line of path of each line of text
   end type deck_source_t

contains

   !> Read the deck file `path` and its includes into a list of cards.
   !> A file that cannot be read gives 'PATH: error: cannot open deck'; a value of
   !> `overrides` whose name no *PARAMETER defines, 'rodyn: error: --set NAME: no
   !> *PARAMETER NAME in PATH'. Parameters never used are listed in deck%warnings.
   subroutine deck_lex(path, deck, err, overrides, source)
      character(len=*), intent(in) :: path   !< path of the main deck file
      type(deck_t), intent(out) :: deck      !< the cards read
      type(error_t), intent(inout) :: err    !< status (stat_input on error)
      type(param_override_t), intent(in), optional :: overrides(:) !< --set values
      type(deck_source_t), intent(in), optional :: source !< the deck's text, for path's
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
      if (present(source)) then
         text = source%text
         ok = .true.
      else
         call read_file_text(path, text, ok)
      end if
      if (.not. ok) then
         call set_error(err, stat_input, path//': error: cannot open deck')
         return
      end if
      stack(0)%s = path_normalise(path)
      if (present(source)) then
         call lex_text(path, text, 0, stack, deck, err, source%line_map)
      else
         call lex_text(path, text, 0, stack, deck, err)
      end if
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
   !> *INCLUDE files (rodyn_deck_include). `depth` is 0 for the main file. With
   !> `line_map`, line k of text is located at line line_map(k) of path.
   recursive subroutine lex_text(path, text, depth, stack, deck, err, line_map)
      character(len=*), intent(in) :: path       !< path the file was opened with
      character(len=*), intent(in) :: text       !< the file's contents
      integer, intent(in) :: depth               !< include depth of this file
      type(field_t), intent(inout) :: stack(0:)  !< normalised paths of the open files
      type(deck_t), intent(inout) :: deck        !< cards read so far
      type(error_t), intent(inout) :: err        !< status
      integer, intent(in), optional :: line_map(:) !< line of path of each line of text
      integer :: first, line_no, cur, k
      character(len=:), allocatable :: s, t, ipath, itext
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
      k = 0
      first = 1
      do while (first <= len(text))
         call next_line(text, first, k, s)
         line_no = k
         if (present(line_map)) line_no = max(1, line_map(min(k, size(line_map))))
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
               call include_open(card, depth, stack, ipath, itext, err)
               if (has_error(err)) return
               call lex_text(ipath, itext, depth + 1, stack, deck, err)
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

   !> Number of cards with the given keyword.
   pure integer function keyword_count(deck, keyword) result(n)
      type(deck_t), intent(in) :: deck        !< all cards
      character(len=*), intent(in) :: keyword !< keyword, upper case, without '*'
      integer :: ic
      n = 0
      do ic = 1, deck%n_cards
         if (deck%cards(ic)%keyword == keyword) n = n + 1
      end do
   end function keyword_count

   !> Index of the last card with the given keyword, 0 if there is none.
   pure integer function last_card(deck, keyword) result(ic)
      type(deck_t), intent(in) :: deck        !< all cards
      character(len=*), intent(in) :: keyword !< keyword, upper case, without '*'
      do ic = deck%n_cards, 1, -1
         if (deck%cards(ic)%keyword == keyword) return
      end do
      ic = 0
   end function last_card

end module rodyn_deck_lexer
