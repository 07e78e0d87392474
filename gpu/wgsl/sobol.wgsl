// ---------------------------------------------------------------------------------------------
// sobol: the Sobol sequence (core/src/sequence/sobol.rs) over the Joe–Kuo generator matrices.
//
// The matrices are a storage buffer of 1024 × 32 words, column k of dimension d at 32·d + k
// (`nyquist_gpu::sobol_matrices()`, 128 KiB): a table that size has no place in shader
// constants. Its group and binding are those below unless the engine asks for others
// (`nyquist_gpu::Bindings`).

@group(0) @binding(0) var<storage, read> nyq_sobol_matrices: array<u32>;

// The number of Sobol dimensions; dimension d reads the matrix of d mod 1024.
const NYQ_SOBOL_DIMS: u32 = 1024u;

// Sobol point `index`, dimension `dim` (mod 1024), as a 32-bit fraction: the XOR of the
// columns of the index's set bits. core `sobol_u32`.
fn nyq_sobol_u32(index: u32, dim: u32) -> u32 {
    let base = (dim % NYQ_SOBOL_DIMS) * 32u;
    var v = 0u;
    var bits = index;
    while bits != 0u {
        v ^= nyq_sobol_matrices[base + countTrailingZeros(bits)];
        bits &= bits - 1u;
    }
    return v;
}

// reverse(sobol(reverse(r), dim)): the product on bit-reversed words, where the core's
// Owen-scrambled forms work.
fn nyq_sobol_rev(r: u32, dim: u32) -> u32 {
    return reverseBits(nyq_sobol_u32(reverseBits(r), dim));
}

// The Sobol sequence over `dims` dimensions, plain or with a per-dimension digital shift
// (core `Sobol::new`, `Sobol::with_digital_shift`). Build it with `nyq_sobol`.
struct NyqSobol {
    dims: u32,
    scrambled: u32,
    seed: vec2<u32>,
}

// The sequence of `dims` dimensions (1..=1024, which the host checks: core `Sobol::new`);
// `scrambled` != 0 adds the digital shift of `seed`.
fn nyq_sobol(dims: u32, scrambled: bool, seed: vec2<u32>) -> NyqSobol {
    return NyqSobol(dims, select(0u, 1u, scrambled), seed);
}

// Point `index`, dimension `dim` (mod dims) as a 32-bit fraction: core `Sobol::sample_u32`.
fn nyq_sobol_sample_u32(s: NyqSobol, index: u32, dim: u32) -> u32 {
    let d = dim % s.dims;
    var shift = 0u;
    if s.scrambled != 0u {
        shift = nyq_hash2(s.seed, nyq_u64(d)).y;
    }
    return nyq_sobol_u32(index, d) ^ shift;
}

// Point `index`, dimension `dim` as an f32: core `Sequence::sample`.
fn nyq_sobol_sample(s: NyqSobol, index: u32, dim: u32) -> f32 {
    return nyq_fraction_to_f32(nyq_sobol_sample_u32(s, index, dim));
}

// The global Sobol pixel sampler (core `SobolSampler`, pbrt-v3's): one Sobol sequence over the
// image's power-of-two square; a pixel's samples are the indices whose first two dimensions
// fall in it, found by inverting the map from the low 2m index bits to the top m bits of
// dimensions 0 and 1 over GF(2). Build it with `nyq_sobol_sampler`.
struct NyqSobolSampler {
    spp: u32,
    m: u32,
    scramble: u32,
    seed: vec2<u32>,
    // The inverse map's 32 columns, four to a vector (an array member would not survive
    // naga's GLSL round trip).
    inverse0: vec4<u32>,
    inverse1: vec4<u32>,
    inverse2: vec4<u32>,
    inverse3: vec4<u32>,
    inverse4: vec4<u32>,
    inverse5: vec4<u32>,
    inverse6: vec4<u32>,
    inverse7: vec4<u32>,
    shift: vec2<u32>,
    index: u32,
    dim: u32,
}

// The top `bits` bits of v (0 for none).
fn nyq_top(v: u32, bits: u32) -> u32 {
    return select(v >> ((32u - bits) & 31u), 0u, bits == 0u);
}

// The sampler for an image of `resolution` at `spp` (rounded up to a power of two), scrambled
// by `scramble` (NYQ_SCRAMBLE_*) under `seed`: core `SobolSampler::new` (the host
// checks 2·⌈log₂ max(resolution)⌉ + log₂ spp ≤ 32). The core's sampler named `sobol` (NamedSampler)
// is NYQ_SCRAMBLE_PERMUTE_DIGITS, `sobol-plain` NYQ_SCRAMBLE_NONE.
fn nyq_sobol_sampler(resolution: vec2<u32>, spp_requested: u32, scramble: u32, seed_in: vec2<u32>) -> NyqSobolSampler {
    let spp = nyq_round_up_pow2(spp_requested);
    let side = max(resolution.x, resolution.y);
    let m = 32u - countLeadingZeros(side - 1u);
    var seed = seed_in;
    if scramble == NYQ_SCRAMBLE_NONE {
        seed = vec2<u32>(0u, 0u);
    }
    var shift = vec2<u32>(0u, 0u);
    if scramble == NYQ_SCRAMBLE_PERMUTE_DIGITS {
        let mask = select(0xffffffffu >> (m & 31u), 0xffffffffu, m == 0u);
        shift = vec2<u32>(nyq_hash2(seed, nyq_u64(0u)).x & mask, nyq_hash2(seed, nyq_u64(1u)).x & mask);
    }
    // Gauss–Jordan over GF(2): row i's low word says which index bits feed target bit i, its
    // high word starts as the identity and ends as the inverse's row.
    let n = 2u * m;
    var rows: array<vec2<u32>, 32>;
    for (var c = 0u; c < n; c++) {
        let x = nyq_top(nyq_sobol_u32(1u << c, 0u), m);
        let y = nyq_top(nyq_sobol_u32(1u << c, 1u), m);
        let image_bits = vec2<u32>(x | (y << (m & 31u)), select(y >> ((32u - m) & 31u), 0u, m == 0u));
        for (var i = 0u; i < n; i++) {
            let bit = select(image_bits.x >> i, image_bits.y >> (i - 32u), i >= 32u) & 1u;
            if bit == 1u {
                rows[i].x |= 1u << c;
            }
        }
    }
    for (var i = 0u; i < n; i++) {
        rows[i].y |= 1u << i;
    }
    for (var col = 0u; col < n; col++) {
        var pivot = col;
        for (var r = col; r < n; r++) {
            if ((rows[r].x >> col) & 1u) == 1u {
                pivot = r;
                break;
            }
        }
        let t = rows[col];
        rows[col] = rows[pivot];
        rows[pivot] = t;
        for (var r = 0u; r < n; r++) {
            if r != col && ((rows[r].x >> col) & 1u) == 1u {
                rows[r] ^= rows[col];
            }
        }
    }
    var inverse: array<u32, 32>;
    for (var i = 0u; i < n; i++) {
        for (var r = 0u; r < n; r++) {
            if ((rows[i].y >> r) & 1u) == 1u {
                inverse[r] |= 1u << i;
            }
        }
    }
    let v0 = vec4<u32>(inverse[0], inverse[1], inverse[2], inverse[3]);
    let v1 = vec4<u32>(inverse[4], inverse[5], inverse[6], inverse[7]);
    let v2 = vec4<u32>(inverse[8], inverse[9], inverse[10], inverse[11]);
    let v3 = vec4<u32>(inverse[12], inverse[13], inverse[14], inverse[15]);
    let v4 = vec4<u32>(inverse[16], inverse[17], inverse[18], inverse[19]);
    let v5 = vec4<u32>(inverse[20], inverse[21], inverse[22], inverse[23]);
    let v6 = vec4<u32>(inverse[24], inverse[25], inverse[26], inverse[27]);
    let v7 = vec4<u32>(inverse[28], inverse[29], inverse[30], inverse[31]);
    return NyqSobolSampler(spp, m, scramble, seed, v0, v1, v2, v3, v4, v5, v6, v7, shift, 0u, 0u);
}

// The inverse map applied to the target bits t.
fn nyq_sobol_sampler_invert(s: ptr<function, NyqSobolSampler>, t_in: u32) -> u32 {
    var low = 0u;
    var t = t_in;
    while t != 0u {
        let k = countTrailingZeros(t);
        var four: vec4<u32>;
        switch k >> 2u {
            case 0u: { four = (*s).inverse0; }
            case 1u: { four = (*s).inverse1; }
            case 2u: { four = (*s).inverse2; }
            case 3u: { four = (*s).inverse3; }
            case 4u: { four = (*s).inverse4; }
            case 5u: { four = (*s).inverse5; }
            case 6u: { four = (*s).inverse6; }
            default: { four = (*s).inverse7; }
        }
        low ^= four[k & 3u];
        t &= t - 1u;
    }
    return low;
}

// The global Sobol index of sample `sample_index` (mod spp) of `pixel` (coordinates wrap
// modulo 2^m): core `SobolSampler::sequence_index`.
fn nyq_sobol_sampler_index(s: ptr<function, NyqSobolSampler>, pixel: vec2<u32>, sample_index: u32) -> u32 {
    let m = (*s).m;
    let si = sample_index % (*s).spp;
    let high = select(si << ((2u * m) & 31u), 0u, 2u * m >= 32u);
    let mask = select(0xffffffffu >> ((32u - m) & 31u), 0u, m == 0u);
    let want = (pixel.x & mask) | ((pixel.y & mask) << (m & 31u));
    let have = nyq_top(nyq_sobol_u32(high, 0u), m) | (nyq_top(nyq_sobol_u32(high, 1u), m) << (m & 31u));
    return high | nyq_sobol_sampler_invert(s, want ^ have);
}

// Dimension `dim` of the current sample.
fn nyq_sobol_sampler_value(s: ptr<function, NyqSobolSampler>, dim: u32) -> f32 {
    let d = dim % NYQ_SOBOL_DIMS;
    let seed = (*s).seed;
    var v = nyq_sobol_u32((*s).index, d);
    let how = (*s).scramble;
    if how == NYQ_SCRAMBLE_FAST_OWEN || how == NYQ_SCRAMBLE_OWEN {
        // Dimensions 0 and 1: the fraction inside the pixel.
        let w = select(v, v << ((*s).m & 31u), d < 2u && (*s).m < 32u);
        return nyq_fraction_to_f32(nyq_scramble_u32(w, nyq_hash2(seed, nyq_u64(d)).y, how));
    }
    if d < 2u {
        v = (v ^ (*s).shift[d]) << (*s).m;
    } else if how == NYQ_SCRAMBLE_PERMUTE_DIGITS {
        v ^= nyq_hash2(seed, nyq_u64(d)).x;
    }
    return nyq_fraction_to_f32(v);
}

// Moves to sample `sample_index` of `pixel`, at dimension `dim`.
fn nyq_sobol_sampler_start(s: ptr<function, NyqSobolSampler>, pixel: vec2<u32>, sample_index: u32, dim: u32) {
    (*s).index = nyq_sobol_sampler_index(s, pixel, sample_index);
    (*s).dim = dim;
}

// The next dimension.
fn nyq_sobol_sampler_get_1d(s: ptr<function, NyqSobolSampler>) -> f32 {
    let d = (*s).dim;
    (*s).dim = d + 1u;
    return nyq_sobol_sampler_value(s, d);
}

// The next two dimensions.
fn nyq_sobol_sampler_get_2d(s: ptr<function, NyqSobolSampler>) -> vec2<f32> {
    let d = (*s).dim;
    (*s).dim = d + 2u;
    return vec2<f32>(nyq_sobol_sampler_value(s, d), nyq_sobol_sampler_value(s, d + 1u));
}

// Dimensions 0 and 1, whatever the cursor.
fn nyq_sobol_sampler_get_pixel_2d(s: ptr<function, NyqSobolSampler>) -> vec2<f32> {
    (*s).dim = max((*s).dim, 2u);
    return vec2<f32>(nyq_sobol_sampler_value(s, 0u), nyq_sobol_sampler_value(s, 1u));
}

// The camera's sample: image (0, 1), time (2), lens (3, 4).
fn nyq_sobol_sampler_camera_sample(s: ptr<function, NyqSobolSampler>, pixel: vec2<u32>, sample_index: u32) -> NyqCameraSample {
    nyq_sobol_sampler_start(s, pixel, sample_index, 0u);
    let p = nyq_sobol_sampler_get_pixel_2d(s);
    let time = nyq_sobol_sampler_get_1d(s);
    let lens = nyq_sobol_sampler_get_2d(s);
    let film = vec2<f32>(nyq_film_coordinate(pixel.x, p.x), nyq_film_coordinate(pixel.y, p.y));
    return NyqCameraSample(film, lens, time);
}
