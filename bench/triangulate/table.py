#!/usr/bin/env python3
"""Markdown tables from a bench_triangulate JSON file: median CPU time per input and
triangulator with the ratio peer time / pear time (same run), then quality and memory.

    python3 bench/triangulate/table.py docs/results/FILE.json [--reference pear_fast]

For older results files; bench/run.sh and bench/report/ make docs/benchmarks.md.
"""
import argparse
import json
import sys


def load(path):
    with open(path) as f:
        data = json.load(f)
    rows = {}  # input -> triangulator -> median entry or error text
    order = []
    for b in data["benchmarks"]:
        name = b.get("run_name", b["name"]).removesuffix("/real_time")
        parts = name.split("/")
        if len(parts) < 3:
            continue
        tri = parts[-1]
        inp = "/".join(parts[1:-1])
        if inp not in rows:
            rows[inp] = {}
            order.append(inp)
        if b.get("error_occurred"):
            rows[inp][tri] = b.get("error_message", "error")
        elif b.get("run_type") == "aggregate" and b.get("aggregate_name") == "median":
            rows[inp][tri] = b
        elif b.get("run_type") != "aggregate" and tri not in rows[inp]:
            rows[inp][tri] = b  # a run without repetitions
    return data.get("context", {}), order, rows


def ms(entry):
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[entry.get("time_unit", "ns")]
    return entry["cpu_time"] * scale


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("json")
    parser.add_argument("--reference", default="pear_fast", help="the pear variant ratios are against")
    args = parser.parse_args()
    context, order, rows = load(args.json)
    tris = []
    for inp in order:
        for tri in rows[inp]:
            if tri not in tris:
                tris.append(tri)
    peers = [t for t in tris if t != args.reference]

    print(f"Run: {context.get('date', '?')} on {context.get('host_name', '?')}, "
          f"{context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz. "
          f"Medians of CPU time; "
          f"x = peer time / {args.reference} time in the same run (> 1: pear faster).\n")
    head = ["input", "vertices", "holes", f"{args.reference} ms", "ns/vertex"]
    head += [f"{t} ms (x)" for t in peers]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    notes = []
    for inp in order:
        row = rows[inp]
        ref = row.get(args.reference)
        any_entry = next((e for e in row.values() if isinstance(e, dict)), None)
        n = int(any_entry["vertices"]) if any_entry else 0
        h = int(any_entry["holes"]) if any_entry else 0
        cells = [inp, f"{n:,}", f"{h:,}"]
        if isinstance(ref, dict):
            cells += [f"{ms(ref):.3g}", f"{ref['ns_per_vertex']:.0f}"]
        else:
            cells += ["skipped", ""]
            if ref:
                notes.append(f"{inp}/{args.reference}: {ref}")
        for t in peers:
            e = row.get(t)
            if isinstance(e, dict):
                ratio = f" ({ms(e) / ms(ref):.2f}x)" if isinstance(ref, dict) else ""
                cells.append(f"{ms(e):.3g}{ratio}")
            else:
                cells.append("skipped" if e else "")
                if e:
                    notes.append(f"{inp}/{t}: {e}")
        print("| " + " | ".join(cells) + " |")
    if notes:
        print("\nSkipped:\n")
        for note in notes:
            print(f"- {note}")

    print("\nQuality (average smallest angle / average |angle - 60|, degrees) and peak heap "
          "bytes per vertex of one run; `invalid` marks output that pear::validate rejects.\n")
    head = ["input"] + tris
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for inp in order:
        cells = [inp]
        for t in tris:
            e = rows[inp].get(t)
            if isinstance(e, dict):
                flag = "" if e.get("valid", 1) >= 1 else " invalid"
                cells.append(f"{e['min_angle_avg_deg']:.1f} / {e['dev60_avg_deg']:.1f}, "
                             f"{e['peak_bytes_per_vertex']:.0f} B{flag}")
            else:
                cells.append("")
        print("| " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
