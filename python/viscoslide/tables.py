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


def steady(row):
    """Whether a row is a converged steady state (steady = 1); a table
    without the column counts as steady."""
    return row.get('steady', 1) not in (0, '0')
