#!/bin/sh
# Instancing (issue 42), in TAP: an LDraw-style model (scenes/ldraw-model.sh:
# parts declared once as unions of meshes, placed by matrix with their own
# textures, a face and a mesh textured inside the parts, see-through parts,
# smooth triangles) renders with each shared mesh kept once
# (--instancing auto, the default) as it renders flattened (--instancing
# off): the same image within rounding, every exact method's decisions the
# shadow ray's (--verify-shadows), the same image on 1 and 2 threads, and
# both against POV-Ray's render.
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray; may be empty).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
tap_work hstinst
[ -x "$hstrace" ] || bail "$hstrace is not built"
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" >"$work/out" 2>"$work/err"; status=$?
}

# 72 parts (a layer of 64 and 8 on top), studs of 8 segments: parts of 108
# to 300 triangles, and a baseplate placed once (flattened).
sh "$srcdir/scenes/ldraw-model.sh" 72 8 >"$work/bricks.pov" || bail "scenes/ldraw-model.sh failed"

run "$work/bricks.pov" +W160 +H120 +FE -o "$work/inst.exr" --stats-json "$work/inst.json"
check "LDraw-style model renders with instancing" exited 0
run "$work/bricks.pov" +W160 +H120 +FE -o "$work/flat.exr" --stats-json "$work/flat.json" --instancing off
check "LDraw-style model renders with --instancing off" exited 0
ninst=$(json_value instances "$work/inst.json")
nproto=$(json_value prototypes "$work/inst.json")
# a part's meshes: 3001 two, 3003 one, 3710 one, 553 two; 72 parts, 24 of
# them 3001 and 12 553 (the generator's cycle): 72 + 24 + 12 placements of meshes
check "instancing auto: the 108 placed meshes are instances" same_count "$ninst" 108
check "instancing auto: of 6 meshes kept once" same_count "$nproto" 6
check "--instancing off: no instance" same_count "$(json_value instances "$work/flat.json")" 0
# The same polygons either way: the world's own and the instances' add up
# to the flattened world's.
inst_all=$(($(json_value polygons "$work/inst.json") + $(json_value instanced_polygons "$work/inst.json")))
check "instances place every polygon flattening makes" same_count "$inst_all" "$(json_value polygons "$work/flat.json")"
check "--instancing off: the same image as instancing, up to rounding" \
    "$hstrace" compare "$work/flat.exr" "$work/inst.exr" --max-error 1e-5

# Every exact method decides on instances as the shadow ray does (hst,
# cache and the light buffer, whose cells list instances, on the instanced
# world; volume and hst with --volumes always get the flattened world,
# which their shadow volumes want), with anti-aliasing and see-through
# parts: 0 disagreements, and the conventional method's image.
for m in conventional cache hst volume light-buffer hst-always; do
    case $m in
    hst-always) opts="--shadows hst --volumes always" ;;
    *) opts="--shadows $m" ;;
    esac
    # shellcheck disable=SC2086 # the method's options, one word each
    run "$work/bricks.pov" +W96 +H72 +A0.3 +FE $opts --verify-shadows --stats-json "$work/v-$m.json" -o "$work/v-$m.exr"
    check "$m --verify-shadows on the model: renders" exited 0
    dis=$(sed -n 's/.*"disagreements": \([0-9]*\).*/\1/p' "$work/v-$m.json" | head -1)
    check "$m --verify-shadows: ${dis:-no} disagreements with the shadow ray" test "${dis:-x}" = 0
    case $m in
    conventional | cache | hst | light-buffer) want=108 ;;
    *) want=0 ;;
    esac
    check "$m: $want instances" same_count "$(json_value instances "$work/v-$m.json")" "$want"
    if [ "$want" = 108 ]; then
        check "$m: the same image as conventional" \
            "$hstrace" compare "$work/v-conventional.exr" "$work/v-$m.exr" --max-error 0
    else
        check "$m (flattened): the image of conventional on instances, up to rounding" \
            "$hstrace" compare "$work/v-conventional.exr" "$work/v-$m.exr" --max-error 1e-5
    fi
done

# An area light: sampled by the shadow ray (cache) on instances, its
# decisions the shadow ray's; hst's beams want world polygons (flattened).
sed 's|color rgb <0.8, 0.8, 0.8> }|color rgb <0.8, 0.8, 0.8> area_light <40,0,0>, <0,0,40>, 3, 3 }|' \
    "$work/bricks.pov" >"$work/area.pov"
for m in cache hst; do
    run "$work/area.pov" +W64 +H48 +FE --shadows "$m" --verify-shadows --stats-json "$work/a-$m.json" -o "$work/a-$m.exr"
    check "area light, $m --verify-shadows: renders" exited 0
    dis=$(sed -n 's/.*"disagreements": \([0-9]*\).*/\1/p' "$work/a-$m.json" | head -1)
    check "area light, $m: ${dis:-no} disagreements with the shadow ray" test "${dis:-x}" = 0
done
check "area light, cache: 108 instances" same_count "$(json_value instances "$work/a-cache.json")" 108
check "area light, hst (its beams): flattened, no instance" same_count "$(json_value instances "$work/a-hst.json")" 0
check "area light: hst flattened gives cache's image on instances, up to rounding" \
    "$hstrace" compare "$work/a-cache.exr" "$work/a-hst.exr" --max-error 1e-5

# Embree (where built in) on instances: its prototypes' scenes instanced in
# its top scene; not exact by design (float tests: its disagreements are a
# figure), so held to the instances it took and to the image.
if "$hstrace" --version 2>/dev/null | grep -q "Embree [0-9]"; then
    run "$work/bricks.pov" +W96 +H72 +A0.3 +FE --shadows embree --verify-shadows --stats-json "$work/v-embree.json" \
        -o "$work/v-embree.exr"
    check "embree --verify-shadows on the model: renders" exited 0
    check "embree: 108 instances" same_count "$(json_value instances "$work/v-embree.json")" 108
    check "embree on instances: the image of conventional within an RMSE of 1e-4" \
        "$hstrace" compare "$work/v-conventional.exr" "$work/v-embree.exr" --max-rmse 1e-4
else
    skip "embree on instances" "hstrace built without Embree (Debian package libembree-dev)"
fi

# Threads: the same image, bit for bit.
for t in 1 2; do
    run "$work/bricks.pov" +W96 +H72 +A0.3 +FE --threads "$t" -o "$work/t$t.exr"
done
check "instanced model: the same image on 1 and 2 threads" \
    "$hstrace" compare "$work/t1.exr" "$work/t2.exr" --max-error 0

# Against POV-Ray, instanced (the default) and flattened, at 240x180 (the
# rule of tests/regress.sh): each LIMIT (MEASURED) pair is the limit and the
# value measured on 2026-12-07 against POV-Ray 3.7.0.10 (one thread), about
# the larger of twice that and 1e-5 for an RMSE, twice that and 1 for a
# count of pixels: the +Q9 image's RMSE and its pixels off by more than
# 0.02, and the shadow-mask pixels that disagree (at edges and silhouettes;
# none may in the interior).
limits='
# scene       RMSE   (measured)   off (m.)  mask pixels (m.)
bricks        1e-5   (2.23e-6)    1 (0)     1 (0)
'
povray_scenes_check "$limits" tests/instancing.sh bricks
run() {
    "$hstrace" "$@" --instancing off >"$work/out" 2>"$work/err"; status=$?
}
cp "$work/bricks.pov" "$work/bricks-flat.pov"
limits='
# scene       RMSE   (measured)   off (m.)  mask pixels (m.)
bricks-flat   1e-5   (2.23e-6)    1 (0)     1 (0)
'
povray_scenes_check "$limits" tests/instancing.sh bricks-flat

tap_end
