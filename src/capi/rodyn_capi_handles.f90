!> The handles of librodyn (docs/capi.md): a MoorDyn system handle points to a
!> capi_system_t, a line or point handle to one of its items; MoorDyn's codes; a C
!> string read.
module rodyn_capi_handles
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_char, c_f_pointer, &
                                          c_associated, c_size_t, c_double
   use rodyn_capi_system, only: md_system_t
   use rodyn_outfile, only: out_file_t
   use rodyn_capi_outputs, only: channel_t
   implicit none
   private
   public :: capi_item_t, capi_system_t, system_of, item_of, f_string
   public :: md_success, md_invalid_input_file, md_invalid_output_file, md_invalid_input, &
             md_nan_error, &
             md_invalid_value, md_unhandled

   integer(c_int), parameter :: md_success = 0, md_invalid_input_file = -1, &
                                md_invalid_output_file = -2, &
                                md_invalid_input = -3, md_nan_error = -4, &
                                md_invalid_value = -6, md_unhandled = -255

   !> A line or a point of a system, as its handle points to.
   type :: capi_item_t
      type(capi_system_t), pointer :: sys => null() !< its system
      integer :: index = 0                          !< model%lines or model%points
   end type capi_item_t

   !> A system with the handles of its lines and points.
   type :: capi_system_t
      type(md_system_t) :: s                     !< the system
      type(capi_item_t), allocatable :: lines(:), points(:), bodies(:), rods(:)
      type(channel_t), allocatable :: ch(:)      !< the OUTPUTS channels
      type(out_file_t) :: out                    !< FILE.out, when there are channels
      character(len=:), allocatable :: path      !< the MoorDyn file
      logical :: write_units = .true.            !< the .out file's units row
      real(c_double) :: cfl = 0.0_c_double       !< MoorDyn_SetCFL's value (not used)
   end type capi_system_t

   interface
      pure function c_strlen(s) result(n) bind(c, name='strlen')
         import :: c_ptr, c_size_t
         type(c_ptr), value :: s
         integer(c_size_t) :: n
      end function c_strlen
   end interface

contains

   !> A C string as Fortran text.
   function f_string(p) result(s)
      type(c_ptr), intent(in) :: p          !< const char*
      character(len=:), allocatable :: s
      character(kind=c_char), pointer :: c(:)
      integer :: k, n
      if (.not. c_associated(p)) then
         s = ''
         return
      end if
      n = int(c_strlen(p))
      call c_f_pointer(p, c, [n])
      allocate (character(len=n) :: s)
      do k = 1, n
         s(k:k) = c(k)
      end do
   end function f_string

   !> The system a handle points to (null: not associated).
   function system_of(h) result(cs)
      type(c_ptr), intent(in) :: h          !< MoorDyn handle
      type(capi_system_t), pointer :: cs
      cs => null()
      if (c_associated(h)) call c_f_pointer(h, cs)
   end function system_of

   !> The item a line or point handle points to.
   function item_of(h) result(it)
      type(c_ptr), intent(in) :: h          !< MoorDynLine or MoorDynPoint
      type(capi_item_t), pointer :: it
      it => null()
      if (c_associated(h)) call c_f_pointer(h, it)
   end function item_of

end module rodyn_capi_handles
