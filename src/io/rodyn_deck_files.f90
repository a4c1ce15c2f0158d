!> Deck lexer, files: the whole text of a deck or table file (a UTF-8 byte-order mark
!> dropped, old Mac line ends made line feeds), why a text cannot be read as a deck (a
!> UTF-16 or binary file), the folder of a path, and a path normalised to recognise a
!> file already open (include cycles).
module rodyn_deck_files
   use rodyn_kinds, only: i8
   use rodyn_deck_text, only: lf, cr
   implicit none
   private
   public :: read_file_text, encoding_problem, dir_of, path_normalise

   !> the UTF-8 byte-order mark, EF BB BF
   character(len=3), parameter :: utf8_bom = char(239)//char(187)//char(191)

contains

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

end module rodyn_deck_files
