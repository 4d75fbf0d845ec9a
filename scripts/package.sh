#!/usr/bin/env bash
# Builds crt's packages into dist/: the Debian package dist/crt_<version>_amd64.deb (CPack,
# from the install rules in cmake/CrtInstall.cmake) and the VS Code extension
# dist/crt-<version>.vsix (editors/vscode/package.sh). Reuses build/ when it is configured;
# builds only what is installed, not the tests. Extra arguments go to CMake's configure step.
#   scripts/package.sh
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
mkdir -p dist

debian_package() {
    cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
    cmake --build build --target crt_installed_files
    cpack --config build/CPackConfig.cmake -G DEB -B "$PWD/dist"
    rm -rf dist/_CPack_Packages # CPack's staging folder
}

debian_package "$@"
editors/vscode/package.sh "$PWD/dist"
echo "== packages in dist/:"
ls -1 dist/*.deb dist/*.vsix
