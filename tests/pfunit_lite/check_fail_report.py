#!/usr/bin/env python3
"""Run the deliberately failing pfunit-lite test program and check its report.

Usage: check_fail_report.py EXECUTABLE TEST.pf

Checks that the program exits with status 1, that every assertion marked
`! expect-fail: TEXT | TEXT` in TEST.pf is reported as `TEST.pf:LINE: assertion failed: `
with each TEXT in its report, that no line marked `! not-reached` is reported, that each
failing test is named, and that the closing line `N passed, M failed` has the right counts.
"""

import os
import re
import subprocess
import sys


def main(exe, pf):
    fname = os.path.basename(pf)
    with open(pf, encoding='utf-8') as f:
        lines = f.read().splitlines()
    expected, unreached, n_tests, test = {}, [], 0, None
    for lineno, line in enumerate(lines, start=1):
        text = line.strip()
        if re.match(r'@test\s*$', text, re.I):
            n_tests += 1
        m = re.match(r'subroutine\s+(\w+)', text, re.I)
        if m:
            test = m.group(1)
        if text.startswith('! expect-fail'):
            wanted = text[len('! expect-fail'):].lstrip(':').strip()
            texts = [t.strip() for t in wanted.split(' | ') if t.strip()]
            expected[lineno + 1] = (test, texts)
        elif text.startswith('! not-reached'):
            unreached.append(lineno + 1)

    run = subprocess.run([exe], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         universal_newlines=True, check=False)
    out = run.stdout
    print(out)
    problems = []
    if run.returncode != 1:
        problems.append(f'exit status {run.returncode}, expected 1')

    # split the output into reports: a header line and its indented continuation lines
    reports, current = {}, None
    for line in out.splitlines():
        m = re.match(re.escape(fname) + r':(\d+): assertion failed: ', line)
        if m:
            current = int(m.group(1))
            reports.setdefault(current, []).append(line)
        elif current is not None and line.startswith(' '):
            reports[current].append(line)
        else:
            current = None
    for lineno, (test, texts) in sorted(expected.items()):
        if lineno not in reports:
            problems.append(f'no failure reported for {fname}:{lineno}: ({test})')
            continue
        report = '\n'.join(reports[lineno])
        for text in texts:
            if text not in report:
                problems.append(f'{fname}:{lineno}: report lacks {text!r}')
        if not re.search(r'^FAILED\s+\S*::' + test + r'\b', out, re.M):
            problems.append(f'test {test} not reported as FAILED')
    for lineno in sorted(set(reports) - set(expected)):
        problems.append(f'unexpected failure reported at {fname}:{lineno}')
    for lineno in unreached:
        if f'{fname}:{lineno}:' in out:
            problems.append(f'{fname}:{lineno}: evaluated after the test had failed')
    summary = f'{n_tests - len(expected)} passed, {len(expected)} failed'
    if not re.search('^' + summary + '$', out, re.M):
        problems.append(f'closing line {summary!r} not found')

    for problem in problems:
        print('CHECK FAILED: ' + problem)
    if not problems:
        print(f'check_fail_report: OK ({len(expected)} expected failures reported)')
    return 1 if problems else 0


if __name__ == '__main__':
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
