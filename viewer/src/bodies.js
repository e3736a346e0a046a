// Meshes for the creature's parts and the scene's props, posed per moment.
// Each part is its true shape, coloured by its gene (a part its scene record
// names, a catapult's projectile, in the record's colour, whatever its
// gene); joint axes hang on the child part (the replay gives anchor and axes
// in the child's frame), so they move with it. A lessin2015 creature's
// muscles (muscle_view.js) and eyes (eye_view.js) come with it.
import {
  ArrowHelper, EdgesGeometry, Group, LineBasicMaterial, LineSegments, Mesh, MeshBasicMaterial,
  MeshStandardMaterial, SphereGeometry, Vector3,
} from 'three';
import { fadedColor, geneColor } from './palette.js';
import { recordOf } from './scene_record.js';
import { shapeGeometry } from './shapes.js';
import { partPoseAt } from './timeline.js';
import { propPoseAt, sceneProps } from './props.js';
import { createMuscles } from './muscle_view.js';
import { createEyes } from './eye_view.js';

/** Colours of a joint's axes: first degree of freedom red, second green. */
const AXIS_COLORS = [0xd8342c, 0x2f9e44];
/** Glow of a highlighted part (its material's emissive colour), the others faded (palette.js). */
export const HIGHLIGHT_GLOW = 0x2a2a2a;
/** Joint types that use axis2 as well as axis1. */
const TWO_AXES = new Set(['universal', 'spherical']);

/** A part's or prop's mesh: its true shape in `color`, casting and taking shadows. */
export function solid(shape, size, color, opacity = 1) {
  const mesh = new Mesh(
    shapeGeometry(shape, size),
    new MeshStandardMaterial({
      color, roughness: 0.6, metalness: 0.05, transparent: opacity < 1, opacity,
    }),
  );
  mesh.castShadow = true;
  mesh.receiveShadow = true;
  // boxes get dark edges: faces of one colour read as one blob otherwise
  if (shape === 'box') {
    const edges = new LineSegments(
      new EdgesGeometry(mesh.geometry),
      new LineBasicMaterial({ color: 0x1d232a, transparent: true, opacity: 0.35 }),
    );
    mesh.add(edges);
  }
  return mesh;
}

function setPose(obj, p) {
  obj.position.set(p[0], p[1], p[2]);
  obj.quaternion.set(p[4], p[5], p[6], p[3]); // replay: w first; three: w last
}

// a joint's marker: a small ball at the anchor and one arrow per axis,
// drawn over the parts so they show through
function jointMarker(joint, partSize) {
  const g = new Group();
  const len = Math.min(Math.max(Math.max(...partSize) * 0.7, 0.08), 0.5);
  const ball = new Mesh(
    new SphereGeometry(len * 0.1, 12, 8),
    new MeshBasicMaterial({ color: 0x202428, depthTest: false }),
  );
  g.add(ball);
  const axes = joint.type === 'fixed' ? [] : TWO_AXES.has(joint.type) ? [joint.axis1, joint.axis2] : [joint.axis1];
  axes.forEach((a, k) => {
    const dir = new Vector3(...a);
    if (dir.lengthSq() < 1e-12) return;
    const arrow = new ArrowHelper(dir.normalize(), new Vector3(), len, AXIS_COLORS[k], len * 0.25, len * 0.12);
    arrow.traverse((o) => {
      if (o.material) o.material.depthTest = false;
    });
    g.add(arrow);
  });
  g.position.set(...joint.anchor);
  g.traverse((o) => (o.renderOrder = 10));
  return g;
}

/**
 * The creature and props of a replay as one group. `setTime(t)` poses every
 * mesh (and sets each muscle's and eye's activity); `showJoints(on)` toggles
 * the joint markers; `highlight(parts)` makes those parts (indices; null or
 * [] for none) glow and fades the others; `muscles` and `eyes` are muscle_view.js's and
 * eye_view.js's views; `dispose()` frees GPU data.
 */
export function createBodies(replay) {
  const group = new Group();
  // parts, each with the markers of the joints that attach it to its parent
  // a part the scene record names (a catapult's projectile) in its colour
  const named = new Map(recordOf(replay).parts.map((p) => [p.part, p.color]));
  const colors = replay.parts.map((p, k) => named.get(k) ?? geneColor(p.gene, p.mirrored));
  const parts = replay.parts.map((p, k) => {
    const color = colors[k];
    const mesh = solid(p.shape, p.size, color);
    group.add(mesh);
    return mesh;
  });
  const markers = replay.joints.map((j) => {
    const m = jointMarker(j, replay.parts[j.child].size);
    m.visible = false;
    parts[j.child].add(m);
    return m;
  });
  // muscles between their parts, eyes on theirs
  const muscles = createMuscles(replay);
  group.add(muscles.object);
  const eyes = createEyes(replay, parts);
  // props, from their descriptions
  const props = sceneProps(replay);
  const propMeshes = props.map((p) => {
    const mesh = solid(p.shape, p.size, p.color, p.opacity);
    group.add(mesh);
    return mesh;
  });

  return {
    group,
    parts,
    props: propMeshes,
    muscles,
    eyes,
    setTime(t) {
      parts.forEach((m, k) => setPose(m, partPoseAt(replay.frames, k, t)));
      muscles.setTime(t);
      eyes.setTime(t);
      propMeshes.forEach((m, i) => setPose(m, propPoseAt(replay, props[i], i, t)));
    },
    showJoints(on) {
      markers.forEach((m) => (m.visible = on));
    },
    highlight(list) {
      const some = list !== null && list !== undefined && list.length > 0;
      parts.forEach((m, k) => {
        m.material.color.setHex(some ? fadedColor(colors[k]) : colors[k]);
        m.material.emissive.setHex(0x000000);
      });
      if (!some) return;
      for (const k of list) {
        if (!parts[k]) continue;
        parts[k].material.color.setHex(colors[k]);
        parts[k].material.emissive.setHex(HIGHLIGHT_GLOW);
      }
    },
    dispose() {
      group.traverse((o) => {
        o.geometry?.dispose();
        o.material?.dispose();
      });
    },
  };
}
