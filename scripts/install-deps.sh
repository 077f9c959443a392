#!/usr/bin/env bash
# Install the system packages geocert builds against, on Debian (bookworm or later).
#   scripts/install-deps.sh demo   GMP and MPFR for rug (system libraries, see
#                                  Cargo.toml), m4, pkg-config, and gcc with the C
#                                  headers (gmp-mpfr-sys compiles small C programs to
#                                  probe the system libraries; Rust links through cc):
#                                  enough to build and run the binary and the library.
#   scripts/install-deps.sh test   (the default) also CGAL 5.5 (header-only, brings the
#                                  Boost headers) and g++ for the oracle of the tests.
# Does nothing when everything is installed; otherwise needs root, or sudo when it is
# there.
set -euo pipefail
packages=(libgmp-dev libmpfr-dev m4 pkg-config gcc libc6-dev)
if [ "${1:-test}" = "test" ]; then
  packages+=(libcgal-dev g++)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
sudo=()
if [ "$(id -u)" -ne 0 ]; then
  if ! command -v sudo >/dev/null 2>&1; then
    echo "geocert needs these packages: ${missing[*]}" >&2
    echo "Install them as root (apt-get install ${missing[*]}); sudo is not available." >&2
    exit 1
  fi
  sudo=(sudo)
fi
echo "installing: ${missing[*]}" >&2
"${sudo[@]}" apt-get update
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y "${missing[@]}"
