// The video encoder's command line.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { ffmpegArgs } from '../render.mjs';

test('mp4: H.264 in yuv420p, playable everywhere', () => {
  const a = ffmpegArgs({ format: 'mp4', fps: 25, out: 'x.tmp' });
  assert.deepEqual(a.slice(a.indexOf('-framerate'), a.indexOf('-framerate') + 2), ['-framerate', '25']);
  for (const s of ['libx264', 'yuv420p', '+faststart']) assert.ok(a.includes(s), s);
  assert.deepEqual(a.slice(-3), ['-f', 'mp4', 'x.tmp']);
});

test('gif: a palette made from the frames themselves', () => {
  const a = ffmpegArgs({ format: 'gif', fps: 10, out: 'y.tmp' });
  assert.ok(a.some((s) => s.includes('palettegen') && s.includes('paletteuse')));
  assert.deepEqual(a.slice(-3), ['-f', 'gif', 'y.tmp']);
});

test('other formats are refused', () => {
  assert.throws(() => ffmpegArgs({ format: 'avi', fps: 10, out: 'z' }), /unknown format "avi"/);
});
