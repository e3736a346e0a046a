// Which part of the creature is under the pointer in the scene. The pointer's
// moves are only noted; the viewer's loop asks `update()` once per animation
// frame, which casts one ray when the pointer moved (one Raycaster, one list
// of hits, reused) and reports a change of part. Leaving the scene is
// reported at once.
import { Raycaster, Vector2 } from 'three';

/**
 * Hovering over `canvas`: `camera()` and `parts()` (the part meshes, in part
 * order) give what to look at; `onChange(part)` is told the part under the
 * pointer when it changes (-1: none). Returns {update(), reset(), dispose()}.
 */
export function createPartHover(canvas, camera, parts, onChange) {
  const ray = new Raycaster();
  const ndc = new Vector2();
  const hits = [];
  let moved = false, inside = false, part = -1, x = 0, y = 0;
  const move = (ev) => {
    x = ev.clientX;
    y = ev.clientY;
    inside = true;
    moved = true;
  };
  const set = (p) => {
    if (p === part) return;
    part = p;
    onChange(p);
  };
  // leaving is told at once: the pointer may be over a gene of the panel
  // before the next frame, and that gene's highlight must stay
  const leave = () => {
    inside = false;
    moved = false;
    set(-1);
  };
  canvas.addEventListener('pointermove', move);
  canvas.addEventListener('pointerleave', leave);
  return {
    update() {
      if (!moved) return;
      moved = false;
      if (!inside) return set(-1);
      const box = canvas.getBoundingClientRect();
      if (box.width <= 0 || box.height <= 0) return set(-1);
      ndc.set(((x - box.left) / box.width) * 2 - 1, -((y - box.top) / box.height) * 2 + 1);
      ray.setFromCamera(ndc, camera());
      const meshes = parts();
      hits.length = 0;
      ray.intersectObjects(meshes, false, hits);
      set(hits.length ? meshes.indexOf(hits[0].object) : -1);
    },
    /** Forgets the part under the pointer (a new replay), telling no one. */
    reset() {
      part = -1;
      moved = inside;
    },
    dispose() {
      canvas.removeEventListener('pointermove', move);
      canvas.removeEventListener('pointerleave', leave);
    },
  };
}
