#!/bin/sh
# Runs shellcheck (Debian package shellcheck) over every shell script of the
# tests and the benchmarks, tests/*.sh and bench/*.sh, in TAP: one check per
# script, which fails on any finding, style included. A warning that is
# wrong for a line is disabled there, with a comment saying why. Without
# the program, every check is a SKIP with that reason.
#
# Environment: top_srcdir (default .).
set -u
srcdir=${top_srcdir:-.}
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
shellcheck=$(command -v shellcheck 2>/dev/null || true)
# From the source folder, so that the "source=tests/tap.sh" directives are
# found (-x follows them).
cd "$srcdir" || bail "cannot enter $srcdir"
for f in tests/*.sh bench/*.sh; do
    [ -f "$f" ] || continue
    if [ -z "$shellcheck" ]; then
        skip "shellcheck $f" "shellcheck not installed (Debian package shellcheck)"
    else
        check "shellcheck $f" "$shellcheck" -x -f gcc "$f"
    fi
done
tap_end
