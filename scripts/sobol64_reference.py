#!/usr/bin/env python3
"""Reference values of the Sobol sequence at 64-bit indices, computed independently of
scripts/gen_sobol.py, for the test `agrees_with_the_python_reference_past_2_32` (sobol.rs).

Usage (from the repository root):

    python3 scripts/sobol64_reference.py            # rewrite the reference file
    python3 scripts/sobol64_reference.py --check    # exit 1 if it is stale

gen_sobol.py runs Joe and Kuo's recurrence on shifted direction numbers V_k in fixed-width words.
This script instead runs Bratley and Fox's recurrence on the odd integers m_k themselves, as
Python big integers (P. Bratley and B. L. Fox, "Algorithm 659: Implementing Sobol's
quasirandom sequence generator", ACM TOMS 14, 1988):

    m_k = 2 a_1 m_{k-1} ^ 2^2 a_2 m_{k-2} ^ ... ^ 2^{s-1} a_{s-1} m_{k-s+1} ^ 2^s m_{k-s} ^ m_{k-s}

and point i of a dimension as the exact binary fraction x = XOR over the set bits k of i of
m_{k+1} / 2^{k+1}, summed as an integer over the common denominator 2^64. The file holds
floor(x * 2^32), the 32-bit value nyquist's `sobol_u64` returns, for chosen indices from 2^32 to
2^64 - 1 in 16 dimensions. Standard library only.
"""

import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "data", "sobol", "new-joe-kuo-6.1024.txt")
OUT = os.path.join(ROOT, "core", "src", "sequence", "sobol64_reference.txt")
DIMS = [0, 1, 2, 3, 4, 7, 15, 16, 63, 64, 100, 255, 256, 511, 700, 1023]


def m_integers(s, a, m0, count=64):
    m = list(m0)
    for k in range(s, count):
        x = m[k - s] ^ (m[k - s] << s)
        for j in range(1, s):
            if (a >> (s - 1 - j)) & 1:
                x ^= m[k - j] << j
        m.append(x)
    return m


def lines_by_dim():
    with open(DATA, encoding="ascii") as f:
        rows = f.read().split("\n")[1:]
    out = {0: [1] * 64}  # van der Corput: every m_k is 1
    for line in rows:
        fields = [int(x) for x in line.split()]
        if fields:
            d, s, a = fields[0] - 1, fields[1], fields[2]
            out[d] = m_integers(s, a, fields[3:])
    return out


def point(m, index):
    x = 0
    k = 0
    while index:
        if index & 1:
            x ^= m[k] << (64 - (k + 1))
        index >>= 1
        k += 1
    return x >> 32


def indices():
    out = [1 << 32, (1 << 32) + 1, (1 << 33) - 1, (1 << 36) + 5, 1 << 40, (1 << 40) + 12345,
           (1 << 48) - 1, 1 << 63, (1 << 64) - 1, 0xDEAD_BEEF_0123_4567]
    x = 0x9E37_79B9_7F4A_7C15
    while len(out) < 24:  # a fixed 64-bit LCG (Knuth's MMIX constants)
        x = (x * 6364136223846793005 + 1442695040888963407) % (1 << 64)
        out.append(x | (1 << 32))
    return out


def main():
    m = lines_by_dim()
    text = ["# dim index value: floor(2^32 x), x the Sobol point (scripts/sobol64_reference.py)"]
    for d in DIMS:
        for i in indices():
            text.append(f"{d} {i} {point(m[d], i)}")
    text = "\n".join(text) + "\n"
    if "--check" in sys.argv[1:]:
        with open(OUT, encoding="utf-8") as f:
            if f.read() != text:
                print(f"{OUT} is stale: run python3 scripts/sobol64_reference.py", file=sys.stderr)
                sys.exit(1)
        return
    with open(OUT, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)


if __name__ == "__main__":
    main()
