// The WebAssembly build against the native one: for every bundled corpus polygon and several
// options, the same status and the same triangles, in the same order, as the `pear` CLI of the
// native build (PEAR_CLI; the meson test 'js' sets it) writes them. Skipped without the CLI.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';

import { Triangulator } from '../index.js';
import { bundledCorpus, folderPolygons } from './polygons.js';

const cli = process.env.PEAR_CLI;
const folders = ['earcut', 'countries', 'glyphs'];
const variants = [
  { name: 'defaults', options: {}, args: [] },
  { name: 'fast heuristic', options: { heuristic: 'fast' }, args: ['--heuristic', 'fast'] },
  { name: 'CDT', options: { cdt: true }, args: ['--cdt'] },
  { name: 'mark-and-cut', options: { algorithm: 'mark-and-cut' }, args: ['--algorithm', 'mark-and-cut'] },
];

// The CLI's statuses (--stats) and OBJ triangles (1-based) of every file in `folder`.
function native(folder, args) {
  const out = mkdtempSync(join(tmpdir(), 'pear-js-'));
  try {
    const run = spawnSync(cli, ['triangulate', '--keep-small-rings', '--threads', '1', '--stats',
      '--format', 'obj', '-o', `${out}/`, ...args, join(bundledCorpus, folder)], { encoding: 'utf8' });
    // 1: some inputs are not valid polygons (named on stderr); anything else is a failure.
    assert.ok(run.status === 0 || run.status === 1, `pear CLI exit ${run.status}: ${run.stderr}`);
    const results = new Map();
    for (const line of run.stdout.split('\n').filter(Boolean)) {
      const stats = JSON.parse(line);
      const name = stats.file.split('/').at(-1).replace(/\.json$/, '');
      const obj = readFileSync(join(out, `${name}.obj`), 'utf8').split('\n');
      const vertices = obj.filter((l) => l.startsWith('v ')).length;
      const triangles = obj.filter((l) => l.startsWith('f ')).flatMap((l) => l.slice(2).split(' ').map((i) => i - 1));
      results.set(name, { status: stats.status, vertices, triangles });
    }
    return results;
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
}

for (const variant of variants) {
  test(`same triangles as the native CLI: ${variant.name}`, { skip: !cli || !existsSync(cli) ? 'PEAR_CLI not set' : false }, () => {
    const triangulator = new Triangulator(variant.options);
    let compared = 0;
    for (const folder of folders) {
      const expected = native(folder, variant.args);
      for (const polygon of folderPolygons(join(bundledCorpus, folder))) {
        const want = expected.get(polygon.name);
        assert.ok(want, `${folder}/${polygon.name}: no result from the CLI`);
        const result = triangulator.triangulate(polygon.coords, polygon.holes);
        const where = `${folder}/${polygon.name} (${variant.name})`;
        assert.equal(polygon.coords.length / 2, want.vertices, `${where}: vertex count`);
        assert.equal(result.status, want.status, `${where}: status`);
        assert.deepEqual(Array.from(result.triangles), want.triangles, `${where}: triangles`);
        ++compared;
      }
    }
    assert.ok(compared >= 45, `only ${compared} polygons compared`);
  });
}
