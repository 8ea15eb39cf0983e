// The web build's frame time (bench/README.md, "The web build"): the page's
// renderer in headless Chromium (SwiftShader) at a layout's start, frame
// after frame with glFinish, against `impossible bench` (llvmpipe) at the
// same view and size, in one run; and the CPU's part of a web frame (the
// walk, the portal recursion and culling, the WebGL calls). Usage:
//   node web/tools/web-bench.mjs [--size WxH] [--frames N] LAYOUT...
import fs from 'node:fs';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { openPage, repoRoot } from './browser.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? args.splice(i, 2)[1] : fallback;
};
const size = option('--size', '640x360');
const frames = Number(option('--frames', '40'));
const native = process.env.IMPOSSIBLE_BIN || path.join(repoRoot, 'build', 'impossible');
const [w, h] = size.split('x').map(Number);
const median = (v) => { const s = [...v].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };

const session = await openPage({ width: 640, height: 400 });
try {
  await session.page.evaluate(() => window.impossible.preview.pause());
  console.log(`size ${size} per eye, ${frames} frames; medians in ms`);
  console.log('layout | native (llvmpipe) | web (SwiftShader) | web/native | web CPU | of which the walk');
  for (const layout of args) {
    const dir = path.dirname(path.resolve(layout));
    const files = fs.readdirSync(dir, { recursive: true }).filter((f) => fs.statSync(path.join(dir, f)).isFile())
      .map((f) => ({ path: path.join(dir, f), base64: fs.readFileSync(path.join(dir, f)).toString('base64') }));
    const web = await session.page.evaluate(async ([layoutPath, files, w, h, frames]) => {
      const { api, run } = window.impossible;
      run(['validate', layoutPath], { inputs: files });
      if (api.open(layoutPath) !== 0) throw new Error(api.message());
      const info = JSON.parse(api.layoutInfo());
      const y = (info.start[3] * Math.PI) / 360;
      const request = JSON.stringify({ space: 'layout', finish: true, size: [w, h],
        head: { position: info.start.slice(0, 3), orientation: [0, Math.sin(y), 0, Math.cos(y)] } });
      const out = [];
      for (let i = 0; i < frames + 5; ++i) {
        if (api.frame(request) !== 0) throw new Error(api.message());
        if (i >= 5) out.push(JSON.parse(api.status()));
      }
      return out;
    }, [path.resolve(layout), files, w, h, frames]);
    const json = path.join(fs.mkdtempSync('/tmp/web-bench-'), 'bench.json');
    execFileSync(native, ['bench', layout, '--size', size, '--frames', String(frames), '--json', json]);
    const nativeMs = JSON.parse(fs.readFileSync(json, 'utf8')).configs[0].frame_ms_median;
    const webMs = median(web.map((s) => s.frame_ms));
    console.log(`${path.basename(layout)} | ${nativeMs.toFixed(2)} | ${webMs.toFixed(2)} | ` +
      `${(webMs / nativeMs).toFixed(2)} | ${median(web.map((s) => s.ms)).toFixed(2)} | ` +
      `${median(web.map((s) => s.walk_ms)).toFixed(3)}`);
  }
} finally {
  await session.close();
}
const site = path.join(repoRoot, 'build-web', 'site');
const kb = (f) => (fs.statSync(path.join(site, f)).size / 1024).toFixed(0);
console.log(`bundle: impossible.wasm ${kb('impossible.wasm')} KiB, impossible.js ${kb('impossible.js')} KiB`);
