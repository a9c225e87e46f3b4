// What each call of the package costs per polygon, on the counties of the shared corpus
// (../shared/corpus, or PEAR_SHARED_CORPUS): CPU time, the calls interleaved round by round,
// the median round. The README's "What a call costs" table comes from here.
//
//   node bench/calls.js [--rounds 9]
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

import earcut from 'earcut';

import { Triangulator, triangulate, triangulateBatch, validate } from '../index.js';
import { geojsonPolygons } from '../test/polygons.js';

const corpus = process.env.PEAR_SHARED_CORPUS ?? new URL('../../../shared/corpus/', import.meta.url).pathname;
const at = process.argv.indexOf('--rounds');
const rounds = at < 0 ? 9 : Number(process.argv[at + 1]);

const folder = join(corpus, 'counties');
const names = readFileSync(join(folder, 'MANIFEST.tsv'), 'utf8').split('\n').slice(1).filter(Boolean);
const polygons = names.flatMap((line) => geojsonPolygons(JSON.parse(readFileSync(join(folder, line.split('\t')[0]), 'utf8'))));
for (const p of polygons) p.holesOrUndefined = p.holes.length ? p.holes : undefined;

// The batch: every county in one call, GeoArrow's layout.
const coords = [];
const ringOffsets = [0];
const polygonOffsets = [0];
for (const p of polygons) {
  const base = coords.length / 2;
  coords.push(...p.coords);
  for (const h of p.holes) ringOffsets.push(base + h);
  ringOffsets.push(coords.length / 2);
  polygonOffsets.push(ringOffsets.length - 1);
}
const flat = Float64Array.from(coords);

const top = new Triangulator();
const fast = new Triangulator({ heuristic: 'fast' });
const out = new Uint32Array(3 * 10000);
const triangles = polygons.map((p) => top.triangulate(p.coords, p.holes).triangles.slice());
const each = (call) => () => polygons.forEach(call);
const calls = {
  'triangulate(coords, holes)': each((p) => triangulate(p.coords, p.holesOrUndefined)),
  'new Triangulator().triangulate + copyTrianglesTo': each((p) => top.triangulate(p.coords, p.holes).copyTrianglesTo(out)),
  "the same, heuristic 'fast'": each((p) => fast.triangulate(p.coords, p.holes).copyTrianglesTo(out)),
  'triangulateBatch (all counties in one call)': () => triangulateBatch(flat, ringOffsets, polygonOffsets),
  'validate(coords, holes, triangles)': () => polygons.forEach((p, i) => validate(p.coords, p.holes, triangles[i])),
  'earcut.js 3.2.4 (for comparison)': each((p) => earcut(p.coords, p.holesOrUndefined)),
};

function seconds(run) {
  const start = process.cpuUsage();
  run();
  const used = process.cpuUsage(start);
  return (used.user + used.system) / 1e6;
}

const times = Object.fromEntries(Object.keys(calls).map((c) => [c, []]));
for (let warm = 0; warm < 5; ++warm) for (const run of Object.values(calls)) run();
for (let round = 0; round < rounds; ++round) {
  const order = Object.keys(calls);
  if (round % 2) order.reverse();
  for (const c of order) times[c].push(seconds(calls[c]));
}
const vertices = polygons.reduce((sum, p) => sum + p.coords.length / 2, 0);
console.log(`node ${process.version}, ${polygons.length} counties (${(vertices / polygons.length).toFixed(1)} vertices each), ${rounds} rounds, median, CPU time`);
console.log('| call | us a polygon |');
console.log('|---|---:|');
for (const [c, t] of Object.entries(times)) {
  const median = [...t].sort((a, b) => a - b)[Math.floor(t.length / 2)];
  console.log(`| ${c} | ${((median / polygons.length) * 1e6).toFixed(2)} |`);
}
