// Types of pear-triangulate (index.js, core.js).

export type Status = 'ok' | 'not_simple' | 'invalid_input' | 'index_overflow';
export const STATUS: readonly Status[];

export interface Options {
  /** Default 'auto' (sequential at this size and one thread). */
  algorithm?: 'auto' | 'sequential' | 'partition-and-cut' | 'mark-and-cut' | 'divide-and-conquer';
  /** 'top' (default): near-CDT angles; 'fast': a walk along the boundary. */
  heuristic?: 'top' | 'fast';
  /** Make the triangulation constrained Delaunay by exact flips. */
  cdt?: boolean;
  /** Check exactly that no edges cross (default true); without it bad input may come back ok. */
  checkSimplicity?: boolean;
}

export interface Diagnostic {
  issue: string;
  /** 0: the outer ring, then the holes in order. */
  ring: number;
  /** The vertex within that ring, the caller's numbering. */
  vertex: number;
  message: string;
}

export interface Result {
  readonly status: Status;
  readonly ok: boolean;
  readonly statusCode: number;
  readonly triangleCount: number;
  readonly flips: number;
  /** A view of wasm memory, valid until the next call. */
  readonly triangles: Uint32Array;
  readonly diagnostics: Diagnostic[];
  copyTrianglesTo(target: Uint32Array | number[], offset?: number): number;
}

export type Coordinates = ArrayLike<number>;

export class Triangulator {
  constructor(options?: Options);
  readonly result: Result;
  triangulate(coords: Coordinates, holeIndices?: ArrayLike<number> | null, dim?: number): Result;
}

export function triangulate(coords: Coordinates, holeIndices?: ArrayLike<number> | null, dim?: number): Uint32Array;

export interface ValidationReport {
  valid: boolean;
  triangles: number;
  expectedTriangles: number;
  zeroAreaTriangles: number;
  badOrientation: number;
  badEdges: number;
  nonDelaunayEdges: number;
  areaRelError: number;
  messages: string[];
}

export function validate(
  coords: Coordinates,
  holeIndices: ArrayLike<number> | null,
  triangles: ArrayLike<number>,
  options?: { dim?: number; cdt?: boolean },
): ValidationReport;

export interface BatchResult {
  triangles: Uint32Array;
  triangleOffsets: Uint32Array;
  diagnosticOffsets: Uint32Array;
  status: Uint8Array;
  flips: number;
  diagnostics: (Diagnostic & { polygon: number })[];
}

export function triangulateBatch(
  coords: Coordinates,
  ringOffsets: ArrayLike<number>,
  polygonOffsets: ArrayLike<number>,
  options?: Options,
): BatchResult;

export class PearError extends Error {
  status: Status;
  diagnostics: Diagnostic[];
}

export const memory: WebAssembly.Memory;

export function createPear(module: WebAssembly.Module): {
  triangulate: typeof triangulate;
  validate: typeof validate;
  triangulateBatch: typeof triangulateBatch;
  Triangulator: typeof Triangulator;
  memory: WebAssembly.Memory;
};

export function optionBits(options?: Options): number;
