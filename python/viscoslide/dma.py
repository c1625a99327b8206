# SPDX-License-Identifier: LGPL-2.1-or-later
"""From a DMA measurement to the Prony series viscoslide reads: the master
curve by time-temperature superposition, its shift law, and the fit.

    scripts/dma FILE.csv [--reference-temperature T] [--tolerance E]
                [--poisson NU] [--tau-ref SECONDS] [-o PREFIX]

FILE.csv holds the isothermal frequency sweeps of a dynamic mechanical
analysis: a header naming the columns f (frequency), E_stor and E_loss
(or G_stor and G_loss, converted with E = 2 (1 + nu) G, --poisson), T and
Set (one label per isothermal sweep), and a second line with their
units: Hz or rad/s; Pa, kPa, MPa or GPa; C or K (the layout of the
example files of pyvisco, NREL, BSD-3-Clause).

1. Shift factors: each isotherm is shifted along log f onto its
   neighbour nearer the reference temperature (default: the median of
   the sweeps) by the mean horizontal distance of their log E' against
   log f where their E' meet (interpolated where they overlap, extended
   by their end slopes across a gap); the shifts add up outwards from
   the reference.
2. Shift laws fitted to them: WLF, log aT = -C1 (T - Tref)/(C2 + T -
   Tref), and Arrhenius, log aT = Ea/(R ln 10) (1/T - 1/Tref); both
   reported, with their RMS residuals in decades.
3. The Prony series E(t) = E_relaxed + sum_k E_k exp(-t/tau_k): its
   moduli found by non-negative least squares on E' and E'' at once,
   each point weighted by 1/value (relative errors), on the sparsest grid
   of relaxation times (a quarter, half, one or two per decade over the
   master curve's span) whose RMS relative error of E' and E'' is within
   --tolerance (default 0.05), or within 10 % of the error on two per
   decade where the data's scatter keeps that above the tolerance; then
   its smallest terms are dropped one by one while it still is. Values far off the fit on all the times (beyond
   2.5 robust standard deviations of the relative residuals) are weighted
   down (Huber) and left out of the error, their number printed. A fit
   whose error is still above --tolerance is written with a warning, on
   stderr and in the header of PREFIX_prony.csv, naming the decade of
   omega a_T where its RMS error is largest.
4. Written: PREFIX_prony.csv (the columns tau_over_tau and weight that
   'Material/Prony file' reads, tau over --tau-ref, default 1 s, and
   E_k in Pa), PREFIX_shift.csv (T, log_aT measured, WLF, Arrhenius),
   PREFIX_master.png (data against fit) and PREFIX_shift.png; printed:
   E0 (the relaxed modulus), Einf, E0/Einf (for 'Material/E0 over
   Einf'), the WLF constants, Ea, the number of terms and the fit's
   errors.

Refused, with exit 1 and a message naming the file's line or the option:
a missing column or unit, a value that is not a finite number (nan, inf)
or a negative modulus, a single temperature, a --reference-temperature
outside the sweeps' temperatures (the shift there would be extrapolated),
and neighbouring sweeps that come out more than 10 decades apart (E' too
flat to be superposed)."""
import argparse
import math
import os
import sys

R_GAS = 8.314462618  # J/(mol K)
PRESSURE = {'Pa': 1., 'kPa': 1e3, 'MPa': 1e6, 'GPa': 1e9}
MAX_PAIR_SHIFT = 10.  # decades between neighbouring isotherms


class DmaError(ValueError):
    """Bad input, with a message naming the column or the entry."""


def read(path, poisson=0.5):
    """Isotherms {set: (T in K, f in Hz, E' in Pa, E'' in Pa)} from a DMA CSV,
    sorted by frequency."""
    import numpy as np
    try:
        with open(path, encoding='utf-8-sig') as f:
            # Blank lines are skipped but counted, so that a message names
            # the line an editor shows.
            lines = [(k, l.strip()) for k, l in enumerate(f, start=1) if l.strip()]
    except OSError as e:
        raise DmaError(f'cannot read {path}: {e.strerror}')
    if len(lines) < 3:
        raise DmaError(f'{path}: a header, a units line and data are needed')
    names = [n.strip() for n in lines[0][1].split(',')]
    units = [u.strip() for u in lines[1][1].split(',')]
    kind = 'G' if 'G_stor' in names and 'E_stor' not in names else 'E'
    needed = ['f', f'{kind}_stor', f'{kind}_loss', 'T', 'Set']
    for n in needed:
        if n not in names:
            raise DmaError(f'{path}: no column {n} (columns: {", ".join(names)})')
    if len(units) != len(names):
        raise DmaError(f'{path}: the units line has {len(units)} entries for {len(names)} columns')
    col = {n: names.index(n) for n in needed}
    unit = {n: units[col[n]] for n in needed}
    if unit['f'] not in ('Hz', 'rad/s'):
        raise DmaError(f'{path}: unknown unit {unit["f"]!r} of column f (Hz or rad/s)')
    for n in needed[1:3]:
        if unit[n] not in PRESSURE:
            raise DmaError(f'{path}: unknown unit {unit[n]!r} of column {n} ({", ".join(PRESSURE)})')
    if unit['T'] not in ('C', 'K'):
        raise DmaError(f'{path}: unknown unit {unit["T"]!r} of column T (C or K)')
    to_modulus = 2 * (1 + poisson) if kind == 'G' else 1.
    sets = {}
    for k, line in lines[2:]:
        v = line.split(',')
        if len(v) <= max(col.values()):
            raise DmaError(f'{path}, line {k}: {len(v)} entries for {len(names)} columns')
        try:
            f, s, l, T = (float(v[col[n]]) for n in needed[:4])
        except ValueError:
            raise DmaError(f'{path}, line {k}: not a number in {needed[:4]}')
        # float() takes nan and inf, which no comparison below refuses and
        # which would reach the least squares of the fit.
        for n, x in zip(needed[:4], (f, s, l, T)):
            if not math.isfinite(x):
                raise DmaError(f'{path}, line {k}: column {n} is {v[col[n]].strip()!r}, '
                               'not a finite number')
        if f <= 0 or s <= 0 or l < 0:
            raise DmaError(f'{path}, line {k}: frequency and storage modulus must be positive '
                           f'and the loss modulus non-negative ({f}, {s}, {l})')
        if unit['f'] == 'rad/s':
            f /= 2 * math.pi
        T += 273.15 if unit['T'] == 'C' else 0.
        sets.setdefault(v[col['Set']].strip(), []).append(
            (T, f, s * PRESSURE[unit[needed[1]]] * to_modulus,
             l * PRESSURE[unit[needed[2]]] * to_modulus))
    out = {}
    for name, rows in sets.items():
        rows.sort(key=lambda r: r[1])
        a = np.array(rows)
        out[name] = (a[:, 0].mean(), a[:, 1], a[:, 2], a[:, 3])
    return out


def pair_shift(fixed, moving):
    """log10 of the factor that moves isotherm `moving` along f onto `fixed`:
    the mean horizontal distance between the two sweeps' log E' against
    log f, over ten levels of log E' spanning where they meet. Where their
    E' overlap, each sweep is read at those levels by interpolation (E'
    rises with f); where it does not (on the glassy plateau E' changes by
    a few percent per decade and neighbouring sweeps miss each other),
    each is extended across the gap by the slope of a line fitted to the
    whole sweep."""
    import numpy as np
    sweeps = []
    for c in (fixed, moving):
        x, y = np.log10(c[1]), np.log10(c[2])
        # Measured E' on a plateau wobbles: its running maximum along f is
        # the rising curve TTS assumes; the whole sweep's slope extends it.
        y = np.maximum.accumulate(y)
        slope = np.polyfit(x, y, 1)[0]
        if slope <= 0:
            raise DmaError('the storage modulus of the sweep at '
                           f'{c[0] - 273.15:g} C does not rise with frequency: it cannot be shifted')
        sweeps.append((x, y, 1 / slope))

    def log_f(sweep, level):
        """log f where the sweep's log E' is `level`, extended linearly."""
        x, y, inverse_slope = sweep
        if level < y[0]:
            return x[0] + inverse_slope * (level - y[0])
        if level > y[-1]:
            return x[-1] + inverse_slope * (level - y[-1])
        return np.interp(level, y, x)

    (xf, yf, _), (xm, ym, _) = sweeps
    lo, hi = max(yf[0], ym[0]), min(yf[-1], ym[-1])
    if lo > hi:  # no overlap: the gap between them
        lo, hi = hi, lo
    levels = np.linspace(lo, hi, 10)
    return float(np.mean([log_f(sweeps[0], v) - log_f(sweeps[1], v) for v in levels]))


def shift_factors(isotherms, T_ref=None):
    """{set: log10 aT} (aT multiplies the frequency onto the reference
    temperature's curve), and T_ref in K (default the median sweep's)."""
    import numpy as np
    order = sorted(isotherms, key=lambda k: isotherms[k][0])
    if len(order) < 2:
        raise DmaError('a master curve needs isotherms at two temperatures at least; '
                       f'the file has {len(order)}')
    temps = [isotherms[k][0] for k in order]
    if T_ref is None:
        T_ref = temps[len(temps) // 2]
    if not temps[0] <= T_ref <= temps[-1]:
        # Beyond the sweeps the offset below would be clamped to the end
        # sweep's: the curve would be that sweep's, labelled T_ref.
        raise DmaError(f'--reference-temperature {T_ref - 273.15:g} C is outside the temperatures '
                       f'of the sweeps, {temps[0] - 273.15:g} to {temps[-1] - 273.15:g} C: the '
                       'master curve there would be extrapolated')
    r = min(range(len(order)), key=lambda i: abs(temps[i] - T_ref))
    log_a = {order[r]: 0.}
    for i in list(range(r + 1, len(order))) + list(range(r - 1, -1, -1)):
        j = i - 1 if i > r else i + 1
        step = pair_shift(isotherms[order[j]], isotherms[order[i]])
        # A sweep whose E' barely rises (a plateau, within its scatter) is
        # extended across a gap by a near-infinite inverse slope; no
        # neighbouring isotherms of a real measurement are MAX_PAIR_SHIFT
        # decades apart.
        if not abs(step) <= MAX_PAIR_SHIFT:
            lo, hi = sorted((temps[i] - 273.15, temps[j] - 273.15))
            raise DmaError(f'the sweeps at {lo:g} and {hi:g} C come out {abs(step):.3g} decades '
                           f'apart (more than {MAX_PAIR_SHIFT:g}): their storage moduli are too '
                           'flat (against their scatter) to be superposed')
        log_a[order[i]] = log_a[order[j]] + step
    # The reference temperature may lie between sweeps: the shift there by
    # linear interpolation is subtracted.
    T = [isotherms[k][0] for k in order]
    a = [log_a[k] for k in order]
    offset = float(np.interp(T_ref, T, a))
    return {k: v - offset for k, v in log_a.items()}, T_ref


def fit_wlf(T, log_a, T_ref):
    """C1, C2 (K) of WLF, and the RMS residual in decades."""
    import numpy as np
    from scipy.optimize import curve_fit
    wlf = lambda T, C1, C2: -C1 * (T - T_ref) / (C2 + T - T_ref)
    T, log_a = np.asarray(T), np.asarray(log_a)
    (C1, C2), _ = curve_fit(wlf, T, log_a, p0=(17.4, 51.6 + max(0., T_ref - T.min())),
                            maxfev=20000)
    return C1, C2, float(np.sqrt(np.mean((wlf(T, C1, C2) - log_a) ** 2)))


def fit_arrhenius(T, log_a, T_ref):
    """Ea (J/mol), and the RMS residual in decades."""
    import numpy as np
    x = 1 / np.asarray(T) - 1 / T_ref
    slope = float(np.dot(x, log_a) / np.dot(x, x))
    return slope * R_GAS * math.log(10), float(np.sqrt(np.mean((slope * x - log_a) ** 2)))


def moduli(omega, E_relaxed, E, tau):
    """E'(omega), E''(omega) of the Prony series."""
    import numpy as np
    wt = np.outer(omega, tau)
    return (E_relaxed + (wt ** 2 / (1 + wt ** 2)) @ E, (wt / (1 + wt ** 2)) @ E)


def relative_residuals(omega, storage, loss, E_relaxed, E, tau):
    """The relative errors of E' and then of E'' at the points."""
    import numpy as np
    s, l = moduli(omega, E_relaxed, E, tau)
    return np.concatenate([s / storage - 1, l / loss - 1])


def fit_prony(omega, storage, loss, tolerance=0.05, per_decade=2):
    """(E_relaxed, E_k, tau_k, error, outliers, counted): the Prony series with the
    fewest terms whose RMS relative error in E' and E'' is within
    tolerance (or within 10 % of the error of all the times, where the
    data's scatter keeps that above the tolerance): the sparsest of the
    grids of per_decade/8, /4, /2 and per_decade relaxation times per
    decade over the master curve's span that meets it, then its smallest
    terms removed one by one while it still does. The fit is
    robust (Huber): a value whose relative residual on all the times
    exceeds 2.5 robust standard deviations (1.4826 times the median
    absolute residual) is weighted down in proportion; error is the RMS
    over the values not weighted down (counted: True for those, E' values
    first, then E''), outliers the count of the others."""
    import numpy as np
    from scipy.optimize import nnls
    lo = math.floor(math.log10(1 / omega.max()))
    hi = math.ceil(math.log10(1 / omega.min()))
    grid = lambda n: 10. ** np.linspace(lo, hi, int(round((hi - lo) * n)) + 1)
    weight = np.ones(2 * len(omega))

    def solve(tau):
        wt = np.outer(omega, tau)
        A = np.vstack([np.hstack([np.ones((len(omega), 1)), wt ** 2 / (1 + wt ** 2)]) / storage[:, None],
                       np.hstack([np.zeros((len(omega), 1)), wt / (1 + wt ** 2)]) / loss[:, None]])
        x, _ = nnls(A * weight[:, None], weight)
        keep = x[1:] > 0
        r = relative_residuals(omega, storage, loss, x[0], x[1:][keep], tau[keep])
        return x[0], x[1:][keep], tau[keep], float(np.sqrt(np.mean(r[weight == 1] ** 2)))

    r = relative_residuals(omega, storage, loss, *solve(grid(per_decade))[:3])
    limit = 2.5 * 1.4826 * np.median(np.abs(r))
    weight = np.minimum(1., limit / np.maximum(np.abs(r), 1e-300))
    finest = solve(grid(per_decade))
    target = max(tolerance, 1.1 * finest[3])
    # The sparsest grid of times that meets the target, then its terms
    # one by one while it still does.
    best = finest
    for n in (per_decade / 8, per_decade / 4, per_decade / 2):
        fit = solve(grid(n))
        if fit[3] <= target:
            best = fit
            break
    while len(best[1]) > 1:
        trial = solve(np.delete(best[2], np.argmin(best[1])))
        if trial[3] > target:
            break
        best = trial
    return best + (int((weight < 1).sum()), weight == 1)


def worst_band(omega, storage, loss, E_relaxed, E, tau, counted):
    """(omega_lo, omega_hi, rms, n): the decade of omega (from a power of
    ten to the next) where the RMS relative error of the fit's E' and E''
    over the counted values is largest, and the number of those values."""
    import numpy as np
    r = relative_residuals(omega, storage, loss, E_relaxed, E, tau)
    decade = np.tile(np.floor(np.log10(omega)), 2)
    bands = []
    for d in np.unique(decade[counted]):
        inside = counted & (decade == d)
        bands.append((float(np.sqrt(np.mean(r[inside] ** 2))), d, int(inside.sum())))
    rms, d, n = max(bands)
    return 10. ** d, 10. ** (d + 1), rms, n


def master_curve(isotherms, log_a):
    """omega (rad/s) on the reference temperature, E', E'', sorted."""
    import numpy as np
    rows = sorted((2 * math.pi * f * 10 ** log_a[k], s, l)
                  for k, (T, fs, ss, ls) in isotherms.items() for f, s, l in zip(fs, ss, ls))
    a = np.array(rows)
    return a[:, 0], a[:, 1], a[:, 2]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split('\n\n', 1)[1])
    ap.add_argument('csv')
    ap.add_argument('--reference-temperature', type=float, help='in C')
    ap.add_argument('--tolerance', type=float, default=0.05)
    ap.add_argument('--poisson', type=float, default=0.5)
    ap.add_argument('--tau-ref', type=float, default=1.)
    ap.add_argument('-o', dest='prefix')
    a = ap.parse_args(argv)
    prefix = a.prefix or os.path.splitext(a.csv)[0]
    try:
        if not 0 <= a.poisson < 0.5 + 1e-12:
            raise DmaError(f'--poisson {a.poisson} is outside [0, 0.5]')
        if not a.tolerance > 0 or not a.tau_ref > 0:
            raise DmaError('--tolerance and --tau-ref must be positive')
        isotherms = read(a.csv, a.poisson)
        T_ref = None if a.reference_temperature is None else a.reference_temperature + 273.15
        log_a, T_ref = shift_factors(isotherms, T_ref)
    except DmaError as e:
        sys.exit(f'scripts/dma: {e}')
    T = sorted(isotherms[k][0] for k in isotherms)
    la = [log_a[k] for k in sorted(isotherms, key=lambda k: isotherms[k][0])]
    C1, C2, wlf_rms = fit_wlf(T, la, T_ref)
    Ea, arr_rms = fit_arrhenius(T, la, T_ref)
    omega, storage, loss = master_curve(isotherms, log_a)
    E_relaxed, E, tau, error, outliers, counted = fit_prony(omega, storage, loss, a.tolerance)
    warning = None
    if error > a.tolerance:
        lo, hi, band_rms, n = worst_band(omega, storage, loss, E_relaxed, E, tau, counted)
        warning = (f'the Prony fit misses its tolerance: RMS relative error of E\' and E\'\' '
                   f'{error:.3g} against --tolerance {a.tolerance:g}; the misfit is largest at '
                   f'omega a_T {lo:.3g} to {hi:.3g} rad/s at {T_ref - 273.15:g} C (RMS {band_rms:.3g} '
                   f'over its {n} values)')
        print(f'scripts/dma: warning: {warning}', file=sys.stderr)
    try:
        write(prefix, T, la, T_ref, C1, C2, Ea, E_relaxed, E, tau, a.tau_ref, warning)
    except OSError as e:
        sys.exit(f'scripts/dma: cannot write {e.filename}: {e.strerror}')
    Einf = E_relaxed + E.sum()
    print(f'master curve at T_ref = {T_ref - 273.15:g} C: {len(isotherms)} isotherms, '
          f'omega {omega.min():.3g} to {omega.max():.3g} rad/s')
    print(f'WLF: C1 = {C1:.4g}, C2 = {C2:.4g} K (RMS {wlf_rms:.3g} decades); '
          f'Arrhenius: Ea = {Ea / 1e3:.4g} kJ/mol (RMS {arr_rms:.3g} decades)')
    print(f'Prony series: {len(E)} terms, tau {tau.min():.3g} to {tau.max():.3g} s, RMS '
          f'relative error of E\' and E\'\' {error:.3g} (tolerance {a.tolerance:g}) over the '
          f'{2 * len(omega) - outliers} of {2 * len(omega)} values not weighted down as outliers')
    print(f'E0 (relaxed) = {E_relaxed:.4g} Pa, Einf = {Einf:.4g} Pa, E0 over Einf = '
          f'{E_relaxed / Einf:.4g}')
    print(f'{prefix}_prony.csv, {prefix}_shift.csv')
    plot(prefix, T, la, T_ref, C1, C2, Ea, omega, storage, loss, E_relaxed, E, tau)


def write(prefix, T, la, T_ref, C1, C2, Ea, E_relaxed, E, tau, tau_ref, warning=None):
    x = lambda T: 1 / T - 1 / T_ref
    with open(prefix + '_prony.csv', 'w') as f:
        Einf = E_relaxed + E.sum()
        f.write(f'# Prony series from the DMA master curve at {T_ref - 273.15:g} C (scripts/dma):\n'
                f'# tau_over_tau: relaxation time over {tau_ref:g} s; weight: E_k in Pa.\n'
                f'# With it: Material/E0 over Einf = {E_relaxed / Einf:.6g} (E0 {E_relaxed:.6g} Pa, '
                f'Einf {Einf:.6g} Pa).\n'
                + (f'# Warning: {warning}.\n' if warning else '') +
                'tau_over_tau,weight\n')
        for t, e in zip(tau, E):
            f.write(f'{t / tau_ref:.6g},{e:.6g}\n')
    with open(prefix + '_shift.csv', 'w') as f:
        f.write(f'# shift factors to {T_ref - 273.15:g} C; WLF C1 {C1:.6g}, C2 {C2:.6g} K; '
                f'Arrhenius Ea {Ea:.6g} J/mol\nT_C,log_aT,log_aT_WLF,log_aT_Arrhenius\n')
        for t, l in zip(T, la):
            f.write(f'{t - 273.15:.6g},{l:.6g},{-C1 * (t - T_ref) / (C2 + t - T_ref):.6g},'
                    f'{Ea / (R_GAS * math.log(10)) * x(t):.6g}\n')


def plot(prefix, T, la, T_ref, C1, C2, Ea, omega, storage, loss, E_relaxed, E, tau):
    from . import style
    import numpy as np
    plt = style.pyplot(style.BASE, 'scripts/dma')
    fig, ax = plt.subplots(figsize=style.SIZE, layout='constrained')
    w = np.logspace(math.log10(omega.min()) - 0.5, math.log10(omega.max()) + 0.5, 300)
    s, l = moduli(w, E_relaxed, E, tau)
    ax.loglog(omega, storage, 'o', ms=3, mfc='none', color='C0', label="$E'$ measured")
    ax.loglog(omega, loss, 's', ms=3, mfc='none', color='C1', label="$E''$ measured")
    ax.loglog(w, s, '-', color='C0', label=f"$E'$ Prony, {len(E)} terms")
    ax.loglog(w, l, '-', color='C1', label="$E''$ Prony")
    ax.set_xlabel(r'$\omega\,a_T$ (rad/s) at $T_{ref} = %g$ °C' % (T_ref - 273.15))
    ax.set_ylabel('modulus (Pa)')
    ax.legend()
    style.save(fig, prefix + '_master')
    fig, ax = plt.subplots(figsize=style.SIZE, layout='constrained')
    Tc = np.array(T) - 273.15
    Tf = np.linspace(min(T), max(T), 200)
    ax.plot(Tc, la, 'o', label='from the data (neighbouring isotherms)')
    ax.plot(Tf - 273.15, -C1 * (Tf - T_ref) / (C2 + Tf - T_ref), '-',
            label=f'WLF: $C_1$ = {C1:.3g}, $C_2$ = {C2:.3g} K')
    ax.plot(Tf - 273.15, Ea / (R_GAS * math.log(10)) * (1 / Tf - 1 / T_ref), '--',
            label=f'Arrhenius: $E_a$ = {Ea / 1e3:.3g} kJ/mol')
    ax.set_xlabel('T (°C)')
    ax.set_ylabel(r'$\log_{10} a_T$ (to $T_{ref} = %g$ °C)' % (T_ref - 273.15))
    ax.legend()
    style.save(fig, prefix + '_shift')


if __name__ == '__main__':
    main()
