#!/usr/bin/env bash
# Renders the pictures of docs/language.md's image mappings into docs/mappings/: a test
# card (card.png, itself rendered by crtc: hues from left to right, a grid of cells, a dark
# band along its top edge) laid on a sphere, a cylinder and a box through each mapping.
#   scripts/render_mapping_pictures.sh [path/to/crtc]
set -euo pipefail
cd "$(dirname "$0")/.."
crtc="${1:-build/bin/crtc}"
out=docs/mappings
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The card: a 2 × 1 quad seen square on, lit flat, so that each pixel is its colour.
cat >"$work/card.crt" <<'CRT'
Settings {
    width -> 256 height -> 128 supersampling -> 2
    camera -> Camera { position -> vec3(1, 0.5, -20) pointing -> vec3(1, 0.5, 0) fov -> 2.864 }
    lights -> [ParallelLight { from -> vec3(1, 0.5, -20) pointing -> vec3(1, 0.5, 0) color -> rgb(1, 1, 1) }]
}
hues = Material { texture -> Gradient { axis -> vec3(1, 0, 0) colors -> [
    [0, rgb(0.9, 0.1, 0.1)], [0.2, rgb(0.9, 0.8, 0.1)], [0.4, rgb(0.2, 0.8, 0.2)],
    [0.6, rgb(0.1, 0.7, 0.8)], [0.8, rgb(0.2, 0.3, 0.9)], [1, rgb(0.8, 0.2, 0.7)]] } <scale 2> }
cells = Material { texture -> Checker { colors -> [[0, rgba(0, 0, 0, 0.3)], [1, rgba(0, 0, 0, 0)]] } <scale 0.125> }
top = Material { texture -> Gradient { axis -> vec3(0, 1, 0) colors -> [
    [0, rgba(0.1, 0.1, 0.1, 0)], [0.85, rgba(0.1, 0.1, 0.1, 0)], [0.85, rgba(0.1, 0.1, 0.1, 1)], [1, rgba(0.1, 0.1, 0.1, 1)]] } }
Scene { Quad { corner -> vec3(0, 0, 0) edgeA -> vec3(2, 0, 0) edgeB -> vec3(0, 1, 0)
               material -> Layered { materials -> [hues, cells, top] } } }
CRT
"$crtc" -q "$work/card.crt" -o "$out/card.png"
cp "$out/card.png" "$work/card.png"

for mapping in uv planar spherical cylindrical cubic; do
    cat >"$work/$mapping.crt" <<CRT
Settings {
    width -> 360 height -> 150 supersampling -> 3 ambient -> rgb(0.35, 0.35, 0.35)
    background -> rgb(0.8, 0.8, 0.8)
    camera -> Camera { position -> vec3(0, 2.6, -8.5) pointing -> vec3(0, 0.9, 0) fov -> 22 }
    lights -> [ParallelLight { from -> vec3(-3, 4, -6) pointing -> vec3(0, 0, 0) color -> rgb(0.7, 0.7, 0.7) }]
}
card = Material { texture -> Image { file -> "card.png" mapping -> "$mapping" } }
Scene {
    Sphere { center -> vec3(-2.6, 1, 0) radius -> 1 material -> card }
    Cylinder { base -> vec3(0, 0, 0) top -> vec3(0, 2, 0) radius -> 0.8 material -> card }
    Box { cornerA -> vec3(-0.8, 0, -0.8) cornerB -> vec3(0.8, 1.6, 0.8) material -> card } <rotate vec3(0, 30, 0), translate vec3(2.6, 0, 0)>
}
CRT
    "$crtc" -q "$work/$mapping.crt" -o "$out/$mapping.png"
done
echo "rendered the card and 5 mappings into $out/"
