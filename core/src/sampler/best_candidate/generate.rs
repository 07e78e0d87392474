//! With the `lazy-tables` feature: the best-candidate table generated at first use instead of
//! stored (40 KiB), by the algorithm `scripts/gen_best_candidate.py` documents and runs to write
//! the stored table, with the same double-precision operations in the same order, so the rows
//! are the same bit for bit (the test below compares all 4096).
//!
//! The generation is the costliest first use of any table (timings: `docs/performance.md`) and
//! needs about 180 KiB of stack (the points in `f64` and a grid over the torus), which suits a
//! WebAssembly module's 1 MiB stack.

use super::TABLE_SIZE;
use crate::lazy_table::{Fill, LazyTable};

const N: usize = TABLE_SIZE as usize;
/// SplitMix64 seed, "nyquist1".
pub(super) const SEED: u64 = 0x6E79_7175_6973_7431;
/// Image candidates for point `i`: `min(1 + K·i, MAX_CANDIDATES)`.
const K: usize = 4;
const MAX_CANDIDATES: usize = 4096;
/// Time and lens candidates per point, judged against this many image neighbours.
const TL_CANDIDATES: usize = 32;
const NEIGHBOURS: usize = 8;
/// The grid over the image torus: `G × G` cells.
const G: usize = 64;
/// Below this many points the searches are brute force, as in the script.
const BRUTE: usize = 64;
/// End of a cell's list.
const NONE: u16 = u16::MAX;

/// SplitMix64 (Steele, Lea & Flood 2014); a float is `(u >> 11) · 2⁻⁵³`.
pub(super) struct SplitMix64(pub(super) u64);

impl SplitMix64 {
    pub(super) fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 * (1.0 / 9_007_199_254_740_992.0)
    }
}

/// Toroidal distance along one axis: `min(|d|, 1 − |d|)`.
pub(super) fn wrap(d: f64) -> f64 {
    let d = d.abs();
    if d > 0.5 { 1.0 - d } else { d }
}

/// The grid cell of a coordinate in `[0, 1)`.
fn cell(v: f64) -> usize {
    ((v * G as f64) as usize).min(G - 1)
}

/// The points so far (`[x, y, time, u, v]`) and a grid of per-cell lists over their images.
struct Points {
    p: [[f64; 5]; N],
    len: usize,
    head: [u16; G * G],
    next: [u16; N],
}

impl Points {
    fn d2(&self, j: usize, x: f64, y: f64) -> f64 {
        let (a, b) = (wrap(x - self.p[j][0]), wrap(y - self.p[j][1]));
        a * a + b * b
    }

    /// The points of cell `(cx mod G, cy mod G)`, most recent first.
    fn cell_points(&self, cx: usize, cy: usize) -> impl Iterator<Item = usize> + '_ {
        let mut j = self.head[(cy % G) * G + cx % G];
        core::iter::from_fn(move || {
            (j != NONE).then(|| {
                let k = j as usize;
                j = self.next[k];
                k
            })
        })
    }

    fn push(&mut self, q: [f64; 5]) {
        let c = cell(q[1]) * G + cell(q[0]);
        self.p[self.len] = q;
        self.next[self.len] = self.head[c];
        self.head[c] = self.len as u16;
        self.len += 1;
    }

    /// The squared toroidal distance from `(x, y)` to the nearest point, or any value
    /// `≤ beat` as soon as some point is that close (the candidate then cannot win).
    fn nearest_d2(&self, x: f64, y: f64, beat: f64) -> f64 {
        let mut d = 8.0;
        if self.len < BRUTE {
            for j in 0..self.len {
                let e = self.d2(j, x, y);
                if e < d {
                    d = e;
                    if d <= beat {
                        return d;
                    }
                }
            }
            return d;
        }
        let (cx, cy) = (cell(x) + G, cell(y) + G);
        let mut r = 0;
        loop {
            // Ring r: the cells with max(|dx|, |dy|) = r.
            for dy in 0..=2 * r {
                let step = if dy == 0 || dy == 2 * r { 1 } else { 2 * r };
                let mut dx = 0;
                while dx <= 2 * r {
                    for j in self.cell_points(cx + dx - r, cy + dy - r) {
                        let e = self.d2(j, x, y);
                        if e < d {
                            d = e;
                            if d <= beat {
                                return d;
                            }
                        }
                    }
                    dx += step;
                }
            }
            // Every point outside rings 0 ..= r is at least r / G away.
            let lim = r as f64 / G as f64;
            if d <= lim * lim || 2 * r + 1 >= G {
                return d;
            }
            r += 1;
        }
    }

    /// The `NEIGHBOURS` earlier points nearest to `(x, y)` (fewer while there are fewer),
    /// nearest first, ties by index; returns how many.
    fn neighbours(&self, x: f64, y: f64, out: &mut [usize; NEIGHBOURS]) -> usize {
        // The nearest so far in `keys[..n]`, sorted by (d2, index): insertion of each offer.
        let mut n = 0;
        let mut keys = [(0.0f64, 0usize); NEIGHBOURS];
        let offer = |j: usize, keys: &mut [(f64, usize); NEIGHBOURS], n: &mut usize| {
            let key = (self.d2(j, x, y), j);
            let less = |a: (f64, usize), b: (f64, usize)| a.0 < b.0 || (a.0 == b.0 && a.1 < b.1);
            if *n == NEIGHBOURS && !less(key, keys[NEIGHBOURS - 1]) {
                return;
            }
            let mut k = (*n).min(NEIGHBOURS - 1);
            *n = (*n + 1).min(NEIGHBOURS);
            while k > 0 && less(key, keys[k - 1]) {
                keys[k] = keys[k - 1];
                k -= 1;
            }
            keys[k] = key;
        };
        if self.len < BRUTE {
            for j in 0..self.len {
                offer(j, &mut keys, &mut n);
            }
        } else {
            // Grow the block of (2r + 1)² cells until it holds NEIGHBOURS points and its
            // NEIGHBOURS-th nearest is within r / G (everything outside is at least that far).
            let (cx, cy) = (cell(x) + G, cell(y) + G);
            let mut r = 1;
            loop {
                n = 0;
                for dy in 0..=2 * r {
                    for dx in 0..=2 * r {
                        for j in self.cell_points(cx + dx - r, cy + dy - r) {
                            offer(j, &mut keys, &mut n);
                        }
                    }
                }
                let lim = r as f64 / G as f64;
                if n == NEIGHBOURS && keys[NEIGHBOURS - 1].0 <= lim * lim || 2 * r + 1 >= G {
                    break;
                }
                r += 1;
            }
        }
        for (o, k) in out.iter_mut().zip(&keys[..n]) {
            *o = k.1;
        }
        n
    }
}

/// Writes the table: Mitchell's best candidate on the unit torus for the image, then the best
/// of `TL_CANDIDATES` times and lens positions against the image neighbours' (the script's
/// docstring has the details), each value stored as `min(floor(v · 65536), 65535)`.
fn generate(t: &mut [[u16; 5]; N]) {
    let mut rng = SplitMix64(SEED);
    let mut pts = Points {
        p: [[0.0; 5]; N],
        len: 0,
        head: [NONE; G * G],
        next: [NONE; N],
    };
    for i in 0..N {
        let (mut x, mut y, mut best_d2) = (0.0, 0.0, -1.0);
        for _ in 0..(1 + K * i).min(MAX_CANDIDATES) {
            let cx = rng.unit();
            let cy = rng.unit();
            let d2 = pts.nearest_d2(cx, cy, best_d2);
            if d2 > best_d2 {
                (best_d2, x, y) = (d2, cx, cy);
            }
        }
        let mut nbs = [0usize; NEIGHBOURS];
        let n = pts.neighbours(x, y, &mut nbs);
        let nbs = &nbs[..n];
        let (mut bt, mut bd) = (0.0, -1.0);
        for _ in 0..TL_CANDIDATES {
            let c = rng.unit();
            let mut d = 2.0;
            for &j in nbs {
                let e = wrap(c - pts.p[j][2]);
                if e < d {
                    d = e;
                }
            }
            if d > bd {
                (bd, bt) = (d, c);
            }
        }
        let (mut bu, mut bv, mut bd) = (0.0, 0.0, -1.0);
        for _ in 0..TL_CANDIDATES {
            let u = rng.unit();
            let v = rng.unit();
            let mut d = 8.0;
            for &j in nbs {
                let (a, b) = (wrap(u - pts.p[j][3]), wrap(v - pts.p[j][4]));
                let e = a * a + b * b;
                if e < d {
                    d = e;
                }
            }
            if d > bd {
                (bd, bu, bv) = (d, u, v);
            }
        }
        let q = [x, y, bt, bu, bv];
        t[i] = q.map(|v| ((v * 65536.0) as u32).min(65535) as u16);
        pts.push(q);
    }
}

/// The table's fill.
pub(crate) struct Generated;

impl Fill for Generated {
    type Table = [[u16; 5]; N];

    fn fill(t: &mut [[u16; 5]; N]) {
        generate(t)
    }
}

/// The best-candidate table, generated at first use.
#[cfg_attr(all(test, not(feature = "lazy-tables")), allow(dead_code))]
pub(crate) static TABLE: LazyTable<Generated> = LazyTable::new([[0; 5]; N]);

#[cfg(test)]
mod tests {
    /// The generated table is the stored one, which `scripts/gen_best_candidate.py --check`
    /// checks against the script (32 s of Python; not part of CI).
    #[test]
    fn generated_table_equals_the_stored_one() {
        let stored = &super::super::table::TABLE;
        let generated = &*super::TABLE;
        for (i, (g, s)) in generated.iter().zip(stored.iter()).enumerate() {
            assert_eq!(g, s, "row {i}");
        }
    }
}
