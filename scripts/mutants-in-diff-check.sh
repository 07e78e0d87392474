#!/usr/bin/env bash
# Checks that the mutation stage (scripts/mutants-in-diff.sh) tests a whole submission, not only
# its last commit, and keeps its rules (docs/mutation.md). On a scratch clone of HEAD:
#
#   commit 1  records HEAD in .ci/last-tested, as after a passing CI run;
#   commit 2  adds a function with a branch no test reaches to core/src/hash.rs;
#   commit 3  changes only a comment elsewhere (the last commit of the submission).
#
# then checks, without building anything (about 15 s; `cargo mutants --list` only):
#
#   - from .ci/last-tested the stage lists the new function's mutants, from HEAD's first parent
#     (the old base) it lists none of them;
#   - a run whose time box reaches none of them fails (more than half left untested) and
#     --record refuses it;
#   - once hash's row in docs/mutation.md names commit 2 (as if `scripts/mutants.sh hash` had
#     measured it there), the row covers the file, the run passes and --record accepts it.
#
#   scripts/mutants-in-diff-check.sh [--full]
#
# --full also runs the mutants (a debug build of the core and a minute or two of mutants):
# the stage must fail, naming a missed mutant of the new function. CARGO_TARGET_DIR is used for
# that build (default: the scratch clone's own target). Exit status 0 when every check holds, 1
# otherwise; the last line starts with MUTANTS_IN_DIFF_CHECK.
set -euo pipefail
cd "$(dirname "$0")/.."
full=0
[ "${1:-}" = --full ] && full=1
if ! cargo mutants --version >/dev/null 2>&1; then
    echo "SKIPPED: cargo-mutants is not installed (cargo install cargo-mutants --locked)"
    exit 0
fi

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
git clone -q --no-local . "$scratch/repo"
# The scripts as they are here, edits included.
cp scripts/mutants-*.sh "$scratch/repo/scripts/"
cd "$scratch/repo"
git config user.email check@nyquist.invalid
git config user.name "mutants-in-diff-check"
base=$(git rev-parse HEAD)
export MUTANTS_OUT=$scratch/out

failures=0
check() { # check WHAT COMMAND...: runs COMMAND, which must succeed
    local what=$1
    shift
    if "$@"; then echo "ok: $what"; else echo "FAILED: $what"; failures=$((failures + 1)); fi
}

{
    echo "# scratch record for scripts/mutants-in-diff-check.sh"
    echo "$base"
} >.ci/last-tested
git commit -q -am "record the base as tested"
cat >>core/src/hash.rs <<'EOF'

/// A function with a branch no test reaches (scripts/mutants-in-diff-check.sh).
pub fn mutation_probe(x: u32) -> u32 {
    if x > 7 { x - 7 } else { 0 }
}
EOF
git commit -q -am "an untested branch"
probe_commit=$(git rev-parse HEAD)
sed -i '1s|$| |' core/src/lib.rs
git commit -q -am "a last commit that carries no mutant"

scripts/mutants-in-diff.sh --list >"$scratch/list.txt"
scripts/mutants-in-diff.sh --list HEAD^ >"$scratch/list-parent.txt"
check "the stage starts at .ci/last-tested and takes all three commits" \
    grep -q -x "commits tested: 3 (${base:0:12}..$(git rev-parse --short=12 HEAD))" "$scratch/list.txt"
check "it lists the new function's mutants in hash.rs to test" \
    grep -q "^    core/src/hash.rs:.*in mutation_probe" "$scratch/list.txt"
check "from HEAD's first parent (the last commit only) it lists none of them" \
    bash -c "! grep -q mutation_probe '$scratch/list-parent.txt'"

rc=0
MUTANTS_DIFF_SECONDS=0 scripts/mutants-in-diff.sh >"$scratch/boxed.txt" 2>&1 || rc=$?
check "a run that reaches none of them fails (exit $rc)" test "$rc" = 2
check "and says why" grep -q "^FAILED: more than half of the change's mutants" "$scratch/boxed.txt"
check "--record refuses that run" bash -c "! scripts/mutants-in-diff.sh --record HEAD 2>/dev/null"

# hash's row as if measured at the commit that added the function.
sed -i "s/^| \`hash\` | [0-9a-f]* |/| \`hash\` | ${probe_commit:0:7} |/" docs/mutation.md
git commit -q -am "hash's row measured with the function"
scripts/mutants-in-diff.sh --list >"$scratch/list-covered.txt"
check "a row measured at a commit where the file reads as at HEAD covers it" \
    grep -q "^== core/src/hash.rs: [0-9]* mutants, covered by the row of hash (measured at ${probe_commit:0:7})" "$scratch/list-covered.txt"
rc=0
MUTANTS_DIFF_SECONDS=0 scripts/mutants-in-diff.sh >"$scratch/covered.txt" 2>&1 || rc=$?
check "the covered run passes (exit $rc)" test "$rc" = 0
check "--record accepts it" scripts/mutants-in-diff.sh --record HEAD
git checkout -q .ci/last-tested
sed -i "s/^| \`hash\` | [0-9a-f]* |/| \`hash\` | ${base:0:7} |/" docs/mutation.md
git commit -q -am "hash's row back at the base"

if [ $full = 1 ]; then
    rc=0
    MUTANTS_DIFF_SECONDS=1200 scripts/mutants-in-diff.sh --in-place >"$scratch/full.txt" 2>&1 || rc=$?
    grep -E '^(==|MUTANTS_IN_DIFF|    core/src/hash.rs)' "$scratch/full.txt" || true
    check "the full run fails (exit $rc)" test "$rc" = 2
    check "naming a missed mutant of the new function" \
        grep -q "^    core/src/hash.rs:.*in mutation_probe" "$scratch/full.txt"
fi
echo "MUTANTS_IN_DIFF_CHECK $([ $failures = 0 ] && echo passed || echo "$failures failed")"
[ $failures = 0 ]
