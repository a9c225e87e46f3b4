#!/usr/bin/env python3
"""Median wall-clock times of bench_cdt's JSON output, and CGAL's time divided by each (> 1:
faster than CGAL), one row per input."""
import json
import sys

ENTRIES = ["pear_ear_t1", "pear_cdt_t1", "pear_cdt_fast_t1", "pear_cdt_t2", "pear_cdt_fast_t2",
           "cgal_cdt", "geos_cdt"]
RATIOS = ["pear_cdt_t1", "pear_cdt_fast_t1", "pear_cdt_t2", "pear_cdt_fast_t2"]


def medians(path):
    times, counters = {}, {}
    for run in json.load(open(path))["benchmarks"]:
        if run.get("aggregate_name", "median") != "median" or run.get("error_occurred"):
            continue
        _, folder, name, entry = run["run_name"].split("/")[:4]
        key = folder + "/" + name
        times.setdefault(key, {})[entry] = run["real_time"]
        counters[(key, entry)] = run
    return times, counters


def main():
    times, counters = medians(sys.argv[1])
    print("| input | " + " | ".join(e + " ms" for e in ENTRIES) +
          " | " + " | ".join("CGAL / " + e for e in RATIOS) +
          " | flips per edge t1 | t2 (in sets + borders) |")
    print("|---" * (len(ENTRIES) + len(RATIOS) + 3) + "|")
    for key, row in times.items():
        cells = ["%.1f" % row[e] if e in row else "-" for e in ENTRIES]
        cgal = row.get("cgal_cdt")
        ratios = ["%.2fx" % (cgal / row[e]) if cgal and e in row else "-"
                  for e in RATIOS]
        one = counters.get((key, "pear_cdt_t1"), {})
        two = counters.get((key, "pear_cdt_t2"), {})
        flips_one = "%.3f" % one.get("flips_per_edge", 0) if one else "-"
        flips_two = "%.3f (%.3f + %.3f)" % (
            two.get("flips_per_edge", 0), two.get("in_partitions_per_edge", 0),
            two.get("on_borders_per_edge", 0)) if two else "-"
        print("| " + " | ".join([key] + cells + ratios + [flips_one, flips_two]) + " |")


if __name__ == "__main__":
    main()
