// The page as a user meets it: the default layout walking in the preview,
// a layout named in the URL, a layout opened with its textures, and bad
// input (a malformed layout, a missing texture) shown as one message line
// while the layout before keeps running.
import test from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { openPage } from '../tools/browser.mjs';
import { layouts, scratch } from './common.mjs';

const statusOf = (page) => page.evaluate(() => window.impossible.preview.state.lastStatus);
const messageOf = (page) => page.evaluate(() => {
  const m = document.getElementById('message');
  return m.hidden ? '' : m.textContent;
});
async function framesPass(page, n = 3) {
  const start = await page.evaluate(() => window.impossible.preview.state.frames + window.impossible.preview.state.fps);
  await page.waitForFunction((s) => window.impossible.preview.state.frames + window.impossible.preview.state.fps !== s,
                             start, { timeout: 10000 });
  await page.waitForTimeout(50 * n);
}

test('the preview walks the default layout with the keys, through its door', async () => {
  const session = await openPage({ width: 640, height: 400 });
  try {
    await framesPass(session.page);
    assert.equal((await statusOf(session.page)).room, 'hall');
    assert.match(await session.page.textContent('#hud'), /room hall/);
    // Walk from the start (0.3, 1.6, 1.6, yaw 8) straight through the door
    // at z = 0: face -z, then W for long enough.
    await session.page.evaluate(() => { const h = window.impossible.preview.state.head; h.x = 0; h.yaw = 0; });
    await session.page.keyboard.down('KeyW');
    await session.page.waitForFunction(() => window.impossible.preview.state.head.z < -0.5, null, { timeout: 20000 });
    await session.page.keyboard.up('KeyW');
    await framesPass(session.page);
    assert.equal((await statusOf(session.page)).room, 'annex');
    assert.match(await session.page.textContent('#hud'), /room annex\s+teleports 1/);
    assert.equal(await messageOf(session.page), '');
  } finally {
    await session.close();
  }
});

test('a bad layout shows its message and the layout before keeps running', async () => {
  const dir = scratch('page');
  const bad = path.join(dir, 'bad.json');
  fs.writeFileSync(bad, '{"format": "impossible-layout", "version": 1, "rooms": [\n  {"id": "a", "size": [4, 3]}\n');
  const missing = path.join(dir, 'missing_texture.json');
  const text = JSON.parse(fs.readFileSync(path.join(layouts, 'default.json'), 'utf8'));
  text.rooms[0].textures = { all: 'nowhere.png' };
  fs.writeFileSync(missing, JSON.stringify(text, null, 1));
  const session = await openPage({ width: 640, height: 400 });
  try {
    await framesPass(session.page);
    for (const file of [bad, missing]) {
      await session.page.setInputFiles('#open', file);
      await session.page.waitForFunction(() => !document.getElementById('message').hidden, null, { timeout: 10000 });
      const message = await messageOf(session.page);
      console.log(`${path.basename(file)}: ${message}`);
      assert.ok(!message.includes('\n'), 'one line');
      assert.match(message, path.basename(file) === 'bad.json' ? /bad\.json:\d+:\d+/ : /nowhere\.png/);
      const frames = await session.page.evaluate(() => window.impossible.preview.state.frames);
      await session.page.waitForFunction((f) => window.impossible.preview.state.frames > f + 2, frames, { timeout: 10000 });
      assert.equal((await statusOf(session.page)).room, 'hall', 'the default layout still runs');
    }
    // A good layout with a texture of its own, picked with it, opens and
    // clears the message.
    await session.page.setInputFiles('#open', [path.join(layouts, 'gallery.json'),
      ...fs.readdirSync(path.join(layouts, 'gallery')).map((f) => path.join(layouts, 'gallery', f))]);
    await session.page.waitForFunction(() => document.getElementById('message').hidden, null, { timeout: 10000 })
      .catch(async () => assert.fail(await messageOf(session.page)));
    const info = await session.page.evaluate(() => JSON.parse(window.impossible.api.layoutInfo()));
    assert.match(info.source, /gallery\.json$/);
  } finally {
    await session.close();
  }
});

test('a layout named in the URL opens with the files it names', async () => {
  const session = await openPage({ width: 640, height: 400, query: 'layout=layouts/lamp_hall.json', serveRepo: true });
  try {
    await framesPass(session.page);
    assert.equal(await messageOf(session.page), '');
    const info = await session.page.evaluate(() => JSON.parse(window.impossible.api.layoutInfo()));
    assert.match(info.source, /lamp_hall\.json$/);
  } finally {
    await session.close();
  }
});
