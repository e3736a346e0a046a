// Looks at a viewer page as a person would, for the end-to-end tests
// (tests/viewer): opens it in headless Chromium, draws given moments, saves
// screenshots and prints what it saw as one JSON object on stdout.
//
//   node tools/inspect.mjs --html PAGE --shots DIR [--name NAME] [--times 1,5]
//                          [--width 1280] [--height 720] [--run]
//
// It reports every URL the page requested, page errors, per moment the root
// part's and centre of mass's positions and the canvas's colours, the share
// of pixels that change between the first and last moment under a still
// (orbit) camera, and with
// --run what the run panel shows and whether choosing a generation switches
// the creature.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { openViewer } from './browser.mjs';

function parseArgs(argv) {
  const a = { times: '1,5', width: '1280', height: '720', name: 'page', run: false };
  for (let i = 0; i < argv.length; ++i) {
    const k = argv[i].slice(2);
    if (k === 'run') a.run = true;
    else a[k] = argv[++i];
  }
  a.times = a.times.split(',').map(Number);
  return a;
}

// Colours of the 3D canvas, read in the page: distinct colours (4 bits per
// channel) and the share of strongly coloured pixels (the parts are; sky,
// ground and grid are grey). The pixels stay in the page as `previous`, and
// the share that changed since the last call is returned too.
function canvasColours() {
  const c = document.getElementById('view');
  const copy = document.createElement('canvas');
  copy.width = c.width;
  copy.height = c.height;
  const g = copy.getContext('2d');
  g.drawImage(c, 0, 0);
  const px = g.getImageData(0, 0, copy.width, copy.height).data;
  const before = window.__inspectPrevious;
  const seen = new Set();
  let saturated = 0, changed = 0;
  for (let i = 0; i < px.length; i += 4) {
    const [r, gr, b] = [px[i], px[i + 1], px[i + 2]];
    seen.add(((r >> 4) << 8) | ((gr >> 4) << 4) | (b >> 4));
    if (Math.max(r, gr, b) - Math.min(r, gr, b) > 60) ++saturated;
    if (before && Math.abs(r - before[i]) + Math.abs(gr - before[i + 1]) + Math.abs(b - before[i + 2]) > 24) ++changed;
  }
  window.__inspectPrevious = px;
  const n = px.length / 4;
  return { width: copy.width, height: copy.height, distinct: seen.size, saturated: saturated / n, changed: before ? changed / n : null };
}

async function main() {
  const a = parseArgs(process.argv.slice(2));
  mkdirSync(a.shots, { recursive: true });
  const { browser, page, requests, errors } = await openViewer(a.html, { width: Number(a.width), height: Number(a.height) });
  try {
    const out = { requests, errors, replayCount: await page.evaluate(() => window.bestiary.replayCount), moments: [] };
    // the moments, in the follow view, with screenshots of the whole page
    for (const t of a.times) {
      const state = await page.evaluate((t) => window.bestiary.renderFrame(t), t);
      const colours = await page.evaluate(canvasColours);
      const shot = join(a.shots, `${a.name}_t${t}.png`);
      await page.screenshot({ path: shot });
      out.moments.push({ t, state, colours, screenshot: shot });
    }
    // the same moments under a still camera: the creature's pixels move
    await page.evaluate(() => window.bestiary.setCamera('orbit'));
    for (const t of [a.times[0], a.times[a.times.length - 1]]) {
      await page.evaluate((t) => window.bestiary.renderFrame(t), t);
      out.orbitChanged = (await page.evaluate(canvasColours)).changed;
    }
    await page.evaluate(() => window.bestiary.setCamera('follow'));
    // the panels
    out.sparklines = await page.locator('#neurons .spark').count();
    out.player = await page.locator('#player button, #player input, #player select').count();
    if (a.run) out.run = await inspectRun(page, a);
    console.log(JSON.stringify(out));
  } finally {
    await browser.close();
  }
}

// the run panel: curves drawn, generations offered, choosing one switches the creature
async function inspectRun(page, a) {
  if (await page.locator('#run').isHidden()) return { shown: false };
  const curves = await page.$$eval('#run svg path.curve', (ps) => ps.map((p) => ({ cls: p.getAttribute('class'), points: (p.getAttribute('d').match(/[ML]/g) || []).length })));
  const options = await page.$$eval('#generation option', (os) => os.map((o) => ({ value: o.value, text: o.textContent })));
  const r = { shown: true, curves, options, before: await page.evaluate(() => window.bestiary.replayIndex) };
  // choose the last generation from the list
  await page.selectOption('#generation', options[options.length - 1].value);
  r.afterSelect = await page.evaluate(() => window.bestiary.replayIndex);
  r.label = await page.locator('#info h1').textContent();
  await page.screenshot({ path: join(a.shots, `${a.name}_run.png`) });
  // click the chart's left edge: the first generation
  const box = await page.locator('#run svg').boundingBox();
  await page.mouse.click(box.x + 40, box.y + box.height / 2);
  r.afterClick = await page.evaluate(() => window.bestiary.replayIndex);
  return r;
}

main().catch((e) => {
  process.stderr.write(`${e.message.split('\n')[0]}\n`);
  process.exit(1);
});
