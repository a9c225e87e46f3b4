#!/usr/bin/env python3
"""Draws `pear triangulate -o X.svg` with real renderers and checks where the paint lands.

usage: test_svg_render.py PATH/TO/pear [TEST ...]
The default tests use a polygon from `pear generate`, large enough that the SVG writer must cut
its paths; the 'large' suite names the tests that draw GSHHG coastlines from the shared corpus.
Each picture is compared with the polygon rasterized here, independently: pixel centres inside
by even-odd scanlines (numpy), that raster checked against the polygon's shoelace area. Then:
pixels well inside are painted with the triangles' colour, pixels well outside (the holes too)
keep the background. A missing renderer, numpy or Pillow skips (exit 77 when all skip).
"""
import gzip
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import corpus  # noqa: E402 (tests/support)
from scratch import ScratchTest  # noqa: E402 (tests/support)

try:
    import numpy as np
    from PIL import Image
except ImportError as e:  # the tests say so and skip
    np = Image = None
    IMPORT_ERROR = str(e)

PEAR = None
SIZE = 1000  # the CLI's picture: 1000 pixels on the longer side, io.hpp's SvgOptions::size
BACKGROUND = (0xfb, 0xfb, 0xf8)


def require_tool(name, package):
    if np is None:
        raise unittest.SkipTest(corpus.MISSING_TOOL + "numpy and Pillow: " + IMPORT_ERROR)
    path = shutil.which(name)
    if path is None:
        raise unittest.SkipTest(corpus.MISSING_TOOL + name + " (Debian package " + package + ")")
    return path


def read_rings(path):
    """The GeoJSON Polygon or MultiPolygon's rings as (n, 2) arrays, the closing point dropped."""
    opener = gzip.open if str(path).endswith(".gz") else open
    with opener(path, "rt") as f:
        geometry = json.load(f)
    polygons = ([geometry["coordinates"]] if geometry["type"] == "Polygon"
                else geometry["coordinates"])
    return [[np.array(ring[:-1] if ring[0] == ring[-1] else ring, dtype=float) for ring in p]
            for p in polygons]


def shoelace(ring):
    x, y = ring[:, 0], ring[:, 1]
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


class Picture:
    """Where io.hpp's write_svg puts a polygon: its box scaled to SIZE pixels on the longer side,
    a 2% margin all round, y up. A renderer that fits the picture to the PNG scales it as SVG's
    default preserveAspectRatio (xMidYMid meet) says; a browser draws it at its own size."""

    def __init__(self, rings, svg_size, png_size, fits):
        points = np.concatenate([r for p in rings for r in p])
        self.low, self.high = points.min(axis=0), points.max(axis=0)
        margin = 0.02 * SIZE
        self.scale = (SIZE - 2 * margin) / (self.high - self.low).max()
        self.margin = margin
        zoom = min(png_size[0] / svg_size[0], png_size[1] / svg_size[1]) if fits else 1
        self.zoom = zoom
        self.offset = ((png_size[0] - svg_size[0] * zoom) / 2,
                       (png_size[1] - svg_size[1] * zoom) / 2) if fits else (0, 0)

    def pixels(self, ring):
        x = self.margin + (ring[:, 0] - self.low[0]) * self.scale
        y = self.margin + (self.high[1] - ring[:, 1]) * self.scale
        return np.stack([self.offset[0] + x * self.zoom, self.offset[1] + y * self.zoom], axis=1)

    def box(self):
        corners = self.pixels(np.array([self.low, self.high]))
        return corners[:, 0].min(), corners[:, 1].min(), corners[:, 0].max(), corners[:, 1].max()


def inside_mask(rings_in_pixels, width, height):
    """Pixel centres inside the rings by the even-odd rule: scanlines through the centres."""
    x0 = np.concatenate([r[:, 0] for r in rings_in_pixels])
    y0 = np.concatenate([r[:, 1] for r in rings_in_pixels])
    x1 = np.concatenate([np.roll(r[:, 0], -1) for r in rings_in_pixels])
    y1 = np.concatenate([np.roll(r[:, 1], -1) for r in rings_in_pixels])
    # Rows whose centre r + 0.5 lies in [min y, max y): each crossing counted once.
    first = np.clip(np.ceil(np.minimum(y0, y1) - 0.5), 0, height).astype(np.int64)
    stop = np.clip(np.ceil(np.maximum(y0, y1) - 0.5), 0, height).astype(np.int64)
    counts = stop - first
    edge = np.repeat(np.arange(len(x0)), counts)
    row = first[edge] + (np.arange(len(edge)) - np.repeat(np.cumsum(counts) - counts, counts))
    t = (row + 0.5 - y0[edge]) / (y1[edge] - y0[edge])
    x = x0[edge] + t * (x1[edge] - x0[edge])
    order = np.lexsort((x, row))
    row, x = row[order], x[order]
    assert len(row) % 2 == 0 and np.all(row[0::2] == row[1::2]), "odd crossings in a row"
    # Each pair of crossings in a row bounds a run of centres c + 0.5 in [start, end).
    start = np.clip(np.ceil(x[0::2] - 0.5), 0, width).astype(np.int64)
    end = np.clip(np.ceil(x[1::2] - 0.5), 0, width).astype(np.int64)
    runs = np.zeros((height, width + 1), dtype=np.int64)
    np.add.at(runs, (row[0::2], start), 1)
    np.add.at(runs, (row[0::2], end), -1)
    return np.cumsum(runs, axis=1)[:, :width] > 0


def erode(mask, radius):
    """True where the whole (2 radius + 1) square around a pixel is True (edges count False)."""
    padded = np.pad(mask, radius, constant_values=False)
    out = np.ones_like(mask)
    height, width = mask.shape
    for dy in range(2 * radius + 1):
        for dx in range(2 * radius + 1):
            out &= padded[dy:dy + height, dx:dx + width]
    return out


class Render(ScratchTest):
    def svg_of(self, polygon_file):
        svg = self.path("picture.svg")
        result = subprocess.run([PEAR, "triangulate", str(polygon_file), "-o", svg],
                                capture_output=True, text=True, timeout=600)
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(svg) as f:
            head = f.read(400)
        size = re.search(r'<svg [^>]*width="([0-9.]+)" height="([0-9.]+)"', head)
        self.assertIsNotNone(size, head)
        return svg, (float(size.group(1)), float(size.group(2)))

    def rsvg(self, svg, width, height):
        png = self.path("rsvg.png")
        started = time.monotonic()
        result = subprocess.run([require_tool("rsvg-convert", "librsvg2-bin"), "-w", str(width),
                                 "-h", str(height), "-o", png, svg],
                                capture_output=True, text=True, timeout=300)
        print(f"rsvg-convert: {time.monotonic() - started:.2f} s", file=sys.stderr)
        self.assertEqual(result.returncode, 0, result.stderr)
        return png, True

    def chromium(self, svg, width, height):
        png = self.path("chromium.png")
        command = [require_tool("chromium", "chromium"), "--headless", "--disable-gpu",
                   "--disable-dev-shm-usage", "--user-data-dir=" + self.path("profile"),
                   "--hide-scrollbars", f"--window-size={width},{height}",
                   f"--screenshot={png}", "file://" + svg]
        if os.geteuid() == 0:
            command.insert(1, "--no-sandbox")  # Chromium refuses to run as root with its sandbox
        started = time.monotonic()
        result = subprocess.run(command, capture_output=True, text=True, timeout=300)
        print(f"chromium: {time.monotonic() - started:.2f} s", file=sys.stderr)
        self.assertEqual(result.returncode, 0, result.stderr)
        return png, False

    def assert_draws(self, polygon_file, renderer, zoom):
        """Renders the CLI's picture of the polygon at `zoom` and compares it with the raster."""
        rings = read_rings(polygon_file)
        svg, svg_size = self.svg_of(polygon_file)
        with open(svg) as f:
            self.assertGreater(f.read().count("<path "), 3, "the test needs a picture cut up")
        width, height = math.ceil(svg_size[0] * zoom), math.ceil(svg_size[1] * zoom)
        png, fits = renderer(svg, width, height)
        with Image.open(png) as image:
            self.assertEqual(image.size, (width, height))
            rgb = np.asarray(image.convert("RGB")).astype(np.int64)
        picture = Picture(rings, svg_size, (width, height), fits)
        pixel_rings = [[picture.pixels(r) for r in p] for p in rings]
        inside = inside_mask([r for p in pixel_rings for r in p], width, height)
        # The raster against the shoelace area: the reference itself is sound.
        area = sum(shoelace(p[0]) - sum(shoelace(h) for h in p[1:]) for p in pixel_rings)
        self.assertAlmostEqual(inside.sum() / area, 1, delta=0.01)

        painted = np.abs(rgb - BACKGROUND).max(axis=2) > 12
        triangle_blue = (rgb[:, :, 2] - rgb[:, :, 0]) > 20  # #a6cee3, edges #2b4a6b; not #e4e4de
        deep_inside = erode(inside, 1)
        self.assertGreater(deep_inside.sum(), 1000)
        self.assertGreater(triangle_blue[deep_inside].mean(), 0.995)
        # Outside, two pixels from any boundary; sub-pixel spits may still paint a few.
        x0, y0, x1, y1 = picture.box()
        in_box = np.zeros_like(inside)
        in_box[int(y0):int(np.ceil(y1)) + 1, int(x0):int(np.ceil(x1)) + 1] = True
        far_outside = erode(~inside, 2) & in_box
        self.assertGreater(far_outside.sum(), 1000)
        self.assertLess(painted[far_outside].mean(), 0.002)
        # The holes: inside an outer ring, outside the polygon; they must stay open too.
        outers = inside_mask([p[0] for p in pixel_rings], width, height)
        far_in_holes = erode(outers & ~inside, 2)
        print(f"{width}x{height}: inside {deep_inside.sum()} px, "
              f"{triangle_blue[deep_inside].mean():.5f} triangles' colour; outside "
              f"{far_outside.sum()} px, {painted[far_outside].mean():.5f} painted; holes "
              f"{far_in_holes.sum()} px, {painted[far_in_holes].mean():.5f} painted",
              file=sys.stderr)
        if far_in_holes.sum() >= 20:
            self.assertLess(painted[far_in_holes].mean(), 0.01)
        return far_in_holes.sum()

    def test_generated_polygon_with_holes_rsvg(self):
        require_tool("rsvg-convert", "librsvg2-bin")
        polygon = self.path("holes.json")
        result = subprocess.run([PEAR, "generate", "random-holes", "30000", "-o", polygon],
                                capture_output=True, text=True, timeout=120)
        self.assertEqual(result.returncode, 0, result.stderr)
        hole_pixels = self.assert_draws(polygon, self.rsvg, zoom=1.5)
        self.assertGreater(hole_pixels, 1000, "the holes should be visible")

    def coastline(self, name):
        [row] = [f for f in corpus.read_folder(corpus.shared_root(), "coast") if f.file == name]
        corpus.require(row.path)
        return row.path

    def test_large_eurasia_rsvg(self):
        require_tool("rsvg-convert", "librsvg2-bin")
        self.assert_draws(self.coastline("eurasia_gshhg_full.json.gz"), self.rsvg, zoom=1.25)

    def test_large_eurasia_chromium(self):
        require_tool("chromium", "chromium")
        self.assert_draws(self.coastline("eurasia_gshhg_full.json.gz"), self.chromium, zoom=1)


if __name__ == "__main__":
    PEAR = os.path.abspath(sys.argv[1])
    del sys.argv[1]
    corpus.main()
