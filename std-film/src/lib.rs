//! # nyquist-film
//!
//! Film accumulation and image output for renderers built on [`nyquist`]. This crate grows with
//! the film work; today it holds the pixel geometry shared by the CLI.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

/// Film-space bounds of pixel `(x, y)`: it covers `[x, x+1) × [y, y+1)`, centre `(x+½, y+½)`.
///
/// ```
/// assert_eq!(nyquist_film::pixel_center(3, 4), (3.5, 4.5));
/// ```
pub fn pixel_center(x: u32, y: u32) -> (f64, f64) {
    (f64::from(x) + 0.5, f64::from(y) + 0.5)
}

pub mod periodogram;
