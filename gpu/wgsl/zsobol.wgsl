// ---------------------------------------------------------------------------------------------
// zsobol: Sobol indices along a hash-permuted Morton curve (Ahmed & Wonka 2020; pbrt-v4's
// ZSobolSampler), core/src/sampler/zsobol.rs. The core caches a pixel's permuted digits; this
// is its direct form (`ZSobolSampler::sequence_index`), the same bits.

// All 24 permutations of 0..4 in lexicographic order, entry k in bits 2k .. 2k + 2.
const NYQ_PERMUTATIONS_4 = array<u32, 24>(
    0xe4u, 0xb4u, 0xd8u, 0x78u, 0x9cu, 0x6cu, 0xe1u, 0xb1u, 0xc9u, 0x39u, 0x8du, 0x2du,
    0xd2u, 0x72u, 0xc6u, 0x36u, 0x4eu, 0x1eu, 0x93u, 0x63u, 0x87u, 0x27u, 0x4bu, 0x1bu,
);

// A ZSobol sampler (core `ZSobolSampler`). Build it with `nyq_zsobol_sampler`.
struct NyqZSobolSampler {
    spp: u32,
    log2_spp: u32,
    log2_res: u32,
    scramble: u32,
    seed: vec2<u32>,
    // Base-4 digits of the Morton index, those that hold sample bits, and whether log₂ spp is
    // odd (a last base-2 digit).
    digits: u32,
    sample_digits: u32,
    odd: u32,
    // The current sample's Morton index.
    morton: u32,
    dim: u32,
}

// The sampler for an image of `resolution` pixels at `spp` samples per pixel (rounded up to a
// power of two), scrambled by `scramble` (NYQ_SCRAMBLE_*) under `seed`. The host checks the
// arguments as core `ZSobolSampler::new` does (2·⌈log₂ max(resolution)⌉ + log₂ spp ≤ 32).
fn nyq_zsobol_sampler(resolution: vec2<u32>, spp_requested: u32, scramble: u32, seed: vec2<u32>) -> NyqZSobolSampler {
    let spp = nyq_round_up_pow2(spp_requested);
    let side = max(resolution.x, resolution.y);
    let log2_res = 32u - countLeadingZeros(side - 1u);
    let log2_spp = countTrailingZeros(spp);
    let bits = 2u * log2_res + log2_spp;
    return NyqZSobolSampler(spp, log2_spp, log2_res, scramble, seed, bits / 2u, log2_spp / 2u, log2_spp & 1u, 0u, 0u);
}

// x's low 16 bits spread to the even bits.
fn nyq_spread(x_in: u32) -> u32 {
    var x = x_in & 0xffffu;
    x = (x | (x << 8u)) & 0x00ff00ffu;
    x = (x | (x << 4u)) & 0x0f0f0f0fu;
    x = (x | (x << 2u)) & 0x33333333u;
    return (x | (x << 1u)) & 0x55555555u;
}

// The pixel's Morton code in the sampler's power-of-two square (coordinates wrap).
fn nyq_zsobol_morton(s: NyqZSobolSampler, pixel: vec2<u32>) -> u32 {
    let mask = select(0xffffffffu >> ((32u - s.log2_res) & 31u), 0u, s.log2_res == 0u);
    return nyq_spread(pixel.x & mask) | (nyq_spread(pixel.y & mask) << 1u);
}

// One of the 24 permutations by a 32-bit hash: ⌊h · 24 / 2³²⌋.
fn nyq_one_of_24(h: u32) -> u32 {
    return nyq_mul_wide(h, 24u).y;
}

// The hash key of requests at dimension `dim`: hash2(seed, dim ^ "ZSOBOL").
fn nyq_zsobol_dim_key(seed: vec2<u32>, dim: u32) -> vec2<u32> {
    return nyq_hash2(seed, vec2<u32>(dim ^ 0x4f424f4cu, 0x5a53u));
}

// The permutation of the pixel digit below the digits `higher`, under the request's key.
fn nyq_zsobol_pixel_node(higher: u32, key: vec2<u32>) -> u32 {
    return NYQ_PERMUTATIONS_4[nyq_one_of_24(nyq_mix32(higher ^ nyq_shr64(key, 16u).x))];
}

// Base-4 digit `digit` through the packed permutation `perm`, placed at bit `shift`.
fn nyq_permuted_digit(perm: u32, digit: u32, shift: u32) -> u32 {
    return ((perm >> (2u * digit)) & 3u) << shift;
}

// The random word of a pixel (its Morton code) for the requests keyed `key`:
// mix64(morton ^ rotate_left(key, 17)).
fn nyq_zsobol_pixel_word(pixel_morton: u32, key: vec2<u32>) -> vec2<u32> {
    let rotated = nyq_shl64(key, 17u) | vec2<u32>(key.y >> 15u, 0u);
    return nyq_mix64(nyq_u64(pixel_morton) ^ rotated);
}

// The word that picks the permutation of the sample digit at bit `shift` given the sample
// digits above it: (w ^ ((higher << 6 | shift) · ⌊2⁶⁴/φ⌋)) · 0xd1b54a32d192ed03.
fn nyq_zsobol_nested_word(w: vec2<u32>, higher: u32, shift: u32) -> vec2<u32> {
    let tag = vec2<u32>((higher << 6u) | shift, higher >> 26u);
    let spread = nyq_mul64(tag, vec2<u32>(0x7f4a7c15u, 0x9e3779b9u));
    return nyq_mul64(w ^ spread, vec2<u32>(0xd192ed03u, 0xd1b54a32u));
}

// The permuted Sobol index of the sample whose Morton index is `morton`, for the request at
// dimension `dim`: core `ZSobolSampler::sequence_index`.
fn nyq_zsobol_index(s: NyqZSobolSampler, morton: u32, key: vec2<u32>) -> u32 {
    var index = 0u;
    // The pixel's digits, the most significant first, each permuted by a hash of those above.
    for (var i = s.digits; i > s.sample_digits; i--) {
        let shift = 2u * (i - 1u) + s.odd;
        let digit = (morton >> shift) & 3u;
        index |= nyq_permuted_digit(nyq_zsobol_pixel_node(nyq_shr(morton, shift + 2u), key), digit, shift);
    }
    // The sample's digits, each permuted by a multiplicative hash of the pixel word.
    let w = nyq_zsobol_pixel_word(nyq_shr(morton, s.log2_spp), key);
    let sample = morton & (s.spp - 1u);
    for (var i = s.sample_digits; i > 0u; i--) {
        let shift = 2u * (i - 1u) + s.odd;
        let digit = (sample >> shift) & 3u;
        let node = nyq_one_of_24(nyq_zsobol_nested_word(w, nyq_shr(sample, shift + 2u), shift).y);
        index |= nyq_permuted_digit(NYQ_PERMUTATIONS_4[node], digit, shift);
    }
    if s.odd == 1u {
        index |= (sample & 1u) ^ (nyq_zsobol_nested_word(w, sample >> 1u, 0u).y >> 31u);
    }
    return index;
}

// The permuted Sobol index of sample `sample_index` (mod spp) of `pixel` for the request at
// `dim`: core `ZSobolSampler::sequence_index`.
fn nyq_zsobol_sequence_index(s: NyqZSobolSampler, pixel: vec2<u32>, sample_index: u32, dim: u32) -> u32 {
    let morton = (nyq_zsobol_morton(s, pixel) << s.log2_spp) | (sample_index & (s.spp - 1u));
    return nyq_zsobol_index(s, morton, nyq_zsobol_dim_key(s.seed, dim));
}

// Sobol dimension 0 at `index` scrambled by `how` under `seed`.
fn nyq_zsobol_dim0(index: u32, seed: u32, how: u32) -> u32 {
    if how == NYQ_SCRAMBLE_FAST_OWEN {
        return reverseBits(nyq_lk_hash(index, seed));
    }
    return nyq_scramble_u32(reverseBits(index), seed, how);
}

// The value of a 1-D request at `dim`.
fn nyq_zsobol_value_1d(s: ptr<function, NyqZSobolSampler>, dim: u32) -> f32 {
    let key = nyq_zsobol_dim_key((*s).seed, dim);
    let index = nyq_zsobol_index(*s, (*s).morton, key);
    return nyq_fraction_to_f32(nyq_zsobol_dim0(index, key.x, (*s).scramble));
}

// The value of a 2-D request at `dim`: Sobol dimensions 0 and 1 at the request's index.
fn nyq_zsobol_value_2d(s: ptr<function, NyqZSobolSampler>, dim: u32) -> vec2<f32> {
    let key = nyq_zsobol_dim_key((*s).seed, dim);
    let index = nyq_zsobol_index(*s, (*s).morton, key);
    let x = nyq_zsobol_dim0(index, key.x, (*s).scramble);
    var y: u32;
    if (*s).scramble == NYQ_SCRAMBLE_FAST_OWEN {
        // The core's reversed-table form: the LK hash keyed by the key's high half directly.
        y = reverseBits(nyq_lk_hash(reverseBits(nyq_sobol_u32(index, 1u)), key.y));
    } else {
        y = nyq_scramble_u32(nyq_sobol_u32(index, 1u), key.y, (*s).scramble);
    }
    return vec2<f32>(nyq_fraction_to_f32(x), nyq_fraction_to_f32(y));
}

// Moves to sample `sample_index` (mod spp) of `pixel`, at dimension `dim`.
fn nyq_zsobol_start(s: ptr<function, NyqZSobolSampler>, pixel: vec2<u32>, sample_index: u32, dim: u32) {
    (*s).morton = (nyq_zsobol_morton(*s, pixel) << (*s).log2_spp) | (sample_index & ((*s).spp - 1u));
    (*s).dim = dim;
}

// The next dimension: core `get_1d`.
fn nyq_zsobol_get_1d(s: ptr<function, NyqZSobolSampler>) -> f32 {
    let d = (*s).dim;
    (*s).dim = d + 1u;
    return nyq_zsobol_value_1d(s, d);
}

// The next 2-D request: core `get_2d`.
fn nyq_zsobol_get_2d(s: ptr<function, NyqZSobolSampler>) -> vec2<f32> {
    let d = (*s).dim;
    (*s).dim = d + 2u;
    return nyq_zsobol_value_2d(s, d);
}

// The image sample (the request at dimension 0), whatever the cursor: core `get_pixel_2d`.
fn nyq_zsobol_get_pixel_2d(s: ptr<function, NyqZSobolSampler>) -> vec2<f32> {
    (*s).dim = max((*s).dim, 2u);
    return nyq_zsobol_value_2d(s, 0u);
}

// The camera's sample: the image request at 0, time at 2, lens at 3; the cursor ends at 5.
fn nyq_zsobol_camera_sample(s: ptr<function, NyqZSobolSampler>, pixel: vec2<u32>, sample_index: u32) -> NyqCameraSample {
    nyq_zsobol_start(s, pixel, sample_index, 0u);
    let p = nyq_zsobol_value_2d(s, 0u);
    let time = nyq_zsobol_value_1d(s, 2u);
    let lens = nyq_zsobol_value_2d(s, 3u);
    (*s).dim = 5u;
    let film = vec2<f32>(nyq_film_coordinate(pixel.x, p.x), nyq_film_coordinate(pixel.y, p.y));
    return NyqCameraSample(film, lens, time);
}
