//! Rank-1 lattices and Kronecker sequences: point `k` is `frac(k·g/N + Δ)` for a lattice of `N`
//! points with generating vector `g`, or `frac(s + k·α)` for a Kronecker sequence with
//! irrational `α`, where the shift `Δ` (or `s`) is an optional Cranley–Patterson rotation.
//!
//! | type | point `k`, dimension `j` |
//! |---|---|
//! | [`FibonacciLattice`] | `(k/F_m, frac(k·F_{m−1}/F_m))`, two dimensions |
//! | [`Korobov`] | `frac(k·a^j mod N / N)`, generator `(1, a, a², …)`, `a` tabled or searched |
//! | [`Kronecker`] | Roberts' `R_d`: `frac(½ + k/φ_d^{j+1})`, `φ_d` the root of `x^{d+1} = x + 1` |
//!
//! Coordinates are computed in 64-bit fixed point (`frac` is a wrapping add), then rounded down
//! to the `f32` (24 bits) or `f64` (53 bits) grid, so every value lies in `[0, 1)` exactly and no
//! rounding drifts with the index.
//!
//! Sources: I. H. Sloan and S. Joe, *Lattice Methods for Multiple Integration* (Oxford 1994),
//! §2 (rank-1 lattices, Fibonacci lattices) and §4.1 (Cranley–Patterson rotation, after
//! R. Cranley and T. N. L. Patterson, *SIAM J. Numer. Anal.* 13, 1976); N. M. Korobov (1959) for
//! the generator `(1, a, a², …)`; A. H. Stroud, *Approximate Calculation of Multiple Integrals*
//! (Prentice-Hall 1971), Tables 6.2–6.5, for the tabled multipliers ([`KOROBOV_TABLE`]);
//! M. Roberts, "The unreasonable effectiveness of quasirandom sequences"
//! (extremelearning.com.au, 2018) for `R_d`.

mod fibonacci;
mod korobov;
mod korobov_table;
mod kronecker;

pub use fibonacci::{FIBONACCI_MAX_INDEX, FibonacciLattice, fibonacci};
pub use korobov::{KOROBOV_MAX_SEARCHED_2D, Korobov};
pub use korobov_table::{KOROBOV_TABLE, KorobovTableRow};
pub use kronecker::{KRONECKER_MAX_DIMS, Kronecker};

/// A fixed-point fraction `x / 2⁶⁴` rounded down to the `f32` grid of `[0, 1)` (24 bits).
#[inline]
pub(crate) fn fixed_to_f32(x: u64) -> f32 {
    (x >> 40) as f32 * (1.0 / (1u64 << 24) as f32)
}

/// A fixed-point fraction `x / 2⁶⁴` rounded down to the `f64` grid of `[0, 1)` (53 bits).
#[inline]
pub(crate) fn fixed_to_f64(x: u64) -> f64 {
    (x >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// `⌊2⁶⁴ · num / den⌋` for `num < den`: the fraction `num/den` in 64-bit fixed point.
#[inline]
pub(crate) fn fixed_ratio(num: u64, den: u64) -> u64 {
    ((u128::from(num) << 64) / u128::from(den)) as u64
}

/// The Cranley–Patterson shift of dimension `dim` for `seed`, in 64-bit fixed point.
#[inline]
pub(crate) fn rotation(seed: u64, dim: u32) -> u64 {
    crate::hash::hash2(seed, u64::from(dim))
}

#[cfg(test)]
mod tests;
