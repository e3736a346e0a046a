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
 * pixel positions, and the scales both ways. The fitness range holds zero,
 * the three curves and the run's members (so a lineage fits too).
 */
export function curveLayout(run, width, height, pad = { left: 36, right: 8, top: 8, bottom: 20 }) {
  const gens = [...run.generations].sort((a, b) => a.gen - b.gen);
  const g0 = gens.length ? gens[0].gen : 0;
  const g1 = gens.length ? gens[gens.length - 1].gen : 1;
  let y0 = 0, y1 = 0;
  const widen = (v) => {
    y0 = Math.min(y0, v);
    y1 = Math.max(y1, v);
  };
  for (const g of gens) for (const k of CURVES) widen(g[k]);
  for (const m of run.members ?? []) widen(m.fitness);
  const yTicks = niceTicks(y0, y1 > y0 ? y1 : y0 + 1, 4);
  const yLo = Math.min(y0, yTicks[0]), yHi = Math.max(y1, yTicks[yTicks.length - 1]);
  // (one generation: its tick alone, in the middle)
  const xTicks = niceTicks(g0, g1 > g0 ? g1 : g0 + 1, 5).filter((v) => Number.isInteger(v) && (g1 > g0 || v === g0));
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
 * The creatures a run offers by generation: per generation its best,
 * [{ gen, id, best (its fitness), replayIndex (null when not replayed) }] in
 * generation order.
 */
export function generationChoices(run) {
  const replayOf = new Map(run.members.map((m) => [m.id, m.replay_index]));
  return [...run.generations]
    .sort((a, b) => a.gen - b.gen)
    .map((g) => ({ gen: g.gen, id: g.best_id, best: g.best, replayIndex: replayOf.get(g.best_id) ?? null }));
}

/** The playable choice whose generation is nearest to `gen` (null when there is none). */
export function nearestChoice(choices, gen) {
  let best = null;
  for (const c of choices) {
    if (c.replayIndex === null) continue;
    if (!best || Math.abs(c.gen - gen) < Math.abs(best.gen - gen)) best = c;
  }
  return best;
}
