// The earcut-style entry, the batch, bad arguments, and memory: repeated calls must neither
// grow the wasm heap nor allocate on the JavaScript side once warm.
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { test } from 'node:test';

import { memory, PearError, triangulate, triangulateBatch, Triangulator, validate } from '../index.js';
import { bundledCorpus, folderPolygons } from './polygons.js';

const square = [0, 0, 4, 0, 4, 4, 0, 4];
const hole = [1, 1, 1, 3, 3, 3, 3, 1];

test("earcut's convention: flat arrays in, a Uint32Array of vertex indices out", () => {
  const triangles = triangulate([...square, ...hole], [4]);
  assert.ok(triangles instanceof Uint32Array);
  assert.equal(triangles.length, 3 * 8);
  assert.equal(validate([...square, ...hole], [4], triangles).valid, true);
  // dim 3: z is skipped, vertices are still numbered one per triple.
  const xyz = [0, 0, 9, 4, 0, 9, 4, 4, 9, 0, 4, 9];
  assert.deepEqual(Array.from(triangulate(xyz, null, 3)).sort(), Array.from(triangulate(square)).sort());
  assert.equal(triangulate(square, []).length, 6);
  assert.equal(triangulate(new Float64Array(square)).length, 6);
});

test('bad arguments: a clear error that names what is wrong', () => {
  assert.throws(() => triangulate([0, 0, 1, 0, 1]), /coords has 5 numbers, not a multiple of dim 2/);
  assert.throws(() => triangulate(square, null, 1), /dim must be an integer >= 2/);
  assert.throws(() => triangulate(square, null, 2.5), /dim must be an integer >= 2/);
  assert.throws(() => triangulate(null), /coords must be an array/);
  assert.throws(() => triangulate(square, [1.5]), /holeIndices\[0\] is 1.5, not a vertex index/);
  assert.throws(() => triangulate(square, [-1]), /holeIndices\[0\] is -1/);
  assert.throws(() => new Triangulator({ heuristic: 'best' }), /heuristic 'best' is not 'top' or 'fast'/);
  assert.throws(() => new Triangulator({ algoritm: 'sequential' }), /unknown option 'algoritm'/);
  assert.throws(() => new Triangulator({ algorithm: 'greedy' }), /algorithm 'greedy' is not one of/);
  assert.throws(() => validate(square, null, [0, 1]), /triangles has 2 indices, not a multiple of 3/);
  assert.throws(() => validate(square, null, [0, 1, 2.5]), /triangles\[2\] is 2.5, not a vertex index/);
});

test('bad input: triangulate throws a PearError with the status and the place', () => {
  const nan = () => triangulate([...square, 1, 1, NaN, 3, 3, 3], [4]);
  assert.throws(nan, (error) => {
    assert.ok(error instanceof PearError);
    assert.equal(error.status, 'invalid_input');
    assert.match(error.message, /ring 1, vertex 1: coordinate is NaN or infinite/);
    assert.equal(error.diagnostics[0].issue, 'non_finite_coordinate');
    return true;
  });
  assert.throws(() => triangulate(square, [7]), (error) => {
    assert.equal(error.diagnostics[0].issue, 'invalid_offsets');
    assert.match(error.message, /holeIndices must rise, each at most 4/);
    return true;
  });
  // Not simple is no error here (earcut's convention): the best effort comes back.
  assert.equal(triangulate([0, 0, 2, 2, 2, 0, 0, 2]).length % 3, 0);
});

test('batch: the same triangles as one polygon at a time, offset into the batch', () => {
  const polygons = ['countries', 'glyphs'].flatMap((f) => folderPolygons(join(bundledCorpus, f)));
  const coords = [];
  const rings = [0];
  const parts = [0];
  for (const p of polygons) {
    const base = coords.length / 2;
    coords.push(...p.coords);
    for (const h of p.holes) rings.push(base + h);
    rings.push(coords.length / 2);
    parts.push(rings.length - 1);
  }
  const batch = triangulateBatch(coords, rings, parts, { heuristic: 'fast' });
  const one = new Triangulator({ heuristic: 'fast' });
  let base = 0;
  for (const [i, p] of polygons.entries()) {
    const single = one.triangulate(p.coords, p.holes);
    assert.equal(batch.status[i], single.statusCode, p.name);
    const mine = batch.triangles.subarray(3 * batch.triangleOffsets[i], 3 * batch.triangleOffsets[i + 1]);
    assert.deepEqual(Array.from(mine, (v) => v - base), Array.from(single.triangles), p.name);
    base += p.coords.length / 2;
  }
});

test('batch: bad offsets give that polygon invalid_input, the others are triangulated', () => {
  const coords = [...square, ...square];
  const batch = triangulateBatch(coords, [0, 4, 9], [0, 1, 2]);
  assert.deepEqual(Array.from(batch.status), [0, 2]);
  assert.equal(batch.triangleOffsets[1] - batch.triangleOffsets[0], 2);
  assert.deepEqual(batch.diagnostics.map((d) => [d.polygon, d.issue]), [[1, 'invalid_offsets']]);
  assert.throws(() => triangulateBatch(coords, [], [0]), /ringOffsets needs at least one entry/);
  assert.throws(() => triangulateBatch(coords, [0, 4.5], [0, 1]), /ringOffsets\[1\] is 4.5, not an index/);
  assert.throws(() => triangulateBatch([0, 0, 1], [0, 1], [0, 1]), /not x, y pairs/);
});

test('memory: repeated calls (single, batch, validator) do not grow the wasm heap once warm', () => {
  const polygons = ['earcut', 'countries', 'glyphs'].flatMap((f) => folderPolygons(join(bundledCorpus, f)));
  const triangulators = [new Triangulator(), new Triangulator({ heuristic: 'fast', cdt: true })];
  const batch = { coords: [], rings: [0], parts: [0] };
  for (const p of polygons.slice(0, 20)) {
    const base = batch.coords.length / 2;
    batch.coords.push(...p.coords);
    for (const h of p.holes) batch.rings.push(base + h);
    batch.rings.push(batch.coords.length / 2);
    batch.parts.push(batch.rings.length - 1);
  }
  const once = () => {
    for (const p of polygons) {
      for (const t of triangulators) validate(p.coords, p.holes, t.triangulate(p.coords, p.holes).triangles.slice());
      triangulate(p.coords, p.holes.length ? p.holes : null);
    }
    triangulateBatch(batch.coords, batch.rings, batch.parts);
  };
  const safely = () => {
    try {
      once();
    } catch (error) {
      if (!(error instanceof PearError)) throw error;
    }
  };
  for (let i = 0; i < 3; ++i) safely();
  const warm = memory.buffer.byteLength;
  for (let i = 0; i < 20; ++i) safely();
  assert.equal(memory.buffer.byteLength, warm);
});

// The loader keeps typed views of wasm memory and makes them again only once memory grew (its
// old buffer is then detached): a result read after a call that grew the heap must be read
// through the new views, in every kind of call.
test('memory: results stay right across calls that grow the heap', () => {
  const square = [0, 0, 4, 0, 4, 4, 0, 4];
  const t = new Triangulator();
  const small = t.triangulate(square).triangles.slice();
  assert.equal(small.length, 6);
  const grow = (vertices) => {
    const circle = new Float64Array(2 * vertices);
    for (let i = 0; i < vertices; ++i) {
      circle[2 * i] = Math.cos((2 * Math.PI * i) / vertices);
      circle[2 * i + 1] = Math.sin((2 * Math.PI * i) / vertices);
    }
    return circle;
  };
  const before = memory.buffer.byteLength;
  const circle = grow(Math.ceil(before / 16) + 1000);  // its points alone outgrow the heap
  const result = t.triangulate(circle);
  assert.ok(memory.buffer.byteLength > before);
  assert.equal(result.status, 'ok');
  const indices = result.triangles;
  assert.equal(indices.length, 3 * (circle.length / 2 - 2));
  assert.ok(indices.every((v) => v < circle.length / 2));
  const out = new Uint32Array(indices.length);
  assert.equal(result.copyTrianglesTo(out), indices.length);
  assert.deepEqual(out, indices);
  assert.deepEqual(t.triangulate(square).triangles, small);
  assert.deepEqual(triangulate(square), small);
  const again = memory.buffer.byteLength;
  const larger = grow(Math.ceil(again / 16) + 1000);
  assert.equal(triangulate(larger).length, 3 * (larger.length / 2 - 2));
  assert.ok(memory.buffer.byteLength > again);
  assert.equal(validate(square, null, small).valid, true);
});

test('no allocation on the JavaScript side: Triangulator.triangulate + copyTrianglesTo', (t) => {
  if (typeof globalThis.gc !== 'function') {
    t.skip('needs node --expose-gc');
    return;
  }
  const polygon = folderPolygons(join(bundledCorpus, 'earcut')).find((p) => p.name === 'building');
  const triangulator = new Triangulator();
  const out = new Uint32Array(3 * polygon.coords.length);
  const loop = (calls) => {
    let sum = 0;
    for (let i = 0; i < calls; ++i) {
      const result = triangulator.triangulate(polygon.coords, polygon.holes);
      sum += triangulator.result.copyTrianglesTo(out) + result.statusCode;
    }
    return sum;
  };
  const calls = 20000;
  // The least growth of five rounds: until the optimizing compiler has run (two rounds or so)
  // numbers are boxed on the heap; an allocation in every call would show in every round.
  let grown = Infinity;
  for (let round = 0; round < 5; ++round) {
    loop(calls);
    globalThis.gc();
    const before = process.memoryUsage().heapUsed;
    loop(calls);
    grown = Math.min(grown, process.memoryUsage().heapUsed - before);
  }
  assert.ok(grown < calls, `${grown} bytes for ${calls} calls`);
});

test('random input never traps: an answer, a PearError or an argument error, indices in range', () => {
  let seed = 12345;
  const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const specials = [NaN, Infinity, -Infinity, 0, -0, 2 ** 201, 2 ** -201, 1e-300, 5e-324];
  const triangulator = new Triangulator({ cdt: true });
  for (let round = 0; round < 2000; ++round) {
    const vertices = Math.floor(random() * 40);
    const coords = Array.from({ length: 2 * vertices }, () =>
      random() < 0.02 ? specials[Math.floor(random() * specials.length)] : Math.floor(random() * 8));
    const holes = [];
    for (let h = Math.floor(random() * 4); h > 0; --h) holes.push(Math.floor(random() * (vertices + 3)));
    if (random() < 0.7) holes.sort((a, b) => a - b);
    const result = triangulator.triangulate(coords, holes);
    assert.ok(['ok', 'not_simple', 'invalid_input'].includes(result.status), result.status);
    for (const index of result.triangles) assert.ok(index < vertices, `index ${index} of ${vertices}`);
    if (result.ok) assert.equal(validate(coords, holes, result.triangles.slice(), { cdt: true }).valid, true);
    try {
      triangulate(coords, holes);
    } catch (error) {
      assert.ok(error instanceof PearError, String(error));
    }
  }
});
