//! The van der Corput and Halton sequences and their folded (Halton–Zaremba) and digit-scrambled
//! variants: point `i`, dimension `d` is a radical inverse of `i` in the `d`-th prime base.
//!
//! Sources: van der Corput (1935); Halton (1960); Kocis & Whiten (1997) for the Halton–Zaremba
//! (folded) form; Kollig & Keller (2002) for scrambling by digit permutation; Owen (1995) for the
//! nested scrambles of [`ScrambledHalton::with_strategy`].

use super::{Sequence, check_fill};
use crate::Error;
use crate::radical::{
    PRIME_COUNT, fast_owen_scrambled_radical_inverse, fast_owen_scrambled_radical_inverse_f64,
    fill_consecutive, folded_radical_inverse, folded_radical_inverse_f64,
    owen_scrambled_radical_inverse, owen_scrambled_radical_inverse_f64, radical_inverse,
    radical_inverse_f64, scrambled_radical_inverse, scrambled_radical_inverse_column_f64,
    scrambled_radical_inverse_f64,
};
use crate::scramble::Scramble;

/// Validates a dimension count for the radical-inverse sets: `1 ..= 1024`.
fn check_dims(dims: u32) -> Result<u32, Error> {
    super::dims_within(dims, PRIME_COUNT)
}

/// The van der Corput sequence: Φ₂(i), one dimension, every `u64` index its own point.
///
/// ```
/// use nyquist::sequence::{Sequence, VanDerCorput};
/// assert_eq!(VanDerCorput.sample(6, 0), 0.375); // 110₂ → 0.011₂
/// assert_eq!(VanDerCorput.sample(6, 5), 0.375); // every dim reads dimension 0
/// assert_eq!(VanDerCorput.point_count(), None);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct VanDerCorput;

impl Sequence for VanDerCorput {
    fn dims(&self) -> u32 {
        1
    }

    fn point_count(&self) -> Option<u64> {
        None
    }

    #[inline]
    fn sample(&self, index: u64, _dim: u32) -> f32 {
        crate::radical::phi2(index)
    }

    fn fill(&self, first: u64, dims: u32, out: &mut [f32]) -> Result<u64, Error> {
        let n = check_fill(1, None, first, dims, out.len())?;
        fill_consecutive(0, first, out, 0, 1);
        Ok(n)
    }

    #[inline]
    fn sample_f64(&self, index: u64, _dim: u32) -> f64 {
        radical_inverse_f64(0, index)
    }
}

/// The Halton sequence: point `i` is `(Φ₂(i), Φ₃(i), Φ₅(i), …)`, dimension `d` in base
/// [`prime`](crate::radical::prime)`(d)`, up to 1024 dimensions; every `u64` index is a point.
///
/// ```
/// use nyquist::sequence::{Halton, Sequence};
/// let h = Halton::new(3).unwrap();
/// assert_eq!((h.sample(3, 0), h.sample(3, 1)), (0.75, 1.0 / 9.0));
/// assert_eq!(h.sample(3, 3), h.sample(3, 0)); // dim wraps modulo dims
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Halton {
    dims: u32,
}

impl Halton {
    /// A Halton sequence with `dims` dimensions.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `dims == 0`; [`Error::NotInRange`] (`what: "dims"`) if `dims > 1024`.
    ///
    /// ```
    /// use nyquist::{sequence::Halton, Error};
    /// assert!(Halton::new(1024).is_ok());
    /// assert_eq!(Halton::new(0), Err(Error::ZeroSize { what: "dims" }));
    /// assert_eq!(Halton::new(1025).unwrap_err().to_string(), "dims 1025 is outside 1..=1024");
    /// ```
    pub fn new(dims: u32) -> Result<Halton, Error> {
        Ok(Halton {
            dims: check_dims(dims)?,
        })
    }
}

impl Sequence for Halton {
    fn dims(&self) -> u32 {
        self.dims
    }

    fn point_count(&self) -> Option<u64> {
        None
    }

    #[inline]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        radical_inverse(dim % self.dims, index)
    }

    #[inline]
    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        radical_inverse_f64(dim % self.dims, index)
    }

    /// As [`Sequence::fill`], the same bits, but each dimension's run of consecutive indices is
    /// generated incrementally ([`fill_radical_inverse`](crate::radical::fill_radical_inverse)):
    /// amortised O(1) per value instead of O(digits).
    fn fill(&self, first: u64, dims: u32, out: &mut [f32]) -> Result<u64, Error> {
        let n = check_fill(self.dims, None, first, dims, out.len())?;
        let stride = dims as usize;
        for dim in 0..dims {
            fill_consecutive(dim, first, out, dim as usize, stride);
        }
        Ok(n)
    }
}

/// The Halton–Zaremba sequence: Halton with the folded radical inverse Ψ_b in place of Φ_b.
///
/// ```
/// use nyquist::sequence::{HaltonZaremba, Sequence};
/// let h = HaltonZaremba::new(2).unwrap();
/// assert_eq!(h.sample(0, 0), 1.0 / 3.0); // Ψ₂(0) = 0.0101…₂
/// assert_eq!(h.sample(1, 0), 5.0 / 6.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HaltonZaremba {
    dims: u32,
}

impl HaltonZaremba {
    /// A Halton–Zaremba sequence with `dims` dimensions.
    ///
    /// # Errors
    /// As [`Halton::new`].
    ///
    /// ```
    /// assert!(nyquist::sequence::HaltonZaremba::new(0).is_err());
    /// ```
    pub fn new(dims: u32) -> Result<HaltonZaremba, Error> {
        Ok(HaltonZaremba {
            dims: check_dims(dims)?,
        })
    }
}

impl Sequence for HaltonZaremba {
    fn dims(&self) -> u32 {
        self.dims
    }

    fn point_count(&self) -> Option<u64> {
        None
    }

    fn sample(&self, index: u64, dim: u32) -> f32 {
        folded_radical_inverse(dim % self.dims, index)
    }

    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        folded_radical_inverse_f64(dim % self.dims, index)
    }
}

/// The Halton sequence randomized by a [`Scramble`] chosen with `seed`: by default
/// ([`ScrambledHalton::new`]) one random digit permutation per base (see
/// [`scrambled_radical_inverse`]); [`ScrambledHalton::with_strategy`] picks any of the four.
///
/// | strategy | dimension `d` of point `i` |
/// |---|---|
/// | `None` | Φ_b(i), the plain [`Halton`] values |
/// | `PermuteDigits` | [`scrambled_radical_inverse`] |
/// | `FastOwen` | [`fast_owen_scrambled_radical_inverse`] (nested, affine digit permutations) |
/// | `Owen` | [`owen_scrambled_radical_inverse`] (nested uniform) |
///
/// Every seed gives a stratified set: the first `bᵐ` points fall one per `1/bᵐ` in each base.
///
/// ```
/// use nyquist::sequence::{ScrambledHalton, Sequence};
/// let a = ScrambledHalton::new(4, 1).unwrap();
/// let b = ScrambledHalton::new(4, 2).unwrap();
/// assert_ne!(a.sample(5, 2), b.sample(5, 2));
/// assert_eq!(a.sample(5, 2), ScrambledHalton::new(4, 1).unwrap().sample(5, 2));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScrambledHalton {
    dims: u32,
    seed: u64,
    strategy: Scramble,
}

impl ScrambledHalton {
    /// A digit-permuted Halton sequence with `dims` dimensions; every `seed` is valid. The same
    /// as [`ScrambledHalton::with_strategy`]`(dims, Scramble::PermuteDigits, seed)`.
    ///
    /// # Errors
    /// As [`Halton::new`].
    ///
    /// ```
    /// assert!(nyquist::sequence::ScrambledHalton::new(2000, 0).is_err());
    /// ```
    pub fn new(dims: u32, seed: u64) -> Result<ScrambledHalton, Error> {
        ScrambledHalton::with_strategy(dims, Scramble::PermuteDigits, seed)
    }

    /// A Halton sequence with `dims` dimensions randomized by `strategy` under `seed` (every
    /// seed is valid; with [`Scramble::None`] the seed is ignored and the values are
    /// [`Halton`]'s).
    ///
    /// # Errors
    /// As [`Halton::new`].
    ///
    /// ```
    /// use nyquist::radical::owen_scrambled_radical_inverse;
    /// use nyquist::scramble::Scramble;
    /// use nyquist::sequence::{Halton, ScrambledHalton, Sequence};
    /// let owen = ScrambledHalton::with_strategy(3, Scramble::Owen, 7).unwrap();
    /// assert_eq!(owen.sample(10, 2), owen_scrambled_radical_inverse(2, 10, 7));
    /// let plain = ScrambledHalton::with_strategy(3, Scramble::None, 7).unwrap();
    /// assert_eq!(plain.sample(10, 2), Halton::new(3).unwrap().sample(10, 2));
    /// assert!(ScrambledHalton::with_strategy(0, Scramble::Owen, 7).is_err());
    /// ```
    pub fn with_strategy(
        dims: u32,
        strategy: Scramble,
        seed: u64,
    ) -> Result<ScrambledHalton, Error> {
        Ok(ScrambledHalton {
            dims: check_dims(dims)?,
            seed,
            strategy,
        })
    }

    /// Points `first ..` as `f64`s into `out`, `dims` coordinates each (point-major), equal to
    /// [`Sequence::sample_f64`] value for value; returns the number of points. Digit
    /// permutation fills each dimension of a block of 256 points with
    /// [`scrambled_radical_inverse_column_f64`] (amortised O(1) per value instead of one pass
    /// over the index's digits), so the block stays in cache; the other strategies compute
    /// each value on its own. Allocates: no.
    ///
    /// # Errors
    /// As [`Sequence::fill`].
    ///
    /// ```
    /// use nyquist::sequence::{ScrambledHalton, Sequence};
    /// let h = ScrambledHalton::new(3, 9).unwrap();
    /// let mut out = [0.0; 3 * 300];
    /// assert_eq!(h.fill_f64(1000, 3, &mut out), Ok(300));
    /// assert_eq!(out[3 * 299 + 2], h.sample_f64(1299, 2));
    /// ```
    pub fn fill_f64(&self, first: u64, dims: u32, out: &mut [f64]) -> Result<u64, Error> {
        const BLOCK: usize = 256;
        let n = check_fill(self.dims, None, first, dims, out.len())?;
        let d = dims as usize;
        if self.strategy != Scramble::PermuteDigits {
            for (k, point) in (0..n).zip(out.chunks_exact_mut(d)) {
                for (dim, x) in (0..dims).zip(point) {
                    *x = self.sample_f64(first + k, dim);
                }
            }
            return Ok(n);
        }
        for (b, block) in out.chunks_mut(BLOCK * d).enumerate() {
            let start = first + (b * BLOCK) as u64;
            for (dim, column) in (0..dims).zip(0..d) {
                scrambled_radical_inverse_column_f64(
                    dim,
                    start,
                    self.seed,
                    &mut block[column..],
                    d,
                )?;
            }
        }
        Ok(n)
    }

    /// The randomization this set applies.
    ///
    /// ```
    /// use nyquist::{scramble::Scramble, sequence::ScrambledHalton};
    /// assert_eq!(ScrambledHalton::new(2, 0).unwrap().strategy(), Scramble::PermuteDigits);
    /// ```
    pub fn strategy(&self) -> Scramble {
        self.strategy
    }
}

impl Sequence for ScrambledHalton {
    fn dims(&self) -> u32 {
        self.dims
    }

    fn point_count(&self) -> Option<u64> {
        None
    }

    fn sample(&self, index: u64, dim: u32) -> f32 {
        let (dim, seed) = (dim % self.dims, self.seed);
        match self.strategy {
            Scramble::None => radical_inverse(dim, index),
            Scramble::PermuteDigits => scrambled_radical_inverse(dim, index, seed),
            Scramble::FastOwen => fast_owen_scrambled_radical_inverse(dim, index, seed),
            Scramble::Owen => owen_scrambled_radical_inverse(dim, index, seed),
        }
    }

    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        let (dim, seed) = (dim % self.dims, self.seed);
        match self.strategy {
            Scramble::None => radical_inverse_f64(dim, index),
            Scramble::PermuteDigits => scrambled_radical_inverse_f64(dim, index, seed),
            Scramble::FastOwen => fast_owen_scrambled_radical_inverse_f64(dim, index, seed),
            Scramble::Owen => owen_scrambled_radical_inverse_f64(dim, index, seed),
        }
    }

    /// As [`Sequence::fill`]; with [`Scramble::None`], [`Halton::fill`]'s incremental path.
    fn fill(&self, first: u64, dims: u32, out: &mut [f32]) -> Result<u64, Error> {
        if self.strategy == Scramble::None {
            return Halton { dims: self.dims }.fill(first, dims, out);
        }
        let n = check_fill(self.dims, None, first, dims, out.len())?;
        for (k, point) in (0..n).zip(out.chunks_exact_mut(dims as usize)) {
            for (dim, x) in (0..dims).zip(point) {
                *x = self.sample(first + k, dim);
            }
        }
        Ok(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fill_f64_equals_the_values_one_by_one_for_every_strategy() {
        let strategies = [
            Scramble::None,
            Scramble::PermuteDigits,
            Scramble::FastOwen,
            Scramble::Owen,
        ];
        for strategy in strategies {
            let h = ScrambledHalton::with_strategy(9, strategy, 21).unwrap();
            for (first, n, dims) in [(0u64, 700usize, 9u32), (12345, 3, 4), (1 << 40, 300, 1)] {
                let mut out = std::vec![f64::NAN; n * dims as usize];
                assert_eq!(h.fill_f64(first, dims, &mut out), Ok(n as u64));
                for (k, point) in out.chunks_exact(dims as usize).enumerate() {
                    for (dim, &x) in (0..dims).zip(point) {
                        let want = h.sample_f64(first + k as u64, dim);
                        assert_eq!(
                            x.to_bits(),
                            want.to_bits(),
                            "{strategy:?} {first} {k} {dim}"
                        );
                    }
                }
            }
        }
        let h = ScrambledHalton::new(2, 1).unwrap();
        assert_eq!(
            h.fill_f64(0, 3, &mut [0.0; 3]),
            Err(Error::DimensionOutOfRange { dim: 2, dims: 2 })
        );
        assert_eq!(
            h.fill_f64(0, 2, &mut [0.0; 3]),
            Err(Error::BufferLength {
                multiple_of: 2,
                actual: 3
            })
        );
    }

    /// Found by the fuzzer: the default `fill` overflowed (debug panic) when its last index
    /// was `u64::MAX − 1`, computing the next index past the end.
    #[test]
    fn default_fill_reaches_the_last_indices_without_overflow() {
        let z = HaltonZaremba::new(1).unwrap();
        let mut buf = [0.0f32; 1];
        assert_eq!(z.fill(u64::MAX - 1, 1, &mut buf), Ok(1));
        assert_eq!(buf[0], z.sample(u64::MAX - 1, 0));
    }
    use proptest::prelude::*;

    fn sets() -> [(&'static str, std::boxed::Box<dyn Sequence>); 7] {
        [
            ("vdc", std::boxed::Box::new(VanDerCorput)),
            ("halton", std::boxed::Box::new(Halton::new(7).unwrap())),
            (
                "zaremba",
                std::boxed::Box::new(HaltonZaremba::new(7).unwrap()),
            ),
            (
                "scrambled",
                std::boxed::Box::new(ScrambledHalton::new(7, 3).unwrap()),
            ),
            (
                "unscrambled",
                std::boxed::Box::new(ScrambledHalton::with_strategy(7, Scramble::None, 3).unwrap()),
            ),
            (
                "fast-owen",
                std::boxed::Box::new(
                    ScrambledHalton::with_strategy(7, Scramble::FastOwen, 3).unwrap(),
                ),
            ),
            (
                "owen",
                std::boxed::Box::new(ScrambledHalton::with_strategy(7, Scramble::Owen, 3).unwrap()),
            ),
        ]
    }

    #[test]
    fn halton_points_are_the_radical_inverses_of_the_primes() {
        let h = Halton::new(1024).unwrap();
        for i in [0u64, 1, 2, 17, 1 << 40] {
            for d in [0u32, 1, 2, 100, 1023] {
                assert_eq!(h.sample(i, d), radical_inverse(d, i));
                assert_eq!(h.sample_f64(i, d), radical_inverse_f64(d, i));
            }
        }
        // The first Halton points in 2D.
        let expect = [
            (0.0, 0.0),
            (0.5, 1.0 / 3.0),
            (0.25, 2.0 / 3.0),
            (0.75, 1.0 / 9.0),
        ];
        for (i, &(x, y)) in expect.iter().enumerate() {
            assert_eq!(h.sample_f64(i as u64, 0), x);
            assert_eq!(h.sample_f64(i as u64, 1), y);
        }
    }

    #[test]
    fn constructors_validate_dims() {
        assert_eq!(Halton::new(0), Err(Error::ZeroSize { what: "dims" }));
        assert_eq!(
            Halton::new(1025),
            Err(Error::NotInRange {
                what: "dims",
                value: 1025,
                min: 1,
                max: 1024
            })
        );
        assert!(HaltonZaremba::new(1025).is_err());
        assert!(ScrambledHalton::new(0, 1).is_err());
        assert_eq!(Halton::new(1024).unwrap().dims(), 1024);
    }

    #[test]
    fn fill_equals_repeated_sample() {
        for (name, set) in sets() {
            let dims = set.dims().min(3);
            let mut buf = [0.0f32; 30];
            let n = set.fill(1000, dims, &mut buf).unwrap();
            assert_eq!(n, 30 / u64::from(dims));
            for (p, point) in buf.chunks_exact(dims as usize).enumerate() {
                for (d, &x) in point.iter().enumerate() {
                    assert_eq!(x, set.sample(1000 + p as u64, d as u32), "{name}");
                }
            }
        }
    }

    #[test]
    fn halton_2d_first_points_are_stratified() {
        // The first 2^a·3^b Halton points fall one per cell of a 2^a × 3^b grid.
        let h = Halton::new(2).unwrap();
        let (nx, ny) = (16usize, 9usize);
        let mut seen = [[false; 9]; 16];
        for i in 0..(nx * ny) as u64 {
            let cx = (h.sample_f64(i, 0) * nx as f64) as usize;
            let cy = (h.sample_f64(i, 1) * ny as f64) as usize;
            assert!(!seen[cx][cy], "cell ({cx}, {cy}) twice");
            seen[cx][cy] = true;
        }
    }

    #[test]
    fn strategies_give_their_radical_inverses() {
        for (i, d) in [(0u64, 0u32), (5, 1), (1 << 40, 6), (u64::MAX, 3)] {
            let set = |s| ScrambledHalton::with_strategy(7, s, 11).unwrap();
            let f32s = [
                radical_inverse(d, i),
                scrambled_radical_inverse(d, i, 11),
                fast_owen_scrambled_radical_inverse(d, i, 11),
                owen_scrambled_radical_inverse(d, i, 11),
            ];
            let f64s = [
                radical_inverse_f64(d, i),
                scrambled_radical_inverse_f64(d, i, 11),
                fast_owen_scrambled_radical_inverse_f64(d, i, 11),
                owen_scrambled_radical_inverse_f64(d, i, 11),
            ];
            for (k, s) in Scramble::ALL.into_iter().enumerate() {
                assert_eq!(set(s).sample(i, d + 7), f32s[k], "{s:?}");
                assert_eq!(set(s).sample_f64(i, d), f64s[k], "{s:?}");
                assert_eq!(set(s).strategy(), s);
            }
        }
        assert_eq!(
            ScrambledHalton::new(3, 4),
            ScrambledHalton::with_strategy(3, Scramble::PermuteDigits, 4)
        );
    }

    /// Every strategy keeps the 2-D stratification of the first `2^a·3^b` points.
    #[test]
    fn scrambled_2d_first_points_are_stratified_for_every_strategy() {
        for s in Scramble::ALL {
            let h = ScrambledHalton::with_strategy(2, s, 5).unwrap();
            let mut seen = [[false; 27]; 32];
            for i in 0..32 * 27 {
                // Unscrambled values sit on cell edges, which f64 can round just below.
                let cx = h.sample_f64(i, 0) * 32.0 + 1e-9;
                let cy = h.sample_f64(i, 1) * 27.0 + 1e-9;
                let (cx, cy) = (cx as usize, cy as usize);
                assert!(!seen[cx][cy], "{s:?}: cell ({cx}, {cy}) twice");
                seen[cx][cy] = true;
            }
        }
    }

    /// Every set here is infinite: no point count, every `u64` index a point (the last one
    /// included), and the dimension count it was built with.
    #[test]
    fn every_set_is_infinite_with_its_own_dims() {
        for (name, set) in sets() {
            assert_eq!(set.point_count(), None, "{name}");
            assert_eq!(set.dims(), if name == "vdc" { 1 } else { 7 }, "{name}");
            assert!((0.0..1.0).contains(&set.sample(u64::MAX, 0)), "{name}");
            // A fill's exclusive end must be a `u64`: the last fillable index is one before.
            let mut last = [0.0f32; 1];
            assert_eq!(set.fill(u64::MAX - 1, 1, &mut last), Ok(1), "{name}");
            assert_eq!(last[0], set.sample(u64::MAX - 1, 0), "{name}");
        }
    }

    /// Φ₂(i) is `i`'s bits mirrored about the binary point: `reverse_bits(i) / 2⁶⁴`, exact in
    /// f64 for `i < 2⁵³` (the mirrored word then ends in 11 zero bits), and in f32 rounded to
    /// nearest but kept below 1. Every dimension of the van der Corput set reads it.
    #[test]
    fn van_der_corput_is_the_mirrored_index() {
        for i in [0u64, 1, 6, 0x2d, 0xdead_beef, (1 << 53) - 1] {
            let mirrored = i.reverse_bits() as f64 / 2f64.powi(64);
            for d in [0, 1, 9] {
                assert_eq!(VanDerCorput.sample_f64(i, d), mirrored, "i = {i}");
                let below_one = f32::from_bits(0x3f7f_ffff); // 1 − 2⁻²⁴
                assert_eq!(VanDerCorput.sample(i, d), (mirrored as f32).min(below_one));
            }
        }
    }

    /// The folded radical inverse from its definition (Kocis & Whiten 1997): digit `k` of `i`
    /// in base `b`, `a_k`, becomes `(a_k + k) mod b`, over infinitely many digits (the zeros
    /// above `i`'s top digit fold to nonzero digits), so Ψ₂(0) = 0.0101…₂ = 1/3. Summed here
    /// in f64 from the last digit that can matter to the first; dimension `d` is base
    /// `prime(d)` and dimensions wrap modulo `dims`.
    #[test]
    fn zaremba_folds_digit_k_by_k() {
        fn folded(b: u64, mut i: u64) -> f64 {
            let mut digits = [0u64; 80];
            for (k, digit) in digits.iter_mut().enumerate() {
                *digit = (i % b + k as u64) % b;
                i /= b;
            }
            // Base 2 needs the most digits: 2⁻⁸⁰ is far below f64's resolution near any value.
            digits
                .iter()
                .rev()
                .fold(0.0, |tail, &a| (a as f64 + tail) / b as f64)
        }
        let z = HaltonZaremba::new(7).unwrap();
        for i in [0u64, 1, 2, 5, 1000, 123_456_789, 1 << 40] {
            for d in 0..7u32 {
                let want = folded(crate::radical::prime(d).into(), i);
                for dim in [d, d + 7, d + 700] {
                    let (x, y) = (z.sample_f64(i, dim), z.sample(i, dim));
                    assert!(
                        (x - want).abs() < 1e-15,
                        "i = {i}, dim {dim}: {x} vs {want}"
                    );
                    assert!(
                        (f64::from(y) - want).abs() < 1.2e-7,
                        "i = {i}, dim {dim}: {y}"
                    );
                }
            }
        }
        assert_eq!(z.sample_f64(0, 0), 1.0 / 3.0);
    }

    proptest! {
        #[test]
        fn values_are_in_unit_interval(index in any::<u64>(), dim in any::<u32>()) {
            for (_, set) in sets() {
                let x = set.sample(index, dim);
                prop_assert!((0.0..1.0).contains(&x));
                let y = set.sample_f64(index, dim);
                prop_assert!((0.0..1.0).contains(&y));
            }
        }
    }
}
