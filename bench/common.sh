# Shared by the benchmark scripts (sourced, not run): their options and usage, the crtc
# check, the output folder with a private POV-Ray HOME, and timing helpers.
#   bench_check_crtc            sets have_crtc (0: measure POV-Ray only); exits 2 if unusable
#   bench_check_base            sets have_base (1 if $base names a second crtc); exits 2 if unusable
#   bench_build_commit REV      builds crtc of commit REV and sets base to it (after the folder)
#   bench_output_folder NAME    sets out, logs, povhome and keep_hint
#   bench_parse_options SPEC... -- ARGS...
#                               the script's options (see below); sets crtc from CRTC
#   bench_usage                 prints the script's header comment

# The header comment of the script that sourced this file, up to the first line that is not
# a comment.
bench_usage() { awk 'NR == 1 { next } !/^#/ { exit } { sub(/^# ?/, ""); print }' "$0"; }

# Options `--NAME VALUE` or `--NAME=VALUE`, each SPEC being NAME (which sets the variable
# NAME) or NAME=VARIABLE; -h or --help prints the usage; one argument that is not an option
# names the crtc to measure (else $CRTC, else build/bin/crtc) and sets `crtc`. Anything else
# exits with status 2.
bench_parse_options() {
    local -A variable=()
    while [[ $1 != -- ]]; do
        if [[ $1 == *=* ]]; then variable[${1%%=*}]=${1#*=}; else variable[$1]=$1; fi
        shift
    done
    shift
    local crtc_arg= name value
    while [[ $# -gt 0 ]]; do
        case $1 in
        -h | --help) bench_usage; exit 0 ;;
        --*=*) name=${1%%=*} value=${1#*=}; shift ;;
        --*)
            [[ $# -ge 2 ]] || { echo "$0: '$1' needs a value" >&2; bench_usage >&2; exit 2; }
            name=$1 value=$2; shift 2 ;;
        -*) echo "$0: unknown option '$1'" >&2; bench_usage >&2; exit 2 ;;
        *)
            [[ -z $crtc_arg ]] || { echo "$0: more than one CRTC given" >&2; exit 2; }
            crtc_arg=$1; shift; continue ;;
        esac
        name=${name#--}
        [[ -n ${variable[$name]:-} ]] || { echo "$0: unknown option '--$name'" >&2; bench_usage >&2; exit 2; }
        printf -v "${variable[$name]}" '%s' "$value"
    done
    crtc=${crtc_arg:-${CRTC:-$root/build/bin/crtc}}
}

bench_check_crtc() {
    have_crtc=1
    if [[ ! -f $crtc ]]; then
        have_crtc=0
        echo "$0: crtc not found at '$crtc'." >&2
        echo "    Build it first (cmake --build build --target crtc) or pass its path:" >&2
        echo "    $0 path/to/crtc   or   CRTC=path/to/crtc $0" >&2
        echo "    Measuring the POV-Ray side only; the crtc columns will read 'missing'." >&2
    elif [[ ! -x $crtc ]]; then
        echo "$0: '$crtc' exists but is not executable" >&2
        exit 2
    fi
}

# The optional second crtc build ($base, from CRTC_BASE or an option), timed in the same
# alternating loop as $crtc so that both are measured against the same POV-Ray runs.
bench_check_base() {
    have_base=0
    [[ -n ${base:-} ]] || return 0
    if [[ ! -f $base || ! -x $base ]]; then
        echo "$0: the base crtc '$base' is not an executable file" >&2
        exit 2
    fi
    have_base=1
}

# bench_build_commit REV: builds crtc as it was at commit REV of this repository (its tree
# exported with git archive into $out/base-SHA, configured Release, the crtc target only) and
# sets base to the binary. With BENCH_OUT, a build left there by an earlier run is reused.
bench_build_commit() {
    local rev=$1 sha tree binary
    if ! sha=$(git -C "$root" rev-parse --verify --quiet "$rev^{commit}"); then
        echo "$0: --base-commit: '$rev' is not a commit of $root" >&2
        exit 2
    fi
    tree=$out/base-${sha:0:12}
    if [[ ! -d $tree/build ]]; then
        echo "building crtc of ${sha:0:12} in $tree (a few minutes) ..." >&2
        mkdir -p "$tree"
        git -C "$root" archive "$sha" | tar -x -C "$tree"
        if ! { cmake -S "$tree" -B "$tree/build" -G Ninja -DCMAKE_BUILD_TYPE=Release &&
            cmake --build "$tree/build" --target crtc; } >"$logs/base-build.log" 2>&1; then
            echo "$0: building ${sha:0:12} failed; log: $logs/base-build.log$keep_hint" >&2
            tail -n 20 "$logs/base-build.log" >&2
            exit 2
        fi
    fi
    # Where the crtc target's binary is depends on the commit: build/bin/ today, the folder
    # of its sources before.
    for binary in "$tree/build/bin/crtc" "$tree/build/lang/crtc" "$tree/build/apps/crtc"; do
        [[ -x $binary ]] && break
    done
    if [[ ! -x $binary ]]; then
        echo "$0: the build of ${sha:0:12} has no crtc binary (see $logs/base-build.log)" >&2
        exit 2
    fi
    base=$binary
}

# Output folder: images or generated files, logs, and a private HOME for POV-Ray (so it
# reads no user povray.ini and does not warn about a missing user povray.conf).
bench_output_folder() {
    if [[ -n ${BENCH_OUT:-} ]]; then
        out=$BENCH_OUT
        mkdir -p "$out"
        out=$(cd "$out" && pwd)
        keep_hint=
    else
        out=$(mktemp -d "${TMPDIR:-/tmp}/crt-bench-$1.XXXXXX")
        trap 'rm -rf "$out"' EXIT
        keep_hint=" (removed at exit; set BENCH_OUT to keep it)"
    fi
    logs=$out/logs
    povhome=$out/povray-home
    mkdir -p "$logs" "$povhome/.povray/3.7"
    : >"$povhome/.povray/3.7/povray.conf"
}

# stamp VAR: the time now, in nanoseconds, into VAR, without starting a process (bash's
# EPOCHREALTIME, microsecond resolution; `date` where that is missing). A timed command is
# then charged for itself only: starting `date` twice and GNU time around it would add their
# own start-up, a sizeable part of crtc's time on the short front-end workloads.
stamp() {
    if [[ -n ${EPOCHREALTIME:-} ]]; then
        printf -v "$1" '%s000' "${EPOCHREALTIME/[.,]/}"
    else
        printf -v "$1" '%s' "$(date +%s%N)"
    fi
}

# seconds between two nanosecond stamps, with DECIMALS digits (default 3)
elapsed() { awk -v a="$1" -v b="$2" -v d="${3:-3}" 'BEGIN { printf("%." d "f", (b - a) / 1e9) }'; }

# median of the numbers given as arguments (lower middle for an even count)
median() {
    printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'
}

# children_cpu_ms VAR: user + system CPU milliseconds of this shell's finished children so
# far, from bash's `times` (no process started, so nothing extra in a timed run). Needs
# $logs (bench_output_folder).
children_cpu_ms() {
    local part minutes seconds total=0 user sys
    times >"$logs/.times"
    { read -r _ _; read -r user sys; } <"$logs/.times"
    for part in "$user" "$sys"; do # e.g. 1m2.345s
        minutes=${part%%m*} seconds=${part#*m}
        seconds=${seconds%s}
        total=$((total + 10#$minutes * 60000 + 10#${seconds%[.,]*} * 1000 + 10#${seconds#*[.,]}))
    done
    printf -v "$1" '%s' "$total"
}
