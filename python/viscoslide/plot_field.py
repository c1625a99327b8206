"""Draws one scalar field of a viscoslide .pvtu (all its pieces) as a
colour map near the contact, PNG (200 dpi) and PDF (the dissipation maps
of Fig. 5).

    scripts/plot_field FILE.pvtu [FIELD] [-o PREFIX] [--width W] [--depth D]
                       [--per-speed V_HAT] [--linear]

FIELD defaults to dissipation_rate. The window is W wide (default: 4 times
the extent of the surface region where FIELD exceeds 1e-3 of its maximum)
and D deep (default W/4), centred on the indenter (x = 0), equal aspect,
in eps (x/R on the top axis when R_hat is known). With --per-speed V_HAT
the field is divided by V_HAT: the steady dissipation rate density D then
becomes the energy dissipated per unit volume per eps of sliding (in E0*,
eps units), which compares speeds. Colour map 'magma' on a log scale
(four decades below the largest value in the window) when the field is
positive and spans more than two decades, unless --linear; a field of
both signs (stresses) gets the diverging 'RdBu_r', centred on 0. The
title names the field and the speed (V_HAT from --per-speed, or the .pvd
time of a steady_KKKKK.pvtu, or row KK of steady_state.csv next to it);
the caption the run's parameters from that steady_state.csv. PREFIX
defaults to FILE without .pvtu + '_' + FIELD; PREFIX.png is printed. The
fields are read by viscoslide.vtu (standard library only, also used by
the tests)."""
import argparse
import os
import re

from . import style, tables, vtu
from .style import fmt


NAMES = {  # field: (title, colour bar symbol)
    'dissipation_rate': ('Dissipation rate density', r'$\mathcal{D}$'),
    'dissipated_energy': ('Dissipated energy per unit volume', r'$W$'),
    'dissipated_energy_hat': ('Dissipated energy per unit volume', r'$\hat W$'),
    'stress_xx': ('Stress', r'$\sigma_{xx}$'), 'stress_yy': ('Stress', r'$\sigma_{yy}$'),
    'stress_xy': ('Stress', r'$\sigma_{xy}$'), 'stress_zz': ('Stress', r'$\sigma_{zz}$'),
    'viscous_strain_xx': ('Viscous strain', r'$h_{xx}$'),
    'viscous_strain_yy': ('Viscous strain', r'$h_{yy}$'),
    'viscous_strain_xy': ('Viscous strain', r'$h_{xy}$'),
}


def run_row(pvtu):
    """The steady_state.csv row of this file's speed (steady_KKKKK.pvtu: row
    KK), else the table's last row; None without a table."""
    path = os.path.join(os.path.dirname(pvtu) or '.', 'steady_state.csv')
    if not os.path.exists(path):
        return None
    rows = [r for r in tables.read(path, text=True) if r.get('V_hat')]
    if not rows:
        return None
    m = re.match(r'steady_(\d+)\.pvtu$', os.path.basename(pvtu))
    return rows[int(m.group(1))] if m and int(m.group(1)) < len(rows) else rows[-1]


def pvd_speed(pvtu):
    """V_hat of a steady_KKKKK.pvtu: its time in steady.pvd."""
    name = os.path.basename(pvtu)
    path = os.path.join(os.path.dirname(pvtu) or '.', 'steady.pvd')
    if not name.startswith('steady_') or not os.path.exists(path):
        return None
    with open(path) as f:
        m = re.search(r'timestep="([^"]+)"[^>]*file="%s"' % re.escape(name), f.read())
    try:
        return float(m.group(1)) if m else None
    except ValueError:
        return None


def caption(row):
    if not row:
        return ''
    parts = []
    num = lambda k: float(row[k]) if row.get(k) not in (None, '') else None
    try:
        if num('mu_T') is not None:
            parts.append(r'$\mu_T = %s$' % fmt(num('mu_T')))
        if num('R_hat') is not None:
            parts.append(r'$\hat R = %s$' % fmt(num('R_hat')))
        t = row.get('t_hat', '')
        if row.get('substrate') == 'half-plane' or t in ('half-plane', 'inf'):
            parts.append('half-plane')
        elif t:
            parts.append(r'$\hat t = %s$' % fmt(float(t)))
        control = row.get('control', '')
        if control:
            parts.append(f'{control} control')
        load = {'force': ('F_n_hat', r'\hat F_n'), 'displacement': ('delta_hat', r'\hat\delta')}.get(control)
        if load and num(load[0]) is not None:
            parts.append(r'$%s = %s$' % (load[1], fmt(num(load[0]))))
    except ValueError:
        pass
    solver = style.SOLVER.get(row.get('solver', ''))
    if solver:
        parts.append(solver)
    return ', '.join(parts)


def main():
    plt = style.pyplot(style.FIELDS, 'scripts/plot_field')
    import matplotlib.tri as mtri
    from matplotlib.colors import LogNorm, Normalize
    import numpy as np
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split('\n\n', 1)[1])
    ap.add_argument('pvtu')
    ap.add_argument('field', nargs='?', default='dissipation_rate')
    ap.add_argument('-o', dest='prefix')
    ap.add_argument('--width', type=float)
    ap.add_argument('--depth', type=float)
    ap.add_argument('--per-speed', type=float)
    ap.add_argument('--linear', action='store_true')
    a = ap.parse_args()
    prefix = a.prefix or os.path.splitext(a.pvtu)[0] + '_' + a.field

    x, y, v, tris = vtu.read_pvtu(a.pvtu, a.field)
    x, y, v = np.array(x), np.array(y), np.array(v, dtype=float)
    if a.per_speed:
        v = v / a.per_speed
    top, vmax = y.max(), np.abs(v).max()
    at_top = top - y < 1e-6 * (1 + abs(top))
    surface = x[at_top & (np.abs(v) > 1e-3 * vmax)]
    extent = (surface.max() - surface.min()) if surface.size else (x.max() - x.min()) / 10
    width = a.width or 4 * extent
    depth = a.depth or width / 4
    seen = (np.abs(x) <= width / 2) & (y >= top - depth)
    shown = v[seen] if seen.any() else v
    hi = np.abs(shown).max() or 1.
    signed = shown.min() < -1e-6 * hi and shown.max() > 1e-6 * hi
    positive = shown[shown > 0]
    log = (not a.linear and not signed and positive.size and
           hi / positive.min() > 100)
    if signed:
        cmap, norm, vals = 'RdBu_r', Normalize(-hi, hi), v
    elif log:
        lo = hi * 1e-4
        cmap, norm, vals = 'magma', LogNorm(vmin=lo, vmax=hi), np.maximum(v, lo * 1e-2)
    else:
        cmap, norm, vals = 'magma', Normalize(min(0., shown.min()), shown.max()), v

    row = run_row(a.pvtu)
    V = a.per_speed or pvd_speed(a.pvtu)
    if V is None and row and re.match(r'steady_\d+\.pvtu$', os.path.basename(a.pvtu)):
        V = float(row['V_hat'])
    title, symbol = NAMES.get(a.field, (a.field.replace('_', ' '), a.field.replace('_', r'\_')))
    if a.per_speed:
        if a.field == 'dissipation_rate':
            title = 'Dissipation per unit sliding distance'
        symbol = symbol + r'$/\hat V$'
    title += ' ' + symbol
    if V is not None:
        title += r', $\hat V = %s$' % fmt(V)

    tri = mtri.Triangulation(x, y, tris)
    fig, ax = plt.subplots(figsize=(6.4, 2.9), layout='constrained')
    pc = ax.tripcolor(tri, vals, shading='gouraud', cmap=cmap, norm=norm, rasterized=True)
    ax.set_xlim(-width / 2, width / 2)
    ax.set_ylim(top - depth, top)
    ax.set_aspect('equal')
    ax.set_xlabel(r'$x/\varepsilon$ (indenter apex at 0, sliding towards $+x$)')
    ax.set_ylabel(r'$y/\varepsilon$')
    R = None
    try:
        R = float(row['R_hat']) if row else None
    except (KeyError, ValueError):
        pass
    if R:
        sec = ax.secondary_xaxis('top', functions=(lambda u: u / R, lambda u: u * R))
        sec.set_xlabel(r'$x/R$', fontsize=9)
        sec.tick_params(labelsize=8)
    fig.colorbar(pc, ax=ax, label=symbol, shrink=0.9, aspect=15, pad=0.02)
    ax.set_title(title, fontsize=11)
    cap = caption(row)
    if cap:
        fig.suptitle(cap, fontsize=9, color='0.15')
    style.save(fig, prefix)


if __name__ == '__main__':
    main()
