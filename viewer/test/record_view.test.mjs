// The scene record drawn: the grid's cells on the ground under the grid,
// stones as boxes on their cells and on the carrying part, the heat map
// changing at the field's recorded times, a catapult's target as a sphere,
// props from their times on, a spinning one turned about the vertical, and
// the legend's entries.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Box3, Matrix4, Quaternion, Vector3 } from 'three';
import { createBodies } from '../src/bodies.js';
import { createRecordView } from '../src/record_view.js';
import { legendOf } from '../src/cells_legend.js';
import { CELL_PX } from '../src/cell_paint.js';
import { recordOf } from '../src/scene_record.js';
import { AXIS_UP, makeCatapult, makeReplay, makeRiver, makeTargets } from './fixture.mjs';

function view(replay) {
  const bodies = createBodies(replay);
  const world = createRecordView(recordOf(replay), replay, bodies);
  return { bodies, world };
}

test('the grid lies on the ground where the record lays it, in its kinds colours', () => {
  const { world } = view(makeRiver());
  world.setTime(0);
  assert.deepEqual(world.state(), { grid: [4, 3], items: 2, carried: false, field: 0, heat: true, points: 0, props: 0 });
  const tiles = world.group.children.find((m) => m.material?.map?.image?.width === 4 * CELL_PX);
  assert.ok(tiles, 'a plane with the cells texture');
  tiles.geometry.computeBoundingBox();
  const box = tiles.geometry.boundingBox.clone().applyMatrix4(tiles.matrixWorld.clone().compose(tiles.position, tiles.quaternion, tiles.scale));
  assert.deepEqual([box.min.x, box.min.y, box.max.x, box.max.y, box.max.z], [-1, -0.5, 1, 1, 0]);
  // cell (3, 0) is water: its texels are the water's blue
  const o = 4 * (1 * 4 * CELL_PX + 3 * CELL_PX + 1);
  assert.deepEqual(Array.from(world.cellsTexture.slice(o, o + 3)), [0x3b, 0x82, 0xc4]);
  world.dispose();
});

test('a stone picked up leaves its cell and rides on the part; put down, it is gone', () => {
  const { bodies, world } = view(makeRiver());
  world.setTime(0);
  // the stones stand on the middles of cells (1, 0) and (2, 2)
  const stones = world.group.children.filter((m) => m.visible && m.geometry?.type === 'BoxGeometry');
  const at = stones.map((m) => [m.position.x, m.position.y]).sort();
  assert.deepEqual(at, [[-0.25, -0.25], [0.25, 0.75]]);
  world.setTime(0.5);
  assert.equal(world.state().items, 1);
  assert.equal(world.state().carried, true);
  const carried = bodies.parts[0].children.find((c) => c.geometry?.type === 'BoxGeometry' && c !== bodies.parts[0].children[0]);
  assert.ok(carried, 'a box on part 0');
  bodies.setTime(0.5);
  bodies.group.updateMatrixWorld(true);
  const p = carried.getWorldPosition(new Vector3());
  // on top of the part (0.2 high, its centre at 0.1): 0.2 plus half the box (0.3 x 0.5 m / 2)
  assert.ok(Math.abs(p.z - (0.2 + 0.075)) < 1e-9, String(p.z));
  world.setTime(1.7);
  assert.equal(world.state().carried, false);
  assert.equal(world.state().items, 1);
  // back to the start: two stones again, nothing carried
  world.setTime(0.1);
  assert.deepEqual([world.state().items, world.state().carried], [2, false]);
  world.dispose();
});

test('the heat map changes at the field recorded times and can be hidden', () => {
  const { world } = view(makeRiver());
  world.setTime(0.2);
  const before = Array.from(world.fieldTexture);
  assert.ok(before.every((v) => v === 0), 'an all-zero field is clear');
  world.setTime(0.6);
  assert.equal(world.state().field, 0.5);
  const after = world.fieldTexture;
  assert.ok(after[4 * 0 + 3] > 0 && after[4 * 0] > after[4 * 0 + 2], 'the source (0, 0) is warm');
  assert.ok(after[4 * 3 + 2] > after[4 * 3], 'the water at (3, 0) is cold');
  world.showField(false);
  assert.equal(world.state().heat, false);
  world.showField(true);
  assert.equal(world.state().heat, true);
  assert.equal(world.fieldName, 'landscape');
  world.dispose();
});

test("a catapult's target is a sphere at its point; its projectile in the record's colour", () => {
  const replay = makeCatapult({ target: [2, 0, 0.075] });
  const { bodies, world } = view(replay);
  world.setTime(0);
  assert.deepEqual(world.state(), { grid: null, items: 0, carried: false, field: null, heat: false, points: 1, props: 0 });
  const ball = world.group.children[0];
  assert.deepEqual(ball.position.toArray(), [2, 0, 0.075]);
  assert.equal(ball.material.color.getHex(), 0xd6336c);
  assert.equal(bodies.parts[2].material.color.getHex(), 0xffc61a);
  world.dispose();
});

test('props appear at their time, lie as their poses say, and a spinning one turns about the vertical', () => {
  const { world } = view(makeTargets());
  const [disc, stack] = world.group.children;
  world.setTime(0.4);
  assert.equal(world.state().props, 0);
  assert.deepEqual([disc.visible, stack.visible], [false, false]);
  world.setTime(0.5);
  assert.equal(world.state().props, 2);
  assert.equal(disc.material.color.getHex(), 0x3b82c4);
  assert.equal(disc.castShadow, true);
  // the disc's axis is up: 0.6 m across on the ground, 0.02 m thick (to
  // the geometry's single precision)
  world.group.updateMatrixWorld(true);
  const box = new Box3().setFromObject(disc);
  const extents = box.max.clone().sub(box.min).toArray();
  [0.6, 0.6, 0.02].forEach((v, k) => assert.ok(Math.abs(extents[k] - v) < 1e-6, String(extents)));
  assert.ok(Math.abs(box.min.z) < 1e-6, String(box.min.z));
  // 1 s later the stack has turned 2 rad about the world's vertical through
  // its centre, after its own rotation: Rz(2) R
  world.setTime(1.5);
  assert.deepEqual(stack.position.toArray(), [1, 1, 0.17]);
  const [w, x, y, z] = AXIS_UP;
  const want = new Matrix4().makeRotationZ(2).multiply(new Matrix4().makeRotationFromQuaternion(new Quaternion(x, y, z, w)));
  const got = new Matrix4().makeRotationFromQuaternion(stack.quaternion);
  got.elements.forEach((v, k) => assert.ok(Math.abs(v - want.elements[k]) < 1e-12, `${got.elements} vs ${want.elements}`));
  // the disc, not spinning, as it appeared
  assert.ok(disc.quaternion.angleTo(new Quaternion(x, y, z, w)) < 1e-12);
  // back before their time: hidden again
  world.setTime(0.2);
  assert.equal(world.state().props, 0);
  world.dispose();
});

test("the legend lists the grid's kinds and the heat map's scale; nothing without a grid", () => {
  const l = legendOf(recordOf(makeRiver()));
  assert.deepEqual(l.kinds.map((k) => k.name), ['grass', 'stone', 'water', 'bridge']);
  assert.deepEqual(l.kinds[1], { name: 'stone', color: '#7c838b', item: true });
  assert.deepEqual(l.field, { name: 'landscape', lo: -15, hi: 15 });
  assert.deepEqual(legendOf(recordOf(makeCatapult({ target: [2, 0, 0] }))), { kinds: [], field: null });
  assert.deepEqual(legendOf(recordOf(makeReplay())), { kinds: [], field: null });
});
