!> A rodyn deck written from a MoorDyn file (rodyn_moordyn_deck): its text grown a line
!> at a time, each line remembering the line of the MoorDyn file it stands for, so that
!> the deck reader's messages point into the MoorDyn file (rodyn_deck_lexer,
!> deck_source_t); the notes for the log (options ignored, with why); and the checked
!> fields of a MoorDyn row: a number, a name, a triple `a|b|c`, each refused with
!> 'FILE:LINE: error: SECTION: column NAME: ...'.
module rodyn_moordyn_out
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, set_error, has_error, stat_input
   use rodyn_deck_text, only: field_t, lf
   use rodyn_deck_numbers, only: parse_real, int_str
   use rodyn_moordyn_file, only: md_row_t, md_section_names
   implicit none
   private
   public :: md_deck_t, md_info_t, put, note, md_real, md_columns, md_fail, md_text_of, word

   !> What a host program needs of a MoorDyn file besides the model.
   type :: md_info_t
      !> the rods a host program moves (Coupled, Vessel: their IDs, in order); the points
      !> and bodies it moves are those of the deck with HOST=YES
      integer, allocatable :: coupled_rods(:)
      integer :: n_points = 0                 !< MoorDyn's points (the deck's first)
      integer :: n_bodies = 0                 !< MoorDyn's bodies (the deck's first)
      !> OUTPUTS: the channels' names and lines; write the units row (WriteUnits > 0)
      type(field_t), allocatable :: outputs(:)
      integer, allocatable :: output_line(:)
      logical :: write_units = .true.
      logical :: external_waves = .false.     !< WaveKin 1: the host gives the water's
                                              !< velocity and acceleration at the nodes
      integer, allocatable :: rod_nodes(:)    !< (rods) NumSegs + 1 of each rod
      real(wp), allocatable :: rod_ends(:, :) !< (6, rods) its ends A and B [m]
   end type md_info_t

   !> The deck being written.
   type :: md_deck_t
      character(len=:), allocatable :: path   !< the MoorDyn file
      character(len=:), allocatable :: text   !< the deck's lines, each ended by LF
      integer, allocatable :: map(:)          !< line of the MoorDyn file of each line
      integer :: n = 0                        !< lines written
      character(len=:), allocatable :: notes  !< 'FILE:LINE: note: ...' lines, LF-ended
      type(md_info_t) :: info                 !< for a host program
   end type md_deck_t

contains

   !> Append a line of deck standing for line `at` of the MoorDyn file (0: none).
   subroutine put(d, s, at)
      type(md_deck_t), intent(inout) :: d   !< the deck
      character(len=*), intent(in) :: s     !< the line
      integer, intent(in) :: at             !< its MoorDyn line
      integer, allocatable :: tmp(:)
      if (.not. allocated(d%map)) then
         allocate (d%map(64))
         d%text = ''
      end if
      if (d%n == size(d%map)) then
         allocate (tmp(2*d%n))
         tmp(1:d%n) = d%map(1:d%n)
         call move_alloc(tmp, d%map)
      end if
      d%n = d%n + 1
      d%map(d%n) = at
      d%text = d%text//s//lf
   end subroutine put

   !> A note for the log, located at line `at` of the MoorDyn file.
   subroutine note(d, at, s)
      type(md_deck_t), intent(inout) :: d   !< the deck
      integer, intent(in) :: at             !< MoorDyn line
      character(len=*), intent(in) :: s     !< what to say
      if (.not. allocated(d%notes)) d%notes = ''
      d%notes = d%notes//d%path//':'//int_str(at)//': note: '//s//lf
   end subroutine note

   !> An error at a row: 'FILE:LINE: error: SECTION: message'.
   subroutine md_fail(d, sec, row, message, err)
      type(md_deck_t), intent(in) :: d      !< the deck (its MoorDyn path)
      integer, intent(in) :: sec            !< the section (md_line_types, ...)
      type(md_row_t), intent(in) :: row     !< the row
      character(len=*), intent(in) :: message !< what is wrong
      type(error_t), intent(inout) :: err   !< status
      if (has_error(err)) return
      call set_error(err, stat_input, d%path//':'//int_str(row%line)//': error: '// &
                     trim(md_section_names(sec))//': '//message)
   end subroutine md_fail

   !> A row has at least the columns `names` (blank-separated, the first required ones).
   subroutine md_columns(d, sec, row, names, n_min, err)
      type(md_deck_t), intent(in) :: d      !< the deck
      integer, intent(in) :: sec            !< the section
      type(md_row_t), intent(in) :: row     !< the row
      character(len=*), intent(in) :: names !< the columns' names, as MoorDyn's docs
      integer, intent(in) :: n_min          !< columns required
      type(error_t), intent(inout) :: err   !< status
      if (size(row%f) >= n_min) return
      call md_fail(d, sec, row, int_str(size(row%f))//' values where '//int_str(n_min)// &
                   ' are needed ('//names//'): the column '//word(names, size(row%f) + 1)// &
                   ' is missing', err)
   end subroutine md_columns

   !> Column k of a row as a real; `name` names the column in the message.
   subroutine md_real(d, sec, row, k, name, x, err)
      type(md_deck_t), intent(in) :: d      !< the deck
      integer, intent(in) :: sec            !< the section
      type(md_row_t), intent(in) :: row     !< the row
      integer, intent(in) :: k              !< the column
      character(len=*), intent(in) :: name  !< its name
      real(wp), intent(out) :: x            !< its value
      type(error_t), intent(inout) :: err   !< status
      character(len=:), allocatable :: msg
      x = 0.0_wp
      if (has_error(err)) return
      call parse_real(row%f(k)%s, x, msg)
      if (len(msg) > 0) call md_fail(d, sec, row, 'column '//name//': '//msg, err)
   end subroutine md_real

   !> The deck's text (for --to-deck).
   function md_text_of(d) result(s)
      type(md_deck_t), intent(in) :: d      !< the deck
      character(len=:), allocatable :: s
      s = ''
      if (allocated(d%text)) s = d%text
   end function md_text_of

   !> Word k of a blank-separated list ('' past its end).
   pure function word(list, k) result(w)
      character(len=*), intent(in) :: list  !< the list
      integer, intent(in) :: k              !< which word
      character(len=:), allocatable :: w
      integer :: j, p, q
      p = 1
      w = ''
      do j = 1, k
         do while (p <= len(list))
            if (list(p:p) /= ' ') exit
            p = p + 1
         end do
         q = index(list(p:)//' ', ' ')
         if (j == k) w = list(p:p + q - 2)
         p = p + q
      end do
   end function word
end module rodyn_moordyn_out
