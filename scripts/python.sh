#!/usr/bin/env bash
# Installs the Python package sharp_features for Debian's python3 (/usr/bin/python3, whatever
# python3 comes first in PATH), so that `/usr/bin/python3 -c "import sharp_features"` works from
# any directory, for every user, with no PYTHONPATH:
#
#   bash scripts/python.sh [cmake arguments]
#
# Installs the Debian packages that are missing, builds the module (Release) in build-python/
# and copies it into the site-packages directory that Debian's python3 reads and dpkg leaves
# alone (/usr/local/lib/python3.X/dist-packages, where `pip install` puts packages as root).
# To remove it: the files listed in build-python/install_manifest_python.txt.
# To use the module without installing it instead: PYTHONPATH=build-python/python.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$SFE_ROOT"

SFE_BUILD_DIR="$SFE_ROOT/build-python"
install_missing_packages "${SFE_PACKAGES[@]}" "${SFE_PYTHON_PACKAGES[@]}"

# The platform site-packages of Debian's python3 (posix_local scheme), if its sys.path has it.
site_packages="$("$SFE_PYTHON" -c 'import sysconfig; print(sysconfig.get_path("platlib"))')"
"$SFE_PYTHON" -c 'import sys; sys.exit(sys.argv[1] not in sys.path)' "$site_packages" \
  || sfe_die "$site_packages is not on the path of $SFE_PYTHON; use PYTHONPATH=$SFE_BUILD_DIR/python"

sfe_log "configuring into $SFE_BUILD_DIR"
cmake -S "$SFE_ROOT" -B "$SFE_BUILD_DIR" -DCMAKE_BUILD_TYPE=Release \
  -DSFE_BUILD_EXAMPLES=OFF -DSFE_BUILD_TESTS=OFF -DSFE_BUILD_BENCHMARK=OFF -DSFE_BUILD_MESHING=OFF \
  -DSFE_BUILD_PYTHON=ON -DPython_EXECUTABLE="$SFE_PYTHON" -DSFE_PYTHON_INSTALL_DIR="$site_packages" "$@"
sfe_log "building the module with $SFE_JOBS jobs"
cmake --build "$SFE_BUILD_DIR" -j "$SFE_JOBS" --target sharp_features

sfe_log "installing into $site_packages"
if [ -w "$site_packages" ] || { [ ! -e "$site_packages" ] && [ -w "$(dirname "$site_packages")" ]; }; then
  cmake --install "$SFE_BUILD_DIR" --component python
else
  sfe_as_root cmake --install "$SFE_BUILD_DIR" --component python
fi

# Imported from elsewhere than the build tree, with a clean environment: what a user gets.
imported="$(cd / && env -u PYTHONPATH "$SFE_PYTHON" -c 'import sharp_features; print(sharp_features.__file__)')"
case "$imported" in
  "$site_packages"/*) sfe_log "$SFE_PYTHON imports sharp_features from $imported" ;;
  *) sfe_die "$SFE_PYTHON imports sharp_features from $imported, not from $site_packages (an older copy?)" ;;
esac
