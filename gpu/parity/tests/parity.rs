//! Every sampler and sequence of the shaders, from each checked-in source (the WGSL, and the
//! emitted SPIR-V and GLSL through wgpu's front ends), against the core, bit for bit: 2¹⁷
//! random requests (2²⁰ values) per job and source. Where no adapter can be had the test says
//! so and passes (`.ci/run` prints `SKIPPED` before it gets here).

use nyquist::sampler::Jitter;
use nyquist::scramble::Scramble;
use nyquist_gpu_parity::{Gpu, Job, Source, first_mismatch, random_requests};

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
    jobs
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
        .map(|source| gpu.pipeline(source).unwrap())
        .collect();
    let mut failures = Vec::new();
    for (j, job) in jobs().iter().enumerate() {
        let requests = random_requests(n, j as u64);
        let t = std::time::Instant::now();
        let want = job.cpu(&requests);
        let cpu_seconds = t.elapsed().as_secs_f64();
        for pipeline in &pipelines {
            let t = std::time::Instant::now();
            let have = gpu.run(pipeline, job, &requests);
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
