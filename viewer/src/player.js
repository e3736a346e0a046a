// The player bar under the scene: play/pause, scrub (with the span the task
// scored and a catapult's release marked on it), time, speed, camera and
// what to draw. It holds no
// state of its own: the viewer tells it what to show, and it reports what
// the user did.
import { el } from './dom.js';
import { seconds } from './format.js';

/** Playback speeds offered. */
export const SPEEDS = [0.25, 0.5, 1, 2, 4];

/** What the camera button says in each mode. */
const CAMERA_TEXT = { follow: 'camera: follow', projectile: 'camera: projectile', orbit: 'camera: orbit' };

/**
 * Where a moment sits on the scrub bar: its time over the duration, in [0, 1]
 * (0 for a replay of no length).
 */
export function scrubFraction(t, duration) {
  return duration > 0 ? Math.min(Math.max(t / duration, 0), 1) : 0;
}

/**
 * The bar in `container`. `on` has callbacks: togglePlay(), seek(t),
 * speed(x), camera(), joints(on), trail(on), flight(on), field(on).
 */
export function createPlayer(container, on) {
  const play = el('button', { id: 'play', title: 'play / pause (space)', onclick: () => on.togglePlay() });
  const scrub = el('input', { id: 'scrub', type: 'range', min: '0', max: '1', step: 'any', value: '0', 'aria-label': 'time' });
  scrub.addEventListener('input', () => on.seek(Number(scrub.value)));
  // the release's mark rides over the bar, where the thumb's centre is at that time
  const mark = el('div', { id: 'release-mark', class: 'release-mark', hidden: true });
  // the span the task scored, a band under the bar
  const span = el('div', { id: 'scored-span', class: 'scored-span', hidden: true });
  const scrubBox = el('div', { class: 'scrub-box' }, span, scrub, mark);
  const time = el('span', { id: 'time', class: 'time' });
  const speed = el('select', { id: 'speed', title: 'speed', 'aria-label': 'speed' },
    ...SPEEDS.map((s) => el('option', { value: String(s), selected: s === 1 }, `${s}x`)));
  speed.addEventListener('change', () => on.speed(Number(speed.value)));
  const camera = el('button', { id: 'camera', title: 'camera: follow the creature (or a catapult\'s projectile) or orbit over its path (c)', onclick: () => on.camera() });
  const check = (id, label, title, checked, cb) => {
    const box = el('input', { id, type: 'checkbox', checked });
    box.addEventListener('change', () => cb(box.checked));
    return { box, label: el('label', { class: 'check', title }, box, label) };
  };
  const joints = check('joints', 'joint axes', 'joint anchors and axes: red axis 1, green axis 2 (j)', false, on.joints);
  const trail = check('trail', 'trail', 'path of the centre of mass (t)', true, on.trail);
  const flight = check('flight', 'flight', 'path of the projectile since its release (f)', true, on.flight);
  flight.label.hidden = true;
  const field = check('field', 'heat map', 'the recorded field over the grid as a heat map (h)', true, on.field);
  field.label.hidden = true;
  container.replaceChildren(play, scrubBox, time, speed, camera, joints.label, trail.label, flight.label, field.label);

  return {
    /** Shows the present state: {t, duration, playing, speed, mode}. */
    show(s) {
      play.textContent = s.playing ? '❚❚' : '▶';
      scrub.max = String(s.duration);
      if (document.activeElement !== scrub) scrub.value = String(s.t);
      time.textContent = `${seconds(s.t)} / ${seconds(s.duration)}`;
      camera.textContent = CAMERA_TEXT[s.mode] ?? `camera: ${s.mode}`;
    },
    setJoints(v) { joints.box.checked = v; },
    setTrail(v) { trail.box.checked = v; },
    setFlight(v) { flight.box.checked = v; },
    /**
     * A recorded field (`name`, e.g. "landscape", or null for none): the heat
     * map's toggle, named for it, shown only then.
     */
    setField(name) {
      field.label.hidden = name === null;
      if (name !== null) field.label.lastChild.textContent = `heat map (${name})`;
    },
    setFieldOn(v) { field.box.checked = v; },
    /**
     * A catapult's bar (`throwing`): the flight toggle, and the release at
     * time `release` (s, or null when it never happened) marked on the scrub
     * bar of a replay `duration` long. Not throwing: neither.
     */
    /**
     * The span the task scored ({from, to} in s, or null: none marked),
     * shaded on the scrub bar of a replay `duration` long.
     */
    setSpan(scored, duration) {
      span.hidden = scored === null;
      if (scored === null) return;
      span.style.setProperty('--from', String(scrubFraction(scored.from, duration)));
      span.style.setProperty('--to', String(scrubFraction(scored.to, duration)));
      span.title = `scored from ${seconds(scored.from)} to ${seconds(scored.to)}`;
    },
    setThrow(throwing, release, duration) {
      flight.label.hidden = !throwing;
      mark.hidden = !throwing || release === null || release > duration;
      if (!mark.hidden) {
        mark.style.setProperty('--at', String(scrubFraction(release, duration)));
        mark.title = `released at ${seconds(release)}`;
      }
      scrub.title = throwing ? (release === null ? 'not released' : `released at ${seconds(release)}`) : '';
    },
  };
}
