!> Deck lexer, the text of a line: a field of any length (field_t), a line cleaned of
!> tabs, carriage returns and outer blanks, names made upper case with runs of blanks
!> collapsed, a line split at its commas. The lexer (rodyn_deck_lexer), the card readers
!> and the table reader (rodyn_deck_table) share them.
module rodyn_deck_text
   use rodyn_deck_params, only: upper_case
   implicit none
   private
   public :: field_t
   public :: normalise_name, clean_line, next_line, without_cr, split_commas, item_of
   public :: next_of
   public :: is_digit
   public :: lf, cr

   character(len=1), parameter :: lf = achar(10), cr = achar(13), tab = achar(9)

   !> A string of any length (one field of a data line, one line of a file).
   type :: field_t
      character(len=:), allocatable :: s !< the text, trimmed
   end type field_t

contains

   !> A keyword or parameter name: trimmed, upper case, runs of blanks made one blank.
   !> One pass into a buffer of the name's length (time linear in the length: growing
   !> the result a character at a time took 17 s for a keyword of 200 000 characters).
   pure function normalise_name(s) result(n)
      character(len=*), intent(in) :: s   !< name as written
      character(len=:), allocatable :: n  !< normalised name
      character(len=:), allocatable :: t
      integer :: k
      t = upper_case(trim(adjustl(s)))
      n = kept(t, [(t(k:k) /= ' ' .or. t(max(k - 1, 1):max(k - 1, 1)) /= ' ', &
                    k = 1, len(t))])
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

   !> The line of text that starts at `first`, cleaned (clean_line); first moves past
   !> its line feed (or the end of the text) and line_no counts it.
   pure subroutine next_line(text, first, line_no, s)
      character(len=*), intent(in) :: text            !< the text, lines ended by LF
      integer, intent(inout) :: first                 !< where the line starts
      integer, intent(inout) :: line_no               !< number of the line before
      character(len=:), allocatable, intent(out) :: s !< the line, cleaned
      integer :: last
      last = next_of(text, first, lf)
      line_no = line_no + 1
      s = clean_line(text(first:last - 1))
      first = last + 1
   end subroutine next_line

   !> Text with the carriage return of each CR LF line end removed (one pass).
   pure function without_cr(text) result(t)
      character(len=*), intent(in) :: text !< text with any line ends
      character(len=:), allocatable :: t   !< the text with LF line ends only
      integer :: k, n
      n = len(text)
      t = kept(text, [(text(k:k) /= cr .or. k == n .or. text(min(k + 1, n):min(k + 1, n)) &
                       /= lf, k = 1, n)])
   end function without_cr

   !> The characters of t where keep is true, in one pass.
   pure function kept(t, keep) result(s)
      character(len=*), intent(in) :: t    !< text
      logical, intent(in) :: keep(:)       !< per character of t: keep it
      character(len=:), allocatable :: s   !< the characters kept
      integer :: k, m
      allocate (character(len=count(keep)) :: s)
      m = 0
      do k = 1, len(t)
         if (.not. keep(k)) cycle
         m = m + 1
         s(m:m) = t(k:k)
      end do
   end function kept

   !> Position of the first c in s at or after first; len(s) + 1 if there is none.
   pure integer function next_of(s, first, c) result(last)
      character(len=*), intent(in) :: s  !< text
      integer, intent(in) :: first       !< where to start looking
      character(len=1), intent(in) :: c  !< the separator
      last = index(s(first:), c)
      if (last == 0) then
         last = len(s) + 1
      else
         last = first + last - 1
      end if
   end function next_of

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
         last = next_of(s, first, ',')
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

end module rodyn_deck_text
