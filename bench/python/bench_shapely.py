#!/usr/bin/env python3
"""pear.triangulate_many over shapely polygons: through WKB, through their GEOS handles (shapely
1.8) or to_ragged_array (shapely 2), against ragged arrays and the per-polygon loop over numpy
arrays, in one process.

usage: /usr/bin/python3 bench/python/bench_shapely.py [--build BUILD] [--rounds N]
           [--folder counties]

Imports pear from BUILD/python (default build/). The folder's polygons are loaded once as
numpy arrays (coordinates without closing points, ring ends), as ragged arrays and as shapely
geometries. Rounds interleave the candidates, each timed run after an untimed one
(bench_python.measure); the table gives medians over the rounds and each one's speed
against the per-polygon loop; then the loop against the shapely batch with calls back to
back (bench_python.steady_scaling). Page faults: the median of the timed calls' minor faults
(fresh pages that glibc gave back after the call before). `uptime` is printed before and after.
CI does not run this.
"""
import argparse
import os
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from bench_python import ROOT, load, measure, ragged, steady_scaling  # noqa: E402


def shapely_polygons(polygons):
    from shapely.geometry import Polygon
    return [Polygon(c[:e[0]], [c[a:b] for a, b in zip(e[:-1], e[1:])]) for c, e in polygons]


def candidates(pear, polygons):
    """name -> function running one pass over the polygons."""
    coords, rings, first_ring = ragged(polygons)
    shapes = shapely_polygons(polygons)
    triangulate = pear.triangulate

    def loop():
        for c, e in polygons:
            triangulate(c, e, strict=False)

    def shapely_batch(threads, way):
        def run():
            pear._many._read_geos_handles = way == "GEOS"
            pear._many._read_ragged_arrays = way == "to_ragged_array"
            try:
                pear.triangulate_many(shapes, threads=threads)
            finally:
                pear._many._read_geos_handles = pear._many._read_ragged_arrays = True
        return run

    def ragged_batch(threads):
        return lambda: pear.triangulate_many(coords, rings, first_ring, threads=threads)

    way = reading_way(pear)
    return {"per-polygon loop (numpy arrays)": loop,
            "triangulate_many(shapely), WKB, 1 thread": shapely_batch(1, "WKB"),
            f"triangulate_many(shapely), {way}, 1 thread": shapely_batch(1, way),
            f"triangulate_many(shapely), {way}, 2 threads": shapely_batch(2, way),
            "triangulate_many(ragged), 1 thread": ragged_batch(1),
            "triangulate_many(ragged), 2 threads": ragged_batch(2)}


def reading_way(pear):
    """How triangulate_many reads shapely geometries here: shapely 1.8's GEOS handles, shapely
    2's to_ragged_array, or WKB (a module without the GEOS reader under shapely 1.8)."""
    import shapely
    if hasattr(shapely, "to_ragged_array"):
        return "to_ragged_array"
    return "GEOS" if pear._many._reads_geos_handles() else "WKB"


def uptime():
    return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--rounds", type=int, default=11)
    parser.add_argument("--folder", default="counties")
    args = parser.parse_args()
    sys.path.insert(0, os.path.join(args.build, "python"))
    import pear
    import shapely
    print(f"pear from {os.path.dirname(pear.__file__)}; shapely {shapely.__version__} read "
          f"through {reading_way(pear)}; {os.cpu_count()} CPUs")
    print(f"uptime before: {uptime()}")
    polygons = load(args.folder)
    runs = candidates(pear, polygons)
    reference = "per-polygon loop (numpy arrays)"
    faults = {}
    medians, cpu, ratios = measure(runs, args.rounds, reference, faults=faults)
    vertices = sum(len(c) for c, _ in polygons)
    print(f"\n{args.folder}: {len(polygons)} polygons, {vertices} vertices, median of "
          f"{args.rounds} rounds\n")
    print("| candidate | ms per pass | us per polygon | loop time / its time (median of rounds) "
          "| CPU ms | page faults a call |")
    print("|---|---|---|---|---|---|")
    for name, seconds in medians.items():
        print(f"| {name} | {seconds * 1e3:.2f} | {seconds / len(polygons) * 1e6:.2f} "
              f"| {ratios[name]:.2f}x | {cpu[name] * 1e3:.2f} | {faults[name]:.0f} |")
    way = reading_way(pear)
    wkb = medians["triangulate_many(shapely), WKB, 1 thread"]
    one = medians[f"triangulate_many(shapely), {way}, 1 thread"]
    print(f"\n{way} against WKB (1 thread): {wkb / one:.2f}x; {way} 2 threads against 1: "
          f"{one / medians[f'triangulate_many(shapely), {way}, 2 threads']:.2f}x")
    # Calls back to back, as a long job makes them: the rounds above start each candidate on a
    # core that idled through the one before (bench_python.measure says what that costs).
    for threads in (1, 2):
        name = f"triangulate_many(shapely), {way}, {threads} thread{'s' * (threads > 1)}"
        print(f"steady state, per-polygon loop / {name}: "
              f"{steady_scaling(runs[reference], runs[name]):.2f}x")
    print(f"uptime after: {uptime()}")


if __name__ == "__main__":
    main()
