!> Small helpers shared by the static and dynamic output writers: file paths, names as
!> CSV fields, one-line texts, status words, the description attributes of HDF5
!> datasets, the results of the water physics with their dry defaults, and the
!> environment (sea, current, seabed) as key-value rows and as an HDF5 group, the deck
!> parameters as an HDF5 group.
module rodyn_output_common
   use rodyn_kinds, only: wp, pi
   use rodyn_model, only: model_t
   use rodyn_results, only: line_result_t, run_summary_t
   use rodyn_hdf5, only: hdf5_file_t, hdf5_write_attribute, hdf5_write_attributes, &
      hdf5_write_dataset, hdf5_create_group
   use rodyn_error, only: error_t, set_error, stat_io, has_error
   use rodyn_output_schema, only: schema_dataset, schema_field, schema_environment, row_len, &
      schema_header
   use rodyn_outfile, only: path_join, text_or, out_file_t, outfile_create, outfile_put, remove_file
   implicit none
   private
   public :: text_or, status_of, path_join, one_line, describe, csv_name
   public :: described, dataset_texts, table_started
   public :: env_item_t, environment_items, write_environment_h5, write_parameters_h5
   public :: wall_tension_of, seabed_force_of, water_fields_fit, touchdown_of

   !> The text attributes every dataset carries (rodyn_output_schema's fields 3 and 4).
   character(len=*), parameter :: described(2) = ['units      ', 'description']

   !> One entry of the environment (docs/output.md, environment.csv): a key, its value
   !> in the unit given (angles in degrees), and a one-line description.
   type :: env_item_t
      character(len=:), allocatable :: key          !< 'surface_z', 'current_speed_2', ...
      real(wp) :: value = 0.0_wp                    !< value in `unit`
      character(len=:), allocatable :: unit         !< 'm', 'deg', 'kg/m3', '-', ...
      character(len=:), allocatable :: description  !< one line
   end type env_item_t

contains

   !> Group /parameters (docs/output.md): one attribute per deck parameter as used (after
   !> --set), named as the parameter (upper case): a float for a number, a string for a
   !> string. Nothing when the deck has no *PARAMETER.
   subroutine write_parameters_h5(h5, model, err)
      type(hdf5_file_t), intent(in) :: h5   !< open file
      type(model_t), intent(in) :: model    !< model
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: g = '/parameters'
      integer :: k
      if (.not. allocated(model%parameters)) return
      if (size(model%parameters) == 0) return
      call hdf5_create_group(h5, g, err)
      do k = 1, size(model%parameters)
         associate (p => model%parameters(k))
            if (p%is_number) then
               call hdf5_write_attribute(h5, g, p%name, p%value, err)
            else
               call hdf5_write_attribute(h5, g, p%name, p%text, err)
            end if
         end associate
      end do
   end subroutine write_parameters_h5

   !> Start the static CSV table `name` in folder `dir`: remove the file an earlier run
   !> left there, then, when `wanted`, create it (a temporary until outfile_commit) with
   !> its header from rodyn_output_schema. True when f is open for the rows.
   logical function table_started(f, dir, name, wanted, err)
      type(out_file_t), intent(out) :: f    !< the table
      character(len=*), intent(in) :: dir   !< output folder (exists)
      character(len=*), intent(in) :: name  !< file name, 'static_points.csv', ...
      logical, intent(in) :: wanted         !< the run has rows for it
      type(error_t), intent(inout) :: err   !< status
      table_started = .false.
      if (has_error(err)) return
      call remove_file(path_join(dir, name))
      if (.not. wanted) return
      call outfile_create(f, dir, name, err)
      if (has_error(err)) return
      call outfile_put(f, schema_header(name))
      table_started = .true.
   end function table_started

   !> The status message of a summary, with a default when none was set.
   pure function status_of(summary) result(s)
      type(run_summary_t), intent(in) :: summary !< how the run went
      character(len=:), allocatable :: s         !< message
      if (allocated(summary%status)) then
         s = summary%status
      else if (summary%complete) then
         s = 'complete'
      else
         s = 'incomplete'
      end if
   end function status_of


   !> Text on one line: line breaks and tabs become blanks, trailing blanks dropped.
   pure function one_line(text) result(s)
      character(len=*), intent(in) :: text  !< text
      character(len=:), allocatable :: s    !< same text on one line
      integer :: k
      s = text
      do k = 1, len(s)
         if (iachar(s(k:k)) < 32) s(k:k) = ' '
      end do
      s = trim(s)
   end function one_line

   !> Attach the `units` and `description` attributes to a dataset.
   subroutine describe(h5, path, units, description, err)
      type(hdf5_file_t), intent(in) :: h5           !< open file
      character(len=*), intent(in) :: path          !< dataset path
      character(len=*), intent(in) :: units         !< units text ('-': none)
      character(len=*), intent(in) :: description   !< one-line description
      type(error_t), intent(inout) :: err           !< status
      character(len=max(len(units), len(description))) :: texts(2)
      texts(1) = units
      texts(2) = description
      call hdf5_write_attributes(h5, path, described, texts, err)
   end subroutine describe

   !> The `units` and `description` (`described`) of dataset `path` of file `file` in
   !> rodyn_output_schema (a line's dataset: `line_group` its group); a dataset the
   !> schema does not know is an error (a writer and the schema out of step).
   subroutine dataset_texts(file, path, texts, err, line_group)
      character(len=*), intent(in) :: file                 !< 'results.h5', 'dynamic.h5'
      character(len=*), intent(in) :: path                 !< dataset path
      character(len=row_len), intent(out) :: texts(2)      !< units, description
      type(error_t), intent(inout) :: err                  !< status
      character(len=*), intent(in), optional :: line_group !< group of the line, if any
      character(len=:), allocatable :: row
      texts = ''
      if (has_error(err)) return
      row = schema_dataset(file, path, line_group)
      if (len(row) == 0) then
         call set_error(err, stat_io, 'describe_dataset: '//path//' of '//file// &
            ' is not in rodyn_output_schema')
         return
      end if
      texts(1) = schema_field(row, 3)
      texts(2) = schema_field(row, 4)
   end subroutine dataset_texts

   !> A line name as a CSV field: as given, quoted only if it holds a comma or quote.
   pure function csv_name(name) result(s)
      character(len=*), intent(in) :: name  !< line name
      character(len=:), allocatable :: s    !< field
      integer :: i
      if (scan(trim(name), ',"') == 0) then
         s = trim(name)
         return
      end if
      s = '"'
      do i = 1, len_trim(name)
         if (name(i:i) == '"') then
            s = s//'""'
         else
            s = s//name(i:i)
         end if
      end do
      s = s//'"'
   end function csv_name

   !> The wall (true) tension of a line at its integration points [N]: the result's
   !> wall_tension, or its effective tension when that was not filled (a dry model).
   pure function wall_tension_of(r) result(t)
      type(line_result_t), intent(in) :: r  !< line result (tension allocated)
      real(wp), allocatable :: t(:)         !< (ng) wall tension [N]
      if (allocated(r%wall_tension)) then
         t = r%wall_tension
      else
         t = r%tension
      end if
   end function wall_tension_of

   !> The seabed contact force per length at the nodes [N/m]: which = 1 the normal,
   !> 2 the friction force; zeros when the result does not carry it.
   pure function seabed_force_of(r, which) result(f)
      type(line_result_t), intent(in) :: r  !< line result (node_x allocated)
      integer, intent(in) :: which          !< 1: normal, 2: friction
      real(wp), allocatable :: f(:)         !< (nn) [N/m]
      allocate (f(size(r%node_x, 2)))
      f = 0.0_wp
      if (which == 1 .and. allocated(r%seabed_normal)) f = r%seabed_normal
      if (which == 2 .and. allocated(r%seabed_friction)) f = r%seabed_friction
   end function seabed_force_of

   !> The touchdown arc length of a line [m]; -1 when nothing touches the seabed (any
   !> negative or NaN value of the result).
   pure real(wp) function touchdown_of(r)
      type(line_result_t), intent(in) :: r   !< line result
      touchdown_of = r%touchdown_s
      if (.not. (touchdown_of >= 0.0_wp)) touchdown_of = -1.0_wp
   end function touchdown_of

   !> Whether the water results of a line, where allocated, have nn nodes and ng points
   !> (unallocated ones are allowed: the writers use wall = effective, seabed zeros).
   pure logical function water_fields_fit(r, nn, ng)
      type(line_result_t), intent(in) :: r  !< line result
      integer, intent(in) :: nn             !< nodes
      integer, intent(in) :: ng             !< integration points
      water_fields_fit = .true.
      if (allocated(r%wall_tension)) water_fields_fit = size(r%wall_tension) == ng
      if (allocated(r%seabed_normal)) water_fields_fit = water_fields_fit .and. &
         size(r%seabed_normal) == nn
      if (allocated(r%seabed_friction)) water_fields_fit = water_fields_fit .and. &
         size(r%seabed_friction) == nn
   end function water_fields_fit

   !> The environment of a model with water (*WATER, *CURRENT, *SEABED) as a list of
   !> items, in the order of environment.csv; angles in degrees. Empty for a dry model.
   !> Current profile levels are numbered from 1: current_z_1, current_speed_1, ...
   function environment_items(model) result(items)
      type(model_t), intent(in) :: model              !< model
      type(env_item_t), allocatable :: items(:)       !< entries
      real(wp), parameter :: deg = 180.0_wp/pi
      integer :: k, nc
      character(len=12) :: num
      allocate (items(0))
      if (.not. model%water%present) return
      associate (w => model%water, b => model%seabed)
         call add('surface_z', w%surface, 'm', 'z of the still water level')
         call add('depth', w%depth, 'm', 'water depth at x = y = 0')
         call add('density', w%density, 'kg/m3', 'sea water density')
         nc = 0
         if (allocated(w%cur_z)) nc = size(w%cur_z)
         call add('current_levels', real(nc, wp), '-', 'levels of the current profile')
         call add('current_ramp', w%cur_ramp, 's', &
            'ramp-in duration of the current in dynamics')
         do k = 1, nc
            write (num, '(i0)') k
            call add('current_z_'//trim(num), w%cur_z(k), 'm', 'level of profile point')
            call add('current_speed_'//trim(num), w%cur_speed(k), 'm/s', 'current speed')
            call add('current_heading_'//trim(num), w%cur_heading(k)*deg, 'deg', &
               'direction the current flows towards, from +x towards +y')
         end do
         call add('seabed', merge(1.0_wp, 0.0_wp, b%present), '-', '1: a seabed is modelled')
         if (b%present) then
            call add('seabed_slope', b%slope*deg, 'deg', 'angle of the seabed plane')
            call add('seabed_slope_dir', b%slope_dir*deg, 'deg', &
               'heading of steepest ascent, from +x towards +y')
            call add('seabed_stiffness', b%stiffness, 'N/m3', &
               'normal stiffness per contact area')
            call add('seabed_damping', b%damping, 'Pa s/m', 'normal damping per contact area')
            call add('seabed_mu_axial', b%mu_axial, '-', 'axial friction coefficient')
            call add('seabed_mu_lateral', b%mu_lateral, '-', 'lateral friction coefficient')
            call add('seabed_v_mob', b%v_mob, 'm/s', 'friction mobilisation velocity')
         end if
      end associate
   contains
      !> Append one item.
      subroutine add(key, value, unit, description)
         character(len=*), intent(in) :: key          !< key
         real(wp), intent(in) :: value                !< value
         character(len=*), intent(in) :: unit         !< unit
         character(len=*), intent(in) :: description  !< description
         type(env_item_t) :: item
         item%key = key
         item%value = value
         item%unit = unit
         item%description = description
         items = [items, item]
      end subroutine add
   end function environment_items

   !> The /environment group of results.h5 and dynamic.h5 (nothing for a dry model):
   !> scalar datasets surface_z, depth, density, current_ramp; the profile as 1-D
   !> datasets current_z, current_speed, current_heading [deg] when a current is given;
   !> seabed_* scalars when a seabed is; attribute seabed = 0/1. Each dataset carries
   !> `units` and `description`.
   subroutine write_environment_h5(h5, model, err)
      type(hdf5_file_t), intent(in) :: h5   !< open file
      type(model_t), intent(in) :: model    !< model
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: g = '/environment'
      real(wp), parameter :: deg = 180.0_wp/pi
      type(env_item_t), allocatable :: items(:)
      integer :: k
      if (.not. model%water%present) return
      items = environment_items(model)
      call hdf5_create_group(h5, g, err)
      call hdf5_write_attribute(h5, g, 'seabed', merge(1, 0, model%seabed%present), err)
      do k = 1, size(items)
         associate (it => items(k))
            if (it%key == 'seabed' .or. it%key == 'current_levels' .or. &
               index(it%key, 'current_z_') == 1 .or. index(it%key, 'current_speed_') == 1 &
               .or. index(it%key, 'current_heading_') == 1) cycle
            call hdf5_write_dataset(h5, g//'/'//it%key, it%value, err)
            call describe_environment(g//'/'//it%key, it%unit)
         end associate
      end do
      associate (w => model%water)
         if (allocated(w%cur_z)) then
            if (size(w%cur_z) > 0) then
               call hdf5_write_dataset(h5, g//'/current_z', w%cur_z, err)
               call describe_environment(g//'/current_z', 'm')
               call hdf5_write_dataset(h5, g//'/current_speed', w%cur_speed, err)
               call describe_environment(g//'/current_speed', 'm/s')
               call hdf5_write_dataset(h5, g//'/current_heading', w%cur_heading*deg, err)
               call describe_environment(g//'/current_heading', 'deg')
            end if
         end if
      end associate
   contains
      !> The units and description of rodyn_output_schema's environment_datasets; a
      !> dataset it does not list, or with other units than environment.csv's, is an
      !> error (the writers and the schema out of step).
      subroutine describe_environment(path, unit)
         character(len=*), intent(in) :: path   !< dataset path
         character(len=*), intent(in) :: unit   !< its unit in environment.csv
         character(len=:), allocatable :: row
         if (has_error(err)) return
         row = schema_environment(path)
         if (len(row) == 0) then
            call set_error(err, stat_io, 'write_environment_h5: '//path// &
                           ' is not in rodyn_output_schema')
         else if (schema_field(row, 3) /= unit) then
            call set_error(err, stat_io, 'write_environment_h5: '//path//' in '//unit// &
                           ', in '//schema_field(row, 3)//' in rodyn_output_schema')
         else
            call describe(h5, path, unit, schema_field(row, 4), err)
         end if
      end subroutine describe_environment
   end subroutine write_environment_h5
end module rodyn_output_common
