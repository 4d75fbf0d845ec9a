#!/usr/bin/env bash
# Installs everything crt needs to build and test, from Debian 12's packages.
# Quick and quiet when everything is already installed. Run as root.
#   scripts/setup.sh          build and test dependencies
#   scripts/setup.sh --bench  also Embree and the tools the benchmarks use
#   scripts/setup.sh --fuzz   also clang and its libFuzzer runtime (tests/fuzz/)
set -euo pipefail

packages=(
    g++ cmake ninja-build re2c bison
    libfmt-dev libglm-dev nlohmann-json3-dev catch2
    libopenimageio-dev openimageio-tools # image input and output; oiiotool in the tests
    libpng-dev # PNG output, written without OpenImageIO
    libopenexr-dev # OpenEXR output, written without OpenImageIO
    libcli11-dev # crtc's command line
    libfreetype-dev fonts-dejavu-core # Text: glyph outlines, and its default font
    libassimp-dev # Mesh: PLY, STL and glTF files
    python3 # the language server's protocol session tests (tests/lsp), docs transcripts (tests/docs)
    jq # the docs' transcripts that pipe JSON through it
    neovim  # the language server's end-to-end test (tests/lsp/nvim)
    emacs-nox elpa-eglot # the Emacs mode's end-to-end test (tests/editors/emacs)
    unzip # the VS Code package's test opens the .vsix (tests/editors/vscode)
    strace # the files a short render creates (tests/cli/resume.sh)
    go-md2man # the manual pages, from docs/man/*.md
    dpkg-dev file # the Debian package: dpkg-shlibdeps computes Depends, on files file finds ELF
    man-db    # the install tests read the installed manual pages with man
    pkg-config libcpp-httplib-dev # crtc --preview's HTTP server
    chromium # crtc --preview's browser test (puppeteer-core, tests/preview)
    povray # the oracle of the pattern twin tests (tests/render/povray) and the benchmarks' peer
    libopenmpi-dev openmpi-bin # crtc under mpirun (apps/crtc/distributed, tests/mpi)
)
# The VS Code extension's tests and package.sh need node and npm. The machines come with
# Node.js 20 and its npm (not Debian's packages, which conflict with them): Debian's only
# where there is none.
command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
case "${1:-}" in
--bench) packages+=(time libembree-dev blender) ;; # libembree-dev: bench/embree/ only; blender: bench/gi/ only
--fuzz) packages+=(clang libclang-rt-14-dev) ;;
esac

missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
    echo "setup: missing packages: ${missing[*]}; run this script as root" >&2
    exit 1
fi
echo "setup: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
