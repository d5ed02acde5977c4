// The per-sample error map of one evaluated capture (docs/viewer.md): each sample of
// GET /v1/evaluations/{id}?samples=true is a coloured marker on a fisheye disc, in the projection
// of the sky image (sky_projection.js: equidistant, North up, East left), with a colour scale.
// The values are the API's own: per sample the RMSE over the compared wavelengths and the bias
// (mean of model - measured), both mW/(m²·sr·nm) (models/evaluation/README.md).
import { toPixel } from './sky_projection.js';

export const DISC_FILL = [43, 48, 64];  // the disc where there is no sample (#2b3040)
const MARKER_RADIUS_PX = 8;
const POINTER_REACH_PX = 12;

// Diverging red-blue (ColorBrewer RdBu, 7 classes, reversed: blue under, red over the measurement).
const DIVERGING = [[33, 102, 172], [103, 169, 207], [209, 229, 240], [247, 247, 247],
  [253, 219, 199], [239, 138, 98], [178, 24, 43]];
// Sequential for the RMSE, from no error (light) to the largest (dark): ColorBrewer Purples.
const SEQUENTIAL = [[252, 251, 253], [218, 218, 235], [158, 154, 200], [106, 81, 163], [63, 0, 125]];

function ramp(stops, t) {
  const x = Math.min(1, Math.max(0, t)) * (stops.length - 1);
  const i = Math.min(stops.length - 2, Math.floor(x));
  const f = x - i;
  return stops[i].map((c, k) => Math.round(c + (stops[i + 1][k] - c) * f));
}

// The colour scale of a quantity over all the run's samples, so that captures compare.
export function colourScale(quantity, captures) {
  const values = captures.flatMap((c) => (c.samples ?? []).map((s) => s[quantity])).filter(Number.isFinite);
  if (quantity === 'bias') {
    const reach = Math.max(1e-9, ...values.map(Math.abs));
    return { quantity, min: -reach, max: reach, colour: (v) => ramp(DIVERGING, (v + reach) / (2 * reach)),
      stops: DIVERGING };
  }
  const top = Math.max(1e-9, ...values);
  return { quantity, min: 0, max: top, colour: (v) => ramp(SEQUENTIAL, v / top), stops: SEQUENTIAL };
}

const css = (rgb) => `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;

// Draws the capture's samples on `canvas` (square) and the scale on `legend`; returns what the
// pointer needs.
export function drawErrorMap(canvas, legend, capture, scale) {
  const size = canvas.width;
  const g = canvas.getContext('2d');
  g.clearRect(0, 0, size, size);
  g.fillStyle = css(DISC_FILL);
  g.beginPath();
  g.arc(size / 2, size / 2, size / 2, 0, 2 * Math.PI);
  g.fill();
  // Zenith angle rings every 30 degrees, and the cardinal directions.
  g.strokeStyle = 'rgba(255,255,255,0.25)';
  g.lineWidth = 1;
  g.fillStyle = 'rgba(255,255,255,0.75)';
  g.font = '12px system-ui, sans-serif';
  g.textAlign = 'center';
  g.textBaseline = 'middle';
  for (const zenith of [30, 60]) {
    g.beginPath();
    g.arc(size / 2, size / 2, (zenith / 90) * (size / 2), 0, 2 * Math.PI);
    g.stroke();
  }
  // The ring labels between the scan's rings of markers (Kider et al. 2014: 8 samples on the
  // ring nearest the zenith, 16 on the next; azimuth 191.25 lies between two of each).
  for (const [label, zenith] of [['30°', 27], ['60°', 67]]) {
    const [x, y] = toPixel('fisheye', zenith, 191.25, size, size);
    g.fillText(label, x, y);
  }
  for (const [label, azimuth] of [['N', 0], ['E', 90], ['S', 180], ['W', 270]]) {
    const [x, y] = toPixel('fisheye', 86, azimuth, size, size);
    g.fillText(label, x, y);
  }
  const placed = [];
  for (const sample of capture.samples ?? []) {
    const value = sample[scale.quantity];
    if (!Number.isFinite(value)) continue;
    const [x, y] = toPixel('fisheye', sample.view_zenith, sample.view_azimuth, size, size);
    g.fillStyle = css(scale.colour(value));
    g.strokeStyle = '#000';
    g.beginPath();
    g.arc(x, y, MARKER_RADIUS_PX, 0, 2 * Math.PI);
    g.fill();
    g.stroke();
    placed.push({ x, y, sample });
  }
  // The sun of the capture, as on the sky image.
  if (Number.isFinite(capture.sun_zenith) && capture.sun_zenith <= 90) {
    const [x, y] = toPixel('fisheye', capture.sun_zenith, capture.sun_azimuth, size, size);
    g.strokeStyle = '#ffd400';
    g.lineWidth = 2.5;
    g.beginPath();
    g.arc(x, y, 11, 0, 2 * Math.PI);
    g.stroke();
  }
  drawLegend(legend, scale);
  return { placed, scale, size };
}

function drawLegend(legend, scale) {
  const g = legend.getContext('2d');
  const w = legend.width, h = legend.height, pad = 30, barH = 14;
  g.clearRect(0, 0, w, h);
  for (let x = pad; x <= w - pad; x++) {
    const t = (x - pad) / (w - 2 * pad);
    g.fillStyle = css(scale.colour(scale.min + t * (scale.max - scale.min)));
    g.fillRect(x, 4, 1, barH);
  }
  g.strokeStyle = '#1d2330';
  g.strokeRect(pad, 4, w - 2 * pad, barH);
  g.fillStyle = '#1d2330';
  g.font = '12px system-ui, sans-serif';
  g.textAlign = 'center';
  g.textBaseline = 'top';
  const ticks = scale.quantity === 'bias' ? [scale.min, 0, scale.max] : [0, scale.max / 2, scale.max];
  for (const v of ticks) {
    const x = pad + ((v - scale.min) / (scale.max - scale.min)) * (w - 2 * pad);
    g.fillRect(Math.round(x), 4 + barH, 1, 4);
    g.fillText((scale.quantity === 'bias' && v > 0 ? '+' : '') + v.toFixed(1), x, 4 + barH + 6);
  }
}

// The sample whose marker is nearest to (x, y) in canvas pixels, within reach of the pointer.
export function sampleAt(map, x, y) {
  let best = null, bestD = POINTER_REACH_PX;
  for (const p of map.placed) {
    const d = Math.hypot(p.x - x, p.y - y);
    if (d <= bestD) { best = p.sample; bestD = d; }
  }
  return best;
}

export function describeSample(sample) {
  const bias = `${sample.bias > 0 ? '+' : ''}${sample.bias.toFixed(2)}`;
  return `sample ${sample.index}: view zenith ${sample.view_zenith.toFixed(1)}°, azimuth ` +
    `${sample.view_azimuth.toFixed(1)}°, bias ${bias}, RMSE ${sample.rmse.toFixed(2)} mW/(m²·sr·nm)`;
}
