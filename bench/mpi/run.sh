#!/usr/bin/env bash
# MPI benchmark: the speed-up of crtc under mpirun (2 processes of 1 thread) against crtc
# alone with 1 thread, beside crtc alone with 2 threads, on the render benchmark's scenes
# (bench/render/*.crt), a 60-frame animation (demos/orbit.crt) and a scene whose cost sits in one
# corner, first or last in the tiles' order (bench/mpi/corner.crt). Runs alternate the three
# ways, several times; prints median wall times and speed-ups as a Markdown table, and checks
# that every image is the same bytes whichever way it was made. See bench/README.md.
#
# usage: bench/mpi/run.sh [--runs N] [--size WxH] [--frames N] [--args "OPTIONS"] [--only RE] [CRTC]
#
#   --runs N     timed runs of each way per workload; medians reported (default 3)
#   --size WxH   the stills' size (default 1920x1080)
#   --frames N   the animation's frames (default 60)
#   --args OPTS  more crtc options for every render, e.g. "--supersampling 3" for longer ones
#   --only RE    only the workloads whose name matches the extended regular expression RE
#   CRTC         the crtc binary (default: $CRTC, else build/bin/crtc), built with MPI
#
# environment:
#   BENCH_OUT    folder for the images and logs (default: a temporary folder, removed at exit)
#   MPIRUN       the mpirun command (default: mpirun with shared memory between the processes)
#
# exit status: 0 done; 1 a run failed or images differed; 2 bad usage or missing tool.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=../common.sh
source "$here/../common.sh"
root=$(cd "$here/../.." && pwd)

runs=3
size=1920x1080
frames=60
args=
only=
bench_parse_options runs size frames args only -- "$@"
read -r -a extra <<<"$args"
bench_check_crtc
[[ $have_crtc == 1 ]] || exit 2
command -v mpirun >/dev/null || { echo "$0: mpirun not found (apt-get install openmpi-bin)" >&2; exit 2; }
bench_output_folder mpi
width=${size%x*}
height=${size#*x}
# Shared memory between the processes, no UCX (docs/distributed.md); root may run MPI jobs in a
# container.
read -r -a mpirun <<<"${MPIRUN:-mpirun --allow-run-as-root --oversubscribe --bind-to none --mca btl self,vader --mca btl_vader_single_copy_mechanism none --mca pml ob1}"

# time_run VAR command...: the wall time of the command, in seconds, into VAR, the time crtc's
# summary line reports (from its first evaluation to the last file, so without the start of
# the processes and MPI's initialisation) into VAR_render, and the processor time of all its
# processes (user and system, mpirun's included) into VAR_cpu.
time_run() {
    local var=$1 start end
    shift
    stamp start
    /usr/bin/time -f "cpu %U %S" -o "$logs/cpu" "$@" >"$logs/last.log" 2>&1 ||
        { cat "$logs/last.log" >&2; echo "$0: failed: $*" >&2; exit 1; }
    stamp end
    cat "$logs/last.log" >>"$logs/run.log"
    printf -v "${var}_cpu" '%s' "$(awk '/^cpu / { printf "%.3f", $2 + $3 }' "$logs/cpu")"
    printf -v "$var" '%s' "$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", (b - a) / 1e9 }')"
    printf -v "${var}_render" '%s' "$(sed -n 's/^crtc: .*, \([0-9.]*\)s, [0-9.]* Mrays.*/\1/p' "$logs/last.log" | tail -1)"
}
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# bench NAME OUTPUT crtc-arguments...: the three ways, alternating; one table row.
bench() {
    local name=$1 output=$2
    shift 2
    [[ -z $only ]] || grep -qE -- "$only" <<<"$name" || return 0
    set -- "$@" "${extra[@]}"
    local alone=() ranks=() threads=() alone_r=() ranks_r=() threads_r=() alone_c=() ranks_c=() threads_c=()
    local t t_render t_cpu
    for ((run = 1; run <= runs; run++)); do
        time_run t "$crtc" --threads 1 "$@" -o "$out/alone.$output"
        alone+=("$t") alone_r+=("$t_render") alone_c+=("$t_cpu")
        time_run t "${mpirun[@]}" -np 2 "$crtc" --threads 1 "$@" -o "$out/ranks.$output"
        ranks+=("$t") ranks_r+=("$t_render") ranks_c+=("$t_cpu")
        time_run t "$crtc" --threads 2 "$@" -o "$out/threads.$output"
        threads+=("$t") threads_r+=("$t_render") threads_c+=("$t_cpu")
        for way in ranks threads; do
            for f in "$out"/alone.${output/\%04d/*}; do
                cmp -s "$f" "${f/alone./$way.}" || { echo "$0: $name: $way made a different ${f##*/}" >&2; exit 1; }
            done
        done
    done
    row "$name, wall" "$(median "${alone[@]}")" "$(median "${ranks[@]}")" "$(median "${threads[@]}")"
    row "$name, crtc's time" "$(median "${alone_r[@]}")" "$(median "${ranks_r[@]}")" "$(median "${threads_r[@]}")"
    # Processor time: on a loaded machine the one figure the other builds do not change much.
    # "speed-up" here is 1 process's processor time over the others', the work each way wastes.
    row "$name, processor time" "$(median "${alone_c[@]}")" "$(median "${ranks_c[@]}")" "$(median "${threads_c[@]}")"
}
row() { # name alone ranks threads
    awk -v n="$1" -v a="$2" -v r="$3" -v h="$4" 'BEGIN {
        printf "| %s | %.2f | %.2f | %.2f | %.2fx | %.2fx | %+.1f %% |\n", n, a, r, h, a / r, a / h, (a / r - a / h) / (a / h) * 100 }'
}

echo "crtc: $crtc; $runs runs, medians; stills ${width}x${height}, animation $frames frames${extra:+; options ${extra[*]}}; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| workload | 1 process x 1 thread (s) | 2 processes x 1 thread (s) | 1 process x 2 threads (s) | speed-up, 2 processes | speed-up, 2 threads | processes against threads |"
echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
for scene in "$root"/bench/render/*.crt; do
    name=$(basename "$scene" .crt)
    # mesh.crt reads the 1M-triangle terrain that bench/render writes on first use.
    if [[ $name == mesh && ! -f $root/bench/render/generated/terrain.ply ]] &&
        { [[ -z $only ]] || grep -qE -- "$only" <<<"$name ${width}x${height}"; }; then
        echo "writing the terrain mesh into $root/bench/render/generated/ ..." >&2
        python3 "$root/bench/render/gen_terrain.py" "$root/bench/render/generated" >&2 ||
            { echo "$0: could not write the terrain" >&2; exit 1; }
    fi
    bench "$name ${width}x${height}" "$name.png" "$scene" --width "$width" --height "$height"
done
bench "orbit, $frames frames" "orbit_%04d.png" "$root/demos/orbit.crt" --frames "$frames"
# The same work either way: the costly corner's tiles handed out first, then last.
bench "corner, costly tiles first" "corner_first.png" "$here/corner.crt" --time 0
bench "corner, costly tiles last" "corner_last.png" "$here/corner.crt" --time 1
echo
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "images and logs: $out$keep_hint"
