!> rodyn: static analysis of marine cables, risers and mooring lines as geometrically
!> exact rods. Reads a keyword deck, solves, writes CSV tables and an HDF5 file.
!> Exit status: 0 success, 1 bad input, 2 numerical failure, 3 I/O failure.
program rodyn
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use rodyn_kinds, only: rodyn_version
   use rodyn_error, only: error_t, has_error, stat_ok, stat_io
   use rodyn_cli, only: cli_options_t, cli_parse, cli_usage
   use rodyn_model, only: model_t
   use rodyn_deck, only: deck_read
   use rodyn_mesh, only: mesh_t, mesh_build
   use rodyn_state, only: state_t
   use rodyn_statics, only: static_problem_t, statics_run
   use rodyn_recovery, only: recover_static
   use rodyn_results, only: line_result_t, run_summary_t
   use rodyn_output, only: output_write_static, output_write_status
   implicit none

   interface
      subroutine c_exit(status) bind(c, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
   end interface

   type(cli_options_t) :: opts
   type(error_t) :: err, out_err
   type(model_t) :: model
   type(mesh_t), target :: mesh
   type(state_t), target :: state
   type(static_problem_t) :: prob
   type(run_summary_t) :: summary
   type(line_result_t), allocatable :: lines(:)
   integer :: log_unit

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

   call deck_read(opts%deck, model, err)
   if (.not. has_error(err)) call mesh_build(model, mesh, state, err)
   if (has_error(err)) then
      write (error_unit, '(a)') err%message
      call finish(err%code)
   end if
   if (opts%check) then
      if (.not. opts%quiet) write (output_unit, '(a,i0,a,i0,a,i0,a,i0,a)') &
         opts%deck//': ok: ', mesh%n_lines, ' line(s), ', mesh%n_elements, ' elements, ', &
         mesh%n_nodes, ' nodes, ', 6*mesh%n_nodes, ' unknowns'
      call finish(stat_ok)
   end if

   if (.not. opts%quiet) write (output_unit, '(a,i0,a,i0,a)') 'rodyn '//rodyn_version// &
      ': '//opts%deck//': static analysis, ', mesh%n_elements, ' elements, ', &
      6*mesh%n_nodes, ' unknowns'
   ! the output folder is made and marked 'running' before any computing: an unwritable
   ! folder fails now, and a run killed midway leaves a status that says so
   summary%status = 'running'
   call output_write_status(opts%outdir, summary, err, opts%deck)
   if (has_error(err)) then
      write (error_unit, '(a)') err%message
      call finish(err%code)
   end if
   log_unit = -1
   if (opts%verbose .and. .not. opts%quiet) log_unit = output_unit
   call statics_run(prob, model, mesh, state, summary, err, log_unit)
   if (has_error(err)) write (error_unit, '(a)') opts%deck//': error: '//err%message

   ! results of the last converged state, complete or not
   call recover_static(model, prob, lines)
   call output_write_static(opts%outdir, model, lines, summary, out_err)
   if (has_error(out_err)) then
      write (error_unit, '(a)') out_err%message
      if (.not. has_error(err)) call finish(stat_io)
   end if
   if (.not. opts%quiet) then
      if (summary%complete) then
         write (output_unit, '(a,i0,a,i0,a,i0,a,f0.3,a)') 'static solution: ', &
            summary%increments, ' increment(s), ', summary%iterations, ' iterations, ', &
            summary%cutbacks, ' cut-backs, ', summary%wall_time, ' s'
      end if
      write (output_unit, '(a)') 'results in '//opts%outdir//'/'
   end if
   if (has_error(err)) call finish(err%code)
   call finish(stat_ok)

contains

   !> Flush and leave with the given exit status (no STOP text on the terminal).
   subroutine finish(code)
      integer, intent(in) :: code !< exit status
      flush (output_unit)
      flush (error_unit)
      call c_exit(int(code, c_int))
   end subroutine finish
end program rodyn
