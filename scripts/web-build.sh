#!/usr/bin/env bash
# Builds the web build (docs/web.md): the renderer compiled to WebAssembly by
# Debian's emscripten into build-web/, the page as static files in
# build-web/site/, and the browser tests' npm packages (web/package-lock.json)
# in web/node_modules. Installs Debian's emscripten and chromium first when
# they are missing.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh" emscripten chromium
command -v npm >/dev/null || { echo "web-build: needs node and npm (node 20)" >&2; exit 1; }
# Emscripten's optimiser finds its node modules in Debian's folder.
export NODE_PATH=/usr/share/nodejs
if [ ! -f "$root/build-web/build.ninja" ]; then
  emcmake cmake -S "$root" -B "$root/build-web" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$root/build-web" -j"$(nproc)"
if [ ! -f "$root/web/node_modules/.package-lock.json" ] ||
   [ "$root/web/package-lock.json" -nt "$root/web/node_modules/.package-lock.json" ]; then
  (cd "$root/web" && npm ci --no-audit --no-fund --loglevel=error)
fi
