//! The published convergence orders, measured by the study engine (`nyquist_lab::study`): RMSE over 64
//! independent runs at N = 16, 32, …, 4096 on the five integrands of Christensen, Kensler and
//! Kilpatrick 2018, and the least-squares slope of log RMSE against log N.
//!
//! Sampling error makes a measured slope scatter: with 64 runs the RMSE at each N is within
//! about ±9 % (one standard deviation), which moves a slope fitted over nine octaves by about
//! ±0.016; the bounds below are five of those or more from the expected orders.

use nyquist::sampler::{NamedSampler, NamedSamplerError};
use nyquist_lab::study::unit_square::SquareIntegrand as Integrand;
use nyquist_lab::study::{Curve, Study, powers_of_two};

/// The sweep of the published study: N = 16 … 4096, 64 runs.
fn study(samplers: &[&str], seed: u64) -> Vec<Curve<Integrand>> {
    Study {
        samplers: samplers.iter().map(|s| (*s).to_owned()).collect(),
        integrands: Integrand::ALL.to_vec(),
        counts: powers_of_two(16, 4096),
        runs: 64,
        seed,
        spp_hint: None,
    }
    .run(std::thread::available_parallelism().map_or(1, usize::from))
    .unwrap()
    .curves
}

fn slope(curves: &[Curve<Integrand>], sampler: &str, f: Integrand) -> f64 {
    let c = curves
        .iter()
        .find(|c| c.sampler == sampler && c.integrand == f)
        .unwrap();
    assert_eq!(c.spp, powers_of_two(16, 4096), "{sampler} rounds N");
    c.slope
        .unwrap_or_else(|| panic!("{sampler} {f:?}: no slope"))
}

fn report(curves: &[Curve<Integrand>]) {
    for c in curves {
        eprintln!(
            "{} {}: slope {:.3}",
            c.sampler,
            c.integrand.name(),
            c.slope.unwrap_or(f64::NAN)
        );
    }
}

#[test]
fn random_converges_at_order_one_half_on_every_integrand() {
    for seed in [0, 1] {
        let curves = study(&["random"], seed);
        report(&curves);
        for f in Integrand::ALL {
            let s = slope(&curves, "random", f);
            assert!((-0.58..=-0.42).contains(&s), "seed {seed}, {f:?}: {s}");
        }
    }
}

#[test]
fn jittered_strata_converge_at_order_three_quarters_on_disk_and_triangle() {
    for seed in [0, 1] {
        let curves = study(&["stratified"], seed);
        report(&curves);
        for f in [Integrand::Disk, Integrand::Triangle] {
            let s = slope(&curves, "stratified", f);
            assert!((-0.85..=-0.65).contains(&s), "seed {seed}, {f:?}: {s}");
        }
        // Smooth integrands: jittered strata reach order one (variance N^-2 in 2D).
        for f in [Integrand::Gaussian, Integrand::Bilinear] {
            let s = slope(&curves, "stratified", f);
            assert!((-1.1..=-0.9).contains(&s), "seed {seed}, {f:?}: {s}");
        }
    }
}

/// Owen-scrambled Sobol and PMJ02: published −0.75 on the discontinuous and about −1.45 on the
/// smooth integrands. Skips (with a note) each sampler the core does not have yet.
#[test]
fn owen_sobol_and_pmj02_reach_the_published_orders() {
    for name in ["owen-sobol", "pmj02"] {
        if NamedSampler::new(name, [1, 1], 16, 1).err() == Some(NamedSamplerError::UnknownName) {
            eprintln!("note: sampler {name} does not exist yet; its convergence test skips");
            continue;
        }
        let curves = study(&[name], 0);
        report(&curves);
        for f in [Integrand::Disk, Integrand::Triangle] {
            let s = slope(&curves, name, f);
            assert!(s <= -0.70, "{name} {f:?}: {s}");
        }
        for f in [Integrand::Gaussian, Integrand::Bilinear] {
            let s = slope(&curves, name, f);
            assert!(s <= -1.35, "{name} {f:?}: {s}");
        }
    }
}

/// Global Sobol with a digital shift (XOR): a shift keeps the nets but does not randomise them
/// enough for the −1.5 of Owen scrambling, so the smooth integrands converge at order one.
/// Measured (seeds 0 to 4): disk −0.80 … −0.83, triangle −0.57 … −0.61, step −0.99 … −1.09,
/// gaussian and bilinear −0.98 … −1.03. Asserted: the stable part.
#[test]
fn digitally_shifted_sobol_converges_at_order_one_on_smooth_integrands() {
    let curves = study(&["sobol"], 0);
    report(&curves);
    assert!(slope(&curves, "sobol", Integrand::Disk) <= -0.70);
    for f in [Integrand::Gaussian, Integrand::Bilinear] {
        let s = slope(&curves, "sobol", f);
        assert!(s <= -0.88, "{f:?}: {s}");
    }
}
