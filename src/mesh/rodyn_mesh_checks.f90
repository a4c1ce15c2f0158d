!> Checks of a mesh's configuration and advice on its elements: the spurious shape of a
!> cubic rod element under selective quadrature (mesh_spurious_shape, refused by statics
!> and dynamics), rods that would be better as cables (mesh_cable_like_rods), and the
!> numbers of the messages (fix_leading_dots; docs/element.md, "Known limits").
module rodyn_mesh_checks
   use rodyn_kinds, only: wp
   use rodyn_model, only: model_t
   use rodyn_state, only: state_t
   use rodyn_rod_element, only: max_points, rod_hidden_shear
   use rodyn_shape, only: max_nen
   use rodyn_mesh, only: mesh_t, line_mean_weight
   implicit none
   private
   public :: mesh_spurious_shape, fix_leading_dots, mesh_cable_like_rods

   !> EI / (T_ref l_e^2) below which a rod line's bending stiffness is negligible: a
   !> bending length sqrt(EI/T_ref) under a hundredth of the element (line_bending_ratio)
   real(wp), parameter :: ratio_min = 1.0e-4_wp

contains

   !> A configuration refused when an element of order 3 of a rod line has taken the
   !> spurious shape of its selective quadrature (rod_hidden_shear): shear strain above
   !> hidden_max at its extension points and more than ten times the largest at its shear
   !> points. Such a shape zig-zags at touch-down, and a run that reaches it reads a far
   !> too low fairlead tension (a chain of small EI as cubic rods: docs/element.md,
   !> "Known limits"; tests/program/surge_rod_static.inp).
   !> Returns the reason (empty: none). Statics checks its solution, dynamics each frame.
   function mesh_spurious_shape(model, mesh, state) result(why)
      type(model_t), intent(in) :: model   !< model (line names)
      type(mesh_t), intent(in) :: mesh     !< mesh
      type(state_t), intent(in) :: state   !< configuration
      character(len=:), allocatable :: why
      real(wp), parameter :: hidden_max = 0.05_wp  ! shear strain no line carries [-]
      real(wp) :: xe(3, 4), de(3, 3, 4), hidden, seen
      integer :: e, l, a, node
      character(len=200) :: msg
      why = ''
      do e = 1, mesh%n_elements
         l = mesh%elem_line(e)
         if (mesh%line_order(l) /= 3 .or. mesh%elem_cable(e)) cycle
         do a = 1, 4
            node = mesh%elem_nodes(a, e)
            xe(:, a) = state%x(:, node)
            de(:, :, a) = state%d(:, :, node)
         end do
         call rod_hidden_shear(3, mesh%elem_le(e), xe, de, mesh%eps0(:, :, e), hidden_max, &
                               hidden, seen, mesh%rules(3))
         if (hidden <= hidden_max .or. hidden <= 10.0_wp*seen) cycle
         write (msg, '(a,i0,a,f0.2,a,f0.2,a,es8.2,a,es8.2,a)') 'element ', &
            e - mesh%line_first_elem(l) + 1, ' (S = ', mesh%elem_s0(e), ' to ', &
            mesh%elem_s0(e) + mesh%elem_le(e), ' m) has taken a spurious shape: shear'// &
            ' strain ', hidden, ' between its shear points, ', seen, ' at them'
         why = 'line '//trim(model%lines(l)%name)//', '//fix_leading_dots(trim(msg))// &
               ' (a mode of cubic rod elements that only the bending stiffness holds '// &
               'against, docs/element.md, "Known limits"; '//spurious_cause(model, mesh, l)//')'
         return
      end do
   end function mesh_spurious_shape

   !> Why a spurious shape formed on rod line l: its bending stiffness negligible
   !> (line_bending_ratio below ratio_min: a cable as rods), else loads that deform it
   !> faster or more sharply than its elements resolve.
   function spurious_cause(model, mesh, l) result(cause)
      type(model_t), intent(in) :: model     !< model
      type(mesh_t), intent(in) :: mesh       !< mesh
      integer, intent(in) :: l               !< line index
      character(len=:), allocatable :: cause !< the cause, as advice
      real(wp) :: ratio
      ratio = line_bending_ratio(model, mesh, l)
      if (ratio < ratio_min) then
         cause = 'its bending stiffness is negligible, '//ratio_text(ratio)// &
                 ': a chain, wire or rope wants ELEMENT=CABLE on its *LINE'
      else if (ratio < huge(1.0_wp)) then
         cause = 'its bending stiffness is not negligible, '//ratio_text(ratio)// &
                 ': loads bent or sheared it far more sharply than its elements resolve;'// &
                 ' check the motions, *DAMPING and drag for violent or absurd values, or'// &
                 ' use another element count'
      else
         cause = 'loads bent or sheared it far more sharply than its elements resolve;'// &
                 ' check the motions, *DAMPING and drag for violent or absurd values, or'// &
                 ' use another element count'
      end if
   end function spurious_cause

   !> A hint for a failed statics: the first line of rod elements whose bending stiffness
   !> is negligible (line_bending_ratio below ratio_min). Such a line is a cable (chain,
   !> wire, fibre rope): as rods its stiffness matrix is near singular in bending.
   !> Returns '' when every line is fine.
   function mesh_cable_like_rods(model, mesh) result(hint)
      type(model_t), intent(in) :: model    !< model (lines, water, gravity)
      type(mesh_t), intent(in) :: mesh      !< mesh (element stiffness and lengths)
      character(len=:), allocatable :: hint !< '' or the hint
      real(wp) :: ratio
      integer :: l
      hint = ''
      do l = 1, size(model%lines)
         ratio = line_bending_ratio(model, mesh, l)
         if (ratio >= ratio_min) cycle
         hint = 'line '//trim(model%lines(l)%name)//' is made of rod elements whose '// &
                'bending stiffness is negligible ('//ratio_text(ratio)//'): a chain, '// &
                'wire or rope wants ELEMENT=CABLE on its *LINE (docs/element.md)'
         return
      end do
   end function mesh_cable_like_rods

   !> The smallest EI / (T_ref l_e^2) over the rod elements of line l (a bending length
   !> sqrt(EI/T_ref) against the element length, squared), T_ref = |w| L the line's
   !> weight (in water when wet); huge() for a weightless line or one of cable elements.
   function line_bending_ratio(model, mesh, l) result(worst)
      type(model_t), intent(in) :: model  !< model (lines, water, gravity)
      type(mesh_t), intent(in) :: mesh    !< mesh (element stiffness and lengths)
      integer, intent(in) :: l            !< line index
      real(wp) :: worst                   !< the ratio [-]
      real(wp) :: w, ea, tref
      integer :: e
      worst = huge(1.0_wp)
      call line_mean_weight(model, mesh, l, w, ea)
      tref = abs(w)*model%lines(l)%length
      if (.not. tref > 0.0_wp) return
      do e = mesh%line_first_elem(l), mesh%line_first_elem(l) + model%lines(l)%n_elements - 1
         if (mesh%elem_cable(e)) cycle
         worst = min(worst, min(mesh%elem_c(4, e), mesh%elem_c(5, e))/(tref*mesh%elem_le(e)**2))
      end do
   end function line_bending_ratio

   !> 'EI / (weight x length x element length^2) down to R' for a bending ratio R.
   function ratio_text(ratio) result(s)
      real(wp), intent(in) :: ratio       !< line_bending_ratio
      character(len=:), allocatable :: s  !< the text
      character(len=16) :: buf
      write (buf, '(es8.1)') ratio
      s = 'EI / (weight x length x element length^2) down to '//trim(adjustl(buf))
   end function ratio_text

   !> The text with a 0 before every '.' that follows a blank or '(' or '-' (f0.d writes
   !> 0.25 as '.25').
   pure function fix_leading_dots(text) result(out)
      character(len=*), intent(in) :: text   !< text with numbers written by f0.d
      character(len=:), allocatable :: out   !< the numbers with their leading zero
      integer :: k
      out = ''
      do k = 1, len(text)
         if (text(k:k) == '.' .and. k < len(text)) then
            if (scan(text(k + 1:k + 1), '0123456789') == 1) then
               if (k == 1) then
                  out = out//'0'
               else if (scan(text(k - 1:k - 1), ' (-=') == 1) then
                  out = out//'0'
               end if
            end if
         end if
         out = out//text(k:k)
      end do
   end function fix_leading_dots
end module rodyn_mesh_checks
