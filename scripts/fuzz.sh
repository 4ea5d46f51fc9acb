#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with clang-16, ASan and UBSan into build-fuzz/, replays each
# target's regression inputs (fuzz/regressions/<target>/, every crash found so far), then fuzzes
# each target for SECONDS (default 5) on a copy of its seed corpus, so the repository is never
# modified. Prints the inputs tried per target; exits nonzero on any crash, leak, UB or timeout.
# Usage: scripts/fuzz.sh [SECONDS]   (longer runs: scripts/fuzz.sh 600)
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET=${1:-5}
TARGETS=(cue disc exe state memcard cpu gpu input_script level_map integration memsearch)

export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
CC=clang-16 CXX=clang++-16 cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPSXRL_FUZZ=ON -DPSXRL_BUILD_TESTS=OFF "${launcher[@]}" >/dev/null
cmake --build build-fuzz --target "${TARGETS[@]/#/fuzz_}"

# Scratch: corpus copies, crash artifacts and logs; the memory-card target's image writes are
# synced, so a memory-backed temp folder keeps them cheap where there is one.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -w /dev/shm ] && export TMPDIR=/dev/shm
failed=()
for t in "${TARGETS[@]}"; do
  bin=build-fuzz/fuzz/fuzz_$t
  mkdir -p "$work/$t/corpus" "$work/$t/artifacts"
  cp -r fuzz/corpus/$t/. "$work/$t/corpus/"
  opts=(-rss_limit_mb=2048 -timeout=10 -artifact_prefix="$work/$t/artifacts/")
  regressions=(fuzz/regressions/$t/*)
  if [ -e "${regressions[0]}" ] && ! "$bin" "${opts[@]}" "${regressions[@]}" >"$work/$t/regress.log" 2>&1; then
    tail -n 40 "$work/$t/regress.log"
    failed+=("$t (regression input)")
    continue
  fi
  if "$bin" "${opts[@]}" -max_total_time="$SECONDS_PER_TARGET" -print_final_stats=1 "$work/$t/corpus" \
    >"$work/$t/fuzz.log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$t/fuzz.log")
    echo "fuzz: $t: ${runs:-?} inputs, no crash"
  else
    tail -n 40 "$work/$t/fuzz.log"
    mkdir -p build-fuzz/crashes/$t
    cp "$work/$t/artifacts/"* build-fuzz/crashes/$t/ 2>/dev/null || true
    echo "fuzz: $t: CRASH (input kept in build-fuzz/crashes/$t/)"
    failed+=("$t")
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: failed: ${failed[*]}" >&2
  exit 1
fi
