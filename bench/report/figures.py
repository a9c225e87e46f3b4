"""The paper's figures from one run: Fig. 7 (ears), Fig. 8 (time per vertex), Fig. 9 (speedup,
measured and projected from work/span), and peak memory per vertex. Each as SVG and PNG."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import PEERS, VARIANT_NAMES, median  # noqa: E402

STYLE = {
    "pear_top": ("tab:blue", "o", "pear sequential (top)"),
    "pear_fast": ("tab:cyan", "o", "pear sequential (fast)"),
    "pear_cdt": ("tab:purple", "s", "pear CDT sequential"),
    "pear_mc_t2": ("tab:green", "^", "pear mark-and-cut, 2 threads"),
    "pear_pc_t2": ("tab:olive", "v", "pear partition-and-cut, 2 threads"),
    "pear_pc_t2_cdt": ("tab:pink", "D", "pear partition-and-cut + CDT, 2 threads"),
    "cgal_cdt": ("tab:red", "x", "CGAL CDT"),
    "geos_ear": ("tab:brown", "+", "GEOS PolygonTriangulator"),
    "geos_cdt": ("tab:orange", "*", "GEOS ConstrainedDelaunayTriangulator"),
    "glu": ("tab:gray", "1", "GLU tessellator"),
}


def save(fig, docs, name):
    out = os.path.join(docs, "figures")
    os.makedirs(out, exist_ok=True)
    # No date and fixed element ids: the same data renders to the same files.
    plt.rcParams["svg.hashsalt"] = "pear"
    for ext in ("svg", "png"):
        metadata = {"Date": None} if ext == "svg" else {"Software": None}
        fig.savefig(os.path.join(out, f"{name}.{ext}"), dpi=110, bbox_inches="tight",
                    metadata=metadata)
    plt.close(fig)
    return f"figures/{name}.svg"


def fig7_ears(ears, docs):
    if not ears:
        return None
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    folders = sorted({e["folder"] for e in ears})
    for folder in folders:
        rows = [e for e in ears if e["folder"] == folder and e["vertices"] > 0]
        n = [e["vertices"] for e in rows]
        left.scatter(n, [e["ears"] / e["vertices"] for e in rows], s=6, label=folder, alpha=0.6)
    left.set_xscale("log")
    left.set_ylim(0, 1)
    left.set_xlabel("vertices (after cleaning and bridging)")
    left.set_ylabel("fraction of vertices that are ears")
    left.axhline(0.5, color="k", lw=0.5, ls=":")
    left.legend(fontsize=7, markerscale=2)
    # Tiny polygons (most counties) have few possible fractions; leave them out of the histogram.
    large = [e for e in ears if e["vertices"] >= 100]
    fractions = [e["ears"] / e["vertices"] for e in large]
    convex = [e["convex"] / e["vertices"] for e in large]
    bins = [i / 40 for i in range(41)]
    right.hist(fractions, bins=bins, alpha=0.7, label="ears")
    right.hist(convex, bins=bins, alpha=0.5, label="convex vertices")
    right.set_xlabel("fraction of a polygon's vertices")
    right.set_ylabel(f"polygons with >= 100 vertices ({len(large)})")
    right.legend(fontsize=8)
    fig.suptitle(f"Fig. 7: ear prevalence over {len(ears)} polygons")
    return save(fig, docs, "fig7-ears")


def fig8_time_per_vertex(timings, docs):
    fig, ax = plt.subplots(figsize=(9, 5.5))
    for tri, (color, marker, label) in STYLE.items():
        points = []
        for inp in timings.inputs:
            e = timings.get(inp, tri)
            if e:
                points.append((e["vertices"], e["ms"] * 1e6 / e["vertices"]))
        if points:
            points.sort()
            ax.scatter(*zip(*points), color=color, marker=marker, s=22, label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("vertices")
    ax.set_ylabel("wall-clock time per vertex (ns)")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7, ncol=2)
    ax.set_title("Fig. 8: time per vertex (all inputs of the run; valid results only)")
    return save(fig, docs, "fig8-time-per-vertex")


def measured_speedups(timings, variant, threads, cdt):
    base = "pear_cdt" if cdt else "pear_top"
    tri = f"pear_{variant}_t{threads}" + ("_cdt" if cdt else "")
    points = []
    for inp in timings.inputs:
        b, t = timings.ms(inp, base), timings.ms(inp, tri)
        if b and t:
            points.append((timings.vertices(inp)[0], b / t))
    return sorted(points)


def many_core_speedups(threads_run, variant, threads, cdt):
    """Points (vertices, speedup) of a bench/threads.sh run: the variant (its CDT panel: automatic
    with the CDT, which clips by partition-and-cut past 2 threads) over the sequential engine."""
    if not threads_run:
        return []
    records = threads_run[0]
    base = "cdt" if cdt else "top"
    config = (f"auto_t{threads}_cdt" if cdt else f"{variant}_t{threads}")
    times, vertices = {}, {}
    for r in records:
        if "median_ms" in r and r.get("triangles", 0) > 0:
            times.setdefault(r["input"], {})[r["config"]] = r["median_ms"]
            vertices[r["input"]] = r["vertices"]
    return sorted((vertices[i], c[base] / c[config]) for i, c in times.items()
                  if c.get(base) and c.get(config))


def projected_speedups(profile, variant, threads):
    points = []
    for run in profile:
        base = run["sequential_cdt"] if variant.endswith("_cdt") else run["sequential"]
        for v in run["variants"]:
            if v["variant"] == variant and v["partitions"] == threads:
                points.append((run["vertices"], base / v["projected"][str(threads)]))
    return sorted(points)


def fig9_speedup(timings, profile, docs, threads_run=None):
    panels = [("dc", False), ("pc", False), ("mc", False), ("pc", True)]
    fig, axes = plt.subplots(2, 2, figsize=(11, 8), sharey=True)
    colors = {1: "tab:gray", 2: "tab:blue", 4: "tab:green", 8: "tab:red", 16: "tab:purple"}
    for ax, (variant, cdt) in zip(axes.flat, panels):
        for t in (1, 2, 4, 8):
            points = measured_speedups(timings, variant, t, cdt)
            if points:
                over = " (oversubscribed)" if t > 2 else ""
                ax.scatter(*zip(*points), s=22, label=f"{t} thread{'s' if t > 1 else ''}, measured{over}",
                           facecolors="none" if t > 2 else colors[t], edgecolors=colors[t])
        cores = threads_run[1].get("cpus", "?") if threads_run else None
        for t in (2, 4, 8, 16):
            points = many_core_speedups(threads_run, variant, t, cdt)
            if points:
                ax.scatter(*zip(*points), s=26, marker="^", facecolors=colors[t], edgecolors="k",
                           linewidths=0.4, label=f"{t} threads, measured on {cores} cores")
        key = variant + ("_cdt" if cdt else "")
        for t in (2, 4, 8, 16):
            points = projected_speedups(profile, key, t)
            if points:
                ax.scatter(*zip(*points), color=colors[t], marker="x", s=14, lw=0.8,
                           label=f"{t} threads, work/span projection")
        ax.axhline(1, color="k", lw=0.5)
        ax.set_xscale("log")
        ax.set_xlabel("vertices")
        title = VARIANT_NAMES[variant] + (" + parallel CDT (vs sequential CDT)" if cdt else "")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=6)
    axes[0][0].set_ylabel("speedup over pear's sequential engine")
    axes[1][0].set_ylabel("speedup over pear's sequential engine")
    fig.suptitle("Fig. 9: speedup against input size per thread count")
    fig.tight_layout()
    return save(fig, docs, "fig9-speedup")


def fig_memory(timings, docs):
    names, values = [], []
    for tri in timings.triangulators():
        per_vertex = [timings.get(inp, tri)["peak_bytes_per_vertex"] for inp in timings.inputs
                      if timings.get(inp, tri) and timings.vertices(inp)[0] >= 10000]
        if per_vertex and (tri in PEERS or tri in STYLE):
            names.append(tri)
            values.append(median(per_vertex))
    if not names:
        return None
    fig, ax = plt.subplots(figsize=(9, 4))
    ax.bar(names, values, color=[STYLE.get(n, ("tab:gray",))[0] for n in names])
    ax.set_ylabel("peak heap bytes per vertex (median, inputs >= 10k)")
    ax.tick_params(axis="x", labelrotation=45, labelsize=8)
    ax.set_title("Peak heap memory per vertex")
    return save(fig, docs, "memory-per-vertex")


def render(run, docs):
    timings = run["timings"]
    return {
        "fig7": fig7_ears(run["ears"], docs),
        "fig8": fig8_time_per_vertex(timings, docs),
        "fig9": fig9_speedup(timings, run["profile"], docs, run.get("threads")),
        "memory": fig_memory(timings, docs),
    }
