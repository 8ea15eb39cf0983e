// What the browser tests share: the native program (the oracle's `trace`
// and `walk`), a scratch folder, and the comparison of a web frame with
// trace's (`impossible compare`).
import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { repoRoot } from '../tools/browser.mjs';

export { repoRoot };
export const native = process.env.IMPOSSIBLE_BIN || path.join(repoRoot, 'build', 'impossible');
export const layouts = path.join(repoRoot, 'layouts');
export const webRender = path.join(repoRoot, 'scripts', 'web-render');

export function scratch(name) {
  return fs.mkdtempSync(path.join(os.tmpdir(), `impossible-web-${name}-`));
}

export function runNative(args) {
  return execFileSync(native, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

export function runWebRender(args, cwd) {
  return spawnSync(webRender, args, { encoding: 'utf8', cwd });
}

// `impossible compare` of two frames with their id maps, as numbers.
export function compare(a, b, aIds, bIds) {
  const line = runNative(['compare', a, b, '--ids-a', aIds, '--ids-b', bIds]).trim();
  const out = { line };
  for (const item of line.split(' ')) {
    const [k, v] = item.split('=');
    out[k] = v === 'inf' ? Infinity : Number(v);
  }
  return out;
}

// The tolerance against the oracle (docs/web.md, "Accuracy"): the native
// tests' id tolerance (a few lone edge pixels) and a colour floor below the
// native one, for SwiftShader's ties at edges on pixel centres.
export const maxIdMismatchPct = 0.01;
export const minPsnrDb = 30;
