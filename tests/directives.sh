#!/bin/sh
# The directive language through the hstrace command, in TAP: a scene that
# includes every POV-Ray 3.7 standard include file renders one triangle,
# with --strict too;
# #debug, #warning and #error reach stderr (and #error the exit status 2);
# an error inside a macro names the macro's line and the call.
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
incdir=/usr/share/povray-3.7/include
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstdir.XXXXXX") || bail "cannot make a temporary folder"
trap 'rm -rf "$work"' EXIT
[ -x "$hstrace" ] || bail "$hstrace is not built"
render() { # scene file: runs hstrace on it; sets status, leaves stderr in $work/err
    rm -f "$work/out.png"
    "$hstrace" "$1" --width 16 --height 12 --threads 1 -o "$work/out.png" 2>"$work/err"
    status=$?
}

# Include files hstrace cannot read yet, each with the reason. They are left
# out of the all-includes scene, and must still fail cleanly (status 2, with
# FILE:LINE:COLUMN).
# None today; each entry is a line "x.inc|why".
known_failing=""

if [ ! -d "$incdir" ]; then
    for d in "a scene including all standard include files renders a triangle" \
             "... and with --strict, which refuses nothing the scene does not use" \
             "a function from functions.inc: error at its use, naming its declaration"; do
        skip "$d" "POV-Ray's include files are not installed (Debian package povray-includes; $incdir absent)"
    done
else
    # colors.inc first: stdcam.inc and others use its names without
    # including it, as POV-Ray scenes always include it before them.
    {
        echo '#version 3.7;'
        echo '#include "colors.inc"'
        for f in "$incdir"/*.inc; do
            b=${f##*/}
            case "
$known_failing" in *"
$b|"*) continue ;; esac
            echo "#include \"$b\""
        done
        echo 'camera { location <0.3, 0.3, -2> look_at <0.3, 0.3, 0> }'
        echo 'light_source { <0, 0, -5>, White }'
        echo 'triangle { 0, x, y pigment { White } }'
    } >"$work/all.pov"
    count=$(grep -c '^#include' "$work/all.pov")
    render "$work/all.pov"
    check "a scene including all $count standard include files renders a triangle" exited 0
    check "... an image" [ -s "$work/out.png" ]
    check "... nothing on stderr" [ ! -s "$work/err" ]
    # --strict refuses only what the scene uses (issue 42): the declarations
    # the includes make and the scene never uses are not its business, a
    # value declared right before a #declare that uses it included
    # (skies.inc's T_Cloud3, a layered texture, and O_Cloud2 after it).
    rm -f "$work/out.png"
    "$hstrace" "$work/all.pov" --width 16 --height 12 --threads 1 --strict -o "$work/out.png" 2>"$work/err"
    status=$?
    check "... and with --strict, which refuses nothing the scene does not use" exited 0
    check "... nothing on stderr with --strict" [ ! -s "$work/err" ]

    while IFS='|' read -r b reason; do
        [ -n "$b" ] || continue
        printf '#include "colors.inc"\n#include "%s"\ntriangle { 0, x, y }\n' "$b" >"$work/one.pov"
        render "$work/one.pov"
        if [ $status -eq 0 ]; then
            not_ok "$b: now renders; take it off the known_failing list"
        else
            check "$b fails cleanly ($reason)" exited 2 "^$incdir/$b:[0-9]*:[0-9]*: "
        fi
    done <<EOF
$known_failing
EOF

    # functions.inc and shapes.inc declare functions and isosurfaces: those
    # stay unread until used, and using one names its declaration.
    printf '#include "functions.inc"\n#include "shapes.inc"\n#declare R = f_sphere(1, 0, 0, 1);\ntriangle { 0, x, y translate R * z }\n' >"$work/fn.pov"
    render "$work/fn.pov"
    check "a function from functions.inc: error at its use, naming its declaration" \
        exited 2 "^$work/fn.pov:4:30: 'function' is not supported by hstrace (declared at $incdir/functions.inc:[0-9]*)\$"
fi

# #debug, #warning, #error
cat >"$work/msg.pov" <<'POV'
#debug concat("value ", str(6 * 7, 0, 0), "\n")
#warning "careful"
triangle { 0, x, y }
#error concat("stop ", "here")
POV
render "$work/msg.pov"
# err_is TEXT: stderr of the last render is TEXT
err_is() { [ "$(cat "$work/err")" = "$1" ] || { echo "stderr:"; cat "$work/err"; echo "expected:"; echo "$1"; return 1; }; }
check "#error stops with status 2" exited 2
check "#debug prints its text, #warning a located warning, #error its message" err_is "value 42
$work/msg.pov:2:1: warning: careful
$work/msg.pov:4:1: #error: stop here"
check "... no image" [ ! -e "$work/out.png" ]

# #debug text without a final newline (POV-Ray's sample portfolio scenes
# print "Generated the file: X" so) must not swallow the start of the next
# message: a warning or the error starts a line of its own.
cat >"$work/open.pov" <<'POV'
#debug "one"
#warning "careful"
#debug "two"
#error "stop"
POV
render "$work/open.pov"
check "#error after #debug text without a newline: status 2" exited 2
check "a message after #debug text without a newline starts a line of its own" err_is "one
$work/open.pov:2:1: warning: careful
two
$work/open.pov:4:1: #error: stop"
printf '#debug "last"\ntriangle { 0, x, y }\n' >"$work/open2.pov"
render "$work/open2.pov"
check "#debug text without a newline at the end of the scene: renders" exited 0
check "#debug text without a newline at the end of the scene: the line is ended" \
    [ "$(od -c "$work/err" | head -1 | tr -s " ")" = "0000000 l a s t \\n" ]

# An error inside a macro: the offending token in the macro, then the call.
cat >"$work/mac.pov" <<'POV'
#macro Leg(H)
  box { 0, <0.1, H, 0.1> pigmnt { rgb 1 } }
#end
#macro Table(H)
  union { Leg(H) Leg(H) }
#end
Table(1)
POV
render "$work/mac.pov"
check "an error inside nested macros: status 2" exited 2
check "an error inside nested macros: the body's token, then each call" \
    err_is "$work/mac.pov:2:26: expected an object modifier or '}' in 'box', found 'pigmnt'
$work/mac.pov:5:11: note: in macro 'Leg' called here
$work/mac.pov:7:1: note: in macro 'Table' called here"
sed 's/^/# /' "$work/err"

tap_end
