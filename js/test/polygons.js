// Test and benchmark helpers: GeoJSON polygons as earcut's flat arrays, numbered as pear's
// readers number them (each ring's closing point, when it repeats the first, is dropped).
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

/** The repository's bundled corpus (corpus/, beside js/). */
export const bundledCorpus = fileURLToPath(new URL('../../corpus/', import.meta.url));

/** Flat coordinates and hole indices of a polygon given as rings of [x, y] points. */
export function flatten(rings) {
  const coords = [];
  const holes = [];
  for (const [r, ring] of rings.entries()) {
    if (r > 0) holes.push(coords.length / 2);
    const closed = ring.length > 1 && ring[0][0] === ring.at(-1)[0] && ring[0][1] === ring.at(-1)[1];
    const count = closed ? ring.length - 1 : ring.length;
    for (let i = 0; i < count; ++i) coords.push(ring[i][0], ring[i][1]);
  }
  return { coords: Float64Array.from(coords), holes };
}

/** The polygons of a GeoJSON text (Polygon, MultiPolygon, Feature, FeatureCollection). */
export function geojsonPolygons(value) {
  switch (value.type) {
    case 'FeatureCollection':
      return value.features.flatMap(geojsonPolygons);
    case 'Feature':
      return value.geometry ? geojsonPolygons(value.geometry) : [];
    case 'Polygon':
      return [flatten(value.coordinates)];
    case 'MultiPolygon':
      return value.coordinates.map(flatten);
    default:
      return [];
  }
}

/** The one polygon of each .json file in `folder` (the bundled corpus has one a file). */
export function folderPolygons(folder) {
  const polygons = [];
  for (const file of readdirSync(folder).sort()) {
    if (!file.endsWith('.json') || file === 'expected.json') continue;
    const [polygon] = geojsonPolygons(JSON.parse(readFileSync(join(folder, file), 'utf8')));
    polygons.push({ name: file.replace(/\.json$/, ''), ...polygon });
  }
  return polygons;
}

