#!/usr/bin/env bash
# Builds the libFuzzer targets alone in a clang tree and runs each for a fixed
# time from its committed corpus; any finding (crash, sanitizer report, leak,
# timeout, out of memory) fails the script. CI runs it after the tests.
# Usage: scripts/fuzz.sh [SECONDS]   (per fuzzer; default 60)
#
# The fuzzers (tests/fuzz/, docs/layout-limits.md "Fuzzing the parsers"):
#   layout_fuzzer  the layout loader      seeds tests/fuzz/layout_corpus
#   path_fuzzer    the path-file parser   seeds tests/fuzz/path_corpus
#   gltf_fuzzer    the glTF loader        seeds tests/fuzz/gltf_corpus, layouts/**/*.glb
# Each runs on a copy of its corpus in a temporary folder (the committed one
# is never changed), as many at a time as there are cores, with -timeout=10
# -rss_limit_mb=2048. A finding is kept under BUILD/findings/NAME/ and its
# report is printed; reproduce it with BUILD/tests/NAME FILE.
# Environment: IMPOSSIBLE_FUZZ_BUILD (default build-fuzz/ in the repository),
# IMPOSSIBLE_FUZZ_JOBS (default: the number of cores).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
if ! [[ $seconds =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: scripts/fuzz.sh [SECONDS]" >&2
  exit 2
fi
build=${IMPOSSIBLE_FUZZ_BUILD:-$root/build-fuzz}
jobs=${IMPOSSIBLE_FUZZ_JOBS:-$(nproc)}
fuzzers=(layout_fuzzer path_fuzzer gltf_fuzzer)

# The project's packages, then clang with its libFuzzer and sanitizer runtimes
# (libclang-rt-14-dev is only recommended by clang, so asked for by name) and
# llvm-symbolizer for the reports, through setup.sh: only what is missing.
"$root/scripts/setup.sh" clang libclang-rt-14-dev llvm

# Only the three programs and the libraries they link.
start=$SECONDS
generator=()
[ -f "$build/CMakeCache.txt" ] || generator=(-G Ninja)
CC=clang CXX=clang++ cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DIMPOSSIBLE_FUZZER=ON >/dev/null
cmake --build "$build" --target "${fuzzers[@]}" -j"$(nproc)"
echo "fuzz: built ${fuzzers[*]} in $((SECONDS - start)) s"

work=$(mktemp -d "${TMPDIR:-/tmp}/impossible-fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT
findings=$build/findings
rm -rf "$findings"

# Sets up NAME's folder under $work (its corpus copy, and what its inputs may
# name) and runs it; its exit status and log stay in the folder.
run_one() {
  local name=$1 dir=$work/$1
  mkdir -p "$dir/corpus" "$findings/$name"
  echo 1 >"$dir/rc"
  : >"$dir/log"
  case $name in
    layout_fuzzer)
      # Layouts name textures and models relative to the current folder.
      cp "$root"/tests/fuzz/layout_corpus/* "$dir/corpus/"
      cp -r "$root/layouts/gallery" "$root/layouts/models" "$dir/" ;;
    path_fuzzer)
      cp "$root"/tests/fuzz/path_corpus/* "$dir/corpus/" ;;
    gltf_fuzzer)
      cp "$root"/layouts/gallery/*.glb "$root"/layouts/models/*.glb "$dir/corpus/"
      cp "$root"/tests/fuzz/gltf_corpus/* "$dir/corpus/" ;;
  esac
  local rc=0
  (
    cd "$dir"
    ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=0 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      timeout --kill-after=30 $((seconds * 2 + 120)) \
      "$build/tests/$name" corpus -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        -print_final_stats=1 -artifact_prefix="$findings/$name/" </dev/null >"$dir/log" 2>&1
  ) || rc=$?
  echo "$rc" >"$dir/rc"
}

pids=()
for name in "${fuzzers[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  run_one "$name" &
  pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid" || true; done

failed=0
for name in "${fuzzers[@]}"; do
  dir=$work/$name
  rc=$(cat "$dir/rc" 2>/dev/null || echo 1)
  done_line=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$dir/log" | tail -1 || true)
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$dir/log" | tail -1)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$done_line")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$done_line")
  corp=$(sed -n 's/.* corp: \([0-9]*\/[0-9a-zA-Z]*\).*/\1/p' <<<"$done_line")
  artifacts=$(find "$findings/$name" -type f 2>/dev/null | sort)
  if [ "$rc" -eq 0 ] && [ -n "$done_line" ] && [ -z "$artifacts" ]; then
    echo "fuzz: $name: ${runs:-?} inputs in $seconds s (${rate:-?}/s), cov ${cov:-?}, ft ${ft:-?}, corpus ${corp:-?}: no finding"
  else
    failed=1
    echo "fuzz: $name FAILED (exit status $rc); the end of its log:" >&2
    tail -n 80 "$dir/log" >&2
    if [ -n "$artifacts" ]; then
      echo "fuzz: $name: reproduce with: $build/tests/$name FILE, FILE one of:" >&2
      sed 's/^/  /' <<<"$artifacts" >&2
    fi
  fi
done
exit "$failed"
