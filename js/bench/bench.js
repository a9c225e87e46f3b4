// pear.wasm against earcut.js (the devDependency, 3.2.4) in one node process, per polygon, on
// the shared corpus (../shared/corpus, or PEAR_SHARED_CORPUS): CPU time, interleaved rounds;
// polygons/s from the median round, the ratios the median of each round's ratio; then pear's
// validator on every output of both. docs/benchmarks.md shows the figures.
//
//   node bench/bench.js [--rounds 5] [--sets counties,glyphs,...] [--limit N] [--baseline OLD.wasm]
// --baseline: another build of pear.wasm (`top`) in the same rounds, for a speed ratio that the
// load of the machine touches less than two runs' ratios.
import { readFileSync, existsSync } from 'node:fs';
import { join } from 'node:path';
import { gunzipSync } from 'node:zlib';

import earcut from 'earcut';

import { createPear, Triangulator, validate } from '../index.js';
import { geojsonPolygons } from '../test/polygons.js';

const corpus = process.env.PEAR_SHARED_CORPUS ?? new URL('../../../shared/corpus/', import.meta.url).pathname;
const sets = {
  counties: { folder: 'counties' },
  glyphs: { folder: 'glyphs' },
  countries: { folder: 'countries' },
  'Koch-8': { folder: 'synthetic', files: ['koch-8.json'] },
  comb: { folder: 'synthetic', files: ['comb-100000.json'] },
  'holes grid': { folder: 'synthetic', files: ['holes-100x100.json'] },
  Australia: { folder: 'coast', files: ['australia_gshhg_full.json.gz'] },
};

function option(name, fallback) {
  const at = process.argv.indexOf(`--${name}`);
  return at < 0 ? fallback : process.argv[at + 1];
}

function readPolygons({ folder, files }, limit) {
  const manifest = readFileSync(join(corpus, folder, 'MANIFEST.tsv'), 'utf8').split('\n').slice(1);
  const names = files ?? manifest.filter(Boolean).map((line) => line.split('\t')[0]);
  return names.slice(0, limit).flatMap((name) => {
    const bytes = readFileSync(join(corpus, folder, name));
    const text = (name.endsWith('.gz') ? gunzipSync(bytes) : bytes).toString('utf8');
    return geojsonPolygons(JSON.parse(text)).map((p) => ({ name, ...p, holesOrUndefined: p.holes.length ? p.holes : undefined }));
  });
}

const pearTop = new Triangulator();
const pearFast = new Triangulator({ heuristic: 'fast' });
const contenders = {
  'earcut.js': (p) => earcut(p.coords, p.holesOrUndefined).length,
  'pear fast': (p) => pearFast.triangulate(p.coords, p.holes).triangleCount,
  'pear top': (p) => pearTop.triangulate(p.coords, p.holes).triangleCount,
};
const baselineFile = option('baseline', undefined);
if (baselineFile) {
  const baseline = createPear(new WebAssembly.Module(readFileSync(baselineFile)));
  const baselineTop = new baseline.Triangulator();
  contenders['baseline top'] = (p) => baselineTop.triangulate(p.coords, p.holes).triangleCount;
}

// CPU seconds for one pass over the polygons (the passes repeated so a round takes >= 50 ms):
// each polygon once a pass, as a caller with many different polygons calls (the same polygon
// called again and again lets the branch predictor learn it).
function pass(run, polygons, repeat) {
  const start = process.cpuUsage();
  for (let r = 0; r < repeat; ++r) for (const p of polygons) run(p);
  const used = process.cpuUsage(start);
  return (used.user + used.system) / 1e6 / repeat;
}

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

// pear's validator on every output: how many of earcut's are not valid, how many polygons pear
// does not call ok (not simple: a best effort; invalid input), and how many it calls ok that
// are not valid (none, if pear keeps its promise).
function verdicts(polygons) {
  const outcome = { earcutInvalid: 0, pearNotOk: 0, pearOkInvalid: 0 };
  for (const p of polygons) {
    if (!validate(p.coords, p.holes, earcut(p.coords, p.holesOrUndefined)).valid) ++outcome.earcutInvalid;
    for (const triangulator of [pearFast, pearTop]) {
      const result = triangulator.triangulate(p.coords, p.holes);
      if (!result.ok) {
        if (triangulator === pearTop) ++outcome.pearNotOk;
        continue;
      }
      if (!validate(p.coords, p.holes, result.triangles.slice()).valid) ++outcome.pearOkInvalid;
    }
  }
  return outcome;
}

function benchmark(name, polygons, rounds) {
  const vertices = polygons.reduce((sum, p) => sum + p.coords.length / 2, 0);
  const times = Object.fromEntries(Object.keys(contenders).map((c) => [c, []]));
  // Warm up (three passes: earcut.js's code settles late), and find how often to repeat each
  // polygon for a pass of about 50 ms.
  const probe = pass(contenders['pear top'], polygons, 1);
  const repeat = Math.max(1, Math.ceil(0.05 / Math.max(probe, 1e-6)));
  const warmups = probe < 0.2 ? 3 : 1;
  for (let warm = 0; warm < warmups; ++warm) for (const run of Object.values(contenders)) pass(run, polygons, repeat);
  for (let round = 0; round < rounds; ++round) {
    const order = Object.keys(contenders);
    if (round % 2) order.reverse();
    for (const c of order) times[c].push(pass(contenders[c], polygons, repeat));
  }
  const perSecond = Object.fromEntries(Object.entries(times).map(([c, t]) => [c, polygons.length / median(t)]));
  // Speed over another contender: the median over rounds of the two passes' ratio in the same
  // round (side by side in time), steadier on a shared machine than the ratio of the medians.
  const over = (c, base) => median(times[c].map((t, round) => times[base][round] / t));
  return { name, polygons: polygons.length, vertices, perSecond, over, verdicts: verdicts(polygons) };
}

function format(value) {
  return value >= 100 ? Math.round(value).toLocaleString('en-US') : value.toPrecision(3);
}

const rounds = Number(option('rounds', 5));
const limit = option('limit', undefined) === undefined ? undefined : Number(option('limit'));
const chosen = option('sets', Object.keys(sets).join(',')).split(',');
console.log(`node ${process.version}, earcut.js ${JSON.parse(readFileSync(new URL('../node_modules/earcut/package.json', import.meta.url))).version}, ${rounds} rounds (median), CPU time`);
const againstBaseline = baselineFile ? ' top / baseline top |' : '';
console.log('| set | polygons | vertices | earcut.js polygons/s | pear fast | pear top | fast / earcut | top / earcut | earcut.js not valid | pear not ok | pear ok, not valid |' + againstBaseline);
console.log('|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|' + (baselineFile ? '---:|' : ''));
for (const name of chosen) {
  const set = sets[name];
  if (!set) throw new Error(`no set '${name}': ${Object.keys(sets).join(', ')}`);
  if (!existsSync(join(corpus, set.folder))) {
    console.log(`| ${name} | (missing: ${join(corpus, set.folder)}) |`);
    continue;
  }
  const r = benchmark(name, readPolygons(set, limit), rounds);
  const [e, f, t] = ['earcut.js', 'pear fast', 'pear top'].map((c) => r.perSecond[c]);
  const v = r.verdicts;
  console.log(`| ${name} | ${r.polygons} | ${r.vertices.toLocaleString('en-US')} | ${format(e)} | ${format(f)} | ${format(t)} | ` +
    `${r.over('pear fast', 'earcut.js').toFixed(2)}x | ${r.over('pear top', 'earcut.js').toFixed(2)}x | ${v.earcutInvalid} | ${v.pearNotOk} | ${v.pearOkInvalid} |` +
    (baselineFile ? ` ${r.over('pear top', 'baseline top').toFixed(3)}x |` : ''));
}
