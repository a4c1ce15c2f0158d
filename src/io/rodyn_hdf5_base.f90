!> The core of the HDF5 layer: the file and series types and the pieces every reader and
!> writer of rodyn_hdf5 and rodyn_hdf5_arrays is built of (status checks, identifiers
!> released by kind, datasets and attributes created and opened, strings read, series
!> extended). The conventions are rodyn_hdf5's; only the three modules of the layer use
!> this one.
module rodyn_hdf5_base
   use, intrinsic :: iso_c_binding, only: c_char, c_ptr, c_loc, c_null_char, c_size_t, &
      c_f_pointer, c_associated, c_null_ptr
   use hdf5, only: hid_t, hsize_t, size_t, h5gclose_f, &
      h5dcreate_f, h5dopen_f, h5dclose_f, h5dread_f, h5dget_space_f, &
      h5dget_type_f, h5dset_extent_f, h5dvlen_reclaim_f, &
      h5acreate_f, h5aopen_f, h5aclose_f, h5awrite_f, h5aread_f, h5aexists_f, &
      h5adelete_f, h5aget_space_f, h5aget_type_f, &
      h5screate_f, h5screate_simple_f, h5sclose_f, h5sget_simple_extent_ndims_f, &
      h5sget_simple_extent_dims_f, h5sget_simple_extent_npoints_f, h5sselect_hyperslab_f, &
      h5tcopy_f, h5tclose_f, h5tset_cset_f, h5tget_cset_f, h5tget_class_f, &
      h5tget_size_f, h5tset_strpad_f, h5tis_variable_str_f, &
      h5pcreate_f, h5pclose_f, h5pset_create_inter_group_f, &
      h5oopen_f, h5oclose_f, h5iget_type_f, &
      H5P_LINK_CREATE_F, H5P_DEFAULT_F, H5S_SCALAR_F, H5S_SELECT_SET_F, &
      H5T_STRING, H5T_STRING_F, H5T_CSET_UTF8_F, H5T_STR_NULLPAD_F, &
      H5I_DATASET_F, H5I_GROUP_F, H5I_ATTR_F, H5I_DATASPACE_F, H5I_DATATYPE_F, &
      H5I_GENPROP_LST_F
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, set_error, has_error, stat_io
   use rodyn_outfile, only: text_or
   implicit none
   private
   public :: hdf5_file_t, hdf5_series_t
   public :: check, failed, file_name, release, vlen_string_type, c_chars
   public :: create_dataset, open_shaped, create_attribute, open_object
   public :: attribute_on, text_attributes, read_string_from
   public :: prepare_append, finish_append

   !> An open HDF5 file.
   type :: hdf5_file_t
      integer(hid_t) :: id = -1                 !< HDF5 file identifier (< 0: not open)
      character(len=:), allocatable :: path     !< file name as given, for messages
   end type hdf5_file_t

   !> An extendible dataset (hdf5_create_series, hdf5_create_series_1d) kept open for
   !> appending with hdf5_append_steps: hdf5_open_series ... hdf5_close_series.
   type :: hdf5_series_t
      integer(hid_t) :: id = -1                  !< dataset identifier (< 0: not open)
      integer :: rank = 0                        !< 1: one value per step; 2: n_cols
      integer(hsize_t) :: n_cols = 1             !< values per step
      integer(hsize_t) :: n_steps = 0            !< steps in the dataset so far
      logical :: integers = .false.              !< integer dataset (else real)
      type(hdf5_file_t) :: file                  !< the file (its id and name)
      character(len=:), allocatable :: path      !< dataset path, for messages
      real(wp), allocatable :: held(:)           !< steps appended, not yet written
      integer(hsize_t) :: n_held = 0             !< values in held
   end type hdf5_series_t


   interface
      !> C strlen, to measure strings HDF5 returns as char *.
      function c_strlen(s) bind(c, name='strlen') result(n)
         import :: c_ptr, c_size_t
         type(c_ptr), value :: s          !< NUL-terminated C string
         integer(c_size_t) :: n           !< its length without the NUL
      end function c_strlen
   end interface

contains

   ! ------------------------------------------------------------------ status

   !> Map an HDF5 status to stat_io: err set when stat < 0.
   subroutine check(stat, action, where, file, object, err)
      integer, intent(in) :: stat              !< HDF5 status (< 0: failure)
      character(len=*), intent(in) :: action   !< what was attempted ('write dataset')
      character(len=*), intent(in) :: where    !< routine name
      type(hdf5_file_t), intent(in) :: file    !< file, for its name
      character(len=*), intent(in) :: object   !< object path (or path@attribute)
      type(error_t), intent(inout) :: err      !< status to fill
      if (stat < 0) call set_error(err, stat_io, where//': cannot '//action//' '''// &
         object//''' in '''//file_name(file)//'''')
   end subroutine check

   !> As check, and true when stat < 0 (for `if (failed(...)) exit blk`).
   logical function failed(stat, action, where, file, object, err)
      integer, intent(in) :: stat              !< HDF5 status (< 0: failure)
      character(len=*), intent(in) :: action   !< what was attempted ('write dataset')
      character(len=*), intent(in) :: where    !< routine name
      type(hdf5_file_t), intent(in) :: file    !< file, for its name
      character(len=*), intent(in) :: object   !< object path (or path@attribute)
      type(error_t), intent(inout) :: err      !< status to fill
      failed = stat < 0
      call check(stat, action, where, file, object, err)
   end function failed

   !> The file name for messages.
   pure function file_name(file) result(name)
      type(hdf5_file_t), intent(in) :: file  !< file handle
      character(len=:), allocatable :: name  !< its path, or '?' when unknown
      name = text_or(file%path, '?')
   end function file_name

   !> Close any HDF5 identifier by its kind and mark it closed (-1). Ignores id < 0.
   subroutine release(id)
      integer(hid_t), intent(inout) :: id !< identifier to close
      integer :: itype, stat
      if (id < 0) return
      call h5iget_type_f(id, itype, stat)
      if (stat >= 0) then
         if (itype == H5I_DATASET_F) then
            call h5dclose_f(id, stat)
         else if (itype == H5I_GROUP_F) then
            call h5gclose_f(id, stat)
         else if (itype == H5I_ATTR_F) then
            call h5aclose_f(id, stat)
         else if (itype == H5I_DATASPACE_F) then
            call h5sclose_f(id, stat)
         else if (itype == H5I_DATATYPE_F) then
            call h5tclose_f(id, stat)
         else if (itype == H5I_GENPROP_LST_F) then
            call h5pclose_f(id, stat)
         else
            call h5oclose_f(id, stat)
         end if
      end if
      id = -1
   end subroutine release

   ! ------------------------------------------------------------------ objects

   !> Create a dataspace of shape dims (size 0: scalar) and a dataset on it, creating
   !> missing parent groups. dset < 0 on failure.
   subroutine create_dataset(file, path, ftype, dims, dset, where, err, maxdims, dcpl, &
                             names, texts)
      type(hdf5_file_t), intent(in) :: file                   !< open file
      character(len=*), intent(in) :: path                    !< absolute dataset path
      integer(hid_t), intent(in) :: ftype                     !< datatype in the file
      integer(hsize_t), intent(in) :: dims(:)                 !< shape (Fortran order)
      integer(hid_t), intent(out) :: dset                     !< new dataset
      character(len=*), intent(in) :: where                   !< calling routine
      type(error_t), intent(inout) :: err                     !< status
      integer(hsize_t), intent(in), optional :: maxdims(:)    !< maximum shape
      integer(hid_t), intent(in), optional :: dcpl            !< creation property list
      character(len=*), intent(in), optional :: names(:)      !< text attributes to attach
      character(len=*), intent(in), optional :: texts(:)      !< their texts
      integer(hid_t) :: space, lcpl
      integer :: stat
      dset = -1
      space = -1
      lcpl = -1
      blk: block
         call new_space(dims, space, stat, maxdims)
         if (failed(stat, 'create dataspace for', where, file, path, err)) exit blk
         call h5pcreate_f(H5P_LINK_CREATE_F, lcpl, stat)
         if (failed(stat, 'set up dataset', where, file, path, err)) exit blk
         call h5pset_create_inter_group_f(lcpl, 1, stat)
         if (failed(stat, 'set up dataset', where, file, path, err)) exit blk
         call h5dcreate_f(file%id, path, ftype, space, dset, stat, dcpl_id=dcpl, &
            lcpl_id=lcpl)
         if (stat < 0) dset = -1
         if (failed(stat, 'create dataset', where, file, path, err)) exit blk
         if (present(names) .and. present(texts)) &
            call text_attributes(file, dset, path, names, texts, .false., err)
      end block blk
      call release(space)
      call release(lcpl)
   end subroutine create_dataset

   !> Open an object, replace any attribute of that name and create it with file type
   !> ftype and shape dims (size 0: scalar). oid/aid < 0 on failure.
   subroutine create_attribute(file, obj, name, ftype, dims, oid, aid, where, err)
      type(hdf5_file_t), intent(in) :: file   !< open file
      character(len=*), intent(in) :: obj     !< object path
      character(len=*), intent(in) :: name    !< attribute name
      integer(hid_t), intent(in) :: ftype     !< datatype in the file
      integer(hsize_t), intent(in) :: dims(:) !< shape
      integer(hid_t), intent(out) :: oid      !< open object
      integer(hid_t), intent(out) :: aid      !< new attribute
      character(len=*), intent(in) :: where   !< calling routine
      type(error_t), intent(inout) :: err     !< status
      aid = -1
      call open_object(file, obj, oid, where, err)
      if (has_error(err)) return
      call attribute_on(file, oid, obj, name, ftype, dims, aid, where, err)
   end subroutine create_attribute

   !> Open object `obj` (a group or dataset path); oid < 0 on failure.
   subroutine open_object(file, obj, oid, where, err)
      type(hdf5_file_t), intent(in) :: file   !< open file
      character(len=*), intent(in) :: obj     !< object path
      integer(hid_t), intent(out) :: oid      !< open object
      character(len=*), intent(in) :: where   !< calling routine
      type(error_t), intent(inout) :: err     !< status
      integer :: stat
      call h5oopen_f(file%id, obj, oid, stat)
      if (stat < 0) oid = -1
      call check(stat, 'open object', where, file, obj, err)
   end subroutine open_object

   !> Create attribute `name` of type ftype and shape dims (size 0: scalar) on the open
   !> object oid (path obj, for messages), replacing one of that name; aid < 0 on failure.
   subroutine attribute_on(file, oid, obj, name, ftype, dims, aid, where, err)
      type(hdf5_file_t), intent(in) :: file   !< open file
      integer(hid_t), intent(in) :: oid       !< open object
      character(len=*), intent(in) :: obj     !< its path
      character(len=*), intent(in) :: name    !< attribute name
      integer(hid_t), intent(in) :: ftype     !< datatype in the file
      integer(hsize_t), intent(in) :: dims(:) !< shape
      integer(hid_t), intent(out) :: aid      !< new attribute
      character(len=*), intent(in) :: where   !< calling routine
      type(error_t), intent(inout) :: err     !< status
      integer(hid_t) :: space
      integer :: stat
      logical :: exists
      aid = -1
      space = -1
      blk: block
         call h5aexists_f(oid, name, exists, stat)
         if (failed(stat, 'look up attribute', where, file, obj//'@'//name, err)) exit blk
         if (exists) then
            call h5adelete_f(oid, name, stat)
            if (failed(stat, 'replace attribute', where, file, obj//'@'//name, err)) &
               exit blk
         end if
         call new_space(dims, space, stat)
         if (failed(stat, 'create dataspace for', where, file, obj//'@'//name, err)) &
            exit blk
         call h5acreate_f(oid, name, ftype, space, aid, stat)
         if (stat < 0) aid = -1
         if (failed(stat, 'create attribute', where, file, obj//'@'//name, err)) exit blk
      end block blk
      call release(space)
   end subroutine attribute_on

   !> Open dataset `obj` (name '') or attribute `name` of object `obj` and return its
   !> shape; fails unless its rank is `rank` (0: a scalar or a single element). On
   !> failure everything opened is closed again (ids -1).
   subroutine open_shaped(file, obj, name, rank, oid, id, dims, where, err)
      type(hdf5_file_t), intent(in) :: file     !< open file
      character(len=*), intent(in) :: obj       !< dataset or object path
      character(len=*), intent(in) :: name      !< attribute name ('': the dataset obj)
      integer, intent(in) :: rank               !< expected rank
      integer(hid_t), intent(out) :: oid        !< the attribute's open object, else -1
      integer(hid_t), intent(out) :: id         !< open dataset or attribute
      integer(hsize_t), intent(out) :: dims(:)  !< shape, size rank
      character(len=*), intent(in) :: where     !< calling routine
      type(error_t), intent(inout) :: err       !< status
      character(len=:), allocatable :: object
      integer(hid_t) :: space
      integer :: stat
      oid = -1
      id = -1
      space = -1
      blk: block
         if (len(name) == 0) then
            object = obj
            call h5dopen_f(file%id, obj, id, stat)
            if (stat < 0) id = -1
            if (failed(stat, 'open dataset', where, file, object, err)) exit blk
            call h5dget_space_f(id, space, stat)
         else
            object = obj//'@'//name
            call open_object(file, obj, oid, where, err)
            if (has_error(err)) exit blk
            call h5aopen_f(oid, name, id, stat)
            if (stat < 0) id = -1
            if (failed(stat, 'open attribute', where, file, object, err)) exit blk
            call h5aget_space_f(id, space, stat)
         end if
         if (failed(stat, 'read shape of', where, file, object, err)) exit blk
         call space_shape(space, rank, dims, stat)
         call check(stat, 'use (wrong rank)', where, file, object, err)
      end block blk
      call release(space)
      if (has_error(err)) then
         call release(id)
         call release(oid)
      end if
   end subroutine open_shaped

   !> A new dataspace of shape dims (size 0: scalar), at most maxdims.
   subroutine new_space(dims, space, stat, maxdims)
      integer(hsize_t), intent(in) :: dims(:)              !< shape (Fortran order)
      integer(hid_t), intent(out) :: space                 !< the dataspace
      integer, intent(out) :: stat                         !< HDF5 status
      integer(hsize_t), intent(in), optional :: maxdims(:) !< maximum shape
      if (size(dims) == 0) then
         call h5screate_f(H5S_SCALAR_F, space, stat)
      else
         call h5screate_simple_f(size(dims), dims, space, stat, maxdims)
      end if
   end subroutine new_space

   !> Shape of a dataspace, checked against the expected rank (stat = -1 if wrong).
   subroutine space_shape(space, rank, dims, stat)
      integer(hid_t), intent(in) :: space       !< dataspace
      integer, intent(in) :: rank               !< expected rank (0: one element)
      integer(hsize_t), intent(out) :: dims(:)  !< shape, size rank
      integer, intent(out) :: stat              !< 0, or -1 on failure / wrong rank
      integer(hsize_t) :: maxdims(max(rank, 1))
      integer(hsize_t) :: npoints
      integer :: ndims
      call h5sget_simple_extent_ndims_f(space, ndims, stat)
      if (stat < 0) return
      if (rank == 0) then
         call h5sget_simple_extent_npoints_f(space, npoints, stat)
         if (stat < 0) return
         if (npoints /= 1) stat = -1
         return
      end if
      if (ndims /= rank) then
         stat = -1
         return
      end if
      call h5sget_simple_extent_dims_f(space, dims, maxdims, stat)
      if (stat >= 0) stat = 0
   end subroutine space_shape

   ! ------------------------------------------------------------------ strings

   !> A new variable-length UTF-8 string datatype (caller releases it).
   subroutine vlen_string_type(stype, stat)
      integer(hid_t), intent(out) :: stype !< datatype identifier
      integer, intent(out) :: stat         !< HDF5 status
      call h5tcopy_f(H5T_STRING, stype, stat)
      if (stat < 0) return
      call h5tset_cset_f(stype, H5T_CSET_UTF8_F, stat)
   end subroutine vlen_string_type

   !> Copy a Fortran string into a NUL-terminated C character array.
   pure subroutine c_chars(text, buf)
      character(len=*), intent(in) :: text                        !< text
      character(kind=c_char), allocatable, intent(out) :: buf(:)  !< text + NUL
      integer :: i
      allocate (buf(len(text) + 1))
      do i = 1, len(text)
         buf(i) = text(i:i)
      end do
      buf(len(text) + 1) = c_null_char
   end subroutine c_chars

   !> Text attributes names(i) = values(i) (variable-length UTF-8 scalars; trimmed unless
   !> keep) on the open object oid (path obj, for messages), replacing any of those names.
   subroutine text_attributes(file, oid, obj, names, values, keep, err)
      type(hdf5_file_t), intent(in) :: file     !< open file
      integer(hid_t), intent(in) :: oid         !< open object
      character(len=*), intent(in) :: obj       !< its path
      character(len=*), intent(in) :: names(:)  !< attribute names
      character(len=*), intent(in) :: values(:) !< their texts
      logical, intent(in) :: keep               !< write values(i) with trailing blanks
      type(error_t), intent(inout) :: err       !< status
      character(len=*), parameter :: where = 'hdf5_write_attribute_string'
      character(kind=c_char), allocatable, target :: buf(:)
      type(c_ptr), target :: ptr(1)
      integer(hid_t) :: aid, stype
      integer(hsize_t) :: dims(0)
      integer :: stat, i
      aid = -1
      stype = -1
      blk: block
         call vlen_string_type(stype, stat)
         if (failed(stat, 'set up string', where, file, obj, err)) exit blk
         do i = 1, size(names)
            call attribute_on(file, oid, obj, trim(names(i)), stype, dims, aid, where, err)
            if (has_error(err)) exit blk
            if (keep) then
               call c_chars(values(i), buf)
            else
               call c_chars(trim(values(i)), buf)
            end if
            ptr(1) = c_loc(buf)
            call h5awrite_f(aid, stype, c_loc(ptr), stat)
            if (failed(stat, 'write attribute', where, file, obj//'@'//trim(names(i)), err)) &
               exit blk
            call release(aid)
         end do
      end block blk
      call release(aid)
      call release(stype)
   end subroutine text_attributes

   !> Read a single string from an open dataset or attribute (variable or fixed length).
   subroutine read_string_from(file, id, is_attr, object, text, where, err)
      type(hdf5_file_t), intent(in) :: file              !< open file, for messages
      integer(hid_t), intent(in) :: id                   !< dataset or attribute
      logical, intent(in) :: is_attr                     !< id is an attribute
      character(len=*), intent(in) :: object             !< its name, for messages
      character(len=:), allocatable, intent(inout) :: text !< the text
      character(len=*), intent(in) :: where              !< calling routine
      type(error_t), intent(inout) :: err                !< status
      character(kind=c_char), allocatable, target :: fixed(:)
      character(kind=c_char), pointer :: chars(:)
      type(c_ptr), target :: ptr(1)
      type(c_ptr) :: bufp
      integer(hid_t) :: ftype, mtype, space
      integer(size_t) :: nbytes
      integer :: stat, tclass, cset, i, n
      logical :: is_vlen
      ftype = -1
      mtype = -1
      space = -1
      blk: block
         call item_type(id, is_attr, ftype, stat)
         if (failed(stat, 'read type of', where, file, object, err)) exit blk
         call h5tget_class_f(ftype, tclass, stat)
         if (stat >= 0 .and. tclass /= H5T_STRING_F) stat = -1
         if (failed(stat, 'read as string', where, file, object, err)) exit blk
         call h5tis_variable_str_f(ftype, is_vlen, stat)
         if (failed(stat, 'read type of', where, file, object, err)) exit blk
         call h5tget_cset_f(ftype, cset, stat)
         if (failed(stat, 'read type of', where, file, object, err)) exit blk
         if (is_vlen) then
            call h5tcopy_f(H5T_STRING, mtype, stat)
         else
            call h5tcopy_f(ftype, mtype, stat)
         end if
         if (failed(stat, 'read type of', where, file, object, err)) exit blk
         call h5tset_cset_f(mtype, cset, stat)
         if (failed(stat, 'read type of', where, file, object, err)) exit blk
         if (is_vlen) then
            ptr(1) = c_null_ptr
            bufp = c_loc(ptr)
            call read_item(id, is_attr, mtype, bufp, stat, space)
            if (failed(stat, 'read', where, file, object, err)) exit blk
            n = 0
            if (c_associated(ptr(1))) n = int(c_strlen(ptr(1)))
            if (allocated(text)) deallocate (text)
            allocate (character(len=n) :: text)
            if (n > 0) then
               call c_f_pointer(ptr(1), chars, [n])
               do i = 1, n
                  text(i:i) = chars(i)
               end do
            end if
            call h5dvlen_reclaim_f(mtype, space, H5P_DEFAULT_F, bufp, stat)
         else
            call h5tget_size_f(ftype, nbytes, stat)
            if (failed(stat, 'read type of', where, file, object, err)) exit blk
            call h5tset_strpad_f(mtype, H5T_STR_NULLPAD_F, stat)
            if (failed(stat, 'read type of', where, file, object, err)) exit blk
            allocate (fixed(max(nbytes, 1_size_t)))
            fixed = c_null_char
            bufp = c_loc(fixed)
            call read_item(id, is_attr, mtype, bufp, stat)
            if (failed(stat, 'read', where, file, object, err)) exit blk
            n = int(nbytes)
            do i = 1, int(nbytes)
               if (fixed(i) == c_null_char) then
                  n = i - 1
                  exit
               end if
            end do
            if (allocated(text)) deallocate (text)
            allocate (character(len=n) :: text)
            do i = 1, n
               text(i:i) = fixed(i)
            end do
         end if
      end block blk
      call release(space)
      call release(mtype)
      call release(ftype)
   end subroutine read_string_from

   !> The datatype of dataset or attribute id (caller releases it).
   subroutine item_type(id, is_attr, ftype, stat)
      integer(hid_t), intent(in) :: id      !< dataset or attribute
      logical, intent(in) :: is_attr       !< id is an attribute
      integer(hid_t), intent(out) :: ftype  !< its datatype
      integer, intent(out) :: stat          !< HDF5 status
      if (is_attr) then
         call h5aget_type_f(id, ftype, stat)
      else
         call h5dget_type_f(id, ftype, stat)
      end if
   end subroutine item_type

   !> Read dataset or attribute id whole into bufp as memory type mtype; then its
   !> dataspace, when asked for.
   subroutine read_item(id, is_attr, mtype, bufp, stat, space)
      integer(hid_t), intent(in) :: id                !< dataset or attribute
      logical, intent(in) :: is_attr                  !< id is an attribute
      integer(hid_t), intent(in) :: mtype             !< memory datatype
      type(c_ptr), intent(inout) :: bufp              !< where the values go
      integer, intent(out) :: stat                    !< HDF5 status
      integer(hid_t), intent(inout), optional :: space !< its dataspace
      if (is_attr) then
         call h5aread_f(id, mtype, bufp, stat)
         if (stat >= 0 .and. present(space)) call h5aget_space_f(id, space, stat)
      else
         call h5dread_f(id, mtype, bufp, stat)
         if (stat >= 0 .and. present(space)) call h5dget_space_f(id, space, stat)
      end if
   end subroutine read_item

   ! ------------------------------------------------------------------ series

   !> Check an append of n values, grow the dataset and select the new steps: fspace
   !> (the new steps in the file) and mspace (n values in memory). Nothing for n = 0.
   subroutine prepare_append(series, n, integers, fspace, mspace, err)
      type(hdf5_series_t), intent(inout) :: series !< open series
      integer(hsize_t), intent(in) :: n            !< number of values to append
      logical, intent(in) :: integers              !< the values are integers
      integer(hid_t), intent(out) :: fspace        !< file dataspace (-1 when none)
      integer(hid_t), intent(out) :: mspace        !< memory dataspace (-1 when none)
      type(error_t), intent(inout) :: err          !< status
      character(len=*), parameter :: where = 'hdf5_append_steps'
      integer(hsize_t) :: m, dims(2), start(2), count(2)
      integer :: stat, r
      fspace = -1
      mspace = -1
      if (series%id < 0) then
         call set_error(err, stat_io, where//': series '''//text_or(series%path, '?')// &
            ''' is not open')
         return
      end if
      if (mod(n, series%n_cols) /= 0 .or. (integers .neqv. series%integers)) then
         call set_error(err, stat_io, where//': values of wrong size or type for '''// &
            series%path//''' in '''//file_name(series%file)//'''')
         return
      end if
      if (n == 0) return
      m = n/series%n_cols
      r = series%rank
      dims = [series%n_cols, series%n_steps + m]
      start = [0_hsize_t, series%n_steps]
      count = [series%n_cols, m]
      blk: block
         call h5dset_extent_f(series%id, dims(3 - r:), stat)
         if (failed(stat, 'extend dataset', where, series%file, series%path, err)) exit blk
         call h5dget_space_f(series%id, fspace, stat)
         if (failed(stat, 'extend dataset', where, series%file, series%path, err)) exit blk
         call h5sselect_hyperslab_f(fspace, H5S_SELECT_SET_F, start(3 - r:), &
            count(3 - r:), stat)
         if (failed(stat, 'select in dataset', where, series%file, series%path, err)) &
            exit blk
         ! the memory space has the shape of the file selection: HDF5 then copies the
         ! block as a whole instead of iterating over a 1-D to 2-D match element by
         ! element
         call h5screate_simple_f(r, count(3 - r:), mspace, stat)
         if (failed(stat, 'select in dataset', where, series%file, series%path, err)) &
            exit blk
         series%n_steps = series%n_steps + m
      end block blk
      if (has_error(err)) then
         call release(fspace)
         call release(mspace)
      end if
   end subroutine prepare_append

   !> Check the write of an append and release its dataspaces.
   subroutine finish_append(series, stat, fspace, mspace, err)
      type(hdf5_series_t), intent(in) :: series !< open series
      integer, intent(in) :: stat               !< status of h5dwrite_f
      integer(hid_t), intent(inout) :: fspace   !< file dataspace, released
      integer(hid_t), intent(inout) :: mspace   !< memory dataspace, released
      type(error_t), intent(inout) :: err       !< status
      integer :: stat2
      call check(stat, 'write dataset', 'hdf5_append_steps', series%file, series%path, err)
      call h5sclose_f(fspace, stat2)
      call h5sclose_f(mspace, stat2)
      fspace = -1
      mspace = -1
   end subroutine finish_append

end module rodyn_hdf5_base
