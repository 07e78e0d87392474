//! Adaptive sampling by error against uniform spp and against the contrast-test sampler, at
//! equal RMSE: how many samples each needs for the error adaptive sampling reaches
//! (`pathtracer adaptive`, `docs/path-tracer.md`).
//!
//! The uniform curve is the RMSE of the same sampler at spp 16 … 1024 against the reference.
//! For a render of RMSE e with n samples per pixel on average, the uniform spp reaching e is read
//! off that curve by log-log interpolation between its two neighbouring points (or the slope of
//! the last two points beyond its end), and the saving is that spp over n.

use anyhow::{Context, Result};
use nyquist_film::Image;
use nyquist_film::adaptive::{AdaptiveConfig, AdaptiveReport};

use crate::{RenderConfig, render};

/// Uniform spp of the curve.
pub const UNIFORM_SPP: [u32; 7] = [16, 32, 64, 128, 256, 512, 1024];

/// One measured render.
#[derive(Clone, Debug)]
pub struct Measured {
    /// What was rendered: `uniform`, `adaptive T` or `contrast`.
    pub method: String,
    /// Budget or spp asked for.
    pub spp: u32,
    /// Samples per pixel taken, on average.
    pub mean_spp: f64,
    /// RMSE against the reference.
    pub rmse: f64,
    /// Uniform spp reaching the same RMSE (interpolated), for the non-uniform methods.
    pub uniform_equivalent: Option<f64>,
    /// The adaptive report (the spp map), for adaptive renders.
    pub report: Option<AdaptiveReport>,
    /// The image.
    pub image: Image,
}

/// Renders `base` as configured but with `spp`, the sampler and adaptive settings given, once
/// per seed in `seeds`, and measures it against `reference`: the RMSE over the seeds (the root
/// of the mean squared RMSE), the mean spp over them, and the first seed's report and image.
fn measure(
    base: &RenderConfig,
    sampler: &str,
    spp: u32,
    adaptive: Option<AdaptiveConfig>,
    seeds: &[u64],
    reference: &Image,
) -> Result<(f64, f64, Option<AdaptiveReport>, Image)> {
    let mut config = base.clone();
    config.spp = spp;
    config.sampler = sampler.into();
    config.adaptive = adaptive;
    // The stateless layer for every method, so that they differ only in where samples go.
    config.stateless = true;
    let pixels = f64::from(config.size[0]) * f64::from(config.size[1]);
    let (mut squares, mut samples, mut first) = (0.0, 0.0, None);
    for &seed in seeds {
        config.seed = seed;
        let out = render(&config, |_, _| {})
            .with_context(|| format!("{sampler} at {spp} spp, seed {seed}"))?;
        squares += out.image.rmse(reference).context("RMSE")?.powi(2);
        samples += out.samples as f64 / pixels;
        first.get_or_insert((out.adaptive, out.image));
    }
    let (report, image) = first.context("no seeds")?;
    let n = seeds.len() as f64;
    Ok(((squares / n).sqrt(), samples / n, report, image))
}

/// The uniform spp whose RMSE is `e` on the curve `(spp, rmse)` (increasing spp), by log-log
/// interpolation, extrapolated from the last two points past the end and the first two before
/// the start.
///
/// ```
/// use nyquist_examples::adaptive_study::equivalent_spp;
/// let curve = [(16.0, 0.04), (64.0, 0.02), (256.0, 0.01)];
/// assert!((equivalent_spp(&curve, 0.02) - 64.0).abs() < 1e-9);
/// assert!((equivalent_spp(&curve, 0.005) - 1024.0).abs() < 1e-6); // slope −½ continued
/// ```
pub fn equivalent_spp(curve: &[(f64, f64)], e: f64) -> f64 {
    let n = curve.len();
    if n < 2 {
        return f64::NAN;
    }
    // The segment whose RMSE range holds e, else the end segment on e's side.
    let k = (0..n - 1)
        .find(|&k| curve[k].1 >= e && e >= curve[k + 1].1)
        .unwrap_or(if e > curve[0].1 { 0 } else { n - 2 });
    let ((s0, e0), (s1, e1)) = (curve[k], curve[k + 1]);
    let slope = (e1.ln() - e0.ln()) / (s1.ln() - s0.ln());
    (s0.ln() + (e.ln() - e0.ln()) / slope).exp()
}

/// What a study renders beside the uniform curve.
#[derive(Clone, Debug)]
pub struct StudyConfig {
    /// The progressive sampler of every render.
    pub sampler: String,
    /// Budgets (mean spp) of the adaptive and contrast-test renders.
    pub budgets: Vec<u32>,
    /// Thresholds of the adaptive renders, one render per budget and threshold.
    pub thresholds: Vec<f64>,
    /// The adaptive renders' floor.
    pub floor: f64,
    /// Seeds: every configuration is rendered once per seed.
    pub seeds: Vec<u64>,
}

/// The study for `base` (scene, size, filter, threads): the uniform curve of the sampler, adaptive
/// renders at each budget and threshold, and the contrast-test sampler (`adaptive`, spp/4
/// samples then all where they disagree) at the same spp, each over every seed.
/// `progress(done, total)`.
///
/// # Errors
/// A render that fails.
pub fn run(
    base: &RenderConfig,
    study: &StudyConfig,
    reference: &Image,
    mut progress: impl FnMut(usize, usize),
) -> Result<Vec<Measured>> {
    let per_budget = study.thresholds.len() + 1;
    let total = UNIFORM_SPP.len() + per_budget * study.budgets.len();
    let mut done = 0;
    let mut out = Vec::new();
    let mut curve = Vec::new();
    let seeds = &study.seeds;
    for spp in UNIFORM_SPP {
        let (rmse, mean_spp, _, image) =
            measure(base, &study.sampler, spp, None, seeds, reference)?;
        curve.push((mean_spp, rmse));
        out.push(Measured {
            method: "uniform".into(),
            spp,
            mean_spp,
            rmse,
            uniform_equivalent: None,
            report: None,
            image,
        });
        done += 1;
        progress(done, total);
    }
    for &budget in &study.budgets {
        for &threshold in &study.thresholds {
            let config = AdaptiveConfig {
                floor: study.floor,
                ..AdaptiveConfig::new(budget, threshold)
            };
            let (rmse, mean_spp, report, image) =
                measure(base, &study.sampler, budget, Some(config), seeds, reference)?;
            out.push(Measured {
                method: format!("adaptive {threshold}"),
                spp: budget,
                mean_spp,
                rmse,
                uniform_equivalent: Some(equivalent_spp(&curve, rmse)),
                report,
                image,
            });
            done += 1;
            progress(done, total);
        }
        let (rmse, mean_spp, _, image) = measure(base, "adaptive", budget, None, seeds, reference)?;
        out.push(Measured {
            method: "contrast".into(),
            spp: budget,
            mean_spp,
            rmse,
            uniform_equivalent: Some(equivalent_spp(&curve, rmse)),
            report: None,
            image,
        });
        done += 1;
        progress(done, total);
    }
    Ok(out)
}

/// The Markdown table of a study.
pub fn markdown(rows: &[Measured]) -> String {
    let mut s = String::from(
        "| method | spp asked | spp taken (mean) | RMSE | uniform spp for this RMSE | samples saved |\n|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let (eq, saved) = match r.uniform_equivalent {
            Some(u) => (format!("{u:.0}"), format!("{:.2}×", u / r.mean_spp)),
            None => ("-".into(), "-".into()),
        };
        s += &format!(
            "| {} | {} | {:.1} | {:.5} | {eq} | {saved} |\n",
            r.method, r.spp, r.mean_spp, r.rmse
        );
    }
    s
}
