//! Runs nyquist-gpu's `nyq_fill` kernel through wgpu on whatever adapter the machine has and
//! computes the same requests with the core on the CPU, so that the two can be compared bit
//! for bit.
//!
//! - [`Gpu::new`] takes the first adapter wgpu offers (a real GPU, or Mesa's software Vulkan,
//!   lavapipe, which is what CI has); `NYQUIST_GPU_BACKENDS` (e.g. `vulkan`, `metal`, `dx12`)
//!   narrows the search as wgpu's `WGPU_BACKEND` does.
//! - [`Gpu::pipeline`] builds the kernel from one of the checked-in shaders ([`Source`]): the
//!   WGSL itself, or the emitted SPIR-V or GLSL loaded back through wgpu's front ends.
//! - [`Job`] names a sampler or sequence and its parameters; [`Job::cpu`] is the core's answer
//!   to one request, [`Gpu::run`] the shader's answers to many.

use std::borrow::Cow;

use nyquist::lattice::{FibonacciLattice, Korobov, Kronecker};
use nyquist::sampler::{
    HaltonSampler, Jitter, LatticeBlueSampler, LatticeSampler, OwenSobolBlueSampler,
    OwenSobolSampler, Pmj02BlueSampler, Pmj02Sampler, RandomSampler, Sampler, SobolSampler,
    StratifiedSampler, ZSobolSampler,
};
use nyquist::scramble::Scramble;
use nyquist::sequence::{Halton, OwenSobol, Pmj02, ScrambledHalton, Sequence, Sobol};
use nyquist_gpu::WORDS_PER_REQUEST;

/// A request: `[pixel.x, pixel.y, sample index, dimension]` (for a sequence: the point index in
/// the third word and the first dimension in the fourth).
pub type Request = [u32; 4];

/// The words the kernel writes for one request.
pub type Answer = [u32; WORDS_PER_REQUEST];

/// A checked-in shader the kernel is built from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// `gpu/shaders/nyquist.wgsl`.
    Wgsl,
    /// `gpu/shaders/nyquist.spv`, through wgpu's SPIR-V front end.
    SpirV,
    /// `gpu/shaders/nyquist.comp.glsl`, through wgpu's GLSL front end.
    Glsl,
}

impl Source {
    /// Every source.
    pub const ALL: [Source; 3] = [Source::Wgsl, Source::SpirV, Source::Glsl];

    /// The source's name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Source::Wgsl => "WGSL",
            Source::SpirV => "SPIR-V",
            Source::Glsl => "GLSL",
        }
    }
}

const WGSL_FILE: &str = include_str!("../../shaders/nyquist.wgsl");
const SPIRV_FILE: &[u8] = include_bytes!("../../shaders/nyquist.spv");
const GLSL_FILE: &str = include_str!("../../shaders/nyquist.comp.glsl");

/// A sampler or sequence with its parameters: what one dispatch of the kernel computes.
#[derive(Clone, Debug)]
pub enum Job {
    /// `OwenSobolSampler::new(spp, seed).with_frame(frame)`.
    OwenSobolSampler {
        /// Samples per pixel (reported only; every index is a new point).
        spp: u32,
        /// The seed.
        seed: u64,
        /// The animation frame.
        frame: u32,
    },
    /// `ZSobolSampler::new(resolution, spp, scramble, seed)`.
    ZSobolSampler {
        /// Image size.
        resolution: [u32; 2],
        /// Samples per pixel, rounded up to a power of two.
        spp: u32,
        /// The values' scramble.
        scramble: Scramble,
        /// The seed.
        seed: u64,
    },
    /// `RandomSampler::new(spp, seed)`.
    RandomSampler {
        /// Samples per pixel (reported only).
        spp: u32,
        /// The seed.
        seed: u64,
    },
    /// `LatticeSampler::fibonacci`, `korobov` or `r2` (`set` 0, 1, 2) of `spp` and `seed`.
    LatticeSampler {
        /// 0 Fibonacci, 1 Korobov, 2 R2.
        set: u32,
        /// Samples per pixel asked for.
        spp: u32,
        /// The seed.
        seed: u64,
    },
    /// `StratifiedSampler::new(strata[0], strata[1], jitter, seed)`.
    StratifiedSampler {
        /// Strata along x and y.
        strata: [u32; 2],
        /// Jittered or centred.
        jitter: Jitter,
        /// The seed.
        seed: u64,
    },
    /// `Pmj02Sampler::new(spp, seed)`.
    Pmj02Sampler {
        /// Samples per pixel, at most 2¹⁶.
        spp: u32,
        /// The seed.
        seed: u64,
    },
    /// `Pmj02::new()` or, with a seed, `Pmj02::scrambled(seed)`.
    Pmj02 {
        /// The scramble's seed, if any.
        seed: Option<u64>,
    },
    /// `SobolSampler::new(resolution, spp, scramble, seed)`.
    SobolSampler {
        /// Image size.
        resolution: [u32; 2],
        /// Samples per pixel, rounded up to a power of two.
        spp: u32,
        /// The values' scramble.
        scramble: Scramble,
        /// The seed.
        seed: u64,
    },
    /// A lattice as a sequence: `FibonacciLattice::new(m)` (`lattice` 0, `n` = m),
    /// `Korobov::new(n, generator, dims)` (1) or `Kronecker::new(2)` (2, R2), rotated by the
    /// seed if there is one.
    Lattice {
        /// 0 Fibonacci, 1 Korobov, 2 R2.
        lattice: u32,
        /// Fibonacci: the index m of F_m; Korobov: the point count.
        n: u32,
        /// Korobov: the multiplier.
        generator: u32,
        /// Korobov: the dimension count.
        dims: u32,
        /// The rotation's seed, if any.
        seed: Option<u64>,
    },
    /// `Sobol::new(dims)` or, with a seed, `Sobol::with_digital_shift(dims, seed)`.
    Sobol {
        /// Dimensions, 1..=1024.
        dims: u32,
        /// The digital shift's seed, if any.
        seed: Option<u64>,
    },
    /// `OwenSobol::new(dims, seed)`.
    OwenSobol {
        /// Dimensions, 1..=1024.
        dims: u32,
        /// The seed.
        seed: u64,
    },
    /// `HaltonSampler::new(resolution, spp, scramble, seed)`.
    HaltonSampler {
        /// Image size.
        resolution: [u32; 2],
        /// Samples per pixel (reported only; every index is a new point).
        spp: u32,
        /// The values' scramble.
        scramble: Scramble,
        /// The seed.
        seed: u64,
    },
    /// A screen-space blue-noise sampler: `OwenSobolBlueSampler`, `Pmj02BlueSampler` or
    /// `LatticeBlueSampler` (`family` 0, 1, 2: the order of `nyquist_gpu::BLUE_FAMILIES`)
    /// `::new(spp, seed).with_frame(frame)`.
    BlueNoiseSampler {
        /// 0 owen-sobol-bn, 1 pmj02-bn, 2 lattice-bn.
        family: u32,
        /// Samples per pixel (reported only; every index is a new sample).
        spp: u32,
        /// The seed.
        seed: u64,
        /// The animation frame.
        frame: u32,
    },
    /// `Halton::new(dims)` for `Scramble::None`, else
    /// `ScrambledHalton::with_strategy(dims, scramble, seed)`: point `index` in words 0..3 and
    /// the 64-bit point [`halton_high_index`] in words 4..7.
    Halton {
        /// Dimensions, 1..=1024.
        dims: u32,
        /// The scramble.
        scramble: Scramble,
        /// The seed.
        seed: u64,
    },
}

/// The 64-bit index whose point the Halton sequence job writes in words 4..7 of a request:
/// `high·2³² + index`, `high = (x · 0x9e3779b9 + y) >> (y mod 32)` (wrapping), as fill.wgsl
/// documents.
pub fn halton_high_index(&[x, y, index, _]: &Request) -> u64 {
    let high = x.wrapping_mul(0x9e37_79b9).wrapping_add(y) >> (y & 31);
    u64::from(high) << 32 | u64::from(index)
}

/// The kernel's uniform block (`NyqFillJob` in fill.wgsl), 48 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
struct FillJob {
    kind: u32,
    scramble: u32,
    spp: u32,
    frame: u32,
    seed: [u32; 2],
    resolution: [u32; 2],
    dims: u32,
    implicit: u32,
    first: u32,
    count: u32,
    set: u32,
    generator: u32,
    pad: [u32; 2],
}

fn seed_words(seed: u64) -> [u32; 2] {
    [seed as u32, (seed >> 32) as u32]
}

fn scramble_code(s: Scramble) -> u32 {
    match s {
        Scramble::None => 0,
        Scramble::PermuteDigits => 1,
        Scramble::FastOwen => 2,
        Scramble::Owen => 3,
    }
}

/// The sampler names [`Job::by_name`] knows, in the order the examples print them.
pub const SAMPLER_NAMES: [&str; 13] = [
    "owen-sobol",
    "zsobol",
    "sobol",
    "halton",
    "pmj02",
    "random",
    "stratified",
    "fibonacci",
    "korobov",
    "r2",
    "owen-sobol-bn",
    "pmj02-bn",
    "lattice-bn",
];

impl Job {
    /// The pixel sampler called `name` (one of [`SAMPLER_NAMES`]) for an image of `resolution`
    /// at `spp` under `seed`, with the scramble each defaults to in the CLI (fast Owen for
    /// ZSobol, Sobol and Halton); `None` for another name, or for `stratified` with a `spp`
    /// that is not a square.
    pub fn by_name(name: &str, resolution: [u32; 2], spp: u32, seed: u64) -> Option<Job> {
        Some(match name {
            "owen-sobol" => Job::OwenSobolSampler {
                spp,
                seed,
                frame: 0,
            },
            "zsobol" => Job::ZSobolSampler {
                resolution,
                spp,
                scramble: Scramble::FastOwen,
                seed,
            },
            "sobol" => Job::SobolSampler {
                resolution,
                spp,
                scramble: Scramble::FastOwen,
                seed,
            },
            "halton" => Job::HaltonSampler {
                resolution,
                spp,
                scramble: Scramble::FastOwen,
                seed,
            },
            "pmj02" => Job::Pmj02Sampler { spp, seed },
            "random" => Job::RandomSampler { spp, seed },
            "stratified" => {
                let side = (1..=spp).find(|s| s * s >= spp)?;
                if side * side != spp {
                    return None;
                }
                Job::StratifiedSampler {
                    strata: [side, side],
                    jitter: Jitter::Jittered,
                    seed,
                }
            }
            "fibonacci" => Job::LatticeSampler { set: 0, spp, seed },
            "korobov" => Job::LatticeSampler { set: 1, spp, seed },
            "r2" => Job::LatticeSampler { set: 2, spp, seed },
            _ => Job::BlueNoiseSampler {
                family: nyquist_gpu::BLUE_FAMILIES.iter().position(|&f| f == name)? as u32,
                spp,
                seed,
                frame: 0,
            },
        })
    }

    /// A short name for reports.
    pub fn name(&self) -> String {
        match self {
            Job::OwenSobolSampler { .. } => "owen-sobol sampler".into(),
            Job::BlueNoiseSampler { family, frame, .. } => format!(
                "{} sampler (frame {frame})",
                nyquist_gpu::BLUE_FAMILIES[*family as usize]
            ),
            Job::ZSobolSampler { scramble, .. } => format!("zsobol sampler ({})", scramble.name()),
            Job::RandomSampler { .. } => "random sampler".into(),
            Job::LatticeSampler { set, .. } => {
                format!("{} sampler", ["fibonacci", "korobov", "r2"][*set as usize])
            }
            Job::StratifiedSampler { strata, jitter, .. } => {
                format!(
                    "stratified sampler {}x{} ({jitter:?})",
                    strata[0], strata[1]
                )
            }
            Job::Pmj02Sampler { .. } => "pmj02 sampler".into(),
            Job::Pmj02 { seed: None } => "pmj02".into(),
            Job::Pmj02 { seed: Some(_) } => "pmj02 (owen)".into(),
            Job::SobolSampler { scramble, .. } => format!("sobol sampler ({})", scramble.name()),
            Job::Lattice { lattice, seed, .. } => format!(
                "{} lattice{}",
                ["fibonacci", "korobov", "r2"][*lattice as usize],
                if seed.is_some() { " (rotated)" } else { "" }
            ),
            Job::Sobol { seed: None, .. } => "sobol".into(),
            Job::Sobol { seed: Some(_), .. } => "sobol (digital shift)".into(),
            Job::OwenSobol { .. } => "owen-sobol".into(),
            Job::HaltonSampler {
                resolution,
                scramble,
                ..
            } => format!(
                "halton sampler {}x{} ({})",
                resolution[0],
                resolution[1],
                scramble.name()
            ),
            Job::Halton { dims, scramble, .. } => {
                format!("halton {dims}-d ({})", scramble.name())
            }
        }
    }

    fn uniform(&self) -> FillJob {
        match *self {
            Job::OwenSobolSampler { spp, seed, frame } => FillJob {
                kind: 0,
                spp,
                frame,
                seed: seed_words(seed),
                ..FillJob::default()
            },
            Job::BlueNoiseSampler {
                family,
                spp,
                seed,
                frame,
            } => FillJob {
                kind: 8 + family,
                spp,
                frame,
                seed: seed_words(seed),
                ..FillJob::default()
            },
            Job::ZSobolSampler {
                resolution,
                spp,
                scramble,
                seed,
            } => FillJob {
                kind: 1,
                scramble: scramble_code(scramble),
                spp,
                seed: seed_words(seed),
                resolution,
                ..FillJob::default()
            },
            Job::RandomSampler { spp, seed } => FillJob {
                kind: 2,
                spp,
                seed: seed_words(seed),
                ..FillJob::default()
            },
            Job::LatticeSampler { set, spp, seed } => {
                let s = self.lattice();
                let (n, generator) = match set {
                    0 => {
                        let f = FibonacciLattice::at_least(u64::from(spp.max(2))).expect("valid");
                        (f.point_count_u64() as u32, f.generator() as u32)
                    }
                    1 => (spp, s.korobov_multiplier().expect("korobov") as u32),
                    _ => (spp, 0),
                };
                FillJob {
                    kind: 3,
                    spp: n,
                    seed: seed_words(seed),
                    set,
                    generator,
                    ..FillJob::default()
                }
            }
            Job::StratifiedSampler {
                strata,
                jitter,
                seed,
            } => FillJob {
                kind: 4,
                scramble: u32::from(jitter == Jitter::Centered),
                seed: seed_words(seed),
                resolution: strata,
                ..FillJob::default()
            },
            Job::Pmj02Sampler { spp, seed } => FillJob {
                kind: 5,
                spp,
                seed: seed_words(seed),
                ..FillJob::default()
            },
            Job::Pmj02 { seed } => FillJob {
                kind: 18,
                scramble: u32::from(seed.is_some()),
                seed: seed_words(seed.unwrap_or(0)),
                ..FillJob::default()
            },
            Job::SobolSampler {
                resolution,
                spp,
                scramble,
                seed,
            } => FillJob {
                kind: 6,
                scramble: scramble_code(scramble),
                spp,
                seed: seed_words(seed),
                resolution,
                ..FillJob::default()
            },
            Job::Lattice {
                lattice,
                n,
                generator,
                dims,
                seed,
            } => {
                let (n, generator, dims) = match lattice {
                    0 => {
                        let f = FibonacciLattice::new(n).expect("valid lattice");
                        (f.point_count_u64() as u32, f.generator() as u32, 2)
                    }
                    1 => (n, generator, dims),
                    _ => (1, 0, 2),
                };
                FillJob {
                    kind: 20,
                    scramble: u32::from(seed.is_some()),
                    spp: n,
                    seed: seed_words(seed.unwrap_or(0)),
                    dims,
                    set: lattice,
                    generator,
                    ..FillJob::default()
                }
            }
            Job::Sobol { dims, seed } => FillJob {
                kind: 16,
                scramble: u32::from(seed.is_some()),
                seed: seed_words(seed.unwrap_or(0)),
                dims,
                ..FillJob::default()
            },
            Job::OwenSobol { dims, seed } => FillJob {
                kind: 17,
                seed: seed_words(seed),
                dims,
                ..FillJob::default()
            },
            Job::HaltonSampler {
                resolution,
                spp,
                scramble,
                seed,
            } => FillJob {
                kind: 7,
                scramble: scramble_code(scramble),
                spp,
                seed: seed_words(seed),
                resolution,
                ..FillJob::default()
            },
            Job::Halton {
                dims,
                scramble,
                seed,
            } => FillJob {
                kind: 19,
                scramble: scramble_code(scramble),
                seed: seed_words(seed),
                dims,
                ..FillJob::default()
            },
        }
    }

    /// The core's lattice sampler of a [`Job::LatticeSampler`].
    fn lattice(&self) -> LatticeSampler {
        match *self {
            Job::LatticeSampler { set: 0, spp, seed } => LatticeSampler::fibonacci(spp, seed),
            Job::LatticeSampler { set: 1, spp, seed } => LatticeSampler::korobov(spp, seed),
            Job::LatticeSampler { spp, seed, .. } => LatticeSampler::r2(spp, seed),
            _ => panic!("not a lattice job"),
        }
        .expect("valid sampler")
    }

    /// The core's answers to `requests`, in order (the kernel's layout: see fill.wgsl).
    ///
    /// # Panics
    /// If the job's parameters are ones the core rejects (the caller's defect).
    pub fn cpu(&self, requests: &[Request]) -> Vec<Answer> {
        match *self {
            Job::OwenSobolSampler { spp, seed, frame } => {
                let s = OwenSobolSampler::new(spp, seed)
                    .expect("valid sampler")
                    .with_frame(frame);
                sampler_answers(s, requests)
            }
            Job::BlueNoiseSampler {
                family,
                spp,
                seed,
                frame,
            } => match family {
                0 => sampler_answers(
                    OwenSobolBlueSampler::new(spp, seed)
                        .expect("valid sampler")
                        .with_frame(frame),
                    requests,
                ),
                1 => sampler_answers(
                    Pmj02BlueSampler::new(spp, seed)
                        .expect("valid sampler")
                        .with_frame(frame),
                    requests,
                ),
                _ => sampler_answers(
                    LatticeBlueSampler::new(spp, seed)
                        .expect("valid sampler")
                        .with_frame(frame),
                    requests,
                ),
            },
            Job::ZSobolSampler {
                resolution,
                spp,
                scramble,
                seed,
            } => {
                let s = ZSobolSampler::new(resolution, spp, scramble, seed).expect("valid sampler");
                sampler_answers(s, requests)
            }
            Job::RandomSampler { spp, seed } => sampler_answers(
                RandomSampler::new(spp, seed).expect("valid sampler"),
                requests,
            ),
            Job::LatticeSampler { .. } => sampler_answers(self.lattice(), requests),
            Job::StratifiedSampler {
                strata,
                jitter,
                seed,
            } => sampler_answers(
                StratifiedSampler::new(strata[0], strata[1], jitter, seed).expect("valid sampler"),
                requests,
            ),
            Job::Pmj02Sampler { spp, seed } => sampler_answers(
                Pmj02Sampler::new(spp, seed).expect("valid sampler"),
                requests,
            ),
            Job::Pmj02 { seed } => {
                let s = seed.map_or_else(Pmj02::new, Pmj02::scrambled);
                requests
                    .iter()
                    .map(|&[_, _, index, dim]| {
                        let mut a = [0; WORDS_PER_REQUEST];
                        for k in 0..4 {
                            let d = dim.wrapping_add(k as u32);
                            a[k] = s.sample_u32(index, d);
                            a[4 + k] = s.sample(u64::from(index), d).to_bits();
                        }
                        a
                    })
                    .collect()
            }
            Job::SobolSampler {
                resolution,
                spp,
                scramble,
                seed,
            } => sampler_answers(
                SobolSampler::new(resolution, spp, scramble, seed).expect("valid sampler"),
                requests,
            ),
            Job::Lattice {
                lattice,
                n,
                generator,
                dims,
                seed,
            } => {
                let s: Box<dyn Sequence> = match (lattice, seed) {
                    (0, None) => Box::new(FibonacciLattice::new(n).expect("valid")),
                    (0, Some(s)) => Box::new(FibonacciLattice::new(n).expect("valid").rotated(s)),
                    (1, None) => Box::new(
                        Korobov::new(u64::from(n), u64::from(generator), dims).expect("valid"),
                    ),
                    (1, Some(s)) => Box::new(
                        Korobov::new(u64::from(n), u64::from(generator), dims)
                            .expect("valid")
                            .rotated(s),
                    ),
                    (_, None) => Box::new(Kronecker::new(2).expect("valid")),
                    (_, Some(s)) => Box::new(Kronecker::new(2).expect("valid").rotated(s)),
                };
                requests
                    .iter()
                    .map(|&[_, _, index, dim]| {
                        let i = u64::from(index);
                        let mut a = [0; WORDS_PER_REQUEST];
                        for (k, word) in a[..4].iter_mut().enumerate() {
                            *word = s.sample(i, dim.wrapping_add(k as u32)).to_bits();
                        }
                        for k in 0..2 {
                            let bits = s.sample_f64(i, dim.wrapping_add(k as u32)).to_bits();
                            a[4 + 2 * k] = bits as u32;
                            a[5 + 2 * k] = (bits >> 32) as u32;
                        }
                        a
                    })
                    .collect()
            }
            Job::Sobol { dims, seed } => {
                let s = match seed {
                    None => Sobol::new(dims),
                    Some(seed) => Sobol::with_digital_shift(dims, seed),
                }
                .expect("valid sequence");
                requests
                    .iter()
                    .map(|&[_, _, index, dim]| {
                        let mut a = [0; WORDS_PER_REQUEST];
                        for k in 0..4 {
                            let d = dim.wrapping_add(k as u32);
                            a[k] = s.sample_u32(u64::from(index), d);
                            a[4 + k] = s.sample(u64::from(index), d).to_bits();
                        }
                        a
                    })
                    .collect()
            }
            Job::OwenSobol { dims, seed } => {
                let s = OwenSobol::new(dims, seed).expect("valid sequence");
                requests
                    .iter()
                    .map(|&[_, _, index, dim]| {
                        let mut a = [0; WORDS_PER_REQUEST];
                        let four = s.sample_4d(u64::from(index), dim);
                        for k in 0..4 {
                            a[k] = s.sample_u32(u64::from(index), dim.wrapping_add(k as u32));
                            a[4 + k] = four[k].to_bits();
                        }
                        a
                    })
                    .collect()
            }
            Job::HaltonSampler {
                resolution,
                spp,
                scramble,
                seed,
            } => sampler_answers(
                HaltonSampler::new(resolution, spp, scramble, seed).expect("valid sampler"),
                requests,
            ),
            Job::Halton {
                dims,
                scramble,
                seed,
            } => {
                let plain = Halton::new(dims).expect("valid sequence");
                let scrambled =
                    ScrambledHalton::with_strategy(dims, scramble, seed).expect("valid sequence");
                let sample = |index: u64, dim: u32| {
                    if scramble == Scramble::None {
                        plain.sample(index, dim)
                    } else {
                        scrambled.sample(index, dim)
                    }
                };
                requests
                    .iter()
                    .map(|q| {
                        let (index, dim) = (q[2], q[3]);
                        let high = halton_high_index(q);
                        let mut a = [0; WORDS_PER_REQUEST];
                        for k in 0..4 {
                            let d = dim.wrapping_add(k as u32);
                            a[k] = sample(u64::from(index), d).to_bits();
                            a[4 + k] = sample(high, d).to_bits();
                        }
                        a
                    })
                    .collect()
            }
        }
    }
}

/// A pixel sampler's answers: the camera sample, then `start_pixel_sample(pixel, index, dim)`,
/// one `get_1d` and one `get_2d`.
fn sampler_answers<S: Sampler>(mut s: S, requests: &[Request]) -> Vec<Answer> {
    requests
        .iter()
        .map(|&[x, y, index, dim]| {
            let c = s.camera_sample([x, y], index);
            s.start_pixel_sample([x, y], index, dim);
            let one = s.get_1d();
            let two = s.get_2d();
            [
                c.p_film[0].to_bits(),
                c.p_film[1].to_bits(),
                c.time.to_bits(),
                c.lens[0].to_bits(),
                c.lens[1].to_bits(),
                one.to_bits(),
                two[0].to_bits(),
                two[1].to_bits(),
            ]
        })
        .collect()
}

/// A device, its queue and the tables (the Sobol matrices, the Halton bases, the blue-noise
/// tiles) uploaded once.
#[derive(Debug)]
pub struct Gpu {
    device: wgpu::Device,
    queue: wgpu::Queue,
    info: wgpu::AdapterInfo,
    matrices: wgpu::Buffer,
    halton_bases: wgpu::Buffer,
    blue_tiles: wgpu::Buffer,
}

/// The kernel built from one [`Source`].
#[derive(Debug)]
pub struct Pipeline {
    pipeline: wgpu::ComputePipeline,
    source: Source,
}

impl Pipeline {
    /// The source it was built from.
    pub fn source(&self) -> Source {
        self.source
    }
}

/// Requests per dispatch: 2¹⁶ (1024 workgroups of 64).
pub const CHUNK: usize = 1 << 16;

impl Gpu {
    /// The first adapter wgpu finds (software ones included), or why there is none.
    ///
    /// # Errors
    /// A sentence saying what failed: no adapter, or the device request.
    pub fn new() -> Result<Gpu, String> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
        if let Ok(names) = std::env::var("NYQUIST_GPU_BACKENDS") {
            desc.backends = wgpu::Backends::from_comma_list(&names);
        }
        let instance = wgpu::Instance::new(desc);
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            force_fallback_adapter: false,
            compatible_surface: None,
            apply_limit_buckets: false,
        }))
        .map_err(|e| format!("no GPU adapter: {e}"))?;
        let info = adapter.get_info();
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("nyquist parity"),
            required_features: wgpu::Features::empty(),
            // nyq_fill reads five storage buffers (the three tables, the requests and the
            // values): one more than the downlevel defaults' four, within WebGPU's default 8.
            required_limits: wgpu::Limits {
                max_storage_buffers_per_shader_stage: 5,
                ..wgpu::Limits::downlevel_defaults()
            },
            ..Default::default()
        }))
        .map_err(|e| format!("adapter {} refused a device: {e}", info.name))?;
        let table = |label: &str, words: &[u32]| {
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: (words.len() * 4) as u64,
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            queue.write_buffer(&buffer, 0, bytemuck::cast_slice(words));
            buffer
        };
        let matrices = table("nyq_sobol_matrices", &nyquist_gpu::sobol_matrices());
        let halton_bases = table("nyq_halton_bases", &nyquist_gpu::halton_bases());
        let blue_tiles = table("nyq_blue_tiles", &nyquist_gpu::blue_tiles());
        Ok(Gpu {
            device,
            queue,
            info,
            matrices,
            halton_bases,
            blue_tiles,
        })
    }

    /// The adapter: name, backend and device type, for reports.
    pub fn adapter(&self) -> String {
        format!(
            "{} ({:?}, {:?}, driver {} {})",
            self.info.name,
            self.info.backend,
            self.info.device_type,
            self.info.driver,
            self.info.driver_info
        )
    }

    /// Whether the adapter is a CPU (a software rasteriser such as lavapipe): its figures are
    /// CPU figures.
    pub fn is_cpu(&self) -> bool {
        self.info.device_type == wgpu::DeviceType::Cpu
    }

    /// The kernel from `source`.
    ///
    /// # Errors
    /// The front end's or the driver's message, if the shader does not build.
    pub fn pipeline(&self, source: Source) -> Result<Pipeline, String> {
        let shader = match source {
            Source::Wgsl => wgpu::ShaderSource::Wgsl(Cow::Borrowed(WGSL_FILE)),
            Source::SpirV => {
                let words: Vec<u32> = SPIRV_FILE
                    .chunks_exact(4)
                    .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]))
                    .collect();
                wgpu::ShaderSource::SpirV(Cow::Owned(words))
            }
            Source::Glsl => wgpu::ShaderSource::Glsl {
                shader: Cow::Borrowed(GLSL_FILE),
                stage: wgpu::naga::ShaderStage::Compute,
                defines: &[],
            },
        };
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = self
            .device
            .create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(source.name()),
                source: shader,
            });
        let pipeline = self
            .device
            .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(source.name()),
                layout: None,
                module: &module,
                // GLSL has one entry point, `main`.
                entry_point: Some(match source {
                    Source::Glsl => "main",
                    _ => nyquist_gpu::ENTRY_POINT,
                }),
                compilation_options: Default::default(),
                cache: None,
            });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(format!("{}: {e}", source.name()));
        }
        Ok(Pipeline { pipeline, source })
    }

    /// The kernel's answers to `requests` for `job`, one dispatch per [`CHUNK`] requests.
    pub fn run(&self, pipeline: &Pipeline, job: &Job, requests: &[Request]) -> Vec<Answer> {
        let mut out = Vec::with_capacity(requests.len());
        for chunk in requests.chunks(CHUNK) {
            let mut uniform = job.uniform();
            uniform.count = chunk.len() as u32;
            let words = self.dispatch(pipeline, uniform, bytemuck::cast_slice(chunk));
            out.extend(
                words
                    .chunks_exact(WORDS_PER_REQUEST)
                    .map(|w| <Answer>::try_from(w).expect("whole answers")),
            );
        }
        out
    }

    /// The camera samples of a whole image (`implicit` requests: sample `i mod spp` of pixel
    /// `⌊i / spp⌋`, row-major, dimension 5), `count` requests from request `first`.
    pub fn run_image(
        &self,
        pipeline: &Pipeline,
        job: &Job,
        resolution: [u32; 2],
        spp: u32,
        first: u32,
        count: u32,
    ) -> Vec<Answer> {
        let mut uniform = job.uniform();
        uniform.resolution = resolution;
        uniform.spp = spp;
        uniform.implicit = 1;
        uniform.first = first;
        uniform.count = count;
        // The request buffer is bound but not read: one dummy request.
        let words = self.dispatch(pipeline, uniform, &[0u32; 4]);
        words
            .chunks_exact(WORDS_PER_REQUEST)
            .map(|w| <Answer>::try_from(w).expect("whole answers"))
            .collect()
    }

    /// Seconds per dispatch of `count` image requests (as [`Gpu::run_image`], from request 0),
    /// the median of `repeats` dispatches each timed from submission to completion, after one
    /// untimed warm-up; no read-back, so the figure is the kernel's.
    pub fn time_image(
        &self,
        pipeline: &Pipeline,
        job: &Job,
        resolution: [u32; 2],
        spp: u32,
        count: u32,
        repeats: usize,
    ) -> f64 {
        let mut uniform = job.uniform();
        uniform.resolution = resolution;
        uniform.spp = spp;
        uniform.implicit = 1;
        uniform.count = count;
        let (bind, _values) = self.bind(pipeline, uniform, &[0u32; 4], wgpu::BufferUsages::empty());
        let once = || {
            let encoder = self.encode(pipeline, &bind, count);
            let t = std::time::Instant::now();
            self.queue.submit([encoder.finish()]);
            self.device
                .poll(wgpu::PollType::wait_indefinitely())
                .expect("the device finished");
            t.elapsed().as_secs_f64()
        };
        once();
        let mut times: Vec<f64> = (0..repeats.max(1)).map(|_| once()).collect();
        times.sort_by(f64::total_cmp);
        times[times.len() / 2]
    }

    /// The kernel's bind group for `uniform` and `requests` (the tables bound once in
    /// [`Gpu::new`]), and its values buffer (`uniform.count` answers; `usage` added to
    /// `STORAGE`).
    fn bind(
        &self,
        pipeline: &Pipeline,
        uniform: FillJob,
        requests: &[u32],
        usage: wgpu::BufferUsages,
    ) -> (wgpu::BindGroup, wgpu::Buffer) {
        use wgpu::util::DeviceExt;
        let job = self
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("job"),
                contents: bytemuck::bytes_of(&uniform),
                usage: wgpu::BufferUsages::UNIFORM,
            });
        let reqs = self
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("requests"),
                contents: bytemuck::cast_slice(requests),
                usage: wgpu::BufferUsages::STORAGE,
            });
        let values = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("values"),
            size: (uniform.count.max(1) as usize * WORDS_PER_REQUEST * 4) as u64,
            usage: wgpu::BufferUsages::STORAGE | usage,
            mapped_at_creation: false,
        });
        let entries = [
            (0, &self.matrices),
            (1, &job),
            (2, &reqs),
            (3, &values),
            (4, &self.halton_bases),
            (5, &self.blue_tiles),
        ]
        .map(|(binding, buffer)| wgpu::BindGroupEntry {
            binding,
            resource: buffer.as_entire_binding(),
        });
        let bind = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("nyq_fill"),
            layout: &pipeline.pipeline.get_bind_group_layout(0),
            entries: &entries,
        });
        (bind, values)
    }

    /// A command encoder holding one dispatch of the kernel over `count` requests.
    fn encode(
        &self,
        pipeline: &Pipeline,
        bind: &wgpu::BindGroup,
        count: u32,
    ) -> wgpu::CommandEncoder {
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
            pass.set_pipeline(&pipeline.pipeline);
            pass.set_bind_group(0, bind, &[]);
            pass.dispatch_workgroups(count.div_ceil(nyquist_gpu::WORKGROUP_SIZE), 1, 1);
        }
        encoder
    }

    /// One dispatch of `uniform.count` requests; returns the values buffer.
    fn dispatch(&self, pipeline: &Pipeline, uniform: FillJob, requests: &[u32]) -> Vec<u32> {
        let count = uniform.count as usize;
        let (bind, values) = self.bind(pipeline, uniform, requests, wgpu::BufferUsages::COPY_SRC);
        let size = values.size();
        let readback = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut encoder = self.encode(pipeline, &bind, count as u32);
        encoder.copy_buffer_to_buffer(&values, 0, &readback, 0, size);
        self.queue.submit([encoder.finish()]);
        readback.map_async(wgpu::MapMode::Read, .., |r| r.expect("map the values"));
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .expect("the device finished");
        let view = readback.get_mapped_range(..).expect("mapped");
        let words: Vec<u32> = bytemuck::cast_slice(&view)[..count * WORDS_PER_REQUEST].to_vec();
        drop(view);
        readback.unmap();
        words
    }
}

/// `n` random requests from `seed`: pixels mostly below 4096 and some up to 2²⁴ − 1, sample
/// indices over all of `u32` (a quarter below 256), dimensions up to 2047 (past the 1024
/// matrices).
pub fn random_requests(n: usize, seed: u64) -> Vec<Request> {
    let word = |i: u64| nyquist::hash::wyrand(seed, i);
    (0..n as u64)
        .map(|i| {
            let a = word(2 * i);
            let b = word(2 * i + 1);
            let big = a >> 63 == 1 && a >> 62 & 1 == 1;
            let pixel_mask = if big { (1 << 24) - 1 } else { 4095 };
            let index = if b >> 62 == 0 {
                (b as u32) & 255
            } else {
                b as u32
            };
            [
                a as u32 & pixel_mask,
                (a >> 32) as u32 & pixel_mask,
                index,
                ((b >> 32) as u32) & 2047,
            ]
        })
        .collect()
}

/// Limits `requests` to where the shaders follow the core: for the samplers the core made
/// progressive and padded (`docs/gpu.md`), sample indices below the spp the job was made for
/// (PMJ(0,2): below 2¹⁶, its table) and dimensions below 1000 (a request reads a few past its
/// first, all below the 1024 where the core's padding starts). The shaders still wrap past
/// those; the sequences are unchanged.
pub fn restrict_to_the_shaders_domain(job: &Job, requests: &mut [Request]) {
    let spp = match *job {
        Job::ZSobolSampler { spp, .. } => Some(spp.next_power_of_two()),
        Job::SobolSampler { spp, .. } => Some(spp.next_power_of_two()),
        Job::Pmj02Sampler { .. } => Some(1 << 16),
        _ => None,
    };
    let padded = matches!(
        job,
        Job::SobolSampler { .. } | Job::OwenSobolSampler { .. } | Job::HaltonSampler { .. }
    );
    for q in requests {
        if let Some(spp) = spp {
            q[2] %= spp;
        }
        if padded {
            q[3] %= 1000;
        }
    }
}

/// Requests at the blue-noise samplers' edges: pixels at the tile's seams (127, 128, 255,
/// 256) and next to `u32::MAX`, where `pixel + offset` wraps; sample indices at the rank's
/// reach (255, 256), at the PMJ(0,2) epochs' seams (65535, 65536, 131072) and next to
/// `u32::MAX`; dimensions in blocks 0 to 3 and far past them (up to `u32::MAX`).
pub fn blue_edge_requests() -> Vec<Request> {
    let mut out = Vec::new();
    let pixels = [
        [0, 0],
        [127, 128],
        [255, 256],
        [1 << 24, 3],
        [u32::MAX, u32::MAX],
        [u32::MAX - 100, 7],
    ];
    for [x, y] in pixels {
        for index in [0, 1, 255, 256, 65_535, 65_536, 131_072, 1 << 31, u32::MAX] {
            for dim in [0, 1, 3, 4, 6, 7, 8, 11, 12, 13, 1000, u32::MAX - 3] {
                out.push([x, y, index, dim]);
            }
        }
    }
    out
}

/// `requests` with a third of them (every third) moved to pixels anywhere in `u32` and sample
/// indices anywhere (the blue-noise samplers take any `u32` pixel: their film coordinates are
/// rounded from the bits).
pub fn spread_requests(requests: &mut [Request], seed: u64) {
    for (i, q) in requests.iter_mut().enumerate().step_by(3) {
        let w = nyquist::hash::wyrand(seed ^ 0x626c_7565, i as u64);
        q[0] = w as u32;
        q[1] = (w >> 32) as u32;
    }
}

/// The first request whose answers differ, with both answers.
pub fn first_mismatch(
    requests: &[Request],
    gpu: &[Answer],
    cpu: &[Answer],
) -> Option<(Request, Answer, Answer)> {
    requests
        .iter()
        .zip(gpu.iter().zip(cpu))
        .find(|(_, (g, c))| g != c)
        .map(|(&q, (&g, &c))| (q, g, c))
}
