//! 8-bit sRGB PNG output, through the `png` crate.

use crate::error::Error;
use crate::image::Image;
use std::io::Write;

/// Options of the PNG writer.
///
/// ```
/// let opts = nyquist_film::output::png::PngOptions { dither: Some(7) };
/// assert!(opts.dither.is_some());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PngOptions {
    /// Dither the 8-bit quantisation with deterministic hashed noise of this seed (±½ LSB);
    /// `None` rounds to nearest.
    pub dither: Option<u64>,
}

/// The sRGB transfer function (IEC 61966-2-1) applied to a linear value clamped to `[0, 1]`;
/// NaN maps to 0.
///
/// ```
/// use nyquist_film::output::png::linear_to_srgb;
/// assert_eq!(linear_to_srgb(0.0), 0.0);
/// assert_eq!(linear_to_srgb(1.0), 1.0);
/// assert!((linear_to_srgb(0.5) - 0.735_356_9).abs() < 1e-5);
/// ```
pub fn linear_to_srgb(x: f32) -> f32 {
    if !(x > 0.0) {
        return 0.0;
    }
    if x >= 1.0 {
        return 1.0;
    }
    let x = f64::from(x);
    let s = if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    };
    s as f32
}

/// The 8-bit sRGB code of a linear value: `round(255 · srgb(x))`, or with `noise` in `[0, 1)`
/// `floor(255 · srgb(x) + noise)` (dithering). Clamped to `0..=255`.
///
/// ```
/// use nyquist_film::output::png::srgb_byte;
/// assert_eq!(srgb_byte(0.0, None), 0);
/// assert_eq!(srgb_byte(1.0, None), 255);
/// assert_eq!(srgb_byte(0.5, None), 188);
/// assert_eq!(srgb_byte(f32::NAN, None), 0);
/// ```
pub fn srgb_byte(x: f32, noise: Option<f32>) -> u8 {
    let v = 255.0 * linear_to_srgb(x);
    let q = match noise {
        Some(u) => (v + u).floor(),
        None => v.round(),
    };
    q.clamp(0.0, 255.0) as u8
}

/// Writes `image` as an 8-bit RGB PNG with the sRGB transfer function and an `sRGB` chunk.
/// Values are clamped to `[0, 1]`; NaN is written as 0.
///
/// # Errors
/// [`Error::Format`] if the encoder fails, [`Error::Io`] if writing fails.
///
/// ```
/// use nyquist_film::{output::png::{write_png, PngOptions}, Image};
/// let mut out = Vec::new();
/// write_png(&mut out, &Image::new(8, 8).unwrap(), &PngOptions::default()).unwrap();
/// assert!(out.len() > 8);
/// ```
pub fn write_png(w: &mut dyn Write, image: &Image, options: &PngOptions) -> Result<(), Error> {
    let (width, height) = (image.width(), image.height());
    let mut bytes = Vec::with_capacity(image.data().len());
    for (k, &v) in image.data().iter().enumerate() {
        let noise = options.dither.map(|seed| {
            let h = nyquist::hash::hash2(seed, k as u64);
            nyquist::hash::unit_f32((h >> 32) as u32)
        });
        bytes.push(srgb_byte(v, noise));
    }
    let mut encoder = ::png::Encoder::new(w, width, height);
    encoder.set_color(::png::ColorType::Rgb);
    encoder.set_depth(::png::BitDepth::Eight);
    encoder.set_source_srgb(::png::SrgbRenderingIntent::Perceptual);
    // A failing writer is an I/O error (named with its path by `write_image_file`), not the
    // encoder's.
    let fmt = |e: ::png::EncodingError| match e {
        ::png::EncodingError::IoError(e) => Error::Io(e),
        e => Error::Format(format!("PNG: {e}")),
    };
    let mut writer = encoder.write_header().map_err(fmt)?;
    writer.write_image_data(&bytes).map_err(fmt)?;
    writer.finish().map_err(fmt)
}
