#!/usr/bin/env bash
# Ray kernel benchmark: crtc against Embree 3's single-ray API on the same scenes, grids of
# spheres and a terrain of 1M triangles (see bench/README.md, "Ray kernel vs Embree 3"). Per
# pixel one camera ray and, where the surface faces the point light, one shadow ray. Both
# tools run alternately; the table gives median render rates (rays / render seconds, each
# tool's own clock), their ratio measured in the same run, BVH build times and peak memory.
#
# usage: bench/embree/run.sh [--runs N] [--scenes LIST] [--grids LIST] [--threads LIST] [CRTC]
#
#   --runs N        timed runs per tool and case; medians reported (default $RUNS, else 3)
#   --scenes LIST   comma-separated scenes (default spheres,terrain): spheres, one case per
#                   grid of --grids; terrain, the mesh of bench/render/mesh.crt (999,698
#                   triangles, written into bench/render/generated/ by gen_terrain.py on
#                   first use)
#   --grids LIST    comma-separated spheres per side (default 100,1000: 10,000 and 1,000,000)
#   --threads LIST  comma-separated thread counts (default 1,2)
#   CRTC            path of the crtc binary (default: $CRTC, else build/bin/crtc under the
#                   repository root)
#
# environment:
#   BENCH_OUT   folder for the scenes, images, logs and the Embree programs (default: a
#               temporary folder, removed at exit)
#   CXX         compiler for the Embree programs (default g++)
#
# Needs Debian's libembree-dev (Embree 3) and time (scripts/setup.sh --bench installs
# them). The Embree programs are built here, into the output folder; crtc never links Embree.
#
# exit status: 0 done; 1 a run failed or the two tools traced different numbers of rays;
#              2 bad usage or missing tool; 3 crtc not found (Embree side only).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=../common.sh
source "$here/../common.sh"
root=$(cd "$here/../.." && pwd)

runs=${RUNS:-3}
scenes=spheres,terrain
grids=100,1000
thread_counts=1,2
bench_parse_options runs scenes grids threads=thread_counts -- "$@"

positive_list() { [[ $1 =~ ^[1-9][0-9]*(,[1-9][0-9]*)*$ ]]; }
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "$0: --runs must be a positive integer, got '$runs'" >&2; exit 2; }
[[ $scenes =~ ^(spheres|terrain)(,(spheres|terrain))*$ ]] ||
    { echo "$0: bad --scenes '$scenes' (spheres, terrain)" >&2; exit 2; }
positive_list "$grids" || { echo "$0: bad --grids '$grids'" >&2; exit 2; }
positive_list "$thread_counts" || { echo "$0: bad --threads '$thread_counts'" >&2; exit 2; }
IFS=, read -r -a grid_list <<<"$grids"
IFS=, read -r -a thread_list <<<"$thread_counts"
if [[ ! -f /usr/include/embree3/rtcore.h ]]; then
    echo "$0: Embree 3 not found: apt-get install libembree-dev, or scripts/setup.sh --bench" >&2
    exit 2
fi
[[ -x /usr/bin/time ]] || { echo "$0: /usr/bin/time is needed (Debian: time)" >&2; exit 2; }

have_crtc=1
if [[ ! -x $crtc ]]; then
    have_crtc=0
    echo "$0: no crtc at '$crtc' (build it, or pass its path); measuring Embree only" >&2
fi
bench_output_folder embree

# The cases, spheres before the terrain: gridN (N spheres a side) and terrain.
cases=()
if [[ ",$scenes," == *,spheres,* ]]; then
    for n in "${grid_list[@]}"; do cases+=("grid$n"); done
fi
terrain_dir=$root/bench/render/generated
terrain_ply=$terrain_dir/terrain.ply
if [[ ",$scenes," == *,terrain,* ]]; then
    cases+=(terrain)
    if [[ ! -f $terrain_ply ]]; then
        echo "writing the terrain mesh into $terrain_dir/ ..." >&2
        python3 "$root/bench/render/gen_terrain.py" "$terrain_dir" ||
            { echo "$0: gen_terrain.py failed" >&2; exit 2; }
    fi
    terrain_triangles=$(LC_ALL=C awk '/^element face / { print $3 } /^end_header/ { exit }' "$terrain_ply")
fi

# ---------------------------------------------------------------------------
# The scenes: the one place their numbers are set. Both are 800 × 600 and lit by one point
# light. Spheres of radius 0.45·spacing on a grid × grid square 100 units wide at y = radius,
# a camera looking down on it from the near edge, the light above and to the left. The
# terrain (8 × 8 units around the origin) from bench/render/mesh.crt's camera and light.

width=800 height=600
view_of() {
    case $1 in
    grid*) eye=0,50,-30 target=0,0,50 fov=40 light=-30,80,-20 ;;
    terrain) eye=0,3,-6.5 target=0,0,0 fov=50 light=-6,7,-3 ;;
    esac
}
spacing_of() { awk -v n="$1" 'BEGIN { printf "%.17g", 100 / n }'; }
radius_of() { awk -v n="$1" 'BEGIN { printf "%.17g", 45 / n }'; }

# thousands NUMBER: with thousands separators (1,000,000)
thousands() { sed ':a; s/\([0-9]\)\([0-9]\{3\}\)\($\|,\)/\1,\2\3/; ta' <<<"$1"; }
label_of() {
    case $1 in
    grid*) echo "$(thousands $((${1#grid} * ${1#grid}))) spheres" ;;
    terrain) echo "$(thousands "$terrain_triangles")-triangle terrain" ;;
    esac
}
program_of() { [[ $1 == terrain ]] && echo terrain || echo sphere_grid; }

# write_settings CASE: the light, material and Settings in CRT, a plain diffuse white
# material (ambient 0.1 from Settings, Lambert 0.9 from the light, as the Embree programs
# shade), no reflection, so crtc traces one camera ray and at most one shadow ray per pixel.
write_settings() {
    view_of "$1"
    cat <<EOF
light = PointLight { origin -> vec3($light) color -> rgb(0.9, 0.9, 0.9) }
white = Material { color -> rgb(1.0, 1.0, 1.0) }
Settings {
    width -> $width
    height -> $height
    lights -> [light]
    camera -> Camera { position -> vec3($eye) pointing -> vec3($target) fov -> $fov }
    background -> rgb(0.0, 0.0, 0.0)
    ambient -> rgb(0.1, 0.1, 0.1)
    recursiondepth -> 0
    supersampling -> 1
}
EOF
}

# write_crt CASE FILE: the scene in CRT, that of its Embree program.
write_crt() {
    local c=$1 file=$2 n s r half
    if [[ $c == terrain ]]; then
        {
            echo "-- Written by bench/embree/run.sh: the terrain, the scene of its Embree program."
            write_settings "$c"
            echo "Scene { Mesh { file -> \"$terrain_ply\" material -> white } }"
        } >"$file"
        return
    fi
    n=${c#grid}
    s=$(spacing_of "$n") r=$(radius_of "$n") half=$(awk -v n="$n" 'BEGIN { print (n - 1) / 2 }')
    {
        echo "-- Written by bench/embree/run.sh: $((n * n)) spheres, the scene of its Embree program."
        write_settings "$c"
        cat <<EOF
Scene {
    for i in range($n) {
        for j in range($n) {
            Sphere { center -> vec3($s * (i - $half), $r, $s * j) radius -> $r material -> white }
        }
    }
}
EOF
    } >"$file"
}

declare -A built=()
for c in "${cases[@]}"; do
    program=$(program_of "$c")
    [[ -n ${built[$program]:-} ]] && continue
    built[$program]=1
    echo "building the Embree program: ${CXX:-g++} -O3 $here/$program.cpp -lembree3" >&2
    "${CXX:-g++}" -std=c++17 -O3 -Wall -Wextra -o "$out/$program" "$here/$program.cpp" -lembree3 -pthread
done

# run_embree CASE THREADS RUN: sets rays, camera, shadow, build, render, peak (MB)
run_embree() {
    local c=$1 t=$2 r=$3 log scene extra=()
    log=$logs/embree.$c.$t.$r
    view_of "$c"
    if [[ $c == terrain ]]; then
        scene=(--ply "$terrain_ply")
    else
        scene=(--grid "${c#grid}" --spacing "$(spacing_of "${c#grid}")" --radius "$(radius_of "${c#grid}")")
    fi
    [[ $r -eq 1 ]] && extra=(--ppm "$out/embree.$c.ppm")
    if ! /usr/bin/time -f %M -o "$log.mem" "$out/$(program_of "$c")" "${scene[@]}" --size "${width}x$height" \
        --threads "$t" --eye "$eye" --target "$target" --fov "$fov" --light "$light" "${extra[@]}" \
        >"$log.out" 2>"$log.err"; then
        echo "the Embree program failed ($(label_of "$c"), $t threads); log: $log.err$keep_hint" >&2
        head -n 20 "$log.err" >&2
        return 1
    fi
    read -r _ camera _ shadow _ rays < <(sed -n 's/^rays //p' "$log.out")
    build=$(sed -n 's/^build //p' "$log.out")
    render=$(sed -n 's/^render //p' "$log.out")
    peak=$(awk '{ printf "%.1f", $1 / 1024 }' "$log.mem")
}

# run_crtc CASE THREADS RUN: the same values from crtc --stats. crtc encodes its image on a
# thread of its own while it traces; at zlib level 0 that takes the least from its render
# threads, since the Embree program writes its image after its clock stops. The terrain's
# CRT file names the mesh where gen_terrain.py wrote it, outside the folders crtc lets a
# script read by default.
run_crtc() {
    local c=$1 t=$2 r=$3 log extra
    log=$logs/crtc.$c.$t.$r
    extra=(--max-entities 2000000)
    [[ $c == terrain ]] && extra=(--allow-read "$terrain_dir")
    if ! /usr/bin/time -f %M -o "$log.mem" "$crtc" "$out/$c.crt" -o "$out/crtc.$c.png" \
        --png-compression 0 --threads "$t" --stats -q "${extra[@]}" >"$log.out" 2>"$log.err"; then
        echo "$crtc failed on $(label_of "$c") ($t threads); log: $log.err$keep_hint" >&2
        head -n 20 "$log.err" >&2
        return 1
    fi
    local stats
    stats=$(grep 'stats:' "$log.err")
    camera=$(sed -n 's/.*rays: camera \([0-9]*\),.*/\1/p' <<<"$stats")
    shadow=$(sed -n 's/.*shadow \([0-9]*\) (total.*/\1/p' <<<"$stats")
    rays=$(sed -n 's/.*(total \([0-9]*\)).*/\1/p' <<<"$stats")
    build=$(sed -n 's/.*build \([0-9.]*\)s,.*/\1/p' <<<"$stats")
    render=$(sed -n 's/.*render \([0-9.]*\)s.*/\1/p' <<<"$stats")
    peak=$(awk '{ printf "%.1f", $1 / 1024 }' "$log.mem")
    if [[ -z $rays || -z $render ]]; then
        echo "could not read crtc --stats; log: $log.err$keep_hint" >&2
        return 1
    fi
}

mrays() { awk -v r="$1" -v s="$2" 'BEGIN { if (s > 0) printf "%.2f", r / s / 1e6; else print "inf" }'; }

# ---------------------------------------------------------------------------

echo "crtc:   $crtc" >&2
echo "Embree: $(dpkg-query -W -f='${Package} ${Version}' libembree3-3 2>/dev/null || echo 'version unknown')" >&2
echo "runs per tool and case: $runs (median reported); load average: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
for c in "${cases[@]}"; do write_crt "$c" "$out/$c.crt"; done

declare -A E_RATE E_BUILD E_PEAK E_RAYS C_RATE C_BUILD C_PEAK C_RAYS E_ALL C_ALL
failed=0
for c in "${cases[@]}"; do
    for t in "${thread_list[@]}"; do
        k="$c $t"
        echo "running $(label_of "$c"), $t threads ..." >&2
        er=() eb=() ep=() cr=() cb=() cp=()
        status=ok
        for ((r = 1; r <= runs; r++)); do
            # The tools take turns at running first, so neither always meets the machine
            # as the other left it.
            order="embree crtc"
            [[ $((r % 2)) -eq 0 ]] && order="crtc embree"
            for tool in $order; do
                if [[ $tool == embree ]]; then
                    run_embree "$c" "$t" "$r" || { status="embree-error"; break 2; }
                    er+=("$(mrays "$rays" "$render")") eb+=("$build") ep+=("$peak")
                    E_RAYS[$k]="$camera + $shadow"
                elif [[ $have_crtc -eq 1 ]]; then
                    run_crtc "$c" "$t" "$r" || { status="crtc-error"; break 2; }
                    cr+=("$(mrays "$rays" "$render")") cb+=("$build") cp+=("$peak")
                    C_RAYS[$k]="$camera + $shadow"
                fi
            done
        done
        if [[ ${#er[@]} -eq $runs ]]; then
            E_RATE[$k]=$(median "${er[@]}") E_BUILD[$k]=$(median "${eb[@]}") E_PEAK[$k]=$(median "${ep[@]}")
            E_ALL[$k]=${er[*]}
        fi
        if [[ ${#cr[@]} -eq $runs ]]; then
            C_RATE[$k]=$(median "${cr[@]}") C_BUILD[$k]=$(median "${cb[@]}") C_PEAK[$k]=$(median "${cp[@]}")
            C_ALL[$k]=${cr[*]}
        fi
        [[ $status != ok ]] && failed=1
    done
done

# ---------------------------------------------------------------------------

echo
echo "| scene | threads | crtc Mrays/s | Embree Mrays/s | crtc / Embree | crtc build (s) | Embree build (s) | crtc peak MB | Embree peak MB |"
echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
for c in "${cases[@]}"; do
    for t in "${thread_list[@]}"; do
        k="$c $t"
        ratio=—
        [[ -n ${C_RATE[$k]:-} && -n ${E_RATE[$k]:-} ]] &&
            ratio=$(awk -v a="${C_RATE[$k]}" -v b="${E_RATE[$k]}" 'BEGIN { printf "%.0f %%", 100 * a / b }')
        printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$(label_of "$c")" "$t" \
            "${C_RATE[$k]:-—}" "${E_RATE[$k]:-—}" "$ratio" "${C_BUILD[$k]:-—}" "${E_BUILD[$k]:-—}" \
            "${C_PEAK[$k]:-—}" "${E_PEAK[$k]:-—}"
    done
done

echo
echo "Rays (camera + shadow; both must trace one camera ray per pixel and a shadow ray per lit"
echo "point), every single rate in run order, and the images' difference (crtc's PNG against"
echo "the Embree program's grey image, 1/255 units):"
echo
echo "| scene | threads | crtc rays | Embree rays | crtc runs (Mrays/s) | Embree runs (Mrays/s) |"
echo "| --- | ---: | --- | --- | --- | --- |"
for c in "${cases[@]}"; do
    for t in "${thread_list[@]}"; do
        k="$c $t"
        printf '| %s | %s | %s | %s | %s | %s |\n' "$(label_of "$c")" "$t" "${C_RAYS[$k]:-—}" \
            "${E_RAYS[$k]:-—}" "${C_ALL[$k]:-—}" "${E_ALL[$k]:-—}"
        # The shadow rays may differ by a few where float and double tests disagree at
        # silhouettes, or where a camera ray slips between two triangles in Embree (whose
        # default triangle test is not watertight); more than 0.1 % means the scenes differ.
        if [[ -n ${C_RAYS[$k]:-} && -n ${E_RAYS[$k]:-} ]] &&
            ! awk -v a="${C_RAYS[$k]}" -v b="${E_RAYS[$k]}" 'BEGIN {
                split(a, x, " \\+ "); split(b, y, " \\+ ");
                d = x[2] - y[2]; if (d < 0) d = -d;
                exit !(x[1] == y[1] && d <= 0.001 * (x[1] + x[2])) }'; then
            echo "the two tools traced different rays for $(label_of "$c"), $t threads" >&2
            failed=1
        fi
    done
done
if [[ $have_crtc -eq 1 ]] && command -v oiiotool >/dev/null; then
    echo
    for c in "${cases[@]}"; do
        [[ -f $out/crtc.$c.png && -f $out/embree.$c.ppm ]] || continue
        rmse=$(oiiotool "$out/crtc.$c.png" --ch R "$out/embree.$c.ppm" --diff 2>&1 |
            sed -n 's/.*RMS error = \([0-9.eE+-]*\).*/\1/p' | head -n 1 || true)
        why="float against double tests at the silhouettes"
        [[ $c == terrain ]] &&
            why="at shared edges: the triangle a float or a double test picks, and rays between two in Embree"
        rmse=$(awk -v v="${rmse:-0}" 'BEGIN { printf "%.3f", v * 255 }')
        echo "- $(label_of "$c"): image RMSE $rmse/255 ($why)"
    done
fi
echo
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
[[ -n ${BENCH_OUT:-} ]] && echo "scenes, images and logs: $out"

if [[ $failed -ne 0 ]]; then exit 1; fi
if [[ $have_crtc -eq 0 ]]; then exit 3; fi
exit 0
