// Watches a page that `bestiary show RUN --watch` serves, as a person would,
// for the end-to-end test (tests/viewer/watch_test.cpp): opens the URL in
// headless Chromium, picks a creature and a moment, runs a command that lets
// the run go on (`bestiary resume RUN`), and waits until the page has
// reloaded with the generations stored since. Prints one JSON object:
// {before, after: {generations, label, t, playing}, reloads, errors}.
//
//   node tools/watch_check.mjs --url http://127.0.0.1:PORT/ --then "COMMAND" [--timeout 90]
import { execSync } from 'node:child_process';
import { chromium } from 'playwright-core';
import { CHROMIUM_ARGS, chromiumPath } from './browser.mjs';

function parseArgs(argv) {
  const a = { timeout: '90' };
  for (let i = 0; i < argv.length; i += 2) a[argv[i].slice(2)] = argv[i + 1];
  return a;
}

// what the page shows: its run's generations, the creature and moment watched
const seen = () => {
  const data = JSON.parse(document.getElementById('bestiary-data').textContent);
  const st = window.bestiary.state();
  return { generations: data.run.generations.length, label: data.replays[st.replayIndex].label, t: st.t, playing: st.playing };
};

async function main() {
  const a = parseArgs(process.argv.slice(2));
  const browser = await chromium.launch({ executablePath: chromiumPath(), headless: true, args: CHROMIUM_ARGS });
  const errors = [];
  try {
    const page = await (await browser.newContext({ viewport: { width: 1000, height: 700 } })).newPage();
    page.on('pageerror', (e) => errors.push(String(e)));
    let loads = 0;
    page.on('load', () => ++loads);
    const ready = () => page.waitForFunction(() => window.bestiary && window.bestiary.ready, null, { timeout: 30000 });
    await page.goto(a.url, { waitUntil: 'load' });
    await ready();
    // watch the last creature on the page at 1.5 s, paused
    await page.evaluate(() => {
      window.bestiary.select(window.bestiary.replayCount - 1);
      window.bestiary.renderFrame(1.5);
    });
    const before = await page.evaluate(seen);
    execSync(a.then, { stdio: 'ignore' });
    // the page reloads once the server sees the new generations (it may
    // reload more than once while the run stores them: wait for the last)
    const until = Date.now() + Number(a.timeout) * 1000;
    let after = before;
    while (Date.now() < until) {
      await new Promise((r) => setTimeout(r, 1000));
      try {
        await ready();
        after = await page.evaluate(seen);
      } catch {
        continue;  // mid-reload
      }
      if (after.generations > before.generations && (await (await fetch(new URL('stamp', a.url))).text()).startsWith(`${after.generations} generations`))
        break;
    }
    process.stdout.write(JSON.stringify({ before, after, reloads: loads - 1, errors }) + '\n');
  } finally {
    await browser.close();
  }
}

main().catch((e) => {
  process.stderr.write(`watch_check: ${e.message}\n`);
  process.exit(1);
});
