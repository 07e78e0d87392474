//! The film's filter weights: a [`PhaseTable`] for separable filters (one interpolated row of
//! taps per axis and sample), the core's 64-entry [`FilterTable`] for the others, and the
//! per-axis weight sources the tile's generic accumulation loop is generic over (table lookups,
//! or direct evaluation for comparison).

use crate::Error;
use nyquist::filter::{
    Axis, Filter, FilterTable, Interpolation, PhaseTable, SeparableTable, Table2d,
};

/// Entries per axis of the film's [`FilterTable`] (filters a [`PhaseTable`] cannot hold: not
/// separable, or a radius of 8 or more): 64, not pbrt's 16. Lookups cost the same at any size,
/// and linear interpolation's error falls with the square of the size — at 16 entries a Mitchell
/// film converges to an image 1.8·10⁻³ RMSE away from the exactly filtered one (the CLI's
/// sampling-RMSE measured it), a bias that more samples never remove.
pub(crate) const FILM_TABLE: usize = 64;

/// The filter as the film reads it, built once. One per film, behind the film's `Arc`: the
/// phase table is held inline (no pointer to follow per sample), the rarer fallback boxed.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)]
pub(crate) enum Weights {
    /// Separable filters with radii below 8: the polyphase table (grid spacing 1/64 pixel).
    Phase(PhaseTable),
    /// Everything else: a [`FILM_TABLE`]-entry-per-axis linear table (boxed: a 2D one is
    /// 16 KB).
    Table(Box<FilterTable<FILM_TABLE>>),
}

impl Weights {
    pub(crate) fn new(filter: &dyn Filter) -> Result<Weights, Error> {
        if let Ok(t) = PhaseTable::new(filter) {
            return Ok(Weights::Phase(t));
        }
        let table = FilterTable::new(filter, Interpolation::Linear).map_err(Error::Core)?;
        Ok(Weights::Table(Box::new(table)))
    }

    pub(crate) fn radius(&self) -> [f32; 2] {
        match self {
            Weights::Phase(t) => t.radius(),
            Weights::Table(t) => t.radius(),
        }
    }

    pub(crate) fn integral(&self) -> f32 {
        match self {
            Weights::Phase(t) => t.integral(),
            Weights::Table(t) => t.integral(),
        }
    }

    /// Whether the weight is a product of per-axis factors.
    pub(crate) fn is_separable(&self) -> bool {
        match self {
            Weights::Phase(_) => true,
            Weights::Table(t) => t.is_separable(),
        }
    }

    #[inline]
    pub(crate) fn weight(&self, dx: f32, dy: f32) -> f32 {
        match self {
            Weights::Phase(t) => t.weight(dx, dy),
            Weights::Table(t) => t.weight(dx, dy),
        }
    }
}

/// A source of filter weights for the accumulation loop. Separable sources answer `x` and `y`
/// (one 1D value per footprint column and row); the others answer `xy` per pixel.
pub(crate) trait WeightSource {
    /// Whether `x`·`y` is the weight (then `xy` is not called).
    fn separable(&self) -> bool;
    /// The x factor at offset `d` (separable sources only).
    fn x(&self, d: f32) -> f32;
    /// The y factor at offset `d` (separable sources only).
    fn y(&self, d: f32) -> f32;
    /// The weight at offset `(dx, dy)`.
    fn xy(&self, dx: f32, dy: f32) -> f32;
}

impl<const N: usize> WeightSource for SeparableTable<N> {
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn separable(&self) -> bool {
        true
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn x(&self, d: f32) -> f32 {
        self.weight_1d(Axis::X, d)
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn y(&self, d: f32) -> f32 {
        self.weight_1d(Axis::Y, d)
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn xy(&self, dx: f32, dy: f32) -> f32 {
        self.weight(dx, dy)
    }
}

impl<const N: usize> WeightSource for Table2d<N> {
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn separable(&self) -> bool {
        false
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn x(&self, _: f32) -> f32 {
        1.0
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn y(&self, _: f32) -> f32 {
        1.0
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn xy(&self, dx: f32, dy: f32) -> f32 {
        self.weight(dx, dy)
    }
}

/// Direct evaluation of a filter: `eval_1d` per axis when the filter is separable, else `eval`.
pub(crate) struct Direct<'a, F: ?Sized> {
    pub(crate) filter: &'a F,
    pub(crate) separable: bool,
}

impl<F: Filter + ?Sized> WeightSource for Direct<'_, F> {
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn separable(&self) -> bool {
        self.separable
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn x(&self, d: f32) -> f32 {
        self.filter.eval_1d(Axis::X, d).unwrap_or(0.0)
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn y(&self, d: f32) -> f32 {
        self.filter.eval_1d(Axis::Y, d).unwrap_or(0.0)
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn xy(&self, dx: f32, dy: f32) -> f32 {
        self.filter.eval(dx, dy)
    }
}
