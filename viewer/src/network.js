// The developed brain as a network: its sensors, neurons and effectors
// grouped by the part they belong to (global neurons apart), and the wires
// between them as the replay gives them (docs/replay-format.md: each
// neuron's and effector's `inputs`, [slot, weight] or [slot, weight, gate],
// a slot numbering the sensors first, then the neurons); its layout, a band
// per part with sensors, neurons and effectors in three columns; and the
// colours of values and weights. network_view.js draws it.

/** The layout's sizes in px: rows, bands, columns, text. */
export const NET = {
  row: 15, head: 13, bandGap: 5, pad: 6, node: 4.5, charWidth: 5.6, maxLabel: 14, gapSN: 44, gapNE: 24,
  wireMin: 0.6, wireMax: 3.2,
};

/** Whether a replay's brain is a graph brain (not another kind's controller) and whether it has its wires. */
export function brainOf(replay) {
  const controller = typeof replay.creature === 'string' || replay.neurons.some((n) => n.fn === 'controller');
  const wired = replay.neurons.some((n) => Array.isArray(n.inputs)) || (replay.effectors ?? []).some((e) => Array.isArray(e.inputs));
  return { graph: !controller, wired };
}

/**
 * What a slot of the brain's values is: {kind: 'sensor' or 'neuron', index},
 * sensors first (slot < nSensors is sensor `slot`), then neurons (neuron
 * `slot - nSensors`); null for a slot past the last neuron.
 */
export function decodeSlot(slot, nSensors, nNeurons) {
  if (!Number.isInteger(slot) || slot < 0) return null;
  if (slot < nSensors) return { kind: 'sensor', index: slot };
  if (slot < nSensors + nNeurons) return { kind: 'neuron', index: slot - nSensors };
  return null;
}

/**
 * The part an effector belongs to: its joint's child (the part the joint
 * attaches), or its muscle's child end (`part_b`); -1 when unknown.
 */
export function effectorPart(replay, e) {
  if (e.muscle !== undefined) return replay.muscles?.[e.muscle]?.part_b ?? -1;
  return replay.joints[e.joint]?.child ?? -1;
}

/**
 * The network of `replay`'s brain, or null when it is not a graph brain
 * (another kind's controller). `groups`: per part that has any (global
 * neurons first, part -1), its part, gene, whether mirrored, and the indices
 * of its sensors, neurons and effectors; `wires`: {from, to, weight, gate},
 * `from` and `gate` decoded slots (decodeSlot; gate null when ungated), `to`
 * {kind: 'neuron' or 'effector', index}; a wire from a slot the brain lacks
 * is left out and counted in `dropped`; `wired`: whether the replay holds the
 * wires at all; `maxWeight`: the largest |weight|.
 */
export function networkModel(replay) {
  const brain = brainOf(replay);
  if (!brain.graph) return null;
  const sensors = replay.sensors ?? [];
  const effectors = replay.effectors ?? [];
  const nS = sensors.length, nN = replay.neurons.length;
  const byPart = new Map();
  const group = (part) => {
    if (!byPart.has(part)) {
      const p = replay.parts[part];
      byPart.set(part, { part, gene: p ? p.gene : -1, mirrored: p ? !!p.mirrored : false, sensors: [], neurons: [], effectors: [] });
    }
    return byPart.get(part);
  };
  sensors.forEach((s, k) => group(s.part).sensors.push(k));
  replay.neurons.forEach((n, k) => group(n.part < 0 ? -1 : n.part).neurons.push(k));
  effectors.forEach((e, k) => group(effectorPart(replay, e)).effectors.push(k));
  const groups = [...byPart.values()].sort((a, b) => a.part - b.part);
  const wires = [];
  let dropped = 0, maxWeight = 0;
  const wire = (to, inputs) => {
    for (const w of Array.isArray(inputs) ? inputs : []) {
      const from = Array.isArray(w) ? decodeSlot(w[0], nS, nN) : null;
      const weight = Array.isArray(w) && typeof w[1] === 'number' ? w[1] : 0;
      if (!from) {
        ++dropped;
        continue;
      }
      const gate = w.length > 2 ? decodeSlot(w[2], nS, nN) : null;
      wires.push({ from, to, weight, gate });
      maxWeight = Math.max(maxWeight, Math.abs(weight));
    }
  };
  replay.neurons.forEach((n, index) => wire({ kind: 'neuron', index }, n.inputs));
  effectors.forEach((e, index) => wire({ kind: 'effector', index }, e.inputs));
  return { groups, wires, dropped, wired: brain.wired, maxWeight, counts: { sensor: nS, neuron: nN, effector: effectors.length } };
}

/** A sensor's short label: its index and what it reads ("3 touch -z", "0 angle 1", "2 eye", "5 len m2": muscle 2's length). */
export function sensorShort(s, k) {
  switch (s.type) {
    case 'contact': return `${k} touch ${s.face ?? '?'}`;
    case 'photoreceptor': return `${k} eye`;
    case 'muscle_length': return `${k} len m${s.muscle ?? '?'}`;
    default: return `${k} angle ${s.dof ?? 0}`;
  }
}

/** A neuron's short label: its index and function, the function cut to fit. */
export function neuronShort(n, k, max = NET.maxLabel) {
  const text = `${k} ${n.fn ?? '?'}`;
  return text.length > max ? text.slice(0, max - 1) + '…' : text;
}

/** An effector's short label: its index and the joint and dof it drives ("2 j1 d0"), or its muscle ("2 m4"). */
export function effectorShort(e, k) {
  return e.muscle !== undefined ? `${k} m${e.muscle}` : `${k} j${e.joint} d${e.dof}`;
}

/** What a part's band is headed: "part 3 · gene 1" (mirrored: "gene 1'"), or "global". */
export function bandTitle(group) {
  return group.part < 0 ? 'global' : `part ${group.part} · gene ${group.gene}${group.mirrored ? "'" : ''}`;
}

const f = (v) => (Math.round(v * 10) / 10).toString();

/** The columns' headings. */
export const HEADINGS = { sensor: 'sensors', neuron: 'neurons', effector: 'effectors' };

/** A wire's width (px) for its |weight| against the largest: wireMin to wireMax. */
export function wireWidth(weight, maxWeight, g = NET) {
  const share = maxWeight > 0 ? Math.min(Math.abs(weight) / maxWeight, 1) : 0;
  return g.wireMin + (g.wireMax - g.wireMin) * share;
}

/**
 * The network's layout: `at`, where each node is ({sensor, neuron,
 * effector}: per index [x, y], null for one in no band), `labels` (per kind,
 * per index, the short label), `bands` (per group: y, height, title), the
 * columns' x (`columns`), `wires` (the model's, each with its path data `d`
 * and width) and the whole size. A band holds its part's sensors, neurons
 * and effectors, one per row in three columns, the tallest column setting
 * its height; sensors' labels left of them, neurons' and effectors' right.
 * A wire leaves its source's right side and enters its target's left side;
 * one between two neurons bows out to the left of their column.
 */
export function networkLayout(model, replay, g = NET) {
  const sensors = replay.sensors ?? [], effectors = replay.effectors ?? [];
  const labels = {
    sensor: sensors.map(sensorShort),
    neuron: replay.neurons.map((n, k) => neuronShort(n, k, g.maxLabel)),
    effector: effectors.map(effectorShort),
  };
  const longest = (list) => Math.max(0, ...list.map((s) => s.length)) * g.charWidth;
  const bandWidth = Math.max(0, ...model.groups.map((b) => bandTitle(b).length)) * g.charWidth;
  // each column as wide as its longest label or heading (HEADINGS)
  const sx = g.pad + longest([...labels.sensor, HEADINGS.sensor]) + 6 + g.node;
  const nx = sx + g.gapSN;
  const ex = nx + g.node + 6 + longest([...labels.neuron, HEADINGS.neuron]) + g.gapNE;
  const width = Math.ceil(Math.max(ex + g.node + 6 + longest([...labels.effector, HEADINGS.effector]) + g.pad, g.pad + bandWidth + g.pad));
  const at = { sensor: sensors.map(() => null), neuron: replay.neurons.map(() => null), effector: effectors.map(() => null) };
  const bands = [];
  // the columns' headings, then the bands
  let y = g.pad + g.head;
  for (const b of model.groups) {
    const rows = Math.max(1, b.sensors.length, b.neurons.length, b.effectors.length);
    const top = y + g.head;
    b.sensors.forEach((k, r) => (at.sensor[k] = [sx, top + (r + 0.5) * g.row]));
    b.neurons.forEach((k, r) => (at.neuron[k] = [nx, top + (r + 0.5) * g.row]));
    b.effectors.forEach((k, r) => (at.effector[k] = [ex, top + (r + 0.5) * g.row]));
    const height = g.head + rows * g.row + 3;
    bands.push({ part: b.part, gene: b.gene, mirrored: b.mirrored, y, height, title: bandTitle(b) });
    y += height + g.bandGap;
  }
  const wires = [];
  for (const w of model.wires) {
    const a = at[w.from.kind][w.from.index], b = at[w.to.kind][w.to.index];
    if (!a || !b) continue;
    let d;
    if (w.from.kind === 'neuron' && w.to.kind === 'neuron') {
      // out to the left of the column and back: further for a longer way
      const bow = 14 + Math.min(Math.abs(b[1] - a[1]) * 0.25, g.gapSN - 20);
      const x = a[0] - g.node;
      d = a === b
        ? `M${f(x)},${f(a[1] - 2)}C${f(x - 14)},${f(a[1] - 12)} ${f(x - 14)},${f(a[1] + 12)} ${f(x)},${f(a[1] + 2)}`
        : `M${f(x)},${f(a[1])}C${f(x - bow)},${f(a[1])} ${f(x - bow)},${f(b[1])} ${f(x)},${f(b[1])}`;
    } else {
      const x0 = a[0] + g.node, x1 = b[0] - g.node, mid = Math.max((x1 - x0) / 2, 12);
      d = `M${f(x0)},${f(a[1])}C${f(x0 + mid)},${f(a[1])} ${f(x1 - mid)},${f(b[1])} ${f(x1)},${f(b[1])}`;
    }
    wires.push({ ...w, d, width: wireWidth(w.weight, model.maxWeight, g) });
  }
  return {
    at, labels, bands, wires, columns: { sensor: sx, neuron: nx, effector: ex }, headY: g.pad + 9,
    width, height: Math.ceil(y - g.bandGap + g.pad),
  };
}

/** Colour of a positive weight or value, and of a negative one. */
export const POSITIVE = [44, 111, 183], NEGATIVE = [201, 79, 79];

/** Steps of the value colour scale on each side of 0. */
export const VALUE_STEPS = 16;

/**
 * The value colours, from -1 (NEGATIVE) through 0 (white) to +1 (POSITIVE)
 * in VALUE_STEPS steps a side: 2 VALUE_STEPS + 1 CSS colours, made once so
 * that colouring a frame makes no strings.
 */
export const VALUE_COLORS = Array.from({ length: 2 * VALUE_STEPS + 1 }, (_, i) => {
  const u = (i - VALUE_STEPS) / VALUE_STEPS;
  const c = u < 0 ? NEGATIVE : POSITIVE, a = Math.abs(u);
  const ch = (k) => Math.round(255 + (c[k] - 255) * a);
  return `rgb(${ch(0)},${ch(1)},${ch(2)})`;
});

/** The index into VALUE_COLORS of value `v` on a scale of `scale` (|v| >= scale: the end colour). */
export function valueStep(v, scale) {
  const u = scale > 0 ? v / scale : 0;
  const c = u > 1 ? 1 : u < -1 ? -1 : u || 0;
  return Math.round(c * VALUE_STEPS) + VALUE_STEPS;
}

/**
 * Per signal of `key` ('neurons', 'sensors', 'effectors') its colour scale:
 * the largest |value| over the frames from frame 1 on (frame 0 precedes the
 * brain's first step), at least 1, so values within [-1, 1] keep their
 * colour and a sum or an integral beyond it is shaded against its own reach.
 */
export function valueScales(frames, key, n) {
  const out = new Float64Array(n).fill(1);
  for (let i = frames.length > 1 ? 1 : 0; i < frames.length; ++i) {
    const v = frames[i][key];
    if (!v) continue;
    for (let k = 0; k < n; ++k) {
      const a = Math.abs(v[k]);
      if (a > out[k]) out[k] = a;
    }
  }
  return out;
}
