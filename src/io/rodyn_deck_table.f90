!> Deck lexer, tables of numbers (*AMPLITUDE, *MOTION, *VESSEL, ...): one row of reals
!> per data line of a card (card_data_table), or per line of a file named by a parameter
!> (card_get_table: commas or blanks between values, comment lines and a header line
!> skipped). An error in a table file names that file and its line.
module rodyn_deck_table
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_deck_text, only: field_t, next_line, without_cr, split_commas, lf, next_of
   use rodyn_deck_numbers, only: parse_real, fields_reals
   use rodyn_deck_files, only: read_file_text, encoding_problem
   use rodyn_deck_card, only: card_t, card_find_param, card_param_error, card_file_error, &
                              card_check_data
   use rodyn_deck_card_values, only: card_get_file, card_data_reals
   implicit none
   private
   public :: table_t, card_data_table, card_get_table

   !> A table of numbers, one row per data line or per line of a table file
   !> (card_data_table, card_get_table).
   type :: table_t
      character(len=:), allocatable :: path     !< file the rows are in (as opened)
      character(len=:), allocatable :: text     !< the table file's text ('' for data lines)
      integer :: n_rows = 0                     !< number of rows
      real(wp), allocatable :: values(:, :)     !< (columns, rows 1..n_rows)
      integer, allocatable :: line(:)           !< line number of each row in path
   end type table_t

contains

   !> The data lines as a table: each line one row of exactly ncol reals (`what` names
   !> the columns). table%path is the card's file, table%line the data lines' numbers.
   subroutine card_data_table(card, ncol, what, table, err, nmin)
      type(card_t), intent(in) :: card        !< the card
      integer, intent(in) :: ncol             !< number of values on each line
      character(len=*), intent(in) :: what    !< names of the columns
      type(table_t), intent(out) :: table     !< the rows
      type(error_t), intent(inout) :: err     !< status
      integer, intent(in), optional :: nmin   !< fewest data lines (else not checked)
      integer :: id

      if (present(nmin)) call card_check_data(card, nmin, -1, err, what)
      if (has_error(err)) return

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
      integer :: first, line_no

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
         call next_line(table%text, first, line_no, s)
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
               q = next_of(t, p, ' ')
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

end module rodyn_deck_table
