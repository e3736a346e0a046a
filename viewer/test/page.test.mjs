// The built page: one self-contained file with one place for the data, and
// its C++ form holds exactly the same bytes.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { buildPage, cppSource, DATA_MARKER } from '../build.mjs';

const page = await buildPage();

test('the page has one place for the data, in a JSON script tag', () => {
  assert.equal(page.split(DATA_MARKER).length, 2);
  assert.ok(page.includes(`<script id="bestiary-data" type="application/json">${DATA_MARKER}</script>`));
});

test('the page loads nothing from outside', () => {
  assert.doesNotMatch(page, /<script[^>]+src=/i);
  assert.doesNotMatch(page, /<link[^>]+href=/i);
  assert.doesNotMatch(page, /url\(\s*['"]?https?:/i);
  assert.doesNotMatch(page, /@import/i);
});

test('three.js is bundled with its licence', () => {
  assert.match(page, /three\.js authors/i);
  assert.match(page, /MIT/);
});

test('the C++ source decodes to the same bytes', () => {
  const src = cppSource(page);
  // the string literal pieces, between the array's "=" and ";"
  const body = src.slice(src.indexOf('kViewerPage[] =') + 15, src.indexOf(';\nconst std::size_t'));
  const bytes = [];
  for (const piece of body.match(/"(?:[^"\\]|\\[0-7]{3})*"/g)) {
    const s = piece.slice(1, -1);
    for (let i = 0; i < s.length; ++i) {
      if (s[i] === '\\') {
        bytes.push(parseInt(s.slice(i + 1, i + 4), 8));
        i += 3;
      } else {
        bytes.push(s.charCodeAt(i));
      }
    }
  }
  assert.ok(Buffer.from(bytes).equals(Buffer.from(page, 'utf8')));
});
