"""Reading one run's JSON files (bench/run.sh writes them) into plain Python structures."""
import json
import os

SEQUENTIAL = ["pear_top", "pear_fast"]
PEERS = ["cgal_cdt", "geos_ear", "geos_cdt", "glu"]
CDT_PEERS = ["cgal_cdt", "geos_cdt"]
VARIANTS = ["pc", "mc", "dc", "auto"]
VARIANT_NAMES = {"pc": "partition-and-cut", "mc": "mark-and-cut", "dc": "divide-and-conquer",
                 "auto": "automatic"}
UNITS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def load_json(path, default=None):
    if not os.path.exists(path):
        return default
    with open(path) as f:
        return json.load(f)


class Timings:
    """bench_triangulate's results: for each input (in run order) and triangulator, a dict with
    ms (median wall-clock time) and the counters, or the error text of a skipped benchmark."""

    def __init__(self, path):
        data = load_json(path, {"benchmarks": [], "context": {}})
        self.context = data.get("context", {})
        self.inputs = []
        self.rows = {}
        for b in data["benchmarks"]:
            parts = b.get("run_name", b["name"]).removesuffix("/real_time").split("/")
            if len(parts) < 3:
                continue
            tri, inp = parts[-1], "/".join(parts[1:-1])
            if inp not in self.rows:
                self.rows[inp] = {}
                self.inputs.append(inp)
            row = self.rows[inp]
            if b.get("error_occurred"):
                row[tri] = b.get("error_message", "error")
            elif b.get("run_type") == "aggregate":
                if b.get("aggregate_name") == "median":
                    row[tri] = self._entry(b)
            elif tri not in row:
                row[tri] = self._entry(b)  # a run without repetitions

    @staticmethod
    def _entry(b):
        entry = {k: v for k, v in b.items() if isinstance(v, (int, float))}
        entry["ms"] = b["real_time"] * UNITS[b.get("time_unit", "ns")]
        entry["cpu_ms"] = b["cpu_time"] * UNITS[b.get("time_unit", "ns")]
        return entry

    def get(self, inp, tri):
        """The entry of a valid result, else None."""
        e = self.rows.get(inp, {}).get(tri)
        return e if isinstance(e, dict) and e.get("valid", 1) >= 1 else None

    def ms(self, inp, tri):
        e = self.get(inp, tri)
        return e["ms"] if e else None

    def vertices(self, inp):
        for e in self.rows[inp].values():
            if isinstance(e, dict):
                return int(e["vertices"]), int(e["holes"])
        return 0, 0

    def triangulators(self):
        seen = []
        for inp in self.inputs:
            seen += [t for t in self.rows[inp] if t not in seen]
        return seen

    def best(self, inp, candidates):
        """(name, ms) of the fastest valid result among candidates, or (None, None)."""
        found = [(self.ms(inp, t), t) for t in candidates if self.ms(inp, t) is not None]
        if not found:
            return None, None
        ms, name = min(found)
        return name, ms

    def parallel(self, threads, cdt=False):
        suffix = f"_t{threads}" + ("_cdt" if cdt else "")
        return [f"pear_{v}{suffix}" for v in VARIANTS]

    def invalid(self, inp, tri):
        e = self.rows.get(inp, {}).get(tri)
        return isinstance(e, dict) and e.get("valid", 1) < 1

    def error(self, inp, tri):
        e = self.rows.get(inp, {}).get(tri)
        return e if isinstance(e, str) else None


def load_run(stem):
    return {
        "machine": load_json(stem + "-machine.json", {}),
        "timings": Timings(stem + "-triangulate.json"),
        "ears": load_json(stem + "-ears.json", []),
        "quality": load_json(stem + "-quality.json", []),
        "profile": load_json(stem + "-profile.json", []),
    }


def median(values):
    values = sorted(v for v in values if v is not None)
    if not values:
        return None
    mid = len(values) // 2
    return values[mid] if len(values) % 2 else (values[mid - 1] + values[mid]) / 2
