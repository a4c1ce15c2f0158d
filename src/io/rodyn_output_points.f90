!> The tables of the mooring system in the static results (docs/output.md), written by
!> one writer from a list of its files (system_tables):
!> - static_points.csv, a row per *POINT in deck order: where it is and the total force
!>   its lines exert on it, the sum over the line ends on it of minus the force on the
!>   end (the end's reaction, rodyn_recovery). At a FREE point in equilibrium it balances
!>   the point's own weight, buoyancy and load; at a FIXED point it is the load on the
!>   anchor or fairlead.
!> - static_bodies.csv: each body's reference point, rotation and the force and moment
!>   about R of its lines.
!> - static_stiffness.csv: every entry K_jk of the stiffness at the FREE points and
!>   bodies (system_result_t), of everything and of the lines, a row each.
!> - static_body_modes.csv: each FREE body's six natural periods as a rigid body on its
!>   moorings and their modes.
!> - static_offset_curve.csv (*OFFSET CURVE): a row per step of the curve.
!> A run without rows for a table (no points, no bodies, no result: statics not
!> complete) removes the one an earlier run left there.
module rodyn_output_points
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t
   use rodyn_model, only: model_t, point_kind_names, body_kind_names, name_len, body_free
   use rodyn_results, only: line_result_t, system_result_t
   use rodyn_outfile, only: out_file_t, outfile_put, outfile_commit
   use rodyn_output_common, only: table_started
   use rodyn_format, only: real_fields, int_text
   implicit none
   private
   public :: write_system_table, system_tables

   !> The tables, in the order the static writer writes them
   character(len=*), parameter :: system_tables(5) = [character(len=23) :: &
      'static_points.csv', 'static_bodies.csv', 'static_stiffness.csv', &
      'static_body_modes.csv', 'static_offset_curve.csv']

contains

   !> Write table `name` of system_tables into folder `dir`, or remove an older one when
   !> the run has no rows for it.
   subroutine write_system_table(dir, name, model, lines, sys, err)
      character(len=*), intent(in) :: dir          !< output folder (exists)
      character(len=*), intent(in) :: name         !< file name, one of system_tables
      type(model_t), intent(in) :: model           !< model (points, bodies, names)
      type(line_result_t), intent(in) :: lines(:)  !< static results per line
      type(system_result_t), intent(in) :: sys     !< the system's results (may be empty)
      type(error_t), intent(inout) :: err          !< status
      type(out_file_t) :: f
      integer :: b, i
      if (.not. table_started(f, dir, name, has_rows(name, model, sys), err)) return
      select case (name)
      case ('static_points.csv')
         call point_rows(f, model, lines)
      case ('static_bodies.csv')
         do b = 1, size(sys%body_x, 2)
            call outfile_put(f, trim(model%bodies(b)%name)//','// &
                             trim(body_kind_names(model%bodies(b)%kind))// &
                             real_fields([sys%body_x(:, b), sys%body_rot(:, b), &
                                          sys%body_force(:, b)]))
         end do
      case ('static_stiffness.csv')
         call stiffness_rows(f, model, sys)
      case ('static_body_modes.csv')
         do b = 1, size(sys%body_periods, 2)
            if (model%bodies(b)%kind /= body_free) cycle
            do i = 1, 6
               call outfile_put(f, trim(model%bodies(b)%name)//','//int_text(i)// &
                                real_fields([sys%body_periods(i, b), sys%body_modes(:, i, b)]))
            end do
         end do
      case ('static_offset_curve.csv')
         do i = lbound(sys%curve, 2), ubound(sys%curve, 2)
            call outfile_put(f, trim(model%bodies(model%offset_curve%body)%name)//','// &
                             int_text(i)//real_fields(sys%curve(1:9, i)))
         end do
      end select
      call outfile_commit(f, err)
   end subroutine write_system_table

   !> Whether the run has rows for table `name`.
   logical function has_rows(name, model, sys)
      character(len=*), intent(in) :: name         !< file name, one of system_tables
      type(model_t), intent(in) :: model           !< model
      type(system_result_t), intent(in) :: sys     !< the system's results
      has_rows = .false.
      select case (name)
      case ('static_points.csv')
         if (allocated(model%points)) has_rows = size(model%points) > 0
      case ('static_bodies.csv')
         if (allocated(sys%body_x)) has_rows = size(sys%body_x, 2) > 0
      case ('static_stiffness.csv')
         if (allocated(sys%stiffness)) has_rows = size(sys%stiffness, 1) > 0
      case ('static_body_modes.csv')
         if (allocated(sys%body_periods)) has_rows = count(model%bodies%kind == body_free) > 0
      case ('static_offset_curve.csv')
         has_rows = allocated(sys%curve)
      end select
   end function has_rows

   !> The rows of static_points.csv.
   subroutine point_rows(f, model, lines)
      type(out_file_t), intent(inout) :: f         !< the table
      type(model_t), intent(in) :: model           !< model with its points
      type(line_result_t), intent(in) :: lines(:)  !< static results per line
      real(wp) :: x(3), force(3)
      integer :: ip, l, k, n, nn
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
                          trim(point_kind_names(model%points(ip)%kind))// &
                          real_fields([x, force])//','//int_text(n))
      end do
   end subroutine point_rows

   !> The rows of static_stiffness.csv: object, direction of the row and of the column,
   !> the entry of everything and of the lines, its unit.
   subroutine stiffness_rows(f, model, sys)
      type(out_file_t), intent(inout) :: f         !< the table
      type(model_t), intent(in) :: model           !< model with its points and bodies
      type(system_result_t), intent(in) :: sys     !< the stiffness
      character(len=2), parameter :: dofs(6) = ['x ', 'y ', 'z ', 'rx', 'ry', 'rz']
      character(len=*), parameter :: units(2, 2) = reshape([character(len=7) :: 'N/m', &
         'N m/m', 'N/rad', 'N m/rad'], [2, 2])
      character(len=name_len), allocatable :: obj(:)
      integer, allocatable :: dof(:)
      integer :: i, j
      call unknown_names(model, sys, obj, dof)
      do i = 1, size(obj)
         do j = 1, size(obj)
            call outfile_put(f, trim(obj(i))//','//trim(dofs(dof(i)))//','//trim(obj(j))// &
                             ','//trim(dofs(dof(j)))// &
                             real_fields([sys%stiffness(i, j), sys%lines_stiffness(i, j)])// &
                             ','//trim(units(merge(1, 2, dof(i) <= 3), merge(1, 2, dof(j) <= 3))))
         end do
      end do
   end subroutine stiffness_rows

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
end module rodyn_output_points
