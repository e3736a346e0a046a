// The player bar under the scene: play/pause, scrub, time, speed, camera and
// what to draw. It holds no state of its own: the viewer tells it what to
// show, and it reports what the user did.
import { el } from './dom.js';
import { seconds } from './format.js';

/** Playback speeds offered. */
export const SPEEDS = [0.25, 0.5, 1, 2, 4];

/**
 * The bar in `container`. `on` has callbacks: togglePlay(), seek(t),
 * speed(x), camera(mode), joints(on), trail(on).
 */
export function createPlayer(container, on) {
  const play = el('button', { id: 'play', title: 'play / pause (space)', onclick: () => on.togglePlay() });
  const scrub = el('input', { id: 'scrub', type: 'range', min: '0', max: '1', step: 'any', value: '0', 'aria-label': 'time' });
  scrub.addEventListener('input', () => on.seek(Number(scrub.value)));
  const time = el('span', { id: 'time', class: 'time' });
  const speed = el('select', { id: 'speed', title: 'speed', 'aria-label': 'speed' },
    ...SPEEDS.map((s) => el('option', { value: String(s), selected: s === 1 }, `${s}x`)));
  speed.addEventListener('change', () => on.speed(Number(speed.value)));
  const camera = el('button', { id: 'camera', title: 'camera: follow the creature or orbit over its path (c)', onclick: () => on.camera() });
  const check = (id, label, title, checked, cb) => {
    const box = el('input', { id, type: 'checkbox', checked });
    box.addEventListener('change', () => cb(box.checked));
    return { box, label: el('label', { class: 'check', title }, box, label) };
  };
  const joints = check('joints', 'joint axes', 'joint anchors and axes: red axis 1, green axis 2 (j)', false, on.joints);
  const trail = check('trail', 'trail', 'path of the centre of mass (t)', true, on.trail);
  container.replaceChildren(play, scrub, time, speed, camera, joints.label, trail.label);

  return {
    /** Shows the present state: {t, duration, playing, speed, mode}. */
    show(s) {
      play.textContent = s.playing ? '❚❚' : '▶';
      scrub.max = String(s.duration);
      if (document.activeElement !== scrub) scrub.value = String(s.t);
      time.textContent = `${seconds(s.t)} / ${seconds(s.duration)}`;
      camera.textContent = s.mode === 'follow' ? 'camera: follow' : 'camera: orbit';
    },
    setJoints(v) { joints.box.checked = v; },
    setTrail(v) { trail.box.checked = v; },
  };
}
