// The scene record drawn (scene_record.js): its points as spheres, its props
// as solids from their times on (a spinning one turned about the world's
// vertical, z, through its centre), the grid's cells on the ground in their
// kinds' colours, an item kind's cells (stones) as small boxes standing on
// them, an item carried as a box on its part, and a field as a heat map over
// the grid that changes at its recorded times.
// Textures are redrawn only when what they show changed.
import {
  AlwaysDepth, BoxGeometry, DataTexture, Group, LinearFilter, Mesh, MeshBasicMaterial, MeshStandardMaterial, NearestFilter,
  PlaneGeometry, Quaternion, RGBAFormat, SphereGeometry, SRGBColorSpace, Vector3,
} from 'three';
import { solid } from './bodies.js';
import { CELL_PX, paintCells, paintField } from './cell_paint.js';
import { cellsAt, sceneAt } from './scene_record.js';
import { GROUND_ORDER } from './stage.js';

/** An item's box, in cell widths: a flat stone. */
export const ITEM_SIZE = [0.5, 0.5, 0.3];

const UP = new Vector3(0, 0, 1);

function texture(data, w, h, filter) {
  const t = new DataTexture(data, w, h, RGBAFormat);
  t.magFilter = t.minFilter = filter;
  t.generateMipmaps = false;
  t.colorSpace = SRGBColorSpace;
  t.needsUpdate = true;
  return t;
}

// a plane of w x h metres lying on the ground from `origin` (not above it:
// a millimetre flickers under software GL's depth precision)
function groundPlane(material, origin, w, h) {
  const m = new Mesh(new PlaneGeometry(1, 1), material);
  m.scale.set(w, h, 1);
  m.position.set(origin[0] + w / 2, origin[1] + h / 2, origin[2]);
  return m;
}

/**
 * What the record `rec` of `replay` draws, for the creature's meshes
 * `bodies` (bodies.js: a carried item rides on one of its parts).
 * `setTime(t)` shows the scene at t; `showField(on)` the heat map;
 * `state()` says what is drawn; `dispose()` frees it.
 */
export function createRecordView(rec, replay, bodies) {
  const group = new Group();
  // points: fixed, see-through spheres (a target)
  const points = rec.points.map((p) => {
    const m = new Mesh(new SphereGeometry(p.size / 2, 24, 12),
      new MeshStandardMaterial({ color: p.color, roughness: 0.6, transparent: true, opacity: 0.8 }));
    m.position.set(...p.p);
    m.castShadow = true;
    group.add(m);
    return m;
  });
  // props: hidden until they appear; each one's rotation when it appears
  // (w last in three), that its spin turns about the vertical from then on
  const props = rec.props.map((d) => {
    const m = solid(d.shape, d.size, d.color);
    m.position.set(d.pose[0], d.pose[1], d.pose[2]);
    m.visible = false;
    group.add(m);
    return m;
  });
  const propTurns = rec.props.map((d) => new Quaternion(d.pose[4], d.pose[5], d.pose[6], d.pose[3]).normalize());

  // the grid: a cells plane, a heat map plane over it, item boxes on it
  // (on the ground itself: drawn right after it (stage.js's GROUND_ORDER)
  // whatever the depth, then everything else tests against the cells; the
  // heat map, the very same plane, passes where the cells are)
  const tiles = new MeshStandardMaterial({ roughness: 0.95, metalness: 0, depthFunc: AlwaysDepth });
  const heat = new MeshBasicMaterial({ transparent: true, depthWrite: false });
  const itemMaterials = rec.cellKinds.map((k) => (k.item ? new MeshStandardMaterial({ color: k.color, roughness: 0.8 }) : null));
  let tilesMesh = null, heatMesh = null, itemGeometry = null, carried = null;
  const items = [];
  const shown = { grid: null, cellsKey: -2, field: null, carry: null, fieldOn: true };
  const fieldName = rec.events.find((e) => e.type === 'field')?.name ?? null;

  // takes the grid off the ground, its items with it
  function clearGrid() {
    if (tilesMesh) {
      group.remove(tilesMesh, heatMesh);
      tilesMesh.geometry.dispose();
      heatMesh.geometry.dispose();
      tiles.map?.dispose();
      tiles.map = null;
      tilesMesh = heatMesh = null;
    }
    items.forEach((m) => (m.visible = false));
    shown.field = null;
  }

  function layGrid(g) {
    clearGrid();
    const w = g.width * g.cell, h = g.height * g.cell;
    tiles.map = texture(new Uint8Array(g.width * CELL_PX * g.height * CELL_PX * 4), g.width * CELL_PX, g.height * CELL_PX, NearestFilter);
    tiles.needsUpdate = true;
    tilesMesh = groundPlane(tiles, g.origin, w, h);
    tilesMesh.receiveShadow = true;
    tilesMesh.renderOrder = GROUND_ORDER + 1;
    heatMesh = groundPlane(heat, g.origin, w, h);
    heatMesh.renderOrder = 1;
    heatMesh.visible = false;
    group.add(tilesMesh, heatMesh);
    itemGeometry?.dispose();
    itemGeometry = new BoxGeometry(ITEM_SIZE[0] * g.cell, ITEM_SIZE[1] * g.cell, ITEM_SIZE[2] * g.cell);
  }

  // the cells of the current grid, and a box on each item cell
  function paint(g, cells) {
    tiles.map.image.data.set(paintCells(cells, rec.cellKinds, g.width, g.height));
    tiles.map.needsUpdate = true;
    let n = 0;
    cells.forEach((kind, k) => {
      if (!itemMaterials[kind]) return;
      if (n === items.length) {
        const m = new Mesh(itemGeometry, itemMaterials[kind]);
        m.castShadow = m.receiveShadow = true;
        group.add(m);
        items.push(m);
      }
      const m = items[n++];
      m.geometry = itemGeometry;
      m.material = itemMaterials[kind];
      m.visible = true;
      m.position.set(g.origin[0] + ((k % g.width) + 0.5) * g.cell, g.origin[1] + (Math.floor(k / g.width) + 0.5) * g.cell,
        g.origin[2] + (ITEM_SIZE[2] * g.cell) / 2);
    });
    for (let i = n; i < items.length; ++i) items[i].visible = false;
  }

  function showHeat(f) {
    if (!f) {
      heatMesh.visible = false;
      return;
    }
    const data = paintField(f);
    if (heat.map && heat.map.image.width === f.width && heat.map.image.height === f.height) {
      heat.map.image.data.set(data);
      heat.map.needsUpdate = true;
    } else {
      heat.map?.dispose();
      heat.map = texture(data, f.width, f.height, LinearFilter); // values at cell centres, between them bilinear (eq. 4)
      heat.needsUpdate = true;
    }
    heatMesh.visible = shown.fieldOn;
  }

  // the carried item: a box on top of its part, in the part's frame
  // (an item's size follows the grid's cell; before any grid, a 0.1 m cell's)
  function carry(c) {
    if (carried) {
      carried.parent?.remove(carried);
      carried.geometry.dispose();
      if (!itemMaterials.includes(carried.material)) carried.material.dispose();
      carried = null;
    }
    if (!c) return;
    const cell = shown.grid?.cell ?? 0.1;
    const size = ITEM_SIZE.map((s) => s * cell);
    carried = new Mesh(new BoxGeometry(...size),
      itemMaterials[c.kind] ?? new MeshStandardMaterial({ color: rec.cellKinds[c.kind].color }));
    carried.castShadow = true;
    carried.position.set(0, 0, replay.parts[c.part].size[2] / 2 + size[2] / 2);
    bodies.parts[c.part].add(carried);
  }

  return {
    group,
    setTime(t) {
      rec.props.forEach((d, i) => {
        props[i].visible = t >= d.t;
        if (props[i].visible) props[i].quaternion.setFromAxisAngle(UP, d.spin * (t - d.t)).multiply(propTurns[i]);
      });
      const s = sceneAt(rec, t);
      if (s.grid !== shown.grid) {
        shown.grid = s.grid;
        if (s.grid) layGrid(s.grid);
        else clearGrid();
      }
      if (s.grid && s.cellsKey !== shown.cellsKey) paint(s.grid, cellsAt(rec, t));
      shown.cellsKey = s.cellsKey;
      const f = fieldName === null ? null : s.fields[fieldName] ?? null;
      if (s.grid && f !== shown.field) {
        shown.field = f;
        showHeat(f);
      }
      const key = s.carry ? `${s.carry.part}:${s.carry.kind}` : null;
      if (key !== shown.carry) {
        shown.carry = key;
        carry(s.carry);
      }
    },
    /** Shows or hides the heat map. */
    showField(on) {
      shown.fieldOn = on;
      if (heatMesh) heatMesh.visible = on && shown.field !== null;
    },
    /** The field the heat map shows (its first field's name), or null. */
    fieldName,
    /**
     * What is drawn: the grid's size in cells (or null), the item boxes
     * shown, whether an item is carried, the time of the field shown (or
     * null) and whether the heat map is visible; the points drawn; the
     * props shown.
     */
    state() {
      return {
        grid: shown.grid ? [shown.grid.width, shown.grid.height] : null,
        items: items.filter((m) => m.visible).length,
        carried: carried !== null,
        field: shown.field ? shown.field.t : null,
        heat: heatMesh ? heatMesh.visible : false,
        points: points.length,
        props: props.filter((m) => m.visible).length,
      };
    },
    /** The cells' texture (RGBA bytes), or null before a grid: for tests. */
    get cellsTexture() { return tiles.map?.image.data ?? null; },
    /** The heat map's texture (RGBA bytes), or null: for tests. */
    get fieldTexture() { return heat.map?.image.data ?? null; },
    dispose() {
      carry(null);
      group.traverse((o) => {
        if (o.geometry && o.geometry !== itemGeometry) o.geometry.dispose();
      });
      itemGeometry?.dispose();
      tiles.map?.dispose();
      heat.map?.dispose();
      tiles.dispose();
      heat.dispose();
      itemMaterials.forEach((m) => m?.dispose());
      points.forEach((m) => m.material.dispose());
      props.forEach((m) => m.traverse((o) => o.material?.dispose()));
    },
  };
}
