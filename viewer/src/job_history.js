// The run history of one job (docs/viewer.md): the RMSE of each of its runs
// (GET /v1/evaluations?job=ID&status=succeeded) over the run's start time, one line per model
// (uPlot). The RMSE is the API's, mW/(m²·sr·nm).
import uPlot from 'uplot';

const COLOURS = ['#2a6fdb', '#d9480f', '#2b8a3e', '#862e9c', '#e67700', '#0b7285', '#c2255c', '#495057'];

// `runs`: the job's succeeded runs, as GET /v1/evaluations lists them. Returns the new plot and
// the number of points drawn.
export function drawJobHistory(target, runs, plot) {
  target.innerHTML = '';
  if (plot) plot.destroy();
  const timed = runs.filter((r) => r.rmse != null && r.started)
    .map((r) => ({ model: r.model, t: Date.parse(r.started) / 1000, rmse: r.rmse }))
    .sort((a, b) => a.t - b.t);
  const models = [...new Set(timed.map((r) => r.model))].sort();
  // One x per run; each model's series has its value at its own runs and gaps elsewhere,
  // joined across the gaps (spanGaps), so that each model reads as one line.
  const xs = timed.map((r) => r.t);
  const ys = models.map((m) => timed.map((r) => (r.model === m ? r.rmse : null)));
  const chart = new uPlot({
    width: 420, height: 240,
    scales: { x: { time: true }, y: { range: (u, min, max) => [0, max * 1.1] } },
    axes: [{ label: 'run start (local time of this browser)' }, { label: 'RMSE (mW/(m²·sr·nm))', size: 70 }],
    series: [{ label: 'start' }, ...models.map((m, i) => ({
      label: m, stroke: COLOURS[i % COLOURS.length], width: 2, spanGaps: true,
      points: { show: true, size: 7 },
    }))],
  }, [xs, ...ys], target);
  return { plot: chart, points: timed.length, models: models.length };
}
