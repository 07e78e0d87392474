//! The workloads: for each, nyquist's job and each peer's, with the checks that the peers
//! compute what nyquist computes.

// Each peer's entry is pushed under its own `cfg`, so with no peer built a list is created and
// pushed to at once.
#![allow(clippy::vec_init_then_push)]

use crate::check;
use crate::harness::{Entry, Job, Workload};
use nyquist::filter::{Boxcar, Filter, FilterTable, Interpolation, Lanczos, Mitchell};
use nyquist::hash::mix32;
use nyquist::radical::radical_inverse;
use nyquist::sampler::{HaltonSampler, Pmj02Sampler, ZSobolSampler, camera_sample};
use nyquist::scramble::Scramble;
use nyquist::sequence::{OwenSobol, Pmj02, Sequence, Sobol};
use nyquist::stratify::shuffle;
use nyquist_film::{Film, FilmConfig, FilmTile};
use std::hint::black_box;

/// Builds a workload (and runs its checks).
pub type Make = fn() -> Workload<'static>;

/// Every workload by name, in the order of the table.
pub const ALL: &[(&str, Make)] = &[
    ("film mitchell", film_mitchell),
    ("film box", film_box),
    ("shuffle", shuffle_1024),
    ("lanczos direct", lanczos_direct),
    ("filter table nearest", table_nearest),
    ("halton radical inverse", halton_radical_inverse),
    ("halton camera sample", halton_camera),
    ("pmj02 camera sample", pmj02_camera),
    ("pmj02 plain sample_2d", pmj02_plain_sample_2d),
    ("pmj02 scrambled sample_2d", pmj02_sample_2d),
    ("owen-sobol sample_4d", owen_sobol_4d),
    ("owen-sobol sample", owen_sobol_sample),
    ("sobol by index, coherent", sobol_coherent),
    ("sobol by index, incoherent", sobol_incoherent),
    ("zsobol camera sample", zsobol_camera),
];

/// OpenQMC's rows.
const OQMC_PMJ: &str = "OpenQMC `PmjSampler` (2-D + 3-D draw, XOR scramble)";
const OQMC_LOOKUP: &str = "OpenQMC lookup core (`shuffledScrambledLookup`, XOR scramble)";
const OQMC_SOBOL: &str = "OpenQMC `shuffledScrambledSobol<4>` (Owen)";

/// Camera-sample workloads: 8 × 8 pixels from (100, 50), 16 samples each.
const PIXELS: u32 = 8;
const SPP: u32 = 16;
const ORIGIN: [u32; 2] = [100, 50];
const CAMERA_LEN: usize = (5 * PIXELS * PIXELS * SPP) as usize;

/// The row of a peer that was not built: its snapshot variable was unset. (Unused when every
/// peer is built.)
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
            OQMC_PMJ,
            ok,
            job(CAMERA_LEN, move |out| {
                cache.camera(ORIGIN, PIXELS, SPP, out)
            }),
        ));
    }
    #[cfg(not(peer_openqmc))]
    peers.push(unbuilt(OQMC_PMJ, "NYQUIST_OPENQMC"));
    const PMJ02BN: &str = if cfg!(peer_pbrt_v4_substitute_tables) {
        "pbrt-v4 `PMJ02BNSampler` (its code on substitute tables: the snapshot lacks its data files)"
    } else {
        "pbrt-v4 `PMJ02BNSampler`"
    };
    #[cfg(peer_pbrt_v4)]
    peers.push(pbrt_v4_camera(PMJ02BN, 2, || {
        crate::pbrt_v4::Sampler::pmj02bn(SPP, 1)
    }));
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

/// Plain PMJ(0,2) by index: one table read on both sides.
fn pmj02_plain_sample_2d() -> Workload<'static> {
    let idx = hashed_indices();
    let seq: Vec<u32> = (0..POINTS).collect();
    let p = Pmj02::new();
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
    const PEER: &str = if cfg!(peer_pbrt_v4_substitute_tables) {
        "pbrt-v4 `GetPMJ02BNSample` (table read; its code on a substitute table)"
    } else {
        "pbrt-v4 `GetPMJ02BNSample` (table read)"
    };
    #[cfg(peer_pbrt_v4)]
    let peer = {
        use crate::pbrt_v4::pmj02bn_lookup;
        let ok = pmj_check(
            PEER,
            &once(len, |o| pmj02bn_lookup(&idx, o)),
            &once(len, |o| pmj02bn_lookup(&seq, o)),
        );
        let idx = idx.clone();
        Entry::checked(
            PEER,
            ok,
            job(len, move |o| pmj02bn_lookup(black_box(&idx), o)),
        )
    };
    #[cfg(not(peer_pbrt_v4))]
    let peer = unbuilt(PEER, "NYQUIST_PBRT_V4");
    Workload {
        name: "PMJ(0,2) plain `sample_2d`, 4096 hashed indices".into(),
        elements: len as u64,
        unit: "value",
        nyquist: job(len, move |o| fill(black_box(&idx), o)),
        peers: vec![peer],
    }
}

fn pmj02_sample_2d() -> Workload<'static> {
    let idx = hashed_indices();
    let seq: Vec<u32> = (0..POINTS).collect();
    let p = Pmj02::scrambled(7);
    // The batch read, as the peer's loop over the indices is one.
    let fill = move |idx: &[u32], out: &mut [f32]| {
        p.fill_2d(idx, out.as_chunks_mut::<2>().0)
            .expect("one point per index")
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
            OQMC_LOOKUP,
            ok,
            job(len, move |o| table.lookup_2d(7, black_box(&idx), o)),
        ));
    }
    #[cfg(not(peer_openqmc))]
    peers.push(unbuilt(OQMC_LOOKUP, "NYQUIST_OPENQMC"));
    Workload {
        name: "PMJ(0,2) Owen-scrambled `fill_2d`, 4096 hashed indices".into(),
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
                let v = ours.sample_4d(u64::from(black_box(i)), set * 4);
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
            OQMC_SOBOL,
            ok,
            job(SOBOL_LEN, move |o| {
                crate::openqmc::sobol_4d(black_box(POINTS), &seeds, o)
            }),
        ));
    }
    #[cfg(not(peer_openqmc))]
    peers.push(unbuilt(OQMC_SOBOL, "NYQUIST_OPENQMC"));
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
    let ours = HaltonSampler::new([RESOLUTION; 2], SPP, Scramble::PermuteDigits, 1);
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
    // What pbrt-v4's values are checked against.
    #[cfg_attr(not(peer_pbrt_v4), allow(unused_variables))]
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

/// Film workloads: 4096 samples over a 64 × 64 film, each with its own radiance.
const FILM: u32 = 64;
const FILM_SAMPLES: usize = 4096;

fn film_samples() -> (Vec<[f32; 2]>, Vec<[f32; 3]>) {
    let mut rng = nyquist::rng::default_rng(1);
    let p = (0..FILM_SAMPLES)
        .map(|_| [(); 2].map(|_| FILM as f32 * nyquist::rng::uniform_f32(&mut rng)))
        .collect();
    let mut rng = nyquist::rng::default_rng(2);
    let l = (0..FILM_SAMPLES)
        .map(|_| [(); 3].map(|_| nyquist::rng::uniform_f32(&mut rng)))
        .collect();
    (p, l)
}

/// nyquist's film and a tile over all of it.
fn film_tile(filter: &dyn nyquist::filter::Filter) -> (Film, FilmTile) {
    let film = Film::new(FilmConfig::new(FILM, FILM), filter).unwrap();
    let spec = film.tiles(FILM).unwrap()[0];
    let tile = film.tile(spec);
    (film, tile)
}

/// Each pixel's filter weight sum and weighted mean radiance, as nyquist's film holds them
/// after one pass over the samples.
#[cfg(peer_pbrt_v3)]
fn film_pixels(
    filter: &dyn nyquist::filter::Filter,
    p: &[[f32; 2]],
    l: &[[f32; 3]],
) -> Vec<[f64; 2]> {
    let (mut film, mut tile) = film_tile(filter);
    for (&p, &l) in p.iter().zip(l) {
        tile.add_sample(p, l, 1.0);
    }
    film.merge(tile).unwrap();
    (0..FILM * FILM)
        .map(|k| {
            let px = film
                .pixel(i64::from(k % FILM), i64::from(k / FILM))
                .unwrap();
            [px.weight_sum, px.rgb_sum[0]]
        })
        .collect()
}

/// pbrt-v3's tile against nyquist's film after one pass over the same samples: the total filter
/// weight within 0.1 %, and the largest and the mean difference of the pixels' filter weight
/// sums and red sums within `tol`. The filter tables differ: pbrt-v3's has 16 × 16 cells over a
/// quadrant of the support, read at the nearest cell, so with Mitchell its pixel sums are up to
/// about 0.22 and on average about 0.03 from nyquist's, whose table is within 10⁻³ of direct
/// evaluation; a film position off by half a pixel would be several times that.
#[cfg(peer_pbrt_v3)]
fn film_check(
    ours: &[[f64; 2]],
    theirs: &crate::pbrt_v3::Tile,
    tol: FilmTolerance,
) -> Result<(), String> {
    let (mut worst, mut mean) = (0.0f64, 0.0f64);
    for (k, &[w, r]) in ours.iter().enumerate() {
        let (x, y) = (k as u32 % FILM, k as u32 / FILM);
        let [tr, _, _, tw] = theirs.pixel(x, y).map(f64::from);
        for d in [(w - tw).abs(), (r - tr).abs()] {
            worst = worst.max(d);
            mean += d / (2 * ours.len()) as f64;
        }
    }
    let total: f64 = (0..FILM * FILM)
        .map(|k| f64::from(theirs.pixel(k % FILM, k / FILM)[3]))
        .sum();
    let ours_total: f64 = ours.iter().map(|p| p[0]).sum();
    if !((total - ours_total).abs() <= 1e-3 * ours_total) {
        return Err(format!(
            "total filter weight {total} here, {ours_total} in nyquist"
        ));
    }
    if worst <= tol.max && mean <= tol.mean {
        Ok(())
    } else {
        Err(format!(
            "pixel sums differ by up to {worst:.3e}, {mean:.3e} on average (tolerances {:.1e}, \
             {:.1e})",
            tol.max, tol.mean
        ))
    }
}

/// How far pbrt-v3's pixel sums may be from nyquist's: at most `max`, `mean` on average.
#[cfg(peer_pbrt_v3)]
#[derive(Clone, Copy)]
struct FilmTolerance {
    max: f64,
    mean: f64,
}

static MITCHELL: std::sync::LazyLock<Mitchell> = std::sync::LazyLock::new(Mitchell::default);
static BOXCAR: std::sync::LazyLock<Boxcar> = std::sync::LazyLock::new(Boxcar::default);

/// The filters of the film workloads.
#[derive(Clone, Copy)]
enum FilmFilter {
    /// Mitchell, r = 2, B = C = ⅓.
    Mitchell,
    /// Box, r = ½.
    Box,
}

impl FilmFilter {
    fn nyquist(self) -> &'static dyn Filter {
        match self {
            FilmFilter::Mitchell => &*MITCHELL,
            FilmFilter::Box => &*BOXCAR,
        }
    }

    #[cfg(peer_pbrt_v3)]
    fn pbrt_v3(self) -> crate::pbrt_v3::Filter {
        match self {
            FilmFilter::Mitchell => crate::pbrt_v3::Filter::mitchell(2.0, 1.0 / 3.0, 1.0 / 3.0),
            FilmFilter::Box => crate::pbrt_v3::Filter::boxcar(0.5),
        }
    }

    #[cfg(peer_pbrt_v3)]
    fn tolerance(self) -> FilmTolerance {
        match self {
            FilmFilter::Mitchell => FilmTolerance {
                max: 0.3,
                mean: 0.05,
            },
            // One weight of 1 per sample on both sides: only the sums' rounding differs.
            FilmFilter::Box => FilmTolerance {
                max: 1e-5,
                mean: 1e-6,
            },
        }
    }
}

fn film_workload(name: &str, filter: FilmFilter) -> Workload<'static> {
    let (p, l) = film_samples();
    const PEER: &str = "pbrt-v3 `FilmTile::AddSample`";
    #[cfg(peer_pbrt_v3)]
    let peer = {
        let ours = film_pixels(filter.nyquist(), &p, &l);
        let mut tile = crate::pbrt_v3::Tile::new(filter.pbrt_v3(), FILM);
        tile.add(&p, &l);
        let ok = film_check(&ours, &tile, filter.tolerance());
        let mut tile = crate::pbrt_v3::Tile::new(filter.pbrt_v3(), FILM);
        let (p, l) = (p.clone(), l.clone());
        let job: Job<'static> = Box::new(move || {
            tile.add(black_box(&p), &l);
            black_box(&mut tile);
        });
        Entry::checked(PEER, ok, job)
    };
    #[cfg(not(peer_pbrt_v3))]
    let peer = unbuilt(PEER, "NYQUIST_PBRT_V3");
    // One tile, reused across calls (a fresh one each time would time its first-touch page
    // faults); the tile owns its pixels and filter table, the film is not needed.
    let (_, mut tile) = film_tile(filter.nyquist());
    Workload {
        name: name.into(),
        elements: FILM_SAMPLES as u64,
        unit: "sample",
        nyquist: Box::new(move || {
            for (&p, &l) in black_box(&p).iter().zip(&l) {
                tile.add_sample(p, l, 1.0);
            }
            black_box(&mut tile);
        }),
        peers: vec![peer],
    }
}

fn film_mitchell() -> Workload<'static> {
    film_workload(
        "film `add_sample`, Mitchell r = 2, 4096 samples on 64 × 64",
        FilmFilter::Mitchell,
    )
}

fn film_box() -> Workload<'static> {
    film_workload(
        "film `add_sample`, box r = ½, 4096 samples on 64 × 64",
        FilmFilter::Box,
    )
}

fn shuffle_1024() -> Workload<'static> {
    const N: usize = 1024;
    let start: Vec<f32> = (0..N).map(|i| i as f32).collect();
    let is_permutation = |what: &str, v: &[f32]| {
        let mut s = v.to_vec();
        s.sort_by(f32::total_cmp);
        if s != start || v == start.as_slice() {
            Err(format!("{what}: not a shuffle of 0..{N}"))
        } else {
            Ok(())
        }
    };
    let mut rng = nyquist::rng::default_rng(3);
    let mut buf = start.clone();
    shuffle(&mut buf, N, 1, &mut rng).unwrap();
    is_permutation("nyquist", &buf).expect("nyquist's own check");
    const PEER: &str = "pbrt-v3 `Shuffle` (its PCG32 `RNG`)";
    #[cfg(peer_pbrt_v3)]
    let peer = {
        let mut rng = crate::pbrt_v3::Rng::new(3);
        let mut buf = start.clone();
        rng.shuffle(&mut buf, N, 1);
        let ok = is_permutation(PEER, &buf);
        let job: Job<'static> = Box::new(move || {
            rng.shuffle(&mut buf, black_box(N), 1);
            black_box(&mut buf);
        });
        Entry::checked(PEER, ok, job)
    };
    #[cfg(not(peer_pbrt_v3))]
    let peer = unbuilt(PEER, "NYQUIST_PBRT_V3");
    Workload {
        name: "shuffle, 1024 `f32`".into(),
        elements: N as u64,
        unit: "element",
        nyquist: Box::new(move || {
            shuffle(&mut buf, black_box(N), 1, &mut rng).unwrap();
            black_box(&mut buf);
        }),
        peers: vec![peer],
    }
}

/// 1024 filter offsets, uniform over `scale` times the support of radius `r`.
fn offsets(r: f32, scale: f32) -> Vec<[f32; 2]> {
    let mut rng = nyquist::rng::default_rng(42);
    (0..1024)
        .map(|_| [(); 2].map(|_| (nyquist::rng::uniform_f32(&mut rng) * 2.0 - 1.0) * scale * r))
        .collect()
}

fn lanczos_direct() -> Workload<'static> {
    let f = Lanczos::default();
    let pts = offsets(4.0, 1.1);
    let fill = move |pts: &[[f32; 2]], out: &mut [f32]| {
        for (o, &[x, y]) in out.iter_mut().zip(pts) {
            *o = f.eval(x, y);
        }
    };
    // What pbrt-v3's values are checked against.
    #[cfg_attr(not(peer_pbrt_v3), allow(unused_variables))]
    let ours = once(pts.len(), |o| fill(&pts, o));
    const PEER: &str = "pbrt-v3 `LanczosSincFilter::Evaluate` (virtual call)";
    #[cfg(peer_pbrt_v3)]
    let peer = {
        let pf = crate::pbrt_v3::Filter::lanczos(4.0, 3.0);
        let theirs = once(pts.len(), |o| pf.evaluate(&pts, o));
        let pts = pts.clone();
        Entry::checked(
            PEER,
            check::close(PEER, &ours, &theirs, 1e-5),
            job(pts.len(), move |o| pf.evaluate(black_box(&pts), o)),
        )
    };
    #[cfg(not(peer_pbrt_v3))]
    let peer = unbuilt(PEER, "NYQUIST_PBRT_V3");
    Workload {
        name: "Lanczos (r = 4, τ = 3) `eval`, direct, 1024 offsets".into(),
        elements: pts.len() as u64,
        unit: "weight",
        nyquist: job(pts.len(), move |o| fill(black_box(&pts), o)),
        peers: vec![peer],
    }
}

fn table_nearest() -> Workload<'static> {
    let table: FilterTable = FilterTable::new(&*MITCHELL, Interpolation::Nearest).unwrap();
    // Inside the support: pbrt-v3 reads its table only there.
    let pts = offsets(2.0, 0.999);
    let fill = move |pts: &[[f32; 2]], out: &mut [f32]| {
        for (o, &[x, y]) in out.iter_mut().zip(pts) {
            *o = table.weight(x, y);
        }
    };
    let ours = once(pts.len(), |o| fill(&pts, o));
    // Nearest-cell lookups stay within a cell's change of the filter (0.081 at most here).
    let exact: Vec<f32> = pts.iter().map(|&[x, y]| MITCHELL.eval(x, y)).collect();
    check::close("nyquist's table", &exact, &ours, 0.12).expect("nyquist's own check");
    const PEER: &str = "pbrt-v3's 16 × 16 table of its `MitchellFilter`, indexed as `AddSample` \
                        does (index arithmetic in the shim)";
    #[cfg(peer_pbrt_v3)]
    let peer = {
        let t = crate::pbrt_v3::Table::new(&crate::pbrt_v3::Filter::mitchell(
            2.0,
            1.0 / 3.0,
            1.0 / 3.0,
        ));
        let theirs = once(pts.len(), |o| t.lookup(&pts, o));
        let pts = pts.clone();
        // Each value is the filter at the centre of the cell the offset falls in, as pbrt-v3
        // fills its table.
        let centres: Vec<f32> = pts
            .iter()
            .map(|&[x, y]| {
                let c = |v: f32| ((v.abs() * 8.0).floor().min(15.0) + 0.5) / 8.0;
                MITCHELL.eval(c(x), c(y))
            })
            .collect();
        let ok = check::close(PEER, &centres, &theirs, 1e-5);
        Entry::checked(
            PEER,
            ok,
            job(pts.len(), move |o| t.lookup(black_box(&pts), o)),
        )
    };
    #[cfg(not(peer_pbrt_v3))]
    let peer = unbuilt(PEER, "NYQUIST_PBRT_V3");
    Workload {
        name: "Mitchell `FilterTable::weight`, nearest, 1024 offsets in the support".into(),
        elements: pts.len() as u64,
        unit: "weight",
        nyquist: job(pts.len(), move |o| fill(black_box(&pts), o)),
        peers: vec![peer],
    }
}

/// Halton values by random access: 256 random indices below 10⁷, dimensions 0..64 of each.
/// Checked to 10⁻⁶: pbrt's loops accumulate the digit weight in `f32`.
fn halton_radical_inverse() -> Workload<'static> {
    let mut rng = nyquist::rng::default_rng(9);
    let index: Vec<u64> = (0..256)
        .map(|_| u64::from(nyquist::rng::uniform_below(&mut rng, 10_000_000)))
        .collect();
    let len = index.len() * DIMS as usize;
    let fill = |index: &[u64], out: &mut [f32]| {
        let mut o = out.iter_mut();
        for &a in index {
            for d in 0..DIMS {
                *o.next().unwrap() = radical_inverse(d, a);
            }
        }
    };
    // What the peers' values are checked against.
    #[cfg_attr(not(any(peer_pbrt_v3, peer_pbrt_v4)), allow(unused_variables))]
    let ours = once(len, |o| fill(&index, o));
    let mut peers = Vec::new();
    const V3: &str = "pbrt-v3 `RadicalInverse` (a digit loop per base, base a constant)";
    #[cfg(peer_pbrt_v3)]
    {
        let theirs = once(len, |o| crate::pbrt_v3::radical_inverse(&index, DIMS, o));
        let idx = index.clone();
        peers.push(Entry::checked(
            V3,
            check::close(V3, &ours, &theirs, 1e-6),
            job(len, move |o| {
                crate::pbrt_v3::radical_inverse(black_box(&idx), DIMS, o)
            }),
        ));
    }
    #[cfg(not(peer_pbrt_v3))]
    peers.push(unbuilt(V3, "NYQUIST_PBRT_V3"));
    const V4: &str = "pbrt-v4 `RadicalInverse` (one digit loop, base read at run time)";
    #[cfg(peer_pbrt_v4)]
    {
        let theirs = once(len, |o| crate::pbrt_v4::radical_inverse(&index, DIMS, o));
        let idx = index.clone();
        peers.push(Entry::checked(
            V4,
            check::close(V4, &ours, &theirs, 1e-6),
            job(len, move |o| {
                crate::pbrt_v4::radical_inverse(black_box(&idx), DIMS, o)
            }),
        ));
    }
    #[cfg(not(peer_pbrt_v4))]
    peers.push(unbuilt(V4, "NYQUIST_PBRT_V4"));
    Workload {
        name: "Halton `radical_inverse`, 256 random indices < 10⁷ × dims 0..64".into(),
        elements: len as u64,
        unit: "value",
        nyquist: job(len, move |o| fill(black_box(&index), o)),
        peers,
    }
}
