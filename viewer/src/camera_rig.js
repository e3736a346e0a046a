// Cameras in one: "follow" keeps the creature in view as it travels (the
// user can still orbit and zoom around it), "projectile" does the same for a
// catapult's projectile, "orbit" stays put over the whole path (the
// projectile's too). All use three's OrbitControls with z up.
import { PerspectiveCamera, Vector3 } from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { followTarget, nextMode, partTarget, pathBounds, viewDirection, viewScale } from './follow.js';

/** A camera rig on `canvas`, framed for a creature of `radius` travelling `frames`. */
export function createCameraRig(canvas) {
  const camera = new PerspectiveCamera(40, 1, 0.02, 500);
  camera.up.set(0, 0, 1); // before the controls, which read it once
  const controls = new OrbitControls(camera, canvas);
  controls.enableDamping = false;
  controls.maxPolarAngle = Math.PI * 0.495; // stay above the ground

  let frames = null, radius = 1, mode = 'follow', projectile = -1;
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
    /** The mode the camera button goes to next. */
    get next() { return nextMode(mode, projectile >= 0); },
    /**
     * Frames a new replay (`projectile`: part index of a catapult's
     * projectile, or -1); the view starts at t = 0.
     */
    reset(newFrames, newRadius, newProjectile = -1) {
      frames = newFrames;
      radius = newRadius;
      projectile = newProjectile;
      // the depth range grows with a large creature (viewScale)
      const k = viewScale(radius);
      camera.near = 0.02 * k;
      camera.far = 500 * k;
      camera.updateProjectionMatrix();
      // seen across the way it goes: the creature's, or a catapult's throw
      viewDir.set(...viewDirection(frames, 0.5, 0.42, projectile));
      overDir.set(...viewDirection(frames, 0.3, 0.9, projectile));
      rig.setMode(mode);
    },
    /** Where a following camera looks at time t (the creature's, or the projectile's). */
    targetAt(t) {
      return mode === 'projectile' ? partTarget(frames, projectile, t) : followTarget(frames, t);
    },
    /**
     * "follow", "projectile" (a creature without one follows its centre of
     * mass) or "orbit"; resets the view of that mode.
     */
    setMode(m) {
      mode = m === 'projectile' && projectile < 0 ? 'follow' : m;
      if (!frames) return;
      if (mode !== 'orbit') {
        place(rig.targetAt(0), followDistance());
      } else {
        // over the whole path, seen from the same side
        const b = pathBounds(frames, projectile);
        const z = followTarget(frames, 0)[2];
        place([b.centre[0], b.centre[1], z], Math.max(followDistance(), b.span * 1.4 + radius * 3), overDir);
      }
    },
    /** Moves a follow camera with the creature to time t, keeping the user's angle and zoom. */
    track(t) {
      if (mode === 'orbit' || !frames) return;
      const target = new Vector3(...rig.targetAt(t));
      camera.position.add(target.clone().sub(controls.target));
      controls.target.copy(target);
      controls.update();
    },
    /** The follow view of time t exactly as a fresh page shows it (for video frames). */
    standardFollow(t) {
      place(rig.targetAt(t), followDistance());
    },
    resize(w, h) {
      camera.aspect = w / Math.max(h, 1);
      camera.updateProjectionMatrix();
    },
  };
  return rig;
}
