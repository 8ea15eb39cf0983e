// scripts/web-render: `impossible render` (and trace, walk, validate,
// compare) run by the web build in headless Chromium, with the native
// command's argument list, outputs and exit status (docs/web.md). With
// --xr, the frame is drawn through the emulated headset's session at the
// device's own views (xr-frame.mjs).
import fs from 'node:fs';
import path from 'node:path';
import { openPage } from './browser.mjs';
import { xrRender, xrWindow } from './xr-frame.mjs';

const skipDirs = new Set(['.git', 'node_modules', 'build', 'build-web', 'build-asan']);
const maxBytes = 256 << 20;

// Every file under `dir` (for a layout: its textures and models), as
// {path, base64}, up to maxBytes in all.
function mirror(dir, out, seen, budget) {
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const p = path.join(dir, entry.name);
    if (entry.isDirectory()) {
      if (!skipDirs.has(entry.name)) mirror(p, out, seen, budget);
    } else if (entry.isFile() && !seen.has(p)) {
      const size = fs.statSync(p).size;
      if (budget.left < size) continue;
      budget.left -= size;
      seen.add(p);
      out.push({ path: p, base64: fs.readFileSync(p).toString('base64') });
    }
  }
}

// The input files an argument list names (anything that is a file), with
// their folders, and the outputs it asks for.
export function filesOf(args) {
  const inputs = [], seen = new Set(), budget = { left: maxBytes };
  const outputs = [];
  let hasOut = false;
  for (let i = 1; i < args.length; ++i) {
    const a = args[i];
    const flag = a.startsWith('--') ? a.split('=')[0] : null;
    if (flag === '--out' || flag === '--ids' || flag === '--diff') {
      const value = a.includes('=') ? a.slice(a.indexOf('=') + 1) : args[i + 1];
      if (value !== undefined) outputs.push(path.resolve(value));
      if (flag === '--out') hasOut = true;
      continue;
    }
    const p = path.resolve(a);
    if (!a.startsWith('-') && fs.existsSync(p) && fs.statSync(p).isFile() && !seen.has(p)) {
      mirror(path.dirname(p), inputs, seen, budget);
      if (!seen.has(p)) inputs.push({ path: p, base64: fs.readFileSync(p).toString('base64') });
    }
  }
  if ((args[0] === 'render' || args[0] === 'trace') && !hasOut) outputs.push(path.resolve('stereo.png'));
  return { inputs, outputs };
}

async function main() {
  const args = process.argv.slice(2);
  const xr = args.includes('--xr');
  const rest = args.filter((a) => a !== '--xr');
  if (rest.length === 0 || rest[0] === '--help') {
    process.stdout.write('usage: scripts/web-render render [LAYOUT] [render\'s options] [--xr]\n' +
      'Runs `impossible render` (or trace, walk, validate, compare) in the web build, in headless Chromium\n' +
      '(docs/web.md). --xr draws through the emulated headset at its own views and prints, last, the\n' +
      'options with which `impossible trace` draws the same two eye views.\n');
    process.exit(rest.length === 0 ? 2 : 0);
  }
  const { inputs, outputs } = filesOf(rest);
  const session = await openPage({ xr, ...(xr ? xrWindow(rest) : {}) });
  try {
    const result = xr ? await xrRender(session.page, rest, { inputs, outputs, cwd: process.cwd() })
                      : await session.page.evaluate(([a, o]) => window.impossible.run(a, o),
                                                    [rest, { inputs, outputs, cwd: process.cwd() }]);
    for (const [p, b64] of Object.entries(result.files)) fs.writeFileSync(p, Buffer.from(b64, 'base64'));
    process.stdout.write(result.out);
    process.stderr.write(result.err);
    if (result.traceOptions) process.stdout.write(result.traceOptions + '\n');
    process.exitCode = result.status;
  } finally {
    await session.close();
  }
}

main().catch((e) => {
  process.stderr.write('web-render: ' + (e && e.message ? e.message.split('\n')[0] : String(e)) + '\n');
  process.exit(1);
});
