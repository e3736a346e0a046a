// Numbers as the page shows them.

/** Seconds with two decimals: "3.20 s". */
export function seconds(t) {
  return `${t.toFixed(2)} s`;
}

/** Metres with two decimals: "1.73 m". */
export function metres(d) {
  return `${d.toFixed(2)} m`;
}

/** A fitness with four significant digits, no trailing noise: "5.536". */
export function fitness(v) {
  if (!Number.isFinite(v)) return String(v);
  return Number(v.toPrecision(4)).toString();
}

/** A frequency with three significant digits, as `bestiary check` gives it: "30 Hz", "2.5 Hz". */
export function hertz(v) {
  return `${Number(v.toPrecision(3))} Hz`;
}
