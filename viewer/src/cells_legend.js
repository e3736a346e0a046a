// The legend of a recorded grid, in the scene's corner: each cell kind's
// colour and name (an item kind marked as a box on its cell) and, with a
// field, the heat map's scale. Hidden for a record without a grid.
import { el } from './dom.js';
import { heatGradient } from './cell_paint.js';
import { cssColor } from './palette.js';

/**
 * The legend's entries for record `rec`: [{name, color ("#rrggbb"), item}]
 * for the cell kinds when it lays a grid (else none), and the heat map's
 * {name, lo, hi} or null.
 */
export function legendOf(rec) {
  const grid = rec.events.some((e) => e.type === 'grid');
  const field = rec.events.find((e) => e.type === 'field') ?? null;
  return {
    kinds: grid ? rec.cellKinds.map((k) => ({ name: k.name, color: cssColor(k.color), item: k.item })) : [],
    field: grid && field ? { name: field.name, lo: field.lo, hi: field.hi } : null,
  };
}

const short = (v) => String(Number(v.toPrecision(3)));

/** Fills `container` with the legend of `rec`, or hides it. */
export function showCellsLegend(container, rec) {
  const { kinds, field } = legendOf(rec);
  container.hidden = kinds.length === 0;
  container.replaceChildren(
    ...kinds.map((k) => el('span', { class: 'cell-key', title: k.item ? `${k.name}: a box on its cell, or carried` : k.name },
      el('span', { class: k.item ? 'swatch item' : 'swatch', style: `background:${k.color}` }), k.name)),
    field ? el('span', { class: 'cell-key heat-key', title: `${field.name}: the heat map over the grid (square-root scale; key h)` },
      `${field.name} ${short(field.lo)}`,
      el('span', { class: 'heat-bar', style: `background:${heatGradient(field.lo, field.hi)}` }),
      short(field.hi)) : null,
  );
}
