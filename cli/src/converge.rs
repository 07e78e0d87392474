//! `nyquist converge`: how fast each sampler's error falls with the sample count, on the five
//! test integrands of Christensen, Kensler and Kilpatrick, "Progressive Multi-Jittered Sample
//! Sequences" (EGSR 2018): disk, triangle, step, Gaussian and bilinear over the unit square.
//!
//! For every sampler and every power of two `N` from `--min-spp` to `--max-spp`, `--runs`
//! independent copies of the sampler (seeds hashed from `--seed` and the run, never 0) each give
//! the `N` image samples of pixel (0, 0) of a 1 × 1 image; the mean of an integrand over them is
//! one estimate, and `RMSE(N) = √(mean over runs of (estimate − exact)²)`. The slope of
//! `log RMSE` against `log N` (least squares) is the convergence order: −0.5 for independent
//! samples, about −0.75 for stratified samples on the discontinuous integrands, and down to
//! about −1.5 for scrambled nets on the smooth ones.
//!
//! ```
//! use nyquist_cli::converge::{Integrand, Study};
//! let study = Study {
//!     samplers: vec!["random".into()],
//!     integrands: vec![Integrand::Bilinear],
//!     counts: vec![16, 64, 256],
//!     runs: 16,
//!     seed: 7,
//! };
//! let curves = study.run(1).unwrap().curves;
//! assert_eq!(curves.len(), 1);
//! let slope = curves[0].slope.unwrap();
//! assert!((-0.9..-0.2).contains(&slope), "{slope}");
//! ```

use crate::clock::Stopwatch;
use crate::render::{default_threads, json_number, json_string};
use anyhow::{Result, anyhow, bail};
use clap::{Args, ValueEnum};
use nyquist::sampler::{
    Jitter, NAMES, NamedSampler, NamedSamplerError, Sampler, StratifiedSampler,
};
use nyquist_film::CAN_START_THREADS;
use std::path::PathBuf;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

/// erf(1) to the precision of an `f64`; digits from OEIS A099286 ("Decimal expansion of
/// erf(1)": 0.84270079294971486934…), checked in the tests against its Maclaurin series.
pub const ERF_1: f64 = 0.842_700_792_949_714_869_341_220_635_082_6;

/// The largest `--max-spp`.
pub const MAX_SPP: u32 = 1 << 20;
/// The most samples one study may take in all (samplers × runs × the sum of the counts).
pub const MAX_SAMPLES: u64 = 1 << 32;

/// The five test integrands over `[0, 1)²`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Integrand {
    /// 1 inside the quarter disk x² + y² < 2/π, else 0 (exact integral ½).
    Disk,
    /// 1 where y < x, else 0 (exact integral ½).
    Triangle,
    /// 1 where x < 1/π, else 0 (exact integral 1/π).
    Step,
    /// exp(−x² − y²) (exact integral (√π/2 · erf 1)²).
    Gaussian,
    /// x · y (exact integral ¼).
    Bilinear,
}

impl Integrand {
    /// All five, in the order of the paper.
    pub const ALL: [Integrand; 5] = [
        Integrand::Disk,
        Integrand::Triangle,
        Integrand::Step,
        Integrand::Gaussian,
        Integrand::Bilinear,
    ];

    /// The command-line name.
    ///
    /// ```
    /// assert_eq!(nyquist_cli::converge::Integrand::Gaussian.name(), "gaussian");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Integrand::Disk => "disk",
            Integrand::Triangle => "triangle",
            Integrand::Step => "step",
            Integrand::Gaussian => "gaussian",
            Integrand::Bilinear => "bilinear",
        }
    }

    /// The function, as the plot captions it.
    pub fn formula(self) -> &'static str {
        match self {
            Integrand::Disk => "1 where x² + y² < 2/π",
            Integrand::Triangle => "1 where y < x",
            Integrand::Step => "1 where x < 1/π",
            Integrand::Gaussian => "exp(−x² − y²)",
            Integrand::Bilinear => "x·y",
        }
    }

    /// The integrand at `(x, y)`.
    ///
    /// ```
    /// use nyquist_cli::converge::Integrand;
    /// assert_eq!(Integrand::Disk.eval(0.5, 0.5), 1.0); // 0.5 < 2/π ≈ 0.64
    /// assert_eq!(Integrand::Triangle.eval(0.2, 0.3), 0.0);
    /// assert_eq!(Integrand::Bilinear.eval(0.5, 0.25), 0.125);
    /// ```
    #[inline]
    pub fn eval(self, x: f64, y: f64) -> f64 {
        let indicator = |inside: bool| if inside { 1.0 } else { 0.0 };
        match self {
            Integrand::Disk => indicator(x * x + y * y < 2.0 / std::f64::consts::PI),
            Integrand::Triangle => indicator(y < x),
            Integrand::Step => indicator(x < std::f64::consts::FRAC_1_PI),
            Integrand::Gaussian => libm::exp(-x * x - y * y),
            Integrand::Bilinear => x * y,
        }
    }

    /// The exact integral over `[0, 1)²`: the quarter disk of radius² 2/π has area
    /// π · (2/π) / 4 = ½; the triangle ½; the step 1/π; the Gaussian separates into
    /// (∫₀¹ e^(−x²) dx)² = (√π/2 · erf 1)²; the bilinear (½)².
    ///
    /// ```
    /// use nyquist_cli::converge::Integrand;
    /// assert_eq!(Integrand::Disk.reference(), 0.5);
    /// assert!((Integrand::Gaussian.reference() - 0.557_746_285).abs() < 1e-9);
    /// ```
    pub fn reference(self) -> f64 {
        match self {
            Integrand::Disk | Integrand::Triangle => 0.5,
            Integrand::Step => std::f64::consts::FRAC_1_PI,
            Integrand::Gaussian => {
                let g = 0.5 * std::f64::consts::PI.sqrt() * ERF_1;
                g * g
            }
            Integrand::Bilinear => 0.25,
        }
    }
}

/// Sampler `name` for `n` samples of a 1 × 1 image with `seed`, as [`NamedSampler::new`]
/// builds it, except that `stratified` and `uniform` also take an `n` that is not a square: a
/// `nx × ny` grid with `ny` the largest divisor of `n` not above √n (for `n = 2^m`:
/// `2^⌈m/2⌉ × 2^⌊m/2⌋`), so every sampler takes every power of two.
///
/// ```
/// use nyquist::sampler::Sampler;
/// use nyquist_cli::converge::build_sampler;
/// assert_eq!(build_sampler("stratified", 32, 1).unwrap().samples_per_pixel(), 32);
/// assert!(build_sampler("nope", 32, 1).is_err());
/// ```
///
/// # Errors
/// Whatever [`NamedSampler::new`] rejects (e.g. [`NamedSamplerError::UnknownName`]).
pub fn build_sampler(name: &str, n: u32, seed: u64) -> Result<NamedSampler, NamedSamplerError> {
    match NamedSampler::new(name, [1, 1], n, seed) {
        Err(NamedSamplerError::NotSquare { .. }) if matches!(name, "stratified" | "uniform") => {
            let [nx, ny] = strata(n);
            let jitter = if name == "uniform" {
                Jitter::Centered
            } else {
                Jitter::Jittered
            };
            Ok(NamedSampler::Stratified(StratifiedSampler::new(
                nx, ny, jitter, seed,
            )?))
        }
        r => r,
    }
}

/// The strata grid `[nx, ny]` of [`build_sampler`] for `n` samples: `ny` the largest divisor
/// of `n` with `ny² ≤ n`, `nx = n / ny`.
///
/// ```
/// assert_eq!(nyquist_cli::converge::strata(32), [8, 4]);
/// assert_eq!(nyquist_cli::converge::strata(64), [8, 8]);
/// assert_eq!(nyquist_cli::converge::strata(7), [7, 1]);
/// ```
pub fn strata(n: u32) -> [u32; 2] {
    let ny = (1..=n.max(1).isqrt())
        .rev()
        .find(|&d| n.is_multiple_of(d))
        .unwrap_or(1);
    [n / ny, ny]
}

/// The seed of run `run`: a hash of the base seed and the run, never 0 (0 means "not
/// scrambled" to some samplers).
///
/// ```
/// use nyquist_cli::converge::run_seed;
/// assert_ne!(run_seed(0, 0), 0);
/// assert_ne!(run_seed(0, 0), run_seed(0, 1));
/// assert_ne!(run_seed(0, 1), run_seed(1, 1));
/// ```
pub fn run_seed(seed: u64, run: u32) -> u64 {
    nyquist::hash::hash2(seed, u64::from(run)).max(1)
}

/// Takes the sampler's image samples of pixel (0, 0) and writes the mean of each integrand
/// over them to `out` (one entry per integrand); returns the sample count.
///
/// ```
/// use nyquist_cli::converge::{Integrand, build_sampler, estimate};
/// let mut s = build_sampler("stratified", 4, 1).unwrap();
/// let mut out = [0.0];
/// assert_eq!(estimate(&mut s, &[Integrand::Step], &mut out), 4);
/// assert!((0.0..=1.0).contains(&out[0]));
/// ```
pub fn estimate(sampler: &mut NamedSampler, integrands: &[Integrand], out: &mut [f64]) -> u32 {
    let n = sampler.samples_per_pixel();
    out.fill(0.0);
    for i in 0..n {
        sampler.start_pixel_sample([0, 0], i, 0);
        let [x, y] = sampler.get_pixel_2d();
        let (x, y) = (f64::from(x), f64::from(y));
        for (o, f) in out.iter_mut().zip(integrands) {
            *o += f.eval(x, y);
        }
    }
    for o in out.iter_mut() {
        *o /= f64::from(n.max(1));
    }
    n
}

/// The least-squares slope of `ln y` against `ln x` over the points `(x, y)`; `None` when
/// there are fewer than two points, a value is not finite and positive, or all `x` are equal.
///
/// ```
/// use nyquist_cli::converge::fit_slope;
/// let pts: Vec<(f64, f64)> = [16.0, 64.0, 256.0].iter().map(|&n: &f64| (n, 2.0 / n.sqrt())).collect();
/// assert!((fit_slope(&pts).unwrap() + 0.5).abs() < 1e-12);
/// assert_eq!(fit_slope(&[(16.0, 0.1), (32.0, 0.0)]), None);
/// ```
pub fn fit_slope(points: &[(f64, f64)]) -> Option<f64> {
    if points.len() < 2
        || points
            .iter()
            .any(|&(x, y)| !(x.is_finite() && y.is_finite() && x > 0.0 && y > 0.0))
    {
        return None;
    }
    let n = points.len() as f64;
    let mx = points.iter().map(|p| libm::log(p.0)).sum::<f64>() / n;
    let my = points.iter().map(|p| libm::log(p.1)).sum::<f64>() / n;
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for &(x, y) in points {
        let dx = libm::log(x) - mx;
        sxy += dx * (libm::log(y) - my);
        sxx += dx * dx;
    }
    (sxx > 0.0).then(|| sxy / sxx)
}

/// The powers of two from `min` to `max` (both powers of two, `min ≤ max`).
///
/// ```
/// assert_eq!(nyquist_cli::converge::powers_of_two(16, 128), [16, 32, 64, 128]);
/// ```
pub fn powers_of_two(min: u32, max: u32) -> Vec<u32> {
    let mut v = Vec::new();
    let mut n = u64::from(min.max(1));
    while n <= u64::from(max) {
        v.push(n as u32);
        n *= 2;
    }
    v
}

/// One convergence study: every sampler at every count, `runs` times.
#[derive(Clone, Debug)]
pub struct Study {
    /// Sampler names (as [`NamedSampler::new`] takes them).
    pub samplers: Vec<String>,
    /// The integrands, each estimated from the same samples.
    pub integrands: Vec<Integrand>,
    /// Sample counts `N` asked for, increasing.
    pub counts: Vec<u32>,
    /// Independent runs per sampler and count.
    pub runs: u32,
    /// Base seed; run `r` uses [`run_seed`]`(seed, r)`.
    pub seed: u64,
}

/// RMSE against `N` of one sampler on one integrand.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    /// Sampler name.
    pub sampler: String,
    /// The integrand.
    pub integrand: Integrand,
    /// Samples per pixel the sampler used at each count (differs from the count asked for
    /// where a sampler rounds).
    pub spp: Vec<u32>,
    /// RMSE over the runs at each count.
    pub rmse: Vec<f64>,
    /// Least-squares slope of log RMSE against log spp ([`fit_slope`]).
    pub slope: Option<f64>,
}

/// What [`Study::run`] returns.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// One curve per sampler and integrand, sampler-major in the study's orders.
    pub curves: Vec<Curve>,
    /// Samples taken in all.
    pub samples: u64,
}

impl Study {
    /// Samples the study takes: samplers × runs × the sum of the counts (saturating).
    ///
    /// ```
    /// use nyquist_cli::converge::{Integrand, Study};
    /// let s = Study { samplers: vec!["random".into(); 2], integrands: vec![Integrand::Disk],
    ///                 counts: vec![16, 32], runs: 10, seed: 0 };
    /// assert_eq!(s.work(), 2 * 10 * 48);
    /// ```
    pub fn work(&self) -> u64 {
        let per_run: u64 = self.counts.iter().map(|&n| u64::from(n)).sum();
        per_run
            .saturating_mul(u64::from(self.runs))
            .saturating_mul(self.samplers.len() as u64)
    }

    /// Builds every sampler at every count (with run 0's seed), so that a name or count a
    /// sampler rejects is an error before any work; returns the spp each uses, sampler-major.
    ///
    /// # Errors
    /// One line naming the sampler and count, e.g. `--samplers nope: unknown sampler name`.
    pub fn check(&self) -> Result<Vec<Vec<u32>>> {
        let seed = run_seed(self.seed, 0);
        self.samplers
            .iter()
            .map(|name| {
                self.counts
                    .iter()
                    .map(|&n| {
                        if let Some(max) = crate::render::spp_limit(name)
                            && n > max
                        {
                            bail!(
                                "--samplers {name} at {n} spp: {name} takes at most {max} \
                                 samples per pixel (give --max-spp {max} or less)"
                            );
                        }
                        build_sampler(name, n, seed)
                            .map(|s| s.samples_per_pixel())
                            .map_err(|e| match e {
                                NamedSamplerError::UnknownName => anyhow!(
                                    "--samplers {name}: unknown sampler (known: {})",
                                    NAMES.join(", ")
                                ),
                                e => anyhow!("--samplers {name} at {n} spp: {e}"),
                            })
                    })
                    .collect()
            })
            .collect()
    }

    /// Runs the study on `threads` threads. The result depends on the study only, not on the
    /// thread count: every (sampler, count, run) is one independent task with its own seed,
    /// and the squared errors are summed in run order afterwards.
    ///
    /// # Errors
    /// As [`Study::check`].
    pub fn run(&self, threads: usize) -> Result<Outcome> {
        self.run_with_progress(threads, &|_, _| {})
    }

    /// [`Study::run`], calling `progress(done, total)` after each (sampler, count, run) task
    /// (from the worker threads; on the calling thread when `threads` is 1, which starts no
    /// thread at all).
    ///
    /// ```
    /// use nyquist_cli::converge::{Integrand, Study};
    /// use std::sync::atomic::{AtomicUsize, Ordering};
    /// let s = Study { samplers: vec!["random".into()], integrands: vec![Integrand::Disk],
    ///                 counts: vec![16, 32], runs: 3, seed: 0 };
    /// let calls = AtomicUsize::new(0);
    /// let o = s.run_with_progress(1, &|_, total| { calls.fetch_add(1, Ordering::Relaxed); assert_eq!(total, 6); })
    ///     .unwrap();
    /// assert_eq!(calls.into_inner(), 6);
    /// assert_eq!(o.curves, s.run(2).unwrap().curves);
    /// ```
    ///
    /// # Errors
    /// As [`Study::check`].
    pub fn run_with_progress(
        &self,
        threads: usize,
        progress: &(dyn Fn(usize, usize) + Sync),
    ) -> Result<Outcome> {
        let spp = self.check()?;
        let (ns, nc, nr, ni) = (
            self.samplers.len(),
            self.counts.len(),
            self.runs as usize,
            self.integrands.len(),
        );
        let tasks = ns * nc * nr;
        let mut estimates = vec![0.0f64; tasks * ni];
        let failure: Mutex<Option<anyhow::Error>> = Mutex::new(None);
        {
            // Largest counts first, so the last tasks handed out are short.
            let mut queue: Vec<(usize, &mut [f64])> =
                estimates.chunks_mut(ni.max(1)).enumerate().collect();
            // Ties by task index: the order a stable sort gives, without a stable sort's code.
            queue.sort_unstable_by_key(|(t, _)| (self.counts[(t / nr) % nc], *t));
            let queue = Mutex::new(queue);
            let done = AtomicUsize::new(0);
            let work = || {
                while let Some((t, out)) = queue.lock().ok().and_then(|mut q| q.pop()) {
                    let (s, c, r) = (t / (nc * nr), (t / nr) % nc, t % nr);
                    let seed = run_seed(self.seed, r as u32);
                    match build_sampler(&self.samplers[s], self.counts[c], seed) {
                        Ok(mut sampler) => {
                            estimate(&mut sampler, &self.integrands, out);
                        }
                        Err(e) => {
                            if let Ok(mut f) = failure.lock() {
                                f.get_or_insert_with(|| {
                                    anyhow!(
                                        "--samplers {} at {} spp, seed {seed}: {e}",
                                        self.samplers[s],
                                        self.counts[c]
                                    )
                                });
                            }
                            break;
                        }
                    }
                    progress(done.fetch_add(1, Ordering::Relaxed) + 1, tasks);
                }
            };
            if threads <= 1 || !CAN_START_THREADS {
                work();
            } else {
                std::thread::scope(|scope| {
                    for _ in 0..threads.min(tasks.max(1)) {
                        scope.spawn(work);
                    }
                });
            }
        }
        if let Some(e) = failure.into_inner().ok().flatten() {
            return Err(e);
        }
        let mut curves = Vec::with_capacity(ns * ni);
        let mut samples = 0u64;
        for (s, name) in self.samplers.iter().enumerate() {
            for c in 0..nc {
                samples += u64::from(spp[s][c]) * nr as u64;
            }
            for (i, &integrand) in self.integrands.iter().enumerate() {
                let exact = integrand.reference();
                let rmse: Vec<f64> = (0..nc)
                    .map(|c| {
                        let base = (s * nc + c) * nr;
                        let sum: f64 = (0..nr)
                            .map(|r| {
                                let e = estimates[(base + r) * ni + i] - exact;
                                e * e
                            })
                            .sum();
                        (sum / nr.max(1) as f64).sqrt()
                    })
                    .collect();
                let points: Vec<(f64, f64)> = spp[s]
                    .iter()
                    .zip(&rmse)
                    .map(|(&n, &e)| (f64::from(n), e))
                    .collect();
                curves.push(Curve {
                    sampler: name.clone(),
                    integrand,
                    spp: spp[s].clone(),
                    rmse,
                    slope: fit_slope(&points),
                });
            }
        }
        Ok(Outcome { curves, samples })
    }
}

/// The samplers `converge` studies by default: every name [`NamedSampler::new`] knows except
/// `uniform` (no randomness: every run is the same) and `adaptive` (it needs radiance reports;
/// without them it is `zero-two`).
pub fn default_samplers() -> Vec<String> {
    NAMES
        .iter()
        .filter(|n| !matches!(**n, "uniform" | "adaptive"))
        .map(|n| (*n).to_owned())
        .collect()
}

/// Arguments of `nyquist converge`.
#[derive(Debug, Args)]
#[command(
    after_help = "Example: nyquist converge --samplers random,stratified,sobol \
    --integrands disk,triangle,step,gaussian,bilinear --max-spp 4096 --runs 64 --plot converge.png"
)]
pub struct ConvergeArgs {
    /// Samplers, comma-separated (names as in `render --sampler`) [default: every sampler except
    /// uniform and adaptive]. `stratified` takes every power of two as a 2^⌈m/2⌉ × 2^⌊m/2⌋ grid.
    /// best-candidate takes at most 4096 spp and pmj02 at most 65536: above that, the default
    /// list leaves them out with a note, and naming them is an error.
    #[arg(long, value_delimiter = ',', value_name = "LIST")]
    pub samplers: Vec<String>,
    /// Integrands, comma-separated.
    #[arg(
        long,
        value_enum,
        value_delimiter = ',',
        value_name = "LIST",
        default_value = "disk,triangle,step,gaussian,bilinear"
    )]
    pub integrands: Vec<Integrand>,
    /// Smallest sample count N (a power of two).
    #[arg(long, value_name = "N", default_value_t = 16)]
    pub min_spp: u32,
    /// Largest sample count N (a power of two, at most 2^20); the study takes every power of two
    /// from --min-spp to --max-spp.
    #[arg(long, value_name = "N", default_value_t = 4096)]
    pub max_spp: u32,
    /// Independent runs (scrambles) per sampler and N.
    #[arg(long, default_value_t = 64, value_parser = clap::value_parser!(u32).range(1..=1 << 20))]
    pub runs: u32,
    /// Base seed: run r uses a hash of (seed, r).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Worker threads [default: the number of cores]; the numbers do not depend on it.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=1024))]
    pub threads: Option<u16>,
    /// Also draw RMSE against N, log-log, one panel per integrand and one line per sampler,
    /// each panel with a legend of the samplers' slopes: SVG for FILE.svg, PNG for FILE.png.
    #[arg(long, value_name = "FILE.png|FILE.svg")]
    pub plot: Option<PathBuf>,
    /// Print JSON (slopes and every RMSE) instead of the Markdown table.
    #[arg(long)]
    pub json: bool,
    /// Instead of the 2-D integrands, Genz's six test families in D dimensions (2 … 64; e.g.
    /// 4, 16, 64), with fixed parameters and exact integrals; the samplers also take
    /// halton-plain and sobol-plain (unscrambled). Prints a table of slopes and relative RMSE;
    /// --integrands, --plot and --json do not apply.
    #[arg(long, value_name = "D", value_parser = clap::value_parser!(u32).range(2..=64))]
    pub dims: Option<u32>,
}

/// Checks the flags and turns them into a study.
fn study_of(args: &ConvergeArgs) -> Result<Study> {
    let mut samplers = if args.samplers.is_empty() {
        default_samplers()
    } else {
        args.samplers.iter().map(|s| s.trim().to_owned()).collect()
    };
    for (i, s) in samplers.iter().enumerate() {
        if s.is_empty() {
            bail!("--samplers: empty sampler name (e.g. random,stratified)");
        }
        if samplers[..i].contains(s) {
            bail!("--samplers: {s} is given twice");
        }
    }
    for (i, f) in args.integrands.iter().enumerate() {
        if args.integrands[..i].contains(f) {
            bail!("--integrands: {} is given twice", f.name());
        }
    }
    for (flag, n) in [("--min-spp", args.min_spp), ("--max-spp", args.max_spp)] {
        if !n.is_power_of_two() {
            bail!("{flag} {n}: not a power of two (1, 2, 4, …, 16, …, 4096, …)");
        }
        if n > MAX_SPP {
            bail!("{flag} {n}: at most {MAX_SPP}");
        }
    }
    if args.min_spp >= args.max_spp {
        bail!(
            "--min-spp {} --max-spp {}: need at least two sample counts to fit a slope",
            args.min_spp,
            args.max_spp
        );
    }
    // A default sampler whose limit is below --max-spp is left out, with a note once every
    // flag is checked; named in --samplers it is an error.
    let mut left_out = Vec::new();
    if args.samplers.is_empty() {
        samplers.retain(|name| match crate::render::spp_limit(name) {
            Some(max) if args.max_spp > max => {
                left_out.push(format!(
                    "--max-spp {}: {name} takes at most {max} samples per pixel; left out of \
                     the study",
                    args.max_spp
                ));
                false
            }
            _ => true,
        });
    }
    let study = Study {
        samplers,
        integrands: args.integrands.clone(),
        counts: powers_of_two(args.min_spp, args.max_spp),
        runs: args.runs,
        seed: args.seed,
    };
    if study.work() > MAX_SAMPLES {
        bail!(
            "{} samplers × {} runs × N = {}..{} is {} samples; at most {MAX_SAMPLES}",
            study.samplers.len(),
            study.runs,
            args.min_spp,
            args.max_spp,
            study.work()
        );
    }
    left_out.iter().for_each(|n| crate::output::note(n));
    Ok(study)
}

/// Runs `nyquist converge`.
pub fn run(args: &ConvergeArgs) -> Result<()> {
    if let Some(dims) = args.dims {
        return crate::genz::run(args, dims);
    }
    if let Some(p) = &args.plot {
        crate::plot::kind_of(p, "--plot")?;
    }
    let study = study_of(args)?;
    study.check()?;
    let threads = args.threads.map_or_else(default_threads, usize::from);
    let start = Stopwatch::start();
    let outcome = study.run(threads)?;
    let seconds = start.seconds();
    if let Some(p) = &args.plot {
        let figure = Plot {
            study: &study,
            curves: &outcome.curves,
        };
        crate::plot::save(&figure, p, "--plot")?;
    }
    let text = if args.json {
        json(&study, &outcome, args, threads, seconds)
    } else {
        table(&study, &outcome, args, threads, seconds)
    };
    crate::output::to_stdout_or_file(None, |w| {
        w.write_all(text.as_bytes())?;
        Ok(())
    })
}

/// The study `nyquist converge ARGS --json` prints (without `--dims`), run on `threads` threads
/// with `progress(done, total)` after each task; the same numbers whatever the thread count.
///
/// ```
/// use clap::Parser;
/// #[derive(Parser)]
/// struct Cli { #[command(flatten)] a: nyquist_cli::converge::ConvergeArgs }
/// let cli = Cli::parse_from(["x", "--samplers", "stratified", "--integrands", "disk",
///                            "--min-spp", "16", "--max-spp", "256", "--runs", "8"]);
/// let json = nyquist_cli::converge::json_report(&cli.a, 1, &|_, _| {}).unwrap();
/// assert!(json.starts_with("{\"runs\":8,") && json.contains("\"sampler\":\"stratified\""));
/// ```
///
/// # Errors
/// As `nyquist converge` reports them (one line naming the flag).
pub fn json_report(
    args: &ConvergeArgs,
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<String> {
    if args.dims.is_some() {
        bail!("--dims: Genz's study prints a table only");
    }
    let study = study_of(args)?;
    let start = Stopwatch::start();
    let outcome = study.run_with_progress(threads, progress)?;
    Ok(json(&study, &outcome, args, threads, start.seconds()))
}

/// A slope for the table: two decimals, or `-` where there is none.
fn slope_text(s: Option<f64>) -> String {
    s.map_or_else(|| "-".to_owned(), |s| format!("{s:.2}"))
}

/// The Markdown table: one row per sampler, per integrand the slope and the RMSE at the
/// largest N.
fn table(study: &Study, o: &Outcome, args: &ConvergeArgs, threads: usize, seconds: f64) -> String {
    let mut s = format!(
        "Slope of log RMSE against log N (least squares over N = {}, {}, …, {}; {} independent runs \
         per N, seeds hashed from --seed {}), with the RMSE at N = {} in brackets{}\n\n",
        args.min_spp,
        2 * args.min_spp,
        args.max_spp,
        study.runs,
        study.seed,
        args.max_spp,
        args.plot
            .as_ref()
            .map_or_else(String::new, |p| format!("; plot: {}", p.display()))
    );
    s.push_str("| sampler |");
    let mut rule = String::from("|---|");
    for f in &study.integrands {
        s.push_str(&format!(" {} |", f.name()));
        rule.push_str("---:|");
    }
    s.push('\n');
    s.push_str(&rule);
    s.push('\n');
    let ni = study.integrands.len();
    for row in o.curves.chunks(ni.max(1)) {
        let Some(first) = row.first() else { continue };
        s.push_str(&format!("| {} |", first.sampler));
        for c in row {
            let last = c.rmse.last().copied().unwrap_or(f64::NAN);
            s.push_str(&format!(" {} ({last:.1e}) |", slope_text(c.slope)));
        }
        s.push('\n');
    }
    let rounded: Vec<String> = o
        .curves
        .chunks(ni.max(1))
        .filter_map(|row| row.first())
        .filter(|c| c.spp != study.counts)
        .map(|c| {
            format!(
                "{} uses {} spp",
                c.sampler,
                c.spp
                    .iter()
                    .map(u32::to_string)
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        })
        .collect();
    s.push('\n');
    if !rounded.is_empty() {
        s.push_str(&format!(
            "Rounded sample counts (slopes fit the counts used): {}\n",
            rounded.join("; ")
        ));
    }
    s.push_str(&format!(
        "Exact integrals: {}\n",
        study
            .integrands
            .iter()
            .map(|f| format!("{} {:.6}", f.name(), f.reference()))
            .collect::<Vec<_>>()
            .join(", ")
    ));
    s.push_str(&format!(
        "{} samplers × {} N × {} runs: {:.1} M samples in {seconds:.2} s on {threads} thread{}\n",
        study.samplers.len(),
        study.counts.len(),
        study.runs,
        o.samples as f64 / 1e6,
        if threads == 1 { "" } else { "s" }
    ));
    s
}

/// One JSON object: the study, the exact integrals and every curve.
fn json(study: &Study, o: &Outcome, args: &ConvergeArgs, threads: usize, seconds: f64) -> String {
    let list = |v: Vec<String>| v.join(",");
    let integrands = list(
        study
            .integrands
            .iter()
            .map(|f| {
                format!(
                    "{{\"name\":{},\"reference\":{}}}",
                    json_string(f.name()),
                    json_number(f.reference())
                )
            })
            .collect(),
    );
    let curves = list(
        o.curves
            .iter()
            .map(|c| {
                format!(
                    "{{\"sampler\":{},\"integrand\":{},\"slope\":{},\"spp\":[{}],\"rmse\":[{}]}}",
                    json_string(&c.sampler),
                    json_string(c.integrand.name()),
                    c.slope.map_or_else(|| "null".to_owned(), json_number),
                    list(c.spp.iter().map(u32::to_string).collect()),
                    list(c.rmse.iter().map(|&e| json_number(e)).collect()),
                )
            })
            .collect(),
    );
    format!(
        "{{\"runs\":{},\"seed\":{},\"min_spp\":{},\"max_spp\":{},\"counts\":[{}],\"plot\":{},\"threads\":{threads},\"seconds\":{},\"samples\":{},\"integrands\":[{integrands}],\"curves\":[{curves}]}}\n",
        study.runs,
        study.seed,
        args.min_spp,
        args.max_spp,
        list(study.counts.iter().map(u32::to_string).collect()),
        args.plot
            .as_ref()
            .map_or_else(|| "null".to_owned(), |p| json_string(&p.to_string_lossy())),
        json_number(seconds),
        o.samples,
    )
}

/// Width of one panel of the plot: the log-log chart and its legend beside it.
pub const PANEL_W: u32 = 640;
/// Height of one panel of the plot.
pub const PANEL_H: u32 = 380;
/// Width of a panel's legend.
const LEGEND_W: u32 = 190;
/// Margin around the plot and between panels.
const MARGIN: u32 = 16;
/// Panels per row.
const COLUMNS: u32 = 3;
/// Pixels of the title block at the top: the command (up to three lines) and the notes (two).
const HEADER_H: u32 = 96;

/// The plot's size for `integrands` panels: at most three panels across.
///
/// ```
/// use nyquist_cli::converge::{plot_size, PANEL_W, PANEL_H};
/// assert_eq!(plot_size(5), [16 + 3 * (PANEL_W + 16), 16 + 96 + 2 * (PANEL_H + 16)]);
/// assert_eq!(plot_size(1), [16 + PANEL_W + 16, 16 + 96 + PANEL_H + 16]);
/// ```
pub fn plot_size(integrands: usize) -> [u32; 2] {
    let cells = (integrands as u32).max(1);
    let cols = cells.min(COLUMNS);
    let rows = cells.div_ceil(cols);
    [
        MARGIN + cols * (PANEL_W + MARGIN),
        MARGIN + HEADER_H + rows * (PANEL_H + MARGIN),
    ]
}

/// The command line that reproduces a study (every flag written out), the plot's title.
///
/// ```
/// use nyquist_cli::converge::{Integrand, Study, command};
/// let s = Study { samplers: vec!["random".into()], integrands: vec![Integrand::Disk],
///                 counts: vec![16, 32], runs: 8, seed: 1 };
/// assert_eq!(command(&s), "nyquist converge --samplers random --integrands disk \
///     --min-spp 16 --max-spp 32 --runs 8 --seed 1");
/// ```
pub fn command(study: &Study) -> String {
    format!(
        "nyquist converge --samplers {} --integrands {} --min-spp {} --max-spp {} --runs {} --seed {}",
        study.samplers.join(","),
        study
            .integrands
            .iter()
            .map(|f| f.name())
            .collect::<Vec<_>>()
            .join(","),
        study.counts.first().copied().unwrap_or(1),
        study.counts.last().copied().unwrap_or(1),
        study.runs,
        study.seed
    )
}

/// The convergence plot: per integrand a log-log panel of RMSE against N (decade ticks with
/// 2..9 minors, dashed N^−½ and N^−1 guides) with a legend beside it giving each sampler's
/// colour, marker and fitted slope.
#[derive(Debug)]
pub struct Plot<'a> {
    /// The study the curves come from.
    pub study: &'a Study,
    /// Its curves.
    pub curves: &'a [Curve],
}

#[cfg(not(target_family = "wasm"))]
impl crate::plot::Figure for Plot<'_> {
    fn size(&self) -> (u32, u32) {
        let [w, h] = plot_size(self.study.integrands.len());
        (w, h)
    }

    fn draw<DB: plotters::prelude::DrawingBackend>(
        &self,
        root: &plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    ) -> Result<Vec<crate::plot::Raster>>
    where
        DB::ErrorType: 'static,
    {
        use crate::plot::{Axes, GUIDE, INK, bold, color, font, marker, panel, title, wrap};
        use plotters::prelude::*;
        use plotters::style::text_anchor::{HPos, Pos, VPos};
        let study = self.study;
        let (w, _) = self.size();
        // The command in up to three lines, smaller when it is long.
        let m = MARGIN as i32;
        let sizes = [(18.0, 2), (14.0, 3)];
        let mut y = m + title(root, &command(study), (m, m), w - 2 * MARGIN, &sizes)?;
        let notes = format!(
            "RMSE of the mean over N samples against N, {} independent runs per N; slope: \
             least-squares fit of log RMSE on log N; grey dashed: slopes −1/2 and −1 for scale",
            study.runs
        );
        for line in wrap(&notes, w - 2 * MARGIN, 13.0).iter().take(2) {
            root.draw_text(line, &font(13.0).color(&INK), (m, y + 2))?;
            y += 17;
        }
        let ni = study.integrands.len();
        let cols = (ni as u32).clamp(1, COLUMNS);
        for (i, &integrand) in study.integrands.iter().enumerate() {
            let (col, row) = (i as u32 % cols, i as u32 / cols);
            let ox = (MARGIN + col * (PANEL_W + MARGIN)) as i32;
            let oy = (MARGIN + HEADER_H + row * (PANEL_H + MARGIN)) as i32;
            let cell = root.clone().shrink((ox, oy), (PANEL_W, PANEL_H));
            let (chart_area, legend) = cell.split_horizontally(PANEL_W - LEGEND_W);
            let mine: Vec<&Curve> = self
                .curves
                .iter()
                .filter(|c| c.integrand == integrand)
                .collect();
            let finite = |c: &Curve| {
                c.spp
                    .iter()
                    .zip(&c.rmse)
                    .filter(|&(_, &e)| e.is_finite() && e > 0.0)
                    .map(|(&n, &e)| (f64::from(n).log10(), e.log10()))
                    .collect::<Vec<_>>()
            };
            let all: Vec<(f64, f64)> = mine.iter().flat_map(|c| finite(c)).collect();
            let (mut x0, mut x1, mut y0, mut y1) = all.iter().fold(
                (
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                ),
                |(a, b, c, d), &(x, y)| (a.min(x), b.max(x), c.min(y), d.max(y)),
            );
            if !(x0.is_finite() && y0.is_finite()) {
                let n = study.counts.first().copied().unwrap_or(1).max(1);
                let m = study.counts.last().copied().unwrap_or(2).max(n + 1);
                (x0, x1, y0, y1) = (f64::from(n).log10(), f64::from(m).log10(), -2.0, -1.0);
            }
            // Guides of slope −½ and −1 from just above the highest first point, so that
            // they run above the curves' start and read as a scale, not as data.
            let guide_y = mine
                .iter()
                .filter_map(|c| finite(c).first().map(|p| p.1))
                .fold(f64::NEG_INFINITY, f64::max)
                + 0.15;
            if guide_y.is_finite() {
                y1 = y1.max(guide_y);
            }
            let (xpad, ypad) = (0.04 * (x1 - x0).max(0.3), 0.06 * (y1 - y0).max(0.5));
            let mut axes = Axes::log_log(
                10f64.powf(x0 - xpad)..10f64.powf(x1 + xpad),
                10f64.powf(y0 - ypad)..10f64.powf(y1 + ypad),
            );
            axes.caption = format!("{}: {}", integrand.name(), integrand.formula());
            axes.x_desc = "N (samples)".to_owned();
            axes.y_desc = "RMSE".to_owned();
            let mut chart = panel(&chart_area, &axes)?;
            if guide_y.is_finite() {
                for slope in [-0.5, -1.0] {
                    // Clipped at the bottom of the panel.
                    let end_x = x1.min(x0 + (guide_y - axes.y.start) / -slope);
                    let (a, b) = ((x0, guide_y), (end_x, guide_y + slope * (end_x - x0)));
                    chart.draw_series(DashedLineSeries::new(
                        [a, b],
                        6,
                        4,
                        GUIDE.stroke_width(1),
                    ))?;
                }
            }
            for (k, curve) in mine.iter().enumerate() {
                let s = study
                    .samplers
                    .iter()
                    .position(|s| *s == curve.sampler)
                    .unwrap_or(k);
                let pts = finite(curve);
                chart.draw_series(LineSeries::new(
                    pts.iter().copied(),
                    color(s).stroke_width(2),
                ))?;
                for p in &pts {
                    marker(root, chart.backend_coord(p), s, color(s))?;
                }
            }
            // Legend: colour, marker, name and slope of each sampler.
            let (lx, ly) = (10, 12);
            legend.draw_text("sampler", &bold(13.0).color(&INK), (lx, ly))?;
            legend.draw_text(
                "slope",
                &bold(13.0).color(&INK).pos(Pos::new(HPos::Right, VPos::Top)),
                (LEGEND_W as i32 - 8, ly),
            )?;
            let base = legend.get_base_pixel();
            for (k, curve) in mine.iter().enumerate() {
                let s = study
                    .samplers
                    .iter()
                    .position(|s| *s == curve.sampler)
                    .unwrap_or(k);
                let row_y = ly + 22 + 19 * k as i32;
                let mid = row_y + 7;
                legend.draw(&PathElement::new(
                    vec![(lx, mid), (lx + 24, mid)],
                    color(s).stroke_width(2),
                ))?;
                marker(root, (base.0 + lx + 12, base.1 + mid), s, color(s))?;
                legend.draw_text(&curve.sampler, &font(13.0).color(&INK), (lx + 30, row_y))?;
                legend.draw_text(
                    &curve
                        .slope
                        .map_or_else(|| "n/a".to_owned(), |v| format!("{v:.2}").replace('-', "−")),
                    &font(13.0)
                        .color(&color(s))
                        .pos(Pos::new(HPos::Right, VPos::Top)),
                    (LEGEND_W as i32 - 8, row_y),
                )?;
            }
        }
        Ok(Vec::new())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// erf(1) by its Maclaurin series 2/√π · Σ (−1)ⁿ / (n! (2n + 1)).
    fn erf_1_series() -> f64 {
        let mut sum = 0.0;
        let mut term = 1.0; // (−1)ⁿ / n!
        for n in 0..30 {
            sum += term / f64::from(2 * n + 1);
            term *= -1.0 / f64::from(n + 1);
        }
        2.0 / std::f64::consts::PI.sqrt() * sum
    }

    #[test]
    fn erf_1_matches_its_series() {
        assert!((ERF_1 - erf_1_series()).abs() < 1e-15, "{}", erf_1_series());
    }

    /// The midpoint rule on a `k × k` grid.
    fn midpoint(f: Integrand, k: u32) -> f64 {
        let h = 1.0 / f64::from(k);
        let mut sum = 0.0;
        for j in 0..k {
            for i in 0..k {
                sum += f.eval((f64::from(i) + 0.5) * h, (f64::from(j) + 0.5) * h);
            }
        }
        sum * h * h
    }

    #[test]
    fn references_match_a_fine_quadrature() {
        // Smooth integrands: midpoint error ~ h²/24 · |f''| ≲ 1e-8 at k = 1024. Indicators:
        // an error of the order of the boundary cells, ≲ 1/k.
        let k = 1024;
        for f in [Integrand::Gaussian, Integrand::Bilinear] {
            let q = midpoint(f, k);
            assert!((q - f.reference()).abs() < 1e-7, "{f:?}: {q}");
        }
        for f in [Integrand::Disk, Integrand::Triangle, Integrand::Step] {
            let q = midpoint(f, k);
            assert!((q - f.reference()).abs() < 1.0 / f64::from(k), "{f:?}: {q}");
        }
        // Finer, in one dimension: the quarter disk's area as ∫ √(2/π − x²) dx over
        // [0, √(2/π)], and the step's as the share of 2^20 midpoints below 1/π.
        let k = 1 << 20;
        let h = 1.0 / f64::from(k);
        let (mut disk, mut step) = (0.0, 0.0);
        for i in 0..k {
            let x = (f64::from(i) + 0.5) * h;
            disk += (2.0 / std::f64::consts::PI - x * x).max(0.0).sqrt() * h;
            step += Integrand::Step.eval(x, 0.5) * h;
        }
        assert!((disk - Integrand::Disk.reference()).abs() < 1e-8, "{disk}");
        assert!((step - Integrand::Step.reference()).abs() < 1e-6, "{step}");
        assert!((Integrand::Gaussian.reference() - 0.557_746_285_351_034).abs() < 1e-12);
    }

    #[test]
    fn slope_fit_is_exact_on_power_laws() {
        for order in [-0.5, -0.75, -1.5, 0.25] {
            let pts: Vec<(f64, f64)> = powers_of_two(16, 4096)
                .iter()
                .map(|&n| (f64::from(n), 0.3 * f64::from(n).powf(order)))
                .collect();
            let s = fit_slope(&pts).unwrap();
            assert!((s - order).abs() < 1e-12, "{order}: {s}");
        }
        // Least squares, not end points: log deviations (δ, −3δ, 3δ, −δ) at the centred log
        // abscissae (−1.5, −0.5, 0.5, 1.5) ln 2 have zero covariance with them, so the fit
        // stays −1 while the end points alone would say −1 − 2δ / (3 ln 2).
        let d = 0.05f64;
        let pts: Vec<(f64, f64)> = [(1.0, d), (2.0, -3.0 * d), (4.0, 3.0 * d), (8.0, -d)]
            .into_iter()
            .map(|(x, dev): (f64, f64)| (x, dev.exp() / x))
            .collect();
        let ends = (pts[3].1 / pts[0].1).ln() / 8f64.ln();
        assert!(
            (ends + 1.0 + 2.0 * d / (3.0 * 2f64.ln())).abs() < 1e-12,
            "{ends}"
        );
        assert!((fit_slope(&pts).unwrap() + 1.0).abs() < 1e-12);
        assert_eq!(fit_slope(&[(16.0, 0.1)]), None);
        assert_eq!(fit_slope(&[(16.0, 0.1), (16.0, 0.2)]), None);
        assert_eq!(fit_slope(&[(16.0, 0.1), (32.0, f64::NAN)]), None);
    }

    #[test]
    fn strata_cover_every_power_of_two() {
        for m in 0..=20u32 {
            let n = 1u32 << m;
            assert_eq!(strata(n), [1 << m.div_ceil(2), 1 << (m / 2)], "{n}");
            let s = build_sampler("stratified", n, 3).unwrap();
            assert_eq!(s.samples_per_pixel(), n);
            assert_eq!(s.name(), "stratified");
            assert_eq!(build_sampler("uniform", n, 3).unwrap().name(), "uniform");
        }
        assert_eq!(strata(12), [4, 3]);
        assert_eq!(
            build_sampler("halton", 16, 0).unwrap().name(),
            NamedSampler::new("halton", [1, 1], 16, 0).unwrap().name()
        );
    }

    #[test]
    fn jittered_rectangles_put_one_sample_in_each_stratum() {
        let mut s = build_sampler("stratified", 32, 9).unwrap();
        let mut seen = [false; 32];
        for i in 0..32 {
            s.start_pixel_sample([0, 0], i, 0);
            let [x, y] = s.get_pixel_2d();
            let cell = (y * 4.0) as usize * 8 + (x * 8.0) as usize;
            assert!(!seen[cell], "two samples in stratum {cell}");
            seen[cell] = true;
        }
    }

    #[test]
    fn run_seeds_are_distinct_and_never_zero() {
        let mut seeds: Vec<u64> = (0..1000).map(|r| run_seed(5, r)).collect();
        assert!(seeds.iter().all(|&s| s != 0));
        seeds.sort_unstable();
        seeds.dedup();
        assert_eq!(seeds.len(), 1000);
    }

    fn small_study() -> Study {
        Study {
            samplers: vec!["random".into(), "stratified".into(), "zero-two".into()],
            integrands: Integrand::ALL.to_vec(),
            counts: powers_of_two(4, 64),
            runs: 8,
            seed: 11,
        }
    }

    #[test]
    fn results_do_not_depend_on_the_thread_count() {
        let s = small_study();
        let a = s.run(1).unwrap();
        let b = s.run(3).unwrap();
        assert_eq!(a.curves, b.curves);
        assert_eq!(a.samples, 3 * 8 * (4 + 8 + 16 + 32 + 64));
        assert_eq!(a.curves.len(), 15);
        // A different base seed gives different numbers.
        let c = Study { seed: 12, ..s }.run(2).unwrap();
        assert_ne!(a.curves[0].rmse, c.curves[0].rmse);
    }

    #[test]
    fn rmse_is_the_root_mean_square_of_the_run_errors() {
        let s = Study {
            samplers: vec!["random".into()],
            integrands: vec![Integrand::Step],
            counts: vec![8, 16],
            runs: 5,
            seed: 2,
        };
        let got = s.run(2).unwrap().curves[0].rmse.clone();
        for (c, &n) in s.counts.iter().enumerate() {
            let mut sum = 0.0;
            for r in 0..5 {
                let mut sampler = build_sampler("random", n, run_seed(2, r)).unwrap();
                let mut e = [0.0];
                estimate(&mut sampler, &[Integrand::Step], &mut e);
                sum += (e[0] - Integrand::Step.reference()).powi(2);
            }
            assert_eq!(got[c], (sum / 5.0).sqrt());
        }
    }

    #[test]
    fn unknown_samplers_fail_before_any_work() {
        let s = Study {
            samplers: vec!["random".into(), "nope".into()],
            ..small_study()
        };
        let e = s.run(1).unwrap_err().to_string();
        assert!(e.starts_with("--samplers nope: unknown sampler"), "{e}");
        let s = Study {
            samplers: vec!["best-candidate".into()],
            counts: vec![4096, 8192],
            ..small_study()
        };
        let e = s.run(1).unwrap_err().to_string();
        assert!(e.contains("best-candidate at 8192 spp"), "{e}");
    }

    #[test]
    fn the_plot_has_its_size_and_draws_every_sampler_colour() {
        use crate::plot::{Figure, Kind, color, render};
        let s = small_study();
        let o = s.run(2).unwrap();
        let figure = Plot {
            study: &s,
            curves: &o.curves,
        };
        assert_eq!(figure.size(), (plot_size(5)[0], plot_size(5)[1]));
        let png = render(&figure, Kind::Png).unwrap();
        let mut reader = png::Decoder::new(std::io::Cursor::new(png))
            .read_info()
            .unwrap();
        let mut rgb = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut rgb).unwrap();
        assert_eq!((info.width, info.height), figure.size());
        for k in 0..3 {
            let c = color(k);
            let count = rgb
                .chunks_exact(3)
                .filter(|p| p == &[c.0, c.1, c.2])
                .count();
            // Five curves with their markers, five legend rows: well over 500 pixels.
            assert!(count > 500, "sampler {k}: {count} pixels");
        }
        // The outer margin stays white.
        assert_eq!(rgb[rgb.len() - 3..], [255; 3]);
        let svg = String::from_utf8(render(&figure, Kind::Svg).unwrap()).unwrap();
        assert!(svg.contains(&command(&s)));
        assert!(svg.contains("zero-two"));
    }
}
