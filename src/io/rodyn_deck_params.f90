!> Deck parameters (*PARAMETER, docs/deck.md): the table of `NAME = value` definitions,
!> the evaluation of a value (a number, a string, or arithmetic of numbers and earlier
!> parameters), the `<NAME>` substitution in a line of text, and the text a number is
!> written as (the shortest that reads back to the same double, bit for bit).
!>
!> Everything here is pure: errors come back as an error_t (code stat_input) whose
!> message says what is wrong without a location; the lexer (rodyn_deck_lexer) adds
!> 'FILE:LINE: error: *KEYWORD: '. Names are case-insensitive and kept upper case.
!>
!> Arithmetic (evaluated in double precision, the usual precedence):
!>   sum     = product {('+'|'-') product}
!>   product = unary {('*'|'/') unary}
!>   unary   = ('+'|'-') unary | power
!>   power   = primary ['**' unary]          (right-associative: 2**3**2 = 2**9)
!>   primary = number | NAME | '(' sum ')'
!> so -2**2 = -4 as in Fortran. Every intermediate value must stay below 1e300 in
!> magnitude (no overflow, no floating-point exception), a divisor must not be zero,
!> a negative number has only whole powers. Signs, powers and parentheses nest at most
!> max_depth deep (the parser recurses once a level: 50 000 levels overflowed the stack).
module rodyn_deck_params
   use, intrinsic :: iso_fortran_env, only: int64
   use rodyn_kinds, only: wp
   use rodyn_error, only: error_t, stat_input
   implicit none
   private
   public :: deck_param_t, param_table_t, param_override_t
   public :: param_valid_name, param_find, param_add, param_split_definition
   public :: param_value, param_eval, param_substitute, param_number_text
   public :: param_name_len, upper_case, shortest_text, int_str

   integer, parameter :: param_name_len = 32      !< longest parameter name
   real(wp), parameter :: big = 1.0e300_wp        !< largest magnitude of a value
   integer, parameter :: max_depth = 100          !< deepest nesting of an expression
   character(len=*), parameter :: letters = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz'
   character(len=*), parameter :: digits10 = '0123456789'

   !> One parameter, as defined (or overridden) in the deck.
   type :: deck_param_t
      character(len=:), allocatable :: name   !< upper case
      character(len=:), allocatable :: text   !< text substituted for <NAME>
      logical :: is_number = .false.          !< a number (else a string)
      real(wp) :: value = 0.0_wp              !< the number (0 for a string)
      character(len=:), allocatable :: file   !< file of the definition, as opened
      integer :: line = 0                     !< line of the definition
      logical :: used = .false.               !< referred to by <NAME> or an expression
      logical :: overridden = .false.         !< the value came from --set
   end type deck_param_t

   !> The parameters defined so far, in the order of their definitions.
   type :: param_table_t
      integer :: n = 0                        !< number of parameters
      type(deck_param_t), allocatable :: p(:) !< parameters 1..n (capacity may exceed)
   end type param_table_t

   !> A value given on the command line (--set NAME=VALUE).
   type :: param_override_t
      character(len=:), allocatable :: name   !< upper case
      character(len=:), allocatable :: text   !< VALUE, as given
      logical :: matched = .false.            !< the deck defines NAME
   end type param_override_t

   !> Expression parser state.
   type :: parser_t
      character(len=:), allocatable :: s      !< the expression
      integer :: pos = 1                      !< next character
      integer :: depth = 0                    !< unary levels open (signs, **, '(')
      character(len=:), allocatable :: msg    !< '' or the first problem
   end type parser_t

contains

   ! ================================================================== table

   !> True for a valid name: a letter, then letters, digits and '_', at most
   !> param_name_len characters.
   pure logical function param_valid_name(name) result(ok)
      character(len=*), intent(in) :: name !< name as written
      ok = .false.
      if (len(name) == 0 .or. len(name) > param_name_len) return
      if (index(letters, name(1:1)) == 0) return
      ok = verify(name, letters//digits10//'_') == 0
   end function param_valid_name

   !> Index of parameter `name` (any case) in the table, 0 if not defined.
   pure integer function param_find(table, name) result(k)
      type(param_table_t), intent(in) :: table !< parameters
      character(len=*), intent(in) :: name     !< name, any case
      character(len=len(name)) :: u
      u = upper_case(name)
      do k = 1, table%n
         if (table%p(k)%name == u) return
      end do
      k = 0
   end function param_find

   !> Append a parameter to the table (growing it when full).
   pure subroutine param_add(table, p)
      type(param_table_t), intent(inout) :: table !< parameters
      type(deck_param_t), intent(in) :: p         !< the new parameter
      type(deck_param_t), allocatable :: tmp(:)
      if (.not. allocated(table%p)) allocate (table%p(8))
      if (table%n == size(table%p)) then
         allocate (tmp(2*size(table%p)))
         tmp(1:table%n) = table%p(1:table%n)
         call move_alloc(tmp, table%p)
      end if
      table%n = table%n + 1
      table%p(table%n) = p
   end subroutine param_add

   !> Split a definition line `NAME = value` into the name (upper case) and the value
   !> text (trimmed). err: no '=', a bad name, or no value.
   pure subroutine param_split_definition(line, name, text, err)
      character(len=*), intent(in) :: line                 !< the data line
      character(len=:), allocatable, intent(out) :: name   !< NAME, upper case
      character(len=:), allocatable, intent(out) :: text   !< the value text
      type(error_t), intent(inout) :: err                  !< status
      integer :: eq
      name = ''
      text = ''
      eq = index(line, '=')
      if (eq == 0) then
         call fail(err, "expected 'NAME = value', got '"//line//"'")
         return
      end if
      name = trim(adjustl(line(:eq - 1)))
      text = trim(adjustl(line(eq + 1:)))
      if (.not. param_valid_name(name)) then
         call fail(err, "'"//name//"' is not a valid parameter name (a letter, then "// &
                   "letters, digits and '_', at most "//int_str(param_name_len)//' characters)')
         return
      end if
      name = upper_case(name)
      if (len(text) == 0) call fail(err, name//": no value after '='")
   end subroutine param_split_definition

   ! ================================================================== values

   !> The value of a definition's text: a string in double or single quotes (the
   !> quotes dropped); the name of an earlier parameter (a copy of it); a bare word
   !> (a letter, then letters, digits, '_' and '.'; kept as written) that names no
   !> parameter: a string; anything else: an arithmetic expression (param_eval).
   !> The parameters referred to are marked used.
   pure subroutine param_value(text, table, p, err)
      character(len=*), intent(in) :: text          !< value text, trimmed
      type(param_table_t), intent(inout) :: table   !< earlier parameters
      type(deck_param_t), intent(inout) :: p        !< gets text, is_number, value
      type(error_t), intent(inout) :: err           !< status
      integer :: n, k
      character(len=1) :: q

      n = len(text)
      p%is_number = .false.
      p%value = 0.0_wp
      p%text = ''
      if (n == 0) then
         call fail(err, 'empty value')
         return
      end if
      q = text(1:1)
      if (q == '"' .or. q == "'") then
         if (n < 2 .or. index(text(2:), q) /= n - 1) then
            call fail(err, 'string '//text//' is not closed by one '//q//' at its end')
            return
         end if
         p%text = text(2:n - 1)
         return
      end if
      if (index(letters, q) > 0 .and. verify(text, letters//digits10//'_.') == 0) then
         k = 0
         if (verify(text, letters//digits10//'_') == 0) k = param_find(table, text)
         if (k == 0) then
            p%text = text
         else
            table%p(k)%used = .true.
            p%text = table%p(k)%text
            p%is_number = table%p(k)%is_number
            p%value = table%p(k)%value
         end if
         return
      end if
      call param_eval(text, table, p%value, err)
      if (err%code /= 0) return
      p%is_number = .true.
      p%text = param_number_text(p%value)
      ! an integer literal, signed or not, is substituted as written (but for a '+'): a
      ! message about it (an integer out of range) then quotes what the user typed, not
      ! its rounded real value ('1e20')
      k = 1
      if (text(1:1) == '+' .or. text(1:1) == '-') k = 2
      if (k <= n) then
         if (verify(text(k:), digits10) == 0) p%text = text(merge(2, 1, q == '+'):)
      end if
   end subroutine param_value

   !> Evaluate an arithmetic expression of numbers and numeric parameters (grammar in
   !> the module header); the parameters named are marked used.
   pure subroutine param_eval(expr, table, value, err)
      character(len=*), intent(in) :: expr         !< the expression
      type(param_table_t), intent(inout) :: table  !< parameters it may name
      real(wp), intent(out) :: value               !< its value
      type(error_t), intent(inout) :: err          !< status
      type(parser_t) :: ps
      ps%s = expr
      ps%pos = 1
      ps%msg = ''
      value = 0.0_wp
      call parse_terms(ps, table, '+-', value)
      if (len(ps%msg) == 0) then
         call skip_blanks(ps)
         if (ps%pos <= len(ps%s)) then
            if (ps%s(ps%pos:ps%pos) == ')') then
               ps%msg = "')' without '('"
            else
               ps%msg = "unexpected '"//ps%s(ps%pos:)//"'"
            end if
         end if
      end if
      if (len(ps%msg) > 0) then
         value = 0.0_wp
         call fail(err, 'bad expression '''//expr//''': '//ps%msg)
      end if
   end subroutine param_eval

   !> sum = product {('+'|'-') product} (ops '+-'), product = unary {('*'|'/') unary}
   !> (ops '*/').
   pure recursive subroutine parse_terms(ps, table, ops, v)
      type(parser_t), intent(inout) :: ps          !< parser
      type(param_table_t), intent(inout) :: table  !< parameters
      character(len=2), intent(in) :: ops          !< '+-' (a sum) or '*/' (a product)
      real(wp), intent(out) :: v                   !< value
      real(wp) :: w
      character(len=1) :: op
      op = ' '
      v = 0.0_wp
      do while (len(ps%msg) == 0)
         if (ops == '+-') then
            call parse_terms(ps, table, '*/', w)
         else
            call parse_unary(ps, table, w)
         end if
         if (op == ' ') v = w
         if (op /= ' ' .and. len(ps%msg) == 0) call apply_operator(ps, op, v, w)
         if (len(ps%msg) > 0) exit
         call next_operator(ps, ops, op)
         if (op == ' ') exit
      end do
   end subroutine parse_terms

   !> v = v op w for op '+', '-', '*' or '/', or the reason why not in ps%msg (a result
   !> above 1e300 in magnitude, a division by zero).
   pure subroutine apply_operator(ps, op, v, w)
      type(parser_t), intent(inout) :: ps  !< parser
      character(len=1), intent(in) :: op   !< the operator
      real(wp), intent(inout) :: v         !< left operand, then the result
      real(wp), intent(in) :: w            !< right operand
      select case (op)
      case ('+', '-')
         v = v + merge(w, -w, op == '+')
         if (abs(v) > big) ps%msg = 'a sum is out of range (above 1e300)'
      case ('*')
         if (abs(v) > 1.0_wp) then
            if (abs(w) > big/abs(v)) then
               ps%msg = 'a product is out of range (above 1e300)'
               return
            end if
         end if
         v = v*w
      case default
         if (w == 0.0_wp) then
            ps%msg = 'division by zero'
            return
         end if
         if (abs(w) < 1.0_wp) then
            if (abs(v) > big*abs(w)) then
               ps%msg = 'a quotient is out of range (above 1e300)'
               return
            end if
         end if
         v = v/w
      end select
   end subroutine apply_operator

   !> The binary operator at the parser's position (after blanks) when it is one of
   !> `ops`, and the parser moved past it; ' ' otherwise ('**', a power, is a unary's).
   pure subroutine next_operator(ps, ops, op)
      type(parser_t), intent(inout) :: ps  !< parser
      character(len=*), intent(in) :: ops  !< the operators looked for
      character(len=1), intent(out) :: op  !< the operator, or ' '
      op = ' '
      call skip_blanks(ps)
      if (ps%pos > len(ps%s)) return
      if (index(ops, ps%s(ps%pos:ps%pos)) == 0) return
      if (ps%s(ps%pos:min(ps%pos + 1, len(ps%s))) == '**') return
      op = ps%s(ps%pos:ps%pos)
      ps%pos = ps%pos + 1
   end subroutine next_operator

   !> unary = ('+'|'-') unary | power
   pure recursive subroutine parse_unary(ps, table, v)
      type(parser_t), intent(inout) :: ps          !< parser
      type(param_table_t), intent(inout) :: table  !< parameters
      real(wp), intent(out) :: v                   !< value
      character(len=1) :: op
      call skip_blanks(ps)
      v = 0.0_wp
      if (ps%depth >= max_depth) then
         ps%msg = 'signs, powers and parentheses nested deeper than '//int_str(max_depth)// &
                  ' levels'
         return
      end if
      ps%depth = ps%depth + 1
      if (ps%pos <= len(ps%s)) then
         op = ps%s(ps%pos:ps%pos)
         if (op == '+' .or. op == '-') then
            ps%pos = ps%pos + 1
            call parse_unary(ps, table, v)
            if (op == '-') v = -v
            ps%depth = ps%depth - 1
            return
         end if
      end if
      call parse_power(ps, table, v)
      ps%depth = ps%depth - 1
   end subroutine parse_unary

   !> power = primary ['**' unary]
   pure recursive subroutine parse_power(ps, table, v)
      type(parser_t), intent(inout) :: ps          !< parser
      type(param_table_t), intent(inout) :: table  !< parameters
      real(wp), intent(out) :: v                   !< value
      real(wp) :: w, lg
      call parse_primary(ps, table, v)
      if (len(ps%msg) > 0) return
      call skip_blanks(ps)
      if (ps%pos >= len(ps%s)) return
      if (ps%s(ps%pos:ps%pos + 1) /= '**') return
      ps%pos = ps%pos + 2
      call parse_unary(ps, table, w)
      if (len(ps%msg) > 0) return
      if (v == 0.0_wp) then
         if (w < 0.0_wp) then
            ps%msg = 'division by zero (0 to a negative power)'
         else if (w == 0.0_wp) then
            v = 1.0_wp
         end if
         return
      end if
      if (v < 0.0_wp .and. aint(w) /= w) then
         ps%msg = 'a negative number to a power that is not whole'
         return
      end if
      lg = w*log(abs(v))
      if (lg > log(big)) then
         ps%msg = 'a power is out of range (above 1e300)'
         return
      end if
      if (lg < -log(big)) then
         v = 0.0_wp
      else if (aint(w) == w .and. abs(w) < 1.0e9_wp) then
         v = v**nint(w)
      else
         v = v**w
      end if
   end subroutine parse_power

   !> primary = number | NAME | '(' sum ')'
   pure recursive subroutine parse_primary(ps, table, v)
      type(parser_t), intent(inout) :: ps          !< parser
      type(param_table_t), intent(inout) :: table  !< parameters
      real(wp), intent(out) :: v                   !< value
      integer :: first, k
      character(len=1) :: c
      character(len=:), allocatable :: name

      v = 0.0_wp
      call skip_blanks(ps)
      if (ps%pos > len(ps%s)) then
         ps%msg = 'a number, a name or ''('' is missing at the end'
         return
      end if
      c = ps%s(ps%pos:ps%pos)
      if (c == '(') then
         ps%pos = ps%pos + 1
         call parse_terms(ps, table, '+-', v)
         if (len(ps%msg) > 0) return
         call skip_blanks(ps)
         if (ps%pos > len(ps%s)) then
            ps%msg = "'(' without ')'"
            return
         end if
         if (ps%s(ps%pos:ps%pos) /= ')') then
            ps%msg = "')' expected before '"//ps%s(ps%pos:)//"'"
            return
         end if
         ps%pos = ps%pos + 1
      else if (index(digits10//'.', c) > 0) then
         call parse_number(ps, v)
      else if (index(letters, c) > 0) then
         first = ps%pos
         do while (ps%pos <= len(ps%s))
            if (index(letters//digits10//'_', ps%s(ps%pos:ps%pos)) == 0) exit
            ps%pos = ps%pos + 1
         end do
         name = upper_case(ps%s(first:ps%pos - 1))
         k = param_find(table, name)
         if (k == 0) then
            ps%msg = "unknown name '"//name//"' (not a parameter defined above)"
            return
         end if
         table%p(k)%used = .true.
         if (.not. table%p(k)%is_number) then
            ps%msg = "parameter "//name//" is the string '"//table%p(k)%text// &
                     "', not a number"
            return
         end if
         v = table%p(k)%value
      else
         ps%msg = "a number, a name or '(' expected at '"//ps%s(ps%pos:)//"'"
      end if
   end subroutine parse_primary

   !> A number: digits [. digits] [e|E|d|D [sign] digits] (or . digits ...).
   pure subroutine parse_number(ps, v)
      type(parser_t), intent(inout) :: ps  !< parser, at the first digit or '.'
      real(wp), intent(out) :: v           !< the number
      integer :: first, n_mant, ios, p
      character(len=:), allocatable :: tok

      v = 0.0_wp
      first = ps%pos
      n_mant = 0
      p = ps%pos
      call scan_digits(ps%s, p, n_mant)
      if (p <= len(ps%s)) then
         if (ps%s(p:p) == '.') then
            p = p + 1
            call scan_digits(ps%s, p, n_mant)
         end if
      end if
      if (n_mant == 0) then
         ps%msg = "'.' is not a number"
         return
      end if
      if (p <= len(ps%s)) then
         if (index('eEdD', ps%s(p:p)) > 0) then
            p = p + 1
            if (p <= len(ps%s)) then
               if (index('+-', ps%s(p:p)) > 0) p = p + 1
            end if
            n_mant = 0
            call scan_digits(ps%s, p, n_mant)
            if (n_mant == 0) then
               ps%msg = "'"//ps%s(first:p - 1)//"' is not a number"
               return
            end if
            if (n_mant > 4) then
               ps%msg = "'"//ps%s(first:p - 1)//"' is out of range"
               return
            end if
         end if
      end if
      tok = ps%s(first:p - 1)
      do p = 1, len(tok)
         if (tok(p:p) == 'd' .or. tok(p:p) == 'D') tok(p:p) = 'e'
      end do
      ps%pos = first + len(tok)
      if (log10_estimate(tok) > 300) then
         ps%msg = "'"//tok//"' is out of range (above 1e300)"
         return
      end if
      read (tok, *, iostat=ios) v
      if (ios /= 0) ps%msg = "'"//tok//"' is not a number"
   end subroutine parse_number

   !> Advance p over the digits of s at p, counting them in n.
   pure subroutine scan_digits(s, p, n)
      character(len=*), intent(in) :: s  !< text
      integer, intent(inout) :: p        !< position
      integer, intent(inout) :: n        !< digits counted
      do while (p <= len(s))
         if (index(digits10, s(p:p)) == 0) exit
         p = p + 1
         n = n + 1
      end do
   end subroutine scan_digits

   !> Decimal exponent of the leading digit of a number token (a bound for overflow):
   !> digits before the point (leading zeros not counted) - 1 + the exponent.
   pure integer function log10_estimate(tok) result(e)
      character(len=*), intent(in) :: tok  !< digits [. digits] [e [sign] digits]
      integer :: p, ep, ios, x
      ep = scan(tok, 'eE')
      x = 0
      if (ep > 0) then
         read (tok(ep + 1:), *, iostat=ios) x
         if (ios /= 0) x = 0
      else
         ep = len(tok) + 1
      end if
      p = index(tok(:ep - 1), '.')
      if (p == 0) p = ep
      e = len(tok(:p - 1)) - (verify(tok(:p - 1)//'.', '0') - 1) - 1 + x
   end function log10_estimate

   !> Skip blanks.
   pure subroutine skip_blanks(ps)
      type(parser_t), intent(inout) :: ps  !< parser
      do while (ps%pos <= len(ps%s))
         if (ps%s(ps%pos:ps%pos) /= ' ') exit
         ps%pos = ps%pos + 1
      end do
   end subroutine skip_blanks

   ! ============================================================= substitution

   !> Replace every `<NAME>` in line by the text of parameter NAME (any case) and mark
   !> it used; a '<' followed by anything but a letter is plain text. err: a '<' and a
   !> letter without '>', a '<...>' that is not a name, an undefined name.
   pure subroutine param_substitute(line, table, out, err)
      character(len=*), intent(in) :: line              !< text with references
      type(param_table_t), intent(inout) :: table       !< parameters defined so far
      character(len=:), allocatable, intent(out) :: out !< the text substituted
      type(error_t), intent(inout) :: err               !< status
      integer :: p, lt, gt, k
      character(len=:), allocatable :: name

      out = ''
      p = 1
      do
         lt = index(line(p:), '<')
         if (lt == 0) then
            out = out//line(p:)
            exit
         end if
         lt = p + lt - 1
         out = out//line(p:lt - 1)
         ! a '<' not followed by a letter is text ('t < 3 s' in a *HEADING line)
         if (lt == len(line)) then
            out = out//'<'
            exit
         end if
         if (index(letters, line(lt + 1:lt + 1)) == 0) then
            out = out//'<'
            p = lt + 1
            cycle
         end if
         gt = index(line(lt + 1:), '>')
         if (gt == 0) then
            call fail(err, "'<' without '>' in '"//line(lt:)//"' (a reference is <NAME>)")
            return
         end if
         gt = lt + gt
         name = line(lt + 1:gt - 1)
         if (.not. param_valid_name(name)) then
            call fail(err, "'"//line(lt:gt)//"' is not a parameter reference "// &
                      "(<NAME>: a letter, then letters, digits and '_')")
            return
         end if
         k = param_find(table, name)
         if (k == 0) then
            call fail(err, '<'//upper_case(name)//'> is not defined (no *PARAMETER '// &
                      upper_case(name)//' above)')
            return
         end if
         table%p(k)%used = .true.
         out = out//table%p(k)%text
         p = gt + 1
      end do
   end subroutine param_substitute

   !> Text of a number that reads back to the same double bit for bit: a whole number
   !> below 1e15 in magnitude as an integer ('40', '-3'); otherwise the fewest
   !> significant digits (at most 17) that read back exactly: '0.01', '33.333333333333336',
   !> '1.5e-7'.
   pure function param_number_text(x) result(s)
      real(wp), intent(in) :: x           !< the number (finite)
      character(len=:), allocatable :: s  !< its text
      character(len=40) :: buf

      if (x == 0.0_wp) then
         s = '0'
         return
      end if
      if (abs(x) < 1.0e15_wp .and. aint(x) == x) then
         write (buf, '(i0)') int(x, int64)
         s = trim(buf)
         return
      end if
      s = shortest_text(x, 15, huge(x))
   end function param_number_text

   ! ================================================================== helpers

   !> The shortest decimal text of x (finite, not zero) that reads back to the same
   !> double: the fewest significant digits (at most 17), in fixed notation for a decimal
   !> exponent e with -4 <= e < e_fixed, else as 'd.ddde-7'. A candidate of x above
   !> check_max in magnitude is not read back (rounding up could overflow): 17 digits.
   pure function shortest_text(x, e_fixed, check_max) result(s)
      real(wp), intent(in) :: x           !< the number
      integer, intent(in) :: e_fixed      !< fixed notation below this exponent
      real(wp), intent(in) :: check_max   !< largest magnitude whose text is read back
      character(len=:), allocatable :: s  !< its text
      character(len=40) :: buf
      character(len=16) :: fmt
      character(len=:), allocatable :: mant, dig
      real(wp) :: y
      integer :: p, ios, epos, e, k

      do p = 1, 17
         write (fmt, '(a,i0,a)') '(es40.', p - 1, 'e3)'
         write (buf, fmt) x
         if (abs(x) > check_max) cycle
         read (buf, *, iostat=ios) y
         if (ios == 0) then
            if (y == x) exit
         end if
      end do
      buf = adjustl(buf)
      epos = index(buf, 'E')
      mant = trim(buf(:epos - 1))
      read (buf(epos + 1:), *) e
      dig = ''
      do k = 1, len(mant)
         if (index(digits10, mant(k:k)) > 0) dig = dig//mant(k:k)
      end do
      do while (len(dig) > 1)
         if (dig(len(dig):len(dig)) /= '0') exit
         dig = dig(:len(dig) - 1)
      end do
      if (e >= 0 .and. e < e_fixed) then
         if (len(dig) <= e + 1) then
            s = dig//repeat('0', e + 1 - len(dig))
         else
            s = dig(:e + 1)//'.'//dig(e + 2:)
         end if
      else if (e < 0 .and. e >= -4) then
         s = '0.'//repeat('0', -e - 1)//dig
      else
         s = dig(1:1)
         if (len(dig) > 1) s = s//'.'//dig(2:)
         s = s//'e'//int_str(e)
      end if
      if (x < 0.0_wp) s = '-'//s
   end function shortest_text

   !> Record an input error (the first one wins).
   pure subroutine fail(err, message)
      type(error_t), intent(inout) :: err      !< status
      character(len=*), intent(in) :: message  !< what is wrong
      if (err%code /= 0) return
      err%code = stat_input
      err%message = message
   end subroutine fail

   !> Upper-case copy of s (ASCII letters only).
   pure function upper_case(s) result(u)
      character(len=*), intent(in) :: s  !< text
      character(len=len(s)) :: u         !< the text in upper case
      integer :: k, c
      u = s
      do k = 1, len(s)
         c = iachar(s(k:k))
         if (c >= iachar('a') .and. c <= iachar('z')) u(k:k) = achar(c - 32)
      end do
   end function upper_case

   !> Integer as text.
   pure function int_str(i) result(s)
      integer, intent(in) :: i            !< the number
      character(len=:), allocatable :: s  !< its text
      character(len=24) :: buf
      write (buf, '(i0)') i
      s = trim(buf)
   end function int_str
end module rodyn_deck_params
