// The files a command's argument list reads and writes, for the module's
// in-memory file system: each input with every file in its folder (a
// layout's textures and models), and the outputs it asks for.
import fs from 'node:fs';
import path from 'node:path';

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

