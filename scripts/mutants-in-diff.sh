#!/usr/bin/env bash
# Mutation testing of the lines a change touches (docs/mutation.md).
#
#   scripts/mutants-in-diff.sh [BASE]
#
# Diffs HEAD against BASE (default: `git merge-base HEAD origin/main`, or HEAD~1 when there is
# no origin/main), and runs `cargo mutants --in-diff` on the changed Rust files of the core and
# the film, testing each mutant with the lib tests of its package. Missed mutants listed in
# scripts/mutants-equivalent.txt are forgiven; any other missed mutant fails the script.
#
# Environment: MUTANTS_DIFF_SECONDS (the whole run's time box, default 900; a run cut short
# fails), MUTANTS_TIMEOUT (seconds of tests per mutant, default 60), MUTANTS_JOBS (default 1),
# MUTANTS_OUT (default $CARGO_TARGET_DIR/mutants-diff, else target/mutants-diff).
#
# Exit status: 0 when nothing was missed (or nothing to test), 2 when a mutant outside the
# equivalent list was missed, 1 on any other failure. Prints "SKIPPED: <why>" and exits 0 when
# cargo-mutants is not installed; it never installs it.
set -euo pipefail
cd "$(dirname "$0")/.."
# As .ci/run: line tables only keep each mutant's build short.
export CARGO_PROFILE_DEV_DEBUG=${CARGO_PROFILE_DEV_DEBUG:-line-tables-only}

if ! cargo mutants --version >/dev/null 2>&1; then
    echo "SKIPPED: cargo-mutants is not installed (cargo install cargo-mutants --locked)"
    exit 0
fi

EQUIVALENT=scripts/mutants-equivalent.txt
SECONDS_BOX=${MUTANTS_DIFF_SECONDS:-900}
TIMEOUT=${MUTANTS_TIMEOUT:-60}
JOBS=${MUTANTS_JOBS:-1}
OUT=${MUTANTS_OUT:-${CARGO_TARGET_DIR:-target}/mutants-diff}

if [ $# -gt 0 ]; then
    base=$1
elif base=$(git merge-base HEAD origin/main 2>/dev/null); then
    :
elif base=$(git rev-parse --verify -q HEAD~1); then
    :
else
    echo "SKIPPED: no origin/main and no parent commit to diff against"
    exit 0
fi

rm -rf "$OUT"
mkdir -p "$OUT"
diff="$OUT/change.diff"
git diff "$base" HEAD -- 'core/src/*.rs' 'std-film/src/*.rs' >"$diff"
if [ ! -s "$diff" ]; then
    echo "no change to core/src or std-film/src since ${base:0:12}: nothing to mutate"
    exit 0
fi
# Each touched package tests its own mutants with its own lib tests.
packages=()
git diff --name-only "$base" HEAD -- 'core/src/*.rs' | grep -q . && packages+=(nyquist)
git diff --name-only "$base" HEAD -- 'std-film/src/*.rs' | grep -q . && packages+=(nyquist-film)

strip_position() { sed -E 's/^([^:]+):[0-9]+:[0-9]+: /\1: /'; }
equivalent_names() { grep -v -e '^#' -e '^[[:space:]]*$' "$EQUIVALENT" | sed -E 's/  # .*$//'; }

status=0
for package in "${packages[@]}"; do
    dir="$OUT/$package"
    mkdir -p "$dir"
    cmd=(cargo mutants --in-diff "$diff" --package "$package" --test-package "$package"
        --no-shuffle --jobs "$JOBS" --timeout "$TIMEOUT" --output "$dir" --cargo-arg=--lib)
    echo "== ${cmd[*]} (diff against ${base:0:12}, at most ${SECONDS_BOX} s)"
    rc=0
    timeout "$SECONDS_BOX" nice -n 15 "${cmd[@]}" || rc=$?
    case $rc in
        0 | 2 | 3) ;;
        124) echo "$package: the run took over ${SECONDS_BOX} s (MUTANTS_DIFF_SECONDS)" >&2; exit 1 ;;
        *) echo "$package: cargo mutants exited $rc" >&2; exit 1 ;;
    esac
    missed="$dir/mutants.out/missed.txt"
    if [ -s "$missed" ]; then
        unlisted=$(strip_position <"$missed" | grep -v -F -x -f <(equivalent_names) || true)
        if [ -n "$unlisted" ]; then
            echo "$package: missed mutants not listed in $EQUIVALENT:"
            printf '%s\n' "$unlisted" | sed 's/^/    /'
            status=2
        fi
    fi
    if [ -s "$dir/mutants.out/timeout.txt" ]; then
        echo "$package: timed out (not counted as missed):"
        sed 's/^/    /' "$dir/mutants.out/timeout.txt"
    fi
done
exit $status
