//! With the `lazy-tables` feature: the Sobol generator matrices built at first use from Joe and
//! Kuo's direction numbers bit-packed ([`SOBOL_DIRECTION_BITS`], 10 KiB) instead of stored
//! (128 KiB).
//! The recurrence is the one `scripts/gen_sobol.py` documents and runs to write the stored table.

use super::sobol_table::SOBOL_DIRECTION_BITS;
use crate::lazy_table::{Fill, LazyTable};

/// `n` bits of [`SOBOL_DIRECTION_BITS`] from bit `*at`, least significant first; advances `*at`.
const fn take(at: &mut usize, n: usize) -> u32 {
    let mut v = 0;
    let mut i = 0;
    while i < n {
        let b = *at + i;
        v |= ((SOBOL_DIRECTION_BITS[b / 8] >> (b % 8)) as u32 & 1) << i;
        i += 1;
    }
    *at += n;
    v
}

/// Rows `0 .. t.len()` (at most 1024) of the generator matrices, from [`SOBOL_DIRECTION_BITS`]:
/// `V_k = m_k · 2^(32 − k)` for `k ≤ s`, then
/// `V_k = a_1 V_(k−1) ^ … ^ a_(s−1) V_(k−s+1) ^ V_(k−s) ^ (V_(k−s) >> s)` (`a_1` the most
/// significant of the `s − 1` bits of `a`); dimension 0 is van der Corput, `V_k = 2^(32 − k)`.
/// A `const fn`, so `compact::Sobol` bakes its few rows at compile time from the same words.
pub(crate) const fn matrix_rows(t: &mut [[u32; 32]]) {
    let mut at = 0;
    let mut d = 0;
    while d < t.len() && d < 1024 {
        if d == 0 {
            let mut k = 0;
            while k < 32 {
                t[0][k] = 1 << (31 - k);
                k += 1;
            }
        } else {
            let s = take(&mut at, 4) as usize;
            let a = take(&mut at, s - 1);
            let mut k = 0;
            while k < s {
                // m_(k+1), odd, below 2^(k+1), stored as (m − 1)/2 in k bits.
                let m = 2 * take(&mut at, k) + 1;
                t[d][k] = m << (31 - k);
                k += 1;
            }
            while k < 32 {
                let mut v = t[d][k - s] ^ (t[d][k - s] >> s);
                let mut j = 1;
                while j < s {
                    if (a >> (s - 1 - j)) & 1 == 1 {
                        v ^= t[d][k - j];
                    }
                    j += 1;
                }
                t[d][k] = v;
                k += 1;
            }
        }
        d += 1;
    }
}

/// Rows `0 .. t.len()` (at most 1024) of the columns past 32 ([`SOBOL_MATRICES_HI`]): the same
/// recurrence on 64-bit words (`V_k = m_k · 2^(64 − k)`, exact up to `k = 64`), each word's upper
/// half for `k = 33 ..= 64`. A `const fn`, so `compact::Sobol` bakes its few rows too.
pub(crate) const fn matrix_rows_hi(t: &mut [[u32; 32]]) {
    let mut at = 0;
    let mut d = 0;
    while d < t.len() && d < 1024 {
        // Dimension 0 (van der Corput) has no bits past 2^-32 in these columns: all zero.
        if d > 0 {
            let s = take(&mut at, 4) as usize;
            let a = take(&mut at, s - 1);
            let mut v = [0u64; 64];
            let mut k = 0;
            while k < 64 {
                v[k] = if k < s {
                    ((2 * take(&mut at, k) + 1) as u64) << (63 - k)
                } else {
                    let mut x = v[k - s] ^ (v[k - s] >> s);
                    let mut j = 1;
                    while j < s {
                        if (a >> (s - 1 - j)) & 1 == 1 {
                            x ^= v[k - j];
                        }
                        j += 1;
                    }
                    x
                };
                k += 1;
            }
            let mut k = 0;
            while k < 32 {
                t[d][k] = (v[32 + k] >> 32) as u32;
                k += 1;
            }
        }
        d += 1;
    }
}

/// [`SOBOL_MATRICES`]' fill.
pub(crate) struct FromDirections;

impl Fill for FromDirections {
    type Table = [[u32; 32]; 1024];

    fn fill(t: &mut [[u32; 32]; 1024]) {
        matrix_rows(t)
    }
}

/// `SOBOL_MATRICES[d][k]`: as the stored table in `sobol_table.rs`, built at first use (in
/// tests, next to the stored table).
#[cfg_attr(all(test, not(feature = "lazy-tables")), allow(dead_code))]
pub(crate) static SOBOL_MATRICES: LazyTable<FromDirections> = LazyTable::new([[0; 32]; 1024]);

/// [`SOBOL_MATRICES_HI`]' fill.
pub(crate) struct HighFromDirections;

impl Fill for HighFromDirections {
    type Table = [[u32; 32]; 1024];

    fn fill(t: &mut [[u32; 32]; 1024]) {
        matrix_rows_hi(t)
    }
}

/// `SOBOL_MATRICES_HI[d][k]`: as the stored table in `sobol_table.rs`, built at first use.
#[cfg_attr(all(test, not(feature = "lazy-tables")), allow(dead_code))]
pub(crate) static SOBOL_MATRICES_HI: LazyTable<HighFromDirections> =
    LazyTable::new([[0; 32]; 1024]);

#[cfg(test)]
mod tests {
    use super::*;

    /// The matrices built from the packed numbers equal the stored table, which `table_is_current`
    /// (in `sobol.rs`) checks against the data file; so do the rows baked at compile time.
    #[test]
    fn matrices_from_packed_directions_equal_the_stored_table() {
        let stored = &super::super::sobol_table::SOBOL_MATRICES;
        assert!(*SOBOL_MATRICES == *stored);
        const FIRST: [[u32; 32]; 5] = {
            let mut t = [[0; 32]; 5];
            matrix_rows(&mut t);
            t
        };
        assert_eq!(FIRST, stored[..5]);
    }

    /// The columns past 32 built from the packed numbers equal the stored ones.
    #[test]
    fn high_columns_from_packed_directions_equal_the_stored_table() {
        let stored = &super::super::sobol_table::SOBOL_MATRICES_HI;
        assert!(*SOBOL_MATRICES_HI == *stored);
        const FIRST: [[u32; 32]; 5] = {
            let mut t = [[0; 32]; 5];
            matrix_rows_hi(&mut t);
            t
        };
        assert_eq!(FIRST, stored[..5]);
    }
}
