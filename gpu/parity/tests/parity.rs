//! Every sampler and sequence of the shaders, from each checked-in source (the WGSL, and the
//! emitted SPIR-V and GLSL through wgpu's front ends), against the core, bit for bit: 2¹⁷
//! random requests (2²⁰ values) for the first job of each sampler and sequence, 2¹⁴ for each
//! further job of it (other scrambles, image shapes, seeds), fewer per Halton job but 2²⁰
//! values or more per Halton sampler and sequence ([`halton_jobs`]); the blue-noise samplers'
//! requests also take pixels anywhere in `u32` and edge cases ([`blue_edge_requests`]). Where no adapter can be had the test says
//! so and passes (`.ci/run` prints `SKIPPED` before it gets here). `NYQUIST_PARITY_JOBS=halton`
//! runs only the jobs whose name contains the string.

use nyquist::sampler::Jitter;
use nyquist::scramble::Scramble;
use nyquist_gpu_parity::{
    Gpu, Job, Request, Source, blue_edge_requests, first_mismatch, random_requests,
    restrict_to_the_shaders_domain, spread_requests,
};

fn jobs() -> Vec<Job> {
    let mut jobs = vec![
        Job::OwenSobolSampler {
            spp: 16,
            seed: 7,
            frame: 0,
        },
        Job::OwenSobolSampler {
            spp: 1024,
            seed: 0xdead_beef_0123_4567,
            frame: 12,
        },
        Job::RandomSampler { spp: 4, seed: 5 },
        Job::RandomSampler {
            spp: 1,
            seed: u64::MAX - 2,
        },
        Job::LatticeSampler {
            set: 0,
            spp: 16,
            seed: 1,
        },
        Job::LatticeSampler {
            set: 0,
            spp: 1 << 30,
            seed: 2,
        },
        Job::LatticeSampler {
            set: 1,
            spp: 100,
            seed: 3,
        },
        Job::LatticeSampler {
            set: 1,
            spp: 1,
            seed: 4,
        },
        Job::LatticeSampler {
            set: 2,
            spp: 64,
            seed: 5,
        },
        Job::Pmj02Sampler { spp: 16, seed: 12 },
        Job::Pmj02Sampler {
            spp: 65536,
            seed: u64::MAX,
        },
        Job::Pmj02 { seed: None },
        Job::Pmj02 { seed: Some(13) },
        Job::Sobol {
            dims: 1024,
            seed: None,
        },
        Job::Lattice {
            lattice: 0,
            n: 20,
            generator: 0,
            dims: 2,
            seed: None,
        },
        Job::Lattice {
            lattice: 0,
            n: 47,
            generator: 0,
            dims: 2,
            seed: Some(31),
        },
        Job::Lattice {
            lattice: 1,
            n: 1021,
            generator: 76,
            dims: 16,
            seed: Some(32),
        },
        Job::Lattice {
            lattice: 1,
            n: 4_000_000_007,
            generator: 1_234_567_891,
            dims: 1000,
            seed: None,
        },
        Job::Lattice {
            lattice: 2,
            n: 0,
            generator: 0,
            dims: 2,
            seed: None,
        },
        Job::Lattice {
            lattice: 2,
            n: 0,
            generator: 0,
            dims: 2,
            seed: Some(33),
        },
        Job::StratifiedSampler {
            strata: [4, 4],
            jitter: Jitter::Jittered,
            seed: 6,
        },
        Job::StratifiedSampler {
            strata: [3, 1],
            jitter: Jitter::Jittered,
            seed: 7,
        },
        Job::StratifiedSampler {
            strata: [1, 2],
            jitter: Jitter::Centered,
            seed: 8,
        },
        Job::StratifiedSampler {
            strata: [7, 5],
            jitter: Jitter::Jittered,
            seed: 9,
        },
        Job::StratifiedSampler {
            strata: [100_003, 40_000],
            jitter: Jitter::Centered,
            seed: 10,
        },
        Job::StratifiedSampler {
            strata: [65_537, 65_535],
            jitter: Jitter::Jittered,
            seed: 11,
        },
        Job::Sobol {
            dims: 37,
            seed: Some(0x1234_5678_9abc_def0),
        },
        Job::OwenSobol {
            dims: 1024,
            seed: 0,
        },
        Job::OwenSobol {
            dims: 5,
            seed: u64::MAX,
        },
    ];
    for (k, scramble) in Scramble::ALL.into_iter().enumerate() {
        jobs.push(Job::ZSobolSampler {
            resolution: [1920, 1080],
            spp: 16,
            scramble,
            seed: 3 + k as u64,
        });
    }
    for (k, scramble) in Scramble::ALL.into_iter().enumerate() {
        jobs.push(Job::SobolSampler {
            resolution: [1280, 720],
            spp: 16,
            scramble,
            seed: 20 + k as u64,
        });
    }
    // The seed-0 sampler `SobolSampler::new` builds, a one-pixel image, 32 index bits, odd m.
    jobs.push(Job::SobolSampler {
        resolution: [640, 480],
        spp: 8,
        scramble: Scramble::None,
        seed: 0,
    });
    jobs.push(Job::SobolSampler {
        resolution: [1, 1],
        spp: 2,
        scramble: Scramble::PermuteDigits,
        seed: 24,
    });
    jobs.push(Job::SobolSampler {
        resolution: [65536, 3],
        spp: 1,
        scramble: Scramble::Owen,
        seed: 25,
    });
    jobs.push(Job::SobolSampler {
        resolution: [100, 37],
        spp: 64,
        scramble: Scramble::FastOwen,
        seed: 26,
    });
    // Odd log2 spp (a last base-2 digit), a one-pixel image, and the 32-bit edge.
    jobs.push(Job::ZSobolSampler {
        resolution: [64, 64],
        spp: 8,
        scramble: Scramble::FastOwen,
        seed: 11,
    });
    jobs.push(Job::ZSobolSampler {
        resolution: [1, 1],
        spp: 1,
        scramble: Scramble::Owen,
        seed: 12,
    });
    jobs.push(Job::ZSobolSampler {
        resolution: [4096, 2160],
        spp: 256,
        scramble: Scramble::PermuteDigits,
        seed: 13,
    });
    // The blue-noise samplers: frame 0 and later frames (R2 offsets wrapping), seeds 0 and
    // next to u64::MAX; every family's first job gets 2^17 requests.
    for family in [0u32, 1, 2] {
        for (spp, seed, frame) in [
            (16, 7, 0),
            (1, u64::MAX - 1, 1),
            (64, 0, 12_345),
            (4, 0x0123_4567_89ab_cdef, u32::MAX),
        ] {
            jobs.push(Job::BlueNoiseSampler {
                family,
                spp,
                seed,
                frame,
            });
        }
    }
    jobs
}

/// The Halton jobs and their request counts: 2¹⁵ requests (2¹⁸ values) for the sampler under
/// each scramble and for the sequence under each, 2¹³ for the sampler's other shapes, so each
/// has 2²⁰ values or more in all, at a quarter of the time 2¹⁷ per job would take.
fn halton_jobs() -> Vec<(Job, usize)> {
    let mut jobs = Vec::new();
    // Indices up to 2³²·31104 (every sample index of a u32): short and long paths, dimensions
    // past 1024.
    for (k, scramble) in Scramble::ALL.into_iter().enumerate() {
        jobs.push((
            Job::HaltonSampler {
                resolution: [1920, 1080],
                spp: 16,
                scramble,
                seed: 30 + k as u64,
            },
            1 << 15,
        ));
    }
    // 4K and 8K, a one-pixel image (stride 1), a 2 × 3 image, odd sizes.
    let shapes = [
        ([3840, 2160], 64, Scramble::Owen, 34),
        ([7680, 4320], 1024, Scramble::None, 0),
        ([1, 1], 1, Scramble::PermuteDigits, u64::MAX),
        ([2, 3], 4, Scramble::None, 0),
        ([100, 37], 8, Scramble::FastOwen, 35),
    ];
    for (resolution, spp, scramble, seed) in shapes {
        jobs.push((
            Job::HaltonSampler {
                resolution,
                spp,
                scramble,
                seed,
            },
            1 << 13,
        ));
    }
    // The sequence: words 0..3 at 32-bit indices, 4..7 at 64-bit ones of every length.
    for (k, scramble) in Scramble::ALL.into_iter().enumerate() {
        jobs.push((
            Job::Halton {
                dims: if k == 2 { 37 } else { 1024 },
                scramble,
                seed: 0x5eed_0000_0000_0000 + k as u64,
            },
            1 << 15,
        ));
    }
    jobs
}

/// Requests at the Halton code's edges, appended to each Halton job's random ones. For the
/// sequence: for dimensions of every kind of base (2, 3, the chunked bases up to 83, one-digit
/// chunks, the last prime, past 1024), indices 0, 1, bʲ − 1 and bʲ up to 2³² − 1 (the short
/// path's classes and its limit b^k) with high words 0, 1 and 2³² − 1 (`halton_high_index`: the
/// long path's shortest and longest indices), and indices where the short path's two roundings
/// differ from one. For the sampler: the image's first and last pixels, sample indices 0, 1 and
/// 2³² − 1.
fn halton_edge_requests(job: &Job) -> Vec<Request> {
    let mut out = Vec::new();
    if let Job::HaltonSampler { .. } = job {
        for (x, y) in [
            (0, 0),
            (1, 2),
            (127, 242),
            (128, 243),
            ((1 << 24) - 1, (1 << 24) - 1),
        ] {
            for index in [0, 1, 2, 15, 16, u32::MAX - 1, u32::MAX] {
                for dim in [0, 1, 2, 1021, 1022, 1023, 1024, 2047] {
                    out.push([x, y, index, dim]);
                }
            }
        }
        return out;
    }
    // The inverse of the high word's multiplier modulo 2³², so y = 0 picks any high word.
    let phi = 0x9e37_79b9u32;
    let mut inv = phi;
    for _ in 0..5 {
        inv = inv.wrapping_mul(2u32.wrapping_sub(phi.wrapping_mul(inv)));
    }
    // Short-path indices whose product rev·inv, rounded to 53 bits, lands on a midpoint of 24
    // bits: rounded once it would give another float (found by enumerating a fraction of each
    // class with the exact product in u128).
    for (dim, index) in [
        (3, 946_924_512),
        (3, 1_583_193_480),
        (3, 1_892_926_704),
        (7, 60_548_006),
        (7, 120_959_212),
        (7, 192_533_624),
        (8, 3_329_654_896),
    ] {
        out.push([0, 0, index, dim]);
    }
    for dim in [0, 1, 2, 3, 4, 10, 17, 18, 22, 23, 100, 1023, 1024, 1025] {
        let b = u64::from(nyquist::radical::prime(dim));
        let mut indices = vec![0u32, 1, u32::MAX];
        let mut p = b;
        while p < 1 << 32 {
            indices.extend([(p - 1) as u32, p as u32]);
            p *= b;
        }
        for index in indices {
            for high in [0u32, 1, u32::MAX] {
                out.push([high.wrapping_mul(inv), 0, index, dim]);
            }
        }
    }
    out
}

#[test]
fn every_job_matches_the_core_from_every_source() {
    let gpu = match Gpu::new() {
        Ok(gpu) => gpu,
        Err(why) => {
            println!("SKIPPED: {why}");
            return;
        }
    };
    println!("adapter: {}", gpu.adapter());
    let n = 1 << 17;
    let pipelines: Vec<_> = Source::ALL
        .into_iter()
        .map(|source| {
            let t = std::time::Instant::now();
            let pipeline = gpu.pipeline(source).unwrap();
            println!(
                "{} pipeline built in {:.2} s",
                source.name(),
                t.elapsed().as_secs_f64()
            );
            pipeline
        })
        .collect();
    let mut failures = Vec::new();
    let only = std::env::var("NYQUIST_PARITY_JOBS").unwrap_or_default();
    // The first job of each sampler or sequence takes 2^17 requests (2^20 values); the others
    // of the same one (other scrambles, shapes, seeds) 2^14 each, on top.
    let mut seen = Vec::new();
    let sized = jobs().into_iter().map(|job| {
        let family = match &job {
            Job::LatticeSampler { set, .. } => format!("lattice sampler {set}"),
            Job::Lattice { lattice, .. } => format!("lattice {lattice}"),
            Job::BlueNoiseSampler { family, .. } => format!("blue-noise sampler {family}"),
            other => format!("{:?}", std::mem::discriminant(other)),
        };
        let count = if seen.contains(&family) { n >> 3 } else { n };
        seen.push(family);
        (job, count)
    });
    let all = sized.chain(halton_jobs());
    for (j, (job, count)) in all.enumerate() {
        if !job.name().contains(&only) {
            continue;
        }
        let mut requests = random_requests(count, j as u64);
        if let Job::HaltonSampler { .. } | Job::Halton { .. } = job {
            requests.extend(halton_edge_requests(&job));
        }
        if let Job::BlueNoiseSampler { .. } = job {
            spread_requests(&mut requests, j as u64);
            requests.extend(blue_edge_requests());
        }
        restrict_to_the_shaders_domain(&job, &mut requests);
        let t = std::time::Instant::now();
        let want = job.cpu(&requests);
        let cpu_seconds = t.elapsed().as_secs_f64();
        for pipeline in &pipelines {
            let t = std::time::Instant::now();
            let have = gpu.run(pipeline, &job, &requests);
            let values = have.len() * have[0].len();
            let source = pipeline.source().name();
            match first_mismatch(&requests, &have, &want) {
                None => println!(
                    "{source} {}: {values} values equal (gpu {:.2} s, cpu {cpu_seconds:.2} s)",
                    job.name(),
                    t.elapsed().as_secs_f64()
                ),
                Some((q, g, c)) => failures.push(format!(
                    "{source} {}: request {q:?}: gpu {g:08x?} cpu {c:08x?}",
                    job.name()
                )),
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
