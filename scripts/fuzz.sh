#!/usr/bin/env bash
# Fuzz the input readers (docs/fuzzing.md): builds the fuzz tree (build-fuzz/,
# clang, libFuzzer + ASan + UBSan) and runs each harness with its seed corpus.
#
#   bash scripts/fuzz.sh [SECONDS | -runs=N] [HARNESS ...]
#
# SECONDS per harness (default 60), or -runs=N executions per harness;
# harnesses: project moordyn motion wamit_1 wamit_3 wamit_4 wamit_hst wamit_12d
# wamit_gdf (default: all, one after the other on one core). Crashes, hangs
# (> 10 s an input) and sanitizer reports are written to
# build-fuzz/crashes/<harness>/; the grown corpus stays in
# build-fuzz/corpus/<harness>/ for the next run. Exit 1 if anything was found.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

limit=${1:-60}
[ $# -gt 0 ] && shift
if [[ $limit == -runs=* ]]; then
  run_flag=$limit
elif [[ $limit =~ ^[0-9]+$ ]]; then
  run_flag=-max_total_time=$limit
else
  echo "usage: scripts/fuzz.sh [SECONDS | -runs=N] [HARNESS ...]" >&2
  exit 2
fi
all=(project moordyn motion wamit_1 wamit_3 wamit_4 wamit_hst wamit_12d wamit_gdf)
harnesses=("$@")
[ ${#harnesses[@]} -eq 0 ] && harnesses=("${all[@]}")

if ! command -v clang++ > /dev/null; then
  if [ "$(id -u)" -eq 0 ]; then
    apt-get install -y --no-install-recommends clang
  else
    echo "fuzz.sh: clang++ not found (Debian: apt-get install clang)" >&2
    exit 2
  fi
fi

# Only the harnesses and the libraries they read with (engine, design/project,
# design/import) are built; ccache as the main build uses it, when present.
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(dirname "$root")}
if [ ! -f build-fuzz/build.ninja ]; then
  cmake -S . -B build-fuzz -G Ninja -DSPIRAL_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" "${launcher[@]}"
fi
targets=()
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
cmake --build build-fuzz -j2 --target "${targets[@]}"

# Seeds from seeds.txt. The WAMIT tables run to 1.2 MB of rows of one layout:
# they are cut to their first 100 lines and inputs kept under 8 kB, which
# multiplies the executions a second by ten and loses no variety of the format.
# Project files and decks go in whole (the default scenario is 25 kB). The
# regressions go in whole.
seed_corpus() {
  local harness=$1 dir=$2 h folder pattern file lines=100
  [[ $harness == project || $harness == moordyn ]] && lines=100000
  rm -rf "$dir"
  mkdir -p "$dir"
  while read -r h folder pattern; do
    [[ -z $h || $h == \#* || $h != "$harness" ]] && continue
    while IFS= read -r -d '' file; do
      head -n "$lines" "$file" > "$dir/$(echo "$file" | tr '/' '_')"
    done < <(find "$folder" -name "$pattern" -type f -print0)
  done < tests/fuzz/seeds.txt
  if [ -d "tests/fuzz/regressions/$harness" ]; then
    cp tests/fuzz/regressions/"$harness"/* "$dir"/ 2> /dev/null || true
  fi
}

export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
summary=()
found=0
for h in "${harnesses[@]}"; do
  seeds=build-fuzz/seeds/$h
  corpus=build-fuzz/corpus/$h
  crashes=build-fuzz/crashes/$h
  log=build-fuzz/logs/$h.log
  seed_corpus "$h" "$seeds"
  mkdir -p "$corpus" "$crashes" build-fuzz/logs
  echo "== $h ($run_flag)"
  set +e
  max_len=8192
  [[ $h == project || $h == moordyn ]] && max_len=65536
  "build-fuzz/tests/fuzz/fuzz_$h" "$run_flag" -timeout=10 -rss_limit_mb=2048 -max_len=$max_len -print_final_stats=1 \
    -artifact_prefix="$crashes/" "$corpus" "$seeds" > "$log" 2>&1
  status=$?
  set -e
  tail -n 12 "$log"
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  rate=$(grep -o 'exec/s: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
  artifacts=$(find "$crashes" -type f | wc -l)
  [ "$status" -ne 0 ] || [ "$artifacts" -gt 0 ] && found=1
  summary+=("$(printf '%-10s %12s executions  %8s exec/s  exit %d  %d artifact(s) in %s' "$h" "${runs:-?}" "${rate:-?}" \
    "$status" "$artifacts" "$crashes")")
done
echo
echo "== summary ($(date -u '+%Y-%m-%d %H:%M UTC'))"
printf '%s\n' "${summary[@]}"
exit $found
