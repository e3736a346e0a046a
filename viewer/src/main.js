// The page's entry: read the embedded data, check it, start the viewer, and
// publish `window.bestiary` for scripts (video rendering, tests). Any error
// is shown on the page and kept in `window.bestiary.error`.
import { parsePageData } from './data.js';
import { sceneProps } from './props.js';
import { recordOf } from './scene_record.js';
import { createViewer } from './app.js';
import { watchRun } from './watch.js';

function start() {
  const $ = (id) => document.getElementById(id);
  try {
    const data = parsePageData(JSON.parse($('bestiary-data').textContent));
    // props and scene records too, before anything is drawn
    data.replays.forEach((e) => {
      sceneProps(e.replay);
      recordOf(e.replay);
    });
    document.title = data.run ? `${data.run.name}, seed ${data.run.seed} · Bestiary` : `${data.replays[0].label} · Bestiary`;
    const viewer = createViewer({
      canvas: $('view'), stage: $('stage'), hud: $('hud'), cells: $('cells'), info: $('info'), picker: $('picker'),
      run: $('run'), brain: $('brain'), signals: $('signals'), neurons: $('neurons'), player: $('player'),
    }, data);
    window.bestiary = Object.assign(viewer, { ready: true, error: null });
    // served by `bestiary show RUN --watch`: follow the run
    if (data.run?.watch && location.protocol.startsWith('http'))
      watchRun(viewer, data.replays.map((e) => e.label), data.run.watch, window);
  } catch (e) {
    const message = e && e.message ? e.message : String(e);
    $('error').hidden = false;
    $('error').textContent = `Cannot show this page: ${message}`;
    window.bestiary = { ready: true, error: message };
  }
}

start();
