//! The film's filter weights: a thin wrapper over the core's precomputed filter table.
//! (Stop-gap written by the filter work so the workspace builds; the film owner may replace it.)

use crate::Error;
use nyquist::filter::{Axis, Filter, FilterTable, Interpolation};

/// The filter as the film reads it: a 16-entry-per-axis linear table built once.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Weights {
    table: FilterTable,
}

impl Weights {
    pub(crate) fn new(filter: &dyn Filter) -> Result<Weights, Error> {
        let table = FilterTable::new(filter, Interpolation::Linear).map_err(Error::Core)?;
        Ok(Weights { table })
    }

    pub(crate) fn radius(&self) -> [f32; 2] {
        self.table.radius()
    }

    pub(crate) fn integral(&self) -> f32 {
        self.table.integral()
    }

    pub(crate) fn is_separable(&self) -> bool {
        self.table.is_separable()
    }

    #[inline]
    pub(crate) fn weight(&self, dx: f32, dy: f32) -> f32 {
        self.table.weight(dx, dy)
    }

    /// The x factor of a separable table (1 for a 2D table, which callers do not use).
    #[inline]
    pub(crate) fn weight_x(&self, dx: f32) -> f32 {
        self.table.weight_1d(Axis::X, dx).unwrap_or(1.0)
    }

    /// The y factor of a separable table (1 for a 2D table, which callers do not use).
    #[inline]
    pub(crate) fn weight_y(&self, dy: f32) -> f32 {
        self.table.weight_1d(Axis::Y, dy).unwrap_or(1.0)
    }
}
