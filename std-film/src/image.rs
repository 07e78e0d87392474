//! A linear-RGB `f32` image.

use crate::error::Error;

/// A linear-RGB image, `f32` per channel, rows top to bottom, pixels left to right.
///
/// ```
/// let mut img = nyquist_film::Image::new(4, 3).unwrap();
/// img.set(1, 2, [0.5, 0.25, 1.0]);
/// assert_eq!(img.get(1, 2), [0.5, 0.25, 1.0]);
/// assert_eq!(img.data().len(), 4 * 3 * 3);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    width: u32,
    height: u32,
    data: Vec<f32>,
}

impl Image {
    /// A black image.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if a side is zero; [`Error::Config`] if the pixel count overflows
    /// memory limits; [`Error::OutOfMemory`] if the allocator cannot provide the pixels.
    ///
    /// ```
    /// let e = nyquist_film::Image::new(0, 3).unwrap_err();
    /// assert_eq!(e.to_string(), "image width 0 is outside 1..=4294967295");
    /// ```
    pub fn new(width: u32, height: u32) -> Result<Image, Error> {
        let len = Self::data_len(width, height)?;
        Ok(Image {
            width,
            height,
            data: crate::error::try_filled(len, 0.0, "an image")?,
        })
    }

    fn data_len(width: u32, height: u32) -> Result<usize, Error> {
        for (what, side) in [("image width", width), ("image height", height)] {
            if side == 0 {
                return Err(Error::below_one(what, 0, f64::from(u32::MAX)));
            }
        }
        // The floats of the image, at most what one allocation can hold. In u64 (an overflow
        // is reported as more than u64::MAX): no u128 formatter in the programs that link this.
        const LIMIT: usize = isize::MAX as usize / 4;
        let floats = u64::from(width)
            .checked_mul(u64::from(height))
            .and_then(|p| p.checked_mul(3));
        floats
            .and_then(|n| usize::try_from(n).ok())
            .filter(|&n| n <= LIMIT)
            .ok_or_else(|| {
                let needs =
                    floats.map_or_else(|| format!("more than {}", u64::MAX), |n| n.to_string());
                Error::Config(format!(
                    "image size {width}x{height} needs {needs} floats, more than the {LIMIT} \
                     an allocation can hold"
                ))
            })
    }

    /// An image whose pixel `(x, y)` is `f(x, y)`.
    ///
    /// # Panics
    /// If a side is zero (use [`Image::new`] to get an error instead).
    ///
    /// ```
    /// let img = nyquist_film::Image::from_fn(2, 2, |x, y| [x as f32, y as f32, 0.0]);
    /// assert_eq!(img.get(1, 0), [1.0, 0.0, 0.0]);
    /// ```
    pub fn from_fn(width: u32, height: u32, mut f: impl FnMut(u32, u32) -> [f32; 3]) -> Image {
        let mut img = Image::new(width, height).unwrap_or_else(|e| panic!("{e}"));
        for y in 0..height {
            for x in 0..width {
                img.set(x, y, f(x, y));
            }
        }
        img
    }

    /// An image over existing RGB data (`width × height × 3` floats).
    ///
    /// # Errors
    /// [`Error::Config`] if the length does not match.
    ///
    /// ```
    /// assert!(nyquist_film::Image::from_rgb(1, 1, vec![0.0; 3]).is_ok());
    /// assert!(nyquist_film::Image::from_rgb(1, 1, vec![0.0; 4]).is_err());
    /// ```
    pub fn from_rgb(width: u32, height: u32, data: Vec<f32>) -> Result<Image, Error> {
        let len = Self::data_len(width, height)?;
        if data.len() != len {
            return Err(Error::Config(format!(
                "{} floats given for a {width}x{height} RGB image ({len} needed)",
                data.len()
            )));
        }
        Ok(Image {
            width,
            height,
            data,
        })
    }

    /// Width in pixels.
    ///
    /// ```
    /// assert_eq!(nyquist_film::Image::new(4, 3).unwrap().width(), 4);
    /// ```
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    ///
    /// ```
    /// assert_eq!(nyquist_film::Image::new(4, 3).unwrap().height(), 3);
    /// ```
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The RGB floats, row-major from the top row.
    ///
    /// ```
    /// let img = nyquist_film::Image::from_fn(2, 1, |x, _| [x as f32, 0.5, 0.25]);
    /// assert_eq!(img.data(), &[0.0, 0.5, 0.25, 1.0, 0.5, 0.25]);
    /// ```
    pub fn data(&self) -> &[f32] {
        &self.data
    }

    /// The RGB floats, mutable.
    ///
    /// ```
    /// let mut img = nyquist_film::Image::new(2, 1).unwrap();
    /// img.data_mut()[3] = 1.0;
    /// assert_eq!(img.get(1, 0), [1.0, 0.0, 0.0]);
    /// ```
    pub fn data_mut(&mut self) -> &mut [f32] {
        &mut self.data
    }

    fn offset(&self, x: u32, y: u32) -> usize {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside the image"
        );
        (y as usize * self.width as usize + x as usize) * 3
    }

    /// Pixel `(x, y)`.
    ///
    /// # Panics
    /// If `(x, y)` is outside the image.
    ///
    /// ```
    /// let img = nyquist_film::Image::from_fn(3, 2, |x, y| [x as f32, y as f32, 0.0]);
    /// assert_eq!(img.get(2, 1), [2.0, 1.0, 0.0]);
    /// ```
    pub fn get(&self, x: u32, y: u32) -> [f32; 3] {
        let o = self.offset(x, y);
        [self.data[o], self.data[o + 1], self.data[o + 2]]
    }

    /// Sets pixel `(x, y)`.
    ///
    /// # Panics
    /// If `(x, y)` is outside the image.
    ///
    /// ```
    /// let mut img = nyquist_film::Image::new(3, 2).unwrap();
    /// img.set(2, 1, [0.5; 3]);
    /// assert_eq!(img.get(2, 1), [0.5; 3]);
    /// ```
    pub fn set(&mut self, x: u32, y: u32, rgb: [f32; 3]) {
        let o = self.offset(x, y);
        self.data[o..o + 3].copy_from_slice(&rgb);
    }

    /// Root-mean-square difference from `reference` over every channel of every pixel, in
    /// `f64`: `√(Σ (a − b)² / (3·width·height))`. 0 for identical images.
    ///
    /// # Errors
    /// [`Error::Config`] if the sizes differ.
    ///
    /// ```
    /// use nyquist_film::Image;
    /// let a = Image::from_fn(2, 1, |x, _| [x as f32; 3]);
    /// let b = Image::from_fn(2, 1, |_, _| [0.0; 3]);
    /// // Three channels of 1 − 0 and three of 0 − 0: √(3 / 6).
    /// assert_eq!(a.rmse(&b).unwrap(), 0.5f64.sqrt());
    /// assert_eq!(a.rmse(&a).unwrap(), 0.0);
    /// assert!(a.rmse(&Image::new(1, 2).unwrap()).is_err());
    /// ```
    pub fn rmse(&self, reference: &Image) -> Result<f64, Error> {
        self.check_same_size(reference)?;
        let n = self.data.len() as f64;
        let sum: f64 = self
            .data
            .iter()
            .zip(&reference.data)
            .map(|(&a, &b)| (f64::from(a) - f64::from(b)).powi(2))
            .sum();
        Ok((sum / n).sqrt())
    }

    /// Peak signal-to-noise ratio against `reference` in decibels for a peak of 1 (linear
    /// radiance in `[0, 1]`): `−20·log₁₀(`[`rmse`](Image::rmse)`)`, infinite for identical
    /// images.
    ///
    /// # Errors
    /// [`Error::Config`] if the sizes differ.
    ///
    /// ```
    /// use nyquist_film::Image;
    /// let a = Image::from_fn(2, 2, |_, _| [0.5; 3]);
    /// let b = Image::from_fn(2, 2, |_, _| [0.6; 3]);
    /// assert!((a.psnr(&b).unwrap() - 20.0).abs() < 1e-5); // an error of 0.1 everywhere
    /// assert_eq!(a.psnr(&a).unwrap(), f64::INFINITY);
    /// ```
    pub fn psnr(&self, reference: &Image) -> Result<f64, Error> {
        self.rmse(reference).map(psnr_of_rmse)
    }

    /// Root-mean-square difference between one channel (0 red, 1 green, 2 blue) and a
    /// reference value per pixel (row-major, in `f64`, such as an analytic scene's pixel
    /// means): `√(Σ (a − r)² / (width·height))`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if `channel` is above 2; [`Error::Config`] unless `reference`
    /// holds one value per pixel.
    ///
    /// ```
    /// use nyquist_film::Image;
    /// let img = Image::from_fn(2, 1, |x, _| [x as f32, 9.0, 9.0]);
    /// assert_eq!(img.channel_rmse(0, &[0.0, 0.5]).unwrap(), 0.125f64.sqrt());
    /// assert!(img.channel_rmse(3, &[0.0, 0.5]).is_err());
    /// assert!(img.channel_rmse(0, &[0.0]).is_err());
    /// ```
    pub fn channel_rmse(&self, channel: usize, reference: &[f64]) -> Result<f64, Error> {
        if channel > 2 {
            return Err(Error::OutOfRange {
                what: "channel",
                value: channel as f64,
                min: 0.0,
                max: 2.0,
            });
        }
        let pixels = self.data.len() / 3;
        if reference.len() != pixels {
            return Err(Error::Config(format!(
                "{} reference values for a {}x{} image ({pixels} needed)",
                reference.len(),
                self.width,
                self.height
            )));
        }
        let sum: f64 = self
            .data
            .chunks_exact(3)
            .zip(reference)
            .map(|(p, &r)| (f64::from(p[channel]) - r).powi(2))
            .sum();
        Ok((sum / pixels as f64).sqrt())
    }

    /// [`psnr`](Image::psnr) of one channel against a reference value per pixel:
    /// `−20·log₁₀(`[`channel_rmse`](Image::channel_rmse)`)`.
    ///
    /// # Errors
    /// As [`channel_rmse`](Image::channel_rmse).
    ///
    /// ```
    /// use nyquist_film::Image;
    /// let img = Image::from_fn(3, 1, |_, _| [0.25, 0.0, 0.0]);
    /// assert!((img.channel_psnr(0, &[0.35; 3]).unwrap() - 20.0).abs() < 1e-5);
    /// ```
    pub fn channel_psnr(&self, channel: usize, reference: &[f64]) -> Result<f64, Error> {
        self.channel_rmse(channel, reference).map(psnr_of_rmse)
    }

    fn check_same_size(&self, other: &Image) -> Result<(), Error> {
        if (self.width, self.height) != (other.width, other.height) {
            return Err(Error::Config(format!(
                "image sizes differ: {}x{} against a {}x{} reference",
                self.width, self.height, other.width, other.height
            )));
        }
        Ok(())
    }
}

/// PSNR in dB for a peak of 1: `−20·log₁₀(rmse)`, through `libm` so every target gives the same
/// bits.
fn psnr_of_rmse(rmse: f64) -> f64 {
    -20.0 * libm::log10(rmse)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic image with values spread over `[−1, 2)`.
    fn noisy(width: u32, height: u32, seed: u64) -> Image {
        let mut rng = nyquist::rng::default_rng(seed);
        Image::from_fn(width, height, |_, _| {
            [(); 3].map(|_| 3.0 * nyquist::rng::uniform_f32(&mut rng) - 1.0)
        })
    }

    /// The metrics are, bit for bit, the formulas the command line and the path tracer used
    /// before them: all channels against an image (mean over every float), one channel against
    /// per-pixel `f64` references (mean over the pixels), PSNR `−20·log₁₀(rmse)` through `libm`.
    #[test]
    fn metrics_are_the_front_ends_formulas() {
        let (a, b) = (noisy(7, 5, 1), noisy(7, 5, 2));
        let n = a.data().len() as f64;
        let sum: f64 = a
            .data()
            .iter()
            .zip(b.data())
            .map(|(x, y)| (f64::from(*x) - f64::from(*y)).powi(2))
            .sum();
        let want = (sum / n).sqrt();
        assert_eq!(a.rmse(&b).unwrap().to_bits(), want.to_bits());
        assert_eq!(
            a.psnr(&b).unwrap().to_bits(),
            (-20.0 * libm::log10(want)).to_bits()
        );
        let reference: Vec<f64> = (0..35).map(|i| f64::from(i) / 35.0).collect();
        for channel in 0..3 {
            let sum: f64 = a
                .data()
                .chunks_exact(3)
                .zip(&reference)
                .map(|(p, r)| (f64::from(p[channel]) - r).powi(2))
                .sum();
            let want = (sum / 35.0).sqrt();
            let got = a.channel_rmse(channel, &reference).unwrap();
            assert_eq!(got.to_bits(), want.to_bits(), "channel {channel}");
            let psnr = a.channel_psnr(channel, &reference).unwrap();
            assert_eq!(psnr.to_bits(), (-20.0 * libm::log10(want)).to_bits());
        }
        // Sizes and lengths that do not match, and channels past blue, are errors.
        assert!(a.rmse(&noisy(5, 7, 1)).is_err());
        assert!(a.psnr(&noisy(7, 4, 1)).is_err());
        assert!(a.channel_rmse(0, &reference[1..]).is_err());
        let e = a.channel_psnr(3, &reference).unwrap_err();
        assert_eq!(e.to_string(), "channel 3 is outside 0..=2");
        assert_eq!(a.psnr(&a).unwrap(), f64::INFINITY);
    }
}
