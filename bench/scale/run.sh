#!/usr/bin/env bash
# Scale benchmark: one terrain mesh drawn 1, 16, 256 and 10,000 times, at 1M and at 10M
# triangles, crtc against POV-Ray 3.7 (which shares a declared mesh2 between its objects).
# Each scene is rendered once by each tool; prints wall time and peak memory side by side
# as a Markdown table. See bench/README.md, "Scale".
#
# usage: bench/scale/run.sh [--sizes WxH] [--meshes 1M,10M] [--copies 1,16,256,10000] [CRTC]
#
#   --sizes WxH      image size (default 1920x1080)
#   --meshes LIST    terrain sizes: 1M (999,698 triangles) and 10M (9,999,392), written into
#                    bench/scale/generated/ by bench/render/gen_terrain.py on first use
#   --copies LIST    drawings of the mesh, each a square number (default 1,16,256,10000)
#   CRTC             path of the crtc binary (default: $CRTC, else build/bin/crtc)
#
# environment:
#   THREADS     render threads of both tools (default 2)
#   BENCH_OUT   folder for the images and logs (default: a temporary folder, removed at exit)
#   POVRAY      POV-Ray binary (default /usr/bin/povray)
#
# exit status: 0 done; 1 a run failed; 2 bad usage or missing tool; 3 crtc not found.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=../common.sh
source "$here/../common.sh"
root=$(cd "$here/../.." && pwd)

sizes=1920x1080
meshes=1M,10M
copies=1,16,256,10000
bench_parse_options sizes meshes copies -- "$@"
povray=${POVRAY:-/usr/bin/povray}
threads=${THREADS:-2}

if ! [[ $sizes =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]]; then
    echo "$0: --sizes takes one size WxH, got '$sizes'" >&2
    exit 2
fi
width=${BASH_REMATCH[1]} height=${BASH_REMATCH[2]}
IFS=, read -r -a mesh_list <<<"$meshes"
IFS=, read -r -a copy_list <<<"$copies"
for m in "${mesh_list[@]}"; do
    [[ $m == 1M || $m == 10M ]] || { echo "$0: --meshes takes 1M and 10M, got '$m'" >&2; exit 2; }
done
for k in "${copy_list[@]}"; do
    side=$(awk -v k="$k" 'BEGIN { s = int(sqrt(k) + 0.5); print (s * s == k && k > 0) ? s : 0 }')
    [[ $side -gt 0 ]] || { echo "$0: --copies takes square numbers, got '$k'" >&2; exit 2; }
done
[[ -x $povray ]] || { echo "$0: POV-Ray not found at $povray: scripts/setup.sh --bench (or set POVRAY)" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "$0: /usr/bin/time is needed (Debian: time)" >&2; exit 2; }
bench_check_crtc
[[ $have_crtc == 1 ]] || exit 3
bench_output_folder scale

# The terrains: gen_terrain.py's grid of N x N heights over 8 x 8 units.
grid_of() { case $1 in 1M) echo 708 ;; 10M) echo 2237 ;; esac; }
for m in "${mesh_list[@]}"; do
    if [[ ! -f $here/generated/$m/terrain.inc ]]; then
        echo "writing the $m-triangle terrain into $here/generated/$m/ ..." >&2
        python3 "$root/bench/render/gen_terrain.py" "$here/generated/$m" "$(grid_of "$m")"
    fi
done

# write_scenes MESH COPIES: the field of side x side terrains, 8 units apart, seen from above
# one corner, in both languages.
write_scenes() {
    local m=$1 k=$2 side span eye_z
    side=$(awk -v k="$k" 'BEGIN { print int(sqrt(k) + 0.5) }')
    span=$((8 * side))
    eye_z=$(awk -v s="$span" 'BEGIN { print -0.35 * s - 6 }')
    local eye="0.0, $(awk -v s="$span" 'BEGIN { print 0.3 * s + 3 }'), $eye_z"
    local target="0.0, 0.0, $(awk -v s="$span" 'BEGIN { print 0.3 * s }')"
    local first=$(((side - 1) * -4))
    cat >"$out/$m.$k.crt" <<EOF
-- bench/scale: the $m-triangle terrain drawn $k times ($side x $side).
terrain = Mesh { file -> "$here/generated/$m/terrain.ply"
                 material -> Material { color -> rgb(0.45, 0.6, 0.3) specular -> 0.2 shininess -> 10.0 } }
Settings {
    width -> $width
    height -> $height
    lights -> [PointLight { origin -> vec3(-6.0, $((span + 7)).0, -3.0) color -> rgb(1.0, 1.0, 1.0) }]
    camera -> Camera { position -> vec3($eye) pointing -> vec3($target) fov -> 50.0 }
    background -> rgb(0.5, 0.6, 0.75)
    ambient -> rgb(0.1, 0.1, 0.1)
    recursiondepth -> 3
    supersampling -> 1
}
Scene {
    for i in range($side) { for j in range($side) {
        terrain <translate vec3($first.0 + 8.0 * i, 0.0, 8.0 * j)>
    } }
}
EOF
    cat >"$out/$m.$k.pov" <<EOF
// bench/scale: the $m-triangle terrain drawn $k times ($side x $side), as $m.$k.crt.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.1 max_trace_level 4 adc_bailout 0 }
#declare VFov = 50;
camera { perspective location <$eye> direction z * 0.5 / tan(radians(VFov / 2))
         up y right x * image_width / image_height look_at <$target> }
light_source { <-6.0, $((span + 7)).0, -3.0> color rgb 1 }
background { color rgb <0.5, 0.6, 0.75> }
#include "$here/generated/$m/terrain.inc"
#declare I = 0;
#while (I < $side)
  #declare J = 0;
  #while (J < $side)
    object { Terrain translate <$first + 8 * I, 0, 8 * J>
             texture { pigment { color rgb <0.45, 0.6, 0.3> } finish { ambient 1 diffuse 1 phong 0.2 phong_size 10 } } }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
EOF
}

# timed NAME COMMAND...: runs it under GNU time; sets seconds and peak (MiB).
timed() {
    local name=$1 start end
    shift
    stamp start
    if ! /usr/bin/time -f %M -o "$logs/$name.mem" "$@" >"$logs/$name.out" 2>"$logs/$name.err"; then
        echo "$name failed; log: $logs/$name.err$keep_hint" >&2
        tail -n 20 "$logs/$name.err" >&2
        return 1
    fi
    stamp end
    seconds=$(elapsed "$start" "$end" 2)
    peak=$(awk '{ printf "%.0f", $1 / 1024 }' "$logs/$name.mem")
}

echo "crtc: $crtc; POV-Ray: $povray; $threads threads, ${width}x$height" >&2
echo "| triangles | drawings | drawn triangles | crtc s | crtc MiB | POV-Ray s | POV-Ray MiB | time ratio | memory ratio |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for m in "${mesh_list[@]}"; do
    triangles=$( [[ $m == 1M ]] && echo 999698 || echo 9999392 )
    for k in "${copy_list[@]}"; do
        write_scenes "$m" "$k"
        echo "rendering $m x $k ..." >&2
        timed "crtc.$m.$k" "$crtc" --allow-read "$here/generated" --max-primitives 20000000 --threads "$threads" --stats -o "$out/$m.$k.crtc.png" "$out/$m.$k.crt"
        crtc_seconds=$seconds crtc_peak=$peak
        timed "povray.$m.$k" env HOME="$povhome" "$povray" "+I$out/$m.$k.pov" "+O$out/$m.$k.pov.png" +FN \
            "+W$width" "+H$height" -D -V -P -A "+WT$threads" File_Gamma=1.0
        echo "| $m | $k | $(awk -v a="$triangles" -v b="$k" 'BEGIN { printf "%.3g", a * b }') |" \
            "$crtc_seconds | $crtc_peak | $seconds | $peak |" \
            "$(awk -v a="$crtc_seconds" -v b="$seconds" 'BEGIN { printf "%.2f", a / b }') |" \
            "$(awk -v a="$crtc_peak" -v b="$peak" 'BEGIN { printf "%.2f", a / b }') |"
    done
done
echo "images and logs: $out$keep_hint" >&2
