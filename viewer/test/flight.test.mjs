// A catapult's throw: the projectile's flight from its release to the
// present moment, as points and as a tube around them.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  centreAt, centrePath, flightAt, flightPoints, throwOf, throwStatus, thrownAt, tube, tubeIndices,
} from '../src/flight.js';
import { createFlight } from '../src/flight_view.js';
import { makeCatapult, makeReplay, projectileAt } from './fixture.mjs';

const close = (a, b, eps = 1e-6) =>
  a.forEach((v, i) => assert.ok(Math.abs(v - b[i]) < eps, `${JSON.stringify(Array.from(a))} != ${JSON.stringify(b)}`));

test('the throw of a catapult; none for other creatures', () => {
  assert.deepEqual(throwOf(makeCatapult({ target: [2, 0, 0.075] })), { projectile: 2, release: 0.5, target: [2, 0, 0.075], color: 0xffc61a });
  assert.deepEqual(throwOf(makeCatapult({ release: null })).release, null);
  // a file written before scene records: the same throw from its `throw` (its target a prop)
  assert.deepEqual(throwOf(makeCatapult({ release: 0.5, legacy: true })), { projectile: 2, release: 0.5, target: null, color: 0xffc61a });
  assert.equal(throwOf(makeCatapult({ release: null, legacy: true })).release, null);
  assert.equal(throwOf(makeReplay()), null);
});

test('the path holds the projectile centre of every frame', () => {
  const frames = makeCatapult().frames;
  const p = centrePath(frames, 2);
  assert.equal(p.length, 3 * frames.length);
  close(p.slice(3 * 7, 3 * 8), projectileAt(0.7));
  close(centreAt(frames, 2, 0.75), [0.9, 0, (projectileAt(0.7)[2] + projectileAt(0.8)[2]) / 2]);
});

test('nothing flies before the release, or when there was none', () => {
  const frames = makeCatapult().frames;
  assert.equal(flightAt(frames, 2, 0.5, 0), null);
  assert.equal(flightAt(frames, 2, 0.5, 0.49), null);
  assert.equal(flightAt(frames, 2, null, 1), null);
});

test('the flight runs from the release point through the frames to the present', () => {
  const frames = makeCatapult().frames;
  // released on frame 5 (t = 0.5): frames 6 and 7 whole, then the head at 0.75
  const f = flightAt(frames, 2, 0.5, 0.75);
  assert.equal(f.from, 6);
  assert.equal(f.count, 2);
  close(f.start, projectileAt(0.5));
  close(f.head, centreAt(frames, 2, 0.75));
  const out = new Float32Array(3 * (frames.length + 2));
  assert.equal(flightPoints(centrePath(frames, 2), f, out), 4);
  close(out.slice(0, 12), [...projectileAt(0.5), ...projectileAt(0.6), ...projectileAt(0.7), ...f.head]);
  // at the release itself: the release point twice, no frame between
  const now = flightAt(frames, 2, 0.5, 0.5);
  assert.equal(now.count, 0);
  close(now.head, now.start);
  // to the end: every frame after the release
  assert.equal(flightAt(frames, 2, 0.5, 99).count, 5);
});

test('a release between frames starts from the interpolated centre', () => {
  const frames = makeCatapult().frames;
  const f = flightAt(frames, 2, 0.55, frames[6].t);
  assert.equal(f.from, 6);
  assert.equal(f.count, 1); // frame 6 exactly
  close(f.start, centreAt(frames, 2, 0.55));
  // released on the first frame: the flight starts after it; before the first frame: with it
  assert.equal(flightAt(frames, 2, 0, 0.05).from, 1);
  const late = frames.map((fr) => ({ ...fr, t: fr.t + 0.2 }));
  assert.equal(flightAt(late, 2, 0.1, 0.25).from, 0);
});

test('the distance thrown grows from the release, 0 before it', () => {
  const frames = makeCatapult().frames;
  assert.equal(thrownAt(frames, 2, 0.5, 0.3), 0);
  assert.equal(thrownAt(frames, 2, null, 0.3), null);
  assert.ok(Math.abs(thrownAt(frames, 2, 0.5, 1) - 1) < 1e-9); // 2 m/s along x for 0.5 s
  const th = throwOf(makeCatapult());
  assert.equal(throwStatus(frames, th, 0.2), 'held');
  assert.equal(throwStatus(frames, th, 1), 'thrown 1.00 m');
  assert.equal(throwStatus(frames, { ...th, release: null }, 1), 'not released');
});

test('the tube rings stand square to the path, radius out from it', () => {
  // up, then along +x, then up again: a corner in the xz plane
  const path = new Float32Array([0, 0, 0, 0, 0, 1, 1, 0, 1, 1, 0, 2]);
  const sides = 6, r = 0.1;
  const out = new Float32Array(3 * 4 * sides), normals = new Float32Array(3 * 4 * sides);
  tube(path, 4, r, sides, out, normals);
  for (let k = 0; k < 4; ++k) {
    const c = path.slice(3 * k, 3 * k + 3);
    for (let s = 0; s < sides; ++s) {
      const v = out.slice(3 * (k * sides + s), 3 * (k * sides + s) + 3);
      const n = normals.slice(3 * (k * sides + s), 3 * (k * sides + s) + 3);
      assert.ok(Math.abs(Math.hypot(v[0] - c[0], v[1] - c[1], v[2] - c[2]) - r) < 1e-6);
      close(n, [(v[0] - c[0]) / r, (v[1] - c[1]) / r, (v[2] - c[2]) / r]);
    }
  }
  // the first ring is square to its direction (+z): flat in z
  for (let s = 0; s < sides; ++s) assert.ok(Math.abs(out[3 * s + 2]) < 1e-6);
  // the ring at the second point is square to its direction (from point 0 to 2: (1, 0, 1))
  for (let s = 0; s < sides; ++s) {
    const o = 3 * (sides + s);
    assert.ok(Math.abs((out[o] - 0) * 1 + (out[o + 2] - 1) * 1) < 1e-6);
  }
});

test('a tube along a still or vertical path keeps its radius', () => {
  for (const path of [new Float32Array(9), new Float32Array([0, 0, 0, 0, 0, 1, 0, 0, 2])]) {
    const out = tube(path, 3, 0.05, 8, new Float32Array(72));
    for (let i = 0; i < 24; ++i) {
      const k = Math.floor(i / 8);
      const d = Math.hypot(out[3 * i] - path[3 * k], out[3 * i + 1] - path[3 * k + 1], out[3 * i + 2] - path[3 * k + 2]);
      assert.ok(Math.abs(d - 0.05) < 1e-6, String(d));
    }
  }
});

test('tube triangles join consecutive rings, wrapping round', () => {
  assert.deepEqual(Array.from(tubeIndices(2, 3)), [0, 1, 3, 1, 4, 3, 1, 2, 4, 2, 5, 4, 2, 0, 5, 0, 3, 5]);
  assert.equal(tubeIndices(1, 8).length, 0);
  // every index is a vertex of the tube
  assert.ok(Math.max(...tubeIndices(5, 8)) < 5 * 8);
});

test('the drawn flight: nothing before the release, then a tube from the release ball to the projectile', () => {
  const replay = makeCatapult();
  const flight = createFlight(replay, 0.5);
  flight.setTime(0.3);
  assert.equal(flight.drawn, false);
  flight.setTime(0.75);
  assert.equal(flight.drawn, true);
  const [line, ball] = flight.object.children;
  // 4 points (release, frames 6 and 7, head): 3 segments of 10 sides
  assert.equal(line.geometry.drawRange.count, 3 * 10 * 6);
  close([ball.position.x, ball.position.y, ball.position.z], projectileAt(0.5));
  // the tube's last ring is around the projectile's present centre
  const pos = line.geometry.attributes.position.array;
  const ring = Array.from({ length: 10 }, (_, s) => pos.slice(3 * (3 * 10 + s), 3 * (3 * 10 + s) + 3));
  const mean = [0, 1, 2].map((c) => ring.reduce((a, v) => a + v[c], 0) / 10);
  close(mean, centreAt(replay.frames, 2, 0.75), 1e-5);
  // never released: never drawn
  const never = createFlight(makeCatapult({ release: null }), 0.5);
  never.setTime(1);
  assert.equal(never.drawn, false);
  flight.dispose();
  never.dispose();
});
