//! PNG output, through the `png` crate: film images as 8-bit sRGB ([`write_png`]), and already
//! quantised pixels (plots, masks, error images) through the same encoder settings
//! ([`write_png_pixels`]).
//!
//! The compression depends on the size of the pixel data: up to [`FAST_DEFLATE_ABOVE`] bytes
//! (4 MiB: a 1024 × 1024 RGB image, every plot) deflate level 2, above it level 1; every row
//! takes the `png` crate's adaptive filter. With the sRGB codes from a table, [`write_png`]
//! writes a 4096 × 4096 render about ten times faster than `powf` codes and level 6 (the `png`
//! crate's default) would, for about 5 % more bytes (figures: `docs/performance.md`, "PNG
//! output"). The bytes are deterministic.

use crate::error::Error;
use crate::image::Image;
use std::io::Write;
use std::sync::OnceLock;

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
/// Without noise the code comes from a table (built on first use, 16 KiB) instead of a `powf`,
/// with the same result for every `f32`.
///
/// ```
/// use nyquist_film::output::png::srgb_byte;
/// assert_eq!(srgb_byte(0.0, None), 0);
/// assert_eq!(srgb_byte(1.0, None), 255);
/// assert_eq!(srgb_byte(0.5, None), 188);
/// assert_eq!(srgb_byte(f32::NAN, None), 0);
/// ```
pub fn srgb_byte(x: f32, noise: Option<f32>) -> u8 {
    match noise {
        Some(u) => (255.0 * linear_to_srgb(x) + u).floor().clamp(0.0, 255.0) as u8,
        None => SrgbTable::get().code(x),
    }
}

/// `round(255 · srgb(x))` clamped to `0..=255`, from the formula: what [`SrgbTable`] is built
/// from and checked against.
fn srgb_code_formula(x: f32) -> u8 {
    (255.0 * linear_to_srgb(x)).round().clamp(0.0, 255.0) as u8
}

/// The floats of `[0, 1)` fall in `1.0f32.to_bits() >> BUCKET_SHIFT` buckets of `2^16`
/// consecutive bit patterns (a relative width of 1/128).
const BUCKET_SHIFT: u32 = 16;
const BUCKETS: usize = (0x3F80_0000 >> BUCKET_SHIFT) as usize;

/// The 8-bit sRGB code without `powf`. The code is a non-decreasing function of the linear
/// value, so it is the number of thresholds at or below the value. The bucket of the value's
/// bit pattern gives the code at the bucket's start; no bucket holds more than one threshold
/// above its start (checked when the table is built), so one comparison with the next
/// threshold finishes the code, without a branch.
struct SrgbTable {
    /// The code of each bucket's smallest float.
    start: [u8; BUCKETS],
    /// `threshold[b]` (`1 ≤ b ≤ 255`): the smallest float whose code is `b` or more;
    /// `threshold[256]` is infinite.
    threshold: [f32; 257],
}

impl SrgbTable {
    fn get() -> &'static SrgbTable {
        static TABLE: OnceLock<Box<SrgbTable>> = OnceLock::new();
        TABLE.get_or_init(|| {
            let mut t = Box::new(SrgbTable {
                start: [0; BUCKETS],
                threshold: [f32::INFINITY; 257],
            });
            for b in 1..=255u8 {
                // Bisection over the bit patterns of [0, 1], which order as the values do:
                // code(lo) < b ≤ code(hi) throughout.
                // At most 30 halvings of the 2^30 patterns; the bound keeps a broken split from
                // looping.
                let (mut lo, mut hi) = (0u32, 1.0f32.to_bits());
                for _ in 0..32 {
                    if hi - lo <= 1 {
                        break;
                    }
                    let mid = lo + (hi - lo) / 2;
                    if srgb_code_formula(f32::from_bits(mid)) >= b {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                t.threshold[usize::from(b)] = f32::from_bits(hi);
            }
            for (i, s) in t.start.iter_mut().enumerate() {
                *s = srgb_code_formula(f32::from_bits((i as u32) << BUCKET_SHIFT));
            }
            for i in 0..BUCKETS {
                // The code two above the bucket's start begins in a later bucket.
                let two_up = usize::from(t.start[i]) + 2;
                assert!(two_up > 256 || t.threshold[two_up].to_bits() >> BUCKET_SHIFT > i as u32);
            }
            t
        })
    }

    #[inline]
    fn code(&self, x: f32) -> u8 {
        if !(x > 0.0) {
            return 0;
        }
        if !(x < 1.0) {
            return 255;
        }
        let b = self.start[(x.to_bits() >> BUCKET_SHIFT) as usize];
        b + u8::from(x >= self.threshold[usize::from(b) + 1])
    }
}

/// The channels of [`write_png_pixels`]'s samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PngColor {
    /// One channel.
    Grey,
    /// Grey and alpha.
    GreyAlpha,
    /// Red, green, blue.
    Rgb,
    /// Red, green, blue, alpha.
    Rgba,
}

/// Bits per sample of [`write_png_pixels`]: 8, or 16 (big-endian, as PNG stores them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PngDepth {
    /// One byte per sample.
    Eight,
    /// Two bytes per sample, most significant first.
    Sixteen,
}

/// The layout of [`write_png_pixels`]'s rows, top to bottom without padding, and whether the
/// file declares them sRGB (an `sRGB` chunk, perceptual intent).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PngLayout {
    /// Pixels per row.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// Channels per pixel.
    pub color: PngColor,
    /// Bits per sample.
    pub depth: PngDepth,
    /// Write an `sRGB` chunk.
    pub srgb: bool,
}

impl PngLayout {
    /// `width × height` pixels of `color`, 8 bits per sample, no `sRGB` chunk.
    ///
    /// ```
    /// use nyquist_film::output::png::{PngColor, PngLayout};
    /// assert_eq!(PngLayout::new(4, 2, PngColor::Rgb).data_bytes(), 24);
    /// ```
    pub fn new(width: u32, height: u32, color: PngColor) -> PngLayout {
        PngLayout {
            width,
            height,
            color,
            depth: PngDepth::Eight,
            srgb: false,
        }
    }

    /// The bytes of the pixel data this layout takes.
    pub fn data_bytes(&self) -> u64 {
        let channels = match self.color {
            PngColor::Grey => 1,
            PngColor::GreyAlpha => 2,
            PngColor::Rgb => 3,
            PngColor::Rgba => 4,
        };
        let bytes = match self.depth {
            PngDepth::Eight => 1,
            PngDepth::Sixteen => 2,
        };
        u64::from(self.width) * u64::from(self.height) * channels * bytes
    }
}

/// Pixel data of more bytes than this is deflated at level 1, else at level 2.
///
/// Level 2 gives files within 7 % of level 6's (the `png` crate's default) in a sixth of its
/// time or less on a noisy render; level 1 takes about two thirds of level 2's time on such an
/// image for about 1 % more bytes, but makes plots (flat colours, lines, text) up to 30 % larger
/// than level 2 does. Up to this size (a 1024 × 1024 RGB image, every plot) level 2 costs well
/// under 0.1 s; above it the time is what matters, so level 1. Figures: `docs/performance.md`,
/// "PNG output".
///
/// ```
/// use nyquist_film::output::png::{FAST_DEFLATE_ABOVE, PngColor, PngLayout};
/// assert!(PngLayout::new(1024, 1024, PngColor::Rgb).data_bytes() <= FAST_DEFLATE_ABOVE as u64);
/// assert!(PngLayout::new(2048, 2048, PngColor::Rgb).data_bytes() > FAST_DEFLATE_ABOVE as u64);
/// ```
pub const FAST_DEFLATE_ABOVE: usize = 4 << 20;

/// Writes `data`, laid out as `layout` says, as a PNG: deflate level 2 up to
/// [`FAST_DEFLATE_ABOVE`] bytes of data, level 1 above, the adaptive row filter. The one PNG
/// encoder of the workspace: [`write_png`], the command line's masks and error images, and the
/// laboratory's plots all go through it.
///
/// # Errors
/// [`Error::Format`] if `data` does not have [`PngLayout::data_bytes`] bytes or the encoder
/// rejects the layout (a zero width or height), [`Error::Io`] if writing fails.
///
/// ```
/// use nyquist_film::output::png::{write_png_pixels, PngColor, PngLayout};
/// let mut out = Vec::new();
/// write_png_pixels(&mut out, &PngLayout::new(2, 1, PngColor::Grey), &[0, 255]).unwrap();
/// assert!(out.starts_with(b"\x89PNG"));
/// assert!(write_png_pixels(&mut out, &PngLayout::new(2, 1, PngColor::Grey), &[0]).is_err());
/// ```
pub fn write_png_pixels(w: &mut dyn Write, layout: &PngLayout, data: &[u8]) -> Result<(), Error> {
    if data.len() as u64 != layout.data_bytes() {
        return Err(Error::Format(format!(
            "PNG: {} bytes of pixel data for {} × {} pixels of {:?} at {:?} bits (expected {})",
            data.len(),
            layout.width,
            layout.height,
            layout.color,
            layout.depth,
            layout.data_bytes()
        )));
    }
    encode(w, layout, data, deflate_level(data.len()))
}

/// The deflate level of `bytes` bytes of pixel data: 2 up to [`FAST_DEFLATE_ABOVE`], else 1.
fn deflate_level(bytes: usize) -> u8 {
    if bytes > FAST_DEFLATE_ABOVE { 1 } else { 2 }
}

/// The encoder of [`write_png_pixels`] at a given deflate level; `data` has the layout's size.
fn encode(w: &mut dyn Write, layout: &PngLayout, data: &[u8], level: u8) -> Result<(), Error> {
    let mut encoder = ::png::Encoder::new(w, layout.width, layout.height);
    encoder.set_color(match layout.color {
        PngColor::Grey => ::png::ColorType::Grayscale,
        PngColor::GreyAlpha => ::png::ColorType::GrayscaleAlpha,
        PngColor::Rgb => ::png::ColorType::Rgb,
        PngColor::Rgba => ::png::ColorType::Rgba,
    });
    encoder.set_depth(match layout.depth {
        PngDepth::Eight => ::png::BitDepth::Eight,
        PngDepth::Sixteen => ::png::BitDepth::Sixteen,
    });
    if layout.srgb {
        encoder.set_source_srgb(::png::SrgbRenderingIntent::Perceptual);
    }
    encoder.set_deflate_compression(::png::DeflateCompression::Level(level));
    encoder.set_filter(::png::Filter::Adaptive);
    // A failing writer is an I/O error (named with its path by `write_image_file`), not the
    // encoder's.
    let fmt = |e: ::png::EncodingError| match e {
        ::png::EncodingError::IoError(e) => Error::Io(e),
        e => Error::Format(format!("PNG: {e}")),
    };
    let mut writer = encoder.write_header().map_err(fmt)?;
    writer.write_image_data(data).map_err(fmt)?;
    writer.finish().map_err(fmt)
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
    let bytes: Vec<u8> = match options.dither {
        Some(seed) => image
            .data()
            .iter()
            .enumerate()
            .map(|(k, &v)| {
                let h = nyquist::hash::hash2(seed, k as u64);
                srgb_byte(v, Some(nyquist::hash::unit_f32((h >> 32) as u32)))
            })
            .collect(),
        None => {
            let table = SrgbTable::get();
            image.data().iter().map(|&v| table.code(v)).collect()
        }
    };
    let layout = PngLayout {
        srgb: true,
        ..PngLayout::new(image.width(), image.height(), PngColor::Rgb)
    };
    write_png_pixels(w, &layout, &bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The table against the formula on every float within 1024 steps of each threshold and
    /// 16 of each bucket's start, and on every 1009th float of `[0, 1]`.
    #[test]
    fn the_table_gives_the_formulas_code_near_every_threshold_and_across_the_range() {
        let t = SrgbTable::get();
        let check = |bits: u32| {
            let x = f32::from_bits(bits);
            assert_eq!(
                t.code(x),
                srgb_code_formula(x),
                "x = {x:e} (bits {bits:#x})"
            );
        };
        let one = 1.0f32.to_bits();
        let mut checked = 0u64;
        let starts = (0..BUCKETS as u32).map(|i| i << BUCKET_SHIFT);
        let thresholds = t.threshold[1..256].iter().map(|x| (x.to_bits(), 1024));
        for (centre, reach) in thresholds.chain(starts.map(|s| (s, 16))) {
            for bits in centre.saturating_sub(reach)..=(centre + reach).min(one) {
                check(bits);
                checked += 1;
            }
        }
        for bits in (0..=one).step_by(1009) {
            check(bits);
        }
        assert!(checked > 255 * 2000 + (BUCKETS as u64 - 1) * 33);
        // The thresholds are where the formula's code steps up by one.
        assert_eq!(t.threshold[256], f32::INFINITY);
        for b in 1..=255usize {
            let at = t.threshold[b];
            let below = f32::from_bits(at.to_bits() - 1);
            assert_eq!(usize::from(srgb_code_formula(at)), b);
            assert_eq!(usize::from(srgb_code_formula(below)), b - 1);
        }
    }

    /// Every float of `[0, 1]` (about 10⁹; some 20 s in a release build):
    /// `cargo test --release -p nyquist-film --lib -- --ignored every_float`.
    #[test]
    #[ignore = "exhaustive over 2^30 floats; run in release"]
    fn the_table_gives_the_formulas_code_for_every_float_in_the_unit_interval() {
        let t = SrgbTable::get();
        for bits in 0..=1.0f32.to_bits() {
            let x = f32::from_bits(bits);
            assert_eq!(t.code(x), srgb_code_formula(x), "x = {x:e}");
        }
    }

    #[test]
    fn the_table_handles_values_outside_the_unit_interval() {
        let t = SrgbTable::get();
        for x in [
            f32::NAN,
            -f32::NAN,
            f32::NEG_INFINITY,
            -1.0,
            -0.0,
            -f32::MIN_POSITIVE,
            1.0,
            1.0 + f32::EPSILON,
            2.0,
            f32::MAX,
            f32::INFINITY,
        ] {
            assert_eq!(t.code(x), srgb_code_formula(x), "x = {x:e}");
        }
    }

    #[test]
    fn srgb_byte_rounds_without_noise_and_floors_with_it() {
        // 255·srgb(0.5) = 187.52…: rounded 188; with noise u, ⌊187.52 + u⌋.
        assert_eq!(srgb_byte(0.5, None), 188);
        assert_eq!(srgb_byte(0.5, Some(0.0)), 187);
        assert_eq!(srgb_byte(0.5, Some(0.47)), 187);
        assert_eq!(srgb_byte(0.5, Some(0.49)), 188);
        assert_eq!(srgb_byte(0.5, Some(0.999)), 188);
        // 255·srgb(0.2) = 124.0…: the noise decides between 124 and 125.
        let v = 255.0 * linear_to_srgb(0.2);
        assert_eq!(srgb_byte(0.2, Some(0.0)), v.floor() as u8);
        assert_eq!(srgb_byte(0.2, Some(0.999)), (v + 0.999).floor() as u8);
        // Clamped at both ends; NaN is 0.
        assert_eq!(srgb_byte(1.0, Some(0.999)), 255);
        assert_eq!(srgb_byte(2.0, Some(0.5)), 255);
        assert_eq!(srgb_byte(-1.0, Some(0.999)), 0);
        assert_eq!(srgb_byte(f32::NAN, Some(0.5)), 0);
        assert_eq!(srgb_byte(1.0, None), 255);
        // Without noise, the table's code for every 4099th float of [0, 1].
        for bits in (0..=1.0f32.to_bits()).step_by(4099) {
            let x = f32::from_bits(bits);
            assert_eq!(srgb_byte(x, None), srgb_code_formula(x), "{x:e}");
        }
    }

    #[test]
    fn data_bytes_count_every_channel_and_byte() {
        let at = |w, h, color, depth| PngLayout {
            depth,
            ..PngLayout::new(w, h, color)
        };
        assert_eq!(at(3, 2, PngColor::Grey, PngDepth::Eight).data_bytes(), 6);
        assert_eq!(
            at(3, 2, PngColor::GreyAlpha, PngDepth::Sixteen).data_bytes(),
            24
        );
        assert_eq!(at(3, 2, PngColor::Rgb, PngDepth::Sixteen).data_bytes(), 36);
        assert_eq!(at(3, 2, PngColor::Rgba, PngDepth::Sixteen).data_bytes(), 48);
    }

    /// Decodes a PNG: (width, height, colour type, bit depth, has an sRGB chunk, pixels).
    fn decode(bytes: &[u8]) -> (u32, u32, ::png::ColorType, ::png::BitDepth, bool, Vec<u8>) {
        let mut reader = ::png::Decoder::new(std::io::Cursor::new(bytes))
            .read_info()
            .unwrap();
        let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
        let frame = reader.next_frame(&mut pixels).unwrap();
        pixels.truncate(frame.buffer_size());
        let info = reader.info();
        let srgb = info.srgb.is_some();
        (
            info.width,
            info.height,
            info.color_type,
            info.bit_depth,
            srgb,
            pixels,
        )
    }

    #[test]
    fn write_png_writes_the_images_srgb_codes_with_an_srgb_chunk() {
        let mut image = Image::new(3, 2).unwrap();
        let values = [0.0, 0.5, 1.0, 0.2, f32::NAN, 2.0, 0.01, 0.8, -1.0];
        for (k, v) in image.data_mut().iter_mut().enumerate() {
            *v = values[k % values.len()];
        }
        let mut out = Vec::new();
        write_png(&mut out, &image, &PngOptions::default()).unwrap();
        let (w, h, color, depth, srgb, pixels) = decode(&out);
        assert_eq!((w, h), (3, 2));
        assert_eq!(
            (color, depth),
            (::png::ColorType::Rgb, ::png::BitDepth::Eight)
        );
        assert!(srgb, "no sRGB chunk");
        let want: Vec<u8> = image.data().iter().map(|&v| srgb_code_formula(v)).collect();
        assert_eq!(pixels, want);
    }

    #[test]
    fn dithered_codes_average_to_the_unrounded_value() {
        // 255·srgb(0.43) = 175.2…: rounding and flooring give 175 everywhere; only noise spread
        // over [0, 1) averages to the fraction. The hash noise is fixed by the seed, so the test
        // is deterministic; its mean over 12 288 codes is within 0.05 of the target (binomial σ
        // below 0.004).
        let mut image = Image::new(64, 64).unwrap();
        let v = 0.43f32;
        image.data_mut().iter_mut().for_each(|x| *x = v);
        let target = 255.0 * f64::from(linear_to_srgb(v));
        assert!((target.fract() - 0.5).abs() < 0.45, "{target}");
        let mut out = Vec::new();
        write_png(&mut out, &image, &PngOptions { dither: Some(7) }).unwrap();
        let (.., pixels) = decode(&out);
        let mean = pixels.iter().map(|&p| f64::from(p)).sum::<f64>() / pixels.len() as f64;
        assert!((mean - target).abs() < 0.05, "mean {mean}, target {target}");
        // Each code is the floor or the ceiling of the target.
        assert!(
            pixels
                .iter()
                .all(|&p| f64::from(p) == target.floor() || f64::from(p) == target.ceil())
        );
    }

    #[test]
    fn the_deflate_level_is_2_up_to_the_limit_and_1_above() {
        assert_eq!(deflate_level(0), 2);
        assert_eq!(deflate_level(FAST_DEFLATE_ABOVE), 2);
        assert_eq!(deflate_level(FAST_DEFLATE_ABOVE + 1), 1);
        assert_eq!(deflate_level(usize::MAX), 1);
    }

    #[test]
    fn both_levels_keep_the_pixels_and_write_png_pixels_uses_the_level_of_its_size() {
        let (w, h) = (200u32, 150u32);
        // Smooth ramps under hashed noise of a few codes: compressible, but not trivially.
        let data: Vec<u8> = (0..u64::from(w * h) * 3)
            .map(|k| {
                let (x, y) = ((k / 3) % u64::from(w), (k / 3) / u64::from(w));
                let noise = (nyquist::hash::hash2(5, k) >> 61) as u8;
                (x + 2 * y) as u8 / 2 + noise
            })
            .collect();
        let layout = PngLayout::new(w, h, PngColor::Rgb);
        let decode = |png: &[u8]| {
            let mut reader = ::png::Decoder::new(std::io::Cursor::new(png))
                .read_info()
                .unwrap();
            let mut buf = vec![0; reader.output_buffer_size().unwrap()];
            let info = reader.next_frame(&mut buf).unwrap();
            assert_eq!((info.width, info.height), (w, h));
            assert_eq!(info.color_type, ::png::ColorType::Rgb);
            buf.truncate(info.buffer_size());
            buf
        };
        let mut by_level = Vec::new();
        for level in [1, 2] {
            let mut out = Vec::new();
            encode(&mut out, &layout, &data, level).unwrap();
            assert_eq!(decode(&out), data, "level {level}");
            by_level.push(out);
        }
        assert_ne!(by_level[0], by_level[1]);
        let mut out = Vec::new();
        write_png_pixels(&mut out, &layout, &data).unwrap();
        assert_eq!(out, by_level[1]);
    }
}
