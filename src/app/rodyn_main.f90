!> rodyn: static and dynamic analysis of marine cables, risers and mooring lines as
!> geometrically exact rods. Reads a keyword deck; solves the static equilibrium when the
!> deck calls for it (always, unless *DYNAMIC, START=DEFINED comes without *STATIC), then
!> the dynamics if *DYNAMIC is given; writes CSV tables and HDF5 files.
!> Exit status: 0 success, 1 bad input, 2 numerical failure, 3 I/O failure.
program rodyn
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use rodyn_kinds, only: rodyn_version
   use rodyn_error, only: error_t, has_error, set_error, stat_ok, stat_io, stat_input, &
                          stat_numerical
   use rodyn_cli, only: cli_options_t, cli_parse, cli_usage
   use rodyn_model, only: model_t, scheme_names, scheme_emc, scheme_alpha
   use rodyn_deck, only: deck_read
   use rodyn_moordyn, only: moordyn_file, moordyn_read, moordyn_deck_text
   use rodyn_mesh, only: mesh_t, mesh_build
   use rodyn_mesh_checks, only: fix_leading_dots
   use rodyn_state, only: state_t
   use rodyn_statics, only: static_problem_t, statics_run
   use rodyn_assembly, only: dof_map
   use rodyn_recovery, only: recover_static, recover_system
   use rodyn_offset_curve, only: offset_curve
   use rodyn_modal, only: modal_analysis
   use rodyn_results, only: line_result_t, run_summary_t, system_result_t
   use rodyn_output, only: output_write_static, output_write_status, status_dynamics_pending
   use rodyn_outdir, only: outdir_lock_t, outdir_lock, outdir_unlock
   use rodyn_run_dynamic, only: run_dynamic, dynamic_not_available, stderr_is_terminal
   use rodyn_checkpoint, only: checkpoint_t, checkpoint_read
   use rodyn_kinds, only: wp
   implicit none

   interface
      subroutine c_exit(status) bind(c, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
      !> POSIX _exit(2): leave without the exit handlers (HDF5's among them).
      subroutine c_quick_exit(status) bind(c, name='_exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_quick_exit
   end interface

   type(cli_options_t) :: opts
   character(len=160) :: line  ! a line of the terminal summary
   type(error_t) :: err, out_err
   type(model_t) :: model
   type(outdir_lock_t) :: lock   ! the output folder's lock, released in finish
   type(mesh_t), target :: mesh
   type(state_t), target :: state
   type(static_problem_t), allocatable :: prob
   type(system_result_t) :: system
   type(run_summary_t) :: summary
   type(line_result_t), allocatable :: lines(:)
   type(state_t), target :: dstate
   type(checkpoint_t) :: ck      ! --restart: the checkpoint continued
   real(wp), allocatable :: r0(:, :)
   character(len=:), allocatable :: missing, warnings, notes, deck_text
   logical :: static_runs, show_progress
   integer :: log_unit, n_dof, half_bw
   integer, allocatable :: dof_first(:), dof_count(:)

   call cli_parse(opts, err)
   if (has_error(err)) then
      write (error_unit, '(a)') err%message
      write (error_unit, '(a)') cli_usage
      call finish(err%code)
   end if
   if (opts%help) then
      write (output_unit, '(a)') cli_usage
      call finish(stat_ok)
   end if
   if (opts%version) then
      write (output_unit, '(2a)') 'rodyn ', rodyn_version
      call finish(stat_ok)
   end if

   warnings = ''
   notes = ''
   if (moordyn_file(opts%deck)) then
      if (opts%to_deck) then
         call moordyn_deck_text(opts%deck, deck_text, notes, err)
         if (.not. has_error(err)) write (output_unit, '(a)', advance='no') deck_text
         if (has_error(err)) write (error_unit, '(a)') err%message
         call finish(err%code)
      end if
      if (size(opts%sets) > 0) call set_error(err, stat_input, 'rodyn: error: --set: '// &
                                              opts%deck//' is a MoorDyn file: no *PARAMETER')
      if (.not. has_error(err)) call moordyn_read(opts%deck, model, err, notes, warnings)
      if (len(notes) > 0 .and. .not. opts%quiet) write (output_unit, '(a)', advance='no') notes
   else if (opts%to_deck) then
      write (error_unit, '(a)') 'rodyn: error: --to-deck: '//opts%deck//' is not a MoorDyn '// &
         'input file (no line of dashes naming LINE TYPES, POINTS, LINES, ...)'
      call finish(stat_input)
   else
      call deck_read(opts%deck, model, err, opts%sets, warnings)
   end if
   if (len(warnings) > 0) write (error_unit, '(a)', advance='no') warnings
   ! --check computes nothing: the lines' starting catenaries are solved only for a run
   if (.not. has_error(err)) call mesh_build(model, mesh, state, err, &
                                             initial_shape=.not. opts%check)
   if (has_error(err)) then
      write (error_unit, '(a)') err%message
      ! a starting shape that cannot be computed is a failed run: status.txt says so
      if (err%code == stat_numerical) then
         summary%status = err%message
         call output_write_status(opts%outdir, summary, out_err, opts%deck, model%parameters)
         if (has_error(out_err)) write (error_unit, '(a)') out_err%message
      end if
      call finish(err%code)
   end if
   call dof_map(mesh, dof_first, dof_count, n_dof, half_bw)
   if (opts%check) then
      if (.not. opts%quiet) write (output_unit, '(a,i0,a,i0,a,i0,a,i0,a)') &
         opts%deck//': ok: ', mesh%n_lines, ' line(s), ', mesh%n_elements, ' elements, ', &
         mesh%n_nodes, ' nodes, ', n_dof, ' unknowns'
      call finish(stat_ok)
   end if

   ! --restart: the checkpoint is read and checked before anything is computed
   if (opts%restart .and. .not. model%dynamic%requested) call set_error(err, stat_input, &
      'rodyn: error: --restart: '//opts%deck//' has no *DYNAMIC: there is no run to continue')
   ! a run stopped between its statics and its dynamics (status.txt says the dynamics
   ! are still to run) has no checkpoint of its dynamics: the whole deck runs again
   if (opts%restart .and. .not. has_error(err)) then
      if (status_dynamics_pending(opts%outdir)) then
         opts%restart = .false.
         if (.not. opts%quiet) write (output_unit, '(a)') 'rodyn: --restart '// &
            opts%outdir//': the dynamics have not started (status.txt): running the deck'
      end if
   end if
   if (opts%restart) call checkpoint_read(opts%outdir, model, state, ck, err)
   if (has_error(err)) then
      write (error_unit, '(a)') err%message
      call finish(err%code)
   end if

   missing = dynamic_not_available(model)
   if (len(missing) > 0) then
      write (error_unit, '(a)') opts%deck//': error: '//missing
      call finish(stat_input)
   end if
   static_runs = (.not. model%dynamic%requested .or. model%dynamic%start_static .or. &
                  model%static%requested) .and. .not. opts%restart
   dstate = state        ! the defined start, kept for a START=DEFINED dynamic run

   ! the output folder is made and marked 'running' before any computing: an unwritable
   ! folder fails now, and a run killed midway leaves a status that says so
   if (opts%restart) summary = ck%summary   ! the static run's counters, kept
   summary%status = 'running'
   ! one run per output folder: a second run into it is refused here (exit 3)
   call outdir_lock(opts%outdir, lock, err)
   if (.not. has_error(err)) call output_write_status(opts%outdir, summary, err, opts%deck, &
                                                      model%parameters)
   if (has_error(err)) then
      write (error_unit, '(a)') err%message
      call finish(err%code)
   end if
   log_unit = -1
   if (opts%verbose .and. .not. opts%quiet) log_unit = output_unit

   allocate (r0(6, mesh%n_nodes))
   r0 = 0.0_wp
   if (static_runs) then
      if (.not. opts%quiet) write (output_unit, '(a,i0,a,i0,a)') 'rodyn '//rodyn_version// &
         ': '//opts%deck//': static analysis, ', mesh%n_elements, ' elements, ', &
         n_dof, ' unknowns'
      allocate (prob)
      call statics_run(prob, model, mesh, state, summary, err, log_unit)
      if (has_error(err)) write (error_unit, '(a)') opts%deck//': error: '//err%message
      ! results of the last converged state, complete or not
      call recover_static(model, prob, lines)
      if (summary%complete) then
         call recover_system(model, prob, system, err)
         call modal_analysis(model, prob, system, err)
         if (.not. has_error(err)) call offset_curve(prob, model, system, err)
         if (has_error(err)) then     ! the equilibrium stands; what follows it failed
            summary%complete = .false.
            summary%status = err%message
            write (error_unit, '(a)') opts%deck//': error: '//err%message
         end if
         call output_write_static(opts%outdir, model, lines, summary, out_err, system)
      else
         call output_write_static(opts%outdir, model, lines, summary, out_err)
      end if
      if (has_error(out_err)) then
         write (error_unit, '(a)') out_err%message
         if (.not. has_error(err)) call finish(stat_io)
      end if
      if (.not. opts%quiet .and. summary%complete) then
         write (line, '(a,i0,a,i0,a,i0,a,f0.3,a)') 'static solution: ', &
            summary%increments, ' increment(s), ', summary%iterations, ' iterations, ', &
            summary%cutbacks, ' cut-backs, ', summary%wall_time, ' s'
         write (output_unit, '(a)') fix_leading_dots(trim(line))
      end if
      if (has_error(err)) then
         if (.not. opts%quiet) write (output_unit, '(a)') 'results in '//opts%outdir//'/'
         call finish(err%code)
      end if
      if (model%dynamic%start_static) then
         dstate = state
         r0 = prob%r
      end if
      ! the static problem is not needed any more: a dynamic run has its own workspace
      deallocate (prob, lines)
   end if

   if (model%dynamic%requested) then
      if (.not. opts%quiet) write (output_unit, '(a,i0,a,es10.3,a,es10.3,a)') &
         'dynamic analysis: '//trim(scheme_name(model%dynamic%scheme))// &
         trim(rho_text(model))//', ', &
         nint(model%dynamic%duration/model%dynamic%dt), ' steps of ', model%dynamic%dt, &
         ' s to ', model%dynamic%duration, ' s'
      summary%complete = .false.
      deallocate (summary%status)
      show_progress = stderr_is_terminal()
      show_progress = (opts%progress .or. show_progress) .and. .not. opts%quiet
      if (opts%restart) then
         if (.not. opts%quiet) write (output_unit, '(a,es10.3,a)') &
            'continued from the checkpoint at t = ', ck%loop%t, ' s'
         dstate = ck%start
         call run_dynamic(model, mesh, dstate, r0, opts%outdir, summary, err, log_unit, &
                          show_progress, ck)
      else
         call run_dynamic(model, mesh, dstate, r0, opts%outdir, summary, err, log_unit, &
                          show_progress)
      end if
      if (has_error(err)) write (error_unit, '(a)') opts%deck//': error: '//err%message
      if (.not. opts%quiet .and. .not. has_error(err)) write (output_unit, &
         '(a,i0,a,i0,a,i0,a,i0,a)') 'dynamic solution: ', summary%steps, ' steps, ', &
         summary%step_iterations, ' Newton iterations, ', summary%step_tangents, &
         ' tangents, ', summary%step_cutbacks, ' halvings'
      if (.not. opts%quiet .and. .not. has_error(err) .and. summary%step_cutbacks > 0) &
         call halving_note(model)
   end if
   if (.not. opts%quiet) write (output_unit, '(a)') 'results in '//opts%outdir//'/'
   if (has_error(err)) call finish(err%code)
   call finish(stat_ok)

contains

   !> After a conservative EMC run (RHO INF = 1) that halved its step: the sections
   !> without axial damping, and two remedies measured on a line with a free end
   !> (docs/dynamics.md, "Refinement with a slack end"). EMC keeps the energy of the axial
   !> modes a step does not resolve; slack-taut switching feeds them, and Newton then
   !> needs smaller steps.
   subroutine halving_note(model)
      type(model_t), intent(in) :: model !< model
      character(len=:), allocatable :: names
      integer :: i
      if (model%dynamic%scheme /= scheme_emc .or. model%dynamic%rho_inf < 1.0_wp) return
      names = ''
      do i = 1, size(model%sections)
         if (model%sections(i)%axial_damping > 0.0_wp .or. &
             model%sections(i)%axial_damping_ratio > 0.0_wp) cycle
         if (len(names) > 0) names = names//', '
         names = names//trim(model%sections(i)%name)
      end do
      if (len(names) == 0) return
      write (output_unit, '(a)') 'note: EMC keeps the energy of the axial modes a step '// &
         'does not resolve, which slack-taut switching feeds; AXIAL DAMPING RATIO=1 on '// &
         '*SECTION '//names//' (MoorDyn''s BA = -1), or RHO INF=0.8 on *DYNAMIC (the '// &
         'dissipative EMC), damps them (docs/dynamics.md, "Refinement with a slack end")'
   end subroutine halving_note

   !> ' (RHO INF r)' for ALPHA and the dissipative EMC, else ''.
   function rho_text(model) result(text)
      type(model_t), intent(in) :: model !< model
      character(len=:), allocatable :: text
      character(len=16) :: buf
      text = ''
      if (model%dynamic%rho_inf >= 1.0_wp .and. model%dynamic%scheme == scheme_emc) return
      if (model%dynamic%scheme /= scheme_emc .and. model%dynamic%scheme /= scheme_alpha) return
      write (buf, '(f6.3)') model%dynamic%rho_inf
      text = ' (RHO INF '//trim(adjustl(buf))//')'
   end function rho_text

   !> Name of a scheme for the log.
   function scheme_name(k) result(name)
      integer, intent(in) :: k !< scheme_* constant
      character(len=12) :: name
      name = scheme_names(k)
   end function scheme_name

   !> Release the output folder's lock, flush and leave with the given exit status (no
   !> STOP text on the terminal). Every file is closed by then; after a failure the
   !> exit handlers are skipped: HDF5's would try again to flush a file whose close
   !> failed (a full disk) and crash.
   subroutine finish(code)
      integer, intent(in) :: code !< exit status
      call outdir_unlock(lock)
      flush (output_unit)
      flush (error_unit)
      if (code /= stat_ok) call c_quick_exit(int(code, c_int))
      call c_exit(int(code, c_int))
   end subroutine finish
end program rodyn
