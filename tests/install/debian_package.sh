#!/usr/bin/env bash
# The Debian package, for real: CPack builds it from the build tree (without rebuilding), apt
# installs it system-wide (its dependencies are already there, so offline), check_installed.sh
# checks /usr as a user meets it, and apt removes it again.
#   debian_package.sh BUILD_DIR SOURCE_DIR PYTHON
# Skipped (77) unless run as root with dpkg and apt-get, or when a crt package is installed
# already (it would be replaced, then removed).
set -u
source "$(dirname "$0")/common.sh"
build=$1 source_dir=$2 python=$3
here=$(cd "$(dirname "$0")" && pwd)
if [ "$(id -u)" -ne 0 ]; then
    echo "skipped: installing a package system-wide needs root"
    exit 77
fi
for tool in dpkg dpkg-deb apt-get man; do
    if ! command -v $tool >/dev/null 2>&1; then
        echo "skipped: $tool is not installed"
        exit 77
    fi
done
# Slim container images tell dpkg to drop manual pages and documentation on install.
if grep -sqE '^path-exclude[= ]+/usr/share/(man|doc)' /etc/dpkg/dpkg.cfg /etc/dpkg/dpkg.cfg.d/*; then
    echo "skipped: dpkg is told not to install manual pages or documentation (path-exclude in /etc/dpkg)"
    exit 77
fi
if dpkg-query -W -f='${Status}' crt 2>/dev/null | grep -q "install ok installed"; then
    echo "skipped: a crt package is installed already; this test would replace and remove it"
    exit 77
fi
work=$(mktemp -d)
installed=false
cleanup() {
    if $installed; then
        DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq crt >/dev/null ||
            echo "FAIL: apt-get purge crt"
    fi
    rm -rf "$work"
}
trap cleanup EXIT

if ! (cd "$work" && cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work") >"$work/cpack.log" 2>&1; then
    cat "$work/cpack.log"
    echo "FAIL: cpack"
    exit 1
fi
debs=("$work"/crt_*_amd64.deb)
[ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ] || { echo "FAIL: no crt_<version>_amd64.deb in: $(ls "$work")"; exit 1; }
deb=${debs[0]}

field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = crt ] || fail "Package: $(field Package)"
[ "$deb" = "$work/crt_$(field Version)_amd64.deb" ] || fail "file name $deb for version $(field Version)"
[ "$(field Section)" = graphics ] || fail "Section: $(field Section)"
[ -n "$(field Maintainer)" ] || fail "no Maintainer"
# Depends comes from the shared libraries the programs and the modules link, and names the
# default font of Text.
for library in libc6 libstdc++6 libopenimageio libpng16 libfreetype6 libassimp5 fonts-dejavu-core; do
    field Depends | grep -q "$library" || fail "Depends lacks $library: $(field Depends)"
done
dpkg-deb -c "$deb" | grep -q ' ./usr/share/man/man1/crtc.1.gz$' || fail "no gzipped crtc.1 in the package"
# The MPI module (when built) and, from the libraries it links, OpenMPI.
if [ -f "$build/bin/crt_mpi.so" ]; then
    dpkg-deb -c "$deb" | grep -q ' ./usr/lib/crt/crt_mpi.so$' || fail "no crt_mpi.so in the package"
    field Depends | grep -q libopenmpi || fail "Depends lacks libopenmpi: $(field Depends)"
fi

if ! DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$deb" \
    >"$work/apt.log" 2>&1; then
    cat "$work/apt.log"
    echo "FAIL: apt-get install $deb"
    exit 1
fi
installed=true
[ "$(command -v crtc)" = /usr/bin/crtc ] || fail "crtc on PATH is $(command -v crtc), not /usr/bin/crtc"
[ "$(man -w crtc)" = /usr/share/man/man1/crtc.1.gz ] || fail "man -w crtc: $(man -w crtc 2>&1)"
[ "$(crt-lsp --version)" = "crt-lsp $(field Version)" ] || fail "crt-lsp --version: $(crt-lsp --version 2>&1)"
bash "$here/check_installed.sh" /usr "$build/bin/crtc" "$source_dir" "$python" || fail "check_installed.sh /usr"

DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq crt >/dev/null || fail "apt-get purge crt"
installed=false
[ -e /usr/bin/crtc ] && fail "/usr/bin/crtc is still there after apt-get purge"
[ -e /usr/lib/crt ] && fail "/usr/lib/crt is still there after apt-get purge"
dpkg-query -W crt >/dev/null 2>&1 && fail "dpkg still lists crt after apt-get purge"

finish "Debian package $(basename "$deb")"
