#!/usr/bin/env bash
# Installs dependencies, builds, and runs every test: GoogleTest units and test programs (CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
ctest --test-dir build --output-on-failure -j2
