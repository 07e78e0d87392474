//! What a film can keep per pixel beside its RGB sums ([`PixelExtras`]): the variance of each
//! channel's weighted mean, the sums of two half-sample sets (A and B), and extra channels
//! (albedo, normal, depth, or any number of floats), all through the film's filter.
//!
//! **Variance.** A pixel's value is the weighted mean I = Σ fᵢxᵢ / Σ fᵢ of its samples' values
//! xᵢ (`weight·rgb`) with filter weights fᵢ. Its variance, by the delta method, is
//! Σ fᵢ²(xᵢ − I)² / (Σ fᵢ)², and with the effective sample count n = (Σ fᵢ)²/Σ fᵢ² in place of
//! n − 1 (unbiased for equal weights: the familiar s²/n) it is
//! Q / ((Σ fᵢ)² − Σ fᵢ²), Q = Σ fᵢ²(xᵢ − I)².
//! Q is kept without cancellation: the pixel holds the f²-weighted mean m and the sum
//! S = Σ fᵢ²(xᵢ − m)², updated per sample by Welford's method with weights (West 1979,
//! "Updating mean and variance estimates: an improved method"), so Q = S + (m − I)²·Σ fᵢ², since
//! Σ fᵢ²(xᵢ − m) = 0. The weights f² are never negative, so negative filter lobes cannot make
//! the update unstable. Tiles are merged by Chan, Golub and LeVeque's pairwise formula (1979,
//! "Updating formulae and a pairwise algorithm for computing sample variances"), in tile-index
//! order like the sums, so the result is bit-identical for any thread count and arrival order.
//!
//! **Halves.** A sample's class is the parity of `popcount(index & 0xaaaa…aaaa)` (Christensen,
//! Kensler and Kilpatrick 2018, "Progressive multi-jittered sample sequences", §10.2.1; Cycles'
//! adaptive sampling): for (0,2) sequences such as PMJ02 and Sobol each class is itself well
//! stratified, so the two half-images are independent estimates of the pixel with half the
//! samples each, and their difference measures the error: E|A − B|/2 ≈ the standard error of I.
//! The film keeps the B sums; A is the whole less B.
//!
//! **Channels.** `channels` floats per sample, accumulated as Σ f·a with the pixel's own Σ f
//! (not multiplied by the sample weight: an albedo is not radiance).

use crate::error::Error;
use crate::image::Image;
use crate::pixel::Pixel;

/// What a film keeps per pixel beside its RGB sums; all off by default, and a film that asks for
/// nothing stores and computes nothing more. Costs per stored pixel: variance 56 bytes, halves
/// 32, channels 8 each (the RGB sums take 32).
///
/// ```
/// use nyquist_film::{FilmConfig, PixelExtras};
/// let mut config = FilmConfig::new(64, 64);
/// config.extras = PixelExtras { variance: true, halves: true, channels: 7 };
/// assert_eq!(config.extras.bytes_per_pixel(), 56 + 32 + 7 * 8);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PixelExtras {
    /// The variance of each channel's weighted mean ([`crate::Film::estimate`]).
    pub variance: bool,
    /// The sums of the A and B sample classes ([`sample_half`], [`crate::Film::extra_images`]).
    pub halves: bool,
    /// Extra channels per sample ([`crate::FilmSample::channels`],
    /// [`crate::Film::channel_values`]), at most [`MAX_CHANNELS`].
    pub channels: u16,
}

/// The most extra channels a film keeps per pixel.
///
/// ```
/// use nyquist_film::{Film, FilmConfig, PixelExtras, extras::MAX_CHANNELS};
/// let mut config = FilmConfig::new(4, 4);
/// config.extras.channels = MAX_CHANNELS + 1;
/// assert!(Film::new(config, &nyquist::filter::Boxcar::default()).is_err());
/// ```
pub const MAX_CHANNELS: u16 = 64;

impl PixelExtras {
    /// Whether anything beyond the RGB sums is kept.
    ///
    /// ```
    /// assert!(!nyquist_film::PixelExtras::default().any());
    /// ```
    pub fn any(&self) -> bool {
        self.variance || self.halves || self.channels > 0
    }

    /// Bytes per stored pixel beyond the RGB sums.
    ///
    /// ```
    /// let e = nyquist_film::PixelExtras { channels: 3, ..Default::default() };
    /// assert_eq!(e.bytes_per_pixel(), 24);
    /// ```
    pub fn bytes_per_pixel(&self) -> usize {
        usize::from(self.variance) * size_of::<Moments>()
            + usize::from(self.halves) * size_of::<Pixel>()
            + usize::from(self.channels) * size_of::<f64>()
    }
}

/// The half a sample of index `index` belongs to: 0 (A) or 1 (B), the parity of
/// `popcount(index & 0xaaaa_aaaa_aaaa_aaaa)`. Of every 4 consecutive indices from a multiple of
/// 4, two fall in each half; below 2³² this is Cycles' rule.
///
/// ```
/// use nyquist_film::extras::sample_half;
/// let halves: Vec<usize> = (0..8).map(sample_half).collect();
/// assert_eq!(halves, [0, 0, 1, 1, 0, 0, 1, 1]);
/// ```
pub fn sample_half(index: u64) -> usize {
    ((index & 0xaaaa_aaaa_aaaa_aaaa).count_ones() & 1) as usize
}

/// A pixel's value and the error estimates its film keeps for it ([`crate::Film::estimate`]).
///
/// ```
/// let e = nyquist_film::extras::Estimate {
///     value: [1.0; 3],
///     variance: Some([0.04, 0.09, 0.0]),
///     halves: Some([[1.1, 1.0, 1.0], [0.9, 1.0, 1.0]]),
/// };
/// assert_eq!(e.standard_error(), Some([0.2, 0.3, 0.0]));
/// let d = e.half_difference().unwrap();
/// assert!((d[0] - 0.1).abs() < 1e-12 && d[1] == 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// The weighted mean per channel, Σ f·x / Σ f (0 where Σ f ≤ 0), before splats and
    /// without the image's clamp of negative values.
    pub value: [f64; 3],
    /// The variance of `value` per channel (module docs), when the film keeps variance and the
    /// pixel has more than one effective sample.
    pub variance: Option<[f64; 3]>,
    /// The means of the A and B halves, when the film keeps halves and both have Σ f > 0.
    pub halves: Option<[[f64; 3]; 2]>,
}

impl Estimate {
    /// The standard error of `value`: the square root of `variance`.
    pub fn standard_error(&self) -> Option<[f64; 3]> {
        self.variance.map(|v| v.map(f64::sqrt))
    }

    /// Half the difference of the halves' means, |A − B| / 2: an estimate of the standard
    /// error of `value` from the halves (for independent halves of n/2 samples each,
    /// Var(A − B) = 4·Var(value), so |A − B|/2 has the standard error's scale).
    pub fn half_difference(&self) -> Option<[f64; 3]> {
        self.halves
            .map(|[a, b]| [0, 1, 2].map(|c| (a[c] - b[c]).abs() * 0.5))
    }
}

/// The mean `sums / weight`, or 0 where `weight ≤ 0`.
pub(crate) fn mean(p: &Pixel) -> [f64; 3] {
    if p.weight_sum > 0.0 {
        p.rgb_sum.map(|s| s / p.weight_sum)
    } else {
        [0.0; 3]
    }
}

/// The images of a film's extras ([`crate::Film::extra_images`]), each `None` when not kept.
#[derive(Clone, Debug, Default)]
pub struct ExtraImages {
    /// The variance of each pixel's value per channel (NaN where undefined).
    pub variance: Option<Image>,
    /// The means of the A and B halves.
    pub halves: Option<[Image; 2]>,
    /// The extra channels' means.
    pub channels: Option<ChannelImage>,
}

impl ExtraImages {
    /// The film's image and these layers as named planes, ready for
    /// [`write_exr_planes`](crate::output::exr::write_exr_planes): `R`, `G`, `B` for the image,
    /// `variance.R` …, `half_a.R` …, `half_b.R` … when kept, and one plane per extra channel
    /// named by `channel_names` (OpenEXR's `layer.channel` convention: `albedo.R`, `normal.X`,
    /// `depth.Z`). Planes are row-major.
    ///
    /// # Errors
    /// [`Error::Config`] when `channel_names` does not give one name per extra channel, or a
    /// name is empty or repeats another plane's; [`Error::Format`] when an image's size differs
    /// from `image`'s.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig, FilmSample, PixelExtras};
    /// let mut config = FilmConfig::new(2, 2);
    /// config.extras = PixelExtras { variance: true, halves: false, channels: 1 };
    /// let mut film = Film::new(config, &nyquist::filter::Boxcar::default()).unwrap();
    /// film.add(&FilmSample { channels: &[4.0], ..FilmSample::new([0.5, 0.5], [1.0; 3], 1.0) });
    /// let image = film.try_image().unwrap().0;
    /// let planes = film.extra_images().unwrap().planes(&image, &["depth.Z"]).unwrap();
    /// let names: Vec<&str> = planes.iter().map(|(n, _)| n.as_str()).collect();
    /// assert_eq!(names, ["R", "G", "B", "variance.R", "variance.G", "variance.B", "depth.Z"]);
    /// assert_eq!(planes[6].1, [4.0, 0.0, 0.0, 0.0]);
    /// ```
    pub fn planes(
        &self,
        image: &Image,
        channel_names: &[&str],
    ) -> Result<Vec<crate::output::exr::Plane>, Error> {
        let mut planes = Vec::new();
        let mut rgb = |prefix: &str, im: &Image| -> Result<(), Error> {
            if (im.width(), im.height()) != (image.width(), image.height()) {
                return Err(Error::Format(format!(
                    "layer {prefix}: {}x{} against the image's {}x{}",
                    im.width(),
                    im.height(),
                    image.width(),
                    image.height()
                )));
            }
            for (c, name) in ["R", "G", "B"].into_iter().enumerate() {
                let plane = im.data().iter().skip(c).step_by(3).copied().collect();
                planes.push((format!("{prefix}{name}"), plane));
            }
            Ok(())
        };
        rgb("", image)?;
        if let Some(v) = &self.variance {
            rgb("variance.", v)?;
        }
        if let Some([a, b]) = &self.halves {
            rgb("half_a.", a)?;
            rgb("half_b.", b)?;
        }
        let channels = self.channels.as_ref().map_or(0, |c| c.channels());
        if channel_names.len() != channels {
            return Err(Error::Config(format!(
                "{} channel names for the film's {channels} extra channels",
                channel_names.len()
            )));
        }
        if let Some(c) = &self.channels {
            if (c.width(), c.height()) != (image.width(), image.height()) {
                return Err(Error::Format(format!(
                    "channels: {}x{} against the image's {}x{}",
                    c.width(),
                    c.height(),
                    image.width(),
                    image.height()
                )));
            }
            for (k, name) in channel_names.iter().enumerate() {
                let plane = c
                    .data()
                    .iter()
                    .skip(k)
                    .step_by(c.channels())
                    .copied()
                    .collect();
                planes.push((name.to_string(), plane));
            }
        }
        for (i, (name, _)) in planes.iter().enumerate() {
            if name.is_empty() || planes[..i].iter().any(|(n, _)| n == name) {
                return Err(Error::Config(format!(
                    "channel name '{name}' is empty or used twice"
                )));
            }
        }
        Ok(planes)
    }
}

/// An image of any number of `f32` channels per pixel, row-major, interleaved.
///
/// ```
/// let mut c = nyquist_film::extras::ChannelImage::new(2, 1, 4).unwrap();
/// c.data_mut()[7] = 1.5;
/// assert_eq!((c.width(), c.height(), c.channels()), (2, 1, 4));
/// assert_eq!(c.pixel(1, 0), [0.0, 0.0, 0.0, 1.5]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ChannelImage {
    width: u32,
    height: u32,
    channels: usize,
    data: Vec<f32>,
}

impl ChannelImage {
    /// A zero image of `width × height` pixels of `channels` values each.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a zero side or no channels; [`Error::Config`] when the size
    /// overflows an allocation; [`Error::OutOfMemory`] if the allocator cannot provide it.
    pub fn new(width: u32, height: u32, channels: usize) -> Result<ChannelImage, Error> {
        for (what, side) in [("image width", width), ("image height", height)] {
            if side == 0 {
                return Err(Error::below_one(what, 0, f64::from(u32::MAX)));
            }
        }
        if channels == 0 {
            return Err(Error::below_one(
                "image channels",
                0,
                f64::from(MAX_CHANNELS),
            ));
        }
        let len = (width as usize)
            .checked_mul(height as usize)
            .and_then(|p| p.checked_mul(channels))
            .filter(|&n| n <= isize::MAX as usize / 4)
            .ok_or_else(|| {
                Error::Config(format!(
                    "image size {width}x{height} of {channels} channels is more than an allocation can hold"
                ))
            })?;
        Ok(ChannelImage {
            width,
            height,
            channels,
            data: crate::error::try_filled(len, 0.0, "an image")?,
        })
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Values per pixel.
    pub fn channels(&self) -> usize {
        self.channels
    }

    /// The values, row-major, `channels` per pixel.
    pub fn data(&self) -> &[f32] {
        &self.data
    }

    /// The values, mutable.
    pub fn data_mut(&mut self) -> &mut [f32] {
        &mut self.data
    }

    /// The values of pixel `(x, y)`.
    ///
    /// # Panics
    /// If `(x, y)` is outside the image.
    pub fn pixel(&self, x: u32, y: u32) -> &[f32] {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside {}x{}",
            self.width,
            self.height
        );
        let i = (y as usize * self.width as usize + x as usize) * self.channels;
        &self.data[i..i + self.channels]
    }

    /// Channel `c` as an RGB [`Image`] (the value in all three components), for the PNG and
    /// PFM writers; `None` when `c` is not a channel.
    ///
    /// ```
    /// let mut c = nyquist_film::extras::ChannelImage::new(1, 1, 2).unwrap();
    /// c.data_mut()[1] = 0.25;
    /// assert_eq!(c.channel_image(1).unwrap().get(0, 0), [0.25; 3]);
    /// assert!(c.channel_image(2).is_none());
    /// ```
    pub fn channel_image(&self, c: usize) -> Option<Image> {
        (c < self.channels)
            .then(|| Image::from_fn(self.width, self.height, |x, y| [self.pixel(x, y)[c]; 3]))
    }
}

/// One pixel's second moments: Σ f², the f²-weighted mean of each channel and the sum of
/// f²-weighted squared deviations from it (West's weighted Welford update; see the module
/// docs).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Moments {
    /// Σ f².
    pub(crate) w2: f64,
    /// Σ f²·x / Σ f², per channel.
    pub(crate) mean: [f64; 3],
    /// Σ f²·(x − mean)², per channel.
    pub(crate) m2: [f64; 3],
}

impl Moments {
    /// Adds the value `x` with filter weight `f` (weight `f²`); a weight whose square is 0 adds
    /// nothing.
    pub(crate) fn add(&mut self, f: f64, x: [f64; 3]) {
        let v = f * f;
        if v == 0.0 {
            return;
        }
        self.w2 += v;
        let r = v / self.w2;
        for c in 0..3 {
            let d = x[c] - self.mean[c];
            self.mean[c] += d * r;
            self.m2[c] += v * d * (x[c] - self.mean[c]);
        }
    }

    /// Merges `o` into these moments (Chan, Golub and LeVeque's pairwise update).
    pub(crate) fn merge(&mut self, o: &Moments) {
        if o.w2 == 0.0 {
            return;
        }
        if self.w2 == 0.0 {
            *self = *o;
            return;
        }
        let w = self.w2 + o.w2;
        let r = o.w2 / w;
        let cross = self.w2 * r;
        for c in 0..3 {
            let d = o.mean[c] - self.mean[c];
            self.mean[c] += d * r;
            self.m2[c] += o.m2[c] + d * d * cross;
        }
        self.w2 = w;
    }

    /// The variance of the weighted mean of channel `c` of a pixel whose sums are `p`:
    /// Q / ((Σ f)² − Σ f²) with Q = m2 + (mean − I)²·Σ f² (see the module docs); `None` when
    /// the denominator is not positive (fewer than two effective samples) or the result is not
    /// finite.
    pub(crate) fn variance_of_mean(&self, p: &Pixel, c: usize) -> Option<f64> {
        let w1 = p.weight_sum;
        let denominator = w1 * w1 - self.w2;
        if !(denominator > 0.0) {
            return None;
        }
        let d = self.mean[c] - p.rgb_sum[c] / w1;
        let v = (self.m2[c] + d * d * self.w2) / denominator;
        v.is_finite().then_some(v.max(0.0))
    }
}

/// A tile's (or the film's) extra sums, per stored pixel, row-major like its pixels; each part
/// empty when the film does not keep it.
#[derive(Clone, Debug, Default)]
pub(crate) struct ExtraSums {
    pub(crate) moments: Vec<Moments>,
    /// The B half's sums (A is the whole less B).
    pub(crate) half_b: Vec<Pixel>,
    /// `channels` sums Σ f·a per pixel.
    pub(crate) channels: Vec<f64>,
    /// Channels per pixel.
    pub(crate) n: usize,
}

impl ExtraSums {
    /// Zeroed sums for `pixels` stored pixels, or `None` when `extras` keeps nothing.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`] if the allocator cannot provide them.
    pub(crate) fn new(
        extras: &PixelExtras,
        pixels: usize,
    ) -> Result<Option<Box<ExtraSums>>, crate::Error> {
        if !extras.any() {
            return Ok(None);
        }
        let n = usize::from(extras.channels);
        let sized = |on: bool, len: usize| if on { len } else { 0 };
        Ok(Some(Box::new(ExtraSums {
            moments: crate::error::try_filled(
                sized(extras.variance, pixels),
                Moments::default(),
                "the film's variance sums",
            )?,
            half_b: crate::error::try_filled(
                sized(extras.halves, pixels),
                Pixel::default(),
                "the film's half sums",
            )?,
            channels: crate::error::try_filled(
                n.saturating_mul(pixels),
                0.0,
                "the film's channel sums",
            )?,
            n,
        })))
    }

    /// Adds one sample's contribution to stored pixel `i`: filter weight `f = b·a` (the two
    /// factors the film's sums take, so that the B half's sums are formed as the sums are:
    /// `b·(a·l)`), value `l` (`weight·rgb`), half `half`, channel values `v`.
    pub(crate) fn add(&mut self, i: usize, a: f64, b: f64, l: [f64; 3], half: usize, v: &[f32]) {
        let f = b * a;
        if let Some(m) = self.moments.get_mut(i) {
            m.add(f, l);
        }
        if half == 1
            && let Some(p) = self.half_b.get_mut(i)
        {
            for c in 0..3 {
                p.rgb_sum[c] += b * (a * l[c]);
            }
            p.weight_sum += f;
        }
        if let Some(sums) = self.channels.get_mut(i * self.n..(i + 1) * self.n) {
            for (s, &v) in sums.iter_mut().zip(v) {
                *s += f * f64::from(v);
            }
        }
    }

    /// Merges stored pixel `from` of `o` into pixel `to` of these sums.
    pub(crate) fn merge_pixel(&mut self, to: usize, o: &ExtraSums, from: usize) {
        if let (Some(d), Some(s)) = (self.moments.get_mut(to), o.moments.get(from)) {
            d.merge(s);
        }
        if let (Some(d), Some(s)) = (self.half_b.get_mut(to), o.half_b.get(from)) {
            d.add(s);
        }
        let n = self.n;
        if let (Some(d), Some(s)) = (
            self.channels.get_mut(to * n..(to + 1) * n),
            o.channels.get(from * n..(from + 1) * n),
        ) {
            for (d, s) in d.iter_mut().zip(s) {
                *d += s;
            }
        }
    }

    /// The estimate of stored pixel `i`, whose sums are `p`.
    pub(crate) fn estimate(&self, i: usize, p: &Pixel) -> Estimate {
        let variance = self.moments.get(i).and_then(|m| {
            let v = [0, 1, 2].map(|c| m.variance_of_mean(p, c));
            Some([v[0]?, v[1]?, v[2]?])
        });
        let halves = self.half_b.get(i).and_then(|b| {
            let a = Pixel {
                rgb_sum: [0, 1, 2].map(|c| p.rgb_sum[c] - b.rgb_sum[c]),
                weight_sum: p.weight_sum - b.weight_sum,
            };
            (a.weight_sum > 0.0 && b.weight_sum > 0.0).then(|| [mean(&a), mean(b)])
        });
        Estimate {
            value: mean(p),
            variance,
            halves,
        }
    }

    /// The channel means of stored pixel `i` whose filter weights sum to `weight` (0 where
    /// `weight ≤ 0`).
    pub(crate) fn channel_means(&self, i: usize, weight: f64) -> impl Iterator<Item = f64> + '_ {
        let inv = if weight > 0.0 { 1.0 / weight } else { 0.0 };
        self.channels
            .get(i * self.n..(i + 1) * self.n)
            .unwrap_or(&[])
            .iter()
            .map(move |s| s * inv)
    }

    /// Bytes of these sums.
    pub(crate) fn bytes(&self) -> usize {
        self.moments.len() * size_of::<Moments>()
            + self.half_b.len() * size_of::<Pixel>()
            + self.channels.len() * size_of::<f64>()
    }
}

#[cfg(test)]
#[path = "../tests/support/double_double.rs"]
mod double_double;

#[cfg(test)]
mod tests {
    use super::double_double::{ulps, variance_of_mean};
    use super::*;

    fn pixel_of(samples: &[(f64, f64)]) -> (Pixel, Moments) {
        let mut p = Pixel::default();
        let mut m = Moments::default();
        for &(f, x) in samples {
            p.rgb_sum[0] += f * x;
            p.weight_sum += f;
            m.add(f, [x, 2.0 * x, -x]);
        }
        (p, m)
    }

    #[test]
    fn equal_weights_give_the_sample_variance_over_n() {
        // 1, 2, 3, 4: s² = 5/3, so the variance of the mean is 5/12.
        let s: Vec<(f64, f64)> = (1..=4).map(|x| (0.5, f64::from(x))).collect();
        let (p, m) = pixel_of(&s);
        assert_eq!(m.w2, 1.0);
        assert_eq!(m.mean[0], 2.5);
        assert_eq!(m.m2[0], 0.25 * 5.0);
        let v = m.variance_of_mean(&p, 0).unwrap();
        assert!((v - 5.0 / 12.0).abs() < 1e-15, "{v}");
    }

    #[test]
    fn one_sample_or_zero_weights_have_no_variance() {
        let (p, m) = pixel_of(&[(0.7, 3.0)]);
        assert_eq!(m.variance_of_mean(&p, 0), None);
        let (p, m) = pixel_of(&[(0.0, 3.0), (0.0, 1.0)]);
        assert_eq!((m.w2, m.mean, m.m2), (0.0, [0.0; 3], [0.0; 3]));
        assert_eq!(m.variance_of_mean(&p, 0), None);
    }

    #[test]
    fn a_constant_has_variance_zero() {
        let s: Vec<(f64, f64)> = (0..9).map(|i| (0.25 + f64::from(i) * 0.1, 7.5)).collect();
        let (p, m) = pixel_of(&s);
        assert_eq!(m.m2, [0.0; 3]);
        assert_eq!(m.mean, [7.5, 15.0, -7.5]);
        // Only the rounding of I = Σ f·x / Σ f (a few ulps of 7.5) is left.
        let v = m.variance_of_mean(&p, 0).unwrap();
        assert!(v < (8.0 * f64::EPSILON * 7.5).powi(2), "{v}");
    }

    #[test]
    fn merging_halves_equals_adding_in_one_run() {
        let s: Vec<(f64, f64)> = (0..40)
            .map(|i| {
                let i = f64::from(i);
                (0.2 + (i * 0.37) % 1.0 - 0.1, (i * 1.618) % 3.0)
            })
            .collect();
        let (p, whole) = pixel_of(&s);
        for cut in [0, 1, 17, 39, 40] {
            let (_, mut a) = pixel_of(&s[..cut]);
            let (_, b) = pixel_of(&s[cut..]);
            a.merge(&b);
            assert!((a.w2 - whole.w2).abs() <= 1e-15 * whole.w2, "cut {cut}");
            for c in 0..3 {
                let scale = whole.mean[c].abs().max(1.0);
                assert!(
                    (a.mean[c] - whole.mean[c]).abs() <= 1e-14 * scale,
                    "cut {cut}"
                );
                assert!(
                    (a.m2[c] - whole.m2[c]).abs() <= 1e-13 * whole.m2[c],
                    "cut {cut}"
                );
            }
            let (va, vw) = (a.variance_of_mean(&p, 0), whole.variance_of_mean(&p, 0));
            assert!(
                (va.unwrap() - vw.unwrap()).abs() <= 1e-13 * vw.unwrap(),
                "cut {cut}"
            );
        }
    }

    #[test]
    fn the_variance_agrees_with_two_passes_in_double_double() {
        // Weights from a Mitchell-like range with negative lobes, values far from 0 (the case
        // where a one-pass Σx² form cancels: here the variance's relative condition is about
        // 10⁶, and a Σx² form loses every digit).
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut worst = 0.0f64;
        for n in [2usize, 3, 10, 100, 1000, 10_000] {
            let s: Vec<(f64, f64)> = (0..n)
                .map(|_| (next() * 1.2 - 0.1, 1000.0 + next()))
                .collect();
            let (p, m) = pixel_of(&s);
            let want = variance_of_mean(&s);
            let got = m.variance_of_mean(&p, 0).unwrap();
            worst = worst.max(ulps(got, want));
        }
        // Measured: 6419 ulps (1.4·10⁻¹² relative) at most over these six sets, against a
        // condition number of about 10⁶; the bound is 2¹⁴ ulps.
        assert!(worst <= 16384.0, "{worst} ulps");
    }

    #[test]
    fn halves_alternate_in_pairs_and_balance_every_four() {
        for base in (0..1u64 << 12).step_by(4) {
            let b: usize = (base..base + 4).map(sample_half).sum();
            assert_eq!(b, 2, "indices {base}..{}", base + 4);
        }
        assert_eq!(sample_half(0xaaaa_aaaa_aaaa_aaaa), 0); // 32 bits set
        assert_eq!(sample_half(1 << 63), 1);
        assert_eq!(sample_half((1 << 62) | 1), 0);
    }

    #[test]
    fn the_error_estimates_are_the_square_root_and_half_the_difference() {
        let e = Estimate {
            value: [1.0; 3],
            variance: Some([0.04, 0.09, 0.0]),
            halves: Some([[1.5, 1.0, 0.0], [0.5, 1.25, 0.0]]),
        };
        assert_eq!(e.standard_error(), Some([0.2, 0.3, 0.0]));
        assert_eq!(e.half_difference(), Some([0.5, 0.125, 0.0]));
        let none = Estimate {
            variance: None,
            halves: None,
            ..e
        };
        assert_eq!(
            (none.standard_error(), none.half_difference()),
            (None, None)
        );
    }

    #[test]
    fn a_channel_image_gives_each_channel_and_no_other() {
        let mut c = ChannelImage::new(2, 1, 3).unwrap();
        c.data_mut()
            .copy_from_slice(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        assert_eq!(
            c.channel_image(0).unwrap().data(),
            [1.0, 1.0, 1.0, 4.0, 4.0, 4.0]
        );
        assert_eq!(
            c.channel_image(2).unwrap().data(),
            [3.0, 3.0, 3.0, 6.0, 6.0, 6.0]
        );
        assert!(c.channel_image(3).is_none());
        assert!(ChannelImage::new(2, 1, 0).is_err());
        assert!(ChannelImage::new(0, 1, 2).is_err());
    }

    #[test]
    fn plane_names_must_be_given_once_and_not_empty() {
        let image = Image::new(1, 1).unwrap();
        let layers = ExtraImages {
            channels: Some(ChannelImage::new(1, 1, 1).unwrap()),
            ..ExtraImages::default()
        };
        assert_eq!(layers.planes(&image, &["depth.Z"]).unwrap().len(), 4);
        for bad in ["", "G"] {
            let e = layers.planes(&image, &[bad]).unwrap_err();
            assert_eq!(
                e.to_string(),
                format!("invalid configuration: channel name '{bad}' is empty or used twice")
            );
        }
        let e = layers.planes(&image, &[]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid configuration: 0 channel names for the film's 1 extra channels"
        );
    }

    #[test]
    fn extra_sums_add_and_merge_each_part() {
        let extras = PixelExtras {
            variance: true,
            halves: true,
            channels: 2,
        };
        let mut a = ExtraSums::new(&extras, 3).unwrap().unwrap();
        a.add(1, 0.5, 1.0, [2.0, 4.0, 6.0], 1, &[1.0, -1.0]);
        a.add(1, 1.0, 0.25, [1.0; 3], 0, &[3.0, 5.0]);
        assert_eq!(a.half_b[1].rgb_sum, [1.0, 2.0, 3.0]);
        assert_eq!(a.half_b[1].weight_sum, 0.5);
        assert_eq!(a.channels[2..4], [1.25, 0.75]);
        assert_eq!(a.moments[1].w2, 0.3125);
        let mut b = ExtraSums::new(&extras, 2).unwrap().unwrap();
        b.merge_pixel(0, &a, 1);
        assert_eq!(b.half_b[0], a.half_b[1]);
        assert_eq!(b.channels[..2], a.channels[2..4]);
        assert_eq!(b.moments[0], a.moments[1]);
        assert_eq!(b.bytes(), 2 * (56 + 32 + 16));
        assert!(
            ExtraSums::new(&PixelExtras::default(), 3)
                .unwrap()
                .is_none()
        );
    }

    #[test]
    fn channels_merge_between_any_pixels() {
        // Three channels, pixels 2 and 3: an index formed with + instead of × (or the other
        // way) would read or write other pixels' channels.
        let extras = PixelExtras {
            channels: 3,
            ..PixelExtras::default()
        };
        let mut a = ExtraSums::new(&extras, 4).unwrap().unwrap();
        a.add(2, 1.0, 1.0, [0.0; 3], 0, &[1.0, 2.0, 3.0]);
        let mut b = ExtraSums::new(&extras, 5).unwrap().unwrap();
        b.merge_pixel(3, &a, 2);
        b.merge_pixel(3, &a, 2);
        assert_eq!(b.channels[9..12], [2.0, 4.0, 6.0]);
        assert!(
            b.channels[..9]
                .iter()
                .chain(&b.channels[12..])
                .all(|&v| v == 0.0)
        );
        assert!(
            a.channels[..6]
                .iter()
                .chain(&a.channels[9..])
                .all(|&v| v == 0.0)
        );
    }
}
