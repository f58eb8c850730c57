#!/usr/bin/python3
"""ctest `report_builds_from_synthetic_outputs`: builds the report from a tiny synthetic build
directory (results.csv with a rerun duplicate and LaTeX special characters, one centre-line
profile pair, one convergence table, a ctest log) and checks that a PDF comes out.
usage: test_build_report.py WORK_DIR     exit 0 pass, 1 fail, 77 skipped (no LaTeX / modules)"""
import os
import shutil
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
work = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "synthetic")
if shutil.which("latexmk") is None or shutil.which("pdflatex") is None:
    print("skipped: latexmk/pdflatex not installed (scripts/install-deps.sh --report)")
    sys.exit(77)
try:
    import h5py, matplotlib, numpy  # noqa: F401,E401
except ImportError as e:
    print("skipped: %s" % e)
    sys.exit(77)

shutil.rmtree(work, ignore_errors=True)
case = os.path.join(work, "validation", "lid_driven_cavity_re100")
os.makedirs(case)
os.makedirs(os.path.join(work, "verification_results"))
os.makedirs(os.path.join(work, "Testing", "Temporary"))
with open(os.path.join(work, "validation", "results.csv"), "w") as f:
    f.write('lid_driven_cavity_re100,"max |u - Ghia| (lid speed 1)",0.01,0.5,FAIL\n')
    f.write('lid_driven_cavity_re100,"max |u - Ghia| (lid speed 1)",0.01,0.009,pass\n')  # rerun wins
    f.write('lid_driven_cavity_re100,"GCI_fine of min u_x & 50% #{odd} ~^\\ (order nan)",,nan,info\n')
    f.write('synthetic_case_without_outputs,"metric with_underscore",1e-10,3.3e-16,pass\n')
for comp, coord in (("u", "y"), ("v", "x")):
    with open(os.path.join(case, "lid_driven_cavity_re100_8_centreline_%s.csv" % comp), "w") as f:
        f.write("# synthetic profile\n%s [length],%s [length/time]\n" % (coord, comp))
        for k in range(9):
            f.write("%g,%g\n" % (k / 8, (k / 8) * (1 - k / 8)))
with open(os.path.join(work, "verification_results", "convergence.csv"), "w") as f:
    f.write("title,N,h,error,order\n")
    for n in (8, 16, 32, 64):
        f.write('"synthetic: u, L2 norm",%d,%g,%g,%s\n' % (n, 1 / n, (1 / n) ** 2, "" if n == 8 else "2"))
with open(os.path.join(work, "Testing", "Temporary", "LastTest.log"), "w") as f:
    f.write("1/1 Testing: test_x\n1/1 Test: test_x\nCommand: x\nTest time =   0.50 sec\n"
            "----------------------------------------------------------\nTest Passed.\n")

pdf = os.path.join(work, "report.pdf")
proc = subprocess.run([sys.executable, os.path.join(here, "build_report.py"), "--build", work,
                       "--output", pdf], capture_output=True, text=True, timeout=240)
print(proc.stdout, proc.stderr)
if proc.returncode != 0:
    print("FAIL: build_report.py exited %d" % proc.returncode)
    sys.exit(1)
with open(pdf, "rb") as f:
    head = f.read(5)
size = os.path.getsize(pdf)
if head != b"%PDF-" or size < 10000:
    print("FAIL: %s is not a plausible PDF (%d bytes)" % (pdf, size))
    sys.exit(1)
leftovers = [d for d in os.listdir(work) if d.startswith("report-")]
if leftovers:
    print("FAIL: temporary directories left behind: %s" % leftovers)
    sys.exit(1)
print("pass: %s (%d bytes)" % (pdf, size))
