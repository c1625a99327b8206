# SPDX-License-Identifier: LGPL-2.1-or-later
"""Draws the steady sliding curves of one or more runs as figures for a
paper: PNG (200 dpi) and PDF, matplotlib.

    scripts/plot OUTPUT_DIR [OUTPUT_DIR ...] [-o PREFIX] [--label COLUMN]
                 [--maxima COLUMN] [--contact-set]

Each OUTPUT_DIR is a run's or a sweep's output directory. A sweep's
steady_state.csv (with a `case` column) gives one curve per case (cases
without results are skipped and named on stderr), a run's steady_state.csv
one curve. A curve's points are its table's rows (one per speed with the
steady-state and boundary-element solvers, one per run with the transient
one), sorted by V_hat. Columns are found by name; t_hat = `half-plane` or
`inf` (or substrate = `half-plane`) is the half-plane.

Curves: one colour per curve, the same in every figure: viridis, the
curves ordered by it, when 3 or more curves differ in one number only
(e.g. the load or t_hat); else tab10, or tab20 beyond 10 curves. Where few
categorical curves may coincide (two solvers), later ones are drawn
thinner, on top. Legend: what differs between the curves, among mu_T,
R_hat, t_hat (or half-plane), the control, the load (F_n_hat under force
control, delta_hat under displacement control, if constant along every
curve) and the solver (finite elements [steady-state, transient] or
boundary elements); the case or folder name when nothing differs (and
added where two curves would read the same); --label COLUMN shows that
column's value instead. Inside the axes, or right of them beyond 8
entries. Caption (top line of each figure): what all curves share. Rows
with steady = 0 are open symbols ("open: not steady" in the legend).
A y axis is logarithmic when its values are positive and span more than
a decade; the V_hat axis is logarithmic.

  PREFIX_mu        mu = |F_t/F_n| (solid, circles) and mu_energy, the
                   dissipation over V|F_n| (dashed), against V_hat; with
                   --contact-set also mu_contact_set (dash-dot). Where F_n
                   changes sign along a curve (mu unbounded there), a
                   dotted vertical line in the curve's colour at the V_hat
                   interpolated linearly in log V_hat.
  PREFIX_L         L_hat = L/R against V_hat (PREFIX_A: A_hat = A/(pi R eps), a sphere).
  PREFIX_forces    two panels sharing the V_hat axis: F_t_hat above (with
                   --contact-set also F_t_contact_set_hat, dash-dot),
                   F_n_hat below with its zero line and the sign changes
                   marked as in _mu (and a cross on the zero line). A load
                   constant to 1e-3 is drawn from 0.
  PREFIX_profiles  where surface_profile_steady_KK.csv (row KK of the run's
                   table) or else surface_profile_steady.csv exist: the
                   steady pressure p_hat against x/R, one panel per curve
                   (titled with its legend), one line per speed, at most 8
                   evenly picked, coloured by V_hat (plasma, colour bar;
                   several loads at one speed: a legend instead). Panels
                   share x, limited to the loaded region (|p| above 2 % of
                   its peak) plus 20 %, unless their loaded regions lie
                   apart, and share y unless their peaks differ over 3
                   times. The transient solver's profile, written in the
                   block's frame, is moved back by the sliding distance.
  PREFIX_mu_max    with --maxima COLUMN: the largest steady mu of each
                   curve against COLUMN in that row (F_n_hat: Fig. 10;
                   t_hat: the inset of Fig. 12b, log x, the half-plane a
                   dashed horizontal line labelled half-plane); the
                   caption leaves out the parameter drawn.

Each figure is written as PREFIX_NAME.png and PREFIX_NAME.pdf, and the PNG
path printed. PREFIX defaults to the first OUTPUT_DIR + '/plot'."""
import argparse
import glob
import math
import os
import re
import sys

from . import style, tables
from .style import SIZE, SYMBOL, V_LABEL, fmt

plt = style.pyplot(style.CURVES, 'scripts/plot')
import matplotlib  # noqa: E402  (after the backend is chosen)
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap, LogNorm, Normalize  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.ticker import FuncFormatter  # noqa: E402

# The solvers' names in legends (describe() tells the two finite element
# solvers apart when both are drawn).
SOLVER = dict(style.SOLVER)
# Cells are kept as the program wrote them (tables.read(text=True)): a
# legend shows a column's value or a case's name as written.


def fnum(text):
    """A table entry as a number, nan when empty or a word."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def thickness(row):
    """t_hat, inf for the half-plane (t_hat 'half-plane' or 'inf', or
    substrate 'half-plane')."""
    if (row.get('substrate') or '').strip() == 'half-plane':
        return math.inf
    t = (row.get('t_hat') or '').strip()
    return math.inf if t == 'half-plane' else fnum(t)


def value(row, column):
    return thickness(row) if column == 't_hat' else fnum(row.get(column))


def param_text(key, v):
    """The legend / caption text of one parameter's value."""
    if key == 'control':
        return f'{v} control'
    if key == 'indenter':
        return v
    if key == 'solver':
        return SOLVER.get(v, v)
    if key == 'time_constant':
        return rf'$\tau$: {v} time'
    if key == 't':
        return 'half-plane' if math.isinf(v) else r'$\hat t = %s$' % fmt(v)
    if key == 'load':
        column, x = v
        return r'$%s = %s$' % (SYMBOL[column], fmt(x))
    return r'$%s = %s$' % (SYMBOL[key], fmt(v))


def curve_params(rows):
    """The parameters of one curve: key -> (value, text), the value None when
    it is not the same along the curve (e.g. F_n under displacement control)."""
    out = {}

    def same(key, values):
        texts = {param_text(key, v) for v in values}
        out[key] = (values[0], texts.pop()) if len(texts) == 1 else (None, None)

    same('indenter', ['sphere' if 'A_hat' in r else 'cylinder' for r in rows])
    same('mu_T', [fnum(r.get('mu_T')) for r in rows])
    same('R_hat', [fnum(r.get('R_hat')) for r in rows])
    same('t', [thickness(r) for r in rows])
    same('control', [r.get('control', '?') for r in rows])
    control = out['control'][0]
    load = {'force': 'F_n_hat', 'displacement': 'delta_hat'}.get(control)
    if load:
        same('load', [(load, fnum(r.get(load))) for r in rows])
    else:
        out['load'] = (None, None)
    same('solver', [r.get('solver', '?') for r in rows])
    same('time_constant', [r.get('time_constant', 'relaxation') for r in rows])
    return out


ORDER = ['indenter', 'mu_T', 'R_hat', 't', 'control', 'load', 'solver', 'time_constant']
NUMERIC = {'mu_T', 'R_hat', 't', 'load'}


class Curve:
    def __init__(self, name, folder, rows):
        self.name, self.folder = name, folder
        rows = [r for r in rows if math.isfinite(fnum(r.get('V_hat')))]
        self.file_rows = rows  # in the table's order (the KK of the profiles)
        self.rows = sorted(rows, key=lambda r: fnum(r['V_hat']))
        self.params = curve_params(self.rows)
        self.label, self.color, self.rank, self.lw, self.ms = name, 'C0', 0, 1.6, 5.5

    def steady(self, r):
        return (r.get('steady') or '1').strip() != '0'

    def xy(self, key, steady=True):
        """V_hat and key of the (un)steady rows where both are numbers."""
        pts = [(fnum(r['V_hat']), fnum(r.get(key))) for r in self.rows
               if self.steady(r) == steady]
        pts = [p for p in pts if math.isfinite(p[1])]
        return [p[0] for p in pts], [p[1] for p in pts]

    def has(self, key):
        return any(math.isfinite(fnum(r.get(key))) for r in self.rows)

    def crossings(self):
        """The V_hat where F_n changes sign (interpolated in log V_hat)."""
        pts = [(fnum(r['V_hat']), fnum(r.get('F_n_hat'))) for r in self.rows]
        pts = [p for p in pts if math.isfinite(p[1])]
        out = [v for v, f in pts if f == 0]
        for (v1, f1), (v2, f2) in zip(pts, pts[1:]):
            if f1 * f2 < 0 and v1 != v2:
                s = f1 / (f1 - f2)
                if v1 > 0 and v2 > 0:
                    out.append(math.exp(math.log(v1) + s * (math.log(v2) - math.log(v1))))
                else:
                    out.append(v1 + s * (v2 - v1))
        return sorted(out)


def load_curves(dirs):
    curves = []
    for d in dirs:
        path = os.path.join(d, 'steady_state.csv')
        if not os.path.exists(path):
            sys.exit(f'scripts/plot: no steady_state.csv in {d}')
        rows = tables.read(path, text=True)
        if rows and 'case' in rows[0]:  # a sweep: one curve per case
            groups = {}
            for r in rows:
                groups.setdefault(r['case'], []).append(r)
            for case, g in groups.items():
                c = Curve(case, os.path.join(d, case), g)
                if c.rows:
                    curves.append(c)
                else:
                    print(f"scripts/plot: {d}: case {case} has no results "
                          f"({g[0].get('status', '')} {g[0].get('reason', '')})".rstrip(),
                          file=sys.stderr)
        else:
            c = Curve(os.path.basename(os.path.normpath(d)), d, rows)
            if c.rows:
                curves.append(c)
            else:
                print(f'scripts/plot: {d}: no results', file=sys.stderr)
    return curves


def describe(curves, label_column):
    """Legend labels, colours and the caption (what all curves share)."""
    solvers = {c.params['solver'][0] for c in curves}
    if 'transient' in solvers:  # tell the two finite element solvers apart
        SOLVER['steady-state'] = 'finite elements, steady-state'
    for c in curves:
        c.params = curve_params(c.rows)
    varying, fixed = [], []
    spheres = [c.has('A_hat') for c in curves]
    for key in ORDER:
        if key == 'indenter' and not any(spheres):
            continue  # a cylinder goes without saying
        texts = [c.params[key][1] for c in curves]
        if any(t is None for t in texts):
            continue  # not constant along some curve: neither legend nor caption
        if len(set(texts)) > 1:
            varying.append(key)
        elif key != 'time_constant' or curves[0].params[key][0] != 'relaxation':
            fixed.append(texts[0])
    caption = ', '.join(fixed)
    if any(spheres):  # 3D, or a cylinder beside a sphere
        caption = caption.replace('half-plane', 'half-space')
    if any(spheres) and not all(spheres):  # loads per length and total
        caption += r", $\hat F$ in each indenter's unit"
    if label_column:
        for c in curves:
            v = c.rows[0].get(label_column, '')
            if label_column in SYMBOL and not math.isnan(value(c.rows[0], label_column)):
                x = value(c.rows[0], label_column)
                c.label = ('half-plane' if label_column == 't_hat' and math.isinf(x)
                           else r'$%s = %s$' % (SYMBOL[label_column], fmt(x)))
            else:
                c.label = v
    elif varying:
        for c in curves:
            c.label = ', '.join(c.params[k][1] for k in varying)
    elif len(curves) > 1:
        for c in curves:
            c.label = c.name
    else:
        curves[0].label = None  # all in the caption
    labels = [c.label for c in curves]
    for c in curves:  # the same parameters twice: add the case name
        if c.label is not None and labels.count(c.label) > 1 and c.label != c.name:
            c.label += f' ({c.name})'
    # Colours: ordered by the one number that differs, else categorical.
    n = len(curves)
    numeric = (len(varying) == 1 and varying[0] in NUMERIC and not label_column and n >= 3)
    if numeric:
        key = varying[0]
        num = (lambda c: c.params[key][0][1]) if key == 'load' else (lambda c: c.params[key][0])
        curves.sort(key=num)
        colors = plt.get_cmap('viridis')(np.linspace(0, 0.88, n))
    elif n <= 10:
        colors = [plt.get_cmap('tab10')(i) for i in range(n)]
    elif n <= 20:  # the dark half of tab20 first, then the light one
        t20 = plt.get_cmap('tab20')
        colors = [t20(2 * i) for i in range(10)] + [t20(2 * i + 1) for i in range(n - 10)]
    else:
        colors = plt.get_cmap('turbo')(np.linspace(0.05, 0.95, n))
    for i, c in enumerate(curves):
        c.color, c.rank = colors[i], i
        # Categorical curves (e.g. two solvers) may lie on each other: the
        # later ones a little thinner, on top, so that all show.
        s = i / (n - 1) if n > 1 and not numeric and n <= 5 else 0.5
        c.lw, c.ms = 2.0 - 0.8 * s, 6.5 - 2.5 * s
    return caption


def log_if_decades(ax, values):
    """A log y axis when the values are positive and span over a decade."""
    v = [x for x in values if math.isfinite(x)]
    if v and min(v) > 0 and max(v) / min(v) > 10:
        ax.set_yscale('log')
        if max(v) / min(v) < 100:  # few decades: label some minor ticks too
            ax.yaxis.set_minor_formatter(FuncFormatter(minor_label))


def minor_label(y, pos=None):
    """2 and 5 times a power of ten, labelled like the major ticks."""
    if y <= 0:
        return ''
    e = math.floor(math.log10(y) + 1e-9)
    m = y / 10.0 ** e
    if abs(m - round(m)) > 1e-6 or round(m) not in (2, 5):
        return ''
    return r'$\mathdefault{%d\times10^{%d}}$' % (round(m), e)


def v_axis(ax, curves):
    vs = [fnum(r['V_hat']) for c in curves for r in c.rows]
    if min(vs) > 0:
        ax.set_xscale('log')
        if max(vs) / min(vs) < 100:
            ax.xaxis.set_minor_formatter(FuncFormatter(minor_label))
    ax.grid(True, which='major', alpha=0.3, lw=0.6)
    ax.grid(True, which='minor', alpha=0.12, lw=0.4)


def draw(ax, curves, quantities):
    """quantities: (column, line style, marker, open marker, legend text).
    Returns the legend handles of the quantities."""
    n = len(curves)
    points = set()  # quantities drawn as isolated points somewhere
    for c in curves:
        lw, ms = c.lw, c.ms
        for key, ls, marker, open_marker, _ in quantities:
            x, y = c.xy(key)
            # A single speed, or several rows at one speed (a load path):
            # points, a quantity without markers as crosses.
            single = len(set(x)) < len(x) or len(x) == 1
            if single and not marker:
                points.add(key)
            ax.plot(x, y, ls='none' if single else ls, marker=marker or ('x' if single else None),
                    color=c.color, lw=lw, ms=ms, mec=c.color, zorder=3 + 0.01 * c.rank)
            xo, yo = c.xy(key, steady=False)
            if xo:
                ax.plot(xo, yo, ls='none', marker=open_marker, mfc='white', mec=c.color,
                        mew=1.2, ms=ms if marker else 0.7 * ms, zorder=4 if marker else 3.9)
    color = curves[0].color if n == 1 else '0.25'
    return [Line2D([], [], color=color, ls=ls, marker=marker or ('x' if key in points else None),
                   label=text)
            for key, ls, marker, _, text in quantities if any(c.has(key) for c in curves)]


def extras(curves, mark_crossings=True):
    """Legend handles for open symbols and F_n = 0, where they occur."""
    h = []
    color = curves[0].color if len(curves) == 1 else '0.25'
    if any(not c.steady(r) for c in curves for r in c.rows):
        h.append(Line2D([], [], ls='none', marker='o', mfc='white', mec=color,
                        label='open: not steady'))
    if mark_crossings and any(c.crossings() for c in curves):
        h.append(Line2D([], [], color=color, ls=':', lw=1.2,
                        label=r'$\hat F_n = 0$ ($\mu$ unbounded)'))
    return h


def mark_crossings(ax, curves, on_zero=False):
    for c in curves:
        for v in c.crossings():
            ax.axvline(v, color=c.color, ls=':', lw=1.2, zorder=2)
            if on_zero:
                ax.plot([v], [0], marker='x', color=c.color, ms=7, mew=1.5, zorder=5)


def legend(ax, curves, handles, more=(), force_outside=False):
    """One legend: the curves (colours), then the quantities (line styles),
    then the open symbols and F_n = 0 (more)."""
    case_handles = [Line2D([], [], color=c.color, marker='o', ms=5, lw=1.6, label=c.label)
                    for c in curves if c.label is not None]
    if len(handles) == 1:
        handles = []  # one quantity: the y label names it
    allh = case_handles + list(handles) + list(more)
    if not allh:
        return
    if force_outside or len(allh) > 8:
        # A figure legend right of the axes: the figure widens by its width
        # and the axes keep theirs.
        fig = ax.figure
        leg = fig.legend(handles=allh, loc='upper left', frameon=False, borderaxespad=0)
        box = leg.get_window_extent(fig.canvas.get_renderer())
        w, h = box.width / fig.dpi, box.height / fig.dpi
        W, H = fig.get_size_inches()
        W2, H2 = W + w + 0.2, max(H, h + 0.5)
        fig.set_size_inches(W2, H2)
        fig.get_layout_engine().set(rect=(0, 0, W / W2, 1))
        leg.set_bbox_to_anchor((W / W2 + 0.05 / W2, 1 - 0.4 / H2), transform=fig.transFigure)
    else:
        ax.legend(handles=allh, loc='best')


def new_figure(caption, size=SIZE, **kw):
    fig, ax = plt.subplots(figsize=size, layout='constrained', **kw)
    if caption:
        fig.suptitle(caption, fontsize=9.5, color='0.15')
    return fig, ax


def save(fig, prefix, name):
    style.save(fig, f'{prefix}_{name}')


def plot_mu(curves, caption, prefix, contact_set):
    q = [('mu', '-', 'o', 'o', r'$\mu = |\hat F_t/\hat F_n|$'),
         ('mu_energy', '--', None, 'D', r'$\mu_E$ = dissipation$/V|F_n|$')]
    if contact_set:
        q.append(('mu_contact_set', '-.', None, '^', r'$\mu$ on the contact set (eq. 2)'))
    fig, ax = new_figure(caption)
    handles = draw(ax, curves, q)
    v_axis(ax, curves)
    log_if_decades(ax, [y for c in curves for k, *_ in q for y in c.xy(k)[1] + c.xy(k, False)[1]])
    mark_crossings(ax, curves)
    ax.set_xlabel(V_LABEL)
    ax.set_ylabel(r'$\mu$')
    legend(ax, curves, handles, extras(curves))
    save(fig, prefix, 'mu')


# The contact's measure: its length in 2D, its area in 3D (a sphere).
CONTACT = {'L_hat': (r'$\hat L$', r'$\hat L = L/R$', 'L'),
           'A_hat': (r'$\hat A$', r'$\hat A = A/(\pi R \epsilon)$', 'A')}


def plot_L(curves, caption, prefix, column='L_hat'):
    short, axis_label, name = CONTACT[column]
    q = [(column, '-', 'o', 'o', short)]
    fig, ax = new_figure(caption)
    draw(ax, curves, q)
    v_axis(ax, curves)
    log_if_decades(ax, [y for c in curves for y in c.xy(column)[1]])
    ax.set_xlabel(V_LABEL)
    ax.set_ylabel(axis_label)
    legend(ax, curves, [], extras(curves, mark_crossings=False))
    save(fig, prefix, name)


def plot_forces(curves, caption, prefix, contact_set):
    fig, (top, bottom) = new_figure(caption, size=(6.4, 6.0), nrows=2, sharex=True)
    q = [('F_t_hat', '-', 'o', 'o', r'$\hat F_t$ (on the indenter)')]
    if contact_set:
        q.append(('F_t_contact_set_hat', '-.', None, '^', r'$\hat F_t$ on the contact set'))
    handles = draw(top, curves, q)
    draw(bottom, curves, [('F_n_hat', '-', 'o', 'o', r'$\hat F_n$')])
    for ax in (top, bottom):
        v_axis(ax, curves)
    log_if_decades(top, [y for c in curves for k, *_ in q for y in c.xy(k)[1] + c.xy(k, False)[1]])
    fn = [y for c in curves for y in c.xy('F_n_hat')[1] + c.xy('F_n_hat', False)[1]]
    if fn and min(fn) < 0 < max(fn) or any(c.crossings() for c in curves):
        bottom.axhline(0, color='0.5', lw=0.8, zorder=1)
    elif fn and max(fn) - min(fn) < 1e-3 * max(abs(f) for f in fn):
        # a constant load (force control): from 0, not the rounding noise
        lo, hi = min(0., min(fn)), max(0., max(fn))
        bottom.set_ylim(lo - 0.15 * (hi - lo), hi + 0.15 * (hi - lo))
        bottom.axhline(0, color='0.5', lw=0.8, zorder=1)
    bottom.ticklabel_format(axis='y', useOffset=False)
    mark_crossings(top, curves)
    mark_crossings(bottom, curves, on_zero=True)
    top.set_ylabel(r'$\hat F_t$')
    bottom.set_ylabel(r'$\hat F_n$')
    bottom.set_xlabel(V_LABEL)
    legend(top, curves, handles, extras(curves))
    save(fig, prefix, 'forces')


def plot_maxima(curves, caption_curves, prefix, column):
    points, lines = [], []
    for c in curves:
        ok = [r for r in c.rows if c.steady(r) and math.isfinite(fnum(r.get('mu')))]
        if not ok:
            continue
        best = max(ok, key=lambda r: fnum(r['mu']))
        x = value(best, column)
        if math.isinf(x):
            lines.append((c, fnum(best['mu'])))
        elif math.isfinite(x):
            points.append((x, fnum(best['mu']), c))
    if not points and not lines:
        print('scripts/plot: no steady mu for --maxima', file=sys.stderr)
        return
    # The caption: what the curves share, without the column drawn.
    skip = {'t_hat': 't', 'F_n_hat': 'load', 'delta_hat': 'load', 'mu_T': 'mu_T',
            'R_hat': 'R_hat', 'solver': 'solver', 'control': 'control'}.get(column)
    fixed = []
    for key in ORDER:
        texts = {c.params[key][1] for c in caption_curves}
        if key != skip and len(texts) == 1 and None not in texts and \
                (key != 'time_constant' or caption_curves[0].params[key][0] != 'relaxation'):
            fixed.append(texts.pop())
    fig, ax = new_figure(', '.join(fixed))
    points.sort(key=lambda p: p[0])
    if points:
        ax.plot([p[0] for p in points], [p[1] for p in points], '-', color='0.4', lw=1.2, zorder=2)
        for x, y, c in points:
            ax.plot([x], [y], 'o', color=c.color, ms=7, zorder=3)
        if min(p[0] for p in points) > 0 and column in ('t_hat', 'R_hat', 'mu_T'):
            ax.set_xscale('log')
    for c, top in lines:
        label = 'half-plane' if column == 't_hat' else (c.label or c.name)
        ax.axhline(top, ls='--', color=c.color, lw=1.5, label=label)
    log_if_decades(ax, [p[1] for p in points] + [t for _, t in lines])
    ax.set_xlabel(r'$%s$' % SYMBOL[column] if column in SYMBOL else column)
    ax.set_ylabel(r'$\mu_{\max}$')
    ax.grid(True, which='major', alpha=0.3, lw=0.6)
    ax.grid(True, which='minor', alpha=0.12, lw=0.4)
    if lines:
        ax.legend(loc='best')
    save(fig, prefix, 'mu_max')


def stations(c):
    """(V_hat, load text, profile rows) of a curve's steady profiles, at
    most 8 evenly picked by speed."""
    table = c.file_rows
    own = os.path.join(c.folder, 'steady_state.csv')
    if os.path.exists(own):  # the run's own table: its rows are the KK
        rows = [r for r in tables.read(own, text=True) if math.isfinite(fnum(r.get('V_hat')))]
        if rows:
            table = rows
    out = []
    files = sorted(glob.glob(os.path.join(c.folder, 'surface_profile_steady_*.csv')))
    for path in files:
        try:
            k = int(path.rsplit('_', 1)[1].split('.')[0])
        except ValueError:
            continue
        if k < len(table):
            out.append((k, table[k], path))
    if not out and os.path.exists(os.path.join(c.folder, 'surface_profile_steady.csv')):
        out.append((len(table) - 1, table[-1], os.path.join(c.folder, 'surface_profile_steady.csv')))
    out.sort(key=lambda s: fnum(s[1]['V_hat']))
    if len(out) > 8:
        out = [out[round(i * (len(out) - 1) / 7)] for i in range(8)]
    result = []
    for k, row, path in out:
        prof = tables.read(path, text=True)
        x = np.array([fnum(p.get('x_over_R')) for p in prof])
        p = np.array([fnum(p.get('p_hat')) for p in prof])
        good = np.isfinite(x) & np.isfinite(p)
        # The transient solver's profile is in the block's frame, the
        # indenter moved on by the sliding distance: back to its frame.
        shift = fnum(row.get('sliding_distance_over_eps')) / fnum(row.get('R_hat'))
        if row.get('solver') == 'transient' and math.isfinite(shift):
            x = x - shift
        if good.any():
            load = curve_params([row])['load'][1] or ''
            result.append((fnum(row['V_hat']), load, x[good], p[good]))
    return result


def readable(color):
    """The colour, darkened where too light for text."""
    r, g, b = matplotlib.colors.to_rgb(color)
    light = 0.299 * r + 0.587 * g + 0.114 * b
    return (r, g, b) if light < 0.55 else tuple(x * 0.45 / light for x in (r, g, b))


def wrap(label, width):
    """A legend label in lines of about width visible characters, broken
    after its commas (never inside $...$)."""
    lines, line = [], ''
    for part in label.split(', '):
        shown = len(re.sub(r'\\[a-zA-Z]+|[${}^_ ]', '', line + part))
        if line and shown > width:
            lines.append(line.rstrip(', ') + ',')
            line = ''
        line += part + ', '
    return '\n'.join(lines + [line.rstrip(', ')])


def loaded_region(x, p):
    """Where |p| exceeds 2 % of its largest value."""
    big = np.abs(p).max()
    x = x[np.abs(p) > 0.02 * big] if big > 0 else x
    return (x.min(), x.max()) if x.size else (math.inf, -math.inf)


def plot_profiles(curves, caption, prefix):
    panels = [(c, s) for c in curves for s in [stations(c)] if s]
    if not panels:
        return
    n = len(panels)
    ncols = 1 if n <= 3 else (2 if n <= 8 else 3)
    nrows = math.ceil(n / ncols)
    size = SIZE if n == 1 else (6.4 if ncols < 3 else 8.0, 1.0 + (2.3 if nrows <= 3 else 2.0) * nrows)
    # One p axis for all panels unless their pressures differ much in size
    # (e.g. a thin layer against the half-plane); one x axis unless the
    # loaded regions lie apart.
    tops = [max(np.abs(p).max() for *_, p in s) for _, s in panels]
    sharey = bool(min(tops) > 0 and max(tops) <= 3 * min(tops))
    regions = []
    for _, st in panels:
        r = [loaded_region(x, p) for _, _, x, p in st]
        regions.append((min(a for a, _ in r), max(b for _, b in r)))
    lo, hi = min(a for a, _ in regions), max(b for _, b in regions)
    sharex = bool(hi - lo <= 2 * max(b - a for a, b in regions))
    fig, axes = new_figure(caption, size=size, nrows=nrows, ncols=ncols, sharex=sharex,
                           sharey=sharey, squeeze=False)
    axes = axes.ravel()
    vs = [v for _, s in panels for v, *_ in s]
    cmap = ListedColormap(plt.get_cmap('plasma')(np.linspace(0, 0.88, 256)))
    if min(vs) > 0 and max(vs) / min(vs) >= 10:
        norm = LogNorm(min(vs), max(vs))
    else:
        norm = Normalize(min(vs), max(vs) if max(vs) > min(vs) else min(vs) + 1)
    colorbar = max(vs) > min(vs)
    for i, (ax, (c, st)) in enumerate(zip(axes, panels)):
        speeds = [v for v, *_ in st]
        by_station = len(set(speeds)) < len(speeds)  # several loads at one speed
        for k, (v, load, x, p) in enumerate(st):
            if by_station:
                color, label = plt.get_cmap('tab10')(k % 10), r'$\hat V = %s$, %s' % (fmt(v), load)
            else:
                color, label = (cmap(norm(v)) if colorbar else 'C0'), None
            ax.plot(x, p, color=color, lw=1.3, label=label)
        ax.axhline(0, color='0.5', lw=0.7, zorder=1)
        ax.grid(True, alpha=0.3, lw=0.6)
        if by_station:
            ax.legend(loc='best', fontsize=7.5)
        elif not colorbar:
            ax.text(0.03, 0.95, r'$\hat V = %s$' % fmt(speeds[0]), transform=ax.transAxes,
                    va='top')
        if n > 1 or c.label:
            ax.set_title(wrap(c.label or c.name, 70 // ncols), fontsize=10 if ncols == 1 else 9,
                         color=readable(c.color) if n > 1 else 'k')
        a, b = (lo, hi) if sharex else regions[i]
        if a < b:  # the loaded part of the surface, with a margin
            ax.set_xlim(a - 0.2 * (b - a), b + 0.2 * (b - a))
        if not sharex or i // ncols == nrows - 1 or i + ncols >= n:
            ax.set_xlabel(r'$x/R$')
            ax.tick_params(labelbottom=True)
        if i % ncols == 0 or not sharey:
            ax.set_ylabel(r'$\hat p$')
    for ax in axes[n:]:
        ax.set_visible(False)
    if colorbar:
        sm = plt.cm.ScalarMappable(norm=norm, cmap=cmap)
        fig.colorbar(sm, ax=axes[:n].tolist(), label=r'$\hat V$', shrink=0.9 if n > 1 else 1.0,
                     aspect=30 if n > 2 else 20)
    save(fig, prefix, 'profiles')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split('\n\n', 1)[1])
    ap.add_argument('dirs', nargs='+', metavar='OUTPUT_DIR')
    ap.add_argument('-o', dest='prefix', help="output prefix (default: OUTPUT_DIR/plot)")
    ap.add_argument('--label', metavar='COLUMN', help='legend from this column of the table')
    ap.add_argument('--maxima', metavar='COLUMN',
                    help='also PREFIX_mu_max: largest mu of each curve against COLUMN')
    ap.add_argument('--contact-set', action='store_true',
                    help='also mu_contact_set and F_t_contact_set_hat (dash-dot)')
    a = ap.parse_args()
    prefix = a.prefix or os.path.join(a.dirs[0], 'plot')

    curves = load_curves(a.dirs)
    if not curves:
        print('scripts/plot: no results to plot in ' + ' '.join(a.dirs), file=sys.stderr)
        return
    caption = describe(curves, a.label)
    plot_mu(curves, caption, prefix, a.contact_set)
    for column in CONTACT:
        if any(c.has(column) for c in curves):
            plot_L(curves, caption, prefix, column)
    plot_forces(curves, caption, prefix, a.contact_set)
    if a.maxima:
        plot_maxima(curves, curves, prefix, a.maxima)
    plot_profiles(curves, caption, prefix)


if __name__ == '__main__':
    main()
