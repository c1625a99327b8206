# SPDX-License-Identifier: LGPL-2.1-or-later
"""Draws one scalar field of a viscoslide .pvtu (all its pieces) as a
colour map near the contact, PNG (200 dpi) and PDF (the dissipation maps
of Fig. 5).

    scripts/plot_field FILE.pvtu [FIELD] [-o PREFIX] [--width W] [--depth D]
                       [--center X] [--per-speed V_HAT] [--linear | --both]
                       [--decades N]

FIELD defaults to dissipation_rate. The window is W wide (default: 4 times
the extent of the surface region where FIELD exceeds 1e-3 of its maximum)
and D deep (default W/4), centred on x = X (default 0, the indenter's
apex; 'trailing' or 'leading' for an end of the contact), equal aspect,
in eps (x/R on the top axis when R_hat is known). With --per-speed V_HAT
the field is divided by V_HAT: the steady dissipation rate density D then
becomes the energy dissipated per unit volume per eps of sliding (in E0*,
eps units), which compares speeds. Colour map 'magma' on a log scale
(N decades below the largest value in the window, default 4, stated on
the colour bar; white contours at each decade) when the field is
positive and spans more than two decades, unless --linear (contours at
a fifth, two fifths ... of the largest value); --both draws the log and
the linear map one above the other. A field of both signs (stresses)
gets the diverging 'RdBu_r', centred on 0, with black contours at
+-0.2, 0.4, 0.6, 0.8 of its largest magnitude. The contact's ends (gap below
1.2 eps in surface_profile_steady_KK.csv beside a steady_KKKKK.pvtu) are
marked on the surface. The title names the field and the speed (V_HAT
from --per-speed, or the .pvd time of a steady_KKKKK.pvtu, or row KK of
steady_state.csv next to it); the caption the run's parameters from that
steady_state.csv. PREFIX defaults to FILE without .pvtu + '_' + FIELD;
PREFIX.png is printed. The fields are read by viscoslide.vtu (standard
library only, also used by the tests).

In 3D a steady_KKKKK.pvtu is drawn in the plane y = 0 (the track's centre
line, a plane of the mesh's faces), depth z downwards, and a
steady_surface_KKKKK.pvtu (FIELD p_hat or gap_over_eps) seen from above,
about where FIELD exceeds 1e-3 of its largest magnitude (--width W: the
square's side)."""
import argparse
import os
import re
import sys

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
    m = re.match(r'steady_(?:surface_)?(\d+)\.pvtu$', os.path.basename(pvtu))
    return rows[int(m.group(1))] if m and int(m.group(1)) < len(rows) else rows[-1]


def pvd_speed(pvtu):
    """V_hat of a steady_KKKKK.pvtu (or steady_surface_KKKKK.pvtu): its time
    in steady.pvd (steady_surface.pvd)."""
    name = os.path.basename(pvtu)
    path = os.path.join(os.path.dirname(pvtu) or '.', name.rsplit('_', 1)[0] + '.pvd')
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
            parts.append('half-space' if 'A_hat' in row else 'half-plane')
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


def contact_ends(pvtu, R):
    """x (in eps) of the contact's trailing and leading ends, from the
    surface profile beside a steady_KKKKK.pvtu, or None."""
    m = re.match(r'steady_(\d+)\.pvtu$', os.path.basename(pvtu))
    if not m or not R:
        return None
    path = os.path.join(os.path.dirname(pvtu) or '.',
                        f'surface_profile_steady_{int(m.group(1)):02d}.csv')
    if not os.path.exists(path):
        return None
    inside = [p['x_over_R'] * R for p in tables.read(path) if p['gap_over_eps'] < 1.2]
    return (min(inside), max(inside)) if inside else None


def from_above(plt, mtri, np, a, x, y, v, tris, row, prefix):
    """A field of the 3D top surface (steady_surface_KKKKK.pvtu) seen from
    above, about where it exceeds 1e-3 of its largest magnitude."""
    hi = np.abs(v).max() or 1.
    seen = np.abs(v) > 1e-3 * hi
    half = 0.8 * max(np.abs(x[seen]).max(), np.abs(y[seen]).max()) + 1 if seen.any() else 10
    half = a.width / 2 if a.width else 1.5 * half
    signed = v.min() < -1e-3 * hi and v.max() > 1e-3 * hi
    V = a.per_speed or pvd_speed(a.pvtu)
    if V is None and row:
        V = float(row['V_hat'])
    title = NAMES.get(a.field, (a.field.replace('_', ' '),))[0]
    if a.field == 'p_hat':
        title = r'Surface pressure $\hat p$'
    title += ' seen from above' + (r', $\hat V = %s$' % fmt(V) if V is not None else '')
    fig, ax = plt.subplots(figsize=(5.4, 4.6), layout='constrained')
    tri = mtri.Triangulation(x, y, tris)
    from matplotlib.colors import Normalize
    cmap, norm = ('RdBu_r', Normalize(-hi, hi)) if signed else ('magma', Normalize(0, hi))
    pc = ax.tripcolor(tri, v, shading='gouraud', cmap=cmap, norm=norm, rasterized=True)
    ax.tricontour(tri, v, levels=[hi * f for f in (0.2, 0.4, 0.6, 0.8)],
                  colors='k' if signed else 'w', linewidths=0.4, alpha=0.8)
    if signed:
        ax.tricontour(tri, v, levels=[0.], colors='k', linewidths=0.8)
    ax.set_xlim(-half, half)
    ax.set_ylim(-half, half)
    ax.set_aspect('equal')
    ax.set_xlabel(r'$x/\varepsilon$ (sliding towards $+x$)')
    ax.set_ylabel(r'$y/\varepsilon$')
    label = {'p_hat': r'$\hat p$', 'gap_over_eps': r'gap/$\varepsilon$'}.get(a.field, a.field)
    fig.colorbar(pc, ax=ax, label=label, shrink=0.9, aspect=15, pad=0.02)
    ax.set_title(title, fontsize=11)
    ax.text(0.01, 0.02, 'contours at 0.2 ... 0.8 of the peak' + ('; thick: 0' if signed else ''),
            transform=ax.transAxes, fontsize=7, color='k' if signed else 'w')
    cap = caption(row)
    if cap:
        fig.suptitle(cap, fontsize=9, color='0.15')
    style.save(fig, prefix)


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
    ap.add_argument('--both', action='store_true')
    ap.add_argument('--decades', type=float, default=4)
    ap.add_argument('--center', default='0')
    a = ap.parse_args()
    prefix = a.prefix or os.path.splitext(a.pvtu)[0] + '_' + a.field

    shape = vtu.cell_shape(a.pvtu)
    if shape == 'hexahedra':  # 3D: the plane y = 0 of the track's centre line
        x, y, v, tris = vtu.read_pvtu_slice(a.pvtu, a.field)
    else:
        x, y, v, tris = vtu.read_pvtu(a.pvtu, a.field)
    x, y, v = np.array(x), np.array(y), np.array(v, dtype=float)
    row = run_row(a.pvtu)
    if shape == 'quadrilaterals' and 'surface' in os.path.basename(a.pvtu):
        return from_above(plt, mtri, np, a, x, y, v, tris, row, prefix)
    R = None
    try:
        R = float(row['R_hat']) if row else None
    except (KeyError, ValueError):
        pass
    ends = contact_ends(a.pvtu, R)
    if a.center in ('trailing', 'leading'):
        if not ends:
            sys.exit(f'scripts/plot_field: --center {a.center}: no contact profile beside {a.pvtu}')
        center = ends[0] if a.center == 'trailing' else ends[1]
    else:
        center = float(a.center)
    if a.per_speed:
        v = v / a.per_speed
    top, vmax = y.max(), np.abs(v).max()
    at_top = top - y < 1e-6 * (1 + abs(top))
    surface = x[at_top & (np.abs(v) > 1e-3 * vmax)]
    extent = (surface.max() - surface.min()) if surface.size else (x.max() - x.min()) / 10
    width = a.width or min(4 * extent, x.max() - x.min())
    depth = a.depth or width / 4
    seen = (np.abs(x - center) <= width / 2) & (y >= top - depth)
    shown = v[seen] if seen.any() else v
    hi = np.abs(shown).max() or 1.
    signed = shown.min() < -1e-6 * hi and shown.max() > 1e-6 * hi
    positive = shown[shown > 0]
    can_log = not signed and positive.size and hi / positive.min() > 100
    scales = (['log', 'linear'] if a.both and can_log else
              ['signed'] if signed else ['log'] if can_log and not a.linear else ['linear'])

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
    # Each panel as tall as its window's aspect wants, plus its labels.
    panel = 0.9 + 5.0 * min(depth / width, 0.5)
    fig, axes = plt.subplots(len(scales), 1, figsize=(6.4, 0.6 + panel * len(scales)),
                             layout='constrained', squeeze=False)
    for ax, scale in zip(axes[:, 0], scales):
        if scale == 'signed':
            cmap, norm, vals = 'RdBu_r', Normalize(-hi, hi), v
            levels = [hi * f for f in (-0.8, -0.6, -0.4, -0.2, 0.2, 0.4, 0.6, 0.8)]
            label = symbol
        elif scale == 'log':
            lo = hi * 10 ** -a.decades
            cmap, norm = 'magma', LogNorm(vmin=lo, vmax=hi)
            vals = np.maximum(v, lo * 1e-2)
            levels = [10 ** e for e in range(int(np.ceil(np.log10(lo))),
                                             int(np.floor(np.log10(hi))) + 1)]
            label = symbol + f' (log; lowest: {a.decades:g} decades below the peak)'
        else:
            cmap, norm, vals = 'magma', Normalize(min(0., shown.min()), shown.max()), v
            levels = [shown.max() * f for f in (0.2, 0.4, 0.6, 0.8)]
            label = symbol + (' (linear)' if len(scales) > 1 else '')
        pc = ax.tripcolor(tri, vals, shading='gouraud', cmap=cmap, norm=norm, rasterized=True)
        if levels:
            ax.tricontour(tri, vals, levels=levels, colors='k' if scale == 'signed' else 'w',
                          linewidths=0.4, alpha=0.8)
        ax.axhline(top, color='0.5', lw=0.8)
        if ends:
            ax.plot(ends, [top, top], 'v', color='c', ms=5, clip_on=False, zorder=5,
                    label='contact ends (gap < 1.2 $\\varepsilon$)')
            ax.legend(loc='lower right', fontsize=7, framealpha=0.6)
        ax.set_xlim(center - width / 2, center + width / 2)
        ax.set_ylim(top - depth, top)
        ax.set_aspect('equal')
        ax.set_ylabel(r'$z/\varepsilon$ (plane $y = 0$)' if shape == 'hexahedra'
                      else r'$y/\varepsilon$')
        fig.colorbar(pc, ax=ax, label=label if len(label) < 40 else symbol, shrink=0.9,
                     aspect=15, pad=0.02)
        if scale == 'log':
            ax.text(0.01, 0.03, f'contours: decades; floor {10 ** -a.decades:g} of the peak',
                    transform=ax.transAxes, fontsize=7, color='w')
        elif len(scales) > 1:
            ax.text(0.01, 0.03, 'linear; contours at 0.2, 0.4, 0.6, 0.8 of the peak',
                    transform=ax.transAxes, fontsize=7, color='w')
    axes[-1, 0].set_xlabel(r'$x/\varepsilon$ (indenter apex at 0, sliding towards $+x$)')
    if R:
        sec = axes[0, 0].secondary_xaxis('top', functions=(lambda u: u / R, lambda u: u * R))
        sec.set_xlabel(r'$x/R$', fontsize=9)
        sec.tick_params(labelsize=8)
    axes[0, 0].set_title(title, fontsize=11)
    cap = caption(row)
    if cap:
        fig.suptitle(cap, fontsize=9, color='0.15')
    style.save(fig, prefix)


if __name__ == '__main__':
    main()
