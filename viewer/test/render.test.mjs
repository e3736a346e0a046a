// The video encoder's command line, and the progress lines.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { duration, ffmpegArgs, progressLine, screenshotType } from '../render.mjs';

test('mp4: H.264 in yuv420p, playable everywhere, from JPEG screenshots', () => {
  const a = ffmpegArgs({ format: 'mp4', fps: 25, out: 'x.tmp' });
  assert.equal(screenshotType('mp4'), 'jpeg');
  assert.deepEqual(a.slice(a.indexOf('-c:v'), a.indexOf('-c:v') + 2), ['-c:v', 'mjpeg']);
  assert.deepEqual(a.slice(a.indexOf('-framerate'), a.indexOf('-framerate') + 2), ['-framerate', '25']);
  for (const s of ['libx264', 'yuv420p', '+faststart']) assert.ok(a.includes(s), s);
  assert.deepEqual(a.slice(-3), ['-f', 'mp4', 'x.tmp']);
});

test('gif: a small palette made from the frames themselves, from lossless screenshots', () => {
  const a = ffmpegArgs({ format: 'gif', fps: 10, out: 'y.tmp' });
  assert.equal(screenshotType('gif'), 'png');
  assert.deepEqual(a.slice(a.indexOf('-c:v'), a.indexOf('-c:v') + 2), ['-c:v', 'png']);
  const filter = a[a.indexOf('-filter_complex') + 1];
  for (const s of ['palettegen=max_colors=64', 'stats_mode=diff', 'paletteuse', 'diff_mode=rectangle'])
    assert.ok(filter.includes(s), s);
  assert.deepEqual(a.slice(-3), ['-f', 'gif', 'y.tmp']);
});

test('other formats are refused', () => {
  assert.throws(() => ffmpegArgs({ format: 'avi', fps: 10, out: 'z' }), /unknown format "avi"/);
});

test('progress: frames done of the total, elapsed and left at the pace so far', () => {
  assert.equal(progressLine(30, 300, 4.1), 'frame 30/300 (10%)  elapsed 4s  left 37s');
  assert.equal(progressLine(300, 300, 41), 'frame 300/300 (100%)  elapsed 41s  left 0s');
  assert.equal(progressLine(1, 3, 0.2), 'frame 1/3 (33%)  elapsed 0s  left 0s');
});

test('durations read as bestiary run writes them', () => {
  assert.equal(duration(59.4), '59s');
  assert.equal(duration(65), '1m05s');
  assert.equal(duration(3725), '1h02m');
  assert.equal(duration(NaN), '?');
});
