# Helpers shared by scripts/mutants.sh and scripts/mutants-in-diff.sh (sourced; they set
# EQUIVALENT to the list of equivalent mutants first).

# A mutant's name without its line and column, as scripts/mutants-equivalent.txt lists it:
# "core/src/hash.rs:12:5: replace + with - in mix" -> "core/src/hash.rs: replace + with - in mix".
strip_position() { sed -E 's/^([^:]+):[0-9]+:[0-9]+: /\1: /'; }
# The listed equivalent mutants' names (the part of each line before "  # ").
equivalent_names() { grep -v -e '^#' -e '^[[:space:]]*$' "$EQUIVALENT" | sed -E 's/  # .*$//'; }
# The number of non-empty lines of a file (0 when it is missing or empty).
count() { if [ -s "$1" ]; then grep -c . "$1"; else echo 0; fi; }

# The commit that .ci/last-tested names in COMMIT's tree (the last commit CI passed on when
# COMMIT was tested), as a full hash; nothing when the file is absent or names no commit here.
recorded_pass() {
    local text hash
    text=$(git show "$1:.ci/last-tested" 2>/dev/null) || return 0
    hash=$(printf '%s\n' "$text" | grep -v '^#' | grep -o -m1 -E '^[0-9a-f]{7,40}' || true)
    [ -n "$hash" ] || return 0
    git rev-parse -q --verify "$hash^{commit}" 2>/dev/null || true
}

# Sets BASE to what HEAD's change is diffed against, BASE_WHY to a sentence saying where it came
# from, and BASE_RECORDED to 1 when it is HEAD's .ci/last-tested (else 0). In order: the commit
# .ci/last-tested names, when it is HEAD or an ancestor of it; else the merge base with
# origin/main, when that is not HEAD itself; else HEAD's first parent (only the last commit is
# then tested); else BASE is empty.
diff_base() {
    local last head merge
    head=$(git rev-parse HEAD)
    last=$(recorded_pass HEAD)
    BASE_RECORDED=0
    if [ -n "$last" ] && git merge-base --is-ancestor "$last" HEAD; then
        BASE=$last BASE_RECORDED=1
        BASE_WHY=".ci/last-tested: the last commit CI passed on"
        return 0
    fi
    if ! git cat-file -e HEAD:.ci/last-tested 2>/dev/null; then
        BASE_WHY="HEAD has no .ci/last-tested"
    elif [ -z "$last" ]; then
        BASE_WHY="the commit .ci/last-tested names is not in this clone"
    else
        BASE_WHY=".ci/last-tested names ${last:0:12}, which is not an ancestor of HEAD"
    fi
    if merge=$(git merge-base HEAD origin/main 2>/dev/null) && [ "$merge" != "$head" ]; then
        BASE=$merge
        BASE_WHY="$BASE_WHY; falling back to the merge base with origin/main"
    elif BASE=$(git rev-parse -q --verify 'HEAD^1'); then
        BASE_WHY="$BASE_WHY; falling back to HEAD's first parent: only the last commit is tested"
    else
        BASE=
        BASE_WHY="$BASE_WHY, no origin/main to diff against and HEAD has no parent"
    fi
}

# The oldest commit from which on every change up to BASE went through a passing CI run's
# mutation stage, for a BASE read from .ci/last-tested: each recorded commit's own tree names the
# commit its CI run diffed against, and the walk goes back while that is an ancestor.
coverage_start() {
    local start prev
    start=$(git rev-parse "$1")
    for _ in $(seq 10000); do
        prev=$(recorded_pass "$start")
        if [ -z "$prev" ] || [ "$prev" = "$start" ] || ! git merge-base --is-ancestor "$prev" "$start"; then
            break
        fi
        start=$prev
    done
    echo "$start"
}
