# SPDX-License-Identifier: LGPL-2.1-or-later
"""Maugis-Dugdale adhesion of a rigid sphere on an elastic half-space
(Maugis 1992, in the notation of Johnson and Greenwood 1997): a contact of
radius a, a cohesive zone a < r < c of constant tension sigma0 that ends
where the gap has opened by h0 = w/sigma0 (w the work of adhesion). With
the reduced quantities

  A = a (4 E*/(3 pi w R^2))^(1/3),  P_bar = P/(pi w R),  m = c/a,
  lambda = sigma0 (9 R/(2 pi w E*^2))^(1/3)

the two equations are

  1 = (lambda A^2/2) [sqrt(m^2 - 1) + (m^2 - 2) arctan sqrt(m^2 - 1)]
      + (4 lambda^2 A/3) [sqrt(m^2 - 1) arctan sqrt(m^2 - 1) - m + 1]
  P_bar = A^3 - lambda A^2 [sqrt(m^2 - 1) + m^2 arctan sqrt(m^2 - 1)]

For lambda -> infinity this is JKR (pull-off P_bar = -3/2), for lambda -> 0
DMT (-2). The pull-off under load control is the minimum of P_bar(A).
Standard library only; __main__ checks both limits."""
import math


def _terms(m):
    s = math.sqrt(m * m - 1)
    return s, math.atan(s)


def _gap_condition(A, m, lam):
    s, t = _terms(m)
    return (lam * A * A / 2 * (s + (m * m - 2) * t)
            + 4 * lam * lam * A / 3 * (s * t - m + 1) - 1)


def load(A, lam):
    """(P_bar, m) at the reduced contact radius A: m from the gap
    condition (bisection; it grows monotonically with m)."""
    lo, hi = 1., 2.
    while _gap_condition(A, hi, lam) < 0:
        hi *= 2
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if _gap_condition(A, mid, lam) < 0:
            lo = mid
        else:
            hi = mid
    m = 0.5 * (lo + hi)
    s, t = _terms(m)
    return A**3 - lam * A * A * (s + m * m * t), m


def pull_off(lam):
    """(P_bar_min, A, m): the minimum of P_bar(A), golden-section search."""
    lo, hi = 1e-4, 3.
    g = (math.sqrt(5) - 1) / 2
    for _ in range(200):
        x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
        if load(x1, lam)[0] < load(x2, lam)[0]:
            hi = x2
        else:
            lo = x1
    A = 0.5 * (lo + hi)
    P, m = load(A, lam)
    return P, A, m


def maugis_parameter(muT):
    """lambda of the Lennard-Jones law with the same work of adhesion and
    peak traction sigma_max = 16 w/(9 sqrt(3) eps), at Tabor parameter muT =
    (R w^2/(E*^2 eps^3))^(1/3): lambda = sigma_max (9R/(2 pi w E*^2))^(1/3)."""
    return 16 / (9 * math.sqrt(3)) * (9 / (2 * math.pi)) ** (1 / 3) * muT


if __name__ == '__main__':
    print('JKR limit (lambda 1e3):', pull_off(1e3)[0], '(-1.5)')
    print('DMT limit (lambda 1e-3):', pull_off(1e-3)[0], '(-2)')
    for muT in (1, 3, 10):
        lam = maugis_parameter(muT)
        P, A, m = pull_off(lam)
        print(f'muT {muT}: lambda {lam:.4f}, pull-off P/(pi w R) = {P:.5f}, F_hat = {P / 1.5:.5f}, m = {m:.4f}')
