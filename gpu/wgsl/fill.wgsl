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
