// The page: the module (impossible.js + impossible.wasm, built from the same
// sources as the native program), the side-by-side preview, the headset
// session and the command line's bridge. web/README.md tells how it fits.
import { writeFile, readFileOrNull, toBase64, fromBase64, makeDirs } from './files.js';
import { startPreview } from './preview.js';

const module = await createImpossible({
  canvas: document.getElementById('impossible-gl'),
  print: (text) => console.log(text),
  printErr: (text) => console.warn(text),
});

const runCommand = module.cwrap('impossible_run', 'number', ['string']);
const runOutput = module.cwrap('impossible_run_output', 'string', []);
const runErrors = module.cwrap('impossible_run_errors', 'string', []);

// The command line's bridge (scripts/web-render): `impossible ARGS...` with
// `inputs` ({path, base64}) written to the same paths first, in the
// working directory `cwd`; returns the exit status, the output, the errors
// and the files named in `outputs` that the command wrote.
function run(args, { inputs = [], outputs = [], cwd = '/' } = {}) {
  for (const f of inputs) writeFile(module.FS, f.path, fromBase64(f.base64));
  makeDirs(module.FS, cwd + '/x');
  module.FS.chdir(cwd);
  for (const path of outputs) { try { module.FS.unlink(path); } catch (e) { /* none yet */ } }
  const status = runCommand(JSON.stringify(args));
  const files = {};
  for (const path of outputs) {
    // Emscripten's umask is all ones: the files come out mode 0.
    try { module.FS.chmod(path, 0o644); } catch (e) { /* not written */ }
    const bytes = readFileOrNull(module.FS, path);
    if (bytes) files[path] = toBase64(bytes);
  }
  return { status, out: runOutput(), err: runErrors(), files };
}

window.impossible = { module, run, ready: true };
window.impossible.preview = startPreview(module);
