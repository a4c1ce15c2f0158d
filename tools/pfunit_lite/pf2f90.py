#!/usr/bin/env python3
"""pf2f90.py - translate the pFUnit .pf subset used by rodyn into plain Fortran.

Usage:
    pf2f90.py INPUT.pf OUTPUT.F90 [--driver DRIVER.F90]
    pf2f90.py --driver DRIVER.F90 --driver-only A.pf [B.pf ...]

The first form writes the translated test module (and, with --driver, a driver program
running its tests).  The second form writes only a driver program that runs the tests of
several already translated modules, for an executable built from more than one .pf file.

Supported subset: one `module <file stem>` per file, `@test`, `@before`, `@after` before
argument-free subroutines, and the one-line assertions @assertEqual, @assertRelativelyEqual,
@assertLessThan, @assertLessThanOrEqual, @assertGreaterThan, @assertGreaterThanOrEqual,
@assertTrue, @assertFalse and @assertFail with `tolerance=` / `message=` keywords.
Each assertion becomes a call into module `funit` (tools/pfunit_lite/funit.f90) followed by
`if (funit_failed()) return`, so the first failing assertion ends the test.
"""

import argparse
import os
import re
import sys

MAX_COLS = 132                 # free-form line length limit
SUITE = 'funit_run_suite'      # generated module procedure running every test of a module

# directive -> (funit procedure, positional arguments, allowed keywords, op)
ASSERTS = {
    'assertEqual': ('funit_assert_equal', (2, 2), ('tolerance', 'message'), None),
    'assertRelativelyEqual': ('funit_assert_relatively_equal', (2, 2),
                              ('tolerance', 'message'), None),
    'assertLessThan': ('funit_assert_compare', (2, 2), ('message',), '<'),
    'assertLessThanOrEqual': ('funit_assert_compare', (2, 2), ('message',), '<='),
    'assertGreaterThan': ('funit_assert_compare', (2, 2), ('message',), '>'),
    'assertGreaterThanOrEqual': ('funit_assert_compare', (2, 2), ('message',), '>='),
    'assertTrue': ('funit_assert_true', (1, 1), ('message',), None),
    'assertFalse': ('funit_assert_false', (1, 1), ('message',), None),
    'assertFail': ('funit_fail', (0, 1), ('message',), None),
}
ASSERTS_LOWER = {key.lower(): value for key, value in ASSERTS.items()}
MARKERS = ('test', 'before', 'after')

RE_NAME = re.compile(r'^[A-Za-z]\w{0,62}$')
RE_BLANK_OR_COMMENT = re.compile(r'^\s*(!.*)?$')
RE_MODULE = re.compile(r'^\s*module\s+(\w+)\s*(!.*)?$', re.I)
RE_END_MODULE = re.compile(r'^\s*end\s*module\b\s*(\w*)\s*(!.*)?$', re.I)
RE_CONTAINS = re.compile(r'^\s*contains\s*(!.*)?$', re.I)
RE_TYPE_DEF = re.compile(r'^\s*type\s*(,|::|[A-Za-z])', re.I)     # not `type(t) :: x`
RE_END_TYPE = re.compile(r'^\s*end\s*type\b', re.I)
RE_USE_FUNIT = re.compile(r'^\s*use\s*(::)?\s*funit\s*(!.*)?$', re.I)
RE_SUBROUTINE = re.compile(
    r'^\s*((recursive|impure|module|non_recursive)\s+)*subroutine\s+(\w+)\s*'
    r'(\((.*)\))?\s*(!.*)?$', re.I)
RE_DIRECTIVE = re.compile(r'^(\s*)@(\w+)\s*(.*?)\s*$')
RE_KEYWORD = re.compile(r'^\s*([A-Za-z]\w*)\s*=(?!=)\s*(.*?)\s*$', re.S)


class PfError(Exception):
    """A problem in the .pf input, reported as FILE:LINE: error: MESSAGE."""

    def __init__(self, path, lineno, message):
        super().__init__(f'{path}:{lineno}: error: {message}')


def fstring(text):
    """Fortran character literal for text."""
    return "'" + text.replace("'", "''") + "'"


def split_args(text, path, lineno):
    """Split text, which starts with '(', into its top-level arguments.

    Returns (arguments, index just after the closing parenthesis)."""
    args, depth, quote, start, i = [], 0, None, 1, 0
    while i < len(text):
        ch = text[i]
        if quote:
            if ch == quote:
                if text[i + 1:i + 2] == quote:        # doubled quote inside a literal
                    i += 1
                else:
                    quote = None
        elif ch in '\'"':
            quote = ch
        elif ch in '([':
            depth += 1
        elif ch in ')]':
            depth -= 1
            if depth == 0:
                if ch != ')':
                    break
                args.append(text[start:i].strip())
                if args == ['']:
                    args = []
                if any(a == '' for a in args):
                    raise PfError(path, lineno, 'empty argument in directive')
                return args, i + 1
        elif ch == ',' and depth == 1:
            args.append(text[start:i].strip())
            start = i + 1
        elif ch == '!':
            break
        i += 1
    raise PfError(path, lineno, 'unbalanced parentheses, brackets or quotes in directive '
                  '(directives must fit on one line, without & continuation)')


def string_state(line):
    """inside[i] is True when the position just before line[i] lies inside a literal."""
    inside, quote, i = [False] * (len(line) + 1), None, 0
    while i < len(line):
        inside[i] = quote is not None
        ch = line[i]
        if quote:
            if ch == quote:
                if line[i + 1:i + 2] == quote:
                    inside[i + 1] = True
                    i += 1
                else:
                    quote = None
        elif ch in '\'"':
            quote = ch
        i += 1
    inside[len(line)] = quote is not None
    return inside


def wrap(line, width=MAX_COLS):
    """Split a generated free-form line into continuation lines of at most width columns.

    Breaks after a comma or blank outside literals when possible, otherwise inside a
    literal (between two non-blank characters); continuation lines start with '&', which
    is what a continued character context requires."""
    if len(line) <= width:
        return [line]
    inside = string_state(line)
    indent = ' ' * (len(line) - len(line.lstrip()) + 4)
    out, pos = [], 0
    while True:
        prefix = indent + '&' if out else ''
        if len(prefix) + len(line) - pos <= width:
            out.append(prefix + line[pos:])
            return out
        last = pos + width - len(prefix) - 1           # room for the trailing '&'
        nice, fallback = None, None
        for cut in range(last, pos + 1, -1):
            before, after = line[cut - 1], line[cut]
            if not inside[cut]:
                if before in ', ':
                    nice = cut
                    break
                fallback = fallback or cut
            elif before not in ' \'"' and after != ' ':
                fallback = fallback or cut
        cut = nice or fallback
        if cut is None:
            raise ValueError('cannot split generated line: ' + line)
        out.append(prefix + line[pos:cut] + '&')
        pos = cut


class Translator:
    """Translates one .pf file; collects the tests for the generated suite procedure."""

    def __init__(self, path):
        self.path = path
        self.fname = os.path.basename(path)
        self.stem = os.path.splitext(self.fname)[0]
        self.module = None
        self.tests = []                   # names of @test subroutines, in file order
        self.hooks = {'before': None, 'after': None}

    def error(self, lineno, message):
        raise PfError(self.path, lineno, message)

    def translate(self, lines):
        out = []
        state = 'head'                    # head -> spec -> body -> done
        in_type, pending = False, None
        # the generated code needs funit's public names even if the file lists `only:` ones
        need_use = not any(RE_USE_FUNIT.match(line) for line in lines)
        for lineno, raw in enumerate(lines, start=1):
            line = raw.rstrip('\r\n')
            is_filler = RE_BLANK_OR_COMMENT.match(line) or line.lstrip().startswith('#')
            if state == 'done':
                if not is_filler:
                    self.error(lineno, 'only one module per .pf file is supported')
                out.append(line)
                continue
            directive = RE_DIRECTIVE.match(line)
            if pending and not is_filler:
                if directive:
                    self.error(lineno, f'expected a subroutine after @{pending[0]} '
                                       f'(line {pending[1]})')
                self.mark_subroutine(pending[0], line, lineno)
                pending = None
                out.append(line)
                continue
            if directive:
                indent, name, rest = directive.groups()
                if state != 'body':
                    self.error(lineno, f'@{name} before the module\'s `contains`')
                low = name.lower()
                if low in MARKERS:
                    if rest:
                        self.error(lineno, f'@{name}{rest}: options of @{low} are not '
                                           'supported by pfunit-lite')
                    pending = (low, lineno)
                    out.append(f'{indent}! @{name}')
                else:
                    out.extend(self.assertion(indent, name, rest, lineno))
                continue
            if line.lstrip().startswith('@'):
                self.error(lineno, 'malformed directive')
            if state == 'head':
                if is_filler:
                    out.append(line)
                    continue
                m = RE_MODULE.match(line)
                if not m:
                    self.error(lineno, f'expected `module {self.stem}`')
                self.module = m.group(1)
                if self.module.lower() != self.stem.lower():
                    self.error(lineno, f'module {self.module} must be named like its file '
                                       f'({self.stem})')
                state = 'spec'
                out.append(line)
                if need_use:
                    out.append('   use funit')
                continue
            if state == 'spec':
                # `contains` of a derived type definition does not end the module's spec
                if not in_type and RE_TYPE_DEF.match(line):
                    in_type = True
                elif in_type and RE_END_TYPE.match(line):
                    in_type = False
                elif not in_type and RE_CONTAINS.match(line):
                    out.append(f'   public :: {SUITE}')
                    out.append(line)
                    state = 'body'
                    continue
            m = RE_END_MODULE.match(line)
            if m:
                if state != 'body':
                    self.error(lineno, 'the module has no `contains` (no tests)')
                if m.group(1) and m.group(1).lower() != self.module.lower():
                    self.error(lineno, f'`end module {m.group(1)}` does not match '
                                       f'`module {self.module}`')
                out.extend(self.suite())
                out.append(line)
                state = 'done'
                continue
            out.append(line)
        if pending:
            self.error(pending[1], f'@{pending[0]} is not followed by a subroutine')
        if state != 'done':
            self.error(len(lines), f'missing `end module {self.stem}`')
        if not self.tests:
            print(f'{self.path}: warning: no @test procedures', file=sys.stderr)
        return out

    def mark_subroutine(self, kind, line, lineno):
        m = RE_SUBROUTINE.match(line)
        if not m:
            self.error(lineno, f'@{kind} must be followed by a `subroutine name()` line')
        name, dummies = m.group(3), m.group(5)
        if dummies and dummies.strip():
            self.error(lineno, f'subroutine {name} takes arguments; pfunit-lite supports '
                               'only argument-free test procedures')
        if kind == 'test':
            if name.lower() in (t.lower() for t in self.tests):
                self.error(lineno, f'duplicate test {name}')
            self.tests.append(name)
        else:
            if self.hooks[kind]:
                self.error(lineno, f'more than one @{kind} procedure')
            self.hooks[kind] = name

    def assertion(self, indent, name, rest, lineno):
        spec = ASSERTS_LOWER.get(name.lower())
        if spec is None:
            self.error(lineno, f'@{name} is not supported by pfunit-lite (supported: '
                               + ', '.join('@' + k for k in MARKERS) + ' and the '
                               'assertions ' + ', '.join('@' + k for k in ASSERTS) + ')')
        proc, (nmin, nmax), keywords, op = spec
        if not rest.startswith('('):
            self.error(lineno, f'@{name} needs an argument list in parentheses')
        args, end = split_args(rest, self.path, lineno)
        if rest[end:].strip():
            self.error(lineno, f'unexpected text after @{name}(...): {rest[end:].strip()!r} '
                               '(pFUnit requires the directive to end the line)')
        positional, given = [], {}
        for arg in args:
            kw = RE_KEYWORD.match(arg)
            if kw:
                key = kw.group(1).lower()
                if key not in keywords:
                    self.error(lineno, f'@{name} does not accept keyword {kw.group(1)}= '
                                       f'(accepted: {", ".join(keywords)})')
                if key in given:
                    self.error(lineno, f'{key}= given twice')
                given[key] = kw.group(2)
            elif given:
                self.error(lineno, 'positional argument after a keyword argument')
            else:
                positional.append(arg)
        if name.lower() == 'assertfail' and positional and 'message' in given:
            self.error(lineno, '@assertFail takes one message')
        if not nmin <= len(positional) <= nmax:
            want = str(nmin) if nmin == nmax else f'{nmin} to {nmax}'
            extra = ' (pass tolerance= and message= as keywords)' if nmax == 2 else ''
            self.error(lineno, f'@{name} takes {want} positional argument(s), '
                               f'got {len(positional)}{extra}')
        if name.lower() == 'assertrelativelyequal' and 'tolerance' not in given:
            self.error(lineno, '@assertRelativelyEqual needs tolerance=')
        if name.lower() == 'assertfail' and positional:
            given['message'] = positional.pop()
        call = [fstring(self.fname), str(lineno), fstring(name + rest[:end])]
        if op:
            call.append(fstring(op))
        call.extend(positional)
        if 'tolerance' in given:
            call.append(f'tolerance=real({given["tolerance"]}, funit_rk)')
        if 'message' in given:
            call.append(f'message={given["message"]}')
        lines = wrap(f'{indent}call {proc}({", ".join(call)})')
        check = 'if (funit_failed()) return'
        if len(lines[-1]) + len(check) + 2 <= MAX_COLS:
            lines[-1] += '; ' + check
        else:
            lines.append(indent + check)
        return lines

    def suite(self):
        body = [f'   subroutine {SUITE}()', '      ! generated by pf2f90.py: runs each test']
        for test in self.tests:
            body.append(f'      call funit_start_test({fstring(self.fname)}, '
                        f'{fstring(self.module)}, {fstring(test)})')
            if self.hooks['before']:
                body.append(f'      call {self.hooks["before"]}()')
                body.append(f'      if (.not. funit_failed()) call {test}()')
            else:
                body.append(f'      call {test}()')
            if self.hooks['after']:
                body.append(f'      call {self.hooks["after"]}()')
            body.append('      call funit_end_test()')
        body.append(f'   end subroutine {SUITE}')
        body.append('')
        return [piece for line in body for piece in wrap(line)]


def driver(modules):
    """Text of a program running the suites of the given test modules."""
    lines = ['! generated by pf2f90.py: runs the tests of ' + ', '.join(modules),
             'program funit_driver',
             '   use funit, only: funit_init, funit_finish']
    for k, mod in enumerate(modules, start=1):
        lines.append(f'   use {mod}, only: suite_{k} => {SUITE}')
    lines += ['   implicit none', '   call funit_init()']
    lines += [f'   call suite_{k}()' for k in range(1, len(modules) + 1)]
    lines += ['   call funit_finish()', 'end program funit_driver']
    return '\n'.join(piece for line in lines for piece in wrap(line)) + '\n'


def write(path, text):
    """Write atomically so that a failed run never leaves a half-written output."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    tmp = path + '.tmp'
    with open(tmp, 'w', encoding='utf-8') as f:
        f.write(text)
    os.replace(tmp, path)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('files', nargs='+', help='INPUT.pf OUTPUT.F90, or with --driver-only '
                                             'the .pf files whose suites the driver runs')
    ap.add_argument('--driver', metavar='DRIVER.F90', help='also write a driver program')
    ap.add_argument('--driver-only', action='store_true',
                    help='write only the driver (needs --driver) for the given .pf files')
    opts = ap.parse_args(argv)
    try:
        if opts.driver_only:
            if not opts.driver:
                ap.error('--driver-only needs --driver DRIVER.F90')
            modules = [os.path.splitext(os.path.basename(p))[0] for p in opts.files]
            for path, mod in zip(opts.files, modules):
                if not RE_NAME.match(mod):
                    raise PfError(path, 1, f'{mod!r} is not a valid Fortran module name')
            write(opts.driver, driver(modules))
            return 0
        if len(opts.files) != 2:
            ap.error('expected INPUT.pf OUTPUT.F90')
        source, target = opts.files
        try:
            with open(source, encoding='utf-8') as f:
                lines = f.readlines()
        except OSError as exc:
            raise PfError(source, 0, f'cannot read: {exc.strerror}') from exc
        tr = Translator(source)
        text = '\n'.join(tr.translate(lines)) + '\n'
        write(target, f'! generated by pf2f90.py from {tr.fname}; do not edit\n' + text)
        if opts.driver:
            write(opts.driver, driver([tr.module]))
    except PfError as exc:
        print(exc, file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
