// The player bar's pure parts: where a moment sits on the scrub bar.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { scrubFraction } from '../src/player.js';

test('a moment on the scrub bar: its share of the duration, clamped', () => {
  assert.equal(scrubFraction(0.5, 2), 0.25);
  assert.equal(scrubFraction(3, 2), 1);
  assert.equal(scrubFraction(-1, 2), 0);
  assert.equal(scrubFraction(0.5, 0), 0);
});
