#!/usr/bin/env bash
# Set up, build, and run every test through CTest (benchmarks are built, not run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
