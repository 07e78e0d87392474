//! The workloads: for each, nyquist's job and each peer's, with the checks that the peers
//! compute what nyquist computes.

// Each peer's entry is pushed under its own `cfg`, so with no peer built a list is created and
// pushed to at once.
#![allow(clippy::vec_init_then_push)]

use crate::check;
use crate::harness::{Entry, Job, Workload};
use nyquist::hash::mix32;
use nyquist::sampler::{HaltonSampler, HaltonScramble, Pmj02Sampler, ZSobolSampler, camera_sample};
use nyquist::scramble::Scramble;
use nyquist::sequence::{OwenSobol, Pmj02, Sequence, Sobol};
use std::hint::black_box;

/// Builds a workload (and runs its checks).
pub type Make = fn() -> Workload<'static>;

/// Every workload by name, in the order of the table.
pub const ALL: &[(&str, Make)] = &[
    ("halton camera sample", halton_camera),
    ("pmj02 camera sample", pmj02_camera),
    ("pmj02 scrambled sample_2d", pmj02_sample_2d),
    ("owen-sobol sample_4d", owen_sobol_4d),
    ("owen-sobol sample", owen_sobol_sample),
    ("sobol by index, coherent", sobol_coherent),
    ("sobol by index, incoherent", sobol_incoherent),
    ("zsobol camera sample", zsobol_camera),
];

/// Camera-sample workloads: 8 × 8 pixels from (100, 50), 16 samples each.
const PIXELS: u32 = 8;
const SPP: u32 = 16;
const ORIGIN: [u32; 2] = [100, 50];
const CAMERA_LEN: usize = (5 * PIXELS * PIXELS * SPP) as usize;

/// The row of a peer that was not built: its snapshot variable was unset.
#[allow(dead_code)]
fn unbuilt(peer: &str, var: &str) -> Entry<'static> {
    Entry::skipped(peer, format!("not built ({var} unset)"))
}

/// A job that runs `fill` into its own buffer of `len` floats and hands the buffer to
/// `black_box`.
fn job(len: usize, mut fill: impl FnMut(&mut [f32]) + 'static) -> Job<'static> {
    let mut out = vec![0.0f32; len];
    Box::new(move || {
        fill(&mut out);
        black_box(&mut out);
    })
}

/// `fill` run once into a fresh buffer, for the checks.
fn once(len: usize, mut fill: impl FnMut(&mut [f32])) -> Vec<f32> {
    let mut out = vec![0.0f32; len];
    fill(&mut out);
    out
}

/// nyquist's camera samples of the 8 × 8 pixels, pixel-major, 5 floats each.
fn camera_fill<S: nyquist::sampler::Sampler>(s: &mut S, out: &mut [f32]) {
    let mut chunks = out.chunks_exact_mut(5);
    for y in ORIGIN[1]..ORIGIN[1] + PIXELS {
        for x in ORIGIN[0]..ORIGIN[0] + PIXELS {
            for i in 0..SPP {
                let c = camera_sample(s, [x, y], black_box(i));
                let o = chunks.next().unwrap();
                o.copy_from_slice(&[c.p_film[0], c.p_film[1], c.time, c.lens[0], c.lens[1]]);
            }
        }
    }
}

fn pmj02_camera() -> Workload<'static> {
    let fill = |out: &mut [f32]| camera_fill(&mut Pmj02Sampler::new(SPP, 1).unwrap(), out);
    let ours = once(CAMERA_LEN, fill);
    check::camera("nyquist", &ours, ORIGIN, PIXELS, SPP, 2).expect("nyquist's own check");
    let mut s = Pmj02Sampler::new(SPP, 1).unwrap();
    let nyquist = job(CAMERA_LEN, move |out| camera_fill(&mut s, out));
    let mut peers = Vec::new();
    #[cfg(peer_openqmc)]
    {
        let cache = crate::openqmc::PmjCache::new();
        let theirs = once(CAMERA_LEN, |out| cache.camera(ORIGIN, PIXELS, SPP, out));
        let ok = check::camera("OpenQMC", &theirs, ORIGIN, PIXELS, SPP, 2);
        peers.push(Entry::checked(
            "OpenQMC `PmjSampler` (2-D + 3-D draw, XOR scramble)",
            ok,
            job(CAMERA_LEN, move |out| {
                cache.camera(ORIGIN, PIXELS, SPP, out)
            }),
        ));
    }
    #[cfg(not(peer_openqmc))]
    peers.push(unbuilt("OpenQMC `PmjSampler`", "NYQUIST_OPENQMC"));
    const PMJ02BN: &str = "pbrt-v4 `PMJ02BNSampler`";
    #[cfg(peer_pbrt_v4_pmj02bn)]
    peers.push(pbrt_v4_camera(PMJ02BN, 2, || {
        crate::pbrt_v4::Sampler::pmj02bn(SPP, 1)
    }));
    #[cfg(all(peer_pbrt_v4, not(peer_pbrt_v4_pmj02bn)))]
    peers.push(Entry::skipped(
        PMJ02BN,
        "not built (the snapshot lacks src/pbrt/util/pmj02tables.cpp or bluenoise.cpp)",
    ));
    #[cfg(not(peer_pbrt_v4))]
    peers.push(unbuilt(PMJ02BN, "NYQUIST_PBRT_V4"));
    Workload {
        name: "`Pmj02Sampler` camera sample, 8 × 8 px × 16 spp".into(),
        elements: (PIXELS * PIXELS * SPP) as u64,
        unit: "sample",
        nyquist,
        peers,
    }
}

const POINTS: u32 = 4096;

/// 4096 incoherent indices into the 2¹⁶-point table.
fn hashed_indices() -> Vec<u32> {
    (0..POINTS)
        .map(|i| mix32(i ^ 0x9e37_79b9) & 0xffff)
        .collect()
}

/// Both dimensions of 4096 points in `[0, 1)`, near ½ on average and, for the first 4096 points
/// by sequential index, stratified in each dimension.
fn pmj_check(what: &str, hashed: &[f32], sequential: &[f32]) -> Result<(), String> {
    check::unit_range(what, hashed)?;
    for d in 0..2 {
        check::mean(what, hashed, d, 2, 0.5, 0.02)?;
        check::stratified(what, sequential, d, 2, POINTS as usize)?;
    }
    Ok(())
}

fn pmj02_sample_2d() -> Workload<'static> {
    let idx = hashed_indices();
    let seq: Vec<u32> = (0..POINTS).collect();
    let p = Pmj02::scrambled(7);
    let fill = move |idx: &[u32], out: &mut [f32]| {
        for (o, &i) in out.chunks_exact_mut(2).zip(idx) {
            o.copy_from_slice(&p.sample_2d(i));
        }
    };
    let len = 2 * POINTS as usize;
    pmj_check(
        "nyquist",
        &once(len, |o| fill(&idx, o)),
        &once(len, |o| fill(&seq, o)),
    )
    .expect("nyquist's own check");
    let mut peers = Vec::new();
    #[cfg(peer_openqmc)]
    {
        let table = crate::openqmc::PmjTable::new();
        let ok = pmj_check(
            "OpenQMC",
            &once(len, |o| table.lookup_2d(7, &idx, o)),
            &once(len, |o| table.lookup_2d(7, &seq, o)),
        );
        let idx = idx.clone();
        peers.push(Entry::checked(
            "OpenQMC lookup core (`shuffledScrambledLookup`, XOR scramble)",
            ok,
            job(len, move |o| table.lookup_2d(7, black_box(&idx), o)),
        ));
    }
    #[cfg(not(peer_openqmc))]
    peers.push(unbuilt("OpenQMC lookup core", "NYQUIST_OPENQMC"));
    Workload {
        name: "PMJ(0,2) Owen-scrambled `sample_2d`, 4096 hashed indices".into(),
        elements: len as u64,
        unit: "value",
        nyquist: job(len, move |o| fill(black_box(&idx), o)),
        peers,
    }
}

const SEED: u32 = 0x5eed;
const DIMS: u32 = 64;
const SOBOL_LEN: usize = (POINTS * DIMS) as usize;

/// 4096 points × 64 dimensions (index-major): each dimension stratified over the 4096 points.
fn sobol_check(what: &str, v: &[f32]) -> Result<(), String> {
    check::unit_range(what, v)?;
    for d in 0..DIMS as usize {
        check::stratified(
            &format!("{what}, dim {d}"),
            v,
            d,
            DIMS as usize,
            POINTS as usize,
        )?;
    }
    Ok(())
}

fn owen_sobol_4d() -> Workload<'static> {
    let ours = OwenSobol::new(DIMS, u64::from(SEED)).unwrap();
    let fill = move |out: &mut [f32]| {
        let mut chunks = out.chunks_exact_mut(4);
        for i in 0..POINTS {
            for set in 0..DIMS / 4 {
                let v = ours.sample_4d(black_box(i), set * 4);
                chunks.next().unwrap().copy_from_slice(&v);
            }
        }
    };
    sobol_check("nyquist", &once(SOBOL_LEN, fill)).expect("nyquist's own check");
    let burley = |out: &mut [f32]| {
        let mut chunks = out.chunks_exact_mut(4);
        for i in 0..POINTS {
            for set in 0..DIMS / 4 {
                let v = sobol_burley::sample_4d(black_box(i), set, SEED);
                chunks.next().unwrap().copy_from_slice(&v);
            }
        }
    };
    let mut peers = vec![Entry::checked(
        "`sobol_burley` 0.5 `sample_4d` (crates.io)",
        sobol_check("sobol_burley", &once(SOBOL_LEN, burley)),
        job(SOBOL_LEN, burley),
    )];
    #[cfg(peer_openqmc)]
    {
        let seeds: Vec<u32> = (0..DIMS / 4)
            .map(|s| mix32(SEED ^ s.wrapping_mul(0x9e37_79b9)))
            .collect();
        let ok = sobol_check(
            "OpenQMC",
            &once(SOBOL_LEN, |o| crate::openqmc::sobol_4d(POINTS, &seeds, o)),
        );
        peers.push(Entry::checked(
            "OpenQMC `shuffledScrambledSobol<4>` (Owen)",
            ok,
            job(SOBOL_LEN, move |o| {
                crate::openqmc::sobol_4d(black_box(POINTS), &seeds, o)
            }),
        ));
    }
    #[cfg(not(peer_openqmc))]
    peers.push(unbuilt(
        "OpenQMC `shuffledScrambledSobol<4>`",
        "NYQUIST_OPENQMC",
    ));
    Workload {
        name: "Owen-Sobol `sample_4d`, 4096 points × 64 dims".into(),
        elements: SOBOL_LEN as u64,
        unit: "value",
        nyquist: job(SOBOL_LEN, fill),
        peers,
    }
}

fn owen_sobol_sample() -> Workload<'static> {
    let ours = OwenSobol::new(DIMS, u64::from(SEED)).unwrap();
    let fill = move |out: &mut [f32]| {
        let mut o = out.iter_mut();
        for i in 0..POINTS {
            for d in 0..DIMS {
                *o.next().unwrap() = ours.sample(u64::from(black_box(i)), d);
            }
        }
    };
    sobol_check("nyquist", &once(SOBOL_LEN, fill)).expect("nyquist's own check");
    let burley = |out: &mut [f32]| {
        let mut o = out.iter_mut();
        for i in 0..POINTS {
            for d in 0..DIMS {
                *o.next().unwrap() = sobol_burley::sample(black_box(i), d, SEED);
            }
        }
    };
    let peers = vec![Entry::checked(
        "`sobol_burley` 0.5 `sample` (crates.io)",
        sobol_check("sobol_burley", &once(SOBOL_LEN, burley)),
        job(SOBOL_LEN, burley),
    )];
    Workload {
        name: "Owen-Sobol `sample`, 4096 points × 64 dims".into(),
        elements: SOBOL_LEN as u64,
        unit: "value",
        nyquist: job(SOBOL_LEN, fill),
        peers,
    }
}

/// A pbrt-v4 sampler's camera-sample entry, checked like nyquist's (`stratified_dims` film
/// dimensions stratified over each pixel's samples).
#[cfg(peer_pbrt_v4)]
fn pbrt_v4_camera(
    peer: &str,
    stratified_dims: usize,
    make: impl Fn() -> crate::pbrt_v4::Sampler,
) -> Entry<'static> {
    let mut s = make();
    let theirs = once(CAMERA_LEN, |out| s.camera(ORIGIN, PIXELS, SPP, out));
    let ok = check::camera(peer, &theirs, ORIGIN, PIXELS, SPP, stratified_dims);
    Entry::checked(
        peer,
        ok,
        job(CAMERA_LEN, move |out| s.camera(ORIGIN, PIXELS, SPP, out)),
    )
}

/// Image resolution of the whole-image samplers (Halton, ZSobol).
const RESOLUTION: u32 = 1024;

/// A camera-sample workload of nyquist's sampler `s`, checked (`stratified_dims` film
/// dimensions stratified over each pixel's samples), beside `peers`.
fn camera_workload<S: nyquist::sampler::Sampler + 'static>(
    name: &str,
    stratified_dims: usize,
    mut s: S,
    peers: Vec<Entry<'static>>,
) -> Workload<'static> {
    let v = once(CAMERA_LEN, |out| camera_fill(&mut s, out));
    check::camera("nyquist", &v, ORIGIN, PIXELS, SPP, stratified_dims)
        .expect("nyquist's own check");
    Workload {
        name: name.into(),
        elements: (PIXELS * PIXELS * SPP) as u64,
        unit: "sample",
        nyquist: job(CAMERA_LEN, move |out| camera_fill(&mut s, out)),
        peers,
    }
}

/// pbrt-v4's `GetPixel2D` returns unscrambled radical inverses and scrambles the other
/// dimensions; nyquist scrambles all five.
fn halton_camera() -> Workload<'static> {
    const PEER: &str = "pbrt-v4 `HaltonSampler` (`PermuteDigits`)";
    #[cfg(peer_pbrt_v4)]
    let peer = pbrt_v4_camera(PEER, 1, || {
        crate::pbrt_v4::Sampler::halton(SPP, RESOLUTION, 1)
    });
    #[cfg(not(peer_pbrt_v4))]
    let peer = unbuilt(PEER, "NYQUIST_PBRT_V4");
    let ours = HaltonSampler::new([RESOLUTION; 2], SPP, HaltonScramble::PermuteDigits, 1);
    camera_workload(
        "`HaltonSampler` (`PermuteDigits`) camera sample, 8 × 8 px × 16 spp, 1024² image",
        1,
        ours.unwrap(),
        vec![peer],
    )
}

fn zsobol_camera() -> Workload<'static> {
    const PEER: &str = "pbrt-v4 `ZSobolSampler` (`FastOwen`)";
    #[cfg(peer_pbrt_v4)]
    let peer = pbrt_v4_camera(PEER, 2, || {
        crate::pbrt_v4::Sampler::zsobol(SPP, RESOLUTION, 1)
    });
    #[cfg(not(peer_pbrt_v4))]
    let peer = unbuilt(PEER, "NYQUIST_PBRT_V4");
    let ours = ZSobolSampler::new([RESOLUTION; 2], SPP, Scramble::FastOwen, 1);
    camera_workload(
        "`ZSobolSampler` (`FastOwen`) camera sample, 8 × 8 px × 16 spp, 1024² image",
        2,
        ours.unwrap(),
        vec![peer],
    )
}

/// Sobol by index, unscrambled, dimensions 0..64 of each index: nyquist's `Sequence::sample`
/// and pbrt-v4's `SobolSample` with `NoRandomizer` compute the same 32-bit values; their
/// conversions to `f32` round differently, so the floats may differ by one unit in the last
/// place (2⁻²⁴ below ½, 2⁻²⁵ … 2⁻²³ above).
fn sobol_by_index(name: &str, index: Vec<u32>) -> Workload<'static> {
    let len = index.len() * DIMS as usize;
    let sobol = Sobol::new(DIMS).unwrap();
    let fill = move |index: &[u32], out: &mut [f32]| {
        let mut o = out.iter_mut();
        for &i in index {
            for d in 0..DIMS {
                *o.next().unwrap() = sobol.sample(u64::from(i), d);
            }
        }
    };
    #[allow(unused_variables)]
    let ours = once(len, |o| fill(&index, o));
    const PEER: &str = "pbrt-v4 `SobolSample` (`NoRandomizer`)";
    #[cfg(peer_pbrt_v4)]
    let peer = {
        let idx = index.clone();
        let theirs = once(len, |o| crate::pbrt_v4::sobol(&idx, DIMS, o));
        Entry::checked(
            PEER,
            check::close(PEER, &ours, &theirs, 1.0 / 8_388_608.0),
            job(len, move |o| {
                crate::pbrt_v4::sobol(black_box(&idx), DIMS, o)
            }),
        )
    };
    #[cfg(not(peer_pbrt_v4))]
    let peer = unbuilt(PEER, "NYQUIST_PBRT_V4");
    Workload {
        name: name.into(),
        elements: len as u64,
        unit: "value",
        nyquist: job(len, move |o| fill(black_box(&index), o)),
        peers: vec![peer],
    }
}

fn sobol_coherent() -> Workload<'static> {
    sobol_by_index(
        "Sobol by index, indices 0..1024 × 64 dims",
        (0..1024).collect(),
    )
}

fn sobol_incoherent() -> Workload<'static> {
    sobol_by_index(
        "Sobol by index, 1024 hashed 32-bit indices × 64 dims",
        (0..1024u32).map(|i| mix32(i ^ 0x2545_f491)).collect(),
    )
}
