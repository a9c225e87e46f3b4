// The package's size budget (issue 29): the .wasm under 300 KB. A change to the library that
// instantiates more for the web shows here first (a vector allocator once added 8.6 KB).
import assert from 'node:assert/strict';
import { statSync } from 'node:fs';
import { test } from 'node:test';

test('the .wasm is under 300 KB', () => {
  const bytes = statSync(new URL('../pear.wasm', import.meta.url)).size;
  assert.ok(bytes < 300_000, `pear.wasm is ${bytes} bytes`);
});
