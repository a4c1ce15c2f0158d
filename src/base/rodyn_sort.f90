!> Sorting of short arrays (a few values: table levels, a few eigenvalues).
module rodyn_sort
   use rodyn_kinds, only: wp
   implicit none
   private
   public :: sorted_order

contains

   !> The permutation that sorts x increasingly (insertion sort: a few values; equal
   !> values keep their order).
   pure function sorted_order(x) result(order)
      real(wp), intent(in) :: x(:)     !< values
      integer :: order(size(x))        !< x(order) is increasing
      integer :: i, j, k
      order = [(i, i = 1, size(x))]
      do i = 2, size(x)
         k = order(i)
         j = i - 1
         do while (j >= 1)
            if (x(order(j)) <= x(k)) exit
            order(j + 1) = order(j)
            j = j - 1
         end do
         order(j + 1) = k
      end do
   end function sorted_order
end module rodyn_sort
