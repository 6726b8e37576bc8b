#!/usr/bin/env bash
# Runs clang-tidy (.clang-tidy's small set) on the C++ sources a change
# touches: the files changed against REV (default: origin's main, else HEAD~1),
# or the files given. Needs a configured build (compile_commands.json).
#   bash scripts/tidy.sh [--base REV] [FILE...]
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-tidy >/dev/null || { echo "tidy: install Debian's clang-tidy" >&2; exit 2; }
[ -f build/compile_commands.json ] || { echo "tidy: configure first (bash scripts/setup.sh)" >&2; exit 2; }
base=""
if [ "${1:-}" = "--base" ]; then base="$2"; shift 2; fi
if [ $# -gt 0 ]; then
  files=("$@")
else
  [ -n "$base" ] || base=$(git rev-parse -q --verify origin/main || git rev-parse HEAD~1)
  mapfile -t files < <(git diff --name-only --diff-filter=AM "$base" -- '*.cpp' | grep -E '^(engine|design|report|app)/' || true)
fi
[ ${#files[@]} -gt 0 ] || { echo "tidy: no C++ source changed"; exit 0; }
clang-tidy -p build --quiet "${files[@]}"
