// The README's JavaScript blocks marked <!-- test: run --> run as written, with the package's
// name pointing at this folder's index.js: the example users copy keeps working.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

const readme = readFileSync(new URL('../../README.md', import.meta.url), 'utf8').split('\n');
const blocks = [];
for (let i = 0; i < readme.length; ++i) {
  if (readme[i].trim() !== '```js') continue;
  const end = readme.indexOf('```', i + 1);
  blocks.push({ line: i + 1, marked: readme[i - 1]?.trim() === '<!-- test: run -->', code: readme.slice(i + 1, end).join('\n') });
  i = end;
}

test('the README has a JavaScript example, every block marked to run', () => {
  assert.ok(blocks.length > 0, 'no ```js block in README.md');
  for (const block of blocks) assert.ok(block.marked, `README.md:${block.line} is not marked <!-- test: run -->`);
});

for (const block of blocks) {
  test(`README.md:${block.line} runs`, async () => {
    const index = new URL('../index.js', import.meta.url).href;
    const code = block.code.replaceAll("from 'pear-triangulate'", `from '${index}'`);
    const logged = [];
    const log = console.log;
    console.log = (...args) => logged.push(args);
    try {
      await import(`data:text/javascript,${encodeURIComponent(code)}`);
    } finally {
      console.log = log;
    }
    assert.ok(logged.length > 0, 'the example prints nothing');
  });
}
