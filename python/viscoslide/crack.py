# SPDX-License-Identifier: LGPL-2.1-or-later
"""The contact edges of a sliding cylinder as viscoelastic cracks
(doc/boundary_element.md, The edges as cracks).

Where the adhesive zone and the relaxation length V tau_c are both small
against the contact, the contact looks from afar like an elastic contact
of the relaxed solid whose edges carry square-root singularities: the
trailing edge an opening crack, the leading edge a closing one. Their
energy release rates G, measured with the relaxed modulus, are the
apparent works of adhesion, and the friction force per unit length is
their difference (the energy balance of the two moving cracks, the bulk's
hysteresis aside).

Internal units as the program's: eps = 1, E0* = 1; the work of adhesion
dgamma = sqrt(muT^3/R_hat).

* `edge_energy_release(F, x_trail, x_lead, R)`: G at each edge from the
  load and the edges of a computed steady state (the relaxed outer
  solution, below);
* `persson_brener(v_tau_c, dgamma, einf_over_e0)`: G/dgamma of an opening
  crack in a standard linear solid (Persson and Brener 2005), its cut-off
  where the crack tip's stress reaches the law's peak;
* `analyse(out)`: both, the JKR width and Hunter's bulk hysteresis for
  each station of a finished run;
* `edge_model(...)`: the cylinder's friction and width from the edges' G
  of a resolved run, at any Tabor parameter and R_hat;
* `main`: scripts/edge_cracks, the tables and the figure.

The outer solution: a rigid parabola h = x^2/(2R) on the relaxed
half-plane, in contact on c1 < x < c2 (centre e, half-width c), with the
pressure (compressive positive, xi = x - e)
    p = sqrt(c^2 - xi^2)/(2R) + (A - e xi/(2R))/sqrt(c^2 - xi^2),
    A = (F - pi c^2/(4R))/pi,
the Hertz part, a load and a tilt (the slope e/R of the profile at the
centre), each solving (2/pi) PV int p(t)/(x - t) dt = x/R (Johnson, Contact
Mechanics, 2.25). At an edge p ~ (A -+ e c/(2R))/sqrt(2 c s) = K/sqrt(2 pi s)
at the distance s (upper sign at c2), and G = K^2/2 (a rigid body on the
half-plane, E0* = 1). Their difference, pi A e/R, is the x force of the
pressure on the profile: the friction of the crack picture.
"""
import argparse
import json
import math
import os
import sys

from . import style, tables

# Hunter's closed form (tests/hunter.py) is the adhesionless reference.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'tests'))
from hunter import hunter  # noqa: E402

# The edge model's premise: V tau_c below this fraction of the contact's
# width. Beyond, the contact's size shows in the edges' G (measured at
# muT 100: the model's mu 2.5 % high where V tau_c is 0.5 % of the width,
# 22 % at 4.7 %; doc/boundary_element.md).
MODEL_REACH = 0.002


def within_reach(row):
    """Whether an analyse() row's V tau_c is within the edge model's reach."""
    return row['v_tau_c'] < MODEL_REACH * row['L_hat'] * row['R_hat']


def edge_energy_release(F, x_trail, x_lead, R):
    """(G at the trailing edge x_trail, G at the leading edge x_lead) of the
    relaxed contact under the load F per unit length (internal units)."""
    c = 0.5 * (x_lead - x_trail)
    e = 0.5 * (x_lead + x_trail)
    A = (F - math.pi * c * c / (4 * R)) / math.pi
    g = lambda coefficient: math.pi * coefficient ** 2 / (2 * c)
    return g(A + e * c / (2 * R)), g(A - e * c / (2 * R))


def persson_brener(v_tau_c, dgamma, einf_over_e0):
    """G/dgamma of the opening crack at the speed whose retardation length
    is v_tau_c (eps), in the standard linear solid whose glassy modulus is
    einf_over_e0 times the relaxed one, for the Lennard-Jones law of work
    dgamma (its peak stress 16 dgamma/(9 sqrt 3)).

    Persson and Brener, Phys. Rev. E 71, 036123 (2005):
        dgamma/G = 1 - (2/pi) E0 int_0^{2 pi v/a} F(w)/w Im 1/E(w) dw,
        F(w) = sqrt(1 - (w a/(2 pi v))^2),
    with a the cut-off where the stress of the crack tip's field,
    K/sqrt(2 pi a), reaches the law's peak: a = K^2/(2 pi sigma^2) =
    G/(pi sigma^2). For 1/E = 1/Einf + (1/E0 - 1/Einf)/(1 - i w tau_c) the
    integral is closed: with b = 2 pi v tau_c/a,
        dgamma/G = 1 - (1 - E0/Einf) (sqrt(1 + b^2) - 1)/b,
    from 1 at rest to E0/Einf when the zone is passed in much less than
    tau_c. Solved for G by bisection (the right side rises with G)."""
    loss = 1 - 1 / einf_over_e0

    def excess(g):
        b = 2 * math.pi * v_tau_c / (g * cut_off(dgamma))
        return 1 / g - (1 - loss * (math.sqrt(1 + b * b) - 1) / b)

    low, high = 1.0, einf_over_e0
    for _ in range(100):
        middle = math.sqrt(low * high)
        if excess(middle) > 0:
            low = middle
        else:
            high = middle
    return math.sqrt(low * high)


def contact_edges(profile, R, threshold):
    """The contact's trailing and leading x (internal units) in a surface
    profile (x_over_R, gap_over_eps): where the gap crosses `threshold`
    eps, interpolated linearly, outermost crossings."""
    x = [R * float(r['x_over_R']) for r in profile]
    g = [float(r['gap_over_eps']) for r in profile]
    inside = [k for k in range(len(g)) if g[k] < threshold]
    if not inside:
        raise ValueError('no contact in the profile')

    def crossing(k, j):
        return x[k] + (threshold - g[k]) * (x[j] - x[k]) / (g[j] - g[k])

    first, last = inside[0], inside[-1]
    trail = crossing(first, first - 1) if first > 0 else x[first]
    lead = crossing(last, last + 1) if last + 1 < len(x) else x[last]
    return trail, lead


def jkr_half_width(F, dgamma, R):
    """The JKR line contact's half-width under F (internal units, relaxed
    modulus): F = pi c^2/(4R) - sqrt(2 pi dgamma c), the larger root."""
    load = lambda c: math.pi * c * c / (4 * R) - math.sqrt(2 * math.pi * dgamma * c)
    # from the width at the pull-off, where the load is least
    low = high = (2 * dgamma * R * R / math.pi) ** (1 / 3)
    while load(high) < F:
        high *= 2
    for _ in range(200):
        c = 0.5 * (low + high)
        low, high = (c, high) if load(c) < F else (low, c)
    return 0.5 * (low + high)


def cut_off(dgamma):
    """The relaxed crack tip's cut-off dgamma/(pi sigma^2) (persson_brener):
    the unit of the speeds' retardation lengths at which the edges of
    every Tabor parameter and R_hat meet alike."""
    return dgamma / (math.pi * (16 * dgamma / (9 * math.sqrt(3))) ** 2)


def analyse(out):
    """Per station of a finished 2D run in `out` (half-plane, standard
    linear solid, force control; e.g. scripts/bench_graded): the speed,
    mu, the energy balance, L_hat against JKR's, the edges' G/dgamma, the
    friction of the edges as cracks (G_trail - G_lead)/F and the bulk's
    (Hunter's adhesionless mu at the Hertz load of the same contact width,
    times that load over F), Persson and Brener's G/dgamma."""
    with open(os.path.join(out, 'parameters.json')) as f:
        p = json.load(f)
    muT = float(p['Adhesion']['Tabor parameter']['value'])
    R = float(p['Adhesion']['R over eps']['value'])
    ratio = 1 / float(p['Material']['E0 over Einf']['value'])
    retardation = p['Material']['Time constant']['value'] == 'retardation'
    threshold = float(p['Adhesion']['Contact gap threshold']['value'])
    dgamma = math.sqrt(muT ** 3 / R)
    unit = (math.pi * dgamma ** 2 * R) ** (1 / 3)
    result = []
    for k, r in enumerate(tables.read(os.path.join(out, 'steady_state.csv'))):
        v_tau_c = r['V_hat'] * (1 if retardation else ratio)
        F = r['F_n_hat'] * unit
        profile = tables.read(os.path.join(out, f'surface_profile_steady_{k:02d}.csv'))
        trail, lead = contact_edges(profile, R, threshold)
        g_trail, g_lead = edge_energy_release(F, trail, lead, R)
        hertz = math.pi * (lead - trail) ** 2 / (16 * R)
        result.append(dict(
            muT=muT, R_hat=R, F_hat=r['F_n_hat'], V_hat=r['V_hat'], v_tau_c=v_tau_c,
            s=v_tau_c / cut_off(dgamma),
            mu=r['mu'], L_hat=r['L_hat'],
            balance=r['mu_energy'] / r['mu'] - 1,
            L_jkr=r['L_hat'] * R / (2 * jkr_half_width(F, dgamma, R)) - 1,
            G_trail=g_trail / dgamma, G_lead=g_lead / dgamma, mu_cracks=(g_trail - g_lead) / F,
            mu_bulk=hunter(hertz, R, 1.0, ratio, v_tau_c)['mu'] * hertz / F,
            persson_brener=persson_brener(v_tau_c, dgamma, ratio), einf_over_e0=ratio))
    return result


def print_table(rows):
    print(f"muT {rows[0]['muT']:g}, R_hat {rows[0]['R_hat']:g} "
          "(s = V tau_c/a0; cracks, bulk: each part over mu)")
    print('V_hat      s          mu           balance  L/L_JKR-1  G_trail  P&B      G_lead   '
          'cracks     bulk       sum-1')
    for r in rows:
        parts = r['mu_cracks'] / r['mu'], r['mu_bulk'] / r['mu']
        print(f"{r['V_hat']:<10.4g} {r['s']:<10.4g} {r['mu']:.5e}  {100 * r['balance']:+6.2f} %"
              f"  {100 * r['L_jkr']:+7.3f} %  {r['G_trail']:7.4f}  {r['persson_brener']:7.4f}  "
              f"{r['G_lead']:7.4f}  {100 * parts[0]:7.3f} %  {100 * parts[1]:7.3f} %  "
              f"{100 * (sum(parts) - 1):+6.2f} %")


def interpolate_log(x, xs, ys):
    """ys at x, linear in log x between the points xs (ascending); None outside."""
    for k in range(len(xs) - 1):
        if xs[k] <= x <= xs[k + 1]:
            t = math.log(x / xs[k]) / math.log(xs[k + 1] / xs[k])
            return ys[k] + t * (ys[k + 1] - ys[k])
    return None


def case(rows):
    """A run's Tabor parameter and R_hat, for the printed lines."""
    return f"muT {rows[0]['muT']:g}, R_hat {rows[0]['R_hat']:g}"


def print_collapse(runs):
    """Each run's trailing G against the last run's (runs sorted by muT
    and R_hat) at the same s, within the edge model's reach in both, and
    the factor on s that brings Persson and Brener's G to the
    largest Tabor parameter's at G = 2, 4 and 8 dgamma."""
    top = runs[-1]
    for rows in runs:
        if rows is top:
            continue
        gaps = []
        for r in rows:
            g = interpolate_log(r['s'], [t['s'] for t in top], [t['G_trail'] for t in top])
            if g is not None and within_reach(r):
                gaps.append((r['s'], r['G_trail'] / g - 1))
        if not gaps:
            print(f"G_trail at {case(rows)} against {case(top)}: no speed within "
                  "the edge model's reach in both")
            continue
        worst = max(gaps, key=lambda x: abs(x[1]))
        print(f"G_trail at {case(rows)} against {case(top)} at the same s, "
              f"{len(gaps)} speeds: within {100 * abs(worst[1]):.2f} % (at s = {worst[0]:.3g})")
    einf = top[0]['einf_over_e0']
    for level in (2, 4, 8):
        pairs = [(r['G_trail'], r['s']) for r in top]
        s_run = next((a[1] * (b[1] / a[1]) ** ((level - a[0]) / (b[0] - a[0]))
                      for a, b in zip(pairs, pairs[1:]) if a[0] <= level <= b[0]), None)
        low, high = 1e-6, 1e6
        for _ in range(200):
            mid = math.sqrt(low * high)
            low, high = (mid, high) if persson_brener_scaled(mid, einf) < level else (low, mid)
        if s_run:
            print(f"G = {level} dgamma: s = {s_run:.4g} (muT {top[0]['muT']:g}), "
                  f"Persson and Brener {low:.4g}: a factor {s_run / low:.3g}")


def edge_curves(rows):
    """The edges' G/dgamma against s from a resolved run's analyse() rows,
    within the model's reach: (s, G_trail, G_lead) ascending."""
    return [(r['s'], r['G_trail'], r['G_lead']) for r in rows if within_reach(r)]


def edge_model(F_hat, muT, R_hat, V_hat, curves, einf_over_e0=10., retardation=False):
    """The cylinder's steady sliding with its edges as cracks whose G
    follow `curves` (edge_curves of a resolved run; the same s = V tau_c/a0
    for any Tabor parameter and R_hat): (mu, L_hat, the edges' share of
    mu). Both edges move at V, so their G are known; the relaxed outer
    contact then gives its half-width c from the load,
        F = pi c^2/(4R) - sqrt(pi c/2) (sqrt(G_t) + sqrt(G_l)),
    the friction of the edges (G_t - G_l)/F and the bulk's as
    analyse() counts it. Below the curves' range the difference of the
    G is linear in s (the response near rest), above it they are held at
    the last point's (the glassy limits within a few percent)."""
    dgamma = math.sqrt(muT ** 3 / R_hat)
    R = R_hat
    F = F_hat * (math.pi * dgamma ** 2 * R) ** (1 / 3)
    v_tau_c = V_hat * (1 if retardation else einf_over_e0)
    s = v_tau_c / cut_off(dgamma)
    # Their difference (the friction) in log-log, as the power law it is
    # near rest (linear in s), where it is a small difference of two G;
    # their sum linearly in log s.
    xs = [c[0] for c in curves]
    clamp = min(max(s, xs[0]), xs[-1])
    difference = math.exp(interpolate_log(clamp, xs, [math.log(c[1] - c[2]) for c in curves]))
    if s < xs[0]:
        difference *= s / xs[0]
    total = interpolate_log(clamp, xs, [c[1] + c[2] for c in curves])
    g_t, g_l = dgamma * (total + difference) / 2, dgamma * (total - difference) / 2
    load = lambda c: math.pi * c * c / (4 * R) - math.sqrt(math.pi * c / 2) * \
        (math.sqrt(g_t) + math.sqrt(g_l))
    low = high = (dgamma * R * R / math.pi) ** (1 / 3)
    while load(high) < F:
        high *= 2
    for _ in range(200):
        c = 0.5 * (low + high)
        low, high = (c, high) if load(c) < F else (low, c)
    hertz = math.pi * low * low / (4 * R)
    edges = (g_t - g_l) / F
    bulk = hunter(hertz, R, 1.0, einf_over_e0, v_tau_c)['mu'] * hertz / F
    return edges + bulk, 2 * low / R, edges / (edges + bulk)


def print_edge_model(curves_run, runs):
    """The edge model with the curves of curves_run against the other
    resolved runs: the largest errors of mu and L_hat within the model's
    reach and at all speeds."""
    curves = edge_curves(curves_run)
    for rows in runs:
        if rows is curves_run:
            continue
        errors = []
        for r in rows:
            mu, L, _ = edge_model(r['F_hat'], r['muT'], r['R_hat'], r['V_hat'], curves,
                                  r['einf_over_e0'])
            errors.append((within_reach(r), abs(mu / r['mu'] - 1), abs(L / r['L_hat'] - 1)))
        for what, chosen in ((f'V tau_c < {100 * MODEL_REACH:g} % of the width',
                              [e for e in errors if e[0]]),
                             ('all speeds', errors)):
            if not chosen:
                continue
            print(f"edge model (the curves of {case(curves_run)}) at {case(rows)}, "
                  f"{what} ({len(chosen)}): mu within "
                  f"{100 * max(e[1] for e in chosen):.2f} %, L_hat within "
                  f"{100 * max(e[2] for e in chosen):.3f} %")


def persson_brener_scaled(s, einf_over_e0):
    """persson_brener at V tau_c = s times the relaxed cut-off."""
    return persson_brener(s * cut_off(1.0), 1.0, einf_over_e0)


def figure(runs, path):
    """Left: G/dgamma of both edges over s, against Persson and Brener's.
    Middle: the contact width against JKR's. Right: mu of the full
    solution against its parts, the edges as cracks and the bulk's
    hysteresis (Hunter)."""
    plt = style.pyplot(style.CURVES, 'scripts/edge_cracks')
    fig, (left, width, right) = plt.subplots(1, 3, figsize=(15, 5.6))
    colours = plt.rcParams['axes.prop_cycle'].by_key()['color']
    one_R = len({rows[0]['R_hat'] for rows in runs}) == 1
    for k, (colour, rows) in enumerate(zip(colours, runs)):
        label = rf"$\mu_T = {rows[0]['muT']:g}$" + \
            ('' if one_R else rf", $\hat R = {style.fmt(rows[0]['R_hat'])}$")
        s = [r['s'] for r in rows]
        # the smaller Tabor parameters smaller and on top: the points meet
        size = 4 + 2.5 * (len(runs) - 1 - k)
        left.loglog(s, [r['G_trail'] for r in rows], 'o', mfc='none', mew=1.2, color=colour,
                    ms=size, zorder=3 + k)
        left.loglog(s, [r['G_lead'] for r in rows], 's', mfc='none', mew=1.2, color=colour,
                    ms=size, zorder=3 + k)
        left.plot([], [], '-', color=colour, lw=2, label=label)
        width.semilogx(s, [100 * r['L_jkr'] for r in rows], 'o-', color=colour, ms=4, lw=0.8,
                       label=label)
        V = [r['V_hat'] for r in rows]
        right.loglog(V, [r['mu'] for r in rows], 'o', color=colour, ms=5, label=label)
        right.loglog(V, [r['mu_cracks'] for r in rows], '--', color=colour, lw=1)
        right.loglog(V, [r['mu_bulk'] for r in rows], ':', color=colour, lw=1.2)
        right.loglog(V, [r['mu_cracks'] + r['mu_bulk'] for r in rows], '-', color=colour, lw=0.8)
    s_all = [r['s'] for rows in runs for r in rows]
    grid = [min(s_all) * (max(s_all) / min(s_all)) ** (k / 200) for k in range(201)]
    einf = runs[0][0]['einf_over_e0']
    left.loglog(grid, [persson_brener_scaled(x, einf) for x in grid], 'k-', lw=1,
                label='Persson & Brener, opening crack')
    for level in (1, einf, 1 / einf):
        left.axhline(level, color='0.7', lw=0.6, zorder=0)
    left.set_xlabel(r'$s = V\tau_c/a_0$,  $a_0 = \Delta\gamma/(\pi\sigma_{max}^2)$')
    left.set_ylabel(r'$G/\Delta\gamma$ of the relaxed outer contact')
    left.set_title('edges as cracks' + (rf": $\hat R = {style.fmt(runs[0][0]['R_hat'])}$"
                                        if one_R else ''), fontsize=10)
    left.plot([], [], 'ko', mfc='none', label='trailing edge')
    left.plot([], [], 'ks', mfc='none', label='leading edge')
    # below the panels: at many Tabor parameters a legend inside covers
    # the curves
    left.legend(fontsize=7, loc='upper center', bbox_to_anchor=(0.5, -0.16), ncol=3)
    width.axhline(0, color='0.7', lw=0.6, zorder=0)
    width.set_xlabel(r'$s = V\tau_c/a_0$')
    width.set_ylabel(r'$L/L_{JKR} - 1$ (%), JKR of the relaxed solid')
    width.set_title('contact width: the slow limit', fontsize=10)
    width.legend(fontsize=7, loc='upper center', bbox_to_anchor=(0.5, -0.16), ncol=3)
    right.plot([], [], 'k--', lw=1, label=r'edges as cracks, $(G_t - G_l)/F$')
    right.plot([], [], 'k:', lw=1.2, label='bulk: Hunter at the Hertz load of the width')
    right.plot([], [], 'k-', lw=0.8, label='their sum')
    mu_min = min(r['mu'] for rows in runs for r in rows)
    right.set_ylim(mu_min / 5, 2 * max(r['mu'] for rows in runs for r in rows))
    right.set_xlabel(style.V_LABEL)
    right.set_ylabel(r'$\mu$')
    right.set_title('friction: full solution (points) and its parts', fontsize=10)
    right.legend(fontsize=7, loc='upper center', bbox_to_anchor=(0.5, -0.16), ncol=3)
    fig.tight_layout()
    style.save(fig, path)


def print_prediction(curves_run, muT, R_hat, speeds):
    """The edge model's curve (F_hat 1) at a Tabor parameter and R_hat
    beyond the resolved runs, with the curves of curves_run (a speed
    whose V tau_c is beyond MODEL_REACH of the width is marked; the time
    constant the relaxation time, as in the runs)."""
    curves = edge_curves(curves_run)
    print(f"edge model (the curves of muT {curves_run[0]['muT']:g}): muT {muT:g}, "
          f"R_hat {R_hat:g}, F_hat 1")
    print('V_hat      mu           L_hat        edges\' share  V tau_c within the reach')
    ratio = curves_run[0]['einf_over_e0']
    for V in speeds:
        mu, L, share = edge_model(1.0, muT, R_hat, V, curves, ratio)
        inside = 'yes' if V * ratio < MODEL_REACH * L * R_hat else 'no'
        print(f'{V:<10.4g} {mu:.5e}  {L:.5e}  {100 * share:6.2f} %        {inside}')


def main(argv=None):
    """scripts/edge_cracks FIGURE OUT_DIR [OUT_DIR ...] [--curves OUT_DIR]
    [--predict muT:R_hat ...]: the tables, the collapse of the trailing
    edge's G over s, the edge model with the curves of the --curves run
    (by default the largest Tabor parameter's) against the other runs (and
    its curves at the muT:R_hat given, 0.01 to 1000) and the figure
    (FIGURE.png and .pdf) of finished 2D runs, e.g. scripts/bench_graded's."""
    ap = argparse.ArgumentParser(prog='scripts/edge_cracks', description=main.__doc__)
    ap.add_argument('figure')
    ap.add_argument('outs', nargs='+', metavar='OUT_DIR')
    ap.add_argument('--curves', metavar='OUT_DIR')
    ap.add_argument('--predict', nargs='+', default=[], metavar='muT:R_hat')
    a = ap.parse_args(sys.argv[1:] if argv is None else argv)
    outs = list(dict.fromkeys(a.outs + ([a.curves] if a.curves else [])))
    analysed = {out: analyse(out) for out in outs}
    runs = sorted(analysed.values(), key=lambda rows: (rows[0]['muT'], rows[0]['R_hat']))
    # the curves of the largest Tabor parameter (and R_hat) serve the others
    curves_run = analysed[a.curves] if a.curves else runs[-1]
    for rows in runs:
        print_table(rows)
    print_collapse(runs)
    print_edge_model(curves_run, runs)
    for case in a.predict:
        muT, R_hat = map(float, case.split(':'))
        print_prediction(curves_run, muT, R_hat, [10 ** (k / 4 - 2) for k in range(21)])
    figure(runs, a.figure[:-4] if a.figure.endswith('.png') else a.figure)
