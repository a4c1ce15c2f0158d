#!/usr/bin/env python3
"""Unit tests of the pfunit-lite translator (tools/pfunit_lite/pf2f90.py).

Usage: test_pf2f90.py PATH/TO/pf2f90.py
"""

import importlib.util
import os
import re
import subprocess
import sys
import tempfile
import unittest

TRANSLATOR = None
pf2f90 = None

GOOD_HEAD = 'module test_bad\n   use funit\n   implicit none\ncontains\n'


class Translate(unittest.TestCase):

    def run_translator(self, text, name='test_bad.pf'):
        with tempfile.TemporaryDirectory() as tmp:
            src = os.path.join(tmp, name)
            with open(src, 'w', encoding='utf-8') as f:
                f.write(text)
            out = os.path.join(tmp, 'out.F90')
            run = subprocess.run([sys.executable, TRANSLATOR, src, out],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                 universal_newlines=True, check=False)
            generated = None
            if os.path.exists(out):
                with open(out, encoding='utf-8') as f:
                    generated = f.read()
            return run, generated

    def assert_error(self, text, lineno, fragment, name='test_bad.pf'):
        run, generated = self.run_translator(text, name)
        self.assertEqual(run.returncode, 1, run.stderr)
        self.assertIn(f'{name}:{lineno}: error: ', run.stderr)
        self.assertIn(fragment, run.stderr)
        self.assertIsNone(generated)

    def test_errors(self):
        body = '   @test\n   subroutine t()\n      {}\n   end subroutine t\nend module test_bad\n'
        self.assert_error(GOOD_HEAD + body.format('@assertIsNaN(x)'), 7, 'not supported')
        self.assert_error(GOOD_HEAD + body.format('@assertEqual(1, 2, 0.5)'), 7,
                          'as keywords')
        self.assert_error(GOOD_HEAD + body.format('@assertEqual(1, 2, tol=1)'), 7,
                          'keyword tol=')
        self.assert_error(GOOD_HEAD + body.format('@assertEqual(f(1, 2)'), 7, 'unbalanced')
        self.assert_error(GOOD_HEAD + body.format('@assertTrue(x) ! note'), 7,
                          'unexpected text')
        self.assert_error(GOOD_HEAD + body.format('@assertEqual(a, &'), 7, 'one line')
        self.assert_error(GOOD_HEAD + body.format('@assertRelativelyEqual(a, b)'), 7,
                          'tolerance=')
        self.assert_error(GOOD_HEAD + '   @test(npes=[1])\n   subroutine t()\n'
                          '   end subroutine t\nend module test_bad\n', 5, 'options')
        self.assert_error(GOOD_HEAD + '   @test\n   subroutine t(this)\n'
                          '   end subroutine t\nend module test_bad\n', 6, 'arguments')
        self.assert_error(GOOD_HEAD + '   @before\n   integer :: i\n', 6,
                          'subroutine')
        self.assert_error(GOOD_HEAD + 'end module test_bad\n', 1, 'named like its file',
                          name='test_other.pf')
        self.assert_error(GOOD_HEAD.replace('contains\n', '@assertTrue(.true.)\ncontains\n'),
                          4, 'contains')
        self.assert_error(GOOD_HEAD, 4, 'missing `end module')

    def test_generated_code(self):
        text = (GOOD_HEAD + '   @test\n   subroutine t()\n'
                "      @assertEqual(f(a, ')'), [1, 2], tolerance=1, message='x, ''y''')\n"
                '   end subroutine t\nend module test_bad\n')
        run, generated = self.run_translator(text)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertTrue(all(len(line) <= 132 for line in generated.splitlines()))
        generated = re.sub(r'&\n\s*&', '', generated)      # undo line continuation
        self.assertIn("call funit_assert_equal('test_bad.pf', 7, ", generated)
        self.assertIn("f(a, ')'), [1, 2], tolerance=real(1, funit_rk), message='x, ''y'''",
                      generated)
        self.assertIn('if (funit_failed()) return', generated)
        self.assertIn("call funit_start_test('test_bad.pf', 'test_bad', 't')", generated)


class Helpers(unittest.TestCase):

    def test_split_args(self):
        args, end = pf2f90.split_args("(a(1, 2), [3, 4], 'x, (y', \"q\"\"r, s\", m=1)", 'f', 1)
        self.assertEqual(args, ['a(1, 2)', '[3, 4]', "'x, (y'", '"q""r, s"', 'm=1'])
        self.assertEqual(end, 42)

    def test_wrap(self):
        for line in ['   call x(' + ', '.join(['abcdefgh'] * 40) + ')',
                     "   call y('" + 'word ' * 60 + "it''s', '" + 'z' * 200 + "')",
                     '   call z(' + 'q' * 300 + ')']:
            pieces = pf2f90.wrap(line)
            self.assertTrue(all(len(p) <= 132 for p in pieces))
            self.assertTrue(all(p.endswith('&') for p in pieces[:-1]))
            joined = pieces[0][:-1] + ''.join(p.lstrip()[1:-1] for p in pieces[1:-1])
            if len(pieces) > 1:
                joined += pieces[-1].lstrip()[1:]
            self.assertEqual(joined, line)


if __name__ == '__main__':
    sys.dont_write_bytecode = True          # keep the source tree free of __pycache__
    TRANSLATOR = os.path.abspath(sys.argv.pop(1))
    spec = importlib.util.spec_from_file_location('pf2f90', TRANSLATOR)
    pf2f90 = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(pf2f90)
    unittest.main(verbosity=2)
