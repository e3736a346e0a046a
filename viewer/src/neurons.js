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
 * One series per neuron (series.js), its range min..max from frame 1 on
 * (frame 0 is before the brain's first step). They share their drawn range,
 * so traces compare at a glance: -1..1 for those inside it (the bounded sets'
 * outputs), and one range together for those beyond it (sims1994's sums and
 * integrals), widened to at least 1e-6.
 */
export function neuronSeries(replay) {
  const frames = replay.frames;
  const from = brainFrom(frames);
  const out = replay.neurons.map((n, k) => makeSeries({
    label: neuronLabel(n, k), kind: 'neuron', from,
    values: Float32Array.from(frames, (f) => f.neurons[k]),
  }));
  const beyond = out.filter((s) => s.min < -1 || s.max > 1);
  let lo = Math.min(...beyond.map((s) => s.min)), hi = Math.max(...beyond.map((s) => s.max));
  if (hi - lo < 1e-6) {
    lo -= 0.5;
    hi += 0.5;
  }
  for (const s of out) {
    const wide = beyond.includes(s);
    s.lo = wide ? lo : -1;
    s.hi = wide ? hi : 1;
    if (s.lo < 0 && s.hi > 0) s.lines.push({ v: 0, kind: 'zero' });
  }
  return out;
}

/** What the neurons' plots' vertical ranges are, in words. */
export function neuronAxis(series) {
  const beyond = series.filter((s) => s.lo !== -1 || s.hi !== 1);
  if (beyond.length === 0) return 'axis -1 .. 1';
  const range = `${beyond[0].format(beyond[0].lo)} .. ${beyond[0].format(beyond[0].hi)}`;
  return beyond.length === series.length
    ? `axis ${range}, shared`
    : `axis -1 .. 1; ${beyond.length} beyond it share ${range}`;
}
