#!/usr/bin/env bash
# Mutation testing: does the suite notice small planted bugs?
#
# Every tests/mutations/NN-name.patch is one small bug (a unified diff for
# `patch -p1` from the top of the tree; the text before its first '---'
# says what it breaks, a "Survives:" line why it may go unnoticed). Each is
# applied in a temporary copy of the source tree (the tracked files as they
# stand in the working tree; the real tree is never touched), the copy is
# built (an out-of-tree build configured once per copy, so a mutant
# recompiles only what it touches) and the whole suite runs (`make check`).
# A mutant is caught when a test fails (FAIL, ERROR, or a TODO that passes:
# XPASS), or when the copy no longer builds ("caught by the compiler");
# it survives when the suite passes. A patch that no longer applies is
# "stale", a suite that outlives the timeout is a "timeout": neither counts
# as caught. tests/MUTATION.md gets the score, a table of mutants and the
# checks that caught them, and the survivors with the reasons in their
# patches.
#
# Results are cached per mutant, keyed by the patch's diff, the tree's
# tracked files and the configure flags, so an interrupted run resumes and
# a rerun only runs what changed. Not part of `make check` (an hour or more).
#
# Usage: tests/mutation.sh [BUILDDIR]   (or `make mutation` in a build)
#   BUILDDIR: a configured build of this tree (default .): its configure
#   flags are reused and the cache lives in it.
# Environment:
#   MUTANTS='03 17'        only these (numbers or names); the report still lists all
#   MUTATION_JOBS=N        N copies at once (default 1)
#   MUTATION_FRESH=1       ignore cached results (they are rewritten)
#   MUTATION_TIMEOUT=S     seconds allowed for one build or one suite run (default 1200)
#   MUTATION_MAKEFLAGS     flags for make in a copy (default -j2)
#   MUTATION_CONFIGURE     configure arguments for the copies (default: BUILDDIR's, else --enable-werror)
#   MUTATION_CACHE=DIR     the results cache (default BUILDDIR/mutation.cache)
#   MUTATION_REPORT=FILE   the report (default tests/MUTATION.md in the source tree)
#   MUTATION_POVRAY_MEMO=0 run POV-Ray for every mutant (default: each render once, tests/povray-memo.sh)
set -u -o pipefail

cache_version=1
here=$(cd "$(dirname "$0")" && pwd) || exit 2
srcdir=$(cd "$here/.." && pwd) || exit 2
builddir=$(cd "${1:-.}" && pwd) || { echo "mutation: no build folder '${1:-.}'" >&2; exit 2; }
jobs=${MUTATION_JOBS:-1}
timeout_s=${MUTATION_TIMEOUT:-1200}
read -r -a makeflags <<<"${MUTATION_MAKEFLAGS:--j2}"
cache=${MUTATION_CACHE:-$builddir/mutation.cache}
report=${MUTATION_REPORT:-$srcdir/tests/MUTATION.md}
tmp=${TMPDIR:-/tmp}
# The copies run their own make: nothing of a calling make's jobserver.
unset MAKEFLAGS MFLAGS MAKELEVEL GNUMAKEFLAGS

die() { echo "mutation: $*" >&2; exit 2; }
say() { printf '%s mutation: %s\n' "$(date +%H:%M:%S)" "$*"; }

case $jobs in '' | *[!0-9]* | 0) die "MUTATION_JOBS must be a positive number, not '$jobs'" ;; esac
case $timeout_s in '' | *[!0-9]* | 0) die "MUTATION_TIMEOUT must be a positive number of seconds" ;; esac
for tool in git patch tar sha256sum timeout autoreconf; do
    command -v "$tool" >/dev/null 2>&1 || die "needs $tool"
done
git -C "$srcdir" rev-parse --is-inside-work-tree >/dev/null 2>&1 ||
    die "needs the git work tree of the sources (the copies are made of its tracked files)"

# ---- what runs -------------------------------------------------------------

all_patches=()
for p in "$srcdir"/tests/mutations/[0-9][0-9]-*.patch; do
    [ -f "$p" ] && all_patches+=("$p")
done
[ ${#all_patches[@]} -gt 0 ] || die "no patches in tests/mutations"

mutant_id() { basename "$1" .patch; }
selected() { # patch: is it in $MUTANTS (numbers or names)?
    local id want
    id=$(mutant_id "$1")
    [ -z "${MUTANTS:-}" ] && return 0
    for want in $MUTANTS; do
        case $id in "$want" | "$want"-* | [0-9][0-9]-"$want") return 0 ;; esac
    done
    return 1
}
patches=()
for p in "${all_patches[@]}"; do
    selected "$p" && patches+=("$p")
done
[ ${#patches[@]} -gt 0 ] || die "MUTANTS='${MUTANTS:-}' names no patch in tests/mutations"

# The copies' configure arguments: the calling build's, as it was configured.
configure_args=()
if [ -n "${MUTATION_CONFIGURE+set}" ]; then
    read -r -a configure_args <<<"$MUTATION_CONFIGURE"
elif [ -x "$builddir/config.status" ]; then
    eval "configure_args=($("$builddir/config.status" --config))" || die "cannot read $builddir/config.status"
else
    configure_args=(--enable-werror)
fi
# POV-Ray's renders are the same for every mutant: the copies call it
# through tests/povray-memo.sh, which renders each scene once for the whole
# run (MUTATION_POVRAY_MEMO=0: POV-Ray itself every time).
if [ "${MUTATION_POVRAY_MEMO:-1}" = 1 ] && command -v povray >/dev/null 2>&1; then
    POVRAY_MEMO_REAL=$(command -v povray)
    POVRAY_MEMO_DIR=$cache/povray-memo
    export POVRAY_MEMO_REAL POVRAY_MEMO_DIR
    configure_args+=("POVRAY=$srcdir/tests/povray-memo.sh")
fi

# The tracked files as they stand (deleted ones left out).
tracked_files() {
    git -C "$srcdir" ls-files -z | while IFS= read -r -d '' f; do
        if [ -e "$srcdir/$f" ] || [ -L "$srcdir/$f" ]; then printf '%s\0' "$f"; fi
    done
}
# What a result depends on: every tracked file but the mutation machinery
# and its report (a new patch or a reworded header changes no other result).
tree_hash() {
    tracked_files | while IFS= read -r -d '' f; do
        case $f in tests/MUTATION.md | tests/mutation.sh | tests/mutations/*) continue ;; esac
        printf '%s ' "$f"
        sha256sum <"$srcdir/$f" | cut -c1-64
    done | sha256sum | cut -c1-16
}
# A patch's diff (from its first '--- ' line), without the header comment.
patch_body() { sed -n '/^--- /,$p' "$1"; }
patch_header() { sed -n '/^--- /q;p' "$1"; }
patch_key() { # patch
    { echo "v$cache_version"; echo "$tree"; printf '%s\n' "${configure_args[@]}"; patch_body "$1"; } |
        sha256sum | cut -c1-16
}
patch_files() { # the files a patch touches (p1), one a line
    sed -n -e 's|^--- a/\([^[:space:]]*\).*|\1|p' -e 's|^+++ b/\([^[:space:]]*\).*|\1|p' "$1" | sort -u
}

tree=$(tree_hash) || die "cannot hash the tree"
mkdir -p "$cache" || die "cannot make the cache $cache"
result_file() { echo "$cache/$(mutant_id "$1").$(patch_key "$1").result"; }

exec 9>"$cache/lock"
if command -v flock >/dev/null 2>&1 && ! flock -n 9; then
    die "another mutation run holds $cache/lock"
fi

# ---- a copy to mutate --------------------------------------------------------

# run_timed DIR LOG COMMAND...: COMMAND in DIR under the timeout, its output
# in LOG. In the background, waited for, so that a signal to this shell can
# stop it (timeout passes the signal on to everything it started).
child=""
run_timed() {
    local dir=$1 log=$2
    shift 2
    (cd "$dir" && exec timeout -k 60 "$timeout_s" "$@") >"$log" 2>&1 &
    child=$!
    wait "$child"
}

# Masks the copies' and temporary folders' names in anything reported.
scrub() {
    sed -e "s|$tmp/hstmutation\\.[A-Za-z0-9]*/src|<copy>|g" -e "s|$tmp/hstmutation\\.[A-Za-z0-9]*/build|<build>|g" \
        -e "s|$tmp/[A-Za-z0-9._-]*|<tmp>|g" -e "s|$srcdir|<src>|g" -e "s|$builddir|<build>|g"
}

# make_copy DIR: the tracked files in DIR/src, configured in DIR/build and
# built with the test programs.
make_copy() {
    local dir=$1
    mkdir -p "$dir/src" "$dir/build" "$dir/orig" || return 1
    tracked_files | (cd "$srcdir" && tar --null -T - -cf -) | tar -xf - -C "$dir/src" || return 1
    (cd "$dir/src" && autoreconf -fi) >"$dir/setup.log" 2>&1 || return 1
    (cd "$dir/build" && "$dir/src/configure" "${configure_args[@]}") >>"$dir/setup.log" 2>&1 || return 1
    run_timed "$dir/build" "$dir/build.log" make "${makeflags[@]}" check TESTS=
    local rc=$?
    cat "$dir/build.log" >>"$dir/setup.log"
    return $rc
}

# The test programs and scripts in the order make check lists them.
test_order() { # builddir
    # shellcheck disable=SC2016 # $(TESTS) is make's
    printf 'mutation-print-tests:\n\t@echo $(TESTS)\n' |
        make -s -C "$1" -f Makefile -f - mutation-print-tests 2>/dev/null
}

# run_suite BUILDDIR RESULT: make check; writes status, failing tests and
# the first failing checks to RESULT (key=value lines).
run_suite() {
    local build=$1 out=$2 rc t trs log global nfail lines=0 total=0 failing=""
    local started=$SECONDS
    rm -f "$build"/tests/*.log "$build"/tests/*.trs "$build"/test-suite.log
    run_timed "$build" "$build/check.out" make "${makeflags[@]}" check
    rc=$?
    local first=() order
    read -r -a order <<<"$(test_order "$build")"
    if [ ${#order[@]} -eq 0 ]; then # make could not say: every log there is
        for trs in "$build"/tests/*.trs; do [ -f "$trs" ] && order+=("tests/$(basename "$trs" .trs)"); done
    fi
    for t in "${order[@]}"; do
        # automake's logs drop the .sh of TEST_EXTENSIONS
        trs="$build/${t%.sh}.trs"
        log="${trs%.trs}.log"
        [ -f "$trs" ] || continue
        global=$(sed -n 's/^:global-test-result: //p' "$trs")
        case $global in FAIL | ERROR | XPASS) ;; *) continue ;; esac
        nfail=$(grep -cE '^(FAIL|ERROR|XPASS): ' "$log")
        [ "$nfail" -gt 0 ] || nfail=1
        total=$((total + nfail))
        failing="$failing ${t#tests/}:$nfail"
        while IFS= read -r line && [ $lines -lt 3 ]; do
            first+=("$line")
            lines=$((lines + 1))
        done < <(grep -E '^(FAIL|ERROR|XPASS): ' "$log")
    done
    local status
    if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then
        status=timeout
    elif [ -n "$failing" ]; then
        status=caught
    elif [ $rc -ne 0 ]; then
        status=broken # make check failed, yet no test did: see check.out
    else
        status=survived
    fi
    {
        echo "status=$status"
        echo "seconds=$((SECONDS - started))"
        echo "failing=${failing# }"
        echo "failed_checks=$total"
        for line in "${first[@]}"; do echo "first=$line"; done
        if [ $status = broken ]; then
            tail -n 5 "$build/check.out" | sed 's/^/detail=/'
        fi
        sed -n 's/^# \(TOTAL\|PASS\|SKIP\|XFAIL\|FAIL\|XPASS\|ERROR\): *\([0-9]*\)$/summary_\1=\2/p' "$build/check.out"
    } | scrub >"$out"
}

# run_mutant DIR PATCH: apply, build, run, restore; the result to the cache.
run_mutant() {
    local dir=$1 patch=$2 id f result started=$SECONDS
    id=$(mutant_id "$patch")
    result=$(result_file "$patch")
    local tmpres="$result.part"
    local files
    mapfile -t files < <(patch_files "$patch")
    if ! patch -p1 --dry-run --fuzz=0 -s -d "$dir/src" <"$patch" >"$dir/patch.log" 2>&1; then
        { echo "status=stale"; echo "seconds=0"; sed 's/^/detail=/' "$dir/patch.log"; } | scrub >"$tmpres"
        mv "$tmpres" "$result"
        say "$id: stale (does not apply)"
        return 0
    fi
    rm -rf "$dir/orig" && mkdir -p "$dir/orig"
    for f in "${files[@]}"; do
        if [ -e "$dir/src/$f" ]; then
            mkdir -p "$dir/orig/$(dirname "$f")" && cp -p "$dir/src/$f" "$dir/orig/$f"
        fi
    done
    patch -p1 --fuzz=0 -s --no-backup-if-mismatch -d "$dir/src" <"$patch" >"$dir/patch.log" 2>&1 ||
        { say "$id: patch failed after a dry run that passed"; return 1; }
    run_timed "$dir/build" "$dir/build.log" make "${makeflags[@]}" check TESTS=
    local rc=$?
    if [ $rc -eq 0 ]; then
        run_suite "$dir/build" "$tmpres"
    else
        {
            if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then echo "status=timeout"; else echo "status=compiler"; fi
            grep -m 3 -E 'error|Error' "$dir/build.log" | sed 's/^/first=/'
        } | scrub >"$tmpres"
    fi
    # Back to the pristine copy: the originals' contents with a new time, so
    # that the next build recompiles what this mutant compiled.
    for f in "${files[@]}"; do
        if [ -e "$dir/orig/$f" ]; then
            if ! { cat "$dir/orig/$f" >"$dir/src/$f" && cmp -s "$dir/orig/$f" "$dir/src/$f"; }; then
                say "$id: the copy's $f could not be restored"
                return 1
            fi
        else
            rm -f "$dir/src/$f"
        fi
    done
    { grep -v '^seconds=' "$tmpres"; echo "seconds=$((SECONDS - started))"; } >"$tmpres.s" && rm -f "$tmpres" &&
        mv "$tmpres.s" "$result"
    local status failing
    status=$(sed -n 's/^status=//p' "$result")
    failing=$(sed -n 's/^failing=//p' "$result")
    say "$id: $status${failing:+ by $failing} ($((SECONDS - started)) s)"
}

# ---- the run -----------------------------------------------------------------

todo=()
for p in "${patches[@]}"; do
    if [ -n "${MUTATION_FRESH:-}" ] || [ ! -f "$(result_file "$p")" ]; then todo+=("$p"); fi
done
baseline="$cache/baseline.$(
    {
        echo "v$cache_version"
        echo "$tree"
        printf '%s\n' "${configure_args[@]}"
    } | sha256sum | cut -c1-16
).result"
run_started=$SECONDS
workdirs=()
workers=()
cleanup() {
    local pid d
    [ -n "$child" ] && kill "$child" 2>/dev/null
    for pid in "${workers[@]}"; do kill "$pid" 2>/dev/null; done
    wait 2>/dev/null
    for d in "${workdirs[@]}"; do rm -rf "$d"; done
}
trap cleanup EXIT
trap 'exit 130' INT TERM HUP

if [ ${#todo[@]} -gt 0 ] || [ -n "${MUTATION_FRESH:-}" ] || [ ! -f "$baseline" ]; then
    [ "$jobs" -le ${#todo[@]} ] || jobs=${#todo[@]}
    [ "$jobs" -ge 1 ] || jobs=1
    say "${#todo[@]} of ${#patches[@]} mutants to run, $jobs at a time (tree $tree, configure ${configure_args[*]:-(none)})" | scrub
    for ((k = 0; k < jobs; k++)); do
        d=$(mktemp -d "$tmp/hstmutation.XXXXXX") || die "no temporary folder"
        workdirs+=("$d")
    done
    say "building a copy of the tree"
    make_copy "${workdirs[0]}" || { scrub <"${workdirs[0]}/setup.log" | tail -n 20 >&2; die "the unmutated copy does not build"; }
    if [ -n "${MUTATION_FRESH:-}" ] || [ ! -f "$baseline" ]; then
        say "the suite on the unmutated copy (the baseline)"
        run_suite "${workdirs[0]}/build" "$baseline.part"
        mv "$baseline.part" "$baseline"
    fi
    if ! grep -qx 'status=survived' "$baseline"; then
        sed 's/^/  /' "$baseline" >&2
        rm -f "$baseline"
        die "the unmutated tree does not pass its own suite: fix that first"
    fi
    say "baseline passes ($(sed -n 's/^seconds=//p' "$baseline") s)"
    for ((k = 0; k < jobs; k++)); do
        (
            trap - EXIT
            trap '[ -n "$child" ] && kill "$child" 2>/dev/null; exit 143' TERM
            if [ "$k" -gt 0 ]; then
                make_copy "${workdirs[$k]}" || { say "copy $k does not build"; exit 1; }
            fi
            for ((i = k; i < ${#todo[@]}; i += jobs)); do
                run_mutant "${workdirs[$k]}" "${todo[$i]}" || exit 1
            done
        ) &
        workers+=("$!")
    done
    failed=0
    for pid in "${workers[@]}"; do wait "$pid" || failed=1; done
    workers=()
    [ $failed = 0 ] || die "a copy failed (see above); finished results are kept in the cache"
fi
run_seconds=$((SECONDS - run_started))

# ---- the report --------------------------------------------------------------

field() { sed -n "s/^$2=//p" "$1" | head -n 1; }
md() { sed -e 's/|/\\|/g' -e 's/^\(.\{180\}\).*/\1.../'; }

total=0 caught=0 by_test=0 by_compiler=0 survived=0 stale=0 timeouts=0 broken=0 notrun=0 sum_seconds=0
rows=""
survivors=""
for p in "${all_patches[@]}"; do
    id=$(mutant_id "$p")
    what=$(patch_header "$p" | sed -n 's/^Breaks: //p' | head -n 1)
    why=$(patch_header "$p" | sed -n 's/^Survives: //p' | head -n 1)
    r=$(result_file "$p")
    if [ ! -f "$r" ]; then
        notrun=$((notrun + 1))
        rows+="| $id | not run | |"$'\n'
        continue
    fi
    status=$(field "$r" status)
    seconds=$(field "$r" seconds)
    sum_seconds=$((sum_seconds + ${seconds:-0}))
    check=$(field "$r" first | md)
    by=""
    case $status in
        caught)
            total=$((total + 1)) caught=$((caught + 1)) by_test=$((by_test + 1))
            by=$(field "$r" failing | sed -e 's/:\([0-9]*\)/ (\1)/g' -e 's/) /), /g')
            ;;
        compiler)
            total=$((total + 1)) caught=$((caught + 1)) by_compiler=$((by_compiler + 1))
            by="the compiler"
            ;;
        survived)
            total=$((total + 1)) survived=$((survived + 1))
            by="**survived**"
            survivors+="- **$id**: $what"$'\n'"  "
            if [ -n "$why" ]; then survivors+="Why it survives: $why"; else survivors+="Why it survives: not analysed yet (add a 'Survives:' line to the patch's header)."; fi
            survivors+=$'\n'
            ;;
        timeout)
            total=$((total + 1)) timeouts=$((timeouts + 1))
            by="timed out (not counted as caught)"
            ;;
        broken)
            total=$((total + 1)) broken=$((broken + 1))
            by="make check failed with no failing test (not counted as caught)"
            check=$(field "$r" detail | md)
            ;;
        stale)
            stale=$((stale + 1))
            by="stale: the patch no longer applies"
            ;;
    esac
    rows+="| $id | $by | ${check:-} |"$'\n'
done
score="n/a"
[ $total -gt 0 ] && score=$(awk -v c=$caught -v t=$total 'BEGIN { printf "%.1f%%", 100 * c / t }')

commit=$(git -C "$srcdir" rev-parse --short HEAD)
dirty=""
[ -n "$(git -C "$srcdir" status --porcelain --untracked-files=no -- . ':!tests/MUTATION.md')" ] &&
    dirty=" (with uncommitted changes to tracked files)"
base_total=$(field "$baseline" summary_TOTAL)
base_skip=$(field "$baseline" summary_SKIP)
base_xfail=$(field "$baseline" summary_XFAIL)
base_seconds=$(field "$baseline" seconds)
cmd="make mutation"
[ -n "${MUTANTS:-}" ] && cmd="make mutation MUTANTS='$MUTANTS'"
per=0
[ $((total + stale)) -gt 0 ] && per=$((sum_seconds / (total + stale)))
{
    echo "# Mutation testing"
    echo
    echo "Written by \`tests/mutation.sh\` (\`$cmd\`) on $(date -u +%Y-%m-%d), for commit $commit$dirty;"
    echo "tree hash $tree, copies configured with \`${configure_args[*]:-(no arguments)}\`. Each mutant in"
    echo "\`tests/mutations/\` is applied to a temporary copy of the tree, built, and the whole suite run"
    echo "(\`make ${makeflags[*]} check\`, at most $timeout_s s). Caught means a test failed (FAIL, ERROR, or a"
    echo "TODO test that passed) or the copy did not build; a timeout, a stale patch or a suite that failed"
    echo "without a failing test is not counted as caught."
    echo
    echo "**Score: $caught / $total caught ($score)**: $by_test by a failing test, $by_compiler by the compiler;"
    echo "$survived survived, $timeouts timed out, $broken broken, $stale stale, $notrun not run."
    echo
    echo "The unmutated tree passes its suite: ${base_total:-?} checks, ${base_skip:-0} skipped, ${base_xfail:-0} expected"
    echo "failures (TODO), in ${base_seconds:-?} s. A mutant takes ${per} s on average here (a rebuild of what it"
    echo "touches and the suite): about $(((sum_seconds + 59) / 60)) min for all $((total + stale)) run, one copy at a time."
    echo
    echo "| mutant | caught by (failed checks) | first failing check |"
    echo "|---|---|---|"
    printf '%s' "$rows"
    echo
    echo "## Survivors"
    echo
    if [ -n "$survivors" ]; then printf '%s' "$survivors"; else echo "None."; fi
    echo
    echo "## Re-running"
    echo
    echo "\`make mutation\` (from a configured build) reruns the mutants whose patch, tree or configure flags"
    echo "changed since their cached result; \`MUTANTS='03 17'\` runs a subset, \`MUTATION_FRESH=1\` ignores the"
    echo "cache, \`MUTATION_JOBS=2\` runs two copies at once. Re-run it when the code the mutants touch changes,"
    echo "and add a mutant for each bug the suite once missed."
} | scrub >"$report.part" && mv "$report.part" "$report"
say "$caught / $total caught ($score); $survived survived, $timeouts timed out, $stale stale, $notrun not run; report in $(basename "$report") (this run: $run_seconds s)"
