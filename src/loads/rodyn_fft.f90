!> Discrete Fourier transform of a real record of any length n (docs/waves.md, the wave
!> record): X_k = sum_{m=0}^{n-1} x_m exp(-2 pi i k m/n), k = 0..n-1, by an iterative
!> radix-2 FFT (Cooley & Tukey 1965) when n is a power of two, and otherwise by
!> Bluestein's chirp z-transform (Bluestein 1970; Rabiner, Schafer & Rader 1969):
!> k m = (k^2 + m^2 - (k - m)^2)/2 turns the transform into a circular convolution of
!> the chirped record with the chirp conj(c), c_m = exp(-i pi m^2/n), done by radix-2
!> FFTs of a power of two >= 2n - 1. The chirp's angle is reduced exactly in integers
!> (m^2 mod 2n) before the cosine, so that it keeps its digits for long records. Every
!> twiddle factor is a cosine and sine of its own (no recurrence). O(n log n); the error
!> is a few eps log2 n of sum |x|.
!> It gives the components of an elevation record, docs/theory.md eq. (93).
module rodyn_fft
   use rodyn_kinds, only: wp, i8, pi, two_pi
   implicit none
   private
   public :: dft_real

contains

   !> X = DFT(x) (module header) of a real record x(0:n-1).
   pure subroutine dft_real(x, xk)
      real(wp), intent(in) :: x(0:)        !< the record [any unit]
      complex(wp), intent(out) :: xk(0:)   !< (0:n-1) its transform [unit of x]
      complex(wp), allocatable :: a(:), b(:), c(:)
      integer :: n, m, j
      n = size(x)
      if (n == 0) return
      if (iand(n, n - 1) == 0) then
         xk = cmplx(x, 0.0_wp, wp)
         call fft_pow2(xk, .false.)
         return
      end if
      m = 1
      do while (m < 2*n - 1)
         m = 2*m
      end do
      allocate (a(0:m - 1), b(0:m - 1), c(0:n - 1))
      do j = 0, n - 1
         c(j) = chirp(j, n)
      end do
      a = (0.0_wp, 0.0_wp)
      b = (0.0_wp, 0.0_wp)
      a(0:n - 1) = x*c
      b(0:n - 1) = conjg(c)
      do j = 1, n - 1
         b(m - j) = conjg(c(j))
      end do
      call fft_pow2(a, .false.)
      call fft_pow2(b, .false.)
      a = a*b
      call fft_pow2(a, .true.)
      xk = c*a(0:n - 1)/real(m, wp)
   end subroutine dft_real

   !> exp(-i pi j^2/n), the angle reduced modulo 2 pi in integers.
   pure complex(wp) function chirp(j, n)
      integer, intent(in) :: j  !< index, >= 0
      integer, intent(in) :: n  !< record length
      real(wp) :: ang
      ang = pi*real(modulo(int(j, i8)*int(j, i8), 2_i8*int(n, i8)), wp)/real(n, wp)
      chirp = cmplx(cos(ang), -sin(ang), wp)
   end function chirp

   !> In-place radix-2 FFT of z (length a power of two): sum z_m exp(-+2 pi i k m/n),
   !> the sign + for the inverse (unscaled).
   pure subroutine fft_pow2(z, inverse)
      complex(wp), intent(inout) :: z(0:) !< data, then its transform
      logical, intent(in) :: inverse      !< exp(+2 pi i k m/n) (no 1/n)
      complex(wp) :: t, w
      real(wp) :: sgn, ang
      integer :: n, i, j, k, len, half
      n = size(z)
      ! bit-reversal permutation
      j = 0
      do i = 0, n - 2
         if (i < j) then
            t = z(i)
            z(i) = z(j)
            z(j) = t
         end if
         k = n/2
         do while (k >= 1 .and. j >= k)
            j = j - k
            k = k/2
         end do
         j = j + k
      end do
      sgn = merge(1.0_wp, -1.0_wp, inverse)
      len = 2
      do while (len <= n)
         half = len/2
         do k = 0, half - 1
            ang = sgn*two_pi*real(k, wp)/real(len, wp)
            w = cmplx(cos(ang), sin(ang), wp)
            do i = 0, n - 1, len
               t = w*z(i + k + half)
               z(i + k + half) = z(i + k) - t
               z(i + k) = z(i + k) + t
            end do
         end do
         len = 2*len
      end do
   end subroutine fft_pow2
end module rodyn_fft
