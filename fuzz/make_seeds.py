#!/usr/bin/env python3
"""Writes the seed inputs of corpus/fuzz/<target>/ in each target's byte layout.

Usage: fuzz/make_seeds.py PEAR_CLI   (run from the repository root; PEAR_CLI is a built `pear`
tool, used for the synthetic families of `pear generate`). Sources: corpus/earcut (mapbox/earcut's
fixtures; see corpus/fuzz/MANIFEST.tsv), hand-made degenerate shapes and cell sets, the synthetic
families. Files found by fuzzing (crash-*, regression-*) are not touched.
The layouts are documented in fuzz/ring_bytes.hpp, fuzz/cell_polygon.hpp and the targets.
"""
import json
import pathlib
import random
import struct
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
OUT = ROOT / "corpus" / "fuzz"
manifest = []

SMALL_GRID, ANY_DOUBLE, SCALED_GRID = 0, 2, 3
T_JUNCTION_MOVES = 32


def write(target, name, data, source):
    path = OUT / target / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(bytes(data))
    manifest.append((f"{target}/{name}", source))


def ring_bytes(rings, mode, grid=14, exponent=0):
    """ring_bytes.hpp: mode header, grid byte, exponent byte, then count + points per ring."""
    out = [mode, grid, exponent & 0xFF]
    for ring in rings:
        out.append(len(ring))
        for x, y in ring:
            if mode == ANY_DOUBLE:
                out += struct.pack("<dd", x, y)
            else:
                out.append(int(x) | int(y) << 4)
    return out


def open_rings(coordinates):
    """GeoJSON rings without their closing point."""
    return [ring[:-1] if len(ring) > 1 and ring[0] == ring[-1] else ring for ring in coordinates]


def earcut_fixtures():
    for path in sorted((ROOT / "corpus" / "earcut").glob("*.json")):
        data = json.loads(path.read_text())
        if not isinstance(data, dict) or data.get("type") != "Polygon":
            continue
        rings = open_rings(data["coordinates"])
        if sum(map(len, rings)) <= 256 and len(rings) <= 32 and max(map(len, rings)) <= 255:
            yield path, rings


# Small-grid shapes (coordinates 0..15): the degenerate cases the issue names.
SHAPES = {
    "square": [[(0, 0), (4, 0), (4, 4), (0, 4)]],
    "square-hole": [[(0, 0), (6, 0), (6, 6), (0, 6)], [(2, 2), (2, 4), (4, 4), (4, 2)]],
    "collinear-run": [[(0, 0), (1, 0), (2, 0), (3, 0), (3, 1), (3, 2), (3, 3), (0, 3)]],
    "repeated-points": [[(0, 0), (0, 0), (4, 0), (4, 4), (4, 4), (0, 4), (0, 0)]],
    "spike": [[(0, 0), (4, 0), (4, 2), (6, 2), (4, 2), (4, 4), (0, 4)]],
    "spike-inward": [[(0, 0), (4, 0), (4, 2), (2, 2), (4, 2), (4, 4), (0, 4)]],
    "bowtie": [[(0, 0), (4, 4), (4, 0), (0, 4)]],
    "figure-eight": [[(0, 0), (2, 0), (2, 2), (4, 2), (4, 4), (2, 4), (2, 2), (0, 2)]],
    "hole-touching-outer": [[(0, 0), (6, 0), (6, 6), (0, 6), (0, 3)], [(0, 3), (3, 2), (3, 4)]],
    "holes-touching": [[(0, 0), (8, 0), (8, 8), (0, 8)], [(2, 2), (4, 4), (4, 2)],
                       [(4, 4), (6, 6), (6, 4)]],
    "hole-outside": [[(0, 0), (4, 0), (4, 4), (0, 4)], [(6, 6), (8, 6), (8, 8)]],
    "nested-holes": [[(0, 0), (9, 0), (9, 9), (0, 9)], [(1, 1), (1, 8), (8, 8), (8, 1)],
                     [(3, 3), (3, 5), (5, 5), (5, 3)]],
    "zero-area-hole": [[(0, 0), (6, 0), (6, 6), (0, 6)], [(1, 1), (2, 2), (3, 3)]],
    "vertex-on-edge": [[(0, 0), (6, 0), (6, 6), (0, 6)], [(0, 3), (3, 2), (3, 4)]],
    "overlapping-edges": [[(0, 0), (6, 0), (6, 6), (0, 6)], [(0, 0), (3, 0), (3, 3)]],
    "hole-in-reflex-corner": [[(0, 0), (4, 0), (4, 4), (8, 4), (8, 8), (0, 8)],
                              [(4, 4), (4, 6), (2, 6), (2, 4)]],
    "hole-chord": [[(0, 0), (4, 0), (8, 0), (8, 8), (4, 8), (0, 8)], [(4, 0), (6, 4), (4, 8), (2, 4)]],
    # Issue 19: a vertex exactly inside another edge (split), zero-width antennas (dissolved).
    "t-junction-hole-on-hole": [[(0, 0), (10, 0), (10, 10), (0, 10)], [(2, 2), (2, 6), (8, 6), (8, 2)],
                                [(5, 6), (4, 8), (6, 8)]],
    "t-junction-own-edge": [[(0, 0), (4, 0), (4, 4), (2, 0), (0, 4)]],
    "t-junction-several": [[(0, 0), (12, 0), (12, 8), (0, 8)], [(3, 0), (2, 2), (4, 2)],
                           [(6, 0), (5, 2), (6, 2)], [(6, 0), (7, 2), (8, 2)], [(10, 0), (9, 2), (11, 2)]],
    "antenna": [[(0, 0), (4, 0), (4, 4), (2, 4), (2, 6), (2, 8), (2, 6), (2, 4), (0, 4)]],
}

# T-junction moves (ring_bytes.hpp, header bit 5): (vertex, edge, eighths) per move.
MOVES = {
    "square-hole": [(4, 0, 3)],
    "holes-touching": [(3, 0, 3), (9, 7, 1)],
    "nested-holes": [(4, 0, 3), (8, 5, 3)],
    "collinear-run": [(7, 1, 0)],
}


def degenerate_seeds():
    for path, rings in earcut_fixtures():
        write("degenerate", f"earcut-{path.stem}", ring_bytes(rings, ANY_DOUBLE),
              f"corpus/earcut/{path.name}")
    for name, rings in SHAPES.items():
        write("degenerate", f"grid-{name}", ring_bytes(rings, SMALL_GRID), "hand-made")
    for name, moves in MOVES.items():
        data = ring_bytes(SHAPES[name], SMALL_GRID | T_JUNCTION_MOVES)
        data[3:3] = [len(moves) - 1] + [b for move in moves for b in move]
        write("degenerate", f"moves-{name}", data, f"grid-{name} with T-junction moves")
    square_hole = SHAPES["square-hole"]
    for exponent in (-100, -50, 50, 100, 127, -128):  # 2^(2e): both range limits crossed
        write("degenerate", f"scaled-{exponent}", ring_bytes(square_hole, SCALED_GRID, 14, exponent),
              "hand-made")
    for name, value in (("1e300", 1e300), ("subnormal", 5e-324), ("tiny", 2.0 ** -200)):
        ring = [(0, 0), (value, 0), (value, value), (0, value)]
        write("degenerate", f"double-{name}", ring_bytes([ring], ANY_DOUBLE), "hand-made")
    nan_ring = [(0, 0), (float("nan"), 0), (1, 1)]
    write("degenerate", "double-nan", [ANY_DOUBLE | 4] + ring_bytes([nan_ring], ANY_DOUBLE)[1:],
          "hand-made")
    thin = [(0, 0), (1, 1e-15), (2, 0), (3, 1e-15), (3, 1), (0, 1)]
    write("degenerate", "double-near-collinear", ring_bytes([thin], ANY_DOUBLE), "hand-made")


def cell_bytes(rows, flags=0, start=0, exponent=0, offset=0):
    """cell_polygon.hpp: width, height, flags, start, exponent, offset, then the cells' bits."""
    height, width = len(rows), len(rows[0])
    bits = [ch == "#" for row in reversed(rows) for ch in row]
    out = [width - 2, height - 2, flags, start, exponent & 0xFF, offset & 0xFF, offset >> 8]
    for i in range(0, len(bits), 8):
        out.append(sum(1 << k for k, bit in enumerate(bits[i:i + 8]) if bit))
    return out


CELLS = {
    "full": ["###", "###", "###"],
    "ring": ["###", "#.#", "###"],
    "diagonal-holes": ["#####", "#.###", "##.##", "#####"],
    "hole-touching-outer": ["####", "####", "#.##", ".###"],
    "checkerboard": ["#.#.#.", ".#.#.#", "#.#.#.", ".#.#.#", "#.#.#.", ".#.#.#"],
    "comb": ["#########", "#.#.#.#.#", "#.#.#.#.#", "#.#.#.#.#"],
    "spiral": ["#######", "#.....#", "#.###.#", "#.#.#.#", "#.#...#", "#.#####", "#......"],
    "many-holes": ["#########", "#.#.#.#.#", "#########", "#.#.#.#.#", "#########"],
}


def random_cells(rng, size, fill):
    return ["".join("#" if rng.random() < fill else "." for _ in range(size)) for _ in range(size)]


def cell_seeds():
    rng = random.Random(7)
    seeds = []
    for name, rows in CELLS.items():
        for flags, suffix in ((0, ""), (1, "-corners")):
            seeds.append((f"cells-{name}{suffix}", cell_bytes(rows, flags)))
    seeds.append(("cells-ring-placed", cell_bytes(CELLS["ring"], 16 | 8 | 4, 0, -90, 12345)))
    seeds.append(("cells-comb-no-collinear", cell_bytes(CELLS["comb"], 2)))
    for k in range(6):
        rows = random_cells(rng, 8 + k, 0.55 + 0.05 * (k % 3))
        seeds.append((f"cells-random-{k}", cell_bytes(rows, k % 2, rng.randrange(256))))
    # Triangular holes standing on unit edges (T-junctions): 16 bits a pick after the cells.
    for name, flags, picks in (("ring", 0, [0, 5, 13]), ("many-holes", 3, [1, 40, 77, 90]),
                               ("comb", 2, [3, 17, 30]), ("checkerboard", 1, [2, 9, 60, 61])):
        extra = [b for pick in picks for b in (pick & 0xFF, pick >> 8)]
        seeds.append((f"cells-t-junctions-{name}", cell_bytes(CELLS[name], flags) + extra))
    return seeds


def generated_families(cli):
    for kind in ("star", "comb", "spiral", "koch", "hilbert", "random", "holes", "random-holes"):
        run = subprocess.run([cli, "generate", kind, "100", "--seed", "3"], capture_output=True, text=True)
        if run.returncode != 0:  # families with a larger minimum size (spiral) are left out
            continue
        text = run.stdout
        data = json.loads(text)
        coordinates = data["coordinates"] if data.get("type") == "Polygon" else data["coordinates"][0]
        rings = open_rings(coordinates)
        if sum(map(len, rings)) <= 256 and len(rings) <= 32:
            yield kind, rings


def configured_seeds(cli):
    """parallel and cdt: a header byte (bit 0: rings instead of cells), a partitions byte."""
    for name, cells in cell_seeds():
        write("bridged", name, [0] + cells, "hand-made" if "random" not in name else "random cells")
        write("parallel", name, [0, 3] + cells, "as bridged")
        write("cdt", name, [0, 1] + cells, "as bridged")
    sources = [(f"earcut-{p.stem}", r, f"corpus/earcut/{p.name}") for p, r in earcut_fixtures()]
    sources += [(f"generate-{k}", r, f"pear generate {k} 100 --seed 3") for k, r in generated_families(cli)]
    for name, rings, source in sources:
        write("parallel", name, [1, 2] + ring_bytes(rings, ANY_DOUBLE), source)
        write("cdt", name, [1, 1] + ring_bytes(rings, ANY_DOUBLE), source)
        if name.startswith("generate"):
            write("degenerate", name, ring_bytes(rings, ANY_DOUBLE), source)


def wkt(rings):
    return "POLYGON(" + ",".join(
        "(" + ",".join(f"{x!r} {y!r}" for x, y in ring + ring[:1]) + ")" for ring in rings) + ")"


def reader_seeds():
    for path, rings in earcut_fixtures():
        if len(path.read_bytes()) < 3000:
            write("readers", f"geojson-{path.stem}", b"\0" + path.read_bytes(), f"corpus/earcut/{path.name}")
            write("readers", f"wkt-{path.stem}", b"\1" + wkt(rings).encode(), f"corpus/earcut/{path.name}")
    texts = {
        "geojson-feature-collection": (0, '{"type":"FeatureCollection","features":[{"type":"Feature",'
                                          '"properties":{},"geometry":{"type":"MultiPolygon","coordinates":'
                                          '[[[[0,0],[1,0],[1,1],[0,0]]],[[[2,2],[3,2],[3,3,7]]]]}},'
                                          '{"type":"Feature","geometry":null}]}'),
        "geojson-geometry-collection": (0, '{"type":"GeometryCollection","geometries":[{"type":"Polygon",'
                                           '"coordinates":[[[0,0],[1e-5,0],[0,1E3]]]}]}'),
        "geojson-small-ring": (4, '[[[0,0],[4,0],[4,4]],[[1,1]]]'),
        "wkt-multi": (1, "MULTIPOLYGON Z (((0 0 1,4 0 1,4 4 1,0 0 1)),((5 5 0,6 5 0,6 6 0,5 5 0)))\n"
                         "POLYGON EMPTY polygon ((0 0, 1 0, 0 1, 0 0), (0.1 0.1, 0.2 0.1, 0.1 0.2, 0.1 0.1))"),
        "wkt-zm": (1, "POLYGON ZM ((0 0 0 0,2 0 0 0,2 2 0 0,0 0 0 0))"),
        "poly-square-hole": (2, "# a square with a square hole\n8 2 0 0\n0 0 0\n1 6 0\n2 6 6\n3 0 6\n"
                                "4 2 2\n5 4 2\n6 4 4\n7 2 4\n8 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n"
                                "4 4 5\n5 5 6\n6 6 7\n7 7 4\n1\n0 3 3\n"),
        "poly-one-based": (2, "3 2 0 1\n1 0 0 0\n2 1 0 0\n3 0 1 0\n3 1\n1 1 2 0\n2 2 3 0\n3 3 1 0\n0\n0\n"),
    }
    for name, (header, text) in texts.items():
        write("readers", name, bytes([header]) + text.encode(), "hand-made")


def offset(value):
    """fuzz/batch.cpp's offset entry for value: a small one in a byte, else 8 raw bytes."""
    return [value << 3] if 0 <= value <= 31 else [6] + list(struct.pack("<q", value))


def extreme(k):
    """fuzz/batch.cpp's ends: INT64_MIN, INT64_MAX, -1, limit + 1, ... (mode 5)."""
    return [(k << 3) | 5]


def batch_bytes(rings_of_points, ring_offsets, polygon_offsets, header=0):
    """fuzz/batch.cpp: header, points (x | y << 4), ring offsets, polygon offsets."""
    points = [x | y << 4 for ring in rings_of_points for x, y in ring]
    out = [header, len(points)] + points + [len(ring_offsets)]
    out += [b for o in ring_offsets for b in (o if isinstance(o, list) else offset(o))]
    out += [len(polygon_offsets)]
    return out + [b for o in polygon_offsets for b in (o if isinstance(o, list) else offset(o))]


INT64_MIN, INT64_MAX = -2**63, 2**63 - 1


def batch_seeds():
    square = [(0, 0), (3, 0), (3, 3), (0, 3)]
    triangle = [(5, 5), (8, 5), (6, 8)]
    big, hole = [(0, 0), (8, 0), (8, 8), (0, 8)], [(2, 2), (2, 4), (4, 4), (4, 2)]
    bowtie = [(0, 0), (4, 4), (4, 0), (0, 4)]
    issue = "issue 30, item 2"
    seeds = {
        "squares": ([square] * 3, [0, 4, 8, 12], [0, 1, 2, 3], 0, "hand-made"),
        "squares-two-threads-delaunay": ([square] * 3, [0, 4, 8, 12], [0, 1, 2, 3], 3, "hand-made"),
        "square-with-hole": ([big, hole], [0, 4, 8], [0, 2], 0, "hand-made"),
        "mixed-no-simplicity-check": ([big, hole, bowtie, triangle], [0, 4, 8, 12, 15],
                                      [0, 2, 3, 4], 4, "hand-made"),
        "ring-offset-int64-min": ([square, triangle], [INT64_MIN, 4, 7], [0, 1, 2], 0, issue),
        "ring-offset-int64-max": ([square, triangle], [0, 4, INT64_MAX], [0, 1, 2], 1, issue),
        "ring-offsets-ends": ([square, triangle], [extreme(1), extreme(0), extreme(1)], [0, 1, 2],
                              0, "hand-made"),
        "polygon-offsets-ends": ([square, triangle], [0, 4, 7], [INT64_MIN, 1, INT64_MAX], 0,
                                 "hand-made"),
        "ring-past-the-points": ([square, triangle], [0, 4, extreme(3)], [0, 1, 2], 0, "hand-made"),
        "slice-from-polygon-1": ([square] * 3, [0, 4, 8, 12], [1, 2, 3], 0, "hand-made"),
        "polygons-backwards": ([square] * 3, [0, 4, 8, 12], [0, 2, 1, 3], 0, "hand-made"),
        "empty-polygon": ([square] * 2, [0, 4, 8], [0, 0, 1, 2], 0, "hand-made"),
        "no-ring-offsets": ([square], [], [0, 0], 0, "hand-made"),
        "rings-out-of-order": ([square, triangle], [0, 5, 4, 7], [0, 3], 0, "hand-made"),
    }
    for name, (rings, ring_offsets, polygon_offsets, header, source) in seeds.items():
        write("batch", name, batch_bytes(rings, ring_offsets, polygon_offsets, header), source)


def polygon_wkb(rings, order="<", z=False, srid=None, code=3):
    """One WKB Polygon (code 3) of rings, closed as given; ISO Z, or EWKB with an SRID."""
    out = struct.pack("<B" if order == "<" else ">B", 1 if order == "<" else 0)
    if srid is not None:
        out += struct.pack(order + "II", code | 0x20000000 | (0x80000000 if z else 0), srid)
    else:
        out += struct.pack(order + "I", code + (1000 if z else 0))
    out += struct.pack(order + "I", len(rings))
    for ring in rings:
        out += struct.pack(order + "I", len(ring))
        for x, y in ring:
            out += struct.pack(order + ("ddd" if z else "dd"), x, y, *([7.0] if z else []))
    return out


def multipolygon_wkb(parts, order="<"):
    head = struct.pack("<B" if order == "<" else ">B", 1 if order == "<" else 0)
    head += struct.pack(order + "II", 6, len(parts))
    return head + b"".join(polygon_wkb(p, order) for p in parts)


def wkb_bytes(values, header=0):
    """fuzz/wkb.cpp: header (values = 1 + header % 4), 16-bit lengths but the last, values."""
    assert len(values) == 1 + header % 4
    out = bytes([header]) + b"".join(struct.pack("<H", len(v)) for v in values[:-1])
    return out + b"".join(values)


def wkb_seeds():
    square = [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0), (0.0, 0.0)]
    hole = [(1.0, 1.0), (1.0, 2.0), (2.0, 2.0), (1.0, 1.0)]
    far = [(10.0, 0.0), (11.0, 0.0), (10.5, 1e-300), (10.0, 0.0)]
    poly = polygon_wkb([square, hole])
    multi = multipolygon_wkb([[square, hole], [far]])
    empty_collection = struct.pack("<BII", 1, 7, 0)
    seeds = {
        "polygon": ([poly], 0),
        "polygon-big-endian": ([polygon_wkb([square, hole], ">")], 4),
        "polygon-z": ([polygon_wkb([square], z=True)], 8),
        "polygon-ewkb-srid-z": ([polygon_wkb([square, hole], ">", z=True, srid=4326)], 16 | 8),
        "multipolygon": ([multi], 4 | 16),
        "multipolygon-big-endian": ([multipolygon_wkb([[square], [far, hole]], ">")], 8),
        "empty-collection": ([empty_collection], 0),
        "three-values-one-missing": ([poly, b"", multi], 2),
        "four-values": ([poly, empty_collection, multi, polygon_wkb([far], ">")], 3 | 4),
        "truncated-in-a-point": ([poly[:-5]], 0),
        "truncated-after-good-value": ([poly, multi[:30]], 1),
        "ring-count-huge": ([poly[:5] + struct.pack("<I", 0xFFFFFFFF) + poly[9:]], 0),
        "point-count-huge": ([poly[:9] + struct.pack("<I", 0xFFFFFFF0) + poly[13:]], 0),
        "part-count-huge": ([multi[:5] + struct.pack("<I", 0x7FFFFFFF) + multi[9:]], 0),
        "byte-order-2": ([b"\x02" + poly[1:]], 0),
        "byte-order-wrong-way": ([b"\x00" + poly[1:]], 0),
        "trailing-bytes": ([poly + b"\x00\x01"], 0),
        "linestring": ([struct.pack("<BII", 1, 2, 2) + struct.pack("<4d", 0, 0, 1, 1)], 0),
        "collection-not-empty": ([struct.pack("<BII", 1, 7, 1) + poly], 0),
        "multipolygon-part-not-polygon": ([struct.pack("<BII", 1, 6, 1) + empty_collection], 0),
        "polygon-no-rings-and-empty-ring": ([polygon_wkb([]), polygon_wkb([[]])], 1),
    }
    for name, (values, header) in seeds.items():
        write("wkb", name, wkb_bytes(values, header), "hand-made")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: fuzz/make_seeds.py PEAR_CLI")
    degenerate_seeds()
    configured_seeds(sys.argv[1])
    reader_seeds()
    batch_seeds()
    wkb_seeds()
    found = OUT / "MANIFEST.tsv"  # keep the lines of inputs found by fuzzing
    kept = [line.split("\t", 1) for line in found.read_text().splitlines()[1:]] if found.exists() else []
    manifest.extend((f, s) for f, s in kept if "/crash-" in f or "/regression-" in f)
    lines = ["file\tsource"] + [f"{f}\t{s}" for f, s in sorted(manifest)]
    (OUT / "MANIFEST.tsv").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
