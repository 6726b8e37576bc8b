#!/usr/bin/env bash
# Rewrites the golden regression baselines (tests/regression/baselines/) from
# the current build. Run it only for a change that moves numbers on purpose,
# and commit the new baselines on their own with the reason in the message.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
SPIRAL_GOLDEN_UPDATE=1 ctest --test-dir build -L golden --parallel "$(nproc)" --output-on-failure
git status --short tests/regression/baselines
