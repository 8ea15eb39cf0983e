// scripts/web-render --xr: the frame drawn through the emulated headset's
// immersive-vr session (iwer's Meta Quest 3, stereo): the device is put at
// the head pose asked for (--pose, else the layout's start), the session's
// viewer pose and views (each eye's pose relative to the head and its
// projection, its viewport's size) become --pose, --eye-poses,
// --fov-angles and --size, and `render` draws them; the options are printed
// as the last line, for `impossible trace` to draw the same two eye views.

import fs from 'node:fs';
import path from 'node:path';

// Options the device's views replace.
const viewFlags = new Set(['--pose', '--ipd', '--fov', '--fov-angles', '--eye-poses', '--hmd', '--size']);
const outputFlags = new Set(['--out', '--ids']);

function splitOptions(args) {
  const kept = [], outputs = [];
  let pose = null, size = null;
  for (let i = 1; i < args.length; ++i) {
    const a = args[i];
    const [flag, inline] = a.startsWith('--') ? [a.split('=')[0], a.includes('=') ? a.slice(a.indexOf('=') + 1) : null] : [null, null];
    if (flag && (viewFlags.has(flag) || outputFlags.has(flag))) {
      const value = inline ?? args[++i];
      if (flag === '--pose') pose = value;
      if (flag === '--size') size = value;
      if (outputFlags.has(flag)) outputs.push(flag, value);
      continue;
    }
    kept.push(a);
  }
  return { kept, outputs, pose, size };
}

export async function xrRender(page, args, { inputs, outputs, cwd }) {
  const { kept, outputs: outputArgs, pose } = splitOptions(args);
  // The layout: the first argument that is a file (none: the built-in default).
  const layoutIndex = kept.findIndex((a) => !a.startsWith('-') && fs.existsSync(a) && fs.statSync(a).isFile());
  const layout = layoutIndex >= 0 ? path.resolve(kept[layoutIndex]) : null;
  const others = kept.filter((_, i) => i !== layoutIndex);
  return page.evaluate(async ([command, others, outputArgs, pose, layout, inputs, outputs, cwd]) => {
    const { api, run, xr } = window.impossible;
    run(['validate', ...(layout ? [layout] : [])], { inputs, cwd });  // writes the inputs
    if (api.open(layout || '') !== 0)
      return { status: 1, out: '', err: `impossible ${command}: ${api.message()}\n`, files: {} };
    const info = JSON.parse(api.layoutInfo());
    const p = pose ? pose.split(',').map(Number) : [...info.start, 0, 0];
    if (p.length !== 6 || p.some((v) => !Number.isFinite(v)))
      return { status: 2, out: '', err: `impossible ${command}: --pose: expected X,Y,Z,YAW,PITCH,ROLL\n`, files: {} };
    const placed = xr.layoutToFloor(info.start, p);
    window.emulatedHeadset.position.set(...placed.position);
    window.emulatedHeadset.quaternion.set(...placed.orientation);
    await xr.enter();
    const started = performance.now();
    while (xr.frames < 2 && performance.now() - started < 20000) await new Promise((r) => setTimeout(r, 20));
    await xr.exit();
    if (xr.frames < 2) return { status: 1, out: '', err: 'web-render --xr: the emulated session drew no frame\n', files: {} };
    const view = api.viewOptions(JSON.stringify(xr.lastRequest));
    if (!view) return { status: 1, out: '', err: `web-render --xr: ${api.message()}\n`, files: {} };
    // Without --pose the head stands at the start, in the start's room.
    const room = !pose && !others.some((a) => a === '--room' || a.startsWith('--room=')) ? ['--room', info.start_room] : [];
    const options = [...others, ...room, ...view.split(' ')];
    const result = run([command, ...(layout ? [layout] : []), ...options, ...outputArgs], { outputs, cwd });
    result.traceOptions = options.join(' ');
    return result;
  }, [args[0], others, outputArgs, pose, layout, inputs, outputs, cwd]);
}

// The browser window for --size WxH: the device's canvas is the window, and
// each eye's viewport half of it.
export function xrWindow(args) {
  const { size } = splitOptions(args);
  if (!size) return {};
  const [w, h] = size.split('x').map(Number);
  return w > 0 && h > 0 ? { width: 2 * w, height: h } : {};
}
