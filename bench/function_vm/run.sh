#!/usr/bin/env bash
# Function VM benchmark: how long one evaluation of a Function takes in crtc and in POV-Ray
# 3.7's function VM. Each tool renders a wall whose pattern is a 24-term Function
# (function.crt, function.pov) and the same wall with a plain gradient (plain.crt,
# plain.pov), alternating, several times; the difference of the median CPU times, over the
# pixels (one evaluation each), is the time of one evaluation. Prints a Markdown table. See
# bench/README.md.
#
# usage: bench/function_vm/run.sh [--runs N] [--size WxH] [CRTC]
#
#   --runs N     timed runs per tool and scene; medians reported (default 3)
#   --size WxH   image size (default 2560x1440: 3.7 million evaluations)
#   CRTC         path of the crtc binary (default: $CRTC, else build/bin/crtc under the
#                repository root)
#
# environment:
#   THREADS     render threads of both tools (default 2)
#   BENCH_OUT   folder for the images and logs (default: a temporary folder, removed at exit)
#   POVRAY      POV-Ray binary (default /usr/bin/povray)
#
# exit status: 0 done; 1 a run failed; 2 bad usage or missing tool.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=../common.sh
source "$here/../common.sh"
root=$(cd "$here/../.." && pwd)

runs=3
size=2560x1440
bench_parse_options runs size -- "$@"
povray=${POVRAY:-/usr/bin/povray}
threads=${THREADS:-2}
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "$0: --runs must be a positive integer" >&2; exit 2; }
[[ $size =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || { echo "$0: bad size '$size' (want WxH)" >&2; exit 2; }
[[ -x $povray ]] || { echo "$0: POV-Ray not found at $povray (scripts/setup.sh --bench)" >&2; exit 2; }
W=${size%x*} H=${size#*x}

bench_check_crtc
[[ $have_crtc -eq 1 ]] || { echo "$0: no crtc to measure" >&2; exit 2; }
bench_output_folder function_vm

# cpu_of TOOL SCENE RUN -> sets cpu (seconds of user + system time)
cpu_of() {
    local tool=$1 scene=$2 r=$3 c0 c1 log=$logs/$scene.$tool.$r
    children_cpu_ms c0
    if [[ $tool == crtc ]]; then
        "$crtc" "$here/$scene.crt" -o "$out/$scene.crtc.png" --width "$W" --height "$H" \
            --threads "$threads" -q >"$log.out" 2>"$log.err"
    else
        (cd "$here" && HOME=$povhome "$povray" "+I$scene.pov" "+O$out/$scene.pov.png" +FN \
            "+W$W" "+H$H" -D -V -P -A "+WT$threads" >"$log.out" 2>"$log.err")
    fi
    children_cpu_ms c1
    cpu=$(awk -v a="$c0" -v b="$c1" 'BEGIN { printf "%.3f", (b - a) / 1000 }')
}

declare -A CPU
for tool in pov crtc; do
    for scene in function plain; do
        times_list=()
        for ((r = 1; r <= runs; r++)); do
            cpu_of "$tool" "$scene" "$r"
            times_list+=("$cpu")
        done
        CPU[$tool.$scene]=$(median "${times_list[@]}")
        echo "$tool $scene: ${times_list[*]} s of CPU (median ${CPU[$tool.$scene]})" >&2
    done
done

pixels=$((W * H))
per() { awk -v f="$1" -v p="$2" -v n="$pixels" 'BEGIN { printf "%.0f", (f - p) * 1e9 / n }'; }
pov_ns=$(per "${CPU[pov.function]}" "${CPU[pov.plain]}")
crtc_ns=$(per "${CPU[crtc.function]}" "${CPU[crtc.plain]}")
echo
echo "| tool | function wall (s CPU) | plain wall (s CPU) | one evaluation (ns) |"
echo "| --- | ---: | ---: | ---: |"
echo "| POV-Ray 3.7 | ${CPU[pov.function]} | ${CPU[pov.plain]} | $pov_ns |"
echo "| crtc | ${CPU[crtc.function]} | ${CPU[crtc.plain]} | $crtc_ns |"
echo
awk -v p="$pov_ns" -v c="$crtc_ns" 'BEGIN { printf "crtc evaluates a Function in %.2f of POV-Ray'"'"'s time (%d x %d, %d threads)\n", c / p, '"$W"', '"$H"', '"$threads"' }'
