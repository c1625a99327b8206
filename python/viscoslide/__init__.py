# SPDX-License-Identifier: LGPL-2.1-or-later
"""viscoslide's Python side: reading, checking, drawing and converting the
results of build/viscoslide, in one importable package (Python 3.11).

Why a package: the scripts and the tests used to carry their own copies of
the table reader, the parameter-file edits and the paper's claims; here
each is written once and every script and test check imports it.

    tables        the reader of viscoslide's CSV tables (# comments, then
                  a header; cells to floats where they parse)
    prm           changing and reading entries of a deal.II .prm file by
                  'Subsection/Entry' path (python3 -m viscoslide.prm)
    claims        the paper's qualitative claims, judged on a study's
                  curves: scripts/claims prints them, tests/figure_sweep.check
                  asserts them
    vtu           a standard-library reader of deal.II's VTU/PVTU fields
    style         the matplotlib style and the labels shared by the plots
    plot          scripts/plot: mu, L_hat, forces, profiles against V_hat
    plot_field    scripts/plot_field: one field of a .pvtu near the contact
    units         scripts/units: SI to parameter entries, results to SI
    dma           scripts/dma: a DMA measurement to master curve, shift
                  laws and Prony series
    plot_temperatures  scripts/plot_temperatures: mu of a temperature
                  sweep in SI units against speed and temperature
    plot_history  scripts/plot_history: a sliding program's history
                  against time, and the F_t loop of its strokes
    compare       scripts/compare_curves: two steady_state.csv row by row
    bench         scripts/bench, bench_sliding, bench_curve,
                  bench_steady_curve: benchmark runs and their tables
    figures       scripts/figures: a figure's study run and drawn
    plot_map      scripts/plot_map: a sphere's contact footprint from the
                  .vti maps of the 3D boundary elements
    convergence   scripts/convergence: mesh-refinement studies against the
                  independent reference curves (tests/convergence.check
                  asserts them)
    test_table    scripts/test_table: doc/test_results.md from the tests'
                  own summaries

Every module that is a command runs as `python3 -m viscoslide.NAME ...`
with the command line of its script in scripts/, which is a wrapper of a
few lines. tables, prm, claims and vtu use the standard library only (the
tests import them with whatever Python CMake found); the drawing modules
import numpy and matplotlib (Debian's python3-matplotlib) when they draw.

How it is found: the scripts in scripts/ and the tests' viscoslide_test.py
put the python/ folder of their own checkout first on sys.path, so a
checkout always runs its own package, set up or not. scripts/setup also
writes viscoslide.pth into /usr/bin/python3's site-packages, pointing at
the checkout's python/ folder, so that `python3 -m viscoslide.plot` and
`import viscoslide` work from anywhere (for the last checkout set up)."""
