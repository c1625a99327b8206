# SPDX-License-Identifier: LGPL-2.1-or-later
"""The step-by-step history of a transient run with a sliding program
(Sliding/Program): start-ups, stops, restarts and reciprocating strokes,
PNG (200 dpi) and PDF.

    scripts/plot_history OUTPUT_DIR [-o PREFIX]

OUTPUT_DIR holds the run's history.csv (and approach.csv).

  PREFIX_time   three panels against time t/tau: the signed friction
                F_t/F_n (negative where the indenter slides back), the
                contact's ends x_trail and x_lead (over R, from the apex)
                and the speed V_hat; rests shaded grey.
  PREFIX_loop   F_t_hat against s/eps, one colour per cycle of the
                program (viridis), where the indenter moves back and
                forth: the loop of a reciprocating tribometer, whose area
                (in the legend, F_hat eps) is the energy dissipated per
                cycle; each cycle starts where the one before ended, the
                first solid, the others dashed.

PREFIX defaults to OUTPUT_DIR + '/history'."""
import argparse
import os
import sys

from . import style, tables


def segments(rows):
    """Runs of consecutive rows with the same V_hat: (V_hat, rows)."""
    runs = []
    for r in rows:
        if runs and runs[-1][0] == r['V_hat']:
            runs[-1][1].append(r)
        else:
            runs.append((r['V_hat'], [r]))
    return runs


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('directory')
    ap.add_argument('-o', '--prefix')
    a = ap.parse_args()
    prefix = a.prefix or os.path.join(a.directory, 'history')
    rows = tables.read(os.path.join(a.directory, 'history.csv'))
    if not rows or 'V_hat' not in rows[0]:
        sys.exit(f'{a.directory}/history.csv: no rows of a sliding program')
    plt = style.pyplot(style.CURVES, 'scripts/plot_history')
    t = [r['time_over_tau'] for r in rows]

    fig, axes = plt.subplots(3, 1, figsize=(6.4, 6.4), sharex=True,
                             gridspec_kw={'height_ratios': [2, 1.4, 1]})
    mu = [r['F_t_hat'] / r['F_n_hat'] for r in rows]
    axes[0].plot(t, mu, '-', color='C0', lw=1)
    axes[0].axhline(0, color='0.6', lw=0.6)
    axes[0].set_ylabel(r'$F_t/F_n$')
    axes[1].plot(t, [r['x_trail_over_R'] for r in rows], '-', color='C1', lw=1,
                 label=r'$x_{\rm trail}$ (smallest $x$)')
    axes[1].plot(t, [r['x_lead_over_R'] for r in rows], '-', color='C2', lw=1,
                 label=r'$x_{\rm lead}$ (largest $x$)')
    axes[1].set_ylabel(r'contact end $/R$ from the apex')
    axes[1].legend(loc='best')
    axes[2].step(t, [r['V_hat'] for r in rows], where='pre', color='k', lw=1)
    axes[2].set_ylabel(r'$\hat V$')
    axes[2].set_xlabel(r'time $t/\tau$')
    previous = t[0]
    for V, run in segments(rows):
        end = run[-1]['time_over_tau']
        if V == 0:
            for ax in axes:
                ax.axvspan(previous, end, color='0.9', zorder=0)
        previous = end
    axes[0].set_title('rests shaded', fontsize=9)
    fig.tight_layout()
    style.save(fig, prefix + '_time')

    runs = segments(rows)
    if not any(V < 0 for V, _ in runs):
        return
    # A cycle ends where the indenter turns forward again.
    cycles, current = [], []
    for V, run in runs:
        if V > 0 and current and any(v < 0 for v, _ in current):
            cycles.append(current)
            current = []
        current.append((V, run))
    cycles.append(current)
    cmap = plt.get_cmap('viridis')
    fig, ax = plt.subplots(figsize=style.SIZE)
    last = None
    for k, cycle in enumerate(cycles):
        # from where the cycle before ended, so that the loop closes
        points = ([last] if last else []) + [r for _, run in cycle for r in run]
        last = points[-1]
        area = sum(0.5 * (a['F_t_hat'] + b['F_t_hat']) * (b['s_over_eps'] - a['s_over_eps'])
                   for a, b in zip(points, points[1:]))
        ax.plot([r['s_over_eps'] for r in points], [r['F_t_hat'] for r in points],
                linestyle='-' if k == 0 else (0, (4, 2 + k)), lw=1.2,
                color=cmap(0.9 * k / max(len(cycles) - 1, 1)),
                label=rf'cycle {k + 1}, $\hat V$ = {style.fmt(abs(cycle[0][0]))}: '
                      rf'$\oint \hat F_t\,ds$ = {area:.3g}')
    ax.axhline(0, color='0.6', lw=0.6)
    ax.set_xlabel(r'indenter position $s/\varepsilon$')
    ax.set_ylabel(r'$\hat F_t$ (x force on the indenter)')
    ax.legend()
    style.save(fig, prefix + '_loop')


if __name__ == '__main__':
    main()
