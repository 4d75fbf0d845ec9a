#!/usr/bin/env bash
# crtc loads only what a run needs: MPI's libraries only under mpirun (through crt_mpi.so), and
# cpp-httplib with the OpenSSL libraries Debian builds it with only for --preview (in
# crtc-preview). Brotli is not among them: Debian's FreeType, which reads Text's fonts, links
# it for WOFF2 fonts. The dynamic loader's trace (LD_DEBUG=libs) names every library it
# initialises, linked or dlopened.
#   loaded_libraries.sh CRTC
set -u
crtc=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$here/expect.sh"
scene=$here/../mpi/still.crt
unneeded="libmpi|libopen-pal|crt_mpi|libcpp-httplib|libssl|libcrypto"

initialised() { # the libraries named in $work/err that match $unneeded
    grep "calling init:" "$work/err" | grep -oE "[^ ]*($unneeded)[^ ]*" | xargs -rn1 basename | sort -u | xargs
}

for run in "--version" "--check $scene" "--quiet $scene --width 8 --height 8 -o $work/plain.png"; do
    # shellcheck disable=SC2086 # the arguments are split on purpose
    LD_DEBUG=libs expect_status 0 "crtc $run" "$crtc" $run
    loaded=$(initialised)
    [ -z "$loaded" ] || fail "crtc $run loads $loaded"
done

# The preview does load the HTTP server's libraries: the trace above would have shown them.
LD_DEBUG=libs "$crtc" --preview "$scene" >"$work/out" 2>"$work/err" &
preview=$!
for _ in $(seq 100); do # up to 10 s for its URL, which it prints once it serves
    grep -q "^preview: " "$work/out" && break
    sleep 0.1
done
kill "$preview"
wait "$preview"
expect_text "$work/out" "^preview: http://127.0.0.1:" "crtc --preview prints its URL"
case " $(initialised) " in
*" libcpp-httplib.so"*) ;;
*) fail "crtc --preview does not show cpp-httplib in the loader's trace: $(initialised)" ;;
esac

# Without crtc-preview beside it (or in ../lib/crt/), --preview says where it looked.
mkdir "$work/alone"
cp "$crtc" "$work/alone/crtc"
expect_status 2 "--preview without crtc-preview" timeout 10 "$work/alone/crtc" --preview "$scene"
expect_text "$work/err" "^crtc: the preview program crtc-preview was not found; looked for $work/alone/crtc-preview and $work/lib/crt/crtc-preview$" \
    "the missing preview program's message"
finish
