// Files between the page and the module's in-memory file system (MEMFS):
// the command line's inputs and outputs (scripts/web-render), and the files
// a user drops on the page.

export function makeDirs(FS, path) {
  let at = '';
  for (const part of path.split('/').slice(0, -1)) {
    if (!part) continue;
    at += '/' + part;
    try { FS.mkdir(at); } catch (e) { /* it exists */ }
  }
}

export function writeFile(FS, path, bytes) {
  makeDirs(FS, path);
  FS.writeFile(path, bytes);
}

export function readFileOrNull(FS, path) {
  try { return FS.readFile(path); } catch (e) { return null; }
}

export function toBase64(bytes) {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

export function fromBase64(text) {
  const s = atob(text);
  const bytes = new Uint8Array(s.length);
  for (let i = 0; i < s.length; ++i) bytes[i] = s.charCodeAt(i);
  return bytes;
}
