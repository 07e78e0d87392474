// ---------------------------------------------------------------------------------------------
// random: independent uniform values (core/src/sampler/random.rs): PCG32 (O'Neill's XSH RR
// 64/32, as the rand_pcg crate defines it) seeded per pixel sample, one value per dimension.

// PCG32's multiplier and the sampler's stream increment ((0x2545f4914f6cdd1d << 1) | 1).
const NYQ_PCG_MULTIPLIER = vec2<u32>(0x4c957f2du, 0x5851f42du);
const NYQ_RANDOM_INCREMENT = vec2<u32>(0x9ed9ba3bu, 0x4a8be922u);

// A PCG32 generator on the sampler's stream: its 64-bit state.
struct NyqPcg32 {
    state: vec2<u32>,
}

// rand_pcg's `Pcg32::new(state, stream)` on the sampler's stream.
fn nyq_pcg32(state: vec2<u32>) -> NyqPcg32 {
    let s = nyq_add64(state, NYQ_RANDOM_INCREMENT);
    return NyqPcg32(nyq_add64(nyq_mul64(s, NYQ_PCG_MULTIPLIER), NYQ_RANDOM_INCREMENT));
}

// The next 32-bit output.
fn nyq_pcg32_next(g: ptr<function, NyqPcg32>) -> u32 {
    let old = (*g).state;
    (*g).state = nyq_add64(nyq_mul64(old, NYQ_PCG_MULTIPLIER), NYQ_RANDOM_INCREMENT);
    let x = nyq_shr64(nyq_shr64(old, 18u) ^ old, 27u).x;
    let rot = old.y >> 27u;
    return (x >> rot) | (x << ((32u - rot) & 31u));
}

// Jumps `delta` outputs ahead in O(log delta) (Brown 1994, as rand_pcg's `advance`).
fn nyq_pcg32_advance(g: ptr<function, NyqPcg32>, delta: u32) {
    var acc_mult = vec2<u32>(1u, 0u);
    var acc_plus = vec2<u32>(0u, 0u);
    var cur_mult = NYQ_PCG_MULTIPLIER;
    var cur_plus = NYQ_RANDOM_INCREMENT;
    var d = delta;
    while d > 0u {
        if (d & 1u) != 0u {
            acc_mult = nyq_mul64(acc_mult, cur_mult);
            acc_plus = nyq_add64(nyq_mul64(acc_plus, cur_mult), cur_plus);
        }
        cur_plus = nyq_mul64(nyq_add64(cur_mult, vec2<u32>(1u, 0u)), cur_plus);
        cur_mult = nyq_mul64(cur_mult, cur_mult);
        d >>= 1u;
    }
    (*g).state = nyq_add64(nyq_mul64(acc_mult, (*g).state), acc_plus);
}

// hash3(a, b, c) = mix64(hash2(a, b) ^ (c + 3·⌊2⁶⁴/φ⌋)): core `hash3`.
fn nyq_hash3(a: vec2<u32>, b: vec2<u32>, c: vec2<u32>) -> vec2<u32> {
    return nyq_mix64(nyq_hash2(a, b) ^ nyq_add64(c, vec2<u32>(0x7ddf743fu, 0xdaa66d2cu)));
}

// The random sampler (core `RandomSampler`). Build it with `nyq_random_sampler`.
struct NyqRandomSampler {
    seed: vec2<u32>,
    // The current sample's generator seed, its generator and dimension.
    base: vec2<u32>,
    rng: NyqPcg32,
    dim: u32,
}

// The sampler under the 64-bit `seed`.
fn nyq_random_sampler(seed: vec2<u32>) -> NyqRandomSampler {
    return NyqRandomSampler(seed, vec2<u32>(0u, 0u), NyqPcg32(vec2<u32>(0u, 0u)), 0u);
}

// The generator of dimension `dim` of the current sample (every u32 dimension its own output).
fn nyq_random_at(s: ptr<function, NyqRandomSampler>, dim: u32) -> NyqPcg32 {
    var g = nyq_pcg32((*s).base);
    if dim != 0u {
        nyq_pcg32_advance(&g, dim);
    }
    return g;
}

// Moves to sample `sample_index` of `pixel`, at dimension `dim`.
fn nyq_random_start(s: ptr<function, NyqRandomSampler>, pixel: vec2<u32>, sample_index: u32, dim: u32) {
    // "rand"
    let key = nyq_hash3(pixel, (*s).seed, nyq_u64(0x72616e64u));
    let golden = vec2<u32>(0x7f4a7c15u, 0x9e3779b9u);
    (*s).base = nyq_mix64(key ^ nyq_mul64(nyq_u64(sample_index), golden));
    (*s).dim = dim;
    (*s).rng = nyq_random_at(s, dim);
}

// The next dimension.
fn nyq_random_get_1d(s: ptr<function, NyqRandomSampler>) -> f32 {
    // A local copy: naga's SPIR-V writer cannot pass a pointer to a member of a pointee.
    var g = (*s).rng;
    let v = nyq_fraction_to_f32(nyq_pcg32_next(&g));
    (*s).rng = g;
    (*s).dim += 1u;
    if (*s).dim == 0u {
        // The cursor wrapped past u32's last dimension.
        (*s).rng = nyq_random_at(s, 0u);
    }
    return v;
}

// The next two dimensions.
fn nyq_random_get_2d(s: ptr<function, NyqRandomSampler>) -> vec2<f32> {
    let u = nyq_random_get_1d(s);
    return vec2<f32>(u, nyq_random_get_1d(s));
}

// Dimensions 0 and 1, whatever the cursor.
fn nyq_random_get_pixel_2d(s: ptr<function, NyqRandomSampler>) -> vec2<f32> {
    if (*s).dim == 0u {
        return nyq_random_get_2d(s);
    }
    var g = nyq_random_at(s, 0u);
    let u = nyq_fraction_to_f32(nyq_pcg32_next(&g));
    let p = vec2<f32>(u, nyq_fraction_to_f32(nyq_pcg32_next(&g)));
    if (*s).dim < 2u {
        (*s).dim = 2u;
        (*s).rng = g;
    }
    return p;
}

// The camera's sample: image (0, 1), time (2), lens (3, 4).
fn nyq_random_camera_sample(s: ptr<function, NyqRandomSampler>, pixel: vec2<u32>, sample_index: u32) -> NyqCameraSample {
    nyq_random_start(s, pixel, sample_index, 0u);
    let p = nyq_random_get_pixel_2d(s);
    let time = nyq_random_get_1d(s);
    let lens = nyq_random_get_2d(s);
    let film = vec2<f32>(nyq_film_coordinate(pixel.x, p.x), nyq_film_coordinate(pixel.y, p.y));
    return NyqCameraSample(film, lens, time);
}
