#!/usr/bin/env python3
"""bench_cdt's JSON output as Markdown: median times per input and entry, CGAL's median divided
by pear's (> 1: pear is faster), and the flip counts. Single-threaded entries are compared by CPU
time (steadier on a shared machine), the 2-thread ones by wall-clock time against CGAL's."""
import json
import sys

ENTRIES = ["pear_ear_t1", "pear_cdt_t1", "pear_cdt_fast_t1", "pear_cdt_t2", "pear_cdt_fast_t2",
           "cgal_cdt", "geos_cdt"]
ONE_THREAD = ["pear_cdt_t1", "pear_cdt_fast_t1"]
TWO_THREADS = ["pear_cdt_t2", "pear_cdt_fast_t2"]


def medians(path):
    rows = {}
    for run in json.load(open(path))["benchmarks"]:
        if run.get("aggregate_name") != "median" or run.get("error_occurred"):
            continue
        _, folder, name, entry = run["run_name"].split("/")[:4]
        rows.setdefault(folder + "/" + name, {})[entry] = run
    return rows


def ratio(row, entry, clock):
    if "cgal_cdt" not in row or entry not in row:
        return "-"
    return "%.2fx" % (row["cgal_cdt"][clock] / row[entry][clock])


def flips(run):
    if run is None:
        return "-"
    return "%.3f (%.3f + %.3f)" % (run.get("flips_per_edge", 0),
                                   run.get("in_partitions_per_edge", 0),
                                   run.get("on_borders_per_edge", 0))


def main():
    rows = medians(sys.argv[1])
    print("Median CPU ms (wall-clock ms):\n")
    print("| input | " + " | ".join(ENTRIES) + " |")
    print("|---" * (len(ENTRIES) + 1) + "|")
    for key, row in rows.items():
        cells = ["%.0f (%.0f)" % (row[e]["cpu_time"], row[e]["real_time"]) if e in row else "-"
                 for e in ENTRIES]
        print("| " + " | ".join([key] + cells) + " |")
    print("\nCGAL's median over pear's (CPU time at 1 thread, wall-clock at 2), flips per edge "
          "(in sets + on borders):\n")
    print("| input | " + " | ".join(ONE_THREAD + TWO_THREADS) +
          " | flips pear_cdt_t1 | flips pear_cdt_t2 |")
    print("|---" * (len(ONE_THREAD) + len(TWO_THREADS) + 3) + "|")
    for key, row in rows.items():
        cells = [ratio(row, e, "cpu_time") for e in ONE_THREAD]
        cells += [ratio(row, e, "real_time") for e in TWO_THREADS]
        cells += [flips(row.get("pear_cdt_t1")), flips(row.get("pear_cdt_t2"))]
        print("| " + " | ".join([key] + cells) + " |")


if __name__ == "__main__":
    main()
