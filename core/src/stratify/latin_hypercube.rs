//! Latin hypercube sampling: `n` points in `dims` dimensions whose projection on every axis puts
//! exactly one point in each of the `n` strata.

use rand_core::Rng;

use super::Strata;
use crate::{
    Error, hash,
    rng::{CounterRng, uniform_below_from},
};

/// Validates a point-major buffer of `dims`-dimensional points; returns the point count.
fn points_in(len: usize, dims: u32) -> Result<u32, Error> {
    if dims == 0 {
        return Err(Error::ZeroSize { what: "dims" });
    }
    let d = dims as usize;
    if len == 0 || !len.is_multiple_of(d) {
        return Err(Error::BufferLength {
            multiple_of: d,
            actual: len,
        });
    }
    u32::try_from(len / d).map_err(|_| Error::TooMany {
        what: "points",
        value: (len / d) as u64,
        max: u64::from(u32::MAX),
    })
}

/// Fills `out` with `n = out.len() / dims` Latin-hypercube points, point-major
/// (`[x0, y0, z0, x1, …]`), and returns `n`. In every dimension the `n` values fall one in each
/// stratum `[k/n, (k+1)/n)`, jittered uniformly inside it, the strata assigned to points by an
/// independent uniform permutation per dimension. Values are in `[0, 1)`. Allocates: no.
///
/// One pass per dimension: the stratum values are written straight into a uniformly shuffled
/// position (the "inside-out" Fisher–Yates), with unbiased bounded draws (Lemire's method).
/// Jitters have `22 − ⌈log₂ n⌉` random bits (as [`super::stratified_1d`]). Takes one `u64`
/// from `rng`, as the key of the [`CounterRng`] stream that supplies one word per value.
///
/// # Errors
/// [`Error::ZeroSize`] if `dims == 0`; [`Error::BufferLength`] if `out` is empty or its length
/// is not a multiple of `dims`; [`Error::TooMany`] if there are more than `u32::MAX` points.
///
/// ```
/// use nyquist::rng::default_rng;
/// use nyquist::stratify::latin_hypercube;
/// let mut pts = [0.0f32; 8 * 3];
/// assert_eq!(latin_hypercube(&mut pts, 3, &mut default_rng(2)), Ok(8));
/// let mut strata: Vec<u32> = pts.chunks_exact(3).map(|p| (p[1] * 8.0) as u32).collect();
/// strata.sort();
/// assert_eq!(strata, [0, 1, 2, 3, 4, 5, 6, 7]);
/// assert!(latin_hypercube(&mut pts, 5, &mut default_rng(2)).is_err());
/// ```
pub fn latin_hypercube<R: Rng + ?Sized>(
    out: &mut [f32],
    dims: u32,
    rng: &mut R,
) -> Result<u32, Error> {
    let n = points_in(out.len(), dims)?;
    let d = dims as usize;
    let strata = Strata::new(n);
    let shift = 32 - strata.jitter_bits();
    // One word per value from a counter stream keyed by one draw of `rng`: the jitter from
    // its low half, the bounded draw from its high half (more words only on the rare
    // rejection), with no generator chain between the steps.
    let rng = &mut CounterRng::keyed_by(rng);
    for dim in 0..d {
        // Inside-out Fisher–Yates over the column: after step k, positions 0..=k hold a uniform
        // permutation of the strata 0..=k.
        for k in 0..n {
            let w = rng.next_u64();
            // The low half's top bits, shifted in 64 bits: at 2²² strata the shift is 32.
            let value = strata.jittered(k, (u64::from(w as u32) >> shift) as u32);
            let j = uniform_below_from((w >> 32) as u32, k + 1, rng) as usize;
            let (kk, jj) = (k as usize * d + dim, j * d + dim);
            out[kk] = out[jj];
            out[jj] = value;
        }
    }
    Ok(n)
}

/// A stateless Latin hypercube: point `i`'s coordinate in dimension `d` is stratum
/// `permute(i, n, hash(seed, d))` jittered by a hash of `(seed, i, d)`. No generator, `&self`
/// only: any thread can fill any batch and get the same bits.
///
/// ```
/// use nyquist::stratify::LatinHypercube;
/// let lhs = LatinHypercube::new(2, 7).unwrap();
/// let mut pts = [0.0f32; 2 * 16];
/// assert_eq!(lhs.required_len(16), Some(32));
/// assert_eq!(lhs.fill(&mut pts), Ok(16));
/// let mut again = [0.0f32; 32];
/// lhs.fill(&mut again).unwrap();
/// assert_eq!(pts, again);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LatinHypercube {
    dims: u32,
    seed: u64,
}

impl LatinHypercube {
    /// A Latin hypercube in `dims` dimensions chosen by `seed` (every seed is valid).
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `dims == 0`.
    ///
    /// ```
    /// use nyquist::{Error, stratify::LatinHypercube};
    /// assert_eq!(LatinHypercube::new(0, 1), Err(Error::ZeroSize { what: "dims" }));
    /// assert_eq!(LatinHypercube::new(3, 1).unwrap().dims(), 3);
    /// ```
    pub fn new(dims: u32, seed: u64) -> Result<LatinHypercube, Error> {
        if dims == 0 {
            return Err(Error::ZeroSize { what: "dims" });
        }
        Ok(LatinHypercube { dims, seed })
    }

    /// The number of dimensions.
    ///
    /// ```
    /// assert_eq!(nyquist::stratify::LatinHypercube::new(4, 0).unwrap().dims(), 4);
    /// ```
    pub fn dims(&self) -> u32 {
        self.dims
    }

    /// Floats needed for `points` points, or `None` on overflow.
    ///
    /// ```
    /// let lhs = nyquist::stratify::LatinHypercube::new(3, 0).unwrap();
    /// assert_eq!(lhs.required_len(10), Some(30));
    /// ```
    pub fn required_len(&self, points: u32) -> Option<usize> {
        (points as usize).checked_mul(self.dims as usize)
    }

    /// Fills `out` with `out.len() / dims` points, point-major (`[x0, y0, z0, x1, …]`), and
    /// returns the number of points. Values are in `[0, 1)`; every dimension's `n` strata are
    /// hit once. Allocates: no.
    ///
    /// # Errors
    /// [`Error::BufferLength`] if `out` is empty or not a multiple of `dims`;
    /// [`Error::TooMany`] for more than `u32::MAX` points.
    ///
    /// ```
    /// use nyquist::stratify::LatinHypercube;
    /// let lhs = LatinHypercube::new(3, 1).unwrap();
    /// let mut buf = [0.0f32; 7];
    /// assert!(lhs.fill(&mut buf).is_err());
    /// assert_eq!(lhs.fill(&mut buf[..6]), Ok(2));
    /// ```
    pub fn fill(&self, out: &mut [f32]) -> Result<u32, Error> {
        let n = points_in(out.len(), self.dims)?;
        let strata = Strata::new(n);
        let discard = 32 - strata.jitter_bits();
        for (dim, x0) in (0..self.dims).zip(0..) {
            let key = hash::hash2(self.seed, u64::from(dim));
            let perm = hash::Permutation::new(n, (key >> 32) as u32);
            for (i, point) in (0..n).zip(out.chunks_exact_mut(self.dims as usize)) {
                let stratum = perm.apply(i);
                let jitter = (hash::hash2(key, u64::from(i)) >> 32 >> discard) as u32;
                point[x0] = strata.jittered(stratum, jitter);
            }
        }
        Ok(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::default_rng;
    use proptest::prelude::*;

    fn assert_latin(buf: &[f32], dims: usize) {
        let n = buf.len() / dims;
        for d in 0..dims {
            let mut seen = std::vec![false; n];
            for p in buf.chunks_exact(dims) {
                assert!((0.0..1.0).contains(&p[d]));
                let s = (f64::from(p[d]) * n as f64) as usize;
                assert!(
                    !core::mem::replace(&mut seen[s], true),
                    "dim {d}: stratum {s} twice"
                );
            }
        }
    }

    proptest! {
        #[test]
        fn every_dimension_hits_every_stratum_once(n in 1usize..400, dims in 1u32..9, seed: u64) {
            let mut buf = std::vec![0.0f32; n * dims as usize];
            prop_assert_eq!(latin_hypercube(&mut buf, dims, &mut default_rng(seed)), Ok(n as u32));
            assert_latin(&buf, dims as usize);
            let lhs = LatinHypercube::new(dims, seed).unwrap();
            prop_assert_eq!(lhs.fill(&mut buf), Ok(n as u32));
            assert_latin(&buf, dims as usize);
        }

        #[test]
        fn bad_sizes_are_errors(len in 0usize..50, dims in 0u32..7) {
            let mut buf = std::vec![0.0f32; len];
            let expected = if dims == 0 {
                Err(Error::ZeroSize { what: "dims" })
            } else if len == 0 || len % dims as usize != 0 {
                Err(Error::BufferLength { multiple_of: dims as usize, actual: len })
            } else {
                Ok((len / dims as usize) as u32)
            };
            prop_assert_eq!(latin_hypercube(&mut buf, dims, &mut default_rng(1)), expected);
            if dims > 0 {
                prop_assert_eq!(LatinHypercube::new(dims, 3).unwrap().fill(&mut buf), expected);
            }
        }
    }

    #[test]
    fn stratum_permutation_is_uniform() {
        // n = 3 points in 1 dimension: the 6 stratum orders are equally likely
        // (chi-square, 5 dof, 0.999 quantile 20.5; 60000 trials).
        let mut rng = default_rng(17);
        let mut counts = [0u32; 27];
        let mut buf = [0.0f32; 3];
        for _ in 0..60_000 {
            latin_hypercube(&mut buf, 1, &mut rng).unwrap();
            let s = buf.map(|x| (x * 3.0) as usize);
            counts[s[0] * 9 + s[1] * 3 + s[2]] += 1;
        }
        let hit: std::vec::Vec<u32> = counts.iter().copied().filter(|&c| c > 0).collect();
        assert_eq!(hit.len(), 6);
        let chi = crate::tests::chi_square_uniform(&hit);
        assert!(chi < 20.5, "chi2 {chi}");
    }

    #[test]
    fn dimensions_are_decorrelated() {
        // With 64 points, the strata of dims 0 and 1 should not be equal for most points.
        let mut buf = [0.0f32; 64 * 2];
        latin_hypercube(&mut buf, 2, &mut default_rng(8)).unwrap();
        let same = buf
            .chunks_exact(2)
            .filter(|p| (p[0] * 64.0) as u32 == (p[1] * 64.0) as u32)
            .count();
        assert!(same < 8, "{same}");
    }

    /// The accessors agree with what `fill` does: `dims()` is the constructed dimension count
    /// and `required_len(n)` is exactly the buffer length that `fill` turns into `n` points.
    #[test]
    fn accessors_match_what_fill_accepts() {
        for dims in [1u32, 2, 3, 7] {
            let lhs = LatinHypercube::new(dims, 9).unwrap();
            assert_eq!(lhs.dims(), dims);
            for n in [1u32, 2, 5, 64] {
                let len = lhs.required_len(n).unwrap();
                assert_eq!(len, (n * dims) as usize);
                let mut buf = std::vec![0.0f32; len];
                assert_eq!(lhs.fill(&mut buf), Ok(n));
            }
            assert_eq!(lhs.required_len(0), Some(0));
        }
    }

    /// At 2²² strata the exact route has no jitter bits left (every value is its stratum's
    /// centre) and one more stratum takes the checked route with 24 bits: both still put one
    /// value in each stratum.
    #[test]
    fn every_stratum_once_at_the_ends_of_the_jitter_range() {
        for n in [1usize << 22, (1 << 22) + 1] {
            let mut buf = std::vec![0.0f32; n];
            for stateless in [false, true] {
                let filled = if stateless {
                    LatinHypercube::new(1, 3).unwrap().fill(&mut buf)
                } else {
                    latin_hypercube(&mut buf, 1, &mut default_rng(3))
                };
                assert_eq!(filled, Ok(n as u32));
                let mut seen = std::vec![false; n];
                for &x in &buf {
                    assert!((0.0..1.0).contains(&x), "{n}, stateless {stateless}: {x}");
                    let s = (f64::from(x) * n as f64) as usize;
                    assert!(
                        !core::mem::replace(&mut seen[s], true),
                        "{n}, stateless {stateless}: stratum {s} twice"
                    );
                }
            }
        }
    }

    /// The offsets of `buf`'s values inside their strata (`x·n − stratum`), every dimension.
    fn offsets(buf: &[f32], dims: usize) -> std::vec::Vec<f64> {
        let n = (buf.len() / dims) as f64;
        buf.iter()
            .map(|&x| f64::from(x) * n - (f64::from(x) * n).floor())
            .collect()
    }

    /// Offsets uniform over the stratum: mean ½ and variance 1/12 within about six standard
    /// errors (0.009 and 0.0023 over 1024 offsets), and at least 900 distinct values (256 strata
    /// leave 14 jitter bits: about 992 distinct of 1024 draws, standard deviation under 6; a
    /// jitter of one bit, or none, or always the largest, gives one or two).
    fn assert_spread(u: &[f64], what: &str) {
        let m = u.len() as f64;
        let mean = u.iter().sum::<f64>() / m;
        let var = u.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / m;
        assert!((mean - 0.5).abs() < 0.05, "{what}: mean offset {mean}");
        assert!(
            (var - 1.0 / 12.0).abs() < 0.015,
            "{what}: offset variance {var}"
        );
        let mut distinct: std::vec::Vec<u64> = u.iter().map(|x| x.to_bits()).collect();
        distinct.sort_unstable();
        distinct.dedup();
        assert!(
            distinct.len() >= 900,
            "{what}: {} distinct offsets",
            distinct.len()
        );
    }

    #[test]
    fn jitters_are_spread_over_each_stratum() {
        let mut buf = std::vec![0.0f32; 256 * 4];
        latin_hypercube(&mut buf, 4, &mut default_rng(21)).unwrap();
        assert_spread(&offsets(&buf, 4), "latin_hypercube");
        LatinHypercube::new(4, 21).unwrap().fill(&mut buf).unwrap();
        assert_spread(&offsets(&buf, 4), "LatinHypercube::fill");
    }

    /// The stratum order of each dimension of `buf`.
    fn orders(buf: &[f32], dims: usize) -> std::vec::Vec<std::vec::Vec<u32>> {
        let n = (buf.len() / dims) as f32;
        (0..dims)
            .map(|d| buf.chunks_exact(dims).map(|p| (p[d] * n) as u32).collect())
            .collect()
    }

    /// Every dimension and every seed has its own stratum permutation: among 64 points two
    /// independent uniform permutations agree at one place on average, so more than 8 common
    /// places (probability below 10⁻⁵ per pair) means a shared permutation.
    #[test]
    fn dimensions_and_seeds_have_their_own_permutations() {
        let agree = |a: &[u32], b: &[u32]| a.iter().zip(b).filter(|(x, y)| x == y).count();
        let mut one = std::vec![0.0f32; 64 * 4];
        let mut two = std::vec![0.0f32; 64 * 4];
        for (what, fill) in [
            (
                "LatinHypercube::fill",
                (|buf: &mut [f32], seed: u64| {
                    LatinHypercube::new(4, seed).unwrap().fill(buf).unwrap();
                }) as fn(&mut [f32], u64),
            ),
            ("latin_hypercube", |buf: &mut [f32], seed: u64| {
                latin_hypercube(buf, 4, &mut default_rng(seed)).unwrap();
            }),
        ] {
            fill(&mut one, 5);
            fill(&mut two, 6);
            let (a, b) = (orders(&one, 4), orders(&two, 4));
            for d in 0..4 {
                for e in d + 1..4 {
                    assert!(
                        agree(&a[d], &a[e]) <= 8,
                        "{what}: dims {d} and {e} share strata"
                    );
                }
                assert!(
                    agree(&a[d], &b[d]) <= 8,
                    "{what}: seeds 5 and 6 share dim {d}'s strata"
                );
            }
        }
    }
}
