// Colours of parts by gene: a fixed palette indexed by the gene (the genome's
// node), so a gene keeps its colour in every creature and frame. Parts grown
// through a reflection get a lighter shade of their gene's colour.

// Twelve well-separated hues, mid lightness so both shades read on the grey ground.
const BASE = [
  0x3f7fc7, 0xe0833a, 0x4fa45a, 0xc94f4f, 0x8a67c1, 0x9c6b4e,
  0xd46fb0, 0x6d7f8c, 0xb9b13b, 0x35aeb8, 0x2f4f9e, 0xa13f6e,
];

function mix(c, toward, f) {
  const ch = (s) => (c >> s) & 255;
  const tw = (s) => (toward >> s) & 255;
  const m = (s) => Math.round(ch(s) + (tw(s) - ch(s)) * f);
  return (m(16) << 16) | (m(8) << 8) | m(0);
}

/**
 * Colour of a part (0xRRGGBB) from its gene index and whether it is mirrored.
 * Past twelve genes the palette repeats, darker each round.
 */
export function geneColor(gene, mirrored = false) {
  const n = BASE.length;
  const g = Math.max(0, Math.floor(gene));
  const round = Math.floor(g / n);
  let c = BASE[g % n];
  if (round > 0) c = mix(c, 0x000000, Math.min(0.6, 0.22 * round));
  return mirrored ? mix(c, 0xffffff, 0.35) : c;
}

/** A colour faded toward the ground's grey: a part left out of a highlight. */
export function fadedColor(c) {
  return mix(c, 0xd5d9dd, 0.65);
}

/**
 * Colour of a catapult's projectile: a warm yellow far from every gene's
 * colour (the nearest, gene 1's orange, is on most bodies), so the
 * projectile stands out from the body.
 */
export const PROJECTILE_COLOR = 0xffc61a;

/** Colour of the projectile's flight path: a deeper shade of its yellow, to read on the grey ground. */
export const FLIGHT_COLOR = 0xe8a100;

/** A colour as CSS text, "#rrggbb". */
export function cssColor(c) {
  return '#' + c.toString(16).padStart(6, '0');
}

/** Parses "#rgb" or "#rrggbb" (a prop's optional colour); null when not a colour. */
export function parseCssColor(s) {
  if (typeof s !== 'string') return null;
  let m = /^#([0-9a-f]{6})$/i.exec(s);
  if (m) return parseInt(m[1], 16);
  m = /^#([0-9a-f])([0-9a-f])([0-9a-f])$/i.exec(s);
  if (m) return parseInt(m[1] + m[1] + m[2] + m[2] + m[3] + m[3], 16);
  return null;
}
