#!/usr/bin/env bash
# Whether the table of docs/mutation.md still describes the code (docs/mutation.md).
#
#   scripts/mutants-table-check.sh [BASE]
#
# Each row names the commit its module's file was measured at. A row is out of date when a line
# of that file that carries a mutant was added or changed after that commit and before the
# mutation stage's coverage starts. The stage (scripts/mutants-in-diff.sh) tests the mutants of
# every line changed since BASE; the earlier passing runs that .ci/last-tested's history records
# tested the commits before BASE back to where that record starts. Changes that carry no mutant
# (tests, comments, attributes, deleted lines) leave a row current. A module of
# scripts/mutants-modules.txt that has mutants but no row yet (a new file, or a file split off
# another) makes no claim the code could contradict: it gets a warning with the command that
# measures it, and the mutation stage still tests every line of it that a change touches.
#
# It then checks the list of equivalent mutants as scripts/mutants-equivalent.sh does: every
# entry must name exactly one mutant of the working tree.
#
# BASE is chosen as scripts/mutants-in-diff.sh chooses it (from .ci/last-tested, else the merge
# base with origin/main, else HEAD's first parent); only with the first is the record's history
# counted. Costs a `git log` per row and, for a row whose file changed, two
# `cargo mutants --list` (about a second each). SKIPPED without cargo-mutants.
#
# Exit status: 0 when every row is current and every entry resolves, 2 when some row is out of
# date (each is printed with the command that measures it again) or some entry does not resolve,
# 1 on any other failure.
set -euo pipefail
cd "$(dirname "$0")/.."

DOC=docs/mutation.md

# diff_base, coverage_start, list_mutants, equivalent_files, equivalent_resolve; MODULES_FILE.
. scripts/mutants-common.sh

if [ $# -gt 0 ]; then
    base=$(git rev-parse --verify "$1^{commit}")
    start=$base
else
    diff_base
    if [ -z "$BASE" ]; then
        echo "SKIPPED: $BASE_WHY"
        exit 0
    fi
    base=$BASE
    start=$base
    [ "$BASE_RECORDED" = 0 ] || start=$(coverage_start "$base")
fi
echo "lines changed since ${start:0:12} are mutation-tested in diff (this run from ${base:0:12})"
if ! cargo mutants --version >/dev/null 2>&1; then
    echo "SKIPPED: cargo-mutants is not installed (cargo install cargo-mutants --locked)"
    exit 0
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The mutants of FILE (in PACKAGE) on the lines DIFF adds or changes, as HEAD's tree places them.
mutants_in() {
    cargo mutants --list --in-diff "$3" --package "$1" --file "$2" </dev/null 2>/dev/null
}

status=0 current=0
while IFS='|' read -r module package file _; do
    row=$(awk -v m="| \`$module\` |" '/<!-- mutants-table-end -->/ { exit } index($0, m) == 1 { print; exit }' "$DOC")
    again="scripts/mutants.sh $module"
    if [ -z "$row" ]; then
        n=$(cargo mutants --list --package "$package" --file "$file" </dev/null 2>/dev/null | grep -c . || true)
        if [ "$n" -gt 0 ]; then
            echo "WARNING: $module: no row yet for its $n mutants: $again"
        fi
        continue
    fi
    at=$(awk -F'|' '{ gsub(/ /, "", $3); print $3 }' <<<"$row")
    if ! measured=$(git rev-parse -q --verify "$at^{commit}" 2>/dev/null) ||
        ! git merge-base --is-ancestor "$measured" HEAD; then
        echo "$module: measured at '$at', which is not a commit of HEAD's history: $again"
        status=2
        continue
    fi
    commits=$(git log --format=%h "$measured..HEAD" -- "$file" | tr '\n' ' ')
    if [ -z "$commits" ] || git merge-base --is-ancestor "$start" "$measured"; then
        current=$((current + 1))
        continue
    fi
    git diff "$measured" HEAD -- "$file" >"$tmp/since-row.diff"
    git diff "$start" HEAD -- "$file" >"$tmp/covered.diff"
    mutants_in "$package" "$file" "$tmp/since-row.diff" >"$tmp/since-row.txt" || true
    mutants_in "$package" "$file" "$tmp/covered.diff" >"$tmp/covered.txt" || true
    uncovered=$(grep -c -v -F -x -f <(cat "$tmp/covered.txt" <(echo)) "$tmp/since-row.txt" || true)
    if [ "$uncovered" -gt 0 ]; then
        echo "$module: $file changed since ${at} (${commits% }); $uncovered mutants on lines changed between ${at} and ${start:0:12}, which neither its row nor a recorded mutation stage covers: $again"
        status=2
    else
        current=$((current + 1))
    fi
done < <(grep -v -e '^#' -e '^[[:space:]]*$' "$MODULES_FILE")
echo "MUTANTS_TABLE $current rows current$([ $status = 0 ] || echo "; out of date: see above")"

mapfile -t files < <(equivalent_files)
list_mutants "${files[@]}" >"$tmp/all-mutants.txt"
equivalent_resolve check . "$tmp/all-mutants.txt" || status=2
exit $status
