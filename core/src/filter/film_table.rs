//! [`FilmTable`]: the table a film reconstructs through.

use super::{Axis, Filter, FilterTable, Interpolation, PhaseTable, Weights};
use crate::Error;

/// The filter as a film reads it, built once per film: a [`PhaseTable`] for separable filters
/// with radii below 8 pixels (every footprint weight along an axis from one interpolated row;
/// grid spacing 1/64 pixel), and a linear [`FilterTable<N>`] for every other filter (not
/// separable, or wider). Both answer through [`Weights`]; a film's fast paths match on the
/// variant.
///
/// `N` defaults to 64, not the other tables' 16 (see [`Table`](super::Table#table-size)):
/// a film's pixels are weighted means of many samples, so a table's interpolation error is not
/// averaged away but stays in the converged image as a bias that more samples never remove.
/// Lookups cost the same at any size, and the linear error falls with the square of `N`: a
/// Mitchell film through a 16-entry table converges to an image 1.8·10⁻³ RMSE away from the
/// exactly filtered one. Allocates: no; as large as a [`FilterTable<N>`] (16 KB at 64).
///
/// ```
/// use nyquist::filter::{FilmTable, Filter, Lanczos, Weights};
/// let l = Lanczos::default();
/// let t: FilmTable = FilmTable::new(&l).unwrap();
/// assert!(matches!(t, FilmTable::Phase(_)));
/// assert!((t.weight(1.3, -0.2) - l.eval(1.3, -0.2)).abs() < 1e-3);
/// // Radius 8 and more: the 64-entry fallback.
/// let wide = Lanczos::new([8.0, 8.0], 3.0).unwrap();
/// assert!(matches!(FilmTable::<64>::new(&wide).unwrap(), FilmTable::Table(_)));
/// ```
#[derive(Clone, Debug, PartialEq)]
// The fallback is the larger variant; a film holds one table, behind its shared setup.
#[allow(clippy::large_enum_variant)]
pub enum FilmTable<const N: usize = 64> {
    /// Separable filters with radii below 8 pixels.
    Phase(PhaseTable),
    /// Every other filter: `N` linear entries per axis (two 1D tables, or one 2D table for a
    /// filter that is not separable).
    Table(FilterTable<N>),
}

impl<const N: usize> FilmTable<N> {
    /// Tabulates `filter` the way a film reads it: a [`PhaseTable`] when one holds it, else a
    /// linear [`FilterTable<N>`].
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if the filter's radius is not finite and `> 0`.
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, FilmTable, Weights};
    /// let t: FilmTable = FilmTable::new(&Boxcar::default()).unwrap();
    /// assert_eq!((t.radius(), t.weight(0.5, 0.0)), ([0.5, 0.5], 1.0));
    /// ```
    pub fn new<F: Filter + ?Sized>(filter: &F) -> Result<FilmTable<N>, Error> {
        if let Ok(t) = PhaseTable::new(filter) {
            return Ok(FilmTable::Phase(t));
        }
        FilterTable::new(filter, Interpolation::Linear).map(FilmTable::Table)
    }
}

impl<const N: usize> Weights for FilmTable<N> {
    fn radius(&self) -> [f32; 2] {
        match self {
            FilmTable::Phase(t) => t.radius(),
            FilmTable::Table(t) => t.radius(),
        }
    }

    fn integral(&self) -> f32 {
        match self {
            FilmTable::Phase(t) => t.integral(),
            FilmTable::Table(t) => t.integral(),
        }
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn weight(&self, dx: f32, dy: f32) -> f32 {
        match self {
            FilmTable::Phase(t) => t.weight(dx, dy),
            FilmTable::Table(t) => t.weight(dx, dy),
        }
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn weight_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        match self {
            FilmTable::Phase(t) => Some(t.weight_1d(axis, d)),
            FilmTable::Table(t) => t.weight_1d(axis, d),
        }
    }

    fn is_separable(&self) -> bool {
        match self {
            FilmTable::Phase(_) => true,
            FilmTable::Table(t) => t.is_separable(),
        }
    }

    fn footprint(&self, d0: [f32; 2], nx: usize, out: &mut [f32]) -> Result<(), Error> {
        match self {
            FilmTable::Phase(t) => t.footprint(d0, nx, out),
            FilmTable::Table(t) => t.footprint(d0, nx, out),
        }
    }
}
