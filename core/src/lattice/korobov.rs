//! Korobov rank-1 lattices: `N` points, point `k` is `frac(k·(1, a, a², …)/N)`.

use super::korobov_table::KOROBOV_TABLE;
use super::{fixed_ratio, fixed_to_f32, fixed_to_f64, rotation};
use crate::Error;
use crate::sequence::Sequence;

/// The most dimensions a [`Korobov`] lattice has.
const MAX_DIMS: u32 = 1024;

/// The most points [`Korobov::searched`] searches a multiplier for.
const MAX_SEARCHED: u64 = 4096;

/// The most points [`Korobov::searched_2d`] searches a multiplier for (2²⁴).
pub const KOROBOV_MAX_SEARCHED_2D: u64 = 1 << 24;

/// How many multipliers [`Korobov::searched_2d`] ranks by its cheap estimate and then measures
/// exactly.
const CANDIDATES_2D: usize = 16;

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
/// The multiplier decides the quality. [`Korobov::tabled`] takes it from A. H. Stroud's
/// published tables (3 to 6 dimensions, 101 to 10007 points, see [`KOROBOV_TABLE`]);
/// [`Korobov::searched`] picks the one that minimises the lattice's `P₂` criterion (the
/// criterion of Sloan & Joe 1994, §5.1) by an exhaustive search, and
/// [`Korobov::searched_2d`] does the same in two dimensions for up to 2²⁴ points.
///
/// [`KOROBOV_TABLE`]: super::KOROBOV_TABLE
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
    /// [`Error::ZeroSize`] for `n == 0` or `dims == 0`; [`Error::NotInRange`] (`what: "dims"`)
    /// above 1024. Unless `n == 1`: [`Error::NotInRange`] (`what: "a"`) unless `1 ≤ a < n`,
    /// and [`Error::Invalid`] (`what: "a"`, `other: n`) unless `gcd(a, n) = 1` (so that every
    /// coordinate is a permutation of the `k/N`).
    ///
    /// ```
    /// use nyquist::{lattice::Korobov, Error};
    /// assert!(Korobov::new(1024, 189, 4).is_ok());
    /// assert_eq!(
    ///     Korobov::new(1024, 190, 4).unwrap_err().to_string(),
    ///     "a 190 is not coprime to n = 1024"
    /// );
    /// assert_eq!(
    ///     Korobov::new(1024, 1024, 4),
    ///     Err(Error::NotInRange { what: "a", value: 1024, min: 1, max: 1023 })
    /// );
    /// ```
    pub fn new(n: u64, a: u64, dims: u32) -> Result<Korobov, Error> {
        if n == 0 {
            return Err(Error::ZeroSize { what: "n" });
        }
        if dims == 0 {
            return Err(Error::ZeroSize { what: "dims" });
        }
        if dims > MAX_DIMS {
            return Err(Error::NotInRange {
                what: "dims",
                value: u64::from(dims),
                min: 1,
                max: u64::from(MAX_DIMS),
            });
        }
        if n > 1 && (a == 0 || a >= n) {
            return Err(Error::NotInRange {
                what: "a",
                value: a,
                min: 1,
                max: n - 1,
            });
        }
        if n > 1 && gcd(a, n) != 1 {
            return Err(Error::Invalid {
                what: "a",
                value: a,
                rule: "is not coprime to n =",
                other: n,
            });
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
    /// [`Error::NotInRange`] (`what: "n"`, `1..=4096`) above 4096; then as [`Korobov::new`].
    ///
    /// ```
    /// use nyquist::lattice::Korobov;
    /// // In two dimensions the best multiplier for a Fibonacci number of points is the
    /// // Fibonacci generator (or its inverse, which gives the same lattice transposed).
    /// let k = Korobov::searched(89, 2).unwrap();
    /// assert!([34, 55].contains(&k.multiplier()));
    /// ```
    pub fn searched(n: u64, dims: u32) -> Result<Korobov, Error> {
        if n > MAX_SEARCHED {
            return Err(Error::NotInRange {
                what: "n",
                value: n,
                min: 1,
                max: MAX_SEARCHED,
            });
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

    /// The two-dimensional lattice of `n` points whose multiplier minimises `P₂` (as
    /// [`Korobov::searched`]`(n, 2)`), for up to 2²⁴ points, in time about linear in `n`
    /// (timings: `docs/performance.md`).
    ///
    /// In two dimensions the dual lattice of `(1, a)` is `{h : h₁ + a·h₂ ≡ 0 (mod n)}` and `P₂`
    /// is the sum of `1/(h̄₁·h̄₂)²`, `h̄ = max(1, |h|)`, over its non-zero vectors
    /// (Sloan & Joe 1994, §5.1). The vectors with the smallest `h̄₁·h̄₂` are the best
    /// approximations of `a/n`: the convergents and intermediate fractions of its continued
    /// fraction. The search ranks every `a ≤ n/2` coprime to `n` by the sum over those vectors
    /// alone (one continued-fraction expansion, cut short once the sum passes the 16th best so
    /// far), then computes `P₂` exactly for the 16 best and keeps the smallest (the smallest `a`
    /// on ties). It returns the exhaustive search's multiplier for every `n ≤ 600` and for the
    /// larger `n` tested (1009, 1024, 1597, 2039, 2048, 3001, 4093, 4096: test
    /// `searched_2d_matches_the_exhaustive_search`), though nothing guarantees that in general.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] for `n == 0`; [`Error::NotInRange`] (`what: "n"`, `1..=2²⁴`) above
    /// 2²⁴.
    ///
    /// ```
    /// use nyquist::lattice::Korobov;
    /// assert_eq!(Korobov::searched_2d(1000).unwrap(), Korobov::searched(1000, 2).unwrap());
    /// // F_17 = 1597 points: F_15 = 610 ≡ −F_16, the Fibonacci lattice reflected.
    /// assert_eq!(Korobov::searched_2d(1597).unwrap().multiplier(), 610);
    /// ```
    pub fn searched_2d(n: u64) -> Result<Korobov, Error> {
        if n > KOROBOV_MAX_SEARCHED_2D {
            return Err(Error::NotInRange {
                what: "n",
                value: n,
                min: 1,
                max: KOROBOV_MAX_SEARCHED_2D,
            });
        }
        Korobov::new(n, 1, 2)?;
        // The CANDIDATES_2D multipliers with the smallest estimate, kept sorted by estimate.
        let mut best = [(f64::INFINITY, 0u64); CANDIDATES_2D];
        for a in (1..=(n / 2).max(1)).filter(|&a| gcd(a, n) == 1) {
            let e = best_approximation_sum(n, a, best[CANDIDATES_2D - 1].0);
            if e < best[CANDIDATES_2D - 1].0 {
                let at = best.partition_point(|c| c.0 <= e);
                best.copy_within(at..CANDIDATES_2D - 1, at + 1);
                best[at] = (e, a);
            }
        }
        best.sort_unstable_by_key(|c| c.1);
        let mut pick = (f64::INFINITY, 1);
        for &(_, a) in best.iter().filter(|c| c.1 != 0) {
            let p = p2_2d(n, a);
            if p < pick.0 {
                pick = (p, a);
            }
        }
        Korobov::new(n, pick.1, 2)
    }

    /// The lattice of `n` points in `dims` dimensions with the multiplier of A. H. Stroud's
    /// tables (*Approximate Calculation of Multiple Integrals*, 1971, Tables 6.2–6.5; see
    /// [`KOROBOV_TABLE`]): the minimiser of Korobov's criterion
    /// `H(a) = (3^s/p) Σ_k Π_j (1 − 2{k a^j/p})²` for the prime `n = p` and `s = dims`, the first
    /// of the two multipliers the table prints.
    ///
    /// # Errors
    /// [`Error::NotInRange`] (`what: "dims"`) unless `3 ≤ dims ≤ 6`; [`Error::Invalid`]
    /// (`what: "n"`, `other: dims`) when the table has no row for `n` points in `dims`
    /// dimensions ([`Korobov::tabled_sizes`] lists those it has).
    ///
    /// [`KOROBOV_TABLE`]: super::KOROBOV_TABLE
    ///
    /// ```
    /// use nyquist::{lattice::Korobov, Error};
    /// assert_eq!(Korobov::tabled(1069, 4).unwrap().multiplier(), 71);
    /// let e = Korobov::tabled(1024, 4).unwrap_err();
    /// assert!(matches!(e, Error::Invalid { what: "n", value: 1024, other: 4, .. }));
    /// assert_eq!(e.to_string(), "n 1024 has no tabled multiplier for dims 4");
    /// assert_eq!(Korobov::tabled(1069, 2).unwrap_err().to_string(), "dims 2 is outside 3..=6");
    /// ```
    pub fn tabled(n: u64, dims: u32) -> Result<Korobov, Error> {
        if !(3..=6).contains(&dims) {
            return Err(Error::NotInRange {
                what: "dims",
                value: u64::from(dims),
                min: 3,
                max: 6,
            });
        }
        let row = KOROBOV_TABLE
            .iter()
            .find(|r| r.dims == dims && r.n == n)
            .ok_or(Error::Invalid {
                what: "n",
                value: n,
                rule: "has no tabled multiplier for dims",
                other: u64::from(dims),
            })?;
        Korobov::new(n, row.multipliers[0], dims)
    }

    /// The point counts [`Korobov::tabled`] has a multiplier for in `dims` dimensions, in
    /// increasing order (none outside 3 … 6).
    ///
    /// ```
    /// use nyquist::lattice::Korobov;
    /// let sizes: Vec<u64> = Korobov::tabled_sizes(6).collect();
    /// assert_eq!(sizes, [2129, 3001, 4001, 5003, 6007, 8191, 10007]);
    /// assert_eq!(Korobov::tabled_sizes(2).count(), 0);
    /// ```
    pub fn tabled_sizes(dims: u32) -> impl Iterator<Item = u64> {
        KOROBOV_TABLE
            .iter()
            .filter(move |r| r.dims == dims)
            .map(|r| r.n)
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

    /// Coordinate `dim` of point `index` in 64-bit fixed point, rotation included.
    #[inline]
    pub(crate) fn fixed(&self, index: u64, dim: u32) -> u64 {
        let dim = dim % self.dims;
        let g = match dim {
            0 => 1 % self.n,
            1 => self.a,
            _ => pow_mod(self.a, u64::from(dim), self.n),
        };
        let k = index % self.n;
        let step = (u128::from(k) * u128::from(g) % u128::from(self.n)) as u64;
        let shift = self.seed.map_or(0, |s| rotation(s, dim));
        fixed_ratio(step, self.n).wrapping_add(shift)
    }
}

/// `2π²`, the factor of `B₂` in the `P₂` criterion.
const TWO_PI2: f64 = 2.0 * core::f64::consts::PI * core::f64::consts::PI;

/// `1 + 2π² B₂(x/n)`, `B₂(t) = t² − t + 1/6`: one factor of the `P₂` sum.
#[inline]
fn p2_factor(x: u64, n: u64) -> f64 {
    let t = x as f64 / n as f64;
    1.0 + TWO_PI2 * (t * t - t + 1.0 / 6.0)
}

/// The `P₂` criterion of the Korobov lattice `(n, a)` in `dims` dimensions, `n ≤ 2³²`.
pub(crate) fn p2(n: u64, a: u64, dims: u32) -> f64 {
    debug_assert!(n <= 1 << 32);
    let mut sum = 0.0;
    for k in 0..n {
        let mut prod = 1.0;
        let mut g = 1u64;
        for _ in 0..dims {
            prod *= p2_factor(k * g % n, n);
            g = g * a % n;
        }
        sum += prod;
    }
    sum / n as f64 - 1.0
}

/// [`p2`] in two dimensions, by increments instead of products; `n ≤ 2⁶²`.
pub(crate) fn p2_2d(n: u64, a: u64) -> f64 {
    let mut sum = 0.0;
    let mut y = 0u64;
    for x in 0..n {
        sum += p2_factor(x, n) * p2_factor(y, n);
        y += a;
        if y >= n {
            y -= n;
        }
    }
    sum / n as f64 - 1.0
}

/// `Σ 1/(h̄₁ h̄₂)²` over the dual vectors `(h₁, h₂) = (|q·a − p·n|, q)` of the two-dimensional
/// lattice `(n, a)` where `p/q` runs over the convergents and intermediate fractions of `a/n`:
/// the terms of `P₂` that dominate it (each counted once, not with its signs and multiples).
/// Stops as soon as the sum passes `bound` (returning a value above it).
fn best_approximation_sum(n: u64, a: u64, bound: f64) -> f64 {
    let term = |q: u64, r: u64| {
        let t = q.max(1) as f64 * r.max(1) as f64;
        1.0 / (t * t)
    };
    // (q0, r0), (q1, r1): consecutive convergents' denominators and residues |q·a − p·n|.
    let (mut q0, mut r0, mut q1, mut r1) = (0u64, n, 1u64, a);
    let mut sum = 0.0;
    while r1 != 0 {
        sum += term(q1, r1);
        let c = r0 / r1;
        for j in 1..c {
            if sum > bound {
                return sum;
            }
            sum += term(q0 + j * q1, r0 - j * r1);
        }
        (q0, r0, q1, r1) = (q1, r1, q0 + c * q1, r0 - c * r1);
    }
    sum + term(q1, 0)
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
