#!/usr/bin/env bash
# Checks that every C++ source follows .clang-format (Debian's clang-format).
# Usage: scripts/check-format.sh [--fix]   (--fix rewrites the files instead)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
command -v clang-format >/dev/null || "$root/scripts/setup.sh" clang-format
mapfile -t files < <(git ls-files 'src/*.cpp' 'src/*.hpp' 'tests/*.cpp' 'tests/*.hpp' 'tools/*.cpp' 'tools/*.hpp' \
                                  'bench/*.cpp' 'bench/*.hpp' 'examples/*.cpp' 'python/*.cpp')
if [ "${1:-}" = "--fix" ]; then
    clang-format -i "${files[@]}"
    exit 0
fi
if ! clang-format --dry-run -Werror "${files[@]}" 2>/tmp/check-format.$$; then
    grep -E "^[^ ].*: error" /tmp/check-format.$$ | sed 's/: error.*//' | sort -u | head -20
    echo "check-format: the files above differ from .clang-format; run scripts/check-format.sh --fix"
    rm -f /tmp/check-format.$$
    exit 1
fi
rm -f /tmp/check-format.$$
echo "check-format: ${#files[@]} files follow .clang-format"
