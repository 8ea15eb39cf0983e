#!/usr/bin/env bash
# The install test (CTest "install", cmake/install.cmake; docs/api.md):
# installs the build into a temporary prefix, builds and runs
# examples/embed against it with find_package (CMake) and examples/headless
# with pkg-config, runs the installed CLI, then builds the .deb with CPack,
# checks what it holds, unpacks it and builds examples/headless against that.
# The .deb is left in the build directory (README, "Use it from other programs").
# Usage: install_test.sh SOURCE_DIR BUILD_DIR CMAKE CPACK CXX GENERATOR
set -euo pipefail
src=$1 build=$2 cmake=$3 cpack=$4 cxx=$5 generator=$6
tmp=$(mktemp -d "${TMPDIR:-/tmp}/impossible-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
fail() { echo "install_test: $*" >&2; exit 1; }
step() { echo "--- $* ($SECONDS s)"; }
has() { grep -qE -- "$2" "$1" || { cat "$1"; fail "$1 does not match: $2"; }; }

step "docs/api.md shows the examples' code"
# Each code block after a "<!-- FILE -->" line is FILE's text: runs of its
# lines in order, "// ..." lines standing for what is left out.
python3 - "$src" <<'PY' || fail "docs/api.md: a code block differs from the file it names (above)"
import re, sys
src = sys.argv[1]
doc = open(f"{src}/docs/api.md").read()
blocks = re.findall(r"<!-- (\S+) -->\n```\w*\n(.*?)```", doc, re.S)
assert len(blocks) >= 3, "docs/api.md: fewer than 3 marked code blocks"
for name, block in blocks:
    lines, at, run = open(f"{src}/{name}").read().split("\n"), 0, []
    for line in block.split("\n")[:-1] + ["// ..."]:
        if line.strip().startswith("// ..."):
            found = next((i for i in range(at, len(lines)) if lines[i:i + len(run)] == run), None)
            if found is None:
                sys.exit(f"docs/api.md: these lines are not in {name}:\n" + "\n".join(run))
            at, run = found + len(run), []
        else:
            run.append(line)
PY

step "cmake --install into $prefix"
"$cmake" --install "$build" --prefix "$prefix" >"$tmp/install.log"
version=$(sed -n 's/^#define IMPOSSIBLE_VERSION "\(.*\)"$/\1/p' "$prefix/include/impossible/version.hpp")
[ -n "$version" ] || fail "no IMPOSSIBLE_VERSION in the installed version.hpp"
soversion=${version%.*}
libdir=$(dirname "$(find "$prefix" -name "libimpossible.so.$version" | head -1)")
[ -d "$libdir" ] || fail "no libimpossible.so.$version under $prefix"
for f in "$prefix/bin/impossible" "$prefix/include/impossible/impossible.hpp" "$libdir/libimpossible.so" \
         "$libdir/libimpossible.so.$soversion" "$libdir/cmake/impossible/impossibleConfig.cmake" \
         "$libdir/cmake/impossible/impossibleConfigVersion.cmake" "$libdir/cmake/impossible/impossibleTargets.cmake" \
         "$libdir/pkgconfig/impossible.pc"; do
    [ -e "$f" ] || fail "not installed: $f"
done
# Only the API is exported: no glad, nlohmann or internal module symbols.
nm -D --defined-only -C "$libdir/libimpossible.so" | awk '$2 ~ /[TWVBD]/' >"$tmp/symbols.txt"
has "$tmp/symbols.txt" 'impossible::api::Renderer::in_current_context'
if grep -vE ' impossible::api::' "$tmp/symbols.txt" | grep -vE ' (_init|_fini)$' >"$tmp/extra.txt"; then
    cat "$tmp/extra.txt"
    fail "libimpossible.so exports symbols outside impossible::api"
fi

step "the installed Python module"
[ -x /usr/bin/python3 ] || fail "no /usr/bin/python3 (scripts/setup.sh installs it)"
module=$(find "$prefix/lib/python3/dist-packages" -name 'impossible*.so' | head -1)
[ -n "$module" ] || fail "the Python module is not installed under $prefix/lib/python3/dist-packages"
PYTHONPATH=$prefix/lib/python3/dist-packages /usr/bin/python3 -c \
    'import impossible, sys; l = impossible.builtin(); sys.exit(0 if impossible.__version__ == sys.argv[1] and l.start_room == "hall" else 1)' \
    "$version" || fail "the installed Python module does not import and load the built-in layout"

step "the installed CLI"
"$prefix/bin/impossible" render --size 64x48 --out "$tmp/cli.png" >"$tmp/cli.log" 2>&1 || {
    cat "$tmp/cli.log"
    fail "the installed impossible render failed"
}
[ -s "$tmp/cli.png" ] || fail "the installed impossible render wrote no image"

step "examples/embed with find_package(impossible)"
"$cmake" -S "$src/examples/embed" -B "$tmp/embed-build" -G "$generator" -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF \
    >"$tmp/embed-configure.log"
has "$tmp/embed-build/CMakeCache.txt" "^impossible_DIR:PATH=$libdir/cmake/impossible\$"
"$cmake" --build "$tmp/embed-build" >"$tmp/embed-build.log"
ldd "$tmp/embed-build/embed" >"$tmp/embed-ldd.txt"
has "$tmp/embed-ldd.txt" "libimpossible\.so\.$soversion => $libdir/"
"$tmp/embed-build/embed" "" "$tmp/embed.ppm" >"$tmp/embed.log" 2>&1 && embed_status=0 || embed_status=$?
# An empty layout path is an error, named on one line.
[ "$embed_status" -eq 1 ] || { cat "$tmp/embed.log"; fail "embed with an empty layout path exited $embed_status"; }
"$tmp/embed-build/embed" "$src/layouts/default.json" "$tmp/embed.ppm" >"$tmp/embed.log" 2>&1 || {
    cat "$tmp/embed.log"
    fail "examples/embed failed"
}
has "$tmp/embed.log" "^impossible $version on "
has "$tmp/embed.log" '^frame [0-9]+: room [a-z]+, [0-9]+ portal passes, teleport through '
has "$tmp/embed.log" '^walked [0-9]+ frames, [1-9][0-9]* teleports; frame [0-9]+ \(320x120, [1-9][0-9]* portal passes\): ([2-9]|[1-9][0-9]+) colours, 0 pixels differ from render\(\)$'
head -c 15 "$tmp/embed.ppm" | grep -q "^P6" || fail "examples/embed wrote no PPM"
tail -1 "$tmp/embed.log"

step "examples/headless with pkg-config"
export PKG_CONFIG_PATH=$libdir/pkgconfig
flags=$(pkg-config --cflags --libs impossible | sed "s/ *$//")
[ "$flags" = "-I$prefix/include -L$libdir -limpossible" ] || fail "pkg-config --cflags --libs impossible: $flags"
[ "$(pkg-config --modversion impossible)" = "$version" ] || fail "pkg-config --modversion impossible is not $version"
# shellcheck disable=SC2086  # the flags are words
"$cxx" -std=c++17 -O2 "$src/examples/headless/main.cpp" -o "$tmp/headless" $flags -Wl,-rpath,"$libdir"
"$tmp/headless" >"$tmp/headless.log" 2>&1 || { cat "$tmp/headless.log"; fail "examples/headless failed"; }
has "$tmp/headless.log" "^impossible $version, .*: .+, rooms hall annex\$"
has "$tmp/headless.log" '^render 640x240: [1-9][0-9]* draw calls, [1-9][0-9]* portal passes; trace: [0-9]+ of 153600 cell ids differ$'
# The tracer and the rasteriser agree but for edge pixels (docs/accuracy.md).
differ=$(sed -n 's/.*trace: \([0-9]*\) of.*/\1/p' "$tmp/headless.log")
[ "$differ" -lt 1536 ] || fail "render and trace differ in $differ cell ids (1 % or more)"
# docs/api.md shows the line the program prints (on llvmpipe), counts and all.
shown=$(grep -m1 '^render 640x240:' "$src/docs/api.md")
printed=$(grep -m1 '^render 640x240:' "$tmp/headless.log")
[ "$printed" = "$shown" ] || fail "docs/api.md shows '$shown', examples/headless printed '$printed'"
"$tmp/headless" "$tmp/no-such.json" >"$tmp/headless-bad.log" 2>&1 && fail "examples/headless loaded a missing file"
has "$tmp/headless-bad.log" "no-such\.json"
cat "$tmp/headless.log"

step "cpack -G DEB"
"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$tmp/cpack" >"$tmp/cpack.log" 2>&1 || {
    cat "$tmp/cpack.log"
    fail "cpack failed"
}
deb=$tmp/cpack/impossible_${version}_$(dpkg --print-architecture).deb
[ -f "$deb" ] || { cat "$tmp/cpack.log"; fail "cpack wrote no $(basename "$deb")"; }
dpkg-deb -c "$deb" | awk '{print $6}' >"$tmp/deb-files.txt"
for f in ./usr/bin/impossible "./usr/lib/libimpossible.so.$version" ./usr/lib/libimpossible.so \
         ./usr/include/impossible/impossible.hpp ./usr/include/impossible/version.hpp \
         ./usr/lib/cmake/impossible/impossibleConfig.cmake ./usr/lib/cmake/impossible/impossibleTargets.cmake \
         ./usr/lib/pkgconfig/impossible.pc ./usr/share/doc/impossible/api.md \
         ./usr/share/doc/impossible/examples/embed/main.cpp ./usr/share/doc/impossible/python.md; do
    grep -qxF "$f" "$tmp/deb-files.txt" || { cat "$tmp/deb-files.txt"; fail "the .deb lacks $f"; }
done
grep -qE '^\./usr/lib/python3/dist-packages/impossible\..+\.so$' "$tmp/deb-files.txt" ||
    fail "the .deb lacks the Python module under /usr/lib/python3/dist-packages"
dpkg-deb -f "$deb" Package Version Maintainer Depends >"$tmp/deb-fields.txt"
has "$tmp/deb-fields.txt" '^Package: impossible$'
has "$tmp/deb-fields.txt" "^Version: $version\$"
has "$tmp/deb-fields.txt" '^Maintainer: .+'
for lib in libegl1 libosmesa6 libglfw3 libstdc\\+\\+6; do has "$tmp/deb-fields.txt" "^Depends: .*\\b$lib\\b"; done
# Its files work where they land: unpacked, the .pc names /usr, so build
# against the unpacked tree with the .pc's own flags rewritten to it.
dpkg-deb -x "$deb" "$tmp/deb-root"
has "$tmp/deb-root/usr/lib/pkgconfig/impossible.pc" '^prefix=/usr$'
"$cxx" -std=c++17 -O2 "$src/examples/headless/main.cpp" -o "$tmp/headless-deb" -I"$tmp/deb-root/usr/include" \
    -L"$tmp/deb-root/usr/lib" -limpossible -Wl,-rpath,"$tmp/deb-root/usr/lib"
"$tmp/headless-deb" >"$tmp/headless-deb.log" 2>&1 || { cat "$tmp/headless-deb.log"; fail "headless on the .deb's library failed"; }
cmp -s "$tmp/headless.log" "$tmp/headless-deb.log" || fail "headless prints other lines on the .deb's library"
cp "$deb" "$build/"
step "done: $build/$(basename "$deb"), $(du -k "$deb" | cut -f1) KiB"
