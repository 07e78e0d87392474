#!/usr/bin/env bash
# Builds the size probes for thumbv7em-none-eabihf (Cortex-M4F) and wasm32-unknown-unknown,
# prints each probe's .text + .rodata + .data against its budget, checks that the f32-only
# probes link no software f64 routine, and runs the probes on an emulated Cortex-M4 (QEMU's
# mps2-an386, semihosting) to compare their values bit for bit with the host's. Exits non-zero
# on a probe over budget, a forbidden symbol, or a value that differs. A target or QEMU that
# cannot be installed is skipped with a line starting `SKIPPED:`.
#
# Usage: tests/size-probes/run.sh            (from anywhere; honours CARGO_TARGET_DIR)
#        NO_QEMU=1 tests/size-probes/run.sh  (sizes only)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cd "$here"

# Probe, budget in bytes, and whether it must be free of f64 routines (`f32`; `f64`: the
# probe's constructor computes in f64, software routines on a single-precision FPU). The
# `*_sampler` and `lattice_*` probes are camera-sample loops (`camera_sample`, `get_1d`,
# `get_2d`): 16 KB each, 8 KB for Owen-Sobol and ZSobol; 64 KB for the blue-noise Owen-Sobol and
# lattice, each with its 48 KiB tile and no other probe with any.
budgets=(
    "halton2 4096 f32"
    "halton16 8192 f32"
    "sobol4 4096 f32"
    "owen4 12288 f32"
    "pmj02 8192 f32"
    "stratify 4096 f32"
    "stratified_sampler 8192 f32"
    "mitchell 8192 f32"
    "owen_sampler 8192 f32"
    "zsobol_sampler 8192 f32"
    "sobol_sampler 16384 f32"
    "pmj02_sampler 16384 f32"
    "halton_sampler_none 16384 f32"
    "halton_sampler_permute 16384 f32"
    "halton_sampler_fast_owen 16384 f32"
    "halton_sampler_owen 16384 f32"
    "lattice_fibonacci 16384 f32"
    "lattice_korobov 16384 f64"
    "lattice_r2 16384 f64"
    "random_sampler 16384 f32"
    "owen_sobol_bn_sampler 65536 f32"
    "lattice_bn_sampler 65536 f32"
)
wasm_budget=8192
thumb=thumbv7em-none-eabihf

# Where cargo puts this crate's builds (CARGO_TARGET_DIR, or the crate's own target/).
target_dir=$(cargo metadata --format-version 1 --no-deps |
    sed -n 's/.*"target_directory":"\([^"]*\)".*/\1/p')
sysroot=$(rustc --print sysroot)
host=$(rustc -vV | sed -n 's/^host: //p')
tools=$sysroot/lib/rustlib/$host/bin
if [[ ! -x $tools/llvm-size ]]; then
    timeout 180 rustup component add llvm-tools >/dev/null 2>&1 || true
fi
size_tool=$tools/llvm-size
nm_tool=$tools/llvm-nm
[[ -x $size_tool ]] || size_tool=$(command -v llvm-size || true)
[[ -x $nm_tool ]] || nm_tool=$(command -v llvm-nm || true)
if [[ -z $size_tool || -z $nm_tool ]]; then
    echo "SKIPPED: no llvm-size/llvm-nm (rustup component add llvm-tools); sizes not checked"
    exit 0
fi

have_target() {
    rustup target list --installed 2>/dev/null | grep -qx "$1" ||
        timeout 180 rustup target add "$1" >/dev/null 2>&1
}

failed=0
if have_target "$thumb"; then
    cargo build --quiet --release --target "$thumb"
    printf '%-26s %8s %8s  %s\n' probe bytes budget result
    for entry in "${budgets[@]}"; do
        read -r probe budget float <<<"$entry"
        elf=$target_dir/$thumb/release/$probe
        bytes=$("$size_tool" -A "$elf" |
            awk '$1 == ".text" || $1 == ".rodata" || $1 == ".data" { s += $2 } END { print s + 0 }')
        result=ok
        if ((bytes > budget)); then
            result=OVER
            failed=1
        fi
        # Software double-precision routines: __aeabi_d*, __aeabi_*2d, __*df3 / __*df2 and
        # the conversions (also as the mangled names of compiler_builtins' definitions).
        if [[ $float == f32 ]]; then
            soft=$("$nm_tool" "$elf" | awk '{ print $NF }' |
                grep -E '(__aeabi_d[a-z0-9]+|__aeabi_[a-z0-9]+2d|__[a-z]+df[0-9]|__truncdfsf2)$' |
                tr '\n' ' ' || true)
            if [[ -n $soft ]]; then
                result="$result, f64 routines: $soft"
                failed=1
            fi
        fi
        printf '%-26s %8d %8d  %s\n' "$probe" "$bytes" "$budget" "$result"
    done
else
    echo "SKIPPED: rustup could not install $thumb; the Cortex-M probes were not built"
fi

if have_target wasm32-unknown-unknown; then
    (cd wasm && cargo build --quiet --release --target wasm32-unknown-unknown)
    wasm_dir=$(cd wasm && cargo metadata --format-version 1 --no-deps |
        sed -n 's/.*"target_directory":"\([^"]*\)".*/\1/p')
    bytes=$(wc -c <"$wasm_dir/wasm32-unknown-unknown/release/nyquist_wasm_probe.wasm")
    result=ok
    if ((bytes > wasm_budget)); then
        result=OVER
        failed=1
    fi
    printf '%-26s %8d %8d  %s\n' wasm-halton2 "$bytes" "$wasm_budget" "$result"
else
    echo "SKIPPED: rustup could not install wasm32-unknown-unknown; the WASM probe was not built"
fi

# The same probes on an emulated Cortex-M4, values against the host's table paths.
if [[ -n ${NO_QEMU:-} ]]; then
    echo "SKIPPED: QEMU run (NO_QEMU is set)"
elif ! rustup target list --installed 2>/dev/null | grep -qx "$thumb"; then
    echo "SKIPPED: QEMU run (no $thumb target)"
else
    if ! command -v qemu-system-arm >/dev/null && command -v apt-get >/dev/null &&
        [[ $(id -u) == 0 ]]; then
        echo "installing qemu-system-arm (apt-get)"
        { timeout 300 apt-get update && DEBIAN_FRONTEND=noninteractive \
            timeout 600 apt-get install -y --no-install-recommends qemu-system-arm; } \
            >/dev/null 2>&1 || true
    fi
    if ! command -v qemu-system-arm >/dev/null; then
        echo "SKIPPED: qemu-system-arm is not installed and could not be installed (Debian: apt-get install qemu-system-arm); the probes were not run"
    else
        qemu_dir=$target_dir/qemu-probes
        cargo build --quiet --release --target "$thumb" --features qemu --target-dir "$qemu_dir"
        (cd host && cargo build --quiet --release)
        host_dir=$(cd host && cargo metadata --format-version 1 --no-deps |
            sed -n 's/.*"target_directory":"\([^"]*\)".*/\1/p')
        scratch=$(mktemp -d)
        trap 'rm -rf "$scratch"' EXIT
        for entry in "${budgets[@]}"; do
            read -r probe _ <<<"$entry"
            # Semihosting writes to QEMU's stderr.
            timeout 300 qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
                -semihosting-config enable=on,target=native \
                -kernel "$qemu_dir/$thumb/release/$probe" >/dev/null 2>"$scratch/$probe.arm" || true
            "$host_dir/release/nyquist-probe-host" "$probe" >"$scratch/$probe.host"
            values=$(($(wc -l <"$scratch/$probe.host") - 1))
            if cmp -s "$scratch/$probe.arm" "$scratch/$probe.host"; then
                printf 'qemu %-26s %5d values, bit for bit the host'"'"'s\n' "$probe" "$values"
            else
                printf 'qemu %-26s DIFFERS from the host:\n' "$probe"
                diff "$scratch/$probe.arm" "$scratch/$probe.host" | head -10
                failed=1
            fi
        done
    fi
fi

exit "$failed"
