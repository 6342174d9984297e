#!/bin/sh
# Regression against POV-Ray, in TAP. For every scene in scenes/: hstrace's
# full render against POV-Ray's (RMSE <= 0.01, pixels off by > 0.02 <= 1%),
# and hstrace's shadow mask (+Q3 vs +Q4) against POV-Ray's (<= 0.1% of the
# pixels disagree, and only on shadow edges or silhouettes). With povray
# installed the references are re-rendered first, so they cannot go stale;
# otherwise the committed ones in reference/ are used.
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
compare="$builddir/tests/compare_images"
width=320
height=240
work=$(mktemp -d "${TMPDIR:-/tmp}/hstregress.XXXXXX")
trap 'rm -rf "$work"' EXIT

n=0
ok() { n=$((n + 1)); echo "ok $n - $*"; }
not_ok() { n=$((n + 1)); echo "not ok $n - $*"; }

refs="$srcdir/reference"
if [ -n "${POVRAY:-}" ] && [ -x "${POVRAY}" ]; then
    if POVRAY="$POVRAY" "$srcdir/reference/make-references.sh" "$work/ref" $width $height >"$work/ref.log" 2>&1; then
        refs="$work/ref"
        echo "# references re-rendered with $("$POVRAY" --version 2>&1 | grep -m1 'POV-Ray')"
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
             --share 0.001 2>&1); then
        ok "$name: shadow mask matches POV-Ray: $out"
    else
        not_ok "$name: shadow mask matches POV-Ray: $out"
    fi
done
echo "1..$n"
