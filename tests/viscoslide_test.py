# SPDX-License-Identifier: LGPL-2.1-or-later
"""The harness of the tests' NAME.check scripts: the test's input
tests/NAME.prm (test_input), running viscoslide on a parameter text and a
numdiff-friendly summary (Checker). Tables are read
and parameter files changed by the viscoslide package (python/viscoslide:
tables.read, prm.override), which this module puts on sys.path from the
checkout it sits in, so the checks use that checkout's package whether or
not scripts/setup made it importable. Standard library only."""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'python'))
from viscoslide import prm, tables  # noqa: E402  (re-exported to the checks)

read_csv = tables.read


def test_input(work, source):
    """The text of the test's input, tests/NAME.prm in the tests' folder
    source (argv[4]), NAME the test's name: that of its work folder work
    (argv[1])."""
    name = os.path.basename(os.path.normpath(work))
    with open(os.path.join(source, name + '.prm')) as f:
        return f.read()


def run(viscoslide, prm_text, work_dir, name, nproc=1, mpiexec='mpirun', env=None):
    """Writes NAME.prm into work_dir and runs viscoslide on it there (in
    the environment env, default this process's)."""
    path = os.path.join(work_dir, name + '.prm')
    with open(path, 'w') as f:
        f.write(prm_text)
    cmd = [viscoslide, '--overwrite', path]
    if nproc > 1:
        cmd = [mpiexec, '-np', str(nproc)] + cmd
    return subprocess.run(cmd, cwd=work_dir, env=env, capture_output=True, text=True)


def retraction_pull_off(rows):
    """The pull-off under load control from the rows of a displacement-
    controlled retraction (approach.csv, phase 'retract'): the minimum of
    F_n_hat refined by the vertex of the parabola through it and its two
    neighbours. None when the minimum lies at an end (not passed)."""
    k = min(range(len(rows)), key=lambda i: rows[i]['F_n_hat'])
    if not 0 < k < len(rows) - 1:
        return None
    (x0, y0), (x1, y1), (x2, y2) = [(rows[i]['delta_hat'], rows[i]['F_n_hat'])
                                    for i in (k - 1, k, k + 1)]
    d = (x0 - x1) * (x0 - x2) * (x1 - x2)
    a = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / d
    b = (x2 * x2 * (y0 - y1) + x1 * x1 * (y2 - y0) + x0 * x0 * (y1 - y2)) / d
    return (y0 - a * x0 * x0 - b * x0) - b * b / (4 * a) if a > 0 else y1


class Checker:
    """Collects named checks; prints a numdiff-friendly summary, and at
    finish() writes every check with its detail (what was measured against
    which tolerance) to check_summary.json in the work folder (argv[1]),
    the source of the generated table doc/test_results.md
    (scripts/test_table)."""

    def __init__(self):
        self.failed = []
        self.records = []

    def value(self, name, v, digits=6):
        print(f'{name} = {v:.{digits}g}')
        self.records.append({'value': name, 'printed': f'{v:.{digits}g}'})

    def check(self, name, ok, detail):
        print(f'{name}: {"PASS" if ok else "FAIL"}')
        self.records.append({'check': name, 'pass': bool(ok), 'detail': str(detail)})
        if not ok:
            self.failed.append(name)
            sys.stderr.write(f'{name} FAILED: {detail}\n')
        else:
            sys.stderr.write(f'{name}: {detail}\n')

    def finish(self):
        work = sys.argv[1] if len(sys.argv) > 1 else ''
        if os.path.isdir(work):
            with open(os.path.join(work, 'check_summary.json'), 'w') as f:
                json.dump({'failed': self.failed, 'records': self.records}, f, indent=1)
        sys.exit(1 if self.failed else 0)
