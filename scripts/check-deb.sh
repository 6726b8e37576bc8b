#!/usr/bin/env bash
# Checks the Debian package the way a user meets it (issue 18 §4): a clean
# Debian 12 root made by debootstrap (minbase: nothing of spiral's
# dependencies installed), `apt install ./spiral_*.deb` inside it, then the
# installed spiral runs an installed scenario from another directory.
#
#   sudo bash scripts/check-deb.sh [DEB] [ROOT]
#
# DEB: default build-deb/spiral_*_amd64.deb (bash scripts/package.sh makes it);
# ROOT: the folder for the clean root (default /tmp/spiral-clean-root, made
# afresh). Needs root, debootstrap and Debian's mirror; takes a few minutes
# and ~1 GB. Not part of CTest (root and network); its result is recorded in
# README.md.
set -euo pipefail
cd "$(dirname "$0")/.."
deb=${1:-$(ls build-deb/spiral_*_amd64.deb | tail -1)}
root=${2:-/tmp/spiral-clean-root}
mirror=${SPIRAL_DEBIAN_MIRROR:-http://deb.debian.org/debian}
[ "$(id -u)" -eq 0 ] || { echo "check-deb.sh: run as root (debootstrap, chroot)" >&2; exit 2; }
command -v debootstrap > /dev/null || apt-get install -y --no-install-recommends debootstrap

rm -rf "$root"
debootstrap --variant=minbase bookworm "$root" "$mirror"
mount --bind /proc "$root/proc"
trap 'umount "$root/proc" 2> /dev/null || true' EXIT
cp "$deb" "$root/tmp/"
chroot "$root" apt-get update
chroot "$root" env DEBIAN_FRONTEND=noninteractive apt-get install -y "/tmp/$(basename "$deb")"
# From a directory that is not the install's: the scenario finds its own data.
chroot "$root" sh -c 'cd /tmp && spiral --version && spiral validate /usr/share/spiral/scenarios/oc4-semisubmersible.yaml &&
  spiral run /usr/share/spiral/scenarios/oc4-semisubmersible.yaml --out /tmp/run-oc4 --until preliminary'
chroot "$root" test -f /tmp/run-oc4/preliminary/report.pdf
chroot "$root" test -f /tmp/run-oc4/summary/report.pdf
# The Python package (python3 and numpy are the package's Recommends, which apt installs).
chroot "$root" sh -c 'cd /tmp && python3 -c "import spiral; print(\"import spiral:\", spiral.__file__)"'
echo "check-deb.sh: $(basename "$deb") installs and runs in a clean Debian 12 root ($root)"
