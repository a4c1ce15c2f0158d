!> The roll gauges of rod lines that can roll freely (docs/theory.md eq. (111)): a small
!> torsional spring at the middle node of each such run of rod elements, found once
!> (roll_gauges) and added to the tangent (add_roll_gauges), so that the statics' and a
!> roll-free dynamics' tangent is not singular about the lines' own axes.
module rodyn_roll_gauges
   use rodyn_kinds, only: wp
   use rodyn_mesh, only: mesh_t
   use rodyn_banded, only: banded_t
   use rodyn_assembly, only: supports_t, loads_t, add_node_block
   implicit none
   private
   public :: roll_gauges, add_roll_gauges

contains

   !> The roll gauges (rodyn_statics, module header): for each run of consecutive rod
   !> elements of a line that can roll freely, its middle node and stiffness; node 0 after
   !> the last. With roll_inertia (dynamics: (nn) the inertia of a node's roll, that of
   !> its d1 and d2), a run whose nodes have any is not free: its roll has inertia.
   !> docs/theory.md eq. (111).
   subroutine roll_gauges(mesh, sup, loads, gauge_node, gauge_k, roll_inertia)
      type(mesh_t), intent(in) :: mesh              !< mesh
      type(supports_t), intent(in) :: sup           !< supports
      type(loads_t), intent(in) :: loads            !< point loads
      integer, allocatable, intent(out) :: gauge_node(:) !< (ne) node per run, 0: none
      real(wp), allocatable, intent(out) :: gauge_k(:)   !< (ne) stiffness [N m/rad]
      real(wp), intent(in), optional :: roll_inertia(:)  !< (nn) [kg m2]
      integer :: e, e1, e2, em, i, nr
      logical :: free
      allocate (gauge_node(mesh%n_elements), gauge_k(mesh%n_elements))
      gauge_node = 0
      gauge_k = 0.0_wp
      nr = 0
      ! each run of consecutive rod elements of one line (cable elements have no roll)
      e1 = 1
      do while (e1 <= mesh%n_elements)
         if (mesh%elem_cable(e1)) then
            e1 = e1 + 1
            cycle
         end if
         e2 = e1
         do while (e2 < mesh%n_elements)
            if (mesh%elem_line(e2 + 1) /= mesh%elem_line(e1) .or. mesh%elem_cable(e2 + 1)) exit
            e2 = e2 + 1
         end do
         free = .true.
         do e = e1, e2
            associate (c => mesh%elem_c(:, e), &
                       nodes => mesh%elem_nodes(1:mesh%line_order(mesh%elem_line(e)) + 1, e))
               if (c(1) /= c(2) .or. c(4) /= c(5)) free = .false.
               do i = 1, size(nodes)
                  if (any(sup%held(4:6, nodes(i))) .or. sup%rotated(nodes(i))) free = .false.
                  if (present(roll_inertia)) then
                     if (roll_inertia(nodes(i)) > 0.0_wp) free = .false.
                  end if
                  if (any(loads%pt_node == nodes(i) .and. &
                          any(loads%pt_fm(4:6, :) /= 0.0_wp, dim=1))) free = .false.
               end do
            end associate
         end do
         if (free) then
            nr = nr + 1
            em = (e1 + e2)/2
            gauge_node(nr) = mesh%elem_nodes(1, em)
            gauge_k(nr) = maxval(mesh%elem_c(4:6, em))/mesh%elem_le(em)
         end if
         e1 = e2 + 1
      end do
   end subroutine roll_gauges

   !> Add each roll gauge's k_g d3 d3^T to the rotation block of its node (d3 of the
   !> configuration the matrix is formed at); the residual is not touched.
   !> docs/theory.md eq. (111).
   subroutine add_roll_gauges(sup, gauge_node, gauge_k, d, bm)
      type(supports_t), intent(in) :: sup      !< supports (dof map, node bases)
      integer, intent(in) :: gauge_node(:)     !< node of each gauge, 0 after the last
      real(wp), intent(in) :: gauge_k(:)       !< their stiffness [N m/rad]
      real(wp), intent(in) :: d(:, :, :)       !< (3, 3, nn) directors
      type(banded_t), intent(inout) :: bm      !< matrix
      real(wp) :: kb(6, 6), d3(3)
      integer :: l, i, node
      do l = 1, size(gauge_node)
         node = gauge_node(l)
         if (node == 0) exit
         d3 = d(:, 3, node)
         kb = 0.0_wp
         do i = 1, 3
            kb(4:6, 3 + i) = gauge_k(l)*d3*d3(i)
         end do
         call add_node_block(sup, node, kb, bm)
      end do
   end subroutine add_roll_gauges
end module rodyn_roll_gauges
