// The README's "Use it from Python" and "Use it from a browser" examples, taken as written from
// README.md and run against a real `clearsky serve` (the C++ one is built and run by
// tests/clients/cpp/package_consumer_test.sh). The only change made to an example is its
// address: the README says http://127.0.0.1:8080, the test's server listens on a free port.
//  - Python: the ```python block runs with Debian's python3 in an empty folder, with the
//    repository's clients/python on the path (the block's own sys.path line points there from
//    the repository's root); it must exit 0 and leave the skydome it asked for (an OpenEXR file).
//  - Browser: the ```html block is the index.html and the ```js block the sky.js of the folder
//    the server serves (--viewer-dir); Debian's chromium loads it headless through puppeteer-core and the test
//    checks that the sky image arrived (256 pixels wide) and that the illuminance shown is the
//    API's answer to the same request.
// Exit 77 (CTest: skipped) when chromium is missing.
// Usage: node test/readme_examples_test.mjs --binary build/clearsky --source .
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import puppeteer from 'puppeteer-core';

const CHROMIUM = '/usr/bin/chromium';
const args = Object.fromEntries(process.argv.slice(2).reduce((pairs, a, i, all) =>
  (a.startsWith('--') ? [...pairs, [a.slice(2), all[i + 1]]] : pairs), []));
if (!existsSync(CHROMIUM)) {
  console.log(`skipped: ${CHROMIUM} is missing (apt-get install chromium; deploy/install-deps.sh)`);
  process.exit(77);
}
const binary = resolve(args.binary ?? 'build/clearsky');
const source = resolve(args.source ?? '.');
const python = existsSync('/usr/bin/python3') ? '/usr/bin/python3' : 'python3';

let failures = 0;
function check(condition, what) {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}`);
  if (!condition) failures++;
}

// The first fenced block of a language in README.md, as written.
function readmeBlock(language) {
  const text = readFileSync(join(source, 'README.md'), 'utf8');
  const match = text.match(new RegExp('^```' + language + '\\n([\\s\\S]*?)^```$', 'm'));
  if (!match) throw new Error(`README.md has no \`\`\`${language} block`);
  return match[1];
}

const freePort = () => new Promise((done) => {
  const s = createServer();
  s.listen(0, '127.0.0.1', () => { const { port } = s.address(); s.close(() => done(port)); });
});
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

const work = mkdtempSync(join(tmpdir(), 'clearsky-readme-'));
const port = await freePort();
const origin = `http://127.0.0.1:${port}`;
const README_ORIGIN = 'http://127.0.0.1:8080';
const page = join(work, 'page');
spawnSync('mkdir', ['-p', page, join(work, 'python')]);
writeFileSync(join(page, 'index.html'), readmeBlock('html'));
writeFileSync(join(page, 'sky.js'), readmeBlock('js'));

const server = spawn(binary, ['serve', '--port', String(port), '--db', join(work, 'db.sqlite'),
  '--cache-dir', join(work, 'cache'), '--models', 'preetham,hosek', '--viewer-dir', page],
{ stdio: ['ignore', 'ignore', 'inherit'] });
let browser;
try {
  // Ready: /readyz 200 (generous: a loaded machine).
  const deadline = Date.now() + 120000;
  for (;;) {
    if (server.exitCode !== null) throw new Error('clearsky serve exited at start');
    try { if ((await fetch(`${origin}/readyz`)).status === 200) break; } catch { /* not yet */ }
    if (Date.now() > deadline) throw new Error('clearsky serve not ready within 120 s');
    await sleep(200);
  }

  // Python, from an empty folder; the block's sys.path line is relative to the repository.
  const pythonBlock = readmeBlock('python');
  check(pythonBlock.includes(README_ORIGIN), 'the Python example names the README address');
  const run = spawnSync(python, ['-c', pythonBlock.replaceAll(README_ORIGIN, origin)], {
    cwd: join(work, 'python'),
    env: { ...process.env, PYTHONPATH: join(source, 'clients', 'python'), PYTHONDONTWRITEBYTECODE: '1' },
    encoding: 'utf8',
    timeout: 120000,
  });
  check(run.status === 0, `the Python example exits 0 (${run.status}; ${(run.stderr || '').trim().split('\n').pop()})`);
  check(/\[[^\]]+\]/.test(run.stdout), `the Python example prints the wavelengths and radiances: ${run.stdout.trim()}`);
  const exr = join(work, 'python', 'sky.exr');
  check(existsSync(exr) && readFileSync(exr).readUInt32LE(0) === 20000630,
    'the Python example wrote sky.exr, an OpenEXR file (magic 20000630)');

  // The browser page, served by the server itself.
  browser = await puppeteer.launch({
    executablePath: CHROMIUM,
    headless: 'new',
    args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage'],
  });
  const tab = await browser.newPage();
  const errors = [];
  tab.on('pageerror', (e) => errors.push(String(e)));
  await tab.goto(`${origin}/`, { waitUntil: 'load', timeout: 60000 });
  await tab.waitForFunction(() => document.getElementById('illuminance').textContent !== '...',
    { timeout: 60000 });
  const shown = await tab.$eval('#illuminance', (e) => e.textContent);
  const width = await tab.$eval('#sky', (img) => (img.complete ? img.naturalWidth : 0));
  check(width === 256, `the sky image arrived, ${width} pixels wide`);
  const answer = await (await fetch(`${origin}/v1/irradiance?model=hosek&sun_zenith=30&sun_azimuth=135`)).json();
  const expected = `global horizontal illuminance: ${Math.round(answer.global.illuminance_lx)} lx`;
  check(shown === expected, `the page shows the API's illuminance: "${shown}" (API: "${expected}")`);
  check(errors.length === 0, `no error on the page ${errors.join('; ')}`);
} catch (e) {
  console.log(`FAIL ${e.message}`);
  failures++;
} finally {
  if (browser) await browser.close();
  server.kill('SIGTERM');
  await new Promise((r) => (server.exitCode !== null ? r() : server.once('exit', r)));
  rmSync(work, { recursive: true, force: true });
}
console.log(failures === 0 ? 'README examples: all checks passed' : `README examples: ${failures} failed`);
process.exit(failures === 0 ? 0 : 1);
