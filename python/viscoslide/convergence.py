# SPDX-License-Identifier: LGPL-2.1-or-later
"""Mesh-refinement studies of the steady-state finite elements against the
independent reference curves (../shared/reference/, beside the checkout):
the error of mu and L_hat at three mesh levels, the differences between
levels and the observed order, from which the tests' tolerances are argued
(doc/tests.md).

    scripts/convergence [hunter|adhesive|adhesive_muT1|sphere|sphere_fem|dissipation|all]

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
the one the tests' whole curves get (widened for V_hat 1000).

`sphere` has no reference curve: the 3D boundary elements of
parameter_files/sphere_friction.prm on grids of 1, 0.5 (the file's) and
0.25 eps in its 160-eps window, and on the file's grid in a 240-eps
window. Printed per speed: mu and A_hat per grid, the observed order, the
difference of each grid from Richardson's value, extrapolated from the
three at their observed order, the change with the window, and the
energy balance mu_energy/mu - 1 per grid.

`sphere_fem` measures the 3D finite elements against the 3D boundary
elements: the adhesive sphere of tests/sphere_fem_adhesive.prm (R_hat 100,
Tabor parameter 1, F_hat 1) at V_hat 0.01 and 0.316, the boundary
elements on grids of 2, 1, 0.5 and 0.25 eps (one process) and the finite
elements at the levels of SPHERE_FEM (two processes; the 2-eps level and
the one graded by 0.5 hold half a million unknowns each and take 52 and 36
minutes, the whole study about an hour and a half). Printed per speed:
mu and A_hat of each grid, Richardson's value from the last three, and
each finite-element level's difference from it; the energy balance per
level.

`dissipation` has no reference curve either: where Fig. 5's steady states
(parameter_files/fig05_dissipation_maps.prm, V_hat 1 and 50) dissipate,
at the levels (finest cell, grading) of DISSIPATION: the first three
halve both, the last refines the bulk alone (grading 0.0625: cells of
31 eps under the contact's middle, of 10 eps within 160 eps of its ends,
against V tau_c = 10 eps at V_hat 1). Printed per speed and level: the
total dissipation per sliding distance and its shares within 10 eps of
the surface, behind the apex and in the bulk under the contact
(viscoslide.claims.dissipation_shares, on the written field), with the
change from the previous level."""
import math
import os
import subprocess
import sys
import tempfile
import time

from . import prm, tables
from .bench import ROOT, SPHERE_FEM_BEM, VISCOSLIDE, prepare


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


# The sphere's study: speeds, grids (finest surface cell, twice the
# spacing) and the larger window.
SPHERE = ('parameter_files/sphere_friction.prm', ['1', '10', '100'], [2, 1, 0.5], 240)


# The 3D finite elements' study: the adhesive sphere (R_hat 100, Tabor
# parameter 1, F_hat 1) at two speeds, the finite elements at the levels
# (finest surface cell, grading) and the boundary elements on grids of half
# the finest cells given, the last three extrapolated as the reference.
SPHERE_FEM = ('tests/sphere_fem_adhesive.prm', ['0.01', '0.316227766'],
              [(4, 1), (2, 1), (4, 0.5)], [4, 2, 1, 0.5])


# Fig. 5's study: its input and the levels (finest surface cell, grading).
DISSIPATION = ('parameter_files/fig05_dissipation_maps.prm',
               [(2, 0.5), (1, 0.25), (0.5, 0.125), (1, 0.0625)])


def run_level(viscoslide, source, work, name, speeds, cell, grading, other, procs=1,
              mpiexec='mpirun'):
    """viscoslide on source at one mesh level, by the finite elements
    unless `other` names another solver: the rows of its
    steady_state.csv. With VISCOSLIDE_CHECK_ONLY set (a check run by hand
    in a work folder that holds the levels' output), the
    level's earlier output is read instead of running it again."""
    out = os.path.join(work, name)
    if os.environ.get('VISCOSLIDE_CHECK_ONLY'):
        return tables.read(os.path.join(out, 'steady_state.csv'))
    path = prm.override_file(source, out + '.prm', {
        'Output/Output directory': out, 'Sliding/Solver': 'steady-state',
        'Sweep/Solvers': None, 'Sliding/Sliding speed': ', '.join(speeds),
        'Mesh/Finest surface cell': cell, 'Mesh/Mesh grading': grading, **other})
    start, last = time.time(), 0.
    with open(out + '.log', 'w') as log:
        command = ([mpiexec, '-np', str(procs)] if procs > 1 else []) + [viscoslide, path]
        p = subprocess.Popen(command, stdout=subprocess.PIPE,
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
    reference = {round(r['V_hat'], 6): r for r in
                 tables.read_reference(os.path.join(root, '..', 'shared', 'reference', reference_file))}
    results = [run_level(viscoslide, os.path.join(root, source), work,
                         f'{name}_level{k}', speeds, *level, other)
               for k, level in enumerate(levels)]
    found = {}
    for i, v in enumerate(speeds):
        ref = reference[round(float(v), 6)]
        found[float(v), 'mu'] = ([r[i]['mu'] for r in results], ref['mu'])
        if 'L_hat' in ref:
            found[float(v), 'L_hat'] = ([r[i]['L_hat'] for r in results], ref['L_hat'])
    return found


def study(name, work):
    source, reference_file, _, levels, _ = STUDIES[name]
    found = measure(name, work)
    print(f'{name}: {source} against {reference_file}')
    for (V, quantity), (values, reference) in found.items():
        if quantity == 'mu':
            print(f'  V_hat {V:g}')
        report(quantity, levels, values, reference)


def extrapolated(values):
    """Richardson's value from three levels at their observed order (nan
    where the changes do not shrink)."""
    p = order(values)
    return values[2] + (values[2] - values[1]) / (2 ** p - 1)


def measure_sphere(work, viscoslide=VISCOSLIDE, root=ROOT):
    """The sphere's study: {(V_hat, quantity): values} with quantity mu,
    A_hat and balance (mu_energy/mu - 1) per grid, and mu_window,
    A_hat_window in the larger window on the file's grid."""
    source, speeds, cells, window = SPHERE
    # the uniform grid's convergence (the file's own grid is the nested one)
    other = {'Sliding/Solver': 'boundary-element', 'Boundary element/Grid': 'uniform'}
    path = os.path.join(root, source)
    results = [run_level(viscoslide, path, work, f'sphere_grid{k}', speeds, cell, 0.25, other)
               for k, cell in enumerate(cells)]
    wide = run_level(viscoslide, path, work, 'sphere_window', speeds, cells[1], 0.25,
                     {**other, 'Geometry/Domain width': window})
    found = {}
    for i, v in enumerate(speeds):
        V = float(v)
        found[V, 'mu'] = [r[i]['mu'] for r in results]
        found[V, 'A_hat'] = [r[i]['A_hat'] for r in results]
        found[V, 'balance'] = [r[i]['mu_energy'] / r[i]['mu'] - 1 for r in results]
        found[V, 'mu_window'] = wide[i]['mu']
        found[V, 'A_hat_window'] = wide[i]['A_hat']
    return found


def sphere_study(work):
    source, speeds, cells, window = SPHERE
    found = measure_sphere(work)
    print(f'sphere: {source}, grids of {", ".join(f"{c / 2:g}" for c in cells)} eps, '
          f'windows 160 and {window} eps')
    for v in speeds:
        V = float(v)
        print(f'  V_hat {V:g}')
        for quantity in ('mu', 'A_hat'):
            values, best = found[V, quantity], extrapolated(found[V, quantity])
            for cell, value in zip(cells, values):
                print(f'    {quantity:<6} grid {cell / 2:<5g} {value:.6g}  '
                      f'from extrapolated {value / best - 1:+.3e}')
            print(f'    {quantity:<6} observed order {order(values):.2f}; window {window}: '
                  f'{found[V, quantity + "_window"] / values[1] - 1:+.3e}')
        print('    balance ' + ', '.join(f'{b:+.3e}' for b in found[V, 'balance']))


def measure_sphere_fem(work, viscoslide=VISCOSLIDE, root=ROOT, levels=None, cells=None,
                       mpiexec='mpirun'):
    """The 3D finite elements' study: {(V_hat, quantity): values} with
    quantity mu, A_hat and balance per FEM level, and bem_mu, bem_A_hat per
    boundary-element grid; the levels and grids SPHERE_FEM's unless
    given."""
    source, speeds, all_levels, all_cells = SPHERE_FEM
    levels, cells = levels or all_levels, cells or all_cells
    path = os.path.join(root, source)
    grids = [run_level(viscoslide, path, work, f'sphere_fem_grid{k}', speeds, cell, None,
                       SPHERE_FEM_BEM)
             for k, cell in enumerate(cells)]
    fem = {'Sliding/Viscous strain degree': 1, 'Solver/Linear solver': None}
    results = [run_level(viscoslide, path, work, f'sphere_fem_level{k}', speeds, cell,
                         grading, fem, procs=2, mpiexec=mpiexec)
               for k, (cell, grading) in enumerate(levels)]
    found = {}
    for i, v in enumerate(speeds):
        V = float(v)
        for quantity in ('mu', 'A_hat'):
            found[V, quantity] = [r[i][quantity] for r in results]
            found[V, 'bem_' + quantity] = [g[i][quantity] for g in grids]
        found[V, 'balance'] = [r[i]['mu_energy'] / r[i]['mu'] - 1 for r in results]
    return found


def sphere_fem_study(work):
    source, speeds, levels, cells = SPHERE_FEM
    found = measure_sphere_fem(work)
    print(f'sphere_fem: {source}, finite elements at (finest cell, grading) {levels} on '
          f'two processes, boundary elements on grids of '
          f'{", ".join(f"{c / 2:g}" for c in cells)} eps')
    for v in speeds:
        V = float(v)
        print(f'  V_hat {V:g}')
        for quantity in ('mu', 'A_hat'):
            grid = found[V, 'bem_' + quantity]
            best = extrapolated(grid[-3:])
            for cell, value in zip(cells, grid):
                print(f'    {quantity:<6} BEM grid {cell / 2:<5g} {value:.6g}  '
                      f'from extrapolated {value / best - 1:+.3e}')
            print(f'    {quantity:<6} BEM observed order {order(grid[-3:]):.2f}, '
                  f'extrapolated {best:.6g}')
            for (cell, grading), value in zip(levels, found[V, quantity]):
                print(f'    {quantity:<6} FEM cell {cell:<4g} grading {grading:<4g} {value:.6g}  '
                      f'from extrapolated BEM {value / best - 1:+.3e}')
        print('    FEM balance ' + ', '.join(f'{b:+.3e}' for b in found[V, 'balance']))


SHARES = ('surface', 'trailing', 'bulk_under_contact')


def measure_dissipation(work, viscoslide=VISCOSLIDE, root=ROOT):
    """Fig. 5's study: {(V_hat, quantity): values per level} for the total
    dissipation per sliding distance and the SHARES."""
    from . import claims
    source, levels = DISSIPATION
    found = {}
    for k, (cell, grading) in enumerate(levels):
        name = f'dissipation_level{k}'
        rows = run_level(viscoslide, os.path.join(root, source), work, name, ['1', '50'],
                         cell, grading, {})
        for i, r in enumerate(rows):
            d = claims.dissipation_shares(os.path.join(work, name), i, r['R_hat'])
            found.setdefault((r['V_hat'], 'per_distance'), []).append(d['total'] / r['V_hat'])
            for share in SHARES:
                found.setdefault((r['V_hat'], share), []).append(d[share])
    return found


def dissipation_study(work):
    source, levels = DISSIPATION
    found = measure_dissipation(work)
    print(f'dissipation: {source}, levels (finest cell, grading) {levels}')
    for V in sorted({V for V, _ in found}):
        print(f'  V_hat {V:g}')
        for quantity in ('per_distance',) + SHARES:
            values = found[V, quantity]
            print(f'    {quantity:<18} ' + '  '.join(
                f'{v:.4g}' + (f' ({v / values[k - 1] - 1:+.1%})' if k else '')
                for k, v in enumerate(values)))


# The studies without a reference curve.
OWN = {'sphere': sphere_study, 'sphere_fem': sphere_fem_study,
       'dissipation': dissipation_study}


def main(argv):
    prepare()
    names = list(STUDIES) + list(OWN) if not argv or argv[0] == 'all' else argv
    unknown = [n for n in names if n not in STUDIES and n not in OWN]
    if unknown:
        sys.exit(f'convergence: unknown study {unknown[0]!r}; choose from '
                 f'{", ".join(list(STUDIES) + list(OWN))} or all')
    work = tempfile.mkdtemp(prefix='viscoslide-convergence-')
    for name in names:
        OWN[name](work) if name in OWN else study(name, work)
    print(f'outputs and logs in {work}')


if __name__ == '__main__':
    main(sys.argv[1:])
