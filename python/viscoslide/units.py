# SPDX-License-Identifier: LGPL-2.1-or-later
"""Physical units for viscoslide, whose inputs and outputs are dimensionless
(doc/conventions.md).

    scripts/units prm MATERIAL [--speeds "V1, V2, ..."] [--load F] [--approach D]
        prints the parameter-file entries of the material and the contact:
        Material/E0 over Einf, Poisson ratio, Time constant; Adhesion/Tabor
        parameter, R over eps; and, if given, Sliding/Sliding speed (V in
        m/s), Loading/Target load (F in N/m), Loading/Final approach (D in m).
    scripts/units si MATERIAL OUTPUT_DIR
        writes OUTPUT_DIR/steady_state_si.csv: the rows of steady_state.csv
        with V [m/s], delta [m], F_n, F_t [N/m], L [m] and the dissipation
        rate [W/m] appended.

MATERIAL is given as options, all SI:
    --E0 PA        relaxed Young's modulus
    --Einf PA      instantaneous (glassy) Young's modulus
    --nu NU        Poisson ratio
    --tau S        relaxation time of the standard linear solid
    --dgamma J_M2  work of adhesion (J/m^2)
    --eps M        range of the interaction (m)
    --R M          radius of the cylinder (m)

The scales (internal units eps = 1, E0* = E0/(1 - nu^2) = 1, tau = 1):
    muT   = (R dgamma^2 / (E0*^2 eps^3))^(1/3)      R_hat = R / eps
    V_hat = V tau / eps                               delta_hat = delta / eps
    F_hat = F / (pi dgamma^2 E0* R)^(1/3)             L_hat = L / R
    dissipation_rate_hat = D / (F_scale eps / tau)
"""
import argparse
import csv
import math
import os
import sys

from . import tables


class Scales:
    def __init__(self, a):
        for name in ('E0', 'Einf', 'tau', 'dgamma', 'eps', 'R'):
            if not getattr(a, name) > 0:
                sys.exit(f'scripts/units: --{name} must be positive')
        if not 0 <= a.nu < 0.5:
            sys.exit('scripts/units: --nu must be in [0, 0.5)')
        if not a.Einf >= a.E0:
            sys.exit('scripts/units: --Einf must not be below --E0')
        self.a = a
        self.E0_star = a.E0 / (1 - a.nu ** 2)
        self.muT = (a.R * a.dgamma ** 2 / (self.E0_star ** 2 * a.eps ** 3)) ** (1 / 3)
        self.R_hat = a.R / a.eps
        self.force = (math.pi * a.dgamma ** 2 * self.E0_star * a.R) ** (1 / 3)  # N/m
        self.speed = a.eps / a.tau                                             # m/s
        self.power = self.force * a.eps / a.tau                                # W/m


def numbers(text):
    return [float(w) for w in text.replace(',', ' ').split()]


def prm(s, a):
    print(f'# {s.a.E0:g} Pa / {s.a.Einf:g} Pa, nu {s.a.nu:g}, tau {s.a.tau:g} s, '
          f'dgamma {s.a.dgamma:g} J/m^2, eps {s.a.eps:g} m, R {s.a.R:g} m')
    print(f'# scales: E0* = {s.E0_star:.6g} Pa, force (pi dgamma^2 E0* R)^(1/3) = '
          f'{s.force:.6g} N/m, speed eps/tau = {s.speed:.6g} m/s')
    print('subsection Material')
    print(f'  set E0 over Einf  = {s.a.E0 / s.a.Einf:.6g}')
    print(f'  set Poisson ratio = {s.a.nu:g}')
    print('  set Time constant = relaxation')
    print('end')
    print('subsection Adhesion')
    print(f'  set Tabor parameter = {s.muT:.6g}')
    print(f'  set R over eps      = {s.R_hat:.6g}')
    print('end')
    if a.load is not None or a.approach is not None:
        print('subsection Loading')
        if a.approach is not None:
            print(f'  set Final approach = {a.approach / s.a.eps:.6g}')
        if a.load is not None:
            print(f'  set Target load    = {a.load / s.force:.6g}')
        print('end')
    if a.speeds:
        print('subsection Sliding')
        print('  set Sliding speed = ' +
              ', '.join(f'{v / s.speed:.6g}' for v in numbers(a.speeds)))
        print('end')
    # Where the run will be expensive: the mesh resolves eps at the
    # contact edges of a contact about sqrt(R eps) wide or more.
    if s.R_hat > 1e6 or s.muT > 20:
        print(f'# note: R_hat {s.R_hat:.3g} and muT {s.muT:.3g} are far beyond '
              'the paper\'s 1e4 and 1-6.08: cells of an eps at contact edges '
              'that are R_hat^(1/2) eps apart make a very large mesh',
              file=sys.stderr)


def si(s, directory):
    path = os.path.join(directory, 'steady_state.csv')
    rows = tables.read(path, text=True)  # the cells copied as written
    if not rows:
        sys.exit(f'scripts/units: no rows in {path}')
    extra = ['V_m_per_s', 'delta_m', 'F_n_N_per_m', 'F_t_N_per_m', 'L_m',
             'dissipation_rate_W_per_m']
    out_path = os.path.join(directory, 'steady_state_si.csv')

    def scaled(row, key, factor):
        try:
            return f'{float(row[key]) * factor:.9g}'
        except (KeyError, ValueError):
            return ''
    with open(out_path, 'w', newline='') as f:
        f.write(f'# steady_state.csv in SI units by scripts/units: E0 {s.a.E0:g} Pa, '
                f'Einf {s.a.Einf:g} Pa, nu {s.a.nu:g}, tau {s.a.tau:g} s, '
                f'dgamma {s.a.dgamma:g} J/m^2, eps {s.a.eps:g} m, R {s.a.R:g} m\n')
        w = csv.writer(f)
        w.writerow(list(rows[0].keys()) + extra)
        for r in rows:
            w.writerow(list(r.values()) + [
                scaled(r, 'V_hat', s.speed), scaled(r, 'delta_hat', s.a.eps),
                scaled(r, 'F_n_hat', s.force), scaled(r, 'F_t_hat', s.force),
                scaled(r, 'L_hat', s.a.R),
                scaled(r, 'dissipation_rate_hat', s.power)])
    print(out_path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('mode', choices=['prm', 'si'])
    ap.add_argument('directory', nargs='?')
    for name in ('E0', 'Einf', 'nu', 'tau', 'dgamma', 'eps', 'R'):
        ap.add_argument(f'--{name}', type=float, required=True)
    ap.add_argument('--speeds')
    ap.add_argument('--load', type=float)
    ap.add_argument('--approach', type=float)
    a = ap.parse_args()
    s = Scales(a)
    if a.mode == 'prm':
        prm(s, a)
    else:
        if not a.directory:
            sys.exit('scripts/units si: name the output directory')
        si(s, a.directory)


if __name__ == '__main__':
    main()
