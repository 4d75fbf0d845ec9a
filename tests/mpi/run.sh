#!/usr/bin/env bash
# crtc under a real mpirun (OpenMPI): renders shared over 1, 2 and 3 processes are the same
# bits as crtc alone; a rank that fails or is killed ends the job with an error and no image.
# Under mpirun, a missing MPI module is a clear error (tests/cli/loaded_libraries.sh checks
# that crtc alone loads no MPI library).
#   run.sh stills|animation|frames|frame_failure|frame_continue|failure|killed|interrupted|missing_module|transport CRTC [SANITIZED]
set -u
case_name=$1
crtc=$(realpath "$2") # absolute: some checks run crtc from other folders
# The numbers of processes and threads the comparisons with crtc alone go through. Under the
# sanitizers (SANITIZED 1) a job is several times slower and these tests run one at a time,
# so there they take the ends of each range; the Release suite takes every count.
sanitized=${3:-0}
if [ "$sanitized" = 1 ]; then
    process_counts="1 3" thread_counts="2"
else
    process_counts="1 2 3" thread_counts="1 2"
fi
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$here/../cli/expect.sh"

if ! command -v mpirun >/dev/null 2>&1; then
    echo "SKIP: mpirun is not installed (scripts/setup.sh installs openmpi-bin)"
    exit 77
fi
# A container without a network: shared memory between the processes, no kernel-assisted copy
# (which ptrace restrictions forbid); root may run MPI jobs here.
export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none
# No transport is named (OMPI_MCA_pml): crtc chooses its own, as for a user's plain mpirun.
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Under the sanitizers: what OpenMPI's and OpenImageIO's libraries keep until exit is not ours;
# their allocations are recognised by the whole stack (the fast unwinder stops in libraries
# built without frame pointers, which leaves nothing for the suppressions to match).
export LSAN_OPTIONS="suppressions=$here/lsan_mpi.supp:print_suppressions=0:fast_unwind_on_malloc=0"
# LeakSanitizer's check is most of a sanitized MPI job's time, several times the render of a
# small still: it must unwind every allocation whole to recognise OpenMPI's. So under the
# sanitizers leaks are checked only in the jobs run through leak_checked: a few successful
# ones of each case, through the tile, frame and resume code of crtc. (A job expected to fail
# would hide a leak's exit status in its own.) Every job keeps AddressSanitizer's checks.
if [ "$sanitized" = 1 ]; then
    unchecked_asan_options="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
else
    unchecked_asan_options=${ASAN_OPTIONS:-}
fi
leak_checked() { # command...
    local leaks_checked=1
    "$@"
}
mpirun_job() { # processes program arguments...
    local processes=$1 asan_options=$unchecked_asan_options
    shift
    [ "${leaks_checked:-0}" = 1 ] && asan_options=${ASAN_OPTIONS:-}
    ASAN_OPTIONS=$asan_options timeout 120 mpirun --allow-run-as-root --oversubscribe -np "$processes" "$@"
}
mpi() { # processes crtc-arguments...
    local processes=$1
    shift
    mpirun_job "$processes" "$crtc" "$@"
}
# crtc built without MPI says so under mpirun: nothing to test then.
if ! mpi 2 --quiet "$here/still.crt" --width 8 --height 8 -o "$work/probe.png" 2>"$work/probe.err"; then
    if grep -q "built without MPI" "$work/probe.err"; then
        echo "SKIP: crtc was built without MPI (libopenmpi-dev was not found)"
        exit 77
    fi
fi

# The same image from crtc alone and from each number of processes and threads.
same_as_alone() { # description reference output crtc-arguments...
    local what=$1 reference=$2 output=$3
    shift 3
    for processes in $process_counts; do
        for threads in $thread_counts; do
            rm -f "$output"
            expect_status 0 "$what, $processes processes" mpi "$processes" --quiet --threads "$threads" "$@"
            cmp -s "$reference" "$output" ||
                fail "$what: $processes processes x $threads threads differ from crtc alone"
        done
    done
}

stills() {
    "$crtc" --quiet "$here/still.crt" -o "$work/alone.png"
    same_as_alone "still" "$work/alone.png" "$work/shared.png" "$here/still.crt" -o "$work/shared.png"
    "$crtc" --quiet "$here/costly_tile.crt" -o "$work/costly_alone.png"
    same_as_alone "one costly tile" "$work/costly_alone.png" "$work/costly.png" \
        "$here/costly_tile.crt" -o "$work/costly.png"
    # Workers that take every tile at once: rank 0's threads find none left at the start and
    # take back half of what a worker has not begun, again and again, and a worker that runs
    # out gets half of those; no tile may be lost or traced twice.
    # (320 x 240: 300 tiles, so that the workers ask before rank 0 has traced them all.)
    "$crtc" --quiet "$here/still.crt" --width 320 --height 240 -o "$work/back_alone.png"
    CRT_TEST_QUEUED_TILES=1000 leak_checked same_as_alone "tiles given back" "$work/back_alone.png" \
        "$work/back.png" "$here/still.crt" --width 320 --height 240 -o "$work/back.png"
    # Motion blur: each sample's time within the shutter is the same wherever it is traced.
    "$crtc" --quiet "$here/blurred.crt" -o "$work/blurred_alone.png"
    same_as_alone "blurred" "$work/blurred_alone.png" "$work/blurred.png" "$here/blurred.crt" -o "$work/blurred.png"
    # --region and a Radiance HDR (floats: no rounding to 8 bits to hide a wrong pixel).
    "$crtc" --quiet "$here/still.crt" --region 5:3:77:41 -o "$work/alone.hdr"
    expect_status 0 "region as HDR" mpi 3 --quiet "$here/still.crt" --region 5:3:77:41 -o "$work/shared.hdr"
    cmp -s "$work/alone.hdr" "$work/shared.hdr" || fail "--region over 3 processes differs"
    # The summary and --stats count every process's rays.
    "$crtc" --stats "$here/still.crt" -o "$work/alone.png" 2>"$work/alone.err"
    expect_status 0 "--stats" mpi 3 --stats "$here/still.crt" -o "$work/shared.png"
    diff <(grep -E "rays:|samples/pixel" "$work/alone.err" | sed 's/[0-9.]*s,.*//') \
        <(grep -E "rays:|samples/pixel" "$work/err" | sed 's/[0-9.]*s,.*//') >/dev/null ||
        fail "--stats over 3 processes differs from crtc alone: $(grep rays: "$work/err")"
    [ "$(grep -c 'crtc: stats: rays' "$work/err")" = 1 ] || fail "--stats printed by more than rank 0"
    # The path integrator, adaptive: the same floats, and the same counts of paths and error.
    "$crtc" --stats --integrator path --samples 32 --target-error 0.1 "$here/still.crt" -o "$work/path_alone.hdr" \
        2>"$work/path_alone.err"
    leak_checked expect_status 0 "path tracing" mpi 3 --stats --integrator path --samples 32 --target-error 0.1 "$here/still.crt" \
        -o "$work/path_shared.hdr"
    cmp -s "$work/path_alone.hdr" "$work/path_shared.hdr" || fail "a path-traced image over 3 processes differs"
    diff <(grep -E "paths a pixel|rays:" "$work/path_alone.err") <(grep -E "paths a pixel|rays:" "$work/err") >/dev/null ||
        fail "path --stats over 3 processes differ from crtc alone: $(grep 'paths a pixel' "$work/err")"
    # AOVs travel with the tiles.
    "$crtc" --quiet --integrator path --samples 8 --aov variance,normal "$here/still.crt" -o "$work/aov_alone.hdr"
    leak_checked expect_status 0 "--aov" mpi 3 --quiet --integrator path --samples 8 --aov variance,normal "$here/still.crt" \
        -o "$work/aov_shared.hdr"
    for aov in variance normal; do
        cmp -s "$work/aov_alone.$aov.exr" "$work/aov_shared.$aov.exr" || fail "the $aov AOV over 3 processes differs"
    done
    # A time limit: each process refines its share of the tiles until rank 0's deadline. One
    # the render does not reach leaves the image as it is without it; one it reaches still
    # gives every pixel of every share its paths.
    "$crtc" --quiet --integrator path --samples 8 "$here/still.crt" -o "$work/tl_alone.hdr"
    expect_status 0 "--time-limit not reached" mpi 2 --quiet --integrator path --samples 8 --time-limit 1000 \
        "$here/still.crt" -o "$work/tl.hdr"
    cmp -s "$work/tl_alone.hdr" "$work/tl.hdr" || fail "--time-limit not reached over 2 processes changes the image"
    expect_status 0 "--time-limit reached" mpi 3 --stats --integrator path --samples 1000000 --time-limit 1 \
        "$here/still.crt" -o "$work/tl.hdr"
    expect_text "$work/err" "^crtc: stats: paths a pixel: fewest [1-9][0-9]*, mean [0-9.]+, most [1-9][0-9]*;" \
        "--time-limit over 3 processes: every pixel's paths"
    # --alpha: tiles of four channels.
    "$crtc" --quiet --alpha "$here/still.crt" -o "$work/alpha_alone.png"
    expect_status 0 "--alpha" mpi 3 --quiet --alpha "$here/still.crt" -o "$work/alpha_shared.png"
    cmp -s "$work/alpha_alone.png" "$work/alpha_shared.png" || fail "--alpha over 3 processes differs"
}

animation() {
    mkdir "$work/alone" "$work/shared"
    "$crtc" --quiet --frames 6 "$here/animation.crt" -o "$work/alone/f_%02d.png"
    "$crtc" --quiet --frames 6 "$here/animation.crt" -o "$work/alone.gif"
    for processes in $process_counts; do
        rm -f "$work"/shared/*
        expect_status 0 "numbered frames, $processes processes" mpi "$processes" --stats --frames 6 \
            "$here/animation.crt" -o "$work/shared/f_%02d.png"
        expect_text "$work/err" "frames reused unchanged 2" "unchanged frames reused"
        for f in "$work"/alone/*.png; do
            cmp -s "$f" "$work/shared/$(basename "$f")" ||
                fail "$(basename "$f") of $processes processes differs from crtc alone's"
        done
        expect_status 0 "GIF, $processes processes" mpi "$processes" --quiet --frames 6 \
            "$here/animation.crt" -o "$work/shared.gif"
        cmp -s "$work/alone.gif" "$work/shared.gif" || fail "the GIF of $processes processes differs"
    done
    rm -f "$work"/shared/*
    leak_checked expect_status 0 "--frame-range" mpi 2 --quiet --frames 6 --frame-range 2:4 \
        "$here/animation.crt" -o "$work/shared/f_%02d.png"
    [ "$(ls "$work/shared" | tr '\n' ' ')" = "f_02.png f_03.png f_04.png " ] ||
        fail "--frame-range 2:4 wrote $(ls "$work/shared" | tr '\n' ' ')"
    for f in "$work"/shared/*.png; do
        cmp -s "$f" "$work/alone/$(basename "$f")" || fail "$(basename "$f") of --frame-range differs"
    done
}

# Frames shared out whole: each evaluated once, on the rank that renders it; the files, the
# GIF, the reuse of unchanged frames and --stats as crtc alone has them.
frames() {
    mkdir "$work/alone" "$work/shared"
    "$crtc" --quiet --stats --frames 9 "$here/moving.crt" -o "$work/alone/f_%02d.png" \
        >"$work/alone.out" 2>"$work/alone.err"
    "$crtc" --quiet --frames 9 "$here/moving.crt" -o "$work/alone.gif" >/dev/null
    for processes in $process_counts; do
        for threads in $thread_counts; do
            rm -f "$work"/shared/*
            expect_status 0 "9 frames, $processes processes x $threads threads" mpi "$processes" \
                --quiet --stats --threads "$threads" --frames 9 "$here/moving.crt" -o "$work/shared/f_%02d.png"
            for f in "$work"/alone/*.png; do
                cmp -s "$f" "$work/shared/$(basename "$f")" ||
                    fail "$(basename "$f") of $processes x $threads differs from crtc alone's"
            done
            [ "$(ls "$work/shared" | wc -l)" = 9 ] || fail "$processes x $threads wrote $(ls "$work/shared")"
            [ "$(grep -c "evaluating frame" "$work/out")" = 9 ] ||
                fail "$processes x $threads: frames evaluated $(grep -c "evaluating frame" "$work/out") times, not 9"
            for frame in 0 1 2 3 4 5 6 7 8; do
                grep -q "^evaluating frame $frame " "$work/out" || fail "frame $frame was not evaluated"
            done
            expect_text "$work/err" "moving.crt:.*warning" "the frames' warnings are shown"
            diff <(grep "rays:" "$work/alone.err") <(grep "rays:" "$work/err") >/dev/null ||
                fail "--stats of $processes x $threads: $(grep rays: "$work/err"), alone: $(grep rays: "$work/alone.err")"
        done
        expect_status 0 "GIF of 9 frames, $processes processes" mpi "$processes" --quiet --frames 9 \
            "$here/moving.crt" -o "$work/shared.gif"
        cmp -s "$work/alone.gif" "$work/shared.gif" || fail "the GIF of $processes processes differs"
    done
    # Unchanged frames (animation.crt stops moving at frame 3) are reused, not traced again.
    "$crtc" --quiet --stats --frames 8 "$here/animation.crt" -o "$work/still.gif" 2>"$work/alone.err"
    leak_checked expect_status 0 "GIF with unchanged frames" mpi 3 --quiet --stats --frames 8 "$here/animation.crt" -o "$work/shared.gif"
    expect_text "$work/err" "frames reused unchanged 4" "unchanged frames of the GIF reused"
    diff <(grep "rays:" "$work/alone.err") <(grep "rays:" "$work/err") >/dev/null ||
        fail "unchanged frames were traced: $(grep rays: "$work/err")"
    cmp -s "$work/still.gif" "$work/shared.gif" || fail "the GIF with unchanged frames differs"
    # Frames with --alpha: the frames' tiles carry four channels.
    mkdir "$work/alpha_alone" "$work/alpha_shared"
    "$crtc" --quiet --alpha --frames 3 "$here/moving.crt" -o "$work/alpha_alone/a_%d.png" >/dev/null
    expect_status 0 "3 frames with --alpha" mpi 2 --quiet --alpha --frames 3 "$here/moving.crt" \
        -o "$work/alpha_shared/a_%d.png"
    for f in "$work"/alpha_alone/*.png; do
        cmp -s "$f" "$work/alpha_shared/$(basename "$f")" ||
            fail "$(basename "$f") with --alpha differs from crtc alone's"
    done
    # A frame range: its frames only, the first of them reused as alone when unchanged.
    rm -f "$work"/shared/*
    expect_status 0 "--frame-range" mpi 3 --quiet --frames 9 --frame-range 3:7 \
        "$here/moving.crt" -o "$work/shared/f_%02d.png"
    [ "$(ls "$work/shared" | tr '\n' ' ')" = "f_03.png f_04.png f_05.png f_06.png f_07.png " ] ||
        fail "--frame-range 3:7 wrote $(ls "$work/shared" | tr '\n' ' ')"
    [ "$(grep -c "evaluating frame" "$work/out")" = 5 ] || fail "--frame-range 3:7 evaluated $(grep -c "evaluating" "$work/out") frames"
    for f in "$work"/shared/*.png; do
        cmp -s "$f" "$work/alone/$(basename "$f")" || fail "$(basename "$f") of --frame-range differs"
    done
}

# A frame that fails stops the job with its error on rank 0: the frames before it written,
# none after, no temporary file, no GIF.
frame_failure() {
    mkdir "$work/alone" "$work/shared"
    "$crtc" --quiet --frames 9 "$here/moving.crt" -o "$work/alone/f_%02d.png" >/dev/null
    for processes in 2 3; do
        rm -f "$work"/shared/*
        expect_status 1 "frame 9 fails, $processes processes" mpi "$processes" --quiet --frames 12 \
            "$here/moving.crt" -o "$work/shared/f_%02d.png"
        [ "$(grep -c "moving.crt:6:5: error: sqrt of a negative number" "$work/err")" = 1 ] ||
            fail "frame 9's error was not printed once: $(cat "$work/err")"
        expect_text "$work/err" "frame 9 has errors" "the failed frame is named"
        [ "$(ls -A "$work/shared" | tr '\n' ' ')" = "$(ls "$work/alone" | tr '\n' ' ')" ] ||
            fail "$processes processes left $(ls -A "$work/shared" | tr '\n' ' ')"
        for f in "$work"/alone/*.png; do
            cmp -s "$f" "$work/shared/$(basename "$f")" || fail "$(basename "$f") before the failed frame differs"
        done
        expect_status 1 "a GIF with a failed frame" mpi "$processes" --quiet --frames 12 "$here/moving.crt" -o "$work/failed.gif"
        [ ! -e "$work/failed.gif" ] || fail "a GIF was written although frame 9 failed"
        ls -A "$work" | grep -q "\.tmp$" && fail "a temporary file was left: $(ls -A "$work")"
    done
    # A rank that fails whatever frame it gets: named on rank 0 with its message.
    rm -f "$work"/shared/*
    CRT_TEST_FAIL_RANK=1 expect_status 1 "rank 1 fails its frames" mpi 3 --quiet --frames 9 \
        "$here/moving.crt" -o "$work/shared/f_%02d.png"
    expect_text "$work/err" "rank 1 on .* cannot evaluate frame [0-9]" "the failed rank is named"
    expect_text "$work/err" "evaluation failed on purpose" "its message is shown"
    [ "$(ls "$work/shared" | wc -l)" -lt 9 ] || fail "every frame was written although rank 1 failed"
    ls -A "$work/shared" | grep -q "\.tmp$" && fail "a temporary file was left: $(ls -A "$work/shared")"
}

# An interrupted render of an animation, finished by --continue under mpirun: the frames
# written before are not traced again, and the files are the same as one run's.
frame_continue() {
    mkdir "$work/alone" "$work/shared"
    local size=(--width 320 --height 240 --supersampling 3)
    "$crtc" --quiet --stats --frames 9 "${size[@]}" "$here/moving.crt" -o "$work/alone/f_%02d.png" \
        >/dev/null 2>"$work/alone.err"
    "$crtc" --quiet --threads 1 --frames 9 "${size[@]}" "$here/moving.crt" -o "$work/shared/f_%02d.png" \
        >/dev/null 2>&1 &
    local job=$!
    for _ in $(seq 600); do
        [ -e "$work/shared/f_02.png" ] && break
        sleep 0.05
    done
    kill -INT "$job"
    wait "$job"
    local before
    before=$(ls "$work/shared" | grep -c "png$")
    [ -e "$work/shared/.f_%02d.png.crtc-resume" ] ||
        fail "the interrupted run left no resume log: $(ls -A "$work/shared")"
    leak_checked expect_status 0 "--continue over 3 processes" mpi 3 --quiet --stats --continue --frames 9 "${size[@]}" \
        "$here/moving.crt" -o "$work/shared/f_%02d.png"
    for f in "$work"/alone/*.png; do
        cmp -s "$f" "$work/shared/$(basename "$f")" || fail "$(basename "$f") continued differs from one run's"
    done
    [ "$(ls -A "$work/shared" | wc -l)" = 9 ] || fail "--continue left $(ls -A "$work/shared" | tr '\n' ' ')"
    local all continued
    all=$(sed -n 's/.*rays: camera \([0-9]*\),.*/\1/p' "$work/alone.err")
    continued=$(sed -n 's/.*rays: camera \([0-9]*\),.*/\1/p' "$work/err")
    [ -n "$continued" ] && [ "$continued" -lt "$all" ] ||
        fail "--continue traced $continued camera rays after $before frames were written; a whole run traces $all"
}

failure() {
    # The rank that fails is named on rank 0, with its message; nothing is written.
    CRT_TEST_FAIL_RANK=1 expect_status 1 "rank 1 fails" mpi 3 "$here/still.crt" -o "$work/out.png"
    expect_text "$work/err" "rank 1 on .* cannot evaluate frame 0" "the failed rank is named"
    expect_text "$work/err" "evaluation failed on purpose" "its message is shown"
    [ ! -e "$work/out.png" ] || fail "an image was written although rank 1 failed"
    # A script error: every rank fails alike, and its diagnostic is printed once.
    printf 'Settings { width -> 8 height -> 8 }\nScene { Sphere { center -> vec3(0, 0, 0) radius -> nope } }\n' >"$work/bad.crt"
    expect_status 1 "a script error" mpi 2 "$work/bad.crt" -o "$work/out.png"
    [ "$(grep -c "bad.crt:2:" "$work/err")" = 1 ] || fail "the script's error was not printed once: $(cat "$work/err")"
    # Ranks that read different scripts (same name, another folder each) refuse to render.
    cat >"$work/differ.sh" <<SH
#!/usr/bin/env bash
mkdir -p "$work/rank\$OMPI_COMM_WORLD_RANK" && cd "$work/rank\$OMPI_COMM_WORLD_RANK"
printf 'Settings { width -> 8 height -> 8 }\nScene { Sphere { center -> vec3(0, 0, 0) radius -> 0.%s } }\n' "\${OMPI_COMM_WORLD_RANK}5" >scene.crt
exec "$crtc" scene.crt "\$@"
SH
    chmod +x "$work/differ.sh"
    expect_status 1 "different scenes" mpirun_job 2 "$work/differ.sh" -o "$work/differ.png"
    expect_text "$work/err" "evaluated different scenes" "different scenes are reported"
    [ ! -e "$work/differ.png" ] || fail "an image was written from different scenes"
    # An animation: the scripts are compared before any frame is handed out.
    expect_status 1 "different scripts, an animation" mpirun_job 2 "$work/differ.sh" --frames 3 \
        -o "$work/differ_%d.png"
    expect_text "$work/err" "evaluated different scenes for the script" "different scripts are reported"
    [ "$(grep -c "evaluated different scenes" "$work/err")" = 1 ] || fail "different scripts reported more than once"
    ls "$work" | grep -q "^differ_" && fail "frames were written from different scripts: $(ls "$work")"
}

# Waits (at most a minute) until rank 0 reports progress in $work/err.
await_progress() {
    for _ in $(seq 600); do
        grep -q "crtc: .*[0-9]*%" "$work/err" 2>/dev/null && return
        sleep 0.1
    done
}

# kill_rank_1 OUTPUT crtc-arguments...: a render of a few seconds over 3 processes; once rank 0
# reports progress, rank 1 is killed. The job must end with an error, without hanging,
# leaving no image and no temporary file.
kill_rank_1() {
    local output=$1
    shift
    mpi 3 --threads 1 "$@" -o "$output" >"$work/out" 2>"$work/err" &
    local job=$! rank1=""
    await_progress
    for pid in $(pgrep -x crtc); do
        if tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=1" &&
            tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -q "^PWD=$PWD$"; then
            rank1=$pid
        fi
    done
    [ -n "$rank1" ] || fail "rank 1's process was not found"
    [ -n "$rank1" ] && kill -9 "$rank1"
    wait "$job"
    local status=$?
    [ "$status" != 0 ] || fail "the job succeeded although rank 1 was killed"
    [ "$status" != 124 ] || fail "the job hung after rank 1 was killed"
    expect_text "$work/err" "rank 1 .*exited on signal 9" "mpirun names the killed rank"
    [ ! -e "$output" ] || fail "an image was written although rank 1 was killed"
    ls -A "$work" | grep -q "\.tmp$" && fail "a temporary file was left: $(ls -A "$work")"
}

killed() {
    kill_rank_1 "$work/out.png" "$here/still.crt" --width 640 --height 480 --supersampling 4
    # An animation shared by frames, written as a GIF at the end.
    kill_rank_1 "$work/out.gif" "$here/moving.crt" --frames 9 --width 320 --height 240 --supersampling 4
}

# Ctrl-C to mpirun during a shared still: the job stops with an error, rank 0 says once what
# it left (the resume log, no image), and the other ranks say nothing.
interrupted() {
    mpi 3 --threads 1 --resume-log-after 0 "$here/still.crt" --width 640 --height 480 \
        --supersampling 12 -o "$work/out.png" >"$work/out" 2>"$work/err" &
    local job=$!
    await_progress
    # As a terminal's Ctrl-C would (the job was started in the background, which ignores it).
    pkill -INT -f "^mpirun .* -o $work/out.png" || fail "mpirun was not found"
    wait "$job"
    local status=$?
    [ "$status" != 0 ] || fail "the job succeeded although it was interrupted"
    [ "$status" != 124 ] || fail "the job hung after it was interrupted"
    [ "$(grep -c "interrupted" "$work/err")" = 1 ] ||
        fail "the interruption was not reported once: $(grep -v "%" "$work/err")"
    expect_text "$work/err" "crtc: interrupted; no image written; crtc --continue" "rank 0 says what is left"
    [ ! -e "$work/out.png" ] || fail "an image was written although the job was interrupted"
    [ -e "$work/.out.png.crtc-resume" ] || fail "the interrupted job left no resume log: $(ls -A "$work")"
    ls -A "$work" | grep -q "\.tmp$" && fail "a temporary file was left: $(ls -A "$work")"
}

# Unless the job names a transport, crtc takes OpenMPI's ob1 rather than let it try UCX first,
# which takes some 0.2 s of every start (docs/distributed.md); one the job names is kept.
transport() {
    OMPI_MCA_pml_base_verbose=10 expect_status 0 "a job naming no transport" \
        mpi 2 --quiet --threads 1 "$here/still.crt" --width 8 --height 8 -o "$work/out.png"
    # Each rank opens ob1 alone (OpenMPI left to itself opens every transport it has).
    [ "$(cat "$work/out" "$work/err" | grep -c "components_open: found loaded component")" = 2 ] &&
        [ "$(cat "$work/out" "$work/err" | grep -c "components_open: found loaded component ob1")" = 2 ] ||
        fail "ob1 alone was not opened by both ranks: $(grep -h "components_open: found" "$work/out" "$work/err")"
    OMPI_MCA_pml=cm OMPI_MCA_pml_base_verbose=10 mpi 2 --quiet --threads 1 "$here/still.crt" \
        --width 8 --height 8 -o "$work/named.png" >"$work/out" 2>"$work/err"
    # Only the named one is opened (here it finds no network to run on, and the job fails).
    grep -q "components_open: found loaded component ob1" "$work/out" "$work/err" &&
        fail "crtc replaced the transport the job named"
    grep -q "components_open: found loaded component cm" "$work/out" "$work/err" ||
        fail "the job's own transport was not tried: $(head -5 "$work/err")"
}

missing_module() {
    # Every rank fails to load it; rank 0 alone says why, naming the file, and nothing is written.
    CRT_MPI_MODULE=$work/missing/crt_mpi.so expect_status 2 "a missing MPI module" \
        mpi 2 --quiet "$here/still.crt" -o "$work/out.png"
    expect_text "$work/err" "crtc: cannot share the render over the processes of mpirun: the MPI module $work/missing/crt_mpi.so named by CRT_MPI_MODULE does not exist" \
        "the missing module is named"
    [ "$(grep -c "the MPI module" "$work/err")" = 1 ] || fail "the missing module was not reported once: $(cat "$work/err")"
    [ ! -e "$work/out.png" ] || fail "an image was written without the MPI module"
}

"$case_name"
finish
