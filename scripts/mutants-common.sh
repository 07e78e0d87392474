# shellcheck shell=bash
# Helpers shared by the scripts/mutants*.sh scripts (sourced).

EQUIVALENT=${EQUIVALENT:-scripts/mutants-equivalent.txt}
MODULES_FILE=${MODULES_FILE:-scripts/mutants-modules.txt}

# The number of non-empty lines of a file (0 when it is missing or empty).
count() { if [ -s "$1" ]; then grep -c . "$1"; else echo 0; fi; }

# The package of a source file: its row's in scripts/mutants-modules.txt, else by its folder.
package_of() {
    local p
    p=$(grep -v '^#' "$MODULES_FILE" | awk -F'|' -v f="$1" '$3 == f { print $2; exit }')
    if [ -n "$p" ]; then
        echo "$p"
    else
        case $1 in std-film/*) echo nyquist-film ;; *) echo nyquist ;; esac
    fi
}

# The files scripts/mutants-equivalent.txt has entries for, one a line.
equivalent_files() { grep -v -e '^#' -e '^[[:space:]]*$' "$EQUIVALENT" | cut -d: -f1 | sort -u; }

# Every mutant of FILE... in the working tree, one name a line, as `cargo mutants --list` names
# them (one call per package).
list_mutants() {
    local f pkg
    declare -A by_pkg=()
    for f in "$@"; do
        [ -f "$f" ] || continue
        pkg=$(package_of "$f")
        by_pkg[$pkg]+=" --file $f"
    done
    for pkg in "${!by_pkg[@]}"; do
        # shellcheck disable=SC2086 # the --file arguments
        cargo mutants --list --package "$pkg" ${by_pkg[$pkg]} </dev/null 2>/dev/null
    done
}

# awk functions shared by equivalent_resolve and equivalent_entry.
# shellcheck disable=SC2016 # awk code, not shell expansions
ANCHOR_AWK='
function trim(s) { sub(/^[ \t]+/, "", s); sub(/[ \t]+$/, "", s); return s }
# A line as an anchor: trimmed, without a trailing `// comment` (one after whitespace, outside a
# string: an even number of quotes before it), so editing a comment does not move an entry.
function anchor_of(s,    p, q, before) {
    s = trim(s)
    if (match(s, /[ \t]+\/\//)) {
        before = substr(s, 1, RSTART - 1)
        q = gsub(/"/, "\"", before)
        if (q % 2 == 0) s = before
    }
    return s
}
'

# Resolves the entries of scripts/mutants-equivalent.txt to the mutants they name in one tree.
#
#   equivalent_resolve MODE ROOT MUTANTS [FILE...]
#
# An entry is one equivalent mutant: its name as cargo-mutants prints it, with line and column,
# then "  @ " and the text of its line (trimmed), then "  # " and why it is equivalent. The line
# text anchors the entry when code moves: an entry names the mutant of its name (without the
# position) on a line of its file whose text is the anchor, at the entry's column (or, on a
# re-indented line, the same number of mutants of that name as entries name there). Entries that
# share file, name and anchor are resolved together: at their recorded positions when those still
# hold, else to the sites found, paired in order. An entry resolves when its group finds exactly
# as many sites as it has entries; otherwise the entry matches more or fewer sites than it says.
#
# ROOT is the folder the listed files are read from; MUTANTS a file of the tree's mutant names
# (all of each file's, for `check`), one a line; FILE... limits the entries to these files.
#   names     prints the name (with position) of every mutant an entry resolves to
#   check     prints every entry that does not resolve and every entry whose mutant moved;
#             exit status 1 when some entry does not resolve
#   reanchor  prints the list with each resolved entry's position set to where its mutant is now
equivalent_resolve() {
    local mode=$1 root=$2 mutants=$3
    shift 3
    local sources=() files=() f
    if [ $# -eq 0 ]; then mapfile -t files < <(equivalent_files); else files=("$@"); fi
    for f in "${files[@]}"; do
        [ -f "$root/$f" ] && sources+=("$root/$f")
    done
    awk -v mode="$mode" -v eq="$EQUIVALENT" -v mutants="$mutants" -v root="$root" \
        -v only="${files[*]}" -f <(printf '%s' "$ANCHOR_AWK") -f /dev/fd/3 \
        "$EQUIVALENT" "$mutants" "${sources[@]}" 3<<'AWK'
# "F:L:C: NAME" -> P_f, P_l, P_c, P_n; 0 when it is not such a name.
function parse(s,    p, r) {
    p = index(s, ":"); if (p == 0) return 0
    P_f = substr(s, 1, p - 1); r = substr(s, p + 1)
    p = index(r, ":"); if (p == 0) return 0
    P_l = substr(r, 1, p - 1); r = substr(r, p + 1)
    p = index(r, ": "); if (p == 0) return 0
    P_c = substr(r, 1, p - 1); P_n = substr(r, p + 2)
    return P_l ~ /^[0-9]+$/ && P_c ~ /^[0-9]+$/
}
function before(l1, c1, l2, c2) { return l1 < l2 || (l1 == l2 && c1 < c2) }
BEGIN {
    n = split(only, o, " ")
    for (i = 1; i <= n; i++) wanted[o[i]] = 1
}
FILENAME == eq {
    text[FNR] = $0; nlines = FNR
    if ($0 ~ /^#/ || $0 ~ /^[ \t]*$/) next
    a = index($0, "  @ ")
    if (a == 0 || !parse(substr($0, 1, a - 1))) {
        if (!(substr($0, 1, index($0, ":") - 1) in wanted)) next
        problem[++nproblems] = eq ":" FNR ": not \"FILE:LINE:COLUMN: NAME  @ LINE TEXT  # REASON\": " $0
        next
    }
    if (!(P_f in wanted)) next
    rest = substr($0, a + 4)
    b = index(rest, "  # ")
    anchor = anchor_of(b ? substr(rest, 1, b - 1) : rest)
    E_f[FNR] = P_f; E_l[FNR] = P_l + 0; E_c[FNR] = P_c + 0; E_n[FNR] = P_n; E_a[FNR] = anchor
    g = P_f SUBSEP P_n SUBSEP anchor
    if (!(g in gsize)) { groups[++ngroups] = g }
    gsize[g]++; gmember[g, gsize[g]] = FNR
    next
}
FILENAME == mutants {
    if (parse($0)) at[P_f, P_l + 0, P_n] = at[P_f, P_l + 0, P_n] " " (P_c + 0)
    next
}
{
    f = substr(FILENAME, length(root) + 2)
    t = anchor_of($0)
    lines_of[f, t] = lines_of[f, t] " " FNR
}
END {
    for (gi = 1; gi <= ngroups; gi++) {
        g = groups[gi]; k = gsize[g]
        e1 = gmember[g, 1]; f = E_f[e1]; nm = E_n[e1]; anchor = E_a[e1]
        split("", cols); ncols = 0
        for (m = 1; m <= k; m++) {
            e = gmember[g, m]
            if (!(E_c[e] in cols)) { cols[E_c[e]] = 1; ncols++ }
        }
        # The sites: on each line whose text is the anchor, the mutants of this name at the
        # entries' columns, or, where none is (a re-indented line), all of them if they are as
        # many as the entries' columns.
        ns = 0; split("", here)
        nl = split(lines_of[f, anchor], ls, " ")
        for (i = 1; i <= nl; i++) {
            ln = ls[i] + 0
            nc = split(at[f, ln, nm], cs, " ")
            exact = 0
            for (j = 1; j <= nc; j++) if ((cs[j] + 0) in cols) exact++
            for (j = 1; j <= nc; j++) {
                if (exact > 0 && !((cs[j] + 0) in cols)) continue
                if (exact == 0 && nc != ncols) continue
                ns++; S_l[ns] = ln; S_c[ns] = cs[j] + 0; here[ln, cs[j] + 0] = ns
            }
        }
        # In order of position, for pairing.
        for (i = 2; i <= ns; i++) {
            l = S_l[i]; c = S_c[i]
            for (j = i - 1; j >= 1 && before(l, c, S_l[j], S_c[j]); j--) { S_l[j + 1] = S_l[j]; S_c[j + 1] = S_c[j] }
            S_l[j + 1] = l; S_c[j + 1] = c
        }
        for (i = 1; i <= k; i++) order[i] = gmember[g, i]
        for (i = 2; i <= k; i++) {
            e = order[i]
            for (j = i - 1; j >= 1 && before(E_l[e], E_c[e], E_l[order[j]], E_c[order[j]]); j--) order[j + 1] = order[j]
            order[j + 1] = e
        }
        recorded = 1
        for (i = 1; i <= k; i++) {
            e = order[i]
            if (!((E_l[e], E_c[e]) in here) || (i > 1 && E_l[e] == E_l[order[i - 1]] && E_c[e] == E_c[order[i - 1]])) recorded = 0
        }
        if (!recorded && ns != k) {
            for (i = 1; i <= k; i++) {
                e = order[i]
                problem[++nproblems] = eq ":" e ": " E_f[e] ":" E_l[e] ":" E_c[e] ": " E_n[e] \
                    ": its anchor finds " ns " mutant" (ns == 1 ? "" : "s") " of this name, the list names " k \
                    " (" (nl == 0 ? "no line of " f " reads `" anchor "`" : "on " nl " line" (nl == 1 ? "" : "s") " reading `" anchor "`") ")"
            }
            continue
        }
        for (i = 1; i <= k; i++) {
            e = order[i]
            if (recorded) { R_l[e] = E_l[e]; R_c[e] = E_c[e] } else { R_l[e] = S_l[i]; R_c[e] = S_c[i] }
            resolved[e] = 1
            if (R_l[e] != E_l[e] || R_c[e] != E_c[e]) {
                moved[++nmoved] = eq ":" e ": " E_f[e] ":" E_l[e] ":" E_c[e] ": " E_n[e] " is now at " R_l[e] ":" R_c[e]
            }
        }
    }
    if (mode == "names") {
        for (e = 1; e <= nlines; e++) if (e in resolved) print E_f[e] ":" R_l[e] ":" R_c[e] ": " E_n[e]
    } else if (mode == "reanchor") {
        for (e = 1; e <= nlines; e++) {
            if (e in resolved) {
                a = index(text[e], "  @ ")
                print E_f[e] ":" R_l[e] ":" R_c[e] ": " E_n[e] substr(text[e], a)
            } else print text[e]
        }
    } else {
        for (i = 1; i <= nmoved; i++) print "moved: " moved[i]
        for (i = 1; i <= nproblems; i++) print "NOT RESOLVED: " problem[i]
        nres = 0; for (e in resolved) nres++
        print "EQUIVALENT " nres " entries resolved, " (nmoved + 0) " moved (scripts/mutants-equivalent.sh --reanchor), " (nproblems + 0) " not resolved"
    }
    exit nproblems > 0 ? 1 : 0
}
AWK
}

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
# shellcheck disable=SC2034 # BASE, BASE_WHY and BASE_RECORDED are the callers' to read
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

# The mutants the equivalent list's entries for FILE name, one a line with position, in FILE as
# at COMMIT (the working tree when COMMIT is empty or `uncommitted`), among the mutant names in
# MUTANTS (a file, one a line). Entries that do not resolve name nothing (see
# scripts/mutants-equivalent.sh).
equivalent_sites() {
    local file=$1 commit=$2 mutants=$3 root=.
    local tmp
    tmp=$(mktemp -d)
    if [ -n "$commit" ] && [ "$commit" != uncommitted ]; then
        root=$tmp
        mkdir -p "$tmp/$(dirname "$file")"
        git show "$commit:$file" >"$tmp/$file" 2>/dev/null || rm -f "$tmp/$file"
    fi
    equivalent_resolve names "$root" "$mutants" "$file" || true
    rm -rf "$tmp"
}

# The entry line for each mutant NAME given (with position), as scripts/mutants-equivalent.txt
# takes it, its reason left to write: "NAME  @ LINE TEXT  # ".
equivalent_entry() {
    local name file line
    for name in "$@"; do
        file=${name%%:*}
        line=${name#*:}
        line=${line%%:*}
        # shellcheck disable=SC2016 # awk code, not shell expansions
        printf '%s  @ %s  # \n' "$name" "$(awk -v n="$line" -f <(printf '%s' "$ANCHOR_AWK") \
            -f <(echo 'NR == n { print anchor_of($0); exit }') "$file")"
    done
}
