# SPDX-License-Identifier: LGPL-2.1-or-later
"""The benchmarks of doc/benchmark.md (not tests): viscoslide run on a
parameter file with a few entries changed, timed, and its tables
summarised. Each benchmark was a bash script with a sed edit of the file
and an inline Python summary; here they share the checkout, the timed
run, the edit (viscoslide.prm) and the reader (viscoslide.tables).

    scripts/bench [prm]                        approach()
    scripts/bench_sliding [solver] [prm] ["V_hat list"] ["procs"]
                                               sliding()
    scripts/bench_curve ["transient speeds"] [n_speeds] [prm] [V_min] [V_max]
                                               curve()
    scripts/bench_steady_curve [F_hat] [muT] [finest cell] [procs] [reference csv] [keep csv as]
                                               steady_curve()
    scripts/bench_sphere [R_hat]               sphere_curve()
    scripts/bench_nested [grid] [refinement] ["V_hat list" | file] ["entry=value; ..."]
                                               nested_curve()
    scripts/bench_fem3d [meshes] [solvers] [procs]
                                               fem3d()
    scripts/bench_fem3d_curve [procs] [muT] [linear solver]
                                               fem3d_curve()
    scripts/bench_transient [jobs] [prm ...]   transient_agreement()

Each runs in the checkout (paths are relative to it, as the scripts'
`cd` made them), builds it first with scripts/setup if there is no
build/viscoslide, and lets mpirun run as root."""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

from . import prm, tables

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# The program measured: this checkout's build, or another build named by the
# environment's VISCOSLIDE_PROGRAM (old against new in one run:
# scripts/bench_builds).
VISCOSLIDE = os.environ.get('VISCOSLIDE_PROGRAM', 'build/viscoslide')


def prepare():
    """Into the checkout, built, with mpirun allowed to run as root."""
    os.chdir(ROOT)
    if not os.access(VISCOSLIDE, os.X_OK):
        subprocess.run(['scripts/setup'], check=True)
    os.environ.update(OMPI_ALLOW_RUN_AS_ROOT='1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM='1')


def timed_run(command, log):
    """Runs command with its output into the file log: (exit code, wall s)."""
    start = time.time()
    with open(log, 'w') as f:
        code = subprocess.run(command, stdout=f, stderr=subprocess.STDOUT).returncode
    return code, time.time() - start


def mpirun(np, path):
    return ['mpirun', '-np', str(np), VISCOSLIDE, path]


def rows(path, text=True):
    """The table's rows (cells as written), none where there is no table."""
    return tables.read(path, text=text) if os.path.exists(path) else []


def approach(argv):
    """The main example on 1 and 2 MPI processes: wall time, final n_dofs,
    steps and Newton iterations per step."""
    prepare()
    source = argv[0] if argv else 'parameter_files/approach_hold_retract.prm'
    work = tempfile.mkdtemp()
    print(f"{'procs':<6} {'wall_s':>10} {'n_dofs':>8} {'steps':>6} {'newton/step':>14}")
    for np in (1, 2):
        path = prm.override_file(source, os.path.join(work, 'run.prm'),
                                 {'Output/Output directory': f'{work}/np{np}'})
        code, wall = timed_run(mpirun(np, path), os.path.join(work, f'np{np}.log'))
        if code:
            sys.exit(code)
        r = rows(os.path.join(work, f'np{np}', 'approach.csv'))
        its = sum(int(x['newton_iterations']) for x in r)
        print(f"{np:<6} {wall:10.1f} {r[-1]['n_dofs']:>8} {len(r):6d} {its / len(r):14.1f}")
    shutil.rmtree(work)


def sliding(argv):
    """Steady sliding per V_hat and process count: sliding distance and
    steps to steady state, n_dofs, Newton iterations per step, wall time,
    the steady mu and L_hat."""
    prepare()
    solver = argv[0] if len(argv) > 0 else 'transient'
    source = argv[1] if len(argv) > 1 else 'parameter_files/bench_sliding_transient.prm'
    speeds = (argv[2] if len(argv) > 2 else '0.1 1 10 100').split()
    procs = (argv[3] if len(argv) > 3 else '1 2').split()
    work = tempfile.mkdtemp()
    print(f"{'solver':<13} {'V_hat':>7} {'procs':>5} {'distance':>12} {'steps':>6} {'n_dofs':>8} "
          f"{'newton/step':>12} {'wall_s':>9} {'mu':>10} {'L_hat':>10} {'steady':>6}")
    for v in speeds:
        for np in procs:
            out = f'{work}/V{v}-np{np}'
            path = prm.override_file(source, os.path.join(work, 'run.prm'),
                                     {'Output/Output directory': out, 'Sliding/Sliding speed': v,
                                      'Sliding/Solver': solver})
            _, wall = timed_run(mpirun(np, path), out + '.log')
            ss = rows(os.path.join(out, 'steady_state.csv'))
            # transient: one history row per time step; steady-state: one
            # continuation row per speed (its steps are the continuation steps)
            hist = rows(os.path.join(out, 'history.csv')) or rows(os.path.join(out, 'continuation.csv'))
            steps = len(hist)
            its = sum(int(r['newton_iterations']) for r in hist) / steps if steps else float('nan')
            dofs = hist[-1]['n_dofs'] if hist else '-'
            if ss:
                r = ss[0]
                print(f"{solver:<13} {v:>7} {np:>5} {float(r['sliding_distance_over_eps']):12.0f} "
                      f"{steps:6d} {dofs:>8} {its:12.1f} {wall:9.1f} {float(r['mu']):10.4g} "
                      f"{float(r['L_hat']):10.4g} {r['steady']:>6}")
            else:
                print(f"{solver:<13} {v:>7} {np:>5} failed: see {out}.log")
    print(f'logs and outputs in {work}')


def log_speeds(n, vmin, vmax):
    """n speeds evenly spaced in log V_hat from vmin to vmax, 4 digits."""
    a, b = math.log10(vmin), math.log10(vmax)
    return ['%.4g' % (10 ** (a + (b - a) * k / (n - 1))) for k in range(n)]


def curve(argv):
    """One mu(V_hat) curve by the steady-state solver (one run along all
    speeds) against the transient solver (one run per listed speed): mu
    and L_hat of both per speed, their differences, the wall times and
    their ratio."""
    prepare()
    n = int(argv[1]) if len(argv) > 1 else 25
    source = argv[2] if len(argv) > 2 else 'parameter_files/bench_sliding.prm'
    vmin = float(argv[3]) if len(argv) > 3 else 0.01
    vmax = float(argv[4]) if len(argv) > 4 else 1000
    speeds = log_speeds(n, vmin, vmax)
    transient = argv[0].split() if argv else speeds  # "" : steady-state only
    work = tempfile.mkdtemp()
    wall = {}

    def run(name, solver, v):
        path = prm.override_file(source, os.path.join(work, name + '.prm'),
                                 {'Output/Output directory': f'{work}/{name}',
                                  'Sliding/Sliding speed': v, 'Sliding/Solver': solver})
        wall[name] = timed_run([VISCOSLIDE, path], os.path.join(work, name + '.log'))[1]

    run('steady', 'steady-state', ', '.join(speeds))
    for v in transient:
        run('transient_' + v, 'transient', v)
    print_curve(work, n, transient, wall)


def print_curve(work, n, speeds, wall):
    table = lambda d: rows(os.path.join(work, d, 'steady_state.csv'))
    steady = table('steady')
    t_steady = wall['steady']
    print(f"steady-state: {len(steady)} speeds (of {n}) in {t_steady:.0f} s, "
          f"{sum(r['steady'] == '1' for r in steady)} converged")
    print(f"{'V_hat':>9} {'mu_ss':>10} {'mu_tr':>10} {'dmu':>8} {'L_ss':>9} {'L_tr':>9} {'dL':>8} {'tr_steady':>9} {'tr_wall_s':>9}")
    t_tr = 0.
    for v in speeds:
        tr = table('transient_' + v)
        t_tr += wall['transient_' + v]
        ss = [r for r in steady if abs(float(r['V_hat']) / float(v) - 1) < 1e-3]
        if not tr or not ss:
            print(f"{v:>9} missing (see {work})")
            continue
        a, b = ss[0], tr[0]
        dmu = float(b['mu']) / float(a['mu']) - 1
        dL = float(b['L_hat']) / float(a['L_hat']) - 1
        print(f"{v:>9} {float(a['mu']):10.5g} {float(b['mu']):10.5g} {dmu:8.2%} {float(a['L_hat']):9.5g} "
              f"{float(b['L_hat']):9.5g} {dL:8.2%} {b['steady']:>9} {wall['transient_' + v]:9.0f}")
    if speeds:
        if len(speeds) == n:
            print(f"whole curve: transient {t_tr:.0f} s, steady-state {t_steady:.0f} s, ratio {t_tr / t_steady:.1f}")
        else:
            print(f"transient at {len(speeds)} of {n} speeds only: {t_tr / len(speeds):.0f} s per speed, "
                  f"steady-state {t_steady / n:.0f} s per speed (whole curve / {n}); "
                  f"ratio per speed {t_tr / len(speeds) / (t_steady / n):.1f} (an estimate of the "
                  f"whole-curve ratio, not a measurement of it)")
    print(f"outputs and logs in {work}")


def steady_curve(argv):
    """One mu(V_hat) curve of the Fig. 9b study at one load by the
    steady-state solver, approach included: the wall time, the solver's
    timer sections and, given a reference steady_state.csv, the largest
    relative change of each column against it. The environment may set
    GRADING (Mesh/Mesh grading), SPEEDS (Sliding/Sliding speed) and
    LINEAR_SOLVER (Solver/Linear solver: with 'iterative' the last
    station's line counts GMRES's solves and iterations)."""
    prepare()
    load, muT, cell, np, reference, keep = (argv + ['0.134', '6.08', '1', '1', '', ''][len(argv):])[:6]
    work = tempfile.mkdtemp()
    changes = {'Output/Output directory': f'{work}/out', 'Sweep/Loads': load,
               'Adhesion/Tabor parameter': muT, 'Mesh/Finest surface cell': cell}
    if os.environ.get('GRADING'):
        changes['Mesh/Mesh grading'] = os.environ['GRADING']
    if os.environ.get('SPEEDS'):
        changes['Sliding/Sliding speed'] = os.environ['SPEEDS']
    if os.environ.get('LINEAR_SOLVER'):
        changes['Solver/Linear solver'] = os.environ['LINEAR_SOLVER']
    path = prm.override_file('parameter_files/fig09b_friction_force_control.prm',
                             os.path.join(work, 'run.prm'), changes)
    log = os.path.join(work, 'log')
    code, wall = timed_run(mpirun(np, path), log)
    lines = open(log).read().splitlines()
    if code:
        print('\n'.join(lines[-20:]))
        sys.exit(1)
    csv = sorted((os.path.join(d, 'steady_state.csv') for d, _, files in os.walk(f'{work}/out')
                  if 'steady_state.csv' in files), key=lambda p: p.count(os.sep))[0]
    if keep:
        shutil.copy(csv, keep)
    print(f"F_hat {load}, muT {muT}, finest cell {cell} eps, {np} process(es): wall {wall:.1f} s")
    timers = next((i for i, l in enumerate(lines) if l.startswith('+' + '-' * 10)), len(lines))
    print(''.join(l + '\n' for l in lines[timers:] if l.startswith('|')), end='')
    speeds = [l for l in lines if 'steady V_hat' in l]
    if speeds:
        print(speeds[-1])
    compare_columns(csv, reference)
    shutil.rmtree(work)


def compare_columns(path, reference):
    """Rows and converged rows of a table; with a reference table, the
    largest relative change of each main column against it."""
    now = rows(path)
    print(f"{len(now)} rows, {sum(r['steady'] == '1' for r in now)} steady")
    if not reference:
        return
    ref = rows(reference)
    if len(ref) != len(now):
        print(f"reference has {len(ref)} rows")
        return
    for c in ('mu', 'mu_energy', 'L_hat', 'delta_hat', 'F_t_contact_set_hat', 'F_t_hat', 'F_n_hat'):
        if c not in now[0] or c not in ref[0]:
            continue
        d = [abs(float(a[c]) / float(b[c]) - 1) for a, b in zip(now, ref) if float(b[c]) != 0]
        i = max(range(len(d)), key=d.__getitem__)
        print(f"  {c:10s} largest relative change {d[i]:.2e} (row {i}, V_hat {now[i]['V_hat']})")


def sphere_curve(argv):
    """The sphere's friction curve (parameter_files/sphere_friction.prm:
    muT 3, F_hat 1, 21 speeds from 0.01 to 1000, approach included) by the
    3D boundary elements' uniform grid (scripts/bench_nested times the
    nested one) on one process, at R_hat (default 100) with the
    window scaled as the contact, sqrt(R_hat), and the grid spacing too or
    as given (in eps; the file's is 0.5): the wall time, the grid, GMRES
    iterations per Newton step, the rows.

        scripts/bench_sphere [R_hat [spacing]]"""
    prepare()
    R_hat = float(argv[0]) if argv else 100.
    scale = math.sqrt(R_hat / 100.)
    spacing = float(argv[1]) if len(argv) > 1 else 0.5 * scale
    work = tempfile.mkdtemp()
    changes = {'Output/Output directory': f'{work}/out', 'Adhesion/R over eps': R_hat,
               'Geometry/Domain width': 160 * scale, 'Mesh/Finest surface cell': 2 * spacing,
               'Boundary element/Grid': 'uniform'}
    path = prm.override_file('parameter_files/sphere_friction.prm',
                             os.path.join(work, 'run.prm'), changes)
    log = os.path.join(work, 'log')
    code, wall = timed_run([VISCOSLIDE, path], log)
    text = open(log).read()
    if code:
        print('\n'.join(text.splitlines()[-20:]))
        sys.exit(1)
    for line in text.splitlines():
        if line.startswith(('Boundary-element grid', 'GMRES:')):
            print(line)
    table = rows(f'{work}/out/steady_state.csv')
    print(f"R_hat {R_hat:g}: {len(table)} speeds, {sum(r['steady'] == '1' for r in table)} steady, "
          f"wall {wall:.1f} s (approach included)")
    print(f'output in {work}/out')


def nested_curve(argv):
    """The sphere's friction (parameter_files/sphere_friction.prm, muT 3,
    F_hat 1, R_hat 100) on a boundary-element grid, uniform or nested
    (default nested, Refinement 5), at the given speeds (default the
    reference's 11 from 0.01 to 1000; "file": the file's own 21) against the independent reference curve
    ../shared/reference/sphere_muT3_F1_R100.csv (or muT 1's where
    "Adhesion/Tabor parameter=1" is given): per speed mu and its
    error, A_hat and its error, the run's energy balance (mu_energy against
    mu); the largest grid, GMRES iterations per Newton step, peak memory and
    the wall time, approach included, on one process. Further entries as
    "Section/Entry=value; ..." (e.g. "Loading/Target load=-0.25"; the reference
    is then not the run's, and only the energy balance counts). With two
    processes, they take the speeds from both ends (each holds the whole
    grid).

        scripts/bench_nested [nested|uniform] [refinement] ["V_hat list" | file] ["entry=value; ..."] [processes]"""
    prepare()
    grid = argv[0] if argv else 'nested'
    refinement = argv[1] if len(argv) > 1 else '5'
    speeds = argv[2] if len(argv) > 2 else \
        '0.01, 0.0316228, 0.1, 0.316228, 1, 3.16228, 10, 31.6228, 100, 316.228, 1000'
    work = tempfile.mkdtemp()
    changes = {'Output/Output directory': f'{work}/out', 'Boundary element/Grid': grid,
               'Boundary element/Refinement': refinement}
    if speeds != 'file':
        changes['Sliding/Sliding speed'] = speeds
    for item in (argv[3].split(';') if len(argv) > 3 else []):
        if not item.strip():
            continue
        key, value = item.split('=', 1)
        changes[key.strip()] = value.strip()
    path = prm.override_file('parameter_files/sphere_friction.prm',
                             os.path.join(work, 'run.prm'), changes)
    log = f'{work}/out.log'
    processes = int(argv[4]) if len(argv) > 4 else 1
    code, wall = timed_run(mpirun(processes, path) if processes > 1 else [VISCOSLIDE, path], log)
    text = open(log).read()
    if code:
        print('\n'.join(text.splitlines()[-20:]))
        sys.exit(1)
    grids = re.findall(r'Boundary-element grid: (\d+) points', text)
    gmres = re.findall(r'GMRES: .*\(([\d.]+) per Newton step\)', text)
    with open(f'{work}/out/run.json') as f:
        peak = json.load(f)['peak_memory_gb']['total']
    # The reference at the run's muT, F_hat 1 and R_hat 100, if there is one.
    muT = changes.get('Adhesion/Tabor parameter', '3')
    same = all(changes.get(k, v) == v for k, v in
               (('Loading/Target load', '1'), ('Adhesion/R over eps', '100')))
    path = os.path.join(ROOT, '..', 'shared', 'reference', f'sphere_muT{muT}_F1_R100.csv')
    reference = {float(r['V_hat']): r for r in tables.read_reference(path)} \
        if same and os.path.exists(path) else {}
    print(f'{grid} grid, refinement {refinement}: largest grid {max(map(int, grids))} points, '
          f'GMRES {gmres[-1] if gmres else "-"} per Newton step, peak memory {peak:.2f} GB, '
          f'wall {wall:.1f} s (approach included) on {processes} process(es)')
    print('V_hat      mu        error   A_hat    error   energy balance')
    for r in rows(f'{work}/out/steady_state.csv'):
        V, mu, A = float(r['V_hat']), float(r['mu']), float(r['A_hat'])
        balance = float(r['mu_energy']) / mu - 1
        ref = next((reference[v] for v in reference if abs(v / V - 1) < 1e-4), None)
        e_mu = f"{(mu / float(ref['mu']) - 1) * 100:+6.2f} %" if ref else '   -    '
        e_A = f"{(A / float(ref['A_hat']) - 1) * 100:+6.2f} %" if ref else '   -    '
        print(f'{V:<10g} {mu:.6f}  {e_mu} {A:8.4f} {e_A}  {balance * 100:+.2f} %')
    print(f'output in {work}/out')


def graded_curve(argv):
    """The graded grid's curve at real scale (parameter_files/real_scale_cylinder.prm:
    F_hat 1) on one process at the Tabor parameter (default 100), Grid spacing
    (in eps, default 0.05), R_hat (default 1e7), Grading ratio (default 1.05)
    and number of speeds from V_min to V_max (default 6 from 0.01 to 1000,
    one per decade; 21 is four per decade) given: the wall time, the cells,
    GMRES iterations per Newton step, mu, L_hat and the energy balance of
    each speed.

        scripts/bench_graded [muT [spacing [R_hat [ratio [n_speeds [V_min [V_max]]]]]]]"""
    prepare()
    tabor = float(argv[0]) if argv else 100.
    spacing = float(argv[1]) if len(argv) > 1 else 0.05
    r_hat = float(argv[2]) if len(argv) > 2 else 1e7
    ratio = float(argv[3]) if len(argv) > 3 else 1.05
    n_speeds = int(argv[4]) if len(argv) > 4 else 6
    v_min = float(argv[5]) if len(argv) > 5 else 0.01
    v_max = float(argv[6]) if len(argv) > 6 else 1000.
    speeds = ', '.join(log_speeds(n_speeds, v_min, v_max))
    work = tempfile.mkdtemp()
    path = prm.override_file('parameter_files/real_scale_cylinder.prm',
                             os.path.join(work, 'run.prm'),
                             {'Output/Output directory': f'{work}/out',
                              'Adhesion/Tabor parameter': tabor,
                              'Adhesion/R over eps': r_hat,
                              'Boundary element/Grid spacing': spacing,
                              'Boundary element/Grading ratio': ratio,
                              'Sliding/Sliding speed': speeds})
    log = os.path.join(work, 'log')
    code, wall = timed_run([VISCOSLIDE, path], log)
    text = open(log).read()
    if code:
        print('\n'.join(text.splitlines()[-20:]))
        sys.exit(1)
    cells = [int(c) for c in re.findall(r'Graded boundary-element grid: (\d+) cells', text)]
    for line in text.splitlines():
        if line.startswith('GMRES:'):
            print(line)
    table = rows(f'{work}/out/steady_state.csv')
    print('V_hat      mu          L_hat      energy balance')
    for r in table:
        mu = float(r['mu'])
        balance = float(r['mu_energy']) / mu - 1 if mu > 0 else float('nan')
        print(f"{float(r['V_hat']):<10g} {mu:.6e}  {float(r['L_hat']):.6e}  {balance * 100:+.2f} %")
    balance = [float(r['mu_energy']) / float(r['mu']) - 1 for r in table if float(r['mu']) > 0]
    print(f"muT {tabor:g}, R_hat {r_hat:g}, {spacing:g} eps at the edges, ratio {ratio:g}: "
          f"{min(cells)} to {max(cells)} cells, "
          f"{len(table)} speeds, {sum(r['steady'] == '1' for r in table)} steady, energy balance within "
          f"{100 * max(map(abs, balance)):.2f} %, wall {wall:.1f} s")
    print(f'output in {work}/out')


def run_costs(out):
    """A finished run's (largest unknowns, peak memory summed over the
    processes in GB, GMRES iterations per solve or '-'), from its output
    folder `out` and its log `out`.log."""
    unknowns = max((int(r['n_dofs']) for r in rows(f'{out}/continuation.csv', False)
                    if 'n_dofs' in r), default=0)
    with open(f'{out}/run.json') as f:
        peak = json.load(f)['peak_memory_gb']['total']
    # the stations print running totals; the last holds all
    counts = re.findall(r'GMRES solves (\d+)\s+iterations (\d+)', open(out + '.log').read())
    its = f'{int(counts[-1][1]) / int(counts[-1][0]):.0f}' if counts else '-'
    return unknowns, peak, its


def fem3d(argv):
    """The 3D finite elements' cost against mesh size, linear solver and
    process count: tests/sphere_fem_hertz.prm (R_hat 100, repulsive, F_hat
    0.0075) at rest and at V_hat 1 on meshes given as "finest cell:grading"
    (default "8:1 4:1 4:0.5"), per run the wall time, the unknowns, the
    peak memory (summed over the processes, and per unknown), GMRES
    iterations per solve, and mu and A_hat at V_hat 1. With the case
    'approach' the sphere is pressed to delta_hat 3 under displacement
    control and slides at V_hat 1e-4 alone (no load step: the iterative
    solver's Newton iterations there are each a full solve). The solvers:
    direct, iterative, and factorized (the iterative one with its
    displacement block A~ factorized, Solver/Displacement block = direct).

        scripts/bench_fem3d ["meshes"] ["solvers"] ["procs"] [load|approach]"""
    prepare()
    meshes = (argv[0] if argv else '8:1 4:1 4:0.5').split()
    solvers = (argv[1] if len(argv) > 1 else 'direct iterative').split()
    procs = (argv[2] if len(argv) > 2 else '2 1').split()
    case = argv[3] if len(argv) > 3 else 'load'
    if case not in ('load', 'approach'):
        sys.exit(f"bench_fem3d: the case is 'load' or 'approach', not {case!r}")
    linear = {'direct': {'Solver/Linear solver': 'direct'},
              'iterative': {'Solver/Linear solver': 'iterative'},
              'factorized': {'Solver/Linear solver': 'iterative',
                             'Solver/Displacement block': 'direct'}}
    for solver in solvers:
        if solver not in linear:
            sys.exit(f"bench_fem3d: the solvers are {', '.join(linear)}, not {solver!r}")
    settings = {'Sliding/Sliding speed': '1'} if case == 'load' else {
        'Sliding/Sliding speed': '0.0001', 'Sliding/Control': 'displacement',
        'Loading/Final approach': '3', 'Loading/Target load': None}
    work = tempfile.mkdtemp()
    print(f"{'mesh':<7} {'solver':<9} {'procs':>5} {'wall_s':>8} {'unknowns':>9} "
          f"{'peak_GB':>8} {'kB/unknown':>10} {'its/solve':>9} {'mu':>9} {'A_hat':>7}", flush=True)
    for mesh in meshes:
        cell, grading = mesh.split(':')
        for solver in solvers:
            for np in procs:
                out = f'{work}/{cell}_{grading}_{solver}_np{np}'
                path = prm.override_file(
                    'tests/sphere_fem_hertz.prm', out + '.prm',
                    {'Output/Output directory': out, 'Mesh/Finest surface cell': cell,
                     'Mesh/Mesh grading': grading, **linear[solver], **settings})
                code, wall = timed_run(mpirun(np, path), out + '.log')
                table = rows(f'{out}/steady_state.csv', False)
                if code or not table:
                    print(f'{mesh:<7} {solver:<9} {np:>5} failed: see {out}.log', flush=True)
                    continue
                unknowns, peak, its = run_costs(out)
                r = table[-1]
                print(f"{mesh:<7} {solver:<9} {np:>5} {wall:8.1f} {unknowns:9d} {peak:8.2f} "
                      f"{1e6 * peak / unknowns:10.2f} {its:>9} {r['mu']:9.5g} {r['A_hat']:7.4g}",
                      flush=True)
    print(f'outputs in {work}')


# The FEM-BEM comparison's curve: 11 speeds, two per decade.
CURVE_SPEEDS = '0.01, 0.0316228, 0.1, 0.316228, 1, 3.16228, 10, 31.6228, 100, 316.228, 1000'


# tests/sphere_fem_adhesive.prm turned into its reference, the 3D boundary
# elements' uniform grid in a 160-eps window (the grids of the convergence
# studies that extrapolate it); the grid (Mesh/Finest surface cell) is the
# caller's.
SPHERE_FEM_BEM = {'Sliding/Solver': 'boundary-element', 'Boundary element/Grid': 'uniform',
                  'Sliding/Viscous strain degree': None,
                  'Geometry/Domain width': 160, 'Mesh/Mesh grading': None,
                  'Solver/Linear solver': None}


def fem3d_curve(argv):
    """A whole friction curve of the 3D finite elements, approach included:
    tests/sphere_fem_adhesive.prm (R_hat 100, Lennard-Jones at the Tabor
    parameter given, default 1, F_hat 1, 4-eps cells, the viscous strain
    of degree 1) at 11 speeds from 0.01 to 1000, on each process count
    given (default "2 1") with the linear solver given (default
    automatic), and the same curve by the 3D boundary elements (0.25-eps
    grid, within 0.15 % of their extrapolated values: scripts/convergence
    sphere_fem; 160-eps window) as reference: per run the wall time, the
    unknowns, the peak memory and GMRES iterations per solve; per speed mu
    and A_hat of both and their differences.

    Given a layer thickness t_hat, the same on a layer bonded to a rigid
    base: both methods 8 thicknesses wide (400 eps at least; the boundary
    elements periodic, the finite elements' sides free), at the six speeds
    up to 3.16, whose four wakes the 400-eps block holds (V_hat 1000 would
    want a layer block of 40 000 eps, some 2.7e6 unknowns).

        scripts/bench_fem3d_curve ["procs"] [Tabor parameter] [linear solver] [layer thickness]"""
    prepare()
    procs = (argv[0] if argv else '2 1').split()
    muT = argv[1] if len(argv) > 1 else '1'
    solver = argv[2] if len(argv) > 2 else 'automatic'
    layer = argv[3] if len(argv) > 3 else None
    work = tempfile.mkdtemp()
    common = {'Adhesion/Tabor parameter': muT, 'Sliding/Sliding speed': CURVE_SPEEDS}
    # Given last, over the reference's own Domain width.
    on_layer = {} if not layer else {
        'Geometry/Substrate': 'layer', 'Geometry/Layer thickness': layer,
        'Geometry/Domain width': max(400, 8 * float(layer)),
        'Sliding/Sliding speed': ', '.join(CURVE_SPEEDS.split(', ')[:6])}
    fem_settings = {**common, 'Sliding/Viscous strain degree': '1',
                    'Solver/Linear solver': solver, **on_layer}
    bem_settings = {**common, **SPHERE_FEM_BEM, 'Mesh/Finest surface cell': 0.5, **on_layer}
    if muT != '1':  # the stronger attraction holds the load deeper (doc/steady_state.md)
        fem_settings['Loading/Final approach'] = '6'
        # The boundary elements stop approaching once the load is reached;
        # 20 is the bound parameter_files/sphere_friction.prm gives them.
        bem_settings['Loading/Final approach'] = '20'
    runs = [('bem', 1, bem_settings)] + [(f'fem_np{np}', np, fem_settings) for np in procs]
    tables_of = {}
    print(f"{'run':<9} {'wall_s':>8} {'unknowns':>9} {'peak_GB':>8} {'speeds':>6} "
          f"{'its/solve':>9}", flush=True)
    for name, np, settings in runs:
        out = f'{work}/{name}'
        path = prm.override_file('tests/sphere_fem_adhesive.prm', out + '.prm',
                                 {'Output/Output directory': out, **settings})
        code, wall = timed_run(mpirun(np, path), out + '.log')
        table = rows(f'{out}/steady_state.csv', False)
        if code or not table:
            print(f'{name:<9} failed: see {out}.log', flush=True)
            continue
        tables_of[name] = table
        unknowns, peak, its = run_costs(out)
        print(f'{name:<9} {wall:8.1f} {unknowns:9d} {peak:8.2f} {len(table):6d} {its:>9}',
              flush=True)
    fem = next((t for n, t in tables_of.items() if n.startswith('fem')), None)
    if 'bem' not in tables_of or fem is None:
        sys.exit(f'bench_fem3d_curve: no curve to compare; outputs in {work}')
    print(f"{'V_hat':>8} {'mu FEM':>10} {'mu BEM':>10} {'diff':>7} {'A_hat FEM':>9} "
          f"{'A_hat BEM':>9} {'diff':>7} {'mu_energy/mu-1':>14}")
    for f, b in zip(fem, tables_of['bem']):
        print(f"{f['V_hat']:8.4g} {f['mu']:10.5g} {b['mu']:10.5g} {f['mu'] / b['mu'] - 1:+7.2%} "
              f"{f['A_hat']:9.5g} {b['A_hat']:9.5g} {f['A_hat'] / b['A_hat'] - 1:+7.2%} "
              f"{f['mu_energy'] / f['mu'] - 1:+14.2%}")
    print(f'outputs in {work}')


# The transient's resolved cases (tests/cross_validation_*.prm): V_hat 0.1
# to 1000 at R_hat 400, muT 6.08, each on the mesh, step and window that
# resolve it, under displacement and force control; the longest first, so
# that the others share the second core. V_hat 0.01
# (tests/cross_validation_V001.prm, half an hour) and the Fig. 9b case
# (tests/cross_validation_fig09b_V10.prm) run when named.
RESOLVED_CASES = ['tests/cross_validation_V1000.prm',
                  'tests/cross_validation_V01.prm', 'tests/cross_validation_V01_force.prm',
                  'tests/cross_validation_V1.prm', 'tests/cross_validation_quick.prm',
                  'tests/cross_validation_V10_force.prm', 'tests/cross_validation_V100.prm',
                  'tests/cross_validation_V100_force.prm']


def transient_agreement(argv):
    """Each file's study run by the transient and by the steady-state
    solver, `jobs` single-process runs at a time (default 2): per file the
    wall time of each solver, the distance the transient slid, and mu and
    L_hat of both with their difference; at the end the wall time of the
    whole set."""
    prepare()
    jobs = int(argv[0]) if argv else 2
    files = argv[1:] or RESOLVED_CASES
    work = tempfile.mkdtemp()
    queue = [(f, solver) for f in files for solver in ('transient', 'steady-state')]
    running, wall = [], {}
    start = time.time()
    while queue or running:
        while queue and len(running) < jobs:
            f, solver = queue.pop(0)
            out = os.path.join(work, os.path.basename(f)[:-4] + '-' + solver)
            path = prm.override_file(f, out + '.prm', {'Output/Output directory': out,
                                                       'Sliding/Solver': solver})
            with open(out + '.log', 'w') as log:  # the child keeps its copy
                running.append(((f, solver), out, time.time(),
                                subprocess.Popen([VISCOSLIDE, path], stdout=log,
                                                 stderr=subprocess.STDOUT)))
        time.sleep(0.5)
        for r in [r for r in running if r[3].poll() is not None]:
            running.remove(r)
            wall[r[0]] = (time.time() - r[2], r[1])
            print(f'{os.path.basename(r[0][0])} {r[0][1]}: {wall[r[0]][0]:.1f} s', flush=True)
    total = time.time() - start
    print(f"\n{'file':<30} {'control':<12} {'V_hat':>6} {'distance':>9} {'wall_tr':>8} "
          f"{'wall_ss':>8} {'mu_tr':>9} {'mu_ss':>9} {'d_mu':>8} {'L_tr':>9} {'L_ss':>9} {'d_L':>8}")
    for f in files:
        (t_tr, out_tr), (t_ss, out_ss) = wall[(f, 'transient')], wall[(f, 'steady-state')]
        ss = {(r['control'], r['V_hat']): r for r in rows(os.path.join(out_ss, 'steady_state.csv'), False)}
        for tr in rows(os.path.join(out_tr, 'steady_state.csv'), False):
            s = ss.get((tr['control'], tr['V_hat']))
            if s is None:
                print(f'{os.path.basename(f):<30} no steady-state row: see {out_ss}.log')
                continue
            print(f"{os.path.basename(f)[:-4]:<30} {tr['control']:<12} {tr['V_hat']:6g} "
                  f"{tr['sliding_distance_over_eps']:9.0f} {t_tr:8.1f} {t_ss:8.1f} "
                  f"{tr['mu']:9.5g} {s['mu']:9.5g} {100 * (tr['mu'] / s['mu'] - 1):+7.2f}% "
                  f"{tr['L_hat']:9.5g} {s['L_hat']:9.5g} {100 * (tr['L_hat'] / s['L_hat'] - 1):+7.2f}%")
    print(f'\nthe whole set: {total:.1f} s with {jobs} runs at a time; outputs in {work}')


COMMANDS = {'approach': approach, 'sliding': sliding, 'curve': curve, 'steady_curve': steady_curve,
            'sphere_curve': sphere_curve, 'fem3d': fem3d, 'fem3d_curve': fem3d_curve,
            'transient_agreement': transient_agreement}


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] not in COMMANDS:
        sys.exit(__doc__)
    COMMANDS[argv[0]](argv[1:])


if __name__ == '__main__':
    main()
