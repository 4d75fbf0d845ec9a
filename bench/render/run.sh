#!/usr/bin/env bash
# Render benchmark: crtc against POV-Ray 3.7 on seven equivalent scenes
# (mirror_room, sphere_grid, csg, textured, shapes, functions, mesh), rendered by both tools at each size,
# alternating, several times. Prints median wall times, their ratio and the
# RMSE between the two images as a Markdown table. See bench/README.md.
#
# usage: bench/render/run.sh [--runs N] [--sizes WxH,WxH] [--scenes a,b]
#                            [--base CRTC | --base-commit REV] [CRTC]
#
#   --runs N      timed runs per tool, scene and size; medians reported (default 3)
#   --sizes LIST  comma-separated image sizes (default 800x600,1920x1080)
#   --scenes LIST comma-separated subset of mirror_room,sphere_grid,csg,textured,shapes,
#                 functions,mesh (mesh: a 1M-triangle terrain, written into generated/ by
#                 gen_terrain.py on first use)
#   --base CRTC   a second crtc binary (e.g. the build before a change; default
#                 $CRTC_BASE), timed in the same runs against the same POV-Ray
#                 renders; adds columns with its time, its ratio to POV-Ray and
#                 crtc's time over its own
#   --base-commit REV
#                 the base is crtc as it was at commit REV of this repository,
#                 built first (Release, crtc only) in the output folder
#   CRTC          path of the crtc binary (default: $CRTC, else build/bin/crtc
#                 under the repository root)
#
# environment:
#   THREADS     render threads of both tools (default 2)
#   BENCH_OUT   folder for the images and logs (default: a temporary folder,
#               removed at exit)
#   POVRAY      POV-Ray binary (default /usr/bin/povray)
#   STRICT=1    exit with status 1 when a goal is not met
#
# exit status: 0 done; 1 a run failed (or a goal was missed with STRICT=1);
#              2 bad usage or missing tool; 3 crtc not found (POV-Ray side only).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=../common.sh
source "$here/../common.sh"
root=$(cd "$here/../.." && pwd)

runs=3
sizes=800x600,1920x1080
scenes=mirror_room,sphere_grid,csg,textured,shapes,functions,mesh
base=${CRTC_BASE:-}
base_commit=
bench_parse_options runs sizes scenes base base-commit=base_commit -- "$@"
povray=${POVRAY:-/usr/bin/povray}
threads=${THREADS:-2}

if ! [[ $runs =~ ^[1-9][0-9]*$ ]]; then
    echo "$0: --runs must be a positive integer, got '$runs'" >&2
    exit 2
fi
if ! [[ $threads =~ ^[1-9][0-9]*$ ]]; then
    echo "$0: THREADS must be a positive integer, got '$threads'" >&2
    exit 2
fi
IFS=, read -r -a size_list <<<"$sizes"
for s in "${size_list[@]}"; do
    if ! [[ $s =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]]; then
        echo "$0: bad size '$s' (want WxH, e.g. 800x600)" >&2
        exit 2
    fi
done
IFS=, read -r -a scene_list <<<"$scenes"
for w in "${scene_list[@]}"; do
    case $w in
        mirror_room | sphere_grid | csg | textured | shapes | functions | mesh) ;;
        *) echo "$0: unknown scene '$w' (mirror_room, sphere_grid, csg, textured, shapes, functions, mesh)" >&2; exit 2 ;;
    esac
done
if [[ ! -x $povray ]]; then
    echo "$0: POV-Ray not found at $povray: apt-get install povray, scripts/setup.sh --bench (or set POVRAY)" >&2
    exit 2
fi
if ! command -v oiiotool >/dev/null; then
    echo "$0: oiiotool is needed to compare the images (Debian: openimageio-tools)" >&2
    exit 2
fi

if [[ -n $base_commit && -n $base ]]; then
    echo "$0: give --base or --base-commit, not both" >&2
    exit 2
fi

bench_check_crtc
bench_output_folder render
if [[ ",$scenes," == *,mesh,* && ! -f $here/generated/terrain.inc ]]; then
    echo "writing the terrain mesh into $here/generated/ ..." >&2
    python3 "$here/gen_terrain.py" "$here/generated"
fi
[[ -n $base_commit ]] && bench_build_commit "$base_commit"
bench_check_base

# ---------------------------------------------------------------------------

# seconds, 2 decimals, between two children_cpu_ms readings
cpu_between() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (b - a) / 1000 }'; }

failed=0

# run_pov SCENE W H RUN -> sets pov_wall, pov_cpu, pov_parse, pov_trace; image $out/SCENE.WxH.pov.png
run_pov() {
    local w=$1 W=$2 H=$3 r=$4 log t0 t1 c0 c1 rc
    log=$logs/$w.${W}x$H.pov.$r
    # Started from this shell, in the scenes' folder, as crtc is: a subshell or GNU time
    # around it would add their own start to the time.
    cd "$here"
    children_cpu_ms c0
    stamp t0
    rc=0
    HOME=$povhome "$povray" "+I$w.pov" "+O$out/$w.${W}x$H.pov.png" +FN "+W$W" "+H$H" \
        -D -V -P -A "+WT$threads" File_Gamma=1.0 >"$log.out" 2>"$log.err" || rc=$?
    stamp t1
    children_cpu_ms c1
    cd "$OLDPWD"
    pov_wall=$(elapsed "$t0" "$t1")
    pov_cpu=$(cpu_between "$c0" "$c1")
    pov_parse=$(sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' "$log.err" | head -n 1)
    pov_trace=$(sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$log.err" | head -n 1)
    if [[ $rc -ne 0 ]] || grep -q 'Parse Error' "$log.err"; then
        echo "POV-Ray failed on $w.pov at ${W}x$H (exit $rc); log: $log.err$keep_hint" >&2
        grep -m 5 -i -B2 -A2 'error' "$log.err" >&2 || tail -n 20 "$log.err" >&2
        return 1
    fi
}

# run_crtc BINARY TAG SCENE W H RUN [--stats] -> sets crtc_wall, crtc_cpu; image
# $out/SCENE.WxH.TAG.png (TAG: crtc or base)
run_crtc() {
    local bin=$1 tag=$2 w=$3 W=$4 H=$5 r=$6 extra=${7:-} log t0 t1 c0 c1 rc
    log=$logs/$w.${W}x$H.$tag.$r
    children_cpu_ms c0
    stamp t0
    rc=0
    "$bin" "$here/$w.crt" -o "$out/$w.${W}x$H.$tag.png" --width "$W" --height "$H" \
        --threads "$threads" -q $extra >"$log.out" 2>"$log.err" || rc=$?
    stamp t1
    children_cpu_ms c1
    crtc_wall=$(elapsed "$t0" "$t1")
    crtc_cpu=$(cpu_between "$c0" "$c1")
    if [[ $rc -ne 0 ]]; then
        echo "$bin failed on $w.crt at ${W}x$H (exit $rc); log: $log.err$keep_hint" >&2
        head -n 20 "$log.err" >&2
        return 1
    fi
    if [[ -z $extra && -s $log.err && $r -eq 1 ]]; then
        echo "note: $bin printed diagnostics for $w (the scenes should give none):" >&2
        head -n 10 "$log.err" >&2
    fi
}

# compare SCENE W H -> sets rmse (in 1/255), maxerr (in 1/255), over2 (% of pixels over 2/255)
compare() {
    local w=$1 W=$2 H=$3 a b log
    a=$out/$w.${W}x$H.crtc.png
    b=$out/$w.${W}x$H.pov.png
    log=$logs/$w.${W}x$H.diff
    # --fail/--warn set the threshold of the "N pixels (p%) over T" line to 2/255
    oiiotool "$a" "$b" --fail 0.0078431 --warn 0.0078431 --diff >"$log" 2>&1 || true
    rmse=$(sed -n 's/.*RMS error = \([0-9.eE+-]*\).*/\1/p' "$log" | head -n 1)
    maxerr=$(sed -n 's/.*Max error *= *\([0-9.eE+-]*\).*/\1/p' "$log" | head -n 1)
    over2=$(sed -n 's/.*pixels (\([0-9.eE+-]*\)%) over.*/\1/p' "$log" | head -n 1)
    if [[ -z $rmse ]]; then
        if grep -q 'PASS' "$log"; then
            rmse=0 maxerr=0 over2=0
        else
            echo "could not compare $a and $b; log: $log$keep_hint" >&2
            cat "$log" >&2
            return 1
        fi
    fi
    rmse=$(awk -v v="$rmse" 'BEGIN { printf "%.3f", v * 255 }')
    maxerr=$(awk -v v="${maxerr:-0}" 'BEGIN { printf "%.0f", v * 255 }')
    over2=${over2:-0}
}

# ---------------------------------------------------------------------------

echo "POV-Ray: $povray ($(HOME=$povhome "$povray" --version 2>&1 | grep -m1 -o 'POV-Ray [0-9][0-9.a-z]*' || echo unknown version))" >&2
[[ $have_crtc -eq 1 ]] && echo "crtc:    $crtc" >&2
[[ $have_base -eq 1 ]] && echo "base:    $base" >&2
echo "runs per tool, scene and size: $runs (median reported), $threads threads" >&2
stamp start_all

declare -A P_WALL P_CPU P_PARSE P_TRACE P_SINGLE C_WALL C_CPU C_SINGLE B_WALL B_SINGLE RMSE MAXERR OVER2 STATUS STATS

for w in "${scene_list[@]}"; do
    for s in "${size_list[@]}"; do
        W=${s%x*} H=${s#*x}
        k="$w $s"
        echo "running $w at $s ..." >&2
        pwalls=() pcpus=() pparses=() ptraces=() cwalls=() ccpus=() bwalls=()
        status=ok
        crtc_ok=$have_crtc base_ok=$have_base
        for ((r = 1; r <= runs; r++)); do
            if run_pov "$w" "$W" "$H" "$r"; then
                pwalls+=("$pov_wall") pcpus+=("$pov_cpu") pparses+=("${pov_parse:-0}") ptraces+=("${pov_trace:-0}")
            else
                status=pov-error
                break
            fi
            # With a base build, the two crtc builds take turns at running right after
            # POV-Ray, so that neither always meets the machine as the other left it.
            order="crtc base"
            [[ $((r % 2)) -eq 0 ]] && order="base crtc"
            for tag in $order; do
                if [[ $tag == crtc && $crtc_ok -eq 1 ]]; then
                    if run_crtc "$crtc" crtc "$w" "$W" "$H" "$r"; then
                        cwalls+=("$crtc_wall") ccpus+=("$crtc_cpu")
                    else
                        status=crtc-error
                        crtc_ok=0
                    fi
                elif [[ $tag == base && $base_ok -eq 1 ]]; then
                    if run_crtc "$base" base "$w" "$W" "$H" "$r"; then
                        bwalls+=("$crtc_wall")
                    else
                        [[ $status == ok ]] && status="base-error"
                        base_ok=0
                    fi
                fi
            done
        done
        if [[ $base_ok -eq 1 && ${#bwalls[@]} -eq $runs ]]; then
            B_WALL[$k]=$(median "${bwalls[@]}")
            B_SINGLE[$k]=${bwalls[*]}
        fi
        if [[ ${#pwalls[@]} -eq $runs ]]; then
            P_WALL[$k]=$(median "${pwalls[@]}")
            P_CPU[$k]=$(median "${pcpus[@]}")
            P_PARSE[$k]=$(median "${pparses[@]}")
            P_TRACE[$k]=$(median "${ptraces[@]}")
            P_SINGLE[$k]=${pwalls[*]}
        fi
        if [[ $crtc_ok -eq 1 && ${#cwalls[@]} -eq $runs ]]; then
            C_WALL[$k]=$(median "${cwalls[@]}")
            C_CPU[$k]=$(median "${ccpus[@]}")
            C_SINGLE[$k]=${cwalls[*]}
            # one more, untimed run with --stats (the counters cost a little)
            if run_crtc "$crtc" crtc "$w" "$W" "$H" stats --stats; then
                STATS[$k]=$(grep 'stats:' "$logs/$w.${W}x$H.crtc.stats.err" | sed 's/^crtc: stats: //' | paste -sd ';' | sed 's/;/; /g')
            fi
            if compare "$w" "$W" "$H"; then
                RMSE[$k]=$rmse MAXERR[$k]=$maxerr OVER2[$k]=$over2
            else
                status=compare-error
            fi
        fi
        STATUS[$k]=$status
        [[ $status != ok ]] && failed=1
    done
done
stamp end_all
total=$(elapsed "$start_all" "$end_all")

# ---------------------------------------------------------------------------

goal_missed=0

base_head='' base_rule=''
[[ $have_base -eq 1 ]] && base_head=" base (s) | ratio (POV/base) | crtc/base |" base_rule=" ---: | ---: | ---: |"
echo
echo "| scene | size | POV-Ray (s) | crtc (s) | ratio (POV/crtc) | RMSE (/255) | goal met? (ratio ≥ 3, RMSE ≤ 2; textured: ratio ≥ 1) |$base_head"
echo "| --- | --- | ---: | ---: | ---: | ---: | --- |$base_rule"
for w in "${scene_list[@]}"; do
    for s in "${size_list[@]}"; do
        k="$w $s"
        pw=${P_WALL[$k]:-} cw=${C_WALL[$k]:-} e=${RMSE[$k]:-}
        if [[ $have_crtc -eq 0 ]]; then
            cw_cell=missing ratio=— e_cell=— met=pending
        elif [[ ${STATUS[$k]} == pov-error ]]; then
            cw_cell="not run" ratio=— e_cell=— met=no
        elif [[ -z $cw ]]; then
            cw_cell=error ratio=— e_cell=— met=no
        else
            cw_cell=$cw e_cell=${e:-error}
            ratio=$(awk -v a="$pw" -v b="$cw" 'BEGIN { if (b > 0) printf "%.2fx", a / b; else print "inf" }')
            # textured: crt's noise is its own, so its images are not held to POV-Ray's, and
            # its textured shading need only cost no more than POV-Ray's.
            speed=3 image=2
            [[ $w == textured ]] && speed=1 image=inf
            met=no
            awk -v a="$pw" -v b="$cw" -v e="$e" -v k="$speed" -v m="$image" \
                'BEGIN { exit !(e != "" && a >= k * b && (m == "inf" || e <= m)) }' && met=yes
            if [[ $met == no ]]; then
                why=()
                awk -v a="$pw" -v b="$cw" -v k="$speed" 'BEGIN { exit !(a < k * b) }' && why+=(speed)
                awk -v e="$e" -v m="$image" 'BEGIN { exit !(e == "" || (m != "inf" && e > m)) }' && why+=(image)
                met="no (${why[*]})"
            fi
        fi
        [[ $met != yes ]] && goal_missed=1
        base_cells=
        if [[ $have_base -eq 1 ]]; then
            bw=${B_WALL[$k]:-}
            if [[ -n $bw && -n $pw ]]; then
                base_cells=" $bw | $(awk -v a="$pw" -v b="$bw" 'BEGIN { if (b > 0) printf "%.2fx", a / b; else print "inf" }') |"
                if [[ -n $cw ]]; then
                    base_cells+=" $(awk -v a="$cw" -v b="$bw" 'BEGIN { if (b > 0) printf "%.3f", a / b; else print "—" }') |"
                else
                    base_cells+=" — |"
                fi
            elif [[ ${STATUS[$k]} == pov-error ]]; then
                base_cells=" not run | — | — |"
            else
                base_cells=" ${bw:-error} | — | — |"
            fi
        fi
        echo "| $w | $s | ${pw:-error} | $cw_cell | $ratio | $e_cell | $met |$base_cells"
    done
done

echo
echo "Details: median CPU time (user + system) of the whole process and its ratio, POV-Ray's own"
echo "parse and trace times (medians), every single wall time in run order, and how the images differ:"
echo
base_runs_head='' base_runs_rule=''
[[ $have_base -eq 1 ]] && base_runs_head=" base runs (s) |" base_runs_rule=" --- |"
echo "| scene | size | POV-Ray CPU (s) | crtc CPU (s) | CPU ratio | POV-Ray parse (s) | POV-Ray trace (s) | POV-Ray runs (s) | crtc runs (s) | max diff (/255) | pixels > 2/255 |$base_runs_head"
echo "| --- | --- | ---: | ---: | ---: | ---: | ---: | --- | --- | ---: | ---: |$base_runs_rule"
for w in "${scene_list[@]}"; do
    for s in "${size_list[@]}"; do
        k="$w $s"
        cratio=—
        [[ -n ${P_CPU[$k]:-} && -n ${C_CPU[$k]:-} ]] &&
            cratio=$(awk -v a="${P_CPU[$k]}" -v b="${C_CPU[$k]}" 'BEGIN { if (b > 0) printf "%.2fx", a / b; else print "inf" }')
        echo "| $w | $s | ${P_CPU[$k]:-—} | ${C_CPU[$k]:-—} | $cratio | ${P_PARSE[$k]:-—} | ${P_TRACE[$k]:-—} | ${P_SINGLE[$k]:-—} | ${C_SINGLE[$k]:-—} | ${MAXERR[$k]:-—} | ${OVER2[$k]:-—}${OVER2[$k]:+ %} |${base_runs_head:+ ${B_SINGLE[$k]:-—} |}"
    done
done

if [[ $have_crtc -eq 1 ]]; then
    echo
    echo "crtc --stats (one extra run per scene and size):"
    echo
    for w in "${scene_list[@]}"; do
        for s in "${size_list[@]}"; do
            k="$w $s"
            echo "- $w $s: ${STATS[$k]:-—}"
        done
    done
fi

echo
echo "total time of this run: ${total} s"
if [[ -n ${BENCH_OUT:-} ]]; then
    echo "images and logs: $out"
fi

if [[ $failed -ne 0 ]]; then exit 1; fi
if [[ ${STRICT:-0} == 1 && $goal_missed -ne 0 ]]; then exit 1; fi
if [[ $have_crtc -eq 0 ]]; then exit 3; fi
exit 0
