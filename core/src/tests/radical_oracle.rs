//! Exact rational oracle for the radical inverses: integer digits and a tiny big integer, no
//! floats. A result documented within 1 ulp passes when the exact value lies between its two
//! neighbours; one documented correctly rounded (the `f64` forms of Φ and of the scrambled
//! inverse off its stratum edges) when the exact value lies between the midpoints to its
//! neighbours, and on a midpoint only if its last mantissa bit is even.

use crate::radical::{
    PRIME_COUNT, folded_radical_inverse, folded_radical_inverse_f64, prime, radical_inverse,
    radical_inverse_f64, scrambled_radical_inverse, scrambled_radical_inverse_f64,
};
use crate::{hash, rng};
use core::cmp::Ordering;
use rand_core::Rng;
use std::vec::Vec;

/// A non-negative big integer, little-endian `u32` limbs.
#[derive(Clone, Debug)]
struct Big(Vec<u32>);

impl Big {
    fn from_u64(v: u64) -> Big {
        Big(std::vec![v as u32, (v >> 32) as u32])
    }

    fn mul_small(&mut self, m: u32) {
        let mut carry = 0u64;
        for limb in &mut self.0 {
            let t = u64::from(*limb) * u64::from(m) + carry;
            *limb = t as u32;
            carry = t >> 32;
        }
        if carry > 0 {
            self.0.push(carry as u32);
        }
    }

    fn add_small(&mut self, a: u32) {
        let mut carry = u64::from(a);
        for limb in &mut self.0 {
            if carry == 0 {
                return;
            }
            let t = u64::from(*limb) + carry;
            *limb = t as u32;
            carry = t >> 32;
        }
        if carry > 0 {
            self.0.push(carry as u32);
        }
    }

    fn add(&mut self, other: &Big) {
        if self.0.len() < other.0.len() {
            self.0.resize(other.0.len(), 0);
        }
        let mut carry = 0u64;
        for (i, limb) in self.0.iter_mut().enumerate() {
            let t = u64::from(*limb) + u64::from(other.0.get(i).copied().unwrap_or(0)) + carry;
            *limb = t as u32;
            carry = t >> 32;
        }
        if carry > 0 {
            self.0.push(carry as u32);
        }
    }

    fn shl(&mut self, bits: u32) {
        for _ in 0..bits / 32 {
            self.0.insert(0, 0);
        }
        let s = bits % 32;
        if s > 0 {
            let mut carry = 0u32;
            for limb in &mut self.0 {
                let next = *limb >> (32 - s);
                *limb = (*limb << s) | carry;
                carry = next;
            }
            if carry > 0 {
                self.0.push(carry);
            }
        }
    }

    fn mul_u64(&self, m: u64) -> Big {
        let mut lo = self.clone();
        lo.mul_small(m as u32);
        let mut hi = self.clone();
        hi.mul_small((m >> 32) as u32);
        hi.shl(32);
        lo.add(&hi);
        lo
    }

    fn cmp(&self, other: &Big) -> Ordering {
        let n = self.0.len().max(other.0.len());
        for i in (0..n).rev() {
            let a = self.0.get(i).copied().unwrap_or(0);
            let b = other.0.get(i).copied().unwrap_or(0);
            if a != b {
                return a.cmp(&b);
            }
        }
        Ordering::Equal
    }
}

/// An exact rational `num / den`.
#[derive(Clone, Debug)]
struct Ratio {
    num: Big,
    den: Big,
}

impl Ratio {
    fn from_parts(num: u64, den: u64) -> Ratio {
        Ratio {
            num: Big::from_u64(num),
            den: Big::from_u64(den),
        }
    }
}

/// A finite non-negative float as `mantissa · 2^exp`.
fn decompose(x: f64) -> (u64, i32) {
    if x == 0.0 {
        return (0, 0);
    }
    let bits = x.to_bits();
    let e = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & ((1 << 52) - 1);
    if e == 0 {
        (frac, -1074)
    } else {
        (frac | (1 << 52), e - 1075)
    }
}

/// Compares `num/den` with `m·2^e`.
fn cmp_ratio_scaled(r: &Ratio, m: u64, e: i32) -> Ordering {
    // num/den vs m·2^e  ⇔  num·2^(−e) vs m·den·2^0 (e ≤ 0 for values below 2⁵³).
    let mut lhs = r.num.clone();
    let mut rhs = r.den.mul_u64(m);
    if e < 0 {
        lhs.shl((-e) as u32);
    } else {
        rhs.shl(e as u32);
    }
    lhs.cmp(&rhs)
}

/// Compares `num/den` with the float `x ≥ 0`.
fn cmp_ratio_float(r: &Ratio, x: f64) -> Ordering {
    let (m, e) = decompose(x);
    cmp_ratio_scaled(r, m, e)
}

/// True when the exact value (or, for a bracket `[lo, hi]`, every value in it) lies within one
/// ulp of `got`: between `got`'s predecessor and successor.
fn within_one_ulp_f64(lo: &Ratio, hi: &Ratio, got: f64) -> bool {
    let below = if got == 0.0 {
        0.0
    } else {
        f64::from_bits(got.to_bits() - 1)
    };
    let above = f64::from_bits(got.to_bits() + 1);
    cmp_ratio_float(lo, below) != Ordering::Less && cmp_ratio_float(hi, above) != Ordering::Greater
}

fn within_one_ulp_f32(lo: &Ratio, hi: &Ratio, got: f32) -> bool {
    let below = if got == 0.0 {
        0.0
    } else {
        f32::from_bits(got.to_bits() - 1)
    };
    let above = f32::from_bits(got.to_bits() + 1);
    cmp_ratio_float(lo, f64::from(below)) != Ordering::Less
        && cmp_ratio_float(hi, f64::from(above)) != Ordering::Greater
}

/// Compares `num/den` with the midpoint `(x + y)/2` of two adjacent finite floats
/// `0 ≤ x < y < 1`.
fn cmp_ratio_midpoint(r: &Ratio, x: f64, y: f64) -> Ordering {
    let (my, ey) = decompose(y);
    // 0 decomposes as 0·2⁰; on y's exponent it is the same 0.
    let (mx, ex) = if x == 0.0 { (0, ey) } else { decompose(x) };
    // Adjacent floats' exponents differ by at most 1, so the sum of the two mantissas on the
    // smaller exponent is below 2⁵⁵: (x + y)/2 = sum·2^(e−1).
    let e = ex.min(ey);
    let sum = (mx << (ex - e)) + (my << (ey - e));
    cmp_ratio_scaled(r, sum, e - 1)
}

/// True when `got` is `r` rounded to the nearest `f64`, ties to even, or `r` is at least the
/// midpoint below 1 and `got` the largest `f64` below 1 (the clamp the radical inverses apply).
fn correctly_rounded_f64(r: &Ratio, got: f64) -> bool {
    let even = got.to_bits() & 1 == 0;
    // `r` on `got`'s side of a midpoint, or on it with `got` even.
    let inside = |side: Ordering, mid: Ordering| mid == side || (mid == Ordering::Equal && even);
    let above_low = got == 0.0 || {
        let below = f64::from_bits(got.to_bits() - 1);
        inside(Ordering::Greater, cmp_ratio_midpoint(r, below, got))
    };
    let below_high = got == crate::math::ONE_MINUS_EPSILON_F64 || {
        let above = f64::from_bits(got.to_bits() + 1);
        inside(Ordering::Less, cmp_ratio_midpoint(r, got, above))
    };
    above_low && below_high
}

/// The base-`b` digits of `a`, least significant first, by integer division.
fn digits(mut a: u64, b: u64) -> Vec<u64> {
    let mut out = Vec::new();
    while a > 0 {
        out.push(a % b);
        a /= b;
    }
    out
}

/// `Σ_j f_j b^−(j+1)` over the given digit string, exactly.
fn digit_string(ds: &[u64], b: u64) -> Ratio {
    let mut num = Big::from_u64(0);
    let mut den = Big::from_u64(1);
    for &d in ds {
        num.mul_small(b as u32);
        num.add_small(d as u32);
        den.mul_small(b as u32);
    }
    Ratio { num, den }
}

/// Φ_b(a), exactly.
fn phi_exact(a: u64, b: u64) -> Ratio {
    digit_string(&digits(a, b), b)
}

/// Ψ_b(a) bracketed: the digit string continued until `b^−len < 2⁻²⁰⁰`, then `[N/D, (N+1)/D]`.
fn psi_bracket(a: u64, b: u64) -> (Ratio, Ratio) {
    let mut ds: Vec<u64> = digits(a, b)
        .iter()
        .enumerate()
        .map(|(j, &d)| (d + j as u64) % b)
        .collect();
    let mut scale = 1.0f64;
    let mut j = ds.len() as u64;
    while scale > 1e-62 {
        ds.push(j % b);
        j += 1;
        scale /= b as f64;
    }
    let lo = digit_string(&ds, b);
    let mut hi = lo.clone();
    hi.num.add_small(1);
    (lo, hi)
}

/// The digit-permuted Φ, exactly: `(R·(b−1) + π(0)) / ((b−1)·bⁿ)`.
fn scrambled_exact(a: u64, b: u64, seed: u64) -> Ratio {
    // π = hash::permute keyed by hash2(seed, b) folded to 32 bits, the definition in the docs.
    let key = hash::hash2(seed, b);
    let pi = |d: u64| {
        u64::from(hash::permute(
            d as u32,
            b as u32,
            (key ^ (key >> 32)) as u32,
        ))
    };
    let ds: Vec<u64> = digits(a, b).iter().map(|&d| pi(d)).collect();
    let mut r = digit_string(&ds, b);
    r.num.mul_small(b as u32 - 1);
    r.num.add_small(pi(0) as u32);
    r.den.mul_small(b as u32 - 1);
    r
}

/// Edge indices for base `b`: 0, 1, b−1, b, b²−1, b^k−1 and b^k around the chunk size, u64::MAX.
fn edge_indices(b: u64) -> Vec<u64> {
    let mut out = std::vec![
        0,
        1,
        b - 1,
        b,
        b + 1,
        b * b - 1,
        b * b,
        u64::MAX,
        u64::MAX - 1
    ];
    let mut p = 1u64;
    while let Some(next) = p.checked_mul(b) {
        p = next;
        if p >= 1 << 28 {
            out.extend([p - 1, p, p + 1]);
        }
    }
    out.push(p - 1);
    out
}

fn check_all(dim: u32, a: u64, seed: u64) {
    let b = u64::from(prime(dim));
    let phi = phi_exact(a, b);
    let f = radical_inverse(dim, a);
    assert!(
        f < 1.0 && within_one_ulp_f32(&phi, &phi, f),
        "Φ f32 b={b} a={a}: {f}"
    );
    let g = radical_inverse_f64(dim, a);
    assert!(
        g < 1.0 && correctly_rounded_f64(&phi, g),
        "Φ f64 b={b} a={a}: {g}"
    );

    let (lo, hi) = psi_bracket(a, b);
    let f = folded_radical_inverse(dim, a);
    assert!(
        f < 1.0 && within_one_ulp_f32(&lo, &hi, f),
        "Ψ f32 b={b} a={a}: {f}"
    );
    let g = folded_radical_inverse_f64(dim, a);
    assert!(
        g < 1.0 && within_one_ulp_f64(&lo, &hi, g),
        "Ψ f64 b={b} a={a}: {g}"
    );

    let s = scrambled_exact(a, b, seed);
    let f = scrambled_radical_inverse(dim, a, seed);
    let g = scrambled_radical_inverse_f64(dim, a, seed);
    if scrambled_at_edge(b, seed) {
        // The exact value is the upper edge of the point's stratum: the result must be strictly
        // below it, and within 2 ulp.
        let up2_f = f32::from_bits(f.to_bits() + 2);
        let up2_g = f64::from_bits(g.to_bits() + 2);
        assert!(
            f < 1.0
                && cmp_ratio_float(&s, f64::from(f)) == Ordering::Greater
                && cmp_ratio_float(&s, f64::from(up2_f)) != Ordering::Greater,
            "scrambled f32 at edge b={b} a={a}: {f}"
        );
        assert!(
            g < 1.0
                && cmp_ratio_float(&s, g) == Ordering::Greater
                && cmp_ratio_float(&s, up2_g) != Ordering::Greater,
            "scrambled f64 at edge b={b} a={a}: {g}"
        );
    } else {
        assert!(
            f < 1.0 && within_one_ulp_f32(&s, &s, f),
            "scrambled f32 b={b} a={a}: {f}"
        );
        assert!(
            g < 1.0 && correctly_rounded_f64(&s, g),
            "scrambled f64 b={b} a={a}: {g}"
        );
    }
}

/// Whether π(0) = b − 1 for (b, seed): the scrambled value is then a stratum edge.
fn scrambled_at_edge(b: u64, seed: u64) -> bool {
    let key = hash::hash2(seed, b);
    u64::from(hash::permute(0, b as u32, (key ^ (key >> 32)) as u32)) == b - 1
}

/// For seeds with π(0) = b − 1 in small bases, the first b² points are one per stratum of
/// width b⁻² and strictly inside it (exactly, by rational comparison), and point 0 is below 1.
#[test]
fn scrambled_points_at_the_edge_stay_inside_their_strata() {
    for dim in [0u32, 1, 2, 3, 4] {
        let b = u64::from(prime(dim));
        let seeds: Vec<u64> = (0..4000u64)
            .filter(|&s| scrambled_at_edge(b, s))
            .take(3)
            .collect();
        assert_eq!(seeds.len(), 3, "base {b}");
        for seed in seeds {
            let n = b * b;
            let mut hit = std::vec![false; n as usize];
            for a in 0..n {
                for x in [
                    f64::from(scrambled_radical_inverse(dim, a, seed)),
                    scrambled_radical_inverse_f64(dim, a, seed),
                ] {
                    assert!(x < 1.0);
                    // cell = ⌊x·b²⌋: the rounded product can land on the next integer when x
                    // is just below an edge, so step back when the exact edge is above x.
                    let mut cell = (x * n as f64) as u64;
                    if cmp_ratio_float(&Ratio::from_parts(cell, n), x) == Ordering::Greater {
                        cell -= 1;
                    }
                    let lo = Ratio::from_parts(cell, n);
                    let hi = Ratio::from_parts(cell + 1, n);
                    assert_ne!(cmp_ratio_float(&lo, x), Ordering::Greater);
                    assert_eq!(cmp_ratio_float(&hi, x), Ordering::Greater);
                    if x == scrambled_radical_inverse_f64(dim, a, seed) {
                        assert!(!hit[cell as usize], "b={b} seed={seed}: cell {cell} twice");
                        hit[cell as usize] = true;
                    }
                }
            }
            assert!(hit.iter().all(|&h| h));
        }
    }
}

#[test]
fn every_base_meets_its_rounding_bound_on_edge_and_random_indices() {
    let mut r = rng::default_rng(0x5eed_0001);
    for dim in 0..PRIME_COUNT {
        let b = u64::from(prime(dim));
        for a in edge_indices(b) {
            check_all(dim, a, 17);
        }
        for _ in 0..6 {
            // Random indices of random bit length, so every chunk count is exercised.
            let bits = rng::uniform_below(&mut r, 64) + 1;
            let a = r.next_u64() >> (64 - bits);
            check_all(dim, a, r.next_u64());
        }
    }
}

#[test]
fn small_bases_meet_their_rounding_bounds_on_many_random_indices() {
    let mut r = rng::default_rng(0x5eed_0002);
    for dim in 0..16 {
        for _ in 0..300 {
            let bits = rng::uniform_below(&mut r, 64) + 1;
            let a = r.next_u64() >> (64 - bits);
            check_all(dim, a, r.next_u64());
        }
    }
}

#[test]
fn folded_values_with_all_leading_folded_digits_zero_meet_their_rounding_bounds() {
    // a_j = (−j) mod b makes every folded digit of a zero: the value is only the tiny tail, the
    // hardest case for the precision of the tail.
    for dim in [0u32, 1, 2, 8, 9, 100, 1023] {
        let b = u64::from(prime(dim));
        let mut a = 0u64;
        let mut p = 1u64;
        for j in 0..64u64 {
            let digit = (b - j % b) % b;
            let Some(term) = digit.checked_mul(p).and_then(|t| t.checked_add(a)) else {
                break;
            };
            a = term;
            check_all(dim, a, 3);
            match p.checked_mul(b) {
                Some(next) => p = next,
                None => break,
            }
        }
    }
}

#[test]
fn oracle_self_check() {
    // 1/3 vs floats around it.
    let third = Ratio {
        num: Big::from_u64(1),
        den: Big::from_u64(3),
    };
    assert!(within_one_ulp_f64(&third, &third, 1.0 / 3.0));
    assert!(!within_one_ulp_f64(
        &third,
        &third,
        1.0 / 3.0 + 4.0 * f64::EPSILON
    ));
    assert!(within_one_ulp_f32(&third, &third, 1.0 / 3.0));
    assert_eq!(cmp_ratio_float(&phi_exact(1, 2), 0.5), Ordering::Equal);
}
