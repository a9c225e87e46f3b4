// pear's JavaScript API over its WebAssembly module (wasm/exports.cpp). No runtime
// dependencies and no WASI runtime: the few WASI imports wasi-libc keeps are stubbed here.
// index.js loads pear.wasm (node or a browser) and calls createPear.

/** Statuses by code, as pear::Status numbers them. */
export const STATUS = Object.freeze(['ok', 'not_simple', 'invalid_input', 'index_overflow']);

const ALGORITHMS = Object.freeze({
  auto: 0,
  sequential: 1,
  'partition-and-cut': 2,
  'mark-and-cut': 3,
  'divide-and-conquer': 4,
});
const HEURISTICS = Object.freeze({ top: 0, fast: 8 });
const OPTION_NAMES = new Set(['algorithm', 'heuristic', 'cdt', 'checkSimplicity']);
const BATCH_FIELDS = 3; // BatchResults: triangle_offsets, diagnostic_offsets, status
const REPORT_FIELDS = 8; // Report's uint32 fields before the area error
const NO_ROOM = Object.freeze({ points: -1, offsets: -1, pointsAt: 0, offsetsAt: 0 });

/** Thrown for arguments pear cannot take, and by triangulate() for input it cannot triangulate. */
export class PearError extends Error {
  constructor(message, status = 'invalid_input', diagnostics = []) {
    super(message);
    this.name = 'PearError';
    this.status = status;
    this.diagnostics = diagnostics;
  }
}

/** The option bits of wasm/exports.cpp's options_from, from { algorithm, heuristic, cdt, checkSimplicity }. */
export function optionBits(options = {}) {
  if (options === null || typeof options !== 'object') {
    throw new TypeError('pear: options must be an object');
  }
  for (const key of Object.keys(options)) {
    if (!OPTION_NAMES.has(key)) throw new TypeError(`pear: unknown option '${key}'`);
  }
  const { algorithm = 'auto', heuristic = 'top', cdt = false, checkSimplicity = true } = options;
  if (!(algorithm in ALGORITHMS)) {
    throw new TypeError(`pear: algorithm '${algorithm}' is not one of ${Object.keys(ALGORITHMS).join(', ')}`);
  }
  if (!(heuristic in HEURISTICS)) {
    throw new TypeError(`pear: heuristic '${heuristic}' is not 'top' or 'fast'`);
  }
  return ALGORITHMS[algorithm] | HEURISTICS[heuristic] | (cdt ? 16 : 0) | (checkSimplicity ? 0 : 32);
}

// The WASI functions wasi-libc still imports once pear's exports are linked (stdio for an abort
// message, the clock for std::chrono); anything else answers ENOSYS.
function wasiImports(module, memory) {
  const ENOSYS = 52;
  const ESPIPE = 70;
  const decoder = new TextDecoder();
  const own = {
    fd_write(fd, iovs, count, written) {
      const view = new DataView(memory().buffer);
      let text = '';
      let total = 0;
      for (let i = 0; i < count; ++i) {
        const base = view.getUint32(iovs + 8 * i, true);
        const length = view.getUint32(iovs + 8 * i + 4, true);
        text += decoder.decode(new Uint8Array(memory().buffer, base, length));
        total += length;
      }
      (fd === 2 ? console.error : console.log)(text.replace(/\n$/, ''));
      view.setUint32(written, total, true);
      return 0;
    },
    fd_close: () => 0,
    fd_seek: () => ESPIPE,
    clock_time_get(id, precision, time) {
      const nanoseconds = BigInt(Math.round(performance.now() * 1e6));
      new DataView(memory().buffer).setBigUint64(time, nanoseconds, true);
      return 0;
    },
  };
  const wasi = {};
  for (const { module: from, name } of WebAssembly.Module.imports(module)) {
    if (from === 'wasi_snapshot_preview1') wasi[name] = own[name] ?? (() => ENOSYS);
  }
  return { wasi_snapshot_preview1: wasi };
}

/** pear on a compiled WebAssembly.Module of pear.wasm (synchronous). */
export function createPear(module) {
  let instance = null;
  const memory = () => instance.exports.memory;
  instance = new WebAssembly.Instance(module, wasiImports(module, memory));
  instance.exports._initialize();
  const pear = new Pear(instance.exports);
  return {
    triangulate: pear.triangulate.bind(pear),
    validate: pear.validate.bind(pear),
    triangulateBatch: pear.triangulateBatch.bind(pear),
    Triangulator: class extends Triangulator {
      constructor(options) {
        super(pear, options);
      }
    },
    memory: instance.exports.memory,
  };
}

// Typed views of wasm memory, made again only when memory grew. Growing detaches the old
// buffer, which leaves its views empty: asking a view's length is much cheaper than the
// memory.buffer getter (a county's call asked it three times: 4% of its time in node 20).
class Heap {
  constructor(memory) {
    this.memory = memory;
    this.refresh();
  }
  refresh() {
    if (this.u8 && this.u8.length !== 0) return this;
    const buffer = this.memory.buffer;
    this.u8 = new Uint8Array(buffer);
    this.u32 = new Uint32Array(buffer);
    this.f64 = new Float64Array(buffer);
    return this;
  }
  text(address) {
    const end = this.u8.indexOf(0, address);
    return new TextDecoder().decode(this.u8.subarray(address, end));
  }
}

function checkDim(dim) {
  if (!Number.isInteger(dim) || dim < 2) throw new TypeError(`pear: dim must be an integer >= 2, not ${dim}`);
}

function checkArrayLike(value, name) {
  if (value == null || typeof value.length !== 'number') {
    throw new TypeError(`pear: ${name} must be an array or typed array`);
  }
}

/** The result of Triangulator.triangulate: reused by every call, valid until the next. */
class Result {
  constructor(pear) {
    this.pear = pear;
    this.statusCode = 0;
    this.triangleCount = 0;
    this.diagnosticCount = 0;
    this.flips = 0;
    this.address = 0;
    this.diagnosticAddress = 0;
  }
  /** 'ok', 'not_simple' (best effort triangles), 'invalid_input' or 'index_overflow'. */
  get status() {
    return STATUS[this.statusCode];
  }
  get ok() {
    return this.statusCode === 0;
  }
  /** The triangles as vertex indices, 3 a triangle: a view of wasm memory, valid until the next call. */
  get triangles() {
    return this.pear.heap.refresh().u32.subarray(this.address >>> 2, (this.address >>> 2) + 3 * this.triangleCount);
  }
  /** Copies the triangles' indices into `target` from `offset` (no allocation); returns how many. */
  copyTrianglesTo(target, offset = 0) {
    const count = 3 * this.triangleCount;
    if (target.length - offset < count) {
      throw new RangeError(`pear: the target has room for ${target.length - offset} indices, not ${count}`);
    }
    const u32 = this.pear.heap.refresh().u32;
    const first = this.address >>> 2;
    for (let i = 0; i < count; ++i) target[offset + i] = u32[first + i];
    return count;
  }
  /** What pear found: [{ issue, ring, vertex, message }], ring 0 the outer ring. */
  get diagnostics() {
    return this.pear.readDiagnostics(this.diagnosticAddress, 0, this.diagnosticCount);
  }
}

class Pear {
  constructor(exports) {
    this.exports = exports;
    this.heap = new Heap(exports.memory);
    this.room = NO_ROOM;
  }

  // Copies x and y of every vertex and the ring offsets (0, the holes' starts, the vertex
  // count) into the module's buffers; returns the vertex count.
  writePolygon(coords, holeIndices, dim) {
    checkArrayLike(coords, 'coords');
    checkDim(dim);
    if (coords.length % dim !== 0) {
      throw new RangeError(`pear: coords has ${coords.length} numbers, not a multiple of dim ${dim}`);
    }
    const vertices = coords.length / dim;
    const holes = holeIndices == null ? 0 : holeIndices.length;
    if (holeIndices != null) checkArrayLike(holeIndices, 'holeIndices');
    // The module's buffers only grow: room made once serves every polygon that fits, with no
    // call (a tenth of a small polygon's call in node).
    if (vertices > this.room.points || holes + 2 > this.room.offsets) this.makeRoom(vertices, holes + 2);
    const { u32, f64 } = this.heap.refresh();
    const points = this.room.pointsAt;
    const offsets = this.room.offsetsAt;
    if (dim === 2) {
      f64.set(coords, points);
    } else {
      for (let v = 0; v < vertices; ++v) {
        f64[points + 2 * v] = coords[dim * v];
        f64[points + 2 * v + 1] = coords[dim * v + 1];
      }
    }
    u32[offsets] = 0;
    for (let h = 0; h < holes; ++h) {
      const start = holeIndices[h];
      if (!Number.isInteger(start) || start < 0 || start > 0xffffffff) {
        throw new RangeError(`pear: holeIndices[${h}] is ${start}, not a vertex index`);
      }
      u32[offsets + 1 + h] = start;
    }
    u32[offsets + holes + 1] = vertices;
    return vertices;
  }

  // Room in the module for `points` points and `offsets` ring offsets (pear_polygon).
  makeRoom(points, offsets) {
    const room = this.exports.pear_polygon(points, offsets) >>> 2;
    const u32 = this.heap.refresh().u32;
    this.room = {
      points: Math.max(points, this.room.points),
      offsets: Math.max(offsets, this.room.offsets),
      pointsAt: u32[room] >>> 3,
      offsetsAt: u32[room + 1] >>> 2,
    };
  }

  // Runs pear_triangulate on the polygon written by writePolygon and fills `result`.
  run(vertices, holes, bits, result) {
    const at = this.exports.pear_triangulate(vertices, holes + 2, bits) >>> 2;
    const u32 = this.heap.refresh().u32;
    result.statusCode = u32[at];
    result.address = u32[at + 1];
    result.triangleCount = u32[at + 2];
    result.diagnosticAddress = u32[at + 3];
    result.diagnosticCount = u32[at + 4];
    result.flips = u32[at + 5];
    return result;
  }

  /**
   * earcut's convention: flat coordinates, the holes' first vertex indices, numbers per vertex;
   * returns the triangles as a Uint32Array of vertex indices. Input that is not a simple polygon
   * gets pear's best effort (Triangulator says so); input that cannot be triangulated at all
   * (NaN, holes past the end, ...) throws a PearError naming the ring and vertex.
   */
  triangulate(coords, holeIndices = null, dim = 2) {
    this.earcutResult ??= new Result(this);
    const vertices = this.writePolygon(coords, holeIndices, dim);
    const holes = holeIndices == null ? 0 : holeIndices.length;
    const result = this.run(vertices, holes, 0, this.earcutResult);
    if (result.statusCode >= 2) {
      const diagnostics = result.diagnostics;
      const where = diagnostics.find((d) => d.issue !== 'hole_dropped_too_small') ?? diagnostics[0];
      const hint = where?.issue === 'invalid_offsets' ? ` (holeIndices must rise, each at most ${vertices})` : '';
      throw new PearError(`pear: ${where ? where.message : result.status}${hint}`, result.status, diagnostics);
    }
    const first = result.address >>> 2;
    return this.heap.refresh().u32.slice(first, first + 3 * result.triangleCount);  // one allocation
  }

  /**
   * pear's independent validator on triangles (vertex indices, 3 a triangle) of the polygon
   * given as for triangulate. options: { dim = 2, cdt = false (also require a CDT) }.
   */
  validate(coords, holeIndices, triangles, { dim = 2, cdt = false } = {}) {
    const vertices = this.writePolygon(coords, holeIndices, dim);
    const holes = holeIndices == null ? 0 : holeIndices.length;
    checkArrayLike(triangles, 'triangles');
    if (triangles.length % 3 !== 0) {
      throw new RangeError(`pear: triangles has ${triangles.length} indices, not a multiple of 3`);
    }
    for (let i = 0; i < triangles.length; ++i) {
      const index = triangles[i];
      if (!Number.isInteger(index) || index < 0 || index > 0xffffffff) {
        throw new RangeError(`pear: triangles[${i}] is ${index}, not a vertex index`);
      }
    }
    const input = this.exports.pear_triangle_input(triangles.length / 3) >>> 2;
    this.heap.refresh().u32.set(triangles, input);
    const at = this.exports.pear_validate(vertices, holes + 2, triangles.length / 3, cdt ? 1 : 0);
    const { u32, f64 } = this.heap.refresh();
    const fields = Array.from(u32.subarray(at >>> 2, (at >>> 2) + REPORT_FIELDS));
    const [valid, count, expected, zeroArea, badOrientation, badEdges, nonDelaunay, messages] = fields;
    const report = {
      valid: valid !== 0,
      triangles: count,
      expectedTriangles: expected,
      zeroAreaTriangles: zeroArea,
      badOrientation,
      badEdges,
      nonDelaunayEdges: nonDelaunay,
      areaRelError: f64[(at + 4 * REPORT_FIELDS) >>> 3],
      messages: [],
    };
    for (let m = 0; m < messages; ++m) {
      report.messages.push(this.heap.refresh().text(this.exports.pear_validation_message(m)));
    }
    return report;
  }

  /**
   * Many polygons in one call, GeoArrow's layout: coords x, y interleaved; ring r is vertices
   * [ringOffsets[r], ringOffsets[r + 1]); polygon p is rings [polygonOffsets[p],
   * polygonOffsets[p + 1]), its outer ring first. Returns copies: triangles (indices into all the
   * vertices), triangleOffsets and diagnosticOffsets (per polygon, in triangles and
   * diagnostics), status (a code per polygon, STATUS names them) and diagnostics.
   */
  triangulateBatch(coords, ringOffsets, polygonOffsets, options = {}) {
    const bits = optionBits(options);
    checkArrayLike(coords, 'coords');
    if (coords.length % 2 !== 0) throw new RangeError(`pear: coords has ${coords.length} numbers, not x, y pairs`);
    for (const [offsets, name] of [[ringOffsets, 'ringOffsets'], [polygonOffsets, 'polygonOffsets']]) {
      checkArrayLike(offsets, name);
      if (offsets.length === 0) throw new RangeError(`pear: ${name} needs at least one entry (0)`);
      for (let i = 0; i < offsets.length; ++i) {
        const offset = offsets[i];
        if (!Number.isInteger(offset) || offset < 0 || offset > 0xffffffff) {
          throw new RangeError(`pear: ${name}[${i}] is ${offset}, not an index`);
        }
      }
    }
    const vertices = coords.length / 2;
    this.heap.refresh();
    const points = this.exports.pear_points(vertices) >>> 3;
    this.room = NO_ROOM; // the points may have moved: writePolygon asks again
    const offsets = this.exports.pear_batch_offsets(ringOffsets.length + polygonOffsets.length) >>> 2;
    const { u32, f64 } = this.heap.refresh();
    f64.set(coords, points);
    u32.set(ringOffsets, offsets);
    u32.set(polygonOffsets, offsets + ringOffsets.length);
    const polygons = polygonOffsets.length - 1;
    const at = this.exports.pear_triangulate_batch(vertices, ringOffsets.length - 1, polygons, bits) >>> 2;
    return this.readBatch(at, polygons);
  }

  readBatch(at, polygons) {
    const { u8, u32 } = this.heap.refresh();
    const results = this.exports.pear_results() >>> 2;
    const [triangleOffsets, diagnosticOffsets, status] = u32.subarray(at, at + BATCH_FIELDS);
    const triangles = u32.slice(u32[results + 1] >>> 2, (u32[results + 1] >>> 2) + 3 * u32[results + 2]);
    const batch = {
      triangles,
      triangleOffsets: u32.slice(triangleOffsets >>> 2, (triangleOffsets >>> 2) + polygons + 1),
      diagnosticOffsets: u32.slice(diagnosticOffsets >>> 2, (diagnosticOffsets >>> 2) + polygons + 1),
      status: u8.slice(status, status + polygons),
      flips: u32[results + 5],
      diagnostics: [],
    };
    const diagnostics = this.readDiagnostics(u32[results + 3], 0, u32[results + 4]);
    for (let p = 0; p < polygons; ++p) {
      for (let d = batch.diagnosticOffsets[p]; d < batch.diagnosticOffsets[p + 1]; ++d) {
        batch.diagnostics.push({ polygon: p, ...diagnostics[d] });
      }
    }
    return batch;
  }

  readDiagnostics(address, first, end) {
    const diagnostics = [];
    for (let d = first; d < end; ++d) {
      const u32 = this.heap.refresh().u32;
      const at = (address >>> 2) + 3 * d;
      const [code, ring, vertex] = [u32[at], u32[at + 1], u32[at + 2]];
      const issue = this.heap.text(this.exports.pear_issue_name(code));
      const message = this.heap.refresh().text(this.exports.pear_describe(code, ring, vertex));
      diagnostics.push({ issue, ring, vertex, message });
    }
    return diagnostics;
  }
}

/** A reusable triangulator with fixed options; its result object is reused by every call. */
class Triangulator {
  constructor(pear, options = {}) {
    this.pear = pear;
    this.bits = optionBits(options);
    this.result = new Result(pear);
  }
  /**
   * Triangulates flat coordinates (dim numbers a vertex, x and y first) with holes starting at
   * the vertex indices holeIndices; returns the reused Result: status, triangles, diagnostics.
   */
  triangulate(coords, holeIndices = null, dim = 2) {
    const vertices = this.pear.writePolygon(coords, holeIndices, dim);
    const holes = holeIndices == null ? 0 : holeIndices.length;
    return this.pear.run(vertices, holes, this.bits, this.result);
  }
}
