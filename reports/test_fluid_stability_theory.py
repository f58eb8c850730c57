#!/usr/bin/python3
"""ctest `fluid_stability_theory_matches_eigenvalues`: the von Neumann factors of
fluid_stability_theory.py (closed-form roots of the AB2/CN characteristic polynomial) are the
eigenvalues of the two-level step written as a 2 x 2 matrix on (u^n, u^{n-1}); the boundary
follows the small-CFL asymptote D_min = 4 C^4 / 27 (docs/fluid-stability.md); and in 2D the worst
direction for a given CFL number C_x + C_y is along a grid axis (the 1D limit).
exit 0 pass, 1 fail, 77 skipped (no numpy)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
try:
    import numpy as np
    import fluid_stability_theory as theory
except ImportError as e:
    print("skipped: %s" % e)
    sys.exit(77)

failures = []


def check(claim, ok):
    print("%s: %s" % ("pass" if ok else "FAIL", claim))
    if not ok:
        failures.append(claim)


# (1 - b/2) u^{n+1} = (1 + 3a/2 + b/2) u^n - (a/2) u^{n-1}: the step matrix on (u^n, u^{n-1}).
worst = 0.0
for cfl in (0.1, 0.5, 1.0, 2.0):
    for d in (0.0, 0.01, 0.3, 4.0):
        for theta in np.linspace(0.05, np.pi, 9):
            a, b = -1j * cfl * np.sin(theta), -2 * d * (1 - np.cos(theta))
            step = np.array([[(1 + 1.5 * a + b / 2) / (1 - b / 2), -(a / 2) / (1 - b / 2)], [1, 0]])
            eig = np.sort(np.abs(np.linalg.eigvals(step)))
            roots = np.sort(np.abs(np.array(theory.amplification_roots(cfl, d, theta))))
            worst = max(worst, float(np.max(np.abs(eig - roots))))
check("closed-form roots equal the step matrix's eigenvalues (max difference %.1e)" % worst, worst < 1e-12)

for cfl in (0.02, 0.05):
    d = theory.min_viscous_number(cfl)
    asymptote = 4 * cfl ** 4 / 27
    check("C = %g: D_min = %.5g, asymptote 4 C^4/27 = %.5g" % (cfl, d, asymptote), abs(d / asymptote - 1) < 0.01)

for cfl, d in ((0.5, 0.0), (1.0, 0.1), (1.0, 0.5), (1.5, 1.0)):
    one = theory.max_amplification(cfl, d)
    two = [theory.max_amplification_2d(f * cfl, (1 - f) * cfl, d) for f in (1.0, 0.8, 0.5)]
    check("C = %g, D = %g: 2D max |G| %s <= 1D %.6f" % (cfl, d, ", ".join("%.6f" % g for g in two), one),
          all(g <= one + 1e-9 for g in two))

sys.exit(1 if failures else 0)
