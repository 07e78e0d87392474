//! Adaptive sampling by error ([`render_adaptive`]): passes over the film, each doubling the
//! samples of the pixels whose estimated relative error is still above a threshold, within a
//! total budget.
//!
//! The first pass gives every pixel `initial_spp` samples. After each pass the film's estimate
//! of each pixel ([`crate::Film::estimate`]: the A/B halves or the variance) gives its
//! relative error, err / (value + floor), with err and value summed over the three channels
//! (`floor` keeps dark pixels from needing an absolute error of 0). A pixel stops when it and
//! its eight neighbours are at or below the threshold (with few samples the halves can agree by
//! chance on an edge, rarely in a whole neighbourhood; Cycles dilates its active pixels the same
//! way); the others, worst first by the mean error of their 3 × 3 neighbourhood (so that one
//! pixel's noisy estimate does not decide alone; ties by pixel index), double their samples, as
//! many as the remaining budget pays for. Doubling keeps each pixel's samples a power-of-two prefix
//! of its sequence, where (0,2) sequences such as Sobol and PMJ(0,2) are nets. Every decision
//! is made on the calling thread from the merged film, so the result is the same for any thread
//! count.

use crate::error::Error;
use crate::film::Film;
use crate::image::Image;
use crate::render::render_tiles;
use crate::tile::FilmTile;
use std::ops::Range;

/// Which of the film's estimates measures a pixel's error: [`ErrorEstimate::Halves`] needs a
/// film that keeps [`halves`](crate::PixelExtras::halves), [`ErrorEstimate::Variance`] one that
/// keeps [`variance`](crate::PixelExtras::variance).
pub use nyquist::pixel_stats::ErrorEstimate;

/// How [`render_adaptive`] spends its samples.
///
/// ```
/// use nyquist_film::adaptive::AdaptiveConfig;
/// let c = AdaptiveConfig::new(256, 0.02);
/// assert_eq!((c.initial_spp, c.max_spp, c.budget_spp), (64, 4096, 256));
/// assert_eq!(AdaptiveConfig::new(8, 0.02).initial_spp, 8);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdaptiveConfig {
    /// Samples every pixel takes in the first pass (at least 2, so that both halves or a
    /// variance exist; a power of two for (0,2) sequences).
    pub initial_spp: u32,
    /// The most samples a pixel takes.
    pub max_spp: u32,
    /// The budget, as samples per pixel on average: `budget_spp × pixels` in all.
    pub budget_spp: u32,
    /// A pixel stops when its relative error is at or below this.
    pub threshold: f64,
    /// Added to a pixel's value (the sum of its channels) in the relative error's denominator.
    pub floor: f64,
    /// Which estimate gives the error.
    pub estimate: ErrorEstimate,
}

impl AdaptiveConfig {
    /// A budget of `budget_spp` samples per pixel on average and the threshold `threshold`:
    /// a first pass of a quarter of the budget but at least 16 (at most the budget), at most
    /// 16 times the budget in a pixel, floor 0.01, the halves' estimate.
    ///
    /// The first pass needs enough samples for the estimate to mean something: with 4 samples
    /// the two stratified halves of an edge pixel often cover it equally (one point of two
    /// each) whatever its true coverage, agree, and stop it early. With 16 (8 per half) the
    /// disk of `std-film/tests/adaptive.rs` stops no edge pixel early.
    pub fn new(budget_spp: u32, threshold: f64) -> AdaptiveConfig {
        AdaptiveConfig {
            initial_spp: (budget_spp / 4).max(16).min(budget_spp),
            max_spp: budget_spp.saturating_mul(16),
            budget_spp,
            threshold,
            floor: 0.01,
            estimate: ErrorEstimate::Halves,
        }
    }

    fn check(&self, film: &Film) -> Result<(), Error> {
        let range = |what: &'static str, value: f64, min: f64, max: f64| {
            if (min..=max).contains(&value) {
                Ok(())
            } else {
                Err(Error::OutOfRange {
                    what,
                    value,
                    min,
                    max,
                })
            }
        };
        range(
            "initial spp",
            f64::from(self.initial_spp),
            2.0,
            f64::from(u32::MAX),
        )?;
        range(
            "max spp",
            f64::from(self.max_spp),
            f64::from(self.initial_spp),
            f64::from(u32::MAX),
        )?;
        range(
            "budget spp",
            f64::from(self.budget_spp),
            f64::from(self.initial_spp),
            f64::from(self.max_spp),
        )?;
        range("threshold", self.threshold, 0.0, f64::MAX)?;
        range("floor", self.floor, 0.0, f64::MAX)?;
        let extras = film.extras();
        let kept = match self.estimate {
            ErrorEstimate::Halves => extras.halves,
            ErrorEstimate::Variance => extras.variance,
        };
        if !kept {
            return Err(Error::Config(format!(
                "adaptive sampling by {:?} needs a film that keeps {}",
                self.estimate,
                match self.estimate {
                    ErrorEstimate::Halves => "halves",
                    ErrorEstimate::Variance => "variance",
                }
            )));
        }
        Ok(())
    }
}

/// What [`render_adaptive`] did: the samples of each pixel and the totals.
#[derive(Clone, Debug, PartialEq)]
pub struct AdaptiveReport {
    /// Samples per pixel, row-major over the film's pixels.
    pub spp: Vec<u32>,
    /// The film's width in pixels (the rows of `spp`).
    pub width: u32,
    /// Samples taken in all.
    pub samples: u64,
    /// Passes made.
    pub passes: u32,
    /// Pixels that stopped because their error, and their neighbours', reached the threshold.
    pub converged: u64,
}

impl AdaptiveReport {
    /// The mean samples per pixel.
    pub fn mean_spp(&self) -> f64 {
        self.samples as f64 / self.spp.len().max(1) as f64
    }

    /// The samples per pixel as a grey image, log₂(spp / min) / log₂(max / min) (black: the
    /// fewest, white: the most), for looking at where the samples went.
    ///
    /// # Errors
    /// [`Error::OutOfMemory`] if the image cannot be allocated.
    pub fn spp_image(&self) -> Result<Image, Error> {
        let height = (self.spp.len() / self.width.max(1) as usize) as u32;
        let mut image = Image::new(self.width, height)?;
        let min = self.spp.iter().copied().min().unwrap_or(1).max(1);
        let max = self.spp.iter().copied().max().unwrap_or(1).max(min);
        let span = (f64::from(max) / f64::from(min)).log2();
        for (o, &n) in image.data_mut().chunks_exact_mut(3).zip(&self.spp) {
            let v = if span > 0.0 {
                (f64::from(n.max(min)) / f64::from(min)).log2() / span
            } else {
                1.0
            };
            o.fill(v as f32);
        }
        Ok(image)
    }
}

/// Renders `film` adaptively: `sample(tile, pixel, indices)` adds the samples `indices` of
/// `pixel` (film coordinates) to `tile`, and is called for the pixels of each tile that take
/// samples in a pass, on `threads` threads, as [`render_tiles`] does. `progress(pass, samples)`
/// is called after each pass with the samples taken so far.
///
/// # Errors
/// [`Error::OutOfRange`] for an `initial_spp` below 2, a `max_spp` below it, a `budget_spp`
/// outside `initial_spp ..= max_spp`, or a negative threshold or floor; [`Error::Config`] when
/// the film does not keep the estimate asked for; the errors of [`render_tiles`].
///
/// ```
/// use nyquist_film::adaptive::{AdaptiveConfig, render_adaptive};
/// use nyquist_film::{Film, FilmConfig, FilmSample, PixelExtras};
/// let mut config = FilmConfig::new(8, 4);
/// config.extras = PixelExtras { halves: true, ..Default::default() };
/// let mut film = Film::new(config, &nyquist::filter::Boxcar::default()).unwrap();
/// // The left half is flat, the right half is noise: the noise gets the samples.
/// let report = render_adaptive(&mut film, &AdaptiveConfig::new(64, 0.01), 4, 1, |tile, [x, y], indices| {
///     for i in indices {
///         let u = ((i.wrapping_mul(0x9e37_79b9_7f4a_7c15) >> 40) as f32) / (1 << 24) as f32;
///         let l = if x < 4 { 0.5 } else { u };
///         tile.add(&FilmSample { index: i, ..FilmSample::new([x as f32 + 0.5, y as f32 + 0.5], [l; 3], 1.0) });
///     }
/// }, |_, _| {}).unwrap();
/// assert_eq!(report.spp[0], 16); // flat: converged after the first pass
/// let noisy: u32 = (0..4).flat_map(|y| &report.spp[8 * y + 4..8 * y + 8]).sum();
/// assert!(noisy > 3 * 64 * 16 / 2); // the 16 noisy pixels took more than 1.5 times their share
/// assert!(report.samples <= 64 * 32);
/// ```
pub fn render_adaptive(
    film: &mut Film,
    config: &AdaptiveConfig,
    tile_size: u32,
    threads: usize,
    sample: impl Fn(&mut FilmTile, [u32; 2], Range<u64>) + Sync,
    mut progress: impl FnMut(u32, u64),
) -> Result<AdaptiveReport, Error> {
    config.check(film)?;
    let b = film.pixel_bounds();
    let width = b.width() as usize;
    let pixels = b.area() as usize;
    let budget = config.budget_spp as u64 * pixels as u64;
    let mut spp = vec![0u32; pixels];
    let mut target = vec![config.initial_spp; pixels];
    let mut samples = 0u64;
    let mut passes = 0u32;
    let converged = loop {
        {
            let (spp, target) = (&spp, &target);
            render_tiles(
                film,
                tile_size,
                threads,
                |tile, ctx| {
                    let t = ctx.bounds;
                    for y in t.y0..t.y1 {
                        for x in t.x0..t.x1 {
                            let i = (y - b.y0) as usize * width + (x - b.x0) as usize;
                            let (from, to) = (spp[i], target[i]);
                            if to > from {
                                sample(tile, [x as u32, y as u32], u64::from(from)..u64::from(to));
                            }
                        }
                    }
                },
                |_, _| {},
            )?;
        }
        for (s, &t) in spp.iter_mut().zip(&target) {
            samples += u64::from(t - *s);
            *s = t;
        }
        passes += 1;
        progress(passes, samples);
        film.next_pass()?;
        // Each pixel's error (∞ without an estimate) and whether it is at the threshold.
        let errors: Vec<f64> = (0..pixels)
            .map(|i| {
                let (x, y) = (b.x0 + (i % width) as i64, b.y0 + (i / width) as i64);
                film.estimate(x, y)
                    .and_then(|e| e.relative_error(config.estimate, config.floor))
                    .unwrap_or(f64::INFINITY)
            })
            .collect();
        let height = pixels / width;
        // A pixel converges when it and its 8 neighbours are at the threshold (Cycles dilates
        // its active pixels the same way): with few samples both halves can agree by chance on
        // an edge, rarely in a whole neighbourhood.
        let settled = |i: usize| {
            let (x, y) = (i % width, i / width);
            (y.saturating_sub(1)..(y + 2).min(height)).all(|v| {
                (x.saturating_sub(1)..(x + 2).min(width))
                    .all(|u| errors[v * width + u] <= config.threshold)
            })
        };
        // A pixel's rank: the mean error of its 3 × 3 neighbourhood, so that one pixel's noisy
        // estimate does not decide alone where samples go.
        let smoothed = |i: usize| {
            let (x, y) = (i % width, i / width);
            let (mut sum, mut n) = (0.0, 0.0);
            for v in y.saturating_sub(1)..(y + 2).min(height) {
                for u in x.saturating_sub(1)..(x + 2).min(width) {
                    sum += errors[v * width + u];
                    n += 1.0;
                }
            }
            sum / n
        };
        // The pixels still open that can take more, worst first.
        let mut open: Vec<(f64, usize)> = Vec::new();
        let mut converged = 0u64;
        for (i, &n) in spp.iter().enumerate() {
            if settled(i) {
                converged += 1;
            } else if n < config.max_spp {
                open.push((smoothed(i), i));
            }
        }
        open.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
        let mut left = budget - samples;
        let mut any = false;
        for &(_, i) in &open {
            let more = spp[i].min(config.max_spp - spp[i]);
            if u64::from(more) > left {
                break;
            }
            left -= u64::from(more);
            target[i] = spp[i] + more;
            any = true;
        }
        if !any {
            break converged;
        }
    };
    Ok(AdaptiveReport {
        spp,
        width: width as u32,
        samples,
        passes,
        converged,
    })
}
