// A run of several stages (lessin2015's syllabus, src/io/syllabus.h): the
// stages as a layered graph, one column per depth, an edge from each stage
// to every stage that uses it; and each stage's own part of the run, its
// generations numbered from its first, since each stage's fitness measures
// its own task and one curve over the whole run mixes their scales.

/** The graph's sizes in px: boxes, gaps between columns and rows, the margin. */
export const GRAPH = { boxHeight: 34, minBoxWidth: 64, charWidth: 6.6, gapX: 20, gapY: 10, pad: 6 };

/** The least a graph wider than its panel shrinks to (then it scrolls): its text stays readable. */
export const LEAST_SCALE = 0.75;

/** Whether the run is one of several stages (a plain run has none listed). */
export function isStaged(run) {
  return Array.isArray(run?.stages) && run.stages.length > 0;
}

/**
 * Each stage's depth: 0 when it uses none, otherwise one more than the
 * deepest it uses. A used name that is not an earlier stage is ignored (the
 * data's check refuses it).
 */
export function stageDepths(stages) {
  const depthOf = new Map();
  return stages.map((s) => {
    let d = 0;
    for (const u of s.uses) if (depthOf.has(u)) d = Math.max(d, depthOf.get(u) + 1);
    depthOf.set(s.name, d);
    return d;
  });
}

/** The pandemonium groups, in the order the stages first name them (as the genome numbers them). */
export function stageGroups(stages) {
  const out = [];
  for (const s of stages) if (s.group && !out.includes(s.group)) out.push(s.group);
  return out;
}

/**
 * The graph's layout: `nodes` (per stage, in stage order: index, name,
 * column, row, x, y, width, height, group as an index into `groups` or -1),
 * `edges` (from the used stage's index to the user's, with SVG path data
 * from the right edge of one box to the left edge of the other), `groups`
 * and the whole size. A column's stages are ordered by the mean height of
 * the stages they use (stage order on a tie), which keeps edges short, and
 * each column is centred on the tallest.
 */
export function syllabusLayout(stages, g = GRAPH) {
  const depths = stageDepths(stages);
  const groups = stageGroups(stages);
  const indexOf = new Map(stages.map((s, i) => [s.name, i]));
  const longest = Math.max(0, ...stages.map((s) => s.name.length));
  const w = Math.max(g.minBoxWidth, Math.ceil(longest * g.charWidth) + 12), h = g.boxHeight;
  const nColumns = stages.length ? Math.max(...depths) + 1 : 0;
  const columns = Array.from({ length: nColumns }, () => []);
  depths.forEach((d, i) => columns[d].push(i));
  const tallest = Math.max(0, ...columns.map((c) => c.length));
  const nodes = stages.map((s, i) => ({ index: i, name: s.name, column: depths[i], row: 0, x: 0, y: 0, width: w, height: h,
    group: s.group ? groups.indexOf(s.group) : -1 }));
  // column by column: the stages a column's stages use are placed already
  const centreY = (i) => nodes[i].y + h / 2;
  for (const [c, column] of columns.entries()) {
    const key = (i) => {
      const used = stages[i].uses.filter((u) => indexOf.has(u)).map((u) => centreY(indexOf.get(u)));
      return used.length ? used.reduce((a, b) => a + b, 0) / used.length : 0;
    };
    if (c > 0) column.sort((a, b) => key(a) - key(b) || a - b);
    const top = g.pad + ((tallest - column.length) * (h + g.gapY)) / 2;
    column.forEach((i, row) => Object.assign(nodes[i], { row, x: g.pad + c * (w + g.gapX), y: top + row * (h + g.gapY) }));
  }
  const f = (v) => (Math.round(v * 10) / 10).toString();
  const edges = [];
  stages.forEach((s, to) => {
    for (const u of s.uses) {
      if (!indexOf.has(u)) continue;
      const a = nodes[indexOf.get(u)], b = nodes[to];
      const x0 = a.x + a.width, y0 = a.y + h / 2, x1 = b.x, y1 = b.y + h / 2, mid = (x1 - x0) / 2;
      edges.push({ from: a.index, to, d: `M${f(x0)},${f(y0)}C${f(x0 + mid)},${f(y0)} ${f(x1 - mid)},${f(y1)} ${f(x1)},${f(y1)}` });
    }
  });
  return {
    nodes, edges, groups,
    width: nColumns ? 2 * g.pad + nColumns * w + (nColumns - 1) * g.gapX : 0,
    height: tallest ? 2 * g.pad + tallest * h + (tallest - 1) * g.gapY : 0,
  };
}

/** The run's generations of a stage, [first, last] (null when it has not begun). */
export function stageSpan(stage) {
  return stage.generations > 0 ? [stage.first_gen, stage.first_gen + stage.generations - 1] : null;
}

/** Generations [first, last] as text: "4-9", or "4" for one. */
export function spanText([first, last]) {
  return first === last ? String(first) : `${first}-${last}`;
}

/** The index of the stage whose generations hold the run's generation `gen` (-1: none). */
export function stageAt(stages, gen) {
  return stages.findIndex((s) => {
    const span = stageSpan(s);
    return span !== null && gen >= span[0] && gen <= span[1];
  });
}

/**
 * A stage's part of the run, shaped as a run for the curves (curves.js):
 * its generations and the members born in them, each generation numbered
 * from the stage's first (`offset`, the run's number of that one, turns it
 * back). Null for a stage not begun.
 */
export function stageRun(run, stage) {
  const span = stageSpan(stage);
  if (!span) return null;
  const [from, to] = span;
  const inside = (x) => x.gen >= from && x.gen <= to;
  const local = (x) => ({ ...x, gen: x.gen - from });
  return {
    offset: from,
    generations: run.generations.filter(inside).map(local),
    members: run.members.filter(inside).map(local),
  };
}
