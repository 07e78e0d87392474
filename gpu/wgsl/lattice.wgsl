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
