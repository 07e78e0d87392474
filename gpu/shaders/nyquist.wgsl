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
// (core `Sobol::new`, `Sobol::with_scramble`). Build it with `nyq_sobol`.
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
// by `scramble` (NYQ_SCRAMBLE_*) under `seed`: core `SobolSampler::with_scramble` (the host
// checks 2·⌈log₂ max(resolution)⌉ + log₂ spp ≤ 32). The core's `SobolSampler::new(.., seed)`
// is NYQ_SCRAMBLE_NONE for seed 0 and NYQ_SCRAMBLE_PERMUTE_DIGITS otherwise.
fn nyq_sobol_sampler(resolution: vec2<u32>, spp_requested: u32, scramble: u32, seed_in: vec2<u32>) -> NyqSobolSampler {
    let spp = select(1u << (32u - countLeadingZeros(spp_requested - 1u)), 1u, spp_requested <= 1u);
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
    } else if d < 32u {
        // The core keeps dimensions 2..32's words: the XOR word for digit permutation, else
        // the Owen seed's word (which it also XORs without a scramble: zero only for seed 0's
        // XOR word, not this one).
        if how == NYQ_SCRAMBLE_PERMUTE_DIGITS {
            v ^= select(nyq_hash2(seed, nyq_u64(d)).x, 0u, all(seed == vec2<u32>(0u, 0u)));
        } else {
            v ^= nyq_hash2(seed, nyq_u64(d)).y;
        }
    } else {
        v ^= select(nyq_hash2(seed, nyq_u64(d)).x, 0u, all(seed == vec2<u32>(0u, 0u)));
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
    let spp = select(1u << (32u - countLeadingZeros(spp_requested - 1u)), 1u, spp_requested <= 1u);
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

// A hash's top 24 bits as an f32 in [0, 1): core `unit_f32`.
fn nyq_unit_f32(h: u32) -> f32 {
    return f32(h >> 8u) * (1.0 / 16777216.0);
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

// The generator of dimension `dim` (mod 65536) of the current sample.
fn nyq_random_at(s: ptr<function, NyqRandomSampler>, dim: u32) -> NyqPcg32 {
    var g = nyq_pcg32((*s).base);
    let d = dim & 0xffffu;
    if d != 0u {
        nyq_pcg32_advance(&g, d);
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
    let v = nyq_unit_f32(nyq_pcg32_next(&g));
    (*s).rng = g;
    (*s).dim += 1u;
    if ((*s).dim & 0xffffu) == 0u {
        // Dimensions wrap modulo 65536.
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
    let u = nyq_unit_f32(nyq_pcg32_next(&g));
    let p = vec2<f32>(u, nyq_unit_f32(nyq_pcg32_next(&g)));
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
    return vec2<f32>(nyq_unit_f32(h.y), nyq_unit_f32(h.x));
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
// from, at most 17 WyRand words. With the table's seed the points are the table's, bit for bit.

// The seed the core's baked table was built from ("pmj02_ta").
const NYQ_PMJ02_TABLE_SEED = vec2<u32>(0x325f7461u, 0x706d6a30u);

// WyRand's Weyl increment and its fold constant (Wang Yi's wyhash, final version 4).
const NYQ_WYRAND_INC = vec2<u32>(0x78bd642fu, 0xa0761d64u);
const NYQ_WYRAND_FOLD = vec2<u32>(0xa0b428dbu, 0xe7037ed1u);

// The high 64 bits of the 128-bit product a · b.
fn nyq_mul64_high(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let ll = nyq_mul_wide(a.x, b.x);
    let lh = nyq_mul_wide(a.x, b.y);
    let hl = nyq_mul_wide(a.y, b.x);
    let hh = nyq_mul_wide(a.y, b.y);
    // Bits 32..96 of the sum, column by column with their carries.
    let mid = nyq_add64(nyq_add64(vec2<u32>(ll.y, 0u), vec2<u32>(lh.x, 0u)), vec2<u32>(hl.x, 0u));
    let high = nyq_add64(nyq_add64(hh, vec2<u32>(lh.y, 0u)), nyq_add64(vec2<u32>(hl.y, 0u), vec2<u32>(mid.y, 0u)));
    return high;
}

// Word i of the WyRand stream seeded with `seed`: core `wyrand`.
fn nyq_wyrand(seed: vec2<u32>, i: u32) -> vec2<u32> {
    let s = nyq_add64(seed, nyq_mul64(NYQ_WYRAND_INC, nyq_u64(i + 1u)));
    let t = s ^ NYQ_WYRAND_FOLD;
    return nyq_mul64_high(s, t) ^ nyq_mul64(s, t);
}

// The construction's per-level XOR constants: new point 2^L + i pairs with old point i ^ c[L].
const NYQ_PMJ02_XOR_X = array<u32, 16>(0x0000u, 0x0000u, 0x0002u, 0x0006u, 0x0006u, 0x000eu, 0x0036u, 0x004eu,
                                       0x0016u, 0x002eu, 0x0276u, 0x06ceu, 0x0716u, 0x0c2eu, 0x3076u, 0x40ceu);
const NYQ_PMJ02_XOR_Y = array<u32, 16>(0x0000u, 0x0001u, 0x0003u, 0x0003u, 0x0007u, 0x001bu, 0x0027u, 0x000bu,
                                       0x0017u, 0x013bu, 0x0367u, 0x038bu, 0x0617u, 0x183bu, 0x2067u, 0x008bu);

// Coordinate `dim` (0 or 1) of point `index mod 2¹⁶` of the PMJ(0,2) sequence built from `seed`,
// as a 32-bit fraction.
fn nyq_pmj02_point(seed: vec2<u32>, index: u32, dim: u32) -> u32 {
    var x = 0u;
    var known = 0u;
    var flips = 0u;
    var p = index & 0xffffu;
    while p != 0u {
        let level = 31u - countLeadingZeros(p);
        let swap = 0x80000000u >> level;
        let low = swap - 1u;
        let r = nyq_wyrand(seed, p);
        let bits = select(r.y, r.x, dim == 0u);
        x |= bits & low & ~known;
        known |= low;
        flips ^= swap;
        let c = select(NYQ_PMJ02_XOR_Y[level & 15u], NYQ_PMJ02_XOR_X[level & 15u], dim == 0u);
        p = (p - (1u << level)) ^ c;
    }
    let r0 = nyq_wyrand(seed, 0u);
    x |= select(r0.y, r0.x, dim == 0u) & ~known;
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
// fill: one compute kernel over every sampler and sequence above, for engines to start from and
// for the parity tests that hold each function to the core, bit for bit.
//
// Each invocation takes one request (pixel.x, pixel.y, sample index, dimension) and writes
// eight words: for a pixel sampler, the camera sample of (pixel, sample index) (film x, film y,
// time, lens x, lens y), then after start(pixel, sample index, dimension) one get_1d and one
// get_2d; for a sequence, dimensions dimension .. dimension + 4 of point `sample index` as
// 32-bit fractions, then the same four as the f32 bits of the 4-D form (or of single values
// where a sequence has none).
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
const NYQ_FILL_SOBOL: u32 = 16u;
const NYQ_FILL_OWEN_SOBOL: u32 = 17u;
const NYQ_FILL_PMJ02: u32 = 18u;

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
        default: {
            for (var k = 0u; k < 8u; k++) {
                nyq_values[out + k] = 0xffffffffu;
            }
        }
    }
}
