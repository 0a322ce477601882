#!/usr/bin/env bash
# Installs everything FleCSPH-lite needs on a fresh Debian bookworm machine, idempotently:
# Debian packages (MPI, parallel HDF5, Eigen, Catch2 v2, build and plot tools) and a Kokkos
# source tree for CMake's FetchContent when the upstream release cannot be downloaded.
# A second run installs nothing and takes a few seconds.
#
# FLECSPH_INSTALL_CLIENTS=1 (scripts/run_tests.sh sets it) also installs the viewers that the
# client tests (tests/clients) run on our output: ParaView's pvpython, with Xvfb since Debian's
# ParaView renders through X even offscreen, and splash (about 150 MB to download and 800 MB on
# disk, 2 minutes to install), and python3-venv for the snapshot readers that
# scripts/install_snapshot_clients.sh installs (scripts/build.sh runs it while the code builds).
# The main job does without them.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deps="$here/.deps"

packages=(
  build-essential cmake ninja-build pkg-config curl ca-certificates git
  libopenmpi-dev openmpi-bin libhdf5-openmpi-dev hdf5-tools
  libeigen3-dev catch2
  python3 python3-numpy python3-h5py python3-matplotlib
)
if [ "${FLECSPH_INSTALL_CLIENTS:-0}" = 1 ]; then
  packages+=(python3-paraview xvfb splash python3-venv clang-format)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "install-deps: installing Debian packages: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "install-deps: Debian packages already installed"
fi

# Kokkos source for offline builds (../shared/KOKKOS.md): the Kokkos team's pykokkos-base 0.0.7
# sdist on PyPI carries the complete Kokkos 3.4.01 tree. Used only when CMake cannot find an
# installed Kokkos and cannot reach the upstream release.
kokkos_tar_url="https://files.pythonhosted.org/packages/1d/2e/e3e6035ba1b7358033ad15e07ed0d49ba1b1298fdfa9ea8814a8ccc39df8/pykokkos-base-0.0.7.tar.gz"
kokkos_tar_sha256="6339daced1e81a2748f381847d8717cd77d824407da3c263b9491b5630c642b0"
kokkos_src="$deps/pykokkos-base-0.0.7/external/kokkos"
if [ -f "$kokkos_src/CMakeLists.txt" ]; then
  echo "install-deps: Kokkos source already at $kokkos_src"
else
  mkdir -p "$deps/dl"
  tarball="$deps/dl/pykokkos-base-0.0.7.tar.gz"
  if ! echo "$kokkos_tar_sha256  $tarball" | sha256sum -c --status 2>/dev/null; then
    echo "install-deps: downloading Kokkos 3.4.01 source (pykokkos-base 0.0.7 from PyPI)"
    curl -fsSL --retry 3 -o "$tarball.part" "$kokkos_tar_url"
    mv "$tarball.part" "$tarball"
  fi
  if ! echo "$kokkos_tar_sha256  $tarball" | sha256sum -c --status; then
    echo "install-deps: checksum mismatch for $tarball (expected $kokkos_tar_sha256)" >&2
    rm -f "$tarball"
    exit 1
  fi
  tar xzf "$tarball" -C "$deps"
  echo "install-deps: Kokkos source unpacked at $kokkos_src"
fi

