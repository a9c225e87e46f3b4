// Where pear.wasm stands against earcut.js by polygon size: the polygons of one corpus folder
// (the counties by default) in classes of vertex counts, each class timed on its own, CPU time,
// the contenders interleaved round by round, medians. A small polygon's call is mostly fixed
// cost, a larger one's its work: docs/engine.md ("Small polygons in node") reads them apart.
//
//   node bench/sizes.js [--rounds 15] [--set counties] [--heuristic top] [--module NEW.wasm]
//                       [--baseline OLD.wasm [--baseline-first]]
// --module: a build of pear.wasm other than the package's. --baseline: another build in the
// same rounds (pear over it per class: the A/B of a change to the module, steadier than two
// runs' ratios on a shared machine). Two modules in one process do not run alike (the one
// instantiated second ran the smallest counties up to 8% slower): run the A/B again with
// --baseline-first and take the geometric mean of the two ratios.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

import earcut from 'earcut';

import { createPear } from '../index.js';
import { geojsonPolygons } from '../test/polygons.js';

function option(name, fallback) {
  const at = process.argv.indexOf(`--${name}`);
  return at < 0 ? fallback : process.argv[at + 1];
}

const corpus = process.env.PEAR_SHARED_CORPUS ?? new URL('../../../shared/corpus/', import.meta.url).pathname;
const rounds = Number(option('rounds', 15));
const set = option('set', 'counties');
const heuristic = option('heuristic', 'top');
const baselineFile = option('baseline', undefined);
const moduleFile = option('module', new URL('../pear.wasm', import.meta.url).pathname);
const baselineFirst = process.argv.includes('--baseline-first');

const folder = join(corpus, set);
const names = readFileSync(join(folder, 'MANIFEST.tsv'), 'utf8').split('\n').slice(1).filter(Boolean);
const polygons = names.flatMap((line) => geojsonPolygons(JSON.parse(readFileSync(join(folder, line.split('\t')[0]), 'utf8'))));
for (const p of polygons) p.holesOrUndefined = p.holes.length ? p.holes : undefined;

const triangulator = (file) => new (createPear(new WebAssembly.Module(readFileSync(file))).Triangulator)({ heuristic });
const baseline = baselineFile && baselineFirst ? triangulator(baselineFile) : null;
const pear = triangulator(moduleFile);
const contenders = {
  'earcut.js': (p) => earcut(p.coords, p.holesOrUndefined).length,
  pear: (p) => pear.triangulate(p.coords, p.holes).triangleCount,
};
if (baselineFile) {
  const old = baseline ?? triangulator(baselineFile);
  contenders.baseline = (p) => old.triangulate(p.coords, p.holes).triangleCount;
}

// Microseconds a polygon for one pass over `group`, the passes repeated for >= 30 ms.
const cpu = () => process.cpuUsage().user;
function perPolygon(call, group) {
  const start = cpu();
  let passes = 0;
  let sink = 0;
  while (cpu() - start < 30000) {
    for (const p of group) sink += call(p);
    ++passes;
  }
  if (sink < 0) throw new Error('unreachable');
  return (cpu() - start) / passes / group.length;
}
const median = (values) => [...values].sort((a, b) => a - b)[values.length >> 1];

// Warm-up: V8 compiles the module's hot functions again, optimized, once they have run a
// while (the first class timed cold ran 3-10x slow).
for (const call of Object.values(contenders)) perPolygon(call, polygons), perPolygon(call, polygons);

const classes = [[3, 8], [9, 16], [17, 32], [33, 64], [65, 1024], [1025, Infinity], [3, Infinity]];
const rows = [];
for (const [low, high] of classes) {
  const group = polygons.filter((p) => p.coords.length / 2 >= low && p.coords.length / 2 <= high);
  if (group.length === 0) continue;
  const times = Object.fromEntries(Object.keys(contenders).map((name) => [name, []]));
  const overEarcut = [];
  const overBaseline = [];
  for (let round = 0; round < rounds; ++round) {
    for (const [name, call] of Object.entries(contenders)) times[name].push(perPolygon(call, group));
    overEarcut.push(times['earcut.js'].at(-1) / times.pear.at(-1));
    if (baselineFile) overBaseline.push(times.baseline.at(-1) / times.pear.at(-1));
  }
  const vertices = group.reduce((sum, p) => sum + p.coords.length / 2, 0) / group.length;
  const label = high === Infinity ? (low === 3 ? 'all' : `${low}+`) : `${low}-${high}`;
  rows.push(`| ${label} | ${group.length} | ${vertices.toFixed(1)} | ${median(times['earcut.js']).toFixed(3)} | ` +
    `${median(times.pear).toFixed(3)} | ${median(overEarcut).toFixed(2)}x |` +
    (baselineFile ? ` ${median(overBaseline).toFixed(3)}x |` : ''));
}
console.log(`node ${process.version}, ${set}, pear ${heuristic}, ${rounds} rounds (medians), CPU time` +
  (baselineFile ? `, baseline ${baselineFile} instantiated ${baselineFirst ? 'first' : 'second'}` : ''));
console.log('| vertices | polygons | mean vertices | earcut.js us | pear us | pear over earcut.js |' +
  (baselineFile ? ' pear over baseline |' : ''));
console.log('|---|---:|---:|---:|---:|---:|' + (baselineFile ? '---:|' : ''));
for (const row of rows) console.log(row);
