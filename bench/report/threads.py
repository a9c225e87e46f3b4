#!/usr/bin/env python3
"""Tables of one bench/threads.sh run (docs/results/DATE-threads.json and its -machine.json):
pear's default (`automatic`) and each parallel variant at 1 to 16 threads over the sequential
engine, the CDT over the sequential CDT and over CGAL's, and at the largest thread count the
phases whose elapsed time is furthest above their share of the work. Every ratio compares medians
of interleaved rounds of the same run; below 300,000 vertices `auto_t1` runs what `top` runs, so
their ratio is the run's noise (from 300,000 on `automatic` clips one thread's polygon in
divide-and-conquer's parts, which is faster on a large polygon than the sequential engine)."""
import glob
import json
import os
import sys


def load(path):
    with open(path) as f:
        records = json.load(f)
    machine = {}
    machine_path = path[: -len(".json")] + "-machine.json"
    if os.path.exists(machine_path):
        with open(machine_path) as f:
            machine = json.load(f)
    return records, machine


def latest(results_dir):
    """The newest bench/threads.sh run in results_dir, or None."""
    runs = sorted(glob.glob(os.path.join(results_dir, "*-threads.json")))
    return load(runs[-1]) + (runs[-1],) if runs else None


def timings(records):
    """{input: {config: median ms}}, inputs in run order, and their vertex counts."""
    times, vertices = {}, {}
    for r in records:
        if "median_ms" in r and r.get("triangles", 0) > 0:
            times.setdefault(r["input"], {})[r["config"]] = r["median_ms"]
            vertices[r["input"]] = r["vertices"]
    return times, vertices


def thread_counts(times):
    counts = set()
    for configs in times.values():
        for c in configs:
            if c.startswith("auto_t") and not c.endswith("_cdt"):
                counts.add(int(c[len("auto_t"):]))
    return sorted(counts)


def ratio(base, t):
    return f"{base / t:.2f}x" if base and t else "-"


def bold(text, threshold=1.0):
    try:
        return f"**{text}**" if float(text.rstrip("x")) >= threshold else text
    except ValueError:
        return text


def default_table(times, vertices, counts):
    head = "| input | vertices | sequential `top` (ms) | " + " | ".join(
        f"`automatic`, {t} thread{'s' if t > 1 else ''}" for t in counts) + " | fastest variant, " \
        f"{counts[-1]} threads |"
    rows = [head, "|---|---:|---:|" + "---:|" * (len(counts) + 1)]
    for inp, c in times.items():
        top = c.get("top")
        cells = [bold(ratio(top, c.get(f"auto_t{t}"))) for t in counts]
        best = max(("pc", "mc", "dc"), key=lambda v: top / c.get(f"{v}_t{counts[-1]}", 1e300))
        cells.append(f"{best} {ratio(top, c.get(f'{best}_t{counts[-1]}'))}")
        rows.append(f"| {inp} | {vertices[inp]:,} | {top:.1f} | " + " | ".join(cells) + " |")
    return "\n".join(rows) + "\n"


def variant_table(times, counts):
    variants = ("pc", "mc", "dc")
    head = "| input | " + " | ".join(f"{v} t{t}" for v in variants for t in counts) + " |"
    rows = [head, "|---|" + "---:|" * (len(variants) * len(counts))]
    for inp, c in times.items():
        top = c.get("top")
        rows.append(f"| {inp} | " + " | ".join(
            ratio(top, c.get(f"{v}_t{t}")) for v in variants for t in counts) + " |")
    return "\n".join(rows) + "\n"


def cdt_table(times, counts):
    parallel = [t for t in counts if t > 1]
    head = ("| input | sequential CDT (ms) | CGAL CDT (ms) | " +
            " | ".join(f"{t} threads" for t in parallel) +
            " | sequential over CGAL | " + " | ".join(f"{t} threads over CGAL" for t in parallel) +
            " |")
    rows = [head, "|---|---:|---:|" + "---:|" * (2 * len(parallel) + 1)]
    for inp, c in times.items():
        cdt, cgal = c.get("cdt"), c.get("cgal_cdt")
        cells = [bold(ratio(cdt, c.get(f"auto_t{t}_cdt"))) for t in parallel]
        cells.append(bold(ratio(cgal, cdt)))
        cells += [bold(ratio(cgal, c.get(f"auto_t{t}_cdt"))) for t in parallel]
        cgal_text = f"{cgal:.1f}" if cgal else "-"
        rows.append(f"| {inp} | {cdt:.1f} | {cgal_text} | " + " | ".join(cells) + " |")
    return "\n".join(rows) + "\n"


def phases_table(records, most=5):
    """Per profiled run: its elapsed time against the projection, and the phases that lose most
    time against their work / threads (elapsed minus max(work / threads, longest task))."""
    rows = ["| input | configuration | elapsed (ms) | projected (ms) | phases losing most: "
            "elapsed / (work / threads) / longest task, ms |", "|---|---|---:|---:|---|"]
    for r in records:
        if "phases" not in r:
            continue
        t = r["threads"]
        merged = {}
        for p in r["phases"]:
            m = merged.setdefault(p["name"], [0.0, 0.0, 0.0])
            m[0] += p["wall_ms"]
            m[1] += p["work_ms"]
            m[2] += p["longest_ms"]
        losing = sorted(merged.items(), key=lambda kv: -(kv[1][0] - max(kv[1][1] / t, kv[1][2])))
        text = "; ".join(f"{name} {w:.1f} / {work / t:.1f} / {longest:.1f}"
                         for name, (w, work, longest) in losing[:most])
        rows.append(f"| {r['input']} | {r['config']} | {r['wall_ms']:.1f} | "
                    f"{r['projected_ms']:.1f} | {text} |")
    return "\n".join(rows) + "\n"


ONE_THREAD_PARTS_FROM = 300_000  # src/pipeline/engine.cpp, most_parts_from


def noise(times, vertices):
    """top over auto_t1 where both run the sequential engine."""
    values = [c["top"] / c["auto_t1"] for inp, c in times.items()
              if c.get("top") and c.get("auto_t1") and vertices[inp] < ONE_THREAD_PARTS_FROM]
    return (min(values), max(values)) if values else None


def machine_text(machine, records):
    cpus = machine.get("cpus", "?")
    header = next((r for r in records if "hardware_threads" in r), {})
    load = [machine.get(k, ["?"])[0] for k in ("load_average_start", "load_average_end")]
    load = [f"{x:.1f}" if isinstance(x, (int, float)) else x for x in load]
    built = machine.get("built_with", "")
    return (f"{cpus} hardware threads ({machine.get('cpu', '?')}), {machine.get('memory_gib', '?')} "
            f"GiB, {machine.get('os', '?')}, kernel {machine.get('kernel', '?')}; pear at "
            f"{machine.get('commit', '?')}" + (f" built with {built}" if built else "") +
            f", {machine.get('started', '?')} to {machine.get('finished', '?')}, load average "
            f"{load[0]} at the start and {load[1]} at the end (the run's own threads); medians of "
            f"{header.get('rounds', '?')} interleaved rounds (Eurasia: 3).")


def document(records, machine):
    times, vertices = timings(records)
    counts = thread_counts(times)
    gauge = noise(times, vertices)
    gauge_text = (f" The run's noise: `top` over `auto_t1` (the same computation below 300,000 "
                  f"vertices) is {gauge[0]:.2f}-{gauge[1]:.2f}x across those inputs; from "
                  f"300,000 on `automatic` on one thread clips in divide-and-conquer's parts, "
                  f"so its column there is not noise." if gauge else "")
    return "\n".join([
        machine_text(machine, records) + gauge_text + "\n",
        "`automatic` (pear's default algorithm) over the sequential engine (`top`), wall time; "
        "**bold**: faster than sequential.\n",
        default_table(times, vertices, counts),
        "Each variant over the sequential engine (pc partition-and-cut, mc mark-and-cut, dc "
        "divide-and-conquer; N threads, N partitions):\n",
        variant_table(times, counts),
        "The CDT: `automatic` with `delaunay` over the sequential CDT, and CGAL 5.5's CDT "
        "(exact predicates, with its nesting-level flood fill) over pear's:\n",
        cdt_table(times, counts),
        f"Phases at {counts[-1]} threads, the fastest of three profiled runs "
        "(`RunProfile::Phase::wall_seconds` against Brent's max(work / threads, longest task)); "
        "repeated phases (rounds) summed:\n",
        phases_table(records),
    ])


def main():
    if len(sys.argv) != 2:
        print("usage: threads.py docs/results/DATE-threads.json", file=sys.stderr)
        return 2
    records, machine = load(sys.argv[1])
    print(document(records, machine))
    return 0


if __name__ == "__main__":
    sys.exit(main())
