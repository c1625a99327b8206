# SPDX-License-Identifier: LGPL-2.1-or-later
"""Runs the study behind each named figure of the paper and draws it.

  scripts/figures [-np N] FIG [FIG ...]     e.g. scripts/figures fig04b fig10
  scripts/figures [-np N] all

With -np N the N processes run N cases of a study side by side (--jobs
N), which pays more than N processes per case at the figures' size.
FIG is the prefix of a file parameter_files/FIG_*.prm. Figures that share
a study (4b, 7b, 8a, 8b) share its output folder: the sweep runs once and
later calls skip the finished cases. The plots go to OUTPUT_DIR/FIG_*.png
(scripts/plot); run times of the full-resolution studies are listed in
doc/figures.md. Needs a build (scripts/setup or cmake) in build/."""
import glob
import os
import re
import subprocess
import sys

from . import prm, tables

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Figures drawn with their maxima against a column (scripts/plot --maxima).
MAXIMA = {'fig10': 'F_n_hat', 'fig12b': 't_hat'}


def usage():
    """The docstring as the comment block the bash script printed."""
    return '\n'.join(('# ' + l).rstrip() for l in __doc__.splitlines()) + '\n'


def all_figures():
    """The FIG of every parameter_files/figNN[ab]_*.prm, in file order."""
    names = sorted(glob.glob('parameter_files/fig*.prm'))
    return [m.group(1) for m in (re.match(r'.*/(fig[0-9]*[ab]?)_', n) for n in names) if m]


def rerun_options(out):
    """A sweep skips its finished cases itself. A single run counts as done
    only by its status file: a killed one is resumed or started again.
    Returns (options, done)."""
    if not os.path.isfile(f'{out}/parameters.prm') or os.path.isfile(f'{out}/sweep.prm'):
        return [], False
    options = ['--resume'] if os.path.isfile(f'{out}/checkpoint/state.bin') else ['--overwrite']
    try:
        done = open(f'{out}/status').readline().rstrip('\n') == 'done'
    except OSError:
        done = False
    return options, done


def run_study(fig, path, out, np):
    """Runs the study; False where some cases failed."""
    options, done = rerun_options(out)
    if done:
        print(f'(a single run, done earlier: delete {out} to run it again)', flush=True)
        return True
    ok = subprocess.run(['mpirun', '-np', str(np), 'build/viscoslide', '--jobs', str(np),
                         *options, path]).returncode == 0
    if not ok:
        print(f'scripts/figures: {fig}: some cases failed (see {out}/steady_state.csv)',
              file=sys.stderr, flush=True)
    return ok


def draw(fig, out):
    """scripts/plot of the study; for Fig. 5 a dissipation map per speed."""
    extra = ['--maxima', MAXIMA[fig]] if fig in MAXIMA else []
    subprocess.run(['scripts/plot', out, '-o', f'{out}/{fig}', *extra], check=True)
    if fig == 'fig05':
        # Per speed: the contact and the solid beneath it, and the trailing
        # end of the contact up close, each on a log and a linear scale.
        for k, row in enumerate(tables.read(f'{out}/steady_state.csv', text=True)):
            V = row['V_hat']
            field = [f'{out}/steady_{k:05d}.pvtu', 'dissipation_rate', '--per-speed', V, '--both']
            subprocess.run(['scripts/plot_field', *field, '--width', '1600', '--depth', '400',
                            '-o', f'{out}/fig05_V{V}'], check=True)
            subprocess.run(['scripts/plot_field', *field, '--center', 'trailing', '--width', '160',
                            '--depth', '40', '-o', f'{out}/fig05_V{V}_trailing'], check=True)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    os.chdir(ROOT)
    np = 1
    if argv[:1] == ['-np']:
        np, argv = argv[1], argv[2:]
    if not argv:
        sys.stdout.write(usage())
        sys.exit(1)
    if argv[0] == 'all':
        argv = all_figures()
    os.environ.update(OMPI_ALLOW_RUN_AS_ROOT='1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM='1')
    status = 0
    for fig in argv:
        files = sorted(glob.glob(f'parameter_files/{fig}_*.prm'))
        if not files:
            sys.exit(f'scripts/figures: no parameter_files/{fig}_*.prm')
        path = files[0]
        out = prm.value(open(path).read(), 'Output/Output directory', '')
        print(f'=== {fig}: {path} -> {out}', flush=True)
        if not run_study(fig, path, out, np):
            status = 2
        try:
            draw(fig, out)
        except subprocess.CalledProcessError as e:
            sys.exit(e.returncode)
    sys.exit(status)


if __name__ == '__main__':
    main()
