// Fitness curves of a run: best, mean and median per generation, laid out as
// SVG paths in a box, with round-number ticks.

/** The three curves, in drawing order (the best on top). */
export const CURVES = ['median', 'mean', 'best'];

/** About n round-number ticks covering [lo, hi] (steps of 1, 2 or 5 times a power of ten). */
export function niceTicks(lo, hi, n = 5) {
  if (!(hi > lo)) {
    hi = lo + 1;
  }
  const raw = (hi - lo) / Math.max(1, n);
  const mag = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => s >= raw);
  const ticks = [];
  for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step)
    ticks.push(Math.abs(v) < step * 1e-9 ? 0 : Number(v.toPrecision(12)));
  return ticks;
}

/**
 * Layout of a run's curves in a width x height box with margins `pad`
 * ({left, right, top, bottom}): SVG path data per curve, ticks with their
 * pixel positions, and the scales both ways.
 */
export function curveLayout(run, width, height, pad = { left: 36, right: 8, top: 8, bottom: 20 }) {
  const gens = [...run.generations].sort((a, b) => a.gen - b.gen);
  // ranges: generations on x; all three curves and zero on y
  const g0 = gens.length ? gens[0].gen : 0;
  const g1 = gens.length ? gens[gens.length - 1].gen : 1;
  let y0 = 0, y1 = 0;
  for (const g of gens) for (const k of CURVES) {
    y0 = Math.min(y0, g[k]);
    y1 = Math.max(y1, g[k]);
  }
  const yTicks = niceTicks(y0, y1 > y0 ? y1 : y0 + 1, 4);
  const yLo = Math.min(y0, yTicks[0]), yHi = Math.max(y1, yTicks[yTicks.length - 1]);
  const xTicks = niceTicks(g0, g1 > g0 ? g1 : g0 + 1, 5).filter((v) => Number.isInteger(v));
  const plotW = width - pad.left - pad.right, plotH = height - pad.top - pad.bottom;
  const x = (gen) => pad.left + (g1 > g0 ? (gen - g0) / (g1 - g0) : 0.5) * plotW;
  const y = (v) => pad.top + (1 - (v - yLo) / (yHi - yLo)) * plotH;
  const genAt = (px) => g0 + ((px - pad.left) / plotW) * (g1 - g0);
  // one path per curve
  const f = (v) => (Math.round(v * 10) / 10).toString();
  const paths = {};
  for (const k of CURVES)
    paths[k] = gens.map((g, i) => `${i ? 'L' : 'M'}${f(x(g.gen))},${f(y(g[k]))}`).join('');
  return {
    paths,
    xTicks: xTicks.map((v) => ({ value: v, px: x(v) })),
    yTicks: yTicks.map((v) => ({ value: v, px: y(v) })),
    x, y, genAt,
    plot: { left: pad.left, top: pad.top, width: plotW, height: plotH },
  };
}

/**
 * The creatures a run offers, one per generation that has a best:
 * [{ gen, replayIndex, best }] in generation order.
 */
export function generationChoices(run) {
  const best = new Map(run.generations.map((g) => [g.gen, g.best]));
  return [...run.best_of_generation]
    .sort((a, b) => a.gen - b.gen)
    .map((b) => ({ gen: b.gen, replayIndex: b.replay_index, best: best.get(b.gen) ?? null }));
}

/** The choice whose generation is nearest to `gen` (null when there are none). */
export function nearestChoice(choices, gen) {
  let best = null;
  for (const c of choices) if (!best || Math.abs(c.gen - gen) < Math.abs(best.gen - gen)) best = c;
  return best;
}
