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

// ---------------------------------------------------------------------------------------------
// scramble: base-2 scrambles (core/src/scramble.rs). A 32-bit value x is the binary fraction
// x / 2³², bit 31 its first digit.

// The scramble a sampler applies (core `Scramble`, in its order).
const NYQ_SCRAMBLE_NONE: u32 = 0u;
const NYQ_SCRAMBLE_PERMUTE_DIGITS: u32 = 1u;
const NYQ_SCRAMBLE_FAST_OWEN: u32 = 2u;
const NYQ_SCRAMBLE_OWEN: u32 = 3u;

// The Laine–Karras-style hash with Vegdahl's constants on a bit-reversed value: bit k of the
// result depends only on bits 0..=k of x_rev, so read backwards it is an Owen scramble. `seed`
// must already be mixed. core `lk_hash`.
fn nyq_lk_hash(x_rev: u32, seed: u32) -> u32 {
    var x = x_rev ^ (x_rev * 0x3d20adeau);
    x = (x + seed) * ((seed >> 16u) | 1u);
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// The fast (hash) Owen scramble of x under any seed: core `fast_owen_scramble`.
fn nyq_fast_owen_scramble(x: u32, seed: u32) -> u32 {
    return reverseBits(nyq_lk_hash(reverseBits(x), nyq_mix32(seed ^ 0x6a09e667u)));
}

// Burley's nested uniform shuffle of an index: core `nested_uniform_shuffle`.
fn nyq_nested_uniform_shuffle(index: u32, seed: u32) -> u32 {
    return nyq_fast_owen_scramble(index, seed);
}

// The exact Owen scramble: digit k flips when the top bit of mix64(K · 2³² + 2ᵏ + prefix) is
// set, K = mix32(seed ^ 0xbb67ae85), prefix the k digits before it. 32 hashes: core
// `owen_scramble`.
fn nyq_owen_scramble(x: u32, seed: u32) -> u32 {
    let key = nyq_mix32(seed ^ 0xbb67ae85u);
    var out = x;
    for (var k = 0u; k < 32u; k++) {
        let prefix = select(x >> ((32u - k) & 31u), 0u, k == 0u);
        let word = vec2<u32>((1u << k) | prefix, key);
        if (nyq_mix64(word).y >> 31u) == 1u {
            out ^= 1u << (31u - k);
        }
    }
    return out;
}

// x scrambled by `how` (NYQ_SCRAMBLE_*) under `seed`: core `scramble_u32`.
fn nyq_scramble_u32(x: u32, seed: u32, how: u32) -> u32 {
    switch how {
        case 1u: {
            return x ^ nyq_mix32(seed ^ 0x3c6ef372u);
        }
        case 2u: {
            return nyq_fast_owen_scramble(x, seed);
        }
        case 3u: {
            return nyq_owen_scramble(x, seed);
        }
        default: {
            return x;
        }
    }
}

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

// ---------------------------------------------------------------------------------------------
// lattice: the lattice pixel samplers (core/src/sampler/lattice.rs): the Fibonacci lattice, a
// Korobov lattice or Roberts' R2 in every dimension pair, Cranley–Patterson rotated per pixel
// and pair. Points are 64-bit fixed-point fractions, as in the core.

// The sets (core `LatticeSampler::fibonacci`, `korobov`, `r2`).
const NYQ_LATTICE_FIBONACCI: u32 = 0u;
const NYQ_LATTICE_KOROBOV: u32 = 1u;
const NYQ_LATTICE_R2: u32 = 2u;

// R2's steps, ⌊φ₂^−1·2⁶⁴⌋ and ⌊φ₂^−2·2⁶⁴⌋ for the plastic number φ₂ (Roberts 2018), as the
// core computes them in f64.
const NYQ_R2_ALPHA = array<vec2<u32>, 2>(vec2<u32>(0x02a63000u, 0xc13fa9a9u), vec2<u32>(0xc79e7800u, 0x91e10da5u));

// x mod n for a 64-bit x and 0 < n < 2³² (restoring division, one bit a step).
fn nyq_mod64(x: vec2<u32>, n: u32) -> u32 {
    var r = 0u;
    for (var i = 0u; i < 64u; i++) {
        let word = select(x.x, x.y, i < 32u);
        let bit = (word >> (31u - (i & 31u))) & 1u;
        let carry = r >> 31u;
        r = (r << 1u) | bit;
        if carry == 1u || r >= n {
            r -= n;
        }
    }
    return r;
}

// ⌊num · 2⁶⁴ / den⌋ for num < den < 2³²: the fraction num/den in 64-bit fixed point.
fn nyq_fixed_ratio(num: u32, den: u32) -> vec2<u32> {
    var r = num;
    var q = vec2<u32>(0u, 0u);
    for (var i = 0u; i < 64u; i++) {
        let carry = r >> 31u;
        r <<= 1u;
        q = nyq_shl64(q, 1u);
        if carry == 1u || r >= den {
            r -= den;
            q.x |= 1u;
        }
    }
    return q;
}

// A 64-bit fixed-point fraction as an f32: its top 24 bits.
fn nyq_fixed_to_f32(x: vec2<u32>) -> f32 {
    return f32(x.y >> 8u) * (1.0 / 16777216.0);
}

// A lattice pixel sampler. Build it with `nyq_lattice_sampler`.
struct NyqLatticeSampler {
    lattice: u32,
    // The number of points (the sampler's spp) and, for the Fibonacci and Korobov lattices,
    // the generator of the second coordinate (F_{m−1}, or the Korobov multiplier).
    n: u32,
    g: u32,
    seed: vec2<u32>,
    pixel: vec2<u32>,
    index: u32,
    dim: u32,
}

// The sampler of `lattice` (NYQ_LATTICE_*) with `n` points: for the Fibonacci lattice n = F_m and
// g = F_{m−1} (core `FibonacciLattice::at_least(spp)`), for Korobov n = spp and g its
// multiplier (core `LatticeSampler::korobov_multiplier`), for R2 n = spp and g unused.
fn nyq_lattice_sampler(lattice: u32, n: u32, g: u32, seed: vec2<u32>) -> NyqLatticeSampler {
    return NyqLatticeSampler(lattice, n, g, seed, vec2<u32>(0u, 0u), 0u, 0u);
}

// Dimension `dim` of the current sample.
fn nyq_lattice_value(s: ptr<function, NyqLatticeSampler>, dim: u32) -> f32 {
    let n = (*s).n;
    let k = (*s).index % n;
    let component = dim % 2u;
    var base: vec2<u32>;
    switch (*s).lattice {
        case 2u: {
            base = nyq_add64(vec2<u32>(0u, 0x80000000u), nyq_mul64(nyq_u64(k), NYQ_R2_ALPHA[component]));
        }
        default: {
            var g = (*s).g;
            if component == 0u {
                g = 1u % n;
            }
            base = nyq_fixed_ratio(nyq_mod64(nyq_mul_wide(k, g), n), n);
        }
    }
    let pair = nyq_hash3((*s).pixel, nyq_u64(dim / 2u), (*s).seed);
    return nyq_fixed_to_f32(nyq_add64(base, nyq_hash2(pair, nyq_u64(component))));
}

// Moves to sample `sample_index` of `pixel`, at dimension `dim`.
fn nyq_lattice_start(s: ptr<function, NyqLatticeSampler>, pixel: vec2<u32>, sample_index: u32, dim: u32) {
    (*s).pixel = pixel;
    (*s).index = sample_index;
    (*s).dim = dim;
}

// The next dimension.
fn nyq_lattice_get_1d(s: ptr<function, NyqLatticeSampler>) -> f32 {
    let d = (*s).dim;
    (*s).dim = d + 1u;
    return nyq_lattice_value(s, d);
}

// The next two dimensions.
fn nyq_lattice_get_2d(s: ptr<function, NyqLatticeSampler>) -> vec2<f32> {
    let d = (*s).dim;
    (*s).dim = d + 2u;
    return vec2<f32>(nyq_lattice_value(s, d), nyq_lattice_value(s, d + 1u));
}

// Dimensions 0 and 1, whatever the cursor.
fn nyq_lattice_get_pixel_2d(s: ptr<function, NyqLatticeSampler>) -> vec2<f32> {
    (*s).dim = max((*s).dim, 2u);
    return vec2<f32>(nyq_lattice_value(s, 0u), nyq_lattice_value(s, 1u));
}

// The camera's sample: image (0, 1), time (2), lens (3, 4).
fn nyq_lattice_camera_sample(s: ptr<function, NyqLatticeSampler>, pixel: vec2<u32>, sample_index: u32) -> NyqCameraSample {
    nyq_lattice_start(s, pixel, sample_index, 0u);
    let p = nyq_lattice_get_pixel_2d(s);
    let time = nyq_lattice_get_1d(s);
    let lens = nyq_lattice_get_2d(s);
    let film = vec2<f32>(nyq_film_coordinate(pixel.x, p.x), nyq_film_coordinate(pixel.y, p.y));
    return NyqCameraSample(film, lens, time);
}

// b^e mod n for n < 2³²: core `pow_mod`.
fn nyq_pow_mod(b: u32, e_in: u32, n: u32) -> u32 {
    var base = b % n;
    var r = 1u % n;
    var e = e_in;
    while e > 0u {
        if (e & 1u) == 1u {
            r = nyq_mod64(nyq_mul_wide(r, base), n);
        }
        base = nyq_mod64(nyq_mul_wide(base, base), n);
        e >>= 1u;
    }
    return r;
}

// A lattice as a sequence (core `FibonacciLattice`, `Korobov`, and `Kronecker::new(2)`, R2),
// plain or Cranley–Patterson rotated. Build it with `nyq_lattice`.
struct NyqLattice {
    lattice: u32,
    n: u32,
    g: u32,
    dims: u32,
    rotated: u32,
    seed: vec2<u32>,
}

// The lattice `lattice` (NYQ_LATTICE_*) of `n` points (n < 2³²: Fibonacci lattices up to F_47)
// with generator `g` (F_{m−1}, or the Korobov multiplier) in `dims` dimensions (2 for Fibonacci
// and R2), rotated by `seed` when `rotated` (core `rotated(seed)`).
fn nyq_lattice(lattice: u32, n: u32, g: u32, dims: u32, rotated: bool, seed: vec2<u32>) -> NyqLattice {
    return NyqLattice(lattice, n, g, dims, select(0u, 1u, rotated), seed);
}

// Point `index`, dimension `dim` (mod dims) as a 64-bit fixed-point fraction.
fn nyq_lattice_fixed(l: NyqLattice, index: u32, dim: u32) -> vec2<u32> {
    let d = dim % l.dims;
    var shift = vec2<u32>(0u, 0u);
    if l.rotated != 0u {
        shift = nyq_hash2(l.seed, nyq_u64(d));
    }
    if l.lattice == NYQ_LATTICE_R2 {
        let start = select(vec2<u32>(0u, 0x80000000u), shift, l.rotated != 0u);
        return nyq_add64(start, nyq_mul64(nyq_u64(index), NYQ_R2_ALPHA[d & 1u]));
    }
    var g = l.g;
    if d == 0u {
        g = 1u % l.n;
    } else if d > 1u {
        g = nyq_pow_mod(l.g, d, l.n);
    }
    let step = nyq_mod64(nyq_mul_wide(index % l.n, g), l.n);
    return nyq_add64(nyq_fixed_ratio(step, l.n), shift);
}

// Point `index`, dimension `dim` as an f32 (its top 24 bits): core `Sequence::sample`.
fn nyq_lattice_sample(l: NyqLattice, index: u32, dim: u32) -> f32 {
    return nyq_fixed_to_f32(nyq_lattice_fixed(l, index, dim));
}

// The bits of the f64 the core's `sample_f64` returns: the top 53 bits of the fraction.
fn nyq_fixed_to_f64_bits(x: vec2<u32>) -> vec2<u32> {
    let m = nyq_shr64(x, 11u);
    if m.x == 0u && m.y == 0u {
        return vec2<u32>(0u, 0u);
    }
    // The leading bit's position, then the 52 bits below it and the exponent 1023 + e − 53.
    let e = select(31u - countLeadingZeros(m.x), 63u - countLeadingZeros(m.y), m.y != 0u);
    var frac = m;
    let s = 52u - e;
    if s >= 32u {
        frac = vec2<u32>(0u, m.x << (s - 32u));
    } else if s > 0u {
        frac = nyq_shl64(m, s);
    }
    return vec2<u32>(frac.x, (frac.y & 0xfffffu) | ((1023u + e - 53u) << 20u));
}

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

// ---------------------------------------------------------------------------------------------
// screen_blue: the screen-space blue-noise samplers owen-sobol-bn, pmj02-bn and lattice-bn
// (core/src/sampler/screen_blue/). Each pixel's samples are one family's randomised net; which
// randomisation comes from the family's 128 × 128 tile, optimised so that neighbouring pixels'
// errors differ (blue noise).
//
// Dimensions go in 4-D blocks: dimension d is component d mod 4 of block d / 4. Block b at
// pixel p reads its family's tile entry at p + offset(seed, frame, b), toroidally; the entry is
// `key << 8 | rank`. The key seeds the block's index shuffle and scramble or shift, the rank is
// XOR-ed into the sample index.
//
// The three tiles are a storage buffer of 3 × 128 × 128 words, family-major (owen-sobol-bn,
// pmj02-bn, lattice-bn), each row-major: entry (x, y) of family f at f·16384 + y·128 + x
// (`nyquist_gpu::blue_tiles()`, 192 KiB, read from the core at run time: the tiles are the
// optimiser's output and change with it). Its group and binding are those below unless the
// engine asks for others (`nyquist_gpu::Bindings`).

@group(0) @binding(5) var<storage, read> nyq_blue_tiles: array<u32>;

// The families' places in the tile buffer.
const NYQ_BLUE_OWEN_SOBOL: u32 = 0u;
const NYQ_BLUE_PMJ02: u32 = 1u;
const NYQ_BLUE_LATTICE: u32 = 2u;

// The side of a tile.
const NYQ_BLUE_TILE_SIZE: u32 = 128u;

// Family `family`'s tile entry at (x, y), modulo the tile's side: core `BlueFamily::entry`.
fn nyq_blue_entry(family: u32, x: u32, y: u32) -> u32 {
    let m = NYQ_BLUE_TILE_SIZE - 1u;
    return nyq_blue_tiles[family * NYQ_BLUE_TILE_SIZE * NYQ_BLUE_TILE_SIZE + (y & m) * NYQ_BLUE_TILE_SIZE + (x & m)];
}

// The toroidal offset of `block` in `frame` under `seed`: a hash of the seed and the block plus
// the frame's point of Roberts' R2 sequence in 32-bit fixed point. core `screen_blue::offset`.
fn nyq_blue_offset(seed: vec2<u32>, frame: u32, block: u32) -> vec2<u32> {
    // "BLUE"
    let h = nyq_hash2(seed, nyq_u64(block ^ 0x424c5545u));
    let r = vec2<u32>((frame * 0xc13fa9a9u) >> 25u, (frame * 0x91e10da6u) >> 25u);
    return (h + r) & vec2<u32>(NYQ_BLUE_TILE_SIZE - 1u);
}

// The entry block `block` reads at `pixel`.
fn nyq_blue_block_entry(family: u32, seed: vec2<u32>, frame: u32, pixel: vec2<u32>, block: u32) -> u32 {
    let p = pixel + nyq_blue_offset(seed, frame, block);
    return nyq_blue_entry(family, p.x, p.y);
}

// `pixel + offset` as the core's `film_coordinate` computes it for any u32 pixel: the pixel's
// float rounded to nearest even from its bits (WGSL leaves an inexact conversion's rounding to
// the device), then the same float sums.
fn nyq_blue_film_coordinate(pixel: u32, offset: f32) -> f32 {
    let base = nyq_u32_to_f32(pixel);
    let x = base + offset;
    let edge = base + 1.0;
    if x < edge {
        return x;
    }
    let below = bitcast<f32>(bitcast<u32>(edge) - 1u);
    return select(base, below, below >= base);
}

// The camera sample of five values (film x, film y, time, lens x, lens y) at `pixel`.
fn nyq_blue_camera(pixel: vec2<u32>, v: array<f32, 5>) -> NyqCameraSample {
    let p = vec2<f32>(nyq_blue_film_coordinate(pixel.x, v[0]), nyq_blue_film_coordinate(pixel.y, v[1]));
    return NyqCameraSample(p, vec2<f32>(v[3], v[4]), v[2]);
}

// Shift `c` of a block whose hashed key is `key`: the digital shift of pmj02-bn and the
// Cranley–Patterson shift of lattice-bn (core `screen_blue::shift`).
fn nyq_blue_shift(key: u32, c: u32) -> u32 {
    return nyq_mix32(key ^ ((c + 1u) * 0x9e3779b9u));
}

// The state every blue-noise sampler keeps: the seed and frame, the current pixel, sample
// index and dimension, and for blocks 0 and 1 (the camera's five dimensions and three more)
// the entry's hashed key and what the sample index became in the block.
struct NyqBlueSampler {
    seed: vec2<u32>,
    frame: u32,
    pixel: vec2<u32>,
    index: u32,
    dim: u32,
    key: vec2<u32>,
    prepared: vec2<u32>,
}

fn nyq_blue_sampler(seed: vec2<u32>, frame: u32) -> NyqBlueSampler {
    return NyqBlueSampler(seed, frame, vec2<u32>(0u), 0u, 0u, vec2<u32>(0u), vec2<u32>(0u));
}

// ---------------------------------------------------------------------------------------------
// owen-sobol-bn (core screen_blue/owen_sobol.rs): a block is Sobol dimensions 0 … 3, each
// Owen-scrambled by its own seed, the index shuffled by a nested uniform shuffle, all hashed
// from the entry's key. Reads the Sobol matrices of dimensions 0 … 3.

// The block key of an entry.
fn nyq_owen_sobol_bn_key(entry: u32) -> u32 {
    // "BLK"
    return nyq_mix32((entry >> 8u) ^ 0x424c4b00u);
}

// The reversed shuffled index of sample `index` in the block of `entry` (key `key`), the
// rank XOR-ed in first: core `OwenSobolBlue::index`.
fn nyq_owen_sobol_bn_rev(entry: u32, key: u32, index: u32) -> u32 {
    // "SHUF"
    return nyq_shuffle_rev(index ^ (entry & 0xffu), nyq_mix32(key ^ 0x53485546u));
}

// Component `c` of the block of key `key` at the reversed shuffled index `rev`: core
// `OwenSobolBlue::value`.
fn nyq_owen_sobol_bn_value_at(key: u32, rev: u32, c: u32) -> f32 {
    return nyq_rev_to_f32(nyq_owen_sobol_rev(rev, c, nyq_dim_seed(key, c)));
}

// The sampler under the 64-bit `seed` in `frame` (spp is the host's business: every sample
// index is a new sample).
fn nyq_owen_sobol_bn_sampler(seed: vec2<u32>, frame: u32) -> NyqBlueSampler {
    return nyq_blue_sampler(seed, frame);
}

// Moves to sample `sample_index` of `pixel`, at dimension `dim`: core `start_pixel_sample`.
fn nyq_owen_sobol_bn_start(s: ptr<function, NyqBlueSampler>, pixel: vec2<u32>, sample_index: u32, dim: u32) {
    (*s).pixel = pixel;
    (*s).index = sample_index;
    (*s).dim = dim;
    for (var b = 0u; b < 2u; b++) {
        let e = nyq_blue_block_entry(NYQ_BLUE_OWEN_SOBOL, (*s).seed, (*s).frame, pixel, b);
        let key = nyq_owen_sobol_bn_key(e);
        (*s).key[b] = key;
        (*s).prepared[b] = nyq_owen_sobol_bn_rev(e, key, sample_index);
    }
}

// Dimension `dim` of the current sample.
fn nyq_owen_sobol_bn_value(s: ptr<function, NyqBlueSampler>, dim: u32) -> f32 {
    let b = dim / 4u;
    let c = dim % 4u;
    if b < 2u {
        return nyq_owen_sobol_bn_value_at((*s).key[b], (*s).prepared[b], c);
    }
    let e = nyq_blue_block_entry(NYQ_BLUE_OWEN_SOBOL, (*s).seed, (*s).frame, (*s).pixel, b);
    let key = nyq_owen_sobol_bn_key(e);
    return nyq_owen_sobol_bn_value_at(key, nyq_owen_sobol_bn_rev(e, key, (*s).index), c);
}

// The next dimension: core `get_1d`.
fn nyq_owen_sobol_bn_get_1d(s: ptr<function, NyqBlueSampler>) -> f32 {
    let d = (*s).dim;
    (*s).dim = d + 1u;
    return nyq_owen_sobol_bn_value(s, d);
}

// The next two dimensions: core `get_2d`.
fn nyq_owen_sobol_bn_get_2d(s: ptr<function, NyqBlueSampler>) -> vec2<f32> {
    let d = (*s).dim;
    (*s).dim = d + 2u;
    return vec2<f32>(nyq_owen_sobol_bn_value(s, d), nyq_owen_sobol_bn_value(s, d + 1u));
}

// The image sample, dimensions 0 and 1, whatever the cursor: core `get_pixel_2d`.
fn nyq_owen_sobol_bn_get_pixel_2d(s: ptr<function, NyqBlueSampler>) -> vec2<f32> {
    (*s).dim = max((*s).dim, 2u);
    return vec2<f32>(nyq_owen_sobol_bn_value(s, 0u), nyq_owen_sobol_bn_value(s, 1u));
}

// The camera's sample (film position, time, lens: dimensions 0..5), leaving the cursor at
// dimension 5: core `camera_sample`.
fn nyq_owen_sobol_bn_camera_sample(s: ptr<function, NyqBlueSampler>, pixel: vec2<u32>, sample_index: u32) -> NyqCameraSample {
    nyq_owen_sobol_bn_start(s, pixel, sample_index, 0u);
    var v: array<f32, 5>;
    for (var d = 0u; d < 5u; d++) {
        v[d] = nyq_owen_sobol_bn_value(s, d);
    }
    (*s).dim = 5u;
    return nyq_blue_camera(pixel, v);
}

// ---------------------------------------------------------------------------------------------
// pmj02-bn (core screen_blue/pmj02.rs): a block is two pairs, each a point of the PMJ(0,2)
// table at a nested uniform shuffle of the index's low 16 bits, its coordinates XOR-ed with a
// digital shift; shuffles and shifts are hashed from the entry's key and, past the first 65536
// samples, from the epoch (index >> 16). The table's points are rebuilt as pmj02.wgsl does
// (`nyq_pmj02_point`), not read.

// The block key of an entry in the epoch of the (rank-XOR-ed) sample index `i`: core
// `Pmj02Block::new`'s `k`.
fn nyq_pmj02_bn_key(entry: u32, i: u32) -> u32 {
    // "PMJ"
    let key = nyq_mix32((entry >> 8u) ^ 0x504d4a00u);
    let epoch = i >> 16u;
    return select(nyq_mix32(key ^ nyq_mix32(epoch)), key, epoch == 0u);
}

// The table points of the two pairs of sample `i` (the rank XOR-ed in) under the epoch key `k`,
// packed as two 16-bit halves: core `Pmj02Blue::index`.
fn nyq_pmj02_bn_points(k: u32, i: u32) -> u32 {
    // "SHUF", "SHUG"
    let p0 = reverseBits(nyq_shuffle_rev(i & 0xffffu, nyq_mix32(k ^ 0x53485546u))) & 0xffffu;
    let p1 = reverseBits(nyq_shuffle_rev(i & 0xffffu, nyq_mix32(k ^ 0x53485547u))) & 0xffffu;
    return p0 | (p1 << 16u);
}

// Component `c` of the block of epoch key `k` at the packed points `points`: core
// `Pmj02Blue::value`.
fn nyq_pmj02_bn_value_at(k: u32, points: u32, c: u32) -> f32 {
    let point = (points >> (16u * (c / 2u))) & 0xffffu;
    return nyq_fraction_to_f32(nyq_pmj02_point(NYQ_PMJ02_TABLE_SEED, point, c % 2u) ^ nyq_blue_shift(k, c));
}

fn nyq_pmj02_bn_sampler(seed: vec2<u32>, frame: u32) -> NyqBlueSampler {
    return nyq_blue_sampler(seed, frame);
}

fn nyq_pmj02_bn_start(s: ptr<function, NyqBlueSampler>, pixel: vec2<u32>, sample_index: u32, dim: u32) {
    (*s).pixel = pixel;
    (*s).index = sample_index;
    (*s).dim = dim;
    for (var b = 0u; b < 2u; b++) {
        let e = nyq_blue_block_entry(NYQ_BLUE_PMJ02, (*s).seed, (*s).frame, pixel, b);
        let i = sample_index ^ (e & 0xffu);
        let k = nyq_pmj02_bn_key(e, i);
        (*s).key[b] = k;
        (*s).prepared[b] = nyq_pmj02_bn_points(k, i);
    }
}

fn nyq_pmj02_bn_value(s: ptr<function, NyqBlueSampler>, dim: u32) -> f32 {
    let b = dim / 4u;
    let c = dim % 4u;
    if b < 2u {
        return nyq_pmj02_bn_value_at((*s).key[b], (*s).prepared[b], c);
    }
    let e = nyq_blue_block_entry(NYQ_BLUE_PMJ02, (*s).seed, (*s).frame, (*s).pixel, b);
    let i = (*s).index ^ (e & 0xffu);
    let k = nyq_pmj02_bn_key(e, i);
    return nyq_pmj02_bn_value_at(k, nyq_pmj02_bn_points(k, i), c);
}

fn nyq_pmj02_bn_get_1d(s: ptr<function, NyqBlueSampler>) -> f32 {
    let d = (*s).dim;
    (*s).dim = d + 1u;
    return nyq_pmj02_bn_value(s, d);
}

fn nyq_pmj02_bn_get_2d(s: ptr<function, NyqBlueSampler>) -> vec2<f32> {
    let d = (*s).dim;
    (*s).dim = d + 2u;
    return vec2<f32>(nyq_pmj02_bn_value(s, d), nyq_pmj02_bn_value(s, d + 1u));
}

fn nyq_pmj02_bn_get_pixel_2d(s: ptr<function, NyqBlueSampler>) -> vec2<f32> {
    (*s).dim = max((*s).dim, 2u);
    return vec2<f32>(nyq_pmj02_bn_value(s, 0u), nyq_pmj02_bn_value(s, 1u));
}

fn nyq_pmj02_bn_camera_sample(s: ptr<function, NyqBlueSampler>, pixel: vec2<u32>, sample_index: u32) -> NyqCameraSample {
    nyq_pmj02_bn_start(s, pixel, sample_index, 0u);
    var v: array<f32, 5>;
    for (var d = 0u; d < 5u; d++) {
        v[d] = nyq_pmj02_bn_value(s, d);
    }
    (*s).dim = 5u;
    return nyq_blue_camera(pixel, v);
}

// ---------------------------------------------------------------------------------------------
// lattice-bn (core screen_blue/lattice.rs): sample i of a block is frac(φ₂(s(i)) · g + Δ), g the
// 4-D generating vector, s a nested uniform shuffle and Δ a Cranley–Patterson shift hashed
// from the entry's key, in 32-bit fixed point.

// core `LATTICE_GENERATOR` (Hickernell, Kritzer, Kuo and Nuyens 2011).
const NYQ_LATTICE_BN_GENERATOR = vec4<u32>(1u, 364981u, 245389u, 97823u);

// The block key of an entry.
fn nyq_lattice_bn_key(entry: u32) -> u32 {
    // "LAT"
    return nyq_mix32((entry >> 8u) ^ 0x4c415400u);
}

// The reversed shuffled index of sample `index` (the rank XOR-ed in first): core
// `LatticeBlue::index`.
fn nyq_lattice_bn_rev(entry: u32, key: u32, index: u32) -> u32 {
    return nyq_shuffle_rev(index ^ (entry & 0xffu), nyq_mix32(key ^ 0x53485546u));
}

// Component `c` of the block of key `key` at the reversed shuffled index `rev`: core
// `LatticeBlue::value`.
fn nyq_lattice_bn_value_at(key: u32, rev: u32, c: u32) -> f32 {
    return nyq_fraction_to_f32(rev * NYQ_LATTICE_BN_GENERATOR[c] + nyq_blue_shift(key, c));
}

fn nyq_lattice_bn_sampler(seed: vec2<u32>, frame: u32) -> NyqBlueSampler {
    return nyq_blue_sampler(seed, frame);
}

fn nyq_lattice_bn_start(s: ptr<function, NyqBlueSampler>, pixel: vec2<u32>, sample_index: u32, dim: u32) {
    (*s).pixel = pixel;
    (*s).index = sample_index;
    (*s).dim = dim;
    for (var b = 0u; b < 2u; b++) {
        let e = nyq_blue_block_entry(NYQ_BLUE_LATTICE, (*s).seed, (*s).frame, pixel, b);
        let key = nyq_lattice_bn_key(e);
        (*s).key[b] = key;
        (*s).prepared[b] = nyq_lattice_bn_rev(e, key, sample_index);
    }
}

fn nyq_lattice_bn_value(s: ptr<function, NyqBlueSampler>, dim: u32) -> f32 {
    let b = dim / 4u;
    let c = dim % 4u;
    if b < 2u {
        return nyq_lattice_bn_value_at((*s).key[b], (*s).prepared[b], c);
    }
    let e = nyq_blue_block_entry(NYQ_BLUE_LATTICE, (*s).seed, (*s).frame, (*s).pixel, b);
    let key = nyq_lattice_bn_key(e);
    return nyq_lattice_bn_value_at(key, nyq_lattice_bn_rev(e, key, (*s).index), c);
}

fn nyq_lattice_bn_get_1d(s: ptr<function, NyqBlueSampler>) -> f32 {
    let d = (*s).dim;
    (*s).dim = d + 1u;
    return nyq_lattice_bn_value(s, d);
}

fn nyq_lattice_bn_get_2d(s: ptr<function, NyqBlueSampler>) -> vec2<f32> {
    let d = (*s).dim;
    (*s).dim = d + 2u;
    return vec2<f32>(nyq_lattice_bn_value(s, d), nyq_lattice_bn_value(s, d + 1u));
}

fn nyq_lattice_bn_get_pixel_2d(s: ptr<function, NyqBlueSampler>) -> vec2<f32> {
    (*s).dim = max((*s).dim, 2u);
    return vec2<f32>(nyq_lattice_bn_value(s, 0u), nyq_lattice_bn_value(s, 1u));
}

fn nyq_lattice_bn_camera_sample(s: ptr<function, NyqBlueSampler>, pixel: vec2<u32>, sample_index: u32) -> NyqCameraSample {
    nyq_lattice_bn_start(s, pixel, sample_index, 0u);
    var v: array<f32, 5>;
    for (var d = 0u; d < 5u; d++) {
        v[d] = nyq_lattice_bn_value(s, d);
    }
    (*s).dim = 5u;
    return nyq_blue_camera(pixel, v);
}

// ---------------------------------------------------------------------------------------------
// fill: one compute kernel over every sampler and sequence above, for engines to start from and
// for the parity tests that hold each function to the core, bit for bit.
//
// Each invocation takes one request (pixel.x, pixel.y, sample index, dimension) and writes
// eight words: for a pixel sampler, the camera sample of (pixel, sample index) (film x, film y,
// time, lens x, lens y), then after start(pixel, sample index, dimension) one get_1d and one
// get_2d; for a sequence, dimensions dimension .. dimension + 4 of point `sample index` as
// 32-bit fractions, then the same four as the f32 bits of the 4-D form (or of single values
// where a sequence has none). The Halton sequence (kind 19) writes the f32 bits of point
// `sample index` in words 0..3 and, in words 4..7, those of the 64-bit point
// high·2³² + sample index, high = (pixel.x · 0x9e3779b9 + pixel.y) >> (pixel.y mod 32) (mod 2³²):
// indices of every length from 33 to 64 bits, where its long path runs. The lattice sequences
// (kind 20) write the f32 bits of four dimensions in words 0..3 and the f64 bits (low word
// first) of the first two in words 4..7.
//
// With `implicit` set, request i is sample i mod spp of pixel ⌊i / spp⌋ in row-major order
// over `resolution`, at dimension 5 (a whole image's camera samples without a request buffer).

// The kinds of request.
const NYQ_FILL_OWEN_SOBOL_SAMPLER: u32 = 0u;
const NYQ_FILL_ZSOBOL_SAMPLER: u32 = 1u;
const NYQ_FILL_RANDOM_SAMPLER: u32 = 2u;
const NYQ_FILL_LATTICE_SAMPLER: u32 = 3u;
const NYQ_FILL_STRATIFIED_SAMPLER: u32 = 4u;
const NYQ_FILL_PMJ02_SAMPLER: u32 = 5u;
const NYQ_FILL_SOBOL_SAMPLER: u32 = 6u;
const NYQ_FILL_HALTON_SAMPLER: u32 = 7u;
const NYQ_FILL_OWEN_SOBOL_BN_SAMPLER: u32 = 8u;
const NYQ_FILL_PMJ02_BN_SAMPLER: u32 = 9u;
const NYQ_FILL_LATTICE_BN_SAMPLER: u32 = 10u;
const NYQ_FILL_SOBOL: u32 = 16u;
const NYQ_FILL_OWEN_SOBOL: u32 = 17u;
const NYQ_FILL_PMJ02: u32 = 18u;
const NYQ_FILL_HALTON: u32 = 19u;
const NYQ_FILL_LATTICE: u32 = 20u;

struct NyqFillJob {
    kind: u32,
    scramble: u32,
    spp: u32,
    frame: u32,
    seed: vec2<u32>,
    resolution: vec2<u32>,
    dims: u32,
    implicit: u32,
    // The first request of this dispatch and the number of requests.
    first: u32,
    count: u32,
    // The lattice sampler's set and generator.
    lattice: u32,
    generator: u32,
    pad0: u32,
    pad1: u32,
}

@group(0) @binding(1) var<uniform> nyq_job: NyqFillJob;
@group(0) @binding(2) var<storage, read> nyq_requests: array<vec4<u32>>;
@group(0) @binding(3) var<storage, read_write> nyq_values: array<u32>;

// The request of invocation i: read, or implied by the image.
fn nyq_fill_request(i: u32) -> vec4<u32> {
    if nyq_job.implicit == 0u {
        return nyq_requests[i];
    }
    let n = nyq_job.first + i;
    let pixel = n / nyq_job.spp;
    return vec4<u32>(pixel % nyq_job.resolution.x, pixel / nyq_job.resolution.x, n % nyq_job.spp, 5u);
}

fn nyq_fill_camera(out: u32, c: NyqCameraSample) {
    nyq_values[out] = bitcast<u32>(c.p_film.x);
    nyq_values[out + 1u] = bitcast<u32>(c.p_film.y);
    nyq_values[out + 2u] = bitcast<u32>(c.time);
    nyq_values[out + 3u] = bitcast<u32>(c.lens.x);
    nyq_values[out + 4u] = bitcast<u32>(c.lens.y);
}

fn nyq_fill_values(out: u32, one: f32, two: vec2<f32>) {
    nyq_values[out + 5u] = bitcast<u32>(one);
    nyq_values[out + 6u] = bitcast<u32>(two.x);
    nyq_values[out + 7u] = bitcast<u32>(two.y);
}

@compute @workgroup_size(64)
fn nyq_fill(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if i >= nyq_job.count {
        return;
    }
    let q = nyq_fill_request(i);
    let pixel = q.xy;
    let out = 8u * i;
    switch nyq_job.kind {
        case 0u: {
            var s = nyq_owen_sobol_sampler(nyq_job.seed, nyq_job.frame);
            nyq_fill_camera(out, nyq_owen_sobol_camera_sample(&s, pixel, q.z));
            nyq_owen_sobol_start(&s, pixel, q.z, q.w);
            let one = nyq_owen_sobol_get_1d(&s);
            nyq_fill_values(out, one, nyq_owen_sobol_get_2d(&s));
        }
        case 1u: {
            var s = nyq_zsobol_sampler(nyq_job.resolution, nyq_job.spp, nyq_job.scramble, nyq_job.seed);
            nyq_fill_camera(out, nyq_zsobol_camera_sample(&s, pixel, q.z));
            nyq_zsobol_start(&s, pixel, q.z, q.w);
            let one = nyq_zsobol_get_1d(&s);
            nyq_fill_values(out, one, nyq_zsobol_get_2d(&s));
        }
        case 2u: {
            var s = nyq_random_sampler(nyq_job.seed);
            nyq_fill_camera(out, nyq_random_camera_sample(&s, pixel, q.z));
            nyq_random_start(&s, pixel, q.z, q.w);
            let one = nyq_random_get_1d(&s);
            nyq_fill_values(out, one, nyq_random_get_2d(&s));
        }
        case 3u: {
            var s = nyq_lattice_sampler(nyq_job.lattice, nyq_job.spp, nyq_job.generator, nyq_job.seed);
            nyq_fill_camera(out, nyq_lattice_camera_sample(&s, pixel, q.z));
            nyq_lattice_start(&s, pixel, q.z, q.w);
            let one = nyq_lattice_get_1d(&s);
            nyq_fill_values(out, one, nyq_lattice_get_2d(&s));
        }
        case 4u: {
            // resolution: the strata; scramble: the jitter.
            var s = nyq_stratified_sampler(nyq_job.resolution.x, nyq_job.resolution.y, nyq_job.scramble, nyq_job.seed);
            nyq_fill_camera(out, nyq_stratified_camera_sample(&s, pixel, q.z));
            nyq_stratified_start(&s, pixel, q.z, q.w);
            let one = nyq_stratified_get_1d(&s);
            nyq_fill_values(out, one, nyq_stratified_get_2d(&s));
        }
        case 5u: {
            var s = nyq_pmj02_sampler(nyq_job.seed);
            nyq_fill_camera(out, nyq_pmj02_camera_sample(&s, pixel, q.z));
            nyq_pmj02_start(&s, pixel, q.z, q.w);
            let one = nyq_pmj02_get_1d(&s);
            nyq_fill_values(out, one, nyq_pmj02_get_2d(&s));
        }
        case 6u: {
            var s = nyq_sobol_sampler(nyq_job.resolution, nyq_job.spp, nyq_job.scramble, nyq_job.seed);
            nyq_fill_camera(out, nyq_sobol_sampler_camera_sample(&s, pixel, q.z));
            nyq_sobol_sampler_start(&s, pixel, q.z, q.w);
            let one = nyq_sobol_sampler_get_1d(&s);
            nyq_fill_values(out, one, nyq_sobol_sampler_get_2d(&s));
        }
        case 7u: {
            var s = nyq_halton_sampler(nyq_job.resolution, nyq_job.spp, nyq_job.scramble, nyq_job.seed);
            nyq_fill_camera(out, nyq_halton_sampler_camera_sample(&s, pixel, q.z));
            nyq_halton_sampler_start(&s, pixel, q.z, q.w);
            let one = nyq_halton_sampler_get_1d(&s);
            nyq_fill_values(out, one, nyq_halton_sampler_get_2d(&s));
        }
        case 8u: {
            var s = nyq_owen_sobol_bn_sampler(nyq_job.seed, nyq_job.frame);
            nyq_fill_camera(out, nyq_owen_sobol_bn_camera_sample(&s, pixel, q.z));
            nyq_owen_sobol_bn_start(&s, pixel, q.z, q.w);
            let one = nyq_owen_sobol_bn_get_1d(&s);
            nyq_fill_values(out, one, nyq_owen_sobol_bn_get_2d(&s));
        }
        case 9u: {
            var s = nyq_pmj02_bn_sampler(nyq_job.seed, nyq_job.frame);
            nyq_fill_camera(out, nyq_pmj02_bn_camera_sample(&s, pixel, q.z));
            nyq_pmj02_bn_start(&s, pixel, q.z, q.w);
            let one = nyq_pmj02_bn_get_1d(&s);
            nyq_fill_values(out, one, nyq_pmj02_bn_get_2d(&s));
        }
        case 10u: {
            var s = nyq_lattice_bn_sampler(nyq_job.seed, nyq_job.frame);
            nyq_fill_camera(out, nyq_lattice_bn_camera_sample(&s, pixel, q.z));
            nyq_lattice_bn_start(&s, pixel, q.z, q.w);
            let one = nyq_lattice_bn_get_1d(&s);
            nyq_fill_values(out, one, nyq_lattice_bn_get_2d(&s));
        }
        case 16u: {
            let s = nyq_sobol(nyq_job.dims, nyq_job.scramble != 0u, nyq_job.seed);
            for (var k = 0u; k < 4u; k++) {
                nyq_values[out + k] = nyq_sobol_sample_u32(s, q.z, q.w + k);
                nyq_values[out + 4u + k] = bitcast<u32>(nyq_sobol_sample(s, q.z, q.w + k));
            }
        }
        case 17u: {
            let s = nyq_owen_sobol(nyq_job.dims, nyq_job.seed);
            let four = nyq_owen_sobol_sample_4d(s, q.z, q.w);
            for (var k = 0u; k < 4u; k++) {
                nyq_values[out + k] = nyq_owen_sobol_sample_u32(s, q.z, q.w + k);
                nyq_values[out + 4u + k] = bitcast<u32>(four[k]);
            }
        }
        case 18u: {
            let s = nyq_pmj02(nyq_job.scramble != 0u, nyq_job.seed);
            for (var k = 0u; k < 4u; k++) {
                nyq_values[out + k] = nyq_pmj02_sample_u32(s, q.z, q.w + k);
                nyq_values[out + 4u + k] = bitcast<u32>(nyq_pmj02_sample(s, q.z, q.w + k));
            }
        }
        case 19u: {
            let h = nyq_halton(nyq_job.dims, nyq_job.scramble, nyq_job.seed);
            let high = (q.x * 0x9e3779b9u + q.y) >> (q.y & 31u);
            for (var k = 0u; k < 8u; k++) {
                let index = vec2<u32>(q.z, select(0u, high, k >= 4u));
                nyq_values[out + k] = bitcast<u32>(nyq_halton_sample(h, index, q.w + (k & 3u)));
            }
        }
        case 20u: {
            // lattice: the set; spp: its size; generator; dims; scramble: rotated.
            let l = nyq_lattice(nyq_job.lattice, nyq_job.spp, nyq_job.generator, nyq_job.dims, nyq_job.scramble != 0u, nyq_job.seed);
            for (var k = 0u; k < 4u; k++) {
                nyq_values[out + k] = bitcast<u32>(nyq_lattice_sample(l, q.z, q.w + k));
            }
            let lo = nyq_fixed_to_f64_bits(nyq_lattice_fixed(l, q.z, q.w));
            let hi = nyq_fixed_to_f64_bits(nyq_lattice_fixed(l, q.z, q.w + 1u));
            nyq_values[out + 4u] = lo.x;
            nyq_values[out + 5u] = lo.y;
            nyq_values[out + 6u] = hi.x;
            nyq_values[out + 7u] = hi.y;
        }
        default: {
            for (var k = 0u; k < 8u; k++) {
                nyq_values[out + k] = 0xffffffffu;
            }
        }
    }
}
