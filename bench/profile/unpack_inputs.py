#!/usr/bin/env python3
"""Decompresses every FOLDER/*.json.xz into FOLDER/*.json.gz (gzip level 1, which pear's readers
take), unless that file is there already. bench/threads.sh --pack ships the coasts as xz to keep
the folder small enough to travel (Eurasia 14.2 MB gzip, 8.6 MB xz).

    python3 unpack_inputs.py FOLDER
"""
import glob
import gzip
import lzma
import os
import shutil
import sys

for path in glob.glob(os.path.join(sys.argv[1], "*.json.xz")):
    target = path[: -len(".xz")] + ".gz"
    if not os.path.exists(target):
        with lzma.open(path) as src, gzip.open(target, "wb", compresslevel=1) as dst:
            shutil.copyfileobj(src, dst, 1 << 20)
