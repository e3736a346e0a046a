// What the page says about the creature shown: where it came from, its body
// and brain, and how it did; for a catapult, its projectile and throw.
import { el } from './dom.js';
import { fitness, metres, seconds } from './format.js';
import { throwOf } from './flight.js';
import { cssColor, PROJECTILE_COLOR } from './palette.js';

/** The facts of `entry` ({label, replay}) as [name, text] rows. */
export function infoRows(entry) {
  const r = entry.replay;
  const res = r.result ?? {};
  const th = throwOf(r);
  const num = (v, f) => (typeof v === 'number' ? f(v) : '?');
  const rows = [
    ['genome', r.genome],
    ['dialect', r.dialect],
    ['body', `${r.parts.length} parts, ${r.joints.length} joints, ${r.neurons.length} neurons`],
    ['seed', String(r.seed)],
    ['simulated', num(res.seconds, seconds)],
  ];
  if (th) {
    // a catapult: its distance is the projectile's, from release to rest
    rows.push(
      ['projectile', `part ${th.projectile}`],
      ['release', th.release === null ? 'not released' : `released at ${seconds(th.release)}`],
      ['throw distance', num(res.throw_distance ?? res.distance, metres)],
    );
    if (typeof res.target_miss === 'number') rows.push(['target miss', metres(res.target_miss)]);
  } else {
    rows.push(['distance', num(res.distance, metres)]);
  }
  rows.push(['fitness', num(res.fitness, fitness)]);
  // task.trials > 1: the fitness is a mean; what is shown is the first trial
  const trials = res.trial_fitness;
  if (Array.isArray(trials) && trials.length > 1) {
    rows.push(['trials', `mean of ${trials.length}: ${trials.map(fitness).join(', ')} (shown: the first)`]);
  }
  return rows;
}

/** Fills `container` with the facts of `entry` ({label, replay}). */
export function showInfo(container, entry) {
  const res = entry.replay.result ?? {};
  // the projectile's row carries a swatch of its colour in the scene
  const value = (k, v) => (k === 'projectile'
    ? el('dd', {}, el('span', { class: 'swatch', style: `background:${cssColor(PROJECTILE_COLOR)}` }), v)
    : el('dd', {}, v ?? '?'));
  container.replaceChildren(
    el('h1', {}, entry.label),
    el('dl', {}, ...infoRows(entry).flatMap(([k, v]) => [el('dt', {}, k), value(k, v)])),
  );
  if (res.failed) container.append(el('p', { class: 'warn' }, `failed: ${res.failure}`));
  for (const w of res.warnings ?? []) container.append(el('p', { class: 'warn' }, `warning: ${w}`));
}
