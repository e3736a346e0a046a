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
// (orbit) camera, what the signals panel shows (each group's traces with
// their range text and badges, whether a group closes and opens, whether the
// plots follow a resize), the elements that stick out of their panel, a
// recorded grid's legend, the
// creature's development notes and warnings, and
// with --run what the run page shows and what choosing a creature (from the
// lineage, the generation list or the chart) does.
import { mkdirSync, readFileSync } from 'node:fs';
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
    out.overflow = await page.evaluate(overflowing);
    // a recorded grid's legend, when shown
    out.cells = await page.evaluate(() => {
      const c = document.getElementById('cells');
      return c && !c.hidden ? [...c.querySelectorAll('.cell-key')].map((k) => k.textContent) : null;
    });
    // the creature's facts: development's notes (muted) and warnings (red)
    out.info = await page.evaluate(() => ({
      notes: [...document.querySelectorAll('#info .note')].map((p) => ({ text: p.textContent, color: getComputedStyle(p).color })),
      warnings: [...document.querySelectorAll('#info .warn')].map((p) => p.textContent),
    }));
    out.signals = await inspectSignals(page, a);
    if (a.run) {
      out.run = await inspectRun(page, a);
      out.run.overflow = await page.evaluate(overflowing); // with the panels as the choices left them
    }
    console.log(JSON.stringify(out));
  } finally {
    await browser.close();
  }
}

// Elements drawn (partly) outside their panel (side panel, player bar, the
// scene's line of text, its scale and a grid's legend): side-ways for the side panel, which
// scrolls, either way for the others; and a panel outside the window. Each
// as "panel: tag.class 'text'". A run's syllabus graph scrolls side-ways in
// its box when the panel is too narrow for it at a readable size: the box
// must fit, what it clips is not drawn outside.
function overflowing() {
  const out = [];
  for (const id of ['side', 'player', 'hud', 'scale', 'cells']) {
    const panel = document.getElementById(id);
    if (!panel || panel.offsetParent === null) continue;
    const p = panel.getBoundingClientRect();
    if (p.left < -0.5 || p.right > window.innerWidth + 0.5 || p.bottom > window.innerHeight + 0.5)
      out.push(`${id}: outside the window`);
    for (const e of panel.querySelectorAll('*')) {
      if (e.getClientRects().length === 0) continue; // not drawn (a closed group's)
      if (e.parentElement.closest('.syllabus-box')) continue;
      const r = e.getBoundingClientRect();
      if (r.width === 0 && r.height === 0) continue;
      const out_x = r.left < p.left - 0.5 || r.right > p.right + 0.5;
      const out_y = id !== 'side' && (r.top < p.top - 0.5 || r.bottom > p.bottom + 0.5);
      if (out_x || out_y) out.push(`${id}: ${e.tagName.toLowerCase()}.${e.className} '${(e.textContent || '').slice(0, 30)}'`);
    }
  }
  return out.slice(0, 20);
}

// the signals panel: per group its traces (label, range text, badges), the
// summary's badge; closing a group hides its traces and opening shows them;
// after a resize every plot is as wide as its box
async function inspectSignals(page, a) {
  const read = () => page.evaluate(() => [...document.querySelectorAll('#signals details.group')].map((g) => ({
    key: g.dataset.group,
    title: g.querySelector('summary .group-title').textContent,
    badge: g.querySelector('summary .badge')?.textContent ?? null,
    traces: [...g.querySelectorAll('.spark')].map((s) => ({
      label: s.querySelector('.spark-label').textContent,
      range: s.querySelector('.spark-range').textContent,
      badges: [...s.querySelectorAll('.spark-foot .badge')].map((b) => b.textContent),
      stops: s.querySelector('.spark-stops')?.textContent ?? null,
      cursor: s.querySelector('.spark-cursor').style.left,
    })),
    note: g.querySelector(':scope > .muted')?.textContent ?? null,
  })));
  const groups = await read();
  // close and open the first group with traces
  const first = groups.find((g) => g.traces.length > 0);
  let collapse = null;
  if (first) {
    const summary = page.locator(`#signals details[data-group="${first.key}"] > summary`);
    const visible = () => page.locator(`#signals details[data-group="${first.key}"] .spark`).first().isVisible();
    await summary.click();
    const closed = !(await visible());
    await summary.click();
    collapse = { group: first.key, closed, reopened: await visible() };
  }
  // plots as wide as their boxes, before and after the window narrows
  const widths = () => page.evaluate(() => {
    const cs = [...document.querySelectorAll('#side canvas.spark-plot')].filter((c) => c.getClientRects().length);
    return { boxes: cs.map((c) => c.clientWidth), drawn: cs.map((c) => c.width / (window.devicePixelRatio || 1)) };
  });
  const before = await widths();
  await page.setViewportSize({ width: Math.round(Number(a.width) * 0.8), height: Number(a.height) });
  await page.waitForTimeout(300);
  const after = await widths();
  await page.setViewportSize({ width: Number(a.width), height: Number(a.height) });
  await page.waitForTimeout(300);
  const same = (w) => w.boxes.length > 0 && w.boxes.every((b, i) => Math.abs(b - w.drawn[i]) <= 1);
  return {
    groups, collapse,
    resize: { width: before.boxes[0] ?? 0, narrowed: after.boxes[0] ?? 0, fits: same(before), fitsAfter: same(after) },
  };
}

// the run page: the run's facts, the chart (its size, title, axis labels,
// the colours of its curves and of the shown creature's marker), the table
// of generations, the generation list and the lineage; then playing each
// playable ancestor in the lineage, choosing the first generation's best,
// clicking the chart's right end, and downloading the shown genome; for a
// run of stages, its syllabus graph, then per begun stage picking it there
// and clicking the chart's right end
async function inspectRun(page, a) {
  if (await page.locator('#run').isHidden()) return { shown: false };
  const now = () => page.evaluate(() => {
    const s = window.bestiary.state();
    return {
      replayIndex: s.replayIndex, individual: s.individual, generation: s.generation, anchor: s.anchor,
      fitness: s.fitness, storedFitness: s.storedFitness, evaluations: s.evaluations,
      label: document.querySelector('#info h1').textContent,
    };
  });
  const lineage = () => page.$$eval('#picker .lineage-item', (bs) => bs.map((b) => ({
    id: Number(b.dataset.id), text: b.textContent, playable: !b.disabled, current: b.getAttribute('aria-current') === 'true',
  })));
  const r = await page.evaluate(() => {
    const chart = document.querySelector('#run svg.curves');
    const stroke = (e) => (e ? getComputedStyle(e).stroke : null);
    const cells = (tr) => [...tr.cells].map((c) => c.textContent);
    return {
      shown: true,
      facts: Object.fromEntries([...document.querySelectorAll('#run .run-facts dt')].map((dt) => [dt.textContent, dt.nextElementSibling.textContent])),
      notes: [...document.querySelectorAll('#run > p.muted')].map((p) => p.textContent),
      chart: {
        width: chart.getBoundingClientRect().width, height: chart.getBoundingClientRect().height,
        panel: document.getElementById('run').clientWidth,
        title: chart.parentElement.previousElementSibling.textContent,
        axisLabels: [...chart.querySelectorAll('.axis-label')].map((t) => t.textContent),
        ticks: [...chart.querySelectorAll('.tick')].map((t) => t.textContent),
        tickFont: parseFloat(getComputedStyle(chart.querySelector('.tick')).fontSize),
        curves: [...chart.querySelectorAll('path.curve')].map((p) => ({ cls: p.getAttribute('class'), points: (p.getAttribute('d').match(/[ML]/g) || []).length, stroke: stroke(p) })),
        marker: stroke(chart.querySelector('.marker')),
        lineageDots: chart.querySelectorAll('.lineage-dot').length,
      },
      legend: [...document.querySelectorAll('#run .legend .key')].map((k) => k.textContent),
      table: [...document.querySelectorAll('#run table.gens tr')].map(cells),
      options: [...document.querySelectorAll('#generation option')].map((o) => ({ value: o.value, text: o.textContent, disabled: o.disabled })),
      downloadButton: document.getElementById('download-genome')?.textContent ?? null,
    };
  });
  r.opened = await now();
  r.lineage = await lineage();
  // every playable ancestor, the oldest first: each plays, the list stays
  r.ancestors = [];
  for (const item of [...r.lineage].reverse()) {
    if (!item.playable || item.current) continue;
    await page.click(`#picker .lineage-item[data-id="${item.id}"]`);
    r.ancestors.push({ clicked: item.id, ...(await now()), lineage: (await lineage()).map((x) => x.id),
      current: (await lineage()).filter((x) => x.current).map((x) => x.id) });
  }
  await page.screenshot({ path: join(a.shots, `${a.name}_lineage.png`) });
  // the first generation from the list
  await page.selectOption('#generation', r.options.find((o) => o.value !== '' && !o.disabled).value);
  r.afterSelect = { ...(await now()), lineage: (await lineage()).map((x) => x.id) };
  // the chart's right end: the last generation
  const chart = page.locator('#run svg.curves');
  const box = await chart.boundingBox();
  await chart.click({ position: { x: box.width - 12, y: box.height / 2 } }); // scrolled into view first
  r.afterClick = await now();
  // the shown creature's genome, as the browser saves it
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-genome')]);
  r.download = { name: download.suggestedFilename(), text: readFileSync(await download.path(), 'utf8') };
  if (await page.locator('#run svg.syllabus').count()) r.syllabus = await inspectSyllabus(page, a, now);
  return r;
}

// a run of stages: the syllabus graph (each box's name, text, column and
// state, each edge), then each begun stage picked: the chart (its title, x
// axis, points per curve, marker) and what a click at its right end shows
async function inspectSyllabus(page, a, now) {
  const graph = () => page.evaluate(() => {
    const boxes = [...document.querySelectorAll('#run svg.syllabus .stage')];
    return {
      stages: boxes.map((b) => ({
        index: Number(b.dataset.stage), name: b.querySelector('.stage-name').textContent,
        best: b.querySelector('.stage-best').textContent, x: Number(b.querySelector('rect').getAttribute('x')),
        picked: b.classList.contains('picked'), shown: b.classList.contains('shown'), begun: !b.classList.contains('not-begun'),
        stroke: getComputedStyle(b.querySelector('rect')).stroke,
      })),
      edges: [...document.querySelectorAll('#run svg.syllabus .edge')].map((e) => [Number(e.dataset.from), Number(e.dataset.to)]),
      groups: [...document.querySelectorAll('#run .group-key')].map((k) => k.textContent),
    };
  });
  const chart = () => page.evaluate(() => {
    const c = document.querySelector('#run svg.curves');
    return {
      title: c.parentElement.previousElementSibling.firstChild.textContent,
      axisLabels: [...c.querySelectorAll('.axis-label')].map((t) => t.textContent),
      points: [...c.querySelectorAll('path.curve')].map((p) => (p.getAttribute('d').match(/[ML]/g) || []).length),
      marker: c.querySelectorAll('.marker').length,
    };
  });
  const out = { opened: { ...(await graph()), chart: await chart() }, picked: [] };
  for (const st of out.opened.stages) {
    if (!st.begun) continue;
    await page.click(`#run svg.syllabus .stage[data-stage="${st.index}"]`);
    const picked = { index: st.index, chart: await chart() };
    const c = page.locator('#run svg.curves');
    const box = await c.boundingBox();
    await c.click({ position: { x: box.width - 12, y: box.height / 2 } });
    picked.afterClick = await now();
    picked.graph = await graph();
    out.picked.push(picked);
  }
  await page.screenshot({ path: join(a.shots, `${a.name}_syllabus.png`) });
  await page.click('#run button.whole-run');
  out.whole = await chart();
  return out;
}

main().catch((e) => {
  process.stderr.write(`${e.message.split('\n')[0]}\n`);
  process.exit(1);
});
