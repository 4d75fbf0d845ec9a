# Checks shared by crtc's command-line tests; the including script sets $work and failures=0.
expect_status() { # expected-status description command...
    local want=$1 what=$2
    shift 2
    "$@" >"$work/out" 2>"$work/err"
    local got=$?
    # Under the sanitizers, LeakSanitizer's own tracer sometimes crashes at exit in a process
    # of many threads (google/sanitizers#1353, seen under mpirun, twice in a row once):
    # neither a leak nor the command's failure, so the command runs again, twice at most.
    local retries=2
    while [ "$got" != "$want" ] && [ "$retries" -gt 0 ] &&
        grep -q "LeakSanitizer has encountered a fatal error" "$work/err" &&
        ! grep -q "LeakSanitizer: detected memory leaks" "$work/err"; do
        echo "note: $what: LeakSanitizer's tracer crashed at exit (not a leak); running it again"
        retries=$((retries - 1))
        "$@" >"$work/out" 2>"$work/err"
        got=$?
    done
    if [ "$got" != "$want" ]; then
        echo "FAIL: $what: exit status $got, expected $want"
        sed 's/^/  stdout: /' "$work/out" | head -5
        # The start says what went wrong, the end how the process ended.
        if [ "$(wc -l <"$work/err")" -le 15 ]; then
            sed 's/^/  stderr: /' "$work/err"
        else
            sed 's/^/  stderr: /' "$work/err" | head -5
            echo "  stderr: ..."
            sed 's/^/  stderr: /' "$work/err" | tail -10
        fi
        failures=$((failures + 1))
    fi
}
expect_text() { # file pattern description
    if ! grep -qE -- "$2" "$1"; then
        echo "FAIL: $3: no match for '$2' in:"
        head -5 "$1" | sed 's/^/  /'
        failures=$((failures + 1))
    fi
}
fail() { # description
    echo "FAIL: $1"
    failures=$((failures + 1))
}
finish() {
    if [ "$failures" -gt 0 ]; then
        echo "$failures check(s) failed"
        exit 1
    fi
    echo "all checks passed"
}
