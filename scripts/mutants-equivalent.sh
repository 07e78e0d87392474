#!/usr/bin/env bash
# The list of equivalent mutants, scripts/mutants-equivalent.txt, against the working tree
# (docs/mutation.md).
#
#   scripts/mutants-equivalent.sh              check: every entry names exactly one mutant
#   scripts/mutants-equivalent.sh --reanchor   set each entry's line and column to where its
#                                              mutant is now (after code moved)
#   scripts/mutants-equivalent.sh --names      the mutants the entries name, with positions
#   scripts/mutants-equivalent.sh --entry NAME...
#                                              the entry line for each mutant NAME (as a run
#                                              prints it, with position), its reason left to write
#
# An entry is one mutant: "FILE:LINE:COLUMN: NAME  @ LINE TEXT  # REASON", where NAME is the
# mutant's name as cargo-mutants prints it and LINE TEXT the text of its line, trimmed. When code
# moves, the entry still names the mutant of that name on the line with that text (at the
# entry's column, or, on a re-indented line, its one mutant of that name); entries sharing file,
# name and line text are matched to such lines in order. The check fails when an entry matches
# more or fewer mutants than it says (its line changed, was removed or now appears more often
# than the list names it), and names the entries whose mutant moved.
#
# Costs one `cargo mutants --list` per package (a few seconds). Exit status: 0 when every entry
# resolves, 2 when some does not, 1 on any other failure.
set -euo pipefail
cd "$(dirname "$0")/.."

# list_mutants, equivalent_files, equivalent_resolve, equivalent_entry; EQUIVALENT.
. scripts/mutants-common.sh

mode=check
case ${1:-} in
    "") ;;
    --reanchor) mode=reanchor ;;
    --names) mode=names ;;
    --entry)
        shift
        equivalent_entry "$@"
        exit 0
        ;;
    *) echo "unknown argument '$1' (--reanchor, --names, --entry NAME...)" >&2; exit 1 ;;
esac
if ! cargo mutants --version >/dev/null 2>&1; then
    echo "cargo-mutants is not installed: cargo install cargo-mutants --locked" >&2
    exit 1
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mapfile -t files < <(equivalent_files)
list_mutants "${files[@]}" >"$tmp/mutants.txt"
case $mode in
    check)
        equivalent_resolve check . "$tmp/mutants.txt" || exit 2
        ;;
    names)
        equivalent_resolve names . "$tmp/mutants.txt"
        ;;
    reanchor)
        equivalent_resolve reanchor . "$tmp/mutants.txt" >"$tmp/list" || true
        if cmp -s "$tmp/list" "$EQUIVALENT"; then
            echo "every resolved entry is where its mutant is"
        else
            cp "$tmp/list" "$EQUIVALENT"
            echo "$EQUIVALENT: positions updated (entries that do not resolve are left as they were)"
        fi
        equivalent_resolve check . "$tmp/mutants.txt" || exit 2
        ;;
esac
