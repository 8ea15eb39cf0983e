// The page in headless Chromium (Debian's, on SwiftShader's WebGL 2), served
// from build-web/site on a loopback port: for scripts/web-render and the
// browser tests. playwright-core drives it; iwer, when asked, emulates the
// headset (a Meta Quest 3) before the page's script runs.
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { createRequire } from 'node:module';

const here = path.dirname(fileURLToPath(import.meta.url));
export const repoRoot = path.resolve(here, '../..');
const require = createRequire(import.meta.url);
const { chromium } = require('playwright-core');

const types = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.css': 'text/css',
                '.wasm': 'application/wasm', '.json': 'application/json', '.png': 'image/png' };

// Serves `root` on 127.0.0.1 at a free port (and, for files not there,
// `fallback`: the tests' layouts); resolves to {server, url}.
export function serve(root, fallback = null) {
  const server = http.createServer((req, res) => {
    const rel = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    const inside = (dir) => path.join(dir, path.normalize(rel === '/' ? '/index.html' : rel));
    let file = inside(root);
    if (fallback && !fs.existsSync(file)) file = inside(fallback);
    if (!(file.startsWith(root) || (fallback && file.startsWith(fallback))) || !fs.existsSync(file) ||
        !fs.statSync(file).isFile()) {
      res.writeHead(404);
      res.end('not found');
      return;
    }
    res.writeHead(200, { 'content-type': types[path.extname(file)] || 'application/octet-stream' });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () =>
    resolve({ server, url: `http://127.0.0.1:${server.address().port}/` })));
}

export function siteDir() {
  const dir = process.env.IMPOSSIBLE_WEB_SITE || path.join(repoRoot, 'build-web', 'site');
  if (!fs.existsSync(path.join(dir, 'impossible.wasm')))
    throw new Error(`no web build at ${dir} (build it with scripts/web-build.sh)`);
  return dir;
}

// Chromium's flags: software WebGL 2 (SwiftShader), and none of its
// background traffic, which this machine's closed network refuses.
const chromiumArgs = ['--headless=new', '--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader',
  '--use-gl=angle', '--ignore-gpu-blocklist', '--disable-gpu-sandbox', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync', '--mute-audio'];

// Opens the page; with `xr`, iwer's emulated headset is installed first.
// Resolves to {browser, page, server, close()}.
export async function openPage({ xr = false, query = '', width = 1280, height = 800, serveRepo = false } = {}) {
  const { server, url } = await serve(siteDir(), serveRepo ? repoRoot : null);
  const browser = await chromium.launch({ executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
                                          args: chromiumArgs, headless: true });
  const page = await browser.newPage({ viewport: { width, height } });
  const logs = [];
  page.on('console', (m) => logs.push(m.text()));
  page.on('pageerror', (e) => logs.push('page error: ' + e.message));
  if (xr) {
    await page.addInitScript({ path: require.resolve('iwer/build/iwer.min.js') });
    await page.addInitScript(() => {
      const device = new IWER.XRDevice(IWER.metaQuest3);
      device.installRuntime({ forceInstall: true });
      device.stereoEnabled = true;
      window.emulatedHeadset = device;
    });
  }
  await page.goto(url + (query ? '?' + query : ''));
  await page.waitForFunction(() => window.impossible && window.impossible.ready, null, { timeout: 60000 })
    .catch((e) => { throw new Error(e.message + '\n' + logs.join('\n')); });
  const close = async () => { await browser.close(); server.close(); };
  return { browser, page, server, logs, close };
}
