!> Memory a run needs, estimated from the deck before anything is allocated, and the
!> physical memory of the machine (docs/deck.md, *LINE; docs/benchmarks.md, Memory). The
!> banded tangent of docs/theory.md eq. (45) dominates.
!>
!> The largest arrays of a run are the banded tangent with its LU fill, n x (3 hb + 1)
!> reals for n unknowns and a half bandwidth hb (rodyn_banded), and per-element and
!> per-node arrays that together take about as much again, plus a fixed part of the
!> program (calibrated with bench/memory_scaling.py; docs/benchmarks.md, Memory). The
!> estimate is 2 n (3 hb + 1) 8 B + 17 MiB: 19.7 KiB a cubic element, 9.8 KiB a
!> quadratic one.
module rodyn_memory
   use, intrinsic :: iso_fortran_env, only: int64
   use rodyn_kinds, only: wp
   use rodyn_model, only: model_t, element_cable
   implicit none
   private
   public :: memory_estimate, memory_physical, memory_text

   real(wp), parameter :: base_bytes = 17.0_wp*1048576.0_wp !< a run of a few elements [B]

contains

   !> Estimated peak memory of a run of the model [B], and the line with most elements.
   pure subroutine memory_estimate(model, bytes, largest)
      type(model_t), intent(in) :: model !< model read from the deck
      real(wp), intent(out) :: bytes     !< estimated peak resident memory [B]
      integer, intent(out) :: largest    !< the line with most elements (0 if none)
      real(wp) :: n
      integer :: l, ndof, hb, most
      n = 0.0_wp
      hb = 0
      most = -1
      largest = 0
      if (.not. allocated(model%lines)) then
         bytes = base_bytes
         return
      end if
      do l = 1, size(model%lines)
         associate (ld => model%lines(l))
            ndof = merge(3, 6, line_all_cable(model, l))
            n = n + real(ndof, wp)*(real(ld%n_elements, wp)*real(ld%order, wp) + 1.0_wp)
            hb = max(hb, (ld%order + 1)*ndof - 1)
            if (ld%n_elements > most) then
               most = ld%n_elements
               largest = l
            end if
         end associate
      end do
      bytes = 2.0_wp*n*real(3*hb + 1, wp)*8.0_wp + base_bytes
   end subroutine memory_estimate

   !> Whether every element of line l is a cable element (3 unknowns a node).
   pure logical function line_all_cable(model, l)
      type(model_t), intent(in) :: model !< model
      integer, intent(in) :: l           !< line index
      associate (ld => model%lines(l))
         if (ld%element /= 0) then
            line_all_cable = ld%element == element_cable
         else if (allocated(ld%seg_section)) then
            line_all_cable = all(model%sections(ld%seg_section)%element == element_cable)
         else if (ld%section > 0) then
            line_all_cable = model%sections(ld%section)%element == element_cable
         else
            line_all_cable = .false.
         end if
      end associate
   end function line_all_cable

   !> Physical memory of the machine [B], from MemTotal in /proc/meminfo; -1 when
   !> unknown (then nothing is refused).
   function memory_physical() result(bytes)
      real(wp) :: bytes !< physical memory [B], or -1
      character(len=256) :: line
      integer(int64) :: kib
      integer :: u, ios
      bytes = -1.0_wp
      open (newunit=u, file='/proc/meminfo', status='old', action='read', iostat=ios)
      if (ios /= 0) return
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (index(line, 'MemTotal:') == 1) then
            read (line(10:), *, iostat=ios) kib
            if (ios == 0 .and. kib > 0) bytes = real(kib, wp)*1024.0_wp
            exit
         end if
      end do
      close (u)
   end function memory_physical

   !> A memory size for a message: '1.5 GiB', '320.0 MiB'.
   pure function memory_text(bytes) result(s)
      real(wp), intent(in) :: bytes      !< size [B]
      character(len=:), allocatable :: s !< the text
      character(len=32) :: buf
      if (bytes >= 1024.0_wp**3) then
         write (buf, '(f0.1,a)') bytes/1024.0_wp**3, ' GiB'
      else
         write (buf, '(f0.1,a)') bytes/1024.0_wp**2, ' MiB'
      end if
      s = trim(buf)
   end function memory_text
end module rodyn_memory
