# SPDX-License-Identifier: LGPL-2.1-or-later
"""Compares two steady_state.csv files row by row (matched by V_hat and
load): prints, per speed, mu (the x force on the indenter over F_n),
mu_contact_set (the paper's eq. 2 over the contact set), mu_energy and
L_hat (A_hat in 3D) of both and their relative differences, e.g. the
finite-element and the boundary-element curve of one case
(doc/boundary_element.md), or a curve against one of the reference
curves in shared/reference (matched by V_hat alone: they are at one load,
spelt Vhat, Fhat and Lhat in 2D).

  scripts/compare_curves A/steady_state.csv B/steady_state.csv
  scripts/compare_curves output/sphere_friction/steady_state.csv \
      ../shared/reference/sphere_muT3_F1_R100.csv"""

import sys

from . import tables


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 2:
        sys.exit(__doc__)
    compare(*(tables.read_reference(path, text=True) for path in argv))


def compare(a, b):
    """Prints the rows of a and b that share V_hat and load, and the worst
    relative differences (cells as written: V_hat printed as in a)."""
    # The load that the control holds: delta under displacement control.
    # A reference curve has no control column: it is at one load, and its
    # rows are matched by the speed alone (to the digits the files share).
    if 'control' in a[0] and 'control' in b[0]:
        load = lambda r: 'delta_hat' if r['control'] == 'displacement' else 'F_n_hat'
        key = lambda r: (round(float(r['V_hat']), 9), round(float(r[load(r)]), 6))
    else:
        key = lambda r: float(f"{float(r['V_hat']):.5g}")
    b_rows = {key(r): r for r in b}
    # A file written before mu_contact_set existed has no such column.
    quantities = [q for q in ['mu', 'mu_contact_set', 'mu_energy', 'L_hat', 'A_hat']
                  if q in a[0] and q in b[0]]
    print('V_hat ' + ' '.join(f'{q}_A {q}_B diff' for q in quantities))
    worst = {q: 0. for q in quantities}
    for r in a:
        s = b_rows.get(key(r))
        if s is None:
            continue
        cells = []
        for q in quantities:
            va, vb = float(r[q]), float(s[q])
            d = vb / va - 1 if va != 0 else float('nan')
            worst[q] = max(worst[q], abs(d))
            cells.append(f'{va:.5g} {vb:.5g} {100 * d:+.2f}%')
        print(r['V_hat'], ' '.join(cells))
    print('largest |diff|: ' + ', '.join(f'{q} {100 * w:.2f} %' for q, w in worst.items()))


if __name__ == '__main__':
    main()
