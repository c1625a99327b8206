# SPDX-License-Identifier: LGPL-2.1-or-later
"""Friction of a temperature sweep in SI units: the classic picture of
rubber and polymer friction, PNG (200 dpi) and PDF.

    scripts/plot_temperatures OUTPUT_DIR [OUTPUT_DIR ...] [-o PREFIX]

Each OUTPUT_DIR is a sweep over Sweep/Temperatures of a case given in SI
units (Units/System = SI): its cases' folders hold steady_state.csv with
the SI columns and parameters.prm, whose Units/Temperature labels the
case. Several directories (say one over speeds at three temperatures and
one over temperatures at one speed) are pooled.

Caption (top line): R/eps, the load and the solver of the first case.

  PREFIX_speed        mu against V (m/s), one curve per temperature
                      (plasma, dark cold to bright hot); open symbols: not steady.
  PREFIX_temperature  mu against the temperature, one curve per speed
                      (viridis), where a speed was run at three or more
                      temperatures.

PREFIX defaults to the first OUTPUT_DIR's path + '/friction'."""
import argparse
import os
import sys
from collections import defaultdict

from . import prm, style, tables


def cases(directory):
    """(temperature, rows of steady_state.csv) of each case of a sweep."""
    found = []
    for name in sorted(os.listdir(directory)):
        folder = os.path.join(directory, name)
        table = os.path.join(folder, 'steady_state.csv')
        if not os.path.isfile(table):
            continue
        text = open(os.path.join(folder, 'parameters.prm')).read()
        rows = tables.read(table)
        if rows and 'V_m_per_s' not in rows[0]:
            sys.exit(f'{table}: no SI columns (the case is not in SI units)')
        found.append((float(prm.value(text, 'Units/Temperature')), rows))
    if not found:
        sys.exit(f'{directory}: no case folder with a steady_state.csv')
    return found


def marker(ax, x, y, row, colour, **kw):
    ax.plot([x], [y], 'o', color=colour, ms=4,
            mfc=colour if tables.steady(row) else 'none', **kw)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('directories', nargs='+')
    ap.add_argument('-o', '--prefix')
    a = ap.parse_args()
    prefix = a.prefix or os.path.join(a.directories[0], 'friction')
    plt = style.pyplot(style.CURVES, 'scripts/plot_temperatures')
    by_temperature = defaultdict(list)
    for d in a.directories:
        for T, rows in cases(d):
            by_temperature[T] += rows
    temperatures = sorted(by_temperature)
    first = by_temperature[temperatures[0]][0]
    load = first.get('F_n_N', first.get('F_n_N_per_m'))
    unit = 'N' if 'F_n_N' in first else 'N/m'
    caption = (f"$R/\\varepsilon = {style.fmt(first['R_hat'])}$, "
               f"$F_n = {style.fmt(load)}$ {unit}, {first['solver'].replace('-', ' ')}s")
    cmap = plt.get_cmap('plasma')  # dark cold to bright hot, never white
    colour = {T: cmap(0.9 * i / max(len(temperatures) - 1, 1))
              for i, T in enumerate(temperatures)}
    any_open = any(not tables.steady(r) for rows in by_temperature.values() for r in rows)

    fig, ax = plt.subplots(figsize=style.SIZE)
    for T in temperatures:
        rows = sorted(by_temperature[T], key=lambda r: r['V_m_per_s'])
        ax.plot([r['V_m_per_s'] for r in rows], [r['mu'] for r in rows], '-',
                color=colour[T], label=f'${style.fmt(T)}$ °C')
        for r in rows:
            marker(ax, r['V_m_per_s'], r['mu'], r, colour[T])
    ax.set_xscale('log')
    ax.set_xlabel('sliding speed $V$ (m/s)')
    ax.set_ylabel(r'friction coefficient $\mu = |F_t/F_n|$')
    ax.legend(title='open: not steady' if any_open else None,
              loc='upper left', bbox_to_anchor=(1.02, 1), borderaxespad=0)
    ax.set_title(caption, fontsize=9)
    fig.tight_layout()
    style.save(fig, prefix + '_speed')

    by_speed = defaultdict(list)
    for T in temperatures:
        for r in by_temperature[T]:
            by_speed[r['V_m_per_s']].append((T, r))
    speeds = sorted(V for V, points in by_speed.items() if len(points) >= 3)
    if not speeds:
        return
    cmap = plt.get_cmap('viridis')
    fig, ax = plt.subplots(figsize=style.SIZE)
    for i, V in enumerate(speeds):
        c = cmap(i / max(len(speeds) - 1, 1))
        points = sorted(by_speed[V], key=lambda p: p[0])
        ax.plot([T for T, _ in points], [r['mu'] for _, r in points], '-', color=c,
                label=f'${style.fmt(V)}$ m/s')
        for T, r in points:
            marker(ax, T, r['mu'], r, c)
    ax.set_xlabel('temperature (°C)')
    ax.set_ylabel(r'friction coefficient $\mu = |F_t/F_n|$')
    ax.set_title(caption, fontsize=9)
    ax.legend(title='open: not steady' if any_open else None)
    style.save(fig, prefix + '_temperature')


if __name__ == '__main__':
    main()
