// ---------------------------------------------------------------------------------------------
// halton: the radical inverse Φ_b in the first 1024 prime bases (core/src/radical/), its digit
// permuted and nested (Owen) scrambles, the Halton sequence (core/src/sequence/halton.rs) and
// pbrt's global Halton pixel sampler (core/src/sampler/halton.rs). Indices are 64-bit words
// (vec2<u32>, x low).
//
// The core rounds some values through f64: its short path `(rev as f64 · inv) as f32`, its
// divisions `(num as f64 / den as f64) as f32`. WGSL has no f64 and its f32 division is not
// correctly rounded, so every value here is an exact integer (a product or a quotient of
// multiword integers, 128-bit words as vec4<u32>, x lowest) rounded in integer arithmetic:
// to 53 bits, ties to even, then to 24 bits, ties to even, where the core rounds twice, and
// once to 24 bits where it rounds once. A value is assembled from its bits; no float
// arithmetic touches it (but the film coordinate's one addition, as in every sampler).
//
// The per-base constants are a storage buffer of 1024 × 24 words (`nyquist_gpu::halton_bases()`,
// 96 KiB), base d's words at 24·d:
//   0      b, the d-th prime
//   1      b^k, k the largest with b^k < 2³²: indices below it take the core's short path
//   2, 3   for an index of c + 1 nibbles (c = 0..7), byte c: the digits N_c its reversal spans
//   4      the largest power of b up to 2¹⁶ (a 64-bit index's digits come in runs of that size)
//   5      its exponent
//   6, 7   zero
//   8 + 2c, 9 + 2c  the f64 bits (low, high word) of 1/b^N_c, the core's rounded reciprocal
// Its group and binding are those below unless the engine asks for others
// (`nyquist_gpu::Bindings`).

@group(0) @binding(4) var<storage, read> nyq_halton_bases: array<u32>;

// Words per base in `nyq_halton_bases`.
const NYQ_HALTON_WORDS: u32 = 24u;

// The bits of the largest f32 below one.
const NYQ_BELOW_ONE_BITS: u32 = 0x3f7fffffu;

// The number of prime bases; dimension d reads base d mod 1024.
const NYQ_PRIME_COUNT: u32 = 1024u;

// ---- 64- and 128-bit words

// a − b modulo 2⁶⁴.
fn nyq_sub64(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    return vec2<u32>(a.x - b.x, a.y - b.y - select(0u, 1u, a.x < b.x));
}

// ⌊x / d⌋ (xy) and x mod d (z) for a 64-bit x and 0 < d ≤ 2¹⁶: long division in 16-bit limbs,
// each step's dividend below 2³².
fn nyq_divmod64_small(x: vec2<u32>, d: u32) -> vec3<u32> {
    if x.y == 0u {
        let q = x.x / d;
        return vec3<u32>(q, 0u, x.x - q * d);
    }
    let t3 = x.y >> 16u;
    let q3 = t3 / d;
    let t2 = ((t3 - q3 * d) << 16u) | (x.y & 0xffffu);
    let q2 = t2 / d;
    let t1 = ((t2 - q2 * d) << 16u) | (x.x >> 16u);
    let q1 = t1 / d;
    let t0 = ((t1 - q1 * d) << 16u) | (x.x & 0xffffu);
    let q0 = t0 / d;
    return vec3<u32>((q1 << 16u) | q0, (q3 << 16u) | q2, t0 - q0 * d);
}

// a + b modulo 2¹²⁸.
fn nyq_add128(a: vec4<u32>, b: vec4<u32>) -> vec4<u32> {
    let s = a + b;
    let c = select(vec4<u32>(0u), vec4<u32>(1u), s < a);
    let t1 = s.y + c.x;
    let k1 = c.y + select(0u, 1u, t1 < c.x);
    let t2 = s.z + k1;
    let k2 = c.z + select(0u, 1u, t2 < k1);
    return vec4<u32>(s.x, t1, t2, s.w + k2);
}

// a − b for a ≥ b.
fn nyq_sub128(a: vec4<u32>, b: vec4<u32>) -> vec4<u32> {
    let s = a - b;
    let o = select(vec4<u32>(0u), vec4<u32>(1u), a < b);
    let t1 = s.y - o.x;
    let k1 = o.y + select(0u, 1u, s.y < o.x);
    let t2 = s.z - k1;
    let k2 = o.z + select(0u, 1u, s.z < k1);
    return vec4<u32>(s.x, t1, t2, s.w - k2);
}

// a < b.
fn nyq_lt128(a: vec4<u32>, b: vec4<u32>) -> bool {
    if a.w != b.w {
        return a.w < b.w;
    }
    if a.z != b.z {
        return a.z < b.z;
    }
    if a.y != b.y {
        return a.y < b.y;
    }
    return a.x < b.x;
}

// x · k modulo 2¹²⁸ for a 32-bit k.
fn nyq_mul128_u32(x: vec4<u32>, k: u32) -> vec4<u32> {
    let p0 = nyq_mul_wide(x.x, k);
    let p1 = nyq_add64(nyq_mul_wide(x.y, k), vec2<u32>(p0.y, 0u));
    let p2 = nyq_add64(nyq_mul_wide(x.z, k), vec2<u32>(p1.y, 0u));
    return vec4<u32>(p0.x, p1.x, p2.x, x.w * k + p2.y);
}

// The full 128-bit product of two 64-bit words.
fn nyq_mul64_wide(a: vec2<u32>, b: vec2<u32>) -> vec4<u32> {
    let ll = nyq_mul_wide(a.x, b.x);
    let lh = nyq_mul_wide(a.x, b.y);
    let hl = nyq_mul_wide(a.y, b.x);
    let hh = nyq_mul_wide(a.y, b.y);
    let outer = vec4<u32>(ll.x, ll.y, hh.x, hh.y);
    return nyq_add128(nyq_add128(outer, vec4<u32>(0u, lh.x, lh.y, 0u)), vec4<u32>(0u, hl.x, hl.y, 0u));
}

// Leading zeros of a 128-bit word (128 for 0).
fn nyq_clz128(x: vec4<u32>) -> u32 {
    if x.w != 0u {
        return countLeadingZeros(x.w);
    }
    if x.z != 0u {
        return 32u + countLeadingZeros(x.z);
    }
    if x.y != 0u {
        return 64u + countLeadingZeros(x.y);
    }
    return 96u + countLeadingZeros(x.x);
}

// x << s for 0 ≤ s < 128.
fn nyq_shl128(x: vec4<u32>, s: u32) -> vec4<u32> {
    var v = x;
    var k = s;
    while k >= 32u {
        v = vec4<u32>(0u, v.x, v.y, v.z);
        k -= 32u;
    }
    if k == 0u {
        return v;
    }
    let r = 32u - k;
    return vec4<u32>(v.x << k, (v.y << k) | (v.x >> r), (v.z << k) | (v.y >> r), (v.w << k) | (v.z >> r));
}

// ---- rounding

// A value to round, (x + δ)·2^e with δ ∈ (0, 1) present when `sticky` != 0: to 53 bits and
// then to 24 when `twice` != 0, once to 24 otherwise; then, when `below` != 0, the float below
// (the digit-permuted scramble's stratum-edge rule).
struct NyqRounding {
    x: vec4<u32>,
    e: i32,
    sticky: u32,
    twice: u32,
    below: u32,
}

// The f32 bits of (x + δ)·2^e, x a 128-bit integer and δ ∈ (0, 1) present when `sticky`:
// rounded to 24 bits, ties to even, or (`twice`) first to 53 bits, ties to even, as an f64
// would hold it, then that to 24 bits, ties to even. Not clamped. The value must lie in f32's
// normal range (every caller's does: 0 or above 2⁻¹²⁰).
fn nyq_round_bits(x_in: vec4<u32>, e_in: i32, sticky: bool, twice: bool) -> u32 {
    if all(x_in == vec4<u32>(0u)) {
        return 0u;
    }
    let z = nyq_clz128(x_in);
    let x = nyq_shl128(x_in, z);
    // value = (x + δ)·2^e with x's leading one at bit 127.
    let e = e_in - i32(z);
    let rest = x.x != 0u || x.y != 0u || sticky;
    var m: u32;
    if twice {
        // The top 53 bits, mh (21) and ml (32), rounded by the 75 below.
        var ml = (x.w << 21u) | (x.z >> 11u);
        var mh = x.w >> 11u;
        let r = x.z & 0x7ffu;
        if r > 0x400u || (r == 0x400u && (rest || (ml & 1u) == 1u)) {
            ml += 1u;
            mh += select(0u, 1u, ml == 0u);
        }
        // That 53-bit integer (or 2⁵³) to 24 bits: nothing below it is left.
        m = (mh << 3u) | (ml >> 29u);
        let r2 = ml & 0x1fffffffu;
        if r2 > 0x10000000u || (r2 == 0x10000000u && (m & 1u) == 1u) {
            m += 1u;
        }
    } else {
        m = x.w >> 8u;
        let r = x.w & 0xffu;
        if r > 0x80u || (r == 0x80u && (x.z != 0u || rest || (m & 1u) == 1u)) {
            m += 1u;
        }
    }
    // value ≈ m·2^(e + 104), m ∈ [2²³, 2²⁴] (a carry to 2²⁴ is absorbed by the exponent field).
    return (u32(e + 254) << 23u) + m - 0x800000u;
}

// num / den (0 ≤ num < den < 2⁹⁶) as a value to round: restoring division of num aligned under
// den, 26 quotient bits (55 when `twice`) and the remainder as the sticky bit.
fn nyq_divide(num: vec4<u32>, den: vec4<u32>, twice: bool) -> NyqRounding {
    let tw = select(0u, 1u, twice);
    if all(num == vec4<u32>(0u)) {
        return NyqRounding(vec4<u32>(0u), 0, 0u, tw, 0u);
    }
    let s = nyq_clz128(num) - nyq_clz128(den);
    let steps = select(26u, 55u, twice);
    var q = vec2<u32>(0u, 0u);
    var sticky = false;
    if den.z == 0u && den.w == 0u && den.y < 0x80000000u {
        // Both below 2⁶³: the remainder stays within 64 bits.
        let d = den.xy;
        var r = nyq_shl128(num, s).xy;
        for (var i = 0u; i < steps; i++) {
            q = vec2<u32>(q.x << 1u, (q.y << 1u) | (q.x >> 31u));
            if r.y > d.y || (r.y == d.y && r.x >= d.x) {
                r = nyq_sub64(r, d);
                q.x |= 1u;
            }
            r = vec2<u32>(r.x << 1u, (r.y << 1u) | (r.x >> 31u));
        }
        sticky = r.x != 0u || r.y != 0u;
    } else {
        var r = nyq_shl128(num, s);
        for (var i = 0u; i < steps; i++) {
            q = vec2<u32>(q.x << 1u, (q.y << 1u) | (q.x >> 31u));
            if !nyq_lt128(r, den) {
                r = nyq_sub128(r, den);
                q.x |= 1u;
            }
            r = vec4<u32>(r.x << 1u, (r.y << 1u) | (r.x >> 31u), (r.z << 1u) | (r.y >> 31u), (r.w << 1u) | (r.z >> 31u));
        }
        sticky = any(r != vec4<u32>(0u));
    }
    // q = ⌊num·2^(s + steps − 1) / den⌋.
    return NyqRounding(vec4<u32>(q, 0u, 0u), 1 - i32(steps + s), select(0u, 1u, sticky), tw, 0u);
}

// ---- Φ_b and its scrambles

// The base of dimension `dim`: the (dim mod 1024)-th prime (core `radical::prime`).
fn nyq_prime(dim: u32) -> u32 {
    return nyq_halton_bases[NYQ_HALTON_WORDS * (dim % NYQ_PRIME_COUNT)];
}

// An exact fraction num / den to round, twice (`twice` != 0) or once, then (`below` != 0) to
// step to the float below.
struct NyqFraction {
    num: vec4<u32>,
    den: vec4<u32>,
    twice: u32,
    below: u32,
}

// Φ_b(a) for 0 < a < b^k (base words at t), the core's short path: the digits reversed over
// the N places of a's nibble class, times the core's f64 1/b^N, rounded to 53 bits and then to
// 24, as its `(rev as f64 * inv) as f32` does.
fn nyq_phi_short(t: u32, a: u32) -> NyqRounding {
    let b = nyq_halton_bases[t];
    let c = (35u - countLeadingZeros(a)) / 4u - 1u;
    let places = (nyq_halton_bases[t + 2u + c / 4u] >> (8u * (c % 4u))) & 0xffu;
    let low = nyq_halton_bases[t + 8u + 2u * c];
    let high = nyq_halton_bases[t + 9u + 2u * c];
    var x = a;
    var rev = vec2<u32>(0u, 0u);
    for (var i = 0u; i < places; i++) {
        let q = x / b;
        rev = nyq_add64(nyq_mul64x32(rev, b).xy, vec2<u32>(x - q * b, 0u));
        x = q;
    }
    // inv = mantissa · 2^(exponent − 1075), the mantissa's implicit one restored.
    let mantissa = vec2<u32>(low, (high & 0xfffffu) | 0x100000u);
    let e = i32((high >> 20u) & 0x7ffu) - 1075;
    return NyqRounding(nyq_mul64_wide(rev, mantissa), e, 0u, 1u, 0u);
}

// Φ_b(a) for any a (base words at t) as the exact fraction of the reversed digits over b^n,
// rounded once: the core's long path. The digits come in runs of the base's 16-bit chunk;
// leading zero digits in the last run scale both parts alike.
fn nyq_phi_fraction(t: u32, a: vec2<u32>) -> NyqFraction {
    let b = nyq_halton_bases[t];
    let chunk = nyq_halton_bases[t + 4u];
    let run = nyq_halton_bases[t + 5u];
    var x = a;
    var num = vec4<u32>(0u);
    var den = vec4<u32>(1u, 0u, 0u, 0u);
    while x.x != 0u || x.y != 0u {
        let qr = nyq_divmod64_small(x, chunk);
        x = qr.xy;
        var c = qr.z;
        var rev = 0u;
        for (var i = 0u; i < run; i++) {
            let q = c / b;
            rev = rev * b + (c - q * b);
            c = q;
        }
        num = nyq_add128(nyq_mul128_u32(num, chunk), vec4<u32>(rev, 0u, 0u, 0u));
        den = nyq_mul128_u32(den, chunk);
    }
    return NyqFraction(num, den, 0u, 0u);
}

// The digit-permuted Φ_b(a) (base words at t) as a fraction: every digit through one
// permutation π of 0..b keyed by (seed, b), the infinite tail of π(0)s summed in closed form,
// (R·(b−1) + π(0)) / ((b−1)·bⁿ); rounded through f64 while the denominator is below 2⁵³, once
// above; the float below when π(0) = b − 1 puts the value on its stratum's upper edge (core
// `scrambled_fraction`).
fn nyq_permuted_fraction(t: u32, a: vec2<u32>, seed: vec2<u32>) -> NyqFraction {
    let b = nyq_halton_bases[t];
    let chunk = nyq_halton_bases[t + 4u];
    let run = nyq_halton_bases[t + 5u];
    let key = nyq_hash2(seed, nyq_u64(b));
    let p = nyq_permutation(b, key.x ^ key.y);
    var x = a;
    var num = vec4<u32>(0u);
    var den = vec4<u32>(1u, 0u, 0u, 0u);
    while x.x != 0u || x.y != 0u {
        let qr = nyq_divmod64_small(x, chunk);
        x = qr.xy;
        let last = x.x == 0u && x.y == 0u;
        var c = qr.z;
        // This run's permuted digits (the last run's up to a's leading digit) and b to their
        // count, each below 2¹⁶.
        var part = 0u;
        var scale = 1u;
        for (var i = 0u; i < run; i++) {
            if last && c == 0u {
                break;
            }
            let q = c / b;
            part = part * b + nyq_permutation_apply(p, c - q * b);
            scale *= b;
            c = q;
        }
        num = nyq_add128(nyq_mul128_u32(num, scale), vec4<u32>(part, 0u, 0u, 0u));
        den = nyq_mul128_u32(den, scale);
    }
    let tail = nyq_permutation_apply(p, 0u);
    num = nyq_add128(nyq_mul128_u32(num, b - 1u), vec4<u32>(tail, 0u, 0u, 0u));
    den = nyq_mul128_u32(den, b - 1u);
    let small = den.w == 0u && den.z == 0u && den.y < 0x200000u;
    return NyqFraction(num, den, select(0u, 1u, small), select(0u, 1u, tail == b - 1u));
}

// The nested scrambles' domain tags ("OWEN_UNI", "OWEN_AFF"), level step ⌊2⁶⁴/φ⌋ and prefix
// multiplier: core radical/owen.rs.
const NYQ_OWEN_TAG_UNIFORM = vec2<u32>(0x5f554e49u, 0x4f57454eu);
const NYQ_OWEN_TAG_AFFINE = vec2<u32>(0x5f414646u, 0x4f57454eu);
const NYQ_OWEN_LEVEL_STEP = vec2<u32>(0x7f4a7c15u, 0x9e3779b9u);
const NYQ_OWEN_PREFIX_MUL = vec2<u32>(0x27220a95u, 0x517cc1b7u);

// The nested-scrambled Φ_b(a) (dimension d < 1024) as a fraction: digit j (a's zeros past its
// leading digit included) through a permutation of 0..b drawn from a hash of (seed, d, j,
// a mod bʲ), until b^K ≥ 2³²; uniform permutations or, with `affine`, x ↦ m·x + g mod b. R / b^K
// rounded through f64 (core `nested_f32`).
fn nyq_nested_fraction(d: u32, a: vec2<u32>, seed: vec2<u32>, affine: bool) -> NyqFraction {
    let b = nyq_halton_bases[NYQ_HALTON_WORDS * d];
    let key = nyq_hash3(seed, nyq_u64(d), select(NYQ_OWEN_TAG_UNIFORM, NYQ_OWEN_TAG_AFFINE, affine));
    var rest = a;
    var pow = vec2<u32>(1u, 0u);
    var level = 0u;
    var num = vec2<u32>(0u, 0u);
    var den = vec2<u32>(1u, 0u);
    while den.y == 0u {
        var next = vec2<u32>(0u, 0u);
        var digit = 0u;
        if rest.x != 0u || rest.y != 0u {
            let qr = nyq_divmod64_small(rest, b);
            next = qr.xy;
            digit = qr.z;
        }
        // a mod b^level = a − ⌊a/b^level⌋·b^level.
        let prefix = nyq_sub64(a, nyq_mul64(rest, pow));
        let h = nyq_mix64(nyq_add64(key ^ nyq_mul64(prefix, NYQ_OWEN_PREFIX_MUL), nyq_mul64(nyq_u64(level), NYQ_OWEN_LEVEL_STEP)));
        rest = next;
        pow = nyq_mul64(pow, nyq_u64(b));
        level += 1u;
        var out: u32;
        if affine {
            // g and m − 1 the mixed-radix digits of h/2⁶⁴ in bases b and b − 1.
            let gt = nyq_mul64x32(h, b);
            let m = 1u + nyq_mul64x32(gt.xy, b - 1u).z;
            out = (m * digit + gt.z) % b;
        } else if b <= 16u {
            out = nyq_nibble(nyq_packed_table(b, h), 4u * digit);
        } else {
            out = nyq_permutation_apply(nyq_permutation(b, h.x ^ h.y), digit);
        }
        num = nyq_add64(nyq_mul64x32(num, b).xy, vec2<u32>(out, 0u));
        den = nyq_mul64x32(den, b).xy;
    }
    return NyqFraction(vec4<u32>(num, 0u, 0u), vec4<u32>(den, 0u, 0u), 1u, 0u);
}

// Φ_b(a), b = prime(dim mod 1024), scrambled by `how` (NYQ_SCRAMBLE_*) under `seed`, as an f32
// in [0, 1), for every 64-bit index: core `radical_inverse` (none), `scrambled_radical_inverse`
// (permute digits), `fast_owen_scrambled_radical_inverse` and `owen_scrambled_radical_inverse`,
// bit for bit. One body for all four, each part once: a GPU compiler inlines every call.
fn nyq_radical_inverse_scrambled(dim: u32, a: vec2<u32>, seed: vec2<u32>, how: u32) -> f32 {
    let d = dim % NYQ_PRIME_COUNT;
    let t = NYQ_HALTON_WORDS * d;
    // Zero unless set below: Φ(0) of the short path.
    var r: NyqRounding;
    if how == NYQ_SCRAMBLE_NONE && d == 0u {
        // Φ₂: the 64-bit reversal of a, correctly rounded (core `phi2`).
        r = NyqRounding(vec4<u32>(reverseBits(a.y), reverseBits(a.x), 0u, 0u), -64, 0u, 0u, 0u);
    } else if how == NYQ_SCRAMBLE_NONE && a.y == 0u && a.x < nyq_halton_bases[t + 1u] {
        if a.x != 0u {
            r = nyq_phi_short(t, a.x);
        }
    } else {
        var f: NyqFraction;
        if how == NYQ_SCRAMBLE_NONE {
            f = nyq_phi_fraction(t, a);
        } else if how == NYQ_SCRAMBLE_PERMUTE_DIGITS {
            f = nyq_permuted_fraction(t, a, seed);
        } else {
            f = nyq_nested_fraction(d, a, seed, how == NYQ_SCRAMBLE_FAST_OWEN);
        }
        r = nyq_divide(f.num, f.den, f.twice != 0u);
        r.below = f.below;
    }
    var bits = nyq_round_bits(r.x, r.e, r.sticky != 0u, r.twice != 0u);
    if r.below != 0u {
        // The core clamps its long division's result below one before stepping below (not
        // its f64 division's): a value that rounds to one ends two floats below it.
        if r.twice == 0u {
            bits = min(bits, NYQ_BELOW_ONE_BITS);
        }
        bits -= 1u;
    }
    return bitcast<f32>(min(bits, NYQ_BELOW_ONE_BITS));
}

// Φ_b(a), b = prime(dim mod 1024): core `radical_inverse`.
fn nyq_radical_inverse(dim: u32, a: vec2<u32>) -> f32 {
    return nyq_radical_inverse_scrambled(dim, a, vec2<u32>(0u, 0u), NYQ_SCRAMBLE_NONE);
}

// Φ_b(a) with its digits through one permutation keyed by (seed, b): core
// `scrambled_radical_inverse`.
fn nyq_scrambled_radical_inverse(dim: u32, a: vec2<u32>, seed: vec2<u32>) -> f32 {
    return nyq_radical_inverse_scrambled(dim, a, seed, NYQ_SCRAMBLE_PERMUTE_DIGITS);
}

// Φ_b(a) under the nested uniform (Owen) scramble of `seed`: core
// `owen_scrambled_radical_inverse`.
fn nyq_owen_scrambled_radical_inverse(dim: u32, a: vec2<u32>, seed: vec2<u32>) -> f32 {
    return nyq_radical_inverse_scrambled(dim, a, seed, NYQ_SCRAMBLE_OWEN);
}

// Φ_b(a) under the nested affine scramble of `seed`: core `fast_owen_scrambled_radical_inverse`.
fn nyq_fast_owen_scrambled_radical_inverse(dim: u32, a: vec2<u32>, seed: vec2<u32>) -> f32 {
    return nyq_radical_inverse_scrambled(dim, a, seed, NYQ_SCRAMBLE_FAST_OWEN);
}

// ---- the Halton sequence

// The Halton sequence over `dims` dimensions, plain or scrambled (core `Halton::new(dims)`,
// `ScrambledHalton::with_strategy(dims, scramble, seed)`). Build it with `nyq_halton`.
struct NyqHalton {
    dims: u32,
    scramble: u32,
    seed: vec2<u32>,
}

// The sequence of `dims` dimensions (1..=1024, which the host checks), scrambled by `scramble`
// (NYQ_SCRAMBLE_*) under `seed`.
fn nyq_halton(dims: u32, scramble: u32, seed: vec2<u32>) -> NyqHalton {
    return NyqHalton(dims, scramble, seed);
}

// Point `index` (64-bit), dimension `dim` (mod dims): core `Sequence::sample`.
fn nyq_halton_sample(h: NyqHalton, index: vec2<u32>, dim: u32) -> f32 {
    return nyq_radical_inverse_scrambled(dim % h.dims, index, h.seed, h.scramble);
}

// ---- the Halton sampler

// pbrt-v3/v4's global Halton sampler (core `HaltonSampler`): one Halton sequence over the
// image, dimensions 0 and 1 scaled by 2^j ≥ min(width, 128) and 3^k ≥ min(height, 128); sample
// s of pixel p is index h(p) + s·2^j·3^k, h(p) found by the Chinese remainder theorem. Indices
// are 64-bit (up to 2³²·31104). Build it with `nyq_halton_sampler`.
struct NyqHaltonSampler {
    spp: u32,
    scramble: u32,
    seed: vec2<u32>,
    exponents: vec2<u32>,
    scales: vec2<u32>,
    stride: u32,
    // 3^k·(3^k)⁻¹ mod 2^j and 2^j·(2^j)⁻¹ mod 3^k.
    basis: vec2<u32>,
    index: vec2<u32>,
    dim: u32,
}

// The inverse of a modulo n (coprime, n ≥ 1; both below 2³¹), by extended Euclid.
fn nyq_mod_inverse(a: u32, n: u32) -> u32 {
    var r0 = i32(n);
    var r1 = i32(a % n);
    var t0 = 0;
    var t1 = 1;
    while r1 != 0 {
        let q = r0 / r1;
        let r2 = r0 - q * r1;
        let t2 = t0 - q * t1;
        r0 = r1;
        r1 = r2;
        t0 = t1;
        t1 = t2;
    }
    var m = t0 % i32(n);
    if m < 0 {
        m += i32(n);
    }
    return u32(m);
}

// The scale b^e ≥ min(extent, 128) of one axis and its exponent.
fn nyq_halton_scale(extent: u32, b: u32) -> vec2<u32> {
    let goal = min(extent, 128u);
    var scale = 1u;
    var e = 0u;
    while scale < goal {
        scale *= b;
        e += 1u;
    }
    return vec2<u32>(scale, e);
}

// The sampler for an image of `resolution` (both nonzero, as `spp`, which the host checks:
// core `HaltonSampler::new`), scrambled by `scramble` (NYQ_SCRAMBLE_*) under `seed`.
fn nyq_halton_sampler(resolution: vec2<u32>, spp: u32, scramble: u32, seed: vec2<u32>) -> NyqHaltonSampler {
    let x = nyq_halton_scale(resolution.x, 2u);
    let y = nyq_halton_scale(resolution.y, 3u);
    let scales = vec2<u32>(x.x, y.x);
    let basis = vec2<u32>(y.x * nyq_mod_inverse(y.x, x.x), x.x * nyq_mod_inverse(x.x, y.x));
    return NyqHaltonSampler(spp, scramble, seed, vec2<u32>(x.y, y.y), scales, x.x * y.x, basis, vec2<u32>(0u, 0u), 0u);
}

// The index whose first `n` base-b digits are those of `inverse` reversed: core
// `inverse_radical_inverse` (every value here below 243).
fn nyq_inverse_radical_inverse(b: u32, inverse_in: u32, n: u32) -> u32 {
    var inverse = inverse_in;
    var index = 0u;
    for (var done = 0u; done < n; done++) {
        if inverse == 0u {
            for (var k = done; k < n; k++) {
                index *= b;
            }
            return index;
        }
        let q = inverse / b;
        index = index * b + (inverse - q * b);
        inverse = q;
    }
    return index;
}

// The global Halton index of sample `sample_index` of `pixel`: core
// `HaltonSampler::sequence_index`.
fn nyq_halton_sampler_index(s: ptr<function, NyqHaltonSampler>, pixel: vec2<u32>, sample_index: u32) -> vec2<u32> {
    let stride = (*s).stride;
    let scales = (*s).scales;
    let exponents = (*s).exponents;
    let basis = (*s).basis;
    let dx = nyq_inverse_radical_inverse(2u, pixel.x % scales.x, exponents.x);
    var offset = (dx * basis.x) % stride;
    let dy = nyq_inverse_radical_inverse(3u, pixel.y % scales.y, exponents.y);
    offset = (offset + dy * basis.y) % stride;
    return nyq_add64(nyq_mul_wide(sample_index, stride), nyq_u64(offset));
}

// Dimension `dim` of the current sample: dimensions 0 and 1 read ⌊index / 2^j⌋ and
// ⌊index / 3^k⌋ (the value inside the pixel), the others the index.
fn nyq_halton_sampler_value(s: ptr<function, NyqHaltonSampler>, dim: u32) -> f32 {
    let d = dim % NYQ_PRIME_COUNT;
    let index = (*s).index;
    var a = index;
    if d == 0u {
        let e = (*s).exponents.x;
        if e != 0u {
            a = nyq_shr64(index, e);
        }
    } else if d == 1u {
        a = nyq_divmod64_small(index, (*s).scales.y).xy;
    }
    return nyq_radical_inverse_scrambled(d, a, (*s).seed, (*s).scramble);
}

// Moves to sample `sample_index` of `pixel`, at dimension `dim`.
fn nyq_halton_sampler_start(s: ptr<function, NyqHaltonSampler>, pixel: vec2<u32>, sample_index: u32, dim: u32) {
    (*s).index = nyq_halton_sampler_index(s, pixel, sample_index);
    (*s).dim = dim;
}

// The next dimension.
fn nyq_halton_sampler_get_1d(s: ptr<function, NyqHaltonSampler>) -> f32 {
    let d = (*s).dim;
    (*s).dim = d + 1u;
    return nyq_halton_sampler_value(s, d);
}

// Dimensions `dim` and `dim + 1` (one call site in a loop: a GPU compiler inlines each call
// of the value's whole body).
fn nyq_halton_sampler_pair(s: ptr<function, NyqHaltonSampler>, dim: u32) -> vec2<f32> {
    var v = vec2<f32>(0.0, 0.0);
    for (var k = 0u; k < 2u; k++) {
        v[k] = nyq_halton_sampler_value(s, dim + k);
    }
    return v;
}

// The next two dimensions.
fn nyq_halton_sampler_get_2d(s: ptr<function, NyqHaltonSampler>) -> vec2<f32> {
    let d = (*s).dim;
    (*s).dim = d + 2u;
    return nyq_halton_sampler_pair(s, d);
}

// Dimensions 0 and 1, whatever the cursor.
fn nyq_halton_sampler_get_pixel_2d(s: ptr<function, NyqHaltonSampler>) -> vec2<f32> {
    (*s).dim = max((*s).dim, 2u);
    return nyq_halton_sampler_pair(s, 0u);
}

// The camera's sample: image (0, 1), time (2), lens (3, 4); the values of get_pixel_2d, get_1d
// and get_2d from dimension 0, in one loop.
fn nyq_halton_sampler_camera_sample(s: ptr<function, NyqHaltonSampler>, pixel: vec2<u32>, sample_index: u32) -> NyqCameraSample {
    nyq_halton_sampler_start(s, pixel, sample_index, 5u);
    var v = vec4<f32>(0.0, 0.0, 0.0, 0.0);
    var lens_y = 0.0;
    for (var d = 0u; d < 5u; d++) {
        let x = nyq_halton_sampler_value(s, d);
        if d < 4u {
            v[d] = x;
        } else {
            lens_y = x;
        }
    }
    let film = vec2<f32>(nyq_film_coordinate(pixel.x, v.x), nyq_film_coordinate(pixel.y, v.y));
    return NyqCameraSample(film, vec2<f32>(v.w, lens_y), v.z);
}
