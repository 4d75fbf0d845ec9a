#!/usr/bin/env bash
# The layers of docs/architecture: script -> lang -> scene <- tracer, lang -> lsp, and the
# programs in apps/ above them all. Fails when a file includes a layer it must not know:
# lang never sees the renderer, the renderer never sees the front end or the language server,
# the scene description sees neither, and no library sees the programs.
set -u
root=${1:?usage: check_layers.sh SOURCE_ROOT}
failures=0

# headers of a folder, as other files include them ("ast.hpp" or "tracer/bvh.hpp")
headers_of() { (cd "$root/$1" && find . -name '*.hpp' -printf '%P\n'); }

forbid() { # folder description pattern (an extended regex matched against #include lines)
    local folder=$1 what=$2 pattern=$3 hits
    hits=$(grep -rnE --include='*.cpp' --include='*.hpp' --include='*.yy' --include='*.re' \
        "^[[:space:]]*#[[:space:]]*include[[:space:]]*\"($pattern)\"" "$root/$folder")
    if [ -n "$hits" ]; then
        echo "FAIL: $folder/ includes $what:"
        echo "$hits" | sed "s|$root/||; s/^/  /"
        failures=$((failures + 1))
    fi
}

lang_headers=$(headers_of lang | sed 's/\./\\./g' | paste -sd'|')
lsp_headers=$(headers_of lsp | sed 's/\./\\./g' | paste -sd'|')
[ -n "$lang_headers" ] && [ -n "$lsp_headers" ] || { echo "FAIL: no headers found under $root"; exit 1; }

forbid lang "the renderer" "tracer/[^\"]*"
forbid lang "the language server" "lsp/[^\"]*|$lsp_headers"
forbid lang "a program" "apps/[^\"]*"
forbid scene "the front end" "lang/[^\"]*|$lang_headers"
forbid scene "the renderer" "tracer/[^\"]*"
forbid tracer "the front end" "lang/[^\"]*|$lang_headers"
forbid tracer "the language server" "lsp/[^\"]*|$lsp_headers"
forbid tracer "a program" "apps/[^\"]*"
forbid lsp "the renderer" "tracer/[^\"]*"
forbid lsp "a program" "apps/[^\"]*"

# The libraries' link lines say the same.
link_line() { grep -A3 "target_link_libraries($1 " "$root/$2/CMakeLists.txt" | tr '\n' ' '; }
for forbidden in crt_render crt_geometry crt_image_io crt_lsp; do
    link_line crt_lang lang | grep -qw "$forbidden" && { echo "FAIL: crt_lang links $forbidden"; failures=$((failures + 1)); }
done
for forbidden in crt_lang crt_lsp; do
    link_line crt_render tracer | grep -qw "$forbidden" && { echo "FAIL: crt_render links $forbidden"; failures=$((failures + 1)); }
    link_line crt_scene scene | grep -qw "$forbidden" && { echo "FAIL: crt_scene links $forbidden"; failures=$((failures + 1)); }
done
link_line crt_lsp lsp | grep -qw crt_render && { echo "FAIL: crt_lsp links crt_render"; failures=$((failures + 1)); }

[ "$failures" -eq 0 ] && echo "layers: lang, scene, tracer and lsp include and link only what they may"
exit $((failures > 0))
