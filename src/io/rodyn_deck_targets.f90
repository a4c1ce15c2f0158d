!> What a *MOTION or an *INITIAL VELOCITY acts on when it is not a line: a coupled body
!> or point (*MOTION, BODY= or POINT=: a FIXED one, moved as prescribed) and a FREE body
!> thrown (*INITIAL VELOCITY, BODY=), each resolved once the whole deck is read
!> (docs/deck.md, *MOTION and *INITIAL VELOCITY; docs/systems.md).
module rodyn_deck_targets
   use rodyn_error, only: error_t, has_error
   use rodyn_model, only: model_t, body_fixed, body_free, point_fixed, end_a, end_b
   use rodyn_deck_lexer, only: deck_t
   use rodyn_deck_card, only: card_error
   use rodyn_deck_support, only: ref_t, pending_t, param_fail, location
   use rodyn_deck_body, only: find_body
   use rodyn_deck_system, only: find_point
   implicit none
   private
   public :: resolve_item_body, resolve_motion_point

contains

   !> The body named by the last of a list of *MOTION (BODY=) or *INITIAL VELOCITY cards:
   !> it exists, is FIXED for a *MOTION (held: the motion moves it) and FREE for an
   !> *INITIAL VELOCITY, and no earlier card of the list names it.
   subroutine resolve_item_body(deck, model, refs, earlier, kind, ib, err)
      type(deck_t), intent(in) :: deck       !< all cards
      type(model_t), intent(in) :: model    !< model with the bodies
      type(ref_t), intent(in) :: refs(:)     !< BODY= and card of each item of the list
      integer, intent(in) :: earlier(:)      !< body of each earlier item (0: none)
      integer, intent(in) :: kind            !< body_fixed (*MOTION) or body_free
      integer, intent(out) :: ib             !< the body
      type(error_t), intent(inout) :: err    !< status
      integer :: j
      associate (card => deck%cards(refs(size(refs))%card), name => refs(size(refs))%name)
         call find_body(card, 'BODY', name, model, ib, err)
         if (has_error(err)) return
         if (model%bodies(ib)%kind /= kind .and. kind == body_fixed) then
            call param_fail(card, 'BODY', "body '"//name//"' is FREE: a *MOTION moves a"// &
                            ' FIXED body (its motion prescribed), not a FREE one', err)
         else if (kind == body_fixed .and. model%bodies(ib)%host) then
            call param_fail(card, 'BODY', "body '"//name//"' has HOST=YES: a host program "// &
                            'moves it, not a *MOTION', err)
         else if (model%bodies(ib)%kind /= kind) then
            call param_fail(card, 'BODY', "body '"//name//"' is FIXED: only a FREE body "// &
                            'has a velocity of its own', err)
         end if
         j = findloc(earlier, ib, dim=1)
         if (j > 0) call card_error(card, "body '"//name//"' already has "// &
                                    trim(merge('a *MOTION           ', 'an *INITIAL VELOCITY', &
                                               kind == body_fixed))//' (at '// &
                                    location(deck, refs(j)%card)//')', err)
      end associate
   end subroutine resolve_item_body

   !> The point of motion `im` (POINT=): it exists, is FIXED (its line ends held: the
   !> motion moves them), has no other *MOTION, and no end on it has one of its own.
   subroutine resolve_motion_point(deck, pend, model, im, err)
      type(deck_t), intent(in) :: deck       !< all cards
      type(pending_t), intent(in) :: pend    !< card and POINT= of each motion
      type(model_t), intent(inout) :: model  !< the motion's point set
      integer, intent(in) :: im              !< the motion
      type(error_t), intent(inout) :: err    !< status
      integer :: ip, jm, l
      associate (card => deck%cards(pend%motion_line(im)%card), &
                 name => pend%motion_line(im)%name)
         call find_point(card, 'POINT', name, model, ip, err)
         if (has_error(err)) return
         if (model%points(ip)%kind /= point_fixed) then
            call param_fail(card, 'POINT', "point '"//name//"' is not FIXED: a *MOTION "// &
                            'moves a FIXED point (its line ends held), not a FREE or BODY one', &
                            err)
            return
         end if
         if (model%points(ip)%host) then
            call param_fail(card, 'POINT', "point '"//name//"' has HOST=YES: a host "// &
                            'program moves it, not a *MOTION', err)
            return
         end if
         do jm = 1, size(model%motions)
            if (jm == im) cycle
            if (pend%motion_point(jm) .and. pend%motion_line(jm)%name == name .and. jm < im) &
               then
               call card_error(card, "point '"//name//"' already has a *MOTION (at "// &
                               location(deck, pend%motion_line(jm)%card)//')', err)
               return
            end if
            if (pend%motion_body(jm) .or. pend%motion_point(jm)) cycle
            do l = 1, size(model%lines)
               if (model%lines(l)%name /= pend%motion_line(jm)%name) cycle
               if ((model%lines(l)%point_a == ip .and. model%motions(jm)%node == end_a) .or. &
                   (model%lines(l)%point_b == ip .and. model%motions(jm)%node == end_b)) then
                  call card_error(card, "point '"//name//"': line "//trim(model%lines(l)% &
                                  name)//"'s end on it has a *MOTION of its own (at "// &
                                  location(deck, pend%motion_line(jm)%card)//')', err)
                  return
               end if
            end do
         end do
         model%motions(im)%point = ip
         model%motions(im)%line = 0
      end associate
   end subroutine resolve_motion_point
end module rodyn_deck_targets
