#!/bin/sh
# Every documented option has a test that would notice it broken, in TAP.
#
# The options are read from where a user reads them: the option tables and
# the POV-Ray switches of `hstrace --help`, `hstrace compare --help`,
# `hstrace vs-povray --help` (with vs-povray's paragraph on the render
# options it passes on or refuses) and `hstrace stitch --help`, and the same
# parts of man/hstrace.1 (SYNOPSIS, OPTIONS and its POV-Ray switches,
# COMPARE, VS-POVRAY, STITCH). For each
# option, per command:
#   - it is in both --help and the man page (a disagreement is a failure,
#     or a TODO while tests/options.map records it with `help-lacks:` or
#     `man-lacks:` and the reason; a TODO that passes is an XPASS, which
#     fails the suite, so a fixed disagreement has its entry removed);
#   - tests/options.map names at least one test file and check for it, and
#     every entry holds: the file exists, contains the check's description
#     (a literal part of it) and uses the option itself.
# And POV-Ray 3.7's INI keys and switches: the man page's POV-RAY OPTIONS
# lists the same, with the same verdicts, as the options' table
# (`hstrace --povray-options`), no more and no fewer.
# Entries for options documented nowhere are failures too (stale entries).
#
# Environment: top_srcdir, top_builddir (default .).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
man="$srcdir/man/hstrace.1"
map="$srcdir/tests/options.map"
work=$(mktemp -d "${TMPDIR:-/tmp}/hstoptcov.XXXXXX") || { echo "Bail out! no temporary folder"; exit 1; }
trap 'rm -rf "$work"' EXIT
trap 'exit 1' HUP INT PIPE TERM
[ -x "$hstrace" ] || { echo "Bail out! $hstrace is not built"; exit 1; }
[ -f "$man" ] || { echo "Bail out! $man is missing"; exit 1; }
[ -f "$map" ] || { echo "Bail out! $map is missing"; exit 1; }

n=0
# check DESCRIPTION COMMAND [ARG...]: runs the command; ok when it exits 0.
check() {
    n=$((n + 1)); d=$1; shift
    if "$@"; then echo "ok $n - $d"; else echo "not ok $n - $d"; fi
}
# todo DESCRIPTION REASON COMMAND [ARG...]: the same, as a TAP TODO item.
todo() {
    n=$((n + 1)); d=$1; r=$2; shift 2
    if "$@"; then echo "ok $n - $d # TODO $r"; else echo "not ok $n - $d # TODO $r"; fi
}

# The tokens of a line that are options: --long, -x, and POV-Ray's +X/-X
# switches (the upper-case letters; "+WTn" is +WT, "+Ldir" is +L). Shared by
# both extractions. In an option table (`table` set) a line is read from its
# start: options (alternatives a|b and NAME=VALUE forms split), then their
# values (upper-case names, a|b choices), and the description ends it.
awk_tokens='
function emit(tok) {
    sub(/^[\[(]+/, "", tok); sub(/[\].,;:)]+$/, "", tok)
    if (match(tok, /^[+-][A-Z]+/)) { print cmd, substr(tok, 1, RLENGTH); return }
    if (tok ~ /^--[a-z0-9][a-z0-9-]*$/ || tok ~ /^-[a-z]$/) print cmd, tok
}
function all_tokens(line,   t, k, i) {
    gsub(/[,\/()|;="\[\]]/, " ", line)
    k = split(line, t, /[ \t]+/)
    for (i = 1; i <= k; i++) if (t[i] != "") emit(t[i])
}
function table_line(line,   t, k, i, p, np, j, q) {
    k = split(line, t, /[ \t]+/)
    for (i = 1; i <= k; i++) {
        if (t[i] == "") continue
        if (t[i] ~ /^[-+][-+]?[A-Za-z0-9]/) {
            np = split(t[i], p, "|")
            for (j = 1; j <= np; j++) { q = p[j]; sub(/=.*/, "", q); emit(q) }
        } else if (t[i] !~ /^[A-Z][A-Z0-9_]*$/ && t[i] !~ /[|=]/) {
            break
        }
    }
}'

# help_tokens CMD FILE: "CMD OPTION" for each option in FILE, a --help text.
help_tokens() {
    awk -v cmd="$1" "$awk_tokens"'
        /^POV-Ray switches:/ || /^Render options are those of/ { para = 1 }
        /^[ \t]*$/ { para = 0 }
        para { all_tokens($0); next }
        /^ +[-+]/ && match($0, /[^ ]/) <= 9 { table_line($0) }' "$2" | awk '!seen[$0]++'
}

# help_options CMD: the options of CMD's --help, in order.
help_options() {
    if [ "$1" = hstrace ]; then "$hstrace" --help; else "$hstrace" "$1" --help; fi >"$work/help.$1" 2>&1 ||
        echo "# $1 --help failed: $(head -1 "$work/help.$1")" >&2
    help_tokens "$1" "$work/help.$1"
}

# man_options FILE: "CMD OPTION" for each option the man page FILE documents: the tags
# of .TP entries in OPTIONS (hstrace), COMPARE, VS-POVRAY and STITCH, every switch in
# SYNOPSIS and "POV-Ray switches", and vs-povray's render-option paragraph.
man_options() {
    awk "$awk_tokens"'
        {
            line = $0
            gsub(/\\-/, "-", line); gsub(/\\f\(../, " ", line); gsub(/\\f./, " ", line)
            gsub(/\\\(../, " ", line); gsub(/\\[~&]/, " ", line)
            tag = prev == ".TP"; prev = $1
            if ($1 == ".SH") { sec = $2; sub_ = ""; para = 0; cmd = "hstrace" }
            if ($1 == ".SS") { sub_ = $0; sub(/^\.SS +/, "", sub_); para = 0 }
            sub(/^\.[A-Za-z]+[ \t]*/, "", line)
        }
        sec == "SYNOPSIS" {
            if (line ~ /^hstrace compare/) cmd = "compare"
            else if (line ~ /^hstrace vs-povray/) cmd = "vs-povray"
            else if (line ~ /^hstrace stitch/) cmd = "stitch"
            else if (line ~ /^mpirun/) next  # mpirun -n N: an option of mpirun
            else all_tokens(line)
            next
        }
        sec == "OPTIONS" && sub_ == "POV-Ray switches" { cmd = "hstrace"; all_tokens(line); next }
        sec == "OPTIONS" && tag { cmd = "hstrace"; all_tokens(line); next }
        sec == "COMPARE" && tag { cmd = "compare"; all_tokens(line); next }
        sec == "STITCH" && tag { cmd = "stitch"; all_tokens(line); next }
        sec == "VS-POVRAY" {
            cmd = "vs-povray"
            if (line ~ /^Render options are those of/) para = 1
            if (para || tag) all_tokens(line)
        }' "$1" | awk '!seen[$0]++'
}

: >"$work/help"
for c in hstrace compare vs-povray stitch; do help_options "$c" >>"$work/help"; done
man_options "$man" >"$work/man"
# The union, in the order of first appearance (help first), without repeats.
cat "$work/help" "$work/man" | awk '!seen[$0]++' >"$work/all"

count() { grep -c "^$1 " "$2" || true; }
# at_least FILE HSTRACE COMPARE VS-POVRAY: FILE lists at least that many
# options of each command.
at_least() {
    [ "$(count hstrace "$1")" -ge "$2" ] && [ "$(count compare "$1")" -ge "$3" ] && [ "$(count vs-povray "$1")" -ge "$4" ]
}
has() { grep -qx -- "$1" "$2"; }
both() { has "$1" "$work/help" && has "$1" "$work/man"; }
anchors() {
    for o in "hstrace -o" "hstrace --grid" "hstrace +WT" "hstrace +L" "compare --mask-a" "compare --max-interior" \
             "vs-povray --include-path" "vs-povray +L" "stitch -o"; do
        both "$o" || { echo "# $o not found in both"; return 1; }
    done
}
# The extraction on made-up texts with every form it must read.
cat >"$work/help.sample" <<'HELP'
usage: x [options]
      --alpha|--beta N   an alternative, and an option named in the text: --gamma
  -x, --long-name=VALUE  a NAME=VALUE form
      --choice a|b|c  a choice of values, then --not-this
      --two A3 A4        two values
                         --continuation (a wrapped description, not an option)
POV-Ray switches: +Wn +FN16 -V (+Q, and +Ldir).

Other text: --not-this-either
HELP
cat >"$work/man.sample" <<'MAN'
.SH SYNOPSIS
.RB [ +I\fISCENE.pov ]
.SH OPTIONS
.TP
.BR \-\-alpha " | " \-\-beta " \fIN\fR"
.TP
.BI \-\-name= VALUE
Text naming \-\-not\-this.
.TP
.B hst
.SS POV-Ray switches
.BI +WT n
and
.BR \-A ,
.SH COMPARE
.TP
.BI \-\-threshold " T"
.SH VS-POVRAY
Text naming \-\-not\-this.
.PP
Render options are those of
.BR \-\-width ", " +L
.SS Exit status
.TP
.B 0
\-\-not\-this
MAN
sample_help() {
    [ "$(help_tokens x "$work/help.sample" | tr '\n' ' ')" = "x --alpha x --beta x -x x --long-name x --choice x --two x +W x +FN x -V x +Q x +L " ]
}
sample_man() {
    [ "$(man_options "$work/man.sample" | tr '\n' ' ')" = "hstrace +I hstrace --alpha hstrace --beta hstrace --name hstrace +WT hstrace -A compare --threshold vs-povray --width vs-povray +L " ]
}
check "extraction from a made-up --help: option tables (a|b, NAME=VALUE, -x, values) and POV-Ray switches, not the descriptions" sample_help
check "extraction from a made-up man page: SYNOPSIS, .TP tags per section, POV-Ray switches, vs-povray's render options" sample_man

# The extraction itself: what it must find, so that a reworded help or man
# page cannot make it silently find nothing.
check "--help: $(count hstrace "$work/help") hstrace, $(count compare "$work/help") compare and $(count vs-povray "$work/help") vs-povray options found" \
    at_least "$work/help" 30 14 10
check "man page: $(count hstrace "$work/man") hstrace, $(count compare "$work/man") compare and $(count vs-povray "$work/man") vs-povray options found" \
    at_least "$work/man" 30 14 10
check "both read options with values, alternatives, POV-Ray switches and vs-povray's render options (hstrace -o, --grid, +WT, +L; compare --mask-a, --max-interior; vs-povray --include-path, +L; stitch -o)" \
    anchors

# The map, without comments and blank lines: COMMAND OPTION REST.
grep -v -e '^[[:space:]]*#' -e '^[[:space:]]*$' "$map" >"$work/map"

# entry_ok REST OPTION: REST is "FILE: CHECK"; the file exists, holds the
# check's text and uses the option (not as part of a longer name).
entry_ok() {
    file=${1%%: *} text=${1#*: }
    if [ "$file" = "$1" ] || [ -z "$text" ]; then why="'$1' is not 'FILE: CHECK'"; return 1; fi
    [ -f "$srcdir/$file" ] || { why="$file does not exist"; return 1; }
    grep -qF -- "$text" "$srcdir/$file" || { why="$file has no check '$text'"; return 1; }
    case $2 in
        +*) re="(^|[^A-Za-z0-9_])\\$2(\$|[^A-Z])" ;;
        *) re="(^|[^A-Za-z0-9_-])$2(\$|[^A-Za-z0-9-])" ;;
    esac
    grep -qE -- "$re" "$srcdir/$file" || { why="$file does not use $2"; return 1; }
}

# covered COMMAND OPTION: every entry for it holds, and there is at least one.
covered() {
    found=0 bad=0
    while read -r c o rest; do
        if [ "$c" != "$1" ] || [ "$o" != "$2" ]; then continue; fi
        case $rest in help-lacks:* | man-lacks:*) continue ;; esac
        found=$((found + 1))
        if ! entry_ok "$rest" "$o"; then
            echo "# $c $o: $why"
            bad=1
        fi
    done <"$work/map"
    [ $found -gt 0 ] || echo "# $1 $2: no entry in tests/options.map"
    [ $found -gt 0 ] && [ $bad -eq 0 ]
}
mapped() { covered "$@" >"$work/why"; s=$?; cat "$work/why"; return $s; }

# known COMMAND OPTION KIND: the reason the map gives for a disagreement.
known() {
    awk -v c="$1" -v o="$2" -v k="$3:" '$1 == c && $2 == o && $3 == k {
        sub(/^[^ \t]+[ \t]+[^ \t]+[ \t]+[^ \t]+[ \t]*/, ""); print; exit }' "$work/map"
}

while read -r c o; do
    reason=""
    if ! has "$c $o" "$work/help"; then where="in the man page, not in $c --help" kind=help-lacks
    elif ! has "$c $o" "$work/man"; then where="in $c --help, not in the man page" kind=man-lacks
    else where="in $c --help and in the man page" kind=""
    fi
    [ -n "$kind" ] && reason=$(known "$c" "$o" "$kind")
    for k in help-lacks man-lacks; do
        # a disagreement recorded, for an option documented in both: TODO that passes
        [ -z "$kind" ] && [ -n "$(known "$c" "$o" $k)" ] && reason="$(known "$c" "$o" $k) (recorded as $k: remove the entry)"
    done
    if [ -n "$reason" ]; then
        todo "$c $o: $where" "$reason" test -z "$kind"
    else
        check "$c $o: $where" test -z "$kind"
    fi
    entries=$(awk -v c="$c" -v o="$o" '$1 == c && $2 == o && $3 !~ /^(help|man)-lacks:$/ { k++ } END { print k + 0 }' "$work/map")
    check "$c $o: mapped to $entries check(s) in tests/options.map that would notice it broken" mapped "$c" "$o"
done <"$work/all"

# --- POV-Ray's keys and switches: the man page against the options' table ---
# The man page's POV-RAY OPTIONS lists every INI key and switch of POV-Ray
# 3.7 with hstrace's verdict; `hstrace --povray-options` prints the table's
# (src/options/options_table.c). A row of the table missing from the man
# page, an entry of the man page that is no row, or another verdict, fails.
# Each as "KEY SWITCH VERDICT" ("-" for none; refused-when-on).
man_povray() {
    awk '
        $1 == ".SH" { sec = $0; tag = 0; next }
        sec != ".SH POV-RAY OPTIONS" { next }
        $1 == ".TP" { tag = 1; next }
        tag == 1 {
            line = $0; sub(/^\.B[RI]* +/, "", line); gsub(/\\-/, "-", line)
            key = "-"; sw = "-"; n = split(line, t, /[ ,"]+/)
            for (i = 1; i <= n; i++) if (t[i] ~ /^[+]/) sw = t[i]; else if (t[i] ~ /^[A-Z]/) key = t[i]
            tag = 2; next
        }
        tag == 2 {
            v = $1; sub(/[:.]$/, "", v); if (v == "refused" && $2 == "when") v = "refused-when-on"
            print key, sw, v; tag = 0
        }' "$1" | sort
}
listed_povray() {
    "$hstrace" --povray-options | awk '{ v = $3; sub(/:$/, "", v); if ($3 == "refused" && $4 == "when") v = "refused-when-on"
        print $1, $2, v }' | sort
}
cat >"$work/povray.sample" <<'MAN'
.SH OPTIONS
.TP
.B Not_This +NT
honoured: another section.
.SH POV-RAY OPTIONS
Text.
.TP
.B Some_Key +SK
honoured: text.
.TP
.B Key_Alone
refused when on: field rendering.
.TP
.B Other +O
ignored: why.
.SH COMPARE
MAN
check "extraction of POV-RAY OPTIONS from a made-up man page: keys, switches, verdicts, that section only" \
    test "$(man_povray "$work/povray.sample" | tr '\n' ' ')" = "Key_Alone - refused-when-on Other +O ignored Some_Key +SK honoured "
man_povray "$man" >"$work/man.povray"
listed_povray >"$work/listed.povray"
check "the man page's POV-RAY OPTIONS: $(grep -c . "$work/man.povray") keys and switches found (at least 100)" \
    test "$(grep -c . "$work/man.povray")" -ge 100
check "--povray-options: $(grep -c . "$work/listed.povray") keys and switches (at least 100)" \
    test "$(grep -c . "$work/listed.povray")" -ge 100
# by name: KEY SWITCH
awk '{ print $1, $2 }' "$work/man.povray" >"$work/man.names"
awk '{ print $1, $2 }' "$work/listed.povray" >"$work/listed.names"
missing=$(comm -23 "$work/listed.names" "$work/man.names" | tr '\n' ';')
extra=$(comm -13 "$work/listed.names" "$work/man.names" | tr '\n' ';')
check "every row of the options' table (--povray-options) is in the man page's POV-RAY OPTIONS${missing:+ (missing: $missing)}" \
    test -z "$missing"
check "every entry of the man page's POV-RAY OPTIONS is a row of the table${extra:+ (not rows: $extra)}" test -z "$extra"
other=$(comm -3 "$work/listed.povray" "$work/man.povray" | awk 'NF' | tr -s ' \t' ' ' | tr '\n' ';')
check "the man page's POV-RAY OPTIONS lists what --povray-options lists, each with its verdict${other:+ (differ: $other)}" \
    test -z "$other"

# Entries for options that are documented nowhere.
while read -r c o rest; do
    grep -qx -- "$c $o" "$work/all" && continue
    n=$((n + 1)); echo "not ok $n - tests/options.map: $c $o is documented nowhere (a stale entry: $rest)"
done <"$work/map"
echo "1..$n"
