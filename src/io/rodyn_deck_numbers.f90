!> Deck lexer, numbers: a real or an integer read from the text of a deck (parse_real,
!> parse_int: the syntax of docs/deck.md, refused rather than guessed), the fields of a
!> line read as reals with messages that name each value (fields_reals, field_real),
!> and numbers written for messages (real_str: the shortest text that reads back as the
!> same double; int_str).
module rodyn_deck_numbers
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
   use rodyn_kinds, only: wp, i8
   use rodyn_deck_text, only: field_t, item_of, is_digit
   use rodyn_deck_params, only: shortest_text, int_str
   implicit none
   private
   public :: parse_real, parse_int, real_str, int_str, fields_reals, field_real

   integer, parameter :: max_exponent10 = 100   !< numbers are below 10**max_exponent10
   integer, parameter :: min_exponent10 = -100  !< non-zero numbers are at least 10**min_..

contains

   !> Parse a real written Fortran/C style: [sign] digits [. digits] [e|E|d|D [sign]
   !> digits], at least one digit in the mantissa. Anything else (nan, inf, 1.2.3, ...)
   !> is refused, and so is a magnitude outside [1e-100, 1e100) other than zero (so that
   !> products of a few input values cannot overflow). The token is checked character by
   !> character before it is converted, so that bad text cannot raise a floating-point
   !> exception.
   subroutine parse_real(token, value, msg)
      character(len=*), intent(in) :: token           !< text to convert, trimmed
      real(wp), intent(out) :: value                  !< the number
      character(len=:), allocatable, intent(out) :: msg !< '' on success, else why not
      integer :: n, p, n_int, n_frac, lead, ios
      integer(i8) :: e_val, e_sign, mag
      logical :: nonzero

      value = 0.0_wp
      msg = ''
      n = len(token)
      p = 1
      if (n > 0) then
         if (token(1:1) == '+' .or. token(1:1) == '-') p = 2
      end if
      n_int = 0
      n_frac = 0
      lead = 0            ! decimal exponent of the first non-zero digit (before e)
      nonzero = .false.
      do while (p <= n)
         if (.not. is_digit(token(p:p))) exit
         if (.not. nonzero .and. token(p:p) /= '0') then
            nonzero = .true.
            lead = -n_int    ! fixed below once the number of integer digits is known
         end if
         n_int = n_int + 1
         p = p + 1
      end do
      if (nonzero) lead = lead + n_int - 1
      if (p <= n) then
         if (token(p:p) == '.') then
            p = p + 1
            do while (p <= n)
               if (.not. is_digit(token(p:p))) exit
               n_frac = n_frac + 1
               if (.not. nonzero .and. token(p:p) /= '0') then
                  nonzero = .true.
                  lead = -n_frac
               end if
               p = p + 1
            end do
         end if
      end if
      if (n_int + n_frac == 0) then
         msg = "'"//token//"' is not a number"
         return
      end if
      e_val = 0
      e_sign = 1
      if (p <= n) then
         if (index('eEdD', token(p:p)) > 0) then
            p = p + 1
            if (p <= n) then
               if (token(p:p) == '+' .or. token(p:p) == '-') then
                  if (token(p:p) == '-') e_sign = -1
                  p = p + 1
               end if
            end if
            if (p > n) then
               msg = "'"//token//"' is not a number"
               return
            end if
            do while (p <= n)
               if (.not. is_digit(token(p:p))) exit
               if (e_val < 100000_i8) e_val = 10_i8*e_val + (iachar(token(p:p)) - iachar('0'))
               p = p + 1
            end do
         end if
      end if
      if (p /= n + 1) then
         msg = "'"//token//"' is not a number"
         return
      end if
      if (nonzero) then
         mag = lead + e_sign*e_val
         if (mag >= max_exponent10 .or. mag < min_exponent10) then
            msg = "'"//token//"' is out of range: its magnitude must be between 1e"// &
                  int_str(min_exponent10)//' and 1e'//int_str(max_exponent10)//' (or zero)'
            return
         end if
      end if
      read (token, *, iostat=ios) value
      if (ios /= 0) then
         value = 0.0_wp
         msg = "'"//token//"' is not a number"
      end if
   end subroutine parse_real

   !> Parse an integer: [sign] digits, nothing else ('10.5', '1e3' refused).
   subroutine parse_int(token, value, msg)
      character(len=*), intent(in) :: token           !< text to convert, trimmed
      integer, intent(out) :: value                   !< the number
      character(len=:), allocatable, intent(out) :: msg !< '' on success, else why not
      integer :: p, ios
      integer(i8) :: v8

      value = 0
      msg = ''
      p = 1
      if (len(token) > 0) then
         if (token(1:1) == '+' .or. token(1:1) == '-') p = 2
      end if
      if (p > len(token)) then
         msg = "'"//token//"' is not an integer"
         return
      end if
      if (verify(token(p:), '0123456789') /= 0) then
         msg = "'"//token//"' is not an integer"
         return
      end if
      if (len(token(p:)) - (verify(token(p:), '0') - 1) > 18 .and. &
          verify(token(p:), '0') > 0) then
         msg = "'"//token//"' is out of range"
         return
      end if
      read (token, *, iostat=ios) v8
      if (ios /= 0 .or. abs(v8) > int(huge(value), i8)) then
         msg = "'"//token//"' is out of range"
         return
      end if
      value = int(v8)
   end subroutine parse_int

   !> Shortest text that reads back as x exactly: '10', '9.5', '0.001', '7.96e8'.
   function real_str(x) result(s)
      real(wp), intent(in) :: x           !< the number
      character(len=:), allocatable :: s  !< its text
      if (ieee_is_nan(x)) then      ! not produced by the reader, but be safe
         s = 'NaN'
         return
      end if
      if (.not. ieee_is_finite(x)) then
         s = 'Infinity'
         if (x < 0.0_wp) s = '-'//s
         return
      end if
      if (abs(x) < tiny(x)) then
         s = '0'
         return
      end if
      s = shortest_text(x, 7, 1.0e300_wp)
   end function real_str

   !> Parse fields as exactly size(values) reals. msg = '' on success, else what is
   !> wrong, naming the value by `what` (comma-separated names) and position.
   subroutine fields_reals(fields, values, what, msg)
      type(field_t), intent(in) :: fields(:)          !< the values as text
      real(wp), intent(out) :: values(:)              !< the numbers
      character(len=*), intent(in) :: what            !< names of the values ('' if none)
      character(len=:), allocatable, intent(out) :: msg !< '' or the problem
      integer :: k, n, nf

      values = 0.0_wp
      msg = ''
      n = size(values)
      nf = size(fields)
      if (nf /= n) then
         msg = 'expected '//int_str(n)//' value'
         if (n /= 1) msg = msg//'s'
         msg = msg//', got '//int_str(nf)
         if (len(what) > 0) msg = msg//' ('//what//')'
         return
      end if
      do k = 1, n
         call field_real(fields(k)%s, k, n, what, values(k), msg)
         if (len(msg) > 0) return
      end do
   end subroutine fields_reals

   !> Parse value k of n of a line as a real; msg = '' or the problem, ending with a
   !> label '(NAME, value k of n)' (NAME the k-th item of `what`).
   subroutine field_real(f, k, n, what, value, msg)
      character(len=*), intent(in) :: f               !< the value as text, trimmed
      integer, intent(in) :: k                        !< its position on the line
      integer, intent(in) :: n                        !< number of values of the line
      character(len=*), intent(in) :: what            !< names of the values ('' if none)
      real(wp), intent(out) :: value                  !< the number
      character(len=:), allocatable, intent(out) :: msg !< '' or the problem

      value = 0.0_wp
      if (len(f) == 0) then
         msg = 'empty value '//label()
         return
      end if
      call parse_real(f, value, msg)
      ! (the label is formed only for a message: formed for every value, it took two
      ! thirds of the instructions of reading a table of 12 400 rows)
      if (len(msg) > 0) msg = msg//' '//label()
   contains
      function label() result(s)
         character(len=:), allocatable :: s
         s = item_of(what, k)
         if (len(s) > 0) s = s//', '
         s = '('//s//'value '//int_str(k)//' of '//int_str(n)//')'
      end function label
   end subroutine field_real

end module rodyn_deck_numbers
