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
