!> Dynamic writer, the step log: a step's row of dynamic_log.csv (its number, time,
!> step, Newton effort and energy balance) and the group /dynamic/log of dynamic.h5,
!> one dataset per quantity of step_log_t, to which the rows held in memory are
!> appended at each sync.
module rodyn_output_dynamic_log
   use rodyn_format, only: put_int, put_real, put_reals
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_results, only: step_log_t
   use rodyn_hdf5, only: hdf5_file_t, hdf5_series_t, hdf5_create_group, hdf5_open_series, &
      hdf5_append_steps
   use rodyn_outfile, only: out_file_t, outfile_put
   use rodyn_output_table, only: create_described_series, row_len
   use rodyn_output_dynamic_series, only: log_chunk
   use rodyn_output_dynamic_lines, only: dynamic_h5
   implicit none
   private
   public :: n_log_series, write_log_row, create_h5_log, open_h5_log, write_log_h5

   ! Step log in dynamic.h5 (index into the log's series), one dataset per quantity
   integer, parameter :: lg_step = 1, lg_time = 2, lg_dt = 3, lg_iterations = 4, &
      lg_cutbacks = 5, lg_kinetic = 6, lg_strain = 7, lg_gravity = 8, &
      lg_external_work = 9, lg_damping_work = 10, lg_total = 11, lg_momentum = 12, &
      lg_angular_momentum = 13, lg_hydro_work = 14, lg_seabed_work = 15, &
      lg_numerical_work = 16, lg_numerical_energy = 17, n_log_series = 17
   character(len=*), parameter :: log_series_name(n_log_series) = [character(len=16) :: &
      'step', 'time', 'dt', 'iterations', 'cutbacks', 'kinetic', 'strain', 'gravity', &
      'external_work', 'damping_work', 'total', 'momentum', 'angular_momentum', &
      'hydro_work', 'seabed_work', 'numerical_work', 'numerical_energy']

contains

   !> A step's row of dynamic_log.csv, held in f until the next sync.
   subroutine write_log_row(log, f)
      type(step_log_t), intent(in) :: log         !< the step's effort and balances
      type(out_file_t), intent(inout) :: f        !< dynamic_log.csv
      character(len=row_len) :: row
      integer :: n
      n = 0
      call put_int(row, n, log%step)
      call put_real(row, n, log%time)
      call put_real(row, n, log%dt)
      call put_int(row, n, log%iterations)
      call put_int(row, n, log%cutbacks)
      call put_reals(row, n, [log%kinetic, log%strain, log%gravity, log%external_work, &
         log%damping_work, log%hydro_work, log%seabed_work, log%numerical_work, &
         log%numerical_energy, log%total, log%momentum, log%angular_momentum])
      call outfile_put(f, row(:n))
   end subroutine write_log_row

   !> /dynamic/log: one empty 1-D dataset per quantity of step_log_t (momenta: 3 columns).
   subroutine create_h5_log(h5, log, err)
      type(hdf5_file_t), intent(in) :: h5    !< open file
      type(hdf5_series_t), intent(inout) :: log(:) !< (n_log_series) left open
      type(error_t), intent(inout) :: err    !< status
      character(len=*), parameter :: g = '/dynamic/log/'
      ! the 1-D datasets in the order created (the order h5py lists them)
      integer, parameter :: order(15) = [lg_step, lg_time, lg_dt, lg_iterations, &
         lg_cutbacks, lg_kinetic, lg_strain, lg_gravity, lg_external_work, lg_damping_work, &
         lg_hydro_work, lg_seabed_work, lg_numerical_work, lg_numerical_energy, lg_total]
      integer :: k
      call hdf5_create_group(h5, '/dynamic/log', err)
      do k = 1, size(order)
         call column(order(k), any(order(k) == [lg_step, lg_iterations, lg_cutbacks]))
      end do
      call create_described_series(h5, dynamic_h5, g//trim(log_series_name(lg_momentum)), 3, &
                                   err, log_chunk, series=log(lg_momentum))
      call create_described_series(h5, dynamic_h5, &
                                   g//trim(log_series_name(lg_angular_momentum)), 3, err, &
                                   log_chunk, series=log(lg_angular_momentum))
   contains
      !> One 1-D dataset of the log.
      subroutine column(k, integers)
         integer, intent(in) :: k                     !< lg_* index
         logical, intent(in) :: integers              !< integer values
         call create_described_series(h5, dynamic_h5, g//trim(log_series_name(k)), 0, &
                                      err, log_chunk, integers=integers, series=log(k))
      end subroutine column
   end subroutine create_h5_log

   !> Open the datasets of /dynamic/log of an existing dynamic.h5 for appending.
   subroutine open_h5_log(h5, log, err)
      type(hdf5_file_t), intent(in) :: h5    !< open file
      type(hdf5_series_t), intent(inout) :: log(:) !< (n_log_series) opened
      type(error_t), intent(inout) :: err    !< status
      integer :: k
      do k = 1, n_log_series
         call hdf5_open_series(h5, '/dynamic/log/'//trim(log_series_name(k)), log(k), err)
      end do
   end subroutine open_h5_log

   !> Append the step rows p to /dynamic/log.
   subroutine write_log_h5(log, p, err)
      type(hdf5_series_t), intent(inout) :: log(:) !< (n_log_series) open
      type(step_log_t), intent(in) :: p(:)         !< the rows
      type(error_t), intent(inout) :: err          !< status
      real(wp), allocatable :: vec(:, :)
      integer :: k
      if (size(p) == 0 .or. has_error(err)) return
      associate (s => log)
         call hdf5_append_steps(s(lg_step), p%step, err)
         call hdf5_append_steps(s(lg_time), p%time, err)
         call hdf5_append_steps(s(lg_dt), p%dt, err)
         call hdf5_append_steps(s(lg_iterations), p%iterations, err)
         call hdf5_append_steps(s(lg_cutbacks), p%cutbacks, err)
         call hdf5_append_steps(s(lg_kinetic), p%kinetic, err)
         call hdf5_append_steps(s(lg_strain), p%strain, err)
         call hdf5_append_steps(s(lg_gravity), p%gravity, err)
         call hdf5_append_steps(s(lg_external_work), p%external_work, err)
         call hdf5_append_steps(s(lg_damping_work), p%damping_work, err)
         call hdf5_append_steps(s(lg_hydro_work), p%hydro_work, err)
         call hdf5_append_steps(s(lg_seabed_work), p%seabed_work, err)
         call hdf5_append_steps(s(lg_numerical_work), p%numerical_work, err)
         call hdf5_append_steps(s(lg_numerical_energy), p%numerical_energy, err)
         call hdf5_append_steps(s(lg_total), p%total, err)
         allocate (vec(3, size(p)))
         do k = 1, size(p)
            vec(:, k) = p(k)%momentum
         end do
         call hdf5_append_steps(s(lg_momentum), vec, err)
         do k = 1, size(p)
            vec(:, k) = p(k)%angular_momentum
         end do
         call hdf5_append_steps(s(lg_angular_momentum), vec, err)
      end associate
   end subroutine write_log_h5

end module rodyn_output_dynamic_log
