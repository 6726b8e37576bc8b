#!/usr/bin/env bash
# Installs the Debian packages spiral needs (idempotent, non-interactive) and
# builds it in Release into ./build. Safe to run again: it installs only what is
# missing and rebuilds incrementally.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libsundials-dev libnlopt-cxx-dev libnlopt-dev libyaml-cpp-dev
  libosmesa6-dev libcli11-dev libfmt-dev libspdlog-dev libcairo2-dev libsqlite3-dev
  nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libopenmpi-dev openmpi-bin
  poppler-utils fonts-dejavu-core clang-format
  python3-dev python3-pybind11 python3-numpy python3-pytest python3-matplotlib
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# Configure when there is no build yet or packages were just installed (the
# optional features, e.g. MPI, are found at configure time); otherwise ninja
# re-runs CMake itself when a CMakeLists or a globbed folder changes (3 s
# saved on every run of the two commands).
if [ ! -f build/build.ninja ] || [ ${#missing[@]} -gt 0 ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build build --parallel "$(nproc)"
