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
