#!/usr/bin/env python3
"""Median wall-clock times of bench_cdt's JSON output, and CGAL's time divided by each (> 1:
faster than CGAL), one row per input."""
import json
import sys

ENTRIES = ["pear_ear_t1", "pear_cdt_t1", "pear_cdt_t2", "cgal_cdt", "geos_cdt"]


def medians(path):
    times, counters = {}, {}
    for run in json.load(open(path))["benchmarks"]:
        if run.get("aggregate_name", "median") != "median" or run.get("error_occurred"):
            continue
        _, folder, name, entry = run["run_name"].split("/")[:4]
        key = folder + "/" + name
        times.setdefault(key, {})[entry] = run["real_time"]
        if entry == "pear_cdt_t2":
            counters[key] = run
    return times, counters


def main():
    times, counters = medians(sys.argv[1])
    print("| input | " + " | ".join(e + " ms" for e in ENTRIES) +
          " | CGAL / pear_cdt_t1 | CGAL / pear_cdt_t2 | flips per edge (in sets + borders, t2) |")
    print("|---" * (len(ENTRIES) + 4) + "|")
    for key, row in times.items():
        cells = ["%.1f" % row[e] if e in row else "-" for e in ENTRIES]
        cgal = row.get("cgal_cdt")
        ratios = ["%.2fx" % (cgal / row[e]) if cgal and e in row else "-"
                  for e in ("pear_cdt_t1", "pear_cdt_t2")]
        c = counters.get(key, {})
        flips = "%.3f (%.3f + %.3f)" % (c.get("flips_per_edge", 0), c.get("in_partitions_per_edge", 0),
                                        c.get("on_borders_per_edge", 0)) if c else "-"
        print("| " + " | ".join([key] + cells + ratios + [flips]) + " |")


if __name__ == "__main__":
    main()
