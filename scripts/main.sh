#!/usr/bin/env bash
# The main job: set up, build, then run the default scenario through the
# design spiral (`spiral run`): the preliminary stage (static cases, code
# check, riser SOZ, the governing case's S-C storm), the intermediate stage
# (an enhanced S-C 3-h storm of every load case, ranked) and the advanced
# stage (the critical cases fully coupled, 600 s each as the scenario sets;
# `--full` for 3 h), with pretension feedback when the offsets or tensions
# fail. Every task is kept in out/deepwater-fps/results.sqlite: running this
# again resumes and finishes in seconds. Then the pretension optimization
# report with its trade-off study.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
scenario=scenarios/deepwater-fps.yaml
./build/app/spiral validate "$scenario"
./build/app/spiral run "$scenario" --out out/deepwater-fps || [ $? -eq 3 ]  # 3: a solver failed; reports written
./build/app/spiral results out/deepwater-fps
./build/app/spiral report "$scenario" --stage optimization --out out/deepwater-fps/optimization
