"""Von Neumann stability of the fluid's time scheme (docs/fluid-stability.md): AB2 convection plus
Crank-Nicolson diffusion, second-order central differences, on a periodic grid of spacing h.
For a Fourier mode exp(i theta x/h) and a constant advecting velocity U the step
    u^{n+1} - u^n = (3/2) a u^n - (1/2) a u^{n-1} + (b/2) (u^{n+1} + u^n),
    a = -i C sin(theta)            (C = U dt / h, the CFL number)
    b = -2 D (1 - cos(theta))      (D = nu dt / h^2, the viscous number; D = C / Re_h)
has the amplification factors G, the roots of (1 - b/2) G^2 - (1 + 3a/2 + b/2) G + a/2 = 0.
The scheme is stable for (C, D) when max over theta of the larger |G| is at most 1.
An analytic curve drawn on the measured maps (reports/report_bench.py); no output is recomputed."""
import math

import numpy as np

THETAS = np.linspace(0.0, math.pi, 2001)


def amplification_roots(cfl, viscous_number, theta):
    """Both roots G of the AB2/CN characteristic polynomial at wave angle(s) theta (array)."""
    theta = np.asarray(theta, dtype=float)
    a = -1j * cfl * np.sin(theta)
    b = -2.0 * viscous_number * (1.0 - np.cos(theta))
    quad, lin, const = 1.0 - b / 2.0, -(1.0 + 1.5 * a + b / 2.0), 0.5 * a
    disc = np.sqrt(lin * lin - 4.0 * quad * const + 0j)
    return (-lin + disc) / (2.0 * quad), (-lin - disc) / (2.0 * quad)


def max_amplification(cfl, viscous_number, thetas=THETAS):
    """max over theta of the larger |G| (1D, or the 2D worst case: see max_amplification_2d)."""
    g1, g2 = amplification_roots(cfl, viscous_number, thetas)
    return float(np.max(np.maximum(np.abs(g1), np.abs(g2))))


def max_amplification_2d(cfl_x, cfl_y, viscous_number, n=181):
    """The same in 2D (dx = dy = h): a = -i (C_x sin theta_x + C_y sin theta_y),
    b = -4 D (sin^2(theta_x/2) + sin^2(theta_y/2)); the solver's CFL number is C_x + C_y."""
    tx, ty = np.meshgrid(np.linspace(-math.pi, math.pi, n), np.linspace(-math.pi, math.pi, n))
    a = -1j * (cfl_x * np.sin(tx) + cfl_y * np.sin(ty))
    b = -4.0 * viscous_number * (np.sin(tx / 2) ** 2 + np.sin(ty / 2) ** 2)
    quad, lin, const = 1.0 - b / 2.0, -(1.0 + 1.5 * a + b / 2.0), 0.5 * a
    disc = np.sqrt(lin * lin - 4.0 * quad * const + 0j)
    return float(np.max(np.maximum(np.abs((-lin + disc) / (2 * quad)), np.abs((-lin - disc) / (2 * quad)))))


def min_viscous_number(cfl, tolerance=1e-12):
    """Smallest D with max |G| <= 1 + tolerance at this CFL number (bisection; max |G| falls as D
    grows: CN damps every mode with theta > 0). 0 when C = 0."""
    if cfl <= 0.0:
        return 0.0
    low, high = 0.0, 1.0
    while max_amplification(cfl, high) > 1.0 + tolerance:
        high *= 2.0
    for _ in range(60):
        mid = 0.5 * (low + high)
        if max_amplification(cfl, mid) > 1.0 + tolerance:
            low = mid
        else:
            high = mid
    return high


def cell_reynolds_limit(cfl):
    """Largest cell Reynolds number Re_h = U h / nu = C / D that is stable at this CFL number."""
    d = min_viscous_number(cfl)
    return math.inf if d == 0.0 else cfl / d


def cfl_limit(cell_reynolds):
    """Largest CFL number that is stable at this cell Reynolds number (D = C / Re_h): bisection,
    the stable CFL numbers at a given Re_h forming one interval [0, limit] (checked on a grid of
    300 CFL numbers in [0.01, 3] for Re_h = 0.25 ... 512)."""
    low, high = 0.0, 8.0
    for _ in range(60):
        mid = 0.5 * (low + high)
        if max_amplification(mid, mid / cell_reynolds) > 1.0 + 1e-12:
            high = mid
        else:
            low = mid
    return low


def stability_boundary(cfls):
    """(cfl, Re_h limit, D limit) along the boundary, for drawing."""
    return [(c, cell_reynolds_limit(c), min_viscous_number(c)) for c in cfls]


if __name__ == "__main__":
    print("CFL     D_min(CFL)   Re_h_max = CFL / D_min   max|G|-1 at D = 0")
    for c in (0.05, 0.1, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.75, 0.8, 1.0, 1.25, 1.5, 2.0):
        d = min_viscous_number(c)
        print("%-6g  %-11.5g  %-23.5g  %.4g" % (c, d, c / d, max_amplification(c, 0.0) - 1))
    print("Re_h    CFL limit")
    for r in (0.25, 0.5, 1, 2, 4, 8, 16, 32, 64, 128, 256, 512):
        print("%-6g  %.4f" % (r, cfl_limit(r)))
