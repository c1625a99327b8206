"""Helpers shared by the tests' NAME.check scripts (standard library only)."""
import csv
import math
import os
import subprocess
import sys


def read_csv(path):
    """Rows of a viscoslide CSV as dicts of floats (strings left as is)."""
    with open(path) as f:
        lines = [l for l in f if not l.startswith('#')]
    rows = []
    for r in csv.DictReader(lines):
        row = {}
        for k, v in r.items():
            try:
                row[k] = float(v)
            except ValueError:
                row[k] = v
        rows.append(row)
    return rows


def run(viscoslide, prm_text, work_dir, name, nproc=1, mpiexec='mpirun'):
    """Writes NAME.prm into work_dir and runs viscoslide on it there."""
    prm = os.path.join(work_dir, name + '.prm')
    with open(prm, 'w') as f:
        f.write(prm_text)
    cmd = [viscoslide, '--overwrite', prm]
    if nproc > 1:
        cmd = [mpiexec, '-np', str(nproc)] + cmd
    p = subprocess.run(cmd, cwd=work_dir, capture_output=True, text=True)
    return p


class Checker:
    """Collects named checks; prints a numdiff-friendly summary."""

    def __init__(self):
        self.failed = []

    def value(self, name, v, digits=6):
        print(f'{name} = {v:.{digits}g}')

    def check(self, name, ok, detail):
        print(f'{name}: {"PASS" if ok else "FAIL"}')
        if not ok:
            self.failed.append(name)
            sys.stderr.write(f'{name} FAILED: {detail}\n')
        else:
            sys.stderr.write(f'{name}: {detail}\n')

    def finish(self):
        sys.exit(1 if self.failed else 0)
