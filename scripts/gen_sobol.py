#!/usr/bin/env python3
"""Generate core/src/sequence/sobol_table.rs from the Joe-Kuo direction numbers.

Usage (from the repository root):

    python3 scripts/gen_sobol.py            # rewrite the table
    python3 scripts/gen_sobol.py --check    # exit 1 if the checked-in table is stale

Input: data/sobol/new-joe-kuo-6.1024.txt (S. Joe and F. Y. Kuo, "Constructing Sobol sequences
with better two-dimensional projections", SIAM J. Sci. Comput. 30, 2635-2654, 2008; the first
1024 dimensions of new-joe-kuo-6.21201; see data/sobol/README.md and licenses/joe-kuo.txt).

Each line after the header is `d s a m_1 .. m_s`. The 32 direction numbers of a dimension are
V_k = m_k * 2^(32-k) for k <= s and, for k > s,

    V_k = a_1 V_{k-1} ^ a_2 V_{k-2} ^ ... ^ a_{s-1} V_{k-s+1} ^ V_{k-s} ^ (V_{k-s} >> s)

with a_1 the most significant of the s-1 bits of `a`. Dimension 0 (no line in the file) is the
van der Corput sequence: V_k = 2^(32-k).

The table row for dimension d holds V_1 .. V_32: entry k (0-based) is the direction number
XOR-ed in when bit k of the index is set.

For indices past 2^32 the script also writes SOBOL_MATRICES_HI, the columns V_33 .. V_64 read to
32 bits: the same recurrence run on 64-bit words (V_k = m_k * 2^(64-k), exact for every k <= 64),
each word's upper half. Columns 1 .. 32 of that run equal the 32-bit table (checked here).
`scripts/sobol64_reference.py` checks the result against an independent computation. Standard
library only.
"""

import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "data", "sobol", "new-joe-kuo-6.1024.txt")
OUT = os.path.join(ROOT, "core", "src", "sequence", "sobol_table.rs")
DIMS = 1024
BITS = 32
MASK = (1 << BITS) - 1


def direction_numbers(s, a, m, bits=BITS):
    mask = (1 << bits) - 1
    v = [0] * (bits + 1)  # 1-based
    for k in range(1, bits + 1):
        if k <= s:
            v[k] = (m[k - 1] << (bits - k)) & mask
        else:
            x = v[k - s] ^ (v[k - s] >> s)
            for j in range(1, s):
                if (a >> (s - 1 - j)) & 1:
                    x ^= v[k - j]
            v[k] = x
    return v[1:]


def parse():
    """(s, a, m) per dimension 1 .. DIMS - 1, validated."""
    dims = []
    with open(DATA, encoding="ascii") as f:
        lines = f.read().split("\n")
    for line in lines[1:]:
        fields = line.split()
        if not fields:
            continue
        d, s, a = int(fields[0]), int(fields[1]), int(fields[2])
        m = [int(x) for x in fields[3:]]
        if d != len(dims) + 2 or len(m) != s:
            raise SystemExit(f"malformed line for dimension {d}: {line!r}")
        for k, mk in enumerate(m, start=1):
            if mk % 2 != 1 or mk >= (1 << k):
                raise SystemExit(f"dimension {d}: m_{k} = {mk} is not odd and below 2^{k}")
        dims.append((s, a, m))
    if len(dims) != DIMS - 1:
        raise SystemExit(f"expected {DIMS} dimensions, got {len(dims) + 1}")
    return dims


def matrices(dims):
    rows = [[1 << (BITS - k) for k in range(1, BITS + 1)]]
    for s, a, m in dims:
        rows.append(direction_numbers(s, a, m))
    return rows


def high_matrices(dims, rows):
    """Columns V_33 .. V_64 to 32 bits, from the recurrence on 64-bit words."""
    wide = [[1 << (64 - k) for k in range(1, 65)]]
    for s, a, m in dims:
        wide.append(direction_numbers(s, a, m, 64))
    high = []
    for d, (row, w) in enumerate(zip(rows, wide)):
        if [x >> 32 for x in w[:BITS]] != row:
            raise SystemExit(f"dimension {d}: the 64-bit run disagrees with the 32-bit table")
        high.append([x >> 32 for x in w[BITS:]])
    return high


def render_directions(dims):
    """SOBOL_DIRECTION_BITS: a bit stream, least significant bit of each byte first; per
    dimension 1 .. DIMS - 1, each field least significant bit first: s in 4 bits, a in s - 1
    bits, then for k = 1 .. s, (m_k - 1) / 2 in k - 1 bits (every m_k is odd and below 2^k)."""
    stream = []  # one int per bit

    def put(value, n):
        if value >> n:
            raise SystemExit(f"{value} does not fit {n} bits")
        stream.extend((value >> i) & 1 for i in range(n))

    for s, a, m in dims:
        put(s, 4)
        put(a, s - 1)
        for k, mk in enumerate(m, start=1):
            if mk % 2 == 0:
                raise SystemExit(f"m_{k} = {mk} is even")
            put(mk >> 1, k - 1)
    stream.extend([0] * (-len(stream) % 8))
    data = [sum(stream[i + j] << j for j in range(8)) for i in range(0, len(stream), 8)]
    out = [
        "",
        "/// The same direction numbers packed for [`SOBOL_MATRICES`]' construction at first use",
        "/// (feature `lazy-tables`), as a bit stream read least significant bit first: for each",
        "/// dimension from 1, Joe and Kuo's `s` in 4 bits, `a` in `s − 1` bits, then `(m_k − 1)/2`",
        "/// in `k − 1` bits for `k = 1 ..= s` (each `m_k` is odd and below `2^k`).",
        '#[cfg(any(feature = "lazy-tables", test))]',
        "#[rustfmt::skip]",
        f"pub(crate) static SOBOL_DIRECTION_BITS: [u8; {len(data)}] = [",
    ]
    for i in range(0, len(data), 20):
        out.append("    " + " ".join(f"{w}," for w in data[i:i + 20]))
    out.append("];")
    return "\n".join(out) + "\n"


def render_rows(rows, out):
    for d, row in enumerate(rows):
        first = ", ".join(f"0x{x:08x}" for x in row[:16])
        second = ", ".join(f"0x{x:08x}" for x in row[16:])
        out.append(f"    // dimension {d}")
        out.append(f"    [{first},")
        out.append(f"     {second}],")
    out.append("];")
    return "\n".join(out) + "\n"


def render_header():
    return [
        "//! Sobol direction numbers, generated by `scripts/gen_sobol.py` from",
        "//! `data/sobol/new-joe-kuo-6.1024.txt` (Joe & Kuo 2008, `new-joe-kuo-6.21201`, first 1024",
        "//! dimensions; attribution in `licenses/joe-kuo.txt`). Do not edit by hand: run",
        "//! `python3 scripts/gen_sobol.py`. The unit test `table_is_current` in `sobol.rs` recomputes",
        "//! every entry from the data file with the same recurrence.",
        "",
        "/// `SOBOL_MATRICES[d][k]` is direction number `V_{k+1}` of dimension `d`: the generator-matrix",
        "/// column XOR-ed into the result when bit `k` of the index is set. With the `lazy-tables`",
        "/// feature the library reads the same table built at first use from [`SOBOL_DIRECTION_BITS`]",
        "/// (`sobol_lazy.rs`); tests still compile this one to compare the two.",
        '#[cfg(any(not(feature = "lazy-tables"), test))]',
        "#[rustfmt::skip]",
        f"pub(crate) static SOBOL_MATRICES: [[u32; {BITS}]; {DIMS}] = [",
    ]


def render_high():
    return [
        "",
        "/// `SOBOL_MATRICES_HI[d][k]` is direction number `V_{k+33}` of dimension `d` to 32 bits: the",
        "/// column XOR-ed in when bit `k + 32` of a 64-bit index is set (the recurrence run on 64-bit",
        "/// words, each word's upper half; dimension 0's are all zero). With `lazy-tables` the library",
        "/// builds the same table at first use (`sobol_lazy.rs`).",
        '#[cfg(any(not(feature = "lazy-tables"), test))]',
        "#[rustfmt::skip]",
        f"pub(crate) static SOBOL_MATRICES_HI: [[u32; {BITS}]; {DIMS}] = [",
    ]


def main():
    dims = parse()
    rows = matrices(dims)
    text = (
        render_rows(rows, render_header())
        + render_rows(high_matrices(dims, rows), render_high())
        + render_directions(dims)
    )
    if "--check" in sys.argv[1:]:
        with open(OUT, encoding="utf-8") as f:
            if f.read() != text:
                print(f"{OUT} is stale: run python3 scripts/gen_sobol.py", file=sys.stderr)
                sys.exit(1)
        return
    with open(OUT, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)


if __name__ == "__main__":
    main()
