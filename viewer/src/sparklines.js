// The neurons' outputs over the whole replay, one small plot per neuron with
// a cursor at the present moment. The list scrolls; each plot is drawn once
// and only the cursors and values move.
import { el } from './dom.js';
import { neuronSeries, sparkPoints } from './neurons.js';
import { bracket } from './timeline.js';

/** Most plots drawn; a brain larger than this shows its first neurons. */
export const MAX_SPARKS = 200;
const W = 200, H = 26;

function drawSpark(canvas, series, times) {
  const ratio = window.devicePixelRatio || 1;
  canvas.width = W * ratio;
  canvas.height = H * ratio;
  const g = canvas.getContext('2d');
  g.scale(ratio, ratio);
  // zero line when zero is in range
  if (series.min < 0 && series.max > 0) {
    const y0 = 2 + (1 - (0 - series.min) / (series.max - series.min)) * (H - 4);
    g.strokeStyle = '#d5d9dd';
    g.beginPath();
    g.moveTo(0, y0);
    g.lineTo(W, y0);
    g.stroke();
  }
  // the series
  const pts = sparkPoints(series, times, W, H);
  g.strokeStyle = '#2c6fb7';
  g.lineWidth = 1.2;
  g.beginPath();
  for (let i = 0; i < pts.length; i += 2) (i ? g.lineTo : g.moveTo).call(g, pts[i], pts[i + 1]);
  g.stroke();
}

/** Plots for the neurons of `replay` in `container`; `setTime(t)` moves the cursors. */
export function createSparklines(container, replay) {
  container.replaceChildren();
  const all = neuronSeries(replay);
  const shown = all.slice(0, MAX_SPARKS);
  const times = replay.frames.map((f) => f.t);
  const T = times[times.length - 1] || 1;
  container.append(el('h2', {}, `Neurons (${all.length})`));
  if (all.length === 0) container.append(el('p', { class: 'muted' }, 'This creature has no neurons.'));
  if (all.length > shown.length)
    container.append(el('p', { class: 'muted' }, `showing the first ${shown.length}`));
  // one row per neuron: label and value above, plot with cursor below
  const list = el('div', { class: 'sparks' });
  const rows = shown.map((s) => {
    const value = el('span', { class: 'spark-value' });
    const canvas = el('canvas', { class: 'spark-plot', style: `width:${W}px;height:${H}px` });
    const cursor = el('div', { class: 'spark-cursor' });
    list.append(el('div', { class: 'spark', title: `range ${s.min.toPrecision(3)} .. ${s.max.toPrecision(3)}` },
      el('div', { class: 'spark-head' }, el('span', { class: 'spark-label' }, s.label), value),
      el('div', { class: 'spark-box' }, canvas, cursor)));
    drawSpark(canvas, s, times);
    return { s, value, cursor };
  });
  container.append(list);

  return {
    rows: rows.length,
    setTime(t) {
      const i = bracket(replay.frames, t).i;
      const x = `${(Math.min(Math.max(t / T, 0), 1) * W).toFixed(1)}px`;
      for (const r of rows) {
        r.cursor.style.left = x;
        r.value.textContent = r.s.values[i].toFixed(3);
      }
    },
  };
}
