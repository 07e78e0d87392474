#!/bin/sh
# Extracts the peers' source trees from git repositories you supply, for the peer benchmark.
#
#   peers/fetch-snapshots.sh DEST [openqmc=REPO[@REV]] [pbrt-v4=REPO[@REV]] [pbrt-v3=REPO[@REV]]
#
# REPO is a clone (or a bare repository) of AcademySoftwareFoundation/openqmc, mmp/pbrt-v4 or
# mmp/pbrt-v3; REV defaults to HEAD. Each tree goes to DEST/NAME, replacing what was there, and
# the script prints the variables to export. Files whose contents the repository lacks (a
# partial clone) are left out with a warning; submodules are not needed and not extracted.
set -eu

usage() {
    echo "usage: $0 DEST [openqmc=REPO[@REV]] [pbrt-v4=REPO[@REV]] [pbrt-v3=REPO[@REV]]" >&2
    exit 2
}
[ $# -ge 2 ] || usage
dest=$1
shift
mkdir -p "$dest"
dest=$(cd "$dest" && pwd)
exports=""

for arg in "$@"; do
    name=${arg%%=*}
    spec=${arg#*=}
    case $name in
        openqmc) var=NYQUIST_OPENQMC ;;
        pbrt-v4) var=NYQUIST_PBRT_V4 ;;
        pbrt-v3) var=NYQUIST_PBRT_V3 ;;
        *) usage ;;
    esac
    repo=${spec%@*}
    rev=HEAD
    [ "$repo" = "$spec" ] || rev=${spec##*@}
    gitdir=$(git -C "$repo" rev-parse --absolute-git-dir)
    commit=$(git --git-dir="$gitdir" rev-parse "$rev^{commit}")
    out="$dest/$name"
    rm -rf "$out"
    mkdir -p "$out"
    if ! git --git-dir="$gitdir" archive "$commit" 2>/dev/null | tar -x -C "$out" 2>/dev/null; then
        # Some contents are missing: extract file by file and leave those out.
        rm -rf "$out"
        mkdir -p "$out"
        git --git-dir="$gitdir" ls-tree -r "$commit" | while read -r mode type object path; do
            [ "$type" = blob ] || continue
            mkdir -p "$out/$(dirname "$path")"
            if ! git --git-dir="$gitdir" cat-file blob "$object" >"$out/$path" 2>/dev/null; then
                rm -f "$out/$path"
                echo "warning: $name: $path is missing from $repo; left out" >&2
            fi
        done
    fi
    echo "$commit" >"$out/.snapshot-commit"
    echo "$name: $commit -> $out" >&2
    exports="$exports
export $var=$out"
done
echo "# for the peer benchmark:$exports"
