#!/usr/bin/env bash
# Global illumination: crtc's path tracer (Settings.integrator "path") against Blender's
# Cycles and POV-Ray 3.7's radiosity, on three scenes made alike in the three renderers
# (bench/gi/scenes.py): the Cornell box, the box with a glass sphere, and objects lit by a
# panorama. crtc and Cycles render more and more paths a pixel, POV-Ray radiosity presets
# from quick to best, and crtc and Cycles again with adaptive sampling (each pixel stopping
# once its own noise is below a threshold); each image is compared with crtc's converged reference, and the
# script prints wall time against relative MSE as Markdown tables, the time each renderer
# takes to reach a relative MSE of 1e-2 and 1e-3, and, with --svg, a log-log plot.
# See bench/README.md, "Global illumination".
#
# usage: bench/gi/run.sh [--size WxH] [--runs N] [--scenes a,b] [--svg FILE] [--replot DIR] [CRTC]
#
#   --size WxH    image size of every render (default 256x256)
#   --runs N      timed runs per point; the median wall time is reported (default 1)
#   --scenes LIST comma-separated subset of cornell,glass,panorama (default all)
#   --svg FILE    also draw the curves, one panel per scene, into FILE
#   --replot DIR  render nothing: print the tables (and draw --svg) again from the results a
#                 run kept in DIR (its BENCH_OUT)
#   CRTC          path of the crtc binary (default: $CRTC, else build/bin/crtc)
#
# environment:
#   THREADS            render threads of every renderer (default 2)
#   REFERENCE_SAMPLES  paths a pixel of crtc's reference and of Cycles' (default 4096), each
#                      rendered as two halves of different seeds
#   BOUNCES            crtc's bounces (default 8; Cycles is given one less, see cycles.py)
#   CRTC_SAMPLES       crtc's points, paths a pixel (default "4 16 64 256 1024")
#   CYCLES_SAMPLES     Cycles' points, samples a pixel (default "4 16 64 256 1024")
#   CRTC_TARGETS       crtc's adaptive points, --target-error (default "0.5 0.3 0.2 0.1 0.05
#                      0.03"), each pixel taking at most the last of CRTC_SAMPLES paths
#   CYCLES_THRESHOLDS  Cycles' adaptive points, its noise threshold (default "0.1 0.05 0.02
#                      0.01 0.005"), each pixel taking at most the last of CYCLES_SAMPLES
#   POV_PRESETS        POV-Ray's points, radiosity presets 1 (quick) to 5 (best) (default
#                      "1 2 3 4 5")
#   PLOT_TIME          the plot's time axis: wall (default) or cpu (processor time, the
#                      fairer one when other work shares the machine)
#   BENCH_OUT    folder for the images and logs (default: a temporary folder, removed at exit)
#   POVRAY       POV-Ray binary (default /usr/bin/povray)
#   BLENDER      Blender binary (default: blender on the PATH)
#
# exit status: 0 done; 1 a render or comparison failed; 2 bad usage or missing tool.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=../common.sh
source "$here/../common.sh"
root=$(cd "$here/../.." && pwd)

size=256x256
runs=1
scenes=cornell,glass,panorama
svg=
replot=
bench_parse_options size runs scenes svg replot -- "$@"
povray=${POVRAY:-/usr/bin/povray}
blender=${BLENDER:-blender}
threads=${THREADS:-2}
reference=${REFERENCE_SAMPLES:-4096}
bounces=${BOUNCES:-8}
crtc_samples=${CRTC_SAMPLES:-4 16 64 256 1024}
cycles_samples=${CYCLES_SAMPLES:-4 16 64 256 1024}
crtc_targets=${CRTC_TARGETS-0.5 0.3 0.2 0.1 0.05 0.03}
cycles_thresholds=${CYCLES_THRESHOLDS-0.1 0.05 0.02 0.01 0.005}
pov_presets=${POV_PRESETS:-1 2 3 4 5}
plot_time=${PLOT_TIME:-wall}

positive() { [[ $1 =~ ^[1-9][0-9]*$ ]]; }
positive "$runs" || { echo "$0: --runs must be a positive integer, got '$runs'" >&2; exit 2; }
positive "$threads" || { echo "$0: THREADS must be a positive integer, got '$threads'" >&2; exit 2; }
positive "$bounces" || { echo "$0: BOUNCES must be a positive integer, got '$bounces'" >&2; exit 2; }
[[ $reference =~ ^[1-9][0-9]*$ && $reference -ge 2 ]] ||
    { echo "$0: REFERENCE_SAMPLES must be an integer of at least 2, got '$reference'" >&2; exit 2; }
for n in $crtc_samples $cycles_samples; do positive "$n" || { echo "$0: bad sample count '$n'" >&2; exit 2; }; done
for e in $crtc_targets $cycles_thresholds; do
    [[ $e =~ ^(0\.[0-9]*[1-9][0-9]*|[1-9][0-9]*(\.[0-9]+)?)$ ]] || { echo "$0: bad threshold '$e'" >&2; exit 2; }
done
crtc_most=${crtc_samples##* } cycles_most=${cycles_samples##* }
for p in $pov_presets; do [[ $p =~ ^[1-5]$ ]] || { echo "$0: POV_PRESETS are 1 to 5, got '$p'" >&2; exit 2; }; done
[[ $size =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || { echo "$0: bad size '$size' (want WxH)" >&2; exit 2; }
[[ $plot_time == wall || $plot_time == cpu ]] || { echo "$0: PLOT_TIME is wall or cpu, got '$plot_time'" >&2; exit 2; }
IFS=, read -r -a scene_list <<<"$scenes"
for w in "${scene_list[@]}"; do
    case $w in
        cornell | glass | panorama) ;;
        *) echo "$0: unknown scene '$w' (cornell, glass, panorama)" >&2; exit 2 ;;
    esac
done
if [[ -z $replot ]]; then
    [[ -x $povray ]] || { echo "$0: POV-Ray not found at $povray: scripts/setup.sh --bench (or set POVRAY)" >&2; exit 2; }
    command -v "$blender" >/dev/null || { echo "$0: Blender not found ('$blender'): scripts/setup.sh --bench (or set BLENDER)" >&2; exit 2; }
    command -v oiiotool >/dev/null || { echo "$0: oiiotool is needed (openimageio-tools)" >&2; exit 2; }
    command -v python3 >/dev/null || { echo "$0: python3 is needed (it writes the scenes)" >&2; exit 2; }
    [[ -x $crtc ]] || { echo "$0: crtc not found at '$crtc'; build it or pass its path" >&2; exit 2; }
fi

if [[ -n $replot ]]; then
    [[ -d $replot ]] || { echo "$0: --replot: no folder '$replot'" >&2; exit 2; }
    out=$replot
    # the size, thread count, reference and adaptive caps the results were made with
    if [[ -f $out/run.txt ]]; then
        read -r size threads reference bounces kept_crtc_most kept_cycles_most <"$out/run.txt"
        crtc_most=${kept_crtc_most:-$crtc_most} cycles_most=${kept_cycles_most:-$cycles_most}
    fi
    for w in "${scene_list[@]}"; do
        [[ -s $out/$w.points && -s $out/$w.reference ]] || { echo "$0: --replot: no results for $w in $out" >&2; exit 2; }
    done
else
    bench_output_folder gi
    echo "$size $threads $reference $bounces $crtc_most $cycles_most" >"$out/run.txt"
    # The scenes at this size, and the panorama as a float OpenEXR file.
    python3 "$here/scenes.py" "$out" --size "$size" >"$logs/scenes.log" 2>&1 ||
        { echo "$0: bench/gi/scenes.py failed; log: $logs/scenes.log$keep_hint" >&2; exit 1; }
    oiiotool "$out/sky.pfm" -d float -o "$out/sky.exr" >"$logs/sky.log" 2>&1 ||
        { echo "$0: could not convert the panorama; log: $logs/sky.log$keep_hint" >&2; exit 1; }
fi
W=${size%x*} H=${size#*x}

# relmse IMAGE REFERENCE -> mean over pixels and channels of (a − b)² / (b² + 0.01): the
# squared error relative to the reference's value, 0.01 keeping dark pixels from dominating
relmse() {
    oiiotool "$1" --ch R,G,B "$2" --ch R,G,B --sub --dup --mul "$2" --ch R,G,B --dup --mul --addc 0.01 \
        --div --printstats 2>&1 | sed -n 's/.*Stats Avg: *\([^(]*\)(float).*/\1/p' |
        awk 'NF == 3 { printf "%.4g\n", ($1 + $2 + $3) / 3 }'
}

# timed CMD... -> runs CMD; sets wall and cpu (seconds: its whole process, and its
# processes' user + system time)
timed() {
    local t0 t1 c0 c1
    children_cpu_ms c0
    stamp t0
    "$@" || return 1
    stamp t1
    children_cpu_ms c1
    wall=$(elapsed "$t0" "$t1")
    cpu=$(awk -v a="$c0" -v b="$c1" 'BEGIN { printf "%.3f", (b - a) / 1000 }')
}

# crtc_image SCENE SAMPLES SEED NAME [crtc options] -> $out/NAME.exr
crtc_image() {
    local w=$1 n=$2 seed=$3 name=$4
    shift 4
    sed "s/integrator -> \"path\"/seed -> $seed integrator -> \"path\"/; s/bounces -> [0-9]*/bounces -> $bounces/" \
        "$out/$w.crt" >"$out/$name.crt"
    timed "$crtc" "$out/$name.crt" -o "$out/$name.exr" --samples "$n" --threads "$threads" -q "$@" \
        2>"$logs/$name.err" || { echo "crtc failed on $name.crt; log: $logs/$name.err$keep_hint" >&2; return 1; }
}

# cycles_image SCENE SAMPLES SEED NAME [cycles.py options] -> $out/NAME.exr
cycles_image() {
    local w=$1 n=$2 seed=$3 name=$4
    shift 4
    rm -f "$out/$name.exr"
    timed "$blender" -b --factory-startup --python-exit-code 1 --python "$here/cycles.py" -- \
        --scene "$w" --size "$size" --samples "$n" --bounces "$bounces" --threads "$threads" \
        --seed "$seed" --out "$out/$name.exr" --dir "$out" "$@" >"$logs/$name.out" 2>&1 &&
        [[ -s $out/$name.exr ]] || { echo "Blender failed on $w; log: $logs/$name.out$keep_hint" >&2; return 1; }
}

# The radiosity block of POV-Ray preset P, then its anti-aliasing options after a '|'.
# Preset 1 is POV-Ray's defaults; each next one takes more samples (count), reuses them
# less (error_bound, nearest_count), follows more bounces (recursion_limit) and samples
# more finely before the render (pretrace_end); from 3 on, every pixel is supersampled.
pov_preset() {
    case $1 in
        1) echo "count 35 error_bound 1.8 recursion_limit 2 nearest_count 5 pretrace_end 0.04|-A" ;;
        2) echo "count 100 error_bound 1.0 recursion_limit 3 nearest_count 8 pretrace_end 0.02|-A" ;;
        3) echo "count 200 error_bound 0.5 recursion_limit 4 nearest_count 10 pretrace_end 0.01|+A0.0 +AM1 -J +R2" ;;
        4) echo "count 400 error_bound 0.3 recursion_limit 6 nearest_count 15 pretrace_end 0.005|+A0.0 +AM1 -J +R3" ;;
        5) echo "count 800 error_bound 0.2 recursion_limit 8 nearest_count 20 pretrace_end 0.005|+A0.0 +AM1 -J +R3" ;;
    esac
}

# pov_image SCENE PRESET NAME -> $out/NAME.exr
pov_image() {
    local w=$1 p=$2 name=$3 radiosity aa
    IFS='|' read -r radiosity aa <<<"$(pov_preset "$p")"
    echo "radiosity { $radiosity pretrace_start 0.08 low_error_factor 0.5 minimum_reuse 0.015" \
        "gray_threshold 0 brightness 1 adc_bailout 0.001 }" >"$out/radiosity.inc"
    cd "$out" # in this shell: a subshell would add its start to the time
    # shellcheck disable=SC2086 # the anti-aliasing options are words
    timed env HOME="$povhome" "$povray" "+I$w.pov" "+O$name.exr" +FE "+W$W" "+H$H" -D -V -P \
        "+WT$threads" File_Gamma=1.0 Antialias_Gamma=1.0 $aa >"$logs/$name.out" 2>"$logs/$name.err" ||
        { cd "$OLDPWD"; echo "POV-Ray failed on $w.pov; log: $logs/$name.err$keep_hint" >&2; return 1; }
    cd "$OLDPWD"
}

# point TOOL LABEL SCENE NAME CMD... -> times `runs` renders of one setting, keeps the last
# image, and appends "tool|label|wall|cpu|relmse" to $out/SCENE.points
point() {
    local tool=$1 label=$2 w=$3 name=$4 walls=() cpus=() r e
    shift 4
    for ((r = 1; r <= runs; r++)); do
        "$@" || return 1
        walls+=("$wall") cpus+=("$cpu")
    done
    e=$(relmse "$out/$name.exr" "$out/$w.reference.exr")
    [[ -n $e ]] || { echo "could not compare $name.exr with the reference" >&2; return 1; }
    echo "$tool|$label|$(median "${walls[@]}")|$(median "${cpus[@]}")|$e" >>"$out/$w.points"
}

# reference TOOL SCENE -> $out/SCENE.TOOL_reference.exr, the mean of two halves (seeds 1
# and 2); prints "wall|cpu|noise", the noise being the reference's own relative MSE as
# estimated from its halves: a quarter of their distance (each half's is twice the whole's)
reference_of() {
    local tool=$1 w=$2 half=$((reference / 2)) s total_wall=0 total_cpu=0
    for s in 1 2; do
        "${tool}_image" "$w" "$half" "$s" "$w.${tool}_reference_$s" || return 1
        total_wall=$(awk -v a="$total_wall" -v b="$wall" 'BEGIN { printf "%.3f", a + b }')
        total_cpu=$(awk -v a="$total_cpu" -v b="$cpu" 'BEGIN { printf "%.3f", a + b }')
    done
    oiiotool "$out/$w.${tool}_reference_1.exr" --ch R,G,B "$out/$w.${tool}_reference_2.exr" --ch R,G,B \
        --add --mulc 0.5 -d float -o "$out/$w.${tool}_reference.exr" || return 1
    local d
    d=$(relmse "$out/$w.${tool}_reference_1.exr" "$out/$w.${tool}_reference_2.exr")
    echo "$total_wall|$total_cpu|$(awk -v d="$d" 'BEGIN { printf "%.3g", d / 4 }')"
}

[[ -z $replot ]] && echo "crtc: $crtc; Cycles: $blender; POV-Ray: $povray; $size, $threads threads," \
    "references $reference paths a pixel, bounces $bounces, median of $runs runs" >&2
failed=0
for w in "${scene_list[@]}"; do
    [[ -n $replot ]] && break
    : >"$out/$w.points"
    echo "$w: crtc's reference, $reference paths a pixel ..." >&2
    crtc_ref=$(reference_of crtc "$w") || { failed=1; continue; }
    cp "$out/$w.crtc_reference.exr" "$out/$w.reference.exr"
    echo "$w: Cycles' reference, $reference samples a pixel ..." >&2
    cycles_ref=$(reference_of cycles "$w") || { failed=1; continue; }
    agreement=$(relmse "$out/$w.cycles_reference.exr" "$out/$w.reference.exr")
    echo "$reference|$crtc_ref|$cycles_ref|$agreement" >"$out/$w.reference"
    for n in $crtc_samples; do
        echo "$w: crtc, $n paths a pixel ..." >&2
        point crtc "$n" "$w" "$w.crtc_$n" crtc_image "$w" "$n" 0 "$w.crtc_$n" || failed=1
    done
    for n in $cycles_samples; do
        echo "$w: Cycles, $n samples a pixel ..." >&2
        point cycles "$n" "$w" "$w.cycles_$n" cycles_image "$w" "$n" 0 "$w.cycles_$n" || failed=1
    done
    for e in $crtc_targets; do
        echo "$w: crtc, target error $e, at most $crtc_most paths a pixel ..." >&2
        point crtc_adaptive "$e" "$w" "$w.crtc_adaptive_$e" \
            crtc_image "$w" "$crtc_most" 0 "$w.crtc_adaptive_$e" --target-error "$e" || failed=1
    done
    for e in $cycles_thresholds; do
        echo "$w: Cycles, noise threshold $e, at most $cycles_most samples a pixel ..." >&2
        point cycles_adaptive "$e" "$w" "$w.cycles_adaptive_$e" \
            cycles_image "$w" "$cycles_most" 0 "$w.cycles_adaptive_$e" --adaptive "$e" || failed=1
    done
    for p in $pov_presets; do
        echo "$w: POV-Ray, radiosity preset $p ..." >&2
        point pov "$p" "$w" "$w.pov_$p" pov_image "$w" "$p" "$w.pov_$p" || failed=1
    done
done

# ---------------------------------------------------------------------------

tool_name() {
    case $1 in
        crtc) echo crtc ;; cycles) echo Cycles ;; pov) echo POV-Ray ;;
        crtc_adaptive) echo "crtc, adaptive" ;; cycles_adaptive) echo "Cycles, adaptive" ;;
    esac
}
setting_of() {
    case $1 in
        crtc) echo "$2 paths a pixel" ;;
        cycles) echo "$2 samples a pixel" ;;
        crtc_adaptive) echo "target error $2, at most $crtc_most paths" ;;
        cycles_adaptive) echo "noise threshold $2, at most $cycles_most samples" ;;
        pov) local r
            r=$(pov_preset "$2")
            echo "preset $2: \`${r%|*}\`, \`${r#*|}\`" ;;
    esac
}

# time_to TARGET < "wall|relmse" lines of one tool -> the time at which its error falls to
# TARGET, interpolated log-log between the two points around it; "≤ T" when its first point
# is already below, "not reached (best E)" when none is
time_to() {
    sort -t'|' -k1,1g | awk -F'|' -v target="$1" '
        { t[NR] = $1; e[NR] = $2 }
        END {
            if (NR == 0) { print "—"; exit }
            best = e[1]
            for (i = 1; i <= NR; i++) {
                if (e[i] < best) best = e[i]
                if (e[i] <= target) {
                    if (i == 1) { printf "≤ %.3g\n", t[1]; exit }
                    a = log(t[i - 1]); b = log(t[i]); ea = log(e[i - 1]); eb = log(e[i])
                    if (e[i - 1] <= e[i]) { printf "%.3g\n", t[i]; exit }
                    printf "%.3g\n", exp(a + (log(target) - ea) * (b - a) / (eb - ea)); exit
                }
            }
            printf "not reached (best %.2g)\n", best
        }'
}

for w in "${scene_list[@]}"; do
    [[ -s $out/$w.points ]] || continue
    IFS='|' read -r rn crwall crcpu crnoise cywall cycpu cynoise agree <"$out/$w.reference"
    echo
    echo "### $w, $size"
    echo
    echo "Reference: crtc, $rn paths a pixel (two halves of different seeds), ${crwall} s (${crcpu} s of"
    echo "processor time); its own noise, a quarter of the distance between its halves: relative MSE"
    echo "$crnoise. Cycles' reference ($rn samples a pixel, ${cywall} s, ${cycpu} s of processor time, noise"
    echo "$cynoise) is $agree from it,"
    echo "where the two references' noise alone would make $(awk -v a="$crnoise" -v b="$cynoise" 'BEGIN { printf "%.3g", a + b }')."
    echo
    echo "| renderer | setting | wall time (s) | processor time (s) | relative MSE |"
    echo "| --- | --- | ---: | ---: | ---: |"
    while IFS='|' read -r tool label wall cpu e; do
        echo "| $(tool_name "$tool") | $(setting_of "$tool" "$label") | $wall | $cpu | $e |"
    done <"$out/$w.points"
done

echo
echo "### Time to reach a relative MSE, $size"
echo
echo "Wall time in seconds, interpolated log-log between the two settings around the target (processor time in brackets)."
echo
echo "| scene | renderer | relative MSE 1e-2 | relative MSE 1e-3 |"
echo "| --- | --- | ---: | ---: |"
for w in "${scene_list[@]}"; do
    [[ -s $out/$w.points ]] || continue
    for tool in crtc crtc_adaptive cycles cycles_adaptive pov; do
        grep -q "^$tool|" "$out/$w.points" || continue
        cells=()
        for target in 1e-2 1e-3; do
            by_wall=$(awk -F'|' -v t="$tool" '$1 == t { print $3 "|" $5 }' "$out/$w.points" | time_to "$target")
            by_cpu=$(awk -F'|' -v t="$tool" '$1 == t { print $4 "|" $5 }' "$out/$w.points" | time_to "$target")
            if [[ $by_wall == not* ]]; then cells+=("$by_wall"); else cells+=("$by_wall ($by_cpu)"); fi
        done
        echo "| $w | $(tool_name "$tool") | ${cells[0]} | ${cells[1]} |"
    done
done

# The plot: one panel per scene, log time across (PLOT_TIME), log relative MSE up, one line per
# renderer; the dashed line is the reference's own noise, the dotted ones 1e-2 and 1e-3.
if [[ -n $svg ]]; then
    for w in "${scene_list[@]}"; do
        [[ -s $out/$w.points ]] || continue
        sed "s/^/$w|/" "$out/$w.points"
        IFS='|' read -r _ _ _ crnoise _ _ _ _ <"$out/$w.reference"
        echo "$w|reference|$crnoise"
    done | awk -F'|' -v title="Global illumination: time against error, $size, $threads threads" \
        -v column="$([[ $plot_time == cpu ]] && echo 5 || echo 4)" \
        -v axis="$([[ $plot_time == cpu ]] && echo "processor time (s)" || echo "wall time (s)")" \
        -v crtc_n="${crtc_samples// /, }" -v cycles_n="${cycles_samples// /, }" -v presets="${pov_presets// /, }" \
        -v crtc_e="${crtc_targets// /, }" -v cycles_e="${cycles_thresholds// /, }" '
        function lx(v) { return log(v) / log(10) }
        function floor(v) { return v == int(v) || v > 0 ? int(v) : int(v) - 1 }
        function ceil(v) { return v == int(v) || v < 0 ? int(v) : int(v) + 1 }
        function px(v) { return left + (lx(v) - x0) / (x1 - x0) * pw }
        function py(v) { return top + ph - (lx(v) - y0) / (y1 - y0) * ph }
        $2 == "reference" {
            noise[$1] = ($3 + 0 > 1e-7 ? $3 + 0 : 1e-7)
            if (miny == "" || noise[$1] < miny) miny = noise[$1]
            next
        }
        {
            n = ++count[$1]
            tool[$1, n] = $2; wall[$1, n] = $column + 0; err[$1, n] = ($6 + 0 > 1e-7 ? $6 + 0 : 1e-7)
            if (!($1 in order)) { order[$1] = ++scenes; names[scenes] = $1 }
            if (minx == "" || wall[$1, n] < minx) minx = wall[$1, n]
            if (maxx == "" || wall[$1, n] > maxx) maxx = wall[$1, n]
            if (miny == "" || err[$1, n] < miny) miny = err[$1, n]
            if (maxy == "" || err[$1, n] > maxy) maxy = err[$1, n]
        }
        END {
            pw = 320; ph = 260; top = 50; gap = 90
            x0 = floor(lx(minx)); x1 = ceil(lx(maxx)); y0 = floor(lx(miny)); y1 = ceil(lx(maxy))
            if (x1 == x0) x1++
            if (y1 == y0) y1++
            width = scenes * (pw + gap) + 40; height = top + ph + 142
            printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"12\">\n", width, height
            printf "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n"
            printf "<text x=\"20\" y=\"22\" font-size=\"15\">%s</text>\n", title
            # The adaptive series in the colour of their renderer, dashed, their points hollow.
            split("crtc cycles pov crtc_adaptive cycles_adaptive", tools, " ")
            split("#c0392b #e08a00 #2c6fbb #c0392b #e08a00", colours, " ")
            for (s = 1; s <= scenes; s++) {
                w = names[s]; left = 70 + (s - 1) * (pw + gap)
                printf "<text x=\"%d\" y=\"%d\" font-weight=\"bold\">%s</text>\n", left, top - 8, w
                printf "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"#444\"/>\n", left, top, pw, ph
                for (d = x0; d <= x1; d++) {
                    for (m = 1; m < 10; m++) {
                        v = m * 10 ^ d; if (lx(v) > x1) break
                        printf "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"%s\"/>\n", px(v), top, px(v), top + ph, m == 1 ? "#bbb" : "#eee"
                    }
                    printf "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%g</text>\n", px(10 ^ d), top + ph + 16, 10 ^ d
                }
                for (d = y0; d <= y1; d++) {
                    printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", left, py(10 ^ d), left + pw, py(10 ^ d)
                    printf "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">1e%d</text>\n", left - 6, py(10 ^ d) + 4, d
                }
                for (d = -3; d <= -2; d++)
                    if (d >= y0 && d <= y1)
                        printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#999\" stroke-dasharray=\"2 3\"/>\n", left, py(10 ^ d), left + pw, py(10 ^ d)
                printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">%s</text>\n", left + pw / 2, top + ph + 34, axis
                printf "<text transform=\"translate(%d %d) rotate(-90)\" text-anchor=\"middle\">relative MSE vs crtc reference</text>\n", left - 48, top + ph / 2
                if (w in noise && lx(noise[w]) >= y0) {
                    printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#777\" stroke-dasharray=\"5 4\"/>\n", left, py(noise[w]), left + pw, py(noise[w])
                    printf "<text x=\"%d\" y=\"%.1f\" fill=\"#555\" font-size=\"10\">reference noise</text>\n", left + 4, py(noise[w]) + 12
                }
                for (t = 1; t <= 5; t++) {
                    dashed = t > 3
                    path = ""; m = 0
                    for (i = 1; i <= count[w]; i++) {
                        if (tool[w, i] != tools[t]) continue
                        xs[++m] = px(wall[w, i]); ys[m] = py(err[w, i])
                        printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\" stroke=\"%s\"/>\n", xs[m], ys[m], dashed ? "white" : colours[t], colours[t]
                    }
                    for (a = 2; a <= m; a++)
                        for (b = a; b > 1 && xs[b - 1] > xs[b]; b--) {
                            tx = xs[b]; xs[b] = xs[b - 1]; xs[b - 1] = tx
                            ty = ys[b]; ys[b] = ys[b - 1]; ys[b - 1] = ty
                        }
                    for (a = 1; a <= m; a++) path = path sprintf("%s%.1f,%.1f", a == 1 ? "" : " ", xs[a], ys[a])
                    if (path != "") printf "<polyline points=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\"%s/>\n", path, colours[t], dashed ? " stroke-dasharray=\"6 3\"" : ""
                }
            }
            printf "<text x=\"20\" y=\"%d\" fill=\"%s\">crtc, path tracing: %s paths a pixel</text>\n", height - 84, colours[1], crtc_n
            printf "<text x=\"20\" y=\"%d\" fill=\"%s\">crtc, adaptive (dashed): target errors %s</text>\n", height - 66, colours[1], crtc_e
            printf "<text x=\"20\" y=\"%d\" fill=\"%s\">Blender Cycles, adaptive (dashed): noise thresholds %s</text>\n", height - 48, colours[2], cycles_e
            printf "<text x=\"20\" y=\"%d\" fill=\"%s\">Blender Cycles: %s samples a pixel (whole process: start-up and scene build included)</text>\n", height - 30, colours[2], cycles_n
            printf "<text x=\"20\" y=\"%d\" fill=\"%s\">POV-Ray 3.7 radiosity: presets %s, quick to best</text>\n", height - 12, colours[3], presets
            print "</svg>"
        }' >"$svg"
    echo >&2
    echo "plot written to $svg" >&2
fi

[[ -n ${BENCH_OUT:-} ]] && echo "images and logs: $out" >&2
exit $failed
