!> The points of a mooring system in the static results: static_points.csv, one row per
!> *POINT in deck order (docs/output.md, static_points.csv): where it is and the total
!> force its lines exert on it, the sum over the line ends on it of minus the force on
!> the end (the end's reaction, rodyn_recovery). At a FREE point in equilibrium it
!> balances the point's own weight, buoyancy and load; at a FIXED point it is the load
!> on the anchor or fairlead.
module rodyn_output_points
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, point_kind_names, body_kind_names, name_len, body_free
   use rodyn_results, only: line_result_t, system_result_t
   use rodyn_outfile, only: out_file_t, outfile_create, outfile_put, outfile_commit, &
                            remove_file
   use rodyn_output_schema, only: schema_header
   use rodyn_output_common, only: path_join
   use rodyn_format, only: real_text, int_text
   implicit none
   private
   public :: write_points_csv, points_csv, write_stiffness_csv, stiffness_csv
   public :: write_bodies_csv, bodies_csv, write_body_modes_csv, body_modes_csv
   public :: write_offset_curve_csv, offset_curve_csv

   character(len=*), parameter :: points_csv = 'static_points.csv'
   character(len=*), parameter :: stiffness_csv = 'static_stiffness.csv'
   character(len=*), parameter :: bodies_csv = 'static_bodies.csv'
   character(len=*), parameter :: body_modes_csv = 'static_body_modes.csv'
   character(len=*), parameter :: offset_curve_csv = 'static_offset_curve.csv'

contains

   !> Write static_points.csv into folder `dir` (a deck without *POINT: remove one that
   !> an earlier run left there).
   subroutine write_points_csv(dir, model, lines, err)
      character(len=*), intent(in) :: dir          !< output folder (exists)
      type(model_t), intent(in) :: model           !< model with its points
      type(line_result_t), intent(in) :: lines(:)  !< static results per line
      type(error_t), intent(inout) :: err          !< status
      type(out_file_t) :: f
      real(wp) :: x(3), force(3)
      integer :: ip, l, k, n, nn
      if (has_error(err)) return
      if (.not. allocated(model%points)) then
         call remove_file(path_join(dir, points_csv))
         return
      end if
      if (size(model%points) == 0) then
         call remove_file(path_join(dir, points_csv))
         return
      end if
      call outfile_create(f, dir, points_csv, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(points_csv))
      do ip = 1, size(model%points)
         x = model%points(ip)%position
         force = 0.0_wp
         n = 0
         do l = 1, size(model%lines)
            nn = size(lines(l)%node_s)
            do k = 1, 2
               if (merge(model%lines(l)%point_a, model%lines(l)%point_b, k == 1) /= ip) cycle
               n = n + 1
               x = lines(l)%node_x(:, merge(1, nn, k == 1))
               force = force - lines(l)%reaction(1:3, k)
            end do
         end do
         call outfile_put(f, trim(model%points(ip)%name)//','// &
                          trim(point_kind_names(model%points(ip)%kind))//','// &
                          real_text(x(1))//','//real_text(x(2))//','//real_text(x(3))//','// &
                          real_text(force(1))//','//real_text(force(2))//','// &
                          real_text(force(3))//','//int_text(n))
      end do
      call outfile_commit(f, err)
   end subroutine write_points_csv

   !> Write static_stiffness.csv into folder `dir`: every entry K_jk of the stiffness at
   !> the FREE points and bodies (system_result_t), of everything and of the lines, one
   !> row each; a system without them, or without the result (statics not complete),
   !> removes one an earlier run left there.
   subroutine write_stiffness_csv(dir, model, sys, err)
      character(len=*), intent(in) :: dir                 !< output folder (exists)
      type(model_t), intent(in) :: model                  !< model with its points
      type(system_result_t), intent(in), optional :: sys  !< the stiffness
      type(error_t), intent(inout) :: err                 !< status
      character(len=2), parameter :: dofs(6) = ['x ', 'y ', 'z ', 'rx', 'ry', 'rz']
      character(len=*), parameter :: units(2, 2) = reshape([character(len=7) :: 'N/m', &
         'N m/m', 'N/rad', 'N m/rad'], [2, 2])
      character(len=name_len), allocatable :: obj(:)
      integer, allocatable :: dof(:)
      type(out_file_t) :: f
      integer :: i, j
      if (has_error(err)) return
      if (.not. present(sys)) then
         call remove_file(path_join(dir, stiffness_csv))
         return
      end if
      if (.not. allocated(sys%stiffness)) then
         call remove_file(path_join(dir, stiffness_csv))
         return
      end if
      if (size(sys%stiffness, 1) == 0) then
         call remove_file(path_join(dir, stiffness_csv))
         return
      end if
      call unknown_names(model, sys, obj, dof)
      call outfile_create(f, dir, stiffness_csv, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(stiffness_csv))
      do i = 1, size(obj)
         do j = 1, size(obj)
            call outfile_put(f, trim(obj(i))//','//trim(dofs(dof(i)))//','//trim(obj(j))// &
                             ','//trim(dofs(dof(j)))//','//real_text(sys%stiffness(i, j))// &
                             ','//real_text(sys%lines_stiffness(i, j))//','// &
                             trim(units(merge(1, 2, dof(i) <= 3), merge(1, 2, dof(j) <= 3))))
         end do
      end do
      call outfile_commit(f, err)
   end subroutine write_stiffness_csv

   !> The object (point or body name) and direction (1..6: x, y, z, rx, ry, rz) of each
   !> unknown of the system's stiffness.
   subroutine unknown_names(model, sys, obj, dof)
      type(model_t), intent(in) :: model                        !< model
      type(system_result_t), intent(in) :: sys                  !< masters
      character(len=name_len), allocatable, intent(out) :: obj(:) !< names
      integer, allocatable, intent(out) :: dof(:)               !< directions
      integer :: m, c, k, n
      n = size(sys%stiffness, 1)
      allocate (obj(n), dof(n))
      k = 0
      do m = 1, size(sys%kind)
         do c = 1, merge(3, 6, sys%kind(m) == 1)
            k = k + 1
            dof(k) = c
            if (sys%kind(m) == 1) then
               obj(k) = model%points(sys%index(m))%name
            else
               obj(k) = model%bodies(sys%index(m))%name
            end if
         end do
      end do
   end subroutine unknown_names

   !> Write static_bodies.csv into folder `dir`: each body's reference point, rotation
   !> and the force and moment about R of its lines (a deck without bodies, or without the
   !> result: remove one an earlier run left there).
   subroutine write_bodies_csv(dir, model, sys, err)
      character(len=*), intent(in) :: dir                 !< output folder (exists)
      type(model_t), intent(in) :: model                  !< model with its bodies
      type(system_result_t), intent(in), optional :: sys  !< the bodies' results
      type(error_t), intent(inout) :: err                 !< status
      type(out_file_t) :: f
      integer :: b, k
      character(len=:), allocatable :: row
      if (has_error(err)) return
      call remove_file(path_join(dir, bodies_csv))
      if (.not. present(sys)) return
      if (.not. allocated(sys%body_x)) return
      if (size(sys%body_x, 2) == 0) return
      call outfile_create(f, dir, bodies_csv, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(bodies_csv))
      do b = 1, size(sys%body_x, 2)
         row = trim(model%bodies(b)%name)//','//trim(body_kind_names(model%bodies(b)%kind))
         do k = 1, 3
            row = row//','//real_text(sys%body_x(k, b))
         end do
         do k = 1, 3
            row = row//','//real_text(sys%body_rot(k, b))
         end do
         do k = 1, 6
            row = row//','//real_text(sys%body_force(k, b))
         end do
         call outfile_put(f, row)
      end do
      call outfile_commit(f, err)
   end subroutine write_bodies_csv

   !> Write static_body_modes.csv into folder `dir`: each FREE body's six natural periods
   !> as a rigid body on its moorings and their modes (a deck without them: remove one
   !> an earlier run left there).
   subroutine write_body_modes_csv(dir, model, sys, err)
      character(len=*), intent(in) :: dir                 !< output folder (exists)
      type(model_t), intent(in) :: model                  !< model with its bodies
      type(system_result_t), intent(in), optional :: sys  !< the periods
      type(error_t), intent(inout) :: err                 !< status
      type(out_file_t) :: f
      integer :: b, i, k, n
      character(len=:), allocatable :: row
      if (has_error(err)) return
      call remove_file(path_join(dir, body_modes_csv))
      if (.not. present(sys)) return
      if (.not. allocated(sys%body_periods)) return
      n = count(model%bodies%kind == body_free)
      if (n == 0) return
      call outfile_create(f, dir, body_modes_csv, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(body_modes_csv))
      do b = 1, size(sys%body_periods, 2)
         if (model%bodies(b)%kind /= body_free) cycle
         do i = 1, 6
            row = trim(model%bodies(b)%name)//','//int_text(i)//','// &
                  real_text(sys%body_periods(i, b))
            do k = 1, 6
               row = row//','//real_text(sys%body_modes(k, i, b))
            end do
            call outfile_put(f, row)
         end do
      end do
      call outfile_commit(f, err)
   end subroutine write_body_modes_csv

   !> Write static_offset_curve.csv into folder `dir` (*OFFSET CURVE): a row per step of
   !> the curve (without one: remove one an earlier run left there).
   subroutine write_offset_curve_csv(dir, model, sys, err)
      character(len=*), intent(in) :: dir                 !< output folder (exists)
      type(model_t), intent(in) :: model                  !< model with its curve
      type(system_result_t), intent(in), optional :: sys  !< the curve
      type(error_t), intent(inout) :: err                 !< status
      type(out_file_t) :: f
      integer :: k, j
      character(len=:), allocatable :: row
      if (has_error(err)) return
      call remove_file(path_join(dir, offset_curve_csv))
      if (.not. present(sys)) return
      if (.not. allocated(sys%curve)) return
      call outfile_create(f, dir, offset_curve_csv, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(offset_curve_csv))
      do k = lbound(sys%curve, 2), ubound(sys%curve, 2)
         row = trim(model%bodies(model%offset_curve%body)%name)//','//int_text(k)
         do j = 1, 9
            row = row//','//real_text(sys%curve(j, k))
         end do
         call outfile_put(f, row)
      end do
      call outfile_commit(f, err)
   end subroutine write_offset_curve_csv
end module rodyn_output_points
