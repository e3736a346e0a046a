// Props are drawn from their description alone: a fake prop in a replay's
// scene becomes a mesh of its shape, size, colour and pose.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Box3 } from 'three';
import { parseProp, propPoseAt, PROP_COLOR, sceneProps } from '../src/props.js';
import { createBodies } from '../src/bodies.js';
import { parseReplay } from '../src/data.js';
import { geneColor } from '../src/palette.js';
import { aboutZ, makeReplay } from './fixture.mjs';

const ball = { name: 'ball', shape: 'sphere', size: [0.2, 0.2, 0.2], color: '#cc3333' };

test('a description gets defaults: grey, opaque, at the origin', () => {
  const p = parseProp({ shape: 'box', size: [1, 2, 3] }, 0);
  assert.deepEqual(p, { name: 'prop 0', shape: 'box', size: [1, 2, 3], color: PROP_COLOR, opacity: 1, pose: [0, 0, 0, 1, 0, 0, 0] });
  assert.equal(parseProp(ball, 1).color, 0xcc3333);
});

test('a bad description names the prop and the field', () => {
  assert.throws(() => parseProp({ shape: 'torus', size: [1, 1, 1] }, 2), { message: /^scene\.props\[2\]\.shape: expected one of box, sphere, capsule, cylinder, got "torus"$/ });
  assert.throws(() => parseProp({ shape: 'box', size: [1, 0, 1] }, 0), { message: /scene\.props\[0\]\.size: expected positive extents/ });
  assert.throws(() => parseProp({ shape: 'box', size: [1, 1, 1], color: 'blue' }, 0), { message: /scene\.props\[0\]\.color/ });
  assert.throws(() => parseProp({ shape: 'box', size: [1, 1, 1], opacity: 2 }, 0), { message: /scene\.props\[0\]\.opacity/ });
  assert.throws(() => parseProp({ shape: 'box', size: [1, 1, 1], pose: [0, 0, 0] }, 0), { message: /scene\.props\[0\]\.pose: expected 7 numbers/ });
});

test('a prop without per-frame poses stays at its fixed pose', () => {
  const r = makeReplay();
  r.scene.props = [{ ...ball, pose: [1, 2, 0.1, 1, 0, 0, 0] }];
  const [p] = sceneProps(r);
  assert.deepEqual(propPoseAt(r, p, 0, 1.23), [1, 2, 0.1, 1, 0, 0, 0]);
});

test('a moving prop is interpolated from frames[f].props', () => {
  const r = makeReplay();
  r.scene.props = [ball];
  r.frames.forEach((f) => (f.props = [[0, 0, 1 + f.t, ...aboutZ(f.t)]]));
  parseReplay(r);
  const [p] = sceneProps(r);
  const pose = propPoseAt(r, p, 0, 0.55);
  assert.ok(Math.abs(pose[2] - 1.55) < 1e-9);
  // frames that carry props must carry one pose per prop
  r.frames[3].props = [];
  assert.throws(() => parseReplay(r), { message: /frames\[3\]\.props: expected 1 poses/ });
});

test('the scene draws a fake prop with its shape, size, colour and pose', () => {
  const r = makeReplay();
  r.scene.props = [ball, { shape: 'cylinder', size: [0.6, 0.1, 0.1], pose: [3, 0, 0.05, 1, 0, 0, 0] }];
  r.frames.forEach((f) => (f.props = [[f.t, 1, 0.5, 1, 0, 0, 0], [3, 0, 0.05, 1, 0, 0, 0]]));
  const bodies = createBodies(parseReplay(r));
  assert.equal(bodies.parts.length, 2);
  assert.equal(bodies.props.length, 2);
  bodies.setTime(1.0);
  const [b, c] = bodies.props;
  assert.deepEqual([b.position.x, b.position.y, b.position.z].map((v) => +v.toFixed(6)), [1, 1, 0.5]);
  assert.equal(b.material.color.getHex(), 0xcc3333);
  const size = new Box3().setFromObject(c, true).getSize(c.position.clone());
  assert.ok(Math.abs(size.x - 0.6) < 1e-6 && Math.abs(size.y - 0.1) < 0.002, JSON.stringify(size));
  assert.equal(c.material.color.getHex(), PROP_COLOR);
  // parts keep their gene colours, the mirrored one lighter
  assert.equal(bodies.parts[0].material.color.getHex(), geneColor(0));
  assert.equal(bodies.parts[1].material.color.getHex(), geneColor(1, true));
  bodies.dispose();
});
