// The run panel: where the run came from (preset, dialect, master seed,
// population, generations, failures and redraws), its fitness per generation
// as a chart with the shown creature and its lineage marked, and a table of
// the generations. A click on the chart picks that generation's best. A run
// of several stages shows its syllabus as a graph too, and the chart draws
// one stage's curve at a time (the one picked in the graph; each stage's
// fitness measures its own task), or the whole run's.
import { el, svg } from './dom.js';
import { CURVES, curveLayout, generationChoices, nearestChoice } from './curves.js';
import { fitness } from './format.js';
import { isStaged, spanText, stageAt, stageRun, stageSpan } from './syllabus.js';
import { createSyllabusView } from './syllabus_view.js';

/** Height of the chart for a width: wide enough to read, never too tall. */
export function chartHeight(width) {
  return Math.round(Math.min(Math.max(width * 0.62, 170), 260));
}

const PAD = { right: 10, top: 10, bottom: 34 };
// room on the left for the fitness label and the widest tick (11 px digits)
const padLeft = (L) => 24 + 6.5 * Math.max(...L.yTicks.map((t) => String(t.value).length));

/** The run's context as [name, text] rows. */
export function runRows(run) {
  const gens = run.generations;
  const last = gens[gens.length - 1];
  const sum = (k) => gens.reduce((n, g) => n + g[k], 0);
  const unit = run.algorithm === 'generational' ? 'generations' : 'report intervals';
  const replayed = run.members.filter((m) => m.replay_index !== null).length;
  const begun = isStaged(run) ? run.stages.filter((st) => stageSpan(st) !== null).length : 0;
  return [
    ['preset', `${run.name} (${run.dialect}, ${run.algorithm})`],
    ['master seed', run.seed],
    ['population', String(run.population)],
    ...(isStaged(run) ? [['stages', `${begun} of ${run.stages.length} begun`]] : []),
    [unit, `${gens.length} of ${run.planned_generations}`],
    ['evaluations', `${last ? last.evaluations : 0}, of which ${sum('failed')} failed`],
    ['rejected', `${sum('rejected')} non-viable children redrawn`],
    ['replays', `${replayed} of the ${run.members.length} creatures named` +
      (replayed < run.members.length ? ` (at most ${run.replay_cap})` : '')],
  ];
}

/**
 * What the chart draws with stage `picked` (an index into run.stages, or -1
 * for the whole run): the curves' data (the stage's generations numbered
 * from its first), `offset` (the run's number of its generation 0), the
 * generations' bests offered by a click (numbered so too), and the title.
 */
export function chartView(run, picked) {
  const stage = picked >= 0 ? run.stages[picked] : null;
  const part = stage ? stageRun(run, stage) : null;
  if (!part) {
    const title = isStaged(run) ? 'Fitness per generation: the whole run (its stages measure different tasks)'
      : 'Fitness per generation';
    return { data: run, offset: 0, choices: generationChoices(run), title, xLabel: 'generation' };
  }
  const span = stageSpan(stage), [from, to] = span;
  const choices = generationChoices(run).filter((c) => c.gen >= from && c.gen <= to).map((c) => ({ ...c, gen: c.gen - from }));
  return { data: part, offset: from, choices, title: `Fitness per generation of stage ${stage.name} (the run's ${spanText(span)})`,
    xLabel: `generation of ${stage.name}` };
}

/**
 * The run panel in `container` for `run`. `onGeneration(gen)` is called when
 * the user clicks the chart; `setCurrent(member, lineage)` marks the shown
 * creature and its lineage (members, newest first).
 */
export function createRunPanel(container, run, onGeneration) {
  container.replaceChildren();
  container.hidden = false;
  const choices = generationChoices(run);
  const staged = isStaged(run);
  const rows = runRows(run);
  const dropped = run.members.length - run.members.filter((m) => m.replay_index !== null).length;

  const chartBox = el('div', { class: 'chart-box' });
  const legend = el('div', { class: 'legend' },
    ...CURVES.slice().reverse().map((k) => el('span', { class: `key ${k}` }, k)),
    el('span', { class: 'key lineage' }, 'lineage'),
    el('span', { class: 'key shown' }, 'shown'));
  const table = el('table', { class: 'gens' },
    el('thead', {}, el('tr', {}, ...['gen', 'best', 'mean', 'rejected', 'failed'].map((h) => el('th', {}, h)))),
    el('tbody', {}, ...run.generations.map((g) => el('tr', { 'data-gen': String(g.gen) },
      el('td', {}, String(g.gen)), el('td', {}, fitness(g.best)), el('td', {}, fitness(g.mean)),
      el('td', {}, String(g.rejected)), el('td', {}, String(g.failed))))));
  container.append(
    el('h2', {}, 'Run'),
    el('dl', { class: 'run-facts' }, ...rows.flatMap(([k, v]) => [el('dt', {}, k), el('dd', {}, v)])));
  if (dropped > 0)
    container.append(el('p', { class: 'muted' }, `${dropped} of them not replayed: the page holds at most ` +
      `${run.replay_cap} replays, the best and its lineage first, then the generations' bests, then the other lineages.`));
  // a run of stages: its syllabus, and at first the curve of the best's stage
  const titleText = el('span', {});
  const wholeRun = staged ? el('button', { type: 'button', class: 'whole-run', title: "the whole run's curve, every stage",
    onclick: () => pick(-1) }, 'whole run') : null;
  const chartTitle = el('h3', {}, titleText, wholeRun);
  let first = -1, syllabus = null;
  if (staged) {
    const best = run.members.find((m) => m.id === run.best_id);
    first = stageAt(run.stages, best.gen);
    const graphBox = el('div', {});
    container.append(el('h3', {}, 'Syllabus'), graphBox);
    syllabus = createSyllabusView(graphBox, run.stages, (i) => pick(i));
  }
  container.append(
    chartTitle, chartBox, legend,
    el('details', { class: 'gens-box', open: run.generations.length <= 12 },
      el('summary', {}, `Generations (${run.generations.length}): best, mean, rejected, failed`),
      el('div', { class: 'gens-scroll' }, table)));

  // the chart is drawn at its box's width, again when that changes
  let shown = { member: null, lineage: [] };
  let width = 0;
  let view;
  // picks stage i's curve (-1: the whole run's)
  function pick(i) {
    view = chartView(run, i);
    syllabus?.setPicked(i);
    titleText.textContent = view.title;
    if (wholeRun) wholeRun.hidden = i < 0;
    width = 0;
    draw();
  }
  function draw() {
    const w = chartBox.clientWidth;
    if (w <= 0 || w === width) return;
    width = w;
    const h = chartHeight(w);
    const data = view.data, offset = view.offset;
    const L = curveLayout(data, w, h, { ...PAD, left: padLeft(curveLayout(data, w, h, { ...PAD, left: 0 })) });
    const chart = svg('svg', { class: 'curves', width: w, height: h, viewBox: `0 0 ${w} ${h}`, role: 'img',
      'aria-label': `best, mean and median fitness per ${view.xLabel}` });
    const right = L.plot.left + L.plot.width, bottom = L.plot.top + L.plot.height;
    for (const t of L.yTicks) {
      chart.append(svg('line', { class: 'grid', x1: L.plot.left, x2: right, y1: t.px, y2: t.px }));
      chart.append(svg('text', { class: 'tick', x: L.plot.left - 4, y: t.px + 4, 'text-anchor': 'end' }, String(t.value)));
    }
    for (const t of L.xTicks)
      chart.append(svg('text', { class: 'tick', x: t.px, y: bottom + 14, 'text-anchor': 'middle' }, String(t.value)));
    chart.append(
      svg('line', { class: 'axis', x1: L.plot.left, x2: right, y1: bottom, y2: bottom }),
      svg('line', { class: 'axis', x1: L.plot.left, x2: L.plot.left, y1: L.plot.top, y2: bottom }),
      svg('text', { class: 'axis-label', x: L.plot.left + L.plot.width / 2, y: h - 4, 'text-anchor': 'middle' }, view.xLabel),
      svg('text', { class: 'axis-label', x: 0, y: 0, 'text-anchor': 'middle',
        transform: `translate(11 ${L.plot.top + L.plot.height / 2}) rotate(-90)` }, 'fitness'));
    // the whole run's curve of a run of stages: where each stage begins
    // (and its name, where there is room for it)
    if (staged && data === run) {
      const begun = run.stages.filter((st) => stageSpan(st) !== null);
      begun.forEach((st, k) => {
        const x = k ? L.x(st.first_gen - 0.5) : L.plot.left;
        const next = k + 1 < begun.length ? L.x(begun[k + 1].first_gen - 0.5) : right;
        if (k) chart.append(svg('line', { class: 'stage-edge', x1: x, x2: x, y1: L.plot.top, y2: bottom }));
        if (next - x > 6 * st.name.length + 6)
          chart.append(svg('text', { class: 'stage-label', x: x + 3, y: L.plot.top + 9 }, st.name));
      });
    }
    // the lineage: each ancestor's fitness at the generation it was born in,
    // its line under the curves and its dots over them (in a stage's curve,
    // the ancestors born in it)
    const [g0, g1] = [data.generations[0]?.gen ?? 0, data.generations[data.generations.length - 1]?.gen ?? 0];
    const inView = (m) => m.gen - offset >= g0 && m.gen - offset <= g1;
    const line = shown.lineage.filter(inView).map((m) => [L.x(m.gen - offset), L.y(m.fitness)]);
    if (line.length > 1)
      chart.append(svg('path', { class: 'lineage', d: line.map(([x, y], i) => `${i ? 'L' : 'M'}${x.toFixed(1)},${y.toFixed(1)}`).join('') }));
    for (const k of CURVES) chart.append(svg('path', { class: `curve ${k}`, d: L.paths[k] }));
    for (const [x, y] of line) chart.append(svg('circle', { class: 'lineage-dot', cx: x, cy: y, r: 2.5 }));
    // the shown creature: a dashed line at its generation, a ring at its fitness
    const m = shown.member;
    if (m && inView(m)) {
      const x = L.x(m.gen - offset);
      chart.append(
        svg('line', { class: 'marker', x1: x, x2: x, y1: L.plot.top, y2: bottom }),
        svg('circle', { class: 'marker-dot', cx: x, cy: L.y(m.fitness), r: 4.5 }));
    }
    chart.addEventListener('click', (ev) => {
      const box = chart.getBoundingClientRect();
      const c = nearestChoice(view.choices, L.genAt(((ev.clientX - box.left) / box.width) * w));
      if (c) onGeneration(c.gen + offset);
    });
    chartBox.replaceChildren(chart);
  }
  const observer = typeof ResizeObserver === 'function' ? new ResizeObserver(() => draw()) : null;
  observer?.observe(chartBox);
  pick(first);

  return {
    choices,
    /** Marks `member` (a run member, or null) and `lineage` (members, newest first). */
    setCurrent(member, lineage) {
      shown = { member, lineage };
      syllabus?.setShown(member && staged ? stageAt(run.stages, member.gen) : -1);
      width = 0;
      draw();
      for (const tr of table.tBodies[0].rows) tr.classList.toggle('current', member !== null && Number(tr.dataset.gen) === member.gen);
    },
  };
}
