!> Command line of the rodyn program:
!>   rodyn DECK [-o DIR] [--restart DIR] [--set NAME=VALUE ...] [--check] [--to-deck]
!>         [--verbose] [--quiet] [--progress] [--version] [--help]
!> DECK is a rodyn deck or a MoorDyn v2 input file (docs/moordyn.md).
module rodyn_cli
   use rodyn_error, only: error_t, set_error, stat_input
   use rodyn_deck_params, only: param_override_t, param_valid_name, upper_case
   implicit none
   private
   public :: cli_options_t, cli_parse, cli_usage, cli_default_outdir

   !> Parsed command line.
   type :: cli_options_t
      character(len=:), allocatable :: deck    !< input deck path
      character(len=:), allocatable :: outdir  !< output folder ('' = default)
      logical :: check = .false.               !< validate the deck only
      logical :: to_deck = .false.             !< write the deck of a MoorDyn file
      logical :: restart = .false.             !< continue the run in outdir (--restart)
      logical :: verbose = .false.             !< Newton iteration log on stdout
      logical :: quiet = .false.               !< nothing on stdout
      logical :: progress = .false.            !< progress line even when stderr is no terminal
      logical :: version = .false.             !< print the version and exit
      logical :: help = .false.                !< print the usage and exit
      type(param_override_t), allocatable :: sets(:) !< --set NAME=VALUE, in order
   end type cli_options_t

   character(len=*), parameter :: cli_usage = &
      'usage: rodyn DECK [-o DIR] [--restart DIR] [--set NAME=VALUE ...] [--check]'// &
      ' [--to-deck] [--verbose] [--quiet] [--progress] [--version] [--help]'// &
      new_line('a')//new_line('a')// &
      '  DECK           keyword input deck (see docs/deck.md), or a MoorDyn v2 input'// &
      ' file (docs/moordyn.md)'//new_line('a')// &
      '  -o, --output DIR  folder for the results (default: the deck name without'// &
      ' extension)'//new_line('a')// &
      '  --restart DIR  continue the killed dynamic run in folder DIR from its last'// &
      ' checkpoint'//new_line('a')// &
      '  --set NAME=VALUE  value of the deck''s *PARAMETER NAME (repeatable)'// &
      new_line('a')// &
      '  --check        read and validate the deck, build the mesh, compute nothing'// &
      new_line('a')// &
      '  --to-deck      write the rodyn deck of a MoorDyn file on stdout, compute'// &
      ' nothing'//new_line('a')// &
      '  --verbose      log every Newton iteration'//new_line('a')// &
      '  --quiet        print nothing but errors'//new_line('a')// &
      '  --progress     progress line of a dynamic run on stderr (default: only when'// &
      ' stderr is a terminal)'//new_line('a')// &
      '  --version      print the version'//new_line('a')// &
      '  --help         print this text'//new_line('a')//new_line('a')// &
      'exit status: 0 success, 1 bad input, 2 numerical failure, 3 I/O failure'

contains

   !> Read the command line arguments.
   subroutine cli_parse(opts, err)
      type(cli_options_t), intent(out) :: opts !< parsed options
      type(error_t), intent(inout) :: err      !< stat_input on a bad command line
      integer :: i, n, length
      character(len=:), allocatable :: arg
      opts%outdir = ''
      allocate (opts%sets(0))
      n = command_argument_count()
      i = 0
      do while (i < n)
         i = i + 1
         call get_command_argument(i, length=length)
         allocate (character(len=length) :: arg)
         call get_command_argument(i, arg)
         select case (arg)
         case ('-o', '--output', '--restart')
            if (i == n) then
               call set_error(err, stat_input, 'rodyn: error: '//arg//' needs a folder')
               return
            end if
            if (len(opts%outdir) > 0 .and. (arg == '--restart' .or. opts%restart)) then
               call set_error(err, stat_input, 'rodyn: error: '//arg//': the output '// &
                              'folder is given twice (-o and --restart name it both)')
               return
            end if
            if (arg == '--restart') opts%restart = .true.
            i = i + 1
            call get_command_argument(i, length=length)
            deallocate (opts%outdir)
            allocate (character(len=length) :: opts%outdir)
            call get_command_argument(i, opts%outdir)
         case ('--set')
            if (i == n) then
               call set_error(err, stat_input, 'rodyn: error: --set needs NAME=VALUE')
               return
            end if
            i = i + 1
            call get_command_argument(i, length=length)
            deallocate (arg)
            allocate (character(len=length) :: arg)
            call get_command_argument(i, arg)
            call add_set(opts, arg, err)
            if (err%code /= 0) return
         case ('--check')
            opts%check = .true.
         case ('--to-deck')
            opts%to_deck = .true.
         case ('-v', '--verbose')
            opts%verbose = .true.
         case ('-q', '--quiet')
            opts%quiet = .true.
         case ('--progress')
            opts%progress = .true.
         case ('--version')
            opts%version = .true.
         case ('-h', '--help')
            opts%help = .true.
         case default
            if (arg(1:min(1, len(arg))) == '-') then
               call set_error(err, stat_input, 'rodyn: error: unknown option '//arg)
               return
            end if
            if (allocated(opts%deck)) then
               call set_error(err, stat_input, 'rodyn: error: more than one deck given ('// &
                              opts%deck//', '//arg//')')
               return
            end if
            opts%deck = arg
         end select
         deallocate (arg)
      end do
      if (opts%help .or. opts%version) return
      if (.not. allocated(opts%deck)) then
         call set_error(err, stat_input, 'rodyn: error: no deck given')
         return
      end if
      if (len(opts%outdir) == 0) opts%outdir = cli_default_outdir(opts%deck)
   end subroutine cli_parse

   !> Check one --set argument `NAME=VALUE` and append it to opts%sets (NAME upper case).
   subroutine add_set(opts, arg, err)
      type(cli_options_t), intent(inout) :: opts !< options being read
      character(len=*), intent(in) :: arg        !< the argument after --set
      type(error_t), intent(inout) :: err        !< stat_input on bad syntax
      type(param_override_t) :: o
      integer :: eq, k
      eq = index(arg, '=')
      if (eq == 0) then
         call set_error(err, stat_input, "rodyn: error: --set '"//arg// &
                        "': expected NAME=VALUE")
         return
      end if
      o%name = trim(adjustl(arg(:eq - 1)))
      o%text = trim(adjustl(arg(eq + 1:)))
      if (.not. param_valid_name(o%name)) then
         call set_error(err, stat_input, "rodyn: error: --set '"//arg//"': '"//o%name// &
                        "' is not a parameter name (a letter, then letters, digits and '_')")
         return
      end if
      o%name = upper_case(o%name)
      if (len(o%text) == 0) then
         call set_error(err, stat_input, "rodyn: error: --set '"//arg//"': no value")
         return
      end if
      do k = 1, size(opts%sets)
         if (opts%sets(k)%name == o%name) then
            call set_error(err, stat_input, 'rodyn: error: --set '//o%name//' given twice')
            return
         end if
      end do
      opts%sets = [opts%sets, o]
   end subroutine add_set


   !> Default output folder: the deck's file name without folder and extension.
   pure function cli_default_outdir(deck) result(dir)
      character(len=*), intent(in) :: deck !< deck path
      character(len=:), allocatable :: dir
      integer :: slash, dot
      slash = index(deck, '/', back=.true.)
      dir = deck(slash + 1:)
      dot = index(dir, '.', back=.true.)
      if (dot > 1) dir = dir(1:dot - 1)
      if (len(dir) == 0) dir = 'rodyn_results'
   end function cli_default_outdir
end module rodyn_cli
