#!/usr/bin/env python3
"""Generate nyquist's best-candidate sample table (core/src/sampler/best_candidate/table.rs).

Mitchell's best-candidate algorithm (D. P. Mitchell, "Spectrally optimal sampling for distribution
ray tracing", SIGGRAPH 1991), with toroidal distance so the pattern tiles, as pbrt-v2 describes for
its best-candidate sampler. Each point carries five values: image (x, y), time, lens (u, v).

Point i (i = 0, 1, ...):
  * image: of min(1 + K*i, MAX_CANDIDATES) uniform candidates, the one farthest (toroidal) from
    every earlier point; the first strictly farther candidate wins ties. Because the candidate
    count depends only on i, every prefix of the table is itself a best-candidate pattern (blue
    noise), and a table of n points is the first n rows of a longer one.
  * time, lens: of TL_CANDIDATES candidates, the one whose minimum toroidal distance (1D for time,
    2D for lens) to the time/lens values of the NEIGHBOURS nearest earlier points in image space is
    largest, so nearby image samples get different times and lens positions.

Random numbers: SplitMix64 (Steele, Lea & Flood 2014) from SEED; a float is (u >> 11) * 2^-53.
Every distance is computed in IEEE double with the same operations as the library's own
generator (core/src/sampler/best_candidate/generate.rs, used with the lazy-tables feature and
tested to give this whole table), so the output is bit-reproducible.

The table stores each value as floor(x * 65536) in a u16.

Usage: python3 scripts/gen_best_candidate.py [--check]   (stdlib only)
"""
import os
import sys

N = 4096
SEED = 0x6E79_7175_6973_7431  # "nyquist1"
K = 4
MAX_CANDIDATES = 4096
TL_CANDIDATES = 32
NEIGHBOURS = 8
MASK = (1 << 64) - 1
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "core", "src", "sampler",
                   "best_candidate", "table.rs")


class SplitMix64:
    def __init__(self, seed):
        self.s = seed & MASK

    def next(self):
        self.s = (self.s + 0x9E3779B97F4A7C15) & MASK
        z = self.s
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return z ^ (z >> 31)

    def unit(self):
        return (self.next() >> 11) * (1.0 / 9007199254740992.0)


def wrap(d):
    """Toroidal distance along one axis of the unit torus: min(|d|, 1 - |d|)."""
    d = abs(d)
    return 1.0 - d if d > 0.5 else d


def candidates(i):
    return min(1 + K * i, MAX_CANDIDATES)


G = 64  # grid of G x G cells over the image torus


def cell(v):
    c = int(v * G)
    return c if c < G else G - 1


def generate(n):
    rng = SplitMix64(SEED)
    pts = []  # [x, y, t, u, v]
    grid = [[] for _ in range(G * G)]
    for i in range(n):
        best = None
        best_d2 = -1.0
        for _ in range(candidates(i)):
            x = rng.unit()
            y = rng.unit()
            d2 = nearest_d2(pts, grid, x, y, best_d2)
            if d2 > best_d2:
                best_d2 = d2
                best = (x, y)
        x, y = best
        nbs = neighbours(pts, grid, x, y)
        # time: 1D toroidal distance to the neighbours' times
        bt, bd = 0.0, -1.0
        for _ in range(TL_CANDIDATES):
            t = rng.unit()
            d = 2.0
            for j in nbs:
                e = wrap(t - pts[j][2])
                if e < d:
                    d = e
            if d > bd:
                bd, bt = d, t
        bu, bv, bd = 0.0, 0.0, -1.0
        for _ in range(TL_CANDIDATES):
            u = rng.unit()
            v = rng.unit()
            d = 8.0
            for j in nbs:
                a = wrap(u - pts[j][3])
                b = wrap(v - pts[j][4])
                e = a * a + b * b
                if e < d:
                    d = e
            if d > bd:
                bd, bu, bv = d, u, v
        grid[cell(y) * G + cell(x)].append(len(pts))
        pts.append([x, y, bt, bu, bv])
    return pts


def nearest_d2(pts, grid, x, y, beat):
    """Squared toroidal distance from (x, y) to the nearest point, or any value <= beat as soon
    as some point is at least that close (the candidate then cannot win)."""
    if not pts:
        return 8.0
    if len(pts) < 64:
        d = 8.0
        for p in pts:
            a = wrap(x - p[0])
            b = wrap(y - p[1])
            e = a * a + b * b
            if e < d:
                d = e
                if d <= beat:
                    return d
        return d
    cx, cy = cell(x), cell(y)
    d = 8.0
    r = 0
    while True:
        # ring r: cells with max(|dx|, |dy|) == r
        for dy in range(-r, r + 1):
            row = ((cy + dy) % G) * G
            step = 1 if abs(dy) == r else 2 * r
            dx = -r
            while dx <= r:
                for j in grid[row + (cx + dx) % G]:
                    p = pts[j]
                    a = wrap(x - p[0])
                    b = wrap(y - p[1])
                    e = a * a + b * b
                    if e < d:
                        d = e
                        if d <= beat:
                            return d
                dx += step if step > 0 else 1
        # every point outside rings 0..r is at least r / G away
        lim = r / G
        if d <= lim * lim or 2 * r + 1 >= G:
            return d
        r += 1


def neighbours(pts, grid, x, y):
    """Indices of the NEIGHBOURS earlier points nearest (toroidal) to (x, y); fewer if there are
    fewer points. Ties are broken by index."""
    if len(pts) <= NEIGHBOURS:
        return list(range(len(pts)))
    if len(pts) < 64:
        cand = range(len(pts))
    else:
        cx, cy = cell(x), cell(y)
        r = 1
        while True:
            cand = []
            for dy in range(-r, r + 1):
                for dx in range(-r, r + 1):
                    cand.extend(grid[((cy + dy) % G) * G + (cx + dx) % G])
            if len(cand) >= NEIGHBOURS:
                ds = sorted(d2(pts[j], x, y) for j in cand)
                # all points outside the (2r+1)^2 block are at least r / G away
                if ds[NEIGHBOURS - 1] <= (r / G) ** 2 or 2 * r + 1 >= G:
                    break
            r += 1
    ranked = sorted(cand, key=lambda j: (d2(pts[j], x, y), j))
    return ranked[:NEIGHBOURS]


def d2(p, x, y):
    a = wrap(x - p[0])
    b = wrap(y - p[1])
    return a * a + b * b


def quantize(v):
    q = int(v * 65536.0)
    return min(q, 65535)


def render(pts):
    lines = [
        "// @generated by scripts/gen_best_candidate.py — do not edit.",
        "// Mitchell (1991) best-candidate pattern on the unit torus, %d points; each row is" % len(pts),
        "// [image x, image y, time, lens u, lens v] as floor(value * 65536).",
        "// seed 0x%016x, candidates min(1 + %d i, %d), time/lens: %d candidates against %d neighbours."
        % (SEED, K, MAX_CANDIDATES, TL_CANDIDATES, NEIGHBOURS),
        "",
        "/// The baked best-candidate table (see `scripts/gen_best_candidate.py`).",
        "#[rustfmt::skip]",
        "pub(crate) static TABLE: [[u16; 5]; %d] = [" % len(pts),
    ]
    for p in pts:
        lines.append("    [%s]," % ", ".join(str(quantize(v)) for v in p))
    lines.append("];")
    return "\n".join(lines) + "\n"


def main():
    n = N
    args = sys.argv[1:]
    if "--n" in args:
        n = int(args[args.index("--n") + 1])
    text = render(generate(n))
    if "--stdout" in args:
        sys.stdout.write(text)
        return
    if "--check" in args:
        with open(OUT) as f:
            if f.read() != text:
                sys.exit("best_candidate/table.rs is stale: rerun scripts/gen_best_candidate.py")
        return
    with open(OUT, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
