#!/usr/bin/env bash
# Builds the Debian package of spiral (CPack, see CMakeLists.txt): a Release
# build for the prefix /usr in build-deb/ (no tests), then
# build-deb/spiral_<version>_<arch>.deb. Install it with
#   apt install ./build-deb/spiral_*.deb
# and `spiral run /usr/share/spiral/scenarios/deepwater-fps.yaml` works from
# any directory.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh >/dev/null
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-deb -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr -DSPIRAL_BUILD_TESTS=OFF \
  "${launcher[@]}" >/dev/null
cmake --build build-deb --parallel "$(nproc)"
(cd build-deb && cpack -G DEB)
ls build-deb/spiral_*.deb
