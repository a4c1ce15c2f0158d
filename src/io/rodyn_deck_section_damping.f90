!> The structural damping parameters of a *SECTION card (docs/deck.md, *SECTION;
!> docs/theory.md eqs. (116)-(121)): AXIAL DAMPING = C_a [N s] (axial force C_a times the
!> rate of axial strain), or AXIAL DAMPING RATIO = zeta (MoorDyn's negative BA: C_a =
!> zeta h sqrt(EA m), h the node spacing, resolved per element by rodyn_mesh), and
!> BENDING DAMPING = C_b [N m2 s] (bending moment C_b times the rate of curvature).
module rodyn_deck_section_damping
   use rodyn_kinds, only: wp, pi
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: section_t, element_cable
   use rodyn_deck_card, only: card_t, card_find_param
   use rodyn_deck_card_values, only: card_get_real
   use rodyn_deck_numbers, only: real_str, int_str
   use rodyn_deck_support, only: param_fail, check_at_most, get_bounded
   implicit none
   private
   public :: read_section_damping

   !> Largest C_a/EA and C_b/EI [s]: they act on the axial and bending modes as a
   !> stiffness-proportional damping BETA does, and *DAMPING's bound on BETA applies
   real(wp), parameter :: max_damping_time = 1.0e3_wp
   !> Largest AXIAL DAMPING RATIO [-]: 1 damps a segment's own axial mode critically
   real(wp), parameter :: max_ratio = 100.0_wp

contains

   !> Read AXIAL DAMPING, AXIAL DAMPING RATIO and BENDING DAMPING into sec, after its
   !> data line (EA and EI bound the values) and its element are known. Each >= 0;
   !> AXIAL DAMPING and AXIAL DAMPING RATIO not both; BENDING DAMPING not on a cable
   !> section; C_a/EA and C_b/min(EI1, EI2) at most 1e3 s, the ratio at most 100.
   subroutine read_section_damping(card, sec, err)
      type(card_t), intent(in) :: card        !< the *SECTION card
      type(section_t), intent(inout) :: sec   !< section: data line and element read
      type(error_t), intent(inout) :: err     !< status
      if (has_error(err)) return
      if (card_find_param(card, 'AXIAL DAMPING') > 0 .and. &
          card_find_param(card, 'AXIAL DAMPING RATIO') > 0) then
         call param_fail(card, 'AXIAL DAMPING RATIO', 'give AXIAL DAMPING (N s) or AXIAL'// &
                         ' DAMPING RATIO, not both', err)
         return
      end if
      call get_bounded(card, 'AXIAL DAMPING', sec%axial_damping, .false., err, &
                       hint=' (a damping ratio, MoorDyn''s negative BA, is AXIAL DAMPING'// &
                       ' RATIO=)')
      call get_bounded(card, 'AXIAL DAMPING RATIO', sec%axial_damping_ratio, .false., err)
      call get_bounded(card, 'BENDING DAMPING', sec%bending_damping, .false., err)
      if (has_error(err)) return
      if (sec%bending_damping > 0.0_wp .and. sec%element == element_cable) then
         call param_fail(card, 'BENDING DAMPING', 'BENDING DAMPING needs a rod section:'// &
                         ' a cable element has no bending', err)
         return
      end if
      call check_time(card, 'AXIAL DAMPING', 'EA', sec%axial_damping, sec%ea, 'axial', err)
      if (sec%element /= element_cable) &
         call check_time(card, 'BENDING DAMPING', 'EI', sec%bending_damping, &
                         min(sec%ei1, sec%ei2), 'bending', err)
      call check_at_most(card, 'AXIAL DAMPING RATIO', sec%axial_damping_ratio, max_ratio, &
                         '', 'at 1 the axial mode of one segment is critically damped', err)
   end subroutine read_section_damping

   !> A damping coefficient c over its stiffness k is the time of a stiffness-proportional
   !> damping (*DAMPING BETA) of the modes it acts on: refused beyond max_damping_time.
   subroutine check_time(card, name, kname, c, k, modes, err)
      type(card_t), intent(in) :: card      !< the *SECTION card
      character(len=*), intent(in) :: name  !< parameter name
      character(len=*), intent(in) :: kname !< name of the stiffness ('EA', 'EI')
      real(wp), intent(in) :: c             !< damping coefficient [N s, N m2 s]
      real(wp), intent(in) :: k             !< stiffness [N, N m2]
      character(len=*), intent(in) :: modes !< 'axial' or 'bending'
      type(error_t), intent(inout) :: err   !< status
      if (has_error(err)) return
      if (c/k <= max_damping_time) return
      call param_fail(card, name, name//' / '//kname//' = '//real_str(c/k)//' s is beyond '// &
                      real_str(max_damping_time)//' s: it damps the '//modes//' modes as'// &
                      ' *DAMPING BETA does, every one of period below '// &
                      int_str(nint(pi*max_damping_time))//' s beyond critical', err)
   end subroutine check_time
end module rodyn_deck_section_damping
