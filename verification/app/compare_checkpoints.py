#!/usr/bin/python3
"""Bit-for-bit comparison of the /checkpoint groups of two ibms output files.

Usage: compare_checkpoints.py A.h5 B.h5
Exit 0 when every dataset and attribute of A's /checkpoint equals B's bit for bit (the same names
on both sides); prints the number of values compared and the first differences otherwise.
`fftw_wisdom` is FFTW's planner state, not simulation state (a restarted process imports the
original's and may add to it): it is not compared.
"""
import sys

import h5py
import numpy as np


def checkpoint(path):
    with h5py.File(path, "r") as f:
        group = f["checkpoint"]
        arrays = {name: np.asarray(group[name][()], dtype=np.float64) for name in group
                  if name != "fftw_wisdom"}
        attributes = {name: np.asarray(group.attrs[name]) for name in group.attrs}
    return arrays, attributes


def main():
    a_arrays, a_attributes = checkpoint(sys.argv[1])
    b_arrays, b_attributes = checkpoint(sys.argv[2])
    problems = []
    if sorted(a_arrays) != sorted(b_arrays):
        problems.append(f"datasets differ: {sorted(set(a_arrays) ^ set(b_arrays))}")
    if sorted(a_attributes) != sorted(b_attributes):
        problems.append(f"attributes differ: {sorted(set(a_attributes) ^ set(b_attributes))}")
    n_values = 0
    for name in sorted(set(a_arrays) & set(b_arrays)):
        a, b = a_arrays[name], b_arrays[name]
        n_values += a.size
        if a.shape != b.shape:
            problems.append(f"{name}: shape {a.shape} vs {b.shape}")
        elif not np.array_equal(a.view(np.uint64), b.view(np.uint64)):
            n_diff = int(np.count_nonzero(a.view(np.uint64) != b.view(np.uint64)))
            problems.append(f"{name}: {n_diff} of {a.size} values differ (max |a-b| {np.max(np.abs(a - b)):.3g})")
    for name in sorted(set(a_attributes) & set(b_attributes)):
        a, b = a_attributes[name], b_attributes[name]
        if a.tobytes() != b.tobytes():
            problems.append(f"attribute {name}: {a} vs {b}")
    print(f"compared {n_values} checkpoint values and {len(a_attributes)} attributes: "
          f"{'identical' if not problems else 'DIFFERENT'}")
    for p in problems[:10]:
        print("  " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
