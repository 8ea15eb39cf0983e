// The web build's frames against the oracle: every shipped layout at its
// start, and hard poses (an eye a millimetre from a door, one eye inside the
// door box, looking back out of it, grazing, mirrors, windows, volumes,
// lights), drawn by the web build in headless Chromium and by `trace`.
import test from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { openPage } from '../tools/browser.mjs';
import { filesOf } from '../tools/inputs.mjs';
import { compare, layouts, maxIdMismatchPct, minPsnrDb, runNative, scratch } from './common.mjs';

const only = process.env.IMPOSSIBLE_WEB_CASES;  // a regular expression: the smoke set

const size = process.env.IMPOSSIBLE_WEB_SIZE || '192x108';
const cases = [];
for (const file of fs.readdirSync(layouts).filter((f) => f.endsWith('.json')).sort())
  cases.push({ name: file, args: [path.join(layouts, file)] });
const d = path.join(layouts, 'default.json');
const hard = [
  ['default: eye 1 mm from the door plane', [d, '--pose', '0,1.6,0.001,0,0,0', '--room', 'hall']],
  ['default: one eye inside the door box', [d, '--pose', '0.1,1.6,0.002,90,0,0', '--room', 'hall']],
  ['default: looking back out of the box', [d, '--pose', '0,1.6,-0.01,180,0,0', '--room', 'hall']],
  ['default: the head walked round the door', [d, '--pose', '0,1.6,-0.1,0,0,0', '--room', 'hall']],
  ['default: grazing, 89.9 degrees', [d, '--pose', '1.4,1.2,0.3,89.9,0,0', '--room', 'hall']],
  ['default: asymmetric eyes', [d, '--fov-angles', '-50,40,45,-55']],
  ['default: canted eyes', [d, '--eye-poses', '-0.032,0,0,5,0,0,0.032,0,0,-5,0,0']],
  ['default: standard depth, oblique clip, two-pass', [d, '--depth', 'standard', '--clip', 'oblique', '--stereo', 'two-pass']],
  ['mirror_hall: recursion 3', [path.join(layouts, 'mirror_hall.json'), '--max-depth', '3']],
  ['lamp_hall: light depth 1', [path.join(layouts, 'lamp_hall.json'), '--light-depth', '1']],
  ['sliding_box: moving props at 1.5 s', [path.join(layouts, 'sliding_box.json'), '--time', '1.5']],
];
for (const [name, args] of hard) cases.push({ name, args });
const chosen = only ? cases.filter((c) => new RegExp(only).test(c.name)) : cases;

test('web frames equal trace on every layout and the hard poses', async () => {
  const dir = scratch('render');
  const session = await openPage();
  const failures = [];
  try {
    for (const [k, c] of chosen.entries()) {
      const out = path.join(dir, `${k}-web.png`), ids = path.join(dir, `${k}-web-ids.png`);
      const args = ['render', ...c.args, '--size', size, '--out', out, '--ids', ids];
      const { inputs, outputs } = filesOf(args);
      const r = await session.page.evaluate(([a, o]) => window.impossible.run(a, o), [args, { inputs, outputs, cwd: dir }]);
      if (r.status !== 0) { failures.push(`${c.name}: web render exited ${r.status}: ${r.err}`); continue; }
      for (const [p, b64] of Object.entries(r.files)) fs.writeFileSync(p, Buffer.from(b64, 'base64'));
      const tOut = path.join(dir, `${k}-trace.png`), tIds = path.join(dir, `${k}-trace-ids.png`);
      runNative(['trace', ...c.args, '--size', size, '--out', tOut, '--ids', tIds]);
      const nOut = path.join(dir, `${k}-native.png`), nIds = path.join(dir, `${k}-native-ids.png`);
      runNative(['render', ...c.args, '--size', size, '--out', nOut, '--ids', nIds]);
      const m = compare(out, tOut, ids, tIds), n = compare(nOut, tOut, nIds, tIds);
      // Colour: the floor, or 2 dB under the native build's own PSNR where
      // that is lower (textured layouts: docs/accuracy.md).
      const floor = Math.min(minPsnrDb, n.psnr_db - 2);
      console.log(`${c.name}: ${m.line} (native ${n.psnr_db} dB)`);
      if (!(m.id_mismatch_pct <= maxIdMismatchPct) || !(m.psnr_db >= floor)) failures.push(`${c.name}: ${m.line}`);
    }
  } finally {
    await session.close();
  }
  assert.deepEqual(failures, []);
});
