// The syllabus graph of a run of several stages, as SVG: a box per stage
// (its name and best fitness, its pandemonium group's colour), an arrow from
// each stage to every stage that uses it, the picked stage outlined and the
// shown creature's stage ringed. A click (or Enter) on a stage picks it.
import { el, svg } from './dom.js';
import { fitness } from './format.js';
import { LEAST_SCALE, spanText, stageSpan, syllabusLayout } from './syllabus.js';

// the groups' colours, apart from the curves' blue, orange and green
const GROUP_COLORS = ['#8a67c1', '#35aeb8', '#c94f4f', '#b9b13b', '#d46fb0', '#9c6b4e', '#2f4f9e', '#6d7f8c'];

/** A group's colour (by its index among the run's groups; -1: none). */
export function groupColor(group) {
  return group < 0 ? null : GROUP_COLORS[group % GROUP_COLORS.length];
}

/** What a stage's box says when hovered. */
export function stageTitle(stage) {
  const span = stageSpan(stage);
  return `${stage.name}: ${stage.uses.length ? `uses ${stage.uses.join(', ')}` : 'uses no other stage'}` +
    (stage.group ? `, pandemonium group ${stage.group}` : '') +
    (span ? `; the run's generations ${spanText(span)}, best fitness ${fitness(stage.best)}` : '; not begun') +
    (span ? ' (click: its own curve)' : '');
}

/**
 * The graph of `stages` in `container`; `onPick(index)` is called when a
 * begun stage is clicked. Returns {setPicked(index or -1), setShown(index or -1)}.
 */
export function createSyllabusView(container, stages, onPick) {
  const L = syllabusLayout(stages);
  // as wide as it is, or shrunk to the panel, down to LEAST_SCALE (then it scrolls)
  const graph = svg('svg', { class: 'syllabus', width: L.width, height: L.height, viewBox: `0 0 ${L.width} ${L.height}`,
    style: `min-width:${Math.round(L.width * LEAST_SCALE)}px`,
    role: 'group', 'aria-label': 'the syllabus: each stage, with an arrow to the stages that use it' });
  graph.append(svg('defs', {}, svg('marker', { id: 'syllabus-arrow', viewBox: '0 0 8 8', refX: 8, refY: 4,
    markerWidth: 6, markerHeight: 6, orient: 'auto' }, svg('path', { class: 'arrow-head', d: 'M0,0L8,4L0,8z' }))));
  // the edges under the boxes
  for (const e of L.edges)
    graph.append(svg('path', { class: 'edge', d: e.d, 'marker-end': 'url(#syllabus-arrow)', 'data-from': e.from, 'data-to': e.to }));
  const boxes = L.nodes.map((n) => {
    const stage = stages[n.index];
    const begun = stageSpan(stage) !== null;
    const color = groupColor(n.group);
    const box = svg('g', { class: begun ? 'stage' : 'stage not-begun', 'data-stage': n.index, tabindex: begun ? 0 : -1,
      role: 'button', 'aria-label': stageTitle(stage) },
      svg('title', {}, stageTitle(stage)),
      svg('rect', { x: n.x, y: n.y, width: n.width, height: n.height, rx: 4,
        ...(color ? { style: `stroke:${color};fill:${color};fill-opacity:0.13` } : {}) }),
      svg('text', { class: 'stage-name', x: n.x + n.width / 2, y: n.y + 14, 'text-anchor': 'middle' }, stage.name),
      svg('text', { class: 'stage-best', x: n.x + n.width / 2, y: n.y + 27, 'text-anchor': 'middle' },
        begun ? `best ${fitness(stage.best)}` : 'not begun'),
      svg('circle', { class: 'stage-shown', cx: n.x + n.width - 1, cy: n.y + 1, r: 4 }));
    if (begun) {
      box.addEventListener('click', () => onPick(n.index));
      box.addEventListener('keydown', (ev) => {
        if (ev.key !== 'Enter' && ev.key !== ' ') return;
        ev.preventDefault();
        onPick(n.index);
      });
    }
    return box;
  });
  graph.append(...boxes);
  container.replaceChildren(el('div', { class: 'syllabus-box' }, graph));
  if (L.groups.length)
    container.append(el('div', { class: 'legend' }, el('span', { class: 'muted' }, 'pandemonium groups:'),
      ...L.groups.map((name, i) => el('span', { class: 'group-key' },
        el('span', { class: 'swatch', style: `background:${groupColor(i)}` }), name))));
  container.append(el('p', { class: 'muted' }, 'An arrow goes from a stage to each stage that uses its skill. ' +
    'A click on a stage draws its own fitness curve, its generations counted from its first.'));

  return {
    /** Outlines stage `index` as the one whose curve is drawn (-1: the whole run's). */
    setPicked(index) {
      boxes.forEach((b, i) => b.classList.toggle('picked', i === index));
    },
    /** Rings the stage of the creature shown (-1: none). */
    setShown(index) {
      boxes.forEach((b, i) => b.classList.toggle('shown', i === index));
    },
  };
}
