//! # nyquist-film
//!
//! Film accumulation and image output for renderers built on [`nyquist`]: an [`Image`] of linear
//! RGB `f32` pixels and writers for PNG (8-bit sRGB), OpenEXR (f32 or f16) and PFM, each taking
//! any [`std::io::Write`]; [`write_image_file`] picks the format from the extension and writes a
//! temporary file beside the target that is renamed into place, so a failure leaves nothing behind.
//!
//! ```
//! use nyquist_film::{Image, output::png::{write_png, PngOptions}};
//! let img = Image::from_fn(2, 1, |x, _| [x as f32; 3]);
//! let mut bytes = Vec::new();
//! write_png(&mut bytes, &img, &PngOptions::default()).unwrap();
//! assert_eq!(&bytes[1..4], b"PNG");
//! ```
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod adaptive;
mod bounds;
mod coverage;
mod error;
pub mod extras;
mod film;
mod image;
#[cfg(feature = "output")]
pub mod output;
mod pixel;
mod render;
mod sample;
mod setup;
mod stats;
mod tile;
mod tile_spec;

pub use bounds::Bounds;
pub use error::Error;
pub use extras::PixelExtras;
pub use film::Film;
pub use image::Image;
#[cfg(feature = "output")]
pub use output::{ImageFormat, write_image, write_image_file};
pub use pixel::Pixel;
pub use render::{CAN_START_THREADS, TileContext, render_tiles};
pub use sample::FilmSample;
pub use setup::FilmConfig;
pub use stats::{FilmStats, ResolveStats};
pub use tile::FilmTile;
pub use tile_spec::TileSpec;

/// Film-space centre of pixel `(x, y)`: pixel `(x, y)` covers `[x, x+1) × [y, y+1)`.
///
/// ```
/// assert_eq!(nyquist_film::pixel_center(3, 4), (3.5, 4.5));
/// ```
pub fn pixel_center(x: u32, y: u32) -> (f64, f64) {
    (f64::from(x) + 0.5, f64::from(y) + 0.5)
}

pub mod periodogram;

/// The README's code blocks, compiled and run as doctests (here, where both `nyquist` and
/// `nyquist-film` are in scope).
#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
struct ReadmeDoctests;
