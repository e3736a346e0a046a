// The brain's outputs over time, one series per neuron, for the traces
// beside the scene.
import { brainFrom, makeSeries } from './series.js';

export { sparkPoints } from './series.js';

/** How a neuron is named: the part it belongs to (or "global") and its function. */
export function neuronLabel(n, k) {
  const where = n.part < 0 ? 'global' : `part ${n.part}`;
  return `${k}: ${where} · ${n.fn ?? '?'}`;
}

/**
 * One series per neuron (series.js), each drawn over its own range, min..max
 * from frame 1 on (frame 0 is before the brain's first step). The drawn range
 * is widened to at least 1e-6 so a constant output draws as a flat line.
 */
export function neuronSeries(replay) {
  const frames = replay.frames;
  const from = brainFrom(frames);
  return replay.neurons.map((n, k) => {
    const s = makeSeries({
      label: neuronLabel(n, k), kind: 'neuron', from,
      values: Float32Array.from(frames, (f) => f.neurons[k]),
    });
    if (s.hi - s.lo < 1e-6) {
      s.lo -= 0.5;
      s.hi += 0.5;
    }
    if (s.lo < 0 && s.hi > 0) s.lines.push({ v: 0, kind: 'zero' });
    return s;
  });
}
