#!/usr/bin/env python3
"""Instructions per vertex in each stage of pear's pipeline, counted by callgrind (issue 26).

    bench/profile/stages.py PEAR_CALLS FOLDER... [--modes top fast fastnocheck]

PEAR_CALLS is bench/profile/pear_calls from a build with debug information (buildtype
debugoptimized or release with -g, so that callgrind names the stages' functions). Each FOLDER
(e.g. ../shared/corpus/counties) is triangulated once per polygon in each mode; the table gives
each stage's inclusive instructions divided by the folder's vertices. Instruction counts do not
depend on the machine's load, which makes them the A/B measure on a shared machine; times
still come from the benchmarks (bench/small).
"""
import argparse
import os
import re
import subprocess
import tempfile

# Each stage: the function whose inclusive cost it is (the first line of callgrind_annotate's
# inclusive listing that matches).
STAGES = [
    ("total", r"\brun_calls\("),
    ("clean", r"\bclean_polygon\("),
    ("check", r"SimplicityCheck::check\("),
    ("t-junct", r"Engine::split_t_junctions\("),
    ("bridge", r"Engine::bridge\("),
    ("clip", r"Engine::clip\("),
    ("report", r"Engine::report\("),
]


def count(binary, folder, mode, work):
    out = os.path.join(work, f"callgrind.{os.path.basename(folder.rstrip('/'))}.{mode}")
    run = subprocess.run(["valgrind", "--tool=callgrind", "--toggle-collect=run_calls*",
                          f"--callgrind-out-file={out}", binary, folder, mode],
                         capture_output=True, text=True, check=True)
    vertices = int(re.search(r"vertices (\d+)", run.stdout).group(1))
    polygons = int(re.search(r"polygons (\d+)", run.stdout).group(1))
    listing = subprocess.run(["callgrind_annotate", "--inclusive=yes", out],
                             capture_output=True, text=True, check=True).stdout
    costs = {}
    for name, pattern in STAGES:
        costs[name] = max((int(line.split()[0].replace(",", "")) for line in listing.splitlines()
                           if re.search(pattern, line) and line.strip()[:1].isdigit()),
                          default=0)
    return polygons, vertices, costs


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("binary")
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--modes", nargs="+", default=["top", "fast", "fastnocheck"])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        for folder in args.folders:
            rows = [(mode, *count(args.binary, folder, mode, work)) for mode in args.modes]
            polygons, vertices = rows[0][1], rows[0][2]
            print(f"\n{folder}: {polygons} polygons, {vertices} vertices "
                  f"({vertices / polygons:.0f} a polygon); instructions per vertex")
            print("mode".ljust(12) + "".join(name.rjust(9) for name, _ in STAGES))
            for mode, _, _, costs in rows:
                print(mode.ljust(12) + "".join(
                    f"{costs[name] / vertices:9.0f}" if costs[name] else "-".rjust(9)
                    for name, _ in STAGES))


if __name__ == "__main__":
    main()
