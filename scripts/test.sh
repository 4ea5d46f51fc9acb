#!/usr/bin/env bash
# Installs dependencies, builds, and runs every test: GoogleTest units and test programs (CTest),
# in the release build and again in a sanitizer build.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# -j3 on 2 cores: the window tests play in real time and mostly wait.
ctest --test-dir build --output-on-failure -j3

# The same tests again under AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer:
# guest programs and user files must never make the emulator touch memory it does not own, leak,
# or rely on undefined C++. Any finding exits with 99, a code no psxrl run uses, so that it
# cannot pass for an expected exit code (tests/expect.cmake also reports it as a sanitizer error).
# No benchmark programs there: they are never tests, and would only add compile and link time.
export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR=$PWD
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPSXRL_SANITIZE=ON -DPSXRL_BUILD_BENCH=OFF >/dev/null
cmake --build build-sanitize
# tests/lsan.supp names the system libraries (X11, Mesa, SDL) whose process-lifetime allocations
# LeakSanitizer would otherwise report; psxrl's own allocations are never suppressed.
# Five long replays of whole Tumble levels run in the release pass only: under the sanitizers they
# took 100 CPU-seconds and reach no code that the shorter Tumble tests here do not. So does the
# SPU batching check without idle skipping (49 s there), whose twin with idle skipping stays.
long_replays='^(MemsearchTumble\.FindsTheContractFromWhatAPlayerKnows|TumbleLevels\.EveryLevelCanBeWonInTime|'
long_replays+='GlTumble\.Scale4Level1PictureIs1280x960AndMatchesTheRegressionImage|'
long_replays+='TumblePlaythrough\.Levels1And2ByThePadReachTheExitWithFullScores|'
long_replays+='SpuLazy\.TumbleTitleAndLevelSameWithBatchingIdleSkipOff|'
long_replays+='Determinism\.SameProgramSameHashesEveryFrame|'
# The 50,000-move soak measures host memory, which ASan's quarantine and shadow memory would swamp.
long_replays+='Soak\.FiftyThousandMovesKeepHostMemoryFlat)$'
ASAN_OPTIONS=detect_leaks=1:exitcode=99 UBSAN_OPTIONS=exitcode=99:print_stacktrace=1 \
  LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp ctest --test-dir build-sanitize --output-on-failure -j3 \
  -E "$long_replays"

# Every parser of user files and the CPU/GPU guest side fuzzed briefly (fuzz/, scripts/fuzz.sh):
# past crashes are replayed and a few seconds per target look for new ones.
scripts/fuzz.sh 3
