// The network (network.js) as SVG: a band per part (global neurons first),
// its sensors (squares), neurons (circles) and effectors (diamonds) in
// three columns, the wires between them as wide as their weight and blue
// (positive) or red (negative), dashed when a switch gates them. While the
// replay plays each node takes the colour of its present value; only the
// nodes whose colour step changed are touched, and nothing is made per frame.
import { el, svg } from './dom.js';
import { cssColor, geneColor } from './palette.js';
import { neuronLabel } from './neurons.js';
import { effectorLabel, sensorLabel } from './signals.js';
import { HEADINGS, VALUE_COLORS, networkLayout, valueScales, valueStep } from './network.js';
import { frameIndexAt } from './timeline.js';

/** How much larger than its layout the network is drawn, room allowing. */
const ZOOM = 1.25;
const KINDS = ['sensor', 'neuron', 'effector'];
const FRAME_KEY = { sensor: 'sensors', neuron: 'neurons', effector: 'effectors' };

// a unit's name in a wire's tooltip
const unitName = (u) => `${u.kind} ${u.index}`;

function wireTitle(w) {
  return `${unitName(w.from)} to ${unitName(w.to)}: weight ${w.weight}` + (w.gate ? `, gated by ${unitName(w.gate)}` : '');
}

// a unit's tooltip: its full label, bias and inputs
function unitTitle(replay, kind, k) {
  if (kind === 'sensor') return sensorLabel(replay.sensors[k], k);
  const u = kind === 'neuron' ? replay.neurons[k] : replay.effectors[k];
  const label = kind === 'neuron' ? `neuron ${neuronLabel(u, k)}` : `effector ${effectorLabel(u, k)}`;
  const n = Array.isArray(u.inputs) ? u.inputs.length : 0;
  return `${label}\n${n} input${n === 1 ? '' : 's'}` + (typeof u.bias === 'number' && u.bias !== 0 ? `, bias ${u.bias}` : '');
}

// a node's mark at [x, y]: square, circle or diamond of half-size r
function mark(kind, [x, y], r) {
  if (kind === 'neuron') return svg('circle', { cx: x, cy: y, r });
  if (kind === 'sensor') return svg('rect', { x: x - r, y: y - r, width: 2 * r, height: 2 * r });
  return svg('path', { d: `M${x - r - 1},${y}L${x},${y - r - 1}L${x + r + 1},${y}L${x},${y + r + 1}Z` });
}

/**
 * The network of `model` (network.js) for `replay` in `container`;
 * `onHover(kind, index)` is called with the unit under the pointer (kind
 * null when it leaves). Returns {wires (drawn), setTime(t), setActive(on)
 * (drawn or not: colours follow time only while active), setHighlight(h)}.
 */
export function createNetworkView(container, model, replay, onHover) {
  const L = networkLayout(model, replay);
  const r = 4.5;
  // drawn larger than its layout, room allowing (shrunk to the panel when wider)
  const graph = svg('svg', { class: 'network', width: Math.round(L.width * ZOOM), height: Math.round(L.height * ZOOM),
    viewBox: `0 0 ${L.width} ${L.height}`,
    role: 'group', 'aria-label': 'the brain: sensors, neurons and effectors by part, and the wires between them' });
  // bands, then wires, then nodes and labels over them
  const bands = L.bands.map((b) => {
    const color = b.part < 0 ? '#8c959f' : cssColor(geneColor(b.gene, b.mirrored));
    return svg('g', { class: 'band', 'data-part': b.part },
      svg('rect', { class: 'band-back', x: 1, y: b.y, width: L.width - 2, height: b.height, style: `fill:${color}` }),
      svg('rect', { class: 'band-bar', x: 1, y: b.y, width: 3, height: b.height, style: `fill:${color}` }),
      svg('text', { class: 'band-title', x: 8, y: b.y + 10 }, b.title));
  });
  graph.append(...bands);
  const head = (x, anchor, text) => svg('text', { class: 'column-head', x, y: L.headY, 'text-anchor': anchor }, text);
  graph.append(head(L.columns.sensor + r, 'end', HEADINGS.sensor), head(L.columns.neuron - r, 'start', HEADINGS.neuron),
    head(L.columns.effector - r, 'start', HEADINGS.effector));
  const wires = L.wires.map((w) => svg('path', {
    class: `wire ${w.weight < 0 ? 'neg' : 'pos'}${w.gate ? ' gated' : ''}`, d: w.d, 'stroke-width': w.width.toFixed(2),
  }, svg('title', {}, wireTitle(w))));
  graph.append(...wires);
  // nodes: per kind, per index, the mark (null for none)
  const nodes = {}, marks = {};
  for (const kind of KINDS) {
    nodes[kind] = L.at[kind].map(() => null);
    marks[kind] = L.at[kind].map(() => null);
    L.at[kind].forEach((p, k) => {
      if (!p) return;
      const m = mark(kind, p, r);
      m.setAttribute('class', 'unit-mark');
      m.setAttribute('fill', VALUE_COLORS[(VALUE_COLORS.length - 1) / 2]);
      const left = kind === 'sensor';
      const label = svg('text', { class: 'unit-label', x: left ? p[0] - r - 3 : p[0] + r + 3, y: p[1] + 3.5,
        'text-anchor': left ? 'end' : 'start' }, L.labels[kind][k]);
      const g = svg('g', { class: `unit ${kind}`, 'data-kind': kind, 'data-index': k }, svg('title', {}, unitTitle(replay, kind, k)), m, label);
      g.addEventListener('pointerenter', () => onHover(kind, k));
      g.addEventListener('pointerleave', () => onHover(null, -1));
      graph.append(g);
      nodes[kind][k] = g;
      marks[kind][k] = m;
    });
  }
  const note = model.wired ? null
    : el('p', { class: 'muted graph-note' }, 'This replay was written before replays held the brain\'s wires: its units only.');
  container.replaceChildren(el('div', { class: 'graph-box' }, graph),
    el('p', { class: 'muted graph-note' }, 'Blue: positive, red: negative; a wire as wide as its weight, dashed when a switch gates it; ' +
      'a unit coloured by its value now (white 0, full colour at ±1 or its largest).'), note);

  // colours by value: per kind its scales, the step each node shows
  const frames = replay.frames;
  const scales = {}, shown = {};
  for (const kind of KINDS) {
    scales[kind] = valueScales(frames, FRAME_KEY[kind], L.at[kind].length);
    shown[kind] = new Int16Array(L.at[kind].length).fill(-1);
  }
  let active = false, frame = -1, t = 0;
  function colour() {
    const f = frames[frame];
    for (const kind of KINDS) {
      const values = f[FRAME_KEY[kind]];
      if (!values) continue;
      const m = marks[kind], s = scales[kind], seen = shown[kind];
      for (let k = 0; k < m.length; ++k) {
        if (!m[k]) continue;
        const step = valueStep(values[k], s[k]);
        if (step !== seen[k]) {
          seen[k] = step;
          m[k].setAttribute('fill', VALUE_COLORS[step]);
        }
      }
    }
  }
  // lit units, per kind (reused), for a highlight
  const lit = {};
  for (const kind of KINDS) lit[kind] = new Uint8Array(L.at[kind].length);

  return {
    wires: wires.length,
    setTime(time) {
      t = time;
      if (!active) return;
      const i = frameIndexAt(frames, t);
      if (i === frame) return;
      frame = i;
      colour();
    },
    setActive(on) {
      active = on;
      if (on) {
        frame = -1;
        this.setTime(t);
      }
    },
    setHighlight(h) {
      const on = h !== null && (h.neurons.length + h.sensors.length + h.effectors.length + h.parts.length) > 0;
      graph.classList.toggle('focused', on);
      for (const kind of KINDS) {
        lit[kind].fill(0);
        if (on) for (const k of h[FRAME_KEY[kind]]) lit[kind][k] = 1;
        nodes[kind].forEach((g, k) => g?.classList.toggle('lit', lit[kind][k] === 1));
      }
      L.wires.forEach((w, i) => wires[i].classList.toggle('lit',
        on && (lit[w.from.kind][w.from.index] === 1 || lit[w.to.kind][w.to.index] === 1)));
      bands.forEach((b, i) => b.classList.toggle('lit', on && h.parts.includes(L.bands[i].part)));
    },
  };
}
