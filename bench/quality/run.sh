#!/usr/bin/env bash
# Render time against error: crtc and POV-Ray 3.7 render the same scenes with more and more
# samples per pixel (anti-aliasing, and lens samples for depth of field); each image is
# compared with a converged reference, and the script prints wall time against RMSE for both
# tools as Markdown tables (and, with --svg, a log-log plot).
# See bench/README.md, "Render time against error".
#
# usage: bench/quality/run.sh [--size WxH] [--runs N] [--scenes a,b] [--svg FILE] [--replot DIR] [CRTC]
#
#   --size WxH    image size of every render (default 400x300)
#   --runs N      timed runs per point; the median wall time is reported (default 3)
#   --scenes LIST comma-separated subset of sphere_grid,csg,dof (default all): the first two
#                 are bench/render/'s (anti-aliasing), dof is bench/quality/dof.crt and
#                 dof.pov (depth of field); each pair's images agree between the tools
#   --svg FILE    also draw the curves, one panel per scene, into FILE
#   --replot DIR  render nothing: print the tables (and draw --svg) again from the results a
#                 run kept in DIR (its BENCH_OUT)
#   CRTC          path of the crtc binary (default: $CRTC, else build/bin/crtc)
#
# environment:
#   THREADS      render threads of both tools (default 2)
#   REFERENCE    crtc's grid of the reference image: N x N samples per pixel (default 16)
#   REFERENCE_DOF  dof's reference, SxD: supersampling S, dofsamples D (default 6x64)
#   CRTC_DOF     crtc's dof points, SxD each (default "1x4 1x16 2x4 2x9 2x16 3x16 4x16")
#   POV_BLUR     POV-Ray's dof points: blur_samples, all taken (default "4 7 19 37 64 128 256")
#   CRTC_GRIDS   crtc's points: supersampling values (default "1 2 3 4 6 8")
#   CRTC_ADAPTIVE crtc's adaptive points, THRESHOLD:DEPTH each (default "0.1:2 0.1:3 0.03:3")
#   POV_DEPTHS   POV-Ray's points: +AM1 +A0.0 antialias depths (default "1 2 3 4 6 8")
#   BENCH_OUT    folder for the images and logs (default: a temporary folder, removed at exit)
#   POVRAY       POV-Ray binary (default /usr/bin/povray)
#
# exit status: 0 done; 1 a render or comparison failed; 2 bad usage or missing tool.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=../common.sh
source "$here/../common.sh"
root=$(cd "$here/../.." && pwd)
scenes_dir=$root/bench/render

size=400x300
runs=3
scenes=sphere_grid,csg,dof
svg=
replot=
bench_parse_options size runs scenes svg replot -- "$@"
povray=${POVRAY:-/usr/bin/povray}
threads=${THREADS:-2}
reference=${REFERENCE:-16}
crtc_grids=${CRTC_GRIDS:-1 2 3 4 6 8}
pov_depths=${POV_DEPTHS:-1 2 3 4 6 8}
crtc_adaptive=${CRTC_ADAPTIVE:-0.1:2 0.1:3 0.03:3}
reference_dof=${REFERENCE_DOF:-6x64}
crtc_dof=${CRTC_DOF:-1x4 1x16 2x4 2x9 2x16 3x16 4x16}
pov_blur=${POV_BLUR:-4 7 19 37 64 128 256}

positive() { [[ $1 =~ ^[1-9][0-9]*$ ]]; }
positive "$runs" || { echo "$0: --runs must be a positive integer, got '$runs'" >&2; exit 2; }
positive "$threads" || { echo "$0: THREADS must be a positive integer, got '$threads'" >&2; exit 2; }
positive "$reference" || { echo "$0: REFERENCE must be a positive integer, got '$reference'" >&2; exit 2; }
for n in $crtc_grids; do positive "$n" || { echo "$0: bad CRTC_GRIDS value '$n'" >&2; exit 2; }; done
for a in $crtc_adaptive; do
    [[ $a =~ ^[0-9]*\.?[0-9]+:[1-9]$ ]] || { echo "$0: bad CRTC_ADAPTIVE value '$a' (want THRESHOLD:DEPTH)" >&2; exit 2; }
done
for a in $reference_dof $crtc_dof; do
    [[ $a =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || { echo "$0: bad dof sampling '$a' (want SxD, e.g. 2x16)" >&2; exit 2; }
done
for n in $pov_blur; do positive "$n" || { echo "$0: bad POV_BLUR value '$n'" >&2; exit 2; }; done
for n in $pov_depths; do
    [[ $n =~ ^[1-9]$ ]] || { echo "$0: POV_DEPTHS values are 1 to 9 (POV-Ray's limit), got '$n'" >&2; exit 2; }
done
[[ $size =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || { echo "$0: bad size '$size' (want WxH)" >&2; exit 2; }
W=${size%x*} H=${size#*x}
IFS=, read -r -a scene_list <<<"$scenes"
for w in "${scene_list[@]}"; do
    case $w in
        sphere_grid | csg | dof) ;;
        *) echo "$0: unknown scene '$w' (sphere_grid, csg, dof)" >&2; exit 2 ;;
    esac
done
if [[ -z $replot && ! -x $povray ]]; then
    echo "$0: POV-Ray not found at $povray: scripts/setup.sh --bench (or set POVRAY)" >&2
    exit 2
fi
command -v oiiotool >/dev/null || [[ -n $replot ]] || { echo "$0: oiiotool is needed (openimageio-tools)" >&2; exit 2; }
[[ -x $crtc || -n $replot ]] || { echo "$0: crtc not found at '$crtc'; build it or pass its path" >&2; exit 2; }

if [[ -n $replot ]]; then
    [[ -d $replot ]] || { echo "$0: --replot: no folder '$replot'" >&2; exit 2; }
    out=$replot
    # the size and thread count the results were made with
    [[ -f $out/run.txt ]] && read -r size threads <"$out/run.txt"
    for w in "${scene_list[@]}"; do
        [[ -s $out/$w.points ]] || { echo "$0: --replot: no results for $w in $out" >&2; exit 2; }
    done
else
    bench_output_folder quality
    echo "$size $threads" >"$out/run.txt"
fi


# the folder of a scene's .crt and .pov
scene_dir() { if [[ $1 == dof ]]; then echo "$here"; else echo "$scenes_dir"; fi; }

# crtc_image SCENE SAMPLING NAME [--stats] -> renders $out/NAME.png; SAMPLING is a grid size
# N (N x N samples per pixel), THRESHOLD:DEPTH (adaptive anti-aliasing) or SxD (supersampling
# S and dofsamples D); sets wall (seconds)
crtc_image() {
    local w=$1 sampling=$2 name=$3 extra=${4:-} script=$out/$3.crt settings t0 t1
    if [[ $sampling == *:* ]]; then
        settings="supersampling -> 1 antialias -> \"adaptive\" aathreshold -> ${sampling%:*} aadepth -> ${sampling#*:}"
    elif [[ $sampling == *x* ]]; then
        settings="supersampling -> ${sampling%x*} dofsamples -> ${sampling#*x}"
    else
        settings="supersampling -> $sampling"
    fi
    sed -e "s/supersampling -> 1\$/$settings/" -e '/^ *dofsamples -> 1$/d' "$(scene_dir "$w")/$w.crt" >"$script"
    grep -qF "$settings" "$script" || { echo "$0: $w.crt has no 'supersampling -> 1' line" >&2; return 1; }
    stamp t0
    "$crtc" "$script" -o "$out/$name.png" --width "$W" --height "$H" --threads "$threads" -q $extra \
        2>"$logs/$name.err" || { echo "crtc failed on $script; log: $logs/$name.err$keep_hint" >&2; return 1; }
    stamp t1
    wall=$(elapsed "$t0" "$t1")
}

# pov_image SCENE NAME OPTIONS... -> renders $out/NAME.png; sets wall and spp (POV-Ray's
# own count of samples per pixel)
pov_image() {
    local w=$1 name=$2 t0 t1
    shift 2
    cd "$(scene_dir "$w")" # in this shell: a subshell would add its start to the time
    stamp t0
    HOME=$povhome "$povray" "+I$w.pov" "+O$out/$name.png" +FN "+W$W" "+H$H" -D -V -P \
        "+WT$threads" File_Gamma=1.0 Antialias_Gamma=1.0 "$@" >"$logs/$name.out" 2>"$logs/$name.err" ||
        { cd "$OLDPWD"; echo "POV-Ray failed on $w.pov; log: $logs/$name.err$keep_hint" >&2; return 1; }
    stamp t1
    cd "$OLDPWD"
    wall=$(elapsed "$t0" "$t1")
    spp=$(sed -n 's/.*Smpls\/Pxl: *\([0-9.]*\).*/\1/p' "$logs/$name.err" | tail -n 1)
}

# rmse_of A B -> RMSE between two images in 1/255
rmse_of() {
    local log
    log=$(oiiotool "$1" "$2" --diff 2>&1 || true)
    if grep -q 'PASS' <<<"$log" && ! grep -q 'RMS error' <<<"$log"; then
        echo 0.000
        return
    fi
    sed -n 's/.*RMS error = \([0-9.eE+-]*\).*/\1/p' <<<"$log" | head -n 1 |
        awk '{ printf "%.3f", $1 * 255 }'
}

# point TOOL LABEL SCENE SETTING CMD... -> times `runs` renders of one setting, keeps the
# last image, and appends "tool|label|spp|wall|rmse" to $out/SCENE.points
point() {
    local tool=$1 label=$2 w=$3 setting=$4 walls=() r e
    shift 4
    for ((r = 1; r <= runs; r++)); do
        "$@" || return 1
        walls+=("$wall")
    done
    e=$(rmse_of "$out/$w.$setting.png" "$out/$w.reference.png")
    [[ -n $e ]] || { echo "could not compare $w.$setting.png with the reference" >&2; return 1; }
    if [[ $tool == crtc && $label == "ss "* ]]; then
        spp=$((${label#ss } * ${label#ss }))
    elif [[ $tool == crtc && $label == "dof "* ]]; then
        local sd=${label#dof }
        spp=$((${sd%x*} * ${sd%x*} * ${sd#*x}))
    elif [[ $tool == pov && $label == "blur_samples "*", variance 0" ]]; then
        spp=${label#blur_samples }
        spp=${spp%%,*}
    elif [[ $tool == crtc ]]; then
        # adaptive: the camera rays of one more (untimed) run, per pixel
        local sampling=${setting#crtc_adaptive_}
        crtc_image "$w" "${sampling/_/:}" "$w.$setting.stats" --stats || return 1
        spp=$(sed -n 's/.*rays: camera \([0-9]*\).*/\1/p' "$logs/$w.$setting.stats.err" |
            awk -v p=$((W * H)) '{ printf "%.2f", $1 / p }')
    fi
    echo "$tool|$label|$spp|$(median "${walls[@]}")|$e" >>"$out/$w.points"
}

# the reference of scene W, and how converged it is: a smaller sampling's distance from it
reference_of() {
    local w=$1 ref check
    if [[ $w == dof ]]; then
        ref=$reference_dof
        check="$(( ${ref%x*} * 3 / 4 > 0 ? ${ref%x*} * 3 / 4 : 1 ))x$(( ${ref#*x} * 3 / 4 > 0 ? ${ref#*x} * 3 / 4 : 1 ))"
    else
        ref=$reference
        check=$((reference * 3 / 4 > 0 ? reference * 3 / 4 : 1))
    fi
    echo "$w: reference (crtc, sampling $ref) ..." >&2
    crtc_image "$w" "$ref" "$w.reference" || return 1
    local ref_wall=$wall
    crtc_image "$w" "$check" "$w.reference_check" || return 1
    echo "$w|$ref|$ref_wall|$check|$(rmse_of "$out/$w.reference_check.png" "$out/$w.reference.png")" >"$out/$w.reference.txt"
}

anti_aliasing_points() {
    local w=$1 n a d
    for n in $crtc_grids; do
        echo "$w: crtc supersampling $n ..." >&2
        point crtc "ss $n" "$w" "crtc_ss$n" crtc_image "$w" "$n" "$w.crtc_ss$n" || failed=1
    done
    for a in $crtc_adaptive; do
        echo "$w: crtc adaptive, threshold ${a%:*}, depth ${a#*:} ..." >&2
        point crtc "adaptive $a" "$w" "crtc_adaptive_${a/:/_}" crtc_image "$w" "$a" "$w.crtc_adaptive_${a/:/_}" || failed=1
    done
    for d in $pov_depths; do
        echo "$w: POV-Ray +AM1 +A0.0 +R$d ..." >&2
        point pov "+AM1 +A0.0 -J +R$d" "$w" "pov_m1_r$d" pov_image "$w" "$w.pov_m1_r$d" +AM1 +A0.0 -J "+R$d" || failed=1
    done
    echo "$w: POV-Ray's usual anti-aliasing (+A0.3, method 1, depth 3, jitter) ..." >&2
    point pov "+A0.3 +AM1 +R3 +J" "$w" pov_default pov_image "$w" "$w.pov_default" +A0.3 +AM1 +R3 +J || failed=1
    echo "$w: POV-Ray adaptive (+AM2 +A0.0 +R3) ..." >&2
    point pov "+AM2 +A0.0 -J +R3" "$w" pov_m2_r3 pov_image "$w" "$w.pov_m2_r3" +AM2 +A0.0 -J +R3 || failed=1
}

# Depth of field: crtc's lens samples (per grid sample) against POV-Ray's focal blur, which
# also spreads its samples over the pixel (no separate anti-aliasing: -A).
dof_points() {
    local w=$1 sd n
    for sd in $crtc_dof; do
        echo "$w: crtc supersampling ${sd%x*}, dofsamples ${sd#*x} ..." >&2
        point crtc "dof $sd" "$w" "crtc_dof$sd" crtc_image "$w" "$sd" "$w.crtc_dof$sd" || failed=1
    done
    for n in $pov_blur; do
        echo "$w: POV-Ray blur_samples $n, variance 0 ..." >&2
        point pov "blur_samples $n, variance 0" "$w" "pov_blur$n" pov_image "$w" "$w.pov_blur$n" -A \
            "Declare=Blur=$n" Declare=Variance=0 || failed=1
    done
    echo "$w: POV-Ray blur_samples 64 with its default confidence and variance ..." >&2
    point pov "blur_samples 64, confidence 0.9, variance 1/128" "$w" pov_blur_default pov_image "$w" \
        "$w.pov_blur_default" -A Declare=Blur=64 || failed=1
}

[[ -z $replot ]] && echo "POV-Ray: $povray; crtc: $crtc; $size, $threads threads, median of $runs runs" >&2
failed=0
for w in "${scene_list[@]}"; do
    [[ -n $replot ]] && break
    : >"$out/$w.points"
    reference_of "$w" || { failed=1; continue; }
    if [[ $w == dof ]]; then dof_points "$w"; else anti_aliasing_points "$w"; fi
done

# ---------------------------------------------------------------------------

for w in "${scene_list[@]}"; do
    [[ -s $out/$w.points ]] || continue
    IFS='|' read -r _ rn rwall rhalf rcheck <"$out/$w.reference.txt"
    echo
    echo "### $w, $size"
    echo
    describe() { # a reference's sampling in words
        if [[ $1 == *x* ]]; then echo "supersampling ${1%x*} and dofsamples ${1#*x}"; else echo "$1 × $1 samples per pixel"; fi
    }
    echo "Reference: crtc with $(describe "$rn") (${rwall} s); the image with $(describe "$rhalf")"
    echo "differs from it by ${rcheck}/255 RMSE, so smaller errors are not resolved."
    echo
    if [[ $w == dof ]]; then
        echo "Samples per pixel are camera rays per pixel: crtc's supersampling² × dofsamples, POV-Ray's"
        echo "blur_samples (with variance 0 it takes them all; with its defaults it stops earlier)."
    else
        echo "POV-Ray's samples per pixel are its own statistic (\`Smpls/Pxl\`); with a threshold above 0"
        echo "it counts only the samples of the pixels it supersampled."
    fi
    echo
    echo "| tool | setting | samples / pixel | wall time (s) | RMSE vs reference (/255) |"
    echo "| --- | --- | ---: | ---: | ---: |"
    while IFS='|' read -r tool label spp wall e; do
        name=crtc
        [[ $tool == pov ]] && name=POV-Ray
        setting=$label
        [[ $tool == crtc && $label == "ss "* ]] && setting="supersampling ${label#ss }"
        if [[ $tool == crtc && $label == "dof "* ]]; then
            sd=${label#dof }
            setting="supersampling ${sd%x*}, dofsamples ${sd#*x}"
        fi
        [[ $label == "blur_samples 64, confidence"* ]] && spp="≤ 64"
        if [[ $label == "adaptive "* ]]; then
            a=${label#adaptive }
            setting="antialias \"adaptive\", aathreshold ${a%:*}, aadepth ${a#*:}"
        fi
        echo "| $name | \`$setting\` | $spp | $wall | $e |"
    done <"$out/$w.points"
done

# The plot: one panel per scene, log wall time across, log RMSE up; crtc's points joined in
# order of samples, POV-Ray's method-1 points likewise, the two extra POV-Ray settings alone.
if [[ -n $svg ]]; then
    for w in "${scene_list[@]}"; do
        [[ -s $out/$w.points ]] || continue
        sed "s/^/$w|/" "$out/$w.points"
        IFS='|' read -r _ _ _ _ rcheck <"$out/$w.reference.txt"
        echo "$w|reference|$rcheck"
    done | awk -F'|' -v title="Render time against error, $size, $threads threads" \
        -v grids="${crtc_grids// /, }" -v depths="+R${pov_depths// /, +R}" '
        function lx(v) { return log(v) / log(10) }
        function floor(v) { return v == int(v) || v > 0 ? int(v) : int(v) - 1 }
        function ceil(v) { return v == int(v) || v < 0 ? int(v) : int(v) + 1 }
        function px(v) { return left + (lx(v) - x0) / (x1 - x0) * pw }
        function py(v) { return top + ph - (lx(v) - y0) / (y1 - y0) * ph }
        $2 == "reference" {
            floor_of[$1] = ($3 + 0 > 0.01 ? $3 + 0 : 0.01)
            if (miny == "" || floor_of[$1] < miny) miny = floor_of[$1]
            next
        }
        {
            scene[$1] = 1; n = ++count[$1]
            tool[$1, n] = $2; label[$1, n] = $3; wall[$1, n] = $5 + 0
            err[$1, n] = ($6 + 0 > 0.01 ? $6 + 0 : 0.01)
            if (!($1 in order)) { order[$1] = ++scenes; names[scenes] = $1 }
            if (minx == "" || wall[$1, n] < minx) minx = wall[$1, n]
            if (maxx == "" || wall[$1, n] > maxx) maxx = wall[$1, n]
            if (miny == "" || err[$1, n] < miny) miny = err[$1, n]
            if (maxy == "" || err[$1, n] > maxy) maxy = err[$1, n]
        }
        END {
            pw = 360; ph = 260; top = 50; gap = 90
            x0 = floor(lx(minx)); x1 = ceil(lx(maxx)); y0 = floor(lx(miny)); y1 = ceil(lx(maxy))
            if (x1 == x0) x1++
            if (y1 == y0) y1++
            width = scenes * (pw + gap) + 40; height = top + ph + 88
            printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"12\">\n", width, height
            printf "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n"
            printf "<text x=\"20\" y=\"22\" font-size=\"15\">%s</text>\n", title
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
                    for (m = 1; m < 10; m++) {
                        v = m * 10 ^ d; if (lx(v) > y1) break
                        printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"%s\"/>\n", left, py(v), left + pw, py(v), m == 1 ? "#bbb" : "#eee"
                    }
                    printf "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%g</text>\n", left - 6, py(10 ^ d) + 4, 10 ^ d
                }
                printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">wall time (s)</text>\n", left + pw / 2, top + ph + 34
                printf "<text transform=\"translate(%d %d) rotate(-90)\" text-anchor=\"middle\">RMSE vs reference (/255)</text>\n", left - 45, top + ph / 2
                if (w in floor_of && lx(floor_of[w]) >= y0) {
                    printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#777\" stroke-dasharray=\"5 4\"/>\n", left, py(floor_of[w]), left + pw, py(floor_of[w])
                    printf "<text x=\"%d\" y=\"%.1f\" fill=\"#555\" font-size=\"10\">reference resolution</text>\n", left + 4, py(floor_of[w]) + 12
                }
                for (t = 1; t <= 2; t++) {
                    want = t == 1 ? "crtc" : "pov"; colour = t == 1 ? "#c0392b" : "#2c6fbb"; path = ""; m = 0
                    for (i = 1; i <= count[w]; i++) {
                        if (tool[w, i] != want) continue
                        series = (want == "crtc" && label[w, i] ~ /^(ss|dof) /) || label[w, i] ~ /AM1 \+A0.0|variance 0/
                        if (series) { xs[++m] = px(wall[w, i]); ys[m] = py(err[w, i]) }
                        printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%d\" fill=\"%s\"/>\n", px(wall[w, i]), py(err[w, i]), series ? 3 : 5, series ? colour : "none\" stroke=\"" colour
                    }
                    # joined in order of time (a sampling list need not be in that order)
                    for (a = 2; a <= m; a++)
                        for (b = a; b > 1 && xs[b - 1] > xs[b]; b--) {
                            tx = xs[b]; xs[b] = xs[b - 1]; xs[b - 1] = tx
                            ty = ys[b]; ys[b] = ys[b - 1]; ys[b - 1] = ty
                        }
                    for (a = 1; a <= m; a++) path = path sprintf("%s%.1f,%.1f", a == 1 ? "" : " ", xs[a], ys[a])
                    if (path != "") printf "<polyline points=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\"/>\n", path, colour
                }
            }
            printf "<text x=\"20\" y=\"%d\" fill=\"#c0392b\">crtc: supersampling %s, or supersampling × dofsamples (line); adaptive anti-aliasing (open circles)</text>\n", height - 30, grids
            printf "<text x=\"20\" y=\"%d\" fill=\"#2c6fbb\">POV-Ray: +AM1 +A0.0 -J, %s, or blur_samples with variance 0 (line); +A0.3 +J, +AM2, default focal blur (open circles)</text>\n", height - 12, depths
            print "</svg>"
        }' >"$svg"
    echo >&2
    echo "plot written to $svg" >&2
fi

[[ -n ${BENCH_OUT:-} ]] && echo "images and logs: $out" >&2
exit $failed
