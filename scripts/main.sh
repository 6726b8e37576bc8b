#!/usr/bin/env bash
# The main job: set up, build, then run the default scenario through the design spiral.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
scenario=scenarios/deepwater-fps.yaml
./build/app/spiral validate "$scenario"
./build/app/spiral statics "$scenario"
./build/app/spiral report "$scenario" --out out/deepwater-fps
