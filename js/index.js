// pear for JavaScript: polygon triangulation (exact ear clipping, CDT, a validator) in
// WebAssembly. Loads pear.wasm beside this file, in node (fs) or a browser (fetch), once, at
// import; createPear (core.js) takes an already compiled module instead.
//
//   import { triangulate } from 'pear-triangulate';
//   const triangles = triangulate([0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 1, 2, 2, 2], [4]);
import { createPear } from './core.js';

export { createPear, optionBits, PearError, STATUS } from './core.js';

async function loadModule(url) {
  if (typeof process !== 'undefined' && process.versions?.node) {
    const { readFile } = await import('node:fs/promises');
    return WebAssembly.compile(await readFile(url));
  }
  if (WebAssembly.compileStreaming) {
    return WebAssembly.compileStreaming(fetch(url));
  }
  return WebAssembly.compile(await (await fetch(url)).arrayBuffer());
}

const pear = createPear(await loadModule(new URL('./pear.wasm', import.meta.url)));

/** earcut's convention: triangulate(coords, holeIndices, dim) -> Uint32Array of vertex indices. */
export const triangulate = pear.triangulate;
/** pear's validator: validate(coords, holeIndices, triangles, { dim, cdt }) -> report. */
export const validate = pear.validate;
/** Many polygons: triangulateBatch(coords, ringOffsets, polygonOffsets, options). */
export const triangulateBatch = pear.triangulateBatch;
/** new Triangulator({ algorithm, heuristic, cdt, checkSimplicity }).triangulate(coords, holeIndices, dim). */
export const Triangulator = pear.Triangulator;
/** The module's memory (its buffer's size shows what pear holds). */
export const memory = pear.memory;
