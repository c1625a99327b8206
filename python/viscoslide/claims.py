# SPDX-License-Identifier: LGPL-2.1-or-later
"""The paper's claims, each written once, judged on a study's table.

scripts/claims prints the claims table of doc/verification.md from the
figure studies (`table`); tests/figure_sweep.check asserts the claims its
reduced studies can show. Both call the functions here, so that a claim
and the test of it cannot drift apart.

A claim takes the curves of a study, {case: rows sorted by V_hat}
(`curves`), and returns a Verdict: ok (None: not judged), the numbers
behind it as text, and named values a test prints for numdiff (only the
claims that measure something beyond the table do). Standard library
only: the tests import it."""
import math
import os
from typing import NamedTuple

from . import tables, vtu


class Verdict(NamedTuple):
    ok: bool | None
    numbers: str
    values: dict = {}


def fmt(x):
    return f'{x:.3g}'


def curves(rows, name='', steady_only=True):
    """case -> rows sorted by V_hat; with steady_only the converged rows
    (steady = 1) only. A run's table (no case column) is one curve, name."""
    out = {}
    for r in rows:
        if steady_only and r.get('steady') != 1:
            continue
        out.setdefault(r.get('case', name), []).append(r)
    for k in out:
        out[k].sort(key=lambda r: r['V_hat'])
    return out


def read_study(path, name=''):
    """The curves of the steady_state.csv at path, None where it is not."""
    return curves(tables.read(path), name) if os.path.exists(path) else None


def interior_maximum(rows, key):
    v = [r[key] for r in rows]
    k = max(range(len(v)), key=lambda i: v[i])
    return 0 < k < len(v) - 1, k, v


def sign_changes(rows):
    """(V_hat, V_hat) of each pair of neighbouring rows between which F_n
    changes sign."""
    s = [r['F_n_hat'] for r in rows]
    return [(rows[i]['V_hat'], rows[i + 1]['V_hat']) for i in range(len(s) - 1)
            if s[i] * s[i + 1] < 0]


def thickness(rows):
    t = rows[0]['t_hat']
    return math.inf if t == 'half-plane' else float(t)


def maximum_inside(c, key='L_hat'):
    """Fig. 4b: key (L_hat) is largest at an intermediate speed."""
    details, ok = [], True
    for case, rows in c.items():
        inside, k, v = interior_maximum(rows, key)
        ok &= inside
        details.append(f'{case}: max {fmt(v[k])} at V_hat {fmt(rows[k]["V_hat"])}; '
                       f'{fmt(v[0])} at {fmt(rows[0]["V_hat"])}, {fmt(v[-1])} at {fmt(rows[-1]["V_hat"])}')
    return Verdict(ok, '; '.join(details))


def sign_changes_twice(c, delta_hat=11):
    """Fig. 7b/8b: under displacement control F_n crosses zero (mu
    diverges), twice at delta_hat = 11."""
    details, ok, seen = [], True, False
    for case, rows in c.items():
        ch = sign_changes(rows)
        mu_near = [max(r['mu'] for r in rows if a <= r['V_hat'] <= b) for a, b in ch]
        details.append(f'{case}: F_n changes sign {len(ch)}x' +
                       ''.join(f' between V_hat {fmt(a)} and {fmt(b)} (mu {fmt(m)})'
                               for (a, b), m in zip(ch, mu_near)))
        if abs(rows[0]['delta_hat'] - delta_hat) < 1e-6:
            ok &= len(ch) == 2
            seen = True
    return Verdict(ok and seen, '; '.join(details))


def decreasing(c, key='L_hat'):
    """Fig. 4a: L_hat decreases monotonically with V_hat (muT = 1)."""
    details, ok = [], True
    for case, rows in c.items():
        v = [r[key] for r in rows]
        rises = [(rows[i]['V_hat'], v[i + 1] / v[i] - 1) for i in range(len(v) - 1) if v[i + 1] > v[i]]
        ok &= not rises
        details.append(f'{case}: {key} {fmt(v[0])} -> {fmt(v[-1])}, ' +
                       ('no rise' if not rises else
                        'rises ' + ', '.join(f'{100 * d:.2g} % after V_hat {fmt(V)}' for V, d in rises)))
    return Verdict(ok, '; '.join(details))


def smaller_at_high_speed(c, key='L_hat'):
    """Fig. 4a: elastic limits at both ends, the contact smaller at the
    fastest speed than at the slowest (in every case)."""
    ends = {case: (rows[0][key], rows[-1][key]) for case, rows in sorted(c.items())}
    return Verdict(all(last < first for first, last in ends.values()),
                   f'{key} at the slowest and fastest speed: {ends}')


def bell_shaped(c):
    """Fig. 9b: mu rises to a maximum inside the speed range and falls."""
    details, ok = [], True
    for case, rows in c.items():
        inside, k, v = interior_maximum(rows, 'mu')
        up = all(v[i + 1] >= v[i] for i in range(k))
        down = all(v[i + 1] <= v[i] for i in range(k, len(v) - 1))
        ok &= inside and up and down
        details.append(f'{case}: peak {fmt(v[k])} at V_hat {fmt(rows[k]["V_hat"])}'
                       + ('' if up and down else ' (not monotonic on both sides)'))
    return Verdict(ok, '; '.join(details))


def peak_between(c, low=2, high=4):
    """Fig. 9b: the peak of mu lies near V_hat = 2-4."""
    peaks = [r[max(range(len(r)), key=lambda i: r[i]['mu'])]['V_hat'] for r in c.values()]
    return Verdict(all(low <= V <= high for V in peaks),
                   'peaks at V_hat ' + ', '.join(fmt(V) for V in peaks) +
                   ' (on the speeds of the study; see the text on R_hat)')


def maxima_against_load(c):
    """Fig. 10: mu_max decreases with F_hat > 0 and increases with F_hat < 0."""
    maxima = sorted((rows[0]['F_n_hat'], max(r['mu'] for r in rows)) for rows in c.values())
    pos = [m for F, m in maxima if F > 0]
    neg = [m for F, m in maxima if F < 0]
    ok = all(pos[i + 1] < pos[i] for i in range(len(pos) - 1)) and \
        all(neg[i + 1] > neg[i] for i in range(len(neg) - 1))
    return Verdict(ok, ', '.join(f'F_hat {fmt(F)}: {fmt(m)}' for F, m in maxima))


def flatter_for_thinner(c):
    """Figs. 11, 12: the thinner the layer, the flatter L_hat(V_hat)."""
    spread = [(thickness(r), (max(x['L_hat'] for x in r) - min(x['L_hat'] for x in r)) /
               max(x['L_hat'] for x in r)) for r in sorted(c.values(), key=thickness)]
    ok = all(spread[i + 1][1] >= spread[i][1] for i in range(len(spread) - 1))
    return Verdict(ok, ', '.join(f't_hat {fmt(t)}: (max-min)/max {fmt(s)}' for t, s in spread))


def mu_grows_with_thickness(c, plateau=False):
    """Figs. 11, 12: thinner layers give smaller mu; with plateau (Fig. 12b's
    inset) growth from the thinnest layer and the two thickest within 5 %
    (the maxima are sampled on the study's speeds)."""
    mu_max = [(thickness(r), max(x['mu'] for x in r)) for r in sorted(c.values(), key=thickness)]
    ok = all(mu_max[i + 1][1] >= mu_max[i][1] for i in range(len(mu_max) - 1))
    if plateau:
        ok = mu_max[1][1] > mu_max[0][1] and abs(mu_max[-1][1] / mu_max[-2][1] - 1) < 0.05
    return Verdict(ok, ', '.join(f't_hat {fmt(t)}: {fmt(m)}' for t, m in mu_max))


def dissipation_maps(folder, rows):
    """Fig. 5: the slow case dissipates nearer the surface. For each speed
    (row k, fields steady_KKKKK.pvtu in folder): the peak of D/V, its
    depth and position, the shares of the total within 10 eps of the
    surface and behind the apex, and the total per unit sliding distance
    (the paper: surface at the trailing edge at V_hat = 1, subsurface and
    far lower at 50)."""
    found = [(r['V_hat'], dissipation_shares(folder, k, r['R_hat']))
             for k, r in enumerate(rows)]
    values = {}
    for V, d in found:
        values.update({f'D_over_V_peak({V:g})': d['peak'] / V,
                       f'peak_depth_over_eps({V:g})': d['peak_depth'],
                       f'peak_x_over_eps({V:g})': d['peak_x'],
                       f'surface_share({V:g})': d['surface'],
                       f'trailing_side_share({V:g})': d['trailing'],
                       f'dissipation_per_distance({V:g})': d['total'] / V})
    numbers = ', '.join(f'V_hat {V:g}: {d["surface"]:.3f} within {SURFACE_LAYER:g} eps'
                        for V, d in found)
    return Verdict(found[0][1]['surface'] > found[-1][1]['surface'], numbers, values)


# The depth (in eps) of the surface layer whose share of the dissipation
# Fig. 5's claim is about.
SURFACE_LAYER = 10


def dissipation_shares(folder, k, R_hat):
    """Where the steady state of row k dissipates (the field
    dissipation_rate of steady_KKKKK.pvtu, integrated over the written
    triangles, in eps and E0* units): its total; the shares within
    SURFACE_LAYER eps of the surface, behind (x < 0) and ahead of the apex,
    and in the bulk under the contact (deeper, between the contact's ends
    where the gap of surface_profile_steady_KK.csv is below 1.2 eps); the
    peak value, its depth and x. R_hat converts the profile's x/R."""
    x, y, v, tris = vtu.read_pvtu(os.path.join(folder, f'steady_{k:05d}.pvtu'),
                                  'dissipation_rate')
    profile = tables.read(os.path.join(folder, f'surface_profile_steady_{k:02d}.csv'))
    inside = [p['x_over_R'] * R_hat for p in profile if p['gap_over_eps'] < 1.2]
    trail, lead = (min(inside), max(inside)) if inside else (0., 0.)
    top = max(y)
    total = near = behind = under = 0.
    for w, xm, ym in vtu.triangle_integrals(x, y, v, tris):
        depth = top - ym
        total += w
        if depth < SURFACE_LAYER:
            near += w
        elif trail <= xm <= lead:
            under += w
        if xm < 0:  # behind the apex: the trailing side
            behind += w
    i = max(range(len(v)), key=lambda j: v[j])
    return {'total': total, 'surface': near / total, 'trailing': behind / total,
            'leading': 1 - behind / total, 'bulk_under_contact': under / total,
            'peak': v[i], 'peak_depth': top - y[i], 'peak_x': x[i],
            'contact': (trail, lead)}


def edge_asymmetry(folder, rows):
    """Fig. 6: (x_lead + x_trail)/L of the contact edges (gap below 1.2
    eps in surface_profile_steady_KK.csv), 0 for a symmetric contact, is
    largest at an intermediate speed."""
    values, out = {}, []
    for k, r in enumerate(rows):
        prof = tables.read(os.path.join(folder, f'surface_profile_steady_{k:02d}.csv'))
        inside = [p['x_over_R'] for p in prof if p['gap_over_eps'] < 1.2]
        lead, trail = max(inside), min(inside)
        a = (lead + trail) / (lead - trail)
        values[f'edge_asymmetry({r["V_hat"]:g})'] = a
        out.append(abs(a))
    return Verdict(max(out[1:-1]) > max(out[0], out[-1]), f'values by speed {out}', values)


# The figure studies' output folders (parameter_files/fig*.prm) and the
# long tests that run them (tests/figure_sweep.check).
STUDIES = {'fig04a_07a': 'fig04a_long', 'fig04b_07b_08': 'fig04b_long',
           'fig09_10': 'fig09_long', 'fig11': 'fig11_long', 'fig12': 'fig12_long'}


def table(study):
    """The claims table's rows (text, ok, numbers); study(name) gives the
    curves of a figure study, None where it was not run."""
    out = []
    c = study('fig04b_07b_08')
    if c:
        out.append(('Fig. 4b: L_hat has a maximum at intermediate speed (muT = 6.08)',)
                   + maximum_inside(c, 'L_hat')[:2])
        out.append(('Fig. 7b/8b: under displacement control mu diverges where F_n crosses zero, '
                    'twice for delta_hat = 11',) + sign_changes_twice(c)[:2])
    else:
        out.append(('Fig. 4b, 7b, 8: study fig04b_07b_08', None, 'not run'))
    c = study('fig04a_07a')
    if c:
        out.append(('Fig. 4a: L_hat decreases monotonically with V_hat for muT = 1',)
                   + decreasing(c, 'L_hat')[:2])
    else:
        out.append(('Fig. 4a: study fig04a_07a', None, 'not run'))
    c = study('fig09_10')
    if c:
        out.append(('Fig. 9b: mu is bell-shaped under force control',) + bell_shaped(c)[:2])
        out.append(('Fig. 9b: the peak of mu lies near V_hat = 2-4',) + peak_between(c)[:2])
        out.append(('Fig. 10: mu_max decreases with F_hat > 0 and increases with F_hat < 0',)
                   + maxima_against_load(c)[:2])
    else:
        out.append(('Fig. 9b, 10: study fig09_10', None, 'not run'))
    for name, fig in (('fig11', 'Fig. 11 (displacement control)'), ('fig12', 'Fig. 12 (force control)')):
        c = study(name)
        if not c:
            out.append((f'{fig}: study {name}', None, 'not run'))
            continue
        out.append((f'{fig}: thinner layers give flatter L_hat curves',) + flatter_for_thinner(c)[:2])
        out.append((f'{fig}: thinner layers give smaller mu (mu_max grows with t_hat)' +
                    (', towards a plateau (inset of 12b; the two thickest within 5 %)'
                     if name == 'fig12' else ''),) + mu_grows_with_thickness(c, name == 'fig12')[:2])
    return out


def markdown(rows):
    """The claims table as Markdown lines."""
    lines = ['| claim of the paper | agrees | numbers |', '|---|---|---|']
    for text, verdict, numbers in rows:
        v = 'not run' if verdict is None else ('yes' if verdict else '**no**')
        lines.append(f'| {text} | {v} | {numbers} |')
    return lines


USAGE = """Checks the paper's qualitative claims against the studies' tables and
prints the claims table of doc/verification.md (Markdown).

    scripts/claims [ROOT]
    scripts/claims --tests BUILD_TESTS

ROOT (default: output) holds the output folders of the figure files
(parameter_files/fig*.prm): fig04a_07a, fig04b_07b_08, fig09_10, fig11,
fig12. With --tests the studies are read from the long tests' folders
instead (BUILD_TESTS/fig04a_long/output, ...: the studies of
tests/figure_sweep.check). A missing study gives 'not run'. Each claim is judged on the rows
with steady = 1; the numbers behind the verdict are printed with it."""


def main(argv=None):
    import sys
    argv = sys.argv[1:] if argv is None else argv
    tests = len(argv) > 1 and argv[0] == '--tests'
    root = argv[-1] if argv else 'output'

    def study(name):
        folder = os.path.join(STUDIES[name], 'output') if tests else name
        return read_study(os.path.join(root, folder, 'steady_state.csv'), name)
    print('\n'.join(markdown(table(study))))


if __name__ == '__main__':
    main()
