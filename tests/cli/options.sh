#!/usr/bin/env bash
# crtc's option syntax (--opt=value, --, did-you-mean) and the options that override a script's
# quality and size: --draft, sample counts, --region, and the summary line's samples per pixel.
set -u
crtc=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"

cat >"$work/dof.crt" <<'CRT'
Settings {
    width -> 40 height -> 30
    dofsamples -> 16 supersampling -> 2
    camera -> Camera { position -> vec3(0, 0, -4) pointing -> vec3(0, 0, 0) aperture -> 0.2 }
    lights -> [AreaLight { corner -> vec3(2, 3, -3) edgeA -> vec3(1, 0, 0) edgeB -> vec3(0, 1, 0.5) color -> rgb(1, 1, 1) }]
}
Scene {
    Sphere { center -> vec3(0, 0, 0) radius -> 1 material -> Material { color -> rgb(1, 0.5, 0.2) } }
    Plane { normal -> vec3(0, 1, 0) position -> vec3(0, -1, 0) }
}
CRT
cp "$work/dof.crt" "$work/-dash.crt"

# Option syntax
expect_status 0 "--opt=value" "$crtc" --width=20 --height=10 -o "$work/eq.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: 20x10," "--width=20 --height=10 sets the size"
expect_status 0 "-- before a script named -dash.crt" "$crtc" -q --draft -o "$work/dash.png" -- "$work/-dash.crt"
[ -s "$work/dash.png" ] || fail "-- then a script: no image written"
expect_status 2 "did-you-mean" "$crtc" --widht 20 "$work/dof.crt"
expect_text "$work/err" "unknown option '--widht'; did you mean '--width'\?" "did-you-mean names the option"
expect_status 2 "POV-Ray's options before the script" "$crtc" +W320 +H240 "$work/dof.crt"
expect_text "$work/err" "'\+W320' is a POV-Ray option; crtc's is --width N" "a POV-Ray option is named with crtc's"
expect_status 2 "POV-Ray's options after the script" "$crtc" "$work/dof.crt" +WT2
expect_text "$work/err" "'\+WT2' is a POV-Ray option; crtc's is --threads N" "+WT is read before +W"
expect_status 2 "bad --antialias" "$crtc" --antialias=smooth "$work/dof.crt"
expect_text "$work/err" "--antialias takes grid, adaptive, showadaptive or stratified, not 'smooth'" "--antialias choices"
expect_status 2 "--supersampling out of range" "$crtc" --supersampling 65 "$work/dof.crt"
expect_text "$work/err" "--supersampling needs an integer from 1 to 64, not '65'" "--supersampling range"
expect_status 2 "--max-primitives past what the renderer can number" "$crtc" --max-primitives 134217728 "$work/dof.crt"
expect_text "$work/err" "--max-primitives needs an integer from 0 to 134217727, not '134217728'" "--max-primitives range"
expect_status 0 "--max-primitives at its most" "$crtc" --check --max-primitives 134217727 "$work/dof.crt"
expect_status 2 "two modes" "$crtc" --check --format "$work/dof.crt"
expect_status 2 "region outside the image" "$crtc" --region 0:0:41:30 -o "$work/r.png" "$work/dof.crt"
expect_text "$work/err" "--region 0:0:41:30 is not inside the 40x30 image" "region message"
expect_status 2 "malformed region" "$crtc" --region 5:5:2:8 "$work/dof.crt"

# Samples per pixel: the script's 2x2 grid with 16 lens samples is 64 camera rays a pixel.
expect_status 0 "depth of field render" "$crtc" -o "$work/dof.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: 40x30, 64 samples/pixel," "summary counts depth-of-field samples"
expect_status 0 "--draft" "$crtc" --draft -o "$work/draft.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: 40x30, 1 sample/pixel," "--draft: one sample a pixel"
expect_status 0 "--draft with --supersampling" "$crtc" --draft --supersampling 3 -o "$work/d3.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: 40x30, 9 samples/pixel," "a count given beside --draft wins"
expect_status 0 "--dofsamples" "$crtc" --dofsamples 4 --supersampling 1 -o "$work/d4.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: 40x30, 4 samples/pixel," "--dofsamples overrides the script"
expect_status 0 "--antialias adaptive" "$crtc" --antialias adaptive --dofsamples 1 -o "$work/ad.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: 40x30, [0-9]+\.[0-9]+ samples/pixel," "adaptive sampling reports its average"
expect_status 0 "--shadowsamples" "$crtc" --draft --shadowsamples 64 --stats -o "$work/s64.png" "$work/dof.crt"
shadow_rays() { sed -nE 's/.*shadow ([0-9]+).*/\1/p' "$1"; }
cp "$work/err" "$work/err64"
expect_status 0 "--draft shadows" "$crtc" --draft --stats -o "$work/s1.png" "$work/dof.crt"
[ "$(shadow_rays "$work/err64")" -gt "$(shadow_rays "$work/err")" ] ||
    fail "--shadowsamples 64 traces more shadow rays than --draft's one"
if cmp -s "$work/dof.png" "$work/draft.png"; then fail "--draft renders the same image as the script's quality"; fi

# The path integrator from the command line: its samples are the paths a pixel.
expect_status 0 "--integrator path --samples 5" "$crtc" --integrator path --samples 5 -o "$work/path.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: 40x30, 5 samples/pixel," "--samples: paths a pixel"
if cmp -s "$work/dof.png" "$work/path.png"; then fail "--integrator path renders the Whitted image"; fi
expect_status 0 "--integrator path --draft" "$crtc" --integrator path --draft -o "$work/pd.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: 40x30, 1 sample/pixel," "--draft: one path a pixel"
expect_status 2 "bad --integrator" "$crtc" --integrator radiosity "$work/dof.crt"
expect_text "$work/err" "--integrator takes whitted or path, not 'radiosity'" "--integrator choices"
expect_status 0 "--target-error" "$crtc" --integrator path --samples 64 --target-error 0.05 -o "$work/te.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: 40x30, [0-9]+\.[0-9]+ samples/pixel," "--target-error: the pixels' mean count of paths"
expect_status 0 "--target-error --stats" "$crtc" --integrator path --samples 64 --target-error 0.05 --stats -o "$work/te.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: stats: paths a pixel: fewest 16, mean [0-9.]+, most (6[0-4]|[1-5][0-9]); estimated relative error [0-9.]+ %" "--stats: paths a pixel and the error"
expect_status 2 "--target-error 0" "$crtc" --target-error 0 "$work/dof.crt"
expect_text "$work/err" "--target-error needs a number above 0, not '0'" "--target-error range"
# A time limit the render does not reach leaves its image as it was; one it reaches stops it
# with every pixel the mean of the paths it took.
expect_status 0 "--time-limit not reached" "$crtc" --integrator path --samples 5 --time-limit 1000 -o "$work/tl.png" "$work/dof.crt"
cmp -s "$work/path.png" "$work/tl.png" || fail "--time-limit changes a render that finishes before it"
expect_status 0 "--time-limit reached" "$crtc" --integrator path --samples 1000000 --time-limit 0.5 --stats -o "$work/tl.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: stats: paths a pixel: fewest [1-9][0-9]*, mean [0-9.]+, most [1-9][0-9]*;" "--time-limit: the paths each pixel took"
expect_status 2 "--time-limit under Whitted" "$crtc" --time-limit 10 -o "$work/tl.png" "$work/dof.crt"
expect_text "$work/err" "crtc: --time-limit needs the path integrator, and this scene's is \"whitted\"" "--time-limit needs the path integrator"
expect_status 2 "--time-limit 0" "$crtc" --time-limit 0 "$work/dof.crt"
expect_text "$work/err" "--time-limit needs a number of seconds from 0.001 to 1000000000, not '0'" "--time-limit range"
# AOVs: an EXR beside the image for each one asked for, the image as it was.
expect_status 0 "--aov" "$crtc" --integrator path --samples 5 --aov normal,albedo -o "$work/aov.png" "$work/dof.crt"
cmp -s "$work/path.png" "$work/aov.png" || fail "--aov changes the image"
[ -s "$work/aov.albedo.exr" ] && [ -s "$work/aov.normal.exr" ] || fail "--aov normal,albedo: $(ls "$work")"
[ ! -e "$work/aov.variance.exr" ] || fail "--aov wrote a variance image it was not asked for"
if command -v oiiotool >/dev/null; then
    oiiotool --info "$work/aov.normal.exr" | grep -q "40 x  *30, 3 channel, float" ||
        fail "the normal AOV is not 40x30 floats: $(oiiotool --info "$work/aov.normal.exr")"
fi
expect_status 2 "--aov unknown" "$crtc" --integrator path --aov albedo,depth "$work/dof.crt"
expect_text "$work/err" "--aov takes a list of variance, albedo and normal, not 'depth'" "--aov names"
expect_status 2 "--aov under Whitted" "$crtc" --aov albedo -o "$work/w.png" "$work/dof.crt"
expect_text "$work/err" "crtc: --aov needs the path integrator" "--aov needs the path integrator"
expect_status 2 "--aov into a GIF" "$crtc" --integrator path --aov albedo --frames 2 -o "$work/w.gif" "$work/dof.crt"
expect_text "$work/err" "give -o a numbered name" "--aov needs an image a frame"
expect_status 2 "--samples out of range" "$crtc" --samples 0 "$work/dof.crt"
expect_text "$work/err" "--samples needs an integer from 1 to 1000000, not '0'" "--samples range"

# A region is the same pixels as the whole image's.
expect_status 0 "--region" "$crtc" --region 8:4:36:21 -o "$work/region.png" "$work/dof.crt"
expect_text "$work/err" "^crtc: 28x17," "the region's size"
if command -v oiiotool >/dev/null; then
    oiiotool "$work/dof.png" --cut 28x17+8+4 -o "$work/cut.png"
    idiff -fail 0 -warn 0 "$work/cut.png" "$work/region.png" >/dev/null ||
        fail "--region differs from the same part of the whole image"
else
    echo "skipped the region comparison: oiiotool is not installed"
fi

# The progress bar fits a narrow terminal: no line longer than its 50 columns.
if command -v script >/dev/null; then
    script -qec "stty cols 50; '$crtc' --width 400 --height 300 --threads 1 -o '$work/p.png' '$work/dof.crt'" \
        "$work/typescript" >/dev/null 2>&1
    longest=$(tr '\r' '\n' <"$work/typescript" | grep remaining | awk '{ if (length > n) n = length } END { print n + 0 }')
    [ "$longest" -le 49 ] || fail "the progress bar is $longest columns wide on a 50-column terminal"
    grep -q "remaining" "$work/typescript" || fail "no progress bar was drawn on the terminal"
else
    echo "skipped the terminal width check: script(1) is not installed"
fi

finish
