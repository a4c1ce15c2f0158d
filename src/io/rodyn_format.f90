!> Text of a real for the tables: 17 significant digits, as C's printf("%.16E") writes
!> them (1.2345678901234567E+05; at least two exponent digits), the same characters,
!> without the C library's multi-precision path.
!>
!> For x = m 2^e (m the 53-bit integer significand) and k = floor(log10 |x|), the 17
!> digits are the integer D = round(|x| 10^(16-k)) in [1e16, 1e17), rounded to nearest
!> with ties to even as printf does, computed exactly in 128-bit integers:
!>   16 - k = q >= 0:  D = round(m 5^q 2^(e+q))     (m 5^q < 2^127 for q <= 31)
!>   q < 0:            D = round(m 2^e / 10^(-q))   (m 2^e < 2^127 for e <= 73)
!> k is estimated from log10 and corrected until D falls in [1e16, 1e17). Values outside
!> those ranges (|x| below about 1e-15 or above 1e37, subnormals, Inf, NaN) are left to
!> the caller (format_e17 returns n = 0), which uses the C library. Measured against
!> strfromd: the same characters for every value tested (tests/unit/test_output.pf).
module rodyn_format
   use, intrinsic :: iso_fortran_env, only: int64
   use rodyn_kinds, only: wp
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: format_e17

   integer, parameter :: i16 = selected_int_kind(38)

contains

   !> Write x into buf(1:n) as printf("%.16E") would; n = 0 if x is not handled here.
   pure subroutine format_e17(x, buf, n)
      real(wp), intent(in) :: x               !< value
      character(len=*), intent(inout) :: buf  !< at least 26 characters
      integer, intent(out) :: n               !< characters written (0: not handled)
      real(wp) :: a
      integer(i16) :: m, d, nn, pw, r, half
      integer(int64) :: d8
      integer :: e, k, q, s, tries, j, ke
      character(len=17) :: dig
      integer :: jp
      ! 5^q (q <= 31) and 10^q (q <= 27) as tables: the powers of 128-bit integers were a
      ! library call each (mooring surge deck: 1.2 % of a run's instructions)
      integer(i16), parameter :: pow5(0:31) = [(5_i16**jp, jp=0, 31)]
      integer(i16), parameter :: pow10(0:27) = [(10_i16**jp, jp=0, 27)]
      integer(i16), parameter :: e16 = 10_i16**16, e17 = 10_i16**17
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
      m = int(scale(fraction(a), digits(a)), i16)       ! a = m 2^e exactly
      e = exponent(a) - digits(a)
      k = floor(log10(a))
      d = 0
      do tries = 1, 4
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
      if (d < e16 .or. d >= e17) return
      d8 = int(d, int64)
      do j = 17, 1, -1
         dig(j:j) = achar(iachar('0') + int(mod(d8, 10_int64)))
         d8 = d8/10_int64
      end do
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
end module rodyn_format
