//! Helpers shared by the capi test binaries.

use nyquist::filter::Filter;

/// A C callback filter written again in Rust, as `nyq_filter_create_callback` sees it: `eval`
/// inside the support `[-radius, radius]²` (the only place the handle calls the callback),
/// 0 outside.
pub struct Clipped {
    /// Half-width of the support on both axes, in pixels.
    pub radius: f32,
    /// The callback's formula.
    pub eval: fn(f32, f32) -> f32,
}

impl Filter for Clipped {
    fn radius(&self) -> [f32; 2] {
        [self.radius; 2]
    }
    fn eval(&self, x: f32, y: f32) -> f32 {
        if !(x.abs() <= self.radius && y.abs() <= self.radius) {
            return 0.0;
        }
        (self.eval)(x, y)
    }
}
