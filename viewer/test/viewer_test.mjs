// The viewer in a real browser (docs/viewer.md): starts `clearsky serve` with the built viewer,
// drives Debian's chromium headless through puppeteer-core (never a downloaded browser), and
// checks that the sky image is not blank and changes with the time and the model, that the
// irradiance shown equals the API's answer for the same request, that the spectrum under the
// pointer is drawn, that the per-sample error map of an evaluation draws its samples where they
// are and reads back the API's values under the pointer, that a job's run history has one point
// per run, and that a 400, a 422 and an unreachable server are readable messages.
// The database holds a synthetic capture pair (tests/server/openapi/synthetic_kider.py) imported
// and evaluated by `clearsky import` and `clearsky evaluate`, and a job created by POST /v1/jobs
// and made due (sqlite3, the server stopped) before two server starts: the scheduler runs a due
// job at start (server/scheduler/scheduler.cpp), so the job has run twice.
// Exit 77 (CTest: skipped) when chromium is missing. Prints the page's load time.
// Usage: node test/viewer_test.mjs --binary build/clearsky --viewer-dir build/viewer
//        [--screenshots docs/figures] [--db prepared.sqlite]
import { execFileSync, spawn } from 'node:child_process';
import { copyFileSync, existsSync, mkdtempSync, rmSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
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
const db = join(work, 'db.sqlite');
const token = 'viewer-test-token';
const here = dirname(fileURLToPath(import.meta.url));
const JOB_RUNS = 2;  // occurrences of the test's job

function startServer() {
  const child = spawn(binary, ['serve', '--port', String(port), '--db', db, '--token', token,
    '--cache-dir', join(work, 'cache'), '--models', 'preetham,hosek', '--viewer-dir', viewerDir],
  { stdio: ['ignore', 'ignore', 'inherit'] });
  return child;
}
async function waitReady(child) {
  // Ready: /readyz 200 (generous: a loaded machine).
  const deadline = Date.now() + 120000;
  for (;;) {
    if (child.exitCode !== null) throw new Error('clearsky serve exited at start');
    try { if ((await fetch(`${origin}/readyz`)).status === 200) return; } catch { /* not yet */ }
    if (Date.now() > deadline) throw new Error('clearsky serve not ready within 120 s');
    await sleep(200);
  }
}
async function stopServer(child) {
  if (child.exitCode !== null || child.signalCode !== null) return;
  const gone = new Promise((r) => child.once('exit', r));
  child.kill('SIGTERM');
  await gone;
}
const getJson = async (path) => (await fetch(origin + path)).json();
// The job's succeeded runs, once there are `count` of them (the scheduler runs it in the background).
async function jobRuns(jobId, count) {
  const deadline = Date.now() + 60000;
  for (;;) {
    const runs = await getJson(`/v1/evaluations?job=${jobId}&status=succeeded&limit=1000`);
    if (runs.length >= count) return runs;
    if (Date.now() > deadline) throw new Error(`job ${jobId}: ${runs.length} of ${count} runs within 60 s`);
    await sleep(200);
  }
}
const makeJobDue = (id) => execFileSync('sqlite3', [db, `UPDATE jobs SET next_run_utc = '2000-01-01T00:00:00Z' WHERE id = ${Number(id)}`]);

// The fisheye projection of docs/viewer.md, written out here (not the page's code): equidistant,
// North up, East left, the zenith at the centre, the horizon on the rim.
const fisheyePixel = (zenith, azimuth, size) => [size / 2 - (zenith / 90) * (size / 2) * Math.sin(azimuth * Math.PI / 180),
  size / 2 - (zenith / 90) * (size / 2) * Math.cos(azimuth * Math.PI / 180)];

// The error map of the chosen run and capture: a marker at every sample of the API's answer, the
// disc's own colour away from them, and the API's values of the sample under the pointer.
async function checkErrorMap(page) {
  await page.waitForFunction(() => document.getElementById('error-map').dataset.capture, { timeout: 60000 });
  const { run, capture } = await page.evaluate(() => ({ ...document.getElementById('error-map').dataset }));
  const answer = await getJson(`/v1/evaluations/${run}?samples=true`);
  const shown = answer.captures.find((c) => c.label === capture);
  check(shown && shown.samples.length > 0, `the error map shows run ${run}, capture ${capture} (${shown?.samples.length} samples)`);
  if (!shown) return;
  const size = await page.evaluate(() => document.getElementById('error-map').width);
  const pixels = await page.evaluate(() => {
    const c = document.getElementById('error-map');
    return Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data);
  });
  const rgba = ([x, y]) => pixels.slice((Math.round(y) * size + Math.round(x)) * 4, (Math.round(y) * size + Math.round(x)) * 4 + 4);
  const DISC = [43, 48, 64];
  const isDisc = (p) => p[3] === 255 && p.slice(0, 3).every((v, i) => Math.abs(v - DISC[i]) <= 2);
  const at = shown.samples.map((sm) => fisheyePixel(sm.view_zenith, sm.view_azimuth, size));
  const marked = at.filter((xy) => { const p = rgba(xy); return p[3] === 255 && !isDisc(p); }).length;
  check(marked === at.length, `a marker at each sample's direction: ${marked} of ${at.length}`);
  // Away from every sample and the sun (> 20 px), the disc is bare.
  const sun = fisheyePixel(shown.sun_zenith, shown.sun_azimuth, size);
  const far = (xy) => [...at, sun].every(([x, y]) => Math.hypot(x - xy[0], y - xy[1]) > 20);
  const bare = [22.5, 67.5, 112.5, 157.5, 247.5, 292.5, 337.5].map((az) => fisheyePixel(27, az, size)).filter(far);
  check(bare.length > 0 && bare.every((xy) => isDisc(rgba(xy))), `the disc is bare away from the samples (${bare.length} points)`);
  // The pointer over one sample (a third of the way through the scan) reads its values.
  const sample = shown.samples[Math.floor(shown.samples.length / 3)];
  const [x, y] = fisheyePixel(sample.view_zenith, sample.view_azimuth, size);
  const box = await (await page.$('#error-map')).boundingBox();
  await page.mouse.move(box.x + x * (box.width / size), box.y + y * (box.height / size));
  await page.waitForFunction((i) => document.getElementById('error-readout').dataset.index === String(i), { timeout: 30000 }, sample.index)
    .catch(() => {});
  const readout = await page.evaluate(() => document.getElementById('error-readout').textContent);
  const bias = `${sample.bias > 0 ? '+' : ''}${sample.bias.toFixed(2)}`;
  check(readout.includes(`sample ${sample.index}:`) && readout.includes(`bias ${bias},`) && readout.includes(`RMSE ${sample.rmse.toFixed(2)} `),
    `the pointer reads sample ${sample.index}'s bias ${bias} and RMSE ${sample.rmse.toFixed(2)} from the API: ${readout}`);
}

// The run history of the test's job: one point per succeeded run, one series per model.
async function checkJobHistory(page) {
  await page.waitForFunction(() => document.querySelector('#job-history canvas') && document.getElementById('job-history').dataset.points, { timeout: 60000 });
  await page.evaluate((id) => { const e = document.getElementById('job'); e.value = String(id); e.dispatchEvent(new Event('change')); }, jobId);
  await page.waitForFunction((id) => document.getElementById('job-note').textContent.startsWith('viewer-test-') && document.getElementById('job').value === String(id), { timeout: 60000 }, jobId);
  const runs = await getJson(`/v1/evaluations?job=${jobId}&status=succeeded&limit=1000`);
  const points = await page.evaluate(() => Number(document.getElementById('job-history').dataset.points));
  const series = await page.evaluate(() => Array.from(document.querySelectorAll('#job-history .u-legend .u-series .u-label')).slice(1).map((e) => e.textContent.trim()));
  check(runs.length === JOB_RUNS * jobModels.length && points === runs.length, `the job history has a point per run: ${points} points, ${runs.length} runs`);
  check(series.sort().join(',') === [...jobModels].sort().join(','), `one series per model of the job: ${series.join(', ')}`);
}

let server;
let browser;
let jobId = null;
let jobModels = [];
try {
  if (args.db) {
    copyFileSync(args.db, db);
  } else {
    // Two synthetic captures, imported and evaluated with the executable's own commands.
    const captures = join(work, 'captures');
    execFileSync('python3', ['-c', 'import sys; sys.path.insert(0, sys.argv[1]); import synthetic_kider as s; ' +
      's.write_capture(sys.argv[2] + "/a"); s.write_capture(sys.argv[2] + "/b", label="2013-05-27___13.45.00")',
    resolve(here, '../../tests/server/openapi'), captures]);
    execFileSync(binary, ['import', 'kider', '--db', db, '--name', 'synthetic', captures], { stdio: 'ignore' });
    execFileSync(binary, ['evaluate', '--db', db, '--dataset', 'synthetic', '--models', 'preetham,hosek'], { stdio: 'ignore' });
  }
  // A job on the first dataset, run twice: due at each of the next two starts.
  server = startServer();
  await waitReady(server);
  const datasets = await getJson('/v1/datasets');
  if (datasets.length > 0) {
    jobModels = ['preetham', 'hosek'];
    const created = await fetch(`${origin}/v1/jobs`, { method: 'POST', headers: { Authorization: `Bearer ${token}`, 'Content-Type': 'application/json' },
      body: JSON.stringify({ name: `viewer-test-${Date.now()}`, schedule: '0 3 * * *', dataset: datasets[0].name, models: jobModels }) });
    check(created.status === 201, `POST /v1/jobs created the test's job (${created.status})`);
    jobId = (await created.json()).id;
    const before = (await getJson(`/v1/evaluations?job=${jobId}&limit=1000`)).length;
    for (let occurrence = 1; occurrence <= JOB_RUNS; occurrence++) {
      await stopServer(server);
      makeJobDue(jobId);
      server = startServer();
      await waitReady(server);
      await jobRuns(jobId, before + occurrence * jobModels.length);
    }
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
    await checkErrorMap(page);
  }
  if (jobId !== null) await checkJobHistory(page);
  if (args.screenshots) {
    await page.screenshot({ path: join(args.screenshots, 'viewer-main.png'), fullPage: true });
    await (await page.$('#error-map-section')).screenshot({ path: join(args.screenshots, 'viewer-error-map.png') });
  }

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

  // The quality selector: sent with the sky requests, the served quality shown.
  check((await page.evaluate(() => document.getElementById('caption-a').textContent)).includes('quality standard'), 'the caption shows the served quality');
  await setValue('quality', 'draft');
  await page.waitForFunction(() => document.getElementById('sky-img-a').dataset.query.includes('quality=draft'), { timeout: 60000 });
  await idle('quality change');
  const draftCaption = await page.evaluate(() => document.getElementById('caption-a').textContent);
  check(draftCaption.includes('quality draft'), `the draft sky says so: ${draftCaption}`);
  await setValue('quality', 'standard');
  await page.waitForFunction(() => document.getElementById('sky-img-a').dataset.query.includes('quality=standard'), { timeout: 60000 });
  await idle('back to standard');


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
  if (server && server.exitCode === null && server.signalCode === null) server.kill('SIGTERM');
  rmSync(work, { recursive: true, force: true });
}
console.log(failures === 0 ? 'viewer test passed' : `viewer test: ${failures} failure(s)`);
process.exit(failures === 0 ? 0 : 1);
