"""Cluster resources of one ibms run (cores, memory, time limit) from the run's own estimate.

`ibms info SCENE --set ...` prints the grid ("NX x NY cells") and "estimated cost: C cell-steps"
(steps to end_time from the first time-step estimate, times cells). The time limit is
    runtime [min] = FLOOR + MARGIN * C * SECONDS_PER_CELL_STEP / 60,
with SECONDS_PER_CELL_STEP = 1.5e-7 s: the fluid step measured on this machine, one thread, is
0.83e-7 s per cell at 128^2 and 1.5e-7 s at 1024^2 (bench/README.md, "Both cores"), the settling
disk's 200 x 600 fluid stage 0.79e-7 s per cell. MARGIN = 4 covers body and contact work the
cell count does not see and a slower node. When the run has finished before (its status file
holds the measured seconds) the limit is at least 3x that. Memory: 300 MB plus 2 kB per cell
(ibms keeps a few tens of doubles per cell).

`ibms info` builds the run's solver (FFTW plans) and takes 2-12 s per validation scene on an idle
core (up to a minute on a loaded machine), so its answers are computed once, in parallel
(`prefetch`), and cached in <build>/workflow_estimates.json, keyed by the scene's path and
content and the --set values. The key leaves out the ibms binary on purpose: a rebuild (every
commit) would otherwise redo every estimate, and an estimate a code change has made stale is still
a usable time limit (4x margin, and 3x the last measured time once a run has finished).
"""
import hashlib
import json
import math
import os
import re
import subprocess

SECONDS_PER_CELL_STEP = 1.5e-7
MARGIN = 4.0
FLOOR_MINUTES = 5
DEFAULT = {"mem_mb": 1000, "runtime": 60, "cells": None, "cell_steps": None}


def _cache_path(wf):
    # beside, not inside, the workflow's state directory (the Slurm test removes that one)
    return os.path.join(os.path.dirname(os.path.abspath(wf)), "workflow_estimates.json")


def _load(wf):
    try:
        with open(_cache_path(wf)) as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def _store(wf, cache):
    tmp = _cache_path(wf) + ".%d.tmp" % os.getpid()
    with open(tmp, "w") as f:
        json.dump(cache, f, indent=1, sort_keys=True)
    os.replace(tmp, _cache_path(wf))


def _key(scene, sets):
    try:
        with open(scene, "rb") as f:
            digest = hashlib.sha256(f.read()).hexdigest()[:16]
    except OSError:
        return None
    return json.dumps([scene, digest, list(sets)])


def _ask(scene, sets, ibms):
    cmd = [ibms, "info", scene]
    for s in sets:
        cmd += ["--set", s]
    out = subprocess.run(cmd, capture_output=True, text=True).stdout
    m = re.search(r"^(\d+) x (\d+) cells", out, re.M)
    c = re.search(r"estimated cost: ([0-9.eE+-]+) cell-steps", out)
    return [int(m.group(1)) * int(m.group(2)) if m else None, float(c.group(1)) if c else None]


def prefetch(runs, ibms, wf, workers=None):
    """Fills the cache for every (scene, sets) of `runs` not in it yet, `workers` at a time."""
    from concurrent.futures import ThreadPoolExecutor
    cache = _load(wf)
    todo = {}
    for scene, sets in runs:
        key = _key(scene, sets) if scene else None
        if key and key not in cache:
            todo[key] = (scene, list(sets))
    if not todo:
        return
    with ThreadPoolExecutor(max_workers=workers or os.cpu_count() or 1) as pool:
        answers = dict(zip(todo, pool.map(lambda a: _ask(a[0], a[1], ibms), todo.values())))
    cache = _load(wf)
    cache.update(answers)
    _store(wf, cache)


def info(scene, sets, ibms, wf):
    """(cells, cell_steps) from `ibms info`, cached; (None, None) when it cannot tell."""
    key = _key(scene, sets)
    if key is None:
        return None, None
    cache = _load(wf)
    if key not in cache:
        cache = _load(wf)
        cache[key] = _ask(scene, sets, ibms)
        _store(wf, cache)
    return tuple(cache[key])


def cached_cost(scene, sets, wf):
    """The cell-steps of `ibms info` when the cache holds them, else None (never runs ibms)."""
    key = _key(scene, sets)
    entry = _load(wf).get(key) if key else None
    return entry[1] if entry else None


def resources(scene, sets, ibms, wf, status_path=None, enabled=True):
    if not enabled or not scene:
        return dict(DEFAULT)
    cells, cost = info(scene, sets, ibms, wf)
    minutes = FLOOR_MINUTES + (MARGIN * cost * SECONDS_PER_CELL_STEP / 60 if cost else 55)
    if status_path and os.path.exists(status_path):
        try:
            with open(status_path) as f:
                minutes = max(minutes, 3 * json.load(f).get("seconds", 0) / 60 + 1)
        except (OSError, ValueError):
            pass
    mem = 300 + (2 * cells / 1000 if cells else 700)
    return {"mem_mb": int(math.ceil(mem)), "runtime": int(math.ceil(minutes)), "cells": cells,
            "cell_steps": cost}
