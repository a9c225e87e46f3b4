// pear against earcut.js 3.2.4 (the devDependency) on the bundled corpus: wherever earcut's
// output is a valid triangulation by pear's validator, pear's is valid too, with the same
// triangle count and the exact area (the validator sums both areas exactly); wherever pear says
// ok, its output is valid, whatever earcut gives. (Where pear finds the rings crossing or
// overlapping, as in earcut's empty-square, whose hole is its outer ring, pear's answer is a
// best effort and not compared.) Skipped when earcut is not installed.
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { test } from 'node:test';

import { Triangulator, validate } from '../index.js';
import { bundledCorpus, folderPolygons } from './polygons.js';

let earcut = null;
try {
  earcut = (await import('earcut')).default;
} catch {
  // not installed: `npm ci` in js/ installs it
}
const skip = earcut ? false : 'earcut.js not installed (npm ci in js/)';

test('pear and earcut.js 3.2.4 on the bundled corpus', { skip }, (t) => {
  const pear = new Triangulator();
  let agreed = 0;
  let earcutInvalid = 0;
  for (const folder of ['earcut', 'countries', 'glyphs']) {
    for (const p of folderPolygons(join(bundledCorpus, folder))) {
      const where = `${folder}/${p.name}`;
      const theirs = earcut(p.coords, p.holes.length ? p.holes : undefined);
      const result = pear.triangulate(p.coords, p.holes);
      const ours = result.triangles.slice();
      const mine = validate(p.coords, p.holes, ours);
      if (result.ok) assert.ok(mine.valid, `${where}: pear says ok, the validator: ${mine.messages[0]}`);
      if (!validate(p.coords, p.holes, theirs).valid) {
        ++earcutInvalid;
        continue;
      }
      if (!result.ok) continue;
      assert.equal(ours.length, theirs.length, `${where}: triangle count`);
      assert.equal(mine.areaRelError, 0, `${where}: area`);
      ++agreed;
    }
  }
  // earcut.js drops collinear vertices (their boundary edges are then unused): every bundled
  // country and glyph has some, so the agreements are among earcut's own fixtures.
  t.diagnostic(`earcut.js valid and compared: ${agreed}; earcut.js not valid: ${earcutInvalid}`);
  assert.ok(agreed >= 10, `only ${agreed} polygons where earcut.js is valid`);
});
