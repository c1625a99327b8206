"""Mesh-refinement studies of the steady-state finite elements against the
independent reference curves (../shared/reference/, beside the checkout):
the error of mu and L_hat at three mesh levels, the differences between
levels and the observed order, from which the tests' tolerances are argued
(doc/tests.md).

    scripts/convergence [hunter|adhesive|all]

A level halves every cell: the finest surface cell and the grading
(cell size per distance from the contact edges) together. Each study
starts from a test's input (its block, load and speeds) and runs the
finite elements alone at a few of the reference's speeds. Printed per
speed and level: mu, its error against the reference, the change from
the previous level, and the observed order p = log2(d1/d2) from the last
two changes; the same for L_hat where the reference has it. Runs go to a
temporary folder (named at the end); viscoslide's progress lines are
shown on standard error as they come, one every 10 s.

The speeds stop at 100 where the reference's own period error (1e-3 in
mu at V_hat 1000, its README) would hide the mesh's, and the block is
the one the tests' whole curves get (widened for V_hat 1000)."""
import math
import os
import subprocess
import sys
import tempfile
import time

from . import prm, tables
from .bench import ROOT, VISCOSLIDE, prepare


# name: (input, reference file, speeds, levels as (finest cell, grading),
# other entries). The block is the one the test's whole speed list gets
# (Geometry/Wake lengths widens it for the fastest speed), so that the
# study measures the test's mesh, not a smaller block.
STUDIES = {
    'hunter': ('tests/reference_hunter.prm', 'hunter_adhesionless.csv',
               ['1', '63.095734448', '1000'], [(16, 0.5), (8, 0.25), (4, 0.125)], {}),
    'adhesive': ('tests/reference_halfplane_muT6p08.prm', 'halfplane_muT6p08_F1.csv',
                 ['0.01', '0.1', '1', '10', '100'], [(2, 0.5), (1, 0.25), (0.5, 0.125)],
                 {'Geometry/Domain width': 200000, 'Geometry/Domain height': 50000}),
    'adhesive_muT1': ('tests/reference_halfplane_muT1.prm', 'halfplane_muT1_F1.csv',
                      ['0.01', '0.1', '10', '100'], [(4, 0.5), (2, 0.25), (1, 0.125)],
                      {'Geometry/Domain width': 200000, 'Geometry/Domain height': 50000}),
}


def run_level(viscoslide, source, work, name, speeds, cell, grading, other):
    """viscoslide on source at one mesh level, finite elements only: the
    rows of its steady_state.csv."""
    out = os.path.join(work, name)
    path = prm.override_file(source, out + '.prm', {
        'Output/Output directory': out, 'Sliding/Solver': 'steady-state',
        'Sweep/Solvers': None, 'Sliding/Sliding speed': ', '.join(speeds),
        'Mesh/Finest surface cell': cell, 'Mesh/Mesh grading': grading, **other})
    start, last = time.time(), 0.
    with open(out + '.log', 'w') as log:
        p = subprocess.Popen([viscoslide, path], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
        for line in p.stdout:
            log.write(line)
            if time.time() - last > 10:
                last = time.time()
                print(f'  {name}: {line.strip()[:110]}', file=sys.stderr, flush=True)
    if p.wait():
        sys.exit(f'convergence: {name} failed, see {out}.log')
    print(f'  {name}: done in {time.time() - start:.0f} s', file=sys.stderr, flush=True)
    return tables.read(os.path.join(out, 'steady_state.csv'))


def order(values):
    """Observed order from three levels' values, nan where the changes do
    not shrink monotonically."""
    d1, d2 = values[1] - values[0], values[2] - values[1]
    if d2 == 0 or d1 / d2 <= 1:
        return math.nan
    return math.log2(d1 / d2)


def report(quantity, levels, values, reference):
    """One line per level: value, error against the reference, change."""
    for k, ((cell, grading), v) in enumerate(zip(levels, values)):
        change = f'{v / values[k - 1] - 1:+.3e}' if k else ''
        print(f'    {quantity:<6} cell {cell:<4g} grading {grading:<6g} {v:.6g}  '
              f'error {v / reference - 1:+.3e}  change {change}')
    print(f'    {quantity:<6} observed order {order(values):.2f}')


def measure(name, work, viscoslide=VISCOSLIDE, root=ROOT):
    """Runs the study's levels: {(V_hat, quantity): (values per level,
    reference)} for mu and, where the reference has it, L_hat."""
    source, reference_file, speeds, levels, other = STUDIES[name]
    reference = {round(r['Vhat'], 6): r for r in
                 tables.read(os.path.join(root, '..', 'shared', 'reference', reference_file))}
    results = [run_level(viscoslide, os.path.join(root, source), work,
                         f'{name}_level{k}', speeds, *level, other)
               for k, level in enumerate(levels)]
    found = {}
    for i, v in enumerate(speeds):
        ref = reference[round(float(v), 6)]
        found[float(v), 'mu'] = ([r[i]['mu'] for r in results], ref['mu'])
        if 'Lhat' in ref:
            found[float(v), 'L_hat'] = ([r[i]['L_hat'] for r in results], ref['Lhat'])
    return found


def study(name, work):
    source, reference_file, _, levels, _ = STUDIES[name]
    found = measure(name, work)
    print(f'{name}: {source} against {reference_file}')
    for (V, quantity), (values, reference) in found.items():
        if quantity == 'mu':
            print(f'  V_hat {V:g}')
        report(quantity, levels, values, reference)


def main(argv):
    prepare()
    names = list(STUDIES) if not argv or argv[0] == 'all' else argv
    unknown = [n for n in names if n not in STUDIES]
    if unknown:
        sys.exit(f'convergence: unknown study {unknown[0]!r}; choose from {", ".join(STUDIES)} or all')
    work = tempfile.mkdtemp(prefix='viscoslide-convergence-')
    for name in names:
        study(name, work)
    print(f'outputs and logs in {work}')


if __name__ == '__main__':
    main(sys.argv[1:])
