// Headless Chromium for scripts (render.mjs, inspect.mjs): Debian's browser,
// never a downloaded one, with WebGL drawn in software (SwiftShader) and
// nothing that reaches the network. playwright-core gives each launch a fresh
// temporary profile (user data dir) and removes it on close.
import { chromium } from 'playwright-core';
import { pathToFileURL } from 'node:url';
import { resolve } from 'node:path';

/** Chromium's flags: headless, no sandbox (root in CI), software GL, quiet. */
export const CHROMIUM_ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--mute-audio',
];

/** Default browser: $BESTIARY_CHROMIUM, else Debian's. */
export function chromiumPath(given) {
  return given || process.env.BESTIARY_CHROMIUM || '/usr/bin/chromium';
}

/**
 * Opens `html` (a file) in a new headless browser at width x height CSS
 * pixels and waits until the viewer has started. Returns {browser, page,
 * requests}: `requests` lists every URL the page asked for.
 */
export async function openViewer(html, { width, height, chromium: exe, hash = '' } = {}) {
  const browser = await chromium.launch({ executablePath: chromiumPath(exe), headless: true, args: CHROMIUM_ARGS });
  try {
    const context = await browser.newContext({ viewport: { width, height }, deviceScaleFactor: 1 });
    const page = await context.newPage();
    const requests = [];
    const errors = [];
    page.on('request', (r) => requests.push(r.url()));
    page.on('pageerror', (e) => errors.push(String(e)));
    page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    const url = pathToFileURL(resolve(html)).href + hash;
    await page.goto(url, { waitUntil: 'load' });
    await page.waitForFunction(() => window.bestiary && window.bestiary.ready, null, { timeout: 30000 });
    const error = await page.evaluate(() => window.bestiary.error);
    if (error) throw new Error(`the viewer reports: ${error}`);
    return { browser, page, requests, errors };
  } catch (e) {
    await browser.close();
    throw e;
  }
}
