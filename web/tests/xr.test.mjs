// Through the emulated headset (iwer's Meta Quest 3): scripts/web-render --xr
// draws at the device's own views, and `trace` with the options it prints
// draws the same two eye views: the id maps agree. And a walk through doors
// driven by the headset's poses teleports exactly as `walk` on the same path.
import test from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { openPage } from '../tools/browser.mjs';
import { compare, layouts, maxIdMismatchPct, minPsnrDb, repoRoot, runNative, runWebRender, scratch } from './common.mjs';

const d = path.join(layouts, 'default.json');
const xrCases = [
  ['default at its start', [d]],
  ['default: one eye inside the door box', [d, '--pose', '0.1,1.6,0.002,90,0,0', '--room', 'hall']],
  ['mirror_hall', [path.join(layouts, 'mirror_hall.json')]],
  ['lamp_hall (lights and shadows)', [path.join(layouts, 'lamp_hall.json')]],
  ['scanner_lab (a volume)', [path.join(layouts, 'scanner_lab.json')]],
  ['window_pair', [path.join(layouts, 'window_pair.json')]],
];

// The smoke (the README's test command): three views and two walks.
const smoke = process.env.IMPOSSIBLE_WEB_SMOKE === '1';

test('--xr frames equal trace at the eye views they print', () => {
  const dir = scratch('xr');
  const failures = [];
  for (const [k, [name, args]] of (smoke ? xrCases.filter((_, i) => i % 2 === 1) : xrCases).entries()) {
    const out = path.join(dir, `${k}.png`), ids = path.join(dir, `${k}-ids.png`);
    const r = runWebRender(['render', ...args, '--xr', '--size', '160x100', '--out', out, '--ids', ids], dir);
    assert.equal(r.status, 0, `${name}: ${r.stderr}`);
    const options = r.stdout.trim().split('\n').pop().split(' ');
    assert.ok(options.includes('--eye-poses') && options.includes('--fov-angles'), r.stdout);
    const layout = args[0];
    const tOut = path.join(dir, `${k}-t.png`), tIds = path.join(dir, `${k}-t-ids.png`);
    runNative(['trace', layout, ...options, '--out', tOut, '--ids', tIds]);
    const m = compare(out, tOut, ids, tIds);
    console.log(`${name}: ${options.join(' ')}\n  ${m.line}`);
    if (!(m.id_mismatch_pct <= maxIdMismatchPct) || !(m.psnr_db >= minPsnrDb)) failures.push(`${name}: ${m.line}`);
  }
  assert.deepEqual(failures, []);
});

// The path's poses, `walk`'s format.
function readPath(file) {
  return fs.readFileSync(file, 'utf8').split('\n').map((l) => l.trim())
    .filter((l) => l && !l.startsWith('#')).map((l) => l.split(/\s+/).slice(0, 6).map(Number));
}

// Paths from docs/tours, or (a third element) the layouts folder: the door
// swap changes its pairing on the way (docs/changes.md), at the frame `walk`
// makes the change.
const walks = [['default.json', 'default.txt'], ['four_rooms.json', 'four_rooms.txt'], ['rotated.json', 'rotated.txt'],
               ['curved_corridor.json', 'curved_corridor.txt'], ['door_swap.json', 'door_swap_walk.txt', layouts]];
for (const [layoutName, pathName, pathDir] of smoke ? walks.slice(0, 2) : walks) {
  test(`a walk in the emulated headset teleports as walk does: ${layoutName}`, async () => {
    const layout = path.join(layouts, layoutName);
    const pathFile = path.join(pathDir ?? path.join(repoRoot, 'docs', 'tours'), pathName);
    const original = runNative(['walk', layout, '--path', pathFile]).trim().split('\n').map((l) => JSON.parse(l));
    const poses = readPath(pathFile);
    const session = await openPage({ xr: true, width: 320, height: 100 });
    try {
      const walked = await session.page.evaluate(async ([text, poses]) => {
        const { module, api, xr } = window.impossible;
        module.FS.writeFile('/walk-layout.json', text);
        if (api.open('/walk-layout.json') !== 0) throw new Error(api.message());
        const info = JSON.parse(api.layoutInfo());
        const device = window.emulatedHeadset;
        xr.hold = true;
        await xr.enter();
        const out = [];
        for (const [i, p] of poses.entries()) {
          const placed = xr.layoutToFloor(info.start, p);
          device.position.set(...placed.position);
          device.quaternion.set(...placed.orientation);
          if (i === 0) api.reset();
          const status = await new Promise((resolve) => { xr.onFrame = resolve; xr.hold = false; });
          xr.hold = true;
          out.push({ room: status.room, teleports: status.teleports, physical: status.physical,
                     changes: status.changes ?? [] });
        }
        await xr.exit();
        return out;
      }, [fs.readFileSync(layout, 'utf8'), poses]);
      // WebXR's poses are single precision: the headset walked the path's
      // poses rounded so (within 10 µm and 1e-3 degrees here); `walk` on
      // exactly the poses it walked gives the same rooms and teleports, and
      // those are the path's own.
      const dir = scratch('walk');
      const walkedPath = path.join(dir, 'walked.txt');
      fs.writeFileSync(walkedPath, walked.map((w) => w.physical.map((v) => String(v)).join(' ')).join('\n') + '\n');
      for (const [i, w] of walked.entries())
        for (let k = 0; k < 6; ++k) assert.ok(Math.abs(w.physical[k] - poses[i][k]) < (k < 3 ? 1e-5 : 1e-3), `frame ${i}`);
      const expected = runNative(['walk', layout, '--path', walkedPath]).trim().split('\n').map((l) => JSON.parse(l));
      assert.equal(walked.length, expected.length);
      assert.equal(original.length, expected.length);
      const teleports = expected.reduce((n, e) => n + e.teleports.length, 0);
      assert.ok(teleports > 0, 'the path passes doors');
      for (const [i, e] of expected.entries())
        assert.deepEqual({ room: walked[i].room, teleports: walked[i].teleports, changes: walked[i].changes },
                         { room: e.room, teleports: e.teleports, changes: e.changes ?? [] }, `frame ${i}`);
      const originalTeleports = original.flatMap((e) => e.teleports), walkedTeleports = walked.flatMap((w) => w.teleports);
      assert.deepEqual(walkedTeleports, originalTeleports, 'the same doors, in order, as the path itself');
      const changes = expected.reduce((n, e) => n + (e.changes ?? []).length, 0);
      if (layoutName === 'door_swap.json') assert.equal(changes, 1, 'the swap is made');
      console.log(`${layoutName}: ${walked.length} frames, ${teleports} teleports, ${changes} changes, all as walk`);
    } finally {
      await session.close();
    }
  });
}

test('the controllers are the layout\'s hands: one reached through the door is in the room beyond', async () => {
  const session = await openPage({ xr: true, width: 320, height: 100 });
  try {
    const rooms = await session.page.evaluate(async () => {
      const { api, xr } = window.impossible;
      const info = JSON.parse(api.layoutInfo());
      const device = window.emulatedHeadset;
      // The head in the hall 0.3 m in front of the door (z = 0), facing it.
      const head = xr.layoutToFloor(info.start, [0, 1.6, 0.3, 0, 0, 0]);
      device.position.set(...head.position);
      device.quaternion.set(...head.orientation);
      const place = (hand, p) => {
        const at = xr.layoutToFloor(info.start, p);
        device.controllers[hand].position.set(...at.position);
        device.controllers[hand].quaternion.set(...at.orientation);
      };
      place('left', [-0.2, 1.2, 0.3, 0, 0, 0]);
      place('right', [0.05, 1.4, -0.2, 0, 0, 0]);  // through the door, 0.2 m beyond it
      xr.hold = true;
      await xr.enter();
      api.reset();
      const status = await new Promise((resolve) => { xr.onFrame = resolve; xr.hold = false; });
      await xr.exit();
      return { head: status.room, hands: status.hands };
    });
    assert.deepEqual(rooms, { head: 'hall', hands: ['hall', 'annex'] });
  } finally {
    await session.close();
  }
});
