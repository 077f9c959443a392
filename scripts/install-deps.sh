#!/usr/bin/env bash
# Install the system packages geocert builds against, on Debian (bookworm or later):
# GMP and MPFR for rug (system libraries, see Cargo.toml), CGAL 5.5 (header-only,
# brings the Boost headers) for the oracle. Needs root or sudo; does nothing when
# everything is already installed.
set -euo pipefail
packages=(libgmp-dev libmpfr-dev libmpc-dev libcgal-dev m4 pkg-config g++)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "installing: ${missing[*]}" >&2
$sudo apt-get update
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y "${missing[@]}"
