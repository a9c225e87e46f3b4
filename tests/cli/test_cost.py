#!/usr/bin/env python3
"""Every accepted option costs at most a small multiple of the sequential run (issue 30).

usage: test_cost.py PATH/TO/pear

A 50,000-vertex star (pear generate) is triangulated by every algorithm at the largest accepted
partitions (4096), with and without the CDT, at 2 threads and at the largest accepted thread
count; each run's CPU time and peak memory (the child's rusage) are compared with the plain
sequential run's, measured in the same test. Divide-and-conquer once took 80 s and 4 GB there
(its split lines met twelve million spike edges), and 4,096 worker threads on two cores made
mark-and-cut 20x slower than 16 did.
"""
import os
import subprocess
import sys
import tempfile
import unittest

PEAR = None
ALGORITHMS = ["sequential", "partition-and-cut", "mark-and-cut", "divide-and-conquer"]
# Generous: a parallel variant does more work than the sequential engine (partition-and-cut
# about 2x on this star), and the machine is shared. The unbounded cost was 100x and more.
MAX_TIME_RATIO, SLACK_SECONDS = 8.0, 1.0
MAX_MEMORY_RATIO, SLACK_KB = 6.0, 64 * 1024


def run_measured(args):
    """(CPU seconds, peak resident KB) of one pear run, which must end with exit 0."""
    process = subprocess.Popen([PEAR, *args], stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    process.returncode = os.waitstatus_to_exitcode(status)
    errors = process.stderr.read().decode()
    process.stderr.close()
    if process.returncode != 0:
        raise AssertionError(f"pear {' '.join(args)}: exit {process.returncode}: {errors}")
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss


class LargestPartitions(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory()
        cls.star = os.path.join(cls.dir.name, "star.json")
        with open(cls.star, "w") as f:
            subprocess.run([PEAR, "generate", "star", "50000"], stdout=f, check=True)
        cls.base = {cdt: run_measured(cls.args("sequential", 1, 0, cdt)) for cdt in (False, True)}

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    @classmethod
    def args(cls, algorithm, threads, partitions, cdt):
        args = ["triangulate", cls.star, "--algorithm", algorithm, "--threads", str(threads)]
        if partitions:
            args += ["--partitions", str(partitions)]
        return args + (["--cdt"] if cdt else [])

    def check(self, algorithm, threads, cdt):
        seconds, kb = run_measured(self.args(algorithm, threads, 4096, cdt))
        base_seconds, base_kb = self.base[cdt]
        what = f"{algorithm} --threads {threads} --partitions 4096{' --cdt' if cdt else ''}"
        self.assertLessEqual(seconds, MAX_TIME_RATIO * base_seconds + SLACK_SECONDS,
                             f"{what}: {seconds:.2f} s of CPU against {base_seconds:.2f} s")
        self.assertLessEqual(kb, MAX_MEMORY_RATIO * base_kb + SLACK_KB,
                             f"{what}: {kb} KB at most against {base_kb} KB")

    def test_every_algorithm_at_4096_partitions_on_two_threads(self):
        for algorithm in ALGORITHMS:
            for cdt in (False, True):
                with self.subTest(algorithm=algorithm, cdt=cdt):
                    self.check(algorithm, 2, cdt)

    def test_every_algorithm_at_4096_threads(self):
        for algorithm in ALGORITHMS:
            with self.subTest(algorithm=algorithm):
                self.check(algorithm, 4096, True)


if __name__ == "__main__":
    PEAR = sys.argv.pop(1)
    unittest.main()
