// The brain's outputs over time, one series per neuron, for the sparklines
// beside the scene.

/** How a neuron is named: the part it belongs to (or "global") and its function. */
export function neuronLabel(n, k) {
  const where = n.part < 0 ? 'global' : `part ${n.part}`;
  return `${k}: ${where} · ${n.fn ?? '?'}`;
}

/**
 * One series per neuron: { label, values (per frame), min, max }. The range is
 * widened to at least 1e-6 so a constant output draws as a flat line.
 */
export function neuronSeries(replay) {
  const frames = replay.frames;
  return replay.neurons.map((n, k) => {
    const values = new Float32Array(frames.length);
    let min = Infinity, max = -Infinity;
    frames.forEach((f, i) => {
      const v = f.neurons[k];
      values[i] = v;
      if (v < min) min = v;
      if (v > max) max = v;
    });
    if (max - min < 1e-6) {
      min -= 0.5;
      max += 0.5;
    }
    return { label: neuronLabel(n, k), values, min, max };
  });
}

/**
 * Points of a sparkline in a w x h box: x from the frame's time over the
 * replay's duration, y from the value (top = max). Flat [x0, y0, x1, y1, ...].
 */
export function sparkPoints(series, times, w, h, pad = 2) {
  const T = times[times.length - 1] || 1;
  const out = new Float32Array(series.values.length * 2);
  const range = series.max - series.min;
  series.values.forEach((v, i) => {
    out[2 * i] = (times[i] / T) * w;
    out[2 * i + 1] = pad + (1 - (v - series.min) / range) * (h - 2 * pad);
  });
  return out;
}
