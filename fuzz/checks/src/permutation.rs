//! `nyquist::hash`: the stateless permutations and the hash-to-unit conversions.

use nyquist::hash::{Permutation, permute, unit_f32, unit_f64};

use crate::{Bytes, in_unit, in_unit_f64};

/// Permutations: `Permutation::new(n, seed)` is a bijection of `0..n` for any `n ≤ 4096` and
/// seed (`size() == max(n, 1)`, `apply(i)` for `i ≥ n` is `apply(i % n)`, `n == 0` maps to 0), as is
/// `permute(·, n, seed)`; `unit_f32`/`unit_f64` of any hash are in `[0, 1)`.
pub fn permutation(data: &[u8]) {
    let mut b = Bytes::new(data);
    let n = match b.u8() % 4 {
        0 => b.below(20),
        1 => b.below(300),
        _ => b.below(4096),
    };
    let seed = b.u32();
    let probe = b.u32();
    let h = b.u64();
    assert!(in_unit(unit_f32(h as u32)), "unit_f32({h})");
    assert!(in_unit_f64(unit_f64(h)), "unit_f64({h})");

    let p = Permutation::new(n, seed);
    assert_eq!(
        p.size(),
        n.max(1),
        "Permutation::new({n}, {seed}).size() (n, at least 1)"
    );
    assert_eq!(
        p,
        Permutation::new(n, seed),
        "Permutation::new is not deterministic"
    );
    if n == 0 {
        assert_eq!(p.apply(probe), 0, "the empty permutation maps {probe} to 0");
        let _ = permute(probe, 0, seed); // total
        return;
    }
    let mut seen = vec![false; n as usize];
    let mut seen_fn = vec![false; n as usize];
    for i in 0..n {
        let j = p.apply(i);
        assert!(j < n, "Permutation({n}, {seed}).apply({i}) = {j}");
        assert!(!seen[j as usize], "Permutation({n}, {seed}) hits {j} twice");
        seen[j as usize] = true;
        let k = permute(i, n, seed);
        assert!(k < n, "permute({i}, {n}, {seed}) = {k}");
        assert!(
            !seen_fn[k as usize],
            "permute(·, {n}, {seed}) hits {k} twice"
        );
        seen_fn[k as usize] = true;
    }
    assert_eq!(
        p.apply(probe),
        p.apply(probe % n),
        "apply({probe}) must wrap modulo {n}"
    );
}
