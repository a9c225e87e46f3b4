// The package in a real browser: headless Chromium loads index.js from a local HTTP server (the
// browser path: fetch, WebAssembly.compileStreaming, top-level await), triangulates a square
// with a hole and validates it; the page writes what it got into the DOM, which Chromium dumps.
// Skipped when chromium is not installed (scripts/setup.sh installs it).
import assert from 'node:assert/strict';
import { execFile, spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { test } from 'node:test';

const chromium = ['chromium', 'chromium-browser'].find((name) => spawnSync('which', [name]).status === 0);

const page = `<!doctype html><meta charset="utf-8"><body><pre id="out">pending</pre>
<script type="module">
import { triangulate, validate, Triangulator } from './index.js';
const coords = [0, 0, 10, 0, 10, 10, 0, 10, 4, 4, 4, 6, 6, 6, 6, 4];
const triangles = triangulate(coords, [4]);
const report = validate(coords, [4], triangles);
const nan = new Triangulator().triangulate([0, 0, 1, 0, NaN, 1], null);
document.getElementById('out').textContent = JSON.stringify({
  count: triangles.length / 3, valid: report.valid, area: report.areaRelError,
  status: nan.status, issue: nan.diagnostics[0].issue, vertex: nan.diagnostics[0].vertex });
</script>`;

const types = { '.js': 'text/javascript', '.wasm': 'application/wasm', '.html': 'text/html' };

function serve() {
  const root = new URL('../', import.meta.url);
  const server = createServer((request, response) => {
    const path = request.url === '/' ? '/page.html' : request.url;
    const type = types[path.slice(path.lastIndexOf('.'))];
    if (path === '/page.html') {
      response.writeHead(200, { 'content-type': type }).end(page);
    } else if (type && /^\/[a-z]+\.(js|wasm)$/.test(path)) {
      response.writeHead(200, { 'content-type': type }).end(readFileSync(new URL(`.${path}`, root)));
    } else {
      response.writeHead(404).end();
    }
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

test('index.js in headless Chromium', { skip: chromium ? false : 'chromium not installed', timeout: 60000 }, async () => {
  const server = await serve();
  try {
    const url = `http://127.0.0.1:${server.address().port}/page.html`;
    // Asynchronously: a synchronous spawn would block this process' server.
    const run = await new Promise((resolve) => {
      const args = ['--headless', '--no-sandbox', '--disable-gpu', '--virtual-time-budget=10000', '--dump-dom', url];
      execFile(chromium, args, { timeout: 45000 }, (error, stdout, stderr) => resolve({ error, stdout, stderr }));
    });
    const match = /<pre id="out">(.*?)<\/pre>/s.exec(run.stdout);
    assert.ok(match, `no output from Chromium: ${run.error ?? ''} ${run.stderr.slice(-500)}`);
    assert.deepEqual(JSON.parse(match[1].replaceAll('&quot;', '"')), {
      count: 8, valid: true, area: 0, status: 'invalid_input', issue: 'non_finite_coordinate', vertex: 2,
    });
  } finally {
    server.close();
  }
});
