// `bestiary show RUN --watch`: the page comes from bestiary's server on
// 127.0.0.1, which answers /stamp with where the run stands. Every few
// seconds the page asks; when the run has stored more, the page reloads (the
// server then gives the page made since) and keeps what was being watched:
// the creature (by its label), the moment, playing or not, the camera.
const KEY = 'bestiary-watch';

/** What to keep across a reload, from the viewer's state and its entries' labels. */
export function keptState(viewer, labels) {
  const st = viewer.state();
  return { label: labels[st.replayIndex], t: st.t, playing: st.playing, camera: st.camera };
}

/** Puts back what keptState kept, where it still applies (the creature may be gone). */
export function restoreState(viewer, labels, kept) {
  if (!kept) return;
  const i = labels.indexOf(kept.label);
  if (i >= 0 && i !== viewer.replayIndex) viewer.select(i);
  if (typeof kept.camera === 'string') viewer.setCamera(kept.camera);
  if (typeof kept.t === 'number') viewer.renderFrame(Math.min(kept.t, viewer.duration));
  if (kept.playing) viewer.play();
}

/**
 * Follows the run: restores what the last reload kept, then asks `stamp`
 * every `watch.every` seconds (through `win.fetch`) and reloads when it is
 * no longer `watch.stamp`. Returns a function that stops it.
 */
export function watchRun(viewer, labels, watch, win) {
  try {
    restoreState(viewer, labels, JSON.parse(win.sessionStorage.getItem(KEY) ?? 'null'));
  } catch {
    // a stored state we cannot read: start afresh
  }
  win.sessionStorage.removeItem(KEY);
  let busy = false;
  const timer = win.setInterval(async () => {
    if (busy) return;
    busy = true;
    try {
      const r = await win.fetch('stamp', { cache: 'no-store' });
      const now = r.ok ? (await r.text()).trim() : watch.stamp;
      if (now !== watch.stamp) {
        win.sessionStorage.setItem(KEY, JSON.stringify(keptState(viewer, labels)));
        win.location.reload();
      }
    } catch {
      // the server has stopped (the run ended, or Ctrl-C): the page stays as it is
    } finally {
      busy = false;
    }
  }, watch.every * 1000);
  return () => win.clearInterval(timer);
}
