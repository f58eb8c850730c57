"""What each validation case claims, against what, and how every figure of results.csv is judged.

Case metadata comes from the case README (validation/<case>/README.md): its title, a
`**Validates.** ...` line and a `**Compared with.** MARK: text [key, ...]` line, MARK one of
`published`, `exact` or `own` (ibms against itself). A case in the report without that line stops
the report build: a comparison whose source is not stated must not look like a published one.

Targets: a quantity with published bounds (or a published reading uncertainty) is judged on them,
on the source's own terms: a results.csv line marked pass by a check whose own tolerance is looser
becomes `miss` when the figure lies outside the published bounds (the check's verdict stays in
its target text; a FAIL stays a failure). An `info` line is judged by the report when a target
applies to it (TARGET_RULES below): the published bounds or reading uncertainty of the case's
reference file, else the tolerance the case sets (solver/metrics/case_criteria.hpp, read at report
time, or the case README), marked as ibms's own. Measured outside -> `miss`. Lines with no target
stay `info`. Nothing here hard-codes a measured figure."""
import csv
import io
import math
import os
import re
from collections import OrderedDict

from report_latex import esc, md_text, num

MARKS = ("published", "exact", "own")
MARK_TEXT = {"published": "published", "exact": "exact", "own": "ibms's own"}


class ReportError(Exception):
    """A build error of the report (missing source mark, unknown citation): stops the build."""


# ---------------------------------------------------------------- bibliography
BIBLIOGRAPHY = OrderedDict([
    ("ghia1982", "U. Ghia, K. N. Ghia, C. T. Shin. High-Re solutions for incompressible flow using the "
                 "Navier--Stokes equations and a multigrid method. J. Comput. Phys. 48 (1982) 387--411."),
    ("botella1998", "O. Botella, R. Peyret. Benchmark spectral results on the lid-driven cavity flow. "
                    "Comput. Fluids 27 (1998) 421--433."),
    ("schafer1996", "M. Sch\\\"afer, S. Turek. Benchmark computations of laminar flow around a cylinder. "
                    "In: Flow Simulation with High-Performance Computers II, Notes on Numerical Fluid "
                    "Mechanics 52 (1996) 547--566."),
    ("john2001", "V. John, G. Matthies. Higher-order finite element discretizations in a benchmark problem "
                 "for incompressible flows. Int. J. Numer. Meth. Fluids 37 (2001) 885--903."),
    ("glowinski2001", "R. Glowinski, T.-W. Pan, T. I. Hesla, D. D. Joseph, J. P\\'eriaux. A fictitious domain "
                      "approach to the direct numerical simulation of incompressible viscous flow past "
                      "moving rigid bodies: application to particulate flow. J. Comput. Phys. 169 (2001) "
                      "363--426. (Fine-mesh maximum particle Reynolds numbers 17.27 and 17.31 as cited by "
                      "the project, not re-read from the paper.)"),
    ("wan2006", "D. Wan, S. Turek. Direct numerical simulation of particulate flow via multigrid FEM "
                "techniques and the fictitious boundary method. Int. J. Numer. Meth. Fluids 51 (2006) "
                "531--566. (Values read off the published curves.)"),
    ("rezaee2nnf", "T. Rezaee, public repository \\texttt{taha-re/2D\\_NNF\\_LBM}, figures "
                   "\\texttt{media/*\\_dkt.jpeg} (``Symbols: Wan \\& Turek''), digitised for ibms from "
                   "pixel centroids: \\texttt{validation/dkt\\_two\\_disks/reference/provenance.md}."),
    ("jsst2022", "(Guinea et al., as the companion paper cites it; the copy ibms holds names no authors.) "
                 "Computational method for interactions between deformable objects and fluid flows using "
                 "immersed boundary method and mass spring model. Trans. JSST 14(2) (2022)."),
    ("jsce2023", "N. Guinea, D. Toriu, S. Ushijima. Numerical experiments of swelling objects interacting "
                 "with Newtonian fluids. J. JSCE 11(2) (2023)."),
    ("celik2008", "I. B. Celik, U. Ghia, P. J. Roache, C. J. Freitas, H. Coleman, P. E. Raad. Procedure for "
                  "estimation and reporting of uncertainty due to discretization in CFD applications. "
                  "J. Fluids Eng. 130 (2008) 078001."),
    ("uhlmann2005", "M. Uhlmann. An immersed boundary method with direct forcing for the simulation of "
                    "particulate flows. J. Comput. Phys. 209 (2005) 448--476."),
    ("roache1994", "P. J. Roache. Perspective: a method for uniform reporting of grid refinement studies. "
                   "J. Fluids Eng. 116 (1994) 405--413."),
    ("taira2007", "K. Taira, T. Colonius. The immersed boundary method: a projection approach. "
                  "J. Comput. Phys. 225 (2007) 2118--2137."),
    ("roma1999", "A. M. Roma, C. S. Peskin, M. J. Berger. An adaptive version of the immersed boundary "
                 "method. J. Comput. Phys. 153 (1999) 509--534."),
    ("peskin2002", "C. S. Peskin. The immersed boundary method. Acta Numerica 11 (2002) 479--517."),
    ("bao2016", "Y. Bao, J. Kaye, C. S. Peskin. A Gaussian-like immersed-boundary kernel with three "
                "continuous derivatives and improved translational invariance. "
                "J. Comput. Phys. 316 (2016) 139--144 (arXiv:1505.07529, updated with A. D. Kaiser)."),
    ("popinet_basilisk", "S. Popinet and collaborators. Basilisk, a free-software program for the solution of "
                         "partial differential equations on adaptive Cartesian meshes, "
                         "\\texttt{http://basilisk.fr} (the build recorded in "
                         "\\texttt{bench/reference/basilisk\\_cavity.csv})."),
    ("kempe2012", "T. Kempe, J. Fr\\\"ohlich. An improved immersed boundary method with direct forcing for the "
                  "simulation of particle laden flows. J. Comput. Phys. 231 (2012) 3663--3684."),
    ("stokes1851", "G. G. Stokes. On the effect of the internal friction of fluids on the motion of "
                   "pendulums. Trans. Cambridge Philos. Soc. 9 (1851) 8--106 (the oscillating cylinder of the "
                   "verification tests)."),
    ("openlb", "M. J. Krause et al. OpenLB -- open source lattice Boltzmann code. Comput. Math. Appl. 81 "
               "(2021) 258--288; its example \\texttt{dkt2d}, whose start the DKT case follows."),
    ("breugem2012", "W.-P. Breugem. A second-order accurate immersed boundary method for fully resolved "
                    "simulations of particle-laden flows. J. Comput. Phys. 231 (2012) 4469--4498."),
])

_cited = []


def cite(*keys):
    """\\cite of known keys (an unknown key is a build error); remembers them for the bibliography."""
    for k in keys:
        if k not in BIBLIOGRAPHY:
            raise ReportError("unknown citation key '%s' (add it to BIBLIOGRAPHY in reports/report_cases.py)" % k)
        if k not in _cited:
            _cited.append(k)
    return r"\cite{%s}" % ",".join(keys)


def bibliography_section(out):
    out.append(r"\begin{thebibliography}{99}")
    for k in BIBLIOGRAPHY:  # every entry: the Known limitations and plots may cite any of them
        out.append(r"\bibitem{%s} %s" % (k, BIBLIOGRAPHY[k]))
    out.append(r"\end{thebibliography}")


# ---------------------------------------------------------------- case metadata (README)
def case_folder(name, folders):
    """The case folder of a results.csv case name: itself, or the longest folder name it starts
    with followed by '_' (dfg_cylinder_2d1_slow -> dfg_cylinder_2d1)."""
    if name in folders:
        return name
    best = None
    for f in folders:
        if name.startswith(f + "_") and (best is None or len(f) > len(best)):
            best = f
    return best or name


def read_case_meta(source, case):
    """Title, what it validates, source mark, comparison text (LaTeX) and citation keys from
    validation/<case>/README.md. Raises ReportError without a valid `**Compared with.**` line."""
    path = os.path.join(source, "validation", case, "README.md")
    readme = "validation/%s/README.md" % case
    if not os.path.isfile(path):
        raise ReportError("validation case '%s' has no source mark: %s does not exist (it needs a line "
                          "'**Compared with.** published|exact|own: ... [citation keys]')" % (case, readme))
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    title = next((line[2:].strip() for line in text.splitlines() if line.startswith("# ")), case)
    m = re.search(r"^\*\*Compared with\.\*\*\s*(.+)$", text, re.M)
    if not m:
        raise ReportError("validation case '%s' has no source mark: %s needs a line "
                          "'**Compared with.** published|exact|own: ... [citation keys]'" % (case, readme))
    compared = m.group(1).strip()
    mark = re.split(r"[,:]", compared, 1)[0].strip().lower()
    if mark not in MARKS:
        raise ReportError("validation case '%s': the source mark '%s' in %s is not one of %s" %
                          (case, mark, readme, ", ".join(MARKS)))
    body = md_text((compared.split(":", 1)[1] if ":" in compared else "").strip().rstrip("."))
    # [key, key] -> \cite{key,key} where it stands (esc leaves brackets and these keys alone)
    body = re.sub(r"\s*\[([a-z0-9, ]+)\]", lambda g: "~" + cite(*[k.strip() for k in g.group(1).split(",")]), body)
    v = re.search(r"^\*\*Validates\.\*\*\s*(.+)$", text, re.M)
    qualifier = compared.split(":", 1)[0].strip()
    return dict(case=case, title=title, validates=md_text(v.group(1).strip().rstrip(".")) if v else "--",
                mark=mark, qualifier=qualifier, detail=qualifier[len(mark):].strip(" ,"), compared=body)


# ---------------------------------------------------------------- criteria and reference files
def read_criteria(source):
    """Named constants of solver/metrics/case_criteria.hpp (`inline constexpr double name = v;`,
    several per line allowed) and the cavity tolerances, read as text (the one definition)."""
    path = os.path.join(source, "solver", "metrics", "case_criteria.hpp")
    crit = {}
    if not os.path.isfile(path):
        return crit
    with open(path, encoding="utf-8") as f:
        text = re.sub(r"//[^\n]*", "", f.read())
    for decl in re.findall(r"inline constexpr double ([^;]+);", text):
        for part in decl.split(","):
            m = re.match(r"\s*(\w+)\s*=\s*([-+0-9.eE]+)\s*$", part)
            if m:
                crit[m.group(1)] = float(m.group(2))
    for name, tol in re.findall(r'\{"(\w+)",\s*([-+0-9.eE]+),', text):
        crit["cavity:" + name] = float(tol)
    return crit


def read_reference(source, case, filename):
    """quantity -> dict of the other columns (numbers where they parse) of a reference CSV."""
    path = os.path.join(source, "validation", case, "reference", filename)
    if not os.path.isfile(path):
        return {}
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = [line for line in f if line.strip() and not line.startswith("#")]
    out = {}
    for r in csv.DictReader(lines):
        q = r.pop("quantity", None)
        if q is None:
            continue
        row = {}
        for k, v in r.items():
            try:
                row[k] = float(v)
            except (TypeError, ValueError):
                row[k] = v
        out[q] = row
    return out


def read_long_reference(source, case, filename):
    """quantity -> (times, values) of a long-format digitised curve file (quantity,time,value,units)
    and its '#' provenance lines."""
    path = os.path.join(source, "validation", case, "reference", filename)
    if not os.path.isfile(path):
        return {}, []
    curves, comments = OrderedDict(), []
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = []
        for line in f:
            if line.startswith("#"):
                comments.append(line[1:].strip())
            elif line.strip():
                lines.append(line)
    for r in csv.DictReader(io.StringIO("".join(lines))):
        t, v = curves.setdefault(r["quantity"], ([], []))
        t.append(float(r["time"]))
        v.append(float(r["value"]))
    return curves, comments


# ---------------------------------------------------------------- targets
class Target:
    """A target of one figure: |x| <= tol ('abs') or lo <= x <= hi ('band'), with where it comes
    from; `percent` formats relative figures."""

    def __init__(self, kind, tol=None, lo=None, hi=None, source="", percent=False, unit="", explicit=True,
                 published=False, reference=None):
        # published: the source's own bounds or uncertainty (judged even over a passing check);
        # reference: the reference value the band is about (the summary's scatter plot), if any
        self.kind, self.tol, self.lo, self.hi, self.explicit = kind, tol, lo, hi, explicit
        self.published, self.reference = published, reference
        self.source, self.percent, self.unit = source, percent, unit

    def met(self, x):
        if not math.isfinite(x):
            return False
        if self.kind == "abs":
            return abs(x) <= self.tol
        return self.lo <= x <= self.hi

    def severity(self, x):
        """|x|/tol, or the distance from the band's middle over its half width (> 1: outside)."""
        if not math.isfinite(x):
            return math.inf
        if self.kind == "abs":
            return abs(x) / self.tol if self.tol > 0 else (0.0 if x == 0 else math.inf)
        half = 0.5 * (self.hi - self.lo)
        return abs(x - 0.5 * (self.hi + self.lo)) / half if half > 0 else math.inf

    def text(self):
        f = (lambda v: fmt_value(v, self.percent, signed=True))
        if self.kind == "abs":
            return r"$|\cdot| \le$ %s%s" % (fmt_value(self.tol, self.percent), self.unit)
        return "[%s, %s]%s" % (f(self.lo), f(self.hi), self.unit)


def fmt_value(x, percent=False, signed=False):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "nan"
    if percent:
        s = ("%+.3g" if signed else "%.3g") % (100 * x)
        return s.replace("-", "$-$") + r"\,\%"
    return num(x, 4).replace("-", "$-$") if not num(x, 4).startswith("$") else num(x, 4)


def _dfg_relative(ctx, m, finest_only=True):
    """Every DFG quantity on the published bounds of Schaefer & Turek (1996), at the finest grid that
    ran (the checks' own 1-2 % gates of case_criteria.hpp are regression gates, not the judgement)."""
    case, quantity, grid = ctx["folder"], m.group(1), m.groupdict().get("grid")
    if finest_only and grid is not None and int(grid) != ctx["finest"].get(ctx["row_case"], -1):
        return None, "target applies at the finest grid"
    ref = ctx["refs"].get(case, {}).get(quantity)
    if ref and isinstance(ref.get("lower"), float):
        v = ref["value"]
        return Target("band", lo=ref["lower"] / v - 1, hi=ref["upper"] / v - 1, percent=True, explicit=False,
                      published=True, reference=v, source="inside the published bounds %s" % cite("schafer1996")), None
    return None, None


def _order_band(ctx, m):
    return Target("band", lo=0.5, hi=2.0, explicit=False,
                  source="formal order 1 of direct forcing; the settling-disk gate's band"), None


def _dkt_quantity(ref_key, tol_kind):
    def rule(ctx, m):
        ref = ctx["refs"].get("dkt_two_disks", {}).get(ref_key)
        if not ref:
            return None, None
        v = ref["value"]
        if tol_kind == "speed":
            tol = ctx["crit"].get("dkt_speed_tolerance")
            return Target("band", lo=v * (1 - tol), hi=v * (1 + tol), unit=" cm/s", reference=v,
                          source="%.3g\\,\\%% of %s cm/s, the trailing disk's tolerance (case\\_criteria.hpp) %s"
                                 % (100 * tol, num(v), cite("wan2006"))), None
        if isinstance(tol_kind, float):  # a README target in seconds
            return Target("band", lo=v - tol_kind, hi=v + tol_kind, unit=" s", reference=v,
                          source="%s s of %s s: the README's first-design target %s"
                                 % (num(tol_kind), num(v), cite("wan2006"))), None
        u = ref.get("reading_uncertainty", 0.0)
        return Target("band", lo=v - u, hi=v + u, unit=" s", explicit=False, published=True, reference=v,
                      source="%s $\\pm$ %s s: reading uncertainty %s"
                             % (num(v), num(u), cite("wan2006"))), None
    return rule


def _settling_speed(ctx, m):
    grid = float(m.group("grid"))
    if abs(grid - ctx["finest"].get(ctx["row_case"], -1)) > 1e-6:
        return None, "target applies at the finest grid"
    # The published figure with its stated uncertainty (Wan & Turek's curve, read to +-0.05 cm/s),
    # not the case check's own 3 % (case_criteria.hpp), which the ctest gate keeps.
    ref = ctx["refs"].get("settling_disk", {}).get("max_settling_speed")
    if not ref:
        return None, None
    v, u = ref["value"], ref.get("reading_uncertainty", 0.0)
    fine = ctx["refs"].get("settling_disk", {}).get("max_settling_speed_glowinski", {}).get("value")
    return Target("band", lo=v - u, hi=v + u, unit=" cm/s", explicit=False, published=True, reference=v,
                  source="%s $\\pm$ %s cm/s: the reading uncertainty of %s's curve%s; the ctest check's own "
                         "limit is 3\\,\\%% (case\\_criteria.hpp)"
                         % (num(v), num(u), cite("wan2006"),
                            (" (Glowinski et al.'s fine meshes: %s cm/s %s)" % (num(fine), cite("glowinski2001")))
                            if fine else "")), None


# (case folder, regex on the metric, rule(ctx, match) -> (Target or None, note)). Only `info`
# lines are judged here; a rule returning no target leaves the line `info` with its note.
TARGET_RULES = [
    ("dfg_cylinder_2d1", r"^(\w+) at D/h = (?P<grid>\d+) relative (?:deviation from|to) the reference$", _dfg_relative),
    ("dfg_cylinder_2d2", r"^(\w+) at D/h = (?P<grid>\d+) relative (?:deviation from|to) the reference$", _dfg_relative),
    ("dfg_cylinder_2d1", r"^(\w+) Richardson value relative (?:deviation from|to) the reference$",
     lambda c, m: _dfg_relative(c, m, finest_only=False)),
    ("dfg_cylinder_2d2", r"^(\w+) Richardson value relative (?:deviation from|to) the reference$",
     lambda c, m: _dfg_relative(c, m, finest_only=False)),
    ("dfg_cylinder_2d1", r"^(\w+): observed order \(finest three grids\)$", _order_band),
    ("dfg_cylinder_2d2", r"^(\w+): observed order \(finest three grids\)$", _order_band),
    ("settling_disk", r"^observed order of the max settling speed", _order_band),
    ("settling_disk", r"^max settling speed \[cm/s\], D/h = (?P<grid>[0-9.]+)$", _settling_speed),
    ("dkt_two_disks", r"^leading max speed", _dkt_quantity("max_settling_speed_leading", "speed")),
    ("dkt_two_disks", r"^time of minimum centre distance", _dkt_quantity("time_of_kissing", 0.2)),
    ("dkt_two_disks", r"^time the pair is horizontal", _dkt_quantity("time_pair_horizontal", 0.15)),
    ("dkt_two_disks", r"^start of kissing", _dkt_quantity("start_of_kissing_distance_below_1.25d", "reading")),
    ("dkt_two_disks", r"^time of max speed, leading", _dkt_quantity("time_of_max_speed_leading", "reading")),
]

# Why a figure misses its target (Known limitations), from the case READMEs: (case folder, regex
# on the metric, cause). A miss without an entry points to the case README.
CAUSES = [
    ("dfg_cylinder_2d2", r"drag_coefficient_max",
     "The shipped scene retracts the markers by $0.3h$, the face constraint's effective radius, as every scene "
     "under that coupling does: max $c_D$ rises towards the bounds from below as the grid is refined ($-2.88$, "
     "$-2.11$, $-0.88$, $-0.66$, $-0.60$, $-0.39$\\,\\% at $D/h = 20, 30, 40, 50, 60, 80$; Richardson value over "
     "50, 60, 80 3.2243, inside the bounds), the boundary layer, 2 to 4 cells thick on the coarse grids, being smeared by the kernel. Under the papers' coupling the slip left at the end of the step and, on the "
     "collocated grid, the momentum interpolation's flux through the body, proportional to $\\Delta t$, raise "
     "max $c_D$ by 11--12\\,\\% on every grid (README)."),
    ("dfg_cylinder_2d1", r"^drag_coefficient at",
     "The diffuse interface's body acts about $0.285h$ larger than its rim; the shipped scene retracts the markers "
     "by $0.3h$ under the no-slip coupling, as every scene under it does ($+0.18$, $+0.03$, $+0.09$\\,\\% at "
     "$D/h = 20, 30, 40$, inside the bounds); the papers' coupling converges at first order and reaches 1\\,\\% "
     "only from $D/h = 60$ (README)."),
    ("dfg_cylinder_2d2", r"lift_coefficient",
     "With the markers retracted by the effective radius ($0.3h$) max $c_L$ rises from below at about the "
     "diffuse interface's first order as the grid is refined ($-10.2$, $-7.3$, $-3.8$, $-3.2$, $-2.95$, "
     "$-2.33$\\,\\% at $D/h = 20, 30, 40, 50, 60, 80$), towards 0.98--0.99 (a fit $a + bh$ over $D/h = 40$--80: "
     "0.990; Richardson over 50, 60, 80: 0.986): the coarse grids' deficit is the regularised interface's "
     "first-order error where the boundary layer, 2 to 4 cells thick, meets the kernel's 3-cell support; the "
     "retraction removes the effective radius' share (the body's size), not the smearing of the shear layer. "
     "Not the step: the retracted scene's lift at $D/h = 20$ moves by $-0.4$\\,\\% from CFL 0.5 to 0.125 "
     "(README, docs/method.md \\S3.7)."),
    ("dfg_cylinder_2d1", r"lift_coefficient",
     "$c_L$ at Re 20 is a small asymmetry of the flow (about 1\\,\\% of $c_D$) that the smeared interface does "
     "not resolve at these grids (README)."),
    ("dfg_cylinder_2d", r"pressure_difference",
     "$\\Delta p$ is extrapolated through the smeared pressure jump of the diffuse boundary (README)."),
    ("dfg_cylinder_2d", r"observed order",
     "The three grids are not in the asymptotic range for this quantity (a small or sign-changing difference "
     "between grids); its Richardson value and GCI mean little."),
    # One cause per DKT quantity, each from validation/dkt_two_disks/README.md: the drafting phase
    # (start of kissing) and the tumbling (leading disk, minimum distance, pair horizontal) differ.
    ("dkt_two_disks", r"^start of kissing",
     "A drafting-phase time, which the offset of the upper disk leaves unchanged (README: trailing peak at "
     "1.116--1.126\\,s for offsets 0.001--0.03\\,cm); the reference's $\\approx 1.2$\\,s is read from symbols "
     "$\\approx 0.3$\\,s apart, too coarse to gate (README: 1.05\\,s under the papers' coupling, 1.09\\,s under "
     "the scene's). So an early start of kissing and a late tumbling are not one timing shift."),
    ("dkt_two_disks", r"^leading max speed",
     "The leading disk's maximum comes after the pair has tumbled (README: 1.6830\\,cm/s at 1.74\\,s under "
     "the scene's coupling, 1.7117 at 1.81\\,s with the virtual mass; Wan \\& Turek 1.57 at 1.36\\,s), and "
     "follows the symmetry-breaking offset: 1.638 / 1.607 / 1.549\\,cm/s at offsets 0.001 / 0.01 / 0.03\\,cm "
     "(README, $D/h = 16$); not gated."),
    ("dkt_two_disks", r"^time of max speed, leading",
     "The same post-tumbling peak as the leading max speed (README: at 1.74\\,s under the scene's coupling, "
     "1.81\\,s with the virtual mass, against Wan \\& Turek's 1.36\\,s before the tumble); the README gives "
     "no offset study of its time."),
    ("dkt_two_disks", r"^time of minimum centre distance",
     "The minimum distance is nearly flat in time: the README's runs reach the same 0.2105\\,cm at 1.734\\,s "
     "(scene's coupling) and at 1.284\\,s (virtual mass), 0.2104\\,cm at 1.21\\,s (papers' coupling), with "
     "their drafting peaks within 3\\,\\%. The README counts it among the quantities set by when the pair tumbles "
     "but measures no offset dependence of it; not gated."),
    ("dkt_two_disks", r"horizontal",
     "Set by when the pair tumbles, which the symmetry-breaking offset of the upper disk controls (README, "
     "$D/h = 16$: horizontal at 2.61 / 2.29 / 1.98\\,s for offsets 0.001 / 0.01 / 0.03\\,cm, about 0.3\\,s per "
     "factor 3 of the offset); Wan \\& Turek state no perturbation; not gated."),
    ("settling_disk", r"^max settling speed",
     "The README's own runs measure 5.5769\\,cm/s at $D/h = 25$: $+1.4$\\,\\% against Wan \\& "
     "Turek's 5.5 $\\pm$ 0.05\\,cm/s read off their curve, inside the range 5.49--5.58\\,cm/s of Wan \\& Turek "
     "and Glowinski et al., 0.85\\,\\% above Glowinski et al.'s cited 5.53. Finer grids do not lower it (5.5778, "
     "5.5783\\,cm/s at $D/h = 37.5, 50$), and three set-ups (the papers' coupling with the $\\nu\\Delta t/h^2$ "
     "cap, the face constraint without and with $0.25h$ retraction) extrapolate to 5.588--5.593\\,cm/s from "
     "both sides, so the README finds the difference is not the coupling but points at the references: "
     "Glowinski et al.'s own fine-mesh values as cited extrapolate to 5.578\\,cm/s, and Wan \\& Turek's value "
     "is read off a curve (README)."),
    ("settling_disk", r"Richardson|observed order",
     "Recorded, not gated: under the end-of-step coupling with the markers retracted by $0.3h$ the diffuse "
     "interface's first-order term is cancelled, and three grids give an order above the scheme's (the wheel's "
     "and the rigid disk's differ, see the results above), so the Richardson value and the GCI computed with it "
     "understate the uncertainty; the papers' coupling with the $\\nu\\Delta t/h^2$ cap and the face constraint "
     "with and without $0.25h$ retraction extrapolate to 5.588--5.593\\,cm/s from both sides, so it is not the "
     "coupling; Glowinski et al.'s own cited fine-mesh values extrapolate to 5.578\\,cm/s (README)."),
]

# The principal published quantity of a case (a regex on the metric): its page-1 headline where
# it is judged on the published bounds, whatever the secondary rows (lift, Strouhal number, pressure
# difference) show; those stay in the list of misses below the summary. DFG 2D-1: c_D; DFG 2D-2:
# max c_D (Schaefer & Turek's first quantity of each benchmark).
PRINCIPAL = {"dfg_cylinder_2d1": r"^drag_coefficient (?:at D/h|Richardson)",
             "dfg_cylinder_2d2": r"^drag_coefficient_max (?:at D/h|Richardson)"}

# Lines compared with ibms itself inside a case compared with the literature: grid convergence
# (GCI, observed order, a Richardson value of ibms's own grids with no reference in the line, the
# change over the grid before), one ibms run against another where no paper states the outcome
# (wheel / rigid, the swelling disk against the D = 0.30 run) and one ibms force against another
# (control-volume against immersed-boundary c_D). A Richardson value judged against a reference
# ("... relative deviation from the reference") stays with the case's mark, and so do the swelling
# cavity's swelling-against-non-swelling lines: they test the paper's qualitative claim (Figs. 2-4
# of Guinea et al. 2023: swelling particles travel less), and its per-run lines (t_end reached,
# rim distances) judge one run each.
OWN_METRICS = (r"GCI|wheel / rigid|observed order|approach to the D = 0.30 run|before onset"
               r"|control-volume|immersed-boundary c_D|over the one before|^Richardson value \[")


# Lines of a case's variant runs beside its shipped scenes: the papers' coupling kept one key away
# and the collision-time contact law. At equal standing a page-1 headline speaks for the case as
# shipped, not for a variant.
VARIANT_RUNS = r"^(?:papers' coupling|collision_time): "


def finest_grids(results):
    """Finest 'D/h = N' per results case (None where the metrics name no grid)."""
    finest = {}
    for case, rows in results.items():
        grids = [float(g) for r in rows for g in re.findall(r"D/h = ([0-9.]+)", r["metric"])]
        if grids:
            finest[case] = max(grids)
    return finest


def judge(results, source, folders):
    """Every results line with its verdict (pass / fail / miss / info), target and source mark,
    grouped by case folder. Returns (OrderedDict folder -> case dict with rows, verdict, headline)."""
    crit = read_criteria(source)
    refs = {"dfg_cylinder_2d1": read_reference(source, "dfg_cylinder_2d1", "dfg_2d1.csv"),
            "dfg_cylinder_2d2": read_reference(source, "dfg_cylinder_2d2", "dfg_2d2.csv"),
            "dkt_two_disks": read_reference(source, "dkt_two_disks", "wan_turek_dkt_digitized.csv"),
            "settling_disk": read_reference(source, "settling_disk", "settling_disk_rho1.25.csv")}
    finest = finest_grids(results)
    cases = OrderedDict()
    for row_case, rows in results.items():
        folder = case_folder(row_case, folders)
        c = cases.setdefault(folder, dict(folder=folder, rows=[], result_names=[]))
        c["result_names"].append(row_case)
        for r in rows:
            c["rows"].append(_judge_row(r, row_case, folder, crit, refs, finest))
    for c in cases.values():
        _case_verdict(c)
    return cases


def _float(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def _judge_row(r, row_case, folder, crit, refs, finest):
    status = r["status"].strip()
    measured = _float(r["measured"])
    out = dict(r, row_case=row_case, target=None, note="", severity=0.0, target_source="",
               own=bool(re.search(OWN_METRICS, r["metric"])),
               percent=bool(re.search(r"relative|- 1\||/ \|v_|/ max\||GCI", r["metric"])))
    tol = _float(r["tolerance"])
    if status == "pass" or status.lower().startswith("fail"):
        out["verdict"] = "pass" if status == "pass" else "fail"
        out["gate"] = "check"
        if math.isfinite(tol):
            out["target_text"] = "check: %s" % fmt_value(tol, out["percent"])
            # Whether the check's bound is an upper or a lower one is not in the line: a passing
            # figure below its tolerance is read as an upper bound, above it as a lower one; both
            # give a closeness to the bound in [0, 1].
            # A figure equal to its bound (a run reached its end time) says nothing about a margin.
            m, t = abs(measured), abs(tol)
            out["severity"] = (0.0 if not math.isfinite(m) or t == 0 or abs(m - t) <= 1e-6 * t else m / t if m < t else t / m) \
                if out["verdict"] == "pass" else math.inf
        else:
            out["target_text"] = "check"
            out["severity"] = 0.0 if out["verdict"] == "pass" else math.inf
        if out["verdict"] == "fail":
            out["severity"] = max(out["severity"], 1e9)
            return out
        # A passing check on a quantity with published bounds: judged on the bounds; on a grid
        # coarser than the finest that ran, not judged (the published target applies at the
        # finest), the check's own pass kept as a note, not counted as a pass.
        target, note = _rule_target(dict(folder=folder, row_case=row_case, crit=crit, refs=refs, finest=finest), r)
        if target is not None and target.published:
            _judge_on(out, target, measured, "%s; ibms's %s" % (target.text(), out["target_text"]))
        elif note and out["verdict"] == "pass":
            out["verdict"] = "info"
            out["severity"] = 0.0
            out["note"] = note
            out["target_text"] = "%s (ibms's %s passes)" % (esc(note), out["target_text"])
        return out
    out["gate"] = "report"
    ctx = dict(folder=folder, row_case=row_case, crit=crit, refs=refs, finest=finest)
    target, note = _rule_target(ctx, r)
    if target is not None:
        return _judge_on(out, target, measured, target.text())
    out["note"] = note or ""
    out["verdict"] = "info"
    out["target_text"] = "--" if not out["note"] else esc(out["note"])
    return out


def _judge_on(out, target, measured, text):
    out.update(target=target, percent=target.percent, target_text=text, target_source=target.source,
               verdict="pass" if target.met(measured) else "miss", severity=target.severity(measured))
    return out


def _rule_target(ctx, r):
    """(Target, None) of the first rule of TARGET_RULES whose case and pattern match the line, or
    (None, that rule's note), or (None, None)."""
    for case, pattern, rule in TARGET_RULES:
        if case != ctx["folder"]:
            continue
        m = re.search(pattern, r["metric"])
        if not m:
            continue
        return rule(ctx, m)
    return None, None


def _case_verdict(c):
    rows = c["rows"]
    verdicts = [r["verdict"] for r in rows]
    c["counts"] = {v: verdicts.count(v) for v in ("pass", "miss", "fail", "info")}
    c["verdict"] = ("fail" if "fail" in verdicts else "miss" if "miss" in verdicts else
                    "pass" if "pass" in verdicts else "info" if verdicts else "not run")
    judged = [r for r in rows if r["verdict"] != "info"]
    # The headline: a failed check first (the case's FAIL); then the case's principal published
    # quantity (PRINCIPAL) where it is judged on its published bounds; then the worst figure, a
    # figure judged on published bounds before one judged on a target the case sets (check
    # tolerance, case_criteria.hpp, README) at equal verdict, then one of the case's class before
    # one of ibms against itself, then one of the shipped scenes before one of a variant run, the
    # farthest from its target first.
    rank = {"fail": 3, "miss": 2, "pass": 1}
    principal = PRINCIPAL.get(c["folder"])

    # At equal verdict a figure of the case's own class (its README mark) goes before one of ibms
    # against itself (OWN_METRICS: GCI, wheel / rigid, ...): a published case's headline is not an
    # own figure while it has a published one of the same verdict; then a figure of the shipped
    # scenes before one of a variant run (VARIANT_RUNS).
    def key(r):
        published = r["target"] is not None and r["target"].published
        is_principal = bool(principal and published and re.search(principal, r["metric"]))
        shipped = not re.search(VARIANT_RUNS, r["metric"])
        return (r["verdict"] == "fail", is_principal, rank[r["verdict"]], published, not r["own"], shipped,
                r["severity"])
    c["headline"] = max(judged, key=key) if judged else None


def cause_of(folder, metric):
    for case, pattern, cause in CAUSES:
        if folder.startswith(case) and re.search(pattern, metric):
            return cause
    return "See \\texttt{validation/%s/README.md}." % esc(folder)


def verdict_cell(v):
    return {"pass": r"\textcolor{passgreen}{pass}", "miss": r"\textcolor{missorange}{\textbf{miss}}",
            "fail": r"\textcolor{red}{\textbf{FAIL}}", "info": r"\textcolor{gray}{info}",
            "not run": r"\textcolor{gray}{not run}"}[v]


def mark_cell(mark):
    return {"published": r"\textsf{P}", "exact": r"\textsf{E}", "own": r"\textsf{O}"}[mark]


def measured_text(row):
    x = _float(row["measured"])
    return fmt_value(x, row["percent"], signed=row["percent"])


def predicted_against_reference(judged):
    """Every judged figure whose target carries its reference value: (case, metric, reference,
    predicted, band low, band high, verdict), the band and the prediction in the reference's units
    (a relative deviation x of a reference v predicts v (1 + x))."""
    points = []
    for folder, c in judged.items():
        for r in c["rows"]:
            t = r.get("target")
            if t is None or t.reference is None or t.kind != "band":
                continue
            x, v = _float(r["measured"]), t.reference
            if not math.isfinite(x):
                continue
            if t.percent:
                points.append((folder, r["metric"], v, v * (1 + x), v * (1 + t.lo), v * (1 + t.hi), r["verdict"]))
            else:
                points.append((folder, r["metric"], v, x, t.lo, t.hi, r["verdict"]))
    return points
