#!/usr/bin/env bash
# Renders the swatches of docs/materials.md into docs/materials/: every colour, material and
# colour map the standard library defines. Each name assigned at the start of a line of a
# library file is asked for its value: a colour of colors.crt is shown flat, a material on a
# sphere under the panorama sky of demos/images, a colour map along a bar. Macros and the
# values that build materials have no swatch.
#   scripts/render_material_swatches.sh [path/to/crtc]
set -euo pipefail
cd "$(dirname "$0")/.."
crtc="${1:-build/bin/crtc}"
out=docs/materials
mkdir -p "$out/colors"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# What each name of FILE is, a line "name kind" per name: kind is the first word of its
# printed value (rgb, <Material, [[…).
kinds() {
    local file=$1
    {
        echo "include \"$file\""
        # (a name that only repeats another, as aluminum, shares its swatch)
        grep -v '^[A-Za-z0-9_]* = [A-Za-z0-9_]*$' "stdlib/$file" |
            sed -n 's/^\([A-Za-z][A-Za-z0-9_]*\) = .*/\1/p' |
            awk '{ printf "print(\"%s\", %s)\n", $1, $1 }'
    } >"$work/kinds.crt"
    "$crtc" --check "$work/kinds.crt" 2>/dev/null | awk '{ print $1, substr($2, 1, 4) }'
}

color_swatch() { # name
    cat >"$work/$1.crt" <<CRT
include "colors.crt"
Settings { width -> 24 height -> 24 ambient -> rgb(1, 1, 1) background -> rgb(0, 0, 0)
    camera -> Camera { position -> vec3(0, 0, -10) pointing -> vec3(0, 0, 0) fov -> 10 } }
Scene { Quad { corner -> vec3(-3, -3, 0) edgeA -> vec3(6, 0, 0) edgeB -> vec3(0, 6, 0)
    material -> Material { color -> $1 } } }
CRT
}

material_swatch() { # name file
    cat >"$work/$1.crt" <<CRT
include "$2"
Settings {
    width -> 128 height -> 128 supersampling -> 3 ambient -> rgb(0.25, 0.25, 0.25)
    camera -> Camera { position -> vec3(0, 1.4, -3.6) pointing -> vec3(0, 0.75, 0) fov -> 38 }
    lights -> [PointLight { origin -> vec3(-3, 5, -4) color -> rgb(0.9, 0.9, 0.9) }]
    background -> Background { image -> "/images/panorama.png" angle -> 2.2 }
    recursiondepth -> 8
}
Scene {
    Plane { normal -> vec3(0, 1, 0) position -> vec3(0, 0, 0) material -> Material {
        texture -> Checker { a -> rgb(0.8, 0.8, 0.8) b -> rgb(0.25, 0.25, 0.25) size -> 0.5 } } }
    Sphere { center -> vec3(0, 0.8, 0) radius -> 0.8 material -> $1 }
}
CRT
}

map_swatch() { # name
    cat >"$work/$1.crt" <<CRT
include "patterns.crt"
Settings { width -> 192 height -> 24 ambient -> rgb(1, 1, 1) background -> rgb(0.5, 0.5, 0.5)
    camera -> Camera { position -> vec3(0.5, 0, -10) pointing -> vec3(0.5, 0, 0) fov -> 0.7162 } }
Scene { Quad { corner -> vec3(-0.5, -0.5, 0) edgeA -> vec3(2, 0, 0) edgeB -> vec3(0, 1, 0)
    material -> Material { texture -> Gradient { axis -> vec3(1, 0, 0) colors -> $1 } } } }
CRT
}

count=0
for file in colors.crt metals.crt glass.crt woods.crt stones.crt patterns.crt materials.crt; do
    while read -r name kind; do
        case "$file:$kind" in
            colors.crt:rgb*) color_swatch "$name" ;;
            *:\<Mat) material_swatch "$name" "$file" ;;
            patterns.crt:\[\[*) map_swatch "$name" ;;
            *) continue ;;
        esac
        # Colours have a folder of their own: gold and silver are colours and metals.
        target=$out/$name.png
        [[ $file == colors.crt ]] && target=$out/colors/$name.png
        "$crtc" -q --assets demos "$work/$name.crt" -o "$target"
        count=$((count + 1))
    done < <(kinds "$file")
done
echo "rendered $count swatches into $out/"
