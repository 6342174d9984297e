#!/usr/bin/env bash
# POV-Ray with its renders remembered, for `make mutation`: every mutant
# runs the same suite, and so the same POV-Ray renders, of which only
# hstrace's side changes. Called as POV-Ray is (+Iscene +Oout ...), it
# answers from its memory when it has rendered the same arguments for the
# same scene before (the +I file and every .pov, .inc and .ini file beside
# it, byte for byte), else runs POV-Ray and remembers the image, the output
# and the exit status. A call without +I or +O is passed straight on.
#
# Environment: POVRAY_MEMO_REAL (the real povray; default: povray in PATH),
# POVRAY_MEMO_DIR (the memory; default ${TMPDIR:-/tmp}/povray-memo).
set -u -o pipefail
real=${POVRAY_MEMO_REAL:-$(command -v povray)}
memo=${POVRAY_MEMO_DIR:-${TMPDIR:-/tmp}/povray-memo}
[ -n "$real" ] || { echo "povray-memo: no povray to run" >&2; exit 127; }

input="" output=""
key_args=()
for a in "$@"; do
    case $a in
    +I*) input=${a#+I}; key_args+=("$a") ;;
    +O*) output=${a#+O}; key_args+=("+O.${output##*.}") ;; # the name's extension only
    *) key_args+=("$a") ;;
    esac
done
if [ -z "$input" ] || [ -z "$output" ] || [ ! -f "$input" ]; then
    exec "$real" "$@"
fi

dir=$(dirname "$input")
key=$({
    printf '%s\n' "${key_args[@]}"
    for f in "$input" "$dir"/*.pov "$dir"/*.inc "$dir"/*.ini; do
        [ -f "$f" ] && { printf '%s\n' "${f##*/}"; cat "$f"; }
    done
} | sha256sum | cut -c1-32)
entry=$memo/$key

if [ -f "$entry/status" ]; then
    [ -f "$entry/image" ] && cp "$entry/image" "$output"
    cat "$entry/stdout"
    cat "$entry/stderr" >&2
    exit "$(cat "$entry/status")"
fi

mkdir -p "$memo" || exit 1
tmp=$(mktemp -d "$memo/new.XXXXXX") || exit 1
"$real" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
status=$?
[ -f "$output" ] && cp "$output" "$tmp/image"
echo "$status" >"$tmp/status"
# Another render of the same may have finished first: either is the answer.
mv -T "$tmp" "$entry" 2>/dev/null || rm -rf "$tmp"
cat "$tmp/stdout" 2>/dev/null || cat "$entry/stdout"
cat "$tmp/stderr" 2>/dev/null >&2 || cat "$entry/stderr" >&2
exit "$status"
