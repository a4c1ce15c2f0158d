!> Checkpoints of a dynamic run (`*DYNAMIC, CHECKPOINT=c`; docs/dynamics.md "Checkpoint
!> and restart"): everything the time loop, the support-force interpolation and the
!> output writer carry from one step to the next, in `checkpoint.h5` in the output
!> folder, so that `rodyn DECK --restart DIR` continues a killed run and writes the
!> same bits as a run never interrupted.
!>
!> The file is written atomically: '.checkpoint.h5.tmp', flushed and closed, then
!> renamed over the last one. It holds the start state (t = 0: dynamics_setup derives
!> the supports and the prescribed positions from it), the state at t_n (positions,
!> directors, their velocities and, for generalized-alpha, accelerations), the
!> problem's residual, step and Newton reference forces, the time loop's state
!> (timeloop_state_t), the pending support forces of run_dynamic, the run summary and
!> where the output files stand (dynamic_output_mark_t). No factorised tangent: the
!> step after a checkpoint forms a new one in both runs (rodyn_timeloop).
!>
!> A checkpoint is refused (stat_input, exit 1) when it was written by another build
!> of rodyn (the version and a hash of the executable differ) or for another deck (the
!> deck text with its includes expanded, and the parameters used, are compared as text,
!> which is stricter than a hash of them).
module rodyn_checkpoint
   use, intrinsic :: iso_fortran_env, only: int64
   use rodyn_kinds, only: wp, i8, rodyn_version
   use rodyn_error, only: error_t, set_error, has_error, stat_io, stat_input
   use rodyn_model, only: model_t, scheme_emc
   use rodyn_state, only: state_t, state_copy
   use rodyn_dynamics, only: dynamic_problem_t
   use rodyn_results, only: run_summary_t, step_log_t
   use rodyn_timeloop, only: timeloop_state_t
   use rodyn_output_dynamic, only: dynamic_output_mark_t
   use rodyn_hdf5, only: hdf5_file_t, hdf5_create_file, hdf5_open_file, hdf5_close_file, &
                         hdf5_write_dataset, hdf5_read_dataset
   use rodyn_outfile, only: temp_name, commit_rename, remove_file, path_join, outfile_size
   implicit none
   private
   public :: checkpoint_t, checkpoint_write, checkpoint_read, checkpoint_file
   public :: checkpoint_problem
   public :: pending_forces_t
   public :: checkpoint_program_id

   character(len=*), parameter :: checkpoint_file = 'checkpoint.h5' !< name in the folder
   integer, parameter :: n_reals = 36  !< scalars in /reals (see transfer_scalars)
   integer, parameter :: n_ints = 24   !< scalars in /integers (see transfer_scalars)

   !> The support forces of a dynamic run that wait for the step after them (the step
   !> force R, the support force averaged over a step: of the last step converged, r_pend,
   !> length h_pend, ending at t_pend, step number k_pend, and of the step before it,
   !> r_back, h_back; rodyn_run_dynamic's write_pending), as the run and a checkpoint
   !> hold them.
   type :: pending_forces_t
      real(wp), allocatable :: r_pend(:, :)     !< (6, nn) force of the pending step
      real(wp), allocatable :: r_back(:, :)     !< (6, nn) force of the step before it
      real(wp) :: h_pend = 0.0_wp, h_back = 0.0_wp !< their lengths [s]
      real(wp) :: t_pend = 0.0_wp               !< end of the pending step [s]
      integer :: k_pend = 0                     !< its number
      logical :: pending = .false.              !< a step waits for its support forces
      logical :: have_back = .false.            !< r_back is set
      logical :: frame_waiting = .false.        !< a frame waits with it
   end type pending_forces_t

   !> Everything a dynamic run carries from one step to the next.
   type :: checkpoint_t
      type(timeloop_state_t) :: loop            !< the time loop's state
      type(run_summary_t) :: summary            !< counters of the run (static and dynamic)
      type(state_t) :: start                    !< state at t = 0
      type(state_t) :: now                      !< state at t_n
      real(wp), allocatable :: r(:, :)          !< (6, nn) residual of the last step [N, N m]
      real(wp) :: dt = 0.0_wp                   !< length of the last step [s]
      real(wp) :: t0 = 0.0_wp                   !< its start [s]
      real(wp) :: f_conv = 0.0_wp, m_conv = 0.0_wp !< Newton reference force, moment
      real(wp) :: f_last = 0.0_wp, m_last = 0.0_wp !< the same of the last iterate
      logical :: have_conv = .false.            !< a step has converged
      type(pending_forces_t) :: pend            !< the support forces still to write
      type(dynamic_output_mark_t) :: mark       !< where the output files stand
      !> the dissipative EMC's histories (6 max_points, ne) and N at t_n
      !> (rodyn_numerical_dissipation; unallocated without it)
      real(wp), allocatable :: nd_rho(:, :), nd_r(:, :)
      real(wp) :: nd_energy = 0.0_wp
   end type checkpoint_t

contains

   !> The dynamic problem's part of a checkpoint, into ck (save) or from it: the state at
   !> t_n, the last step's support forces, its length and start, Newton's reference
   !> forces, and the dissipative EMC's histories.
   subroutine checkpoint_problem(prob, ck, save)
      type(dynamic_problem_t), intent(inout) :: prob !< problem
      type(checkpoint_t), intent(inout) :: ck        !< checkpoint
      logical, intent(in) :: save                    !< prob into ck (else ck into prob)
      if (save) then
         ck%now = prob%s1
         ck%r = prob%r
      else
         call state_copy(ck%now, prob%s1)
         prob%r = ck%r
      end if
      call r(prob%dt, ck%dt)
      call r(prob%t0, ck%t0)
      call r(prob%f_conv, ck%f_conv)
      call r(prob%m_conv, ck%m_conv)
      call r(prob%f_last, ck%f_last)
      call r(prob%m_last, ck%m_last)
      if (save) ck%have_conv = prob%have_conv
      if (.not. save) prob%have_conv = ck%have_conv
      if (.not. prob%nd%on) return
      if (save) then
         ck%nd_rho = reshape(prob%nd%rho, [size(prob%nd%rho, 1)*size(prob%nd%rho, 2), &
                                           size(prob%nd%rho, 3)])
         ck%nd_r = reshape(prob%nd%r, [size(prob%nd%r, 1)*size(prob%nd%r, 2), &
                                       size(prob%nd%r, 3)])
      else
         prob%nd%rho = reshape(ck%nd_rho, shape(prob%nd%rho))
         prob%nd%r = reshape(ck%nd_r, shape(prob%nd%r))
      end if
      call r(prob%nd%energy, ck%nd_energy)
   contains
      !> One value.
      subroutine r(p, c)
         real(wp), intent(inout) :: p  !< the problem's
         real(wp), intent(inout) :: c  !< the checkpoint's
         if (save) c = p
         if (.not. save) p = c
      end subroutine r
   end subroutine checkpoint_problem

   !> Write ck as dir/checkpoint.h5: to a temporary, closed, then renamed over the old.
   subroutine checkpoint_write(dir, model, program_id, ck, err, file)
      character(len=*), intent(in) :: dir         !< output folder
      type(model_t), intent(in) :: model          !< model (deck text, parameters)
      character(len=*), intent(in) :: program_id  !< checkpoint_program_id(), once a run
      type(checkpoint_t), intent(in) :: ck        !< what to keep
      type(error_t), intent(inout) :: err         !< status
      !> the file's name in dir instead of checkpoint.h5 (a host's MoorDyn_Save)
      character(len=*), intent(in), optional :: file
      type(hdf5_file_t) :: h5
      type(error_t) :: e
      type(checkpoint_t) :: c
      real(wp) :: reals(n_reals)
      integer :: ints(n_ints)
      character(len=:), allocatable :: tmp, name
      if (has_error(err)) return
      c = ck
      call transfer_scalars(c, reals, ints, .true.)
      name = checkpoint_file
      if (present(file)) name = file
      tmp = temp_name(dir, name)
      call hdf5_create_file(h5, tmp, e)
      call hdf5_write_dataset(h5, '/program', program_id, e)
      call hdf5_write_dataset(h5, '/deck', deck_identity(model), e)
      call hdf5_write_dataset(h5, '/reals', reals, e)
      call hdf5_write_dataset(h5, '/integers', ints, e)
      call hdf5_write_dataset(h5, '/csv_bytes', real(ck%mark%csv_bytes, wp), e)
      call hdf5_write_dataset(h5, '/r', ck%r, e)
      call hdf5_write_dataset(h5, '/r_pend', ck%pend%r_pend, e)
      call hdf5_write_dataset(h5, '/r_back', ck%pend%r_back, e)
      if (allocated(ck%nd_rho)) then
         call hdf5_write_dataset(h5, '/nd_rho', ck%nd_rho, e)
         call hdf5_write_dataset(h5, '/nd_r', ck%nd_r, e)
      end if
      call write_state('/start_', ck%start)
      call write_state('/now_', ck%now)
      call hdf5_close_file(h5, e)
      if (.not. has_error(e)) call commit_rename(tmp, path_join(dir, name), e)
      if (has_error(e)) then
         call remove_file(tmp)
         call set_error(err, stat_io, 'cannot write the checkpoint '''// &
                        path_join(dir, name)//''': '//e%message)
      end if
   contains
      !> One state as datasets <prefix>x, d, v, dd (and a, ad when allocated for nodes).
      subroutine write_state(prefix, s)
         character(len=*), intent(in) :: prefix   !< dataset name prefix
         type(state_t), intent(in) :: s           !< state
         call hdf5_write_dataset(h5, prefix//'x', s%x, e)
         call hdf5_write_dataset(h5, prefix//'d', reshape(s%d, [9, size(s%d, 3)]), e)
         call hdf5_write_dataset(h5, prefix//'v', s%v, e)
         call hdf5_write_dataset(h5, prefix//'dd', reshape(s%dd, [9, size(s%dd, 3)]), e)
         if (size(s%a, 2) == 0) return
         call hdf5_write_dataset(h5, prefix//'a', s%a, e)
         call hdf5_write_dataset(h5, prefix//'ad', reshape(s%ad, [9, size(s%ad, 3)]), e)
      end subroutine write_state
   end subroutine checkpoint_write

   !> Read dir/checkpoint.h5 into ck (its states allocated as `like`, nn nodes). Refused
   !> with stat_input when there is none, or it is of another build or another deck.
   subroutine checkpoint_read(dir, model, like, ck, err, file)
      character(len=*), intent(in) :: dir          !< output folder of the run
      type(model_t), intent(in) :: model           !< model (deck text, parameters)
      type(state_t), intent(in) :: like            !< a state of the run's sizes
      type(checkpoint_t), intent(out) :: ck        !< what the checkpoint holds
      type(error_t), intent(inout) :: err          !< status
      !> the file's name in dir instead of checkpoint.h5 (a host's MoorDyn_Load)
      character(len=*), intent(in), optional :: file
      type(hdf5_file_t) :: h5
      type(error_t) :: e
      character(len=:), allocatable :: path
      real(wp), allocatable :: reals(:), bytes(:)
      integer, allocatable :: ints(:)
      if (has_error(err)) return
      path = path_join(dir, checkpoint_file)
      if (present(file)) path = path_join(dir, file)
      if (outfile_size(path) < 0) then
         call set_error(err, stat_input, 'rodyn: error: --restart '//dir//': no checkpoint ('''// &
                        path//''' is missing): the run wrote none (no CHECKPOINT on '// &
                        '*DYNAMIC, or killed before the first); run it again without --restart')
         return
      end if
      call hdf5_open_file(h5, path, e)
      call check_identity(h5, dir, path, model, e, err)
      if (has_error(err)) then
         call hdf5_close_file(h5, e)
         return
      end if
      call hdf5_read_dataset(h5, '/reals', reals, e)
      call hdf5_read_dataset(h5, '/integers', ints, e)
      call hdf5_read_dataset(h5, '/csv_bytes', bytes, e)
      call hdf5_read_dataset(h5, '/r', ck%r, e)
      call hdf5_read_dataset(h5, '/r_pend', ck%pend%r_pend, e)
      call hdf5_read_dataset(h5, '/r_back', ck%pend%r_back, e)
      if (model%dynamic%scheme == scheme_emc .and. model%dynamic%rho_inf < 1.0_wp) then
         call hdf5_read_dataset(h5, '/nd_rho', ck%nd_rho, e)
         call hdf5_read_dataset(h5, '/nd_r', ck%nd_r, e)
      end if
      ck%start = like
      ck%now = like
      call read_state(h5, '/start_', ck%start, e)
      call read_state(h5, '/now_', ck%now, e)
      call hdf5_close_file(h5, e)
      if (.not. has_error(e)) then
         if (size(reals) /= n_reals .or. size(ints) /= n_ints .or. &
             size(bytes) /= size(ck%mark%csv_bytes)) &
            call set_error(e, stat_io, 'wrong sizes')
      end if
      if (has_error(e)) then
         call set_error(err, stat_input, 'rodyn: error: --restart '//dir//': '''//path// &
                        ''' is not a whole checkpoint of this run: '//e%message)
         return
      end if
      call transfer_scalars(ck, reals, ints, .false.)
      ck%mark%csv_bytes = int(bytes, i8)
   end subroutine checkpoint_read

   !> Refuse (err, stat_input) a checkpoint that cannot be read, or that another build of
   !> rodyn or another deck wrote: /program against checkpoint_program_id(), /deck
   !> against deck_identity(model).
   subroutine check_identity(h5, dir, path, model, e, err)
      type(hdf5_file_t), intent(in) :: h5          !< the checkpoint, open
      character(len=*), intent(in) :: dir          !< output folder of the run
      character(len=*), intent(in) :: path         !< the checkpoint's path
      type(model_t), intent(in) :: model           !< model (deck text, parameters)
      type(error_t), intent(inout) :: e            !< status of the reads
      type(error_t), intent(inout) :: err          !< set when refused
      character(len=:), allocatable :: text
      call hdf5_read_dataset(h5, '/program', text, e)
      if (has_error(e)) then
         call set_error(err, stat_input, 'rodyn: error: --restart '//dir//': '''//path// &
                        ''' is not a readable checkpoint: '//e%message)
         return
      end if
      if (text /= checkpoint_program_id()) then
         call set_error(err, stat_input, 'rodyn: error: --restart '//dir//': the '// &
                        'checkpoint was written by another build of rodyn ('//text// &
                        '; this is '//checkpoint_program_id()//'): continue it with that '// &
                        'program, or run the deck again without --restart')
         return
      end if
      call hdf5_read_dataset(h5, '/deck', text, e)
      if (.not. has_error(e) .and. text /= deck_identity(model)) then
         call set_error(err, stat_input, 'rodyn: error: --restart '//dir//': the '// &
                        'checkpoint belongs to another deck (its text, an included file or'// &
                        ' a parameter differs from those of the run in '''//dir// &
                        '''): restart with the same deck and --set values')
      end if
   end subroutine check_identity

   !> One state from <prefix>x, d, ... of a checkpoint into s (allocated for the run's
   !> nodes); e says what is missing or of another size.
   subroutine read_state(h5, prefix, s, e)
      type(hdf5_file_t), intent(in) :: h5        !< the checkpoint, open
      character(len=*), intent(in) :: prefix     !< dataset name prefix
      type(state_t), intent(inout) :: s          !< state read
      type(error_t), intent(inout) :: e          !< status
      real(wp), allocatable :: a2(:, :)
      call get2(prefix//'x', s%x)
      call get2(prefix//'v', s%v)
      call hdf5_read_dataset(h5, prefix//'d', a2, e)
      if (.not. has_error(e)) call fit(a2, size(s%d), s%d)
      call hdf5_read_dataset(h5, prefix//'dd', a2, e)
      if (.not. has_error(e)) call fit(a2, size(s%dd), s%dd)
      if (size(s%a, 2) == 0) return
      call get2(prefix//'a', s%a)
      call hdf5_read_dataset(h5, prefix//'ad', a2, e)
      if (.not. has_error(e)) call fit(a2, size(s%ad), s%ad)
   contains
      !> A (3, nn) array of the same shape as x.
      subroutine get2(name, x)
         character(len=*), intent(in) :: name      !< dataset
         real(wp), intent(inout) :: x(:, :)        !< array read
         real(wp), allocatable :: b2(:, :)
         call hdf5_read_dataset(h5, name, b2, e)
         if (has_error(e)) return
         if (any(shape(b2) /= shape(x))) then
            call set_error(e, stat_io, name//' has another size (another mesh)')
            return
         end if
         x = b2
      end subroutine get2
      !> A (9, nn) array into a (3, 3, nn) one of n values.
      subroutine fit(b2, n, x)
         real(wp), intent(in) :: b2(:, :)          !< values read
         integer, intent(in) :: n                  !< size expected
         real(wp), intent(inout) :: x(:, :, :)     !< array set
         if (size(b2) /= n) then
            call set_error(e, stat_io, 'directors of another size (another mesh)')
            return
         end if
         x = reshape(b2, shape(x))
      end subroutine fit
   end subroutine read_state

   !> The scalars of a checkpoint, in this order: loop t, next_frame, next_checkpoint;
   !> the step log's 17 reals; dt, t0, f_conv, m_conv, f_last, m_last; h_pend, h_back,
   !> t_pend; mark last_time; summary load_factor, wall_time, time_reached; the log's
   !> numerical_work, numerical_energy; nd_energy. Integers: loop level, good; the step
   !> log's step, iterations, tangents, cutbacks; have_conv, k_pend, pending, have_back,
   !> frame_waiting; mark frames, steps, end_rows, step_iterations, step_tangents,
   !> step_cutbacks; summary increments, iterations, cutbacks, steps, step_iterations,
   !> step_tangents, step_cutbacks (over every attempt, failed ones too). One list for
   !> both ways: into x and k (store true) or from them into ck.
   subroutine transfer_scalars(ck, x, k, store)
      type(checkpoint_t), intent(inout) :: ck  !< checkpoint
      real(wp), intent(inout) :: x(n_reals)    !< the reals
      integer, intent(inout) :: k(n_ints)      !< the integers (logicals as 0/1)
      logical, intent(in) :: store             !< ck into x, k (else x, k into ck)
      integer :: nx, nk
      nx = 0
      nk = 0
      associate (l => ck%loop%log, m => ck%mark, s => ck%summary, p => ck%pend)
         call f(ck%loop%t, ck%loop%next_frame, ck%loop%next_checkpoint, l%time, l%dt)
         call f(l%kinetic, l%strain, l%strain_scale, l%gravity, l%external_work)
         call f(l%damping_work, l%hydro_work, l%seabed_work, l%total)
         call f(l%momentum(1), l%momentum(2), l%momentum(3), l%angular_momentum(1), &
                l%angular_momentum(2), l%angular_momentum(3))
         call f(ck%dt, ck%t0, ck%f_conv, ck%m_conv, ck%f_last, ck%m_last)
         call f(p%h_pend, p%h_back, p%t_pend, m%last_time)
         call f(s%load_factor, s%wall_time, s%time_reached, l%numerical_work)
         call f(l%numerical_energy, ck%nd_energy)
         call f(ck%loop%level, ck%loop%good, l%step, l%iterations, l%tangents, l%cutbacks)
         call f(ck%have_conv, p%k_pend, p%pending, p%have_back, p%frame_waiting)
         call f(m%frames, m%steps, m%end_rows, m%step_iterations, m%step_tangents, &
                m%step_cutbacks)
         call f(s%increments, s%iterations, s%cutbacks, s%steps, s%step_iterations, &
                s%step_tangents)
         call f(s%step_cutbacks)
      end associate
   contains
      !> The next fields, in the order given.
      subroutine f(v1, v2, v3, v4, v5, v6)
         class(*), intent(inout) :: v1                     !< component of ck
         class(*), intent(inout), optional :: v2, v3, v4, v5, v6 !< the ones after it
         call one(v1)
         if (present(v2)) call one(v2)
         if (present(v3)) call one(v3)
         if (present(v4)) call one(v4)
         if (present(v5)) call one(v5)
         if (present(v6)) call one(v6)
      end subroutine f
      !> The next field: a real the next of x, an integer the next of k, a logical the
      !> next of k as 1 (true) or 0.
      subroutine one(v)
         class(*), intent(inout) :: v   !< component of ck
         select type (v)
         type is (real(wp))
            nx = nx + 1
            if (store) x(nx) = v
            if (.not. store) v = x(nx)
         type is (integer)
            nk = nk + 1
            if (store) k(nk) = v
            if (.not. store) v = k(nk)
         type is (logical)
            nk = nk + 1
            if (store) k(nk) = merge(1, 0, v)
            if (.not. store) v = k(nk) == 1
         end select
      end subroutine one
   end subroutine transfer_scalars

   !> The deck as a checkpoint identifies it: its full text (includes expanded) and the
   !> parameters used (after --set), one 'NAME = text' line each.
   function deck_identity(model) result(text)
      type(model_t), intent(in) :: model      !< model
      character(len=:), allocatable :: text
      integer :: k
      text = ''
      if (allocated(model%deck_text)) text = model%deck_text
      if (.not. allocated(model%parameters)) return
      do k = 1, size(model%parameters)
         text = text//new_line('a')//'parameter '//model%parameters(k)%name//' = '// &
                model%parameters(k)%text
      end do
   end function deck_identity

   !> The build of rodyn: its version and a 64-bit FNV-1a hash of the executable
   !> (/proc/self/exe), so that a rebuilt program, which may round differently, does
   !> not continue another build's run. 'unknown' in place of the hash when the
   !> executable cannot be read.
   function checkpoint_program_id() result(id)
      character(len=:), allocatable :: id
      integer, parameter :: block_len = 1048576
      character(len=:), allocatable :: buf
      character(len=16) :: hex
      integer(int64) :: size_bytes, pos, h_lo, h_hi
      integer :: unit, stat, n, k
      id = 'rodyn '//rodyn_version//' build unknown'
      open (newunit=unit, file='/proc/self/exe', access='stream', form='unformatted', &
            action='read', status='old', iostat=stat)
      if (stat /= 0) return
      inquire (unit=unit, size=size_bytes)
      ! FNV-1a as two 32-bit halves (offset bases of FNV-32 and a second one), each kept
      ! below 2**32 so that the 64-bit products never overflow
      h_lo = 2166136261_int64
      h_hi = 3735928559_int64
      allocate (character(len=block_len) :: buf)
      pos = 1
      do while (pos <= size_bytes)
         n = int(min(int(block_len, int64), size_bytes - pos + 1))
         read (unit, pos=pos, iostat=stat) buf(1:n)
         if (stat /= 0) then
            close (unit)
            return
         end if
         do k = 1, n
            h_lo = iand(ieor(h_lo, int(iachar(buf(k:k)), int64))*16777619_int64, &
                        4294967295_int64)
            h_hi = iand(ieor(h_hi, int(iachar(buf(k:k)), int64))*16777619_int64 + 1_int64, &
                        4294967295_int64)
         end do
         pos = pos + n
      end do
      close (unit)
      write (hex, '(z8.8,z8.8)') h_hi, h_lo
      id = 'rodyn '//rodyn_version//' build '//hex
   end function checkpoint_program_id
end module rodyn_checkpoint
