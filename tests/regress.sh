#!/bin/sh
# Regression against POV-Ray, in TAP. For every scene in scenes/: hstrace's
# full render against POV-Ray's (RMSE <= 0.01, pixels off by > 0.02 <= 1%),
# and hstrace's shadow mask (+Q3 vs +Q4) against POV-Ray's (<= 0.1% of the
# pixels disagree, and only at shadow edges or silhouettes; see
# tests/compare_images.c for the exact rules). With povray installed
# ($POVRAY) the references are re-rendered first, so they cannot go stale;
# otherwise the committed ones in reference/ are used.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray, may be empty), HST_REGRESS_KEEP=1 keeps the renders and the mask
# maps (compare_images --map) and prints where.
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
compare="$builddir/tests/compare_images"
width=320
height=240
work=$(mktemp -d "${TMPDIR:-/tmp}/hstregress.XXXXXX") || { echo "Bail out! cannot make a temporary folder"; exit 1; }
if [ "${HST_REGRESS_KEEP:-0}" = 1 ]; then
    echo "# renders kept in $work"
else
    trap 'rm -rf "$work"' EXIT
    trap 'exit 1' HUP INT PIPE TERM   # so that EXIT cleans up on a signal too
fi

n=0
ok() { n=$((n + 1)); echo "ok $n - $*"; }
not_ok() { n=$((n + 1)); echo "not ok $n - $*"; }

for tool in "$hstrace" "$compare"; do
    [ -x "$tool" ] || { echo "Bail out! $tool is not built"; exit 1; }
done

refs="$srcdir/reference"
povray=""
if [ -n "${POVRAY:-}" ]; then
    povray=$(command -v "$POVRAY" 2>/dev/null || true)
fi
if [ -n "$povray" ] && [ -x "$povray" ]; then
    if POVRAY="$povray" "$srcdir/reference/make-references.sh" "$work/ref" $width $height >"$work/ref.log" 2>&1; then
        refs="$work/ref"
        echo "# references re-rendered with $("$povray" --version 2>&1 | grep -m1 '^POV-Ray')"
    else
        not_ok "re-render POV-Ray references"; sed 's/^/# /' "$work/ref.log"
    fi
else
    echo "# povray not installed: using the committed references"
fi

for scene in "$srcdir"/scenes/*.pov; do
    name=$(basename "$scene" .pov)
    for q in 9 3 4; do
        suffix=$([ "$q" = 9 ] && echo "" || echo ".q$q")
        if ! "$hstrace" "$scene" --width $width --height $height "+Q$q" -o "$work/$name$suffix.exr" 2>"$work/err"; then
            not_ok "$name: hstrace renders at +Q$q"; sed 's/^/# /' "$work/err"
        fi
    done
    if out=$("$compare" full "$refs/$name.exr" "$work/$name.exr" --rmse 0.01 --threshold 0.02 --share 0.01 2>&1); then
        ok "$name: image matches POV-Ray: $out"
    else
        not_ok "$name: image matches POV-Ray: $out"
    fi
    if out=$("$compare" mask "$refs/$name.q3.exr" "$refs/$name.q4.exr" "$work/$name.q3.exr" "$work/$name.q4.exr" \
             --share 0.001 --map "$work/$name.mask-map.png" 2>&1); then
        ok "$name: shadow mask matches POV-Ray: $out"
    else
        not_ok "$name: shadow mask matches POV-Ray: $out"
    fi
done
echo "1..$n"
