#!/usr/bin/env bash
# BVH scaling: renders bench/bvh/spheres.crt with 1,000, 97,336 and 1,000,000 spheres and
# prints BVH nodes visited and intersection tests per ray (from crtc --stats).
#   bench/bvh/run.sh [path/to/crtc]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
crtc="${1:-$here/../../build/bin/crtc}"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| spheres | BVH nodes | depth | rays | nodes visited / ray | intersection tests / ray | render s |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for n in 10 46 100; do
    stats=$("$crtc" --time "$n" --stats -q --max-entities 2000000 "$here/spheres.crt" -o "$out/s.png" 2>&1)
    prims=$(sed -n 's/.*primitives \([0-9]*\) stored.*/\1/p' <<<"$stats")
    nodes=$(sed -n 's/.*, BVH nodes \([0-9]*\),.*/\1/p' <<<"$stats")
    depth=$(sed -n 's/.*BVH depth \([0-9]*\).*/\1/p' <<<"$stats")
    rays=$(sed -n 's/.*(total \([0-9]*\)).*/\1/p' <<<"$stats")
    visited=$(sed -n 's/.*BVH nodes visited \([0-9]*\), intersection tests \([0-9]*\).*/\1/p' <<<"$stats")
    tests=$(sed -n 's/.*BVH nodes visited \([0-9]*\), intersection tests \([0-9]*\).*/\2/p' <<<"$stats")
    render=$(sed -n 's/.*render \([0-9.]*\)s.*/\1/p' <<<"$stats")
    awk -v p="$prims" -v n="$nodes" -v d="$depth" -v r="$rays" -v v="$visited" -v t="$tests" -v s="$render" \
        'BEGIN { printf "| %d | %d | %s | %d | %.1f | %.2f | %s |\n", p, n, d, r, v / r, t / r, s }'
done
