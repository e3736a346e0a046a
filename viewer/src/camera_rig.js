// Cameras in one: "follow" keeps the creature in view as it travels (the
// user can still orbit and zoom around it), "projectile" does the same for a
// catapult's projectile, "orbit" stays put over the whole path (the
// projectile's too). All use three's OrbitControls with z up. A scene with
// lights or targets (interest.js) has them in view too: the orbit frames
// them with the path, the follow views turn and move back to show the
// nearest (follow.js, followView); a scene without them is framed as it
// always was.
import { PerspectiveCamera, Vector3 } from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import {
  distanceToShowAll, followTarget, followView, nextMode, partTarget, pathBounds, showHalfAngle, viewDirection, viewScale,
} from './follow.js';
import { firstShown, shownBy } from './interest.js';

/** A camera rig on `canvas`, framed for a creature of `radius` travelling `frames`. */
export function createCameraRig(canvas) {
  const camera = new PerspectiveCamera(40, 1, 0.02, 500);
  camera.up.set(0, 0, 1); // before the controls, which read it once
  const controls = new OrbitControls(camera, canvas);
  controls.enableDamping = false;
  controls.maxPolarAngle = Math.PI * 0.495; // stay above the ground

  let frames = null, radius = 1, mode = 'follow', projectile = -1, interest = [];
  const viewDir = new Vector3(0, -1, 0), overDir = new Vector3(0, -1, 0);
  // the present follow mode's standard view: viewDir and followDistance(),
  // turned and moved back to show the scene's nearest light or target
  const followDir = new Vector3(0, -1, 0);
  let followDist = 1.2;

  // camera at `dist` from `target` along `dir`
  function place(target, dist, dir = followDir) {
    controls.target.set(...target);
    camera.position.copy(controls.target).addScaledVector(dir, dist);
    controls.update();
  }
  const followDistance = () => Math.max(1.2, radius * 5);
  const end = () => frames[frames.length - 1].t;

  // The follow view, one for the whole replay (video frames glide with the
  // creature, never jump): chosen at the moment the scene first shows a
  // light or target (t = 0 for a light; fight-or-flight's targets once they
  // appear), for the nearest of those shown then.
  function frameFollow() {
    const first = firstShown(interest, end());
    const v = first
      ? followView(rig.targetAt(first.t), viewDir.toArray(), followDistance(), first.shown, showHalfAngle(camera.fov))
      : { dir: viewDir.toArray(), dist: followDistance() };
    followDir.set(...v.dir);
    followDist = v.dist;
  }

  const rig = {
    camera, controls,
    get mode() { return mode; },
    /** The mode the camera button goes to next. */
    get next() { return nextMode(mode, projectile >= 0); },
    /**
     * Frames a new replay (`projectile`: part index of a catapult's
     * projectile, or -1; `newInterest`: its scene's points of interest,
     * interest.js); the view starts at t = 0.
     */
    reset(newFrames, newRadius, newProjectile = -1, newInterest = []) {
      frames = newFrames;
      radius = newRadius;
      projectile = newProjectile;
      interest = newInterest;
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
        frameFollow();
        place(rig.targetAt(0), followDist);
      } else {
        // over the whole path and the lights and targets it ever shows, seen
        // from the same side; far enough back that each of those, and each
        // corner of the path's bounds (with the creature's radius), lies in
        // the cone followView keeps a light in
        const shown = shownBy(interest, end());
        const b = pathBounds(frames, projectile, shown);
        const z = followTarget(frames, 0)[2];
        const centre = [b.centre[0], b.centre[1], z];
        let dist = Math.max(followDistance(), b.span * 1.4 + radius * 3);
        if (shown.length) {
          const { min, max } = pathBounds(frames, projectile);
          const corners = [[min[0], min[1]], [min[0], max[1]], [max[0], min[1]], [max[0], max[1]]]
            .map(([x, y]) => ({ p: [x, y, z], radius }));
          dist = distanceToShowAll(centre, overDir.toArray(), dist, [...shown, ...corners], showHalfAngle(camera.fov));
        }
        place(centre, dist, overDir);
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
      place(rig.targetAt(t), followDist);
    },
    resize(w, h) {
      camera.aspect = w / Math.max(h, 1);
      camera.updateProjectionMatrix();
    },
  };
  return rig;
}
