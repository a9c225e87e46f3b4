// Every status and every issue pear reports, on inputs small enough to see by eye where the
// problem is (ring and vertex in the caller's numbering), and the validator's verdicts.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { STATUS, Triangulator, validate } from '../index.js';

const square = [0, 0, 4, 0, 4, 4, 0, 4];
const hole = [1, 1, 1, 3, 3, 3, 3, 1];

function run(coords, holes = null, options = {}) {
  const result = new Triangulator(options).triangulate(coords, holes);
  return { status: result.status, triangles: Array.from(result.triangles), diagnostics: result.diagnostics };
}

function issues(result) {
  return result.diagnostics.map(({ issue, ring, vertex }) => [issue, ring, vertex]);
}

test('the status names are pear::Status in order', () => {
  assert.deepEqual(STATUS, ['ok', 'not_simple', 'invalid_input', 'index_overflow']);
});

test('ok: a square with a hole, n + 2h - 2 triangles, valid', () => {
  const coords = [...square, ...hole];
  const result = run(coords, [4]);
  assert.equal(result.status, 'ok');
  assert.equal(result.triangles.length / 3, 8 + 2 - 2);
  assert.deepEqual(result.diagnostics, []);
  const report = validate(coords, [4], result.triangles);
  assert.equal(report.valid, true, report.messages.join('; '));
  assert.equal(report.areaRelError, 0);
});

test('not_simple: a bow tie names the crossing, with a best-effort triangulation', () => {
  const result = run([0, 0, 2, 2, 2, 0, 0, 2]);
  assert.equal(result.status, 'not_simple');
  assert.equal(result.diagnostics[0].issue, 'not_simple');
  assert.equal(result.diagnostics[0].ring, 0);
});

test('not_simple: a hole outside the outer ring, a hole inside a hole', () => {
  const outside = run([...square, 5, 5, 6, 5, 6, 6], [4]);
  assert.equal(outside.status, 'not_simple');
  assert.deepEqual(issues(outside), [['hole_outside_outer_ring', 1, 0]]);
  const inner = [1.5, 1.5, 1.5, 2.5, 2.5, 2.5];
  const nested = run([...square, ...hole, ...inner], [4, 8]);
  assert.equal(nested.status, 'not_simple');
  assert.deepEqual(issues(nested), [['hole_inside_hole', 2, 0]]);
});

test('invalid_input: NaN and infinity name their ring and vertex', () => {
  const nan = run([...square, ...hole.slice(0, 5), NaN, ...hole.slice(6)], [4]);
  assert.equal(nan.status, 'invalid_input');
  assert.deepEqual(issues(nan), [['non_finite_coordinate', 1, 2]]);
  assert.equal(nan.triangles.length, 0);
  assert.match(nan.diagnostics[0].message, /ring 1, vertex 2/);
  const infinite = run([0, 0, Infinity, 0, 4, 4]);
  assert.deepEqual(issues(infinite), [['non_finite_coordinate', 0, 1]]);
});

test('invalid_input: coordinates beyond 2^200, no vertices, a degenerate outer ring', () => {
  assert.deepEqual(issues(run([0, 0, 2 ** 201, 0, 4, 4])), [['coordinate_out_of_range', 0, 1]]);
  assert.deepEqual(issues(run([0, 0, 2 ** -201, 0, 4, 4])), [['coordinate_out_of_range', 0, 1]]);
  const empty = run([]);
  assert.equal(empty.status, 'invalid_input');
  assert.equal(empty.diagnostics[0].issue, 'empty_input');
  const line = run([0, 0, 1, 1, 2, 2]);
  assert.equal(line.status, 'invalid_input');
  assert.deepEqual(issues(line), [['outer_ring_too_small', 0, 0]]);
});

test('invalid_input: holes past the end or out of order are invalid offsets', () => {
  const past = run(square, [9]);
  assert.equal(past.status, 'invalid_input');
  assert.equal(past.diagnostics[0].issue, 'invalid_offsets');
  const backwards = run([...square, ...hole, ...hole], [8, 4]);
  assert.equal(backwards.status, 'invalid_input');
  assert.equal(backwards.diagnostics[0].issue, 'invalid_offsets');
});

test('warnings: small and zero-area holes dropped, a spike dissolved, a T-junction split', () => {
  const small = run([...square, 1, 1, 2, 2], [4]);
  assert.equal(small.status, 'ok');
  assert.deepEqual(issues(small), [['hole_dropped_too_small', 1, 0]]);
  const flat = run([...square, 1, 1, 2, 2, 3, 3], [4]);
  assert.equal(flat.status, 'ok');
  assert.deepEqual(issues(flat), [['hole_dropped_zero_area', 1, 0]]);
  // The outer ring goes out to (6, 2) and back: a zero-width spike whose tip is vertex 3.
  const spike = run([0, 0, 4, 0, 4, 2, 6, 2, 4, 2, 4, 4, 0, 4]);
  assert.equal(spike.status, 'ok');
  assert.deepEqual(issues(spike), [['spike_dissolved', 0, 3]]);
  assert.equal(spike.triangles.length / 3, 3);
  // The hole's vertex 0 lies inside the outer ring's edge from (0, 0) to (4, 0).
  const touching = run([...square, 2, 0, 3, 1, 1, 1], [4]);
  assert.equal(touching.status, 'ok');
  assert.deepEqual(issues(touching), [['t_junction_split', 1, 0]]);
  const report = validate([...square, 2, 0, 3, 1, 1, 1], [4], touching.triangles);
  assert.equal(report.valid, true, report.messages.join('; '));
});

test('index_overflow cannot happen here: wasm32 cannot hold 2^32 vertices', () => {
  // Status 3 exists for C++ callers asking for 16-bit indices; pear.wasm always returns uint32.
  assert.equal(STATUS[3], 'index_overflow');
});

test('CDT: the validator finds every interior edge locally Delaunay', () => {
  const coords = [0, 0, 10, 0, 10, 1, 5, 1.2, 0, 1, 0, 0.5];
  const plain = run(coords, null, { heuristic: 'fast' });
  const cdt = run(coords, null, { cdt: true });
  assert.equal(cdt.status, 'ok');
  assert.equal(validate(coords, null, cdt.triangles, { cdt: true }).valid, true);
  assert.equal(validate(coords, null, plain.triangles).valid, true);
});

test('validator: overlapping triangles, a gap, a clockwise triangle, indices out of range', () => {
  const overlap = validate(square, null, [0, 1, 2, 0, 1, 3]);
  assert.equal(overlap.valid, false);
  assert.ok(overlap.badEdges > 0);
  const gap = validate(square, null, [0, 1, 2]);
  assert.equal(gap.valid, false);
  const clockwise = validate(square, null, [0, 2, 1, 0, 3, 2]);
  assert.equal(clockwise.valid, false);
  assert.equal(clockwise.badOrientation, 2);
  const range = validate(square, null, [0, 1, 7, 0, 2, 3]);
  assert.equal(range.valid, false);
  assert.ok(range.messages.length > 0);
});
