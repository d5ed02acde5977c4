// The viewer in a real browser (docs/viewer.md): starts `clearsky serve` with the built viewer,
// drives Debian's chromium headless through puppeteer-core (never a downloaded browser), and
// checks that the sky image is not blank and changes with the time and the model, that the
// irradiance shown equals the API's answer for the same request, that the spectrum under the
// pointer is drawn, and that a 400, a 422 and an unreachable server are readable messages.
// Exit 77 (CTest: skipped) when chromium is missing. Prints the page's load time.
// Usage: node test/viewer_test.mjs --binary build/clearsky --viewer-dir build/viewer
//        [--screenshots docs/figures] [--db prepared.sqlite]
import { spawn } from 'node:child_process';
import { copyFileSync, existsSync, mkdtempSync, rmSync } from 'node:fs';
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
const viewerDir = resolve(args['viewer-dir'] ?? 'build/viewer');
if (!existsSync(join(viewerDir, 'index.html'))) {
  console.error(`FAIL: no viewer in ${viewerDir}: build it with deploy/build.sh (or npm ci && npm run build in viewer/)`);
  process.exit(1);
}

let failures = 0;
function check(condition, what) {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}`);
  if (!condition) failures++;
}

const freePort = () => new Promise((done) => {
  const s = createServer();
  s.listen(0, '127.0.0.1', () => { const { port } = s.address(); s.close(() => done(port)); });
});
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

const work = mkdtempSync(join(tmpdir(), 'clearsky-viewer-'));
const port = await freePort();
const origin = `http://127.0.0.1:${port}`;
if (args.db) copyFileSync(args.db, join(work, 'db.sqlite'));
const server = spawn(binary, ['serve', '--port', String(port), '--db', join(work, 'db.sqlite'),
  '--cache-dir', join(work, 'cache'), '--models', 'preetham,hosek', '--viewer-dir', viewerDir],
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
  const index = await fetch(`${origin}/`);
  check(index.status === 200 && index.headers.get('cache-control') === 'no-cache', 'GET / is the viewer, revalidated (no-cache)');
  const asset = (await index.text()).match(/\/assets\/[^"]+\.js/)[0];
  check((await fetch(origin + asset)).headers.get('cache-control').includes('immutable'), `${asset} is cached as immutable`);
  check((await fetch(`${origin}/nothing-here.js`)).status === 404, 'an unknown file is a 404');

  browser = await puppeteer.launch({
    executablePath: CHROMIUM,
    headless: true,
    userDataDir: mkdtempSync(join(work, 'profile-')),
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  const page = await browser.newPage();
  await page.setViewport({ width: 1400, height: 1000 });
  const external = [];
  page.on('request', (r) => { if (!r.url().startsWith(origin) && !r.url().startsWith('blob:') && !r.url().startsWith('data:')) external.push(r.url()); });
  const pageErrors = [];
  page.on('pageerror', (e) => pageErrors.push(e.message));

  const idle = (what) => page.waitForFunction(() => document.body.dataset.idle === 'true', { timeout: 60000 })
    .catch(() => { throw new Error(`the page did not settle: ${what}`); });
  // A 32 x 32 summary of the first sky image (mean R, G, B of each cell, and the spread of its
  // brightness over opaque pixels).
  const skyStats = (id) => page.evaluate((imgId) => {
    const img = document.getElementById(imgId);
    const c = document.createElement('canvas');
    c.width = 32; c.height = 32;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0, 32, 32);
    const d = g.getImageData(0, 0, 32, 32).data;
    const cells = [];
    let sum = 0, sum2 = 0, n = 0;
    for (let i = 0; i < d.length; i += 4) {
      cells.push(d[i], d[i + 1], d[i + 2]);
      if (d[i + 3] < 255) continue;
      const v = d[i] + d[i + 1] + d[i + 2];
      sum += v; sum2 += v * v; n++;
    }
    const mean = sum / n;
    return { cells, mean, spread: Math.sqrt(sum2 / n - mean * mean), opaque: n, query: img.dataset.query };
  }, id);
  const difference = (a, b) => a.cells.reduce((s, v, i) => s + Math.abs(v - b.cells[i]), 0) / a.cells.length;
  const setValue = (id, value) => page.evaluate((i, v) => {
    const e = document.getElementById(i);
    e.value = v;
    e.dispatchEvent(new Event('change'));
  }, id, value);
  const errorText = () => page.evaluate(() => { const e = document.getElementById('error'); return e.hidden ? '' : e.textContent; });

  // Load: the navigation, then the first sky on screen.
  const t0 = Date.now();
  await page.goto(`${origin}/`, { waitUntil: 'load' });
  const loadMs = Date.now() - t0;
  await page.waitForFunction(() => document.getElementById('sky-img-a').dataset.query, { timeout: 60000 });
  await idle('first load');
  const firstSkyMs = Date.now() - t0;
  console.log(`page load ${loadMs} ms (load event), first sky and figures ${firstSkyMs} ms`);
  check(await errorText() === '', `no error message at load (${await errorText()})`);

  const noon = await skyStats('sky-img-a');
  check(noon.opaque > 500 && noon.mean > 60 && noon.spread > 5, `the sky is not blank (mean ${noon.mean.toFixed(0)}, spread ${noon.spread.toFixed(1)})`);
  // The spectrum under the pointer.
  const box = await (await page.$('#sky-img-a')).boundingBox();
  await page.mouse.move(box.x + box.width * 0.5, box.y + box.height * 0.3);
  await page.waitForFunction(() => document.querySelector('#spectrum canvas') && document.getElementById('spectrum-where').textContent.includes('view zenith'), { timeout: 60000 });
  check(true, 'the spectrum under the pointer is drawn');
  const evaluations = await page.evaluate(() => document.getElementById('evaluations-note').textContent);
  check(evaluations.length > 0, `the evaluations section says what it shows: ${evaluations}`);
  if (!evaluations.startsWith('No stored')) {
    check(await page.evaluate(() => !!document.querySelector('#rmse-models canvas') && !!document.querySelector('#rmse-captures canvas')), 'the RMSE charts are drawn');
  }
  if (args.screenshots) await page.screenshot({ path: join(args.screenshots, 'viewer-main.png'), fullPage: true });

  await setValue('time', '1290');  // 21:30 UTC, 17:30 at Ithaca
  await page.waitForFunction((q) => document.getElementById('sky-img-a').dataset.query !== q, { timeout: 60000 }, noon.query);
  await idle('time change');
  const evening = await skyStats('sky-img-a');
  check(difference(noon, evening) > 5, `the sky changes with the time (mean difference ${difference(noon, evening).toFixed(1)} per component)`);

  await setValue('model', 'hosek');
  await page.waitForFunction(() => document.getElementById('sky-img-a').dataset.query.includes('model=hosek'), { timeout: 60000 });
  await idle('model change');
  const hosek = await skyStats('sky-img-a');
  check(difference(evening, hosek) > 0.5, `the sky changes with the model (mean difference ${difference(evening, hosek).toFixed(2)})`);

  // The figure shown equals the API's answer to the same request.
  const query = new URLSearchParams(hosek.query);
  const answer = await (await fetch(`${origin}/v1/irradiance?${new URLSearchParams({ model: 'hosek', lat: query.get('lat'), lon: query.get('lon'), time: query.get('time') })}`)).json();
  const shown = await page.evaluate(() => document.querySelector('#irradiance tr[data-model="hosek"][data-component="global"] td.w')?.textContent);
  check(shown === answer.global.irradiance_w_m2.toFixed(1), `global irradiance shown ${shown} W/m2 = API ${answer.global.irradiance_w_m2.toFixed(1)}`);


  // Side by side.
  await setValue('model-b', 'preetham');
  await page.waitForFunction(() => !document.getElementById('sky-b').hidden && (document.getElementById('sky-img-b').dataset.query ?? '').includes('model=preetham'), { timeout: 60000 });
  await idle('second model');
  const b = await skyStats('sky-img-b');
  check(b.mean > 20, 'the second model is shown beside the first');
  if (args.screenshots) await page.screenshot({ path: join(args.screenshots, 'viewer-compare.png') });

  // A 400: a latitude out of range, named.
  await setValue('lat', '95');
  await page.waitForFunction(() => !document.getElementById('error').hidden, { timeout: 60000 });
  const bad = await errorText();
  check(/400/.test(bad) && /lat/.test(bad), `a 400 is a readable message: ${bad}`);
  if (args.screenshots) await page.screenshot({ path: join(args.screenshots, 'viewer-error.png') });
  await setValue('lat', '42.444');
  await idle('back to a valid latitude');
  check(await errorText() === '', 'the message goes once the request is valid');

  // A 422: the sun below the horizon (04:00 UTC, midnight at Ithaca) for these models.
  await setValue('time', '240');
  await page.waitForFunction(() => !document.getElementById('error').hidden, { timeout: 60000 });
  const night = await errorText();
  check(/422/.test(night), `a 422 is a readable message: ${night}`);

  // The server gone.
  server.kill('SIGKILL');
  await new Promise((r) => (server.exitCode !== null || server.signalCode !== null ? r() : server.once('exit', r)));
  await setValue('time', '900');
  await page.waitForFunction(() => document.getElementById('error').textContent.includes('cannot be reached'), { timeout: 60000 });
  check(true, `an unreachable server is a readable message: ${await errorText()}`);

  check(external.length === 0, `no request leaves the server (${external.join(', ')})`);
  check(pageErrors.length === 0, `no script error (${pageErrors.join('; ')})`);
} catch (e) {
  console.error(`FAIL: ${e.stack ?? e}`);
  failures++;
} finally {
  if (browser) await browser.close();
  if (server.exitCode === null && server.signalCode === null) server.kill('SIGTERM');
  rmSync(work, { recursive: true, force: true });
}
console.log(failures === 0 ? 'viewer test passed' : `viewer test: ${failures} failure(s)`);
process.exit(failures === 0 ? 0 : 1);
