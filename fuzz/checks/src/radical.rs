//! `nyquist::radical`: every form for any dimension and any `u64` index.

use nyquist::radical::{
    PRIME_COUNT, PRIMES, fast_owen_scrambled_radical_inverse,
    fast_owen_scrambled_radical_inverse_f64, fill_radical_inverse, folded_radical_inverse,
    folded_radical_inverse_f64, inverse_radical_inverse, owen_scrambled_radical_inverse,
    owen_scrambled_radical_inverse_f64, prime, radical_inverse, radical_inverse_at,
    radical_inverse_f64, scrambled_radical_inverse, scrambled_radical_inverse_f64,
};

use crate::{Bytes, in_unit, in_unit_f64};

/// Radical inverses: all forms in `[0, 1)` for any `(dim, index, seed)`; `dim` wraps modulo
/// 1024; `fill_radical_inverse` equals `radical_inverse` bit for bit (indices wrapping at
/// `u64::MAX`); `inverse_radical_inverse` inverts the digit reversal and is total.
pub fn radical(data: &[u8]) {
    let mut b = Bytes::new(data);
    let dim = b.u32();
    let a = if b.bool() {
        u64::from(b.u32())
    } else {
        b.u64()
    };
    let seed = b.u64();
    let len = b.below(300) as usize;
    let n_digits = b.u8();
    let inverse = b.u64();

    let base = prime(dim);
    assert_eq!(
        base,
        PRIMES[(dim % PRIME_COUNT) as usize],
        "prime({dim}) wraps modulo 1024"
    );
    assert_eq!(base, prime(dim % PRIME_COUNT));

    let x = radical_inverse(dim, a);
    assert!(in_unit(x), "radical_inverse({dim}, {a}) = {x}");
    assert_eq!(x.to_bits(), radical_inverse(dim % PRIME_COUNT, a).to_bits());
    let x64 = radical_inverse_f64(dim, a);
    assert!(in_unit_f64(x64), "radical_inverse_f64({dim}, {a}) = {x64}");
    // The f32 form is the f64 value rounded (down or to nearest) — never more than an f32 ulp
    // near 1 away.
    assert!(
        (f64::from(x) - x64).abs() <= 2.0f64.powi(-23),
        "{x} vs {x64}"
    );
    let f = folded_radical_inverse(dim, a);
    assert!(in_unit(f), "folded_radical_inverse({dim}, {a}) = {f}");
    let f64_ = folded_radical_inverse_f64(dim, a);
    assert!(
        in_unit_f64(f64_),
        "folded_radical_inverse_f64({dim}, {a}) = {f64_}"
    );
    let s = scrambled_radical_inverse(dim, a, seed);
    assert!(
        in_unit(s),
        "scrambled_radical_inverse({dim}, {a}, {seed}) = {s}"
    );
    let s64 = scrambled_radical_inverse_f64(dim, a, seed);
    assert!(
        in_unit_f64(s64),
        "scrambled_radical_inverse_f64({dim}, {a}, {seed}) = {s64}"
    );
    assert_eq!(
        s.to_bits(),
        scrambled_radical_inverse(dim, a, seed).to_bits()
    );
    for (name, f, g) in [
        (
            "owen",
            owen_scrambled_radical_inverse as fn(u32, u64, u64) -> f32,
            owen_scrambled_radical_inverse_f64 as fn(u32, u64, u64) -> f64,
        ),
        (
            "fast_owen",
            fast_owen_scrambled_radical_inverse,
            fast_owen_scrambled_radical_inverse_f64,
        ),
    ] {
        let (x, y) = (f(dim, a, seed), g(dim, a, seed));
        assert!(in_unit(x), "{name}({dim}, {a}, {seed}) = {x}");
        assert!(in_unit_f64(y), "{name}_f64({dim}, {a}, {seed}) = {y}");
        assert_eq!(x.to_bits(), f(dim, a, seed).to_bits());
    }

    // fill == per-value, including across the u64 wrap.
    let first = if len > 0 && a % 3 == 0 {
        u64::MAX - (a % 200)
    } else {
        a
    };
    let mut out = vec![2.0f32; len];
    fill_radical_inverse(dim, first, &mut out);
    for (i, &v) in out.iter().enumerate() {
        let want = radical_inverse(dim, first.wrapping_add(i as u64));
        assert_eq!(
            v.to_bits(),
            want.to_bits(),
            "fill_radical_inverse({dim}, {first})[{i}] = {v}, radical_inverse gives {want}"
        );
    }

    // radical_inverse_at == per-value for a batch of arbitrary indices (small, 32-bit and wide
    // ones mixed, so base 2 meets both of its block paths); a short `out` is an error.
    let batch: Vec<u64> = (0..len as u64)
        .map(|i| match i % 3 {
            0 => a.wrapping_add(i),
            1 => (a ^ seed.rotate_left(i as u32)) >> 32,
            _ => seed.wrapping_mul(i | 1),
        })
        .collect();
    let mut at = vec![2.0f32; len + 1];
    radical_inverse_at(dim, &batch, &mut at).unwrap();
    for (i, (&v, &idx)) in at.iter().zip(&batch).enumerate() {
        let want = radical_inverse(dim, idx);
        assert_eq!(
            v.to_bits(),
            want.to_bits(),
            "radical_inverse_at({dim})[{i}] at {idx}"
        );
    }
    assert_eq!(at[len], 2.0, "radical_inverse_at wrote past the batch");
    if len > 0 {
        assert!(radical_inverse_at(dim, &batch, &mut at[..len - 1]).is_err());
    }

    // inverse_radical_inverse: total for any arguments …
    let _ = inverse_radical_inverse(dim, inverse, u32::from(n_digits));
    // … and the inverse of the digit reversal of `a` over its digit count (when it fits).
    let b64 = u128::from(base);
    let mut digits = 0u32;
    let mut rev: u128 = 0;
    let mut rest = u128::from(a);
    while rest > 0 {
        rev = rev * b64 + rest % b64;
        rest /= b64;
        digits += 1;
    }
    let extra = u32::from(n_digits % 4);
    let mut pow: u128 = 1;
    let mut fits = true;
    for _ in 0..extra {
        rev *= b64; // trailing zero digits of `a` become leading zeros of the reversal
        if rev > u128::from(u64::MAX) {
            fits = false;
        }
    }
    for _ in 0..digits + extra {
        pow = pow.saturating_mul(b64);
    }
    if fits && rev <= u128::from(u64::MAX) {
        let back = inverse_radical_inverse(dim, rev as u64, digits + extra);
        assert_eq!(
            back,
            a,
            "inverse_radical_inverse({dim}, {rev}, {})",
            digits + extra
        );
        // And the radical inverse is that reversal over b^digits (a < b^digits).
        if extra == 0 && pow < (1u128 << 100) && a != 0 {
            let exact = rev as f64 / pow as f64;
            assert!(
                (x64 - exact).abs() <= 1e-12,
                "Φ({a}) = {x64}, digits give {exact}"
            );
        }
    }
}
