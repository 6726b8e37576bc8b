#!/usr/bin/env bash
# The main job: set up, build, then run the default scenario through the
# stages that exist today: validation, mooring statics, the preliminary
# stage's static analyses with their report, the pretension optimization
# (largest SOZ margin, with its report and pretension study; `spiral optimize`
# also writes the optimized project), the riser safe operational zones
# (catenary screening model; `--model fe` is the slower reference), a
# semi-coupled 3-hour storm of the first load case and the first 10 minutes
# of the same storm fully coupled (hull + every mooring line and riser as
# dynamic FE lines; the whole 3 hours take ≈ 10 minutes on 2 cores).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
scenario=scenarios/deepwater-fps.yaml
./build/app/spiral validate "$scenario"
./build/app/spiral statics "$scenario"
./build/app/spiral report "$scenario" --out out/deepwater-fps
./build/app/spiral report "$scenario" --stage optimization --out out/deepwater-fps/optimization
./build/app/spiral soz "$scenario" --model catenary --step-deg 15
./build/app/spiral analyze "$scenario" --case lc1-survival-collinear-0deg --level sc-enhanced \
  --out out/deepwater-fps/analyze
./build/app/spiral analyze "$scenario" --case lc1-survival-collinear-0deg --level coupled --duration 600 \
  --out out/deepwater-fps/analyze-coupled
