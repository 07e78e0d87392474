//! `nyquist::sampler`: every sampler (and the adaptive wrapper, the layout and the pixel-range
//! driver) for any spp, seed, resolution, pixel, sample index and dimension.

use nyquist::Error;
use nyquist::sampler::{
    AdaptiveSampler, BestCandidateSampler, HaltonSampler, HammersleySampler, Jitter, NAMES,
    NamedSampler, NamedSamplerError, OwenSobolSampler, PixelRangeSampler, Pmj02Sampler,
    RandomSampler, SCRAMBLE_NAMES, Sample, SampleLayout, Sampler, SobolSampler, StratifiedSampler,
    ZSobolSampler, ZeroTwoSampler, camera_sample,
};
use nyquist::scramble::Scramble;

use crate::{Bytes, error_numbers_hold, in_unit};

struct Args {
    pixel: [u32; 2],
    sample_index: u32,
    dim: u32,
    len_1d: usize,
    len_2d: usize,
    layout: [u32; 2],
    extent: [u32; 2],
    bands: u32,
    min_spp: u32,
    threshold: f32,
    radiance: [f32; 4],
}

/// Samplers: constructors reject `spp == 0` (and zero resolutions) with a typed error; every
/// value (1D, 2D, pixel 2D, arrays) is in `[0, 1)`; `start_pixel_sample` twice replays the same
/// values bit for bit; starting at `dim + 1` gives the value `dim`'s second `get_1d` gave;
/// `camera_sample` lands inside the pixel; a `PixelRangeSampler` yields exactly
/// `total_samples()` samples, all in range, and its bands together yield the same samples;
/// `AdaptiveSampler` answers `pixel_samples` within its `spp_range` whatever is reported;
/// `NamedSampler` builds exactly the names in `NAMES` (an spp above `spp_limit` is
/// `SppAboveLimit`) and its samplers pass the same checks.
pub fn samplers(data: &[u8]) {
    let mut b = Bytes::new(data);
    let kind = b.u8() % 13;
    let scramble = Scramble::ALL[b.below(3) as usize];
    let frame = b.u32();
    let spp = match b.u8() % 4 {
        0 => b.below(17),
        1 => b.below(300),
        2 => 1 << b.below(31),
        _ => b.u32(),
    };
    let seed = b.u64();
    let resolution = if b.bool() {
        [b.below(40), b.below(40)]
    } else {
        [b.u32(), b.u32()]
    };
    let xy = [b.below(20), b.below(20)];
    let flag = b.bool();
    let big_pixel = b.bool();
    let args = Args {
        pixel: if big_pixel {
            [b.u32(), b.u32()]
        } else {
            [b.below(64), b.below(64)]
        },
        sample_index: if b.bool() { b.below(300) } else { b.u32() },
        dim: if b.bool() { b.below(40) } else { b.u32() },
        len_1d: b.below(40) as usize,
        len_2d: b.below(40) as usize,
        layout: [b.below(6), b.below(6)],
        extent: [b.below(4), b.below(4)],
        bands: b.below(5),
        min_spp: b.below(20),
        threshold: b.f32_mixed(),
        radiance: [b.f32_mixed(), b.f32_mixed(), b.f32_mixed(), b.f32_mixed()],
    };
    let jitter = if flag {
        Jitter::Jittered
    } else {
        Jitter::Centered
    };
    match kind {
        0 => run("RandomSampler", spp, RandomSampler::new(spp, seed), &args),
        1 => {
            let r = StratifiedSampler::new(xy[0], xy[1], jitter, seed);
            if let Ok(s) = &r {
                assert_eq!(s.strata(), xy);
                assert_eq!(s.samples_per_pixel(), xy[0] * xy[1]);
            }
            run("StratifiedSampler", xy[0] * xy[1], r, &args)
        }
        2 => run(
            "BestCandidateSampler",
            spp,
            BestCandidateSampler::new(spp, seed),
            &args,
        ),
        3 => {
            let scramble = if flag {
                Scramble::PermuteDigits
            } else {
                Scramble::None
            };
            let r = HaltonSampler::new(resolution, spp, scramble, seed);
            if resolution.contains(&0) {
                assert!(
                    r.is_err(),
                    "HaltonSampler accepted resolution {resolution:?}"
                );
            }
            run("HaltonSampler", spp, r, &args)
        }
        4 => {
            let r = HammersleySampler::new(resolution, spp, scramble, seed);
            if resolution.contains(&0) {
                assert!(
                    r.is_err(),
                    "HammersleySampler accepted resolution {resolution:?}"
                );
            }
            // N = width · H · spp (H the height padded to a power of two) must fit a u64; the
            // error gives the largest width that fits with H · spp.
            let h = u128::from(resolution[1].max(1)).next_power_of_two();
            if !resolution.contains(&0)
                && spp != 0
                && u128::from(resolution[0]) * h * u128::from(spp) >= 1 << 64
            {
                let max = (u128::from(u64::MAX) / (h * u128::from(spp))) as u64;
                assert_eq!(
                    r.as_ref().err(),
                    Some(&Error::TooMany {
                        what: "width (at this height and spp)",
                        value: u64::from(resolution[0]),
                        max,
                    }),
                    "HammersleySampler accepted {resolution:?} × {spp}"
                );
            }
            run("HammersleySampler", spp, r, &args)
        }
        5 => {
            let r = SobolSampler::new(resolution, spp, scramble, seed);
            if resolution.contains(&0) {
                assert!(
                    r.is_err(),
                    "SobolSampler accepted resolution {resolution:?}"
                );
            }
            check_rounded("SobolSampler", spp, SobolSampler::rounded_spp(spp));
            run("SobolSampler", spp, r, &args)
        }
        6 => {
            check_rounded("ZeroTwoSampler", spp, ZeroTwoSampler::rounded_spp(spp));
            run("ZeroTwoSampler", spp, ZeroTwoSampler::new(spp, seed), &args)
        }
        7 => {
            let inner = StratifiedSampler::new(xy[0].max(1), xy[1].max(1), jitter, seed).unwrap();
            adaptive(inner, &args);
        }
        8 => run(
            "OwenSobolSampler",
            spp,
            OwenSobolSampler::new(spp, seed).map(|s| s.with_frame(frame)),
            &args,
        ),
        9 => {
            let r = ZSobolSampler::new(resolution, spp, scramble, seed);
            if resolution.contains(&0) {
                assert!(r.is_err(), "ZSobolSampler accepted {resolution:?}");
            }
            check_rounded("ZSobolSampler", spp, ZSobolSampler::rounded_spp(spp));
            run("ZSobolSampler", spp, r, &args)
        }
        11 => run("Pmj02Sampler", spp, Pmj02Sampler::new(spp, seed), &args),
        10 => {
            let r = SobolSampler::new(resolution, spp, scramble, seed);
            if let Ok(s) = &r {
                assert_eq!(s.scramble(), scramble);
            }
            run("SobolSampler", spp, r, &args)
        }
        _ => {
            let name = if flag {
                NAMES[b.below(NAMES.len() as u32 - 1) as usize].to_string()
            } else {
                String::from_utf8_lossy(b.rest()).chars().take(24).collect()
            };
            named(&name, resolution, spp, seed, &args);
            named_scrambled(&name, resolution, spp, seed, scramble, &args);
        }
    }
}

/// `NamedSampler::with_scramble` with any name: those of `SCRAMBLE_NAMES` build exactly when
/// `new` does (and keep the sampler contract), the other known names say `NoScramble`, unknown
/// names `UnknownName`.
fn named_scrambled(name: &str, size: [u32; 2], spp: u32, seed: u64, scramble: Scramble, a: &Args) {
    let r = NamedSampler::with_scramble(name, size, spp, seed, scramble);
    let canonical = nyquist::sampler::canonical_name(name);
    match canonical.unwrap_or_default() {
        c if SCRAMBLE_NAMES.contains(&c) => {
            let plain = NamedSampler::new(name, size, spp, seed);
            assert_eq!(r.is_ok(), plain.is_ok(), "{name}: with_scramble vs new");
            if let Ok(s) = &r {
                assert_eq!(s.name(), c);
            }
            let r = r.map_err(|e| match e {
                NamedSamplerError::Sampler(e) => e,
                e => panic!("{name}: with_scramble failed with {e:?}"),
            });
            run("NamedSampler::with_scramble", spp, r, a);
        }
        _ if canonical.is_some() => assert_eq!(r.err(), Some(NamedSamplerError::NoScramble)),
        _ => assert_eq!(r.err(), Some(NamedSamplerError::UnknownName)),
    }
}

/// `NamedSampler::new` with any name: a sampler named as asked, or the documented error.
fn named(name: &str, size: [u32; 2], spp: u32, seed: u64, a: &Args) {
    let canonical = nyquist::sampler::canonical_name(name);
    let known = canonical.is_some();
    match NamedSampler::new(name, size, spp, seed) {
        Ok(mut s) => {
            assert!(known, "NamedSampler built unknown name {name:?}");
            let reported = match canonical {
                Some("halton-plain") => "halton",
                Some("sobol-plain") => "sobol",
                Some("sobol-owen") => "owen-sobol",
                c => c.unwrap_or_default(),
            };
            assert_eq!(s.name(), reported);
            if name == "adaptive" {
                // Fewer samples than the maximum where the pixel converged: the adaptive checks.
                check_sampler_adaptive(&mut s, a);
                let n = s.pixel_samples(a.pixel);
                assert!((1..=s.samples_per_pixel()).contains(&n), "adaptive: {n}");
            } else {
                run("NamedSampler", spp, Ok(s), a);
            }
        }
        Err(NamedSamplerError::UnknownName) => {
            assert!(!known, "NamedSampler rejected {name:?}");
        }
        Err(NamedSamplerError::SppAboveLimit { spp: got, max }) => {
            assert_eq!(got, spp);
            assert_eq!(nyquist::sampler::spp_limit(name), Some(max), "{name}");
            assert!(spp > max, "{name}: {spp} ≤ {max}");
        }
        Err(NamedSamplerError::Sampler(e)) => {
            assert!(
                matches!(
                    e,
                    Error::ZeroSize { .. }
                        | Error::TooMany { .. }
                        | Error::OutOfRange { .. }
                        | Error::NotInRange { .. }
                ),
                "NamedSampler {name:?}: unexpected error {e:?}"
            );
            assert!(error_numbers_hold(&e), "NamedSampler {name:?}: {e:?}");
        }
        Err(e) => panic!("NamedSampler {name:?}: an error this check does not know: {e:?}"),
    }
}

/// `(next power of two, changed)`, or `(0, true)` for 0 and requests above 2³¹.
fn check_rounded(name: &str, spp: u32, got: (u32, bool)) {
    let want = if spp == 0 || spp > 1 << 31 {
        (0, true)
    } else {
        let p = spp.next_power_of_two();
        (p, p != spp)
    };
    assert_eq!(got, want, "{name}::rounded_spp({spp})");
}

fn run<S: Sampler + Clone>(name: &str, spp: u32, r: Result<S, Error>, a: &Args) {
    match r {
        Ok(mut s) => {
            assert!(spp > 0, "{name}: accepted spp 0");
            assert!(s.samples_per_pixel() > 0, "{name}: samples_per_pixel() = 0");
            check_sampler(name, &mut s, a);
            check_range(name, s, a);
        }
        Err(e) => {
            assert!(
                matches!(
                    e,
                    Error::ZeroSize { .. }
                        | Error::TooMany { .. }
                        | Error::OutOfRange { .. }
                        | Error::NotInRange { .. }
                ),
                "{name}: unexpected error {e:?}"
            );
            assert!(error_numbers_hold(&e), "{name}: {e:?}");
        }
    }
}

/// All the values one pixel sample yields, as bits.
fn draw<S: Sampler + ?Sized>(name: &str, s: &mut S, a: &Args) -> Vec<u32> {
    let mut v = Vec::new();
    s.start_pixel_sample(a.pixel, a.sample_index, a.dim);
    v.push(s.get_1d());
    v.extend(s.get_2d());
    v.extend(s.get_pixel_2d());
    v.push(s.get_1d());
    let mut arr = vec![3.0f32; a.len_1d];
    s.get_array_1d(&mut arr);
    v.extend(&arr);
    let mut arr = vec![3.0f32; a.len_2d];
    s.get_array_2d(&mut arr);
    if a.len_2d % 2 == 1 {
        assert_eq!(
            arr[a.len_2d - 1],
            3.0,
            "{name}: get_array_2d wrote the odd last value"
        );
        arr.pop();
    }
    v.extend(&arr);
    v.push(s.get_1d());
    for (i, &x) in v.iter().enumerate() {
        assert!(
            in_unit(x),
            "{name}: value {i} of pixel {:?} sample {} dim {} = {x}",
            a.pixel,
            a.sample_index,
            a.dim
        );
    }
    v.into_iter().map(f32::to_bits).collect()
}

fn check_sampler<S: Sampler + ?Sized>(name: &str, s: &mut S, a: &Args) {
    let spp = s.samples_per_pixel();
    let first = draw(name, s, a);
    let again = draw(name, s, a);
    assert_eq!(
        first, again,
        "{name}: start_pixel_sample twice gave different values"
    );
    if let Some(next) = a.dim.checked_add(1) {
        s.start_pixel_sample(a.pixel, a.sample_index, a.dim);
        let _ = s.get_1d();
        let second = s.get_1d();
        s.start_pixel_sample(a.pixel, a.sample_index, next);
        let direct = s.get_1d();
        assert_eq!(
            second.to_bits(),
            direct.to_bits(),
            "{name}: dimension {next} differs when reached by get_1d and by start_pixel_sample"
        );
    }
    for n in [1, 2, 3, 7, 1000, u32::MAX] {
        assert!(s.round_size(n) > 0, "{name}: round_size({n}) = 0");
    }
    assert_eq!(s.round_size(0), s.round_size(0)); // total
    let c = camera_sample(s, a.pixel, a.sample_index);
    for k in 0..2 {
        let p = a.pixel[k] as f32;
        let f = c.p_film[k];
        assert!(
            f == p || (f >= p && f < p + 1.0),
            "{name}: camera_sample p_film[{k}] = {f} outside pixel {}",
            a.pixel[k]
        );
    }
    assert!(
        in_unit(c.time) && in_unit(c.lens[0]) && in_unit(c.lens[1]),
        "{name}: {c:?}"
    );
    assert_eq!(s.pixel_samples(a.pixel), spp);
}

/// The pixel-range driver and the layout over a small rectangle at `a.pixel`.
fn check_range<S: Sampler + Clone>(name: &str, s: S, a: &Args) {
    let spp = s.samples_per_pixel();
    let mut layout = SampleLayout::<2>::new();
    let h1 = layout.add_1d(&s, a.layout[0]);
    let h2 = layout.add_2d(&s, a.layout[1]);
    assert_eq!(
        h1.is_err(),
        a.layout[0] == 0,
        "{name}: add_1d({})",
        a.layout[0]
    );
    assert_eq!(
        h2.is_err(),
        a.layout[1] == 0,
        "{name}: add_2d({})",
        a.layout[1]
    );
    let start = a.pixel;
    let end = [
        start[0].saturating_add(a.extent[0]),
        start[1].saturating_add(a.extent[1]),
    ];
    let r = PixelRangeSampler::new(s, start, end);
    let empty = end[0] <= start[0] || end[1] <= start[1];
    let mut range = match r {
        Ok(r) => {
            assert!(
                !empty,
                "{name}: PixelRangeSampler accepted the empty range {start:?}..{end:?}"
            );
            r
        }
        Err(e) => {
            assert!(
                empty,
                "{name}: PixelRangeSampler rejected {start:?}..{end:?}: {e:?}"
            );
            assert!(matches!(e, Error::ZeroSize { .. }), "{name}: {e:?}");
            return;
        }
    };
    let pixels = u64::from(end[0] - start[0]) * u64::from(end[1] - start[1]);
    let total = range.total_samples();
    assert_eq!(total, pixels * u64::from(spp), "{name}: total_samples");
    if total > 1024 {
        return;
    }
    let mut buf = vec![0.0f32; layout.len() + 3];
    assert!(Sample::new(&layout, &mut buf[..layout.len() - 1]).is_err());
    let all = collect(name, &mut range, &layout, &mut buf, a, start, end, &h1, &h2);
    assert_eq!(all.len() as u64, total, "{name}: next_sample count");
    if a.bands > 0 {
        let whole = PixelRangeSampler::new(range.sampler().clone(), start, end).unwrap();
        let mut joined = Vec::new();
        for i in 0..a.bands {
            if let Some(mut band) = whole.sub_sampler(i, a.bands) {
                joined.extend(collect(
                    name, &mut band, &layout, &mut buf, a, start, end, &h1, &h2,
                ));
            } else {
                assert!(
                    end[1] - start[1] < a.bands,
                    "{name}: band {i} of {} missing",
                    a.bands
                );
            }
        }
        assert!(whole.sub_sampler(a.bands, a.bands).is_none());
        assert_eq!(
            joined, all,
            "{name}: the bands' samples differ from the whole range's"
        );
    }
}

#[allow(clippy::too_many_arguments)]
fn collect<S: Sampler>(
    name: &str,
    range: &mut PixelRangeSampler<S>,
    layout: &SampleLayout<2>,
    buf: &mut [f32],
    a: &Args,
    start: [u32; 2],
    end: [u32; 2],
    h1: &Result<usize, Error>,
    h2: &Result<usize, Error>,
) -> Vec<Vec<u32>> {
    let mut out = Vec::new();
    let mut sample = Sample::new(layout, buf).unwrap();
    while range.next_sample(&mut sample) {
        let p = sample.pixel();
        assert!(
            (start[0]..end[0]).contains(&p[0]) && (start[1]..end[1]).contains(&p[1]),
            "{name}: pixel {p:?} outside {start:?}..{end:?}"
        );
        let image = sample.image();
        for k in 0..2 {
            let pf = p[k] as f32;
            assert!(
                image[k] == pf || (image[k] >= pf && image[k] < pf + 1.0),
                "{name}: image {image:?} outside pixel {p:?}"
            );
        }
        assert!(in_unit(sample.time()), "{name}: time {}", sample.time());
        assert!(sample.lens().iter().all(|&x| in_unit(x)), "{name}: lens");
        if let Ok(h) = h1 {
            let v = sample.array_1d(*h);
            assert!(
                v.len() >= a.layout[0] as usize,
                "{name}: array_1d len {}",
                v.len()
            );
            assert!(v.iter().all(|&x| in_unit(x)), "{name}: array_1d {v:?}");
        }
        if let Ok(h) = h2 {
            let v = sample.array_2d(*h);
            assert!(
                v.len() >= 2 * a.layout[1] as usize,
                "{name}: array_2d len {}",
                v.len()
            );
            assert!(v.iter().all(|&x| in_unit(x)), "{name}: array_2d {v:?}");
        }
        assert_eq!(sample.as_slice().len(), layout.len());
        let mut bits: Vec<u32> = sample.as_slice()[2..].iter().map(|x| x.to_bits()).collect();
        bits.extend([
            p[0],
            p[1],
            sample.sample_index(),
            image[0].to_bits(),
            image[1].to_bits(),
        ]);
        out.push(bits);
        range.report(&a.radiance);
    }
    out
}

fn adaptive(inner: StratifiedSampler, a: &Args) {
    let max = inner.samples_per_pixel();
    let r = AdaptiveSampler::new(inner.clone(), a.min_spp, a.threshold);
    let valid = a.min_spp > 0 && a.min_spp <= max && a.threshold.is_finite() && a.threshold >= 0.0;
    let mut s = match r {
        Ok(s) => {
            assert!(
                valid,
                "AdaptiveSampler::new({}, {}) accepted",
                a.min_spp, a.threshold
            );
            s
        }
        Err(e) => {
            assert!(
                !valid,
                "AdaptiveSampler::new({}, {}) rejected: {e:?}",
                a.min_spp, a.threshold
            );
            return;
        }
    };
    assert_eq!(s.spp_range(), [a.min_spp, max]);
    // The values are the wrapped sampler's.
    let mut plain = inner;
    assert_eq!(
        draw("AdaptiveSampler", &mut s, a),
        draw("inner", &mut plain, a)
    );
    for i in 0..a.min_spp {
        let scale = if i % 2 == 0 { 1.0 } else { 0.5 };
        let rad = a.radiance.map(|x| x * scale);
        s.report(a.pixel, i, &rad[..(i as usize % 5)]);
        let n = s.pixel_samples(a.pixel);
        assert!(
            (a.min_spp..=max).contains(&n),
            "AdaptiveSampler: pixel_samples = {n} outside [{}, {max}]",
            a.min_spp
        );
    }
    check_sampler_adaptive(&mut s, a);
}

fn check_sampler_adaptive<S: Sampler>(s: &mut S, a: &Args) {
    let first = draw("AdaptiveSampler", s, a);
    assert_eq!(first, draw("AdaptiveSampler", s, a));
}
