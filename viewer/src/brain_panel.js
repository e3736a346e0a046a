// The genome and brain panel: two views under tabs, the genotype graph
// (genotype_view.js) and the network (network_view.js), and a line saying
// what is highlighted. Hovering a gene, a unit of the network or (through
// the viewer) a part in the scene highlights that gene, every part grown
// from it and their units in both views and reports it, so the scene lights
// those parts up too (highlight.js).
import { el } from './dom.js';
import { genomeOf } from './genotype.js';
import { createGenotypeView } from './genotype_view.js';
import { brainOf, networkModel } from './network.js';
import { createNetworkView } from './network_view.js';
import { highlightIndex, highlightText } from './highlight.js';

/** The tabs, in order: key and title. */
export const TABS = [['genome', 'Genome'], ['network', 'Network']];

const HINT = 'Hover a part in the scene, a gene or a unit: they light up together.';

/** Why a replay has no network to draw, in one line; '' when it has one. */
export function noNetworkText(replay, model) {
  if (!brainOf(replay).graph)
    return `This creature (${replay.creature ?? 'another kind'}) has no graph brain: its controller's signals are in the panels below.`;
  if (model.groups.length === 0) return 'This creature has no sensors, neurons or effectors.';
  return '';
}

/**
 * The panel for page entry `entry` ({label, replay, genome?}) in
 * `container`, on tab `tab` ('genome' or 'network'; null: the genome's, or
 * the network's when only it is drawn); `on.highlight(h)` is
 * told each change of highlight (h null for none) and `on.tab(key)` each
 * change of tab. Returns {focusPart(part) (-1: none), setTime(t), state()}.
 */
export function createBrainPanel(container, entry, tab, on) {
  const replay = entry.replay;
  const index = highlightIndex(replay);
  const line = el('p', { class: 'muted focus-line' }, HINT);
  let current = null;
  function focus(h) {
    if (h === current) return;
    current = h;
    line.textContent = h ? highlightText(h) || HINT : HINT;
    line.classList.toggle('active', h !== null);
    genome?.setHighlight(h);
    network?.setHighlight(h);
    on.highlight(h);
  }
  // the two views, each in its pane (a one-line reason when it has none)
  const panes = Object.fromEntries(TABS.map(([key]) => [key, el('div', { class: 'brain-pane', 'data-pane': key, role: 'tabpanel' })]));
  const { genome: g, reason } = genomeOf(entry);
  const genome = g ? createGenotypeView(panes.genome, g, replay, (gene) => focus(gene < 0 ? null : index.of(gene))) : null;
  if (!g) panes.genome.replaceChildren(el('p', { class: 'muted', 'data-reason': 'genome' }, reason));
  const model = networkModel(replay);
  const why = noNetworkText(replay, model);
  const network = why ? null : createNetworkView(panes.network, model, replay, (kind, k) => focus(kind ? index.ofUnit(kind, k) : null));
  if (why) panes.network.replaceChildren(el('p', { class: 'muted', 'data-reason': 'network' }, why));

  const buttons = TABS.map(([key, title]) => el('button', {
    type: 'button', class: 'tab', role: 'tab', 'data-tab': key, onclick: () => show(key, true),
  }, title));
  function show(key, told) {
    tab = key;
    buttons.forEach((b) => b.setAttribute('aria-selected', String(b.dataset.tab === key)));
    for (const [k, pane] of Object.entries(panes)) pane.hidden = k !== key;
    network?.setActive(key === 'network');
    if (told) on.tab(key);
  }
  // nothing to hover when neither view is drawn (another kind's creature)
  line.hidden = !genome && !network;
  container.replaceChildren(
    el('div', { class: 'panel-head' }, el('h2', {}, 'Genome and brain'),
      el('div', { class: 'tabs', role: 'tablist', 'aria-label': 'genome or brain' }, ...buttons)),
    line, panes.genome, panes.network);
  show(TABS.some(([k]) => k === tab) ? tab : !genome && network ? 'network' : 'genome', false);

  return {
    /** Highlights the gene of part `part` in the scene (-1: none). */
    focusPart(part) {
      if (line.hidden) return;
      focus(part < 0 ? null : index.ofPart(part));
    },
    setTime(t) { network?.setTime(t); },
    /** What the panel shows: tab, genes and edges drawn (null: none), wires drawn (null: none), the highlight. */
    state() {
      return {
        tab, genes: genome ? genome.nodes : null, edges: genome ? genome.edges : null, wires: network ? network.wires : null,
        highlight: current && { gene: current.gene, parts: current.parts, neurons: current.neurons },
      };
    },
  };
}
