// A trace's numbers: its range and spread over the replay, whether it is
// constant, and where its points fall in a plot. Shared by the neuron
// traces and the signals panel.

/** A series whose standard deviation over the replay is below this is "constant". */
export const CONSTANT_STD = 1e-3;

/**
 * min, max, mean and (population) standard deviation of values[from..]. With
 * nothing from `from` on, of all values.
 */
export function stats(values, from = 0) {
  if (from >= values.length) from = 0;
  let min = Infinity, max = -Infinity, sum = 0;
  for (let i = from; i < values.length; ++i) {
    const v = values[i];
    if (v < min) min = v;
    if (v > max) max = v;
    sum += v;
  }
  const n = values.length - from;
  const mean = n > 0 ? sum / n : 0;
  let sq = 0;
  for (let i = from; i < values.length; ++i) sq += (values[i] - mean) ** 2;
  return { min, max, mean, std: n > 0 ? Math.sqrt(sq / n) : 0 };
}

/**
 * Where the brain's signals start to mean something: frame 0 is recorded
 * before the brain's first step (all its values 0), so a replay of more than
 * one frame takes their range and spread from frame 1 on.
 */
export function brainFrom(frames) {
  return frames.length > 1 ? 1 : 0;
}

/** A number for a range or a value: three decimals, or three digits when large. */
export function num3(v) {
  if (!Number.isFinite(v)) return String(v);
  const r = Math.abs(v) >= 1000 ? v.toPrecision(3) : v.toFixed(3);
  return r === '-0.000' ? '0.000' : r;
}

/** "min .. max" of a series in its own format. */
export function rangeText(s) {
  return `${s.format(s.min)} .. ${s.format(s.max)}`;
}

/** y of value v in a plot h high, `pad` pixels kept free at top and bottom (top = s.hi). */
export function valueY(s, v, h, pad = 2) {
  return pad + (1 - (v - s.lo) / (s.hi - s.lo)) * (h - 2 * pad);
}

/**
 * Points of a sparkline in a w x h box, from frame `series.from` (0 when not
 * given) on: x from the frame's time over the replay's duration, y from the
 * value (top = the drawn range's hi). Flat [x0, y0, x1, y1, ...].
 */
export function sparkPoints(series, times, w, h, pad = 2) {
  const T = times[times.length - 1] || 1;
  const from = Math.min(series.from ?? 0, series.values.length - 1);
  const out = new Float32Array((series.values.length - from) * 2);
  for (let i = from; i < series.values.length; ++i) {
    out[2 * (i - from)] = (times[i] / T) * w;
    out[2 * (i - from) + 1] = valueY(series, series.values[i], h, pad);
  }
  return out;
}

/**
 * A series: `values` (one per frame, in the unit shown: the raw values times
 * `scale`), their `min`, `max` from frame `from` on, their standard deviation
 * `std` in the raw unit and whether it is below CONSTANT_STD (`constant`).
 * The drawn range `lo`..`hi` and the horizontal `lines` ({v, kind: 'zero' |
 * 'stop'}) are the caller's to set; they start as min..max.
 */
export function makeSeries({ label, title = label, values, from = 0, scale = 1, format = num3, kind }) {
  const st = stats(values, from);
  const shown = scale === 1 ? Float32Array.from(values) : Float32Array.from(values, (v) => v * scale);
  return {
    label, title, kind, format, from, values: shown,
    min: st.min * scale, max: st.max * scale, std: st.std, constant: st.std < CONSTANT_STD,
    lo: st.min * scale, hi: st.max * scale, lines: [], stops: null, atStop: null,
  };
}
