#!/usr/bin/env bash
# Front-end benchmark: `crtc --check` (parse + evaluate) against the parse
# phase of POV-Ray 3.7 on four equivalent workloads. See bench/README.md.
#
# usage: bench/frontend/run.sh [CRTC]
#
#   CRTC        path of the crtc binary (default: $CRTC, else build/bin/crtc
#               under the repository root)
#
# environment:
#   CRTC_BASE   a second crtc binary (e.g. the build before a change), timed in
#               the same runs against the same POV-Ray parses; adds columns with
#               its time, peak memory and ratio to POV-Ray
#   RUNS        runs per tool and workload, median reported (default 3)
#   WORKLOADS   space-separated subset of: while_loop nested_spheres
#               macro_spheres literal_spheres (default: all four)
#   BENCH_OUT   folder for the generated literal_spheres files and the logs
#               (default: a temporary folder, removed at exit)
#   POVRAY      POV-Ray binary (default /usr/bin/povray)
#   STRICT=1    exit with status 1 when a goal is not met (literal_spheres
#               has none: it is reported only)
#
# exit status: 0 done; 1 a run failed (or a goal was missed with STRICT=1);
#              2 bad usage or missing tool; 3 crtc not found (POV-Ray side only).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=../common.sh
source "$here/../common.sh"
root=$(cd "$here/../.." && pwd)

if [[ ${1:-} == -h || ${1:-} == --help ]]; then
    # the header comment, up to the first line that is not a comment
    awk 'NR == 1 { next } !/^#/ { exit } { sub(/^# ?/, ""); print }' "${BASH_SOURCE[0]}"
    exit 0
fi
if [[ $# -gt 1 ]]; then
    echo "usage: $0 [CRTC]" >&2
    exit 2
fi

crtc=${1:-${CRTC:-$root/build/bin/crtc}}
base=${CRTC_BASE:-}
runs=${RUNS:-3}
povray=${POVRAY:-/usr/bin/povray}
timebin=/usr/bin/time
workloads=${WORKLOADS:-while_loop nested_spheres macro_spheres literal_spheres}
literal_n=100000

if ! [[ $runs =~ ^[1-9][0-9]*$ ]]; then
    echo "$0: RUNS must be a positive integer, got '$runs'" >&2
    exit 2
fi
for w in $workloads; do
    case $w in
        while_loop | nested_spheres | macro_spheres | literal_spheres) ;;
        *) echo "$0: unknown workload '$w'" >&2; exit 2 ;;
    esac
done
if [[ ! -x $timebin ]]; then
    echo "$0: $timebin (GNU time) is needed to measure peak memory: apt-get install time" >&2
    exit 2
fi
if ! "$timebin" -f '%M' -o /dev/null true 2>/dev/null; then
    echo "$0: $timebin is not GNU time (needs -f and -o): apt-get install time" >&2
    exit 2
fi
if [[ ! -x $povray ]]; then
    echo "$0: POV-Ray not found at $povray: apt-get install povray (or set POVRAY)" >&2
    exit 2
fi

bench_check_crtc
bench_check_base
bench_output_folder frontend

# ---------------------------------------------------------------------------

mb() { awk -v k="$1" 'BEGIN { printf "%.1f", k / 1024 }'; }

# file of a workload for a tool (crt | pov)
script_of() {
    local w=$1 ext=$2
    if [[ $w == literal_spheres ]]; then
        echo "$out/literal_spheres.$ext"
    else
        echo "$here/$w.$ext"
    fi
}

expected_objects() {
    if [[ $1 == while_loop ]]; then echo 1; else echo 100000; fi
}

failed=0

# run_pov WORKLOAD RUN -> sets pov_parse, pov_kb, pov_wall, pov_bound
run_pov() {
    local w=$1 r=$2 file log t0 t1 rc
    file=$(script_of "$w" pov)
    log=$logs/$w.pov.$r
    stamp t0
    rc=0
    (cd "$(dirname "$file")" &&
        HOME=$povhome "$timebin" -f '%M' -o "$log.mem" \
            "$povray" +W16 +H16 -D -F +WT2 "+I$(basename "$file")" \
            >"$log.out" 2>"$log.err") || rc=$?
    stamp t1
    pov_wall=$(elapsed "$t0" "$t1" 4)
    pov_kb=$(tail -n 1 "$log.mem")
    pov_parse=$(sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' "$log.err" | head -n 1)
    pov_bound=$(sed -n 's/.*Bounding Time:.*(\([0-9.]*\) seconds).*/\1/p' "$log.err" | head -n 1)
    local objects
    objects=$(sed -n 's/^Finite Objects: *\([0-9]*\).*/\1/p' "$log.err" | head -n 1)
    if [[ $rc -ne 0 || -z $pov_parse ]] || grep -q 'Parse Error' "$log.err"; then
        echo "POV-Ray failed on $file (exit $rc); log: $log.err$keep_hint" >&2
        grep -m 5 -i -B2 -A2 'error' "$log.err" >&2 || tail -n 20 "$log.err" >&2
        return 1
    fi
    if [[ $objects != "$(expected_objects "$w")" ]]; then
        echo "POV-Ray made ${objects:-no} objects from $file, expected $(expected_objects "$w")" >&2
        return 1
    fi
}

# run_crtc BINARY TAG WORKLOAD RUN -> sets crtc_wall, crtc_kb (TAG: crtc or base, names the logs)
run_crtc() {
    local bin=$1 tag=$2 w=$3 r=$4 file log t0 t1 rc
    file=$(script_of "$w" crt)
    log=$logs/$w.$tag.$r
    stamp t0
    rc=0
    "$bin" --check "$file" >"$log.out" 2>"$log.err" || rc=$?
    stamp t1
    crtc_wall=$(elapsed "$t0" "$t1" 4)
    # Peak memory from a second, untimed run under GNU time: timing that run would charge
    # crtc for starting GNU time. After the timed run, not before, so that the timed run
    # does not find memory another crtc has just freed (faster to touch here; see README).
    "$timebin" -f '%M' -o "$log.mem" "$bin" --check "$file" >/dev/null 2>&1 || rc=$?
    crtc_kb=$(tail -n 1 "$log.mem")
    if [[ $rc -ne 0 ]]; then
        echo "$bin --check failed on $file (exit $rc); log: $log.err$keep_hint" >&2
        head -n 20 "$log.err" >&2
        return 1
    fi
    if [[ -s $log.err && $r -eq 1 ]]; then
        echo "note: $bin printed diagnostics for $w (the workloads should give none):" >&2
        head -n 10 "$log.err" >&2
    fi
}

# ---------------------------------------------------------------------------

case " $workloads " in
    *" literal_spheres "*)
        echo "generating literal_spheres ($literal_n spheres) in $out" >&2
        "$here/gen_literal.sh" "$out" "$literal_n"
        ;;
esac

echo "POV-Ray: $povray ($(HOME=$povhome "$povray" --version 2>&1 | grep -m1 -o 'POV-Ray [0-9][0-9.a-z]*' || echo unknown version))" >&2
[[ $have_crtc -eq 1 ]] && echo "crtc:    $crtc" >&2
[[ $have_base -eq 1 ]] && echo "base:    $base" >&2
echo "runs per tool and workload: $runs (median reported)" >&2

declare -A P_PARSE P_KB P_WALL P_BOUND C_WALL C_KB B_WALL B_KB STATUS LINES LINES_POV BYTES_CRT BYTES_POV XCHECK

for w in $workloads; do
    echo "running $w ..." >&2
    parses=() pkbs=() pwalls=() pbounds=() cwalls=() ckbs=() bwalls=() bkbs=()
    status=ok
    crtc_ok=$have_crtc base_ok=$have_base
    for ((r = 1; r <= runs; r++)); do
        if run_pov "$w" "$r"; then
            parses+=("$pov_parse") pkbs+=("$pov_kb") pwalls+=("$pov_wall") pbounds+=("$pov_bound")
        else
            status="pov-error"
            break
        fi
        # With a base build, the two crtc builds take turns at running right after POV-Ray:
        # a run finds the memory the one before it freed, which changes its time.
        order="crtc base"
        [[ $((r % 2)) -eq 0 ]] && order="base crtc"
        for tag in $order; do
            if [[ $tag == crtc && $crtc_ok -eq 1 ]]; then
                if run_crtc "$crtc" crtc "$w" "$r"; then
                    cwalls+=("$crtc_wall") ckbs+=("$crtc_kb")
                else
                    status="crtc-error"
                    crtc_ok=0
                fi
            elif [[ $tag == base && $base_ok -eq 1 ]]; then
                if run_crtc "$base" base "$w" "$r"; then
                    bwalls+=("$crtc_wall") bkbs+=("$crtc_kb")
                else
                    [[ $status == ok ]] && status="base-error"
                    base_ok=0
                fi
            fi
        done
    done
    STATUS[$w]=$status
    [[ $status != ok ]] && failed=1
    if [[ ${#parses[@]} -eq $runs ]]; then
        P_PARSE[$w]=$(median "${parses[@]}")
        P_KB[$w]=$(median "${pkbs[@]}")
        P_WALL[$w]=$(median "${pwalls[@]}")
        P_BOUND[$w]=$(median "${pbounds[@]}")
    fi
    if [[ $have_crtc -eq 1 && ${#cwalls[@]} -eq $runs ]]; then
        C_WALL[$w]=$(median "${cwalls[@]}")
        C_KB[$w]=$(median "${ckbs[@]}")
    fi
    if [[ $have_base -eq 1 && ${#bwalls[@]} -eq $runs ]]; then
        B_WALL[$w]=$(median "${bwalls[@]}")
        B_KB[$w]=$(median "${bkbs[@]}")
    fi
    crt_file=$(script_of "$w" crt)
    pov_file=$(script_of "$w" pov)
    LINES[$w]=$(wc -l <"$crt_file")
    LINES_POV[$w]=$(wc -l <"$pov_file")
    BYTES_CRT[$w]=$(wc -c <"$crt_file")
    BYTES_POV[$w]=$(wc -c <"$pov_file")

    # while_loop: both tools print the accumulated value; they must agree.
    if [[ $w == while_loop && ($status == ok || $status == base-error) && $have_crtc -eq 1 ]]; then
        pov_x=$(sed -n 's/^x = *//p' "$logs/while_loop.pov.1.err" | head -n 1)
        crtc_x=$(grep -v '^[[:space:]]*$' "$logs/while_loop.crtc.1.out" | tail -n 1 || true)
        if [[ -z $crtc_x ]]; then
            XCHECK[$w]="crtc printed no value: result not cross-checked"
            echo "warning: crtc printed nothing for while_loop; its result is not cross-checked" >&2
        elif awk -v a="$pov_x" -v b="$crtc_x" 'BEGIN {
                d = a - b; if (d < 0) d = -d; m = a < 0 ? -a : a; if (m < 1) m = 1
                exit !(d <= 1e-6 * m) }'; then
            XCHECK[$w]="x agrees: POV-Ray $pov_x, crtc $crtc_x"
        else
            XCHECK[$w]="x DIFFERS: POV-Ray '$pov_x', crtc '$crtc_x'"
            STATUS[$w]=wrong-result
            failed=1
            echo "error: while_loop results differ: POV-Ray '$pov_x', crtc '$crtc_x'" >&2
        fi
    fi
done

# ---------------------------------------------------------------------------

goal_missed=0

fmt_lps() { awk -v n="$1" -v s="$2" 'BEGIN { if (s > 0) printf "%d", n / s; else print "inf" }' | sed ':a;s/\B[0-9]\{3\}\>/,&/;ta'; }

# ratio NUMERATOR DENOMINATOR -> "12.3x" ("—" without a numerator)
ratio_of() {
    [[ -n $1 ]] || { echo —; return; }
    awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.1fx", a / b; else print "inf" }'
}

base_head='' base_rule=''
[[ $have_base -eq 1 ]] && base_head=" base (s) | base peak MB | ratio (POV/base) |" base_rule=" ---: | ---: | ---: |"
echo
echo "| workload | POV-Ray parse (s) | POV-Ray peak MB | crtc (s) | crtc peak MB | ratio (POV/crtc) | goal | met? |$base_head"
echo "| --- | ---: | ---: | ---: | ---: | ---: | --- | --- |$base_rule"
for w in $workloads; do
    # literal_spheres has no goal: it is reported (time and lines/s) only.
    case $w in
        while_loop) goal="≥ 20x" ;;
        nested_spheres) goal="≥ 10x and less memory" ;;
        macro_spheres) goal="≥ 10x" ;;
        literal_spheres) goal="— (reported)" ;;
    esac
    pp=${P_PARSE[$w]:-} pk=${P_KB[$w]:-} cw=${C_WALL[$w]:-} ck=${C_KB[$w]:-}
    pp_cell=${pp:-error} pk_cell=error
    [[ -n $pk ]] && pk_cell=$(mb "$pk")
    if [[ $have_crtc -eq 0 ]]; then
        cw_cell=missing ck_cell=missing ratio=— met=pending
    elif [[ ${STATUS[$w]} == pov-error ]]; then
        cw_cell="not run" ck_cell="not run" ratio=— met=no
    elif [[ -z $cw ]]; then
        cw_cell=error ck_cell=error ratio=— met=no
    else
        cw_cell=$cw ck_cell=$(mb "$ck")
        ratio=$(ratio_of "$pp" "$cw")
        met=no
        case $w in
            while_loop) awk -v a="$pp" -v b="$cw" 'BEGIN { exit !(a != "" && a >= 20 * b) }' && met=yes ;;
            macro_spheres) awk -v a="$pp" -v b="$cw" 'BEGIN { exit !(a != "" && a >= 10 * b) }' && met=yes ;;
            nested_spheres)
                awk -v a="$pp" -v b="$cw" -v pm="$pk" -v cm="$ck" \
                    'BEGIN { exit !(a != "" && a >= 10 * b && cm < pm) }' && met=yes ;;
        esac
        [[ ${STATUS[$w]} == wrong-result ]] && met="no (wrong result)"
        [[ $met != yes && $w != literal_spheres ]] && goal_missed=1
    fi
    # no goal, so nothing met or missed (a failed run still makes the exit status 1)
    [[ $w == literal_spheres ]] && met=—
    base_cells=
    if [[ $have_base -eq 1 ]]; then
        bw=${B_WALL[$w]:-} bk=${B_KB[$w]:-}
        if [[ -n $bw ]]; then
            bw_cell=$bw
            [[ $w == literal_spheres ]] && bw_cell="$bw ($(fmt_lps "${LINES[$w]}" "$bw") lines/s)"
            base_cells=" $bw_cell | $(mb "$bk") | $(ratio_of "$pp" "$bw") |"
        elif [[ ${STATUS[$w]} == pov-error ]]; then
            base_cells=" not run | not run | — |"
        else
            base_cells=" error | error | — |"
        fi
    fi
    if [[ $w == literal_spheres ]]; then
        [[ -n $pp ]] && pp_cell="$pp ($(fmt_lps "${LINES_POV[$w]}" "$pp") lines/s)"
        [[ -n $cw ]] && cw_cell="$cw ($(fmt_lps "${LINES[$w]}" "$cw") lines/s)"
    fi
    echo "| $w | $pp_cell | $pk_cell | $cw_cell | $ck_cell | $ratio | $goal | $met |$base_cells"
done

echo
echo "Details (medians of $runs run(s); POV-Ray wall time includes its start-up, bounding and a 16x16 render):"
echo
echo "| workload | POV-Ray wall (s) | POV-Ray bounding (s) | .crt size | .pov size | notes |"
echo "| --- | ---: | ---: | ---: | ---: | --- |"
for w in $workloads; do
    note=${XCHECK[$w]:-}
    [[ ${STATUS[$w]} != ok ]] && note="${STATUS[$w]}${note:+; $note}"
    size_crt=$(awk -v b="${BYTES_CRT[$w]}" -v l="${LINES[$w]}" 'BEGIN { if (b > 1e6) printf "%.1f MB, %d lines", b / 1e6, l; else printf "%d B", b }')
    size_pov=$(awk -v b="${BYTES_POV[$w]}" 'BEGIN { if (b > 1e6) printf "%.1f MB", b / 1e6; else printf "%d B", b }')
    echo "| $w | ${P_WALL[$w]:-—} | ${P_BOUND[$w]:-—} | $size_crt | $size_pov | $note |"
done

if [[ -n ${BENCH_OUT:-} ]]; then
    echo
    echo "logs: $logs"
fi

if [[ $failed -ne 0 ]]; then exit 1; fi
if [[ ${STRICT:-0} == 1 && $goal_missed -ne 0 ]]; then exit 1; fi
if [[ $have_crtc -eq 0 ]]; then exit 3; fi
exit 0
