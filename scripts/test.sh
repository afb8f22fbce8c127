#!/usr/bin/env bash
# Installs what is missing, builds everything with the tests and runs them; exits with the
# status of ctest. Extra arguments go to cmake, e.g. `bash scripts/test.sh -DSFE_BUILD_MESHING=OFF`.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$SFE_ROOT"

install_missing_packages "${SFE_PACKAGES[@]}"
configure_and_build -DSFE_BUILD_TESTS=ON "$@"

status=0
# --no-tests=error: a build that lost its tests must not pass.
ctest --test-dir "$SFE_BUILD_DIR" --output-on-failure --no-tests=error -j "$SFE_JOBS" || status=$?
exit "$status"
