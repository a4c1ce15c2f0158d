!> MoorDyn v2 input files (docs/moordyn.md): a file recognised by its section headers,
!> and split into its sections, each a list of rows of blank-separated fields that
!> remember their line. What the fields mean is rodyn_moordyn_deck's.
!>
!> The layout is MoorDyn v2.7's (its docs/inputs.rst; MoorDyn2.cpp, ReadInFile): a line
!> of dashes holding a section's name starts the section (LINE TYPES, POINTS, ...); the
!> two lines after the header of a table are its column names and units; OPTIONS rows
!> are `value name [comment]`, OUTPUTS rows channel names; a line with "END" or "need
!> this line" in a header ends the file. Lines before the first section are the title.
module rodyn_moordyn_file
   use rodyn_error, only: error_t, set_error, has_error, stat_input
   use rodyn_deck_text, only: field_t, clean_line, next_line, without_cr, lf
   use rodyn_deck_files, only: read_file_text, encoding_problem
   use rodyn_deck_numbers, only: int_str
   use rodyn_deck_params, only: upper_case
   implicit none
   private
   public :: md_row_t, md_section_t, md_file_t, md_read, md_is_moordyn
   public :: md_line_types, md_rod_types, md_bodies, md_rods, md_points, md_lines, &
             md_failure, md_options, md_outputs, md_n_sections, md_section_names

   !> The sections of a MoorDyn v2 file, in the order of md_section_names.
   integer, parameter :: md_line_types = 1, md_rod_types = 2, md_bodies = 3, md_rods = 4, &
                         md_points = 5, md_lines = 6, md_failure = 7, md_options = 8, &
                         md_outputs = 9, md_n_sections = 9
   !> Their names in messages.
   character(len=*), parameter :: md_section_names(md_n_sections) = [character(len=10) :: &
      'LINE TYPES', 'ROD TYPES', 'BODIES', 'RODS', 'POINTS', 'LINES', 'FAILURE', 'OPTIONS', &
      'OUTPUTS']
   !> Rows of column names and of units after the header of each section.
   integer, parameter :: head_rows(md_n_sections) = [2, 2, 2, 2, 2, 2, 2, 0, 0]

   !> A row of a section: its fields and the line it is on.
   type :: md_row_t
      integer :: line = 0                 !< line of the file
      type(field_t), allocatable :: f(:)  !< the fields, split at blanks
   end type md_row_t

   !> A section: its header's line and its rows (none when absent).
   type :: md_section_t
      integer :: line = 0                 !< line of its header, 0 when absent
      integer :: n = 0                    !< rows 1..n
      type(md_row_t), allocatable :: rows(:)
      type(field_t), allocatable :: columns(:) !< the column names (tables)
   end type md_section_t

   !> A MoorDyn file split into sections.
   type :: md_file_t
      character(len=:), allocatable :: path   !< the path it was read from
      character(len=:), allocatable :: title  !< the text before the first section
      type(md_section_t) :: sec(md_n_sections)
   end type md_file_t

contains

   !> Whether `text` is a MoorDyn input file: a line of dashes naming one of its
   !> sections comes before any line starting with '*' but not '**' (a rodyn keyword;
   !> '**' starts a rodyn comment).
   pure logical function md_is_moordyn(text) result(yes)
      character(len=*), intent(in) :: text !< the file's text
      character(len=:), allocatable :: s
      integer :: first, line_no
      yes = .false.
      first = 1
      line_no = 0
      do while (first <= len(text) .and. line_no < 10000)
         call next_line(text, first, line_no, s)
         if (len(s) == 0) cycle
         if (s(1:1) == '*' .and. s(1:min(2, len(s))) /= '**') return
         if (section_of(s) > 0) then
            yes = .true.
            return
         end if
      end do
   end function md_is_moordyn

   !> The section a header line names: 0 not a header (no '---' in it), -1 a header of
   !> no section MoorDyn reads ('--- MoorDyn Input File ---', '--- need this line ---'),
   !> -2 a section MoorDyn v2 has and rodyn does not read (SYROPE IC, EXTERNAL LOADS,
   !> CONTROL). MoorDyn's test (MoorDyn2.cpp, findStartOfSection): the line holds '---'
   !> and, in upper case, one of the section's names.
   pure integer function section_of(s) result(k)
      character(len=*), intent(in) :: s !< a cleaned line
      character(len=:), allocatable :: u
      k = 0
      if (index(s, '---') == 0) return
      u = upper_case(s)
      if (has(u, 'LINE DICTIONARY') .or. has(u, 'LINE TYPES')) then
         k = md_line_types
      else if (has(u, 'ROD DICTIONARY') .or. has(u, 'ROD TYPES')) then
         k = md_rod_types
      else if (has(u, 'BODY LIST') .or. has(u, 'BODY PROPERTIES') .or. has(u, 'BODIES')) then
         k = md_bodies
      else if (has(u, 'ROD LIST') .or. has(u, 'ROD PROPERTIES') .or. has(u, 'RODS')) then
         k = md_rods
      else if (has(u, 'NODE PROPERTIES') .or. has(u, 'CONNECTION PROPERTIES') .or. &
               has(u, 'POINT PROPERTIES') .or. has(u, 'POINT LIST') .or. has(u, 'POINTS')) then
         k = md_points
      else if (has(u, 'LINE PROPERTIES') .or. has(u, 'LINE LIST') .or. has(u, 'LINES')) then
         k = md_lines
      else if (has(u, 'FAILURE')) then
         k = md_failure
      else if (has(u, 'OPTIONS')) then
         k = md_options
      else if (has(u, 'OUTPUT')) then
         k = md_outputs
      else if (has(u, 'SYROPE') .or. has(u, 'EXTERNAL LOADS') .or. has(u, 'CONTROL')) then
         k = -2
      else
         k = -1
      end if
   contains
      pure logical function has(a, b)
         character(len=*), intent(in) :: a, b
         has = index(a, b) > 0
      end function has
   end function section_of

   !> Read the MoorDyn file `path` into its sections. Errors (stat_input, 'PATH:LINE:
   !> error: ...'): a file that cannot be read, no section, a section given twice, a
   !> header line that names no section MoorDyn has, a table cut off in its heads.
   subroutine md_read(path, md, err)
      character(len=*), intent(in) :: path  !< the file
      type(md_file_t), intent(out) :: md    !< its sections
      type(error_t), intent(inout) :: err   !< status
      character(len=:), allocatable :: text, s, msg
      logical :: ok
      integer :: first, line_no, cur, skip, k

      md%path = path
      md%title = ''
      call read_file_text(path, text, ok)
      if (.not. ok) then
         call set_error(err, stat_input, path//': error: cannot open the MoorDyn file')
         return
      end if
      msg = encoding_problem(text)
      if (len(msg) > 0) then
         call set_error(err, stat_input, path//':1: error: '//msg)
         return
      end if
      text = without_cr(text)
      do k = 1, md_n_sections
         allocate (md%sec(k)%rows(8))
         allocate (md%sec(k)%columns(0))
      end do
      cur = 0
      skip = 0
      first = 1
      line_no = 0
      do while (first <= len(text))
         call next_line(text, first, line_no, s)
         k = section_of(s)
         if (k == 0 .and. skip > 0) then     ! the column names and units, whatever they hold
            if (skip == head_rows(cur)) md%sec(cur)%columns = split_blanks(s)
            skip = skip - 1
            cycle
         end if
         if (len(s) == 0) cycle
         if (k == -2) then
            call set_error(err, stat_input, where(line_no)//'"'//s//'": a section of '// &
                           'MoorDyn that rodyn does not read (docs/moordyn.md, "What is not read")')
            return
         else if (k == -1) then
            cur = -1
            skip = 0
            cycle
         else if (k > 0) then
            if (md%sec(k)%line > 0) then
               call set_error(err, stat_input, where(line_no)//trim(md_section_names(k))// &
                              ': a second '//trim(md_section_names(k))// &
                              ' section (the first is at line '// &
                              int_str(md%sec(k)%line)//')')
               return
            end if
            md%sec(k)%line = line_no
            cur = k
            skip = head_rows(k)
            cycle
         end if
         if (cur <= 0 .and. all(md%sec(:)%line == 0)) then
            if (len(md%title) > 0) md%title = md%title//' '
            md%title = md%title//s
         else if (cur == -1) then
            call set_error(err, stat_input, where(line_no)//'a row after a line of dashes '// &
                           'that names no MoorDyn section (LINE TYPES, ROD TYPES, BODIES, '// &
                           'RODS, POINTS, LINES, FAILURE, OPTIONS, OUTPUTS)')
            return
         else
            call add_row(md%sec(cur), line_no, s)
         end if
      end do
      if (cur > 0 .and. skip > 0 .and. md%sec(max(cur, 1))%n == 0) then
         call set_error(err, stat_input, where(md%sec(cur)%line)// &
                        trim(md_section_names(cur))//': the table ends in its two lines '// &
                        'of column names and units')
         return
      end if
      if (all(md%sec(:)%line == 0)) call set_error(err, stat_input, path// &
         ':1: error: no MoorDyn section (a line of dashes naming LINE TYPES, POINTS, '// &
         'LINES, ...) in the file')
   contains
      function where(line) result(w)
         integer, intent(in) :: line
         character(len=:), allocatable :: w
         w = path//':'//int_str(line)//': error: '
      end function where
   end subroutine md_read

   !> Append a row of fields to a section, the storage doubled when full.
   subroutine add_row(sec, line, s)
      type(md_section_t), intent(inout) :: sec !< the section
      integer, intent(in) :: line              !< the row's line
      character(len=*), intent(in) :: s        !< the row's text
      type(md_row_t), allocatable :: tmp(:)
      type(field_t), allocatable :: f(:)
      integer :: k
      if (sec%n == size(sec%rows)) then
         allocate (tmp(2*sec%n))
         do k = 1, sec%n
            call move_row(sec%rows(k), tmp(k))
         end do
         call move_alloc(tmp, sec%rows)
      end if
      f = split_blanks(s)
      if (size(f) == 0) return          ! a comment line
      sec%n = sec%n + 1
      sec%rows(sec%n)%line = line
      call move_alloc(f, sec%rows(sec%n)%f)
   end subroutine add_row

   !> Move a row's fields without copying them.
   subroutine move_row(from, to)
      type(md_row_t), intent(inout) :: from !< row moved
      type(md_row_t), intent(inout) :: to   !< its new place
      to%line = from%line
      call move_alloc(from%f, to%f)
   end subroutine move_row

   !> The fields of a line, separated by runs of blanks (clean_line has made tabs
   !> blanks); the first field holding '#' and all after it are a comment (MoorDyn's
   !> rule, Misc.cpp str::split).
   pure function split_blanks(s) result(f)
      character(len=*), intent(in) :: s    !< the line
      type(field_t), allocatable :: f(:)   !< its fields
      integer :: k, n, start
      n = 0
      do k = 1, len(s)
         if (s(k:k) /= ' ' .and. (k == 1 .or. s(max(k - 1, 1):max(k - 1, 1)) == ' ')) n = n + 1
      end do
      allocate (f(n))
      n = 0
      start = 0
      do k = 1, len(s) + 1
         if (k <= len(s)) then
            if (s(k:k) /= ' ') then
               if (start == 0) start = k
               cycle
            end if
         end if
         if (start > 0) then
            if (index(s(start:k - 1), '#') > 0) exit
            n = n + 1
            f(n)%s = s(start:k - 1)
            start = 0
         end if
      end do
      if (n < size(f)) f = f(1:n)
   end function split_blanks
end module rodyn_moordyn_file
