# SPDX-License-Identifier: LGPL-2.1-or-later
"""The one reader of viscoslide's CSV tables.

Every table the program writes (steady_state.csv, approach.csv,
history.csv, continuation.csv, surface profiles; doc/outputs.md) starts
with `#` comment lines that say how it was made, then a header row and
the data rows. Scripts and tests used to skip the comments and call
csv.DictReader each in their own way; this module is that reader, once.

Cells become floats where they parse (`nan` and `inf` included) and stay
strings otherwise (a case name, a status, an empty cell of a failed case).
`text=True` keeps every cell as written, for a script that copies a table
(scripts/units si) or shows a cell as the program wrote it.
Standard library only: the tests import it with any Python 3."""
import csv


def number(cell):
    """The cell as a float, or the cell unchanged when it is not a number."""
    try:
        return float(cell)
    except (TypeError, ValueError):
        return cell


def data_lines(path):
    """The lines of a table without its `#` comments (header first)."""
    with open(path) as f:
        return [line for line in f if not line.startswith('#')]


def read(path, text=False):
    """The rows of the table at path as dicts, column name -> cell."""
    rows = csv.DictReader(data_lines(path))
    if text:
        return list(rows)
    return [{k: number(v) for k, v in r.items()} for r in rows]


def read_reference(path, text=False):
    """The rows of one of the independent reference curves
    (shared/reference) in the program's spellings (the 2D curves write
    Vhat, Fhat and Lhat, the 3D ones F_hat), without the speeds 0 and inf
    (the elastic limits), which no run has."""
    rename = {'Vhat': 'V_hat', 'Fhat': 'F_n_hat', 'F_hat': 'F_n_hat', 'Lhat': 'L_hat'}
    rows = [{rename.get(k, k): v for k, v in r.items()} for r in read(path, text)]
    return [r for r in rows if 0 < float(r['V_hat']) < float('inf')]


def steady(row):
    """Whether a row is a converged steady state (steady = 1); a table
    without the column counts as steady."""
    return row.get('steady', 1) not in (0, '0')


def same_numbers(path_a, path_b, tolerance, floor=1e-12, require_rows=False):
    """Whether two tables hold the same rows: every number within tolerance
    relative (differences below floor absolute, round-off of quantities
    zero by symmetry, not counted), every word equal. A missing table has
    no rows; with require_rows an empty pair fails too. (ok, detail)."""
    a, b = (_rows_as_written(p) for p in (path_a, path_b))
    if len(a) != len(b) or (require_rows and not a):
        return False, f'{len(b)} rows against {len(a)}'
    worst = 0.
    for x, y in zip(a, b):
        for u, v in zip(x.strip().split(','), y.strip().split(',')):
            try:
                u, v = float(u), float(v)
            except ValueError:
                if u != v:
                    return False, f'{u} != {v}'
                continue
            if abs(u - v) > floor:
                worst = max(worst, abs(u - v) / max(abs(u), abs(v)))
    return worst <= tolerance, (f'{len(a)} rows, largest relative difference {worst:.1e} '
                                f'(tolerance {tolerance:g})')


def _rows_as_written(path):
    """The data lines of a table (no comments, no header); none if missing."""
    try:
        return data_lines(path)[1:]
    except OSError:
        return []
