#!/usr/bin/env bash
# The option lists cannot drift apart: every option that `crtc --help` prints is documented
# in its manual page (docs/man/crtc.1.md) and completed by its bash completion (which reads
# them from crtc --help), which offers nothing else; every option of `crt-lsp --help` is in
# docs/man/crt-lsp.1.md.
#   options_documented.sh CRTC CRT_LSP SOURCE_DIR
# Options are read from the help text as words starting with - or -- (the layout of the
# help text does not matter).
set -u
source "$(dirname "$0")/common.sh"
crtc=$(realpath "$1") crt_lsp=$2 source_dir=$3
completion=$source_dir/apps/crtc/completion/crtc.bash

# The options named in a text: -x, -Word, --long-option (not Ctrl-C, N-1 or --color's =WHEN).
options_in() {
    grep -oE -- '(^|[][[:space:],(|])--?[A-Za-z][A-Za-z0-9-]*' | sed -E 's/^[][[:space:],(|]//' | sort -u
}

# A page documents an option when it names it in bold, as the term of a definition:
# **--width**, **-I***DIR*, **--color=***WHEN*.
check_page() { # program page options...
    local program=$1 page=$2
    shift 2
    for option in "$@"; do
        grep -qF -- "**$option**" "$page" || grep -qF -- "**$option=" "$page" ||
            fail "$program's option $option is not documented in $page"
    done
}

mapfile -t crtc_options < <("$crtc" --help | options_in)
mapfile -t lsp_options < <("$crt_lsp" --help | options_in)
# A help text that lost its options must not pass for one that lists none to check.
[ ${#crtc_options[@]} -ge 20 ] || fail "crtc --help names only ${#crtc_options[@]} options: ${crtc_options[*]}"
[ ${#lsp_options[@]} -ge 4 ] || fail "crt-lsp --help names only ${#lsp_options[@]} options: ${lsp_options[*]}"

# go-md2man copies a paragraph's lines as they are: one starting with . or ' would be read
# by roff as a request, and its text would vanish from the page.
for page in "$source_dir"/docs/man/*.md; do
    grep -nE "^[[:space:]]*[.']" "$page" | sed "s|^|$page:|" | while read -r line; do
        echo "FAIL: a line that roff would take for a request: $line"
    done | grep . && failures=$((failures + 1))
done

check_page crtc "$source_dir/docs/man/crtc.1.md" "${crtc_options[@]}"
check_page crt-lsp "$source_dir/docs/man/crt-lsp.1.md" "${lsp_options[@]}"

# The completion, run as bash runs it on the crtc under test, offers each option when its
# name is typed and no option crtc lacks; after an option that takes a number it offers
# nothing, elsewhere the .crt scripts.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
touch "$work/scene.crt" "$work/notes.txt"
offered=$(cd "$work" && bash -c 'source "$1"; crtc=$2; shift 2
    complete() { # what _crtc offers after the words given
        COMP_WORDS=("$crtc" "$@"); COMP_CWORD=$#; _crtc; printf "%s\n" "${COMPREPLY[@]}"
    }
    for option in "$@"; do complete "$option" | grep -qxF -- "$option" || echo "missing $option"; done
    complete - | sed "s/^/offered /"
    echo "after-width $(complete --width "" | tr "\n" " ")"
    echo "after-check $(complete --check "" | tr "\n" " ")"' \
    _ "$completion" "$crtc" "${crtc_options[@]}")
while read -r kind option; do
    case $kind in
    missing) fail "the bash completion does not offer crtc's option $option" ;;
    offered)
        [ -n "$option" ] || continue
        printf '%s\n' "${crtc_options[@]}" | grep -qxF -- "$option" ||
            fail "the bash completion offers $option, which crtc --help does not name" ;;
    after-width) [ -z "$option" ] || fail "after --width, the bash completion offers $option" ;;
    after-check) [ "$option" = scene.crt ] || fail "after --check, the bash completion offers '$option', not scene.crt" ;;
    esac
done <<<"$offered"
grep -q "after-check" <<<"$offered" || fail "the bash completion could not be run: $offered"

finish "crtc: ${#crtc_options[@]} options, crt-lsp: ${#lsp_options[@]} options: documented and completed"
