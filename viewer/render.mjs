// Renders a viewer page to a video: headless Chromium draws each frame at its
// exact time (window.bestiary.renderFrame, follow camera), and ffmpeg encodes
// the screenshots. `bestiary render` runs this; see docs/viewer.md.
// An mp4's screenshots are JPEG at quality 95: Chromium encodes a 1280 x 720
// PNG in about 350 ms and a JPEG in about 40 ms, and the video is lossy anyway.
// A GIF's are PNG: the GIF stores only the pixels that change from one frame
// to the next, and JPEG's noise changes nearly all of them (10 s of walker at
// 480 x 270, 15 fps: 5.6 MB from JPEGs, 2.7 MB from PNGs, same filters).
//
//   node render.mjs --html PAGE --out FILE --format mp4|gif --frames N --fps F
//                   --width W --height H [--chromium PATH] [--ffmpeg PATH]
//
// Frame i shows time i / F, so the video lasts N / F seconds. Progress goes to
// stdout, one line after each 5% of the frames or PROGRESS_SECONDS, whichever
// comes first, and after the last: "frame 30/300 (10%)  elapsed 4s  left 37s".
// Errors end in one line on stderr and exit code 1.
import { spawn } from 'node:child_process';
import { openViewer } from './tools/browser.mjs';
import { isMain } from './tools/is_main.mjs';

/** Quality of the frames' JPEG screenshots. */
const JPEG_QUALITY = 95;

/** Longest wait between two progress lines, in seconds. */
const PROGRESS_SECONDS = 2;

/** A duration as `bestiary run` writes it: 37s, 4m05s, 1h02m ("?" if unknown). */
export function duration(s) {
  if (!Number.isFinite(s) || s < 0) return '?';
  const whole = Math.floor(s);
  if (s < 60) return `${Math.round(s)}s`;
  const two = (n) => String(n).padStart(2, '0');
  if (s < 3600) return `${Math.floor(whole / 60)}m${two(whole % 60)}s`;
  return `${Math.floor(whole / 3600)}h${two(Math.floor((whole % 3600) / 60))}m`;
}

/** One progress line: frames done of the total, time elapsed and, at the frames' pace so far, left. */
export function progressLine(done, total, elapsed) {
  const left = done > 0 ? (elapsed / done) * (total - done) : NaN;
  return `frame ${done}/${total} (${Math.floor((100 * done) / total)}%)  elapsed ${duration(elapsed)}  left ${duration(left)}`;
}

/**
 * A GIF's palette and dithering: 64 colours from the pixels that change
 * (stats_mode=diff), ordered dithering coarse enough to compress (bayer_scale
 * 5 of 0 to 5) and only each frame's changed rectangle re-dithered. 10 s of
 * walker at 480 x 270, 15 fps: 1.6 MB (256 colours and bayer_scale 3: 2.7 MB).
 */
const GIF_FILTER = 'split[a][b];[a]palettegen=max_colors=64:stats_mode=diff[p];' +
  '[b][p]paletteuse=dither=bayer:bayer_scale=5:diff_mode=rectangle';

/** The screenshots' type for a format: JPEG for an mp4, PNG for a gif (see above). */
export function screenshotType(format) {
  return format === 'gif' ? 'png' : 'jpeg';
}

/** ffmpeg's arguments: screenshots on stdin, H.264 mp4 or a palette-optimised gif out. */
export function ffmpegArgs({ format, fps, out }) {
  const codec = screenshotType(format) === 'png' ? 'png' : 'mjpeg';
  const input = ['-hide_banner', '-loglevel', 'error', '-y', '-f', 'image2pipe', '-framerate', String(fps), '-c:v', codec, '-i', '-'];
  if (format === 'mp4')
    return [...input, '-c:v', 'libx264', '-pix_fmt', 'yuv420p', '-preset', 'medium', '-crf', '20',
      '-movflags', '+faststart', '-f', 'mp4', out];
  if (format === 'gif') return [...input, '-filter_complex', GIF_FILTER, '-f', 'gif', out];
  throw new Error(`unknown format "${format}" (mp4 or gif)`);
}

function parseArgs(argv) {
  const a = {};
  for (let i = 0; i < argv.length; i += 2) {
    if (!argv[i].startsWith('--') || argv[i + 1] === undefined) throw new Error(`bad argument "${argv[i]}"`);
    a[argv[i].slice(2)] = argv[i + 1];
  }
  for (const k of ['html', 'out', 'format', 'frames', 'fps', 'width', 'height'])
    if (a[k] === undefined) throw new Error(`missing --${k}`);
  for (const k of ['frames', 'fps', 'width', 'height']) {
    a[k] = Number(a[k]);
    if (!Number.isInteger(a[k]) || a[k] < 1) throw new Error(`--${k}: expected a positive integer`);
  }
  return a;
}

// writes to a stream, waiting when its buffer is full
function write(stream, buf) {
  return new Promise((resolve, reject) => {
    if (stream.write(buf)) resolve();
    else {
      stream.once('drain', resolve);
      stream.once('close', () => reject(new Error('ffmpeg stopped reading')));
    }
  });
}

async function main() {
  const a = parseArgs(process.argv.slice(2));
  // the encoder, reading the screenshots from its stdin
  const ffmpeg = spawn(a.ffmpeg || 'ffmpeg', ffmpegArgs(a), { stdio: ['pipe', 'ignore', 'pipe'] });
  let ffmpegErr = '';
  ffmpeg.stderr.on('data', (d) => (ffmpegErr += d));
  const done = new Promise((resolve, reject) => {
    ffmpeg.on('error', (e) => reject(new Error(`cannot run ffmpeg: ${e.message}`)));
    ffmpeg.on('close', (code) => (code === 0 ? resolve() : reject(new Error(`ffmpeg failed: ${ffmpegErr.trim().split('\n').pop()}`))));
  });
  done.catch(() => {}); // awaited below; an early failure is the one to report
  ffmpeg.stdin.on('error', () => {}); // a closed pipe shows as ffmpeg's failure

  // the page in video mode, one screenshot per frame
  const { browser, page } = await openViewer(a.html, { width: a.width, height: a.height, chromium: a.chromium });
  try {
    await page.evaluate(() => window.bestiary.setRenderMode(true));
    const type = screenshotType(a.format);
    const t0 = performance.now();
    let shownFrame = 0, shownAt = t0;
    for (let i = 0; i < a.frames; ++i) {
      await page.evaluate((t) => window.bestiary.renderFrame(t), i / a.fps);
      const shot = await page.screenshot(type === 'jpeg' ? { type, quality: JPEG_QUALITY } : { type });
      if (ffmpeg.exitCode !== null) break;
      await write(ffmpeg.stdin, shot).catch(() => {});
      const frames = i + 1, now = performance.now();
      if (frames === a.frames || frames - shownFrame >= a.frames / 20 || now - shownAt >= PROGRESS_SECONDS * 1000) {
        process.stdout.write(`${progressLine(frames, a.frames, (now - t0) / 1000)}\n`);
        shownFrame = frames;
        shownAt = now;
      }
    }
  } finally {
    await browser.close();
    ffmpeg.stdin.end();
  }
  await done;
}

// as a script (not when a test imports ffmpegArgs)
if (isMain(import.meta.url)) {
  main().catch((e) => {
    process.stderr.write(`${e.message.split('\n')[0]}\n`);
    process.exit(1);
  });
}
