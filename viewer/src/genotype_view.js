// The genotype graph (genotype.js) as SVG: a box per gene in its colour in
// the scene, with its index, shape and how many neurons, sensors and
// effectors it carries, its recursive limit beside it; an arrow per edge,
// dashed when terminal-only, marked "R" and its axes when reflected, a loop
// for recursion. Hovering a gene reports it; a highlight lights one gene up.
import { el, svg } from './dom.js';
import { cssColor, geneColor } from './palette.js';
import { edgeMark, edgeText, geneText, geneTitle, geneUnits, genotypeLayout, genotypeModel, limitText } from './genotype.js';

/** How much larger than its layout the graph is drawn, room allowing. */
const ZOOM = 1.15;

/**
 * The graph of `genome` (parsed) for `replay` in `container`; `onHover(gene)`
 * is called with the gene under the pointer (-1 when it leaves). Returns
 * {nodes, edges (counts), setHighlight(h)}, h a highlight (highlight.js) or
 * null.
 */
export function createGenotypeView(container, genome, replay, onHover) {
  const model = genotypeModel(genome, replay);
  const L = genotypeLayout(model);
  // drawn a little larger than its layout, shrunk to the panel when wider
  const graph = svg('svg', { class: 'genotype', width: Math.round(L.width * ZOOM), height: Math.round(L.height * ZOOM),
    viewBox: `0 0 ${L.width} ${L.height}`,
    role: 'group', 'aria-label': 'the genotype graph: a box per gene, an arrow per edge' });
  graph.append(svg('defs', {}, svg('marker', { id: 'gene-arrow', viewBox: '0 0 8 8', refX: 7.5, refY: 4,
    markerWidth: 7, markerHeight: 7, orient: 'auto-start-reverse' }, svg('path', { class: 'arrow-head', d: 'M0,0L8,4L0,8z' }))));
  for (const e of L.edges) {
    const cls = `gene-edge${e.terminal ? ' terminal' : ''}${e.reflect.length ? ' reflected' : ''}${e.self ? ' self' : ''}`;
    const mark = edgeMark(e);
    graph.append(svg('g', { class: cls, 'data-from': e.from, 'data-to': e.to },
      svg('title', {}, edgeText(e)),
      svg('path', { class: 'edge-hit', d: e.d }),
      svg('path', { class: 'edge-line', d: e.d, 'marker-end': 'url(#gene-arrow)' }),
      mark ? svg('text', { class: 'edge-mark', x: e.markAt[0].toFixed(1), y: (e.markAt[1] + 3.5).toFixed(1), 'text-anchor': 'middle' }, mark) : null));
  }
  const boxes = L.nodes.map((n) => {
    const color = cssColor(geneColor(n.index));
    const box = svg('g', { class: 'gene', 'data-gene': n.index, tabindex: 0, role: 'img', 'aria-label': geneText(n) },
      svg('title', {}, geneText(n)),
      svg('rect', { x: n.x, y: n.y, width: n.width, height: n.height, rx: n.shape === 'box' ? 3 : 12, style: `stroke:${color};fill:${color}` }),
      svg('text', { class: 'gene-title', x: n.x + n.width / 2, y: n.y + 13, 'text-anchor': 'middle' }, geneTitle(n)),
      svg('text', { class: 'gene-units', x: n.x + n.width / 2, y: n.y + 26, 'text-anchor': 'middle' }, geneUnits(n)),
      svg('text', { class: 'gene-limit', x: n.limitAt[0], y: n.limitAt[1] }, limitText(n)));
    const enter = () => onHover(n.index), leave = () => onHover(-1);
    box.addEventListener('pointerenter', enter);
    box.addEventListener('pointerleave', leave);
    box.addEventListener('focus', enter);
    box.addEventListener('blur', leave);
    return box;
  });
  graph.append(...boxes);
  const legend = el('p', { class: 'muted graph-note' },
    'n neurons, s sensors, e effectors; ×N the recursive limit; dashed: terminal only; R: reflected (its axes)' +
    (model.globals ? `. Global neurons: ${model.globals}` : '') + '.');
  container.replaceChildren(el('div', { class: 'graph-box' }, graph), legend);
  const edges = [...graph.querySelectorAll('.gene-edge')];
  return {
    nodes: L.nodes.length,
    edges: L.edges.length,
    setHighlight(h) {
      const on = h !== null && h.gene >= 0;
      graph.classList.toggle('focused', on);
      boxes.forEach((b, i) => b.classList.toggle('lit', on && i === h.gene));
      edges.forEach((e) => e.classList.toggle('lit', on && (Number(e.dataset.from) === h.gene || Number(e.dataset.to) === h.gene)));
    },
  };
}
