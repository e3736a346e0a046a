// The genotype graph of a graph genome (docs/genome-format.md), as Sims
// draws it: one node per gene (the genome's node: shape, recursive limit, its
// neurons, sensors and effectors), an arrow per edge (a self-loop for a
// recursive one), reflected and terminal-only edges marked; and its layout,
// row by row from the root down. genotype_view.js draws it.

/** The layout's sizes in px: node boxes, gaps, margin, loops, text. */
export const GENE_GRAPH = {
  minNodeWidth: 60, nodeHeight: 32, gapX: 30, gapY: 38, pad: 12, charWidth: 6.2,
  parallel: 12, loop: 17, loopStep: 8, backBulge: 22, backStep: 9,
};

/**
 * The graph genome of a page entry ({replay, genome?}), or why there is none:
 * { genome, reason } with exactly one of them null. A creature of another kind
 * (`replay.creature`, e.g. "river") has a vector of numbers for a genome.
 */
export function genomeOf(entry) {
  const kind = entry.replay?.creature;
  if (typeof kind === 'string')
    return { genome: null, reason: `This creature (${kind}) is not a graph genome: its genome is a vector of numbers, with no genotype graph.` };
  if (typeof entry.genome !== 'string')
    return { genome: null, reason: 'This page does not hold the creature\'s genome file: no genotype graph.' };
  let g;
  try {
    g = JSON.parse(entry.genome);
  } catch {
    return { genome: null, reason: 'The genome file on this page is not JSON.' };
  }
  if (!g || !Array.isArray(g.nodes) || g.nodes.length === 0 || !g.nodes.every((n) => n && typeof n === 'object'))
    return { genome: null, reason: 'The genome file on this page has no nodes: not a graph genome.' };
  return { genome: g, reason: null };
}

const count = (list) => (Array.isArray(list) ? list.length : 0);

/**
 * The genotype graph of `genome` (parsed): `nodes` per gene (index, shape,
 * limit: its recursive limit, neurons, sensors and effectors counts, parts:
 * how many parts of `replay` grew from it, or null without a replay),
 * `edges` (from, to, index in its node's list, self, reflect: the axes,
 * terminal, face, scale; an edge to a node the genome lacks is left out) and
 * `globals` (global neurons).
 */
export function genotypeModel(genome, replay = null) {
  const parts = new Map();
  for (const p of replay?.parts ?? []) parts.set(p.gene, (parts.get(p.gene) ?? 0) + 1);
  const n = genome.nodes.length;
  const nodes = genome.nodes.map((g, index) => ({
    index,
    shape: typeof g.shape === 'string' ? g.shape : 'box',
    limit: Number.isInteger(g.recursive_limit) ? g.recursive_limit : 1,
    neurons: count(g.neurons), sensors: count(g.sensors), effectors: count(g.effectors),
    parts: replay ? parts.get(index) ?? 0 : null,
  }));
  const edges = [];
  genome.nodes.forEach((g, from) => {
    (Array.isArray(g.edges) ? g.edges : []).forEach((e, index) => {
      if (!Number.isInteger(e?.to) || e.to < 0 || e.to >= n) return;
      edges.push({
        from, to: e.to, index, self: e.to === from,
        reflect: Array.isArray(e.reflect) ? e.reflect.filter((a) => typeof a === 'string') : [],
        terminal: e.terminal_only === true,
        face: typeof e.face === 'string' ? e.face : '+x',
        scale: typeof e.scale === 'number' ? e.scale : 1,
      });
    });
  });
  return { nodes, edges, globals: count(genome.global_neurons) };
}

/** The first line of a gene's box: its index and shape. */
export function geneTitle(node) {
  return `${node.index} · ${node.shape}`;
}

/** The second line: how many neurons, sensors and effectors it carries ("3n 1s 2e"). */
export function geneUnits(node) {
  return `${node.neurons}n ${node.sensors}s ${node.effectors}e`;
}

/** What is written beside a gene: its recursive limit, "×5". */
export function limitText(node) {
  return `×${node.limit}`;
}

/** What an edge's mark says: "R" and the axes it reflects across ("R y"), or '' for none. */
export function edgeMark(edge) {
  return edge.reflect.length ? `R ${edge.reflect.join('')}` : '';
}

/** An edge in words, for its tooltip. */
export function edgeText(edge) {
  return `edge ${edge.index} of gene ${edge.from} to gene ${edge.to}${edge.self ? ' (itself: recursion)' : ''}: ` +
    `face ${edge.face}, scale ${Number(edge.scale.toPrecision(3))}` +
    (edge.reflect.length ? `, reflected across ${edge.reflect.join(', ')} (${2 ** edge.reflect.length} copies)` : '') +
    (edge.terminal ? ', terminal only (followed where the recursion stops)' : '');
}

/** A gene in words, for its tooltip. */
export function geneText(node) {
  const plural = (k, word) => `${k} ${word}${k === 1 ? '' : 's'}`;
  return `gene ${node.index}: ${node.shape}, recursive limit ${node.limit}; ` +
    `${plural(node.neurons, 'neuron')}, ${plural(node.sensors, 'sensor')}, ${plural(node.effectors, 'effector')}` +
    (node.parts === null ? '' : `; ${plural(node.parts, 'part')} grew from it`);
}

/**
 * Each gene's row: its depth from the root (node 0) along the edges (a
 * self-loop aside); genes the root does not reach go one row below the deepest.
 */
export function geneDepths(model) {
  const depth = new Array(model.nodes.length).fill(-1);
  depth[0] = 0;
  const queue = [0];
  while (queue.length) {
    const a = queue.shift();
    for (const e of model.edges)
      if (e.from === a && depth[e.to] < 0) {
        depth[e.to] = depth[a] + 1;
        queue.push(e.to);
      }
  }
  const deepest = Math.max(...depth);
  return depth.map((d) => (d < 0 ? deepest + 1 : d));
}

const f = (v) => (Math.round(v * 10) / 10).toString();

// a cubic's path data and its middle point (t = 1/2)
function cubic(p0, p1, p2, p3) {
  return {
    d: `M${f(p0[0])},${f(p0[1])}C${f(p1[0])},${f(p1[1])} ${f(p2[0])},${f(p2[1])} ${f(p3[0])},${f(p3[1])}`,
    mid: [(p0[0] + 3 * p1[0] + 3 * p2[0] + p3[0]) / 8, (p0[1] + 3 * p1[1] + 3 * p2[1] + p3[1]) / 8],
  };
}

/**
 * The graph's layout: `nodes` (the model's, each with row, x, y, width,
 * height and `limitAt`, where its recursive limit is written (limitText):
 * beside its top right corner), `edges` (the model's, each with SVG path data `d` and
 * `markAt`, the middle of its path, where a reflection's mark goes) and the
 * whole size. Rows go down from the root; in a row, genes by the mean
 * position of the genes whose edges reach them (index order on a tie).
 * An edge down goes from the bottom of its gene to the top of its child,
 * several between the same two genes side by side; an edge back up (or
 * within a row) goes round the left of both; a self-loop hangs at the
 * bottom right corner, a second one outside the first.
 */
export function genotypeLayout(model, g = GENE_GRAPH) {
  const depth = geneDepths(model);
  const longest = Math.max(0, ...model.nodes.map((n) => Math.max(geneTitle(n).length, geneUnits(n).length)));
  const w = Math.max(g.minNodeWidth, Math.ceil(longest * g.charWidth) + 12), h = g.nodeHeight;
  const nRows = Math.max(...depth) + 1;
  const rows = Array.from({ length: nRows }, () => []);
  depth.forEach((d, i) => rows[d].push(i));
  const back = model.edges.filter((e) => !e.self && depth[e.to] <= depth[e.from]);
  const left = g.pad + (back.length ? g.backBulge + (back.length - 1) * g.backStep : 0);
  const widest = Math.max(...rows.map((r) => r.length));
  const nodes = model.nodes.map((n, i) => ({ ...n, row: depth[i], x: 0, y: 0, width: w, height: h, limitAt: [0, 0] }));
  const centreX = (i) => nodes[i].x + w / 2;
  rows.forEach((row, r) => {
    if (r > 0) {
      const key = (i) => {
        const from = model.edges.filter((e) => e.to === i && depth[e.from] < r).map((e) => centreX(e.from));
        return from.length ? from.reduce((a, b) => a + b, 0) / from.length : Infinity;
      };
      const keys = new Map(row.map((i) => [i, key(i)]));
      row.sort((a, b) => keys.get(a) - keys.get(b) || a - b);
    }
    const x0 = left + ((widest - row.length) * (w + g.gapX)) / 2;
    row.forEach((i, k) => {
      const n = nodes[i];
      n.x = x0 + k * (w + g.gapX);
      n.y = g.pad + r * (h + g.gapY);
      n.limitAt = [n.x + w + 3, n.y + 10];
    });
  });
  // edges: parallel ones (same two genes) side by side, loops nested
  const siblings = new Map();
  const key = (e) => `${e.from}>${e.to}`;
  for (const e of model.edges) siblings.set(key(e), (siblings.get(key(e)) ?? 0) + 1);
  const seen = new Map();
  let backIndex = 0;
  let right = left + widest * w + (widest - 1) * g.gapX;
  let bottom = g.pad + nRows * h + (nRows - 1) * g.gapY;
  const edges = model.edges.map((e) => {
    const k = seen.get(key(e)) ?? 0;
    seen.set(key(e), k + 1);
    const m = siblings.get(key(e));
    const a = nodes[e.from], b = nodes[e.to];
    let c;
    if (e.self) {
      const r = g.loop + k * g.loopStep;
      const x = a.x + w, y = a.y + h;
      c = cubic([x, y - 9], [x + 1.8 * r, y - 9], [x - 14, y + 1.8 * r], [x - 14, y]);
      right = Math.max(right, x + 1.3 * r);
      bottom = Math.max(bottom, y + 1.3 * r);
    } else if (depth[e.to] > depth[e.from]) {
      const off = (k - (m - 1) / 2) * g.parallel;
      const x0 = a.x + w / 2 + off, y0 = a.y + h, x1 = b.x + w / 2 + off, y1 = b.y;
      const dy = (y1 - y0) / 2;
      c = cubic([x0, y0], [x0, y0 + dy], [x1, y1 - dy], [x1, y1]);
    } else {
      const bulge = g.backBulge + backIndex++ * g.backStep;
      const x = Math.min(a.x, b.x) - bulge;
      const y0 = a.y + h / 2 + (k - (m - 1) / 2) * 6, y1 = b.y + h / 2 + (k - (m - 1) / 2) * 6;
      c = cubic([a.x, y0], [x, y0], [x, y1], [b.x, y1]);
    }
    return { ...e, d: c.d, markAt: c.mid };
  });
  // room for the limits beside the last column
  right = Math.max(right, ...nodes.map((n) => n.limitAt[0] + g.charWidth * limitText(n).length));
  return { nodes, edges, width: Math.ceil(right + g.pad), height: Math.ceil(bottom + g.pad) };
}
