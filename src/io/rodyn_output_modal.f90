!> The modal analysis in the static results (*MODAL; docs/output.md): static_modes.csv,
!> a row per mode (period, frequency, the object holding most of its kinetic energy),
!> static_mode_shapes.csv, a row per mode and node of every line and per mode and
!> FREE point or body, and the lines' shapes in results.h5 (/modes).
module rodyn_output_modal
   use rodyn_kinds, only: wp, pi
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t
   use rodyn_results, only: line_result_t, system_result_t
   use rodyn_outfile, only: out_file_t, outfile_put, outfile_commit, remove_file
   use rodyn_output_common, only: path_join, csv_name, table_started
   use rodyn_output_table, only: write_described, group_name
   use rodyn_hdf5, only: hdf5_file_t, hdf5_create_group, hdf5_write_attribute
   use rodyn_format, only: real_fields, int_text
   implicit none
   private
   public :: write_modes_csv, modes_csv, mode_shapes_csv, write_modes_h5

   character(len=*), parameter :: modes_csv = 'static_modes.csv'
   character(len=*), parameter :: mode_shapes_csv = 'static_mode_shapes.csv'
   character(len=*), parameter :: results_h5 = 'results.h5'

contains

   !> Write static_modes.csv and static_mode_shapes.csv into folder `dir` (a deck without
   !> *MODAL: remove those an earlier run left there).
   subroutine write_modes_csv(dir, model, lines, sys, err)
      character(len=*), intent(in) :: dir                 !< output folder (exists)
      type(model_t), intent(in) :: model                  !< model (names)
      type(line_result_t), intent(in) :: lines(:)         !< static results (node S)
      type(system_result_t), intent(in) :: sys            !< the modes (may be none)
      type(error_t), intent(inout) :: err                 !< status
      type(out_file_t) :: f
      integer :: k, j
      if (has_error(err)) return
      call remove_file(path_join(dir, mode_shapes_csv))
      if (.not. table_started(f, dir, modes_csv, allocated(sys%modal_period), err)) return
      do k = 1, size(sys%modal_period)
         j = maxloc(sys%modal_share(:, k), dim=1)
         call outfile_put(f, int_text(k)// &
                          real_fields([sys%modal_period(k), 1.0_wp/sys%modal_period(k)])// &
                          ','//csv_name(object_name(model, lines, sys, j))// &
                          real_fields([sys%modal_share(j, k)]))
      end do
      call outfile_commit(f, err)
      if (has_error(err)) return
      call write_shapes(dir, model, lines, sys, err)
   end subroutine write_modes_csv

   !> static_mode_shapes.csv: every line node's motion, then every master's.
   subroutine write_shapes(dir, model, lines, sys, err)
      character(len=*), intent(in) :: dir                 !< output folder (exists)
      type(model_t), intent(in) :: model                  !< model (names)
      type(line_result_t), intent(in) :: lines(:)         !< static results (node S)
      type(system_result_t), intent(in) :: sys            !< the modes
      type(error_t), intent(inout) :: err                 !< status
      type(out_file_t) :: f
      integer :: k, l, a, n0, m, nl
      if (.not. table_started(f, dir, mode_shapes_csv, .true., err)) return
      nl = size(lines)
      do k = 1, size(sys%modal_period)
         n0 = 0
         do l = 1, nl
            do a = 1, size(lines(l)%node_s)
               call outfile_put(f, int_text(k)//','//csv_name(lines(l)%name)//','// &
                                int_text(a)//real_fields([lines(l)%node_s(a), &
                                                          sys%modal_shape(:, n0 + a, k)]))
            end do
            n0 = n0 + size(lines(l)%node_s)
         end do
         do m = 1, size(sys%modal_master, 2)
            call outfile_put(f, int_text(k)//','// &
                             csv_name(object_name(model, lines, sys, nl + m))//',0,0'// &
                             real_fields(sys%modal_master(:, m, k)))
         end do
      end do
      call outfile_commit(f, err)
   end subroutine write_shapes

   !> The name of object j of the shares: a line, then the masters (points, bodies).
   function object_name(model, lines, sys, j) result(name)
      type(model_t), intent(in) :: model                  !< model
      type(line_result_t), intent(in) :: lines(:)         !< lines
      type(system_result_t), intent(in) :: sys            !< masters' kind and index
      integer, intent(in) :: j                            !< object
      character(len=:), allocatable :: name
      integer :: m
      if (j <= size(lines)) then
         name = trim(lines(j)%name)
         return
      end if
      m = j - size(lines)
      if (sys%kind(m) == 1) then
         name = trim(model%points(sys%index(m))%name)
      else
         name = trim(model%bodies(sys%index(m))%name)
      end if
   end function object_name

   !> results.h5's /modes: periods and frequencies, and each line's node motions, a table
   !> (nodes, modes) per component.
   subroutine write_modes_h5(h5, lines, sys, err)
      type(hdf5_file_t), intent(in) :: h5                 !< open file
      type(line_result_t), intent(in) :: lines(:)         !< lines
      type(system_result_t), intent(in) :: sys            !< the modes (may be none)
      type(error_t), intent(inout) :: err                 !< status
      character(len=2), parameter :: comp(6) = ['ux', 'uy', 'uz', 'rx', 'ry', 'rz']
      character(len=:), allocatable :: g
      integer :: l, n0, nn, c
      if (has_error(err) .or. .not. allocated(sys%modal_period)) return
      call hdf5_create_group(h5, '/modes', err)
      call hdf5_write_attribute(h5, '/modes', 'solver', trim(sys%modal_solver), err)
      call hdf5_write_attribute(h5, '/modes', 'tangent_asymmetry', sys%modal_asymmetry, err)
      call write_described(h5, results_h5, '/modes/period_s', err, x1=sys%modal_period)
      call write_described(h5, results_h5, '/modes/frequency_hz', err, &
                           x1=1.0_wp/sys%modal_period)
      call write_described(h5, results_h5, '/modes/omega_rad_s', err, &
                           x1=2.0_wp*pi/sys%modal_period)
      n0 = 0
      do l = 1, size(lines)
         nn = size(lines(l)%node_s)
         g = '/modes/'//group_name(lines(l)%name, l)
         call hdf5_create_group(h5, g, err)
         do c = 1, 6
            call write_described(h5, results_h5, g//'/'//comp(c), err, g, &
                                 x2=sys%modal_shape(c, n0 + 1:n0 + nn, :))
         end do
         n0 = n0 + nn
      end do
   end subroutine write_modes_h5
end module rodyn_output_modal
