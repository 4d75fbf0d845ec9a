#!/usr/bin/env bash
# Hostile scripts within crtc's default limits end in an error at their location, never in a
# crash or an abort: deep nesting, memory-hungry loops, exponential text, error floods.
set -u
crtc=$1
sanitized=${2:-0} # 1 for an AddressSanitizer build: its shadow memory needs all the address space
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"

# Nesting: deeper than the limit is an error at the script location, for every command.
python3 -c "print('x = 1' + '+1' * 1000100)" >"$work/plus.crt"
python3 -c "print('x = ' + '[' * 1000100 + ']' * 1000100)" >"$work/brackets.crt"
python3 -c "print('x = ' + '- ' * 1000100 + '1')" >"$work/minus.crt"
python3 -c "print('x = ' + '!' * 1000100 + 'true')" >"$work/not.crt"
for script in plus brackets minus not; do
    expect_status 1 "$script nested too deep (--check)" "$crtc" --check "$work/$script.crt"
    expect_text "$work/err" "^$work/$script.crt:1:[0-9]+: error: expressions and blocks nested deeper than 1000000 levels" \
        "$script: the nesting error with its location"
done
expect_status 1 "--dump-ast of a tree too deep" "$crtc" --dump-ast "$work/brackets.crt"
expect_text "$work/err" "nested deeper than 1000000 levels" "--dump-ast: the nesting error"
expect_status 1 "--format of a tree too deep" "$crtc" --format "$work/plus.crt"
expect_text "$work/err" "nested deeper than 1000000 levels" "--format: the nesting error"

# Just under the limit, everything still works (the walks fit their stack).
python3 -c "print('x = ' + '[' * 999000 + ']' * 999000 + '\nprint(x == x)')" >"$work/deep_ok.crt"
expect_status 0 "a list literal 999,000 deep" "$crtc" --check "$work/deep_ok.crt"
expect_text "$work/out" "^true$" "== on a list 999,000 deep"

# Without room for the large stack, the limit shrinks to the stack there is, and says so.
limit_address_space=0
if [ "$sanitized" = 1 ]; then
    echo "note: a sanitizer build; the checks under an address-space limit are skipped"
elif command -v prlimit >/dev/null; then
    limit_address_space=1
else
    echo "note: prlimit not found, the checks under an address-space limit are skipped"
fi
if [ "$limit_address_space" = 1 ]; then
    python3 -c "print('x = 1' + '+1' * 50000)" >"$work/plus50k.crt"
    expect_status 1 "50,000 '+1' without the large stack" prlimit --as=900000000 "$crtc" --check "$work/plus50k.crt"
    expect_text "$work/err" "^warning: cannot reserve a [0-9]+ MiB stack.*nest at most [0-9]+ levels" "the small-stack warning"
    expect_text "$work/err" "plus50k.crt:1:[0-9]+: error: expressions and blocks nested deeper than [0-9]+ levels" \
        "the small-stack nesting error"
fi

# Recursion through macros counts against the same limit: the deepest --max-depth still
# works for a small body, a body nesting deeper per call does not.
cat >"$work/recursion.crt" <<'CRT'
m = Macro (n) { n == 0 ? 0 : 1 + m(n - 1) }
print(m(199000))
CRT
expect_status 0 "macro recursion 199,000 deep" "$crtc" --check --max-depth 200000 "$work/recursion.crt"
expect_text "$work/out" "^199000$" "macro recursion 199,000 deep: its value"
cat >"$work/deep_recursion.crt" <<'CRT'
m = Macro (n) { n == 0 ? 0 : 1 + (1 + (1 + (1 + (1 + (1 + (1 + m(n - 1))))))) }
print(m(199000))
CRT
if [ "$sanitized" = 1 ]; then
    # AddressSanitizer does not clean up a stack deeper than 64 MiB an exception leaves
    # (google/sanitizers issue 189) and then reports false errors.
    echo "note: a sanitizer build; the error thrown from 900 MiB of stack is not checked"
else
    expect_status 1 "macro recursion 199,000 deep, nesting 9 levels a call" "$crtc" --check --max-depth 200000 "$work/deep_recursion.crt"
    expect_text "$work/err" "deep_recursion.crt:1:[0-9]+: error: expressions, blocks and macro calls nested deeper than 1000000 levels" \
        "deep macro recursion: the nesting error"
    expect_text "$work/err" "note: in the macro called here" "deep macro recursion: the call notes"
fi

# Memory: a string doubling forever stops at --max-memory with an error at its statement.
printf 's = "x"\nwhile (true) { s = s + s }\n' >"$work/double.crt"
expect_status 1 "a doubling string" "$crtc" --check --max-memory 256 "$work/double.crt"
expect_text "$work/err" "double.crt:2:16: error: evaluation needs more than 256 MiB of memory; raise the limit with --max-memory" \
    "the doubling string: the memory error"
# With the default budget but less memory than it, the allocation that fails is reported.
if [ "$limit_address_space" = 1 ]; then
    expect_status 1 "a doubling string in 2.5 GB of address space" prlimit --as=2500000000 "$crtc" --check "$work/double.crt"
    expect_text "$work/err" "double.crt:2:16: error: (out of memory while evaluating this statement|evaluation needs more than)" \
        "out of memory: an error at the statement, not an abort"
fi
printf 's = Sphere { center -> vec3(0, 0, 0) radius -> 1 }\nfor i in range(100000) { s = s <translate vec3(0, 0, 0)> }\n' >"$work/modifiers.crt"
expect_status 1 "a chain of 100,000 modifiers" "$crtc" --check --max-memory 64 "$work/modifiers.crt"
expect_text "$work/err" "modifiers.crt:2:26: error: evaluation needs more than 64 MiB" "the modifier chain: the memory error"
expect_status 2 "--max-memory 0" "$crtc" --check --max-memory 0 "$work/modifiers.crt"

# Text of nested lists: linear in its size, and bounded when it would explode.
printf 'l = []\nfor i in range(1000000) { l = [l] }\nprint(l)\n' >"$work/nested.crt"
expect_status 0 "print of a list nested 1,000,000 deep" "$crtc" --check "$work/nested.crt"
[ "$(head -c 8 "$work/out")" = "[[[[[[[[" ] && [ "$(wc -c <"$work/out")" -eq 2000003 ] ||
    fail "print of a deep list: expected 1,000,001 pairs of brackets"
printf 'l = [1]\nfor i in range(60) { l = [l, l] }\nprint(str(l))\n' >"$work/exponential.crt"
expect_status 1 "str of a list holding a list 2^60 times" "$crtc" --check "$work/exponential.crt"
expect_text "$work/err" "exponential.crt:3:1: error: evaluation exceeded 50000000 steps" "exponential text: the step limit"

# Error floods: at most --max-errors errors, then a line saying so.
python3 -c "print('x = = 1\n' * 100000, end='')" >"$work/flood.crt"
expect_status 1 "100,000 syntax errors" "$crtc" --check "$work/flood.crt"
[ "$(grep -c ': error: ' "$work/err")" -eq 50 ] || fail "the error flood: expected 50 errors by default"
expect_text "$work/err" "^crtc: too many errors \(100000\); stopping after 50 \(--max-errors\)" "the error flood: the closing line"
expect_status 1 "--max-errors 3" "$crtc" --check --max-errors 3 "$work/flood.crt"
[ "$(grep -c ': error: ' "$work/err")" -eq 3 ] || fail "--max-errors 3: expected 3 errors"
expect_status 1 "--max-errors 0" "$crtc" --check --max-errors 0 "$work/flood.crt"
[ "$(grep -c ': error: ' "$work/err")" -eq 100000 ] || fail "--max-errors 0: expected every error"

# A render far beyond any machine is announced before it starts, by --check too.
cat >"$work/huge.crt" <<'CRT'
Settings {
    width -> 16384 height -> 16384 supersampling -> 64 dofsamples -> 100000
    camera -> Camera { position -> vec3(0, 0, -4) pointing -> vec3(0, 0, 0) aperture -> 0.2 }
    lights -> [AreaLight { corner -> vec3(2, 3, -3) edgeA -> vec3(1, 0, 0) edgeB -> vec3(0, 1, 0) color -> rgb(1, 1, 1) }]
}
Scene { Sphere { center -> vec3(0, 0, 0) radius -> 1 } }
CRT
expect_status 0 "--check of a render needing 10^18 rays" "$crtc" --check "$work/huge.crt"
expect_text "$work/err" "^crtc: warning: this render traces up to about 1\.9e\+18 rays \(16384x16384 pixels, 409600000 camera samples a pixel, 17 ray\(s\) a sample" \
    "the render cost warning"
expect_status 0 "--check --draft of the same" "$crtc" --check --draft "$work/huge.crt"
grep -q "rays" "$work/err" && fail "--draft: the cost warning is still there"
# Under the path integrator the cost is the paths a pixel times the rays of their bounces:
# 16384² pixels × 1,000,000 paths × (1000 bounces + 1) × (2 + 1 light) rays.
sed -i 's/supersampling -> 64/bounces -> 1000/' "$work/huge.crt"
expect_status 0 "--check of a path-traced render of 1000 bounces" "$crtc" --check --integrator path \
    --samples 1000000 "$work/huge.crt"
expect_text "$work/err" "^crtc: warning: this render traces up to about 8\.1e\+17 rays \(16384x16384 pixels, 1000000 camera samples a pixel, 3003 ray\(s\) a sample" \
    "the path integrator's cost warning"

finish
