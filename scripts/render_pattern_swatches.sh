#!/usr/bin/env bash
# Renders the pattern swatches of docs/language.md into docs/patterns/: each pattern type
# with its defaults, on a wall facing the camera, lit flat so that a pixel is the colour
# its map gives the value there.
#   scripts/render_pattern_swatches.sh [path/to/crtc]
set -euo pipefail
cd "$(dirname "$0")/.."
crtc="${1:-build/bin/crtc}"
out=docs/patterns
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# name, then the texture as written (its required attributes, and modifiers that bring a
# pattern of the x-z plane to the wall or show more than one period)
swatches=(
    "checker|Checker { }"
    "stripes|Stripes { size -> 0.5 }"
    "noise|Noise { size -> 0.5 }"
    "marble|Marble { }"
    "wood|Wood { } <scale 0.5>"
    "gradient|Gradient { axis -> vec3(1, 1, 0) }"
    "onion|Onion { }"
    "leopard|Leopard { } <scale 0.15>"
    "radial|Radial { frequency -> 4 } <rotate vec3(-90, 0, 0)>"
    "spiral|Spiral { arms -> 3 }"
    "brick|Brick { } <scale 0.15>"
    "hexagon|Hexagon { } <rotate vec3(-90, 0, 0), scale 0.5>"
    "boxed|Boxed { } <scale 2>"
    "spherical|Spherical { } <scale 2>"
    "cylindrical|Cylindrical { } <scale 2>"
    "planar|Planar { } <scale 2>"
    "quilted|Quilted { }"
    "mandel|Mandel { iterations -> 40 } <translate vec3(0.7, 0, 0), scale 2>"
    "bozo|Bozo { }"
    "spotted|Spotted { }"
    "granite|Granite { }"
    "agate|Agate { } <rotate vec3(0, 90, 0)>"
    "wrinkles|Wrinkles { }"
    "dents|Dents { }"
    "crackle|Crackle { }"
    "cells|Cells { }"
    "slope|Slope { }"
    "ripples|Ripples { frequency -> 2 } <scale 1.5>"
    "waves|Waves { frequency -> 2 } <scale 1.5>"
)
for swatch in "${swatches[@]}"; do
    name=${swatch%%|*} texture=${swatch#*|}
    shape="Quad { corner -> vec3(-3, -3, 0) edgeA -> vec3(6, 0, 0) edgeB -> vec3(0, 6, 0)"
    # A slope needs a curved surface to show.
    [[ $name == slope ]] && shape="Sphere { center -> vec3(0, 0, 0) radius -> 2.4"
    cat >"$work/$name.crt" <<CRT
Settings {
    width -> 96 height -> 96 supersampling -> 3 ambient -> rgb(1, 1, 1)
    background -> rgb(0.5, 0.5, 0.5)
    camera -> Camera { position -> vec3(0, 0, -10) pointing -> vec3(0, 0, 0) fov -> 28 }
}
Scene { $shape material -> Material { texture -> $texture } } }
CRT
    "$crtc" -q "$work/$name.crt" -o "$out/$name.png"
done
echo "rendered ${#swatches[@]} swatches into $out/"
