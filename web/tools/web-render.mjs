// scripts/web-render: `impossible render` (and trace, walk, validate,
// compare) run by the web build in headless Chromium, with the native
// command's argument list, outputs and exit status (docs/web.md). With
// --xr, the frame is drawn through the emulated headset's session at the
// device's own views (xr-frame.mjs).
import fs from 'node:fs';
import path from 'node:path';
import { openPage } from './browser.mjs';
import { filesOf } from './inputs.mjs';
import { xrRender, xrWindow } from './xr-frame.mjs';

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
