// A replay's scene record (docs/replay-format.md, scene.record): what the
// task and its controller show beside the creature, in one generic shape.
// What holds throughout: named moments (a catapult's "release"), named
// points (its "target"), props (solids shown from a time on, a spinning one
// turning about the vertical: fight-or-flight targets), named parts to
// highlight (its "projectile"), the kinds of grid cell. Then events in time
// order: a grid laid, a cell changed, an item carried, a field over the grid
// (a heat map), a counter's value. This module checks a record and says what
// the scene is at a time; record_view.js draws it.
import { DataError, numbers } from './data.js';
import { parseCssColor, PROJECTILE_COLOR } from './palette.js';
import { DRAWABLE } from './shapes.js';

/** The events' types, each the key of its payload. */
export const EVENT_TYPES = ['grid', 'cell', 'carry', 'field', 'counter'];

function fail(path, what, got) {
  let shown = JSON.stringify(got);
  if (shown === undefined) shown = 'nothing';
  if (shown.length > 60) shown = shown.slice(0, 57) + '...';
  throw new DataError(`${path}: ${what}, got ${shown}`);
}
const isNum = (v) => typeof v === 'number' && Number.isFinite(v);
function obj(v, path) {
  if (v === null || typeof v !== 'object' || Array.isArray(v)) fail(path, 'expected an object', v);
  return v;
}
function list(v, path) {
  if (v === undefined) return [];
  if (!Array.isArray(v)) fail(path, 'expected an array', v);
  return v;
}
function str(v, path) {
  if (typeof v !== 'string') fail(path, 'expected a string', v);
  return v;
}
function int(v, path, lo, hi, what) {
  if (!Number.isInteger(v) || v < lo || v > hi) fail(path, what, v);
  return v;
}
function color(v, path) {
  const c = parseCssColor(v);
  if (c === null) fail(path, 'expected "#rrggbb"', v);
  return c;
}

// a pose as the frames hold one, [x, y, z, qw, qx, qy, qz]: its quaternion
// of unit length, but for the file's rounding (or a hand-written one's)
function pose(v, path) {
  const what = 'expected [x, y, z, qw, qx, qy, qz] with a unit quaternion';
  if (!Array.isArray(v) || v.length !== 7 || !v.every(isNum)) fail(path, what, v);
  if (!(Math.abs(Math.hypot(v[3], v[4], v[5], v[6]) - 1) <= 1e-3)) fail(path, what, v);
  return v;
}

/**
 * Checks a record (the JSON of scene.record) for a creature of `nParts`
 * parts and returns it in the viewer's form: colours as numbers, events as
 * { t, type, ...payload } ({t, type: 'cell', x, y, kind}).
 */
export function parseRecord(rec, nParts, path = 'scene.record') {
  obj(rec, path);
  const markers = list(rec.markers, `${path}.markers`).map((m, i) => {
    const at = `${path}.markers[${i}]`;
    obj(m, at);
    if (!isNum(m.t)) fail(`${at}.t`, 'expected a number', m.t);
    return { name: str(m.name, `${at}.name`), t: m.t };
  });
  const points = list(rec.points, `${path}.points`).map((p, i) => {
    const at = `${path}.points[${i}]`;
    obj(p, at);
    if (!(isNum(p.size) && p.size > 0)) fail(`${at}.size`, 'expected a diameter > 0', p.size);
    return { name: str(p.name, `${at}.name`), p: numbers(p.p, 3, `${at}.p`), size: p.size, color: color(p.color, `${at}.color`) };
  });
  const props = list(rec.props, `${path}.props`).map((d, i) => {
    const at = `${path}.props[${i}]`;
    obj(d, at);
    const name = str(d.name, `${at}.name`);
    if (!DRAWABLE.includes(d.shape)) fail(`${at}.shape`, `expected one of ${DRAWABLE.join(', ')}`, d.shape);
    const size = numbers(d.size, 3, `${at}.size`);
    if (!size.every((v) => v > 0)) fail(`${at}.size`, 'expected extents > 0', d.size);
    const where = pose(d.pose, `${at}.pose`);
    if (!isNum(d.spin)) fail(`${at}.spin`, 'expected a number', d.spin);
    if (!(isNum(d.t) && d.t >= 0)) fail(`${at}.t`, 'expected a time >= 0', d.t);
    return { name, shape: d.shape, size, pose: where, spin: d.spin, t: d.t, color: color(d.color, `${at}.color`) };
  });
  const parts = list(rec.parts, `${path}.parts`).map((p, i) => {
    const at = `${path}.parts[${i}]`;
    obj(p, at);
    const part = int(p.part, `${at}.part`, 0, nParts - 1, `no such part (the creature has ${nParts})`);
    return { name: str(p.name, `${at}.name`), part, color: color(p.color, `${at}.color`) };
  });
  const cellKinds = list(rec.cell_kinds, `${path}.cell_kinds`).map((k, i) => {
    const at = `${path}.cell_kinds[${i}]`;
    obj(k, at);
    if (typeof k.item !== 'boolean') fail(`${at}.item`, 'expected true or false', k.item);
    return { name: str(k.name, `${at}.name`), color: color(k.color, `${at}.color`), item: k.item };
  });
  const nKinds = cellKinds.length;
  const noKind = `no such cell kind (the record has ${nKinds})`;
  let last = -Infinity, grid = null;
  const events = list(rec.events, `${path}.events`).map((e, i) => {
    const at = `${path}.events[${i}]`;
    obj(e, at);
    if (!isNum(e.t) || e.t < last) fail(`${at}.t`, `expected a time >= ${last}`, e.t);
    last = e.t;
    const types = EVENT_TYPES.filter((k) => k in e);
    if (types.length !== 1) fail(at, `expected one of ${EVENT_TYPES.join(', ')}`, e);
    const type = types[0], w = obj(e[type], `${at}.${type}`), where = `${at}.${type}`;
    switch (type) {
      case 'grid': {
        const width = int(w.width, `${where}.width`, 1, 4096, 'expected a count from 1');
        const height = int(w.height, `${where}.height`, 1, 4096, 'expected a count from 1');
        if (!(isNum(w.cell) && w.cell > 0)) fail(`${where}.cell`, 'expected a width > 0', w.cell);
        if (!Array.isArray(w.cells) || w.cells.length !== width * height)
          fail(`${where}.cells`, `expected ${width * height} cell kinds`, Array.isArray(w.cells) ? w.cells.length : w.cells);
        w.cells.forEach((c, k) => int(c, `${where}.cells[${k}]`, 0, nKinds - 1, noKind));
        grid = { width, height };
        return { t: e.t, type, origin: numbers(w.origin, 3, `${where}.origin`), cell: w.cell, width, height, cells: w.cells };
      }
      case 'cell':
        if (!grid) fail(where, 'a cell changed before any grid was laid', w);
        return {
          t: e.t, type,
          x: int(w.x, `${where}.x`, 0, grid.width - 1, `outside the grid's ${grid.width} columns`),
          y: int(w.y, `${where}.y`, 0, grid.height - 1, `outside the grid's ${grid.height} rows`),
          kind: int(w.kind, `${where}.kind`, 0, nKinds - 1, noKind),
        };
      case 'carry':
        return {
          t: e.t, type,
          part: int(w.part, `${where}.part`, 0, nParts - 1, `no such part (the creature has ${nParts})`),
          kind: int(w.kind, `${where}.kind`, -1, nKinds - 1, `${noKind} or -1 for nothing`),
        };
      case 'field': {
        const width = int(w.width, `${where}.width`, 1, 4096, 'expected a count from 1');
        const height = int(w.height, `${where}.height`, 1, 4096, 'expected a count from 1');
        const [lo, hi] = numbers(w.range, 2, `${where}.range`);
        if (!(lo < hi)) fail(`${where}.range`, 'expected [lo, hi] with lo < hi', w.range);
        return { t: e.t, type, name: str(w.name, `${where}.name`), width, height, lo, hi, values: numbers(w.values, width * height, `${where}.values`) };
      }
      default:
        if (!isNum(w.value)) fail(`${where}.value`, 'expected a number', w.value);
        return { t: e.t, type, name: str(w.name, `${where}.name`), value: w.value, unit: w.unit === undefined ? '' : str(w.unit, `${where}.unit`) };
    }
  });
  return { markers, points, props, parts, cellKinds, events };
}

const EMPTY = { markers: [], points: [], props: [], parts: [], cellKinds: [], events: [] };
const parsed = new WeakMap();

/**
 * The checked record of a replay. A replay written before records (version
 * 1 files with a catapult's `throw`) gets the record that throw means: the
 * part "projectile" and the marker "release" (its target is one of its
 * scene.props already). A replay with neither has an empty record.
 */
export function recordOf(replay) {
  if (parsed.has(replay)) return parsed.get(replay);
  let rec = EMPTY;
  const nParts = replay.parts.length;
  if (replay.scene?.record !== undefined) {
    rec = parseRecord(replay.scene.record, nParts);
  } else if (replay.throw) {
    const th = replay.throw;
    rec = {
      ...EMPTY,
      parts: [{ name: 'projectile', part: th.projectile, color: PROJECTILE_COLOR }],
      markers: th.release_t === null || th.release_t === undefined ? [] : [{ name: 'release', t: th.release_t }],
    };
  }
  parsed.set(replay, rec);
  return rec;
}

/** The time of the record's marker `name`, or null. */
export function markerTime(rec, name) {
  return rec.markers.find((m) => m.name === name)?.t ?? null;
}
/** The record's part named `name` ({name, part, color}), or null. */
export function partNamed(rec, name) {
  return rec.parts.find((p) => p.name === name) ?? null;
}
/** The record's point named `name` ({name, p, size, color}), or null. */
export function pointNamed(rec, name) {
  return rec.points.find((p) => p.name === name) ?? null;
}

/** Whether the record draws anything on the ground or a part over time (a grid, a carried item, a field). */
export function hasWorld(rec) {
  return rec.events.some((e) => e.type !== 'counter');
}

/**
 * The scene at time t, from the events up to it (those at t included):
 * `grid` (the last grid event, or null), `cellsKey` (the index of the last
 * grid or cell event: the cells differ only when it does), `carry` ({part,
 * kind} or null), `fields` (name -> the last field event of that name) and
 * `counters` ([name, value, unit] in the order the record first names
 * them; unit '' for a count).
 */
export function sceneAt(rec, t) {
  let grid = null, cellsKey = -1, carry = null;
  const fields = {}, counters = new Map(), units = new Map();
  for (let i = 0; i < rec.events.length; ++i) {
    const e = rec.events[i];
    if (e.type === 'counter' && !counters.has(e.name)) counters.set(e.name, null);
    if (e.t > t) continue; // later counters are still named, in order
    if (e.type === 'grid') { grid = e; cellsKey = i; }
    else if (e.type === 'cell') cellsKey = i;
    else if (e.type === 'carry') carry = e.kind < 0 ? null : { part: e.part, kind: e.kind };
    else if (e.type === 'field') fields[e.name] = e;
    else { counters.set(e.name, e.value); units.set(e.name, e.unit ?? ''); }
  }
  return {
    grid, cellsKey, carry, fields,
    counters: [...counters].filter(([, v]) => v !== null).map(([name, v]) => [name, v, units.get(name)]),
  };
}

/** The current grid's cells at time t (its grid's cells with the changes since), or null before a grid. */
export function cellsAt(rec, t) {
  let cells = null, width = 0;
  for (const e of rec.events) {
    if (e.t > t) break;
    if (e.type === 'grid') {
      cells = e.cells.slice();
      width = e.width;
    } else if (e.type === 'cell' && cells) {
      cells[e.y * width + e.x] = e.kind;
    }
  }
  return cells;
}

/** Counters as the line of text says them: "level 2   score 101   deaths 0", "distance 0.69 m". */
export function countersText(counters) {
  return counters.map(([name, v, unit]) => `${name} ${Number.isInteger(v) ? v : v.toFixed(2)}${unit ? ` ${unit}` : ''}`).join('   ');
}

/** Whether the record counts a counter named `name` at any time. */
export function hasCounter(rec, name) {
  return rec.events.some((e) => e.type === 'counter' && e.name === name);
}

/** The markers of the span a task scores (src/core/scene_record.h: kScoredFrom, kScoredTo). */
export const SCORED_FROM = 'scored from', SCORED_TO = 'scored to';

/**
 * The span the task scored, {from, to} in s, from its markers (no "scored
 * to": the replay's end, `duration`), or null when the record has none.
 */
export function scoredSpan(rec, duration) {
  const from = markerTime(rec, SCORED_FROM);
  if (from === null) return null;
  const to = markerTime(rec, SCORED_TO);
  return { from, to: to === null ? duration : to };
}
