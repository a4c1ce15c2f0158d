!> The configuration the solvers advance: nodal positions and directors, and their
!> rates (docs/theory.md eqs. (32)-(33), (58); docs/architecture.md, the state).
module rodyn_state
   use rodyn_kinds, only: wp
   implicit none
   private
   public :: state_t, state_allocate, state_copy, state_gather, copy_values

   !> Configuration and velocities of all nodes.
   type :: state_t
      real(wp), allocatable :: x(:, :)     !< (3, nn) positions [m]
      real(wp), allocatable :: d(:, :, :)  !< (3, 3, nn) directors d(:, i, a) [-]
      real(wp), allocatable :: v(:, :)     !< (3, nn) velocities [m/s]
      real(wp), allocatable :: dd(:, :, :) !< (3, 3, nn) director velocities [1/s]
      !> (3, nn) accelerations [m/s2] and (3, 3, nn) director accelerations [1/s2]: the
      !> generalized-alpha scheme's; (3, 0) and (3, 3, 0) for the others (state_allocate)
      real(wp), allocatable :: a(:, :)
      real(wp), allocatable :: ad(:, :, :)
   end type state_t

contains

   !> Allocate a state for nn nodes; the accelerations only if asked (the
   !> generalized-alpha scheme; the others never read them: 0.58 KiB a cubic element
   !> for the two states of a step, bench/memory_scaling.py).
   subroutine state_allocate(state, nn, accelerations)
      type(state_t), intent(inout) :: state      !< state to allocate
      integer, intent(in) :: nn                  !< number of nodes
      logical, intent(in), optional :: accelerations !< allocate a and ad (default no)
      integer :: na
      na = 0
      if (present(accelerations)) then
         if (accelerations) na = nn
      end if
      if (allocated(state%x)) deallocate (state%x, state%d, state%v, state%dd, state%a, &
                                          state%ad)
      allocate (state%x(3, nn), state%d(3, 3, nn), state%v(3, nn), state%dd(3, 3, nn), &
                state%a(3, na), state%ad(3, 3, na))
      state%a = 0.0_wp
      state%ad = 0.0_wp
      state%x = 0.0_wp
      state%d = 0.0_wp
      state%v = 0.0_wp
      state%dd = 0.0_wp
   end subroutine state_allocate

   !> dst = src, field by field: copied into dst's arrays when they have src's sizes (every
   !> step), otherwise (re)allocated by assignment (a state not yet allocated).
   subroutine state_copy(src, dst)
      type(state_t), intent(in) :: src    !< state copied
      type(state_t), intent(inout) :: dst !< overwritten
      logical :: fits
      fits = allocated(dst%x) .and. allocated(dst%d) .and. allocated(dst%v) .and. &
             allocated(dst%dd) .and. allocated(dst%a) .and. allocated(dst%ad)
      if (fits) fits = size(dst%x) == size(src%x) .and. size(dst%d) == size(src%d) .and. &
                       size(dst%v) == size(src%v) .and. size(dst%dd) == size(src%dd) .and. &
                       size(dst%a) == size(src%a) .and. size(dst%ad) == size(src%ad)
      if (.not. fits) then               ! (re)allocated by the assignments
         dst%x = src%x
         dst%d = src%d
         dst%v = src%v
         dst%dd = src%dd
         dst%a = src%a
         dst%ad = src%ad
         return
      end if
      ! the same shapes (every step): copied as plain sequences, without the assignments'
      ! shape checks
      call copy_values(size(src%x), src%x, dst%x)
      call copy_values(size(src%d), src%d, dst%d)
      call copy_values(size(src%v), src%v, dst%v)
      call copy_values(size(src%dd), src%dd, dst%dd)
      call copy_values(size(src%a), src%a, dst%a)
      call copy_values(size(src%ad), src%ad, dst%ad)
   end subroutine state_copy

   !> b = a over n values. Explicit shapes tell the compiler that a and b do not overlap:
   !> allocatable components (of a state, of a problem) assigned whole are copied one
   !> value at a time, these in vector moves.
   pure subroutine copy_values(n, a, b)
      integer, intent(in) :: n      !< values
      real(wp), intent(in) :: a(n)  !< source
      real(wp), intent(out) :: b(n) !< copy
      b = a
   end subroutine copy_values

   !> Positions and directors of an element's nodes.
   pure subroutine state_gather(state, nodes, xe, de)
      type(state_t), intent(in) :: state     !< configuration
      integer, intent(in) :: nodes(:)        !< (nen) global nodes of the element
      real(wp), intent(inout) :: xe(:, :)    !< (3, >= nen) positions [m]
      real(wp), intent(inout) :: de(:, :, :) !< (3, 3, >= nen) directors
      integer :: a, node, i, j
      ! (value by value: cheaper than section assignments for 3 and 9 values)
      do a = 1, size(nodes)
         node = nodes(a)
         do i = 1, 3
            xe(i, a) = state%x(i, node)
         end do
         do j = 1, 3
            do i = 1, 3
               de(i, j, a) = state%d(i, j, node)
            end do
         end do
      end do
   end subroutine state_gather
end module rodyn_state
