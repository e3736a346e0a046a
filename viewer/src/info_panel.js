// What the page says about the creature shown: where it came from (in a
// run: its id, generation, parents and stored fitness), its body and brain,
// and how it did; for a catapult, its projectile and throw. Development's
// remarks are notes, not errors: evolved genomes often carry parts that do
// nothing. Its genome, when the page holds it, can be downloaded.
import { el } from './dom.js';
import { fitness, metres, seconds } from './format.js';
import { throwOf } from './flight.js';
import { generationRanges } from './lineage.js';
import { cssColor, PROJECTILE_COLOR } from './palette.js';

// the aim task's metric: D_t, the least distance from the throw's path to the target (m)
const TARGET_MISS = 'target miss';

/** The facts of `entry` ({label, replay}) as [name, text] rows. */
export function infoRows(entry) {
  const r = entry.replay;
  const res = r.result ?? {};
  const th = throwOf(r);
  const num = (v, f) => (typeof v === 'number' ? f(v) : '?');
  // a graph genome's dialect, or another creature kind's name (whose
  // controller has signals of its own rather than a graph brain's neurons)
  const kind = typeof r.creature === 'string' ? ['creature', r.creature] : ['dialect', r.dialect];
  const brain = typeof r.creature === 'string' ? 'controller signals' : 'neurons';
  const rows = [
    ['genome', r.genome],
    kind,
    ['body', `${r.parts.length} parts, ${r.joints.length} joints, ` +
      (r.muscles?.length ? `${r.muscles.length} muscles, ` : '') + `${r.neurons.length} ${brain}`],
    ['seed', String(r.seed)],
    ['simulated', num(res.seconds, seconds)],
  ];
  // the task's own measures by name (the river crossing's levels and food,
  // an aim task's target miss, in m)
  const metrics = { ...(res.metrics ?? {}) };
  if (th) {
    // a catapult: its distance is the projectile's, from release to rest
    rows.push(
      ['projectile', `part ${th.projectile}`],
      ['release', th.release === null ? 'not released' : `released at ${seconds(th.release)}`],
      ['throw distance', num(res.throw_distance ?? res.distance, metres)],
    );
    // (files before the task's metrics held it as result.target_miss)
    const miss = metrics[TARGET_MISS] ?? res.target_miss;
    delete metrics[TARGET_MISS];
    if (typeof miss === 'number') rows.push(['target miss', metres(miss)]);
  } else {
    rows.push(['distance', num(res.distance, metres)]);
  }
  for (const [name, value] of Object.entries(metrics)) rows.push([name, fitness(value)]);
  rows.push(['fitness', num(res.fitness, fitness)]);
  // task.trials > 1: the fitness is their mean or, under task.trial_score =
  // min, the least (a copy of one trial's: a mean equals the least only when
  // all are equal); what is shown is the first trial unless result.trial
  // names another (bestiary simulate --trial, show's page of every trial)
  const trials = res.trial_fitness;
  if (Array.isArray(trials) && trials.length > 1) {
    const least = Math.min(...trials);
    const word = res.fitness === least && trials.some((f) => f !== least) ? 'least' : 'mean';
    const shown = Number.isInteger(res.trial) && res.trial > 1 ? `trial ${res.trial}` : 'the first';
    rows.push(['trials', `${word} of ${trials.length}: ${trials.map(fitness).join(', ')} (shown: ${shown})`]);
  }
  return rows;
}

/**
 * What a run says about `member` ({id, gen, fitness, parent1, parent2,
 * operator, evaluations?, held_out?: {fitness, evaluations}}) as [name, text] rows; `best` is the run's overall best's id,
 * `bestOf` the generations it was the best of (numbers, in order), `score` what
 * the stored fitness takes of several evaluations ('mean' or 'least') and
 * `halfStep` and `quarterStep` whether they cycled through the step, half of it
 * and a quarter of it (the 2nd, 4th, ... at half the step with halfStep alone).
 */
export function memberRows(member, best, bestOf, score = 'mean', halfStep = false, quarterStep = false) {
  const parent = (id) => (id === null ? null : `#${id}`);
  const parents = [parent(member.parent1), parent(member.parent2)].filter((p) => p !== null);
  const rows = [
    ['individual', `#${member.id}` + (member.id === best ? ' (the overall best)' : '')],
    ['born in', `generation ${member.gen}, by ${member.operator || '?'}`],
    ['parents', parents.length ? parents.join(' and ') : 'none'],
  ];
  if (bestOf.length) rows.push(['best of', `generation${bestOf.length > 1 ? 's' : ''} ${generationRanges(bestOf)}`]);
  const n = member.evaluations ?? 1;
  const finer = finerStepText(n, halfStep, quarterStep);
  rows.push(['stored fitness', fitness(member.fitness) +
    (n > 1 ? ` (the ${score} of ${n} evaluations under fresh seeds${finer ? `, ${finer}` : ''}; ` +
      'the replay is the first)' : '')]);
  if (member.held_out)
    rows.push(['held out', `${fitness(member.held_out.fitness)} (the ${score} of ${member.held_out.evaluations} ` +
      'evaluations under seeds the run never used: what it scores where selection never looked)']);
  return rows;
}

/**
 * Which of `n` evaluations stepped finer, their steps cycling through the step,
 * half of it (`halfStep`) and a quarter of it (`quarterStep`), as the command
 * line says it (finer_step_text in src/eval/evaluate.cpp): "evaluation 2 at
 * half the step", "evaluations 2 and 4 at half the step", "evaluations 2 and 5
 * at half the step, 3 at a quarter of it"; '' when none did.
 */
export function finerStepText(n, halfStep = true, quarterStep = false) {
  const cycle = [1, ...(halfStep ? [2] : []), ...(quarterStep ? [4] : [])];
  let out = '';
  for (const divisor of [2, 4]) {
    const which = [];
    for (let k = 1; k < n; ++k) if (cycle[k % cycle.length] === divisor) which.push(String(k + 1));
    if (!which.length) continue;
    const list = which.length === 1 ? which[0] : `${which.slice(0, -1).join(', ')} and ${which.at(-1)}`;
    const head = out ? ', ' : `evaluation${which.length > 1 ? 's' : ''} `;
    out += head + list + (divisor === 2 ? ' at half the step' : out ? ' at a quarter of it' : ' at a quarter of the step');
  }
  return out;
}

/** A file named `name` holding `text`, saved by the browser. */
function download(name, text) {
  const url = URL.createObjectURL(new Blob([text], { type: 'application/json' }));
  const a = el('a', { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/**
 * Fills `container` with the facts of `entry` ({label, replay, genome?});
 * in a run, `run` is {member, best, bestOf, score?, halfStep?, quarterStep?} (memberRows).
 */
export function showInfo(container, entry, run = null) {
  const res = entry.replay.result ?? {};
  // the projectile's row carries a swatch of its colour in the scene
  const projectile = throwOf(entry.replay)?.color ?? PROJECTILE_COLOR;
  const value = (k, v) => (k === 'projectile'
    ? el('dd', {}, el('span', { class: 'swatch', style: `background:${cssColor(projectile)}` }), v)
    : el('dd', {}, v ?? '?'));
  const rows = [...(run ? memberRows(run.member, run.best, run.bestOf, run.score, run.halfStep, run.quarterStep) : []), ...infoRows(entry)];
  container.replaceChildren(
    el('h1', {}, entry.label),
    el('dl', {}, ...rows.flatMap(([k, v]) => [el('dt', {}, k), value(k, v)])),
  );
  if (typeof entry.genome === 'string') {
    const name = run ? `individual-${run.member.id}.json` : `${entry.label}.json`;
    container.append(el('button', {
      type: 'button', id: 'download-genome', class: 'download', title: `save this creature's genome as ${name}`,
      onclick: () => download(name, entry.genome),
    }, 'Download genome'));
  }
  if (res.failed) container.append(el('p', { class: 'warn' }, `failed: ${res.failure}`));
  const notes = res.warnings ?? [];
  if (notes.length) {
    container.append(el('details', { class: 'notes' },
      el('summary', {}, `Development notes (${notes.length})`),
      ...notes.map((w) => el('p', { class: 'muted note' }, w))));
  }
}
