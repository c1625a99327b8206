# SPDX-License-Identifier: LGPL-2.1-or-later
"""Reference solution: Hunter's problem (standard library only).

A rigid parabolic cylinder, profile h(x) = x^2/(2R), slides without friction
(or rolls without tangential traction) at speed V towards +x over a
viscoelastic half-plane in plane strain, under the normal load P per unit
length. The material is a standard linear solid with constant Poisson ratio:
    E(t) = E0 + (Einf - E0) exp(-t/tau),
    J(t) = 1/E0 - (1/E0 - 1/Einf) exp(-t/tau_c),   tau_c = tau Einf/E0,
and the plane-strain moduli are E* = E/(1 - nu^2).

References
  S.C. Hunter, "The rolling contact of a rigid cylinder with a viscoelastic
    half space", J. Appl. Mech. 28 (1961) 611-617 (exact solution for this
    material).
  K.L. Johnson, Contact Mechanics, CUP 1985 (viscoelastic rolling; restates
    Hunter's result).
  B.N.J. Persson, "Rolling friction for hard cylinder and sphere on
    viscoelastic solid", Eur. Phys. J. E (2010).
  G. Carbone, C. Putignano, "A novel methodology to predict sliding and
    rolling friction of viscoelastic materials: theory and experiments",
    J. Mech. Phys. Solids (2013).
The closed form below was derived for this file along Hunter's lines
(reduction to a Hilbert problem). Its notation was not checked against the
original paper. A second, independent direct numerical solution confirms it
(see the end of this docstring).

Notation and conventions
  Lengths are in the units of R; x is measured from the indenter apex in the
  frame that moves with it. Material comes in at +x and leaves at -x. p > 0 is
  compressive. The contact is c1 < x < c2, with c1 = -a_trail and c2 = a_lead;
  m = (c1 + c2)/2 is its centre and h = (c2 - c1)/2 its half-width.
      L   = V tau_c               (retardation length, the V_tau_c argument)
      lam = V tau = L E0*/Einf*   (relaxation length)
      a0  = sqrt(4 P R/(pi E0*))  (Hertz half-width, relaxed modulus)

Governing equation
  A material point now at x was at x + V s a time s ago. Applying the
  hereditary law to the elastic half-plane solution gives the surface
  deflection u (positive into the solid), with H(x) = PV int p(xi)/(x - xi):
      -u'(x) = (2/pi) [ H(x)/Einf* + (1/E0* - 1/Einf*) int_0^inf e^-v H(x + L v) dv ]
             = (2/pi) int p(xi) K(x - xi) dxi,
      K(d)   = 1/(Einf* d) + (1/E0* - 1/Einf*) e^(d/L) E1(d/L) / L.
  Inside the contact, -u'(x) = x/R (rigid profile). Also p(c1) = p(c2) = 0
  (bounded pressure at both edges) and int p = P.

(1) Closed form (Hunter)
  Apply (1 - L d/dx) to the equation. Inside the contact it becomes
  H/E0* - (L/Einf*) H' = (pi/2)(x - L)/R. This is a Hilbert problem for
  W(z) = int [p/E0* - (L/Einf*) p'](xi)/(z - xi) dxi, with W ~ P/(E0* z):
      W(z) = (pi/2R) [ z - L - Q(z)/sqrt((z - c1)(z - c2)) ].
  Here Q is a quadratic, Q(m + h t) = h^2 t^2 + b1 t + b0. Then
  p - lam p' = E0* r, with r = -Q/(2R sqrt((x - c1)(c2 - x))), and p(c2) = 0.
  The constant lost by the differentiation is fixed by the deflection slope
  at the leading edge, which is set by the load-free surface ahead of the
  contact. The conditions are then:
      load:     b0 = -(a0^2 + h^2)/2
      p(c1)=0:  int_-1^1 e^(-zA t) Q dt/sqrt(1-t^2) = 0, which is
                b1 I1(zA) = h^2 (I0(zA) - I1(zA)/zA) + b0 I0(zA),  zA = h/lam
      leading:  int_1^inf e^(-zB t) Q dt/sqrt(t^2-1) = 0, which is
                b1 K1(zB) = -h^2 (K0(zB) + K1(zB)/zB) - b0 K0(zB), zB = h/L
  (I_n and K_n are modified Bessel functions.) Eliminating b1 leaves one
  equation in h; it has a single root with a0 sqrt(E0/Einf) < h < a0. Then
      m = L + b1/h,   a_lead = m + h,   a_trail = h - m,
      p(x) = -(E0*/(2 R lam)) int_0^thx exp(-(m + h cos th - x)/lam)
                                  Q(m + h cos th) dth,  thx = acos((x-m)/h),
      mu = Ft/P = (1/(P R)) int x p dx = (m - lam - b1 h/a0^2)/R.
  For V -> 0: h -> a0 + (L - lam)/2, m -> (L - lam)/2, and
  mu -> (L - lam)/R = (1 - E0/Einf) V tau_c/R. For V -> inf: Hertz with Einf*.

(2) Direct numerical solution (independent of (1))
  p = sqrt(1 - t^2) sum_{k<N} alpha_k U_k(t), with x = m + h t. Then H has a
  closed form: pi sum alpha_k T_{k+1}(y) for |y| <= 1, and
  pi sum alpha_k (y - sqrt(y^2 - 1))^(k+1) for y > 1, where y = (x - m)/h.
  The memory integral int_0^inf e^-v H(x + L v) dv is done by Gauss-Legendre
  quadrature (inside the contact in y; ahead of it in y = cosh(phi)). The
  slope equation is collocated at N+1 Chebyshev points. For a given h it is
  linear in (alpha, m). The load condition (pi/2) h alpha_0 = P fixes h (by a
  secant iteration). Finally mu = (m + h alpha_1/(2 alpha_0))/R.

Run `python3 tests/hunter.py` for the comparison table and limit checks.
"""
import math

_GL = {}


def _gauss_legendre(n):
    """Gauss-Legendre nodes and weights on [-1, 1], cached."""
    if n not in _GL:
        xs, ws = [], []
        for i in range(1, n + 1):
            x = math.cos(math.pi * (i - 0.25) / (n + 0.5))
            for _ in range(100):
                p0, p1 = 1.0, x
                for k in range(2, n + 1):
                    p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
                dp = n * (x * p1 - p0) / (x * x - 1)
                dx = p1 / dp
                x -= dx
                if abs(dx) < 1e-15:
                    break
            xs.append(x)
            ws.append(2 / ((1 - x * x) * dp * dp))
        _GL[n] = (xs, ws)
    return _GL[n]


def _bessel_i_scaled(n, z):
    """exp(-z) I_n(z) = (1/pi) int_0^pi exp(z (cos th - 1)) cos(n th) dth (trapezoid)."""
    M = max(64, int(math.ceil(2 * math.pi * math.sqrt(z))))
    d, s = math.pi / M, 0.5
    for k in range(1, M + 1):
        e = math.exp(z * (math.cos(k * d) - 1.0))
        s += (0.5 if k == M else 1.0) * e * math.cos(n * k * d)
        if e < 1e-18:
            break
    return s * d / math.pi


def _bessel_k_scaled(n, z):
    """exp(z) K_n(z) = int_0^inf exp(-z (cosh t - 1)) cosh(n t) dt (trapezoid)."""
    d, s, k = min(0.1, 0.5 / math.sqrt(z)), 0.5, 0
    while True:
        k += 1
        e = math.exp(-z * (math.cosh(k * d) - 1.0)) * math.cosh(n * k * d)
        s += e
        if e < 1e-18 * s:
            return s * d


def _root(f, a, b, tol):
    """Illinois (regula falsi) root of f in the bracket [a, b]."""
    fa, fb = f(a), f(b)
    if fa * fb > 0:
        raise ValueError('root not bracketed')
    side = 0
    for _ in range(200):
        c = (a * fb - b * fa) / (fb - fa)
        fc = f(c)
        if fc == 0 or abs(b - a) < tol:
            return c
        if fc * fb > 0:
            b, fb = c, fc
            if side == -1:
                fa /= 2
            side = -1
        else:
            a, fa = c, fc
            if side == 1:
                fb /= 2
            side = 1
    return c


# --------------------------------------------------------------------------
# (1) closed form
def _closed(P, R, E0s, Eis, L):
    a0 = math.sqrt(4 * P * R / (math.pi * E0s))
    lam = L * E0s / Eis

    def b0_b1(h):
        zA, zB = h / lam, h / L
        rI = _bessel_i_scaled(1, zA) / _bessel_i_scaled(0, zA)
        rK = _bessel_k_scaled(1, zB) / _bessel_k_scaled(0, zB)
        b0 = -(a0 * a0 + h * h) / 2
        return (b0, (h * h * (1 - rI / zA) + b0) / rI,
                -(h * h * (1 + rK / zB) + b0) / rK)

    h = _root(lambda h: b0_b1(h)[1] - b0_b1(h)[2],
              0.5 * a0 * math.sqrt(E0s / Eis), 1.1 * a0, 1e-14 * a0)
    b0, b1, _ = b0_b1(h)
    m = L + b1 / h
    xs, ws = _gauss_legendre(64)

    def pressure(x):
        t = (x - m) / h
        if abs(t) >= 1:
            return 0.0
        thx, thl = math.acos(t), math.acos(min(1.0, t + 40 * lam / h))
        s = 0.0
        for xi, wi in zip(xs, ws):
            c = math.cos(thl + (thx - thl) * (xi + 1) / 2)
            s += wi * math.exp(-(m + h * c - x) / lam) * (h * h * c * c + b1 * c + b0)
        return -E0s / (2 * R * lam) * s * (thx - thl) / 2

    return m, h, (m - lam - b1 * h / a0 ** 2) / R, pressure


# --------------------------------------------------------------------------
# (2) direct numerical solution
def _memory(t, eps, N, gl):
    """int_0^inf e^-v Phi_n(t + eps v) dv for n = 1..N (Phi_n = H of sqrt(1-t^2) U_{n-1} / pi)."""
    xs, ws = gl
    V = [0.0] * (N + 1)
    yb = min(1.0, t + 40 * eps)
    if yb > t:                                  # inside the contact: T_n(y)
        for xi, wi in zip(xs, ws):
            y = t + (yb - t) * (xi + 1) / 2
            w = wi * (yb - t) / 2 * math.exp(-(y - t) / eps) / eps
            T0, T1 = 1.0, y
            for n in range(1, N + 1):
                V[n] += w * T1
                T0, T1 = T1, 2 * y * T1 - T0
    if t + 40 * eps > 1:                        # ahead: y = cosh(f), (y - sqrt(y^2-1))^n = e^-nf
        fm = math.acosh(t + 40 * eps)
        for xi, wi in zip(xs, ws):
            f = fm * (xi + 1) / 2
            w = wi * fm / 2 * math.exp(-(math.cosh(f) - t) / eps) * math.sinh(f) / eps
            q = math.exp(-f)
            qn = q
            for n in range(1, N + 1):
                V[n] += w * qn
                qn *= q
    return V[1:]


def _solve_linear(A, b):
    n = len(b)
    M = [row[:] + [bi] for row, bi in zip(A, b)]
    for c in range(n):
        piv = max(range(c, n), key=lambda r: abs(M[r][c]))
        M[c], M[piv] = M[piv], M[c]
        for r in range(c + 1, n):
            f = M[r][c] / M[c][c]
            if f:
                Mr, Mc = M[r], M[c]
                for k in range(c, n + 1):
                    Mr[k] -= f * Mc[k]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        x[r] = (M[r][n] - sum(M[r][k] * x[k] for k in range(r + 1, n))) / M[r][r]
    return x


def _numeric(P, R, E0s, Eis, L, N=64, NG=64):
    a0 = math.sqrt(4 * P * R / (math.pi * E0s))
    gl = _gauss_legendre(NG)
    tj = [math.cos(math.pi * (j + 0.5) / (N + 1)) for j in range(N + 1)]

    def collocate(h):                           # unknowns alpha_0..alpha_{N-1}, m
        A, b = [], []
        for t in tj:
            V = _memory(t, L / h, N, gl)
            T0, T1, row = 1.0, t, []
            for k in range(N):
                row.append(2 * R * (T1 / Eis + (1 / E0s - 1 / Eis) * V[k]))
                T0, T1 = T1, 2 * t * T1 - T0
            A.append(row + [-1.0])
            b.append(h * t)
        s = _solve_linear(A, b)
        return s[:N], s[N]

    def F(lh):
        return math.log(math.pi / 2 * math.exp(lh) * collocate(math.exp(lh))[0][0] / P)

    x0, x1 = math.log(a0), math.log(a0 * math.sqrt(E0s / Eis))
    f0, f1 = F(x0), F(x1)
    for _ in range(40):                         # secant in log h
        x0, f0, x1 = x1, f1, x1 - f1 * (x1 - x0) / (f1 - f0)
        f1 = F(x1)
        if abs(f1) < 1e-13 or abs(x1 - x0) < 1e-14:
            break
    h = math.exp(x1)
    al, m = collocate(h)

    def pressure(x):
        t = (x - m) / h
        if abs(t) >= 1:
            return 0.0
        U0, U1, s = 1.0, 2 * t, 0.0
        for a in al:
            s += a * U0
            U0, U1 = U1, 2 * t * U1 - U0
        return math.sqrt(1 - t * t) * s

    return m, h, (m + h * al[1] / (2 * al[0])) / R, pressure


# --------------------------------------------------------------------------
def _peak(m, h, pressure, K=200):
    """max of p over the contact: grid in x = m + h cos(th), then golden section."""
    g = lambda th: pressure(m + h * math.cos(th))
    ths = [math.pi * (k + 0.5) / K for k in range(K)]
    k = max(range(K), key=lambda k: g(ths[k]))
    th = _golden_max(g, ths[k] - math.pi / K, ths[k] + math.pi / K)
    return g(th), m + h * math.cos(th)


def _golden_max(f, a, b, n=40):
    """argmax of a unimodal f on [a, b] by golden-section search."""
    r = (math.sqrt(5) - 1) / 2
    for _ in range(n):
        c, d = b - r * (b - a), a + r * (b - a)
        if f(c) > f(d):
            b = d
        else:
            a = c
    return (a + b) / 2


def hunter(P, R, E0_star, Einf_star, V_tau_c, method='closed'):
    """returns dict(mu=..., a_lead=..., a_trail=..., contact_length=a_lead+a_trail,
    p_max=..., x_pmax=...) ; lengths in the units of R; V_tau_c = V * tau_c (a length).
    x_pmax is measured from the apex, > 0 on the leading side.
    method='closed' (Hunter, fast) or 'numeric' (collocation, ~0.5 s)."""
    if Einf_star < E0_star:
        raise ValueError('standard linear solid needs Einf_star >= E0_star')
    if V_tau_c == 0 or math.isinf(V_tau_c) or Einf_star == E0_star:
        E = Einf_star if math.isinf(V_tau_c) else E0_star
        a = math.sqrt(4 * P * R / (math.pi * E))
        return dict(mu=0.0, a_lead=a, a_trail=a, contact_length=2 * a,
                    p_max=E * a / (2 * R), x_pmax=0.0)
    solver = {'closed': _closed, 'numeric': _numeric}[method]
    m, h, mu, pressure = solver(P, R, E0_star, Einf_star, V_tau_c)
    p_max, x_pmax = _peak(m, h, pressure)
    return dict(mu=mu, a_lead=m + h, a_trail=h - m, contact_length=2 * h,
                p_max=p_max, x_pmax=x_pmax)


if __name__ == '__main__':
    import time
    R, E0s, ratio, a0 = 1e4, 1.0, 0.1, 223.0   # ratio = E0/Einf; nu = 0.49 only enters via E*
    Eis = E0s / ratio
    P = math.pi * E0s * a0 ** 2 / (4 * R)
    ainf, pH = a0 * math.sqrt(ratio), E0s * a0 / (2 * R)
    print('Hunter problem: R = %g, E0* = %g, Einf* = %g, a0 = %g, P = %.6g'
          % (R, E0s, Eis, a0, P))
    print('a_lead/a_trail from the apex (lead = +x side, into which the indenter moves);'
          ' p_max in units of E0* a0/(2R)')
    print('%8s | %-10s %-8s %-8s %-7s %-7s | %-10s %-8s %-8s | %-8s %-8s'
          % ('VTc/a0', 'mu closed', 'lead/a0', 'trail/a0', 'pmax', 'xpmax/a0',
             'mu numer', 'lead/a0', 'trail/a0', 'dmu rel', 'd2a rel'))
    worst = 0.0
    t0 = time.time()
    for s in (0.01, 0.03, 0.1, 0.3, 1, 3, 10, 30, 100):
        c = hunter(P, R, E0s, Eis, s * a0)
        n = hunter(P, R, E0s, Eis, s * a0, method='numeric')
        dmu = abs(n['mu'] / c['mu'] - 1)
        dl = abs(n['contact_length'] / c['contact_length'] - 1)
        worst = max(worst, dmu, dl)
        print('%8g | %.4e %8.5f %8.5f %7.4f %7.4f | %.4e %8.5f %8.5f | %.1e  %.1e'
              % (s, c['mu'], c['a_lead'] / a0, c['a_trail'] / a0, c['p_max'] / pH,
                 c['x_pmax'] / a0, n['mu'], n['a_lead'] / a0, n['a_trail'] / a0, dmu, dl))
    print('largest relative difference closed/numeric (mu, contact length): %.2e -> %s'
          ' (table %.1f s)' % (worst, 'PASS' if worst < 5e-3 else 'FAIL', time.time() - t0))

    print('\nlow-speed limit: Hertz with E0* (a = a0, p_max = E0* a0/2R),'
          ' mu -> (1 - E0/Einf) V tau_c / R')
    for s in (1e-2, 1e-3, 1e-4, 1e-5):
        c = hunter(P, R, E0s, Eis, s * a0)
        print('  VTc/a0 = %g: contact/(2 a0) - 1 = %+.2e, p_max/pH - 1 = %+.2e,'
              ' mu/mu_lim - 1 = %+.2e' % (s, c['contact_length'] / (2 * a0) - 1,
                                          c['p_max'] / pH - 1,
                                          c['mu'] / ((1 - ratio) * s * a0 / R) - 1))
    print('high-speed limit: Hertz with Einf* (a = a0 sqrt(E0/Einf), p_max = Einf* a/2R), mu -> 0')
    for s in (1e2, 1e3, 1e4, 1e5):
        c = hunter(P, R, E0s, Eis, s * a0)
        print('  VTc/a0 = %g: contact/(2 a_inf) - 1 = %+.2e, p_max/(Einf* a_inf/2R) - 1 = %+.2e,'
              ' mu = %.3e' % (s, c['contact_length'] / (2 * ainf) - 1,
                              c['p_max'] / (Eis * ainf / (2 * R)) - 1, c['mu']))

    # maximum of mu(V): golden section in log(V tau_c/a0)
    f = lambda q: hunter(P, R, E0s, Eis, a0 * math.exp(q))['mu']
    q = _golden_max(f, math.log(0.1), math.log(30.0))
    print('\nmu(V) peak (E0/Einf = %g): V tau_c/a0 = %.4f, mu_max = %.5e (mu_max R/a0 = %.4f);'
          ' numeric there: mu = %.5e' % (ratio, math.exp(q), f(q), f(q) * R / a0,
                                         hunter(P, R, E0s, Eis, a0 * math.exp(q), 'numeric')['mu']))
