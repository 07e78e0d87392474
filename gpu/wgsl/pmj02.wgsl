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
// `seed` is the output of T^(m+1)(T(0) + seed); T^n = (A, C), T^n(s) = A s + C, is composed
// from three 6-bit windows of n: entry 64 w + d is T^(d 64^w) (core `hash::lcg_draw`).
const NYQ_LCG_WINDOWS = array<vec2<u32>, 192>(
    vec2<u32>(0x00000001u, 0x00000000u), vec2<u32>(0x2c9277b5u, 0xac564b05u), vec2<u32>(0xfa6dc5f9u, 0x4712a88eu), vec2<u32>(0xcaa5b80du, 0x21dd796bu),
    vec2<u32>(0x83232c31u, 0x3463e0acu), vec2<u32>(0xb15b05a5u, 0xd67c18a1u), vec2<u32>(0x4914b0a9u, 0xb9588bdau), vec2<u32>(0x1621767du, 0x1b478227u),
    vec2<u32>(0x4306e161u, 0x21a37198u), vec2<u32>(0xcbf37095u, 0x5763437du), vec2<u32>(0x2d6ddc59u, 0x932e1d66u), vec2<u32>(0x26dc29edu, 0x77c77e23u),
    vec2<u32>(0x7650cf91u, 0x0bfabec4u), vec2<u32>(0x84512885u, 0x2f144799u), vec2<u32>(0x3f117909u, 0x84370932u), vec2<u32>(0x49bfc25du, 0x930a095fu),
    vec2<u32>(0x1cf7a6c1u, 0xf8f81430u), vec2<u32>(0xdfae9d75u, 0xc87ee0f5u), vec2<u32>(0x3a60b6b9u, 0xd0573b3eu), vec2<u32>(0x3cd32fcdu, 0xf7e8ffdbu),
    vec2<u32>(0xab7316f1u, 0xd1e7fddcu), vec2<u32>(0x397b3f65u, 0x83d60b91u), vec2<u32>(0x7235c569u, 0xe6bedf8au), vec2<u32>(0x60aa623du, 0xbfe77d97u),
    vec2<u32>(0x0eebd021u, 0x8a8147c8u), vec2<u32>(0x894b7e55u, 0x022c036du), vec2<u32>(0xd293d519u, 0x5b366216u), vec2<u32>(0x6ed649adu, 0x29edde93u),
    vec2<u32>(0xba6b8251u, 0x17d0fdf4u), vec2<u32>(0x05c8ca45u, 0x6e4e4489u), vec2<u32>(0xa45715c9u, 0xadaa6ee2u), vec2<u32>(0xa554d61du, 0xc445becfu),
    vec2<u32>(0x6d0cdd81u, 0x43666c60u), vec2<u32>(0x94a19335u, 0x3ee18ae5u), vec2<u32>(0x41e4b779u, 0x8bf7f1eeu), vec2<u32>(0x5700f78du, 0xc5d5fa4bu),
    vec2<u32>(0x612b91b1u, 0xa6bf1f0cu), vec2<u32>(0x77794925u, 0x2dbdd281u), vec2<u32>(0xecdaea29u, 0x79f8173au), vec2<u32>(0xd1029dfdu, 0x729ead07u),
    vec2<u32>(0x94944ee1u, 0x5af2e1f8u), vec2<u32>(0xa5d85c15u, 0x608a575du), vec2<u32>(0xf4c0ddd9u, 0x0bcc4ac6u), vec2<u32>(0x853eb96du, 0xa7753303u),
    vec2<u32>(0xd9b4c511u, 0x289fc124u), vec2<u32>(0x441c3c05u, 0xfe999579u), vec2<u32>(0x5eb6c289u, 0x1e6a3892u), vec2<u32>(0x69c739ddu, 0xe900283fu),
    vec2<u32>(0x61cba441u, 0x44160890u), vec2<u32>(0xa76758f5u, 0xb00548d5u), vec2<u32>(0x3e25c839u, 0xba67cc9eu), vec2<u32>(0x7d4b0f4du, 0x91f368bbu),
    vec2<u32>(0x70189c71u, 0xe1c4443cu), vec2<u32>(0x569122e5u, 0xc20a6d71u), vec2<u32>(0xee701ee9u, 0x8d0732eau), vec2<u32>(0x608629bdu, 0xfc8c1077u),
    vec2<u32>(0xe60c5da1u, 0x2ee34028u), vec2<u32>(0x781609d5u, 0xeca53f4du), vec2<u32>(0x5da0f699u, 0x2382d776u), vec2<u32>(0xf4b1792du, 0xc34c7b73u),
    vec2<u32>(0x587897d1u, 0x7a620854u), vec2<u32>(0x1d077dc5u, 0xf56d3a69u), vec2<u32>(0x981c7f49u, 0x54996642u), vec2<u32>(0xeef2ed9du, 0x74f845afu),
    vec2<u32>(0x00000001u, 0x00000000u), vec2<u32>(0x5dbffb01u, 0x9a11e8c0u), vec2<u32>(0x3b98f601u, 0x2a981180u), vec2<u32>(0x1c8af101u, 0x6c527a40u),
    vec2<u32>(0x8395ec01u, 0x5a012300u), vec2<u32>(0xf3b9e701u, 0x2e640bc0u), vec2<u32>(0xeff6e201u, 0x643b3480u), vec2<u32>(0xfb4cdd01u, 0xb6469d40u),
    vec2<u32>(0x98bbd801u, 0x1f464600u), vec2<u32>(0x4b43d301u, 0xd9fa2ec0u), vec2<u32>(0x95e4ce01u, 0x61225780u), vec2<u32>(0xfb9ec901u, 0x6f7ec040u),
    vec2<u32>(0xff71c401u, 0xffcf6900u), vec2<u32>(0x245dbf01u, 0x4cd451c0u), vec2<u32>(0xed62ba01u, 0xd14d7a80u), vec2<u32>(0xdd80b501u, 0x47fae340u),
    vec2<u32>(0x77b7b001u, 0xab9c8c00u), vec2<u32>(0x3f07ab01u, 0x36f274c0u), vec2<u32>(0xb670a601u, 0x64bc9d80u), vec2<u32>(0x60f2a101u, 0xefbb0640u),
    vec2<u32>(0xc18d9c01u, 0xd2adaf00u), vec2<u32>(0x5b419701u, 0x485497c0u), vec2<u32>(0xb10e9201u, 0xcb6fc080u), vec2<u32>(0x45f48d01u, 0x16bf2940u),
    vec2<u32>(0x9cf38801u, 0x2502d200u), vec2<u32>(0x390b8301u, 0x30fabac0u), vec2<u32>(0x9d3c7e01u, 0xb566e380u), vec2<u32>(0x4c867901u, 0x6d074c40u),
    vec2<u32>(0xc9e97401u, 0x529bf500u), vec2<u32>(0x98656f01u, 0xa0e4ddc0u), vec2<u32>(0x3afa6a01u, 0xd2a20680u), vec2<u32>(0x34a86501u, 0xa2936f40u),
    vec2<u32>(0x086f6001u, 0x0b791800u), vec2<u32>(0x394f5b01u, 0x481300c0u), vec2<u32>(0x4a485601u, 0xd3212980u), vec2<u32>(0xbe5a5101u, 0x67639240u),
    vec2<u32>(0x18854c01u, 0xff9a3b00u), vec2<u32>(0xdbc94701u, 0xd68523c0u), vec2<u32>(0x8b264201u, 0x66e44c80u), vec2<u32>(0xa99c3d01u, 0x6b77b540u),
    vec2<u32>(0xba2b3801u, 0xdeff5e00u), vec2<u32>(0x3fd33301u, 0xfc3b46c0u), vec2<u32>(0xbd942e01u, 0x3deb6f80u), vec2<u32>(0xb66e2901u, 0x5ecfd840u),
    vec2<u32>(0xad612401u, 0x59a88100u), vec2<u32>(0x256d1f01u, 0x693569c0u), vec2<u32>(0xa1921a01u, 0x08369280u), vec2<u32>(0xa4d01501u, 0xf16bfb40u),
    vec2<u32>(0xb2271001u, 0x1f95a400u), vec2<u32>(0x4c970b01u, 0xcd738cc0u), vec2<u32>(0xf7200601u, 0x75c5b580u), vec2<u32>(0x34c20101u, 0xd34c1e40u),
    vec2<u32>(0x887cfc01u, 0xe0c6c700u), vec2<u32>(0x7550f701u, 0xd8f5afc0u), vec2<u32>(0x7e3df201u, 0x3698d880u), vec2<u32>(0x2643ed01u, 0xb4704140u),
    vec2<u32>(0xf062e801u, 0x4d3bea00u), vec2<u32>(0x5f9ae301u, 0x3bbbd2c0u), vec2<u32>(0xf6ebde01u, 0xfaaffb80u), vec2<u32>(0x3955d901u, 0x44d86440u),
    vec2<u32>(0xa9d8d401u, 0x14f50d00u), vec2<u32>(0xcb74cf01u, 0xa5c5f5c0u), vec2<u32>(0x2129ca01u, 0x720b1e80u), vec2<u32>(0x2df7c501u, 0x34848740u),
    vec2<u32>(0x00000001u, 0x00000000u), vec2<u32>(0x74dec001u, 0xe7f23000u), vec2<u32>(0x79bd8001u, 0x13e46000u), vec2<u32>(0x0e9c4001u, 0x83d69000u),
    vec2<u32>(0x337b0001u, 0x37c8c000u), vec2<u32>(0xe859c001u, 0x2fbaf000u), vec2<u32>(0x2d388001u, 0x6bad2000u), vec2<u32>(0x02174001u, 0xeb9f5000u),
    vec2<u32>(0x66f60001u, 0xaf918000u), vec2<u32>(0x5bd4c001u, 0xb783b000u), vec2<u32>(0xe0b38001u, 0x0375e000u), vec2<u32>(0xf5924001u, 0x93681000u),
    vec2<u32>(0x9a710001u, 0x675a4000u), vec2<u32>(0xcf4fc001u, 0x7f4c7000u), vec2<u32>(0x942e8001u, 0xdb3ea000u), vec2<u32>(0xe90d4001u, 0x7b30d000u),
    vec2<u32>(0xcdec0001u, 0x5f230000u), vec2<u32>(0x42cac001u, 0x87153000u), vec2<u32>(0x47a98001u, 0xf3076000u), vec2<u32>(0xdc884001u, 0xa2f99000u),
    vec2<u32>(0x01670001u, 0x96ebc000u), vec2<u32>(0xb645c001u, 0xceddf000u), vec2<u32>(0xfb248001u, 0x4ad02000u), vec2<u32>(0xd0034001u, 0x0ac25000u),
    vec2<u32>(0x34e20001u, 0x0eb48000u), vec2<u32>(0x29c0c001u, 0x56a6b000u), vec2<u32>(0xae9f8001u, 0xe298e000u), vec2<u32>(0xc37e4001u, 0xb28b1000u),
    vec2<u32>(0x685d0001u, 0xc67d4000u), vec2<u32>(0x9d3bc001u, 0x1e6f7000u), vec2<u32>(0x621a8001u, 0xba61a000u), vec2<u32>(0xb6f94001u, 0x9a53d000u),
    vec2<u32>(0x9bd80001u, 0xbe460000u), vec2<u32>(0x10b6c001u, 0x26383000u), vec2<u32>(0x15958001u, 0xd22a6000u), vec2<u32>(0xaa744001u, 0xc21c9000u),
    vec2<u32>(0xcf530001u, 0xf60ec000u), vec2<u32>(0x8431c001u, 0x6e00f000u), vec2<u32>(0xc9108001u, 0x29f32000u), vec2<u32>(0x9def4001u, 0x29e55000u),
    vec2<u32>(0x02ce0001u, 0x6dd78000u), vec2<u32>(0xf7acc001u, 0xf5c9b000u), vec2<u32>(0x7c8b8001u, 0xc1bbe000u), vec2<u32>(0x916a4001u, 0xd1ae1000u),
    vec2<u32>(0x36490001u, 0x25a04000u), vec2<u32>(0x6b27c001u, 0xbd927000u), vec2<u32>(0x30068001u, 0x9984a000u), vec2<u32>(0x84e54001u, 0xb976d000u),
    vec2<u32>(0x69c40001u, 0x1d690000u), vec2<u32>(0xdea2c001u, 0xc55b3000u), vec2<u32>(0xe3818001u, 0xb14d6000u), vec2<u32>(0x78604001u, 0xe13f9000u),
    vec2<u32>(0x9d3f0001u, 0x5531c000u), vec2<u32>(0x521dc001u, 0x0d23f000u), vec2<u32>(0x96fc8001u, 0x09162000u), vec2<u32>(0x6bdb4001u, 0x49085000u),
    vec2<u32>(0xd0ba0001u, 0xccfa8000u), vec2<u32>(0xc598c001u, 0x94ecb000u), vec2<u32>(0x4a778001u, 0xa0dee000u), vec2<u32>(0x5f564001u, 0xf0d11000u),
    vec2<u32>(0x04350001u, 0x84c34000u), vec2<u32>(0x3913c001u, 0x5cb57000u), vec2<u32>(0xfdf28001u, 0x78a7a000u), vec2<u32>(0x52d14001u, 0xd899d000u),
);

// The PCG-RXS-M-XS output of an LCG state (core `hash::rxs_m_xs`).
fn nyq_rxs_m_xs(state: u32) -> u32 {
    var s = state;
    s ^= s >> (4u + (s >> 28u));
    s *= 277803737u;
    return s ^ (s >> 22u);
}

// Draw `m` of OpenQMC's generator from `seed`: core `hash::lcg_draw`.
fn nyq_lcg_draw(seed: u32, m: u32) -> u32 {
    var s = 2891336453u + seed;
    let n = m + 1u;
    for (var w = 0u; w < 3u; w++) {
        let ac = NYQ_LCG_WINDOWS[w * 64u + ((n >> (6u * w)) & 63u)];
        s = ac.x * s + ac.y;
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
