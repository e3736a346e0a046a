// Two cameras in one: "follow" keeps the creature in view as it travels (the
// user can still orbit and zoom around it), "orbit" stays put over the whole
// path. Both use three's OrbitControls with z up.
import { PerspectiveCamera, Vector3 } from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { followTarget, pathBounds, viewDirection } from './follow.js';

/** A camera rig on `canvas`, framed for a creature of `radius` travelling `frames`. */
export function createCameraRig(canvas) {
  const camera = new PerspectiveCamera(40, 1, 0.02, 500);
  camera.up.set(0, 0, 1); // before the controls, which read it once
  const controls = new OrbitControls(camera, canvas);
  controls.enableDamping = false;
  controls.maxPolarAngle = Math.PI * 0.495; // stay above the ground

  let frames = null, radius = 1, mode = 'follow';
  const viewDir = new Vector3(0, -1, 0), overDir = new Vector3(0, -1, 0);

  // camera at `dist` from `target` along `dir`
  function place(target, dist, dir = viewDir) {
    controls.target.set(...target);
    camera.position.copy(controls.target).addScaledVector(dir, dist);
    controls.update();
  }
  const followDistance = () => Math.max(1.2, radius * 5);

  const rig = {
    camera, controls,
    get mode() { return mode; },
    /** Frames a new replay; the view starts at t = 0. */
    reset(newFrames, newRadius) {
      frames = newFrames;
      radius = newRadius;
      viewDir.set(...viewDirection(frames));
      overDir.set(...viewDirection(frames, 0.3, 0.9));
      rig.setMode(mode);
    },
    /** "follow" or "orbit"; resets the view of that mode. */
    setMode(m) {
      mode = m;
      if (!frames) return;
      if (mode === 'follow') {
        place(followTarget(frames, 0), followDistance());
      } else {
        // over the whole path, seen from the same side
        const b = pathBounds(frames);
        const z = followTarget(frames, 0)[2];
        place([b.centre[0], b.centre[1], z], Math.max(followDistance(), b.span * 1.4 + radius * 3), overDir);
      }
    },
    /** Moves a follow camera with the creature to time t, keeping the user's angle and zoom. */
    track(t) {
      if (mode !== 'follow' || !frames) return;
      const target = new Vector3(...followTarget(frames, t));
      camera.position.add(target.clone().sub(controls.target));
      controls.target.copy(target);
      controls.update();
    },
    /** The follow view of time t exactly as a fresh page shows it (for video frames). */
    standardFollow(t) {
      place(followTarget(frames, t), followDistance());
    },
    resize(w, h) {
      camera.aspect = w / Math.max(h, 1);
      camera.updateProjectionMatrix();
    },
  };
  return rig;
}
