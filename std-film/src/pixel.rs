//! [`Pixel`]: one pixel's accumulated sums.

/// Accumulated sums of one pixel: Σ f·w·L per channel and Σ f, in `f64`.
///
/// ```
/// let p = nyquist_film::Pixel::default();
/// assert_eq!(p.weight_sum, 0.0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pixel {
    /// Σ filter weight × sample weight × radiance, per RGB channel.
    pub rgb_sum: [f64; 3],
    /// Σ filter weight.
    pub weight_sum: f64,
}

impl Pixel {
    pub(crate) fn add(&mut self, o: &Pixel) {
        for c in 0..3 {
            self.rgb_sum[c] += o.rgb_sum[c];
        }
        self.weight_sum += o.weight_sum;
    }
}
