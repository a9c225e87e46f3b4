#!/usr/bin/env python3
"""Builds only what the chosen tests need, for `meson test --no-rebuild` after it.

Usage: scripts/build_tests.py BUILD_DIR [--no-suite SUITE]... [-j JOBS] [-n]

`meson test` first builds every test's program, also those of the suites it then leaves out
(in CI's sanitizer and no-thread builds: the corpus and 'large' suites' sweep and CDT corpus
programs, a minute of compiling under ASan for nothing). This asks meson which targets the
remaining tests depend on and builds those and what is installed (the library, the CLI), with
ninja.
"""
import argparse
import json
import os
import subprocess
import sys


def introspect(build: str, what: str) -> list:
    out = subprocess.run(["meson", "introspect", what, build], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


def suites_of(test: dict) -> set:
    # "pear:cdt" -> "cdt"; a test with no suite of its own is listed as the project, "pear".
    return {suite.split(":", 1)[-1] for suite in test["suite"]}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("--no-suite", action="append", default=[])
    parser.add_argument("-j", "--jobs", default="2")
    parser.add_argument("-n", "--dry-run", action="store_true", help="ninja -n")
    args = parser.parse_args()

    tests = introspect(args.build, "--tests")
    targets = {t["id"]: t for t in introspect(args.build, "--targets")}
    wanted, skipped = set(), set()
    for test in tests:
        (skipped if suites_of(test) & set(args.no_suite) else wanted).update(test["depends"])
    # The remaining tests' targets and what is installed (the library, the CLI, which CI runs in
    # other ways); ninja builds what they need (static libraries, generated headers).
    installed = {t for t, target in targets.items()
                 if target.get("installed", False) and target["build_by_default"]}
    chosen = wanted | installed
    unwanted = skipped - chosen
    files = [f for t in sorted(chosen) for f in targets[t]["filename"]]
    names = sorted({os.path.relpath(f, os.path.realpath(args.build)) for f in files})
    left_out = sorted(targets[t]["name"] for t in unwanted)
    print(f"build_tests: {len(names)} targets, left out: {', '.join(left_out) or 'none'}",
          flush=True)
    return subprocess.run(["ninja", "-C", args.build, f"-j{args.jobs}",
                           *(["-n"] if args.dry_run else []), *names]).returncode


if __name__ == "__main__":
    sys.exit(main())
