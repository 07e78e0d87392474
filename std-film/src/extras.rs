//! What a film can keep per pixel beside its RGB sums ([`PixelExtras`]): the variance of each
//! channel's weighted mean, the sums of two half-sample sets (A and B), and extra channels
//! (albedo, normal, depth, or any number of floats), all through the film's filter.
//!
//! **Variance** and **halves** are the estimators of [`nyquist::pixel_stats`] (its module docs
//! give them), kept for every stored pixel: the film holds each pixel's [`Moments`] and the B
//! half's sums, merges tiles in tile-index order, so the result is bit-identical for any thread
//! count and arrival order, and gives each pixel's [`Estimate`].
//!
//! **Channels.** `channels` floats per sample, accumulated as Σ f·a with the pixel's own Σ f
//! (not multiplied by the sample weight: an albedo is not radiance).

use crate::error::Error;
use crate::image::Image;
use crate::pixel::Pixel;

/// A named plane of `f32` samples, row-major: one channel of an image (`R`, `variance.R`,
/// `depth.Z`), as the EXR writer takes them.
pub type Plane = (String, Vec<f32>);
pub use nyquist::pixel_stats::{Estimate, Moments, sample_half};

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
    pub fn planes(&self, image: &Image, channel_names: &[&str]) -> Result<Vec<Plane>, Error> {
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
        Estimate::from_sums(
            p.rgb_sum,
            p.weight_sum,
            self.moments.get(i),
            self.half_b.get(i).map(|b| (b.rgb_sum, b.weight_sum)),
        )
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
mod tests {
    use super::*;

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
        assert_eq!(a.moments[1].weight2_sum(), 0.3125);
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
