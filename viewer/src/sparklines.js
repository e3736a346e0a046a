// Traces of series (series.js) over the whole replay, one small plot each
// with a cursor at the present moment, its range as text and a badge when it
// is constant (or, for a joint, mostly at a stop). A plot takes its box's
// width and is drawn again when that changes; otherwise only the cursors and
// values move. The neurons' panel is one such list.
import { el } from './dom.js';
import { neuronAxis, neuronSeries } from './neurons.js';
import { CONSTANT_STD, rangeText, sparkPoints, valueY } from './series.js';
import { AT_STOP_SHARE } from './signals.js';
import { bracket } from './timeline.js';

/** Most plots drawn in one list; a longer list shows its first. */
export const MAX_SPARKS = 200;
/** Height of a plot (CSS px). */
export const SPARK_HEIGHT = 26;

/** Colour of each kind of trace. */
export const TRACE_COLORS = { neuron: '#2c6fb7', effector: '#8a67c1', sensor: '#1f8a94', joint: '#3d8a48' };
const ZERO_COLOR = '#d5d9dd', STOP_COLOR = '#c94f4f', BEYOND_COLOR = 'rgba(201, 79, 79, 0.09)';

// draws series s over the canvas's width; false when it has none (hidden)
function drawSpark(canvas, s, times) {
  const w = canvas.clientWidth, h = SPARK_HEIGHT;
  if (w <= 0) return false;
  const ratio = window.devicePixelRatio || 1;
  canvas.width = Math.round(w * ratio);
  canvas.height = Math.round(h * ratio);
  const g = canvas.getContext('2d');
  g.scale(ratio, ratio);
  // beyond a joint's stops: shaded
  if (s.stops) {
    g.fillStyle = BEYOND_COLOR;
    const top = valueY(s, s.stops[1], h), bottom = valueY(s, s.stops[0], h);
    g.fillRect(0, 0, w, Math.max(top, 0));
    g.fillRect(0, bottom, w, Math.max(h - bottom, 0));
  }
  // zero and stop lines
  for (const l of s.lines) {
    const y = Math.round(valueY(s, l.v, h)) + 0.5;
    g.strokeStyle = l.kind === 'stop' ? STOP_COLOR : ZERO_COLOR;
    g.lineWidth = 1;
    g.setLineDash(l.kind === 'stop' ? [4, 3] : []);
    g.beginPath();
    g.moveTo(0, y);
    g.lineTo(w, y);
    g.stroke();
  }
  g.setLineDash([]);
  // the series
  const pts = sparkPoints(s, times, w, h);
  g.strokeStyle = TRACE_COLORS[s.kind] ?? TRACE_COLORS.neuron;
  g.lineWidth = 1.2;
  g.beginPath();
  for (let i = 0; i < pts.length; i += 2) (i ? g.lineTo : g.moveTo).call(g, pts[i], pts[i + 1]);
  // a single point: a dot's worth of line
  if (pts.length === 2) g.lineTo(pts[0] + 1, pts[1]);
  g.stroke();
  return true;
}

// the row of one series: label and value, plot and cursor, range and badges
function traceRow(s) {
  const value = el('span', { class: 'spark-value' });
  const canvas = el('canvas', { class: 'spark-plot' });
  const cursor = el('div', { class: 'spark-cursor' });
  const badges = [];
  if (s.constant)
    badges.push(el('span', { class: 'badge constant', title: `standard deviation ${s.std.toPrecision(2)}, below ${CONSTANT_STD}` }, 'constant'));
  if (s.atStop !== null && s.atStop >= AT_STOP_SHARE)
    badges.push(el('span', { class: 'badge at-stop', title: `at or beyond a stop for ${Math.round(100 * s.atStop)}% of the replay` },
      `at stop ${Math.round(100 * s.atStop)}%`));
  const range = rangeText(s);
  const from = s.from > 0 ? ' (from the first brain step; frame 0 comes before it)' : '';
  const row = el('div', { class: 'spark', 'data-kind': s.kind, title: `${s.title}\nrange ${range}${from}` },
    el('div', { class: 'spark-head' }, el('span', { class: 'spark-label' }, s.label), value),
    el('div', { class: 'spark-box' }, canvas, cursor),
    el('div', { class: 'spark-foot' },
      el('span', { class: 'spark-range' }, range), ...badges,
      s.stops ? el('span', { class: 'spark-stops' }, `stops ${s.format(s.stops[0])} .. ${s.format(s.stops[1])}`) : null));
  return { s, row, canvas, value, cursor, width: 0 };
}

/**
 * A list of traces for `series` over `frames`: { element, rows (how many
 * are drawn), setTime(t), dispose() }.
 */
export function createTraceList(series, frames) {
  const shown = series.slice(0, MAX_SPARKS);
  const times = frames.map((f) => f.t);
  const T = times[times.length - 1] || 1;
  const element = el('div', { class: 'sparks' });
  if (series.length > shown.length) element.append(el('p', { class: 'muted' }, `showing the first ${shown.length} of ${series.length}`));
  const rows = shown.map(traceRow);
  element.append(...rows.map((r) => r.row));
  // each plot is drawn at its width, again whenever that changes (a resize,
  // a scroll bar coming or going, a group opened)
  const byCanvas = new Map(rows.map((r) => [r.canvas, r]));
  const redraw = (r) => {
    const w = r.canvas.clientWidth;
    if (w !== r.width && drawSpark(r.canvas, r.s, times)) r.width = w;
  };
  const observer = typeof ResizeObserver === 'function'
    ? new ResizeObserver((entries) => entries.forEach((e) => redraw(byCanvas.get(e.target))))
    : null;
  rows.forEach((r) => observer?.observe(r.canvas));

  return {
    element,
    rows: rows.length,
    /** Draws every plot not yet drawn at its present width (the observer does it too, a frame later). */
    redraw() { rows.forEach(redraw); },
    setTime(t) {
      const i = bracket(frames, t).i;
      const x = `${(Math.min(Math.max(t / T, 0), 1) * 100).toFixed(3)}%`;
      for (const r of rows) {
        r.cursor.style.left = x;
        r.value.textContent = r.s.format(r.s.values[i]);
      }
    },
    dispose() { observer?.disconnect(); },
  };
}

/** Traces of the neurons of `replay` in `container`; `setTime(t)` moves the cursors. */
export function createSparklines(container, replay) {
  container.replaceChildren();
  const all = neuronSeries(replay);
  container.append(el('div', { class: 'panel-head' },
    el('h2', {}, `Neurons (${all.length})`),
    all.length ? el('span', { class: 'group-note' }, neuronAxis(all)) : null));
  if (all.length === 0) {
    container.append(el('p', { class: 'muted' }, 'This creature has no neurons.'));
    return { rows: 0, setTime() {}, dispose() {} };
  }
  const list = createTraceList(all, replay.frames);
  container.append(list.element);
  list.redraw();
  return list;
}
