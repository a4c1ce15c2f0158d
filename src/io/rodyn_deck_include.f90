!> Deck lexer, `*INCLUDE, INPUT=path`: the path taken from the including file's folder,
!> include cycles and nesting deeper than max_include_depth levels refused, the file's
!> text read; the lexer (rodyn_deck_lexer) then reads its lines as those of the deck.
module rodyn_deck_include
   use rodyn_error, only: error_t, has_error
   use rodyn_deck_text, only: field_t
   use rodyn_deck_numbers, only: int_str
   use rodyn_deck_files, only: read_file_text, path_normalise
   use rodyn_deck_card, only: card_t, card_check_params, card_error, param_len
   use rodyn_deck_card_values, only: card_get_file
   implicit none
   private
   public :: include_open, max_include_depth

   integer, parameter :: max_include_depth = 10 !< deepest *INCLUDE nesting allowed

contains

   !> Open the file of one *INCLUDE card: check the card, take the path from the
   !> including file's folder, refuse cycles and nesting deeper than max_include_depth,
   !> read the file's text; its normalised path goes on the stack at depth + 1.
   subroutine include_open(card, depth, stack, path, text, err)
      type(card_t), intent(in) :: card           !< the *INCLUDE card
      integer, intent(in) :: depth               !< include depth of the including file
      type(field_t), intent(inout) :: stack(0:)  !< normalised paths of the open files
      character(len=:), allocatable, intent(out) :: path !< the included file's path
      character(len=:), allocatable, intent(out) :: text !< its contents
      type(error_t), intent(inout) :: err        !< status
      character(len=:), allocatable :: norm
      integer :: k
      logical :: ok

      call card_check_params(card, [character(len=param_len) :: 'INPUT'], err)
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
   end subroutine include_open

end module rodyn_deck_include
