# SPDX-License-Identifier: LGPL-2.1-or-later
"""doc/test_results.md, generated: what each test asserts, against what
reference, with what tolerance and what it measured, from the tests
themselves, so that the numbers cannot go stale.

    scripts/test_table [build folder] [output file]

Sources: tests/CMakeLists.txt (each test's label, numdiff class and check
script), the first paragraph of each check script's docstring (what it
asserts against what reference), and the check_summary.json each check
writes into its work folder (build/tests/NAME/) when it runs: every
assertion with its detail, the measured value against its tolerance.
A test that has not run in that build folder is listed as not run. Run
the labels first (scripts/run_tests quick, long, extended), then this."""
import ast
import datetime
import json
import os
import re
import subprocess
import sys

from .bench import ROOT

LABELS = ('quick', 'long', 'extended')


def declared_tests():
    """(name, label, tolerance class, check script) of each test, in the
    order of tests/CMakeLists.txt."""
    text = open(os.path.join(ROOT, 'tests', 'CMakeLists.txt')).read()
    tests = []
    for m in re.finditer(r'^viscoslide_add_test\((\w+)([^)]*)\)', text, re.M):
        options = m.group(2)
        option = lambda key: (re.search(key + r' (\w+)', options) or [None, None])[1]
        tests.append((m.group(1), option('LABEL'), option('TOLERANCE'),
                      option('CHECK') or m.group(1)))
    return tests


def first_paragraph(check):
    """The first paragraph of the check script's docstring, on one line."""
    path = os.path.join(ROOT, 'tests', check + '.check')
    doc = ast.get_docstring(ast.parse(open(path).read())) or ''
    return ' '.join(doc.split('\n\n')[0].split())


def cell(text):
    """Text fit for a Markdown table cell."""
    return ' '.join(str(text).split()).replace('|', '\\|')


def results(build, name):
    """The check's summary of the test's last run, None if it has not run."""
    path = os.path.join(build, 'tests', name, 'check_summary.json')
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f), datetime.datetime.fromtimestamp(os.path.getmtime(path))


def label_table(build, tests, label):
    lines = [f'## {label}', '', '| test | assertion | measured, reference and tolerance | result |',
             '|---|---|---|---|']
    for name, test_label, _, _ in tests:
        if test_label != label:
            continue
        found = results(build, name)
        if found is None:
            lines.append(f'| `{name}` | | not run in {cell(build)} | |')
            continue
        for r in found[0]['records']:
            if 'check' in r:
                lines.append(f"| `{name}` | {cell(r['check'])} | {cell(r['detail'])} | "
                             f"{'pass' if r['pass'] else '**FAIL**'} |")
    return lines + ['']


def checks_section(tests):
    lines = ['## What each check asserts', '',
             '| check | tests | asserts, against |', '|---|---|---|']
    checks = {}
    for name, _, tolerance, check in tests:
        checks.setdefault(check, []).append(f'`{name}` ({tolerance})')
    for check, names in checks.items():
        lines.append(f'| `tests/{check}.check` | {", ".join(names)} | {cell(first_paragraph(check))} |')
    return lines + ['']


def main(argv):
    build = os.path.abspath(argv[0]) if argv else os.path.join(ROOT, 'build')
    out = argv[1] if len(argv) > 1 else os.path.join(ROOT, 'doc', 'test_results.md')
    tests = declared_tests()
    commit = subprocess.run(['git', '-C', ROOT, 'rev-parse', '--short', 'HEAD'],
                            capture_output=True, text=True).stdout.strip()
    lines = ['# Test results (generated)', '',
             f'Written by `scripts/test_table` from the checks\' summaries in the build folder '
             f'(commit {commit} when written); do not edit. Each row is one assertion of a test: '
             'the detail is what its check measured, against which reference, with which '
             'tolerance (doc/tests.md says how the tests are made; the numdiff class, in '
             'parentheses below, how closely the stored summary is compared).', '']
    for label in LABELS:
        lines += label_table(build, tests, label)
    lines += checks_section(tests)
    with open(out, 'w') as f:
        f.write('\n'.join(lines))
    ran = sum(results(build, t[0]) is not None for t in tests)
    print(f'{out}: {ran} of {len(tests)} tests have results in {build}')


if __name__ == '__main__':
    main(sys.argv[1:])
