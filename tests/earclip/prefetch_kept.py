#!/usr/bin/env python3
"""Fails when the built library holds no prefetch instruction.

`top`'s clip waits on memory; its prefetch of upcoming candidates (ear_test.hpp's
prefetch_upcoming) is worth 10-20% on the coastlines. From 1411fd1 to a19361b GCC dropped the
call to that function, which holds only prefetches, and nothing noticed for a day.

usage: prefetch_kept.py LIBRARY [OBJDUMP]  (exit 77, skipped, without an x86 objdump)
"""
import shutil
import subprocess
import sys

library = sys.argv[1]
objdump = sys.argv[2] if len(sys.argv) > 2 else shutil.which("objdump")
if not objdump:
    print("no objdump: skipped")
    sys.exit(77)
listing = subprocess.run([objdump, "-d", "--no-show-raw-insn", library], check=True,
                         capture_output=True, text=True).stdout
if "x86-64" not in listing[:2000]:
    print("not an x86-64 library: skipped")
    sys.exit(77)
count = sum(1 for line in listing.splitlines() if "\tprefetch" in line)
print(f"{library}: {count} prefetch instructions")
sys.exit(0 if count > 0 else 1)
