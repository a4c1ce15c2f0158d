!> The one row formatter of the output tables (static and dynamic CSV, status.txt,
!> environment.csv): fields appended to a row buffer, separated by commas. Integers as
!> '(i0)' writes them; reals with 17 significant digits (they round-trip binary64) as
!> C's printf("%.16E") writes them: 1.2345678901234567E+05, no blanks, an exponent of
!> two digits unless three are needed; non-finite values as Fortran writes them (NaN,
!> Infinity, -Infinity).
!>
!> format_e17 writes the 17 digits without the C library's multi-precision path. For
!> x = m 2^e (m the 53-bit integer significand) and k = floor(log10 |x|), the 17
!> digits are the integer D = round(|x| 10^(16-k)) in [1e16, 1e17), rounded to nearest
!> with ties to even as printf does, computed exactly in 128-bit integers:
!>   16 - k = q >= 0:  D = round(m 5^q 2^(e+q))     (m 5^q < 2^127 for q <= 31)
!>   q < 0:            D = round(m 2^e / 10^(-q))   (m 2^e < 2^127 for e <= 73)
!> k is estimated from log10 and corrected until D falls in [1e16, 1e17). Values outside
!> those ranges (|x| below about 1e-15 or above 1e37, subnormals, Inf, NaN) are left to
!> format_real (format_e17 returns n = 0), which uses C's strfromd (ISO C23, glibc >=
!> 2.25) for the finite ones: about 6 times faster than a Fortran internal write, the
!> same characters as '(es25.16e3)' with a two-digit exponent where it fits. Checked
!> against strfromd and that write: the same characters for every value tested
!> (tests/unit/test_format.pf).
module rodyn_format
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_size_t, c_double, c_null_char
   use rodyn_kinds, only: wp, i8
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: format_e17, format_real, put_text, put_int, put_real, put_reals
   public :: real_text, real_fields, int_text

   integer, parameter :: i16 = selected_int_kind(38)

   !> C's printf format of a real: 17 significant digits, an exponent of at least two.
   character(kind=c_char, len=*), parameter :: real_format = c_char_'%.16E'//c_null_char

   interface
      !> strfromd (ISO C23; glibc >= 2.25): format one double, no varargs.
      function c_strfromd(str, n, format, fp) bind(c, name='strfromd') result(r)
         import :: c_char, c_size_t, c_double, c_int
         character(kind=c_char), intent(out) :: str(*)  !< output, NUL-terminated
         integer(c_size_t), value :: n                  !< room in str, NUL included
         character(kind=c_char), intent(in) :: format(*) !< %E / %f / %g / %a format
         real(c_double), value :: fp                    !< value
         integer(c_int) :: r                            !< characters (without NUL)
      end function c_strfromd
   end interface

   !> Append an integer field (',' first unless the row is empty): default or 64-bit.
   interface put_int
      module procedure put_int4, put_int8
   end interface put_int

   !> An integer as text, as '(i0)' writes it: default or 64-bit.
   interface int_text
      module procedure int_text4, int_text8
   end interface int_text

contains

   !> Write x into buf(1:n) as printf("%.16E") would; n = 0 if x is not handled here.
   pure subroutine format_e17(x, buf, n)
      real(wp), intent(in) :: x               !< value
      character(len=*), intent(inout) :: buf  !< at least 26 characters
      integer, intent(out) :: n               !< characters written (0: not handled)
      real(wp) :: a
      integer(i16) :: d
      integer(int64) :: d8, hi
      integer :: k, ke
      character(len=17) :: dig
      n = 0
      if (len(buf) < 26) return
      if (.not. ieee_is_finite(x)) return
      a = abs(x)
      if (a == 0.0_wp) then
         if (sign(1.0_wp, x) < 0.0_wp) then
            buf(1:23) = '-0.0000000000000000E+00'
            n = 23
         else
            buf(1:22) = '0.0000000000000000E+00'
            n = 22
         end if
         return
      end if
      if (a < 1.0e-15_wp .or. a > 1.0e37_wp) return
      call decimal_digits(a, d, k)
      if (d == 0) return
      ! the 17 digits as 1 + 8 + 8, each group of 8 by pairs from a table (two digits a
      ! division by 100 instead of one a division by 10)
      d8 = int(d, int64)
      hi = d8/100000000_int64
      dig(1:1) = achar(iachar('0') + int(hi/100000000_int64))
      call eight_digits(int(mod(hi, 100000000_int64)), dig(2:9))
      call eight_digits(int(d8 - hi*100000000_int64), dig(10:17))
      if (x < 0.0_wp) then
         n = 1
         buf(1:1) = '-'
      end if
      buf(n + 1:n + 1) = dig(1:1)         ! (substrings, not //: a library call each)
      buf(n + 2:n + 2) = '.'
      buf(n + 3:n + 18) = dig(2:17)
      buf(n + 19:n + 19) = 'E'
      n = n + 19
      if (k < 0) then
         buf(n + 1:n + 1) = '-'
      else
         buf(n + 1:n + 1) = '+'
      end if
      n = n + 1
      ke = abs(k)
      if (ke >= 100) then
         buf(n + 1:n + 1) = achar(iachar('0') + ke/100)
         n = n + 1
      end if
      buf(n + 1:n + 1) = achar(iachar('0') + mod(ke/10, 10))
      buf(n + 2:n + 2) = achar(iachar('0') + mod(ke, 10))
      n = n + 2
   end subroutine format_e17

   !> The 17 significant digits of a (normal, 1e-15 <= a <= 1e37) as the integer d in
   !> [1e16, 1e17) and its decimal exponent k: a = d 10^(k-16), rounded to nearest with
   !> ties to even (module header); d = 0 when a is outside the exact 128-bit ranges.
   pure subroutine decimal_digits(a, d, k)
      real(wp), intent(in) :: a               !< value, > 0
      integer(i16), intent(out) :: d          !< the digits (0: not handled)
      integer, intent(out) :: k               !< floor(log10 a)
      integer(i16) :: m, nn, pw, r, half
      integer(int64) :: bits
      integer :: e, q, s, tries
      integer :: jp
      ! 5^q (q <= 31) and 10^q (q <= 27) as tables: the powers of 128-bit integers are a
      ! library call each
      integer(i16), parameter :: pow5(0:31) = [(5_i16**jp, jp=0, 31)]
      integer(i16), parameter :: pow10(0:27) = [(10_i16**jp, jp=0, 27)]
      integer(i16), parameter :: e16 = 10_i16**16, e17 = 10_i16**17
      ! a = m 2^e exactly, from the bits of the (normal) binary64: 52 stored bits of m
      ! below its leading 1, the biased exponent above them; k from 2^(e+52) <= a, at
      ! most one below floor(log10 a) (the loop corrects it; log10, fraction and scale
      ! are library calls, which this avoids)
      bits = transfer(a, bits)
      m = int(ior(iand(bits, 4503599627370495_int64), 4503599627370496_int64), i16)
      e = int(shiftr(bits, 52)) - 1075
      k = floor(real(e + 52, wp)*0.30102999566398120_wp)
      do tries = 1, 4
         d = 0                                         ! (0 on every return below)
         q = 16 - k
         if (q >= 0) then
            if (q > 31) return
            nn = m*pow5(q)
            s = e + q
            if (s >= 0) then
               if (s > 10) return
               d = shiftl(nn, s)
            else
               if (-s > 120) return
               d = shiftr(nn, -s)                      ! nn / 2^-s, remainder r
               r = nn - shiftl(d, -s)
               half = shiftl(1_i16, -s - 1)
               if (r > half .or. (r == half .and. iand(d, 1_i16) == 1)) d = d + 1
            end if
         else
            if (-q > 27 .or. e < 0 .or. e > 73) return
            nn = shiftl(m, e)
            pw = pow10(-q)
            d = nn/pw
            r = nn - d*pw
            if (2*r > pw .or. (2*r == pw .and. mod(d, 2_i16) == 1)) d = d + 1
         end if
         if (d >= e17) then
            k = k + 1
         else if (d < e16) then
            k = k - 1
         else
            exit
         end if
      end do
      if (d < e16 .or. d >= e17) d = 0
   end subroutine decimal_digits

   !> The 8 decimal digits of v (0 <= v < 10^8, leading zeros kept), two at a time.
   pure subroutine eight_digits(v, s)
      integer, intent(in) :: v              !< value
      character(len=8), intent(out) :: s    !< its digits
      character(len=*), parameter :: pairs = &
         '00010203040506070809101112131415161718192021222324252627282930313233343536373839'// &
         '40414243444546474849505152535455565758596061626364656667686970717273747576777879'// &
         '8081828384858687888990919293949596979899'
      integer :: j, w, t, r
      w = v
      do j = 7, 1, -2
         t = w/100
         r = 2*(w - 100*t)
         s(j:j + 1) = pairs(r + 1:r + 2)
         w = t
      end do
   end subroutine eight_digits

   !> Write x at row(n+1:) in the format of the module header; row needs 26 free
   !> characters.
   subroutine format_real(x, row, n)
      real(wp), intent(in) :: x               !< value
      character(len=*), intent(inout) :: row  !< row being built
      integer, intent(inout) :: n             !< characters used
      character(len=32) :: buf
      integer :: k
      call format_e17(x, row(n + 1:), k)     ! the same characters, faster
      if (k > 0) then
         n = n + k
         return
      end if
      if (ieee_is_finite(x)) then
         k = c_strfromd(row(n + 1:), int(len(row) - n, c_size_t), real_format, &
            real(x, c_double))
         n = n + min(k, len(row) - n - 1)
      else
         write (buf, '(es25.16e3)') x
         call put_text(row, n, trim(adjustl(buf)))
      end if
   end subroutine format_real

   !> Append text at row(n+1:).
   pure subroutine put_text(row, n, text)
      character(len=*), intent(inout) :: row  !< row being built
      integer, intent(inout) :: n             !< characters used
      character(len=*), intent(in) :: text    !< text to append
      row(n + 1:n + len(text)) = text
      n = n + len(text)
   end subroutine put_text

   !> Append an integer field (',' first unless the row is empty).
   pure subroutine put_int4(row, n, i)
      character(len=*), intent(inout) :: row  !< row being built
      integer, intent(inout) :: n             !< characters used
      integer, intent(in) :: i                !< value
      call put_int8(row, n, int(i, i8))
   end subroutine put_int4

   !> Append a 64-bit integer field (',' first unless the row is empty), as '(i0)'
   !> writes it (digits by hand: an internal write costs ~2 us, as much as a whole row).
   pure subroutine put_int8(row, n, i)
      character(len=*), intent(inout) :: row  !< row being built
      integer, intent(inout) :: n             !< characters used
      integer(i8), intent(in) :: i            !< value
      character(len=20) :: buf
      integer :: k
      if (n > 0) call put_text(row, n, ',')
      call int_digits(i, buf, k)
      call put_text(row, n, buf(k:))
   end subroutine put_int8

   !> The digits of i as '(i0)' writes them, at the end of buf: buf(k:).
   pure subroutine int_digits(i, buf, k)
      integer(i8), intent(in) :: i               !< value
      character(len=20), intent(out) :: buf      !< the digits at its end
      integer, intent(out) :: k                  !< where they start
      integer(i8) :: v
      k = len(buf) + 1
      v = i
      do                                     ! digits of |i| (negative v: no overflow)
         k = k - 1
         buf(k:k) = achar(iachar('0') + int(abs(mod(v, 10_i8))))
         v = v/10_i8
         if (v == 0_i8) exit
      end do
      if (i < 0) then
         k = k - 1
         buf(k:k) = '-'
      end if
   end subroutine int_digits

   !> Append a real field (',' first unless the row is empty).
   subroutine put_real(row, n, x)
      character(len=*), intent(inout) :: row  !< row being built
      integer, intent(inout) :: n             !< characters used
      real(wp), intent(in) :: x               !< value
      if (n > 0) call put_text(row, n, ',')
      call format_real(x, row, n)
   end subroutine put_real

   !> Append real fields, each preceded by ','.
   subroutine put_reals(row, n, x)
      character(len=*), intent(inout) :: row  !< row being built
      integer, intent(inout) :: n             !< characters used (> 0)
      real(wp), intent(in) :: x(:)            !< values
      integer :: k
      do k = 1, size(x)
         call put_text(row, n, ',')
         call format_real(x(k), row, n)
      end do
   end subroutine put_reals

   !> A real as text (format_real).
   function real_text(x) result(s)
      real(wp), intent(in) :: x             !< value
      character(len=:), allocatable :: s    !< text
      s = real_fields([x])
      s = s(2:)
   end function real_text

   !> Real fields as text, each preceded by ',' (put_reals).
   function real_fields(x) result(s)
      real(wp), intent(in) :: x(:)          !< values
      character(len=:), allocatable :: s    !< ',x(1),x(2),...'
      character(len=32*size(x)) :: buf
      integer :: n
      n = 0
      call put_reals(buf, n, x)
      s = buf(:n)
   end function real_fields

   !> An integer as text.
   pure function int_text4(i) result(s)
      integer, intent(in) :: i              !< value
      character(len=:), allocatable :: s    !< text
      s = int_text8(int(i, i8))
   end function int_text4

   !> A 64-bit integer as text.
   pure function int_text8(i) result(s)
      integer(i8), intent(in) :: i          !< value
      character(len=:), allocatable :: s    !< text
      character(len=20) :: buf
      integer :: k
      call int_digits(i, buf, k)
      s = buf(k:)
   end function int_text8
end module rodyn_format
