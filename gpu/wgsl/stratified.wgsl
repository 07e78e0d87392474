// ---------------------------------------------------------------------------------------------
// stratified: jittered or centred strata, hash-permuted per dimension
// (core/src/sampler/stratified.rs), and the keyed permutation behind them (core/src/hash.rs).

// `x as f32` for any u32, rounded to nearest, ties to even, from the bits: WGSL leaves the
// rounding of an inexact integer conversion to the device.
fn nyq_u32_to_f32(x: u32) -> f32 {
    if x < 0x1000000u {
        return f32(x);
    }
    let top = 31u - countLeadingZeros(x);
    let drop = top - 23u;
    var m = x >> drop;
    let rest = x & ((1u << drop) - 1u);
    let half = 1u << (drop - 1u);
    if rest > half || (rest == half && (m & 1u) == 1u) {
        m += 1u;
    }
    // m may have carried to 2²⁴, which the exponent field absorbs.
    return bitcast<f32>(((top + 127u) << 23u) + m - 0x800000u);
}

// 1 / x correctly rounded, for x = 2^e · m (a normal f32 ≥ 1 with an integer value, as the
// sampler's counts are): long division of the mantissa, 25 bits and a sticky bit.
fn nyq_recip_f32(x: f32) -> f32 {
    let bits = bitcast<u32>(x);
    let m = (bits & 0x7fffffu) | 0x800000u;
    let e = i32(bits >> 23u) - 127;
    if m == 0x800000u {
        return bitcast<f32>(u32(127 - e) << 23u);
    }
    // 2²⁴ / m ∈ (1, 2): its first 25 bits by restoring division.
    var r = 0x1000000u;
    var q = 0u;
    for (var i = 0u; i < 25u; i++) {
        q <<= 1u;
        if r >= m {
            r -= m;
            q |= 1u;
        }
        r <<= 1u;
    }
    // q holds 25 bits of 2²⁴/m (the leading one at bit 24): round to 24 bits.
    let round = q & 1u;
    q >>= 1u;
    if round == 1u && (r != 0u || (q & 1u) == 1u) {
        q += 1u;
    }
    // 1/x = (2²⁴/m)·2^(−24−e+23); q ∈ [2²³, 2²⁴] with the leading bit 23 (a carry to 2²⁴ is
    // absorbed by the exponent field).
    return bitcast<f32>((u32(127 - e - 1) << 23u) + q - 0x800000u);
}

// The permutations of two, three and four elements in lexicographic order (two, six and 24 of
// them), element i in nibble i: core `SMALL_PERMUTATIONS`.
const NYQ_SMALL_PERMUTATIONS = array<u32, 32>(
    0x10u, 0x1u, 0x210u, 0x120u, 0x201u, 0x21u, 0x102u, 0x12u, 0x3210u, 0x2310u, 0x3120u,
    0x1320u, 0x2130u, 0x1230u, 0x3201u, 0x2301u, 0x3021u, 0x321u, 0x2031u, 0x231u, 0x3102u,
    0x1302u, 0x3012u, 0x312u, 0x1032u, 0x132u, 0x2103u, 0x1203u, 0x2013u, 0x213u, 0x1023u,
    0x123u,
);

// The high 32 bits of the 96-bit product r · k (64 × 32 bits) and its low 64 bits.
fn nyq_mul64x32(r: vec2<u32>, k: u32) -> vec3<u32> {
    let low = nyq_mul_wide(r.x, k);
    let high = nyq_add64(nyq_mul_wide(r.y, k), vec2<u32>(low.y, 0u));
    return vec3<u32>(low.x, high.x, high.y);
}

// A permutation of 0..n (n ≤ 16) as 16 nibbles, drawn from the 64-bit word r: core
// `packed_table`.
fn nyq_packed_table(n: u32, r_in: vec2<u32>) -> vec2<u32> {
    if n <= 4u {
        if n < 2u {
            return vec2<u32>(0u, 0u);
        }
        let factorial = array<u32, 5>(1u, 1u, 2u, 6u, 24u);
        let start = array<u32, 5>(0u, 0u, 0u, 2u, 8u);
        let rank = nyq_mul64x32(r_in, factorial[n]).z;
        return vec2<u32>(NYQ_SMALL_PERMUTATIONS[(start[n] + rank) & 31u], 0u);
    }
    // Fisher–Yates from the identity, each draw the integer part of r·k.
    var t = vec2<u32>(0x76543210u, 0xfedcba98u);
    if n < 16u {
        let keep = 4u * n;
        if keep < 32u {
            t = vec2<u32>(t.x & ((1u << keep) - 1u), 0u);
        } else {
            t.y &= (1u << (keep - 32u)) - 1u;
        }
    }
    var r = r_in;
    for (var k = n; k > 1u; k--) {
        let p = nyq_mul64x32(r, k);
        let j = p.z;
        r = p.xy;
        let hi = 4u * (k - 1u);
        let lo = 4u * j;
        let x = (nyq_nibble(t, hi) ^ nyq_nibble(t, lo)) & 0xfu;
        t ^= nyq_shl64_any(vec2<u32>(x, 0u), hi) | nyq_shl64_any(vec2<u32>(x, 0u), lo);
    }
    return t;
}

// (t >> s) & 0xf for a nibble offset s < 64.
fn nyq_nibble(t: vec2<u32>, s: u32) -> u32 {
    return (select(t.x, t.y, s >= 32u) >> (s & 31u)) & 0xfu;
}

// x << s for s < 64 (x below 2⁴ here, so nothing crosses the halves but at s = 28).
fn nyq_shl64_any(x: vec2<u32>, s: u32) -> vec2<u32> {
    if s == 0u {
        return x;
    }
    if s >= 32u {
        return vec2<u32>(0u, x.x << (s - 32u));
    }
    return nyq_shl64(x, s);
}

// The keyed permutation of 0..n (core `Permutation`): a table of nibbles for n ≤ 16, else a
// keyed bijection on the next power of two, cycle-walked into [0, n), then rotated.
struct NyqPermutation {
    n: u32,
    mask: u32,
    half: u32,
    third: u32,
    key: u32,
    key2: u32,
    offset: u32,
    table: vec2<u32>,
}

// The permutation of 0..max(n, 1) under `seed`: core `Permutation::new`.
fn nyq_permutation(n_in: u32, seed: u32) -> NyqPermutation {
    let n = max(n_in, 1u);
    if n <= 16u {
        let table = nyq_packed_table(n, nyq_mix64(vec2<u32>(seed ^ 0x85a308d3u, 0x243f6a88u)));
        return NyqPermutation(n, 0u, 0u, 0u, 0u, 0u, 0u, table);
    }
    let mask = 0xffffffffu >> countLeadingZeros(n - 1u);
    let bits = 32u - countLeadingZeros(mask);
    let key = nyq_mix32(seed ^ 0x5bd1e995u);
    let key2 = nyq_mix32(key + 0x68e31da4u);
    let key3 = nyq_mix32(key2 ^ 0x2545f491u);
    let offset = nyq_mul_wide(key3, n).y;
    return NyqPermutation(n, mask, max((bits + 1u) / 2u, 1u), max(bits / 3u, 1u), key, key2, offset, vec2<u32>(0u, 0u));
}

// The image of i (mod n): core `Permutation::apply`.
fn nyq_permutation_apply(p: NyqPermutation, i: u32) -> u32 {
    let n = p.n;
    if n <= 16u {
        return nyq_nibble(p.table, 4u * ((i % n) & 15u));
    }
    var x = i % n;
    loop {
        x ^= p.key & p.mask;
        x = (x * 0xe170893du) & p.mask;
        x ^= x >> p.half;
        x = (x + p.key2) & p.mask;
        x = (x * (p.key | 1u)) & p.mask;
        x ^= x >> p.half;
        x ^= (p.key2 >> 7u) & p.mask;
        x = (x * 0x0929eb3fu) & p.mask;
        x ^= x >> p.half;
        x = (x * (0x6935fa69u ^ (p.key2 & 0xfffffffeu))) & p.mask;
        x ^= x >> p.third;
        if x < n {
            break;
        }
    }
    // (x + offset) mod n, the sum's carry kept.
    let q = x + p.offset;
    return select(q, q - n, q < x || q >= n);
}

// The jitter styles (core `Jitter`).
const NYQ_JITTERED: u32 = 0u;
const NYQ_CENTERED: u32 = 1u;

// The stratified sampler (core `StratifiedSampler`). Build it with `nyq_stratified_sampler`.
struct NyqStratifiedSampler {
    xs: u32,
    ys: u32,
    spp: u32,
    inv: vec3<f32>,
    jitter: u32,
    seed: vec2<u32>,
    pixel_key: vec2<u32>,
    sample_key: vec2<u32>,
    index: u32,
    dim: u32,
}

// ⌊2⁶⁴/φ⌋ and the other odd steps of the sampler's hashes.
const NYQ_DIM_STEP = vec2<u32>(0x7f4a7c15u, 0x9e3779b9u);
const NYQ_JITTER_STEP = vec2<u32>(0x27d4eb4fu, 0xc2b2ae3du);

// `x_samples × y_samples` strata (their product at most 2³² − 1, which the host checks: core
// `StratifiedSampler::new`), jittered or centred (NYQ_JITTERED, NYQ_CENTERED), under `seed`.
fn nyq_stratified_sampler(xs: u32, ys: u32, jitter: u32, seed: vec2<u32>) -> NyqStratifiedSampler {
    let spp = xs * ys;
    let inv = vec3<f32>(nyq_recip_f32(nyq_u32_to_f32(xs)), nyq_recip_f32(nyq_u32_to_f32(ys)), nyq_recip_f32(nyq_u32_to_f32(spp)));
    let zero = vec2<u32>(0u, 0u);
    return NyqStratifiedSampler(xs, ys, spp, inv, jitter, seed, zero, zero, 0u, 0u);
}

// The 32-bit permutation key of dimension `dim` of a pixel.
fn nyq_stratified_dim_key(pixel_key: vec2<u32>, dim: u32) -> u32 {
    let k = nyq_mix64(pixel_key ^ nyq_mul64(nyq_u64(dim), NYQ_DIM_STEP));
    return k.x ^ k.y;
}

// The stratum of dimension `dim` of the current sample.
fn nyq_stratified_stratum(s: ptr<function, NyqStratifiedSampler>, dim: u32) -> u32 {
    if dim == 0u {
        return (*s).index % (*s).spp;
    }
    let p = nyq_permutation((*s).spp, nyq_stratified_dim_key((*s).pixel_key, dim));
    return nyq_permutation_apply(p, (*s).index);
}

// The jitters of dimension `dim` (the second unused for 1-D values).
fn nyq_stratified_jitters(s: ptr<function, NyqStratifiedSampler>, dim: u32) -> vec2<f32> {
    if (*s).jitter != NYQ_JITTERED {
        return vec2<f32>(0.5, 0.5);
    }
    if dim == 2u || dim == 3u {
        // Time (2) and lens (3) share one hash, 21 bits each.
        let h = nyq_mix64((*s).sample_key ^ nyq_mul64(vec2<u32>(2u, 0u), NYQ_JITTER_STEP));
        let scale = 1.0 / 2097152.0;
        if dim == 2u {
            return vec2<f32>(f32((h.y >> 11u) & 0x1fffffu) * scale, 0.5);
        }
        return vec2<f32>(f32(nyq_shr64(h, 22u).x & 0x1fffffu) * scale, f32((h.x >> 1u) & 0x1fffffu) * scale);
    }
    let h = nyq_mix64((*s).sample_key ^ nyq_mul64(nyq_u64(dim), NYQ_JITTER_STEP));
    return vec2<f32>(nyq_fraction_to_f32(h.y), nyq_fraction_to_f32(h.x));
}

// min(x, the largest f32 below one).
fn nyq_below_one(x: f32) -> f32 {
    return min(x, bitcast<f32>(0x3f7fffffu));
}

// The 2-D value of stratum `st` with jitters `j`.
fn nyq_stratified_cell(s: ptr<function, NyqStratifiedSampler>, st: u32, j: vec2<f32>) -> vec2<f32> {
    let cx = st % (*s).xs;
    let cy = st / (*s).xs;
    return vec2<f32>(nyq_below_one((nyq_u32_to_f32(cx) + j.x) * (*s).inv.x), nyq_below_one((nyq_u32_to_f32(cy) + j.y) * (*s).inv.y));
}

// Moves to sample `sample_index` of `pixel`, at dimension `dim`.
fn nyq_stratified_start(s: ptr<function, NyqStratifiedSampler>, pixel: vec2<u32>, sample_index: u32, dim: u32) {
    // "stra"
    (*s).pixel_key = nyq_hash3(pixel, (*s).seed, nyq_u64(0x73747261u));
    (*s).index = sample_index;
    (*s).sample_key = (*s).pixel_key ^ nyq_mul64(nyq_u64(sample_index), NYQ_DIM_STEP);
    (*s).dim = dim;
}

// The next dimension: its stratum of spp, jittered.
fn nyq_stratified_get_1d(s: ptr<function, NyqStratifiedSampler>) -> f32 {
    let d = (*s).dim;
    (*s).dim = d + 1u;
    let st = nyq_stratified_stratum(s, d);
    return nyq_below_one((nyq_u32_to_f32(st) + nyq_stratified_jitters(s, d).x) * (*s).inv.z);
}

// The next two dimensions: a cell of the x × y grid.
fn nyq_stratified_get_2d(s: ptr<function, NyqStratifiedSampler>) -> vec2<f32> {
    let d = (*s).dim;
    (*s).dim = d + 2u;
    return nyq_stratified_cell(s, nyq_stratified_stratum(s, d), nyq_stratified_jitters(s, d));
}

// Dimensions 0 and 1, whatever the cursor.
fn nyq_stratified_get_pixel_2d(s: ptr<function, NyqStratifiedSampler>) -> vec2<f32> {
    (*s).dim = max((*s).dim, 2u);
    return nyq_stratified_cell(s, nyq_stratified_stratum(s, 0u), nyq_stratified_jitters(s, 0u));
}

// The camera's sample: image (0, 1), time (2), lens (3, 4).
fn nyq_stratified_camera_sample(s: ptr<function, NyqStratifiedSampler>, pixel: vec2<u32>, sample_index: u32) -> NyqCameraSample {
    nyq_stratified_start(s, pixel, sample_index, 0u);
    let p = nyq_stratified_get_pixel_2d(s);
    let time = nyq_stratified_get_1d(s);
    let lens = nyq_stratified_get_2d(s);
    let film = vec2<f32>(nyq_film_coordinate(pixel.x, p.x), nyq_film_coordinate(pixel.y, p.y));
    return NyqCameraSample(film, lens, time);
}
