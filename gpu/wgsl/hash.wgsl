// ---------------------------------------------------------------------------------------------
// hash: the integer hashes behind every scramble and per-pixel key (core/src/hash.rs).
//
// WGSL has no 64-bit integers, so a 64-bit word is a vec2<u32> (x: low half, y: high half) and
// its arithmetic is written out on 32-bit halves: the same bits as the core's u64 code.

// The full 64-bit product of two 32-bit words, from four 16 × 16-bit products (none overflows).
fn nyq_mul_wide(a: u32, b: u32) -> vec2<u32> {
    let a0 = a & 0xffffu;
    let a1 = a >> 16u;
    let b0 = b & 0xffffu;
    let b1 = b >> 16u;
    let p00 = a0 * b0;
    let p01 = a0 * b1;
    let p10 = a1 * b0;
    let p11 = a1 * b1;
    let mid = (p00 >> 16u) + (p01 & 0xffffu) + (p10 & 0xffffu);
    return vec2<u32>((p00 & 0xffffu) | (mid << 16u), p11 + (p01 >> 16u) + (p10 >> 16u) + (mid >> 16u));
}

// a · b modulo 2⁶⁴.
fn nyq_mul64(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let low = nyq_mul_wide(a.x, b.x);
    return vec2<u32>(low.x, low.y + a.x * b.y + a.y * b.x);
}

// a + b modulo 2⁶⁴.
fn nyq_add64(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let low = a.x + b.x;
    return vec2<u32>(low, a.y + b.y + select(0u, 1u, low < a.x));
}

// a >> s for 0 < s < 32.
fn nyq_shr64(a: vec2<u32>, s: u32) -> vec2<u32> {
    return vec2<u32>((a.x >> s) | (a.y << (32u - s)), a.y >> s);
}

// a << s for 0 < s < 32.
fn nyq_shl64(a: vec2<u32>, s: u32) -> vec2<u32> {
    return vec2<u32>(a.x << s, (a.y << s) | (a.x >> (32u - s)));
}

// A 32-bit value as a 64-bit word.
fn nyq_u64(x: u32) -> vec2<u32> {
    return vec2<u32>(x, 0u);
}

// The 32-bit avalanche finaliser lowbias32 (Wellons' hash-prospector constants): core `mix32`.
fn nyq_mix32(x_in: u32) -> u32 {
    var x = x_in;
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    return x ^ (x >> 16u);
}

// The 64-bit finaliser of SplitMix64 (Stafford's Mix13 constants): core `mix64`.
fn nyq_mix64(x_in: vec2<u32>) -> vec2<u32> {
    var x = x_in;
    x ^= nyq_shr64(x, 30u);
    x = nyq_mul64(x, vec2<u32>(0x1ce4e5b9u, 0xbf58476du));
    x ^= nyq_shr64(x, 27u);
    x = nyq_mul64(x, vec2<u32>(0x133111ebu, 0x94d049bbu));
    return x ^ nyq_shr64(x, 31u);
}

// Two 64-bit values hashed into one, order mattering: core `hash2`.
fn nyq_hash2(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    // ⌊2⁶⁴/φ⌋ and twice it, modulo 2⁶⁴.
    let golden = vec2<u32>(0x7f4a7c15u, 0x9e3779b9u);
    let golden2 = vec2<u32>(0xfe94f82au, 0x3c6ef372u);
    return nyq_mix64(nyq_mix64(nyq_add64(a, golden)) ^ nyq_add64(b, golden2));
}

// core `hash_slice(&[a, b, c, d])`: hash2 folded over four words from ⌊2⁶⁴/φ⌋.
fn nyq_hash4(a: vec2<u32>, b: vec2<u32>, c: vec2<u32>, d: vec2<u32>) -> vec2<u32> {
    let golden = vec2<u32>(0x7f4a7c15u, 0x9e3779b9u);
    return nyq_hash2(nyq_hash2(nyq_hash2(nyq_hash2(golden, a), b), c), d);
}

// A 32-bit binary fraction v / 2³² as an f32 in [0, 1): its top 24 bits, truncated (an exact
// conversion and an exact scaling, so every device rounds it alike): core `fraction_to_f32`.
fn nyq_fraction_to_f32(v: u32) -> f32 {
    return f32(v >> 8u) * (1.0 / 16777216.0);
}

// The next power of two of n (at least 1): the samplers' rounded spp (core `rounded_spp`).
fn nyq_round_up_pow2(n: u32) -> u32 {
    return select(1u << (32u - countLeadingZeros(n - 1u)), 1u, n <= 1u);
}

// The f32 of the binary fraction reverse(w_rev): what the core's reversed-table reads return.
fn nyq_rev_to_f32(w_rev: u32) -> f32 {
    return nyq_fraction_to_f32(reverseBits(w_rev));
}

// x >> s for any s (0 past 31; WGSL reduces a shift amount modulo 32).
fn nyq_shr(x: u32, s: u32) -> u32 {
    return select(x >> (s & 31u), 0u, s >= 32u);
}

// The film coordinate of an offset in [0, 1) inside a pixel, never on the next pixel's edge:
// core `film_coordinate` (pixel coordinates below 2²⁴, where the conversion is exact).
fn nyq_film_coordinate(pixel: u32, offset: f32) -> f32 {
    let base = f32(pixel);
    let x = base + offset;
    let edge = base + 1.0;
    if x < edge {
        return x;
    }
    // The sum rounded up onto the next pixel's edge: the float just below it.
    let below = bitcast<f32>(bitcast<u32>(edge) - 1u);
    return select(base, below, below >= base);
}

// What a camera asks for at a pixel sample (core `CameraSample`): the film position, the time
// and the lens position.
struct NyqCameraSample {
    p_film: vec2<f32>,
    lens: vec2<f32>,
    time: f32,
}
