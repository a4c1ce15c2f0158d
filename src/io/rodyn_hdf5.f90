!> Thin wrapper over the HDF5 Fortran API: the only module of rodyn that uses `hdf5`
!> (pattern: tblite's src/tblite/io/hdf5.F90; style guide rules 4 and 6).
!>
!> Conventions
!> - Objects are named by absolute paths inside the file ('/static/RISER/node_s');
!>   attributes by the path of their object ('/' for the root group) and a name.
!>   In messages an attribute is shown as '<object>@<name>'.
!> - Arrays are written as they are laid out in memory: a Fortran array x(3, nn)
!>   appears in C/h5py as shape (nn, 3), one row per node.
!> - Reals are stored as IEEE 64-bit little endian, integers as 32-bit little endian,
!>   strings as variable-length UTF-8 scalars (h5py reads attributes as str).
!> - Every routine takes an error_t. Writers and readers do nothing when it already
!>   holds an error, so a sequence of calls can be checked once at its end; closing
!>   routines always act. HDF5's negative status becomes stat_io with a message naming
!>   the routine, the object and the file. HDF5's own error printing is switched off.
!> - Writing a dataset whose parent groups are missing creates them.
!> - Time series: hdf5_create_series (n values per step) and hdf5_create_series_1d (one)
!>   make empty extendible datasets; hdf5_open_series keeps one open so that
!>   hdf5_append_steps costs no lookup; hdf5_flush puts what was written on disk.
module rodyn_hdf5
   use, intrinsic :: iso_c_binding, only: c_char, c_ptr, c_loc, c_null_char, c_size_t, &
      c_f_pointer, c_associated, c_null_ptr
   use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5close_f, h5eset_auto_f, &
      h5fcreate_f, h5fopen_f, h5fclose_f, h5fflush_f, h5gcreate_f, h5gclose_f, &
      h5dcreate_f, h5dopen_f, h5dclose_f, h5dwrite_f, h5dread_f, h5dget_space_f, &
      h5dget_type_f, h5dset_extent_f, h5dvlen_reclaim_f, &
      h5acreate_f, h5aopen_f, h5aclose_f, h5awrite_f, h5aread_f, h5aexists_f, &
      h5adelete_f, h5aget_space_f, h5aget_type_f, &
      h5screate_f, h5screate_simple_f, h5sclose_f, h5sget_simple_extent_ndims_f, &
      h5sget_simple_extent_dims_f, h5sget_simple_extent_npoints_f, h5sselect_hyperslab_f, &
      h5tcopy_f, h5tclose_f, h5tset_cset_f, h5tget_cset_f, h5tget_class_f, &
      h5tget_size_f, h5tset_strpad_f, h5tis_variable_str_f, &
      h5pcreate_f, h5pclose_f, h5pset_chunk_f, h5pset_fclose_degree_f, h5pset_file_locking_f, &
      h5pset_buffer_f, H5P_DATASET_XFER_F, &
      h5pset_link_creation_order_f, h5pset_create_inter_group_f, &
      h5lexists_f, h5oopen_f, h5oclose_f, h5iget_type_f, &
      H5F_ACC_TRUNC_F, H5F_ACC_RDONLY_F, H5F_ACC_RDWR_F, H5F_CLOSE_STRONG_F, &
      H5F_SCOPE_GLOBAL_F, H5P_FILE_ACCESS_F, H5P_FILE_CREATE_F, H5P_GROUP_CREATE_F, &
      H5P_LINK_CREATE_F, H5P_DATASET_CREATE_F, H5P_DEFAULT_F, H5P_CRT_ORDER_TRACKED_F, &
      H5P_CRT_ORDER_INDEXED_F, H5S_SCALAR_F, H5S_UNLIMITED_F, H5S_SELECT_SET_F, &
      H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, H5T_IEEE_F64LE, H5T_STD_I32LE, &
      H5T_STRING, H5T_STRING_F, H5T_INTEGER_F, H5T_CSET_UTF8_F, H5T_STR_NULLPAD_F, &
      H5I_DATASET_F, H5I_GROUP_F, H5I_ATTR_F, H5I_DATASPACE_F, H5I_DATATYPE_F, &
      H5I_GENPROP_LST_F
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, set_error, has_error, stat_io
   implicit none
   private
   public :: hdf5_file_t
   public :: hdf5_init, hdf5_finalize
   public :: hdf5_create_file, hdf5_open_file, hdf5_close_file, hdf5_flush
   public :: hdf5_create_group, hdf5_exists
   public :: hdf5_write_dataset, hdf5_write_attribute, hdf5_write_attributes
   public :: hdf5_read_dataset, hdf5_read_attribute
   public :: hdf5_create_series, hdf5_append_column
   public :: hdf5_series_t, hdf5_create_series_1d, hdf5_open_series, hdf5_close_series
   public :: hdf5_append_steps, hdf5_series_hold, hdf5_series_write_held
   public :: hdf5_series_truncate

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

   !> Append steps to an open series: real or integer values(:) in memory order, n_cols
   !> per step (a 1-D series takes one value per step), or a real block x(n_cols, m).
   interface hdf5_append_steps
      module procedure append_real, append_real_2d, append_int
   end interface hdf5_append_steps

   !> Write a dataset: real scalar, 1-D or 2-D, integer 1-D, or a string (scalar).
   interface hdf5_write_dataset
      module procedure write_real_0d, write_real_1d, write_real_2d, write_int_1d, &
         write_string
   end interface hdf5_write_dataset

   !> Write (or replace) an attribute: string, real or integer scalar, real or integer 1-D.
   interface hdf5_write_attribute
      module procedure attr_write_string, attr_write_real, attr_write_int, &
         attr_write_real_1d, attr_write_int_1d
   end interface hdf5_write_attribute

   !> Read a whole dataset into an allocatable of the matching rank.
   interface hdf5_read_dataset
      module procedure read_real_0d, read_real_1d, read_real_2d, read_int_1d, read_string
   end interface hdf5_read_dataset

   !> Read an attribute.
   interface hdf5_read_attribute
      module procedure attr_read_string, attr_read_real, attr_read_int, &
         attr_read_real_1d, attr_read_int_1d
   end interface hdf5_read_attribute

   interface
      !> C strlen, to measure strings HDF5 returns as char *.
      function c_strlen(s) bind(c, name='strlen') result(n)
         import :: c_ptr, c_size_t
         type(c_ptr), value :: s          !< NUL-terminated C string
         integer(c_size_t) :: n           !< its length without the NUL
      end function c_strlen
   end interface

   !> Whether h5open_f has run and h5close_f has not. The HDF5 library is itself
   !> process-wide state; this flag only mirrors it so that init/finalize can be
   !> called any number of times (h5close_f twice is an error in HDF5).
   logical :: library_open = .false.

contains

   ! ------------------------------------------------------------------ library

   !> Initialise the HDF5 library (h5open_f) and switch off its error printing.
   !> Safe to call many times; the file routines call it themselves.
   subroutine hdf5_init(err)
      type(error_t), intent(inout) :: err !< status
      integer :: stat
      if (library_open) return
      call h5open_f(stat)
      if (stat < 0) then
         call set_error(err, stat_io, 'hdf5_init: cannot initialise the HDF5 library')
         return
      end if
      call h5eset_auto_f(0, stat)
      library_open = .true.
   end subroutine hdf5_init

   !> Close the HDF5 library (h5close_f). Safe to call many times or without hdf5_init;
   !> optional: the HDF5 library also closes itself at program exit.
   subroutine hdf5_finalize(err)
      type(error_t), intent(inout) :: err !< status
      integer :: stat
      if (.not. library_open) return
      call h5close_f(stat)
      library_open = .false.
      if (stat < 0) call set_error(err, stat_io, 'hdf5_finalize: cannot close HDF5')
   end subroutine hdf5_finalize

   ! ------------------------------------------------------------------ files

   !> Create a file, truncating an existing one. The root group tracks link creation
   !> order, so readers list groups in the order they were written.
   subroutine hdf5_create_file(file, path, err)
      type(hdf5_file_t), intent(out) :: file !< the open file
      character(len=*), intent(in) :: path   !< file name
      type(error_t), intent(inout) :: err    !< status
      character(len=*), parameter :: where = 'hdf5_create_file'
      integer(hid_t) :: fapl, fcpl
      integer :: stat
      file%path = path
      if (has_error(err)) return
      call hdf5_init(err)
      if (has_error(err)) return
      fapl = -1
      fcpl = -1
      blk: block
         call h5pcreate_f(H5P_FILE_ACCESS_F, fapl, stat)
         if (failed(stat, 'set up', where, file, '/', err)) exit blk
         call h5pset_fclose_degree_f(fapl, H5F_CLOSE_STRONG_F, stat)
         if (failed(stat, 'set up', where, file, '/', err)) exit blk
         call h5pcreate_f(H5P_FILE_CREATE_F, fcpl, stat)
         if (failed(stat, 'set up', where, file, '/', err)) exit blk
         call h5pset_link_creation_order_f(fcpl, &
            ior(H5P_CRT_ORDER_TRACKED_F, H5P_CRT_ORDER_INDEXED_F), stat)
         if (failed(stat, 'set up', where, file, '/', err)) exit blk
         call h5fcreate_f(path, H5F_ACC_TRUNC_F, file%id, stat, &
            creation_prp=fcpl, access_prp=fapl)
         if (stat < 0) then
            file%id = -1
            call set_error(err, stat_io, where//': cannot create file '''//path//'''')
         end if
      end block blk
      call release(fapl)
      call release(fcpl)
   end subroutine hdf5_create_file

   !> Open an existing file, read-only unless `writable` is true. While a process holds
   !> a file open for writing, HDF5's file lock (flock) makes other processes fail to
   !> open it; `locking = .false.` opens it anyway (HDF5 >= 1.10.7), to read what the
   !> writer last flushed (reading while it writes may see a half-updated file).
   !> The environment variable HDF5_USE_FILE_LOCKING=FALSE does the same for any program.
   subroutine hdf5_open_file(file, path, err, writable, locking)
      type(hdf5_file_t), intent(out) :: file     !< the open file
      character(len=*), intent(in) :: path       !< file name
      type(error_t), intent(inout) :: err        !< status
      logical, intent(in), optional :: writable  !< open for reading and writing
      logical, intent(in), optional :: locking   !< take HDF5's file lock (default true)
      character(len=*), parameter :: where = 'hdf5_open_file'
      integer(hid_t) :: fapl
      integer :: stat, mode
      file%path = path
      if (has_error(err)) return
      call hdf5_init(err)
      if (has_error(err)) return
      mode = H5F_ACC_RDONLY_F
      if (present(writable)) then
         if (writable) mode = H5F_ACC_RDWR_F
      end if
      fapl = -1
      blk: block
         call h5pcreate_f(H5P_FILE_ACCESS_F, fapl, stat)
         if (failed(stat, 'set up', where, file, '/', err)) exit blk
         call h5pset_fclose_degree_f(fapl, H5F_CLOSE_STRONG_F, stat)
         if (failed(stat, 'set up', where, file, '/', err)) exit blk
         if (present(locking)) then
            if (.not. locking) then
               call h5pset_file_locking_f(fapl, .false., .true., stat)
               if (failed(stat, 'set up', where, file, '/', err)) exit blk
            end if
         end if
         call h5fopen_f(path, mode, file%id, stat, access_prp=fapl)
         if (stat < 0) then
            file%id = -1
            call set_error(err, stat_io, where//': cannot open HDF5 file '''//path//'''')
         end if
      end block blk
      call release(fapl)
   end subroutine hdf5_open_file

   !> Close a file (everything still open in it is closed too). Acts even when err
   !> already holds an error; does nothing for a file that is not open.
   subroutine hdf5_close_file(file, err)
      type(hdf5_file_t), intent(inout) :: file !< file to close
      type(error_t), intent(inout) :: err      !< status
      integer :: stat
      if (file%id < 0) return
      call h5fclose_f(file%id, stat)
      file%id = -1
      if (stat < 0) call set_error(err, stat_io, &
         'hdf5_close_file: cannot close '''//file_name(file)//'''')
   end subroutine hdf5_close_file

   !> Flush a file's buffers to disk (for long runs written step by step).
   subroutine hdf5_flush(file, err)
      type(hdf5_file_t), intent(in) :: file !< open file
      type(error_t), intent(inout) :: err   !< status
      integer :: stat
      if (has_error(err)) return
      call h5fflush_f(file%id, H5F_SCOPE_GLOBAL_F, stat)
      if (failed(stat, 'flush', 'hdf5_flush', file, '/', err)) return
   end subroutine hdf5_flush

   ! ------------------------------------------------------------------ groups

   !> Create a group and any missing parents ('/static/RISER'); existing ones are kept.
   !> New groups track link creation order.
   subroutine hdf5_create_group(file, path, err)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: path  !< absolute group path
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: where = 'hdf5_create_group'
      integer(hid_t) :: gcpl, gid
      integer :: stat, k
      logical :: exists
      if (has_error(err)) return
      gcpl = -1
      gid = -1
      blk: block
         call h5pcreate_f(H5P_GROUP_CREATE_F, gcpl, stat)
         if (failed(stat, 'set up group', where, file, path, err)) exit blk
         call h5pset_link_creation_order_f(gcpl, &
            ior(H5P_CRT_ORDER_TRACKED_F, H5P_CRT_ORDER_INDEXED_F), stat)
         if (failed(stat, 'set up group', where, file, path, err)) exit blk
         do k = 2, len(path) + 1
            if (k <= len(path)) then
               if (path(k:k) /= '/') cycle
            end if
            if (path(k - 1:k - 1) == '/') cycle
            call h5lexists_f(file%id, path(:k - 1), exists, stat)
            if (failed(stat, 'look up', where, file, path(:k - 1), err)) exit blk
            if (exists) cycle
            call h5gcreate_f(file%id, path(:k - 1), gid, stat, gcpl_id=gcpl)
            if (failed(stat, 'create group', where, file, path(:k - 1), err)) exit blk
            call release(gid)
         end do
      end block blk
      call release(gcpl)
   end subroutine hdf5_create_group

   !> Whether an object (group or dataset) exists at an absolute path.
   subroutine hdf5_exists(file, path, exists, err)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: path  !< absolute path
      logical, intent(out) :: exists        !< the object exists
      type(error_t), intent(inout) :: err   !< status
      integer :: stat, k
      exists = .false.
      if (has_error(err)) return
      exists = .true.
      do k = 2, len(path) + 1
         if (k <= len(path)) then
            if (path(k:k) /= '/') cycle
         end if
         if (path(k - 1:k - 1) == '/') cycle
         call h5lexists_f(file%id, path(:k - 1), exists, stat)
         if (failed(stat, 'look up', 'hdf5_exists', file, path(:k - 1), err)) exists = .false.
         if (.not. exists) return
      end do
   end subroutine hdf5_exists

   ! ------------------------------------------------------------------ dataset writers

   !> Write a real scalar dataset (h5py: shape ()).
   subroutine write_real_0d(file, path, x, err, names, texts)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: path  !< absolute dataset path
      real(wp), intent(in) :: x             !< value
      type(error_t), intent(inout) :: err   !< status
      character(len=*), intent(in), optional :: names(:) !< text attributes of the dataset
      character(len=*), intent(in), optional :: texts(:) !< their texts (trailing blanks cut)
      character(len=*), parameter :: where = 'hdf5_write_real_0d'
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(0)
      real(wp) :: buf(1)
      integer :: stat
      if (has_error(err)) return
      buf(1) = x
      call create_dataset(file, path, H5T_IEEE_F64LE, dims, dset, where, err, &
         names=names, texts=texts)
      if (.not. has_error(err)) then
         call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, buf, [1_hsize_t], stat)
         call check(stat, 'write dataset', where, file, path, err)
      end if
      call release(dset)
   end subroutine write_real_0d

   !> Write a real 1-D dataset.
   subroutine write_real_1d(file, path, x, err, names, texts)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: path  !< absolute dataset path
      real(wp), intent(in) :: x(:)          !< values
      type(error_t), intent(inout) :: err   !< status
      character(len=*), intent(in), optional :: names(:) !< text attributes of the dataset
      character(len=*), intent(in), optional :: texts(:) !< their texts (trailing blanks cut)
      character(len=*), parameter :: where = 'hdf5_write_real_1d'
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(1)
      integer :: stat
      if (has_error(err)) return
      dims = shape(x, kind=hsize_t)
      call create_dataset(file, path, H5T_IEEE_F64LE, dims, dset, where, err, &
         names=names, texts=texts)
      if (.not. has_error(err)) then
         call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, x, dims, stat)
         call check(stat, 'write dataset', where, file, path, err)
      end if
      call release(dset)
   end subroutine write_real_1d

   !> Write a real 2-D dataset; x(m, n) appears in h5py as shape (n, m).
   subroutine write_real_2d(file, path, x, err, names, texts)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: path  !< absolute dataset path
      real(wp), intent(in) :: x(:, :)       !< values
      type(error_t), intent(inout) :: err   !< status
      character(len=*), intent(in), optional :: names(:) !< text attributes of the dataset
      character(len=*), intent(in), optional :: texts(:) !< their texts (trailing blanks cut)
      character(len=*), parameter :: where = 'hdf5_write_real_2d'
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(2)
      integer :: stat
      if (has_error(err)) return
      dims = shape(x, kind=hsize_t)
      call create_dataset(file, path, H5T_IEEE_F64LE, dims, dset, where, err, &
         names=names, texts=texts)
      if (.not. has_error(err)) then
         call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, x, dims, stat)
         call check(stat, 'write dataset', where, file, path, err)
      end if
      call release(dset)
   end subroutine write_real_2d

   !> Write an integer 1-D dataset.
   subroutine write_int_1d(file, path, x, err, names, texts)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: path  !< absolute dataset path
      integer, intent(in) :: x(:)           !< values
      type(error_t), intent(inout) :: err   !< status
      character(len=*), intent(in), optional :: names(:) !< text attributes of the dataset
      character(len=*), intent(in), optional :: texts(:) !< their texts (trailing blanks cut)
      character(len=*), parameter :: where = 'hdf5_write_int_1d'
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(1)
      integer :: stat
      if (has_error(err)) return
      dims = shape(x, kind=hsize_t)
      call create_dataset(file, path, H5T_STD_I32LE, dims, dset, where, err, &
         names=names, texts=texts)
      if (.not. has_error(err)) then
         call h5dwrite_f(dset, H5T_NATIVE_INTEGER, x, dims, stat)
         call check(stat, 'write dataset', where, file, path, err)
      end if
      call release(dset)
   end subroutine write_int_1d

   !> Write a string as a scalar variable-length UTF-8 dataset (any length, newlines kept).
   subroutine write_string(file, path, text, err, names, texts)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: path  !< absolute dataset path
      character(len=*), intent(in) :: text  !< the text
      type(error_t), intent(inout) :: err   !< status
      character(len=*), intent(in), optional :: names(:) !< text attributes of the dataset
      character(len=*), intent(in), optional :: texts(:) !< their texts (trailing blanks cut)
      character(len=*), parameter :: where = 'hdf5_write_string'
      character(kind=c_char), allocatable, target :: buf(:)
      type(c_ptr), target :: ptr(1)
      integer(hid_t) :: dset, stype, dxpl
      integer(hsize_t) :: dims(0)
      integer :: stat
      if (has_error(err)) return
      dset = -1
      stype = -1
      dxpl = -1
      blk: block
         call vlen_string_type(stype, stat)
         if (failed(stat, 'set up string', where, file, path, err)) exit blk
         call create_dataset(file, path, stype, dims, dset, where, err, &
         names=names, texts=texts)
         if (has_error(err)) exit blk
         ! the string is converted on its way to the file, through a buffer HDF5 zeroes
         ! first: 1 MiB by default, for the one 16-byte pointer written here
         call h5pcreate_f(H5P_DATASET_XFER_F, dxpl, stat)
         if (failed(stat, 'set up the writing of', where, file, path, err)) exit blk
         call h5pset_buffer_f(dxpl, 1024_hsize_t, stat)
         if (failed(stat, 'set up the writing of', where, file, path, err)) exit blk
         call c_chars(text, buf)
         ptr(1) = c_loc(buf)
         call h5dwrite_f(dset, stype, c_loc(ptr), stat, xfer_prp=dxpl)
         if (failed(stat, 'write dataset', where, file, path, err)) exit blk
      end block blk
      call release(dxpl)
      call release(dset)
      call release(stype)
   end subroutine write_string

   ! ------------------------------------------------------------------ time series

   !> Create an empty extendible real dataset of n_cols rows in Fortran order (h5py
   !> shape (0, n_cols)), chunked, to be grown one column (one h5py row, e.g. one time
   !> step) at a time with hdf5_append_column or hdf5_append_steps.
   subroutine hdf5_create_series(file, path, n_cols, err, chunk_steps, names, texts, series)
      type(hdf5_file_t), intent(in) :: file         !< open file
      character(len=*), intent(in) :: path          !< absolute dataset path
      integer, intent(in) :: n_cols                 !< values per step (h5py columns)
      type(error_t), intent(inout) :: err           !< status
      integer, intent(in), optional :: chunk_steps  !< steps per chunk; default ~64 KiB
      character(len=*), intent(in), optional :: names(:) !< text attributes of the dataset
      character(len=*), intent(in), optional :: texts(:) !< their texts (trailing blanks cut)
      !> the new dataset kept open for appending, as hdf5_open_series leaves it
      type(hdf5_series_t), intent(inout), optional :: series
      character(len=*), parameter :: where = 'hdf5_create_series'
      integer :: steps
      if (has_error(err)) return
      if (n_cols < 1) then
         call set_error(err, stat_io, where//': no columns for '''//path//''' in '''// &
            file_name(file)//'''')
         return
      end if
      steps = max(1, 8192/n_cols)
      if (present(chunk_steps)) steps = max(1, chunk_steps)
      call create_extendible(file, path, [integer(hsize_t) :: n_cols, 0], H5T_IEEE_F64LE, &
         steps, where, err, names, texts, series)
   end subroutine hdf5_create_series

   !> Create an empty extendible 1-D dataset (h5py shape (0,)), one value per step:
   !> real (binary64), or 32-bit integer when `integers` is true.
   subroutine hdf5_create_series_1d(file, path, err, chunk_steps, integers, names, texts, &
                                    series)
      type(hdf5_file_t), intent(in) :: file         !< open file
      character(len=*), intent(in) :: path          !< absolute dataset path
      type(error_t), intent(inout) :: err           !< status
      integer, intent(in), optional :: chunk_steps  !< steps per chunk; default 8192
      logical, intent(in), optional :: integers     !< integer values (default: real)
      character(len=*), intent(in), optional :: names(:) !< text attributes of the dataset
      character(len=*), intent(in), optional :: texts(:) !< their texts (trailing blanks cut)
      !> the new dataset kept open for appending, as hdf5_open_series leaves it
      type(hdf5_series_t), intent(inout), optional :: series
      integer(hid_t) :: ftype
      integer :: steps
      if (has_error(err)) return
      steps = 8192
      if (present(chunk_steps)) steps = max(1, chunk_steps)
      ftype = H5T_IEEE_F64LE
      if (present(integers)) then
         if (integers) ftype = H5T_STD_I32LE
      end if
      call create_extendible(file, path, [integer(hsize_t) :: 0], ftype, steps, &
         'hdf5_create_series_1d', err, names, texts, series)
   end subroutine hdf5_create_series_1d

   !> Open a dataset made by hdf5_create_series or hdf5_create_series_1d and keep it
   !> open for appending: one dataset lookup instead of one per append (several times
   !> faster than hdf5_append_column in a loop).
   subroutine hdf5_open_series(file, path, series, err)
      type(hdf5_file_t), intent(in) :: file         !< open file, writable
      character(len=*), intent(in) :: path          !< absolute dataset path
      type(hdf5_series_t), intent(inout) :: series  !< the open series
      type(error_t), intent(inout) :: err           !< status
      character(len=*), parameter :: where = 'hdf5_open_series'
      integer(hid_t) :: dset, space, ftype
      integer(hsize_t) :: dims(2), maxdims(2)
      integer :: stat, ndims, tclass
      call hdf5_close_series(series, err)
      series%path = path
      series%file = file
      if (has_error(err)) return
      space = -1
      ftype = -1
      call h5dopen_f(file%id, path, dset, stat)
      if (stat < 0) dset = -1
      if (failed(stat, 'open dataset', where, file, path, err)) return
      blk: block
         call h5dget_space_f(dset, space, stat)
         if (failed(stat, 'read shape of', where, file, path, err)) exit blk
         call h5sget_simple_extent_ndims_f(space, ndims, stat)
         if (stat >= 0 .and. (ndims < 1 .or. ndims > 2)) stat = -1
         if (failed(stat, 'append to (not a series)', where, file, path, err)) exit blk
         call h5sget_simple_extent_dims_f(space, dims(:ndims), maxdims(:ndims), stat)
         if (failed(stat, 'read shape of', where, file, path, err)) exit blk
         call h5dget_type_f(dset, ftype, stat)
         if (failed(stat, 'read type of', where, file, path, err)) exit blk
         call h5tget_class_f(ftype, tclass, stat)
         if (failed(stat, 'read type of', where, file, path, err)) exit blk
         call series_holds(series, dset, dims(:ndims), tclass == H5T_INTEGER_F)
         dset = -1
      end block blk
      call release(ftype)
      call release(space)
      call release(dset)
   end subroutine hdf5_open_series

   !> The open series takes dataset dset of shape dims (Fortran order, steps last; rank
   !> 1 or 2) and value type (integers or reals): the one description of what a series
   !> knows of its dataset, for hdf5_open_series and for a series kept from its creation.
   pure subroutine series_holds(series, dset, dims, integers)
      type(hdf5_series_t), intent(inout) :: series !< series (path and file set)
      integer(hid_t), intent(in) :: dset           !< the open dataset, now the series'
      integer(hsize_t), intent(in) :: dims(:)      !< its shape
      logical, intent(in) :: integers              !< integer values
      series%rank = size(dims)
      series%n_cols = 1
      if (size(dims) == 2) series%n_cols = dims(1)
      series%n_steps = dims(size(dims))
      series%integers = integers
      series%id = dset
   end subroutine series_holds

   !> Hold the steps appended to a real series in memory, up to `steps` steps, instead of
   !> writing each append: hdf5_series_write_held writes them as one block (and so do an
   !> append that would overflow the hold, and hdf5_close_series). One block of m steps
   !> costs one extent change and one write instead of m.
   subroutine hdf5_series_hold(series, steps)
      type(hdf5_series_t), intent(inout) :: series !< open real series, nothing held
      integer, intent(in) :: steps                 !< steps held at most (>= 1)
      if (allocated(series%held)) deallocate (series%held)
      allocate (series%held(max(steps, 1)*series%n_cols))
      series%n_held = 0
   end subroutine hdf5_series_hold

   !> Write the steps held (hdf5_series_hold) as one block. Nothing when none are held.
   subroutine hdf5_series_write_held(series, err)
      type(hdf5_series_t), intent(inout) :: series !< open series
      type(error_t), intent(inout) :: err          !< status
      integer(hsize_t) :: n
      if (has_error(err) .or. series%n_held == 0) return
      n = series%n_held
      series%n_held = 0
      call write_real(series, series%held(1:n), err)
   end subroutine hdf5_series_write_held

   !> Cut an open series back to its first n_steps steps (a restarted run continues
   !> from its checkpoint; nothing may be held). Refused when it has fewer.
   subroutine hdf5_series_truncate(series, n_steps, err)
      type(hdf5_series_t), intent(inout) :: series !< open series, nothing held
      integer, intent(in) :: n_steps               !< steps kept [-]
      type(error_t), intent(inout) :: err          !< status
      character(len=*), parameter :: where = 'hdf5_series_truncate'
      integer(hsize_t) :: dims(2)
      integer :: stat
      if (has_error(err)) return
      if (series%id < 0 .or. series%n_held > 0) then
         call set_error(err, stat_io, where//': series '''//text_or(series%path)// &
            ''' is not open or holds steps')
         return
      end if
      if (int(n_steps, hsize_t) > series%n_steps) then
         call set_error(err, stat_io, where//': '''//series%path//''' in '''// &
            file_name(series%file)//''' has fewer steps than the checkpoint''s')
         return
      end if
      dims = [series%n_cols, int(n_steps, hsize_t)]
      call h5dset_extent_f(series%id, dims(3 - series%rank:), stat)
      if (failed(stat, 'cut back dataset', where, series%file, series%path, err)) return
      series%n_steps = int(n_steps, hsize_t)
   end subroutine hdf5_series_truncate

   !> Close a series opened by hdf5_open_series, writing the steps it holds first. Acts
   !> even when err already holds an error (then the steps held are dropped); does
   !> nothing for a series that is not open.
   subroutine hdf5_close_series(series, err)
      type(hdf5_series_t), intent(inout) :: series !< series to close
      type(error_t), intent(inout) :: err          !< status
      integer :: stat
      if (series%id < 0) return
      call hdf5_series_write_held(series, err)
      series%n_held = 0
      if (allocated(series%held)) deallocate (series%held)
      call h5dclose_f(series%id, stat)
      series%id = -1
      if (stat < 0) call set_error(err, stat_io, 'hdf5_close_series: cannot close '''// &
         text_or(series%path)//''' in '''//file_name(series%file)//'''')
   end subroutine hdf5_close_series

   !> Append one column (one h5py row) to a dataset made by hdf5_create_series; opens
   !> and closes the dataset (in a loop prefer hdf5_open_series + hdf5_append_steps).
   subroutine hdf5_append_column(file, path, column, err)
      type(hdf5_file_t), intent(in) :: file !< open file, writable
      character(len=*), intent(in) :: path  !< absolute dataset path
      real(wp), intent(in) :: column(:)     !< values of the new step, size n_cols
      type(error_t), intent(inout) :: err   !< status
      type(hdf5_series_t) :: series
      if (has_error(err)) return
      call hdf5_open_series(file, path, series, err)
      if (.not. has_error(err)) then
         if (series%rank /= 2 .or. series%n_cols /= size(column, kind=hsize_t)) &
            call set_error(err, stat_io, 'hdf5_append_column: column of wrong size '// &
            'for '''//path//''' in '''//file_name(file)//'''')
      end if
      call append_real(series, column, err)
      call hdf5_close_series(series, err)
   end subroutine hdf5_append_column

   !> Append steps of real values to an open series: values in memory order, n_cols per
   !> step (size(values) a multiple of n_cols; a 1-D series takes one value per step).
   subroutine append_real(series, values, err)
      type(hdf5_series_t), intent(inout) :: series !< open series
      real(wp), intent(in) :: values(:)            !< the new steps' values
      type(error_t), intent(inout) :: err          !< status
      integer(hsize_t) :: n
      if (has_error(err)) return
      n = size(values, kind=hsize_t)
      if (allocated(series%held) .and. mod(n, series%n_cols) == 0 .and. &
          .not. series%integers) then
         ! held: written with the block (hdf5_series_write_held), or at once if too big
         if (series%n_held + n > size(series%held, kind=hsize_t)) &
            call hdf5_series_write_held(series, err)
         if (n <= size(series%held, kind=hsize_t)) then
            series%held(series%n_held + 1:series%n_held + n) = values
            series%n_held = series%n_held + n
            return
         end if
      end if
      call write_real(series, values, err)
   end subroutine append_real

   !> Write real steps to the end of a series (the write of append_real).
   subroutine write_real(series, values, err)
      type(hdf5_series_t), intent(inout) :: series !< open series
      real(wp), intent(in) :: values(:)            !< the new steps' values
      type(error_t), intent(inout) :: err          !< status
      integer(hid_t) :: fspace, mspace
      integer(hsize_t) :: mdims(1)
      integer :: stat
      if (has_error(err)) return
      mdims = shape(values, kind=hsize_t)
      call prepare_append(series, mdims(1), .false., fspace, mspace, err)
      if (has_error(err) .or. mdims(1) == 0) return
      call h5dwrite_f(series%id, H5T_NATIVE_DOUBLE, values, mdims, stat, &
         mem_space_id=mspace, file_space_id=fspace)
      call finish_append(series, stat, fspace, mspace, err)
   end subroutine write_real

   !> Append steps given as a block x(n_cols, m), m steps, to an open 2-D series.
   subroutine append_real_2d(series, values, err)
      type(hdf5_series_t), intent(inout) :: series !< open series
      real(wp), intent(in) :: values(:, :)         !< (n_cols, m) the new steps
      type(error_t), intent(inout) :: err          !< status
      if (has_error(err)) return
      if (size(values, 1, kind=hsize_t) /= series%n_cols) then
         call set_error(err, stat_io, 'hdf5_append_steps: block of wrong size for '''// &
            text_or(series%path)//''' in '''//file_name(series%file)//'''')
         return
      end if
      call append_real(series, reshape(values, [size(values)]), err)
   end subroutine append_real_2d

   !> Append steps of integer values to an open integer series (as append_real).
   subroutine append_int(series, values, err)
      type(hdf5_series_t), intent(inout) :: series !< open series
      integer, intent(in) :: values(:)             !< the new steps' values
      type(error_t), intent(inout) :: err          !< status
      integer(hid_t) :: fspace, mspace
      integer(hsize_t) :: mdims(1)
      integer :: stat
      if (has_error(err)) return
      mdims = shape(values, kind=hsize_t)
      call prepare_append(series, mdims(1), .true., fspace, mspace, err)
      if (has_error(err) .or. mdims(1) == 0) return
      call h5dwrite_f(series%id, H5T_NATIVE_INTEGER, values, mdims, stat, &
         mem_space_id=mspace, file_space_id=fspace)
      call finish_append(series, stat, fspace, mspace, err)
   end subroutine append_int

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
         call set_error(err, stat_io, where//': series '''//text_or(series%path)// &
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

   !> Create an empty chunked dataset whose last Fortran dimension (the first in h5py)
   !> is unlimited; dims is the shape with 0 steps, chunks hold chunk_steps steps.
   subroutine create_extendible(file, path, dims, ftype, chunk_steps, where, err, names, &
                                texts, series)
      type(hdf5_file_t), intent(in) :: file    !< open file
      character(len=*), intent(in) :: path     !< absolute dataset path
      integer(hsize_t), intent(in) :: dims(:)  !< shape, last extent 0 (Fortran order)
      integer(hid_t), intent(in) :: ftype      !< datatype in the file
      integer, intent(in) :: chunk_steps       !< steps per chunk
      character(len=*), intent(in) :: where    !< calling routine
      type(error_t), intent(inout) :: err      !< status
      character(len=*), intent(in), optional :: names(:) !< text attributes of the dataset
      character(len=*), intent(in), optional :: texts(:) !< their texts
      !> the dataset kept open here, its shape and type as hdf5_open_series reads them
      !> (opening it again by its path would cost as much as creating it)
      type(hdf5_series_t), intent(inout), optional :: series
      integer(hid_t) :: dset, dcpl
      integer(hsize_t) :: maxdims(size(dims)), chunk(size(dims))
      integer :: stat, r
      r = size(dims)
      maxdims = dims
      maxdims(r) = H5S_UNLIMITED_F
      chunk = dims
      chunk(r) = int(chunk_steps, hsize_t)
      dset = -1
      dcpl = -1
      blk: block
         call h5pcreate_f(H5P_DATASET_CREATE_F, dcpl, stat)
         if (failed(stat, 'set up dataset', where, file, path, err)) exit blk
         call h5pset_chunk_f(dcpl, r, chunk, stat)
         if (failed(stat, 'set up dataset', where, file, path, err)) exit blk
         call create_dataset(file, path, ftype, dims, dset, where, err, &
            maxdims=maxdims, dcpl=dcpl, names=names, texts=texts)
         if (has_error(err) .or. .not. present(series)) exit blk
         call hdf5_close_series(series, err)
         series%path = path
         series%file = file
         call series_holds(series, dset, dims, ftype == H5T_STD_I32LE)
         dset = -1
      end block blk
      call release(dset)
      call release(dcpl)
   end subroutine create_extendible

   ! ------------------------------------------------------------------ attribute writers

   !> Write a string attribute (variable-length UTF-8 scalar).
   subroutine attr_write_string(file, obj, name, value, err)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: obj   !< object path ('/' for the root group)
      character(len=*), intent(in) :: name  !< attribute name
      character(len=*), intent(in) :: value !< the text
      type(error_t), intent(inout) :: err   !< status
      call hdf5_write_attributes(file, obj, [name], [value], err, keep_blanks=.true.)
   end subroutine attr_write_string

   !> Write text attributes names(i) = values(i) (trailing blanks removed, unless
   !> keep_blanks) on object `obj`, opened once for all of them: opening an object by
   !> its path is most of what an attribute costs (docs/benchmarks.md). A new dataset
   !> takes its attributes at creation instead (the writers' `names`, `texts`).
   subroutine hdf5_write_attributes(file, obj, names, values, err, keep_blanks)
      type(hdf5_file_t), intent(in) :: file    !< open file
      character(len=*), intent(in) :: obj      !< object path ('/' for the root group)
      character(len=*), intent(in) :: names(:) !< attribute names
      character(len=*), intent(in) :: values(:) !< their texts
      type(error_t), intent(inout) :: err      !< status
      logical, intent(in), optional :: keep_blanks !< write values(i) as given
      integer(hid_t) :: oid
      logical :: keep
      if (has_error(err)) return
      keep = .false.
      if (present(keep_blanks)) keep = keep_blanks
      call open_object(file, obj, oid, 'hdf5_write_attribute_string', err)
      if (.not. has_error(err)) call text_attributes(file, oid, obj, names, values, keep, err)
      call release(oid)
   end subroutine hdf5_write_attributes

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

   !> Write a real scalar attribute.
   subroutine attr_write_real(file, obj, name, value, err)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: obj   !< object path ('/' for the root group)
      character(len=*), intent(in) :: name  !< attribute name
      real(wp), intent(in) :: value         !< value
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: where = 'hdf5_write_attribute_real'
      integer(hid_t) :: oid, aid
      integer(hsize_t) :: dims(0)
      integer :: stat
      if (has_error(err)) return
      call create_attribute(file, obj, name, H5T_IEEE_F64LE, dims, oid, aid, where, err)
      if (.not. has_error(err)) then
         call h5awrite_f(aid, H5T_NATIVE_DOUBLE, value, dims, stat)
         call check(stat, 'write attribute', where, file, obj//'@'//name, err)
      end if
      call release(aid)
      call release(oid)
   end subroutine attr_write_real

   !> Write an integer scalar attribute.
   subroutine attr_write_int(file, obj, name, value, err)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: obj   !< object path ('/' for the root group)
      character(len=*), intent(in) :: name  !< attribute name
      integer, intent(in) :: value          !< value
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: where = 'hdf5_write_attribute_int'
      integer(hid_t) :: oid, aid
      integer(hsize_t) :: dims(0)
      integer :: stat
      if (has_error(err)) return
      call create_attribute(file, obj, name, H5T_STD_I32LE, dims, oid, aid, where, err)
      if (.not. has_error(err)) then
         call h5awrite_f(aid, H5T_NATIVE_INTEGER, value, dims, stat)
         call check(stat, 'write attribute', where, file, obj//'@'//name, err)
      end if
      call release(aid)
      call release(oid)
   end subroutine attr_write_int

   !> Write a real 1-D attribute.
   subroutine attr_write_real_1d(file, obj, name, value, err)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: obj   !< object path ('/' for the root group)
      character(len=*), intent(in) :: name  !< attribute name
      real(wp), intent(in) :: value(:)      !< values
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: where = 'hdf5_write_attribute_real_1d'
      integer(hid_t) :: oid, aid
      integer(hsize_t) :: dims(1)
      integer :: stat
      if (has_error(err)) return
      dims = shape(value, kind=hsize_t)
      call create_attribute(file, obj, name, H5T_IEEE_F64LE, dims, oid, aid, where, err)
      if (.not. has_error(err)) then
         call h5awrite_f(aid, H5T_NATIVE_DOUBLE, value, dims, stat)
         call check(stat, 'write attribute', where, file, obj//'@'//name, err)
      end if
      call release(aid)
      call release(oid)
   end subroutine attr_write_real_1d

   !> Write an integer 1-D attribute.
   subroutine attr_write_int_1d(file, obj, name, value, err)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: obj   !< object path ('/' for the root group)
      character(len=*), intent(in) :: name  !< attribute name
      integer, intent(in) :: value(:)       !< values
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: where = 'hdf5_write_attribute_int_1d'
      integer(hid_t) :: oid, aid
      integer(hsize_t) :: dims(1)
      integer :: stat
      if (has_error(err)) return
      dims = shape(value, kind=hsize_t)
      call create_attribute(file, obj, name, H5T_STD_I32LE, dims, oid, aid, where, err)
      if (.not. has_error(err)) then
         call h5awrite_f(aid, H5T_NATIVE_INTEGER, value, dims, stat)
         call check(stat, 'write attribute', where, file, obj//'@'//name, err)
      end if
      call release(aid)
      call release(oid)
   end subroutine attr_write_int_1d

   ! ------------------------------------------------------------------ dataset readers

   !> Read a real scalar (or single-element) dataset.
   subroutine read_real_0d(file, path, x, err)
      type(hdf5_file_t), intent(in) :: file      !< open file
      character(len=*), intent(in) :: path       !< absolute dataset path
      real(wp), intent(out) :: x                 !< value (0 on failure)
      type(error_t), intent(inout) :: err        !< status
      character(len=*), parameter :: where = 'hdf5_read_real_0d'
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(0)
      real(wp) :: buf(1)
      integer :: stat
      x = 0.0_wp
      if (has_error(err)) return
      call open_dataset(file, path, 0, dset, dims, where, err)
      if (.not. has_error(err)) then
         call h5dread_f(dset, H5T_NATIVE_DOUBLE, buf, [1_hsize_t], stat)
         if (.not. failed(stat, 'read dataset', where, file, path, err)) x = buf(1)
      end if
      call release(dset)
   end subroutine read_real_0d

   !> Read a real 1-D dataset.
   subroutine read_real_1d(file, path, x, err)
      type(hdf5_file_t), intent(in) :: file      !< open file
      character(len=*), intent(in) :: path       !< absolute dataset path
      real(wp), allocatable, intent(out) :: x(:) !< values
      type(error_t), intent(inout) :: err        !< status
      character(len=*), parameter :: where = 'hdf5_read_real_1d'
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(1)
      integer :: stat
      if (has_error(err)) return
      call open_dataset(file, path, 1, dset, dims, where, err)
      if (.not. has_error(err)) then
         allocate (x(dims(1)))
         call h5dread_f(dset, H5T_NATIVE_DOUBLE, x, dims, stat)
         if (failed(stat, 'read dataset', where, file, path, err)) deallocate (x)
      end if
      call release(dset)
   end subroutine read_real_1d

   !> Read a real 2-D dataset; h5py shape (n, m) arrives as x(m, n).
   subroutine read_real_2d(file, path, x, err)
      type(hdf5_file_t), intent(in) :: file         !< open file
      character(len=*), intent(in) :: path          !< absolute dataset path
      real(wp), allocatable, intent(out) :: x(:, :) !< values
      type(error_t), intent(inout) :: err           !< status
      character(len=*), parameter :: where = 'hdf5_read_real_2d'
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(2)
      integer :: stat
      if (has_error(err)) return
      call open_dataset(file, path, 2, dset, dims, where, err)
      if (.not. has_error(err)) then
         allocate (x(dims(1), dims(2)))
         call h5dread_f(dset, H5T_NATIVE_DOUBLE, x, dims, stat)
         if (failed(stat, 'read dataset', where, file, path, err)) deallocate (x)
      end if
      call release(dset)
   end subroutine read_real_2d

   !> Read an integer 1-D dataset.
   subroutine read_int_1d(file, path, x, err)
      type(hdf5_file_t), intent(in) :: file     !< open file
      character(len=*), intent(in) :: path      !< absolute dataset path
      integer, allocatable, intent(out) :: x(:) !< values
      type(error_t), intent(inout) :: err       !< status
      character(len=*), parameter :: where = 'hdf5_read_int_1d'
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(1)
      integer :: stat
      if (has_error(err)) return
      call open_dataset(file, path, 1, dset, dims, where, err)
      if (.not. has_error(err)) then
         allocate (x(dims(1)))
         call h5dread_f(dset, H5T_NATIVE_INTEGER, x, dims, stat)
         if (failed(stat, 'read dataset', where, file, path, err)) deallocate (x)
      end if
      call release(dset)
   end subroutine read_int_1d

   !> Read a scalar string dataset (variable or fixed length).
   subroutine read_string(file, path, text, err)
      type(hdf5_file_t), intent(in) :: file                  !< open file
      character(len=*), intent(in) :: path                   !< absolute dataset path
      character(len=:), allocatable, intent(out) :: text     !< the text
      type(error_t), intent(inout) :: err                    !< status
      character(len=*), parameter :: where = 'hdf5_read_string'
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(0)
      text = ''
      if (has_error(err)) return
      call open_dataset(file, path, 0, dset, dims, where, err)
      if (.not. has_error(err)) then
         call read_string_from(file, dset, .false., path, text, where, err)
      end if
      call release(dset)
   end subroutine read_string

   ! ------------------------------------------------------------------ attribute readers

   !> Read a string attribute (variable or fixed length).
   subroutine attr_read_string(file, obj, name, value, err)
      type(hdf5_file_t), intent(in) :: file               !< open file
      character(len=*), intent(in) :: obj                 !< object path
      character(len=*), intent(in) :: name                !< attribute name
      character(len=:), allocatable, intent(out) :: value !< the text
      type(error_t), intent(inout) :: err                 !< status
      character(len=*), parameter :: where = 'hdf5_read_attribute_string'
      integer(hid_t) :: oid, aid
      integer(hsize_t) :: dims(0)
      value = ''
      if (has_error(err)) return
      call open_attribute(file, obj, name, 0, oid, aid, dims, where, err)
      if (.not. has_error(err)) then
         call read_string_from(file, aid, .true., obj//'@'//name, value, where, err)
      end if
      call release(aid)
      call release(oid)
   end subroutine attr_read_string

   !> Read a real scalar attribute.
   subroutine attr_read_real(file, obj, name, value, err)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: obj   !< object path
      character(len=*), intent(in) :: name  !< attribute name
      real(wp), intent(out) :: value        !< value (0 on error)
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: where = 'hdf5_read_attribute_real'
      integer(hid_t) :: oid, aid
      integer(hsize_t) :: dims(0)
      integer :: stat
      value = 0.0_wp
      if (has_error(err)) return
      call open_attribute(file, obj, name, 0, oid, aid, dims, where, err)
      if (.not. has_error(err)) then
         call h5aread_f(aid, H5T_NATIVE_DOUBLE, value, dims, stat)
         call check(stat, 'read attribute', where, file, obj//'@'//name, err)
      end if
      call release(aid)
      call release(oid)
   end subroutine attr_read_real

   !> Read an integer scalar attribute.
   subroutine attr_read_int(file, obj, name, value, err)
      type(hdf5_file_t), intent(in) :: file !< open file
      character(len=*), intent(in) :: obj   !< object path
      character(len=*), intent(in) :: name  !< attribute name
      integer, intent(out) :: value         !< value (0 on error)
      type(error_t), intent(inout) :: err   !< status
      character(len=*), parameter :: where = 'hdf5_read_attribute_int'
      integer(hid_t) :: oid, aid
      integer(hsize_t) :: dims(0)
      integer :: stat
      value = 0
      if (has_error(err)) return
      call open_attribute(file, obj, name, 0, oid, aid, dims, where, err)
      if (.not. has_error(err)) then
         call h5aread_f(aid, H5T_NATIVE_INTEGER, value, dims, stat)
         call check(stat, 'read attribute', where, file, obj//'@'//name, err)
      end if
      call release(aid)
      call release(oid)
   end subroutine attr_read_int

   !> Read a real 1-D attribute.
   subroutine attr_read_real_1d(file, obj, name, value, err)
      type(hdf5_file_t), intent(in) :: file          !< open file
      character(len=*), intent(in) :: obj            !< object path
      character(len=*), intent(in) :: name           !< attribute name
      real(wp), allocatable, intent(out) :: value(:) !< values
      type(error_t), intent(inout) :: err            !< status
      character(len=*), parameter :: where = 'hdf5_read_attribute_real_1d'
      integer(hid_t) :: oid, aid
      integer(hsize_t) :: dims(1)
      integer :: stat
      if (has_error(err)) return
      call open_attribute(file, obj, name, 1, oid, aid, dims, where, err)
      if (.not. has_error(err)) then
         allocate (value(dims(1)))
         call h5aread_f(aid, H5T_NATIVE_DOUBLE, value, dims, stat)
         if (failed(stat, 'read attribute', where, file, obj//'@'//name, err)) &
            deallocate (value)
      end if
      call release(aid)
      call release(oid)
   end subroutine attr_read_real_1d

   !> Read an integer 1-D attribute.
   subroutine attr_read_int_1d(file, obj, name, value, err)
      type(hdf5_file_t), intent(in) :: file         !< open file
      character(len=*), intent(in) :: obj           !< object path
      character(len=*), intent(in) :: name          !< attribute name
      integer, allocatable, intent(out) :: value(:) !< values
      type(error_t), intent(inout) :: err           !< status
      character(len=*), parameter :: where = 'hdf5_read_attribute_int_1d'
      integer(hid_t) :: oid, aid
      integer(hsize_t) :: dims(1)
      integer :: stat
      if (has_error(err)) return
      call open_attribute(file, obj, name, 1, oid, aid, dims, where, err)
      if (.not. has_error(err)) then
         allocate (value(dims(1)))
         call h5aread_f(aid, H5T_NATIVE_INTEGER, value, dims, stat)
         if (failed(stat, 'read attribute', where, file, obj//'@'//name, err)) &
            deallocate (value)
      end if
      call release(aid)
      call release(oid)
   end subroutine attr_read_int_1d

   ! ------------------------------------------------------------------ internals

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
      if (allocated(file%path)) then
         name = file%path
      else
         name = '?'
      end if
   end function file_name

   !> A string that may be unallocated, for messages ('?' when unallocated).
   pure function text_or(text) result(s)
      character(len=:), allocatable, intent(in) :: text !< string, maybe unallocated
      character(len=:), allocatable :: s                 !< its value or '?'
      if (allocated(text)) then
         s = text
      else
         s = '?'
      end if
   end function text_or

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
         if (size(dims) == 0) then
            call h5screate_f(H5S_SCALAR_F, space, stat)
         else
            call h5screate_simple_f(size(dims), dims, space, stat, maxdims)
         end if
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

   !> Open a dataset and return its shape; fails unless its rank is `rank`
   !> (rank 0: a scalar or a single element).
   subroutine open_dataset(file, path, rank, dset, dims, where, err)
      type(hdf5_file_t), intent(in) :: file     !< open file
      character(len=*), intent(in) :: path      !< absolute dataset path
      integer, intent(in) :: rank               !< expected rank
      integer(hid_t), intent(out) :: dset       !< open dataset (-1 on failure)
      integer(hsize_t), intent(out) :: dims(:)  !< shape, size rank
      character(len=*), intent(in) :: where     !< calling routine
      type(error_t), intent(inout) :: err       !< status
      integer(hid_t) :: space
      integer :: stat
      space = -1
      call h5dopen_f(file%id, path, dset, stat)
      if (stat < 0) dset = -1
      if (failed(stat, 'open dataset', where, file, path, err)) return
      call h5dget_space_f(dset, space, stat)
      if (.not. failed(stat, 'read shape of', where, file, path, err)) then
         call space_shape(space, rank, dims, stat)
         call check(stat, 'use (wrong rank)', where, file, path, err)
      end if
      call release(space)
      if (has_error(err)) call release(dset)
   end subroutine open_dataset

   !> Open an object and an attribute of it; return the attribute's shape; fails unless
   !> its rank is `rank` (0: scalar or single element).
   subroutine open_attribute(file, obj, name, rank, oid, aid, dims, where, err)
      type(hdf5_file_t), intent(in) :: file     !< open file
      character(len=*), intent(in) :: obj       !< object path
      character(len=*), intent(in) :: name      !< attribute name
      integer, intent(in) :: rank               !< expected rank
      integer(hid_t), intent(out) :: oid        !< open object (-1 on failure)
      integer(hid_t), intent(out) :: aid        !< open attribute (-1 on failure)
      integer(hsize_t), intent(out) :: dims(:)  !< shape, size rank
      character(len=*), intent(in) :: where     !< calling routine
      type(error_t), intent(inout) :: err       !< status
      integer(hid_t) :: space
      integer :: stat
      aid = -1
      space = -1
      call h5oopen_f(file%id, obj, oid, stat)
      if (stat < 0) oid = -1
      if (failed(stat, 'open object', where, file, obj, err)) return
      blk: block
         call h5aopen_f(oid, name, aid, stat)
         if (stat < 0) aid = -1
         if (failed(stat, 'open attribute', where, file, obj//'@'//name, err)) exit blk
         call h5aget_space_f(aid, space, stat)
         if (failed(stat, 'read shape of', where, file, obj//'@'//name, err)) exit blk
         call space_shape(space, rank, dims, stat)
         if (failed(stat, 'use (wrong rank)', where, file, obj//'@'//name, err)) exit blk
      end block blk
      call release(space)
      if (has_error(err)) then
         call release(aid)
         call release(oid)
      end if
   end subroutine open_attribute

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
         if (is_attr) then
            call h5aget_type_f(id, ftype, stat)
         else
            call h5dget_type_f(id, ftype, stat)
         end if
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
            if (is_attr) then
               call h5aread_f(id, mtype, bufp, stat)
               if (stat >= 0) call h5aget_space_f(id, space, stat)
            else
               call h5dread_f(id, mtype, bufp, stat)
               if (stat >= 0) call h5dget_space_f(id, space, stat)
            end if
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
            if (is_attr) then
               call h5aread_f(id, mtype, bufp, stat)
            else
               call h5dread_f(id, mtype, bufp, stat)
            end if
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
         if (size(dims) == 0) then
            call h5screate_f(H5S_SCALAR_F, space, stat)
         else
            call h5screate_simple_f(size(dims), dims, space, stat)
         end if
         if (failed(stat, 'create dataspace for', where, file, obj//'@'//name, err)) &
            exit blk
         call h5acreate_f(oid, name, ftype, space, aid, stat)
         if (stat < 0) aid = -1
         if (failed(stat, 'create attribute', where, file, obj//'@'//name, err)) exit blk
      end block blk
      call release(space)
   end subroutine attribute_on

end module rodyn_hdf5
