# shellcheck shell=bash
# Helpers shared by the scripts of this directory; source it, do not run it:
#
#   source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
#
# Works under `set -euo pipefail` on Debian 12 (as root, or as a user with sudo).

SFE_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SFE_BUILD_DIR="${SFE_BUILD_DIR:-$SFE_ROOT/build}"
SFE_JOBS="${SFE_JOBS:-2}"
SFE_OUT_DIR="$SFE_ROOT/out" # git-ignored: meshes, caches and results never enter the repository
# CGAL's sample data as installed by libcgal-demo (fetched into out/cache when missing).
SFE_CGAL_DATA_ARCHIVE="${SFE_CGAL_DATA_ARCHIVE:-/usr/share/doc/libcgal-dev/data.tar.gz}"

# Debian packages needed to build the package, its examples, tests and documentation
# (pkg-config finds OpenJPEG, which the point-cloud coder needs; zlib deflates the programs' PNGs).
SFE_PACKAGES=(build-essential cmake libcgal-dev libeigen3-dev libboost-dev libtbb-dev catch2 doxygen
              pkg-config libopenjp2-7-dev zlib1g-dev)
# Debian packages needed, besides those, to build and test the Python module (python/); dask's
# python3-distributed runs `python3 -m sharp_features --workers K`, python3-tqdm draws its
# progress bar.
# shellcheck disable=SC2034 # used by the scripts that source this file
SFE_PYTHON_PACKAGES=(pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed python3-tqdm)
# Debian's python3, for which the module is built and tested: another python3 coming first in
# PATH (pyenv, conda, a virtual environment) would have neither these packages nor its headers.
# shellcheck disable=SC2034 # used by the scripts that source this file
SFE_PYTHON=/usr/bin/python3

sfe_log() { printf '==> %s\n' "$*" >&2; }
sfe_die() { printf 'error: %s\n' "$*" >&2; exit 1; }

# Runs a command as root: directly when we are root, through sudo otherwise.
sfe_as_root() {
  if [ "$(id -u)" -eq 0 ]; then
    "$@"
  elif command -v sudo > /dev/null 2>&1; then
    sudo "$@"
  else
    sfe_die "'$*' needs root privileges, and sudo is not installed"
  fi
}

SFE_APT_UPDATED=0
sfe_apt_update_once() {
  if [ "$SFE_APT_UPDATED" -eq 0 ]; then
    sfe_log "apt-get update"
    sfe_as_root apt-get update >&2 # stdout may be captured by the caller
    SFE_APT_UPDATED=1
  fi
}

sfe_package_installed() {
  dpkg -s "$1" 2> /dev/null | grep -q '^Status: install ok installed'
}

# Installs the given Debian packages (default: SFE_PACKAGES) that are not installed yet;
# does nothing, not even `apt-get update`, when all are present.
install_missing_packages() {
  local packages=("$@")
  if [ "${#packages[@]}" -eq 0 ]; then
    packages=("${SFE_PACKAGES[@]}")
  fi
  if ! command -v dpkg > /dev/null 2>&1; then
    sfe_log "not a Debian system: make sure these are installed: ${packages[*]}"
    return 0
  fi
  local missing=() package
  for package in "${packages[@]}"; do
    sfe_package_installed "$package" || missing+=("$package")
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    return 0
  fi
  sfe_apt_update_once
  sfe_log "installing ${missing[*]}"
  sfe_as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}" >&2
}

# Configures (Release) and builds into SFE_BUILD_DIR; arguments go to cmake, e.g.
#   configure_and_build -DSFE_BUILD_TESTS=OFF
configure_and_build() {
  sfe_log "configuring into $SFE_BUILD_DIR ($*)"
  cmake -S "$SFE_ROOT" -B "$SFE_BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "$@"
  sfe_log "building with $SFE_JOBS jobs"
  cmake --build "$SFE_BUILD_DIR" -j "$SFE_JOBS"
}

# Makes out/meshes/NAME.off available and prints its path, e.g. `fetch_cgal_mesh fandisk`.
# The meshes come from CGAL's data archive, shipped by the Debian package libcgal-demo. If it
# is not installed, the package is only downloaded and unpacked into out/cache (it is large
# and pulls many dependencies; we need one file of it).
fetch_cgal_mesh() {
  local name="$1"
  local mesh="$SFE_OUT_DIR/meshes/$name.off"
  if [ -s "$mesh" ]; then
    printf '%s\n' "$mesh"
    return 0
  fi
  local archive="$SFE_CGAL_DATA_ARCHIVE"
  if [ ! -f "$archive" ]; then
    local cache="$SFE_OUT_DIR/cache"
    archive="$cache/libcgal-demo/usr/share/doc/libcgal-dev/data.tar.gz" # same path inside the package
    if [ ! -f "$archive" ]; then
      mkdir -p "$cache"
      local debs=("$cache"/libcgal-demo_*.deb)
      if [ ! -f "${debs[0]}" ]; then
        sfe_log "downloading libcgal-demo (for CGAL's sample meshes) into $cache"
        # The package lists may be missing on a fresh system: update once and retry.
        # stdout stays clean for the caller, which captures the printed path.
        if ! (cd "$cache" && apt-get download libcgal-demo >&2); then
          sfe_apt_update_once
          (cd "$cache" && apt-get download libcgal-demo >&2) || sfe_die "apt-get download libcgal-demo failed"
        fi
        debs=("$cache"/libcgal-demo_*.deb)
      fi
      [ -f "${debs[0]}" ] || sfe_die "could not download libcgal-demo"
      rm -rf "$cache/libcgal-demo"
      dpkg -x "${debs[0]}" "$cache/libcgal-demo" >&2 || sfe_die "cannot unpack ${debs[0]}"
      [ -f "$archive" ] || sfe_die "${debs[0]} does not contain $archive"
    fi
  fi
  mkdir -p "$(dirname "$mesh")"
  sfe_log "extracting $name.off from $archive"
  if ! tar -xzf "$archive" -O "data/meshes/$name.off" > "$mesh.part"; then
    rm -f "$mesh.part"
    sfe_die "CGAL's data archive has no mesh data/meshes/$name.off"
  fi
  mv "$mesh.part" "$mesh"
  printf '%s\n' "$mesh"
}
