//! Convergence studies: how fast each sampler's error falls with the sample count, for any
//! family of integrands with known integrals.
//!
//! For every sampler and every count `N`, `runs` independent copies of the sampler (seeds
//! hashed from the study's seed and the run, never 0) each give the `N` samples of pixel
//! (0, 0) of a 1 × 1 image; the mean of an integrand over them is one estimate, and
//! `RMSE(N) = √(mean over runs of (estimate − exact)²)`, divided by the integrand's
//! [`Integrand::error_scale`]. The slope of `log RMSE` against `log N` (least squares,
//! [`fit_slope`]) is the convergence order: −0.5 for independent samples, about −0.75 for
//! stratified samples on discontinuous integrands, and down to about −1.5 for scrambled nets on
//! smooth ones.
//!
//! Two families are built in: [`unit_square::SquareIntegrand`], the five 2-D integrands of
//! Christensen, Kensler and Kilpatrick (EGSR 2018), and [`genz::Genz`], Genz's six families in
//! `D` dimensions.
//!
//! ```
//! use nyquist_lab::study::{Study, unit_square::SquareIntegrand};
//! let study = Study {
//!     samplers: vec!["random".into()],
//!     integrands: vec![SquareIntegrand::Bilinear],
//!     counts: vec![16, 64, 256],
//!     runs: 16,
//!     seed: 7,
//!     spp_hint: None,
//! };
//! let curves = study.run(1).unwrap().curves;
//! assert_eq!(curves.len(), 1);
//! let slope = curves[0].slope.unwrap();
//! assert!((-0.9..-0.2).contains(&slope), "{slope}");
//! ```

pub mod convergence;
pub mod figure;
pub mod genz;
pub mod unit_square;

use core::fmt;
use nyquist::sampler::{NAMES, NamedSampler, NamedSamplerError, Sampler};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The largest sample count a study takes.
pub const MAX_SPP: u32 = 1 << 20;
/// The most samples one study may take in all (samplers × runs × the sum of the counts).
pub const MAX_SAMPLES: u64 = 1 << 32;

/// A function over `[0, 1)^dims` with a known integral, the unit a study estimates.
pub trait Integrand: Sync {
    /// Dimensions of its points.
    fn dims(&self) -> usize;
    /// The function at `x` (`x.len() == self.dims()`).
    fn eval(&self, x: &[f64]) -> f64;
    /// The exact integral over `[0, 1)^dims`.
    fn integral(&self) -> f64;
    /// What the RMSE is divided by: 1 for an absolute error (the default), `|integral|` for a
    /// relative one.
    fn error_scale(&self) -> f64 {
        1.0
    }
}

/// Writes the point of sample `i` in `out.len()` dimensions, as a renderer draws it: the image
/// sample (dimensions 0 and 1) by `get_pixel_2d`, then pairs by `get_2d` (dimensions 2, 3, …)
/// and a last odd dimension by `get_1d`.
///
/// ```
/// use nyquist::sampler::{NamedSampler, Sampler};
/// use nyquist_lab::study::point;
/// let mut s = NamedSampler::new("sobol-plain", [1, 1], 4, 0).unwrap();
/// let mut x = [0.0; 3];
/// point(&mut s, 1, &mut x);
/// assert_eq!(&x[..2], &[0.5, 0.5]);
/// ```
pub fn point(sampler: &mut NamedSampler, i: u32, out: &mut [f64]) {
    sampler.start_pixel_sample([0, 0], i, 0);
    let [x, y] = sampler.get_pixel_2d();
    let mut k = 0;
    for v in [x, y] {
        if let Some(o) = out.get_mut(k) {
            *o = f64::from(v);
        }
        k += 1;
    }
    while k < out.len() {
        if k + 1 < out.len() {
            let [u, v] = sampler.get_2d();
            out[k] = f64::from(u);
            out[k + 1] = f64::from(v);
            k += 2;
        } else {
            out[k] = f64::from(sampler.get_1d());
            k += 1;
        }
    }
}

/// The seed of run `run`: a hash of the base seed and the run, never 0 (0 means "not
/// scrambled" to some samplers).
///
/// ```
/// use nyquist_lab::study::run_seed;
/// assert_ne!(run_seed(0, 0), 0);
/// assert_ne!(run_seed(0, 0), run_seed(0, 1));
/// assert_ne!(run_seed(0, 1), run_seed(1, 1));
/// ```
pub fn run_seed(seed: u64, run: u32) -> u64 {
    nyquist::hash::hash2(seed, u64::from(run)).max(1)
}

/// The least-squares slope of `ln y` against `ln x` over the points `(x, y)`; `None` when
/// there are fewer than two points, a value is not finite and positive, or all `x` are equal.
///
/// ```
/// use nyquist_lab::study::fit_slope;
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

/// The line under a slope table that says why a slope is missing (`-`): for each such curve, the
/// sampler, the integrand (named by `name`) and the first count whose RMSE is 0 (the sampler
/// integrates the function exactly there, so log RMSE is undefined) or not finite. `None` when
/// every curve has its slope.
///
/// ```
/// use nyquist_lab::study::{Curve, missing_slopes};
/// let c = Curve { sampler: "uniform".into(), integrand: "bilinear", spp: vec![16, 32],
///                 rmse: vec![0.0, 0.0], slope: None };
/// assert_eq!(missing_slopes(&[c], |i| i.to_string()).unwrap(),
///            "No slope (-): uniform on bilinear, RMSE 0 at N = 16 (exact there; log 0 is undefined)");
/// ```
pub fn missing_slopes<I>(curves: &[Curve<I>], name: impl Fn(&I) -> String) -> Option<String> {
    let why: Vec<String> = curves
        .iter()
        .filter(|c| c.slope.is_none())
        .map(|c| {
            let at = |pred: &dyn Fn(f64) -> bool| {
                c.rmse
                    .iter()
                    .zip(&c.spp)
                    .find(|(e, _)| pred(**e))
                    .map(|(_, n)| *n)
            };
            let reason = if let Some(n) = at(&|e| e == 0.0) {
                format!("RMSE 0 at N = {n} (exact there; log 0 is undefined)")
            } else if let Some(n) = at(&|e| !e.is_finite()) {
                format!("RMSE not finite at N = {n}")
            } else {
                "fewer than two distinct sample counts".to_owned()
            };
            format!("{} on {}, {reason}", c.sampler, name(&c.integrand))
        })
        .collect();
    (!why.is_empty()).then(|| format!("No slope (-): {}", why.join("; ")))
}

/// The powers of two from `min` to `max` (both powers of two, `min ≤ max`).
///
/// ```
/// assert_eq!(nyquist_lab::study::powers_of_two(16, 128), [16, 32, 64, 128]);
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

/// The samplers a study takes by default: every name [`NamedSampler::new`] knows except
/// `uniform` (no randomness: every run is the same) and `adaptive` (it needs radiance reports;
/// without them it is `zero-two`).
///
/// ```
/// let names = nyquist_lab::study::default_samplers();
/// assert!(names.contains(&"sobol".to_owned()) && !names.contains(&"uniform".to_owned()));
/// ```
pub fn default_samplers() -> Vec<String> {
    NAMES
        .iter()
        .filter(|n| !matches!(**n, "uniform" | "adaptive"))
        .map(|n| (*n).to_owned())
        .collect()
}

/// A sampler the study could not build: its name, the count, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct StudyError {
    /// The sampler's name as the study lists it.
    pub sampler: String,
    /// The sample count asked for.
    pub count: u32,
    /// Why.
    pub error: StudyFault,
}

/// Why a study could not build a sampler.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StudyFault {
    /// What [`NamedSampler::new`] answered.
    Sampler(NamedSamplerError),
    /// The study has an [`Study::spp_hint`] and the sampler lays out a fixed set for its spp
    /// (it is not one of [`nyquist::sampler::CONTINUING_NAMES`]).
    Wraps {
        /// The hint.
        hint: u32,
    },
}

impl fmt::Display for StudyError {
    /// `NAME at N spp: REASON`, or `NAME: unknown sampler (known: …)`.
    ///
    /// ```
    /// use nyquist_lab::study::{Study, unit_square::SquareIntegrand};
    /// let s = Study { samplers: vec!["nope".into()], integrands: vec![SquareIntegrand::Disk],
    ///                 counts: vec![16], runs: 1, seed: 0, spp_hint: None };
    /// assert!(s.check().unwrap_err().to_string().starts_with("nope: unknown sampler name"));
    /// let s = Study { samplers: vec!["zero-two".into()], spp_hint: Some(4), ..s };
    /// assert_eq!(s.check().unwrap_err().to_string(),
    ///            "zero-two at 16 spp: made for 4, it wraps past its spp (the samplers that \
    ///             continue: random, halton, sobol, owen-sobol, owen-sobol-bn, zsobol, pmj02, pmj02-bn, lattice-bn)");
    /// ```
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.error {
            StudyFault::Sampler(NamedSamplerError::UnknownName) => {
                write!(f, "{}: {}", self.sampler, NamedSamplerError::UnknownName)
            }
            StudyFault::Sampler(e) => write!(f, "{} at {} spp: {e}", self.sampler, self.count),
            StudyFault::Wraps { hint } => write!(
                f,
                "{} at {} spp: made for {hint}, it wraps past its spp (the samplers that \
                 continue: {})",
                self.sampler,
                self.count,
                nyquist::sampler::CONTINUING_NAMES.join(", ")
            ),
        }
    }
}

impl std::error::Error for StudyError {}

/// One convergence study: every sampler at every count, `runs` times, on integrands of one
/// family (all of the same dimension).
#[derive(Clone, Debug)]
pub struct Study<I> {
    /// Sampler names (as [`NamedSampler::new`] takes them).
    pub samplers: Vec<String>,
    /// The integrands, each estimated from the same samples.
    pub integrands: Vec<I>,
    /// Sample counts `N` asked for, increasing.
    pub counts: Vec<u32>,
    /// Independent runs per sampler and count.
    pub runs: u32,
    /// Base seed; run `r` uses [`run_seed`]`(seed, r)`.
    pub seed: u64,
    /// `Some(h)`: every sampler is made for `h` samples per pixel and draws each count past
    /// (or short of) it, which only the samplers that continue past their spp can
    /// ([`nyquist::sampler::continues`]); `None`: each is made for the count itself.
    pub spp_hint: Option<u32>,
}

/// RMSE against `N` of one sampler on one integrand.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve<I> {
    /// Sampler name.
    pub sampler: String,
    /// The integrand.
    pub integrand: I,
    /// Samples per pixel the sampler used at each count (differs from the count asked for
    /// where a sampler rounds).
    pub spp: Vec<u32>,
    /// RMSE over the runs at each count, divided by [`Integrand::error_scale`].
    pub rmse: Vec<f64>,
    /// Least-squares slope of log RMSE against log spp ([`fit_slope`]).
    pub slope: Option<f64>,
}

/// What [`Study::run`] returns.
#[derive(Clone, Debug)]
pub struct Outcome<I> {
    /// One curve per sampler and integrand, sampler-major in the study's orders.
    pub curves: Vec<Curve<I>>,
    /// Samples taken in all.
    pub samples: u64,
}

impl<I: Integrand + Clone> Study<I> {
    /// Samples the study takes: samplers × runs × the sum of the counts (saturating).
    ///
    /// ```
    /// use nyquist_lab::study::{Study, unit_square::SquareIntegrand};
    /// let s = Study { samplers: vec!["random".into(); 2], integrands: vec![SquareIntegrand::Disk],
    ///                 counts: vec![16, 32], runs: 10, seed: 0, spp_hint: None };
    /// assert_eq!(s.work(), 2 * 10 * 48);
    /// ```
    pub fn work(&self) -> u64 {
        let per_run: u64 = self.counts.iter().map(|&n| u64::from(n)).sum();
        per_run
            .saturating_mul(u64::from(self.runs))
            .saturating_mul(self.samplers.len() as u64)
    }

    /// Bytes the study holds while it runs on `threads` threads (an estimate for
    /// [`crate::memory::check`]): per task (sampler × count × run) its estimates and its place
    /// in the work order, per thread one sampler at the largest count with up to 64 bytes a
    /// sample (the samplers that precompute their points) and one point.
    ///
    /// ```
    /// use nyquist_lab::study::{Study, unit_square::SquareIntegrand};
    /// let s = Study { samplers: vec!["random".into()], integrands: vec![SquareIntegrand::Disk],
    ///                 counts: vec![16, 32], runs: 10, seed: 0, spp_hint: None };
    /// assert_eq!(s.memory(1), 20 * (8 + 8 + 24) + 32 * 64 + 2 * 8);
    /// ```
    pub fn memory(&self, threads: usize) -> u64 {
        let tasks = (self.samplers.len() as u64)
            .saturating_mul(self.counts.len() as u64)
            .saturating_mul(u64::from(self.runs));
        let per_task = 8 * self.integrands.len() as u64 + 8 + 24;
        let largest = self.counts.iter().copied().max().unwrap_or(0);
        let per_thread = u64::from(largest) * 64 + 8 * self.dims() as u64;
        tasks
            .saturating_mul(per_task)
            .saturating_add((threads.max(1) as u64).saturating_mul(per_thread))
    }

    /// Dimensions of the study's points: the largest of its integrands' (2 at least).
    pub fn dims(&self) -> usize {
        self.integrands
            .iter()
            .map(I::dims)
            .max()
            .unwrap_or(2)
            .max(2)
    }

    /// Builds every sampler at every count (with run 0's seed), so that a name or count a
    /// sampler rejects is an error before any work; returns the spp each uses, sampler-major.
    ///
    /// # Errors
    /// The first sampler and count that cannot be built.
    pub fn check(&self) -> Result<Vec<Vec<u32>>, StudyError> {
        let seed = run_seed(self.seed, 0);
        self.samplers
            .iter()
            .map(|name| {
                self.counts
                    .iter()
                    .map(|&n| self.sampler(name, n, seed).map(|(_, drawn)| drawn))
                    .collect()
            })
            .collect()
    }

    /// Sampler `name` for count `n` under `seed`, and the samples it draws: made for `n` (its
    /// spp where it rounds), or for [`Study::spp_hint`] drawing `n`.
    fn sampler(&self, name: &str, n: u32, seed: u64) -> Result<(NamedSampler, u32), StudyError> {
        let fault = |error| StudyError {
            sampler: name.to_owned(),
            count: n,
            error,
        };
        if let Some(hint) = self.spp_hint
            && !nyquist::sampler::continues(name)
            && nyquist::sampler::canonical_name(name).is_some()
        {
            return Err(fault(StudyFault::Wraps { hint }));
        }
        let s = NamedSampler::new(name, [1, 1], self.spp_hint.unwrap_or(n), seed)
            .map_err(|e| fault(StudyFault::Sampler(e)))?;
        let drawn = self.spp_hint.map_or(s.samples_per_pixel(), |_| n);
        Ok((s, drawn))
    }

    /// Runs the study on `threads` threads. The result depends on the study only, not on the
    /// thread count: every (sampler, count, run) is one independent task with its own seed,
    /// and the squared errors are summed in run order afterwards.
    ///
    /// # Errors
    /// As [`Study::check`].
    pub fn run(&self, threads: usize) -> Result<Outcome<I>, StudyError> {
        self.run_with_progress(threads, &|_, _| {})
    }

    /// [`Study::run`], calling `progress(done, total)` after each (sampler, count, run) task
    /// (from the worker threads; on the calling thread when `threads` is 1, which starts no
    /// thread at all).
    ///
    /// ```
    /// use nyquist_lab::study::{Study, unit_square::SquareIntegrand};
    /// use std::sync::atomic::{AtomicUsize, Ordering};
    /// let s = Study { samplers: vec!["random".into()], integrands: vec![SquareIntegrand::Disk],
    ///                 counts: vec![16, 32], runs: 3, seed: 0, spp_hint: None };
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
    ) -> Result<Outcome<I>, StudyError> {
        let spp = self.check()?;
        let (nc, nr, dims) = (self.counts.len(), self.runs as usize, self.dims());
        let tasks = self.samplers.len() * nc * nr;
        // Largest counts handed out first, so the last tasks are short; ties by task index.
        let mut order: Vec<usize> = (0..tasks).collect();
        order.sort_unstable_by_key(|&t| {
            (
                core::cmp::Reverse(self.counts[(t / nr) % nc]),
                core::cmp::Reverse(t),
            )
        });
        let done = AtomicUsize::new(0);
        let estimates = crate::parallel::map_tasks(&order, threads, |t| {
            let (s, c, r) = (t / (nc * nr), (t / nr) % nc, t % nr);
            let (mut sampler, n) = self.sampler(
                &self.samplers[s],
                self.counts[c],
                run_seed(self.seed, r as u32),
            )?;
            let mut x = vec![0.0; dims];
            let mut sums = vec![0.0f64; self.integrands.len()];
            for i in 0..n {
                point(&mut sampler, i, &mut x);
                for (o, f) in sums.iter_mut().zip(&self.integrands) {
                    *o += f.eval(&x[..f.dims()]);
                }
            }
            sums.iter_mut().for_each(|o| *o /= f64::from(n.max(1)));
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, tasks);
            Ok(sums)
        })?;
        let mut curves = Vec::with_capacity(self.samplers.len() * self.integrands.len());
        let mut samples = 0u64;
        for (s, name) in self.samplers.iter().enumerate() {
            samples += spp[s]
                .iter()
                .map(|&n| u64::from(n) * nr as u64)
                .sum::<u64>();
            for (i, integrand) in self.integrands.iter().enumerate() {
                let exact = integrand.integral();
                let rmse: Vec<f64> = (0..nc)
                    .map(|c| {
                        let base = (s * nc + c) * nr;
                        let sum: f64 = (0..nr)
                            .map(|r| {
                                let e = estimates[base + r][i] - exact;
                                e * e
                            })
                            .sum();
                        (sum / nr.max(1) as f64).sqrt() / integrand.error_scale()
                    })
                    .collect();
                let points: Vec<(f64, f64)> = spp[s]
                    .iter()
                    .zip(&rmse)
                    .map(|(&n, &e)| (f64::from(n), e))
                    .collect();
                curves.push(Curve {
                    sampler: name.clone(),
                    integrand: integrand.clone(),
                    spp: spp[s].clone(),
                    rmse,
                    slope: fit_slope(&points),
                });
            }
        }
        Ok(Outcome { curves, samples })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use unit_square::SquareIntegrand;

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
    fn run_seeds_are_distinct_and_never_zero() {
        let mut seeds: Vec<u64> = (0..1000).map(|r| run_seed(5, r)).collect();
        assert!(seeds.iter().all(|&s| s != 0));
        seeds.sort_unstable();
        seeds.dedup();
        assert_eq!(seeds.len(), 1000);
    }

    fn small_study() -> Study<SquareIntegrand> {
        Study {
            samplers: vec!["random".into(), "stratified".into(), "zero-two".into()],
            integrands: SquareIntegrand::ALL.to_vec(),
            counts: powers_of_two(4, 64),
            runs: 8,
            seed: 11,
            spp_hint: None,
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
            integrands: vec![SquareIntegrand::Step],
            counts: vec![8, 16],
            runs: 5,
            seed: 2,
            spp_hint: None,
        };
        let got = s.run(2).unwrap().curves[0].rmse.clone();
        for (c, &n) in s.counts.iter().enumerate() {
            let mut sum = 0.0;
            for r in 0..5 {
                let mut sampler = NamedSampler::new("random", [1, 1], n, run_seed(2, r)).unwrap();
                let mut mean = 0.0;
                for i in 0..n {
                    let mut x = [0.0; 2];
                    point(&mut sampler, i, &mut x);
                    mean += SquareIntegrand::Step.eval(x[0], x[1]);
                }
                mean /= f64::from(n);
                sum += (mean - SquareIntegrand::Step.integral()).powi(2);
            }
            assert_eq!(got[c], (sum / 5.0).sqrt());
        }
    }

    /// A point in D dimensions: the image sample, then pairs, then a last odd dimension, the
    /// values a renderer would draw in that order.
    #[test]
    fn points_are_drawn_as_a_renderer_draws_them() {
        let mut a = NamedSampler::new("owen-sobol", [1, 1], 8, 3).unwrap();
        let mut b = a.clone();
        let mut x = [0.0; 5];
        point(&mut a, 5, &mut x);
        b.start_pixel_sample([0, 0], 5, 0);
        let [p0, p1] = b.get_pixel_2d();
        let [p2, p3] = b.get_2d();
        let p4 = b.get_1d();
        assert_eq!(x, [p0, p1, p2, p3, p4].map(f64::from));
    }
}
