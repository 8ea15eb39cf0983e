// The page: the module (impossible.js + impossible.wasm, built from the same
// sources as the native program), the side-by-side preview, the headset
// session, opening layouts, and the command line's bridge. docs/web.md
// tells how the parts fit.
import { writeFile, readFileOrNull, toBase64, fromBase64, makeDirs } from './files.js';
import { startPreview } from './preview.js';
import { setUpXr } from './xr.js';
import { openFromUrl, openDropped } from './layouts.js';

const canvas = document.getElementById('impossible-gl');
const messageBox = document.getElementById('message');

const module = await createImpossible({
  canvas,
  print: (text) => console.log(text),
  printErr: (text) => console.warn(text),
});

const api = {
  run: module.cwrap('impossible_run', 'number', ['string']),
  runOutput: module.cwrap('impossible_run_output', 'string', []),
  runErrors: module.cwrap('impossible_run_errors', 'string', []),
  open: module.cwrap('impossible_page_open', 'number', ['string']),
  frame: module.cwrap('impossible_page_frame', 'number', ['string']),
  save: module.cwrap('impossible_page_save', 'number', ['string', 'string']),
  message: module.cwrap('impossible_page_message', 'string', []),
  status: module.cwrap('impossible_page_status', 'string', []),
  layoutInfo: module.cwrap('impossible_page_layout_info', 'string', []),
  viewOptions: module.cwrap('impossible_page_view_options', 'string', ['string']),
  reset: module.cwrap('impossible_page_reset', null, []),
};

// One clear line on the page for bad input; the layout before stays open.
function showMessage(text) {
  messageBox.textContent = text;
  messageBox.hidden = !text;
}

// Opens a layout already in the module's file system ('' the built-in
// default): true, or false with the message shown.
function openLayout(path) {
  if (api.open(path) !== 0) {
    showMessage(api.message());
    return false;
  }
  showMessage('');
  preview.restart();
  return true;
}

// The command line's bridge (scripts/web-render): `impossible ARGS...` with
// `inputs` ({path, base64}) written to the same paths first, in the
// working directory `cwd`; returns the exit status, the output, the errors
// and the files named in `outputs` that the command wrote.
function run(args, { inputs = [], outputs = [], cwd = '/' } = {}) {
  for (const f of inputs) writeFile(module.FS, f.path, fromBase64(f.base64));
  makeDirs(module.FS, cwd + '/x');
  module.FS.chdir(cwd);
  for (const path of outputs) { try { module.FS.unlink(path); } catch (e) { /* none yet */ } }
  const status = api.run(JSON.stringify(args));
  const files = {};
  for (const path of outputs) {
    // Emscripten's umask is all ones: the files come out mode 0.
    try { module.FS.chmod(path, 0o644); } catch (e) { /* not written */ }
    const bytes = readFileOrNull(module.FS, path);
    if (bytes) files[path] = toBase64(bytes);
  }
  return { status, out: api.runOutput(), err: api.runErrors(), files };
}

const preview = startPreview({ api, canvas, showMessage });
const xr = await setUpXr({ module, api, canvas, preview, showMessage });

const params = new URLSearchParams(location.search);
if (params.get('layout')) {
  await openFromUrl(module, params.get('layout'), openLayout, showMessage);
} else {
  openLayout('');
}

document.getElementById('open').addEventListener('change', async (e) => {
  await openDropped(module, [...e.target.files], openLayout, showMessage);
  e.target.value = '';
});
document.addEventListener('dragover', (e) => { e.preventDefault(); document.body.classList.add('dragging'); });
document.addEventListener('dragleave', () => document.body.classList.remove('dragging'));
document.addEventListener('drop', async (e) => {
  e.preventDefault();
  document.body.classList.remove('dragging');
  await openDropped(module, [...e.dataTransfer.files], openLayout, showMessage);
});

// What the tests and scripts/web-render reach.
window.impossible = { module, api, run, openLayout, preview, xr, showMessage,
                      openDropped: (files) => openDropped(module, files, openLayout, showMessage), ready: true };
