"""Markdown tables of docs/benchmarks.md from one run. Ratios are always peer time / pear time
from the same run (> 1: pear faster); times are wall-clock medians in milliseconds."""
from results import CDT_PEERS, PEERS, SEQUENTIAL, VARIANTS, median


def table(head, rows):
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def fmt_ms(ms):
    return "" if ms is None else f"{ms:.3g}" if ms < 1000 else f"{ms:,.0f}"


def ratio(peer_ms, pear_ms):
    return None if not peer_ms or not pear_ms else peer_ms / pear_ms


def fmt_ratio(r):
    return "" if r is None else f"**{r:.2f}x**" if r >= 1 else f"{r:.2f}x"


#: The default options first (`top`, `automatic`), then pear's best setting of each kind.
KEYS = ("default, 1 thread", "default, 2 threads", "sequential", "2 threads", "CDT sequential",
        "CDT 2 threads")


def comparisons(t, inp):
    """The comparisons of one input (KEYS): (pear name, pear ms, peer name, peer ms) each."""
    peer, peer_ms = t.best(inp, PEERS)
    cdt_peer, cdt_peer_ms = t.best(inp, CDT_PEERS)
    top, top_ms = t.best(inp, ["pear_top"])
    auto, auto_ms = t.best(inp, ["pear_auto_t2"])
    seq, seq_ms = t.best(inp, SEQUENTIAL)
    par, par_ms = t.best(inp, t.parallel(2))
    cdt, cdt_ms = t.best(inp, ["pear_cdt"])
    pcdt, pcdt_ms = t.best(inp, t.parallel(2, cdt=True))
    return {
        "default, 1 thread": (top, top_ms, peer, peer_ms),
        "default, 2 threads": (auto, auto_ms, peer, peer_ms),
        "sequential": (seq, seq_ms, peer, peer_ms),
        "2 threads": (par, par_ms, peer, peer_ms),
        "CDT sequential": (cdt, cdt_ms, cdt_peer, cdt_peer_ms),
        "CDT 2 threads": (pcdt, pcdt_ms, cdt_peer, cdt_peer_ms),
    }


def versus_peers(t):
    head = ["input", "vertices", "holes", "best peer (ms)", "pear seq. best (ms)", "x",
            "pear 2 threads best (ms)", "x", "best CDT peer (ms)", "pear CDT (ms)", "x",
            "pear CDT 2 threads (ms)", "x"]
    rows = []
    for inp in t.inputs:
        n, h = t.vertices(inp)
        c = comparisons(t, inp)
        row = [inp, f"{n:,}", f"{h:,}"]
        for key in ("sequential", "2 threads", "CDT sequential", "CDT 2 threads"):
            pear, pear_ms, peer, peer_ms = c[key]
            if key in ("sequential", "CDT sequential"):
                row.append(f"{peer} {fmt_ms(peer_ms)}" if peer else "none valid")
            row += [f"{pear} {fmt_ms(pear_ms)}" if pear else "", fmt_ratio(ratio(peer_ms, pear_ms))]
        rows.append(row)
    return table(head, rows)


def summary(t):
    head = ["comparison", "inputs", "median x", "min x", "max x", "pear faster on"]
    rows = []
    for key in KEYS:
        ratios = [ratio(c[3], c[1]) for c in (comparisons(t, i)[key] for i in t.inputs)]
        ratios = [r for r in ratios if r is not None]
        if ratios:
            wins = sum(r > 1 for r in ratios)
            rows.append([key, len(ratios), f"{median(ratios):.2f}x", f"{min(ratios):.2f}x",
                         f"{max(ratios):.2f}x", f"{wins} of {len(ratios)}"])
    return table(head, rows)


def all_times(t):
    tris = t.triangulators()
    head = ["input"] + tris
    rows = []
    for inp in t.inputs:
        row = [inp]
        for tri in tris:
            e = t.rows[inp].get(tri)
            if isinstance(e, dict):
                row.append(fmt_ms(e["ms"]) + ("" if e.get("valid", 1) >= 1 else " (invalid)"))
            else:
                row.append("skipped" if e else "")
        rows.append(row)
    return table(head, rows)


def speedups(t):
    """Measured speedups only: the work/span projection is docs/scaling.md's one table."""
    head = ["input", "vertices"]
    for v in ("pc", "mc", "dc"):
        head += [f"{v} t1", f"{v} t2"]
    head += ["pc+CDT t2 (vs CDT)"]
    rows = []
    for inp in t.inputs:
        n, _ = t.vertices(inp)
        if n < 50000:
            continue
        base, base_cdt = t.ms(inp, "pear_top"), t.ms(inp, "pear_cdt")
        row = [inp, f"{n:,}"]
        for v in ("pc", "mc", "dc"):
            row += [fmt_ratio(ratio(base, t.ms(inp, f"pear_{v}_t{k}"))) for k in (1, 2)]
        row.append(fmt_ratio(ratio(base_cdt, t.ms(inp, "pear_pc_t2_cdt"))))
        rows.append(row)
    return table(head, rows)


def quality(records):
    """Table 1: the mean over inputs of each configuration's average deviation from 60 degrees
    and average smallest angle, over the inputs every configuration triangulated validly."""
    configs = []
    for r in records:
        configs += [x["config"] for x in r["results"] if x["config"] not in configs]
    common = [r for r in records
              if all(x.get("valid") for x in r["results"]) and len(r["results"]) == len(configs)]
    head = ["", *configs]
    dev = [f"{sum(x['dev60'] for r in common for x in r['results'] if x['config'] == c) / len(common):.2f}"
           for c in configs] if common else []
    angle = [f"{sum(x['min_angle'] for r in common for x in r['results'] if x['config'] == c) / len(common):.2f}"
             for c in configs] if common else []
    invalid = [str(sum(1 for r in records for x in r["results"]
                       if x["config"] == c and not x.get("valid"))) for c in configs]
    # The paper's Table 1 (its own corpus of about 20,000 polygons, 8 cores), for reference.
    paper = {"top": (31.53, 23.40), "dc": (35.29, 20.07), "pc": (34.97, 21.32),
             "mc": (38.38, 21.07), "cdt": (30.79, 24.60)}
    rows = [["avg. deviation from 60° (smaller is better)", *dev],
            ["paper's Table 1, same row", *(f"{paper[c][0]:.2f}" if c in paper else ""
                                            for c in configs)],
            ["avg. smallest angle (larger is better)", *angle],
            ["paper's Table 1, same row", *(f"{paper[c][1]:.2f}" if c in paper else ""
                                            for c in configs)],
            ["inputs not triangulated validly", *invalid]]
    out = table(head, rows) + "\nPer folder (the counties' thousands of small polygons weigh "
    out += "most in the overall mean): deviation from 60° / smallest angle.\n\n"
    rows = []
    for folder in sorted({r["folder"] for r in common}):
        rs = [r for r in common if r["folder"] == folder]
        cells = []
        for c in configs:
            xs = [x for r in rs for x in r["results"] if x["config"] == c]
            cells.append(f"{sum(x['dev60'] for x in xs) / len(xs):.1f} / "
                         f"{sum(x['min_angle'] for x in xs) / len(xs):.1f}")
        rows.append([f"{folder} ({len(rs)})", *cells])
    return out + table(["folder (inputs)", *configs], rows), len(common), len(records)


def flips(records):
    head = ["folder", "configuration", "inputs", "flips per edge", "in partitions", "on borders"]
    rows = []
    folders = sorted({r["folder"] for r in records})
    for folder in folders + ["all"]:
        for config in ("cdt", "pc_cdt_2", "pc_cdt_4", "pc_cdt_8"):
            xs = [x for r in records if folder in ("all", r["folder"]) for x in r["results"]
                  if x["config"] == config and x.get("edges")]
            edges = sum(x["edges"] for x in xs)
            if not edges:
                continue
            total = sum(x["flips"] for x in xs)
            inside = sum(x["flips_in"] for x in xs)
            border = sum(x["flips_border"] for x in xs)
            rows.append([folder, config, len(xs), f"{total / edges:.2f}", f"{inside / edges:.2f}",
                         f"{border / edges:.2f}"])
    return table(head, rows)


def ears(records):
    head = ["folder", "polygons", "median ears / vertices", "median convex / vertices",
            "polygons with 40-60% ears"]
    rows = []
    for folder in sorted({e["folder"] for e in records}) + ["all"]:
        rs = [e for e in records if folder in ("all", e["folder"]) and e["vertices"] > 0]
        fr = [e["ears"] / e["vertices"] for e in rs]
        cv = [e["convex"] / e["vertices"] for e in rs]
        mid = sum(0.4 <= f <= 0.6 for f in fr)
        rows.append([folder, len(rs), f"{median(fr):.3f}", f"{median(cv):.3f}",
                     f"{mid} ({100 * mid / len(rs):.0f}%)"])
    return table(head, rows)


def memory(t):
    head = ["triangulator", "inputs (>= 10k vertices)", "median bytes/vertex", "max bytes/vertex"]
    rows = []
    for tri in t.triangulators():
        values = [t.get(i, tri)["peak_bytes_per_vertex"] for i in t.inputs
                  if t.get(i, tri) and t.vertices(i)[0] >= 10000]
        if values:
            rows.append([tri, len(values), f"{median(values):.0f}", f"{max(values):.0f}"])
    return table(head, rows)


def problems(t):
    lines = []
    for inp in t.inputs:
        for tri, e in t.rows[inp].items():
            if isinstance(e, str):
                lines.append(f"- {inp} / {tri}: {e}")
            elif e.get("valid", 1) < 1:
                lines.append(f"- {inp} / {tri}: output rejected by pear::validate")
    return "\n".join(lines) + "\n" if lines else "None.\n"


def variants_used():
    return ", ".join(VARIANTS)
