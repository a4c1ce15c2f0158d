!> Dynamic writer, the sea, vessel and body outputs of a scene with probes, vessels,
!> connections or bodies (rodyn_sea_output): a row per probe, vessel, connection and
!> body at every step (the _step tables) and at the frames (dynamic_waves, _vessels,
!> _connections, _bodies.csv), and the same in /dynamic/sea of dynamic.h5.
module rodyn_output_dynamic_sea
   use rodyn_format, only: put_text, put_int, put_real, put_reals
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t
   use rodyn_hdf5, only: hdf5_file_t, hdf5_series_t, hdf5_create_group, &
      hdf5_write_attribute, hdf5_open_series, hdf5_append_steps
   use rodyn_sea_output, only: sea_scene_t, sea_values_t
   use rodyn_outfile, only: outfile_put
   use rodyn_output_common, only: csv_name
   use rodyn_output_table, only: write_described, create_described_series, row_len
   use rodyn_output_dynamic_files, only: dynamic_files_t, tb_waves, tb_waves_step, &
      tb_vessels, tb_vessels_step, tb_conn, tb_conn_step, tb_bodies, tb_bodies_step
   use rodyn_output_dynamic_series, only: chunk_bytes, log_chunk
   use rodyn_output_dynamic_lines, only: dynamic_h5
   implicit none
   private
   public :: sea_out_t, n_sea_frame, set_up_sea, sea_tables, write_sea_rows
   public :: write_sea_h5, create_h5_sea, open_h5_sea

   ! /dynamic/sea in dynamic.h5 (index into sea_out_t%h5): at the frames, at every step
   integer, parameter :: sh_elevation = 1, sh_motion = 2, sh_load = 3, sh_conn = 4, &
      sh_body = 5, sh_step_elevation = 6, sh_step_motion = 7, sh_step_load = 8, &
      sh_step_conn = 9, sh_step_time = 10, sh_step_body = 11, n_sea_h5 = 11
   !> the series before sh_step_elevation, held and cut back as a row per frame
   integer, parameter :: n_sea_frame = sh_step_elevation - 1
   character(len=*), parameter :: sea_h5_name(n_sea_h5) = [character(len=24) :: &
      'probe_elevation', 'vessel_motion', 'vessel_load', 'connection_load', 'body_motion', &
      'step_probe_elevation', 'step_vessel_motion', 'step_vessel_load', &
      'step_connection_load', 'step_time', 'step_body_motion']

   !> A string of its own length (rows of an array of texts differ in length).
   type :: text_t
      character(len=:), allocatable :: s !< the text
   end type text_t

   !> The sea outputs of a run: the fixed start of their rows and their series.
   type :: sea_out_t
      logical :: active = .false.                    !< the scene has any of them
      type(text_t), allocatable :: probe_head(:)     !< (np) ',PROBE,x,y'
      type(text_t), allocatable :: vessel_head(:)    !< (nv) ',VESSEL'
      type(text_t), allocatable :: body_head(:)      !< (nb) ',BODY'
      type(text_t), allocatable :: conn_head(:)      !< (nc) ',VESSEL,LINE,END'
      integer :: cols(n_sea_h5) = 0                  !< columns of each /dynamic/sea series
      real(wp), allocatable :: probe_xy(:, :)        !< (2, np) the probes' points [m]
      type(hdf5_series_t) :: h5(n_sea_h5)            !< /dynamic/sea, open when cols > 0
   end type sea_out_t

contains

   !> The sea and vessel outputs a scene asks for, and the fixed start of their rows
   !> (after the step and time columns): the probes' names and points, the vessels'
   !> names, each connection's vessel, line and end, the bodies' names.
   subroutine set_up_sea(so, model, sea)
      type(sea_out_t), intent(inout) :: so        !< the sea outputs
      type(model_t), intent(in) :: model          !< model (names)
      type(sea_scene_t), intent(in) :: sea        !< the scene
      character(len=row_len) :: row
      integer :: k, n
      if (.not. sea%active) return
      so%active = sea%n_probes > 0 .or. sea%n_vessels > 0 .or. sea%n_conn > 0 .or. &
                  sea%n_bodies > 0
      allocate (so%probe_head(sea%n_probes), so%vessel_head(sea%n_vessels), &
                so%conn_head(sea%n_conn), so%body_head(sea%n_bodies))
      so%probe_xy = sea%probe_xy
      so%cols = 0
      so%cols([sh_elevation, sh_step_elevation]) = sea%n_probes
      so%cols([sh_motion, sh_step_motion]) = 7*sea%n_vessels
      so%cols([sh_load, sh_step_load]) = 12*sea%n_vessels
      so%cols([sh_conn, sh_step_conn]) = 13*sea%n_conn
      so%cols([sh_body, sh_step_body]) = 12*sea%n_bodies
      so%cols(sh_step_time) = 1
      do k = 1, sea%n_probes
         n = 0
         call put_text(row, n, ','//csv_name(model%waves%probe_name(k)))
         call put_reals(row, n, sea%probe_xy(:, k))
         so%probe_head(k)%s = row(:n)
      end do
      do k = 1, sea%n_vessels
         so%vessel_head(k)%s = ','//csv_name(model%vessels(k)%name)
      end do
      do k = 1, sea%n_bodies
         so%body_head(k)%s = ','//csv_name(model%bodies(k)%name)
      end do
      do k = 1, sea%n_conn
         so%conn_head(k)%s = ','//csv_name(model%vessels(sea%conn_vessel(k))%name)//','// &
                             csv_name(model%lines(sea%conn_line(k))%name)//','// &
                             trim(sea%conn_end(k))
      end do
   end subroutine set_up_sea

   !> Which of the sea tables of the file list (tb_waves .. tb_bodies_step) the outputs
   !> fill: a table and its _step table for probes, vessels, connections, bodies.
   pure function sea_tables(so) result(on)
      type(sea_out_t), intent(in) :: so   !< the sea outputs
      logical :: on(tb_waves:tb_bodies_step)
      on = .false.
      if (.not. so%active) return
      on(tb_waves:tb_waves_step) = size(so%probe_head) > 0
      on(tb_vessels:tb_vessels_step) = size(so%vessel_head) > 0
      on(tb_conn:tb_conn_step) = size(so%conn_head) > 0
      on(tb_bodies:tb_bodies_step) = size(so%body_head) > 0
   end function sea_tables

   !> The rows of step `step` at time `time`: a row per probe, vessel, connection and
   !> body to the _step tables the run writes, and, when `frame`, to the frame tables.
   subroutine write_sea_rows(so, fl, step, time, v, frame)
      type(sea_out_t), intent(in) :: so             !< the sea outputs
      type(dynamic_files_t), intent(inout) :: fl    !< the tables
      integer, intent(in) :: step                   !< step number (0: start) [-]
      real(wp), intent(in) :: time                  !< time at the end of the step [s]
      type(sea_values_t), intent(in) :: v           !< the values (rodyn_sea_output)
      logical, intent(in) :: frame                  !< also a frame's rows
      character(len=row_len) :: row
      integer :: k, ns
      ns = 0
      call put_int(row, ns, step)
      call put_real(row, ns, time)
      if (fl%on(tb_waves)) then
         do k = 1, size(so%probe_head)
            call put_row(tb_waves, so%probe_head(k)%s, [v%eta(k)])
         end do
      end if
      if (fl%on(tb_vessels)) then
         do k = 1, size(so%vessel_head)
            call put_row(tb_vessels, so%vessel_head(k)%s, [v%pose(:, k), v%load(:, k)])
         end do
      end if
      if (fl%on(tb_conn)) then
         do k = 1, size(so%conn_head)
            call put_row(tb_conn, so%conn_head(k)%s, [v%conn(:, k), norm2(v%conn(1:3, k))])
         end do
      end if
      if (fl%on(tb_bodies)) then
         do k = 1, size(so%body_head)
            call put_row(tb_bodies, so%body_head(k)%s, v%body(:, k))
         end do
      end if
   contains
      !> One row, head and values after the step and time: to table tb + 1 (its _step
      !> table), and without the step to table tb at a frame.
      subroutine put_row(tb, head, values)
         integer, intent(in) :: tb                  !< the frame table (tb_*)
         character(len=*), intent(in) :: head       !< the row's head
         real(wp), intent(in) :: values(:)          !< its values
         integer :: n
         n = ns
         call put_text(row, n, head)
         call put_reals(row, n, values)
         call outfile_put(fl%f(tb + 1), row(:n))
         if (frame) call outfile_put(fl%f(tb), row(index(row, ',') + 1:n))
      end subroutine put_row
   end subroutine write_sea_rows

   !> The values of a step appended to /dynamic/sea (held until the next sync): the
   !> _step series, and at a frame the frame series.
   subroutine write_sea_h5(so, time, v, frame, err)
      type(sea_out_t), intent(inout) :: so          !< the sea outputs
      real(wp), intent(in) :: time                  !< time [s]
      type(sea_values_t), intent(in) :: v           !< the values
      logical, intent(in) :: frame                  !< also at the frames
      type(error_t), intent(inout) :: err           !< status
      integer :: k
      real(wp), allocatable :: conn(:, :)
      allocate (conn(13, size(so%conn_head)))
      do k = 1, size(so%conn_head)
         conn(1:12, k) = v%conn(:, k)
         conn(13, k) = norm2(v%conn(1:3, k))
      end do
      call hdf5_append_steps(so%h5(sh_step_time), [time], err)
      call put(sh_step_elevation, v%eta)
      call put(sh_step_motion, reshape(v%pose, [size(v%pose)]))
      call put(sh_step_load, reshape(v%load, [size(v%load)]))
      call put(sh_step_conn, reshape(conn, [size(conn)]))
      call put(sh_step_body, reshape(v%body, [size(v%body)]))
      if (.not. frame) return
      call put(sh_body, reshape(v%body, [size(v%body)]))
      call put(sh_elevation, v%eta)
      call put(sh_motion, reshape(v%pose, [size(v%pose)]))
      call put(sh_load, reshape(v%load, [size(v%load)]))
      call put(sh_conn, reshape(conn, [size(conn)]))
   contains
      !> One row of series k, if the run has it.
      subroutine put(k, row)
         integer, intent(in) :: k            !< sh_* index
         real(wp), intent(in) :: row(:)      !< the row
         if (so%cols(k) > 0) call hdf5_append_steps(so%h5(k), row, err)
      end subroutine put
   end subroutine write_sea_h5

   !> /dynamic/sea: the names of the probes, vessels and connections (attributes), the
   !> probes' points, and the empty series of the sea and vessel outputs.
   subroutine create_h5_sea(so, h5, err)
      type(sea_out_t), intent(inout) :: so         !< the sea outputs
      type(hdf5_file_t), intent(in) :: h5          !< dynamic.h5, open
      type(error_t), intent(inout) :: err          !< status
      character(len=*), parameter :: g = '/dynamic/sea'
      real(wp), allocatable :: xy(:, :)
      integer :: k
      if (.not. any(so%cols > 0) .or. has_error(err)) return
      call hdf5_create_group(h5, g, err)
      call hdf5_write_attribute(h5, g, 'probes', names(so%probe_head, 1), err)
      call hdf5_write_attribute(h5, g, 'vessels', names(so%vessel_head, 1), err)
      call hdf5_write_attribute(h5, g, 'connections', names(so%conn_head, 3), err)
      call hdf5_write_attribute(h5, g, 'bodies', names(so%body_head, 1), err)
      if (size(so%probe_head) > 0) then
         xy = so%probe_xy     ! (2, np): h5py's (np, 2), a row per probe
         call write_described(h5, dynamic_h5, g//'/probe_xy', err, x2=xy)
      end if
      do k = 1, n_sea_h5
         if (so%cols(k) == 0) cycle
         if (k == sh_step_time) then
            call create_described_series(h5, dynamic_h5, g//'/'//trim(sea_h5_name(k)), &
                                         0, err, log_chunk, series=so%h5(k))
         else
            call create_described_series(h5, dynamic_h5, g//'/'//trim(sea_h5_name(k)), &
               so%cols(k), err, max(8, chunk_bytes/(8*so%cols(k))), series=so%h5(k))
         end if
      end do
   contains
      !> The names of the rows' heads ',A,B,...': the first nf fields, '/'-joined, then
      !> ', '-joined over the rows ('' when none).
      function names(heads, nf) result(s)
         type(text_t), intent(in) :: heads(:)  !< the heads
         integer, intent(in) :: nf             !< fields per name
         character(len=:), allocatable :: s
         character(len=:), allocatable :: h
         integer :: i, j, c
         s = ''
         do i = 1, size(heads)
            h = heads(i)%s(2:)//','
            c = 0
            do j = 1, len(h)
               if (h(j:j) /= ',') cycle
               c = c + 1
               if (c == nf) exit
               h(j:j) = '/'
            end do
            if (i > 1) s = s//', '
            s = s//h(:j - 1)
         end do
      end function names
   end subroutine create_h5_sea

   !> Open the series of /dynamic/sea of an existing dynamic.h5 for appending.
   subroutine open_h5_sea(so, h5, err)
      type(sea_out_t), intent(inout) :: so         !< the sea outputs
      type(hdf5_file_t), intent(in) :: h5          !< dynamic.h5, open
      type(error_t), intent(inout) :: err          !< status
      integer :: k
      do k = 1, n_sea_h5
         if (so%cols(k) > 0) call hdf5_open_series(h5, '/dynamic/sea/'// &
                                                   trim(sea_h5_name(k)), so%h5(k), err)
      end do
   end subroutine open_h5_sea

end module rodyn_output_dynamic_sea
