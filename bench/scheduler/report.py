#!/usr/bin/env python3
"""Turns a scheduler_bench JSON run (with --benchmark_repetitions) into the Markdown table of
docs/scheduler.md: the median of each runner and the ratios measured in that same run."""
import json
import sys

UNITS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def medians(path):
    with open(path) as f:
        run = json.load(f)
    out = {}
    for b in run["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        name = b["run_name"].removesuffix("/real_time")
        workload, runner = name.split("/")[:2]
        out.setdefault(workload, {})[runner] = b["real_time"] * UNITS[b["time_unit"]]
    return run["context"], out


def fmt(seconds):
    return f"{seconds * 1e3:.3f} ms" if seconds < 1 else f"{seconds:.2f} s"


def ratio(a, b):
    return f"{a / b:.2f}" if a and b else "n/a"


def main():
    context, table = medians(sys.argv[1])
    print(f"Machine: {context.get('host_name', '?')}, {context['num_cpus']} CPUs at "
          f"{context['mhz_per_cpu']} MHz; load average at start "
          f"{', '.join(f'{x:.2f}' for x in context.get('load_avg', []))}.\n")
    print("| workload | serial | pear 2 thr | TBB 2 thr | pear 1 thr | TBB 1 thr "
          "| pear/TBB (2 thr) | speedup pear 2 thr | pear 1 thr / serial |")
    print("|---|---|---|---|---|---|---|---|---|")
    for workload, r in table.items():
        get = r.get
        cells = [fmt(get(k)) if get(k) else "-" for k in ("serial", "pear2", "tbb2", "pear1", "tbb1")]
        print(f"| {workload} | " + " | ".join(cells) +
              f" | {ratio(get('pear2'), get('tbb2'))} | {ratio(get('serial'), get('pear2'))}"
              f" | {ratio(get('pear1'), get('serial'))} |")


if __name__ == "__main__":
    main()
