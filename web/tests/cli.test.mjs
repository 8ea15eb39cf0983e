// scripts/web-render as a command: the native command's arguments, outputs
// and exit statuses (cli.md): 0 and both PNGs; 1 and one line for bad input
// (a malformed layout, a missing file, an unknown room); 2 for a usage
// error; and --xr's refusals in one line too.
import test from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { layouts, runNative, runWebRender, scratch } from './common.mjs';

test('web-render writes what render writes, and exits as render does on bad input', () => {
  const dir = scratch('cli');
  const ok = runWebRender(['render', path.join(layouts, 'default.json'), '--size', '64x36', '--out', 'a.png', '--ids',
                           'a-ids.png'], dir);
  assert.equal(ok.status, 0, ok.stderr);
  for (const f of ['a.png', 'a-ids.png']) assert.ok(fs.statSync(path.join(dir, f)).size > 0, f);
  // The default output name and the built-in layout.
  const plain = runWebRender(['render', '--size', '32x18'], dir);
  assert.equal(plain.status, 0, plain.stderr);
  assert.ok(fs.existsSync(path.join(dir, 'stereo.png')));
  // The same bytes as the native command? No (another rasteriser); the same
  // size and ids in the same places is render.test.mjs's business.
  const native = JSON.parse(runNative(['validate', path.join(layouts, 'default.json'), '--json']));
  assert.ok(native.summary || native.rooms || native);

  const bad = path.join(dir, 'bad.json');
  fs.writeFileSync(bad, '{"rooms": [}');
  const cases = [
    [['render', bad, '--out', 'b.png'], 1, /bad\.json:1:\d+/],
    [['render', path.join(dir, 'none.json'), '--out', 'b.png'], 1, /none\.json/],
    [['render', path.join(layouts, 'default.json'), '--room', 'cellar', '--out', 'b.png'], 1, /cellar/],
    [['render', '--size', 'huge'], 1, /--size/],
    [['render', '--frobnicate'], 2, /--frobnicate/],
    [['render', '--samples', '4', '--size', '32x18', '--out', 'b.png'], 1, /multisampling/],
    [['render', bad, '--xr', '--out', 'b.png'], 1, /bad\.json/],
  ];
  for (const [args, status, pattern] of cases) {
    const r = runWebRender(args, dir);
    assert.equal(r.status, status, `${args.join(' ')}: ${r.stderr}`);
    assert.equal(r.stderr.trim().split('\n').length, 1, `one line: ${r.stderr}`);
    assert.match(r.stderr, pattern);
    assert.ok(!fs.existsSync(path.join(dir, 'b.png')), 'no output file on bad input');
  }
});
