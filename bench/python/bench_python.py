#!/usr/bin/env python3
"""pear's Python package against mapbox_earcut, per polygon and batched, in one process.

usage: /usr/bin/python3 bench/python/bench_python.py [--build BUILD] [--rounds N]
           [--folders counties,countries,glyphs,coast] [--coast FILE]

Imports pear from BUILD/python (default build/; or an installed pear when that has none).
Every folder's polygons are loaded once as numpy arrays (coordinates without closing points,
mapbox_earcut's ring ends), as ragged arrays, as shapely polygons and as WKB. Each round runs
every candidate once over the folder (after an untimed warm-up run of it, see measure), the
candidates interleaved so that a busy machine slows them alike; the table gives each one's
median wall-clock time per polygon, polygons per second, the median over rounds of
mapbox_earcut's time over its time in the same round, and its median CPU time (all threads)
per polygon. The load average before and after is printed (docs/benchmarks.md quotes it).
shapely 1.8 (Debian 12) has no polygon triangulation (shapely 2's
constrained_delaunay_triangles needs GEOS 3.10 and shapely 2), so shapely appears as an input
format only. CI does not run this.
"""
import argparse
import json
import os
import pathlib
import resource
import statistics
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "support"))
import corpus  # noqa: E402 (tests/support)


def load(name, only=None):
    """The polygons of a corpus folder as (coords, ring ends) pairs, without closing points."""
    import gzip
    polygons = []
    for row in corpus.read_folder(corpus.shared_root(), name):
        if only and row.file != only:
            continue
        opener = gzip.open if row.file.endswith(".gz") else open
        with opener(row.path, "rt") as f:
            document = json.load(f)
        parts = document["coordinates"] if document["type"] == "MultiPolygon" else \
            [document["coordinates"]]
        for rings in parts:
            rings = [r[:-1] if len(r) > 1 and r[0] == r[-1] else r for r in rings]
            coords = np.array([p[:2] for r in rings for p in r], dtype=np.float64)
            ends = np.cumsum([len(r) for r in rings]).astype(np.uint32)
            if len(coords) >= 3:
                polygons.append((coords, ends))
    return polygons


def ragged(polygons):
    coords = np.vstack([c for c, _ in polygons])
    starts = np.cumsum([0] + [len(c) for c, _ in polygons])
    rings = np.concatenate([[0]] + [e.astype(np.int64) + s for (_, e), s in zip(polygons, starts)])
    first_ring = np.cumsum([0] + [len(e) for _, e in polygons])
    return coords, rings, first_ring


def candidates(pear, polygons, large):
    """name -> function running one round over the polygons."""
    import mapbox_earcut
    from shapely.geometry import Polygon
    earcut = mapbox_earcut.triangulate_float64
    triangulate = pear.triangulate
    coords, rings, first_ring = ragged(polygons)
    shapes = [Polygon(c[:e[0]], [c[a:b] for a, b in zip(e[:-1], e[1:])]) for c, e in polygons]
    wkb = [s.wkb for s in shapes]

    def loop(**options):
        def run():
            for c, e in polygons:
                triangulate(c, e, strict=False, **options)
        return run

    def many(data, *offsets, **options):
        return lambda: pear.triangulate_many(data, *offsets, **options)

    def earcut_loop():
        for c, e in polygons:
            earcut(c, e)

    runs = {"mapbox_earcut, per polygon": earcut_loop,
            "pear, per polygon": loop()}
    if large:  # one big polygon: the parallel algorithms on 2 threads
        runs["pear fast, per polygon"] = loop(heuristic="fast")
        runs["pear partition_and_cut, 2 threads"] = loop(algorithm="partition_and_cut",
                                                         threads=2)
        runs["pear mark_and_cut, 2 threads"] = loop(algorithm="mark_and_cut", threads=2)
        return runs
    runs["pear fast, per polygon"] = loop(heuristic="fast")
    runs["pear no simplicity check, per polygon"] = loop(check_simplicity=False)

    def shapely_loop():
        for s in shapes:
            try:
                triangulate(s)
            except pear.PearError:
                pass
    runs["pear, per shapely polygon"] = shapely_loop
    runs["pear batch (ragged), 1 thread"] = many(coords, rings, first_ring, threads=1)
    runs["pear batch (ragged), 2 threads"] = many(coords, rings, first_ring, threads=2)
    runs["pear batch (WKB), 1 thread"] = many(wkb, threads=1)
    runs["pear batch (shapely), 1 thread"] = many(shapes, threads=1)
    return runs


def measure(runs, rounds, reference, warm_up=True, faults=None):
    """Median wall-clock and CPU seconds per candidate, and the median of per-round wall-clock
    ratios to the reference. On a busy machine the CPU time of a one-thread candidate is the
    steadier figure (it does not count the time other processes hold the core). With warm_up
    (calls of milliseconds), each timed run follows an untimed one of the same candidate: a
    core that sat idle through the previous candidate runs the next few milliseconds slower
    (on the 2-core VM a 2-thread batch of the counties measured 1.6x one thread right after a
    one-thread candidate, 1.8-2x warm; the C++ batch alike), which would charge a 2-thread
    candidate for its neighbour's idle core."""
    wall = {name: [] for name in runs}
    cpu = {name: [] for name in runs}
    minor_faults = {name: [] for name in runs}
    for _ in range(rounds):
        for name, run in runs.items():
            if warm_up:
                run()
            start_faults = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
            start, start_cpu = time.perf_counter(), time.process_time()
            run()
            wall[name].append(time.perf_counter() - start)
            cpu[name].append(time.process_time() - start_cpu)
            minor_faults[name].append(resource.getrusage(resource.RUSAGE_SELF).ru_minflt -
                                      start_faults)
    if faults is not None:  # the median minor page faults of a timed call, by candidate
        faults.update({name: statistics.median(f) for name, f in minor_faults.items()})
    ratios = {name: statistics.median(r / t for r, t in zip(wall[reference], wall[name]))
              for name in runs}
    return ({name: statistics.median(t) for name, t in wall.items()},
            {name: statistics.median(t) for name, t in cpu.items()}, ratios)


def steady_scaling(one, two, blocks=5, calls=21):
    """The 2-thread batch against the 1-thread one in steady state: `calls` timed calls of one
    back to back (after 2 untimed), then of the other; the median over `blocks` such pairs of
    the ratio of their median call times. What a long batch (or a Dask worker going through its
    partitions) sees, where the interleaved rounds above start each call on a core that idled."""
    def median_call(run):
        times = []
        for i in range(calls + 2):
            start = time.perf_counter()
            run()
            if i >= 2:
                times.append(time.perf_counter() - start)
        return statistics.median(times)
    return statistics.median(median_call(one) / median_call(two) for _ in range(blocks))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--rounds", type=int, default=21)
    parser.add_argument("--folders", default="counties,countries,glyphs,coast")
    parser.add_argument("--coast", default="australia_gshhg_full.json.gz")
    args = parser.parse_args()
    sys.path.insert(0, os.path.join(args.build, "python"))
    import pear
    print(f"pear from {os.path.dirname(pear.__file__)}; load average before: "
          f"{' '.join(f'{x:.2f}' for x in os.getloadavg())}; {os.cpu_count()} CPUs")
    for name in args.folders.split(","):
        polygons = load(name, args.coast if name == "coast" else None)
        large = name == "coast"
        runs = candidates(pear, polygons, large)
        rounds = max(3, args.rounds // 4) if large else args.rounds
        medians, cpu, ratios = measure(runs, rounds, "mapbox_earcut, per polygon",
                                       warm_up=not large)
        vertices = sum(len(c) for c, _ in polygons)
        print(f"\n{name}: {len(polygons)} polygons, {vertices} vertices "
              f"({vertices / len(polygons):.0f} per polygon), median of {rounds} rounds\n")
        print("| candidate | us per polygon | polygons/s | earcut time / its time "
              "| CPU us per polygon |")
        print("|---|---|---|---|---|")
        loop = medians["pear, per polygon"]
        for candidate, seconds in medians.items():
            per = seconds / len(polygons)
            print(f"| {candidate} | {per * 1e6:.2f} | {1 / per:,.0f} | {ratios[candidate]:.2f}x "
                  f"| {cpu[candidate] / len(polygons) * 1e6:.2f} |")
        if not large:
            one = medians["pear batch (ragged), 1 thread"]
            two = medians["pear batch (ragged), 2 threads"]
            steady = steady_scaling(runs["pear batch (ragged), 1 thread"],
                                    runs["pear batch (ragged), 2 threads"])
            print(f"\nbatch (1 thread) against the per-polygon loop: {loop / one:.2f}x; "
                  f"2 threads against 1: {one / two:.2f}x in the rounds, {steady:.2f}x with "
                  "calls back to back (median of 5 blocks of 21)")
    print(f"\nload average after: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
