// What the page says about the creature shown: where it came from, its body
// and brain, and how it did.
import { el } from './dom.js';
import { fitness, metres, seconds } from './format.js';

/** Fills `container` with the facts of `entry` ({label, replay}). */
export function showInfo(container, entry) {
  const r = entry.replay;
  const res = r.result ?? {};
  const rows = [
    ['genome', r.genome],
    ['dialect', r.dialect],
    ['body', `${r.parts.length} parts, ${r.joints.length} joints, ${r.neurons.length} neurons`],
    ['seed', String(r.seed)],
    ['simulated', typeof res.seconds === 'number' ? seconds(res.seconds) : '?'],
    ['distance', typeof res.distance === 'number' ? metres(res.distance) : '?'],
    ['fitness', typeof res.fitness === 'number' ? fitness(res.fitness) : '?'],
  ];
  container.replaceChildren(
    el('h1', {}, entry.label),
    el('dl', {}, ...rows.flatMap(([k, v]) => [el('dt', {}, k), el('dd', {}, v ?? '?')])),
  );
  if (res.failed) container.append(el('p', { class: 'warn' }, `failed: ${res.failure}`));
  for (const w of res.warnings ?? []) container.append(el('p', { class: 'warn' }, `warning: ${w}`));
}
