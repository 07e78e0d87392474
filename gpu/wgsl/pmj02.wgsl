// ---------------------------------------------------------------------------------------------
// pmj02: progressive multi-jittered (0,2) points (core/src/sequence/pmj02.rs,
// core/src/sampler/pmj02.rs) without the core's 512 KiB table: each point is rebuilt by walking
// the stochastic construction of Helmer, Christensen & Kensler (2021, "Stochastic generation of
// (t, s) sample sequences") backwards along the chain of points it copies its leading digits
// from, at most 17 draws of OpenQMC's generator. With the table's seed the points are the table's,
// bit for bit.

// The seed of the core's baked table (PMJ02_TABLE_SEED: OpenQMC's table, state 0).
const NYQ_PMJ02_TABLE_SEED = 0u;

// The construction's random digits come from OpenQMC's generator (its pcg.h): the 32-bit LCG
// s <- 747796405 s + 2891336453 with the PCG-RXS-M-XS output (O'Neill 2014). Draw m of seed
// `seed` is the output of T^(m+1)(T(0) + seed). The shader jumps there one bit of n = m + 1 at a
// time (Brown 1994): T^(2^k) = (a, c) applies where bit k is set, and (a, c) -> (a a, (a + 1) c)
// doubles it, so no table is read (a constant array indexed at run time is copied per call on
// some drivers). The core jumps through a table of windows instead; the draws are the same.

// The LCG's multiplier and increment (OpenQMC's pcg.h; core `hash::LCG_A`, `LCG_C`).
const NYQ_LCG_A = 747796405u;
const NYQ_LCG_C = 2891336453u;

// The PCG-RXS-M-XS output of an LCG state (core `hash::rxs_m_xs`).
fn nyq_rxs_m_xs(state: u32) -> u32 {
    var s = state;
    s ^= s >> (4u + (s >> 28u));
    s *= 277803737u;
    return s ^ (s >> 22u);
}

// Draw `m` of OpenQMC's generator from `seed`: core `hash::lcg_draw`.
fn nyq_lcg_draw(seed: u32, m: u32) -> u32 {
    var s = NYQ_LCG_C + seed; // pcg::init(seed): T(0) + seed
    let n = m + 1u;
    var a = NYQ_LCG_A;
    var c = NYQ_LCG_C;
    // A fixed count (n < 2^18), so a compiler can unroll the loop and fold (a, c) to constants.
    for (var k = 0u; k < 18u; k++) {
        s = select(s, a * s + c, ((n >> k) & 1u) != 0u);
        c = (a + 1u) * c;
        a *= a;
    }
    return nyq_rxs_m_xs(s);
}

// The construction's per-level XOR constants: new point 2^L + i pairs with old point i ^ c[L].
const NYQ_PMJ02_XOR_X = array<u32, 16>(0x0000u, 0x0000u, 0x0002u, 0x0006u, 0x0006u, 0x000eu, 0x0036u, 0x004eu,
                                       0x0016u, 0x002eu, 0x0276u, 0x06ceu, 0x0716u, 0x0c2eu, 0x3076u, 0x40ceu);
const NYQ_PMJ02_XOR_Y = array<u32, 16>(0x0000u, 0x0001u, 0x0003u, 0x0003u, 0x0007u, 0x001bu, 0x0027u, 0x000bu,
                                       0x0017u, 0x013bu, 0x0367u, 0x038bu, 0x0617u, 0x183bu, 0x2067u, 0x008bu);

// Coordinate `dim` (0 or 1) of point `index mod 2¹⁶` of the PMJ(0,2) sequence built from `seed`,
// as a 32-bit fraction.
fn nyq_pmj02_point(seed: u32, index: u32, dim: u32) -> u32 {
    var x = 0u;
    var known = 0u;
    var flips = 0u;
    var p = index & 0xffffu;
    while p != 0u {
        let level = 31u - countLeadingZeros(p);
        let swap = 0x80000000u >> level;
        let low = swap - 1u;
        x |= nyq_lcg_draw(seed, 2u * p + dim) & low & ~known;
        known |= low;
        flips ^= swap;
        let c = select(NYQ_PMJ02_XOR_Y[level & 15u], NYQ_PMJ02_XOR_X[level & 15u], dim == 0u);
        p = (p - (1u << level)) ^ c;
    }
    x |= nyq_lcg_draw(seed, dim) & ~known;
    return x ^ flips;
}

// The PMJ(0,2) sequence (core `Pmj02`): the table's points, plain or Owen-scrambled per
// dimension. Build it with `nyq_pmj02`.
struct NyqPmj02 {
    scrambled: u32,
    keys: vec2<u32>,
}

// The plain sequence (`scrambled` false: core `Pmj02::new`) or its scramble by `seed` (core
// `Pmj02::scrambled`).
fn nyq_pmj02(scrambled: bool, seed: vec2<u32>) -> NyqPmj02 {
    // "pmj02_ow"
    let h = nyq_hash2(seed, vec2<u32>(0x325f6f77u, 0x706d6a30u));
    return NyqPmj02(select(0u, 1u, scrambled), h);
}

// Point `index` (mod 2¹⁶), coordinate `dim & 1`, as a 32-bit fraction: core `sample_u32`.
fn nyq_pmj02_sample_u32(s: NyqPmj02, index: u32, dim: u32) -> u32 {
    let d = dim & 1u;
    let v = nyq_pmj02_point(NYQ_PMJ02_TABLE_SEED, index, d);
    if s.scrambled == 0u {
        return v;
    }
    return reverseBits(nyq_lk_hash(reverseBits(v), s.keys[d]));
}

// Point `index`, coordinate `dim` as an f32.
fn nyq_pmj02_sample(s: NyqPmj02, index: u32, dim: u32) -> f32 {
    return nyq_fraction_to_f32(nyq_pmj02_sample_u32(s, index, dim));
}

// The PMJ(0,2) pixel sampler (core `Pmj02Sampler`): the table's points index-shuffled and
// Owen-scrambled per pixel and request; spp up to 2¹⁶ (the host checks it), sample indices
// wrap modulo 2¹⁶. Build it with `nyq_pmj02_sampler`.
struct NyqPmj02Sampler {
    seed: vec2<u32>,
    pixel_key: vec2<u32>,
    index_rev: u32,
    dim: u32,
}

// The sampler under `seed`.
fn nyq_pmj02_sampler(seed: vec2<u32>) -> NyqPmj02Sampler {
    return NyqPmj02Sampler(seed, vec2<u32>(0u, 0u), 0u, 0u);
}

// The low 16 bits of m reversed.
fn nyq_reverse16(m: u32) -> u32 {
    return reverseBits(m & 0xffffu) >> 16u;
}

// The keys of request `request` (2·dim for a 2-D request, 2·dim + 1 for a 1-D one): the index
// shuffle's and the two coordinates' scrambles.
fn nyq_pmj02_keys(s: ptr<function, NyqPmj02Sampler>, request: vec2<u32>) -> vec3<u32> {
    let h = nyq_mix64((*s).pixel_key ^ nyq_mul64(request, vec2<u32>(0x7f4a7c15u, 0x9e3779b9u)));
    let g = nyq_mix64(h ^ vec2<u32>(0x6a303279u, 0x706du));
    return vec3<u32>(h.x, h.y, g.x);
}

// Table point `i`, scrambled by the keys.
fn nyq_pmj02_keyed_point(k: vec3<u32>, i: u32) -> vec2<f32> {
    let x = nyq_pmj02_point(NYQ_PMJ02_TABLE_SEED, i, 0u);
    let y = nyq_pmj02_point(NYQ_PMJ02_TABLE_SEED, i, 1u);
    return vec2<f32>(nyq_rev_to_f32(nyq_lk_hash(reverseBits(x), k.y)), nyq_rev_to_f32(nyq_lk_hash(reverseBits(y), k.z)));
}

// The shuffled row of the current sample under the keys.
fn nyq_pmj02_row(s: ptr<function, NyqPmj02Sampler>, k: vec3<u32>) -> u32 {
    return nyq_lk_hash((*s).index_rev, k.x) >> 16u;
}

// Moves to sample `sample_index` (mod 2¹⁶) of `pixel`, at dimension `dim`.
fn nyq_pmj02_start(s: ptr<function, NyqPmj02Sampler>, pixel: vec2<u32>, sample_index: u32, dim: u32) {
    // "pmj02"
    (*s).pixel_key = nyq_hash3(pixel, (*s).seed, vec2<u32>(0x6d6a3032u, 0x70u));
    (*s).index_rev = nyq_reverse16(sample_index) << 16u;
    (*s).dim = dim;
}

// The next dimension: a scrambled van der Corput point of the request's shuffled row.
fn nyq_pmj02_get_1d(s: ptr<function, NyqPmj02Sampler>) -> f32 {
    let d = (*s).dim;
    (*s).dim = d + 1u;
    let k = nyq_pmj02_keys(s, nyq_add64(nyq_shl64(nyq_u64(d), 1u), vec2<u32>(1u, 0u)));
    return nyq_rev_to_f32(nyq_lk_hash(nyq_reverse16(nyq_pmj02_row(s, k)), k.y));
}

// The next two dimensions: a table point of the request's shuffled row (the sample's own row
// at dimension 0).
fn nyq_pmj02_get_2d(s: ptr<function, NyqPmj02Sampler>) -> vec2<f32> {
    let d = (*s).dim;
    (*s).dim = d + 2u;
    let k = nyq_pmj02_keys(s, nyq_shl64(nyq_u64(d), 1u));
    if d == 0u {
        return nyq_pmj02_keyed_point(k, nyq_reverse16((*s).index_rev >> 16u));
    }
    return nyq_pmj02_keyed_point(k, nyq_reverse16(nyq_pmj02_row(s, k)));
}

// Dimensions 0 and 1, whatever the cursor.
fn nyq_pmj02_get_pixel_2d(s: ptr<function, NyqPmj02Sampler>) -> vec2<f32> {
    (*s).dim = max((*s).dim, 2u);
    return nyq_pmj02_keyed_point(nyq_pmj02_keys(s, vec2<u32>(0u, 0u)), nyq_reverse16((*s).index_rev >> 16u));
}

// The camera's sample: image (0, 1), time (2), lens (3, 4).
fn nyq_pmj02_camera_sample(s: ptr<function, NyqPmj02Sampler>, pixel: vec2<u32>, sample_index: u32) -> NyqCameraSample {
    nyq_pmj02_start(s, pixel, sample_index, 0u);
    let p = nyq_pmj02_get_pixel_2d(s);
    let time = nyq_pmj02_get_1d(s);
    let lens = nyq_pmj02_get_2d(s);
    let film = vec2<f32>(nyq_film_coordinate(pixel.x, p.x), nyq_film_coordinate(pixel.y, p.y));
    return NyqCameraSample(film, lens, time);
}
