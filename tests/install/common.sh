# Sourced by the install tests: failures are counted, not fatal, so that one run reports them
# all; `finish` ends the test with them.
failures=0
fail() {
    echo "FAIL: $*"
    failures=$((failures + 1))
}
finish() { # what passed
    [ $failures -eq 0 ] || exit 1
    echo "$*: ok"
}
# An installed program must need nothing from the environment or the source tree.
run_installed() { env -u CRT_PATH -u CRT_IMAGE_IO_MODULE -u CRT_MPI_MODULE "$@"; }
