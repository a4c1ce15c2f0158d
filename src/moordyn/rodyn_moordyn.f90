!> The MoorDyn layer's face (docs/moordyn.md): whether a file is a MoorDyn v2 input
!> file, and such a file read into a validated model_t through the rodyn deck it
!> translates to (rodyn_moordyn_deck), every message located in the MoorDyn file.
module rodyn_moordyn
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t
   use rodyn_deck_files, only: read_file_text
   use rodyn_deck, only: deck_read, deck_source_t
   use rodyn_moordyn_file, only: md_file_t, md_read, md_is_moordyn
   use rodyn_moordyn_out, only: md_deck_t, md_info_t
   use rodyn_moordyn_deck, only: md_to_deck
   implicit none
   private
   public :: moordyn_file, moordyn_read, moordyn_deck_text, md_info_t

contains

   !> Whether the file at path is a MoorDyn input file (false when it cannot be read).
   logical function moordyn_file(path) result(yes)
      character(len=*), intent(in) :: path  !< the file
      character(len=:), allocatable :: text
      logical :: ok
      call read_file_text(path, text, ok)
      yes = .false.
      if (ok) yes = md_is_moordyn(text)
   end function moordyn_file

   !> The rodyn deck of the MoorDyn file at path: its text and its notes ('FILE:LINE:
   !> note: ...' lines: options ignored, points held for a host).
   subroutine moordyn_deck_text(path, text, notes, err)
      character(len=*), intent(in) :: path  !< the MoorDyn file
      character(len=:), allocatable, intent(out) :: text  !< the deck
      character(len=:), allocatable, intent(out) :: notes !< the notes, LF-ended lines
      type(error_t), intent(inout) :: err   !< status (stat_input)
      type(md_deck_t) :: d
      call translate(path, d, notes, err)
      text = ''
      if (allocated(d%text)) text = d%text
   end subroutine moordyn_deck_text

   !> The MoorDyn file at path read and written as a deck, with its notes.
   subroutine translate(path, d, notes, err, host)
      character(len=*), intent(in) :: path  !< the MoorDyn file
      type(md_deck_t), intent(out) :: d     !< the deck
      character(len=:), allocatable, intent(out) :: notes !< the notes, LF-ended lines
      type(error_t), intent(inout) :: err   !< status (stat_input)
      logical, intent(in), optional :: host !< for a host program's steps (md_to_deck)
      type(md_file_t) :: md
      notes = ''
      call md_read(path, md, err)
      if (has_error(err)) return
      call md_to_deck(md, d, err, host)
      if (allocated(d%notes)) notes = d%notes
   end subroutine translate

   !> Read the MoorDyn file at path into model, validated as a deck (deck_read) whose
   !> lines are located at the MoorDyn lines they come from; notes as moordyn_deck_text.
   !> For a host program (host present): the model has a *DYNAMIC to step, and info what
   !> the host needs besides (md_info_t: the points and bodies it moves, in MoorDyn's
   !> order, the OUTPUTS, ...).
   subroutine moordyn_read(path, model, err, notes, warnings, host, info)
      character(len=*), intent(in) :: path  !< the MoorDyn file
      type(model_t), intent(out) :: model   !< the model
      type(error_t), intent(inout) :: err   !< status (stat_input)
      character(len=:), allocatable, intent(out) :: notes    !< the notes
      character(len=:), allocatable, intent(out) :: warnings !< the deck's warnings
      logical, intent(in), optional :: host !< read for a host program's steps
      type(md_info_t), intent(out), optional :: info !< for a host program
      type(md_deck_t) :: d
      type(deck_source_t) :: source
      warnings = ''
      call translate(path, d, notes, err, host)
      if (present(info)) info = d%info
      if (has_error(err)) return
      source%text = d%text
      source%line_map = d%map(1:d%n)
      call deck_read(path, model, err, warnings=warnings, source=source)
   end subroutine moordyn_read
end module rodyn_moordyn
