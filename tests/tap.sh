# shellcheck shell=sh
# shellcheck disable=SC2154 # $work, $hstrace and $srcdir are the test's
# TAP helpers for the shell tests (POSIX sh), sourced by every tests/*.sh:
#   . "$srcdir/tests/tap.sh"
# A check runs a command and reports from that command's own exit status,
# so a check cannot read a status left over from elsewhere; a status kept
# from earlier is checked with check_status, naming the value it expects.
#
#   check DESC CMD [ARG...]      ok when CMD exits 0; else not ok, with CMD's
#                                status and output as "# " comments (the
#                                three checks return 0 when ok, else 1)
#   check_fails DESC CMD [ARG...]  ok when CMD exits non-zero
#   check_status DESC GOT WANT   ok when the status GOT is WANT
#   ok DESC / not_ok DESC        a result decided by the caller
#   skip DESC REASON             ok N - DESC # SKIP REASON: a check that
#                                cannot run here (a missing tool), with why
#   diag TEXT...                 each line of TEXT as a "# " comment
#   bail TEXT                    Bail out! TEXT, and exit 1
#   tap_end                      the plan, 1..N (last)
# tap_todo, when not empty, marks every result as "# TODO $tap_todo".
# CMD runs in a subshell: a check cannot change the test's variables. A
# condition of several commands is a function, so that check runs it whole:
# `check D [ -s a ] && [ -s b ]` would check only the first.
#
# Commands for check, below: exited (the status and message of the last
# run), at_most, within, above, at_least, same_count (numbers), json_value
# (a figure of --json output); and the comparisons against POV-Ray with
# limits measured per scene: limit_row, image_check, mask_check, ties_check.
tap_n=0
tap_todo=""

tap_result() { # "ok" or "not ok", then the description
    tap_n=$((tap_n + 1))
    echo "$1 $tap_n - $2${tap_todo:+ # TODO $tap_todo}"
}
ok() { tap_result ok "$*"; }
not_ok() { tap_result "not ok" "$*"; }
skip() { tap_n=$((tap_n + 1)); echo "ok $tap_n - $1 # SKIP $2"; }
diag() { printf '%s\n' "$*" | sed 's/^/# /'; }
bail() { echo "Bail out! $*"; exit 1; }
tap_end() { echo "1..$tap_n"; }

check() {
    tap_desc=$1
    shift
    tap_out=$("$@" 2>&1)
    tap_status=$?
    if [ $tap_status -eq 0 ]; then
        ok "$tap_desc"
        return 0
    fi
    not_ok "$tap_desc"
    diag "exit status $tap_status: $*"
    [ -z "$tap_out" ] || printf '%s\n' "$tap_out" | head -n 20 | sed 's/^/#   /'
    return 1
}

check_fails() {
    tap_desc=$1
    shift
    tap_out=$("$@" 2>&1)
    tap_status=$?
    if [ $tap_status -ne 0 ]; then
        ok "$tap_desc"
        return 0
    fi
    not_ok "$tap_desc"
    diag "exit status 0, a failure expected: $*"
    [ -z "$tap_out" ] || printf '%s\n' "$tap_out" | head -n 20 | sed 's/^/#   /'
    return 1
}

check_status() {
    if [ "$2" = "$3" ]; then
        ok "$1"
        return 0
    fi
    not_ok "$1"
    diag "status ${2:-(none)}, expected $3"
    return 1
}

at_most() {
    awk -v v="$1" -v l="$2" 'BEGIN { exit !(v != "" && l != "" && v + 0 <= l + 0) }'
}

# The convention of the tests that run programs: run() keeps the status in
# $status and the standard error in $work/err. exited STATUS [PATTERN]: the
# last run exited STATUS and, given PATTERN (grep's basic regex), its
# standard error matches it; else says what it got, for check to show.
exited() {
    [ "${status:-}" = "$1" ] || { echo "exit status ${status:-(none)}, expected $1; stderr:"; cat "$work/err"; return 1; }
    [ $# -lt 2 ] || grep -q -- "$2" "$work/err" || { echo "stderr does not match '$2':"; cat "$work/err"; return 1; }
}

# json_value KEY FILE: the value of the first line "KEY": VALUE[,] in FILE
# (hstrace's --json output puts each key on a line of its own).
json_value() {
    awk -v k="\"$1\":" '$1 == k { sub(/^[^:]*: /, ""); sub(/,$/, ""); print; exit }' "$2"
}
# same_count A B: A and B are the same number (neither empty).
same_count() {
    if [ -n "$1" ] && [ "$1" = "$2" ]; then return 0; fi
    echo "'$1' is not '$2'"
    return 1
}
# within VALUE LIMIT: like at_most, and says so when VALUE is over LIMIT.
within() {
    at_most "$1" "$2" || { echo "${1:-(no value)} is over the limit ${2:-(none)}"; return 1; }
}
# above VALUE LOW, at_least VALUE LOW: the number VALUE is more than LOW,
# LOW or more; else say so.
above() {
    awk -v v="$1" -v l="$2" 'BEGIN { exit !(v != "" && l != "" && v + 0 > l + 0) }' ||
        { echo "${1:-(no value)} is not above ${2:-(none)}"; return 1; }
}
at_least() {
    awk -v v="$1" -v l="$2" 'BEGIN { exit !(v != "" && l != "" && v + 0 >= l + 0) }' ||
        { echo "${1:-(no value)} is below ${2:-(none)}"; return 1; }
}

# --- images against POV-Ray's, by hstrace compare, against measured limits -
# These use $hstrace, $srcdir and the folder $work.
# limit_row TABLE KEY...: the row of TABLE (lines of fields; "#" starts a
# comment line) whose first fields are the KEYs, without them and without
# the parentheses around measured values: "1e-5 (1.3e-6) 1 (0)" gives
# "1e-5 1.3e-6 1 0". Nothing when there is no such row.
limit_row() {
    tap_table=$1
    shift
    printf '%s\n' "$tap_table" | awk -v keys="$*" '
        BEGIN { nk = split(keys, k, " ") }
        substr($1, 1, 1) == "#" { next }
        { for (i = 1; i <= nk; i++) if ($i != k[i]) next
          out = ""; for (i = nk + 1; i <= NF; i++) { f = $i; gsub(/[()]/, "", f); out = out (out == "" ? "" : " ") f }
          print out; exit }'
}
# image_check LABEL A B RMSE_MAX RMSE_MEASURED OFF_MAX OFF_MEASURED: B's
# image against A's, RMSE and the pixels off by more than 0.02 within the
# limits, and no NaN or infinite pixel. Leaves the figures in $work/image.json.
image_check() {
    "$hstrace" compare "$2" "$3" --json >"$work/image.json" 2>&1
    tap_rmse=$(json_value rmse "$work/image.json")
    tap_off=$(json_value pixels_over_threshold "$work/image.json")
    check "$1: RMSE $tap_rmse <= $4 (measured $5)" within "$tap_rmse" "$4"
    check "$1: $tap_off pixels off by more than 0.02 <= $6 (measured $7)" within "$tap_off" "$6"
    check_status "$1: no NaN or infinite pixels" "$(json_value nonfinite_pixels "$work/image.json")" 0
}
# mask_check LABEL A3 A4 B3 B4 MAX MEASURED [OPTION...]: B's shadow mask
# (+Q3/+Q4 pair) against A's: none disagree in the interior, at most MAX at
# shadow edges and silhouettes (and as A's leaks, with --allow-a-leaks).
# Writes the mask map to $work/mask-map.exr, the figures to $work/mask.json.
# With $mask_todo set, the interior check is a TODO item with that reason.
mask_check() {
    tap_label=$1 tap_a3=$2 tap_a4=$3 tap_b3=$4 tap_b4=$5 tap_max=$6 tap_measured=$7
    shift 7
    "$hstrace" compare "$tap_a4" "$tap_b4" --threshold 0.02 --mask-a "$tap_a3" "$tap_a4" --mask-b "$tap_b3" "$tap_b4" \
        --max-interior 0 --mask-map "$work/mask-map.exr" --json "$@" >"$work/mask.json" 2>&1
    tap_status=$?
    tap_split="$(json_value shadow_edge "$work/mask.json") at shadow edges, $(json_value silhouette "$work/mask.json") at silhouettes"
    [ "$(json_value a_leaks "$work/mask.json")" = 0 ] || tap_split="$tap_split, $(json_value a_leaks "$work/mask.json") A's leaks"
    tap_split="$tap_split, $(json_value interior "$work/mask.json") interior"
    tap_keep=$tap_todo
    tap_todo=${mask_todo:-$tap_todo}
    check "$tap_label: no disagreement in the interior ($tap_split)" \
        no_interior "$tap_status" "$(json_value interior "$work/mask.json")"
    tap_todo=$tap_keep
    tap_disagree=$(json_value disagree "$work/mask.json")
    check "$tap_label: $tap_disagree pixels disagree <= $tap_max (measured $tap_measured)" \
        within "$tap_disagree" "$tap_max"
}
# povray_scenes_check TABLE SCRIPT NAME...: each $work/NAME.pov rendered by
# hstrace (with the caller's run) and by POV-Ray ($POVRAY, skipped when not
# installed) at 240x180, +Q9 for the image and +Q3/+Q4 for the shadow mask,
# held to NAME's row of the limits TABLE (limit_row; SCRIPT names the file
# that records them).
povray_scenes_check() {
    tap_limits=$1 tap_script=$2
    shift 2
    tap_povray=""
    if [ -n "${POVRAY:-}" ]; then tap_povray=$(command -v "$POVRAY" 2>/dev/null || true); fi
    for tap_name in "$@"; do
        tap_rendered=1
        for tap_q in 9 3 4; do
            run "$work/$tap_name.pov" --width 240 --height 180 "+Q$tap_q" -o "$work/$tap_name.h$tap_q.exr"
            check "$tap_name: hstrace renders at +Q$tap_q" exited 0 || tap_rendered=0
        done
        if [ -z "$tap_povray" ]; then
            for tap_d in "image matches POV-Ray" "shadow mask matches POV-Ray"; do
                skip "$tap_name: $tap_d" "povray not installed (Debian package povray)"
            done
            continue
        fi
        # shellcheck disable=SC2046 # three limits, each with its measured value
        set -- $(limit_row "$tap_limits" "$tap_name")
        if [ $# -ne 6 ]; then
            not_ok "$tap_name: limits recorded in $tap_script"
            continue
        fi
        for tap_q in 9 3 4; do
            # POV-Ray 3.7 can time out starting its threads on a loaded machine: one retry
            (cd "$work" && { "$tap_povray" "+I$tap_name.pov" "+O$tap_name.p$tap_q.exr" +FE +W240 +H180 -A -D -GA +WT1 \
                "+Q$tap_q" >/dev/null 2>&1 ||
                "$tap_povray" "+I$tap_name.pov" "+O$tap_name.p$tap_q.exr" +FE +W240 +H180 -A -D -GA +WT1 \
                    "+Q$tap_q" >/dev/null 2>&1; })
            [ -s "$work/$tap_name.p$tap_q.exr" ] || { not_ok "$tap_name: POV-Ray renders at +Q$tap_q"; tap_rendered=0; }
        done
        [ $tap_rendered = 1 ] || continue
        tap_a=$work/$tap_name.p tap_b=$work/$tap_name.h
        image_check "$tap_name: image matches POV-Ray" "${tap_a}9.exr" "${tap_b}9.exr" "$1" "$2" "$3" "$4"
        mask_check "$tap_name: shadow mask matches POV-Ray" "${tap_a}3.exr" "${tap_a}4.exr" "${tap_b}3.exr" \
            "${tap_b}4.exr" "$5" "$6"
    done
}
# verify_methods_check NAME...: each $work/NAME.pov rendered at 120x90 on 2
# threads with --verify-shadows by every exact shadow method (and embree
# where hstrace has it), each held to 0 disagreements with the shadow ray,
# or to the number the caller's verify_expected NAME METHOD OPTIONS prints
# where it defines one (a known inexactness, measured its own way); and
# some decisions verified, but on the scenes named in $verify_unlit.
verify_methods_check() {
    tap_methods="conventional cache light-buffer hst hst-always volume"
    if "$hstrace" --version 2>/dev/null | grep -q "Embree [0-9]"; then
        tap_methods="$tap_methods embree"
    else
        skip "embree --verify-shadows on $*" "hstrace built without Embree (Debian package libembree-dev)"
    fi
    for tap_name in "$@"; do
        for tap_m in $tap_methods; do
            case $tap_m in
            hst-always) tap_opts="--shadows hst --volumes always" ;;
            *) tap_opts="--shadows $tap_m" ;;
            esac
            # shellcheck disable=SC2086 # the method's options
            "$hstrace" "$work/$tap_name.pov" --width 120 --height 90 --threads 2 $tap_opts --verify-shadows \
                --stats-json "$work/v.json" -o "$work/v.exr" >/dev/null 2>"$work/err"
            status=$?
            check "$tap_name, $tap_m: renders with --verify-shadows" exited 0 || continue
            tap_dis=$(sed -n 's/.*"disagreements": \([0-9]*\).*/\1/p' "$work/v.json" | head -1)
            tap_checked=$(sed -n 's/.*"verified": \([0-9]*\).*/\1/p' "$work/v.json" | head -1)
            tap_want=0
            if command -v verify_expected >/dev/null 2>&1; then
                tap_want=$(verify_expected "$tap_name" "$tap_m" "$tap_opts")
                tap_want=${tap_want:-0}
            fi
            check "$tap_name, $tap_m: ${tap_dis:-(none)} disagreements with the shadow ray (expected $tap_want) in ${tap_checked:-(no count of)} decisions" \
                test "${tap_dis:-x}" = "$tap_want"
            case " ${verify_unlit:-} " in
            *" $tap_name "*) ;;
            *) [ "${tap_checked:-0}" -gt 0 ] || not_ok "$tap_name, $tap_m: some decisions verified" ;;
            esac
        done
    done
}
# bad_scenes_check: each line SCENE|MESSAGE of its input written to
# $work/bad.pov and rendered (the caller's run): status 2, MESSAGE at the
# scene's FILE:LINE:COLUMN, and no image.
bad_scenes_check() {
    while IFS='|' read -r tap_scene tap_message; do
        printf '%s\n' "$tap_scene" >"$work/bad.pov"
        rm -f "$work/bad.png"
        run "$work/bad.pov" --width 8 --height 6 -o "$work/bad.png"
        check "$tap_message: status 2, FILE:LINE:COLUMN, no image" \
            test "$status $(grep -c "^$work/bad.pov:[0-9]*:[0-9]*: .*$tap_message" "$work/err") $([ -e "$work/bad.png" ] && echo image || echo none)" = "2 1 none"
    done
}
# no_interior STATUS INTERIOR: compare exited 0 and counted 0 interior pixels
no_interior() {
    if [ "$1" = 0 ] && [ "$2" = 0 ]; then return 0; fi
    echo "compare: exit status $1, ${2:-(no count of)} interior pixels"
    return 1
}
# ties_check LABEL A B RMSE_MAX RMSE_MEASURED OFF_MAX OFF_MEASURED: like
# image_check, with the ties of $work/mask-map.exr (mask_check's, for the
# same pair of renderers) left out, by tests/exr-rmse.pl; skipped without
# Perl's Compress::Zlib.
ties_check() {
    if ! perl -MCompress::Zlib -e 1 2>/dev/null; then
        skip "$1 without its tie pixels" "perl with Compress::Zlib not installed (Debian package perl)"
        return
    fi
    if ! perl "$srcdir/tests/exr-rmse.pl" "$2" "$3" "$work/mask-map.exr" >"$work/ties" 2>&1; then
        not_ok "$1 without its tie pixels: tests/exr-rmse.pl reads the images"
        sed 's/^/# /' "$work/ties"
        return
    fi
    read -r _ tap_rmse _ tap_pixels _ tap_ties _ tap_off <"$work/ties"
    check "$1 without its $tap_ties tie pixels: RMSE $tap_rmse <= $4 (measured $5)" within "$tap_rmse" "$4"
    check "$1 without its $tap_ties tie pixels: $tap_off of $tap_pixels pixels off by more than 0.02 <= $6 (measured $7)" \
        within "$tap_off" "$6"
}

# need_povray: sets povray to the program $POVRAY names; without one (empty,
# or not installed) the whole script is skipped, as TAP says it.
need_povray() {
    povray=""
    if [ -n "${POVRAY:-}" ]; then povray=$(command -v "$POVRAY" 2>/dev/null || true); fi
    if [ -z "$povray" ]; then
        echo "1..0 # SKIP povray is not installed: nothing to compare with"
        exit 0
    fi
}

# tap_work NAME: $work, a temporary folder removed when the script ends.
tap_work() {
    work=$(mktemp -d "${TMPDIR:-/tmp}/$1.XXXXXX") || bail "cannot make a temporary folder"
    trap 'rm -rf "$work"' EXIT
    trap 'exit 1' HUP INT PIPE TERM
}
