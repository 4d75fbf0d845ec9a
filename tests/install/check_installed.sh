#!/usr/bin/env bash
# Checks an installed crt as a user meets it: the layout, renders from a copy of the installed
# examples (the standard library and the image module found beside the programs), the manual
# pages through man, the bash completion and an editor session with crt-lsp.
#   check_installed.sh PREFIX BUILD_CRTC SOURCE_DIR PYTHON
# PREFIX is what was installed into (/usr for the Debian package); BUILD_CRTC is the build
# tree's crtc, whose image the installed one must reproduce bit for bit.
# Prints FAIL lines and exits 1 on any failure.
set -u
source "$(dirname "$0")/common.sh"
prefix=$1 build_crtc=$2 source_dir=$3 python=$4
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for file in bin/crtc bin/crt-lsp lib/crt/crt_image_io_oiio.so lib/crt/crtc-preview share/crt/stdlib/colors.crt \
    share/man/man1/crtc.1.gz share/man/man1/crt-lsp.1.gz \
    share/bash-completion/completions/crtc share/doc/crt/copyright share/doc/crt/README.md \
    share/doc/crt/docs/crtc.md share/doc/crt/examples/piano_foot.crt; do
    [ -f "$prefix/$file" ] || fail "$prefix/$file was not installed"
done
grep -q "MIT License" "$prefix/share/doc/crt/copyright" || fail "the copyright file is not the licence"

# Every editor file, as editors/ holds it, less what npm or a packaging run leaves there.
(cd "$source_dir/editors" && find . -type f -not -path '*/node_modules/*' \
    -not -path '*/.vscode-test/*' -not -name '*.vsix' | sort) >"$work/editors.want"
(cd "$prefix/share/crt/editors" && find . -type f | sort) >"$work/editors.got"
diff -u "$work/editors.want" "$work/editors.got" >"$work/editors.diff" ||
    fail "share/crt/editors differs from editors/: $(cat "$work/editors.diff")"
[ -s "$work/editors.want" ] || fail "editors/ has no files to compare"

# A render from the installed examples, copied away from the prefix: the same image as the
# build tree's crtc makes (PNG, written without the image module).
cp -r "$prefix/share/doc/crt/examples" "$work/examples"
size=(--width 80 --height 60 -q)
run_installed "$prefix/bin/crtc" "$work/examples/piano_foot.crt" "${size[@]}" -o "$work/installed.png" ||
    fail "the installed crtc could not render piano_foot.crt to PNG"
run_installed "$build_crtc" "$work/examples/piano_foot.crt" "${size[@]}" -o "$work/built.png" ||
    fail "the build tree's crtc could not render piano_foot.crt"
cmp -s "$work/installed.png" "$work/built.png" ||
    fail "the installed crtc's image differs from the build tree's"
# A JPEG goes through the image module: the one in lib/crt/.
run_installed "$prefix/bin/crtc" "$work/examples/piano_foot.crt" "${size[@]}" -o "$work/installed.jpg" ||
    fail "the installed crtc could not render piano_foot.crt to JPEG (the image module)"
[ "$(head -c 3 "$work/installed.jpg" | od -An -tx1 | tr -d ' ')" = ffd8ff ] ||
    fail "installed.jpg is not a JPEG file"
# Under mpirun, MPI goes through the MPI module (when crtc was built with it): the one in
# lib/crt/. The image is the one crtc alone made.
if [ -f "$(dirname "$build_crtc")/crt_mpi.so" ]; then
    [ -f "$prefix/lib/crt/crt_mpi.so" ] || fail "$prefix/lib/crt/crt_mpi.so was not installed"
    if command -v mpirun >/dev/null 2>&1; then
        # (A container's shared memory only; under the sanitizers, what OpenMPI keeps is not ours.)
        OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none \
            LSAN_OPTIONS="suppressions=$source_dir/tests/mpi/lsan_mpi.supp:print_suppressions=0:fast_unwind_on_malloc=0" \
            run_installed timeout 120 mpirun --allow-run-as-root --oversubscribe -np 2 \
            "$prefix/bin/crtc" "$work/examples/piano_foot.crt" "${size[@]}" -o "$work/mpi.png" ||
            fail "the installed crtc could not render piano_foot.crt over 2 processes of mpirun"
        cmp -s "$work/installed.png" "$work/mpi.png" ||
            fail "the installed crtc's image over mpirun differs from crtc alone's"
    fi
fi

# The preview runs lib/crt/crtc-preview, which finds the same standard library.
run_installed "$python" "$here/check_preview.py" "$prefix/bin/crtc" "$work/examples/piano_foot.crt" ||
    fail "the installed crtc --preview did not show piano_foot.crt"

[ "$(run_installed "$prefix/bin/crtc" --version)" = "$(run_installed "$build_crtc" --version)" ] ||
    fail "crtc --version differs between the installed and the built crtc"
run_installed "$prefix/bin/crt-lsp" --version | grep -qE '^crt-lsp [0-9]' || fail "crt-lsp --version"

# man finds the pages and renders them.
[ "$(MANPATH="$prefix/share/man" man -w crtc)" = "$prefix/share/man/man1/crtc.1.gz" ] ||
    fail "man -w crtc does not find $prefix/share/man/man1/crtc.1.gz"
MANPATH="$prefix/share/man" MANWIDTH=80 man crt-lsp 2>/dev/null | grep -q -- "--time-budget-ms" ||
    fail "man crt-lsp does not show its options"

# The completion, sourced as bash-completion would: options and their values.
completion=$(bash -c 'source "$1"
    COMP_WORDS=("$2" --dump-s); COMP_CWORD=1; _crtc; echo "${COMPREPLY[*]}"
    COMP_WORDS=("$2" --color al); COMP_CWORD=2; _crtc; echo "${COMPREPLY[*]}"' \
    _ "$prefix/share/bash-completion/completions/crtc" "$prefix/bin/crtc")
[ "$completion" = $'--dump-scene\nalways' ] || fail "the installed completion offers: $completion"

# The language server resolves includes from the installed standard library.
run_installed "$python" "$source_dir/tests/lsp/run_session.py" "$prefix/bin/crt-lsp" \
    "$here/stdlib_session.json" || fail "the crt-lsp session with the installed standard library"

finish "installed crt in $prefix"
