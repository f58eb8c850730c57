#!/usr/bin/python3
"""ctest `report_latex_from_synthetic_outputs` and `report_pdf_from_synthetic_outputs`: builds the
report from a tiny synthetic build directory (results.csv with a rerun duplicate and LaTeX special
characters, one centre-line profile pair, one convergence table, a ctest log, a kernel-moment table,
a work-precision table (and the DFG cylinders' with the time to 3 %), a stability map (and a fluid one), a stage-cost table, and the solid tests'
energy, restitution and contact-history tables).
Stage `tex` (always runs; the README's test command installs its Python modules): the data, the
figures and the LaTeX source (build_report.py --tex-dir) -- every figure the source includes exists
and is a PDF, environments and braces balance, the computed figures are in the text and a stale
rerun row is not; a case's page-1 headline is a figure of its shipped scenes, not of a variant run
(the collision-time law) nearer its bound; a DFG 2D-2 max c_D of +12.34 % filed as info by its check is a miss in its
page-1 row (its headline, though a max c_L of -60 % misses by more), in the page-1 list of misses and in Known limitations; a time study's order below its
asserted band is FAIL against its formal order; the title block gives the outputs' commit with its
dirty flag and Basilisk's version; a snapshot's body rims are read as closed rims; README excerpts
are labelled with their path and end at a sentence, with no ellipsis, and every character of the
case READMEs has a LaTeX form (none set as '?'); a one-grid case whose README says why it has no
grid study quotes that paragraph as its numerical uncertainty, and one whose README holds a grid
study of finer grids quotes that; no figure text (scripts
included) prints below 7 pt, and the LaTeX source sets no size below 7 pt (no \tiny, sub- and
superscripts at 7 pt by \DeclareMathSizes); no control character in the source and a caption on
every table, page 1's counts table unbroken; a control-volume against immersed-boundary c_D line
marked O; the summary plot's band drawn as the band, not out to the point; README and header
notation (code spans, 32^2, c_D, rho_s, sum_l, pi, <=, 1e-4, list items) set as LaTeX, the kernel
formula one math group, nan errors '--', a claim the whole first sentence of its header (not cut
at a semicolon, an ellipsis or inside brackets); the run-time table and the verification count
place test_end_of_run_forces, settling_disk_rigid_* and the unit-labelled dfg_check_gates right; and a results.csv case without a
README source mark stops the build with an error naming it.
Stage `pdf` (skipped without LaTeX): the whole report compiles to a PDF whose text holds the same
figures, with no overfull line in LaTeX's log.
usage: test_build_report.py tex|pdf WORK_DIR     exit 0 pass, 1 fail, 77 skipped (pdf stage, no LaTeX)"""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
if len(sys.argv) < 2 or sys.argv[1] not in ("tex", "pdf"):
    sys.exit("usage: test_build_report.py tex|pdf [WORK_DIR]")
stage = sys.argv[1]
work = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else tempfile.mkdtemp(prefix="ibms_synthetic_"))
if stage == "pdf" and (shutil.which("latexmk") is None or shutil.which("pdflatex") is None):
    print("skipped: latexmk/pdflatex not installed (scripts/install-deps.sh --report); "
          "the LaTeX source is tested by report_latex_from_synthetic_outputs")
    sys.exit(77)
try:
    import h5py, matplotlib, numpy  # noqa: F401,E401
except ImportError as e:  # installed by scripts/install-deps.sh: missing is a failure, not a skip
    print("FAIL: %s (scripts/install-deps.sh installs python3-h5py, -matplotlib, -numpy)" % e)
    sys.exit(1)

shutil.rmtree(work, ignore_errors=True)
case = os.path.join(work, "validation", "lid_driven_cavity_re100")
os.makedirs(case)
os.makedirs(os.path.join(work, "verification_results"))
os.makedirs(os.path.join(work, "Testing", "Temporary"))
with open(os.path.join(work, "validation", "results.csv"), "w") as f:
    f.write('lid_driven_cavity_re100,"max |u - Ghia| (lid speed 1)",0.01,0.5,FAIL\n')
    f.write('lid_driven_cavity_re100,"max |u - Ghia| (lid speed 1)",0.01,0.009,pass\n')  # rerun wins
    f.write('lid_driven_cavity_re100,"GCI_fine of min u_x & 50% #{odd} ~^\\ (order nan)",,nan,info\n')
    f.write('swelling_disk_quiescent,"metric with_underscore",1e-10,3.3e-16,pass\n')
    # A measured infinity (a time that never came, e.g. a first fold of rims that never fold).
    f.write('swelling_disk_quiescent,"first time of something that never happens",,inf,info\n')
    # A measured miss filed as information by its check: max c_D of DFG 2D-2 against the case's 2 %.
    f.write('dfg_cylinder_2d2,"drag_coefficient_max at D/h = 20 relative deviation from the reference",,0.1234,info\n')
    f.write('dfg_cylinder_2d2,"strouhal_number at D/h = 20 relative to the reference",0.01,0.0048,pass\n')
    # A secondary quantity farther outside its published bounds than max c_D: page 1's headline
    # stays max c_D, the case's principal published quantity.
    f.write('dfg_cylinder_2d2,"lift_coefficient_max at D/h = 20 relative deviation from the reference",,-0.6,info\n')
    # ibms against itself inside a published case: two forces of one run (O, not P), and ASCII
    # notation of a metric (32^2, c_D) set as LaTeX math.
    f.write('dfg_cylinder_2d2,"control-volume mean c_D over t >= 8 vs immersed boundary at D/h = 20, relative '
            'difference",0.01,0.0001,pass\n')
    f.write('lid_driven_cavity_re100,"largest |centre-line extremum - Botella & Peyret| on 32^2",,0.002,info\n')
    # A variant run's figure nearer its bound than the shipped scene's: page 1's headline is the
    # shipped scene's.
    f.write('cavity_swelling_particles,"non-swelling: min rim distance between particles",0.0175,0.0384,pass\n')
    f.write('cavity_swelling_particles,"collision_time: non-swelling: min rim distance between particles",'
            '0.0175,0.0361,pass\n')
# One DFG 2D-2 run: its force history (start-up spike, shedding, a spiking shortened last step) and
# an HDF5 output holding the resolved scene and the run time (the case's parameter table).
dfg = os.path.join(work, "validation", "dfg_cylinder_2d2")
os.makedirs(dfg)
with open(os.path.join(dfg, "dfg_2d2_20_bodies.csv"), "w") as f:
    # the slip at the markers of the cell velocities (slip_max) and of the constrained face velocities
    # (face_slip_max): the figure draws both, the caption says which the tolerance holds
    f.write("# synthetic force history\ntime [time],body_000/drag_coefficient [-],body_000/lift_coefficient [-],"
            "body_000/slip_max [-],body_000/face_slip_max [-]\n")
    for k in range(1, 401):
        t = 0.03 * k
        f.write("%g,%g,%g,%g,%g\n" % (t, 40.0 / k + 3.5 + 0.1 * math.sin(6 * t), math.sin(3 * t), 0.04, 9e-5))
    f.write("12.0001,9.0,0.0,0.04,9e-5\n")
import h5py  # noqa: E402,F811 - imported above only to test its presence
with h5py.File(os.path.join(dfg, "dfg_2d2_20.h5"), "w") as h5:
    h5.attrs["ibms_version"] = "0.0-synthetic"
    h5.attrs["git_commit"] = "0123456789ab"
    h5.attrs["start_time"] = "2026-01-01T00:00:00Z"
    h5.attrs["host"] = "synthetic-host"
    h5.attrs["scene"] = ('[run]\ntime_step = 0\ncfl = 0.5\nmax_time_step = inf\nmax_viscous_number = 0\n'
                         '[domain]\nlength_x = 2.2\nlength_y = 0.41\ncells_x = 440\ncells_y = 82\n'
                         '[walls.left]\nkind = "inflow"\ntime_factor = "ramp"\nramp_time = 1.0\n'
                         '[ibm]\nkernel = "roma3"\nforcing_passes = 3\n'
                         '[[bodies]]\nkind = "prescribed"\nn_surface_points = 63\n')
    h5["timing/run"] = 117.0
# One run of a case whose README says why it has no grid study: its section quotes that paragraph.
cavity = os.path.join(work, "validation", "cavity_swelling_particles")
os.makedirs(cavity)
with h5py.File(os.path.join(cavity, "nonswelling.h5"), "w") as h5:
    h5.attrs["git_commit"] = "0123456789ab"
    h5.attrs["scene"] = '[domain]\nlength_x = 1.0\nlength_y = 1.0\ncells_x = 100\ncells_y = 100\n'
    h5["timing/run"] = 20.0
for comp, coord in (("u", "y"), ("v", "x")):
    with open(os.path.join(case, "lid_driven_cavity_re100_8_centreline_%s.csv" % comp), "w") as f:
        f.write("# synthetic profile\n%s [length],%s [length/time]\n" % (coord, comp))
        for k in range(9):
            f.write("%g,%g\n" % (k / 8, (k / 8) * (1 - k / 8)))
with open(os.path.join(work, "verification_results", "convergence.csv"), "w") as f:
    f.write("title,N,h,error,order,fit_order,fit_standard_error,formal_order,asserted_min,asserted_max,refined\n")
    for n in (8, 16, 32, 64):
        f.write('"synthetic: u, L2 norm",%d,%g,%g,%s,%s\n' % (n, 1 / n, (1 / n) ** 2, "" if n == 8 else "2",
                                                         "1.987,0.0123,2,1.9,inf,h" if n == 64 else ",,,,,"))
    for n in (8, 16, 32):  # a time study whose fitted order is below its asserted band
        f.write('"synthetic: p in time (N = steps)",%d,%g,%g,%s,%s\n' % (
            n, 1 / n, 1 / n, "" if n == 8 else "1", "0.777,0.01,2,1.8,inf,dt" if n == 32 else ",,,,,"))
with open(os.path.join(work, "Testing", "Temporary", "LastTest.log"), "w") as f:
    f.write("1/1 Testing: test_x\n1/1 Test: test_x\nCommand: x\nTest time =   0.50 sec\n"
            "----------------------------------------------------------\nTest Passed.\n")
    # a unit test whose name holds '_run_' (no case's), a case's rigid run (its case's) and a unit
    # test named like a case's check (dfg_check_gates: no case's, by its label)
    for name in ("test_end_of_run_forces", "settling_disk_rigid_100_run", "dfg_check_gates"):
        f.write("1/1 Testing: %s\n1/1 Test: %s\nCommand: x\nTest time =   0.25 sec\n"
                "----------------------------------------------------------\nTest Passed.\n" % (name, name))

# The build's test definitions (ctest --show-only reads them): dfg_check_gates is labelled unit.
with open(os.path.join(work, "CTestTestfile.cmake"), "w") as f:
    f.write('add_test(dfg_check_gates "true")\nset_tests_properties(dfg_check_gates PROPERTIES LABELS "unit")\n')

# Inputs of the issue-5 sections (reports/report_bench.py): kernel moments, work-precision,
# stability map, per-stage cost.
with open(os.path.join(work, "verification_results", "kernel_moments.csv"), "w") as f:
    f.write("kernel,moment,expected,max_error,min_sum,max_sum,tolerance\n")
    f.write('roma3,"sum phi","1",2.2e-16,0.9999999999999998,1.0000000000000002,1e-14\n')
    f.write('roma3,"sum over even j of phi","in [1/3, 2/3]",nan,0.3333333,0.6666667,1e-14\n')
os.makedirs(os.path.join(work, "bench"))
with open(os.path.join(work, "bench", "work_precision_mms.csv"), "w") as f:
    f.write("# bench_work_precision mms (level quick): error = L2 norm of u_x & 50%\n")
    f.write("N,h,steps,wall_seconds,error\n")
    for n in (16, 32, 64, 128):
        f.write("%d,%g,%d,%g,%g\n" % (n, 1 / n, 4 * n, 1e-6 * n ** 3, 1.0 / n ** 2))
# A cavity's work-precision table: its figure draws Basilisk's recorded points, so the title block
# names Basilisk's version (or that none is recorded).
with open(os.path.join(work, "bench", "work_precision_cavity_re100.csv"), "w") as f:
    f.write("# bench_work_precision cavity_re100 (level quick): error = synthetic\nN,h,steps,wall_seconds,error\n")
    for n in (32, 64, 128):
        f.write("%d,%g,%d,%g,%g\n" % (n, 1 / n, 40 * n, n ** 3 / 1e5, 0.1 / n ** 2))
# The DFG cylinders under both couplings (one figure of their own) and the bench's time to 3 %.
for family, coupling, errors in (("dfg_2d1", "uhlmann", (0.047, 0.027)), ("dfg_2d1", "no_slip", (0.08, 0.036)),
                                 ("dfg_2d2", "uhlmann", (0.13, 0.123)), ("dfg_2d2", "no_slip", (0.08, 0.016))):
    with open(os.path.join(work, "bench", "work_precision_%s_%s.csv" % (family, coupling)), "w") as f:
        f.write("# bench_work_precision %s_%s (level quick): error = synthetic\nN,h,steps,wall_seconds,error\n"
                % (family, coupling))
        for n, e in zip((10, 20), errors):
            f.write("%d,%g,%d,%g,%g\n" % (n, 0.1 / n, 100 * n, n ** 3 / 100.0, e))
with open(os.path.join(work, "bench", "time_to_target_dfg_2d2.csv"), "w") as f:
    f.write("# synthetic\nwhat,target,seconds,relation,smallest_error\nuhlmann,0.03,80,>,0.123\n"
            "no_slip,0.03,6.5,=,0.016\nratio,0.03,12.3077,>,\n")
with open(os.path.join(work, "bench", "stability_synthetic.csv"), "w") as f:
    f.write("# bench_stability synthetic: fluid dt [s] against spring_stiffness [-]\n")
    f.write("mode,dt,stiffness,substeps,outcome,max_area_change,max_speed_ratio,max_contact_pairs,message\n")
    f.write('auto,0.001,1000,12,stable,0.01,1,0,""\n')
    f.write('fixed,0.001,1000,1,blow-up,0.01,1,0,"blow-up at step 3, t = 0.003: body 0 point 1 left the box at x = -1_0"\n')
    f.write('fixed,0.0001,1000,1,unstable,0.6,1,0,"rim area changed by more than 50 % at step 7"\n')
with open(os.path.join(work, "bench", "stability_fluid_synthetic.csv"), "w") as f:
    f.write("# bench_fluid_stability synthetic: CFL number U dt / h against cell Reynolds number U h / nu\n")
    f.write("mode,cfl,cell_reynolds,viscous_number,dt,nu,theory_max_g,steps,outcome,max_cfl_measured,"
            "max_energy_ratio,end_energy_ratio,late_energy_ratio,max_speed,message\n")
    f.write('default_guard,0.5,4,0.125,0.0078,0.0039,1.0,1280,stable,0.6,0.1,0.1,1,1,""\n')
    f.write('default_guard,1.5,4,0.375,0.023,0.0039,1.8,3,stopped,1.2,0.1,0.1,1,1,'
            '"blow-up at step 3, t = 0.07: CFL number 1.2 exceeds run.max_cfl = 1 in cell (3, 63) at x = 0.05_1"\n')
    f.write('no_cfl_guard,1.5,4,0.375,0.023,0.0039,1.8,300,unstable,9,2,2,5,3,"kinetic energy above the bound"\n')
    f.write('no_cfl_guard,0.5,4,0.125,0.0078,0.0039,1.0,1280,stable,0.6,0.1,0.1,1,1,""\n')
# bench_scale --report: rigid disks whose run grows like N, wheels, and two beds.
with open(os.path.join(work, "bench", "scale.csv"), "w") as f:
    f.write("# bench_scale --report\nset,kind,bodies,cells,steps,fluid,ib,bodies_stage,contacts,output,run\n")
    for kind, body_ms in (("rigid", 0.007), ("wheel", 0.06)):
        for n in (16, 64, 256, 1024):
            f.write("spread,%s,%d,%d,40,%g,%g,%g,%g,%g,%g\n" % (kind, n, 650 * n, 0.075 * n, 0.012 * n, body_ms * n,
                                                               0.1 * body_ms * n, 0.01 * n, (0.1 + body_ms) * n))
    f.write("bed,wheel,64,42025,40,5.0,0.6,64.0,60.0,0.5,71.0\n"
            "bed_outer_step_0.5,wheel,64,42025,40,5.0,0.6,13.0,10.0,0.5,19.0\n")
with open(os.path.join(work, "bench", "overhead.csv"), "w") as f:
    f.write("scene,stage,seconds_per_step,calls\nfluid_only_cavity_128,simulation_step,,0.0014\n"
            "fluid_only_cavity_128,bare_fluid_solver_step,,0.00136\nfluid_only_cavity_128,ratio,,1.03\n"
            "fluid_only_cavity_128,predictor,0.0009,110\nfluid_only_cavity_128,pair_checks_total,,0\n")

# Inputs of the solid section (reports/report_solid.py): the wheel energy table and history (a
# rerun's rows appended: the second table wins), restitution, e = 1 energies, contact histories.
res = os.path.join(work, "verification_results")
with open(os.path.join(res, "wheel_energy.csv"), "w") as f:
    f.write("dt,steps_per_period,omega_max_dt,max_rel_error,first_100T_max,last_100T_max,bound,order\n")
    for rerun in (0, 1):
        for k in range(3):
            dt = 1e-3 / 2 ** k
            f.write("%g,%g,%g,%g,%g,%g,%g,%s\n" % (dt, 200 * 2 ** k, 0.1 / 2 ** k, 0.02 / 2 ** k,
                                                  0.019 / 2 ** k, 0.0195 / 2 ** k, 0.105 / 2 ** k,
                                                  "" if k == 0 else ("9.99", "1")[rerun]))
with open(os.path.join(res, "wheel_energy_history.csv"), "w") as f:
    f.write("dt,periods,max_rel_error_over_period\n")
    for rerun in (0, 1):
        for k in range(3):
            for p in range(1, 51):
                f.write("%g,%d,%g\n" % (1e-3 / 2 ** k, p, (0.015 + 0.005 * (p % 7) / 7) / 2 ** k))
with open(os.path.join(res, "restitution.csv"), "w") as f:
    f.write("case,e_target,e_measured,rel_error,tolerance,steps_per_contact\n")
    for case in ("two points, linear spring-dashpot", "wheel-wall"):
        for e in (0.1, 0.5, 0.9):
            f.write('"%s",%g,%g,%g,0.01,%d\n' % (case, e, e * 1.003, 0.003, 2000))
with open(os.path.join(res, "restitution_elastic.csv"), "w") as f:
    f.write('case,ke_before,ke_after,rel_change,tolerance\n"wheel-wall",0.3927,0.39268,5e-5,0.001\n')
with open(os.path.join(res, "contact_history.csv"), "w") as f:
    f.write("case,e_target,t_over_contact_time,normal_velocity_over_approach,overlap_over_diameter\n")
    for case in ("two points, linear spring-dashpot", "wheel-wall"):
        for e in (0.1, 0.5, 0.9):
            for k in range(21):
                s = k / 20
                f.write('"%s",%g,%g,%g,%g\n' % (case, e, s, -1 + (1 + e) * s, 0.006 * s * (1 - s)))

# Figures the report computes from the tables above: slope of n^-2 error against n^3 time is -2/3,
# the stage-cost ratio, the solid section's headings and its restitution row, the DFG cylinders'
# subsection and the time-to-3 % ratio as the bench wrote it (a bound).
expected = ("-0.667", "1.99", "0.012", "Stability map summary", "Kernel moments", "ratio 1.03",
            "energy error over 1000 periods", "measured against target", "0.5015",
            "DFG cylinders under both immersed-boundary couplings", "ratio > 12.3", "more than 80")


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def check_text(text, where):
    for e in expected:
        if e not in text:
            fail("'%s' not in the %s" % (e, where))
    if "9.99" in text:  # the first run's energy table, replaced by the rerun's
        fail("a stale (rerun-replaced) energy table row is in the %s" % where)


def build_report(*args):
    """build_report.py on the synthetic build directory with `args`; fails the test on an error."""
    proc = subprocess.run([sys.executable, os.path.join(here, "build_report.py"), "--build", work] + list(args),
                          capture_output=True, text=True, timeout=240)
    print(proc.stdout, proc.stderr)
    if proc.returncode != 0:
        fail("build_report.py %s exited %d" % (" ".join(args), proc.returncode))
    if "figure text below" in proc.stderr:  # every figure's text >= 7 pt as printed
        fail("figure text below 7 pt at print size (stderr above)")
    if "overfull lines" in proc.stderr:  # no table column or text line beyond the text width
        fail("text or table columns wider than the page's text (stderr above)")


if stage == "tex":
    # Body rims of a snapshot (docs/output.md: bodies/x, bodies/y split at bodies/first_point): two
    # closed rims, as the vorticity snapshots draw them.
    sys.path.insert(0, here)
    import report_figures  # noqa: E402
    with h5py.File(os.path.join(work, "rims.h5"), "w") as h5:
        g = h5.create_group("snapshots/000010")
        g["bodies/x"] = [0.0, 1.0, 0.0, 2.0, 3.0, 3.0, 2.0]
        g["bodies/y"] = [0.0, 0.0, 1.0, 2.0, 2.0, 3.0, 3.0]
        g["bodies/first_point"] = [0, 3, 7]
        rims = report_figures._body_outlines(g)
    if [len(x) for x, _ in rims] != [4, 5] or rims[1][0][-1] != 2.0 or rims[1][1][0] != 2.0:
        fail("the snapshot's body rims are not read as two closed rims: %r" % (rims,))
    tex_dir = os.path.join(work, "tex")
    build_report("--tex-dir", tex_dir)
    with open(os.path.join(tex_dir, "report.tex"), encoding="utf-8") as f:
        tex = f.read()
    # Structure a LaTeX run would reject: unbalanced environments or braces (escaped ones aside).
    begins, ends = re.findall(r"\\begin\{(\w+\*?)\}", tex), re.findall(r"\\end\{(\w+\*?)\}", tex)
    stack = []
    for m in re.finditer(r"\\(begin|end)\{(\w+\*?)\}", tex):
        if m.group(1) == "begin":
            stack.append(m.group(2))
        elif not stack or stack.pop() != m.group(2):
            fail("\\end{%s} without its \\begin at offset %d" % (m.group(2), m.start()))
    if stack:
        fail("environments left open: %s" % stack)
    unescaped = re.sub(r"\\[{}]", "", tex)
    if unescaped.count("{") != unescaped.count("}"):
        fail("unbalanced braces: %d { against %d }" % (unescaped.count("{"), unescaped.count("}")))
    if not tex.rstrip().endswith("\\end{document}") or len(begins) < 10:
        fail("report.tex is truncated (%d environments)" % len(begins))
    figures = re.findall(r"\\includegraphics(?:\[[^]]*\])?\{([^}]+)\}", tex)
    if len(figures) < 5:
        fail("only %d figures in report.tex" % len(figures))
    for name in figures:
        path = os.path.join(tex_dir, name)
        if not os.path.isfile(path):
            fail("figure %s is included but not written" % name)
        with open(path, "rb") as f:
            if f.read(5) != b"%PDF-":
                fail("figure %s is not a PDF" % name)
    check_text(tex.replace("$", "").replace("{,}", ","), "LaTeX source")
    # Page 1: the synthetic miss is a miss in its case's row and in the list of misses, not info.
    summary = tex[tex.index("Summary: one row per validation case"):tex.index("\\tableofcontents")]
    row = next((line for line in summary.splitlines() if "texttt{dfg\\_\\allowbreak{}cylinder" in line), "")
    if "{miss}" not in row or "+12.3" not in row:
        fail("the synthetic DFG 2D-2 miss (+12.3 %%) is not a miss in its page-1 row: %r" % row[:300])
    if not re.search(r"\{miss\}\} \\texttt\{dfg\\_cylinder\\_2d2\}: drag\\_coefficient\\_max at D/h = 20", summary):
        fail("the synthetic miss is not in the page-1 list of misses")
    row = next((line for line in summary.splitlines() if "swelling\\_\\allowbreak{}particles}" in line), "")
    if "min rim distance between particles" not in row or "collision" in row:
        fail("the swelling cavity's page-1 headline is not its shipped scene's figure: %r" % row[-300:])
    def case_tex(case):
        """The LaTeX of one case's section, up to the next section."""
        section = tex[tex.index("label{case:%s}" % case):]
        return section[:section.index("\\section")] if "\\section" in section else section

    # A one-grid case whose README says why it has no grid study quotes that paragraph as its
    # numerical uncertainty (the spread of perturbed runs, with its figures).
    section = case_tex("cavity_swelling_particles")
    if not re.search(r"Numerical uncertainty at this level.\} One grid \(100\$\\times\$100\), and no grid study at "
                     r"any level; the case README says why", section) or "0.3352" not in section:
        fail("the swelling cavity's section does not quote its README's reason for no grid study and its spread")
    # A one-grid case whose README holds a grid study of finer grids (DFG 2D-2) quotes it.
    section = case_tex("dfg_cylinder_2d2")
    if "the case README's grid study, on finer grids" not in section or "GCI" not in section:
        fail("the DFG 2D-2 section (one grid) does not quote its README's grid study of finer grids")
    # Title block: the outputs' commit with its dirty flag (no CMakeCache.txt here: unknown) and the
    # peer compared with, with its version.
    title = tex[:tex.index("Summary: one row per validation case")]
    if not re.search(r"outputs' commit: & \\texttt\{0123456789ab\} \(dirty flag unknown", title):
        fail("the title block does not give the outputs' commit with its dirty flag")
    if not re.search(r"peer: Basilisk: & .*version", title):
        fail("the title block does not name Basilisk's version, though the work-precision figure compares with it")
    orders = tex[tex.index("Observed orders beside formal orders"):]
    if not re.search(r"p in time \(N = steps\) & \$\\Delta t\$ & 8, 16, 32 & [^&]+ & 2 & 0\.777[^&]*& "
                     r"\[1\.8, \$\\infty\$\] & \\textcolor\{red\}", orders):
        fail("the time study's order 0.777 is not shown against formal order 2 and band [1.8, inf] as FAIL")
    if "Cost against the number of bodies" not in tex:
        fail("no section 'Cost against the number of bodies'")
    scale = tex[tex.index("Cost against the number of bodies"):]
    if "scale.pdf" not in scale or "rigid & 1024 & 1.43 & 0.0933 & 0.133 & 1 & 1" not in scale \
            or "papers' law, outer step 1/2 & wheel & 64 & 5 & 13 & 10 & 2.6" not in scale:
        fail("the scale section lacks its figure, the 1024 rigid disks' ratios and exponents, or the beds' ratio")
    if "time step $\\Delta t$" not in tex:
        fail("the time study's figure caption does not name the time step")
    # README excerpts: labelled as the README's text with its path (their figures are not this
    # run's), each whole or cut at a sentence end, never with an ellipsis.
    excerpts = re.findall(r"\\textbf\{The case README's text\} \(\\texttt\{validation/([^}]*)/README\.md\}.*?``(.*?)''"
                          r"\\end\{quote\}", tex, re.S)
    if not any(c == "lid\\_driven\\_cavity\\_re100" for c, _ in excerpts):
        fail("the README excerpt of lid_driven_cavity_re100 is not labelled as the README's text with its path")
    for c, text in excerpts:
        if not re.search(r"[.!?)]\}?$", text.strip()) or text.strip().endswith("..."):
            fail("the README excerpt of %s does not end at a sentence end: ...%r" % (c, text[-60:]))
    # Every character of the case READMEs, which the report quotes, has a LaTeX form: none is set
    # as '?' (report_latex.esc).
    sys.path.insert(0, here)
    import report_latex  # noqa: E402
    source_root = os.path.dirname(here)
    for name in sorted(os.listdir(os.path.join(source_root, "validation"))):
        readme = os.path.join(source_root, "validation", name, "README.md")
        if os.path.isfile(readme):
            with open(readme, encoding="utf-8") as f:
                unset = sorted({ch for ch in f.read() if ord(ch) > 127 and "?" in report_latex.esc(ch)})
            if unset:
                fail("validation/%s/README.md holds characters the report would set as '?': %r" % (name, unset))
    # No text smaller than 7 pt in the LaTeX source: no \tiny, no \fontsize below 7, and math
    # scripts held at 7 pt in the small sizes the tables use.
    sizes = [float(v) for v in re.findall(r"\\fontsize\{([0-9.]+)\}", tex)]
    if "\\tiny" in tex or any(v < 7 for v in sizes) or "\\DeclareMathSizes{7.5}{7.5}{7}{7}" not in tex \
            or "\\DeclareMathSizes{8}{8}{7}{7}" not in tex:
        fail("the LaTeX source sets text below 7 pt (\\tiny, a \\fontsize below 7: %r) or leaves math scripts "
             "at LaTeX's 5-6 pt" % sizes)
    # The DFG slip panel: the caption says the face velocities' slip is the constrained one and the
    # cell velocities' slip is the momentum-interpolated one, not held to the tolerance.
    if "face velocities' slip (\\texttt{face\\_slip\\_max})" not in tex or "momentum interpolation" not in tex:
        fail("the DFG body-history caption does not tell the constrained face slip from the cell slip")
    # Stability maps: runs marked stable above the von Neumann line are counted with their steps
    # and the analysed growth, and how many ran long enough for it to show (rows below: one of two).
    import report_bench  # noqa: E402
    import fluid_stability_theory  # noqa: E402
    keys = ("mode,cfl,cell_reynolds,viscous_number,theory_max_g,steps,outcome,max_cfl_measured,late_energy_ratio,"
            "max_speed,first_above_cfl_1,first_above_cfl_2").split(",")
    rows = [dict(zip(keys, v.split(","))) for v in (
        "no_cfl_guard,1.5,512,0.003,2.2476,427,stable,0.654,1.4,0.43,-1,-1",   # 2.25^427: long enough
        "no_cfl_guard,0.3,512,0.0006,1.00244,400,stable,0.3,1.0,0.9,-1,-1",    # 1.0024^400 = 2.7: too short
        "no_cfl_guard,0.1,4,0.025,1.0,6000,stable,0.09,1.0,0.9,-1,-1",
        "no_cfl_guard,1.5,0.25,6,1.0,428,stable,2.011,1.0,1.341,1,1")]         # measured CFL above run.cfl
    text = report_bench.fluid_above_line_text(rows, "cavity", fluid_stability_theory)
    if not text or not text.startswith("2 of the 4 runs marked stable") or "ran 400 to 427 steps" not in text \
            or "2.248 per step; 1 of them ran long enough" not in text:
        fail("the stable runs above the von Neumann line are not counted with steps and growth: %r" % (text,))
    text = report_bench.fluid_cfl_overshoot_text(rows, "cavity_adaptive") or ""
    if "\\emph{end} of that step" not in text or "measured 2.01, above 1 from step 1, above 2 from step 1" not in text:
        fail("a measured CFL number above run.cfl is not explained by the measured number's definition: %r" % text)
    # The forcing-passes section: its text names the papers' coupling and the change from 1 to 5 passes.
    rows = [dict(case="couette", passes=p, cells_per_diameter="9.6", l2_error_or_speed_deviation=e, rim_slip=r,
                 max_error_or_max_speed="0.1", ms_per_step="1") for p, e, r in (("1", "0.01", "0.13"),
                                                                                 ("5", "0.055", "0.0065"))]
    text = report_bench.forcing_passes_text(rows, [])
    if "papers' coupling" not in text or "rises from 0.01 to 0.055 (5.5 times higher)" not in text \
            or "(20 times lower)" not in text:
        fail("the forcing-passes text does not state the coupling and the slip and error change: %r" % text)
    # Touching contact-sphere pairs per run (the swelling cavity's runs under two contact laws): the
    # late-window mean and largest count, mean overlap and closest rims, from each run's body series.
    import build_report as builder  # noqa: E402
    pairs_dir = os.path.join(work, "pairs_case")
    os.makedirs(os.path.join(pairs_dir, "collision_time"), exist_ok=True)
    for sub, pairs in (("", 7), ("collision_time", 80)):
        with open(os.path.join(pairs_dir, sub, "swelling_bodies.csv"), "w") as f:
            f.write("# synthetic\ntime [time],contact/n_active_pairs [-],contact/max_overlap [length],"
                    "bodies/min_rim_distance [length]\n")
            for k in range(21):
                f.write("%d,%d,%g,%g\n" % (k, pairs + (k % 2), 1e-7 * pairs, 0.05 + 0.001 * k))
    got = {r["run"]: r for r in builder.contact_pairs_rows(pairs_dir)}
    if sorted(got) != ["collision_time/swelling", "swelling"] or got["collision_time/swelling"]["max_pairs"] != 81 \
            or abs(got["swelling"]["mean_pairs"] - 7.5) > 1e-9 or abs(got["swelling"]["rim"] - 0.065) > 1e-9:
        fail("the touching-pairs table does not read the runs' late windows (t >= 15): %r" % got)
    # DKT: each ungated quantity has its own cause, none the README placeholder.
    import report_cases  # noqa: E402
    causes = [report_cases.cause_of("dkt_two_disks", m) for m in (
        "start of kissing, distance < 1.25 d [s] (Wan & Turek ~1.2)", "leading max speed [cm/s] (Wan & Turek 1.57)",
        "time of max speed, leading [s]", "time of minimum centre distance [s] (Wan & Turek 1.4)",
        "time the pair is horizontal [s] (Wan & Turek 1.87)")]
    if len(set(causes)) != 5 or any(c.startswith("See ") for c in causes):
        fail("the DKT misses do not each have their own cause: %r" % causes)
    # No control character in the source (a "\t" of "\textbf" read as a tab printed "extbf").
    if re.search(r"[\x00-\x09\x0b-\x1f]", tex) or "extbf" in tex.replace("\\textbf", ""):
        fail("report.tex holds a control character or a mangled \\textbf (a backslash escape eaten by Python)")
    # Every table has a caption (numbering without gaps), and page 1's counts table does not break
    # (its total row is not left alone on the next page).
    tables = re.findall(r"\\begin\{longtable\}.*?\\end\{longtable\}", tex, re.S)
    uncaptioned = [t[:120] for t in tables if "\\caption{" not in t]
    if uncaptioned:
        fail("%d tables without a caption, e.g. %r" % (len(uncaptioned), uncaptioned[0]))
    counts = next((t for t in tables if "all classes" in t), "")
    if not re.search(r"\\textbf\{all classes\}[^\n]*\\\\\*", counts) or re.search(r"[^*\s]\s*\\\\\n", counts):
        fail("the page-1 counts table may break before its total row")
    # Lines of ibms against itself in a published case carry O: control-volume against
    # immersed-boundary c_D.
    checks = tex[tex.index("section{Validation checks by case}"):]
    if not re.search(r"\\textsf\{O\} & control-(?:\{\})?volume mean \$c_\{D\}\$", checks):
        fail("the control-volume against immersed-boundary c_D line is not marked O (ibms against itself) "
             "or its c_D is not set as math")
    if "on 32$^{2}$" not in checks:
        fail("the metric's ASCII exponent 32^2 is not set as LaTeX (32$^{2}$)")
    # The summary plot's per-cent panel: each target band from its lower to its upper bound, not
    # drawn out to the figure (a miss lies outside its band).
    import build_report  # noqa: E402
    (k, d, lo, hi, v), = build_report.deviation_rows([("c", "m", 3.23, 3.23 * 1.1234, 3.22, 3.24, "miss")])
    if not (abs(d - 12.34) < 1e-9 and abs(lo + 0.3096) < 1e-3 and abs(hi - 0.3096) < 1e-3):
        fail("the summary plot's band of a +12.34 %% miss against [3.22, 3.24] is [%g, %g] %%, not its "
             "bounds [-0.31, +0.31] %%" % (lo, hi))
    # README and header text set as LaTeX: code spans in typewriter, ASCII exponents and subscripts
    # as math; the kernel table's formula in one math group (its '-' a minus inside it, no break);
    # a range claim's nan error shown as '--'; ASCII notation (sums, Greek names, relations, e-notation)
    # as math; a claim the whole first sentence of its header.
    import report_latex  # noqa: E402
    import report_bench  # noqa: E402
    import report_trace  # noqa: E402
    got = report_latex.md_text("`ibms run` on 32^2: c_D, rho_s, ρ_f, drag_coefficient_max")
    want = (r"\texttt{ibms run} on 32$^{2}$: $c_{D}$, $\rho_{s}$, $\rho_{f}$, "
            r"drag\_coefficient\_max")
    if got != want:
        fail("README notation set as %r, not %r" % (got, want))
    formula = report_bench._formula("K = 59/60 - sqrt(29)/20")
    if formula != r"$K = 59/60 - \sqrt {29}/20$" or report_bench._max_error("nan") != "--":
        fail("the kernel table's formula %r is not one math group, or a nan error is not '--'" % formula)
    got = report_latex.md_text("sum_l dV_l F_l = 2 pi/N_l, 10 <= t, 1e-4, ~1.2, the delta kernels")
    want = (r"$\sum_{l}$ $dV_{l}$ $F_{l}$ = 2 $\pi$/$N_{l}$, 10 $\leq$ t, $10^{-4}$, $\approx$1.2, "
            r"the delta kernels")
    if got != want:
        fail("ASCII notation set as %r, not %r" % (got, want))
    header = os.path.join(work, "claim_header.cpp")
    with open(header, "w", encoding="utf-8") as f:
        f.write("// A claim (Celik et al. 2008): `ibms run SCENE --set ...` accepts it; the list:\n"
                "//  - on square cells the value (round-off tolerance;\n//    see below);\n"
                "//  - elsewhere zero.\n// usage: none\n#include <cmath>\n")
    claim, source = report_trace.first_claim([header])
    if claim != ("A claim (Celik et al. 2008): `ibms run SCENE --set ...` accepts it; the list: on square "
                 "cells the value (round-off tolerance; see below); elsewhere zero.") or source != header:
        fail("a header's first sentence is read as %r, not whole (list items as clauses, no cut at a "
             "semicolon, an ellipsis, an abbreviation or inside brackets)" % claim)
    # Traceability on a tiny source tree: a list of citations with an appendix section (sections
    # 1.1 and A8 after one 'method.md', each with its '§') traces the test to both sections; a
    # section marked Descriptive under its heading and a heading that only groups its subsections
    # are not listed among the sections no test cites, the descriptive one is named with its reason;
    # an uncited requirement (A9) is listed. (The citation is assembled, so that this file, a test's
    # source, cites nothing itself.)
    tree = os.path.join(work, "trace_source")
    os.makedirs(os.path.join(tree, "docs"), exist_ok=True)
    os.makedirs(os.path.join(tree, "verification"), exist_ok=True)
    with open(os.path.join(tree, "docs", "method.md"), "w", encoding="utf-8") as f:
        f.write("# M\n\n## 1. Bodies\n\n### 1.1 Model [P]\n\nA claim.\n\n## 2. Sources\n\n"
                "*Descriptive: the papers only.*\n\nText.\n\n## A8. DEM\n\nFormulas.\n\n"
                "## A9. Kernels\n\nMore formulas.\n")
    script = os.path.join(tree, "verification", "test_trace.sh")
    with open(script, "w", encoding="utf-8") as f:
        f.write("# Claim: a synthetic test (docs/method.md " + "\u00a71.1, \u00a7" + "A8).\n")
    trace_out = []
    report_trace.traceability_section(trace_out, tree, [("test_trace", ["unit"], [script])],
                                      [{"name": "test_trace", "status": "pass"}])
    trace_tex = "\n".join(trace_out)
    rows = {r.split("&")[0].strip(): r for r in trace_tex.splitlines() if re.match(r"M[0-9A]", r)}
    if "allowbreak{}trace}" not in rows.get("MA8", "") or "allowbreak{}trace}" not in rows.get("M1.1", ""):
        fail("an appendix citation in a list ('method.md \u00a71.1, \u00a7A8') does not trace the test to "
             "M1.1 and MA8: %r" % sorted(rows))
    untested = re.search(r"Requirement sections no test cites\}? \((\d+) of (\d+) requirements\): ([^.]*)\.",
                         trace_tex)
    if not untested or untested.group(3) != "MA9" or untested.group(1, 2) != ("1", "3"):
        fail("the requirement sections no test cites are not exactly MA9 of 3 requirements (the descriptive M2 "
             "and the grouping M1 left out): %r" % (untested.group(0) if untested else trace_tex[-600:]))
    if "M2 (the papers only)" not in trace_tex or "group their subsections: M1" not in trace_tex:
        fail("the descriptive section M2 (with its reason) or the grouping heading M1 is not named apart")
    # The run times: a unit test whose name holds '_run_' is no validation case's, a rigid run of
    # the settling disk goes with its case; the verification section counts the unit test.
    times = tex[tex.index("Run time per validation case"):]
    if "test\\_end\\_of" in times or "settling\\_disk\\_rigid" in times or "settling\\_disk}" not in times \
            or "texttt{dfg}" in times:
        fail("the run-time table shows a unit test as a case or splits settling_disk_rigid from settling_disk")
    if not re.search(r"Unit and convergence tests from ctest's logs: 2 tests", tex):
        fail("the verification section does not count test_end_of_run_forces among the unit tests")
    # A case compared only with ibms's own runs is called a consistency check on page 1, not a
    # validation; the work-precision section says its DFG runs are not the validation runs.
    row = next((line for line in summary.splitlines() if "texttt{swelling\\_\\allowbreak{}sedimentation}" in line), "")
    if "Consistency check against ibms's own runs, not validation" not in row:
        fail("swelling_sedimentation (mark own) is not called a consistency check in its page-1 row: %r" % row[:200])
    if "These are not the validation runs" not in tex:
        fail("the DFG work-precision text does not say its runs are not the validation runs")
    if "Known limitations" not in tex or "momentum interpolation" not in tex:
        fail("the Known limitations section does not list the miss with its cause")
    # A case without a source mark (no README with a Compared-with line) stops the build.
    bad = os.path.join(work, "unmarked")
    shutil.rmtree(bad, ignore_errors=True)
    os.makedirs(os.path.join(bad, "validation"))
    with open(os.path.join(bad, "validation", "results.csv"), "w") as f:
        f.write('synthetic_case_without_source_mark,"some metric",0.1,0.01,pass\n')
    proc = subprocess.run([sys.executable, os.path.join(here, "build_report.py"), "--build", bad, "--tex-dir",
                           os.path.join(bad, "tex")], capture_output=True, text=True, timeout=240)
    if proc.returncode == 0 or "synthetic_case_without_source_mark" not in proc.stderr \
            or "no source mark" not in proc.stderr:
        fail("a case without a source mark did not stop the report build with a clear error "
             "(exit %d, stderr %r)" % (proc.returncode, proc.stderr[-300:]))
    leftovers = [d for d in os.listdir(work) if d.startswith("report-")]
    if leftovers:
        fail("temporary directories left behind: %s" % leftovers)
    print("pass: %s (%d figures, %d environments)" % (os.path.join(tex_dir, "report.tex"), len(figures),
                                                      len(begins)))
    sys.exit(0)

pdf = os.path.join(work, "report.pdf")
build_report("--output", pdf)
with open(pdf, "rb") as f:
    head = f.read(5)
size = os.path.getsize(pdf)
if head != b"%PDF-" or size < 10000:
    fail("%s is not a plausible PDF (%d bytes)" % (pdf, size))
if shutil.which("pdftotext"):
    check_text(subprocess.run(["pdftotext", pdf, "-"], capture_output=True, text=True).stdout, "report text")
leftovers = [d for d in os.listdir(work) if d.startswith("report-")]
if leftovers:
    fail("temporary directories left behind: %s" % leftovers)
print("pass: %s (%d bytes)" % (pdf, size))
