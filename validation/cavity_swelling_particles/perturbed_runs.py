#!/usr/bin/python3
"""Spread of the 16-particle statistics over perturbed runs (README.md, "Sixteen colliding
particles are chaotic").

Runs both scenes N times with particle 0 moved by 0, 1, 2, ... times `--shift` in x (one thread),
each with the same extra `--set` options (e.g. the contact model), and prints per run and as mean
+- sample standard deviation (ddof = 1) over the runs:
  - mean centroid path over 10 <= t <= 20 and 15 <= t <= 20 (rim-polygon centroids of /series, one
    row every output.series_every = 5 steps, chords whose ends lie in the window, as ibms compare);
  - mean touching CDS pairs over 15 <= t <= 20 (contact/n_active_pairs rows in the window, as check.cpp);
  - the largest CDS overlap over the run (contact/max_overlap), and the run's wall time.

    perturbed_runs.py IBMS OUT_DIR LABEL [--runs 4] [--shift 1e-5] [--analyse-only] [--set key=value ...]

LABEL names the run set (files OUT_DIR/LABEL_<scene>_<k>.h5). Only reads ibms's outputs: no physics here.
"""
import argparse
import os
import subprocess
import sys
import time
import tomllib

import h5py
import numpy as np

CASE_DIR = os.path.dirname(os.path.abspath(__file__))
SCENES = ("nonswelling", "swelling")


def mean_path(series, t0, t1):
    t = series["time"][:]
    inside = (t[:-1] >= t0) & (t[1:] <= t1)
    x, y = series["per_body/centroid_x"][:], series["per_body/centroid_y"][:]  # rows x bodies
    steps = np.hypot(np.diff(x, axis=0), np.diff(y, axis=0))[inside, :]
    return float(np.sum(steps)) / x.shape[1]


def statistics(path):
    with h5py.File(path, "r") as f:
        s = f["series"]
        t = s["time"][:]
        late = (t >= 15.0) & (t <= 20.0)
        return {
            "path_10_20": mean_path(s, 10.0, 20.0),
            "path_15_20": mean_path(s, 15.0, 20.0),
            "pairs_15_20": float(np.mean(s["contact/n_active_pairs"][:][late])),
            "max_overlap": float(np.max(s["contact/max_overlap"][:])),
            "end_time": float(t[-1]),
            "wall": float(f["timing/run"][()]),
        }


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("ibms")
    parser.add_argument("out_dir")
    parser.add_argument("label")
    parser.add_argument("--runs", type=int, default=4)
    parser.add_argument("--shift", type=float, default=1e-5)
    parser.add_argument("--analyse-only", action="store_true")
    parser.add_argument("--set", action="append", default=[], dest="overrides")
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    rows = {scene: [] for scene in SCENES}
    for scene in SCENES:
        scene_file = os.path.join(CASE_DIR, f"scene_{scene}.toml")
        with open(scene_file, "rb") as f:
            centre = tomllib.load(f)["bodies"][0]["centre"]
        for k in range(args.runs):
            out = os.path.join(args.out_dir, f"{args.label}_{scene}_{k}.h5")
            if not args.analyse_only:
                moved = f"bodies.0.centre=[{centre[0] + k * args.shift!r}, {centre[1]!r}]"
                command = [args.ibms, "run", scene_file, "-o", out, "--quiet", "--threads", "1", "--set", moved]
                for o in args.overrides:
                    command += ["--set", o]
                start = time.time()
                subprocess.run(command, check=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
                print(f"# {scene} run {k}: {time.time() - start:.1f} s", file=sys.stderr, flush=True)
            rows[scene].append(statistics(out))
    keys = ("path_10_20", "path_15_20", "pairs_15_20", "max_overlap", "wall")
    print(f"# {args.label}: {args.runs} runs, particle 0 moved by k * {args.shift:g} in x, overrides {args.overrides}")
    print("scene,run," + ",".join(keys) + ",end_time")
    for scene in SCENES:
        for k, r in enumerate(rows[scene]):
            print(f"{scene},{k}," + ",".join(f"{r[key]:.6g}" for key in keys) + f",{r['end_time']:.6g}")
        for name, reduce in (("mean", np.mean), ("std", lambda v: np.std(v, ddof=1) if len(v) > 1 else 0.0)):
            print(f"{scene},{name}," + ",".join(f"{reduce([r[key] for r in rows[scene]]):.6g}" for key in keys) + ",")


if __name__ == "__main__":
    main()
