!> pfunit-lite: a small stand-in for the pFUnit `funit` module.
!>
!> Test sources written in pFUnit's .pf format are translated by pf2f90.py into plain
!> Fortran that calls the procedures below.  Every assertion receives the .pf file name,
!> the line number and the directive text; the first failing assertion of a test prints a
!> report and sets the failure flag, which the generated code checks to leave the test.
module funit
   use, intrinsic :: iso_fortran_env, only: real64, int64, output_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
   implicit none
   private

   integer, parameter, public :: funit_rk = real64   !< kind used for reals and tolerances

   public :: funit_init, funit_finish, funit_start_test, funit_end_test, funit_failed
   public :: funit_fail, funit_assert_true, funit_assert_false
   public :: funit_assert_equal, funit_assert_relatively_equal, funit_assert_compare

   integer, parameter :: rk = real64

   !> Equality, |actual - expected| <= tolerance (default 0), elementwise for arrays.
   interface funit_assert_equal
      module procedure eq_r0r0, eq_r0r1, eq_r1r1, eq_r0r2, eq_r2r2
      module procedure eq_i0r0, eq_i0r1, eq_i0r2
      module procedure eq_i0i0, eq_i0i1, eq_i1i1, eq_i0i2, eq_i2i2
      module procedure eq_l0l0, eq_c0c0
   end interface funit_assert_equal

   !> Relative equality, |actual - expected| <= tolerance * |expected|.
   interface funit_assert_relatively_equal
      module procedure rel_r0r0, rel_r0r1, rel_r1r1, rel_r0r2, rel_r2r2
   end interface funit_assert_relatively_equal

   !> Ordering, `left op right` with op one of '<', '<=', '>', '>='.
   interface funit_assert_compare
      module procedure cmp_rr, cmp_ii, cmp_ir, cmp_ri
   end interface funit_assert_compare

   logical :: failed = .false.            !< current test has failed
   integer :: n_passed = 0, n_failed = 0
   character(len=:), allocatable :: test_label

contains

   ! ------------------------------------------------------------------ state and driver

   !> Reset the counters (called once by the generated driver program).
   subroutine funit_init()
      n_passed = 0
      n_failed = 0
      failed = .false.
   end subroutine funit_init

   !> Begin a test: clear the failure flag and remember its name for reports.
   subroutine funit_start_test(file, module_name, test_name)
      character(*), intent(in) :: file, module_name, test_name
      failed = .false.
      test_label = module_name // '::' // test_name // ' (' // file // ')'
   end subroutine funit_start_test

   !> Finish a test: count it and print its outcome.
   subroutine funit_end_test()
      if (failed) then
         n_failed = n_failed + 1
         write(output_unit, '(a)') 'FAILED  ' // label()
      else
         n_passed = n_passed + 1
         write(output_unit, '(a)') 'passed  ' // label()
      end if
      flush(output_unit)
   end subroutine funit_end_test

   !> Print the summary line; stop with status 1 when any test failed.
   subroutine funit_finish()
      character(len=64) :: line
      write(line, '(i0,a,i0,a)') n_passed, ' passed, ', n_failed, ' failed'
      write(output_unit, '(a)') trim(line)
      flush(output_unit)
      if (n_failed > 0) stop 1
   end subroutine funit_finish

   !> True once an assertion of the current test has failed.
   logical function funit_failed()
      funit_failed = failed
   end function funit_failed

   !> Unconditional failure (@assertFail).
   subroutine funit_fail(file, line, what, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      character(*), intent(in), optional :: message
      if (failed) return
      call report_head(file, line, what)
      call report_tail(message)
   end subroutine funit_fail

   subroutine funit_assert_true(file, line, what, condition, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      logical, intent(in) :: condition
      character(*), intent(in), optional :: message
      if (failed .or. condition) return
      call report_head(file, line, what)
      call put('expected: .true.')
      call put('  actual: .false.')
      call report_tail(message)
   end subroutine funit_assert_true

   subroutine funit_assert_false(file, line, what, condition, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      logical, intent(in) :: condition
      character(*), intent(in), optional :: message
      if (failed .or. .not. condition) return
      call report_head(file, line, what)
      call put('expected: .false.')
      call put('  actual: .true.')
      call report_tail(message)
   end subroutine funit_assert_false

   ! ------------------------------------------------------------------ reporting helpers

   function label() result(s)
      character(len=:), allocatable :: s
      if (allocated(test_label)) then
         s = test_label
      else
         s = '(no test)'
      end if
   end function label

   subroutine put(text)
      character(*), intent(in) :: text
      write(output_unit, '(4x,a)') text
   end subroutine put

   !> First line of a failure report; marks the current test as failed.
   subroutine report_head(file, line, what)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      failed = .true.
      write(output_unit, '(a,a,i0,a,a)') file, ':', line, ': assertion failed: ', what
      call put('in test: ' // label())
   end subroutine report_head

   subroutine report_tail(message)
      character(*), intent(in), optional :: message
      if (present(message)) call put(' message: ' // message)
      flush(output_unit)
   end subroutine report_tail

   function r2s(x) result(s)
      real(rk), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=32) :: buf
      write(buf, '(es24.16e3)') x
      s = trim(adjustl(buf))
   end function r2s

   function i2s(i) result(s)
      integer(int64), intent(in) :: i
      character(len=:), allocatable :: s
      character(len=24) :: buf
      write(buf, '(i0)') i
      s = trim(buf)
   end function i2s

   !> "(i,j,...)" for linear position k (1-based, column major) in an array of shape ashape.
   function index_text(k, ashape) result(s)
      integer, intent(in) :: k, ashape(:)
      character(len=:), allocatable :: s
      integer :: d, rest
      s = ''
      rest = k - 1
      do d = 1, size(ashape)
         s = s // merge(',', '(', d > 1) // i2s(int(mod(rest, ashape(d)) + 1, int64))
         rest = rest / ashape(d)
      end do
      if (size(ashape) > 0) s = s // ')'
   end function index_text

   function shape_text(sh) result(s)
      integer, intent(in) :: sh(:)
      character(len=:), allocatable :: s
      integer :: d
      s = '['
      do d = 1, size(sh)
         if (d > 1) s = s // ', '
         s = s // i2s(int(sh(d), int64))
      end do
      s = s // ']'
   end function shape_text

   !> Fails (and reports) when the shapes differ; returns .true. in that case.
   logical function shape_mismatch(file, line, what, se, sa, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line, se(:), sa(:)
      character(*), intent(in), optional :: message
      shape_mismatch = .false.
      if (failed) return
      if (size(se) == size(sa)) then
         if (all(se == sa)) return
      end if
      shape_mismatch = .true.
      call report_head(file, line, what)
      call put('shapes differ: expected ' // shape_text(se) // ', actual ' // shape_text(sa))
      call report_tail(message)
   end function shape_mismatch

   real(rk) function tol_of(tolerance)
      real(rk), intent(in), optional :: tolerance
      tol_of = 0.0_rk
      if (present(tolerance)) tol_of = tolerance
   end function tol_of

   ! ------------------------------------------------------------------ comparison cores

   !> |a - e| without overflow (huge when it would overflow); assumes finite values.
   real(rk) function safe_diff(e, a)
      real(rk), intent(in) :: e, a
      real(rk), parameter :: half_big = 0.5_rk * huge(1.0_rk)
      if (abs(e) <= half_big .and. abs(a) <= half_big) then
         safe_diff = abs(a - e)
      else if (abs(0.5_rk * a - 0.5_rk * e) <= half_big) then
         safe_diff = 2.0_rk * abs(0.5_rk * a - 0.5_rk * e)
      else
         safe_diff = huge(1.0_rk)
      end if
   end function safe_diff

   !> Elementwise real comparison.  e has one element (broadcast) or as many as a.
   !> ashape is the shape of the actual argument (empty for a scalar).
   subroutine real_core(file, line, what, e, a, ashape, tol, relative, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line, ashape(:)
      real(rk), intent(in) :: e(:), a(:), tol
      logical, intent(in) :: relative
      character(*), intent(in), optional :: message
      integer :: k, first
      real(rk) :: ek, d, bound, maxdiff, first_bound
      logical :: ok, nonfinite
      if (failed) return
      first = 0
      maxdiff = 0.0_rk
      first_bound = 0.0_rk
      nonfinite = .false.
      do k = 1, size(a)
         ek = e(min(k, size(e)))
         if (ieee_is_nan(ek) .or. ieee_is_nan(a(k))) then
            ok = .false.
            nonfinite = .true.
            bound = tol
         else if (.not. (ieee_is_finite(ek) .and. ieee_is_finite(a(k)))) then
            ! equal only when both are infinite with the same sign
            ok = .not. (ieee_is_finite(ek) .or. ieee_is_finite(a(k))) &
                 .and. ((ek > 0.0_rk) .eqv. (a(k) > 0.0_rk))
            nonfinite = nonfinite .or. .not. ok
            bound = tol
         else
            d = safe_diff(ek, a(k))
            maxdiff = max(maxdiff, d)
            bound = tol
            if (relative) then
               if (abs(ek) <= huge(1.0_rk) / max(tol, 1.0_rk)) then
                  bound = tol * abs(ek)
               else
                  bound = huge(1.0_rk)
               end if
            end if
            ok = (d <= bound)
         end if
         if (.not. ok .and. first == 0) then
            first = k
            first_bound = bound
         end if
      end do
      if (first == 0) return
      call report_head(file, line, what)
      if (size(ashape) > 0) then
         call put('first failing index: ' // index_text(first, ashape) // ' of ' // &
                  i2s(int(size(a), int64)) // ' elements')
      end if
      call put('expected: ' // r2s(e(min(first, size(e)))))
      call put('  actual: ' // r2s(a(first)))
      if (relative) then
         call put('max |actual - expected|: ' // r2s(maxdiff) // ' (allowed here: ' // &
                  r2s(first_bound) // ' = tolerance ' // r2s(tol) // ' * |expected|)')
      else
         call put('max |actual - expected|: ' // r2s(maxdiff) // ' (tolerance: ' // &
                  r2s(tol) // ')')
      end if
      if (nonfinite) call put('(NaN or infinite values involved; the maximum is over ' // &
                              'finite pairs)')
      call report_tail(message)
   end subroutine real_core

   !> Elementwise integer comparison, same conventions as real_core.
   subroutine int_core(file, line, what, e, a, ashape, tol, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line, ashape(:), e(:), a(:)
      real(rk), intent(in) :: tol
      character(*), intent(in), optional :: message
      integer :: k, first
      integer(int64) :: d, maxdiff
      if (failed) return
      first = 0
      maxdiff = 0_int64
      do k = 1, size(a)
         d = abs(int(a(k), int64) - int(e(min(k, size(e))), int64))
         maxdiff = max(maxdiff, d)
         if (real(d, rk) > tol .and. first == 0) first = k
      end do
      if (first == 0) return
      call report_head(file, line, what)
      if (size(ashape) > 0) then
         call put('first failing index: ' // index_text(first, ashape) // ' of ' // &
                  i2s(int(size(a), int64)) // ' elements')
      end if
      call put('expected: ' // i2s(int(e(min(first, size(e))), int64)))
      call put('  actual: ' // i2s(int(a(first), int64)))
      call put('max |actual - expected|: ' // i2s(maxdiff))
      call report_tail(message)
   end subroutine int_core

   ! ------------------------------------------------------------------ assertEqual

   subroutine eq_r0r0(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      real(rk), intent(in) :: expected, actual
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call real_core(file, line, what, [expected], [actual], shape(actual), &
                     tol_of(tolerance), .false., message)
   end subroutine eq_r0r0

   subroutine eq_r0r1(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      real(rk), intent(in) :: expected, actual(:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call real_core(file, line, what, [expected], actual, shape(actual), &
                     tol_of(tolerance), .false., message)
   end subroutine eq_r0r1

   subroutine eq_r1r1(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      real(rk), intent(in) :: expected(:), actual(:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      if (shape_mismatch(file, line, what, shape(expected), shape(actual), message)) return
      call real_core(file, line, what, expected, actual, shape(actual), &
                     tol_of(tolerance), .false., message)
   end subroutine eq_r1r1

   subroutine eq_r0r2(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      real(rk), intent(in) :: expected, actual(:,:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call real_core(file, line, what, [expected], reshape(actual, [size(actual)]), &
                     shape(actual), tol_of(tolerance), .false., message)
   end subroutine eq_r0r2

   subroutine eq_r2r2(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      real(rk), intent(in) :: expected(:,:), actual(:,:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      if (shape_mismatch(file, line, what, shape(expected), shape(actual), message)) return
      call real_core(file, line, what, reshape(expected, [size(expected)]), &
                     reshape(actual, [size(actual)]), shape(actual), &
                     tol_of(tolerance), .false., message)
   end subroutine eq_r2r2

   subroutine eq_i0r0(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line, expected
      real(rk), intent(in) :: actual
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call eq_r0r0(file, line, what, real(expected, rk), actual, tolerance, message)
   end subroutine eq_i0r0

   subroutine eq_i0r1(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line, expected
      real(rk), intent(in) :: actual(:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call eq_r0r1(file, line, what, real(expected, rk), actual, tolerance, message)
   end subroutine eq_i0r1

   subroutine eq_i0r2(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line, expected
      real(rk), intent(in) :: actual(:,:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call eq_r0r2(file, line, what, real(expected, rk), actual, tolerance, message)
   end subroutine eq_i0r2

   subroutine eq_i0i0(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line, expected, actual
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call int_core(file, line, what, [expected], [actual], shape(actual), &
                    tol_of(tolerance), message)
   end subroutine eq_i0i0

   subroutine eq_i0i1(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line, expected, actual(:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call int_core(file, line, what, [expected], actual, shape(actual), &
                    tol_of(tolerance), message)
   end subroutine eq_i0i1

   subroutine eq_i1i1(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line, expected(:), actual(:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      if (shape_mismatch(file, line, what, shape(expected), shape(actual), message)) return
      call int_core(file, line, what, expected, actual, shape(actual), &
                    tol_of(tolerance), message)
   end subroutine eq_i1i1

   subroutine eq_i0i2(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line, expected, actual(:,:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call int_core(file, line, what, [expected], reshape(actual, [size(actual)]), &
                    shape(actual), tol_of(tolerance), message)
   end subroutine eq_i0i2

   subroutine eq_i2i2(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line, expected(:,:), actual(:,:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      if (shape_mismatch(file, line, what, shape(expected), shape(actual), message)) return
      call int_core(file, line, what, reshape(expected, [size(expected)]), &
                    reshape(actual, [size(actual)]), shape(actual), tol_of(tolerance), message)
   end subroutine eq_i2i2

   !> Logical equality; a tolerance, if given, is ignored.
   subroutine eq_l0l0(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      logical, intent(in) :: expected, actual
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      if (failed .or. (expected .eqv. actual)) return
      if (present(tolerance)) continue
      call report_head(file, line, what)
      call put('expected: ' // trim(merge('.true. ', '.false.', expected)))
      call put('  actual: ' // trim(merge('.true. ', '.false.', actual)))
      call report_tail(message)
   end subroutine eq_l0l0

   !> String equality, trailing blanks ignored; a tolerance, if given, is ignored.
   subroutine eq_c0c0(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      character(*), intent(in) :: expected, actual
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      integer :: k
      if (failed .or. expected == actual) return
      if (present(tolerance)) continue
      call report_head(file, line, what)
      call put('expected: "' // trim(expected) // '"')
      call put('  actual: "' // trim(actual) // '"')
      do k = 1, min(len(expected), len(actual))
         if (expected(k:k) /= actual(k:k)) exit
      end do
      call put('first difference at character ' // i2s(int(k, int64)))
      call report_tail(message)
   end subroutine eq_c0c0

   ! ------------------------------------------------------------------ assertRelativelyEqual

   subroutine rel_r0r0(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      real(rk), intent(in) :: expected, actual
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call real_core(file, line, what, [expected], [actual], shape(actual), &
                     tol_of(tolerance), .true., message)
   end subroutine rel_r0r0

   subroutine rel_r0r1(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      real(rk), intent(in) :: expected, actual(:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call real_core(file, line, what, [expected], actual, shape(actual), &
                     tol_of(tolerance), .true., message)
   end subroutine rel_r0r1

   subroutine rel_r1r1(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      real(rk), intent(in) :: expected(:), actual(:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      if (shape_mismatch(file, line, what, shape(expected), shape(actual), message)) return
      call real_core(file, line, what, expected, actual, shape(actual), &
                     tol_of(tolerance), .true., message)
   end subroutine rel_r1r1

   subroutine rel_r0r2(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      real(rk), intent(in) :: expected, actual(:,:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      call real_core(file, line, what, [expected], reshape(actual, [size(actual)]), &
                     shape(actual), tol_of(tolerance), .true., message)
   end subroutine rel_r0r2

   subroutine rel_r2r2(file, line, what, expected, actual, tolerance, message)
      character(*), intent(in) :: file, what
      integer, intent(in) :: line
      real(rk), intent(in) :: expected(:,:), actual(:,:)
      real(rk), intent(in), optional :: tolerance
      character(*), intent(in), optional :: message
      if (shape_mismatch(file, line, what, shape(expected), shape(actual), message)) return
      call real_core(file, line, what, reshape(expected, [size(expected)]), &
                     reshape(actual, [size(actual)]), shape(actual), &
                     tol_of(tolerance), .true., message)
   end subroutine rel_r2r2

   ! ------------------------------------------------------------------ ordering

   !> Shared outcome of the ordering assertions: report when .not. ok.
   subroutine compare_outcome(file, line, what, op, ok, ltext, rtext, message)
      character(*), intent(in) :: file, what, op, ltext, rtext
      integer, intent(in) :: line
      logical, intent(in) :: ok
      character(*), intent(in), optional :: message
      if (failed .or. ok) return
      call report_head(file, line, what)
      call put('expected: left ' // op // ' right')
      call put('    left: ' // ltext)
      call put('   right: ' // rtext)
      call report_tail(message)
   end subroutine compare_outcome

   logical function ordered(op, l, r)
      character(*), intent(in) :: op
      real(rk), intent(in) :: l, r
      ordered = .false.
      if (ieee_is_nan(l) .or. ieee_is_nan(r)) return
      select case (op)
      case ('<')
         ordered = l < r
      case ('<=')
         ordered = l <= r
      case ('>')
         ordered = l > r
      case ('>=')
         ordered = l >= r
      end select
   end function ordered

   subroutine cmp_rr(file, line, what, op, left, right, message)
      character(*), intent(in) :: file, what, op
      integer, intent(in) :: line
      real(rk), intent(in) :: left, right
      character(*), intent(in), optional :: message
      call compare_outcome(file, line, what, op, ordered(op, left, right), r2s(left), &
                           r2s(right), message)
   end subroutine cmp_rr

   subroutine cmp_ii(file, line, what, op, left, right, message)
      character(*), intent(in) :: file, what, op
      integer, intent(in) :: line, left, right
      character(*), intent(in), optional :: message
      logical :: ok
      select case (op)
      case ('<')
         ok = left < right
      case ('<=')
         ok = left <= right
      case ('>')
         ok = left > right
      case default
         ok = left >= right
      end select
      call compare_outcome(file, line, what, op, ok, i2s(int(left, int64)), &
                           i2s(int(right, int64)), message)
   end subroutine cmp_ii

   subroutine cmp_ir(file, line, what, op, left, right, message)
      character(*), intent(in) :: file, what, op
      integer, intent(in) :: line, left
      real(rk), intent(in) :: right
      character(*), intent(in), optional :: message
      call cmp_rr(file, line, what, op, real(left, rk), right, message)
   end subroutine cmp_ir

   subroutine cmp_ri(file, line, what, op, left, right, message)
      character(*), intent(in) :: file, what, op
      integer, intent(in) :: line, right
      real(rk), intent(in) :: left
      character(*), intent(in), optional :: message
      call cmp_rr(file, line, what, op, left, real(right, rk), message)
   end subroutine cmp_ri

end module funit
