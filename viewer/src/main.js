// The clearsky browser viewer (docs/viewer.md): every figure comes from this server's API.
// The sky is GET /v1/skydome?format=png, the sun's marker GET /v1/sun, the spectrum under the
// pointer GET /v1/radiance, the figures GET /v1/irradiance, the charts GET /v1/evaluations,
// the error map GET /v1/evaluations/{id}?samples=true, the job history GET /v1/jobs.
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import './style.css';
import { toPixel, toDirection } from './sky_projection.js';
import { colourScale, drawErrorMap, sampleAt, describeSample } from './error_map.js';
import { drawJobHistory } from './job_history.js';

const $ = (id) => document.getElementById(id);
const SKY_PX = 400;
let pending = 0;  // requests in flight; document.body.dataset.idle says when none (tests wait on it)
let generation = 0;  // the latest update(); older answers are dropped

function busy(delta) {
  pending += delta;
  document.body.dataset.idle = pending === 0 ? 'true' : 'false';
}

// An API error body {"error": {"code", "message", "parameter"}} as a sentence.
class ApiFailure extends Error {}

async function api(path, { blob = false, onHeaders = null } = {}) {
  busy(+1);
  try {
    let response;
    try {
      response = await fetch(path);
    } catch (e) {
      throw new ApiFailure(`The server at ${location.origin} cannot be reached (${e.message}). Is clearsky serve running?`);
    }
    if (!response.ok) {
      let detail = `${response.status} ${response.statusText}`;
      try {
        const body = await response.json();
        if (body && body.error) {
          detail = `${response.status} ${body.error.code}: ${body.error.message}` +
            (body.error.parameter ? ` (parameter: ${body.error.parameter})` : '');
        }
      } catch { /* not JSON: the status line says it */ }
      throw new ApiFailure(`${path.split('?')[0]} answered ${detail}`);
    }
    if (onHeaders) onHeaders(response.headers);
    return blob ? await response.blob() : await response.json();
  } finally {
    busy(-1);
  }
}

function showError(error) {
  const box = $('error');
  if (!error) { box.hidden = true; box.textContent = ''; return; }
  box.hidden = false;
  box.textContent = error instanceof ApiFailure ? error.message : `Unexpected error: ${error.message ?? error}`;
}

function timeText() {
  const minutes = Number($('time').value);
  const hh = String(Math.floor(minutes / 60)).padStart(2, '0');
  const mm = String(minutes % 60).padStart(2, '0');
  return `${$('date').value}T${hh}:${mm}:00Z`;
}

// The place and time of the sun (GET /v1/sun takes nothing else).
function sunPlace() {
  return new URLSearchParams({ lat: $('lat').value, lon: $('lon').value, time: timeText() });
}

// Every sky request carries the chosen quality level (docs/quality-levels.md).
function place() {
  const query = sunPlace();
  query.set('quality', $('quality').value);
  return query;
}

// "quality standard" or, when cheaper tables answered, "quality standard (served draft)".
function qualityText(asked, served) {
  if (!asked) return '';
  return served && served !== asked ? `quality ${asked} (served ${served})` : `quality ${asked}`;
}

const skies = {
  a: { img: $('sky-img-a'), svg: $('sun-a'), caption: $('caption-a'), url: null, sun: null },
  b: { img: $('sky-img-b'), svg: $('sun-b'), caption: $('caption-b'), url: null, sun: null },
};

function markSun(sky, projection) {
  const svg = sky.svg;
  svg.innerHTML = '';
  if (!sky.sun || sky.sun.zenith > 90) return;
  const w = SKY_PX, h = projection === 'fisheye' ? SKY_PX : SKY_PX / 2;
  svg.setAttribute('viewBox', `0 0 ${w} ${h}`);
  const [x, y] = toPixel(projection, sky.sun.zenith, sky.sun.azimuth, w, h);
  svg.innerHTML = `<circle cx="${x}" cy="${y}" r="11" fill="none" stroke="#ffd400" stroke-width="2.5"/>` +
    `<circle cx="${x}" cy="${y}" r="2" fill="#ffd400"/>`;
}

async function loadSky(key, model, projection, sun) {
  const sky = skies[key];
  const query = place();
  query.set('model', model);
  query.set('format', 'png');
  query.set('size', String(SKY_PX));
  query.set('projection', projection);
  query.set('exposure', $('exposure').value);
  let quality = '';
  const blob = await api(`/v1/skydome?${query}`, {
    blob: true,
    onHeaders: (headers) => {
      quality = qualityText(headers.get('Clearsky-Quality'), headers.get('Clearsky-Served-Quality'));
    },
  });
  const url = URL.createObjectURL(blob);
  await new Promise((resolve, reject) => {
    sky.img.onload = resolve;
    sky.img.onerror = () => reject(new ApiFailure('the sky image could not be decoded'));
    sky.img.src = url;
  });
  if (sky.url) URL.revokeObjectURL(sky.url);
  sky.url = url;
  sky.sun = sun;
  sky.img.dataset.query = query.toString();
  sky.caption.textContent = `${model}, ${timeText()}, sun zenith ${sun.zenith.toFixed(2)}°, azimuth ${sun.azimuth.toFixed(2)}°` +
    (quality ? `, ${quality}` : '');
  sky.caption.dataset.servedQuality = quality;
  markSun(sky, projection);
}

async function loadIrradiance(models) {
  const rows = [];
  for (const model of models) {
    const query = place();
    query.set('model', model);
    const answer = await api(`/v1/irradiance?${query}`);
    for (const component of ['direct', 'diffuse', 'global']) {
      const c = answer[component];
      if (!c) continue;
      rows.push(`<tr data-model="${model}" data-component="${component}"><td>${model}</td><td>${component}</td>` +
        `<td class="w">${c.irradiance_w_m2.toFixed(1)}</td><td class="lx">${Math.round(c.illuminance_lx)}</td></tr>`);
    }
  }
  $('irradiance').tBodies[0].innerHTML = rows.join('');
}

let spectrumPlot = null;
function drawSpectrum(answer, where) {
  const x = answer.wavelengths_nm;
  const y = answer.samples[0].radiance;
  $('spectrum-where').textContent = `${answer.model}: view zenith ${where.zenith.toFixed(1)}°, azimuth ${where.azimuth.toFixed(1)}° (W/(m²·sr·nm)), ${qualityText(answer.quality, answer.served_quality)}`;
  if (spectrumPlot) { spectrumPlot.setData([x, y]); return; }
  spectrumPlot = new uPlot({
    width: 420, height: 220,
    scales: { x: { time: false } },
    axes: [{ label: 'wavelength (nm)' }, { label: 'radiance', size: 70 }],
    series: [{ label: 'nm' }, { label: 'W/(m²·sr·nm)', stroke: '#2a6fdb', width: 2 }],
  }, [x, y], $('spectrum'));
}

let pointerTimer = null;
function onPointer(event) {
  const img = event.currentTarget;
  const rect = img.getBoundingClientRect();
  const projection = $('projection').value;
  const where = toDirection(projection, event.clientX - rect.left, event.clientY - rect.top, rect.width, rect.height);
  if (!where) return;
  clearTimeout(pointerTimer);
  pointerTimer = setTimeout(async () => {
    const query = place();
    query.set('model', img.id === 'sky-img-b' ? $('model-b').value : $('model').value);
    query.set('view_zenith', where.zenith.toFixed(3));
    query.set('view_azimuth', where.azimuth.toFixed(3));
    try {
      drawSpectrum(await api(`/v1/radiance?${query}`), where);
    } catch (e) { showError(e); }
  }, 80);
}

function barChart(target, labels, values, label, plot) {
  target.innerHTML = '';
  if (plot) plot.destroy();
  const xs = labels.map((_, i) => i);
  const step = Math.max(1, Math.ceil(labels.length / 6));
  return new uPlot({
    width: 420, height: 220,
    // Bars start at 0, so that their lengths compare.
    scales: { x: { time: false, range: [-0.6, labels.length - 0.4] }, y: { range: (u, min, max) => [0, max * 1.1] } },
    // One label in every `step` bars, so that they do not overlap.
    axes: [{ values: (_, ticks) => ticks.map((t) => (t % step === 0 ? labels[t] ?? '' : '')), splits: () => xs },
      { label, size: 70 }],
    series: [{}, { label, fill: 'rgba(42,111,219,0.5)', stroke: '#2a6fdb', paths: uPlot.paths.bars({ size: [0.6, 60] }), points: { show: false } }],
    legend: { show: false },
  }, [xs, values], target);
}

let modelsPlot = null, capturesPlot = null;
async function loadEvaluations() {
  let runs;
  try {
    runs = await api('/v1/evaluations?status=succeeded');
  } catch (e) {
    $('evaluations-note').textContent = e.message;
    return;
  }
  const list = Array.isArray(runs) ? runs : (runs.items ?? runs.evaluations ?? []);
  if (list.length === 0) {
    $('evaluations-note').textContent = 'No stored evaluation yet (POST /v1/evaluations, docs/data-api.md).';
    return;
  }
  // The newest succeeded run of each model.
  const newest = new Map();
  for (const run of list) {
    if (run.rmse == null) continue;
    const seen = newest.get(run.model);
    if (!seen || run.id > seen.id) newest.set(run.model, run);
  }
  const latest = [...newest.values()];
  $('evaluations-note').textContent = `RMSE (mW/(m²·sr·nm)) of the newest run of each model, ${latest.length} models.`;
  modelsPlot = barChart($('rmse-models'), latest.map((r) => r.model), latest.map((r) => r.rmse), 'RMSE', modelsPlot);
  $('run-label').hidden = false;
  $('run').innerHTML = latest.map((r) => `<option value="${r.id}">${r.model} #${r.id} (${r.dataset ?? ''})</option>`).join('');
  await loadRun();
}


let runAnswer = null;  // the chosen run with its samples (GET /v1/evaluations/{id}?samples=true)
async function loadRun() {
  const id = $('run').value;
  if (!id) return;
  try {
    const run = await api(`/v1/evaluations/${encodeURIComponent(id)}?samples=true`);
    if (run.id !== Number($('run').value)) return;  // another run was chosen meanwhile
    runAnswer = run;
    const captures = (run.captures ?? []).filter((c) => c.rmse != null);
    capturesPlot = barChart($('rmse-captures'), captures.map((c) => (c.time ?? c.label).slice(11, 16)), captures.map((c) => c.rmse), 'RMSE per capture', capturesPlot);
    const withSamples = captures.filter((c) => (c.samples ?? []).length > 0);
    $('error-map-section').hidden = withSamples.length === 0;
    const previous = $('map-capture').value;
    $('map-capture').innerHTML = withSamples.map((c) => `<option value="${c.label}">${c.label} (${(c.time ?? '').slice(11, 16)})</option>`).join('');
    if (withSamples.some((c) => c.label === previous)) $('map-capture').value = previous;
    drawMap();
  } catch (e) { showError(e); }
}

// The error map of the chosen capture of the chosen run (error_map.js).
let errorMap = null;
function drawMap() {
  const capture = (runAnswer?.captures ?? []).find((c) => c.label === $('map-capture').value);
  if (!capture) return;
  const quantity = $('map-quantity').value;
  const scale = colourScale(quantity, runAnswer.captures);
  errorMap = drawErrorMap($('error-map'), $('error-legend'), capture, scale);
  const canvas = $('error-map');
  canvas.dataset.run = String(runAnswer.id);
  canvas.dataset.capture = capture.label;
  canvas.dataset.quantity = quantity;
  $('error-legend-text').textContent = quantity === 'bias'
    ? `Bias of ${runAnswer.model} (mean of model − measured over ${runAnswer.wavelength_range_nm.join('–')} nm, mW/(m²·sr·nm)): red where the model is too bright, blue too dark; the scale spans every capture of run #${runAnswer.id}.`
    : `RMSE of ${runAnswer.model} per sample (over ${runAnswer.wavelength_range_nm.join('–')} nm, mW/(m²·sr·nm)); the scale spans every capture of run #${runAnswer.id}.`;
  $('error-readout').textContent = `${capture.samples.length} samples; sun (yellow ring) at zenith ${capture.sun_zenith.toFixed(1)}°, azimuth ${capture.sun_azimuth.toFixed(1)}°. Move the pointer over a marker.`;
  delete $('error-readout').dataset.index;
}

function onMapPointer(event) {
  if (!errorMap) return;
  const canvas = event.currentTarget;
  const rect = canvas.getBoundingClientRect();
  const x = (event.clientX - rect.left) * (canvas.width / rect.width);
  const y = (event.clientY - rect.top) * (canvas.height / rect.height);
  const sample = sampleAt(errorMap, x, y);
  if (!sample) return;
  $('error-readout').textContent = describeSample(sample);
  $('error-readout').dataset.index = String(sample.index);
}

// The jobs, and the run history of the chosen one (job_history.js).
let historyPlot = null;
async function loadJobs() {
  let jobs;
  try {
    jobs = await api('/v1/jobs?limit=1000');
  } catch (e) {
    $('job-note').textContent = e.message;
    return;
  }
  if (jobs.length === 0) {
    $('job-note').textContent = 'No job yet (POST /v1/jobs, docs/data-api.md).';
    return;
  }
  $('job-label').hidden = false;
  $('job').innerHTML = jobs.map((j) => `<option value="${j.id}">${j.name} #${j.id} (${j.dataset}, ${j.schedule})</option>`).join('');
  await loadJobHistory();
}

async function loadJobHistory() {
  const id = $('job').value;
  if (!id) return;
  try {
    const [job, runs] = await Promise.all([
      api(`/v1/jobs/${encodeURIComponent(id)}`),
      api(`/v1/evaluations?job=${encodeURIComponent(id)}&status=succeeded&limit=1000`),
    ]);
    if (String(job.id) !== $('job').value) return;
    const drawn = drawJobHistory($('job-history'), runs, historyPlot);
    historyPlot = drawn.plot;
    $('job-history').dataset.points = String(drawn.points);
    $('job-note').textContent = `${job.name}: ${drawn.points} succeeded runs of ${drawn.models} models on ${job.dataset}, ` +
      `schedule "${job.schedule}" (UTC)${job.paused ? ', paused' : ''}, next run ${job.next_run ?? 'none'}` +
      (runs.length === 1000 ? '; the newest 1000 runs' : '') + '.';
  } catch (e) { showError(e); }
}

async function update() {
  const mine = ++generation;
  const projection = $('projection').value;
  $('time-text').textContent = timeText().slice(11, 16);
  const models = [$('model').value, $('model-b').value].filter(Boolean);
  $('sky-b').hidden = !$('model-b').value;
  busy(+1);
  try {
    const sun = await api(`/v1/sun?${sunPlace()}`);
    if (mine !== generation) return;
    await Promise.all([
      loadSky('a', models[0], projection, sun),
      ...(models[1] ? [loadSky('b', models[1], projection, sun)] : []),
      loadIrradiance(models),
    ]);
    if (mine === generation) showError(null);
  } catch (e) {
    if (mine === generation) showError(e);
  } finally {
    busy(-1);
  }
}

async function start() {
  busy(+1);
  try {
    const { models } = await api('/v1/models');
    const options = models.map((m) => `<option value="${m.id}">${m.name}</option>`).join('');
    $('model').innerHTML = options;
    $('model-b').innerHTML = '<option value="">(none)</option>' + options;
    for (const id of ['model', 'model-b', 'lat', 'lon', 'date', 'projection', 'exposure', 'quality']) $(id).addEventListener('change', update);
    $('time').addEventListener('input', () => { $('time-text').textContent = timeText().slice(11, 16); });
    $('time').addEventListener('change', update);
    $('run').addEventListener('change', loadRun);
    $('map-capture').addEventListener('change', drawMap);
    $('map-quantity').addEventListener('change', drawMap);
    $('error-map').addEventListener('mousemove', onMapPointer);
    $('job').addEventListener('change', loadJobHistory);
    skies.a.img.addEventListener('mousemove', onPointer);
    skies.b.img.addEventListener('mousemove', onPointer);
    await Promise.all([update(), loadEvaluations(), loadJobs()]);
  } catch (e) {
    showError(e);
  } finally {
    busy(-1);
  }
}

start();
