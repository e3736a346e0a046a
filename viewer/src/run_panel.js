// A run's fitness curves (best, mean, median per generation) as an SVG chart,
// and the choice of any generation's best creature: from a list, or by
// clicking the chart.
import { el, svg } from './dom.js';
import { CURVES, curveLayout, generationChoices, nearestChoice } from './curves.js';
import { fitness } from './format.js';

const W = 272, H = 170;

/**
 * The run panel in `container`. `onChoose(replayIndex)` is called when the
 * user picks a generation; `setCurrent(replayIndex)` marks the shown one.
 */
export function createRunPanel(container, run, onChoose) {
  container.replaceChildren();
  container.hidden = false;
  const L = curveLayout(run, W, H);
  const choices = generationChoices(run);

  // the chart: grid and ticks, one path per curve, a marker for the shown generation
  const chart = svg('svg', { class: 'curves', width: W, height: H, viewBox: `0 0 ${W} ${H}` });
  for (const t of L.yTicks) {
    chart.append(svg('line', { class: 'grid', x1: L.plot.left, x2: L.plot.left + L.plot.width, y1: t.px, y2: t.px }));
    chart.append(svg('text', { class: 'tick', x: L.plot.left - 4, y: t.px + 3, 'text-anchor': 'end' }, String(t.value)));
  }
  for (const t of L.xTicks)
    chart.append(svg('text', { class: 'tick', x: t.px, y: H - 6, 'text-anchor': 'middle' }, String(t.value)));
  const marker = svg('line', { class: 'marker', y1: L.plot.top, y2: L.plot.top + L.plot.height, x1: -10, x2: -10 });
  chart.append(marker);
  for (const k of CURVES) chart.append(svg('path', { class: `curve ${k}`, d: L.paths[k] }));
  chart.addEventListener('click', (ev) => {
    const box = chart.getBoundingClientRect();
    const c = nearestChoice(choices, L.genAt(((ev.clientX - box.left) / box.width) * W));
    if (c) onChoose(c.replayIndex);
  });
  const legend = el('div', { class: 'legend' },
    ...CURVES.slice().reverse().map((k) => el('span', { class: `key ${k}` }, k)));

  // the list of generations
  const select = el('select', { id: 'generation', 'aria-label': 'generation' },
    ...choices.map((c) => el('option', { value: String(c.replayIndex) },
      `generation ${c.gen}` + (c.best === null ? '' : ` (best ${fitness(c.best)})`))));
  select.addEventListener('change', () => onChoose(Number(select.value)));

  container.append(el('h2', {}, 'Run'), chart, legend,
    el('label', { class: 'row' }, 'Best of ', select));

  return {
    choices,
    setCurrent(replayIndex) {
      const c = choices.find((x) => x.replayIndex === replayIndex);
      if (c) {
        select.value = String(replayIndex);
        marker.setAttribute('x1', L.x(c.gen));
        marker.setAttribute('x2', L.x(c.gen));
      }
      marker.style.display = c ? '' : 'none';
    },
  };
}
