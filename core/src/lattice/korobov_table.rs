//! Published Korobov multipliers: A. H. Stroud's tables of Korobov's optimal coefficients.
//!
//! Source: A. H. Stroud, *Approximate Calculation of Multiple Integrals*, Prentice-Hall,
//! Englewood Cliffs NJ, 1971, §6.3, Tables 6.2 (s = 3, p. 202), 6.3 (s = 4, p. 203),
//! 6.4 (s = 5, p. 203) and 6.5 (s = 6, p. 204). Each row gives a prime number of points `p` and
//! the multiplier `a` of the generator `(1, a, a², …, a^{s−1})` that minimises Korobov's
//! criterion (Stroud's Theorem 6.3-5, eq. 6.3-6)
//!
//! `H(a) = (3^s / p) · Σ_{k=1}^{p} Π_{j=0}^{s−1} (1 − 2·{k·a^j / p})²`,
//!
//! printed twice per `p`: the two multipliers are `a` and `±a⁻¹ (mod p)`, the same lattice with
//! its coordinates reversed (and reflected), so they have the same `H`.
//!
//! The numbers were read from the transcription of those tables in the Tracker Component
//! Library (D. F. Crouse, U.S. Naval Research Laboratory, 2015; public domain), file
//! `Mathematical_Functions/Numerical_Integration/Lattice_Rules/KorobovLatticeRules.m`
//! (commit 27317126c57c19f57f6d14eb6aa35700f57b869a), not from the book itself. The tests
//! recompute `H` and find every tabled multiplier to be an exact minimiser, which a misread
//! digit would be unlikely to survive; see `licenses/stroud-korobov.txt`.

/// One row of Stroud's tables: `n` (a prime) points in `dims` dimensions, and the two
/// multipliers printed for them (`multipliers[1] ≡ ±multipliers[0]⁻¹ (mod n)`).
///
/// ```
/// use nyquist::lattice::KOROBOV_TABLE;
/// let row = KOROBOV_TABLE[0];
/// assert_eq!((row.dims, row.n, row.multipliers), (3, 101, [40, 48]));
/// assert_eq!(40 * 48 % 101, 1); // 48 is the inverse of 40 modulo 101
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct KorobovTableRow {
    /// Dimensions `s` the multipliers were chosen for (3 to 6).
    pub dims: u32,
    /// Number of points `p`, a prime (101 to 10007).
    pub n: u64,
    /// The two multipliers of the row, as printed.
    pub multipliers: [u64; 2],
}

const fn row(dims: u32, n: u64, a: u64, b: u64) -> KorobovTableRow {
    KorobovTableRow {
        dims,
        n,
        multipliers: [a, b],
    }
}

/// Stroud's (1971) Tables 6.2–6.5, one row per (dimension, number of points), in the book's
/// order: by dimension, then by `n`.
pub const KOROBOV_TABLE: [KorobovTableRow; 42] = [
    // Table 6.2, s = 3.
    row(3, 101, 40, 48),
    row(3, 199, 30, 73),
    row(3, 307, 75, 131),
    row(3, 523, 78, 114),
    row(3, 701, 215, 313),
    row(3, 1069, 136, 338),
    row(3, 1543, 355, 552),
    row(3, 2129, 359, 937),
    row(3, 3001, 276, 772),
    row(3, 4001, 722, 1934),
    row(3, 5003, 1476, 1949),
    row(3, 6007, 592, 2831),
    row(3, 8191, 739, 3303),
    row(3, 10007, 544, 3072),
    // Table 6.3, s = 4.
    row(4, 307, 42, 95),
    row(4, 523, 178, 238),
    row(4, 701, 82, 265),
    row(4, 1069, 71, 271),
    row(4, 1543, 128, 663),
    row(4, 2129, 766, 970),
    row(4, 3001, 174, 1466),
    row(4, 4001, 113, 956),
    row(4, 5003, 792, 2053),
    row(4, 6007, 1351, 2610),
    row(4, 8191, 2488, 3842),
    row(4, 10007, 1206, 1784),
    // Table 6.4, s = 5.
    row(5, 1069, 63, 526),
    row(5, 1543, 58, 133),
    row(5, 2129, 618, 720),
    row(5, 3001, 408, 890),
    row(5, 4001, 1534, 1651),
    row(5, 5003, 840, 1352),
    row(5, 6007, 509, 1487),
    row(5, 8191, 1386, 2228),
    row(5, 10007, 198, 1870),
    // Table 6.5, s = 6.
    row(6, 2129, 41, 727),
    row(6, 3001, 233, 322),
    row(6, 4001, 1751, 1780),
    row(6, 5003, 2037, 2208),
    row(6, 6007, 312, 1521),
    row(6, 8191, 1632, 3699),
    row(6, 10007, 2240, 2399),
];
