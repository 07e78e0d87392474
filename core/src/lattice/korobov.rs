//! Korobov rank-1 lattices: `N` points, point `k` is `frac(k·(1, a, a², …)/N)`.

use super::{fixed_ratio, fixed_to_f32, fixed_to_f64, rotation};
use crate::Error;
use crate::sequence::Sequence;

/// The most dimensions a [`Korobov`] lattice has.
const MAX_DIMS: u32 = 1024;

/// `b^e mod n` for `n ≥ 1`.
fn pow_mod(b: u64, mut e: u64, n: u64) -> u64 {
    let (n, mut b, mut r) = (
        u128::from(n),
        u128::from(b) % u128::from(n),
        1u128 % u128::from(n),
    );
    while e > 0 {
        if e & 1 == 1 {
            r = r * b % n;
        }
        b = b * b % n;
        e >>= 1;
    }
    r as u64
}

const fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        let t = a % b;
        a = b;
        b = t;
    }
    a
}

/// The Korobov rank-1 lattice of `N` points with multiplier `a`: point `k`, dimension `j`, is
/// `frac(k·a^j mod N / N)`, optionally shifted modulo 1 by a Cranley–Patterson rotation.
/// With `N = F_m` and `a = F_{m−1}` its first two dimensions are the
/// [`FibonacciLattice`](super::FibonacciLattice). Indices wrap modulo `N`.
///
/// The multiplier decides the quality; [`Korobov::searched`] picks the one that minimises the
/// lattice's `P₂` criterion (the criterion of Sloan & Joe 1994, §5.1).
///
/// ```
/// use nyquist::lattice::Korobov;
/// use nyquist::sequence::Sequence;
/// let k = Korobov::new(8, 3, 3).unwrap(); // generator (1, 3, 9 mod 8 = 1)
/// assert_eq!((k.sample(1, 0), k.sample(1, 1), k.sample(1, 2)), (0.125, 0.375, 0.125));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Korobov {
    n: u64,
    a: u64,
    dims: u32,
    seed: Option<u64>,
}

impl Korobov {
    /// The lattice of `n` points, multiplier `a`, in `dims` dimensions, unshifted.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] for `n == 0` or `dims == 0`; [`Error::OutOfRange`] (`what: "a"`) unless
    /// `1 ≤ a < n` and `gcd(a, n) = 1` (so that every coordinate is a permutation of the
    /// `k/N`), or `n == 1`; [`Error::OutOfRange`] (`what: "dims"`) above 1024.
    ///
    /// ```
    /// use nyquist::{lattice::Korobov, Error};
    /// assert!(Korobov::new(1024, 189, 4).is_ok());
    /// assert_eq!(Korobov::new(1024, 190, 4), Err(Error::OutOfRange { what: "a" }));
    /// ```
    pub fn new(n: u64, a: u64, dims: u32) -> Result<Korobov, Error> {
        if n == 0 {
            return Err(Error::ZeroSize { what: "n" });
        }
        if dims == 0 {
            return Err(Error::ZeroSize { what: "dims" });
        }
        if dims > MAX_DIMS {
            return Err(Error::OutOfRange { what: "dims" });
        }
        if n > 1 && (a == 0 || a >= n || gcd(a, n) != 1) {
            return Err(Error::OutOfRange { what: "a" });
        }
        Ok(Korobov {
            n,
            a: a % n.max(1),
            dims,
            seed: None,
        })
    }

    /// The lattice of `n` points in `dims` dimensions whose multiplier minimises the
    /// criterion `P₂(a) = −1 + (1/N) Σ_k Π_j (1 + 2π² B₂({k·a^j/N}))`, `B₂(x) = x² − x + 1/6`
    /// (Korobov 1959; Sloan & Joe 1994, eq. 5.7 and §5.1), over all `1 ≤ a ≤ N/2` coprime to
    /// `N`, the smallest such `a` on ties. The search costs `O(N² · dims)`, so `n` is limited to
    /// 4096.
    ///
    /// # Errors
    /// As [`Korobov::new`]; [`Error::OutOfRange`] (`what: "n"`) above 4096.
    ///
    /// ```
    /// use nyquist::lattice::Korobov;
    /// // In two dimensions the best multiplier for a Fibonacci number of points is the
    /// // Fibonacci generator (or its inverse, which gives the same lattice transposed).
    /// let k = Korobov::searched(89, 2).unwrap();
    /// assert!([34, 55].contains(&k.multiplier()));
    /// ```
    pub fn searched(n: u64, dims: u32) -> Result<Korobov, Error> {
        if n > 4096 {
            return Err(Error::OutOfRange { what: "n" });
        }
        Korobov::new(n, 1, dims)?;
        let mut best = (f64::INFINITY, 1);
        for a in (1..=(n / 2).max(1)).filter(|&a| gcd(a, n) == 1) {
            let p = p2(n, a, dims);
            if p < best.0 {
                best = (p, a);
            }
        }
        Korobov::new(n, best.1, dims)
    }

    /// The same lattice shifted modulo 1 by a Cranley–Patterson rotation drawn from `seed`.
    ///
    /// ```
    /// use nyquist::lattice::Korobov;
    /// use nyquist::sequence::Sequence;
    /// let k = Korobov::new(64, 19, 2).unwrap().rotated(3);
    /// assert_ne!(k.sample(0, 0), 0.0);
    /// ```
    #[must_use]
    pub fn rotated(self, seed: u64) -> Korobov {
        Korobov {
            seed: Some(seed),
            ..self
        }
    }

    /// The multiplier `a`.
    ///
    /// ```
    /// use nyquist::lattice::Korobov;
    /// assert_eq!(Korobov::new(64, 19, 2).unwrap().multiplier(), 19);
    /// ```
    pub fn multiplier(&self) -> u64 {
        self.a
    }

    #[inline]
    fn fixed(&self, index: u64, dim: u32) -> u64 {
        let dim = dim % self.dims;
        let g = pow_mod(self.a, u64::from(dim), self.n);
        let k = index % self.n;
        let step = (u128::from(k) * u128::from(g) % u128::from(self.n)) as u64;
        let shift = self.seed.map_or(0, |s| rotation(s, dim));
        fixed_ratio(step, self.n).wrapping_add(shift)
    }
}

/// The `P₂` criterion of the Korobov lattice `(n, a)` in `dims` dimensions.
fn p2(n: u64, a: u64, dims: u32) -> f64 {
    let two_pi2 = 2.0 * core::f64::consts::PI * core::f64::consts::PI;
    let mut sum = 0.0;
    for k in 0..n {
        let mut prod = 1.0;
        let mut g = 1u64;
        for _ in 0..dims {
            let x = (u128::from(k) * u128::from(g) % u128::from(n)) as f64 / n as f64;
            prod *= 1.0 + two_pi2 * (x * x - x + 1.0 / 6.0);
            g = (u128::from(g) * u128::from(a) % u128::from(n)) as u64;
        }
        sum += prod;
    }
    sum / n as f64 - 1.0
}

impl Sequence for Korobov {
    fn dims(&self) -> u32 {
        self.dims
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
