#!/usr/bin/env python3
"""Describes the machine a benchmark run used, as JSON (stdout), or adds the run's end to such a
file (--finish FILE). The load average is recorded at both ends: on a shared machine it says how
much the absolute times can be trusted (ratios from the same run much more)."""
import datetime
import json
import os
import platform
import subprocess
import sys


def first_line(command):
    try:
        return subprocess.run(command, capture_output=True, text=True).stdout.splitlines()[0]
    except (OSError, IndexError):
        return "?"


def cpu_model():
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    return platform.processor() or "?"


def memory_gib():
    with open("/proc/meminfo") as f:
        kib = int(f.readline().split()[1])
    return round(kib / 2**20, 1)


def os_name():
    try:
        with open("/etc/os-release") as f:
            for line in f:
                if line.startswith("PRETTY_NAME="):
                    return line.split("=", 1)[1].strip().strip('"')
    except OSError:
        pass
    return platform.system()


def now():
    return datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--finish":
        with open(sys.argv[2]) as f:
            machine = json.load(f)
        machine["finished"] = now()
        machine["load_average_end"] = os.getloadavg()
        with open(sys.argv[2], "w") as f:
            json.dump(machine, f, indent=1)
        return 0
    mode, commit = sys.argv[1], sys.argv[2]
    machine = {
        "mode": mode,
        "commit": commit,
        "started": now(),
        "cpu": cpu_model(),
        "cpus": os.cpu_count(),
        "memory_gib": memory_gib(),
        "os": os_name(),
        "kernel": platform.release(),
        "compiler": first_line(["c++", "--version"]),
        "load_average_start": os.getloadavg(),
    }
    json.dump(machine, sys.stdout, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
