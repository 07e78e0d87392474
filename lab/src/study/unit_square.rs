//! The five test integrands over the unit square of Christensen, Kensler and Kilpatrick,
//! "Progressive Multi-Jittered Sample Sequences" (EGSR 2018): disk, triangle, step, Gaussian
//! and bilinear, each with its exact integral.
//!
//! ```
//! use nyquist_lab::study::{Integrand, unit_square::SquareIntegrand};
//! assert_eq!(Integrand::integral(&SquareIntegrand::Step), std::f64::consts::FRAC_1_PI);
//! ```

use super::Integrand;

/// erf(1) to the precision of an `f64`; digits from OEIS A099286 ("Decimal expansion of
/// erf(1)": 0.84270079294971486934…), checked in the tests against its Maclaurin series.
pub const ERF_1: f64 = 0.842_700_792_949_714_869_341_220_635_082_6;

/// The five test integrands over `[0, 1)²`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum SquareIntegrand {
    /// 1 inside the quarter disk x² + y² < 2/π, else 0 (exact integral ½).
    Disk,
    /// 1 where y < x, else 0 (exact integral ½).
    Triangle,
    /// 1 where x < 1/π, else 0 (exact integral 1/π).
    Step,
    /// exp(−x² − y²) (exact integral (√π/2 · erf 1)²).
    Gaussian,
    /// x · y (exact integral ¼).
    Bilinear,
}

impl SquareIntegrand {
    /// All five, in the order of the paper.
    pub const ALL: [SquareIntegrand; 5] = [
        SquareIntegrand::Disk,
        SquareIntegrand::Triangle,
        SquareIntegrand::Step,
        SquareIntegrand::Gaussian,
        SquareIntegrand::Bilinear,
    ];

    /// The command-line name.
    ///
    /// ```
    /// assert_eq!(nyquist_lab::study::unit_square::SquareIntegrand::Gaussian.name(), "gaussian");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            SquareIntegrand::Disk => "disk",
            SquareIntegrand::Triangle => "triangle",
            SquareIntegrand::Step => "step",
            SquareIntegrand::Gaussian => "gaussian",
            SquareIntegrand::Bilinear => "bilinear",
        }
    }

    /// The function, as the plot captions it.
    pub fn formula(self) -> &'static str {
        match self {
            SquareIntegrand::Disk => "1 where x² + y² < 2/π",
            SquareIntegrand::Triangle => "1 where y < x",
            SquareIntegrand::Step => "1 where x < 1/π",
            SquareIntegrand::Gaussian => "exp(−x² − y²)",
            SquareIntegrand::Bilinear => "x·y",
        }
    }

    /// The integrand at `(x, y)`.
    ///
    /// ```
    /// use nyquist_lab::study::unit_square::SquareIntegrand;
    /// assert_eq!(SquareIntegrand::Disk.eval(0.5, 0.5), 1.0); // 0.5 < 2/π ≈ 0.64
    /// assert_eq!(SquareIntegrand::Triangle.eval(0.2, 0.3), 0.0);
    /// assert_eq!(SquareIntegrand::Bilinear.eval(0.5, 0.25), 0.125);
    /// ```
    #[inline]
    pub fn eval(self, x: f64, y: f64) -> f64 {
        let indicator = |inside: bool| if inside { 1.0 } else { 0.0 };
        match self {
            SquareIntegrand::Disk => indicator(x * x + y * y < 2.0 / std::f64::consts::PI),
            SquareIntegrand::Triangle => indicator(y < x),
            SquareIntegrand::Step => indicator(x < std::f64::consts::FRAC_1_PI),
            SquareIntegrand::Gaussian => libm::exp(-x * x - y * y),
            SquareIntegrand::Bilinear => x * y,
        }
    }

    /// The exact integral over `[0, 1)²`: the quarter disk of radius² 2/π has area
    /// π · (2/π) / 4 = ½; the triangle ½; the step 1/π; the Gaussian separates into
    /// (∫₀¹ e^(−x²) dx)² = (√π/2 · erf 1)²; the bilinear (½)².
    ///
    /// ```
    /// use nyquist_lab::study::unit_square::SquareIntegrand;
    /// assert_eq!(SquareIntegrand::Disk.integral(), 0.5);
    /// assert!((SquareIntegrand::Gaussian.integral() - 0.557_746_285).abs() < 1e-9);
    /// ```
    pub fn integral(self) -> f64 {
        match self {
            SquareIntegrand::Disk | SquareIntegrand::Triangle => 0.5,
            SquareIntegrand::Step => std::f64::consts::FRAC_1_PI,
            SquareIntegrand::Gaussian => {
                let g = 0.5 * std::f64::consts::PI.sqrt() * ERF_1;
                g * g
            }
            SquareIntegrand::Bilinear => 0.25,
        }
    }
}

impl Integrand for SquareIntegrand {
    fn dims(&self) -> usize {
        2
    }

    fn eval(&self, x: &[f64]) -> f64 {
        SquareIntegrand::eval(*self, x[0], x[1])
    }

    fn integral(&self) -> f64 {
        SquareIntegrand::integral(*self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// erf(1) by its Maclaurin series 2/√π · Σ (−1)ⁿ / (n! (2n + 1)).
    fn erf_1_series() -> f64 {
        let mut sum = 0.0;
        let mut term = 1.0; // (−1)ⁿ / n!
        for n in 0..30 {
            sum += term / f64::from(2 * n + 1);
            term *= -1.0 / f64::from(n + 1);
        }
        2.0 / std::f64::consts::PI.sqrt() * sum
    }

    #[test]
    fn erf_1_matches_its_series() {
        assert!((ERF_1 - erf_1_series()).abs() < 1e-15, "{}", erf_1_series());
    }

    /// The midpoint rule on a `k × k` grid.
    fn midpoint(f: SquareIntegrand, k: u32) -> f64 {
        let h = 1.0 / f64::from(k);
        let mut sum = 0.0;
        for j in 0..k {
            for i in 0..k {
                sum += f.eval((f64::from(i) + 0.5) * h, (f64::from(j) + 0.5) * h);
            }
        }
        sum * h * h
    }

    #[test]
    fn references_match_a_fine_quadrature() {
        // Smooth integrands: midpoint error ~ h²/24 · |f''| ≲ 1e-8 at k = 1024. Indicators:
        // an error of the order of the boundary cells, ≲ 1/k.
        let k = 1024;
        for f in [SquareIntegrand::Gaussian, SquareIntegrand::Bilinear] {
            let q = midpoint(f, k);
            assert!((q - f.integral()).abs() < 1e-7, "{f:?}: {q}");
        }
        for f in [
            SquareIntegrand::Disk,
            SquareIntegrand::Triangle,
            SquareIntegrand::Step,
        ] {
            let q = midpoint(f, k);
            assert!((q - f.integral()).abs() < 1.0 / f64::from(k), "{f:?}: {q}");
        }
        // Finer, in one dimension: the quarter disk's area as ∫ √(2/π − x²) dx over
        // [0, √(2/π)], and the step's as the share of 2^20 midpoints below 1/π.
        let k = 1 << 20;
        let h = 1.0 / f64::from(k);
        let (mut disk, mut step) = (0.0, 0.0);
        for i in 0..k {
            let x = (f64::from(i) + 0.5) * h;
            disk += (2.0 / std::f64::consts::PI - x * x).max(0.0).sqrt() * h;
            step += SquareIntegrand::Step.eval(x, 0.5) * h;
        }
        assert!(
            (disk - SquareIntegrand::Disk.integral()).abs() < 1e-8,
            "{disk}"
        );
        assert!(
            (step - SquareIntegrand::Step.integral()).abs() < 1e-6,
            "{step}"
        );
        assert!((SquareIntegrand::Gaussian.integral() - 0.557_746_285_351_034).abs() < 1e-12);
    }
}
