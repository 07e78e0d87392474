#!/usr/bin/env bash
# Mutation testing of the core, one module at a time (docs/mutation.md).
#
#   scripts/mutants.sh                 every module below, in order
#   scripts/mutants.sh stratify/jittered hash
#                                      only the named modules
#   scripts/mutants.sh --list          the modules, their files and test filters
#   scripts/mutants.sh --summarize hash
#                                      re-score earlier runs (after editing the equivalent list)
#
# For each module it runs cargo-mutants on that module's file only, and runs only the lib tests
# whose path matches the module's filter (the module's own tests), so a mutant costs one
# incremental build plus a few seconds of tests:
#
#   cargo mutants --package P --file F --test-package P --no-shuffle --jobs J --timeout T \
#       --output OUT/<module> --cargo-arg=--config=profile.dev.package.nyquist.opt-level=0 \
#       --cargo-arg=--lib -- -- <filter>...
#
# (`--lib` is the default test target; a module whose tests live in an integration test names
# its targets in a fifth field, e.g. `--test=film`.)
#
# then counts caught, missed, unviable and timed-out mutants from OUT/<module>/mutants.out/,
# subtracts the missed mutants that scripts/mutants-equivalent.txt names (each entry one mutant,
# found by its position or, where the code moved, by its line's text), and writes the module's
# row of the table in docs/mutation.md (rows of modules not run this time are kept). The row
# names the commit it was measured at: HEAD when the run starts, or `uncommitted` when the
# module's file differs from HEAD (cargo-mutants copies the working tree), which
# scripts/mutants-table-check.sh then counts as out of date.
#
# Environment: MUTANTS_OPT_LEVEL (the core's opt-level while testing mutants; default 0),
# MUTANTS_JOBS (default 1: two cores, one build at a time), MUTANTS_TIMEOUT
# (seconds of tests per mutant before it counts as a timeout; default 30), MUTANTS_OUT (default
# $CARGO_TARGET_DIR/mutants, else target/mutants), MUTANTS_BASELINE=skip (do not first run the
# tests on the unmutated tree: saves one build per module when they are known to pass),
# MUTANTS_ITERATE=1 (test again only the mutants an earlier run in the same output folder did not
# catch, with cargo-mutants' --iterate; the row then counts the earlier catches with the new ones
# and its time is the sum of the runs'. Tests only ever get stronger between runs, so a mutant
# caught once stays caught; a mutant whose line moved is tested again, and an earlier catch that
# is no longer among the file's mutants (its code was changed or removed) is not counted.)
#
# Exit status: 0 when every viable, non-equivalent mutant was caught; 2 when some were missed (the
# list is printed); 1 when cargo-mutants is missing or failed.
set -euo pipefail
cd "$(dirname "$0")/.."
# As .ci/run: line tables only keep each mutant's build short.
export CARGO_PROFILE_DEV_DEBUG=${CARGO_PROFILE_DEV_DEBUG:-line-tables-only}
# The core is built unoptimised for mutants (the dev profile optimises it at level 2 for the
# test suite's sake): an edited core then rebuilds in 2.5 s instead of 19 s here, and the
# slowest module's tests take 10 s instead of 2 (docs/mutation.md).
OPT_LEVEL=${MUTANTS_OPT_LEVEL:-0}

DOC=docs/mutation.md
JOBS=${MUTANTS_JOBS:-1}
TIMEOUT=${MUTANTS_TIMEOUT:-30}
OUT=${MUTANTS_OUT:-${CARGO_TARGET_DIR:-target}/mutants}
BASELINE=${MUTANTS_BASELINE:-run}
ITERATE=${MUTANTS_ITERATE:-0}

# count, equivalent_sites; MODULES_FILE, EQUIVALENT.
. scripts/mutants-common.sh

modules() { grep -v -e '^#' -e '^[[:space:]]*$' "$MODULES_FILE"; }

summarize=0
if [ "${1:-}" = "--summarize" ]; then
    summarize=1
    shift
fi
if [ "${1:-}" = "--list" ]; then
    modules | awk -F'|' '{ printf "%-26s %-12s %-40s %s %s\n", $1, $2, $3, $4, ($5 == "" ? "" : "[" $5 "]") }'
    exit 0
fi
if ! cargo mutants --version >/dev/null 2>&1; then
    echo "cargo-mutants is not installed: cargo install cargo-mutants --locked" >&2
    exit 1
fi

selected=("$@")
[ ${#selected[@]} -gt 0 ] || mapfile -t selected < <(modules | cut -d'|' -f1)

version=$(cargo mutants --version)
machine="$(nproc)-core $(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2- | sed 's/^ *//'), $(uname -sm)"
status=0
for module in "${selected[@]}"; do
    line=$(modules | awk -F'|' -v m="$module" '$1 == m') || true
    [ -n "$line" ] || { echo "unknown module '$module' (see --list)" >&2; exit 1; }
    IFS='|' read -r _ package file filters targets <<<"$line"
    cargo_args=("--cargo-arg=--config=profile.dev.package.nyquist.opt-level=$OPT_LEVEL")
    for t in ${targets:---lib}; do cargo_args+=("--cargo-arg=$t"); done
    dir="$OUT/${module//\//-}"
    # shellcheck disable=SC2206 # the filters are separate libtest arguments
    cmd=(cargo mutants --package "$package" --file "$file" --test-package "$package"
        --no-shuffle --jobs "$JOBS" --timeout "$TIMEOUT" --baseline "$BASELINE" --output "$dir"
        "${cargo_args[@]}" -- -- $filters)
    if [ "$ITERATE" = 1 ]; then cmd=("${cmd[@]:0:2}" --iterate "${cmd[@]:2}"); fi
    res="$dir/mutants.out"
    if [ $summarize = 1 ]; then
        # Re-score an earlier run (after a change to the equivalent list).
        [ -s "$dir/seconds" ] || { echo "$module: no earlier run in $dir" >&2; exit 1; }
        seconds=$(cat "$dir/seconds")
        read -r -a cmd <"$dir/command"
        at=$(cat "$dir/commit" 2>/dev/null || echo uncommitted)
    else
        earlier=0
        at=$(git rev-parse --short=7 HEAD)
        if ! git diff --quiet HEAD -- "$file"; then
            echo "$module: $file differs from HEAD; the row will say 'uncommitted' (run again from a commit)"
            at=uncommitted
        fi
        if [ "$ITERATE" = 1 ]; then
            [ -s "$dir/seconds" ] || { echo "$module: no earlier run in $dir to iterate on" >&2; exit 1; }
            earlier=$(cat "$dir/seconds")
            # cargo-mutants skips the earlier unviable mutants too and lists them with the
            # catches; keep their names to count them apart.
            { cat "$res/unviable.txt" "$dir/unviable-earlier.txt" 2>/dev/null || true; } | sort -u >"$dir/unviable.tmp"
            mv "$dir/unviable.tmp" "$dir/unviable-earlier.txt"
        else
            rm -rf "$dir"
            mkdir -p "$dir"
        fi
        echo "== $module: ${cmd[*]}"
        begin=$((SECONDS - earlier))
        rc=0
        nice -n 15 "${cmd[@]}" || rc=$?
        seconds=$((SECONDS - begin))
        # 0: all caught; 2: some missed; 3: some timed out. Anything else is a failed run.
        case $rc in 0 | 2 | 3) ;; *) echo "$module: cargo mutants exited $rc" >&2; exit 1 ;; esac
        echo "$seconds" >"$dir/seconds"
        echo "${cmd[*]}" >"$dir/command"
        echo "$at" >"$dir/commit"
        # The file's mutants as the code now stands, to drop earlier catches that no longer exist.
        cargo mutants --list --package "$package" --file "$file" >"$dir/current.txt"
    fi
    # An iterated run lists the earlier runs' catches, and their unviable mutants (kept in
    # unviable-earlier.txt before the run), in previously_caught.txt.
    earlier="$dir/earlier-caught.txt"
    if [ -s "$res/previously_caught.txt" ] && [ -s "$dir/current.txt" ]; then
        grep -F -x -f "$dir/current.txt" "$res/previously_caught.txt" >"$earlier" || true
    else
        cp "$res/previously_caught.txt" "$earlier" 2>/dev/null || : >"$earlier"
    fi
    earlier_unviable=0
    if [ -s "$earlier" ] && [ -s "$dir/unviable-earlier.txt" ]; then
        earlier_unviable=$(grep -c -F -x -f "$dir/unviable-earlier.txt" "$earlier" || true)
    fi
    caught=$(($(count "$res/caught.txt") + $(count "$earlier") - earlier_unviable))
    missed=$(count "$res/missed.txt")
    unviable=$(($(count "$res/unviable.txt") + earlier_unviable))
    timeouts=$(count "$res/timeout.txt")
    total=$((caught + missed + unviable + timeouts))
    : >"$dir/unlisted.txt"
    equivalent=0
    if [ -s "$res/missed.txt" ]; then
        # The listed mutants among the file's, as the run saw it: the tree at the row's commit
        # (the working tree when uncommitted) and the file's mutants listed after the run.
        [ -s "$dir/current.txt" ] || jq -r '.[].name' "$res/mutants.json" >"$dir/current.txt"
        equivalent_sites "$file" "$at" "$dir/current.txt" >"$dir/equivalent-sites.txt"
        equivalent=$(grep -c -F -x -f "$dir/equivalent-sites.txt" "$res/missed.txt" || true)
        grep -v -F -x -f "$dir/equivalent-sites.txt" "$res/missed.txt" >"$dir/unlisted.txt" || true
    fi
    denominator=$((caught + missed - equivalent))
    if [ "$denominator" -gt 0 ]; then
        score=$(awk -v c="$caught" -v d="$denominator" 'BEGIN { printf "%.1f %%", 100 * c / d }')
    else
        score="–"
    fi
    # Mean build + test time of one mutant (the baseline excluded), from cargo-mutants' record.
    per=$(jq -r '[.outcomes[] | select(.scenario | type == "object")
        | [.phase_results[].duration] | add] | if length > 0 then add / length * 10 | round / 10
        else "–" end' "$res/outcomes.json" 2>/dev/null || echo "–")
    row="| \`$module\` | $at | $total | $caught | $missed | $unviable | $timeouts | $equivalent | $score | ${seconds} s (${per} s) |"
    echo "$row"
    if [ -s "$dir/unlisted.txt" ]; then
        echo "$module: missed and not listed in $EQUIVALENT (a test should catch each; if one is"
        echo "    equivalent, list it: scripts/mutants-equivalent.sh --entry 'NAME' prints its entry):"
        sed 's/^/    /' "$dir/unlisted.txt"
        status=2
    fi
    # Replace the module's row (or add it before the end marker) in the doc's table.
    awk -v m="\`$module\`" -v row="$row" '
        /<!-- mutants-table-end -->/ { if (!done) print row; done = 1; print; next }
        index($0, "| " m " |") == 1 { if (!done) print row; done = 1; next }
        { print }' "$DOC" >"$DOC.tmp.$$" && mv "$DOC.tmp.$$" "$DOC"
    # Record how and where this row was measured (the output folder left out: it is this
    # machine's).
    shown=()
    skip=0
    for arg in "${cmd[@]}"; do
        if [ $skip = 1 ]; then skip=0; continue; fi
        if [ "$arg" = --output ]; then skip=1; continue; fi
        shown+=("$arg")
    done
    awk -v m="$module" -v run="- \`$module\`: \`${shown[*]}\` — at $at, $(date -u +%Y-%m-%d), $machine, $version" '
        /<!-- mutants-runs-end -->/ { if (!done) print run; done = 1; print; next }
        index($0, "- `" m "`: `cargo mutants ") == 1 { if (!done) print run; done = 1; next }
        { print }' "$DOC" >"$DOC.tmp.$$" && mv "$DOC.tmp.$$" "$DOC"
done
exit $status
