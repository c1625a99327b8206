# SPDX-License-Identifier: LGPL-2.1-or-later
"""The look of every viscoslide figure, in one place: matplotlib's settings
(serif STIX text, TrueType fonts in the PDF as journals ask, 200 dpi), the
symbols and names of the table's columns and solvers, the number format
of labels, and how a figure is saved (PNG and PDF, the PNG path printed).
viscoslide.plot and viscoslide.plot_field draw with it, so that a curve
and a field map of one run read alike."""
import math
import sys

BASE = {
    'font.family': 'serif',
    'font.serif': ['STIXGeneral', 'DejaVu Serif'],
    'mathtext.fontset': 'stix',
    'font.size': 10,
    'axes.labelsize': 11,
    'pdf.fonttype': 42,  # TrueType fonts in the PDF, as journals ask
}
# Curves against V_hat: ticks inside on all four sides, a framed legend.
CURVES = dict(BASE, **{
    'legend.fontsize': 8.5,
    'legend.framealpha': 0.9,
    'xtick.direction': 'in',
    'ytick.direction': 'in',
    'xtick.top': True,
    'ytick.right': True,
    'savefig.dpi': 200,
})
# Field maps: ticks outside, clear of the colours.
FIELDS = dict(BASE, **{'xtick.direction': 'out', 'ytick.direction': 'out'})

DPI = 200
SIZE = (6.4, 4.8)
V_LABEL = r'$\hat V = V\tau/\varepsilon$'
SYMBOL = {'t_hat': r'\hat t', 'F_n_hat': r'\hat F_n', 'delta_hat': r'\hat\delta',
          'mu_T': r'\mu_T', 'R_hat': r'\hat R', 'V_hat': r'\hat V', 'F_t_hat': r'\hat F_t',
          'L_hat': r'\hat L', 'mu': r'\mu', 'mu_energy': r'\mu_E'}
SOLVER = {'boundary-element': 'boundary elements', 'steady-state': 'finite elements',
          'transient': 'finite elements, transient'}


def pyplot(rc, who):
    """matplotlib.pyplot on the Agg backend with the settings rc; who (the
    script) names itself if matplotlib is missing."""
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit(f"{who} needs Debian's numpy and matplotlib for /usr/bin/python3: "
                 "apt-get install python3-matplotlib (scripts/setup installs it)")
    matplotlib.rcParams.update(rc)
    return plt


def fmt(v):
    """A number for mathtext: 3 significant digits, 10^n for powers of ten."""
    if v != v:
        return 'nan'
    if math.isinf(v):
        return r'\infty'
    if v == 0:
        return '0'
    e = math.floor(math.log10(abs(v)) + 1e-12)
    if abs(e) >= 3 and abs(abs(v) / 10.0 ** e - 1) < 1e-9:
        return ('-' if v < 0 else '') + '10^{%d}' % e
    s = '%.3g' % v
    if 'e' in s:
        m, x = s.split('e')
        return r'%s\times10^{%d}' % (m, int(x))
    return s


def save(fig, path):
    """path.png and path.pdf; prints path.png."""
    for ext in ('png', 'pdf'):
        fig.savefig(f'{path}.{ext}', dpi=DPI)
    import matplotlib.pyplot as plt
    plt.close(fig)
    print(f'{path}.png')
