//! How a film is set up: the public [`FilmConfig`] and the validated, shared [`Setup`].

use crate::bounds::Bounds;
use crate::error::Error;
use crate::extras::{MAX_CHANNELS, PixelExtras};
use nyquist::filter::{FilmTable, Filter};

/// How a [`Film`](crate::Film) is set up.
///
/// ```
/// let c = nyquist_film::FilmConfig::new(640, 480);
/// assert_eq!(c.crop_window, [0.0, 1.0, 0.0, 1.0]);
/// assert_eq!(c.max_component, None);
/// assert!(!c.extras.any());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilmConfig {
    /// Full resolution in pixels `[width, height]`.
    pub resolution: [u32; 2],
    /// Crop window in normalised film coordinates `[x0, x1, y0, y1]`, each in `[0, 1]`; the film
    /// stores the pixels `⌈x0·W⌉ … ⌈x1·W⌉ − 1` (and likewise in y), as pbrt does.
    pub crop_window: [f32; 4],
    /// Per-sample clamp: a sample whose largest RGB component exceeds this is scaled down to it
    /// (counted in [`FilmStats::clamped`](crate::FilmStats::clamped)). `None` keeps every
    /// sample as it is.
    pub max_component: Option<f32>,
    /// What the film keeps per pixel beside its RGB sums (variance, halves, extra channels);
    /// nothing by default.
    pub extras: PixelExtras,
}

impl FilmConfig {
    /// A full-frame film of `width × height` pixels with no clamp.
    ///
    /// ```
    /// assert_eq!(nyquist_film::FilmConfig::new(4, 3).resolution, [4, 3]);
    /// ```
    pub fn new(width: u32, height: u32) -> FilmConfig {
        FilmConfig {
            resolution: [width, height],
            crop_window: [0.0, 1.0, 0.0, 1.0],
            max_component: None,
            extras: PixelExtras::default(),
        }
    }
}

/// The parts of a film that its tiles share, read-only: the stored pixels, the filter table and
/// the clamp. Built once per film, behind an `Arc` the tiles hold.
#[derive(Debug)]
pub(crate) struct Setup {
    pub(crate) pixel_bounds: Bounds,
    pub(crate) table: FilmTable,
    pub(crate) max_component: Option<f32>,
    pub(crate) extras: PixelExtras,
}

impl Setup {
    /// Validates `config` and tabulates `filter`.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] for a zero side or a crop coordinate outside `[0, 1]`;
    /// [`Error::Config`] for an empty crop window or one that covers no pixel, and a
    /// non-finite or non-positive `max_component`; [`Error::OutOfRange`] for more than
    /// [`MAX_CHANNELS`] extra channels; [`Error::Core`] if the filter cannot be tabulated.
    pub(crate) fn new(config: &FilmConfig, filter: &dyn Filter) -> Result<Setup, Error> {
        let [w, h] = config.resolution;
        for (what, side) in [("width", w), ("height", h)] {
            if side == 0 {
                return Err(Error::below_one(what, 0, f64::from(u32::MAX)));
            }
        }
        let c = config.crop_window;
        for (what, v) in [
            "crop window x0",
            "crop window x1",
            "crop window y0",
            "crop window y1",
        ]
        .into_iter()
        .zip(c)
        {
            if !(0.0..=1.0).contains(&v) {
                return Err(Error::OutOfRange {
                    what,
                    value: f64::from(v),
                    min: 0.0,
                    max: 1.0,
                });
            }
        }
        for (axis, lo, hi) in [("x", c[0], c[1]), ("y", c[2], c[3])] {
            if lo >= hi {
                return Err(Error::Config(format!(
                    "crop window {axis}0 {lo} is not below {axis}1 {hi}"
                )));
            }
        }
        if let Some(m) = config.max_component
            && !(m.is_finite() && m > 0.0)
        {
            return Err(Error::Config(format!(
                "max component {m} must be finite and above 0"
            )));
        }
        // In f32, as pbrt does, so that 0.2 × 10 is 2 (not 2.0000000298 → 3).
        let ceil = |v: f32, n: u32| (v * n as f32).ceil() as i64;
        let pixel_bounds = Bounds::new(ceil(c[0], w), ceil(c[2], h), ceil(c[1], w), ceil(c[3], h));
        if pixel_bounds.is_empty() {
            return Err(Error::Config(format!(
                "crop window {c:?} covers no pixel of {w}x{h}"
            )));
        }
        if config.extras.channels > MAX_CHANNELS {
            return Err(Error::OutOfRange {
                what: "extra channels",
                value: f64::from(config.extras.channels),
                min: 0.0,
                max: f64::from(MAX_CHANNELS),
            });
        }
        Ok(Setup {
            pixel_bounds,
            table: FilmTable::new(filter)?,
            max_component: config.max_component,
            extras: config.extras,
        })
    }
}
