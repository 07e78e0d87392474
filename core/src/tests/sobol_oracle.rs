//! Naive Sobol oracles: the Joe–Kuo recurrence straight from the data file's text, the generator
//! matrix as a bit matrix, its product with an index over GF(2) one bit at a time, and an
//! elementary-interval check for 2D nets.

use std::vec::Vec;

/// Direction numbers `V_1 … V_32` for every dimension described by a Joe–Kuo text file
/// (`d s a m_1 … m_s` per line after a header), with dimension 0 = van der Corput prepended.
///
/// Recurrence (Joe & Kuo 2008; data/sobol/README.md): `V_k = m_k · 2^(32−k)` for `k ≤ s`, and
/// `V_k = a_1 V_{k−1} ⊕ … ⊕ a_{s−1} V_{k−s+1} ⊕ V_{k−s} ⊕ (V_{k−s} ≫ s)` beyond.
pub(crate) fn matrices_from_joe_kuo(text: &str) -> Vec<[u32; 32]> {
    let mut out = Vec::new();
    out.push(core::array::from_fn(|k| 1u32 << (31 - k)));
    for line in text.lines().skip(1) {
        let fields: Vec<u32> = line
            .split_whitespace()
            .map(|f| f.parse().expect("number"))
            .collect();
        if fields.is_empty() {
            continue;
        }
        let (d, s, a) = (fields[0], fields[1] as usize, fields[2]);
        let m = &fields[3..];
        assert_eq!(d as usize, out.len() + 1, "dimensions are consecutive");
        assert_eq!(m.len(), s, "dimension {d}: s initial numbers");
        let mut v = [0u32; 33]; // 1-based
        for k in 1..=32usize {
            v[k] = if k <= s {
                m[k - 1] << (32 - k)
            } else {
                let mut x = v[k - s] ^ (v[k - s] >> s);
                for j in 1..s {
                    if (a >> (s - 1 - j)) & 1 == 1 {
                        x ^= v[k - j];
                    }
                }
                x
            };
        }
        out.push(core::array::from_fn(|k| v[k + 1]));
    }
    out
}

/// The 32 × 32 generator matrix over GF(2): `rows[r][c]` is bit `31 − r` (the `2^−(r+1)` digit)
/// of column `c`, the direction number used for index bit `c`.
pub(crate) fn generator_matrix(columns: &[u32; 32]) -> [[bool; 32]; 32] {
    core::array::from_fn(|r| core::array::from_fn(|c| (columns[c] >> (31 - r)) & 1 == 1))
}

/// The matrix times the index's bit vector over GF(2), one output digit at a time: digit `r` is
/// the parity of `Σ_c rows[r][c] · bit_c(index)`.
pub(crate) fn gf2_product(rows: &[[bool; 32]; 32], index: u32) -> u32 {
    let mut out = 0u32;
    for (r, row) in rows.iter().enumerate() {
        let mut parity = false;
        for (c, &entry) in row.iter().enumerate() {
            if entry && (index >> c) & 1 == 1 {
                parity = !parity;
            }
        }
        if parity {
            out |= 1 << (31 - r);
        }
    }
    out
}

/// Panics unless the `2^m` points (32-bit fractions) hit every elementary interval
/// `[a/2^i, (a+1)/2^i) × [b/2^(m−i), (b+1)/2^(m−i))`, `i = 0..=m`, exactly once.
pub(crate) fn assert_elementary_intervals(points: &[[u32; 2]], m: u32) {
    assert_eq!(points.len(), 1 << m);
    for i in 0..=m {
        let mut seen = std::vec![false; 1 << m];
        for p in points {
            let a = if i == 0 { 0 } else { p[0] >> (32 - i) } as usize;
            let b = if i == m { 0 } else { p[1] >> (32 - (m - i)) } as usize;
            let cell = (a << (m - i)) | b;
            assert!(
                !core::mem::replace(&mut seen[cell], true),
                "m={m} i={i}: interval ({a}, {b}) hit twice"
            );
        }
    }
}
