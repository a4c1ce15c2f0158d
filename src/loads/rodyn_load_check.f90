!> Why a solve that failed may have diverged: point loads beyond anything the lines can
!> carry. A force F on a line of axial stiffness EA strains it by about F/EA; beyond a
!> strain of 10 (the line ten times its length) no equilibrium is within reach of the
!> solvers, which then overflow; the message then names the load, not a mechanism.
!> (The strain is Gamma_3 of docs/theory.md eq. (4), or the cable's lambda - 1, eq. (61).)
module rodyn_load_check
   use rodyn_kinds, only: wp
   use rodyn_model, only: model_t, end_b
   implicit none
   private
   public :: load_divergence_hint

   real(wp), parameter :: strain_limit = 10.0_wp !< F/EA beyond which a load is absurd [-]

contains

   !> ': the *LOAD at FILE:LINE of F N on line X is N times its largest EA, ...' for the
   !> largest point load beyond strain_limit x EA of its line; '' when none is.
   pure function load_divergence_hint(model) result(hint)
      type(model_t), intent(in) :: model    !< model
      character(len=:), allocatable :: hint !< the reason, or ''
      real(wp) :: f, ea, worst, ratio
      integer :: k, kw, s
      character(len=32) :: b1, b2
      hint = ''
      if (.not. allocated(model%loads) .or. .not. allocated(model%sections)) return
      worst = 0.0_wp
      kw = 0
      do k = 1, size(model%loads)
         associate (ld => model%loads(k))
            if (ld%line < 1) cycle
            f = norm2(ld%force)
            ea = 0.0_wp
            associate (line => model%lines(ld%line))
               if (allocated(line%seg_section)) then
                  do s = 1, size(line%seg_section)
                     ea = max(ea, model%sections(line%seg_section(s))%ea)
                  end do
               else if (line%section > 0) then
                  ea = model%sections(line%section)%ea
               end if
            end associate
            if (.not. ea > 0.0_wp) cycle
            ratio = f/ea
            if (ratio > worst) then
               worst = ratio
               kw = k
            end if
         end associate
      end do
      if (kw == 0 .or. .not. worst > strain_limit) return
      associate (ld => model%loads(kw))
         write (b1, '(es10.3)') norm2(ld%force)
         write (b2, '(es10.3)') worst
         hint = 'the point load of '//trim(adjustl(b1))//' N on line '// &
                trim(model%lines(ld%line)%name)//' '//node_text(ld%node)
         if (allocated(ld%card_at)) hint = hint//' (*LOAD at '//ld%card_at//')'
         hint = hint//' is '//trim(adjustl(b2))//' times the axial stiffness EA of the '// &
                'line: no equilibrium within reach of the solver'
      end associate
   contains
      !> 'end B', 'node k'.
      pure function node_text(node) result(t)
         integer, intent(in) :: node         !< node number or end_b
         character(len=:), allocatable :: t  !< its name
         character(len=12) :: b
         if (node == end_b) then
            t = 'end B'
         else
            write (b, '(i0)') node
            t = 'node '//trim(b)
         end if
      end function node_text
   end function load_divergence_hint
end module rodyn_load_check
