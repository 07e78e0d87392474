#!/usr/bin/env bash
# The C library's size check (docs/c.md): builds the small static library (profile `capi`, no
# std, tables built at first use), links two C programs the way docs/c.md says (-Os,
# -ffunction-sections -fdata-sections, --gc-sections, stripped) and runs them:
#   capi/tests/c/size_halton.c      one Halton value (nyq_halton_sample)      budget 100 KB
#   capi/tests/c/size_owen_sobol.c  one Owen-Sobol sampler, one 2D sample     budget 150 KB
# (KB = 1000 bytes). Fails when a program is over its budget or prints other values than the
# core's; prints each size with its budget, and the sections (`size`: the bss column holds the
# tables built at first use, which take no room in the file). Without a C compiler it prints
# SKIPPED and passes. Respects CARGO_TARGET_DIR and CC (default cc).
set -euo pipefail
cd "$(dirname "$0")/.."

cc=${CC:-cc}
if ! command -v "$cc" >/dev/null; then
    echo "SKIPPED: no C compiler ($cc) on PATH; the C programs' sizes were not measured"
    exit 0
fi

build=(cargo rustc --profile capi -p nyquist-capi --no-default-features --features lazy-tables
    --lib --crate-type staticlib)
lib=$("${build[@]}" --quiet --message-format=json-render-diagnostics |
    grep -o '"[^"]*libnyquist_capi\.a"' | tail -1 | tr -d '"')
if [ ! -f "$lib" ]; then
    echo "${build[*]} reported no libnyquist_capi.a" >&2
    exit 1
fi
echo "static library: $lib, $(wc -c <"$lib") bytes"

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failed=0
# program, budget in bytes, what it must print (the f32 bits of the core's values: Halton's
# Φ₃(3) = 1/9; the Owen-Sobol sampler's, as nyq_sampler_create("owen-sobol", ...) gives them).
for check in "size_halton 100000 3de38e39" "size_owen_sobol 150000 3d1a9790 3db92998"; do
    read -r name budget expected <<<"$check"
    exe=$out/$name
    "$cc" -std=c99 -Os -ffunction-sections -fdata-sections -Icapi/include \
        "capi/tests/c/$name.c" "$lib" -Wl,--gc-sections -s -o "$exe"
    got=$("$exe") || { echo "$name failed: $got" >&2; failed=1; }
    if [ "$got" != "$expected" ]; then
        echo "$name printed '$got', expected '$expected'" >&2
        failed=1
    fi
    bytes=$(wc -c <"$exe")
    verdict=ok
    [ "$bytes" -le "$budget" ] || { verdict="OVER BUDGET"; failed=1; }
    printf '%-16s %7d bytes, budget %7d: %s\n' "$name" "$bytes" "$budget" "$verdict"
    if command -v size >/dev/null; then size "$exe" | sed 1d | awk '{ printf "%18s text %d, data %d, bss %d\n", "", $1, $2, $3 }'; fi
done
exit "$failed"
