// ---------------------------------------------------------------------------------------------
// owen_sobol: Owen-scrambled Sobol (Burley 2020) as a sequence and as a pixel sampler
// (core/src/sequence/owen_sobol.rs, core/src/sampler/owen_sobol.rs).
//
// Point i, dimension d is fast_owen(sobol(shuffle(i), d), seed_d): one nested uniform shuffle
// of the index shared by every dimension, one Owen scramble per dimension. The core reads
// precomputed products of reversed columns; here the same products come from the matrices.

// The scramble seed of dimension `dim` under a sequence key: core `dim_seed`.
fn nyq_dim_seed(key: u32, dim: u32) -> u32 {
    return nyq_mix32(key ^ (dim * 0x9e3779b9u));
}

// The reversed shuffled index of `index` under a mixed shuffle seed (core `IndexShuffle::rev`):
// the LK hash of the reversed index, with the fixed XOR that keeps indices below 2¹⁶ there.
fn nyq_shuffle_rev(index: u32, shuffle_seed: u32) -> u32 {
    let fix = nyq_lk_hash(0u, shuffle_seed) & 0xffffu;
    return nyq_lk_hash(reverseBits(index), shuffle_seed) ^ fix;
}

// Dimension `dim` (mod 1024 for the matrix) at the reversed shuffled index `r`, scrambled under
// the mixed `dim_seed`, still bit-reversed: core `owen_sobol_rev_u32` before its reversal.
fn nyq_owen_sobol_rev(r: u32, dim: u32, dim_seed: u32) -> u32 {
    return nyq_lk_hash(nyq_sobol_rev(r, dim % NYQ_SOBOL_DIMS), dim_seed);
}

// The Owen-scrambled Sobol sequence (core `OwenSobol`). Build it with `nyq_owen_sobol`.
struct NyqOwenSobol {
    dims: u32,
    shuffle_seed: u32,
    key: u32,
}

// The sequence of `dims` dimensions (1..=1024, which the host checks: core `OwenSobol::new`)
// scrambled by the 64-bit `seed`.
fn nyq_owen_sobol(dims: u32, seed: vec2<u32>) -> NyqOwenSobol {
    // "OWEN"
    let h = nyq_hash2(seed, nyq_u64(0x4f57454eu));
    return NyqOwenSobol(dims, nyq_mix32(h.y), h.x);
}

// Point `index`, dimension `dim` (mod dims) as a 32-bit fraction: core `OwenSobol::sample_u32`.
fn nyq_owen_sobol_sample_u32(s: NyqOwenSobol, index: u32, dim: u32) -> u32 {
    let d = dim % s.dims;
    let r = nyq_shuffle_rev(index, s.shuffle_seed);
    return reverseBits(nyq_owen_sobol_rev(r, d, nyq_dim_seed(s.key, d)));
}

// Point `index`, dimension `dim` as an f32: core `Sequence::sample`.
fn nyq_owen_sobol_sample(s: NyqOwenSobol, index: u32, dim: u32) -> f32 {
    return nyq_fraction_to_f32(nyq_owen_sobol_sample_u32(s, index, dim));
}

// Dimensions first_dim .. first_dim + 4 (each mod dims) of point `index`, sharing one index
// shuffle: core `OwenSobol::sample_4d`.
fn nyq_owen_sobol_sample_4d(s: NyqOwenSobol, index: u32, first_dim: u32) -> vec4<f32> {
    let r = nyq_shuffle_rev(index, s.shuffle_seed);
    var out: vec4<f32>;
    for (var k = 0u; k < 4u; k++) {
        let d = (first_dim + k) % s.dims;
        out[k] = nyq_rev_to_f32(nyq_owen_sobol_rev(r, d, nyq_dim_seed(s.key, d)));
    }
    return out;
}

// The Owen-scrambled Sobol pixel sampler (core `OwenSobolSampler`): sample i of pixel p in
// frame f is point i of the sequence whose shuffle and scrambles are keyed by a 64-bit hash of
// (p.x, p.y, f, seed). A cursor: `nyq_owen_sobol_sampler` builds it, the functions below move
// it.
struct NyqOwenSobolSampler {
    seed: vec2<u32>,
    frame: u32,
    // The dimension seeds' key of the current pixel, and its reversed shuffled sample index.
    key: u32,
    r: u32,
    dim: u32,
}

// A sampler for `frame` under the 64-bit `seed` (spp is the host's business: every 32-bit
// sample index is a new point).
fn nyq_owen_sobol_sampler(seed: vec2<u32>, frame: u32) -> NyqOwenSobolSampler {
    return NyqOwenSobolSampler(seed, frame, 0u, 0u, 0u);
}

// Moves to sample `sample_index` of `pixel`, at dimension `dim`: core `start_pixel_sample`.
fn nyq_owen_sobol_start(s: ptr<function, NyqOwenSobolSampler>, pixel: vec2<u32>, sample_index: u32, dim: u32) {
    let h = nyq_hash4(nyq_u64(pixel.x), nyq_u64(pixel.y), nyq_u64((*s).frame), (*s).seed);
    (*s).key = h.x;
    (*s).r = nyq_shuffle_rev(sample_index, nyq_mix32(h.y));
    (*s).dim = dim;
}

// Dimension `dim` of the current sample.
fn nyq_owen_sobol_value(s: ptr<function, NyqOwenSobolSampler>, dim: u32) -> f32 {
    return nyq_rev_to_f32(nyq_owen_sobol_rev((*s).r, dim, nyq_dim_seed((*s).key, dim)));
}

// The next dimension: core `get_1d`.
fn nyq_owen_sobol_get_1d(s: ptr<function, NyqOwenSobolSampler>) -> f32 {
    let d = (*s).dim;
    (*s).dim = d + 1u;
    return nyq_owen_sobol_value(s, d);
}

// The next two dimensions: core `get_2d`.
fn nyq_owen_sobol_get_2d(s: ptr<function, NyqOwenSobolSampler>) -> vec2<f32> {
    let d = (*s).dim;
    (*s).dim = d + 2u;
    return vec2<f32>(nyq_owen_sobol_value(s, d), nyq_owen_sobol_value(s, d + 1u));
}

// The image sample, dimensions 0 and 1, whatever the cursor: core `get_pixel_2d`.
fn nyq_owen_sobol_get_pixel_2d(s: ptr<function, NyqOwenSobolSampler>) -> vec2<f32> {
    (*s).dim = max((*s).dim, 2u);
    return vec2<f32>(nyq_owen_sobol_value(s, 0u), nyq_owen_sobol_value(s, 1u));
}

// The camera's sample (film position, time, lens: dimensions 0..5), leaving the cursor at
// dimension 5: core `camera_sample`.
fn nyq_owen_sobol_camera_sample(s: ptr<function, NyqOwenSobolSampler>, pixel: vec2<u32>, sample_index: u32) -> NyqCameraSample {
    nyq_owen_sobol_start(s, pixel, sample_index, 0u);
    var v: array<f32, 5>;
    for (var d = 0u; d < 5u; d++) {
        v[d] = nyq_owen_sobol_value(s, d);
    }
    (*s).dim = 5u;
    let p = vec2<f32>(nyq_film_coordinate(pixel.x, v[0]), nyq_film_coordinate(pixel.y, v[1]));
    return NyqCameraSample(p, vec2<f32>(v[3], v[4]), v[2]);
}
