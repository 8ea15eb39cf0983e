// Opening layouts: from a URL (?layout=...), with the files it names fetched
// beside it, or from files the user drops or picks (a layout with its
// textures and models). Each goes into the module's file system under a
// folder of its own; a layout that fails to open leaves the one before.
import { writeFile } from './files.js';

const fileLike = /\.(png|jpe?g|gltf|glb|bin|json)$/i;

// The relative file names a layout or glTF text holds (its "texture",
// "model" and "uri" strings, and any other string naming a file).
function namedFiles(text) {
  const names = new Set();
  try {
    const walk = (v) => {
      if (typeof v === 'string') {
        if (fileLike.test(v) && !/^[a-z]+:/i.test(v) && !v.startsWith('/')) names.add(v);
      } else if (Array.isArray(v)) v.forEach(walk);
      else if (v && typeof v === 'object') Object.values(v).forEach(walk);
    };
    walk(JSON.parse(text));
  } catch (e) { /* not JSON: nothing named */ }
  return [...names];
}

let opened = 0;

export async function openFromUrl(module, url, openLayout, showMessage) {
  const base = new URL(url, location.href);
  const root = `/url${++opened}/`;
  const seen = new Set();
  let first = null;
  const fetchInto = async (rel, from) => {
    const at = new URL(rel, from);
    const key = at.href;
    if (seen.has(key)) return;
    seen.add(key);
    const response = await fetch(at);
    if (!response.ok) throw new Error(`${at.href}: ${response.status} ${response.statusText}`);
    const bytes = new Uint8Array(await response.arrayBuffer());
    const path = root + decodeURIComponent(new URL(at.href).pathname).replace(/^\/+/, '');
    writeFile(module.FS, path, bytes);
    if (!first) first = path;
    if (/\.(json|gltf)$/i.test(at.pathname)) {
      const text = new TextDecoder().decode(bytes);
      for (const name of namedFiles(text)) await fetchInto(name, at).catch(() => {});
    }
  };
  try {
    await fetchInto(base.href, base);
  } catch (e) {
    showMessage(`cannot load ${url}: ${e.message}`);
    if (opened === 1) openLayout('');
    return false;
  }
  return openLayout(first);
}

// Files the user dropped or picked: all written to one folder (keeping the
// folders a dropped folder had), and the layout among them opened: the
// .json file with "rooms" in it.
export async function openDropped(module, files, openLayout, showMessage) {
  if (files.length === 0) return false;
  const root = `/dropped${++opened}/`;
  let layout = null, anyJson = null;
  for (const file of files) {
    const name = (file.webkitRelativePath || file.name).replace(/^\/+/, '');
    const bytes = new Uint8Array(await file.arrayBuffer());
    writeFile(module.FS, root + name, bytes);
    if (/\.json$/i.test(name) && !anyJson) anyJson = root + name;
    if (/\.json$/i.test(name) && !layout) {
      const text = new TextDecoder().decode(bytes);
      if (/"rooms"\s*:/.test(text)) layout = root + name;
    }
  }
  layout = layout || anyJson;
  if (!layout) {
    showMessage('no layout among the dropped files (a .json file with "rooms")');
    return false;
  }
  // Files picked one by one lose their folders: a file the layout names as
  // "gallery/brick.png" is found by its name among the dropped ones.
  const byName = new Map(files.map((f) => [f.name, f]));
  const layoutDir = layout.slice(0, layout.lastIndexOf('/') + 1);
  for (const name of namedFiles(new TextDecoder().decode(module.FS.readFile(layout)))) {
    const wanted = layoutDir + name;
    if (module.FS.analyzePath(wanted).exists) continue;
    const file = byName.get(name.split('/').pop());
    if (file) writeFile(module.FS, wanted, new Uint8Array(await file.arrayBuffer()));
  }
  return openLayout(layout);
}
