#!/usr/bin/env bash
# Mutation testing of the lines a change touches (docs/mutation.md).
#
#   scripts/mutants-in-diff.sh [--install] [--in-place] [--list] [BASE]
#   scripts/mutants-in-diff.sh --record [COMMIT]
#
# Diffs HEAD against BASE and runs `cargo mutants --in-diff` on the changed Rust files of the
# core and the film, one file at a time, the files with the most added or changed lines first,
# each against the tests scripts/mutants-modules.txt names for it (a file not listed there: the
# lib tests under its module path, or all of its package's lib tests when none match). Missed
# mutants that scripts/mutants-equivalent.txt names (each entry one mutant, by position or, where
# the code moved, by its line's text) are forgiven; any other missed mutant fails the script.
#
# A changed file whose row in docs/mutation.md was measured at a commit where the file already
# read as it does at HEAD is covered by that row: every one of its mutants was run then, against
# the same tests, so the stage spends its time box on the other files. A large change therefore
# lands by re-measuring its modules' rows (scripts/mutants.sh) before it is submitted.
#
# BASE defaults to the commit .ci/last-tested names, the last commit CI passed on, so every
# commit since, not only the last one, is tested. When HEAD has no such file, or it names a
# commit that is not in the clone or not an ancestor of HEAD, the script says so and falls back
# to `git merge-base HEAD origin/main`, or, when that is HEAD itself (a clone of main), to
# HEAD's first parent (the change that landed last).
#
#   --record    write COMMIT (default HEAD) into .ci/last-tested, after .ci/run passed on it;
#               commit the file (its commit changes no source, so the next run starts there).
#               Refused unless the last run in MUTANTS_OUT tested COMMIT's whole change: from
#               the commit .ci/last-tested names now, nothing missed and nothing left unreached
#               (rows covering files count), so no mutant of the range is skipped for good.
#   --list      print the base, the commits and, per file, the mutants that would be tested (or
#               that a row covers), without building anything; exit 0.
#
#   --install   install cargo-mutants (a debug build, within the time box) when it is missing and there
#               is something to test; without it a missing cargo-mutants is SKIPPED.
#   --in-place  mutate the working tree instead of a copy, so the mutants reuse the target
#               directory the tests were built in (CI: no second build of the dependencies).
#               Refused when core/src or std-film/src differ from HEAD; every file is restored
#               from HEAD when the script exits.
#
# Environment: MUTANTS_DIFF_SECONDS (the time box for the whole run, an install included; default
# 300: files not reached and mutants not tested within it are counted and reported, not
# failed), MUTANTS_TIMEOUT
# (seconds of tests per mutant, default 60), MUTANTS_OPT_LEVEL (the core's opt-level, default 0
# as in scripts/mutants.sh), MUTANTS_OUT (default $CARGO_TARGET_DIR/mutants-diff, else
# target/mutants-diff), MUTANTS_ITERATE=1 (when the run in MUTANTS_OUT had the same base: keep
# its catches and unviable mutants, test the rest with cargo-mutants' --iterate; for a change
# that grew, or whose missed mutants got tests, since that run), MUTANTS_FILES (a space-separated
# list: test only these of the changed files).
#
# Exit status: 0 when nothing was missed (or there was nothing to test) and at least half of the
# change's mutants were tested or covered by rows (those the time box left untested are named);
# 2 when a mutant outside the equivalent list was missed, or when more than half of the change's
# mutants were left untested; 1 on any other failure. The last line starts with MUTANTS_IN_DIFF
# and gives the counts; $MUTANTS_OUT/summary keeps them for --record.
set -euo pipefail
cd "$(dirname "$0")/.."
begin=$SECONDS
# As .ci/run: line tables only keep each mutant's build short; incremental builds make a mutant of
# the core a 2–3 s rebuild (CI turns them off for its one-shot builds).
export CARGO_PROFILE_DEV_DEBUG=${CARGO_PROFILE_DEV_DEBUG:-line-tables-only}
export CARGO_INCREMENTAL=1

install=0
in_place=0
list=0
record=
while [ $# -gt 0 ]; do
    case $1 in
        --install) install=1 ;;
        --in-place) in_place=1 ;;
        --list) list=1 ;;
        --record)
            record=$(git rev-parse --verify "${2:-HEAD}^{commit}")
            break
            ;;
        -*) echo "unknown option '$1' (--install, --in-place, --list, --record)" >&2; exit 1 ;;
        *) break ;;
    esac
    shift
done

BOX=${MUTANTS_DIFF_SECONDS:-300}
TIMEOUT=${MUTANTS_TIMEOUT:-60}
OPT_LEVEL=${MUTANTS_OPT_LEVEL:-0}
OUT=${MUTANTS_OUT:-${CARGO_TARGET_DIR:-target}/mutants-diff}
SOURCES=(core/src std-film/src)

# count, diff_base, recorded_pass, package_of, equivalent_sites; MODULES_FILE, EQUIVALENT.
. scripts/mutants-common.sh
# Set by sourcing a run's summary (--record).
run_base='' run_head='' run_total='' run_tested='' run_covered='' run_unreached='' run_status=''

if [ -n "$record" ]; then
    commit=$record
    # The change since the commit recorded now must have been tested whole, up to COMMIT.
    recorded=$(recorded_pass HEAD)
    summary="$OUT/summary"
    if [ ! -s "$summary" ]; then
        echo "--record: no run in $OUT to vouch for ${commit:0:12}; run scripts/mutants-in-diff.sh at it first" >&2
        exit 1
    fi
    # shellcheck disable=SC1090 # written by this script: key=value lines
    . "$summary"
    if [ "$run_head" != "$commit" ]; then
        echo "--record: the last run in $OUT tested ${run_head:0:12}, not ${commit:0:12}" >&2
        exit 1
    fi
    if [ -n "$recorded" ] && [ "$run_base" != "$recorded" ] && ! git merge-base --is-ancestor "$run_base" "$recorded"; then
        echo "--record: the last run started at ${run_base:0:12}, after ${recorded:0:12} (.ci/last-tested): the commits between were not tested" >&2
        exit 1
    fi
    if [ "$run_status" != 0 ] || [ "$run_unreached" != 0 ]; then
        echo "--record: the last run left $run_unreached of $run_total mutants untested (status $run_status); run it again with a larger MUTANTS_DIFF_SECONDS" >&2
        exit 1
    fi
    {
        echo "# The last commit .ci/run passed on, its mutation stage included. That stage diffs"
        echo "# against it (scripts/mutants-in-diff.sh); record the next with"
        echo "# scripts/mutants-in-diff.sh --record COMMIT (docs/mutation.md)."
        echo "$commit"
    } >.ci/last-tested
    echo ".ci/last-tested: $commit ($run_tested tested and $run_covered covered by rows, of $run_total mutants since ${run_base:0:12})"
    exit 0
fi

# The run's counts as key=value lines, read back by --record: TOTAL TESTED COVERED UNREACHED
# STATUS (base and HEAD from the run).
summary() {
    printf 'run_base=%s\nrun_head=%s\nrun_total=%s\nrun_tested=%s\nrun_covered=%s\nrun_unreached=%s\nrun_status=%s\n' \
        "$base" "$(git rev-parse HEAD)" "$@"
}

# The commit FILE's row in docs/mutation.md was measured at, when the file read then as it does at
# HEAD (so the row ran every one of its mutants); nothing otherwise.
covering_row() {
    local module row at
    module=$(grep -v '^#' "$MODULES_FILE" | awk -F'|' -v f="$1" '$3 == f { print $1; exit }')
    [ -n "$module" ] || return 0
    row=$(awk -v m="| \`$module\` |" '/<!-- mutants-table-end -->/ { exit } index($0, m) == 1 { print; exit }' docs/mutation.md)
    [ -n "$row" ] || return 0
    at=$(awk -F'|' '{ gsub(/ /, "", $3); print $3 }' <<<"$row")
    if git rev-parse -q --verify "$at^{commit}" >/dev/null 2>&1 &&
        git merge-base --is-ancestor "$at" HEAD && git diff --quiet "$at" HEAD -- "$1"; then
        echo "$module $at"
    fi
}

if [ $# -gt 0 ]; then
    base=$(git rev-parse --verify "$1^{commit}")
    echo "base ${base:0:12}: given"
else
    diff_base
    if [ -z "$BASE" ]; then
        echo "SKIPPED: $BASE_WHY"
        exit 0
    fi
    base=$BASE
    echo "base ${base:0:12}: $BASE_WHY"
fi
echo "commits tested: $(git rev-list --count "$base..HEAD") (${base:0:12}..$(git rev-parse --short=12 HEAD))"

# The changed files, most added or changed lines first (the time box then spends itself where
# the change is); ties in path order.
mapfile -t files < <(git diff --numstat --diff-filter=AM "$base" HEAD -- "${SOURCES[@]}" |
    awk -F'\t' '$3 ~ /\.rs$/ { print $1 "\t" $3 }' | sort -t$'\t' -k1,1nr -k2,2 | cut -f2)
if [ ${#files[@]} -eq 0 ]; then
    echo "no change to ${SOURCES[*]} between ${base:0:12} and HEAD: nothing to mutate"
    echo "MUTANTS_IN_DIFF 0 mutants (no source change)"
    [ $list = 1 ] || { mkdir -p "$OUT" && summary 0 0 0 0 0 >"$OUT/summary"; }
    exit 0
fi
if [ -n "${MUTANTS_FILES:-}" ]; then
    # Only these of the changed files (a long run split over processes, each with its own
    # MUTANTS_OUT; their per-file folders copied into one MUTANTS_OUT let a MUTANTS_ITERATE run
    # there count them all).
    mapfile -t files < <(printf '%s\n' "${files[@]}" | grep -F -x -f <(tr ' ' '\n' <<<"$MUTANTS_FILES") || true)
fi
echo "changed since ${base:0:12}, most changed lines first: ${files[*]}"

if ! cargo mutants --version >/dev/null 2>&1; then
    if [ $install = 0 ]; then
        echo "SKIPPED: cargo-mutants is not installed (cargo install cargo-mutants --locked, or --install)"
        exit 0
    fi
    # A debug build installs in about a minute instead of two and a half here; cargo-mutants only
    # parses sources and runs cargo, so its own speed does not matter.
    echo "installing cargo-mutants (debug build, at most $BOX s)"
    if ! timeout "$BOX" cargo install cargo-mutants --locked --debug --quiet >/dev/null 2>&1; then
        echo "SKIPPED: cargo-mutants could not be installed within $BOX s"
        exit 0
    fi
fi

if [ $list = 1 ]; then
    # What a run would do, without building: each file's mutants on the changed lines.
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    git diff "$base" -- "${SOURCES[@]}" >"$tmp/change.diff"
    for file in "${files[@]}"; do
        package=$(package_of "$file")
        cargo mutants --list --in-diff "$tmp/change.diff" --package "$package" --file "$file" </dev/null 2>/dev/null >"$tmp/m.txt" || true
        n=$(count "$tmp/m.txt")
        [ "$n" -gt 0 ] || continue
        read -r module at <<<"$(covering_row "$file")"
        if [ -n "${at:-}" ]; then
            echo "== $file: $n mutants, covered by the row of $module (measured at $at)"
        else
            echo "== $file: $n mutants to test"
        fi
        sed 's/^/    /' "$tmp/m.txt"
    done
    exit 0
fi

if [ $in_place = 1 ]; then
    if ! git diff --quiet HEAD -- "${SOURCES[@]}"; then
        echo "--in-place needs ${SOURCES[*]} as in HEAD (commit or stash first)" >&2
        exit 1
    fi
    # cargo-mutants puts each file back after each mutant; this covers a run killed mid-mutant,
    # and removes the proptest regression files that caught mutants leave in the tree.
    regressions() { git ls-files --others --exclude-standard -- '*proptest-regressions/*'; }
    mapfile -t kept < <(regressions)
    # (`|| true`: grep -v selecting nothing, the usual case, must not fail the script on exit.)
    # shellcheck disable=SC2317 # called by the trap
    restore() {
        git checkout -q HEAD -- "${SOURCES[@]}"
        regressions | { grep -v -F -x -f <(printf '%s\n' "${kept[@]}" "") || true; } | xargs -r rm -f
    }
    trap restore EXIT
fi
# A caught proptest failure need not be shrunk: one step is enough to count it.
export PROPTEST_MAX_SHRINK_ITERS=${PROPTEST_MAX_SHRINK_ITERS:-1}

ITERATE=${MUTANTS_ITERATE:-0}
if [ "$ITERATE" = 1 ] && [ -s "$OUT/summary" ] && grep -q -x "run_base=$base" "$OUT/summary"; then
    echo "iterating on the run in $OUT (same base): its catches stand, the rest are tested"
else
    ITERATE=0
    rm -rf "$OUT"
fi
mkdir -p "$OUT"
diff="$OUT/change.diff"
# The diff of the working tree against BASE: with --in-place it equals HEAD's; otherwise it is
# what the copy cargo-mutants makes holds (uncommitted edits included), which the diff must match.
git diff "$base" -- "${SOURCES[@]}" >"$diff"

config="--config=profile.dev.package.nyquist.opt-level=$OPT_LEVEL"

# The test filter for a file not in the modules list: its module path, `core/src/a/b.rs` ->
# `a::b::`, `a/mod.rs` -> `a::`; the crate root gets all lib tests.
module_filter() {
    local path=${1#*/src/}
    path=${path%.rs}
    path=${path%/mod}
    case $path in lib | main) echo "" ;; *) echo "${path//\//::}::" ;; esac
}

total=0 tested=0 caught=0 missed=0 unviable=0 timeouts=0 equivalent=0 unreached=0 covered=0
status=0
not_reached=()
for file in "${files[@]}"; do
    package=$(package_of "$file")
    line=$(grep -v '^#' "$MODULES_FILE" | awk -F'|' -v f="$file" '$3 == f' | head -1)
    if [ -n "$line" ]; then
        IFS='|' read -r _ package _ filters targets <<<"$line"
    else
        filters=$(module_filter "$file")
        targets=
    fi
    cargo_args=("--cargo-arg=$config")
    for t in ${targets:---lib}; do cargo_args+=("--cargo-arg=$t"); done
    dir="$OUT/${file//\//-}"
    mkdir -p "$dir"
    cargo mutants --list --in-diff "$diff" --package "$package" --file "$file" 2>/dev/null >"$dir/listed.txt" || true
    n=$(count "$dir/listed.txt")
    [ "$n" -gt 0 ] || continue
    total=$((total + n))
    read -r module at <<<"$(covering_row "$file")"
    if [ -n "${at:-}" ]; then
        echo "== $file: $n mutants, covered by the row of $module (measured at $at, the file unchanged since)"
        covered=$((covered + n))
        continue
    fi
    left=$((BOX - (SECONDS - begin)))
    if [ "$left" -le 0 ]; then
        echo "== $file: $n mutants not tested (time box of ${BOX} s used up)"
        unreached=$((unreached + n))
        not_reached+=("$file ($n of $n)")
        continue
    fi
    if [ -n "$filters" ] && [ -z "$line" ]; then
        # An unlisted file: fall back to all lib tests when no test lives under its module path.
        # (This also builds the tests once, unmutated, before the time box's first mutant.)
        # shellcheck disable=SC2086 # the filters are separate libtest arguments
        listed=$(cargo test --quiet -p "$package" --lib "$config" -- --list $filters 2>/dev/null | grep -c ': test$' || true)
        [ "$listed" -gt 0 ] || filters=
    fi
    # shellcheck disable=SC2206 # the filters are separate libtest arguments
    cmd=(cargo mutants --in-diff "$diff" --package "$package" --file "$file" --test-package "$package"
        --no-shuffle --timeout "$TIMEOUT" --baseline skip --output "$dir" "${cargo_args[@]}")
    [ $in_place = 1 ] && cmd+=(--in-place) # one mutant at a time (the default), as it must be here
    # An earlier run's catches (and unviable mutants) stand: cargo-mutants skips them and lists
    # them in previously_caught.txt (a mutant whose line moved is tested again).
    [ "$ITERATE" = 1 ] && [ -d "$dir/mutants.out" ] && cmd+=(--iterate)
    # shellcheck disable=SC2206 # the filters are separate libtest arguments
    [ -n "$filters" ] && cmd+=(-- -- $filters)
    echo "== $file: $n mutants, at most ${left} s: ${cmd[*]}"
    rc=0
    # SIGINT lets cargo-mutants put the file back and write what it has before it stops.
    RUST_BACKTRACE=0 timeout -s INT "$left" nice -n 10 "${cmd[@]}" || rc=$?
    res="$dir/mutants.out"
    case $rc in
        0 | 2 | 3) ;;
        124 | 130) echo "$file: the time box ran out during this file" ;;
        *) echo "$file: cargo mutants exited $rc" >&2; exit 1 ;;
    esac
    # Earlier catches of mutants still on the changed lines count as caught.
    earlier=0
    if [ -s "$res/previously_caught.txt" ]; then
        earlier=$(grep -c -F -x -f "$dir/listed.txt" "$res/previously_caught.txt" || true)
    fi
    c=$(($(count "$res/caught.txt") + earlier)) m=$(count "$res/missed.txt")
    u=$(count "$res/unviable.txt") t=$(count "$res/timeout.txt")
    caught=$((caught + c)) missed=$((missed + m)) unviable=$((unviable + u)) timeouts=$((timeouts + t))
    tested=$((tested + c + m + u + t))
    unreached=$((unreached + n - (c + m + u + t)))
    [ $((c + m + u + t)) -ge "$n" ] || not_reached+=("$file ($((n - (c + m + u + t))) of $n)")
    if [ -s "$res/missed.txt" ]; then
        # The listed mutants among all of the file's (the tree cargo-mutants copied or mutated).
        cargo mutants --list --package "$package" --file "$file" </dev/null 2>/dev/null >"$dir/all.txt" || true
        equivalent_sites "$file" "" "$dir/all.txt" >"$dir/equivalent-sites.txt"
        e=$(grep -c -F -x -f "$dir/equivalent-sites.txt" "$res/missed.txt" || true)
        equivalent=$((equivalent + e))
        unlisted=$(grep -v -F -x -f "$dir/equivalent-sites.txt" "$res/missed.txt" || true)
        if [ -n "$unlisted" ]; then
            echo "$file: missed mutants not listed in $EQUIVALENT (a test should catch each; list an"
            echo "    equivalent one with the line scripts/mutants-equivalent.sh --entry 'NAME' prints):"
            printf '%s\n' "$unlisted" | sed 's/^/    /'
            status=2
        fi
    fi
    if [ -s "$res/timeout.txt" ]; then
        echo "$file: timed out (an endless loop, usually; not counted as missed):"
        sed 's/^/    /' "$res/timeout.txt"
    fi
done
if [ "$unreached" -gt 0 ]; then
    echo "time box: $unreached of $total mutants were not tested, in: ${not_reached[*]}"
    echo "    run scripts/mutants-in-diff.sh ${base:0:12} with a larger MUTANTS_DIFF_SECONDS for them,"
    echo "    or measure their modules' rows (scripts/mutants.sh MODULE), which then cover them"
    # Up to half may wait for the run that --record requires; more fails: the change is larger
    # than CI can check, and its rows are to be measured before it is submitted.
    if [ $((2 * unreached)) -gt "$total" ]; then
        echo "FAILED: more than half of the change's mutants ($unreached of $total) were left untested"
        status=2
    fi
fi
summary "$total" "$tested" "$covered" "$unreached" "$status" >"$OUT/summary"
echo "MUTANTS_IN_DIFF $tested of $total mutants tested in $((SECONDS - begin)) s, $covered covered by rows: caught $caught, missed $missed ($equivalent listed equivalent), unviable $unviable, timeouts $timeouts, not reached $unreached"
exit $status
