//! Adaptive sampling: more samples where a pixel's first samples disagree.

use super::Sampler;
use crate::Error;
use crate::error::Interval;

/// Channels of reported radiance that the contrast test looks at.
///
/// ```
/// assert_eq!(nyquist::sampler::ADAPTIVE_CHANNELS, 4);
/// ```
pub const ADAPTIVE_CHANNELS: usize = 4;

/// Wraps a sampler and takes `min_spp` samples per pixel, or the wrapped sampler's full
/// `samples_per_pixel()` (the maximum) where the first samples disagree.
///
/// The decision uses Mitchell's contrast (Mitchell 1987, "Generating antialiased images at low
/// sampling densities"): per channel, `(max − min) / (|max| + |min|)` over the reported
/// radiance of the pixel's samples so far, compared with `threshold`. It is evaluated as
/// `max − min > threshold · (|max| + |min|)`, so an all-zero pixel divides nothing and takes the
/// minimum. A non-finite reported value counts as disagreement (take the maximum). Only the
/// first [`ADAPTIVE_CHANNELS`] channels are looked at.
///
/// Radiance comes back through [`Sampler::report`] (from
/// [`PixelRangeSampler::report`](super::PixelRangeSampler::report)) and the count through
/// [`Sampler::pixel_samples`]; the stateless value methods delegate to the wrapped sampler, so
/// values stay replayable. The decision state covers the pixel reported last: a `Clone` per
/// thread, reporting pixel by pixel, as the request-and-fill layer does.
///
/// ```
/// use nyquist::sampler::{AdaptiveSampler, Jitter, Sampler, StratifiedSampler};
/// let inner = StratifiedSampler::new(4, 4, Jitter::Jittered, 0).unwrap();
/// let mut a = AdaptiveSampler::new(inner, 4, 0.1).unwrap();
/// for i in 0..4 {
///     a.report([0, 0], i, &[if i == 0 { 1.0 } else { 0.0 }]);
/// }
/// assert_eq!(a.pixel_samples([0, 0]), 16);
/// assert_eq!(a.pixel_samples([1, 0]), 4);
/// ```
#[derive(Clone, Debug)]
pub struct AdaptiveSampler<S> {
    inner: S,
    min_spp: u32,
    threshold: f32,
    pixel: Option<[u32; 2]>,
    reported: u32,
    lo: [f32; ADAPTIVE_CHANNELS],
    hi: [f32; ADAPTIVE_CHANNELS],
    wild: bool,
}

impl<S: Sampler> AdaptiveSampler<S> {
    /// `min_spp` samples per pixel, up to `inner.samples_per_pixel()` where the contrast of the
    /// first `min_spp` exceeds `threshold` (Mitchell suggests 0.4, 0.3, 0.6 for R, G, B; one
    /// threshold serves all channels here).
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `min_spp == 0`; [`Error::NotInRange`] if `min_spp` exceeds the
    /// wrapped sampler's spp; [`Error::NonFinite`] for a NaN or infinite threshold;
    /// [`Error::OutOfRange`] if `threshold < 0`.
    ///
    /// ```
    /// use nyquist::sampler::{AdaptiveSampler, RandomSampler};
    /// let inner = RandomSampler::new(8, 0).unwrap();
    /// let e = AdaptiveSampler::new(inner.clone(), 9, 0.1).unwrap_err();
    /// assert_eq!(e.to_string(), "min_spp 9 is outside 1..=8");
    /// let e = AdaptiveSampler::new(inner.clone(), 2, -0.5).unwrap_err();
    /// assert_eq!(e.to_string(), "threshold -0.5 is outside [0, ∞)");
    /// assert!(AdaptiveSampler::new(inner, 2, f32::NAN).is_err());
    /// ```
    pub fn new(inner: S, min_spp: u32, threshold: f32) -> Result<Self, Error> {
        if min_spp == 0 {
            return Err(Error::ZeroSize { what: "min_spp" });
        }
        if min_spp > inner.samples_per_pixel() {
            return Err(Error::NotInRange {
                what: "min_spp",
                value: u64::from(min_spp),
                min: 1,
                max: u64::from(inner.samples_per_pixel()),
            });
        }
        if !threshold.is_finite() {
            return Err(Error::NonFinite { what: "threshold" });
        }
        if threshold < 0.0 {
            return Err(Error::OutOfRange {
                what: "threshold",
                value: f64::from(threshold),
                range: Interval::at_least(0.0),
            });
        }
        Ok(Self {
            inner,
            min_spp,
            threshold,
            pixel: None,
            reported: 0,
            lo: [0.0; ADAPTIVE_CHANNELS],
            hi: [0.0; ADAPTIVE_CHANNELS],
            wild: false,
        })
    }

    /// `[min_spp, max_spp]`.
    ///
    /// ```
    /// use nyquist::sampler::{AdaptiveSampler, RandomSampler};
    /// let a = AdaptiveSampler::new(RandomSampler::new(8, 0).unwrap(), 2, 0.1).unwrap();
    /// assert_eq!(a.spp_range(), [2, 8]);
    /// ```
    pub fn spp_range(&self) -> [u32; 2] {
        [self.min_spp, self.inner.samples_per_pixel()]
    }

    /// The wrapped sampler.
    ///
    /// ```
    /// use nyquist::sampler::{AdaptiveSampler, RandomSampler, Sampler};
    /// let a = AdaptiveSampler::new(RandomSampler::new(8, 0).unwrap(), 2, 0.1).unwrap();
    /// assert_eq!(a.inner().samples_per_pixel(), 8);
    /// ```
    pub fn inner(&self) -> &S {
        &self.inner
    }

    fn disagrees(&self) -> bool {
        self.wild
            || self
                .lo
                .iter()
                .zip(&self.hi)
                .any(|(&lo, &hi)| hi - lo > self.threshold * (hi.abs() + lo.abs()))
    }
}

impl<S: Sampler> Sampler for AdaptiveSampler<S> {
    fn samples_per_pixel(&self) -> u32 {
        self.inner.samples_per_pixel()
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        self.inner.start_pixel_sample(pixel, sample_index, dim);
    }

    fn get_1d(&mut self) -> f32 {
        self.inner.get_1d()
    }

    fn get_2d(&mut self) -> [f32; 2] {
        self.inner.get_2d()
    }

    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.inner.get_pixel_2d()
    }

    fn camera_sample(&mut self, pixel: [u32; 2], sample_index: u32) -> super::CameraSample {
        self.inner.camera_sample(pixel, sample_index)
    }

    fn round_size(&self, n: u32) -> u32 {
        self.inner.round_size(n)
    }

    fn get_array_1d(&mut self, out: &mut [f32]) {
        self.inner.get_array_1d(out);
    }

    fn get_array_2d(&mut self, out: &mut [f32]) {
        self.inner.get_array_2d(out);
    }

    fn arrays_are_dimension_runs(&self) -> bool {
        self.inner.arrays_are_dimension_runs()
    }

    fn domain(&self) -> Option<super::Domain> {
        self.inner.domain()
    }

    /// `min_spp` until `min_spp` samples of `pixel` were reported; then the maximum if they
    /// disagree, else `min_spp`.
    fn pixel_samples(&self, pixel: [u32; 2]) -> u32 {
        if self.pixel == Some(pixel) && self.reported >= self.min_spp && self.disagrees() {
            self.inner.samples_per_pixel()
        } else {
            self.min_spp
        }
    }

    fn report(&mut self, pixel: [u32; 2], sample_index: u32, radiance: &[f32]) {
        let _ = sample_index;
        if self.pixel != Some(pixel) {
            self.pixel = Some(pixel);
            self.reported = 0;
            self.wild = false;
        }
        for (c, &l) in radiance.iter().take(ADAPTIVE_CHANNELS).enumerate() {
            if !l.is_finite() {
                self.wild = true;
            } else if self.reported == 0 {
                self.lo[c] = l;
                self.hi[c] = l;
            } else {
                self.lo[c] = self.lo[c].min(l);
                self.hi[c] = self.hi[c].max(l);
            }
        }
        if self.reported == 0 {
            for c in radiance.len().min(ADAPTIVE_CHANNELS)..ADAPTIVE_CHANNELS {
                self.lo[c] = 0.0;
                self.hi[c] = 0.0;
            }
        }
        self.reported = self.reported.saturating_add(1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::tests::{consistent_values, threads_agree};
    use crate::sampler::{Jitter, PixelRangeSampler, Sample, SampleLayout, StratifiedSampler};

    /// An adaptive sampler's samples are its inner sampler's domains.
    #[test]
    fn domains_are_the_inner_samplers() {
        let inner = crate::sampler::OwenSobolSampler::new(16, 3).unwrap();
        let mut a = AdaptiveSampler::new(inner.clone(), 4, 0.1).unwrap();
        a.start_pixel_sample([1, 2], 5, 0);
        let mut o = inner;
        o.start_pixel_sample([1, 2], 5, 0);
        assert_eq!(a.domain(), Some(o.pixel_domain()));
    }

    fn run(scene: impl Fn([f32; 2]) -> f32) -> std::vec::Vec<u32> {
        let inner = StratifiedSampler::new(4, 4, Jitter::Jittered, 1).unwrap();
        let a = AdaptiveSampler::new(inner, 8, 0.05).unwrap();
        let layout = SampleLayout::<0>::new();
        let mut buf = [0.0f32; 5];
        let mut sample = Sample::new(&layout, &mut buf).unwrap();
        let mut r = PixelRangeSampler::new(a, [0, 0], [16, 4]).unwrap();
        let mut counts = std::vec![0u32; 64];
        while r.next_sample(&mut sample) {
            let p = sample.pixel();
            counts[(p[1] * 16 + p[0]) as usize] += 1;
            let l = scene(sample.image());
            r.report(&[l, l * 0.5, 0.25]);
        }
        counts
    }

    #[test]
    fn constant_scene_takes_the_minimum_everywhere() {
        assert!(run(|_| 0.7).iter().all(|&c| c == 8));
        assert!(run(|_| 0.0).iter().all(|&c| c == 8)); // (0, 0) divides nothing
    }

    #[test]
    fn an_edge_takes_the_maximum_near_it() {
        // A vertical edge at x = 7.5: pixel column 7 straddles it; 8 of 16 strata see both sides
        // unless all 8 fall on one half (probability 2 / C(16, 8) per pixel for this seed's
        // permutations, and the test is deterministic).
        let counts = run(|[x, _]| if x < 7.5 { 1.0 } else { 0.0 });
        for y in 0..4 {
            for x in 0..16 {
                let c = counts[y * 16 + x];
                assert_eq!(c, if x == 7 { 16 } else { 8 }, "pixel ({x}, {y})");
            }
        }
    }

    #[test]
    fn non_finite_radiance_takes_the_maximum() {
        let inner = StratifiedSampler::new(2, 2, Jitter::Jittered, 1).unwrap();
        let mut a = AdaptiveSampler::new(inner, 1, 0.5).unwrap();
        a.report([3, 3], 0, &[f32::NAN]);
        assert_eq!(a.pixel_samples([3, 3]), 4);
    }

    #[test]
    fn adaptive_is_consistent_and_thread_independent() {
        let inner = StratifiedSampler::new(2, 2, Jitter::Jittered, 1).unwrap();
        let a = AdaptiveSampler::new(inner, 2, 0.1).unwrap();
        consistent_values(&a);
        threads_agree(&a);
    }
}
