// The pixels of a grid's textures: its cells in their kinds' colours with a
// thin line between cells, and a field over it as a heat map. Pure: RGBA
// bytes, row 0 being the grid's row y = 0 (the texture's bottom, which is
// the grid's low y once laid on the ground).

/** Texels per cell side in the cells' texture. */
export const CELL_PX = 8;

const rgb = (c) => [(c >> 16) & 255, (c >> 8) & 255, c & 255];

/**
 * The cells' texture: `cells` (kinds, row by row, `width` per row) painted
 * in the colours of `kinds` ([{color}]), `px` texels a cell, each cell's
 * last column and row a little darker so the cells read apart.
 */
export function paintCells(cells, kinds, width, height, px = CELL_PX) {
  const W = width * px, out = new Uint8Array(W * height * px * 4);
  const colours = kinds.map((k) => rgb(k.color));
  for (let y = 0; y < height; ++y)
    for (let x = 0; x < width; ++x) {
      const c = colours[cells[y * width + x]];
      for (let j = 0; j < px; ++j)
        for (let i = 0; i < px; ++i) {
          const edge = i === px - 1 || j === px - 1 ? 0.82 : 1;
          const o = 4 * ((y * px + j) * W + x * px + i);
          out[o] = Math.round(c[0] * edge);
          out[o + 1] = Math.round(c[1] * edge);
          out[o + 2] = Math.round(c[2] * edge);
          out[o + 3] = 255;
        }
    }
  return out;
}

// the ends of the two scales: above 0 from pale yellow to deep red, below 0
// from pale cyan to deep blue
const WARM = [[255, 236, 130], [190, 20, 30]];
const COLD = [[170, 235, 245], [30, 50, 170]];

/**
 * A field's value v on the scale [lo, hi] (lo < 0 < hi, or 0 at one end) as
 * [r, g, b, a]: 0 is clear, a positive value warm and a negative one cold,
 * more opaque and deeper the nearer its end of the scale, on a square-root
 * scale (a shunting model's landscape falls off fast from its sources, so a
 * linear one would show little beyond them).
 */
export function heatColor(v, lo, hi) {
  const end = v > 0 ? hi : -lo;
  if (!(end > 0) || v === 0) return [0, 0, 0, 0];
  const u = Math.sqrt(Math.min(Math.abs(v) / end, 1));
  const [a, b] = v > 0 ? WARM : COLD;
  const mix = (k) => Math.round(a[k] + (b[k] - a[k]) * u);
  return [mix(0), mix(1), mix(2), Math.round(255 * (0.1 + 0.45 * u))];
}

/** A field ({width, height, lo, hi, values}) as RGBA, one texel per cell. */
export function paintField(field) {
  const out = new Uint8Array(field.values.length * 4);
  field.values.forEach((v, k) => out.set(heatColor(v, field.lo, field.hi), 4 * k));
  return out;
}

/** The heat map's scale as a CSS gradient, cold end to warm end (for a legend). */
export function heatGradient(lo, hi) {
  const stops = [];
  for (let k = 0; k <= 8; ++k) {
    const v = lo + ((hi - lo) * k) / 8;
    const [r, g, b, a] = heatColor(v, lo, hi);
    stops.push(`rgba(${r}, ${g}, ${b}, ${(a / 255).toFixed(2)})`);
  }
  return `linear-gradient(to right, ${stops.join(', ')})`;
}
