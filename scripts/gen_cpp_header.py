#!/usr/bin/env python3
"""Write the generated block of gpu/cpp/nyquist.hpp: the Joe-Kuo Sobol parameters.

Usage (from the repository root):

    python3 scripts/gen_cpp_header.py            # rewrite the block in place
    python3 scripts/gen_cpp_header.py --check    # exit 1 if the checked-in block is stale

Input: data/sobol/new-joe-kuo-6.1024.txt, read by scripts/gen_sobol.py's parser (S. Joe and
F. Y. Kuo 2008, the first 1024 dimensions of new-joe-kuo-6.21201; see data/sobol/README.md and
licenses/joe-kuo.txt).

The block holds, for dimensions 1 .. 1023, Joe and Kuo's `s` (degree of the primitive
polynomial), `a` (its inner coefficients) and the initial direction numbers `m_1 .. m_s`, flat:
`s, a, m_1, ..., m_s` per dimension. The header turns them into generator matrices at compile
time, only for the dimensions a program names (the recurrence is the one gen_sobol.py documents).
Everything outside the markers is written by hand. Standard library only.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_sobol  # noqa: E402  (the same parser and validation as the Rust table)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HEADER = os.path.join(ROOT, "gpu", "cpp", "nyquist.hpp")
BEGIN = "// @generated begin: scripts/gen_cpp_header.py"
END = "// @generated end"


def render(dims):
    count = sum(2 + s for s, _, _ in dims)
    out = [
        BEGIN,
        "// From data/sobol/new-joe-kuo-6.1024.txt (Joe & Kuo 2008, new-joe-kuo-6.21201, first 1024",
        "// dimensions; attribution in licenses/joe-kuo.txt). Do not edit by hand: run",
        "// `python3 scripts/gen_cpp_header.py`. Per dimension 1 .. 1023: s, a, m_1 .. m_s.",
        f"constexpr std::uint32_t kJoeKuoDims = {len(dims) + 1};",
        f"constexpr std::uint16_t kJoeKuo[{count}] = {{",
    ]
    for d, (s, a, m) in enumerate(dims, start=1):
        fields = ", ".join(str(x) for x in [s, a] + m)
        out.append(f"    {fields},  // {d}")
    out.append("};")
    out.append(END)
    return "\n".join(out)


def main():
    dims = gen_sobol.parse()
    block = render(dims)
    with open(HEADER, encoding="utf-8") as f:
        text = f.read()
    start = text.find(BEGIN)
    end = text.find(END)
    if start < 0 or end < start:
        raise SystemExit(f"{HEADER}: the generated-block markers are missing")
    new = text[:start] + block + text[end + len(END):]
    if "--check" in sys.argv[1:]:
        if new != text:
            print(f"{HEADER} is stale: run python3 scripts/gen_cpp_header.py", file=sys.stderr)
            sys.exit(1)
        return
    if new != text:
        with open(HEADER, "w", encoding="utf-8", newline="\n") as f:
            f.write(new)


if __name__ == "__main__":
    main()
