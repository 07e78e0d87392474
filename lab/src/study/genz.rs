//! Genz's six test integrand families in `D` dimensions
//! (A. Genz, "Testing multidimensional integration routines", in *Tools, Methods and Languages
//! for Scientific and Engineering Computation*, 1984, pp. 81–94; and "A package for testing
//! multiple integration subroutines", in *Numerical Integration*, Reidel, 1987, pp. 337–340).
//!
//! Each family is `f(x)` on `[0, 1]^D` with difficulty parameters `a` and shifts `u`:
//!
//! | family | `f(x)` | integral |
//! |---|---|---|
//! | oscillatory | `cos(2π u₁ + Σ aᵢxᵢ)` | `cos(2π u₁ + Σ aᵢ/2) Π 2 sin(aᵢ/2)/aᵢ` |
//! | product peak | `Π (aᵢ⁻² + (xᵢ − uᵢ)²)⁻¹` | `Π aᵢ (atan(aᵢ(1 − uᵢ)) + atan(aᵢuᵢ))` |
//! | corner peak | `(1 + Σ aᵢxᵢ)^−(D+1)` | `(1/D!) ∫₀^∞ t^D e^−t Π (1 − e^−aᵢt)/(aᵢt) dt` |
//! | Gaussian | `exp(−Σ aᵢ²(xᵢ − uᵢ)²)` | `Π √π/(2aᵢ) (erf(aᵢ(1 − uᵢ)) + erf(aᵢuᵢ))` |
//! | continuous | `exp(−Σ aᵢ|xᵢ − uᵢ|)` | `Π (2 − e^−aᵢuᵢ − e^−aᵢ(1−uᵢ))/aᵢ` |
//! | discontinuous | `0` if `x₁ > u₁` or `x₂ > u₂`, else `exp(Σ aᵢxᵢ)` | `Π_{i≤2} (e^{aᵢuᵢ} − 1)/aᵢ Π_{i>2} (e^{aᵢ} − 1)/aᵢ` |
//!
//! The corner peak's integral is a one-dimensional integral (from `(1 + s)^−(D+1) =
//! (1/D!) ∫ t^D e^−t(1+s) dt`), computed by Gauss–Legendre quadrature to about 1e−13; the
//! inclusion–exclusion sum over the `2^D` corners cancels catastrophically beyond small `D`.
//!
//! **Parameters** (fixed): Genz's difficulties `Σ aᵢ = b` with `b = (9.0, 7.25, 1.85, 7.03,
//! 20.4, 4.3)` for the six families in the order above (Genz 1987), spread evenly: `aᵢ = b/D`
//! in every dimension, so that every dimension matters as much as the first (the hardest case
//! for sequences whose high dimensions are poor). Shifts `uᵢ = frac(0.5 + i·(√5 − 1)/2)`,
//! `i = 1 … D`.
//!
//! **Points**: as every study draws them ([`super::point`]). A study of these families
//! compares relative errors ([`super::Integrand::error_scale`] is `|integral|`).
//!
//! ```
//! use nyquist_lab::study::{Study, genz::Genz};
//! let study = Study { samplers: vec!["sobol".into()], integrands: Genz::all(4),
//!                     counts: vec![64, 256], runs: 4, seed: 1, spp_hint: None };
//! assert_eq!(study.run(1).unwrap().curves.len(), 6);
//! ```

/// Genz's difficulty `Σ aᵢ` of each family, in [`Family::ALL`]'s order (Genz 1987).
pub const DIFFICULTY: [f64; 6] = [9.0, 7.25, 1.85, 7.03, 20.4, 4.3];

/// Most dimensions a Genz study takes here (the corner peak's quadrature is checked to there).
pub const MAX_DIMS: u32 = 64;

/// One of Genz's six families.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// `cos(2π u₁ + Σ aᵢxᵢ)`.
    Oscillatory,
    /// `Π (aᵢ⁻² + (xᵢ − uᵢ)²)⁻¹`.
    ProductPeak,
    /// `(1 + Σ aᵢxᵢ)^−(D+1)`.
    CornerPeak,
    /// `exp(−Σ aᵢ²(xᵢ − uᵢ)²)`.
    Gaussian,
    /// `exp(−Σ aᵢ|xᵢ − uᵢ|)`.
    Continuous,
    /// `exp(Σ aᵢxᵢ)` where `x₁ ≤ u₁` and `x₂ ≤ u₂`, else 0.
    Discontinuous,
}

impl Family {
    /// The six, in Genz's order.
    pub const ALL: [Family; 6] = [
        Family::Oscillatory,
        Family::ProductPeak,
        Family::CornerPeak,
        Family::Gaussian,
        Family::Continuous,
        Family::Discontinuous,
    ];

    /// Short name.
    pub fn name(self) -> &'static str {
        match self {
            Family::Oscillatory => "oscillatory",
            Family::ProductPeak => "product-peak",
            Family::CornerPeak => "corner-peak",
            Family::Gaussian => "gaussian",
            Family::Continuous => "continuous",
            Family::Discontinuous => "discontinuous",
        }
    }
}

/// A family in `d` dimensions with its fixed parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Genz {
    /// The family.
    pub family: Family,
    /// Difficulty per dimension.
    pub a: Vec<f64>,
    /// Shift per dimension.
    pub u: Vec<f64>,
}

impl Genz {
    /// `family` in `d ≥ 1` dimensions (`d ≥ 2` for the discontinuous family, which cuts two)
    /// with the documented parameters.
    pub fn new(family: Family, d: usize) -> Genz {
        let b = DIFFICULTY[Family::ALL.iter().position(|f| *f == family).unwrap_or(0)];
        let golden = (5f64.sqrt() - 1.0) / 2.0;
        Genz {
            family,
            a: vec![b / d as f64; d],
            u: (1..=d).map(|i| (0.5 + i as f64 * golden).fract()).collect(),
        }
    }

    /// The six families in `d` dimensions, in [`Family::ALL`]'s order.
    ///
    /// ```
    /// assert_eq!(nyquist_lab::study::genz::Genz::all(3).len(), 6);
    /// ```
    pub fn all(d: usize) -> Vec<Genz> {
        Family::ALL.iter().map(|&f| Genz::new(f, d)).collect()
    }

    /// Dimensions.
    pub fn dims(&self) -> usize {
        self.a.len()
    }

    /// `f(x)`; `x.len()` must be [`Genz::dims`].
    pub fn eval(&self, x: &[f64]) -> f64 {
        let (a, u) = (&self.a, &self.u);
        let terms = || a.iter().zip(u).zip(x);
        match self.family {
            Family::Oscillatory => {
                let s: f64 = a.iter().zip(x).map(|(a, x)| a * x).sum();
                (2.0 * std::f64::consts::PI * u[0] + s).cos()
            }
            Family::ProductPeak => terms()
                .map(|((a, u), x)| 1.0 / (a.powi(-2) + (x - u).powi(2)))
                .product(),
            Family::CornerPeak => {
                let s: f64 = a.iter().zip(x).map(|(a, x)| a * x).sum();
                (1.0 + s).powi(-(self.dims() as i32 + 1))
            }
            Family::Gaussian => {
                let s: f64 = terms().map(|((a, u), x)| (a * (x - u)).powi(2)).sum();
                (-s).exp()
            }
            Family::Continuous => {
                let s: f64 = terms().map(|((a, u), x)| a * (x - u).abs()).sum();
                (-s).exp()
            }
            Family::Discontinuous => {
                if x[0] > u[0] || x.get(1).is_some_and(|x1| *x1 > u[1]) {
                    0.0
                } else {
                    a.iter().zip(x).map(|(a, x)| a * x).sum::<f64>().exp()
                }
            }
        }
    }

    /// The exact integral over `[0, 1]^D` (the corner peak's to quadrature accuracy, ~1e−13).
    pub fn integral(&self) -> f64 {
        let (a, u) = (&self.a, &self.u);
        let pairs = || a.iter().zip(u);
        match self.family {
            Family::Oscillatory => {
                let half: f64 = a.iter().sum::<f64>() / 2.0;
                (2.0 * std::f64::consts::PI * u[0] + half).cos()
                    * a.iter().map(|a| 2.0 * (a / 2.0).sin() / a).product::<f64>()
            }
            Family::ProductPeak => pairs()
                .map(|(a, u)| a * ((a * (1.0 - u)).atan() + (a * u).atan()))
                .product(),
            Family::CornerPeak => corner_peak_integral(a),
            Family::Gaussian => pairs()
                .map(|(a, u)| {
                    std::f64::consts::PI.sqrt() / (2.0 * a)
                        * (libm::erf(a * (1.0 - u)) + libm::erf(a * u))
                })
                .product(),
            Family::Continuous => pairs()
                .map(|(a, u)| (2.0 - (-a * u).exp() - (-a * (1.0 - u)).exp()) / a)
                .product(),
            Family::Discontinuous => pairs()
                .enumerate()
                .map(|(i, (a, u))| {
                    let top = if i < 2 { *u } else { 1.0 };
                    (a * top).exp_m1() / a
                })
                .product(),
        }
    }
}

/// Gauss–Legendre nodes and weights on `[-1, 1]`, 8 points.
const GL8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
];

/// `∫ₗₒʰⁱ f` by 8-point Gauss–Legendre on `panels` equal panels.
pub fn gauss_legendre(lo: f64, hi: f64, panels: u32, f: impl Fn(f64) -> f64) -> f64 {
    let h = (hi - lo) / f64::from(panels);
    (0..panels)
        .map(|p| {
            let mid = lo + (f64::from(p) + 0.5) * h;
            GL8.iter()
                .map(|(x, w)| w * f(mid + 0.5 * h * x))
                .sum::<f64>()
                * 0.5
                * h
        })
        .sum()
}

/// `∫_{[0,1]^D} (1 + a·x)^−(D+1) dx = (1/D!) ∫₀^∞ t^D e^−t Π (1 − e^−aᵢt)/(aᵢt) dt`.
fn corner_peak_integral(a: &[f64]) -> f64 {
    let d = a.len() as f64;
    let ln_fact: f64 = (1..=a.len()).map(|k| (k as f64).ln()).sum();
    let hi = d + 1.0 + 40.0 * (d + 1.0).sqrt() + 60.0;
    gauss_legendre(0.0, hi, 4000, |t| {
        if t <= 0.0 {
            return 0.0;
        }
        let density = (d * t.ln() - t - ln_fact).exp();
        let phi: f64 = a.iter().map(|a| -(-a * t).exp_m1() / (a * t)).product();
        density * phi
    })
}

impl super::Integrand for Genz {
    fn dims(&self) -> usize {
        self.a.len()
    }

    fn eval(&self, x: &[f64]) -> f64 {
        Genz::eval(self, x)
    }

    fn integral(&self) -> f64 {
        Genz::integral(self)
    }

    /// Genz's families are compared by relative error: `|integral|`.
    fn error_scale(&self) -> f64 {
        Genz::integral(self).abs()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::Study;

    /// `∫_{[0,1]^d} f` by tensor Gauss–Legendre with panels split at each `uᵢ` (where the
    /// continuous and discontinuous families have their kinks and jumps).
    fn quadrature(g: &Genz, panels: u32) -> f64 {
        let nodes: Vec<Vec<(f64, f64)>> =
            g.u.iter()
                .map(|&u| {
                    let mut v = Vec::new();
                    for (lo, hi) in [(0.0, u), (u, 1.0)] {
                        let h = (hi - lo) / f64::from(panels);
                        for p in 0..panels {
                            let mid = lo + (f64::from(p) + 0.5) * h;
                            for (x, w) in GL8 {
                                v.push((mid + 0.5 * h * x, 0.5 * h * w));
                            }
                        }
                    }
                    v
                })
                .collect();
        let d = g.dims();
        let mut idx = vec![0usize; d];
        let mut x = vec![0.0; d];
        let mut sum = 0.0;
        'outer: loop {
            let mut w = 1.0;
            for k in 0..d {
                let (xk, wk) = nodes[k][idx[k]];
                x[k] = xk;
                w *= wk;
            }
            sum += w * g.eval(&x);
            for k in 0..d {
                idx[k] += 1;
                if idx[k] < nodes[k].len() {
                    continue 'outer;
                }
                idx[k] = 0;
            }
            break;
        }
        sum
    }

    #[test]
    fn closed_forms_match_quadrature_in_two_and_three_dimensions() {
        for (d, panels) in [(2, 24), (3, 4)] {
            for f in Family::ALL {
                let g = Genz::new(f, d);
                let (exact, quad) = (g.integral(), quadrature(&g, panels));
                let rel = (exact - quad).abs() / exact.abs();
                assert!(
                    rel < 1e-9,
                    "{} d={d}: {exact} vs {quad} ({rel:e})",
                    f.name()
                );
            }
        }
    }

    #[test]
    fn the_corner_peak_integral_matches_inclusion_exclusion_in_low_dimensions() {
        // ∫ (1 + a·x)^−(d+1) = (1/(d! Π a)) Σ_{v ∈ {0,1}^d} (−1)^|v| / (1 + a·v).
        for d in 1..=8usize {
            let g = Genz::new(Family::CornerPeak, d);
            let fact: f64 = (1..=d).map(|k| k as f64).product();
            let prod: f64 = g.a.iter().product();
            let mut sum = 0.0;
            for v in 0u32..(1 << d) {
                let dot: f64 = (0..d).filter(|k| v >> k & 1 == 1).map(|k| g.a[k]).sum();
                let sign = if v.count_ones() % 2 == 0 { 1.0 } else { -1.0 };
                sum += sign / (1.0 + dot);
            }
            let exact = sum / (fact * prod);
            let rel = (g.integral() - exact).abs() / exact;
            assert!(rel < 1e-9, "d={d}: {} vs {exact}", g.integral());
        }
    }

    #[test]
    fn parameters_are_genz_difficulties_spread_evenly() {
        for (f, b) in Family::ALL.iter().zip(DIFFICULTY) {
            let g = Genz::new(*f, 16);
            assert!((g.a.iter().sum::<f64>() - b).abs() < 1e-12);
            assert!(g.u.iter().all(|u| (0.0..1.0).contains(u)));
        }
    }

    fn study(samplers: &[&str], dims: usize, counts: &[u32], runs: u32, seed: u64) -> Study<Genz> {
        Study {
            samplers: samplers.iter().map(|s| (*s).to_owned()).collect(),
            integrands: Genz::all(dims),
            counts: counts.to_vec(),
            runs,
            seed,
            spp_hint: None,
        }
    }

    #[test]
    fn random_points_converge_at_the_monte_carlo_rate() {
        let curves = study(&["random"], 16, &[64, 256, 1024], 32, 3)
            .run(2)
            .unwrap()
            .curves;
        for c in &curves {
            let s = c.slope.unwrap();
            assert!(
                (-0.85..-0.2).contains(&s),
                "{}: {s}",
                c.integrand.family.name()
            );
        }
    }

    #[test]
    fn results_do_not_depend_on_the_thread_count() {
        let s = study(&["sobol", "halton-plain"], 5, &[16, 32], 3, 9);
        let (a, b) = (s.run(1).unwrap(), s.run(3).unwrap());
        assert_eq!(a.curves, b.curves);
        assert!(
            a.curves
                .iter()
                .all(|c| c.rmse.iter().all(|e| e.is_finite() && *e > 0.0))
        );
    }
}
