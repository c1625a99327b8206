# SPDX-License-Identifier: LGPL-2.1-or-later
"""Maugis-Dugdale adhesion of a rigid cylinder on an elastic half-plane
(plane strain; Baney and Hui 1997, Johnson and Greenwood 2008), as derived
in doc/model.md: a contact of half-width a, a cohesive zone a < |x| < c
with the constant tension sigma0 that ends where the gap has opened by
h0 = dgamma/sigma0. With m = c/a:

  load   P = pi E* a^2/(4 R) - 2 sigma0 a sqrt(m^2 - 1)
  gap    h0 = a^2/(2 R) [m sqrt(m^2 - 1) - arccosh m]
              + 2 sigma0 a/(pi E*) [I2(m) - I1(m)]
  I1(m) = 4 int_1^m [artanh(p q(x)) - artanh(q(x))] dx,
          q(x) = x - sqrt(x^2 - 1), p = q(m)
  I2(m) = 2 m ln(2 m) - 2 (m + 1) ln(m + 1) + 2 ln 2

For sigma0 -> infinity this is the JKR line contact,
P = pi E* a^2/(4 R) - sqrt(2 pi E* dgamma a) (checked in __main__). The
pull-off is the minimum of P(a). Standard library only."""
import math


def _I1(m, n=400):
    """Composite Simpson in u, x = cosh u (integrand ~ u ln u at u = 0)."""
    b = math.acosh(m)
    if b == 0:
        return 0.
    h, s = b / n, 0.
    for i in range(1, n + 1):
        u = i * h
        f = (math.atanh(math.exp(-b - u)) - math.atanh(math.exp(-u))) * math.sinh(u)
        s += (1 if i == n else (4 if i % 2 else 2)) * f
    return 4 * s * h / 3


def _I2(m):
    return 2 * m * math.log(2 * m) - 2 * (m + 1) * math.log(m + 1) + 2 * math.log(2)


def _gap_at_c(a, m, E, R, sigma0):
    hertz = a * a / (2 * R) * (m * math.sqrt(m * m - 1) - math.acosh(m))
    return hertz + 2 * sigma0 * a / (math.pi * E) * (_I2(m) - _I1(m))


def load(a, E, R, dgamma, sigma0):
    """(P, m) at contact half-width a: m from the gap condition (bisection)."""
    h0 = dgamma / sigma0
    lo, hi = 1., 2.
    while _gap_at_c(a, hi, E, R, sigma0) < h0:
        lo, hi = hi, 1 + 2 * (hi - 1)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if _gap_at_c(a, mid, E, R, sigma0) < h0:
            lo = mid
        else:
            hi = mid
    m = 0.5 * (lo + hi)
    return math.pi * E * a * a / (4 * R) - 2 * sigma0 * a * math.sqrt(m * m - 1), m


def pull_off(E, R, dgamma, sigma0):
    """(P_min, a, m): the minimum of P(a) by golden-section search."""
    scale = (R * R * dgamma / E) ** (1 / 3)
    lo, hi = 1e-4 * scale, 10 * scale
    g = (math.sqrt(5) - 1) / 2
    x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
    f1, f2 = load(x1, E, R, dgamma, sigma0)[0], load(x2, E, R, dgamma, sigma0)[0]
    for _ in range(90):
        if f1 < f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - g * (hi - lo)
            f1 = load(x1, E, R, dgamma, sigma0)[0]
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + g * (hi - lo)
            f2 = load(x2, E, R, dgamma, sigma0)[0]
    a = 0.5 * (lo + hi)
    P, m = load(a, E, R, dgamma, sigma0)
    return P, a, m


if __name__ == '__main__':
    # JKR limit: sigma0 large at fixed dgamma.
    E, R, dgamma = 1., 1e4, 1e-2
    a = 100.
    for sigma0 in [1., 10., 100.]:
        P, m = load(a, E, R, dgamma, sigma0)
        jkr = math.pi * E * a * a / (4 * R) - math.sqrt(2 * math.pi * E * dgamma * a)
        print(f'sigma0 {sigma0:6g}: P {P:.6f}, JKR {jkr:.6f}, m {m:.6f}')
    unit = (math.pi * dgamma ** 2 * E * R) ** (1 / 3)
    print('JKR pull-off / unit', -0.75 * 2 ** (2 / 3),
          'MD at sigma0 = 100:', pull_off(E, R, dgamma, 100.)[0] / unit)
