//! The Fibonacci lattice: `N = F_m` points, point `k` is `(k/N, frac(k·F_{m−1}/N))`.

use super::{fixed_ratio, fixed_to_f32, fixed_to_f64, rotation};
use crate::Error;
use crate::sequence::Sequence;

/// The largest `m` whose Fibonacci number `F_m` fits a `u64` (`F_93 ≈ 1.2·10¹⁹`).
pub const FIBONACCI_MAX_INDEX: u32 = 93;

/// The Fibonacci number `F_m` (`F_0 = 0`, `F_1 = F_2 = 1`), or `None` when it does not fit a
/// `u64` (`m > 93`).
///
/// ```
/// use nyquist::lattice::fibonacci;
/// assert_eq!(fibonacci(10), Some(55));
/// assert_eq!(fibonacci(93), Some(12_200_160_415_121_876_738));
/// assert_eq!(fibonacci(94), None);
/// ```
pub const fn fibonacci(m: u32) -> Option<u64> {
    if m > FIBONACCI_MAX_INDEX {
        return None;
    }
    let (mut a, mut b) = (0u64, 1u64);
    let mut i = 0;
    while i < m {
        let next = a.wrapping_add(b); // F_94 wraps, and is never returned
        a = b;
        b = next;
        i += 1;
    }
    Some(a)
}

/// The two-dimensional Fibonacci lattice of `N = F_m` points: point `k` is
/// `(k/N, frac(k·F_{m−1}/N))`, optionally shifted modulo 1 by a Cranley–Patterson rotation
/// drawn from a seed. Among rank-1 lattices of `F_m` points it has the best worst-case spacing
/// in two dimensions (Sloan & Joe 1994, §2.6; Niederreiter 1992, §5.3). Indices wrap modulo `N`.
///
/// ```
/// use nyquist::lattice::FibonacciLattice;
/// use nyquist::sequence::Sequence;
/// let f = FibonacciLattice::new(6).unwrap(); // F_6 = 8 points, generator (1, F_5 = 5)
/// let pts: Vec<(f32, f32)> = (0..4).map(|k| (f.sample(k, 0), f.sample(k, 1))).collect();
/// assert_eq!(pts, [(0.0, 0.0), (0.125, 0.625), (0.25, 0.25), (0.375, 0.875)]);
/// assert_eq!(f.point_count(), Some(8));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FibonacciLattice {
    n: u64,
    g: u64,
    shift: [u64; 2],
}

impl FibonacciLattice {
    /// The lattice of `F_m` points, unshifted.
    ///
    /// # Errors
    /// [`Error::NotInRange`] (`what: "m"`) unless `3 ≤ m ≤ 93` (`F_3 = 2` points up to `F_93`).
    ///
    /// ```
    /// use nyquist::{lattice::FibonacciLattice, Error};
    /// assert!(FibonacciLattice::new(17).is_ok()); // 1597 points
    /// assert_eq!(
    ///     FibonacciLattice::new(2),
    ///     Err(Error::NotInRange { what: "m", value: 2, min: 3, max: 93 })
    /// );
    /// assert_eq!(FibonacciLattice::new(94).unwrap_err().to_string(), "m 94 is outside 3..=93");
    /// ```
    pub fn new(m: u32) -> Result<FibonacciLattice, Error> {
        match (m >= 3).then(|| (fibonacci(m), fibonacci(m - 1))) {
            Some((Some(n), Some(g))) => Ok(FibonacciLattice {
                n,
                g,
                shift: [0; 2],
            }),
            _ => Err(Error::NotInRange {
                what: "m",
                value: u64::from(m),
                min: 3,
                max: u64::from(FIBONACCI_MAX_INDEX),
            }),
        }
    }

    /// The smallest lattice with at least `n` points (`F_m ≥ n`).
    ///
    /// # Errors
    /// [`Error::ZeroSize`] for `n == 0`; [`Error::NotInRange`] (`what: "n"`, `1..=F_93`) above
    /// `F_93`.
    ///
    /// ```
    /// use nyquist::lattice::FibonacciLattice;
    /// use nyquist::sequence::Sequence;
    /// assert_eq!(FibonacciLattice::at_least(1000).unwrap().point_count(), Some(1597));
    /// ```
    pub fn at_least(n: u64) -> Result<FibonacciLattice, Error> {
        if n == 0 {
            return Err(Error::ZeroSize { what: "n" });
        }
        let m = (3..=FIBONACCI_MAX_INDEX)
            .find(|&m| fibonacci(m).is_some_and(|f| f >= n))
            .ok_or(Error::NotInRange {
                what: "n",
                value: n,
                min: 1,
                max: fibonacci(FIBONACCI_MAX_INDEX).unwrap_or(u64::MAX),
            })?;
        FibonacciLattice::new(m)
    }

    /// The same lattice shifted modulo 1 by a Cranley–Patterson rotation drawn from `seed`
    /// (every seed gives a rotation; the same seed, the same one).
    ///
    /// ```
    /// use nyquist::lattice::FibonacciLattice;
    /// use nyquist::sequence::Sequence;
    /// let f = FibonacciLattice::new(10).unwrap();
    /// let r = f.rotated(7);
    /// assert_ne!(r.sample(0, 0), 0.0);
    /// assert_eq!(r, f.rotated(7));
    /// ```
    #[must_use]
    pub fn rotated(self, seed: u64) -> FibonacciLattice {
        FibonacciLattice {
            shift: [rotation(seed, 0), rotation(seed, 1)],
            ..self
        }
    }

    /// The number of points `F_m`.
    ///
    /// ```
    /// use nyquist::lattice::FibonacciLattice;
    /// assert_eq!(FibonacciLattice::new(10).unwrap().point_count_u64(), 55);
    /// ```
    pub fn point_count_u64(&self) -> u64 {
        self.n
    }

    /// The generator `F_{m−1}` of the second coordinate.
    ///
    /// ```
    /// use nyquist::lattice::FibonacciLattice;
    /// assert_eq!(FibonacciLattice::new(10).unwrap().generator(), 34);
    /// ```
    pub fn generator(&self) -> u64 {
        self.g
    }

    /// Coordinate `dim` (wrapped to `0..2`) of point `index` (wrapped modulo `N`) in 64-bit
    /// fixed point.
    #[inline]
    pub(crate) fn fixed(&self, index: u64, dim: u32) -> u64 {
        let k = index % self.n;
        let d = (dim % 2) as usize;
        let step = if d == 0 {
            k
        } else {
            (u128::from(k) * u128::from(self.g) % u128::from(self.n)) as u64
        };
        fixed_ratio(step, self.n).wrapping_add(self.shift[d])
    }
}

impl Sequence for FibonacciLattice {
    fn dims(&self) -> u32 {
        2
    }

    fn point_count(&self) -> Option<u64> {
        Some(self.n)
    }

    #[inline]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        fixed_to_f32(self.fixed(index, dim))
    }

    #[inline]
    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        fixed_to_f64(self.fixed(index, dim))
    }
}
