// What lights up together when a part, a gene or a unit of the brain is
// hovered: the gene, every part developed from it (mirrored copies and
// recursion's too), and those parts' sensors, neurons and effectors (and so
// the wires touching them). A global neuron belongs to no gene: it lights up
// alone. Made once per replay (an index by gene), so a hover only looks up.
import { effectorPart } from './network.js';

/**
 * An index of `replay` by gene: `of(gene)`, `ofPart(part)` and `ofUnit(kind,
 * index)` give a highlight {gene, parts, sensors, neurons, effectors} (gene
 * -1 for a global neuron's; the lists are sorted part, sensor, neuron and
 * effector indices, shared: do not change them); `none` is the empty one.
 */
export function highlightIndex(replay) {
  const sensors = replay.sensors ?? [], effectors = replay.effectors ?? [];
  const byGene = new Map();
  const entry = (gene) => {
    if (!byGene.has(gene)) byGene.set(gene, { gene, parts: [], sensors: [], neurons: [], effectors: [] });
    return byGene.get(gene);
  };
  const geneOfPart = (p) => replay.parts[p]?.gene ?? -1;
  replay.parts.forEach((p, i) => entry(p.gene).parts.push(i));
  sensors.forEach((s, k) => s.part >= 0 && entry(geneOfPart(s.part)).sensors.push(k));
  replay.neurons.forEach((n, k) => n.part >= 0 && entry(geneOfPart(n.part)).neurons.push(k));
  effectors.forEach((e, k) => {
    const p = effectorPart(replay, e);
    if (p >= 0) entry(geneOfPart(p)).effectors.push(k);
  });
  const none = { gene: -1, parts: [], sensors: [], neurons: [], effectors: [] };
  const globals = new Map();
  const of = (gene) => byGene.get(gene) ?? { ...none, gene };
  return {
    none,
    of,
    ofPart(part) {
      return part >= 0 && part < replay.parts.length ? of(replay.parts[part].gene) : none;
    },
    ofUnit(kind, index) {
      const unit = kind === 'sensor' ? sensors[index] : kind === 'neuron' ? replay.neurons[index] : effectors[index];
      if (!unit) return none;
      const part = kind === 'effector' ? effectorPart(replay, unit) : unit.part;
      if (part >= 0) return this.ofPart(part);
      // a global neuron: itself alone
      if (!globals.has(index)) globals.set(index, { ...none, neurons: [index] });
      return globals.get(index);
    },
  };
}

/** A highlight in words, for the panel's line: "gene 1: parts 1, 2, 5 · 6 neurons, 2 sensors, 2 effectors". */
export function highlightText(h) {
  const plural = (k, word) => `${k} ${word}${k === 1 ? '' : 's'}`;
  const units = `${plural(h.neurons.length, 'neuron')}, ${plural(h.sensors.length, 'sensor')}, ${plural(h.effectors.length, 'effector')}`;
  if (h.gene < 0) return h.neurons.length ? `global neuron ${h.neurons[0]}: belongs to no part` : '';
  const parts = h.parts.length === 0 ? 'no parts' : `part${h.parts.length > 1 ? 's' : ''} ${listText(h.parts)}`;
  return `gene ${h.gene}: ${parts} · ${units}`;
}

// numbers as a short list, runs shortened: 1-4, 7, 9
function listText(xs, most = 12) {
  const runs = [];
  for (const x of xs) {
    const last = runs[runs.length - 1];
    if (last && x === last[1] + 1) last[1] = x;
    else runs.push([x, x]);
  }
  const text = runs.map(([a, b]) => (a === b ? `${a}` : b === a + 1 ? `${a}, ${b}` : `${a}-${b}`));
  return text.length > most ? `${text.slice(0, most).join(', ')}, ...` : text.join(', ');
}
