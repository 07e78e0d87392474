//! Tests of the filters against f64 oracles, published integrals and invariants.

use super::*;
use crate::error::Interval;
use crate::rng::{default_rng, uniform_f32, uniform_f64};
use proptest::prelude::*;
use std::string::ToString;
use std::vec::Vec;

// ---------------------------------------------------------------------------------------------
// f64 oracles: the closed-form definitions of docs/cli.md ("Filters"), written independently of the
// implementations.

fn sinc64(x: f64) -> f64 {
    if x == 0.0 {
        1.0
    } else {
        (core::f64::consts::PI * x).sin() / (core::f64::consts::PI * x)
    }
}

fn mitchell64(t: f64, b: f64, c: f64) -> f64 {
    let t = t.abs();
    if t < 1.0 {
        ((12.0 - 9.0 * b - 6.0 * c) * t * t * t
            + (-18.0 + 12.0 * b + 6.0 * c) * t * t
            + (6.0 - 2.0 * b))
            / 6.0
    } else if t < 2.0 {
        ((-b - 6.0 * c) * t * t * t
            + (6.0 * b + 30.0 * c) * t * t
            + (-12.0 * b - 48.0 * c) * t
            + (8.0 * b + 24.0 * c))
            / 6.0
    } else {
        0.0
    }
}

#[derive(Clone, Copy, Debug)]
enum Oracle {
    Box,
    Triangle,
    Gaussian(f64),
    Mitchell(f64, f64),
    Lanczos(f64),
    BlackmanHarris,
}

impl Oracle {
    fn axis(self, r: f64, x: f64) -> f64 {
        if !(x.abs() <= r) {
            return 0.0;
        }
        match self {
            Oracle::Box => 1.0,
            Oracle::Triangle => (r - x.abs()).max(0.0),
            Oracle::Gaussian(a) => ((-a * x * x).exp() - (-a * r * r).exp()).max(0.0),
            Oracle::Mitchell(b, c) => mitchell64(2.0 * x / r, b, c),
            Oracle::Lanczos(tau) => sinc64(x) * sinc64(x / tau),
            // Harris's window over [−r, r] at u = x/(2r) + ½, as published.
            Oracle::BlackmanHarris => {
                let u = x / (2.0 * r) + 0.5;
                let w = 2.0 * core::f64::consts::PI * u;
                0.35875 - 0.48829 * w.cos() + 0.14128 * (2.0 * w).cos() - 0.01168 * (3.0 * w).cos()
            }
        }
    }
    fn eval(self, r: [f32; 2], x: f32, y: f32) -> f64 {
        self.axis(f64::from(r[0]), f64::from(x)) * self.axis(f64::from(r[1]), f64::from(y))
    }
}

/// Every built-in with a few parameter sets, paired with its oracle.
fn cases() -> Vec<(FilterKind, Oracle)> {
    let mut v = Vec::new();
    for r in [
        [0.5, 0.5],
        [1.0, 1.0],
        [1.5, 0.25],
        [0.33, 5.2],
        [3.0, 3.0],
        [2.0, 2.0],
    ] {
        v.push((FilterKind::Boxcar(Boxcar::new(r).unwrap()), Oracle::Box));
        v.push((
            FilterKind::Triangle(Triangle::new(r).unwrap()),
            Oracle::Triangle,
        ));
        for a in [0.5f32, 2.0, 7.0] {
            let g = Gaussian::new(r, a).unwrap();
            v.push((FilterKind::Gaussian(g), Oracle::Gaussian(f64::from(a))));
        }
        for (b, c) in [(1.0 / 3.0, 1.0 / 3.0), (0.0, 0.5), (1.0, 0.0), (0.5, 0.25)] {
            let m = Mitchell::new(r, b, c).unwrap();
            v.push((
                FilterKind::Mitchell(m),
                Oracle::Mitchell(f64::from(b), f64::from(c)),
            ));
        }
        for tau in [3.0f32, 2.0, 1.0] {
            let l = Lanczos::new(r, tau).unwrap();
            v.push((FilterKind::Lanczos(l), Oracle::Lanczos(f64::from(tau))));
        }
        v.push((
            FilterKind::BlackmanHarris(BlackmanHarris::new(r).unwrap()),
            Oracle::BlackmanHarris,
        ));
    }
    v
}

fn peak(o: Oracle, r: [f32; 2]) -> f64 {
    (o.eval(r, 0.0, 0.0).abs()).max(1.0)
}

#[test]
fn eval_matches_the_f64_oracle() {
    let mut rng = default_rng(11);
    for (f, o) in cases() {
        let r = f.radius();
        let tol = 4e-6 * peak(o, r);
        let check = |x: f32, y: f32| {
            let got = f64::from(f.eval(x, y));
            let want = o.eval(r, x, y);
            assert!(
                (got - want).abs() <= tol,
                "{f}: eval({x}, {y}) = {got}, oracle {want}"
            );
            // The separable form multiplies to eval exactly.
            let sep = f.eval_1d(Axis::X, x).unwrap() * f.eval_1d(Axis::Y, y).unwrap();
            assert_eq!(sep.to_bits(), f.eval(x, y).to_bits(), "{f} at ({x}, {y})");
        };
        for _ in 0..2000 {
            let x = (2.4 * uniform_f32(&mut rng) - 1.2) * r[0];
            let y = (2.4 * uniform_f32(&mut rng) - 1.2) * r[1];
            check(x, y);
        }
        for k in -8..=8 {
            let t = k as f32 / 8.0;
            check(t * r[0], 0.0);
            check(0.0, t * r[1]);
            check(t * r[0], -t * r[1]);
        }
    }
}

#[test]
fn zero_just_past_the_radius_on_every_edge_and_corner() {
    // pbrt-v4's ZeroPastRadius: points 1e-3 outside.
    for r in [[1.0, 1.0], [1.5, 0.25], [0.33, 5.2], [0.1, 0.1], [3.0, 3.0]] {
        let filters: [FilterKind; 5] = [
            FilterKind::Boxcar(Boxcar::new(r).unwrap()),
            FilterKind::Triangle(Triangle::new(r).unwrap()),
            FilterKind::Gaussian(Gaussian::new(r, 2.0).unwrap()),
            FilterKind::Mitchell(Mitchell::default_with_radius(r)),
            FilterKind::Lanczos(Lanczos::new(r, 3.0).unwrap()),
        ];
        for f in filters {
            let table: FilterTable = FilterTable::new(&f, Interpolation::Linear).unwrap();
            let full: Table2d = Table2d::new(&f, Interpolation::Nearest).unwrap();
            let (ox, oy) = (r[0] + 1e-3, r[1] + 1e-3);
            let mut points = Vec::new();
            for s in [-1.0f32, 1.0] {
                points.push((s * ox, 0.0));
                points.push((0.0, s * oy));
                for t in [-1.0f32, 1.0] {
                    points.push((s * ox, t * oy)); // corners
                    points.push((s * ox, t * r[1] * 0.5)); // along the edges
                    points.push((s * r[0] * 0.5, t * oy));
                    points.push((s * ox, t * r[1]));
                    points.push((s * r[0], t * oy));
                }
            }
            for (x, y) in points {
                assert_eq!(f.eval(x, y), 0.0, "{f} at ({x}, {y})");
                assert_eq!(table.weight(x, y), 0.0, "{f} table at ({x}, {y})");
                assert_eq!(full.weight(x, y), 0.0, "{f} 2D table at ({x}, {y})");
            }
        }
    }
}

impl Mitchell {
    fn default_with_radius(r: [f32; 2]) -> Mitchell {
        Mitchell::new(r, 1.0 / 3.0, 1.0 / 3.0).unwrap()
    }
}

/// 256 × 256 jittered stratified quadrature of `eval` over the support, in f64.
fn stratified_integral(f: &dyn Filter, seed: u64) -> f64 {
    const N: u32 = 256;
    let [rx, ry] = f.radius().map(f64::from);
    let (hx, hy) = (2.0 * rx / f64::from(N), 2.0 * ry / f64::from(N));
    let mut rng = default_rng(seed);
    let mut sum = 0.0;
    for j in 0..N {
        for i in 0..N {
            let x = -rx + (f64::from(i) + uniform_f64(&mut rng)) * hx;
            let y = -ry + (f64::from(j) + uniform_f64(&mut rng)) * hy;
            sum += f64::from(f.eval(x as f32, y as f32));
        }
    }
    sum * hx * hy
}

#[test]
fn integrals_match_stratified_quadrature_within_one_percent() {
    for (k, (f, _)) in cases().into_iter().enumerate() {
        let exact = f64::from(f.integral());
        let q = stratified_integral(&f, k as u64);
        assert!(
            (q - exact).abs() <= 0.01 * exact.abs(),
            "{f}: integral {exact}, quadrature {q}"
        );
    }
}

#[test]
fn integrals_match_known_values() {
    let close = |got: f32, want: f64, rel: f64| {
        assert!(
            (f64::from(got) - want).abs() <= rel * want.abs(),
            "{got} vs {want}"
        );
    };
    for r in [[0.5f32, 0.5], [1.0, 2.0], [0.25, 3.5]] {
        let (rx, ry) = (f64::from(r[0]), f64::from(r[1]));
        close(Boxcar::new(r).unwrap().integral(), 4.0 * rx * ry, 1e-7);
        close(
            Triangle::new(r).unwrap().integral(),
            rx * rx * ry * ry,
            1e-7,
        );
        for (b, c) in [(1.0 / 3.0, 1.0 / 3.0), (0.0, 0.5), (1.0, 0.0), (-0.5, 2.0)] {
            let m = Mitchell::new(r, b, c).unwrap();
            close(m.integral(), rx * ry / 4.0, 1e-7);
            // And numerically, for any (B, C).
            let q = numeric_integral(&m as &dyn Filter);
            assert!(
                (q - rx * ry / 4.0).abs() < 1e-5 * (rx * ry),
                "mitchell {r:?} {b} {c}: {q}"
            );
        }
    }
    assert_eq!(Triangle::default().integral(), 16.0);
    assert_eq!(Mitchell::default().integral(), 1.0);
    close(Gaussian::default().integral(), 1.567_235_830_0, 1e-7);
    close(Lanczos::default().integral(), 1.023_834_842_0, 1e-7);
    // Blackman–Harris: (2r·a₀)² = (3 × 0.35875)² at radius 1.5; Catmull–Rom integrates to 1.
    close(BlackmanHarris::default().integral(), 1.158_314_062_5, 1e-7);
    for r in [[0.5f32, 0.5], [1.0, 2.0], [0.25, 3.5]] {
        let bh = BlackmanHarris::new(r).unwrap();
        let want = 4.0 * f64::from(r[0]) * f64::from(r[1]) * 0.35875 * 0.35875;
        close(bh.integral(), want, 1e-7);
        let q = numeric_integral(&bh as &dyn Filter);
        assert!((q - want).abs() < 1e-5 * want, "blackman-harris {r:?}: {q}");
    }
    assert_eq!(Mitchell::catmull_rom().integral(), 1.0);
    // σ form: σ = 0.5 is α = 2.
    close(
        Gaussian::with_sigma([2.0, 2.0], 0.5).unwrap().integral(),
        1.567_235_830_0,
        1e-7,
    );
    // Tiny α uses the series: compare with quadrature.
    let g = Gaussian::new([2.0, 1.0], 1e-5).unwrap();
    let axis = |r: f64| {
        let n = 100_000;
        let h = 2.0 * r / f64::from(n);
        (0..n)
            .map(|i| Oracle::Gaussian(1e-5).axis(r, -r + (f64::from(i) + 0.5) * h))
            .sum::<f64>()
            * h
    };
    let q = axis(2.0) * axis(1.0);
    assert!(
        (f64::from(g.integral()) - q).abs() < 1e-3 * q,
        "{} vs {q}",
        g.integral()
    );
    // Lanczos at other parameters against the f64 quadrature of the oracle.
    for (r, tau) in [(3.0f64, 3.0f64), (2.0, 2.0), (4.0, 1.0), (1.3, 0.7)] {
        let n = 200_000;
        let h = 2.0 * r / f64::from(n);
        let s: f64 = (0..n)
            .map(|i| Oracle::Lanczos(tau).axis(r, -r + (f64::from(i) + 0.5) * h))
            .sum::<f64>()
            * h;
        let l = Lanczos::new([r as f32, r as f32], tau as f32).unwrap();
        close(l.integral(), s * s, 1e-6);
    }
}

#[test]
fn default_integral_is_numeric_for_plugins() {
    // The trait's provided integral, separable and not.
    #[derive(Debug)]
    struct Sep;
    impl Filter for Sep {
        fn radius(&self) -> [f32; 2] {
            [1.0, 2.0]
        }
        fn eval(&self, x: f32, y: f32) -> f32 {
            self.eval_1d(Axis::X, x).unwrap() * self.eval_1d(Axis::Y, y).unwrap()
        }
        fn eval_1d(&self, axis: Axis, x: f32) -> Option<f32> {
            let r = self.radius()[axis.index()];
            Some(if x.abs() <= r { r - x.abs() } else { 0.0 })
        }
    }
    assert!(Sep.is_separable());
    assert!((Sep.integral() - 4.0).abs() < 1e-5);
    assert!(!Cone.is_separable());
    assert!((Cone.integral() - core::f32::consts::FRAC_PI_2).abs() < 1e-3);
}

#[test]
fn defaults_are_designs() {
    assert_eq!(Boxcar::default(), Boxcar::new([0.5, 0.5]).unwrap());
    assert_eq!(Triangle::default(), Triangle::new([2.0, 2.0]).unwrap());
    assert_eq!(Gaussian::default(), Gaussian::new([2.0, 2.0], 2.0).unwrap());
    assert_eq!(
        Mitchell::default(),
        Mitchell::new([2.0, 2.0], 1.0 / 3.0, 1.0 / 3.0).unwrap()
    );
    assert_eq!(Lanczos::default(), Lanczos::new([4.0, 4.0], 3.0).unwrap());
    assert_eq!(
        BlackmanHarris::default(),
        BlackmanHarris::new([1.5, 1.5]).unwrap()
    );
    assert_eq!(
        Mitchell::catmull_rom(),
        Mitchell::new([2.0, 2.0], 0.0, 0.5).unwrap()
    );
    for (spec, kind) in [
        ("box", FilterKind::Boxcar(Boxcar::default())),
        ("triangle", FilterKind::Triangle(Triangle::default())),
        ("gaussian", FilterKind::Gaussian(Gaussian::default())),
        ("mitchell", FilterKind::Mitchell(Mitchell::default())),
        ("lanczos", FilterKind::Lanczos(Lanczos::default())),
        (
            "blackman-harris",
            FilterKind::BlackmanHarris(BlackmanHarris::default()),
        ),
        ("catmull-rom", FilterKind::Mitchell(Mitchell::catmull_rom())),
        (
            "catmull-rom:radius=3",
            FilterKind::Mitchell(Mitchell::new([3.0, 3.0], 0.0, 0.5).unwrap()),
        ),
    ] {
        assert_eq!(FilterKind::parse(spec).unwrap(), kind, "{spec}");
    }
    // Catmull–Rom fixes B and C: its spec takes only the radius keys.
    assert_eq!(
        FilterKind::parse("catmull-rom:b=1")
            .unwrap_err()
            .to_string(),
        "filter spec: filter `catmull-rom` has no key `b`"
    );
    assert_eq!(
        FilterKind::parse("blackman-harris:tau=1")
            .unwrap_err()
            .to_string(),
        "filter spec: filter `blackman-harris` has no key `tau`"
    );
    // Every name front ends list parses; the unknown-name message lists them all.
    for name in FILTER_NAMES {
        assert!(FilterKind::parse(name).is_ok(), "{name}");
    }
    assert_eq!(
        FilterKind::parse("hann").unwrap_err().to_string(),
        "filter spec: unknown filter `hann` (expected box, triangle, gaussian, mitchell, \
         catmull-rom, blackman-harris or lanczos)"
    );
}

#[test]
fn mitchell_values_and_partition_of_unity() {
    for (b, c) in [
        (1.0f32 / 3.0, 1.0f32 / 3.0),
        (0.0, 0.5),
        (1.0, 0.0),
        (0.5, 0.25),
        (0.2, 0.7),
    ] {
        let m = Mitchell::new([2.0, 2.0], b, c).unwrap();
        let f = |x: f32| m.eval_1d(Axis::X, x).unwrap();
        assert!((f(0.0) - (1.0 - b / 3.0)).abs() < 1e-6, "M(0), B = {b}");
        assert!((f(1.0) - b / 6.0).abs() < 1e-6, "M(1), B = {b}");
        assert!((f(-1.0) - b / 6.0).abs() < 1e-6, "M(-1), B = {b}");
        assert!(f(2.0).abs() < 1e-6);
        for i in 0..=1000 {
            let x = i as f32 / 1000.0;
            let sum: f32 = (-3..=3).map(|k| f(x + k as f32)).sum();
            assert!(
                (sum - 1.0).abs() < 2e-6,
                "B = {b}, C = {c}: Σ M({x} + k) = {sum}"
            );
        }
    }
}

#[test]
fn sinc_decreases_over_the_first_ten_thousand_floats() {
    let mut prev = sinc(0.0);
    assert_eq!(prev, 1.0);
    for bits in 1..=10_000u32 {
        let x = f32::from_bits(bits);
        let s = sinc(x);
        assert!(
            s.is_finite() && s <= prev && s <= 1.0,
            "sinc({x:e}) = {s} after {prev}"
        );
        prev = s;
    }
    // And just above 0 at normal sizes it decreases strictly over a coarse grid.
    let mut prev = 1.0;
    for i in 1..=1000 {
        let s = sinc(i as f32 * 1e-3);
        assert!(s < prev);
        prev = s;
    }
}

#[test]
fn sinc_matches_the_oracle_near_zeros_and_far_out() {
    let mut rng = default_rng(5);
    for _ in 0..100_000 {
        let x = (uniform_f32(&mut rng) - 0.5) * 200.0;
        let want = sinc64(f64::from(x));
        let got = f64::from(sinc(x));
        assert!(
            (got - want).abs() < 1e-7 + 4e-7 * want.abs(),
            "sinc({x}) = {got}, want {want}"
        );
    }
    for n in 1..100 {
        assert_eq!(sinc(n as f32), 0.0);
        assert_eq!(sinc(-(n as f32)), 0.0);
    }
    assert_eq!(sinc(f32::INFINITY), 0.0);
    assert_eq!(sinc(1e30), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Tables.

/// A user-defined, non-separable filter: the cone `max(0, 1 − x² − y²)`.
#[derive(Debug, Clone, Copy)]
struct Cone;
impl Filter for Cone {
    fn radius(&self) -> [f32; 2] {
        [1.0, 1.0]
    }
    fn eval(&self, x: f32, y: f32) -> f32 {
        let d = 1.0 - (x * x + y * y);
        if d > 0.0 { d } else { 0.0 }
    }
}

/// Max |lookup − eval| over a (2k+1)² grid on [−r, r]².
fn table_error(f: &dyn Filter, t: TableView<'_>, k: i32) -> f64 {
    lookup_error(f, |x, y| t.weight(x, y), k)
}

/// Max |lookup(x, y) − eval(x, y)| over a (2k+1)² grid on [−r, r]², for any table's lookup.
fn lookup_error(f: &dyn Filter, lookup: impl Fn(f32, f32) -> f32, k: i32) -> f64 {
    let [rx, ry] = f.radius();
    let mut worst = 0.0f64;
    for j in -k..=k {
        let y = j as f32 / k as f32 * ry;
        for i in -k..=k {
            let x = i as f32 / k as f32 * rx;
            let e = (f64::from(lookup(x, y)) - f64::from(f.eval(x, y))).abs();
            worst = worst.max(e);
        }
    }
    worst
}

#[test]
fn documented_table_error_bounds() {
    // The bounds in table.rs's docs: (nearest, linear) at the default size, defaults.
    let rows: [(FilterKind, f64, f64); 5] = [
        (FilterKind::parse("box").unwrap(), 0.0, 0.0),
        (FilterKind::parse("triangle").unwrap(), 0.26, 7.2e-7),
        (FilterKind::parse("gaussian").unwrap(), 0.113, 0.0171),
        (FilterKind::parse("mitchell").unwrap(), 0.089, 0.0138),
        (FilterKind::parse("lanczos").unwrap(), 0.223, 0.0575),
    ];
    for (f, nearest, linear) in rows {
        let tn: FilterTable = FilterTable::new(&f, Interpolation::Nearest).unwrap();
        let tl: FilterTable = FilterTable::new(&f, Interpolation::Linear).unwrap();
        let (en, el) = (
            table_error(&f, tn.view(), 1000),
            table_error(&f, tl.view(), 1000),
        );
        std::println!("{f}: nearest {en:.3e}, linear {el:.3e}");
        assert!(
            en <= nearest,
            "{f}: nearest error {en} above the documented {nearest}"
        );
        assert!(
            el <= linear,
            "{f}: linear error {el} above the documented {linear}"
        );
    }
}

#[test]
fn tables_are_exact_at_sample_points() {
    let mut filters: Vec<(std::boxed::Box<dyn Filter>, bool)> = Vec::new();
    for (f, _) in cases() {
        filters.push((std::boxed::Box::new(f), true));
    }
    filters.push((std::boxed::Box::new(Cone), false));
    let mut inexact = 0;
    for (f, separable) in &filters {
        let f: &dyn Filter = f.as_ref();
        for interp in [Interpolation::Nearest, Interpolation::Linear] {
            let t: FilterTable = FilterTable::new(f, interp).unwrap();
            assert_eq!(t.is_separable(), *separable);
            let full: Table2d = Table2d::new(f, interp).unwrap();
            let v = t.view();
            for j in 0..16 {
                let y = v.sample_point(Axis::Y, j);
                for i in 0..16 {
                    let x = v.sample_point(Axis::X, i);
                    let want = f.eval(x, y);
                    assert_eq!(t.weight(x, y), v.weight(x, y));
                    assert_eq!(v.entry(i, j), want, "entry ({i}, {j})");
                    assert_eq!(t.weight(-x, y), t.weight(x, y));
                    assert_eq!(full.weight(x, -y), full.weight(x, y));
                    if t.weight(x, y) != want || full.weight(x, y) != want {
                        inexact += 1;
                        // Only possible where no float maps exactly onto the sample: still close.
                        assert!((t.weight(x, y) - want).abs() < 1e-6 * want.abs().max(1.0));
                    }
                }
            }
        }
    }
    assert_eq!(inexact, 0, "lookups not bit-exact at sample points");
}

#[test]
fn separable_table_factors_multiply_to_the_weight() {
    let m = Mitchell::default();
    let t: FilterTable = FilterTable::new(&m, Interpolation::Linear).unwrap();
    let v = t.view();
    let mut rng = default_rng(3);
    for _ in 0..10_000 {
        let x = (uniform_f32(&mut rng) - 0.5) * 5.0;
        let y = (uniform_f32(&mut rng) - 0.5) * 5.0;
        let w = v.weight_1d(Axis::X, x).unwrap() * v.weight_1d(Axis::Y, y).unwrap();
        assert_eq!(w, t.weight(x, y)); // −0 and 0 are equal
        assert_eq!(t.weight_1d(Axis::X, x), v.weight_1d(Axis::X, x));
    }
    assert_eq!(t.integral(), 1.0);
    let full: FilterTable = FilterTable::new(&Cone, Interpolation::Linear).unwrap();
    assert_eq!(full.view().weight_1d(Axis::X, 0.0), None);
}

#[test]
fn footprint_equals_per_weight_lookups() {
    let mut rng = default_rng(21);
    // Shapes cover the scalar remainder (nx % 4 ≠ 0), whole and partial blocks of four rows.
    let shapes = [(1, 1), (3, 2), (4, 4), (5, 9), (8, 8), (13, 6), (2, 17)];
    for f in [
        FilterKind::parse("mitchell").unwrap(),
        FilterKind::parse("lanczos:rx=3,ry=1.5").unwrap(),
        FilterKind::parse("box").unwrap(),
    ] {
        for interp in [Interpolation::Nearest, Interpolation::Linear] {
            let sep: FilterTable = FilterTable::new(&f, interp).unwrap();
            let full: FilterTable = FilterTable::new(&Cone, interp).unwrap();
            for t in [sep, full] {
                let v = t.view();
                for &(nx, ny) in &shapes {
                    for _ in 0..60 {
                        let d0 = [
                            (uniform_f32(&mut rng) - 0.5) * 12.0,
                            (uniform_f32(&mut rng) - 0.5) * 8.0,
                        ];
                        let mut a = std::vec![f32::NAN; nx * ny];
                        let mut b = std::vec![f32::NAN; nx * ny];
                        v.footprint(d0, nx, &mut a).unwrap();
                        t.footprint(d0, nx, &mut b).unwrap();
                        for j in 0..ny {
                            for i in 0..nx {
                                let (dx, dy) = (d0[0] + i as f32, d0[1] + j as f32);
                                let want = t.weight(dx, dy);
                                let k = j * nx + i;
                                assert_eq!(
                                    a[k], want,
                                    "{f} {interp:?} ({i}, {j}) of {nx}×{ny} from {d0:?}"
                                );
                                assert_eq!(
                                    b[k], want,
                                    "{f} {interp:?} ({i}, {j}) of {nx}×{ny} from {d0:?}"
                                );
                            }
                        }
                    }
                }
                let mut bad = [0.0f32; 10];
                assert!(v.footprint([0.0, 0.0], 3, &mut bad).is_err());
                assert!(v.footprint([0.0, 0.0], 0, &mut bad).is_err());
                assert!(t.footprint([0.0, 0.0], 3, &mut bad).is_err());
                assert!(t.footprint([0.0, 0.0], 4, &mut []).is_err());
            }
        }
    }
    // Non-finite origins give zero weights, not NaN.
    let t: FilterTable = FilterTable::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    for d0 in [
        [f32::NAN, 0.0],
        [0.0, f32::INFINITY],
        [f32::NEG_INFINITY, f32::NAN],
    ] {
        let mut w = [1.0f32; 16];
        t.footprint(d0, 4, &mut w).unwrap();
        assert!(w.iter().all(|&w| w == 0.0), "{d0:?}: {w:?}");
    }
}

#[test]
fn lookups_are_exact_at_sample_points_for_any_radius_and_size() {
    // Sample points where no float lands exactly on the index are the hard case; random radii
    // hit them often. Both interpolations, several sizes, through every lookup path.
    fn check<const N: usize>(rng: &mut crate::rng::DefaultRng) {
        for _ in 0..40 {
            let r = [
                MIN_RADIUS + uniform_f32(rng) * 20.0,
                0.01 + uniform_f32(rng) * 300.0,
            ];
            let f = Mitchell::new(r, 1.0 / 3.0, 1.0 / 3.0).unwrap();
            for interp in [Interpolation::Nearest, Interpolation::Linear] {
                let t = SeparableTable::<N>::new(&f, interp).unwrap();
                let full = Table2d::<N>::new(&f, interp).unwrap();
                for i in 0..N {
                    for axis in [Axis::X, Axis::Y] {
                        let x = t.sample_point(axis, i);
                        let want = f.eval_1d(axis, x).unwrap();
                        assert_eq!(t.weight_1d(axis, x), want, "N={N} r={r:?} {axis:?} i={i}");
                        assert_eq!(t.weight_1d(axis, -x), want);
                        assert_eq!(t.view().weight_1d(axis, x), Some(want));
                    }
                    let (x, y) = (
                        t.sample_point(Axis::X, i),
                        t.sample_point(Axis::Y, N - 1 - i),
                    );
                    assert_eq!(t.weight(x, y), f.eval(x, y), "N={N} r={r:?} i={i}");
                    assert_eq!(full.weight(x, y), f.eval(x, y), "2D N={N} r={r:?} i={i}");
                }
                // Just past the radius on each axis: exactly 0.
                assert_eq!(t.weight(r[0].next_up(), 0.0), 0.0);
                assert_eq!(t.weight(0.0, -r[1].next_up()), 0.0);
                assert_eq!(full.weight(r[0].next_up(), 0.0), 0.0);
            }
        }
    }
    let mut rng = default_rng(99);
    check::<2>(&mut rng);
    check::<3>(&mut rng);
    check::<16>(&mut rng);
    check::<17>(&mut rng);
    check::<64>(&mut rng);
}

#[test]
fn user_filter_tabulates_like_a_builtin() {
    for interp in [Interpolation::Nearest, Interpolation::Linear] {
        let t: FilterTable = FilterTable::new(&Cone as &dyn Filter, interp).unwrap();
        let bound = if interp == Interpolation::Linear {
            0.04
        } else {
            0.14
        };
        let e = table_error(&Cone, t.view(), 500);
        assert!(e <= bound, "{interp:?}: {e}");
        assert!((t.integral() - core::f32::consts::FRAC_PI_2).abs() < 1e-3);
        assert_eq!(t.weight(1.001, 0.0), 0.0);
        assert_eq!(t.weight(f32::NAN, 0.0), 0.0);
    }
    // A plugin that breaks the contract is refused (radius, integral) or sanitised (values).
    #[derive(Debug)]
    struct Bad(f32);
    impl Filter for Bad {
        fn radius(&self) -> [f32; 2] {
            [self.0, 1.0]
        }
        fn eval(&self, _: f32, _: f32) -> f32 {
            f32::NAN
        }
        fn integral(&self) -> f32 {
            1.0
        }
    }
    assert!(FilterTable::<16>::new(&Bad(f32::NAN), Interpolation::Linear).is_err());
    assert!(FilterTable::<16>::new(&Bad(-1.0), Interpolation::Linear).is_err());
    let t = FilterTable::<16>::new(&Bad(1.0), Interpolation::Linear).unwrap();
    assert_eq!(t.weight(0.5, 0.5), 0.0);
    assert!(FilterSampler::<_, 8>::new(Bad(0.0)).is_err());
    let s = FilterSampler::<_, 8>::new(Bad(1.0)).unwrap();
    assert_eq!(s.sample([0.5, 0.5]).weight, 0.0);
}

#[test]
fn a_negligible_or_undefined_integral_is_refused_by_every_table() {
    // A filter of the given integral (its values do not matter here).
    #[derive(Debug)]
    struct Weighs(f32);
    impl Filter for Weighs {
        fn radius(&self) -> [f32; 2] {
            [1.0, 1.0]
        }
        fn eval(&self, _: f32, _: f32) -> f32 {
            1.0
        }
        fn integral(&self) -> f32 {
            self.0
        }
        fn eval_1d(&self, _: Axis, _: f32) -> Option<f32> {
            Some(1.0)
        }
    }
    for bad in [
        0.0,
        -1.0,
        9.9e-13,
        f32::NAN,
        f32::INFINITY,
        -f32::MIN_POSITIVE,
    ] {
        let f = Weighs(bad);
        for e in [
            FilterTable::<16>::new(&f, Interpolation::Linear).err(),
            SeparableTable::<16>::new(&f, Interpolation::Nearest).err(),
            Table2d::<16>::new(&f, Interpolation::Linear).err(),
            PhaseTable::new(&f).err(),
            FilmTable::<16>::new(&f).err(),
        ] {
            let e = e.unwrap_or_else(|| panic!("integral {bad} accepted"));
            assert!(
                matches!(
                    e,
                    Error::OutOfRange {
                        what: "filter integral",
                        ..
                    } | Error::NonFinite {
                        what: "filter integral"
                    }
                ),
                "{bad}: {e:?}"
            );
        }
    }
    // At the limit and above: accepted, and the tables keep the filter's integral.
    for good in [MIN_INTEGRAL, 1e-6, 1.0, f32::MAX] {
        let f = Weighs(good);
        assert_eq!(PhaseTable::new(&f).unwrap().integral(), good);
        assert_eq!(
            FilterTable::<16>::new(&f, Interpolation::Linear)
                .unwrap()
                .integral(),
            good
        );
    }
    // A C-style callback that answers NaN everywhere has a NaN numeric integral: refused.
    #[derive(Debug)]
    struct NanEverywhere;
    impl Filter for NanEverywhere {
        fn radius(&self) -> [f32; 2] {
            [1.0, 1.0]
        }
        fn eval(&self, _: f32, _: f32) -> f32 {
            f32::NAN
        }
    }
    assert!(FilmTable::<16>::new(&NanEverywhere).is_err());
}

#[test]
fn a_gaussian_whose_integral_is_negligible_is_refused() {
    // σ = 10¹⁰ over radius 2: α = 5·10⁻²¹, integral about 2.8·10⁻³⁹ (the image would be black).
    let e = Gaussian::with_sigma([2.0, 2.0], 1e10).unwrap_err();
    assert!(
        matches!(
            e,
            Error::OutOfRange {
                what: "filter integral",
                ..
            }
        ),
        "{e:?}"
    );
    let e = Gaussian::new([2.0, 2.0], 1e30).unwrap_err();
    assert!(
        matches!(
            e,
            Error::OutOfRange {
                what: "filter integral",
                ..
            }
        ),
        "{e:?}"
    );
    let msg = FilterKind::parse("gaussian:sigma=1e10")
        .unwrap_err()
        .to_string();
    assert!(
        msg.starts_with(
            "filter spec: invalid value `1e10` for key `sigma`: the filter's integral "
        ) && msg.ends_with("is below 1e-12, so every sample would weigh almost nothing"),
        "{msg}"
    );
    let msg = FilterKind::parse("gaussian:alpha=1e30")
        .unwrap_err()
        .to_string();
    assert!(
        msg.contains("for key `alpha`: the filter's integral"),
        "{msg}"
    );
    // Wide and narrow Gaussians well past any practical use are kept: σ = 1000 at radius 2
    // integrates to about 2.8e-11, α = 10⁶ to about π·10⁻⁶.
    assert!(Gaussian::with_sigma([2.0, 2.0], 1000.0).is_ok());
    assert!(Gaussian::new([2.0, 2.0], 1e6).is_ok());
}

#[test]
fn huge_plugin_values_are_capped_so_masking_stays_exact() {
    #[derive(Debug)]
    struct Huge;
    impl Filter for Huge {
        fn radius(&self) -> [f32; 2] {
            [1.0, 1.0]
        }
        fn eval(&self, x: f32, y: f32) -> f32 {
            if x.abs() <= 1.0 && y.abs() <= 1.0 {
                -f32::MAX
            } else {
                0.0
            }
        }
        fn eval_1d(&self, _: Axis, x: f32) -> Option<f32> {
            Some(if x.abs() <= 1.0 { f32::MAX } else { 0.0 })
        }
        // Stated, so the tables accept it (the numeric one would overflow).
        fn integral(&self) -> f32 {
            1.0
        }
    }
    let cap = 4_611_686_018_427_387_904.0f32; // 2⁶²
    for interp in [Interpolation::Nearest, Interpolation::Linear] {
        let sep = SeparableTable::<16>::new(&Huge, interp).unwrap();
        let full = Table2d::<16>::new(&Huge, interp).unwrap();
        assert_eq!(sep.values(Axis::X)[3], cap);
        assert_eq!(full.values()[3][3], -cap);
        assert_eq!(sep.weight(0.5, 0.5), cap * cap);
        for (x, y) in [
            (1.5, 0.0),
            (0.0, -1.5),
            (f32::NAN, 0.0),
            (f32::INFINITY, 0.5),
        ] {
            assert_eq!(sep.weight(x, y), 0.0, "({x}, {y})");
            assert_eq!(full.weight(x, y), 0.0, "({x}, {y})");
        }
    }
}

#[test]
fn other_table_sizes() {
    let l = Lanczos::default();
    let t2 = FilterTable::<2>::new(&l, Interpolation::Linear).unwrap();
    assert_eq!(t2.weight(0.0, 0.0), 1.0);
    let t256 = FilterTable::<256>::new(&l, Interpolation::Linear).unwrap();
    assert!(table_error(&l, t256.view(), 700) < 5e-4);
    assert_eq!(t256.view().len(), 256);
}

// ---------------------------------------------------------------------------------------------
// Importance sampling.

/// χ² of sampled offsets against |f|/∫|f| on an 8 × 8 histogram.
fn chi_square<F: Filter, const N: usize>(
    s: &FilterSampler<F, N>,
    samples: u32,
    seed: u64,
) -> (f64, usize) {
    chi_square_bins::<8, F, N>(s, samples, seed)
}

/// χ² of sampled offsets against |f|/∫|f| on a `B × B` histogram over the support; the
/// expected counts by midpoint quadrature on a 512 × 512 grid. Bins with fewer than 5 expected
/// counts are pooled; returns (χ², degrees of freedom).
fn chi_square_bins<const B: usize, F: Filter, const N: usize>(
    s: &FilterSampler<F, N>,
    samples: u32,
    seed: u64,
) -> (f64, usize) {
    let f = s.filter();
    let [rx, ry] = f.radius().map(f64::from);
    // Expected bin probabilities by fine midpoint quadrature of |f|.
    let mut expected = [[0.0f64; B]; B];
    let q: usize = 512 / B;
    for (bj, row) in expected.iter_mut().enumerate() {
        for (bi, e) in row.iter_mut().enumerate() {
            for qj in 0..q {
                for qi in 0..q {
                    let x = -rx + ((bi * q + qi) as f64 + 0.5) * 2.0 * rx / (B * q) as f64;
                    let y = -ry + ((bj * q + qj) as f64 + 0.5) * 2.0 * ry / (B * q) as f64;
                    *e += f64::from(f.eval(x as f32, y as f32)).abs();
                }
            }
        }
    }
    let total: f64 = expected.iter().flatten().sum();
    let mut counts = [[0u32; B]; B];
    let mut rng = default_rng(seed);
    for _ in 0..samples {
        let fs = s.sample([uniform_f32(&mut rng), uniform_f32(&mut rng)]);
        let [x, y] = fs.offset;
        assert!(x.abs() <= rx as f32 && y.abs() <= ry as f32);
        let bi = (((f64::from(x) + rx) / (2.0 * rx) * B as f64) as usize).min(B - 1);
        let bj = (((f64::from(y) + ry) / (2.0 * ry) * B as f64) as usize).min(B - 1);
        counts[bj][bi] += 1;
    }
    // Bins with fewer than 5 expected counts are pooled.
    let (mut chi2, mut dof) = (0.0, 0usize);
    let (mut pool_e, mut pool_o) = (0.0, 0.0);
    for j in 0..B {
        for i in 0..B {
            let e = expected[j][i] / total * f64::from(samples);
            let o = f64::from(counts[j][i]);
            if e < 5.0 {
                pool_e += e;
                pool_o += o;
            } else {
                chi2 += (o - e) * (o - e) / e;
                dof += 1;
            }
        }
    }
    if pool_e >= 5.0 {
        chi2 += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        dof += 1;
    }
    (chi2, dof - 1)
}

#[test]
fn sampled_offsets_follow_abs_f() {
    let n = 200_000;
    // χ² critical values at p = 0.001 are below dof + 3.1·√(2·dof) + 10 for these sizes.
    let crit = |dof: usize| dof as f64 + 3.1 * (2.0 * dof as f64).sqrt() + 10.0;
    type Run<'a> = &'a dyn Fn() -> (f64, usize);
    let cases: [(Run<'_>, &str); 5] = [
        (
            &|| {
                chi_square(
                    &FilterSampler::<_, 32>::new(Mitchell::default()).unwrap(),
                    n,
                    1,
                )
            },
            "mitchell",
        ),
        (
            &|| {
                chi_square(
                    &FilterSampler::<_, 64>::new(Lanczos::default()).unwrap(),
                    n,
                    2,
                )
            },
            "lanczos",
        ),
        (
            &|| {
                chi_square(
                    &FilterSampler::<_, 32>::new(Gaussian::default()).unwrap(),
                    n,
                    3,
                )
            },
            "gaussian",
        ),
        (
            &|| {
                chi_square(
                    &FilterSampler::<_, 32>::new(Triangle::new([1.5, 0.5]).unwrap()).unwrap(),
                    n,
                    4,
                )
            },
            "triangle",
        ),
        (
            &|| chi_square(&FilterSampler::<&dyn Filter, 32>::new(&Cone).unwrap(), n, 5),
            "cone (user)",
        ),
    ];
    for (run, name) in cases {
        let (chi2, dof) = run();
        assert!(chi2 < crit(dof), "{name}: χ² = {chi2:.1} with {dof} dof");
    }
}

/// Every built-in filter's default sampler (32 × 32 cells) draws offsets that follow |f| on a
/// 32 × 32 histogram at 10⁶ samples: χ² below the p = 0.001 critical value (family false-alarm
/// rate under 0.7 % for the seven; the seeds are fixed, so the test is deterministic).
/// With each cell weighted by |f| at its centre, Lanczos failed it (χ² = 1727 with 840 degrees of
/// freedom); the cells' masses are integrals now.
#[test]
fn default_samplers_follow_abs_f_at_a_million_samples() {
    let crit = |dof: usize| dof as f64 + 3.1 * (2.0 * dof as f64).sqrt() + 10.0;
    for (k, spec) in FILTER_NAMES.into_iter().enumerate() {
        let f = FilterKind::parse(spec).unwrap();
        let sampler: FilterSampler<_> = FilterSampler::new(f).unwrap();
        let (chi2, dof) = chi_square_bins::<32, _, 32>(&sampler, 1_000_000, 40 + k as u64);
        assert!(chi2 < crit(dof), "{spec}: χ² = {chi2:.1} with {dof} dof");
    }
}

#[test]
fn estimator_converges_to_integral_of_f_times_g() {
    let g = |x: f64, y: f64| (0.7 * x).cos() * (1.0 + 0.3 * y) + 0.2 * x * x + 0.1 * x * y;
    let check = |f: &dyn Filter, sample: &dyn Fn([f32; 2]) -> FilterSample, name: &str| {
        let [rx, ry] = f.radius().map(f64::from);
        // Truth by 1024² midpoint quadrature.
        const Q: u32 = 1024;
        let (hx, hy) = (2.0 * rx / f64::from(Q), 2.0 * ry / f64::from(Q));
        let mut truth = 0.0;
        for j in 0..Q {
            for i in 0..Q {
                let x = -rx + (f64::from(i) + 0.5) * hx;
                let y = -ry + (f64::from(j) + 0.5) * hy;
                truth += f64::from(f.eval(x as f32, y as f32)) * g(x, y);
            }
        }
        truth *= hx * hy;
        let n = 1 << 18;
        let mut rng = default_rng(17);
        let (mut sum, mut sum2) = (0.0f64, 0.0f64);
        for _ in 0..n {
            let s = sample([uniform_f32(&mut rng), uniform_f32(&mut rng)]);
            let v = f64::from(s.weight) * g(f64::from(s.offset[0]), f64::from(s.offset[1]));
            sum += v;
            sum2 += v * v;
        }
        let mean = sum / f64::from(n);
        let sd = ((sum2 / f64::from(n) - mean * mean) / f64::from(n)).sqrt();
        assert!(
            (mean - truth).abs() < 5.0 * sd + 1e-4 * truth.abs()
                && (mean - truth).abs() < 0.01 * truth.abs(),
            "{name}: estimate {mean} ± {sd}, truth {truth}"
        );
    };
    let m = FilterSampler::<_, 32>::new(Mitchell::default()).unwrap();
    check(&Mitchell::default(), &|u| m.sample(u), "mitchell");
    let l = FilterSampler::<_, 16>::new(Lanczos::default()).unwrap();
    check(
        &Lanczos::default(),
        &|u| l.sample(u),
        "lanczos, coarse grid",
    );
    let c = FilterSampler::<&dyn Filter, 32>::new(&Cone).unwrap();
    check(&Cone, &|u| c.sample(u), "cone (user)");
    let b = FilterSampler::<_, 4>::new(Boxcar::new([1.0, 2.0]).unwrap()).unwrap();
    check(&Boxcar::new([1.0, 2.0]).unwrap(), &|u| b.sample(u), "box");
}

/// A constant filter's density is uniform over its support, so its sampler is the uniform
/// inverse CDF on each axis: `u ↦ −r + 2r·u`, and every weight is the support's area.
#[test]
fn box_sampler_is_the_uniform_inverse_cdf_on_each_axis() {
    // Cells of 0.5 × 0.75: no axis where multiplying and dividing by the cell agree.
    let b = FilterSampler::<_, 4>::new(Boxcar::new([1.0, 1.5]).unwrap()).unwrap();
    for i in 0..17 {
        for j in 0..17 {
            let u = [i as f32 / 17.0, j as f32 / 17.0];
            let fs = b.sample(u);
            let want = [-1.0 + 2.0 * u[0], -1.5 + 3.0 * u[1]];
            for k in 0..2 {
                assert!((fs.offset[k] - want[k]).abs() < 1e-6, "{u:?}: {fs:?}");
            }
            assert!((fs.weight - 6.0).abs() < 1e-5, "{u:?}: {fs:?}");
        }
    }
    assert_eq!(b.radius(), [1.0, 1.5]);
}

/// The density is 0 off the support: past the radius on either axis alone, for NaN in either
/// coordinate, and everywhere for a filter that is zero everywhere; inside, the box's
/// density is 1/area.
#[test]
fn sampler_pdf_is_zero_off_the_support_on_each_axis() {
    let b = FilterSampler::<_, 4>::new(Boxcar::new([1.0, 1.5]).unwrap()).unwrap();
    let inside = 1.0 / 6.0;
    for (offset, want) in [
        ([0.5, 1.0], inside),
        ([-1.0, 1.5], inside),
        ([1.01, 0.0], 0.0),
        ([-1.01, 0.0], 0.0),
        ([0.0, 1.51], 0.0),
        ([0.0, -1.51], 0.0),
        ([f32::NAN, 0.0], 0.0),
        ([0.0, f32::NAN], 0.0),
    ] {
        assert!(
            (b.pdf(offset) - want).abs() < 1e-6,
            "{offset:?}: {}",
            b.pdf(offset)
        );
    }
    #[derive(Debug)]
    struct Zero;
    impl Filter for Zero {
        fn radius(&self) -> [f32; 2] {
            [1.0, 1.0]
        }
        fn eval(&self, _: f32, _: f32) -> f32 {
            0.0
        }
    }
    let z = FilterSampler::<_, 4>::new(Zero).unwrap();
    assert_eq!(z.pdf([0.0, 0.0]), 0.0);
    assert_eq!(z.sample([0.5, 0.5]).weight, 0.0);
}

#[test]
fn sampler_weight_is_f_over_pdf_and_pdf_integrates_to_one() {
    let s = FilterSampler::<_, 32>::new(Mitchell::default()).unwrap();
    let f = *s.filter();
    let mut rng = default_rng(9);
    for _ in 0..10_000 {
        let fs = s.sample([uniform_f32(&mut rng), uniform_f32(&mut rng)]);
        let [x, y] = fs.offset;
        let want = f.eval(x, y) / s.pdf(fs.offset);
        assert!(
            (fs.weight - want).abs() <= 1e-5 * want.abs().max(1.0),
            "{fs:?} vs {want}"
        );
        assert!(fs.weight.signum() == f.eval(x, y).signum() || fs.weight == 0.0);
    }
    let pdf_integral = {
        let n = 512;
        let h = 4.0 / n as f64;
        let mut sum = 0.0;
        for j in 0..n {
            for i in 0..n {
                let x = -2.0 + (i as f64 + 0.5) * h;
                let y = -2.0 + (j as f64 + 0.5) * h;
                sum += f64::from(s.pdf([x as f32, y as f32]));
            }
        }
        sum * h * h
    };
    assert!((pdf_integral - 1.0).abs() < 1e-4, "{pdf_integral}");
    // Clamped and non-finite u stay in the support.
    for u in [[1.0, 1.0], [f32::NAN, -3.0], [f32::INFINITY, 0.999_999_9]] {
        let fs = s.sample(u);
        assert!(fs.offset[0].abs() <= 2.0 && fs.offset[1].abs() <= 2.0 && fs.weight.is_finite());
    }
}

// ---------------------------------------------------------------------------------------------
// Specs.

#[test]
fn spec_errors_name_the_offence() {
    use SpecError::*;
    assert_eq!(FilterKind::parse(""), Err(Empty));
    assert_eq!(FilterKind::parse(":b=1"), Err(Empty));
    assert_eq!(
        FilterKind::parse("sinc"),
        Err(UnknownFilter { name: "sinc" })
    );
    assert_eq!(
        FilterKind::parse("box:tau=1"),
        Err(UnknownKey {
            filter: "box",
            key: "tau"
        })
    );
    assert_eq!(
        FilterKind::parse("mitchell:b"),
        Err(MissingValue { item: "b" })
    );
    assert_eq!(
        FilterKind::parse("mitchell:b="),
        Err(MissingValue { item: "b=" })
    );
    assert_eq!(
        FilterKind::parse("mitchell:b=1,"),
        Err(MissingValue { item: "" })
    );
    assert_eq!(
        FilterKind::parse("gaussian:alpha=1x"),
        Err(BadNumber {
            key: "alpha",
            value: "1x"
        })
    );
    assert_eq!(
        FilterKind::parse("gaussian:alpha=1,sigma=2"),
        Err(Conflict {
            first: "alpha",
            second: "sigma"
        })
    );
    // `radius` with `rx` or `ry`, in either order: refused, not settled by the order.
    for (spec, first, second) in [
        ("box:radius=1,rx=2", "radius", "rx"),
        ("box:rx=2,radius=1", "rx", "radius"),
        ("mitchell:ry=2,radius=1", "ry", "radius"),
        ("triangle:radius=1,ry=0.5", "radius", "ry"),
        ("lanczos:rx=1,ry=2,radius=3", "rx", "radius"),
    ] {
        assert_eq!(
            FilterKind::parse(spec),
            Err(Conflict { first, second }),
            "{spec}"
        );
    }
    assert_eq!(
        FilterKind::parse("box:rx=2,ry=1").unwrap().radius(),
        [2.0, 1.0]
    );
    assert_eq!(
        FilterKind::parse("gaussian:sigma=0"),
        Err(Invalid {
            key: "sigma",
            value: "0",
            error: crate::Error::OutOfRange {
                what: "sigma",
                value: 0.0,
                range: Interval::closed(
                    f64::from(gaussian::MIN_SIGMA),
                    f64::from(gaussian::MAX_SIGMA)
                )
            }
        })
    );
    assert_eq!(
        FilterKind::parse("lanczos:rx=2,ry=nan"),
        Err(Invalid {
            key: "ry",
            value: "nan",
            error: crate::Error::NonFinite { what: "ry" }
        })
    );
    assert_eq!(
        FilterKind::parse("mitchell:c=1e9"),
        Err(Invalid {
            key: "c",
            value: "1e9",
            error: crate::Error::OutOfRange {
                what: "c",
                value: 1e9,
                range: Interval::closed(-1000.0, 1000.0)
            }
        })
    );
    let e = FilterKind::parse("triangle:radius=0")
        .unwrap_err()
        .to_string();
    assert!(e.contains("radius") && e.contains('0'), "{e}");
}

#[test]
fn spec_errors_give_the_range_and_refuse_repeated_keys() {
    use SpecError::*;
    assert_eq!(
        FilterKind::parse("box:radius=0").unwrap_err().to_string(),
        "filter spec: invalid value `0` for key `radius`: rx must be in \
         [0.000015258789, 1024] (2^-16 to 1024 pixels)"
    );
    assert_eq!(
        FilterKind::parse("mitchell:c=1e9").unwrap_err().to_string(),
        "filter spec: invalid value `1e9` for key `c`: c must be in [-1000, 1000]"
    );
    // Finite as typed but beyond f32: out of range, not "must be finite".
    // The error's value is the f32 the text rounds to.
    for (big, rounded) in [("1e308", f32::MAX), ("-1e400", f32::MIN)] {
        let spec = std::format!("mitchell:b={big}");
        assert_eq!(
            FilterKind::parse(&spec),
            Err(Invalid {
                key: "b",
                value: big,
                error: crate::Error::OutOfRange {
                    what: "b",
                    value: f64::from(rounded),
                    range: Interval::closed(-1000.0, 1000.0)
                }
            })
        );
    }
    assert!(matches!(
        FilterKind::parse("mitchell:b=inf"),
        Err(Invalid {
            error: crate::Error::NonFinite { what: "b" },
            ..
        })
    ));
    assert_eq!(
        FilterKind::parse("mitchell:b=0.5,c=0.25,b=1"),
        Err(Duplicate { key: "b" })
    );
    assert_eq!(
        FilterKind::parse("box:radius=1,radius=2")
            .unwrap_err()
            .to_string(),
        "filter spec: key `radius` is given twice"
    );
    // `radius` then `rx` would let the order decide: refused.
    assert_eq!(
        FilterKind::parse("box:radius=2,rx=1")
            .unwrap_err()
            .to_string(),
        "filter spec: keys `radius` and `rx` cannot both be given"
    );
}

#[test]
fn bare_names_give_the_documented_defaults_and_every_range_is_spelled_out() {
    // "Unset keys keep the filter's defaults", under every name and alias.
    for (names, default) in [
        (
            &["box", "boxcar", "BOX"][..],
            FilterKind::Boxcar(Boxcar::default()),
        ),
        (
            &["triangle", "tent"][..],
            FilterKind::Triangle(Triangle::default()),
        ),
        (&["gaussian"][..], FilterKind::Gaussian(Gaussian::default())),
        (&["mitchell"][..], FilterKind::Mitchell(Mitchell::default())),
        (&["lanczos"][..], FilterKind::Lanczos(Lanczos::default())),
        (
            &["blackman-harris", "BlackmanHarris", "Blackman-Harris"][..],
            FilterKind::BlackmanHarris(BlackmanHarris::default()),
        ),
        (
            &["catmull-rom", "catmullrom", "Catmull-Rom"][..],
            FilterKind::Mitchell(Mitchell::catmull_rom()),
        ),
    ] {
        for name in names {
            assert_eq!(FilterKind::parse(name), Ok(default), "{name}");
        }
    }
    // Every ranged key names itself and the value as typed, and the message gives its range.
    let f32_range = "[1.1754944e-38, 3.4028235e38]";
    for (spec, key, value, what, range) in [
        (
            "gaussian:alpha=0",
            "alpha",
            "0",
            "alpha",
            std::format!("in {f32_range}"),
        ),
        (
            "gaussian:sigma=-1",
            "sigma",
            "-1",
            "sigma",
            "in [3.8332338e-20, 6.521909e18]".into(),
        ),
        (
            "lanczos:tau=0",
            "tau",
            "0",
            "tau",
            std::format!("in {f32_range}"),
        ),
        (
            "mitchell:b=-2000",
            "b",
            "-2000",
            "b",
            "in [-1000, 1000]".into(),
        ),
        (
            "triangle:ry=4096",
            "ry",
            "4096",
            "ry",
            "in [0.000015258789, 1024] (2^-16 to 1024 pixels)".into(),
        ),
    ] {
        let e = FilterKind::parse(spec).unwrap_err();
        let number = f64::from(value.parse::<f32>().unwrap());
        assert!(
            matches!(
                e,
                SpecError::Invalid {
                    key: k,
                    value: v,
                    error: crate::Error::OutOfRange { what: w, value: x, range }
                } if (k, v, w, x) == (key, value, what, number) && !range.contains(x)
            ),
            "{spec}: {e:?}"
        );
        assert_eq!(
            e.to_string(),
            std::format!(
                "filter spec: invalid value `{value}` for key `{key}`: {what} must be {range}"
            ),
            "{spec}"
        );
    }
}

#[test]
fn each_filter_refuses_the_keys_of_the_others() {
    // alpha and sigma belong to gaussian, b and c to mitchell, tau to lanczos; radius, rx and ry
    // to every filter.
    let own = |name: &str, key: &str| match key {
        "alpha" | "sigma" => name == "gaussian",
        "b" | "c" => name == "mitchell",
        "tau" => name == "lanczos",
        _ => true,
    };
    for name in ["box", "triangle", "gaussian", "mitchell", "lanczos"] {
        for key in ["radius", "rx", "ry", "alpha", "sigma", "b", "c", "tau"] {
            let spec = std::format!("{name}:{key}=0.5");
            let got = FilterKind::parse(&spec);
            if own(name, key) {
                assert!(got.is_ok(), "{spec}: {got:?}");
            } else {
                assert_eq!(
                    got,
                    Err(SpecError::UnknownKey { filter: name, key }),
                    "{spec}"
                );
            }
        }
    }
}

#[test]
fn specs_parse_and_round_trip() {
    let g = FilterKind::parse(" Gaussian : radius = 1.5 , sigma = 0.5 ").unwrap();
    assert_eq!(
        g,
        FilterKind::Gaussian(Gaussian::with_sigma([1.5, 1.5], 0.5).unwrap())
    );
    let t = FilterKind::parse("tent:rx=3,ry=1").unwrap();
    assert_eq!(t.radius(), [3.0, 1.0]);
    assert_eq!(
        FilterKind::parse("boxcar:").unwrap(),
        FilterKind::Boxcar(Boxcar::default())
    );
    for spec in [
        "box:rx=0.7",
        "triangle",
        "gaussian:alpha=3.3",
        "mitchell:b=0.1,c=0.45,radius=2.5",
        "lanczos:tau=2,rx=3",
        "blackman-harris:radius=2",
        "catmull-rom",
    ] {
        let f = FilterKind::parse(spec).unwrap();
        assert_eq!(
            FilterKind::parse(&std::format!("{f}")).unwrap(),
            f,
            "{spec}"
        );
        assert_eq!(f.as_dyn().eval(0.1, 0.2), f.eval(0.1, 0.2));
        assert!(f.is_separable());
        // The filter itself says so too (the film tabulates it per axis only then).
        let inner: &dyn Filter = match &f {
            FilterKind::Boxcar(g) => g,
            FilterKind::Triangle(g) => g,
            FilterKind::Gaussian(g) => g,
            FilterKind::Mitchell(g) => g,
            FilterKind::Lanczos(g) => g,
            FilterKind::BlackmanHarris(g) => g,
        };
        assert!(inner.is_separable(), "{spec}");
    }
}

// ---------------------------------------------------------------------------------------------
// Properties.

fn any_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        prop::num::f32::ANY,
        -10.0f32..10.0,
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(0.0),
    ]
}

fn radius() -> impl Strategy<Value = [f32; 2]> + Clone {
    [MIN_RADIUS..=MAX_RADIUS, MIN_RADIUS..=8.0f32]
}

fn valid_filter() -> impl Strategy<Value = FilterKind> {
    filter_with(radius())
}

/// Every built-in, radii from `radius`.
fn filter_with(
    radius: impl Strategy<Value = [f32; 2]> + Clone + 'static,
) -> impl Strategy<Value = FilterKind> {
    let radius = move || radius.clone();
    prop_oneof![
        radius().prop_map(|r| FilterKind::Boxcar(Boxcar::new(r).unwrap())),
        radius().prop_map(|r| FilterKind::Triangle(Triangle::new(r).unwrap())),
        (
            radius(),
            prop_oneof![f32::MIN_POSITIVE..=f32::MAX, 1e-6f32..100.0]
        )
            // The falloffs whose integral is not negligible (the others are refused).
            .prop_filter_map("negligible integral", |(r, a)| Gaussian::new(r, a)
                .ok()
                .map(FilterKind::Gaussian)),
        (radius(), -1000.0f32..=1000.0, -1000.0f32..=1000.0)
            .prop_map(|(r, b, c)| FilterKind::Mitchell(Mitchell::new(r, b, c).unwrap())),
        (
            radius(),
            prop_oneof![f32::MIN_POSITIVE..=f32::MAX, 0.1f32..10.0]
        )
            .prop_map(|(r, t)| FilterKind::Lanczos(Lanczos::new(r, t).unwrap())),
    ]
}

/// Radii a phase table holds (below 8 pixels).
fn phase_radius() -> impl Strategy<Value = [f32; 2]> + Clone {
    [MIN_RADIUS..7.99f32, MIN_RADIUS..7.99f32]
}

proptest! {
    #[test]
    fn batch_weights_equal_single_lookups(
        f in valid_filter(),
        pts in proptest::collection::vec((any_f32(), any_f32()), 0..23),
        linear: bool,
        full: bool,
    ) {
        let interp = if linear { Interpolation::Linear } else { Interpolation::Nearest };
        let table: FilterTable = if full {
            Table2d::new(&f, interp).map(FilterTable::from).unwrap()
        } else {
            FilterTable::new(&f, interp).unwrap()
        };
        let dx: Vec<f32> = pts.iter().map(|p| p.0).collect();
        let dy: Vec<f32> = pts.iter().map(|p| p.1).collect();
        let mut out = std::vec![f32::NAN; pts.len()];
        table.weights(&dx, &dy, &mut out).unwrap();
        let mut via_view = std::vec![f32::NAN; pts.len()];
        table.view().weights(&dx, &dy, &mut via_view).unwrap();
        for i in 0..pts.len() {
            let w = table.weight(dx[i], dy[i]);
            prop_assert_eq!(out[i].to_bits(), w.to_bits(), "{} at ({}, {})", f, dx[i], dy[i]);
            prop_assert_eq!(via_view[i].to_bits(), w.to_bits());
        }
        if !pts.is_empty() {
            prop_assert!(table.weights(&dx, &dy[1..], &mut out).is_err());
        }
    }

    #[test]
    fn eval_is_finite_and_zero_past_the_radius(f in valid_filter(), x in any_f32(), y in any_f32()) {
        let v = f.eval(x, y);
        prop_assert!(v.is_finite(), "{f}: eval({x}, {y}) = {v}");
        let [rx, ry] = f.radius();
        if !(x.abs() <= rx && y.abs() <= ry) {
            prop_assert_eq!(v, 0.0);
        }
        prop_assert!(f.integral().is_finite());
        prop_assert!(f.eval_1d(Axis::X, x).unwrap().is_finite());
    }

    #[test]
    fn constructors_never_panic(r in [any_f32(), any_f32()], p in any_f32(), q in any_f32()) {
        for f in [
            Boxcar::new(r).map(FilterKind::Boxcar),
            Triangle::new(r).map(FilterKind::Triangle),
            Gaussian::new(r, p).map(FilterKind::Gaussian),
            Gaussian::with_sigma(r, p).map(FilterKind::Gaussian),
            Mitchell::new(r, p, q).map(FilterKind::Mitchell),
            Lanczos::new(r, p).map(FilterKind::Lanczos),
        ].into_iter().flatten() {
            prop_assert!(f.eval(0.0, 0.0).is_finite());
            prop_assert!(f.integral().is_finite());
        }
    }

    /// Any string either parses to a filter whose printed spec parses back to the same filter,
    /// with a finite positive radius, or is refused with a message; specs built from the
    /// grammar's words reach the first branch, arbitrary text mostly the second.
    #[test]
    fn spec_parser_round_trips_or_refuses(
        s in prop_oneof![
            "\\PC{0,40}",
            "(box|triangle|gaussian|mitchell|lanczos)(:(radius|rx|ry|b|c|alpha|sigma|tau)=[0-9.e-]{1,5}){0,3}",
        ]
    ) {
        match FilterKind::parse(&s) {
            Ok(f) => {
                let printed = f.to_string();
                let again = FilterKind::parse(&printed);
                prop_assert!(again.is_ok(), "{s:?} printed as {printed:?}, which does not parse");
                prop_assert_eq!(again.unwrap().to_string(), printed);
                let [rx, ry] = f.radius();
                prop_assert!(rx.is_finite() && rx > 0.0 && ry.is_finite() && ry > 0.0);
            }
            Err(e) => prop_assert!(!e.to_string().is_empty(), "{s:?}: an empty message"),
        }
    }

    #[test]
    fn table_and_sampler_outputs_are_finite(f in valid_filter(), x in any_f32(), y in any_f32(), u in [any_f32(), any_f32()]) {
        let t = FilterTable::<8>::new(&f, Interpolation::Linear).unwrap();
        prop_assert!(t.weight(x, y).is_finite());
        let s = FilterSampler::<_, 4>::new(f).unwrap();
        let fs = s.sample(u);
        prop_assert!(fs.weight.is_finite());
        let [rx, ry] = f.radius();
        prop_assert!(fs.offset[0].abs() <= rx && fs.offset[1].abs() <= ry);
    }
}

/// Found by the fuzzer: a sample drawn in one cell could round onto the next cell's edge, where
/// `pdf` read the neighbour (empty next to a Gaussian's far tail) — a sample with weight but no
/// density. Every sample with weight now has `pdf(offset) > 0`, over a dense grid of `u`.
#[test]
fn sampled_offsets_stay_in_the_cell_they_were_drawn_from() {
    for (radius, sigma) in [
        ([44.820_313f32, 0.5f32], 0.3f32),
        ([7.3, 3.1], 0.4),
        ([2.0, 2.0], 0.5),
    ] {
        let s: FilterSampler<Gaussian> =
            FilterSampler::new(Gaussian::with_sigma(radius, sigma).unwrap()).unwrap();
        for a in 0..=512u32 {
            for b in [0.0f32, 0.25, 0.5, 0.999_999] {
                let u = [a as f32 / 512.0, b];
                let fs = s.sample(u);
                assert!(
                    fs.weight == 0.0 || s.pdf(fs.offset) > 0.0,
                    "{radius:?} σ={sigma} u={u:?}: {fs:?} has weight, pdf 0"
                );
            }
        }
    }
}

/// Found by the fuzzer (CI's smoke runs): with a subnormal radius the cell width rounds so far
/// that the centre of the last cell — where a sample rounded off its cell is moved back to —
/// lies past the radius; with a smaller one still the cell area is 0 in f32 and `pdf` was NaN.
/// Supports whose cell area is not a normal f32 are now refused; the smallest accepted ones
/// keep offsets within the radius and every density finite.
#[test]
fn tiny_radii_are_refused_or_sampled_with_finite_density() {
    #[derive(Debug)]
    struct Flat([f32; 2]);
    impl Filter for Flat {
        fn radius(&self) -> [f32; 2] {
            self.0
        }
        fn eval(&self, x: f32, y: f32) -> f32 {
            if x.abs() <= self.0[0] && y.abs() <= self.0[1] {
                1.0
            } else {
                0.0
            }
        }
    }
    // N = 32: the cell area is rx·ry/256.
    for radius in [
        [91.660_16f32, 1.8e-44],
        [1.8e-44, 3.0],
        [1e-45, 1e-45],
        [2.5e-40, 0.5],
        [1e-45, 0.5],
        [1.7e-18, 1.7e-18],
    ] {
        let r = FilterSampler::<Flat>::new(Flat(radius));
        let area =
            (2.0 * f64::from(radius[0]) / 32.0) as f32 * (2.0 * f64::from(radius[1]) / 32.0) as f32;
        assert_eq!(
            r.err(),
            Some(Error::OutOfRange {
                what: "filter sampler cell area (2rx/N)·(2ry/N)",
                value: f64::from(area),
                range: Interval::at_least(f64::from(f32::MIN_POSITIVE)),
            }),
            "{radius:?}"
        );
    }
    for radius in [[91.660_16f32, 1e-37], [1e-35, 0.5], [1.8e-18, 1.8e-18]] {
        let s: FilterSampler<Flat> = FilterSampler::new(Flat(radius)).unwrap();
        for a in 0..=64u32 {
            for b in 0..=64u32 {
                let u = [a as f32 / 64.0, b as f32 / 64.0];
                let fs = s.sample(u);
                let [x, y] = fs.offset;
                assert!(
                    x.abs() <= radius[0] && y.abs() <= radius[1],
                    "{radius:?} u={u:?}: ({x}, {y})"
                );
                let pdf = s.pdf(fs.offset);
                assert!(
                    pdf.is_finite() && pdf > 0.0,
                    "{radius:?} u={u:?}: pdf {pdf}"
                );
                assert!(fs.weight.is_finite(), "{radius:?} u={u:?}: {fs:?}");
            }
        }
        for p in [[-radius[0], -radius[1]], [radius[0], radius[1]], [0.0, 0.0]] {
            assert!(s.pdf(p).is_finite(), "{radius:?}: pdf({p:?})");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Phase tables.

#[test]
fn phase_rows_are_exact_at_the_stored_phases() {
    // Row j, tap k holds f(k + j/64 − r) (offset rounded once from f64): reading it at phase
    // j/64 (exact in f32) returns that value bit for bit, for every built-in and radius.
    for (f, _) in cases() {
        if f.radius()[0] >= 8.0 || f.radius()[1] >= 8.0 {
            continue;
        }
        let t = PhaseTable::new(&f).unwrap();
        for (a, axis) in [Axis::X, Axis::Y].into_iter().enumerate() {
            let r = f.radius()[a];
            let taps = t.taps(axis);
            assert_eq!(taps, (2.0 * f64::from(r)).floor() as usize + 1, "{f}");
            for j in 0..=PHASES {
                let phase = j as f32 / PHASES as f32;
                let mut w = [f32::NAN; MAX_TAPS];
                assert_eq!(t.row(axis, phase, &mut w), taps);
                for (k, &w) in w[..taps].iter().enumerate() {
                    // Past the radius a tap holds the edge value f(r).
                    let d = (k as f64 + f64::from(phase) - f64::from(r)) as f32;
                    let want = f.eval_1d(axis, d.min(r)).unwrap();
                    assert_eq!(w, want, "{f} axis {a} phase {j}/64 tap {k}");
                    assert_eq!(t.tap(axis, phase, k), w);
                }
                // The padding to a multiple of 4 holds 0.
                for &p in &w[taps..taps.next_multiple_of(4)] {
                    assert_eq!(p, 0.0, "{f}");
                }
            }
        }
    }
}

#[test]
fn phase_footprints_up_to_4x4_match_the_general_path_and_the_weights() {
    // A footprint of at most 4 × 4 that starts at the first taps reads four taps per axis; the
    // same pixels inside an 8 × 8 footprint (the general path: whole padded rows) must get the
    // same weights bit for bit, and each must be the table's weight at that pixel (up to the
    // rounding of the offset `d0 + i`).
    let mut rng = default_rng(41);
    for (f, _) in cases() {
        if f.radius()[0] >= 8.0 || f.radius()[1] >= 8.0 {
            continue;
        }
        let t = PhaseTable::new(&f).unwrap();
        let [rx, ry] = f.radius();
        for k in 0..400 {
            // Offsets of a footprint's first pixel at shift 0: −r + [0, 1), the lattice of
            // 64ths (stored phases), the ends, and random.
            let frac = |rng: &mut _, k: usize| match k % 4 {
                0 => 0.0,
                1 => (k % 64) as f32 / 64.0,
                2 => 1.0 - f32::EPSILON,
                _ => uniform_f32(rng),
            };
            let d0 = [-rx + frac(&mut rng, k), -ry + frac(&mut rng, k / 4)];
            let mut small = [f32::NAN; 16];
            let mut big = [f32::NAN; 64];
            t.footprint(d0, 4, &mut small).unwrap();
            t.footprint(d0, 8, &mut big).unwrap();
            for j in 0..4 {
                for i in 0..4 {
                    let w = small[j * 4 + i];
                    assert_eq!(
                        w.to_bits(),
                        big[j * 8 + i].to_bits(),
                        "{f} {d0:?} ({i}, {j})"
                    );
                    let want = t.weight(d0[0] + i as f32, d0[1] + j as f32);
                    assert!(
                        (w - want).abs() <= 1e-5,
                        "{f} {d0:?} ({i}, {j}): {w} vs {want}"
                    );
                }
            }
        }
    }
}

#[test]
fn phase_table_error_is_below_the_64_entry_tables() {
    // The film's table before phase tables was a 64-entry SeparableTable; the phase grid
    // (spacing 1/64 pixel) is at least as fine for radii ≥ 1, and these are the measured bounds
    // quoted in phase.rs's docs.
    let rows: [(&str, f64); 5] = [
        ("box", 0.0),
        ("triangle", 4.8e-7),
        ("gaussian", 2.5e-4),
        ("mitchell", 2.2e-4),
        ("lanczos", 2.3e-4),
    ];
    for (name, bound) in rows {
        let f = FilterKind::parse(name).unwrap();
        let phase = PhaseTable::new(&f).unwrap();
        let table: FilterTable<64> = FilterTable::new(&f, Interpolation::Linear).unwrap();
        let (ep, et) = (
            lookup_error(&f, |x, y| phase.weight(x, y), 1000),
            table_error(&f, table.view(), 1000),
        );
        std::println!("{name}: phase {ep:.3e}, 64-entry {et:.3e}");
        assert!(ep <= bound, "{name}: phase error {ep} above {bound}");
        assert!(ep <= et.max(1e-6), "{name}: phase {ep} vs table {et}");
    }
}

#[test]
fn phase_table_rejects_what_it_cannot_hold() {
    let cone = Cone;
    assert_eq!(
        PhaseTable::new(&cone).err(),
        Some(Error::NotSeparable {
            what: "phase table"
        })
    );
    let wide = Triangle::new([2.0, 8.0]).unwrap();
    assert_eq!(
        PhaseTable::new(&wide).err(),
        Some(Error::OutOfRange {
            what: "filter radius ry",
            value: 8.0,
            range: Interval::open(0.0, 8.0),
        })
    );
    let just = Triangle::new([2.0, 7.999]).unwrap();
    assert_eq!(PhaseTable::new(&just).unwrap().taps(Axis::Y), 16);
}

/// A table's `footprint(d0, nx, out)`.
type FootprintFn<'a> = &'a dyn Fn([f32; 2], usize, &mut [f32]);

/// Fills an `nx × ny` footprint from `d0` (NaN first, so a weight not written shows) and checks
/// each weight against the single lookup at its offset, up to the rounding of the offsets.
fn assert_footprint_matches_single_lookups(
    what: &str,
    footprint: FootprintFn,
    single: &dyn Fn(f32, f32) -> f32,
    d0: [f32; 2],
    [nx, ny]: [usize; 2],
    scale: f32,
) {
    let mut out = std::vec![f32::NAN; nx * ny];
    footprint(d0, nx, &mut out);
    for j in 0..ny {
        for i in 0..nx {
            let (dx, dy) = (d0[0] + i as f32, d0[1] + j as f32);
            let (got, want) = (out[j * nx + i], single(dx, dy));
            assert!(
                (got - want).abs() <= 1e-4 * scale * scale,
                "{what} {nx}x{ny} from {d0:?} at ({i},{j}): footprint {got} single {want}"
            );
        }
    }
}

/// Footprints whose first pixel is the first tap on both axes (shift 0, where the 4 × 4 outer
/// product serves those that fit) of every size up to 8 × 8: every weight written, each the
/// single lookup's weight; and the table's radius and integral are the filter's.
#[test]
fn phase_footprints_of_every_size_at_shift_0_match_single_lookups() {
    for (f, _) in cases() {
        let [rx, ry] = f.radius();
        if rx >= 8.0 || ry >= 8.0 {
            continue;
        }
        let t = PhaseTable::new(&f).unwrap();
        assert_eq!(t.radius(), [rx, ry], "{f}");
        assert_eq!(t.integral(), f.integral(), "{f}");
        let scale = f.eval(0.0, 0.0).abs().max(1.0);
        for frac in [0.0f32, 0.25, 0.5, 0.9] {
            for nx in 1..=8usize {
                for ny in 1..=8usize {
                    assert_footprint_matches_single_lookups(
                        &std::format!("{f}"),
                        &|d, n, o| t.footprint(d, n, o).unwrap(),
                        &|x, y| t.weight(x, y),
                        [-rx + frac, -ry + frac],
                        [nx, ny],
                        scale,
                    );
                }
            }
        }
    }
}

/// Footprints of every table that are not square: the row count is the buffer's length over the
/// row width (2048 columns × 3 rows is a valid footprint, far below the 2²² limit on a side),
/// and the weights are the single lookups' (to an f32 rounding).
#[test]
fn wide_flat_footprints_are_accepted_and_match_single_lookups() {
    let mitchell = Mitchell::default();
    let phase = PhaseTable::new(&mitchell).unwrap();
    let table: FilterTable = FilterTable::new(&mitchell, Interpolation::Linear).unwrap();
    let (nx, ny) = (2048usize, 3usize);
    let d0 = [-1.3f32, -0.6];
    let check = |name: &str, out: &[f32], single: &dyn Fn(f32, f32) -> f32| {
        for j in 0..ny {
            for i in [0usize, 1, 2, 3, 4, 2047] {
                // Within an f32 rounding: a footprint multiplies its 1D factors in another
                // order than a single lookup.
                let want = single(d0[0] + i as f32, d0[1] + j as f32);
                let got = out[j * nx + i];
                assert!(
                    (got - want).abs() <= 1e-6,
                    "{name} ({i}, {j}): {got} vs {want}"
                );
            }
        }
    };
    let mut out = std::vec![0.0f32; nx * ny];
    phase.footprint(d0, nx, &mut out).unwrap();
    check("phase", &out, &|x, y| phase.weight(x, y));
    table.footprint(d0, nx, &mut out).unwrap();
    check("table", &out, &|x, y| table.weight(x, y));
}

/// A footprint may start any distance before the filter's support: a row of 80 pixels from 70
/// pixels to the left of it gets the single lookups' weights where it crosses the support (the
/// shift of the first pixel was once clamped to ±32, which read the wrong taps there), in the
/// phase, linear and nearest tables.
#[test]
fn phase_footprints_far_from_the_support_match_single_lookups() {
    for (f, _) in cases() {
        let [rx, ry] = f.radius();
        if rx >= 8.0 || ry >= 8.0 {
            continue;
        }
        let phase = PhaseTable::new(&f).unwrap();
        let linear: FilterTable = FilterTable::new(&f, Interpolation::Linear).unwrap();
        let nearest: FilterTable = FilterTable::new(&f, Interpolation::Nearest).unwrap();
        let scale = f.eval(0.0, 0.0).abs().max(1.0);
        for d0 in [[-70.3f32, 0.2], [-33.0, -0.6], [0.4, -70.3]] {
            let size = if d0[0] < -1.0 { [80, 1] } else { [1, 80] };
            let name = |table: &str| std::format!("{table} {f}");
            let check = assert_footprint_matches_single_lookups;
            check(
                &name("phase"),
                &|d, n, o| phase.footprint(d, n, o).unwrap(),
                &|x, y| phase.weight(x, y),
                d0,
                size,
                scale,
            );
            check(
                &name("linear"),
                &|d, n, o| linear.footprint(d, n, o).unwrap(),
                &|x, y| linear.weight(x, y),
                d0,
                size,
                scale,
            );
            check(
                &name("nearest"),
                &|d, n, o| nearest.footprint(d, n, o).unwrap(),
                &|x, y| nearest.weight(x, y),
                d0,
                size,
                scale,
            );
        }
    }
}

/// Footprints of more than 2²² rows or columns are refused (the limit of the exact shift).
#[test]
fn phase_footprints_wider_than_2_pow_22_are_refused() {
    let t = PhaseTable::new(&Mitchell::default()).unwrap();
    let mut out = std::vec![0.0f32; (1 << 22) + 1];
    let refused = Err(Error::TooMany {
        what: "footprint side",
        value: (1 << 22) + 1,
        max: 1 << 22,
    });
    assert_eq!(t.footprint([0.0, 0.0], 1, &mut out), refused);
    assert_eq!(t.footprint([0.0, 0.0], (1 << 22) + 1, &mut out), refused);
    assert_eq!(t.footprint([0.0, 0.0], 1, &mut out[..1 << 22]), Ok(()));
}

/// `row4` is the first four lanes of `row`, bit for bit, for every built-in filter, both axes,
/// stored and in-between phases and phases out of range (clamped as `row` clamps them).
#[test]
fn phase_row4_is_the_first_four_lanes_of_row() {
    let mut rng = default_rng(43);
    for (f, _) in cases() {
        if f.radius()[0] >= 8.0 || f.radius()[1] >= 8.0 {
            continue;
        }
        let t = PhaseTable::new(&f).unwrap();
        for axis in [Axis::X, Axis::Y] {
            let phases = (0..=PHASES)
                .map(|j| j as f32 / PHASES as f32)
                .chain((0..64).map(|_| uniform_f32(&mut rng)))
                .chain([-0.5, 1.5, f32::NAN]);
            for phase in phases {
                // `row` writes whole 4-lane groups (taps, then 0), so its first four lanes are
                // always written.
                let mut w = [f32::NAN; MAX_TAPS];
                t.row(axis, phase, &mut w);
                let want = [w[0], w[1], w[2], w[3]].map(f32::to_bits);
                assert_eq!(
                    t.row4(axis, phase).map(f32::to_bits),
                    want,
                    "{f} {axis:?} {phase}"
                );
            }
        }
    }
}

/// A constant axis answers its 1D factor without a lookup: exactly the box's height inside the
/// radius and exactly 0 past it (and for NaN), on each axis of a box with unequal radii.
#[test]
fn phase_weight_1d_of_a_box_is_its_height_inside_and_0_past_the_radius() {
    let b = Boxcar::new([0.7, 1.5]).unwrap();
    let t = PhaseTable::new(&b).unwrap();
    for (axis, r) in [(Axis::X, 0.7f32), (Axis::Y, 1.5)] {
        for k in -100..=100 {
            let d = k as f32 / 100.0 * r;
            assert_eq!(t.weight_1d(axis, d), 1.0, "{axis:?} d = {d}");
        }
        for d in [
            r.next_up(),
            -r.next_up(),
            2.0 * r,
            100.0,
            f32::INFINITY,
            f32::NAN,
        ] {
            assert_eq!(t.weight_1d(axis, d), 0.0, "{axis:?} d = {d}");
        }
    }
}

#[test]
fn phase_tables_keep_a_box_exact_up_to_its_edge() {
    // A radius whose edge is off the 1/64 grid: rows interpolate towards f(r) = 1, never
    // towards 0, so every offset inside the support weighs exactly 1.
    for r in [0.5f32, 0.7, 1.3, 2.0, 3.01] {
        let b = Boxcar::new([r, r]).unwrap();
        let t = PhaseTable::new(&b).unwrap();
        assert_eq!(t.constant(), Some(1.0), "r = {r}");
        for k in -1000..=1000 {
            let d = k as f32 / 1000.0 * r;
            assert_eq!(t.weight(d, -d), 1.0, "r = {r}, d = {d}");
        }
        assert_eq!(t.weight(r.next_up(), 0.0), 0.0);
    }
    let g = PhaseTable::new(&Gaussian::default()).unwrap();
    assert_eq!(g.constant(), None);
}

proptest! {
    #[test]
    fn phase_footprint_weights_match_single_lookups(
        f in filter_with(phase_radius()),
        d0 in [-12.0f32..4.0, -12.0f32..4.0],
        nx in 1usize..12,
        ny in 1usize..12,
    ) {
        let t = PhaseTable::new(&f).unwrap();
        let mut out = std::vec![f32::NAN; nx * ny];
        t.footprint(d0, nx, &mut out).unwrap();
        // The largest factor magnitude per axis (the table's values, scanned finely).
        let max_abs = |axis: Axis, r: f32| {
            (0..=1024)
                .map(|k| t.weight_1d(axis, r * (k as f32 / 512.0 - 1.0)).abs())
                .fold(0.0f32, f32::max)
        };
        let [rx, ry] = f.radius();
        let (mx, my) = (max_abs(Axis::X, rx), max_abs(Axis::Y, ry));
        for j in 0..ny {
            for i in 0..nx {
                let (dx, dy) = (d0[0] + i as f32, d0[1] + j as f32);
                let (got, want) = (out[j * nx + i], t.weight(dx, dy));
                // Equal up to the rounding of d0 + i against (d0 + r) + i: a few ulps of an
                // offset below 32 (≤ 2e-5) times the slope of a factor (≤ 64 cells × 2·max per
                // cell), times the other factor; plus the product's own rounding.
                let tol = 64.0 * 2.0 * 2e-5 * (mx * my) + 4.0 * f32::EPSILON * want.abs();
                prop_assert!(
                    (got - want).abs() <= tol,
                    "({i},{j}) at {dx},{dy}: footprint {got} single {want}"
                );
                if dx.abs() > f.radius()[0] || dy.abs() > f.radius()[1] {
                    prop_assert_eq!(got, 0.0);
                }
            }
        }
    }

    #[test]
    fn phase_lookups_are_total_and_zero_past_the_radius(
        f in filter_with(phase_radius()),
        x in any_f32(),
        y in any_f32(),
        phase in any_f32(),
    ) {
        let t = PhaseTable::new(&f).unwrap();
        let w = t.weight(x, y);
        prop_assert!(w.is_finite());
        if !(x.abs() <= f.radius()[0] && y.abs() <= f.radius()[1]) {
            prop_assert_eq!(w, 0.0);
        }
        let mut row = [0.0f32; MAX_TAPS];
        t.row(Axis::X, phase, &mut row);
        prop_assert!(row.iter().all(|v| v.is_finite()));
        // Out-of-range phases read as the nearest end (NaN as 0).
        let clamped = if phase.is_nan() { 0.0 } else { phase.clamp(0.0, 1.0) };
        let mut want = [0.0f32; MAX_TAPS];
        t.row(Axis::X, clamped, &mut want);
        prop_assert_eq!(row, want);
    }
}

/// A plugin box of height 0.3 per axis and radii (0.7, 1.5): every table recognises the
/// constant axes; a one-weight footprint answers `0.3 · 0.3` exactly (a linear lookup
/// `(1 − t)·0.3 + t·0.3` need not, and on this grid does not everywhere), 0 past the radius;
/// single lookups are within an ulp of it (exact for the phase table and nearest lookups); a
/// many-weight phase footprint agrees with `weight`.
#[test]
fn constant_plugin_filters_answer_their_constant() {
    struct Flat;
    impl Filter for Flat {
        fn radius(&self) -> [f32; 2] {
            [0.7, 1.5]
        }
        fn eval(&self, x: f32, y: f32) -> f32 {
            self.eval_1d(Axis::X, x).unwrap() * self.eval_1d(Axis::Y, y).unwrap()
        }
        fn eval_1d(&self, axis: Axis, x: f32) -> Option<f32> {
            Some(if x.abs() <= self.radius()[axis.index()] {
                0.3
            } else {
                0.0
            })
        }
    }
    let want = 0.3f32 * 0.3;
    let linear: FilterTable = FilterTable::new(&Flat, Interpolation::Linear).unwrap();
    let nearest: FilterTable = FilterTable::new(&Flat, Interpolation::Nearest).unwrap();
    let phase = PhaseTable::new(&Flat).unwrap();
    assert_eq!(phase.constant(), Some(want));
    type Footprint<'a> = &'a dyn Fn([f32; 2], &mut [f32]);
    let footprints: [(&str, Footprint, f32); 4] = [
        ("linear", &|d, o| linear.footprint(d, 1, o).unwrap(), 1e-7),
        ("nearest", &|d, o| nearest.footprint(d, 1, o).unwrap(), 0.0),
        (
            "view",
            &|d, o| linear.view().footprint(d, 1, o).unwrap(),
            1e-7,
        ),
        ("phase", &|d, o| phase.footprint(d, 1, o).unwrap(), 0.0),
    ];
    for (name, footprint, lookup_error) in footprints {
        let mut one = [0.0f32; 1];
        for k in 0..=4000 {
            let d = [
                -0.7 + 1.4 * k as f32 / 4000.0,
                1.5 - 3.0 * k as f32 / 4000.0,
            ];
            footprint(d, &mut one);
            assert_eq!(one[0], want, "{name} footprint at {d:?}");
            let w = match name {
                "phase" => phase.weight(d[0], d[1]),
                "nearest" => nearest.weight(d[0], d[1]),
                _ => linear.weight(d[0], d[1]),
            };
            assert!(
                (w - want).abs() <= lookup_error,
                "{name} weight at {d:?}: {w}"
            );
        }
        for d in [
            [0.71, 0.0],
            [0.0, -1.51],
            [f32::NAN, 0.0],
            [0.0, f32::INFINITY],
        ] {
            footprint(d, &mut one);
            assert_eq!(one[0], 0.0, "{name} footprint at {d:?}");
        }
    }
    let mut many = [0.0f32; 6];
    for d0 in [[-0.3f32, -1.2], [0.25, 0.6], [-0.69, -1.49]] {
        phase.footprint(d0, 2, &mut many).unwrap();
        for (i, &w) in many.iter().enumerate() {
            let (dx, dy) = (d0[0] + (i % 2) as f32, d0[1] + (i / 2) as f32);
            assert_eq!(w, phase.weight(dx, dy), "phase footprint {d0:?} entry {i}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// One interface over every table: `Weights`, and the film's table.

/// Every answer of `w` equals `table`'s own, bit for bit, at offsets inside, on and past the
/// radius and at NaN: weight, weight_1d, is_separable, radius, integral and a footprint.
fn assert_same_weights(w: &dyn Weights, table: &dyn Weights, what: &str) {
    assert_eq!(w.radius(), table.radius(), "{what}");
    assert_eq!(w.integral().to_bits(), table.integral().to_bits(), "{what}");
    assert_eq!(w.is_separable(), table.is_separable(), "{what}");
    let r = table.radius();
    for (x, y) in [
        (0.0, 0.0),
        (0.3, -0.7),
        (r[0], -r[1]),
        (r[0].next_up(), 0.1),
        (-1.9, 2.6),
        (f32::NAN, 0.5),
    ] {
        assert_eq!(
            w.weight(x, y).to_bits(),
            table.weight(x, y).to_bits(),
            "{what} ({x}, {y})"
        );
        for (axis, d) in [(Axis::X, x), (Axis::Y, y)] {
            assert_eq!(
                w.weight_1d(axis, d).map(f32::to_bits),
                table.weight_1d(axis, d).map(f32::to_bits),
                "{what} {axis:?} {d}"
            );
        }
    }
    let (mut a, mut b) = ([f32::NAN; 12], [f32::NAN; 12]);
    w.footprint([-1.3, -0.8], 4, &mut a).unwrap();
    table.footprint([-1.3, -0.8], 4, &mut b).unwrap();
    assert_eq!(a.map(f32::to_bits), b.map(f32::to_bits), "{what}");
    assert!(w.footprint([0.0, 0.0], 5, &mut a).is_err(), "{what}");
}

/// `FilmTable` holds a phase table exactly when one holds the filter (separable, radii below
/// 8) and a linear 64-entry table otherwise, and answers through `Weights` what that table
/// answers; through `&FilmTable` and `&dyn Weights` as well.
#[test]
fn film_tables_pick_their_table_and_answer_as_it_does() {
    let wide = Gaussian::new([9.0, 2.0], 2.0).unwrap();
    let filters: [(&dyn Filter, bool); 5] = [
        (&Mitchell::default(), true),
        (&Lanczos::default(), true),
        (&Boxcar::new([0.3, 1.5]).unwrap(), true),
        (&wide, false),
        (&Cone, false),
    ];
    for (f, phase) in filters {
        let film = FilmTable::<64>::new(f).unwrap();
        match &film {
            FilmTable::Phase(t) => {
                assert!(phase, "{:?}", f.radius());
                assert_eq!(*t, PhaseTable::new(f).unwrap());
                assert_same_weights(&film, t, "phase");
            }
            FilmTable::Table(t) => {
                assert!(!phase, "{:?}", f.radius());
                assert_eq!(
                    *t,
                    FilterTable::<64>::new(f, Interpolation::Linear).unwrap()
                );
                assert_eq!(t.interpolation(), Interpolation::Linear);
                assert_same_weights(&film, t, "table");
            }
        }
        assert_same_weights(&&film, &film, "by reference");
    }
    struct NoRadius;
    impl Filter for NoRadius {
        fn radius(&self) -> [f32; 2] {
            [f32::NAN, 1.0]
        }
        fn eval(&self, _: f32, _: f32) -> f32 {
            0.0
        }
    }
    assert!(FilmTable::<64>::new(&NoRadius).is_err());
}

/// Every table form answers through `Weights` what its own methods answer, and the forms
/// agree with one another: a `SeparableTable`, the `FilterTable` made from it, their views; a
/// `Table2d` and its `FilterTable`.
#[test]
fn every_table_form_answers_the_same_through_weights() {
    for interp in [Interpolation::Nearest, Interpolation::Linear] {
        let m = Mitchell::new([2.0, 1.5], 0.3, 0.35).unwrap();
        let sep = SeparableTable::<16>::new(&m, interp).unwrap();
        let either = FilterTable::from(sep);
        assert_eq!(either, FilterTable::<16>::new(&m, interp).unwrap());
        assert_same_weights(&either, &sep, "FilterTable from SeparableTable");
        assert_same_weights(&sep.view(), &sep, "view of SeparableTable");
        assert_same_weights(&either.view(), &sep, "view of FilterTable");
        for (x, y) in [(0.3, -0.7), (1.2, 1.4)] {
            assert_eq!(
                Some(sep.weight_1d(Axis::X, x)),
                either.weight_1d(Axis::X, x)
            );
            assert_eq!(
                either.weight_1d(Axis::Y, y),
                sep.view().weight_1d(Axis::Y, y)
            );
        }
        let full = Table2d::<16>::new(&Cone, interp).unwrap();
        let either = FilterTable::from(full);
        assert_eq!(either, FilterTable::<16>::new(&Cone, interp).unwrap());
        assert_same_weights(&either, &full, "FilterTable from Table2d");
        assert_same_weights(&full.view(), &full, "view of Table2d");
        assert_eq!(Weights::weight_1d(&full, Axis::X, 0.0), None);
        assert_eq!(either.weight_1d(Axis::X, 0.0), None);
        assert_eq!((full.len(), full.view().len()), (16, 16));
    }
}

/// The trait's provided methods: a source that gives only a weight is not separable and fills
/// footprints weight by weight, with the footprint's length checks; one that gives per-axis
/// factors is separable.
#[test]
fn weights_provided_methods_fill_footprints_weight_by_weight() {
    struct Ramp;
    impl Weights for Ramp {
        fn radius(&self) -> [f32; 2] {
            [4.0, 4.0]
        }
        fn integral(&self) -> f32 {
            0.0
        }
        fn weight(&self, dx: f32, dy: f32) -> f32 {
            dx + 10.0 * dy
        }
    }
    assert!(!Ramp.is_separable());
    assert_eq!(Ramp.weight_1d(Axis::Y, 1.0), None);
    let mut out = [0.0f32; 6];
    Ramp.footprint([0.5, -1.0], 3, &mut out).unwrap();
    assert_eq!(out, [-9.5, -8.5, -7.5, 0.5, 1.5, 2.5]);
    let mut one = [0.0f32; 1];
    Ramp.footprint([0.25, 2.0], 1, &mut one).unwrap();
    assert_eq!(one, [20.25]);
    assert!(Ramp.footprint([0.0, 0.0], 4, &mut out).is_err());
    assert!(Ramp.footprint([0.0, 0.0], 0, &mut out).is_err());
    assert!(Ramp.footprint([0.0, 0.0], 2, &mut []).is_err());
    // A source that gives the per-axis factors is separable without saying so.
    struct Product;
    impl Weights for Product {
        fn radius(&self) -> [f32; 2] {
            [4.0, 4.0]
        }
        fn integral(&self) -> f32 {
            0.0
        }
        fn weight(&self, dx: f32, dy: f32) -> f32 {
            dx * dy
        }
        fn weight_1d(&self, _: Axis, d: f32) -> Option<f32> {
            Some(d)
        }
    }
    assert!(Product.is_separable());
    assert!((&Product as &dyn Weights).is_separable());
}

/// The sizes the table docs state: `8·N + 36` bytes separable, `4·N² + 36` in 2D, and a
/// `FilterTable` as large as its 2D form would be.
#[test]
fn table_sizes_are_the_documented_ones() {
    assert_eq!(size_of::<SeparableTable<16>>(), 8 * 16 + 36);
    assert_eq!(size_of::<SeparableTable<64>>(), 8 * 64 + 36);
    assert_eq!(size_of::<Table2d<16>>(), 4 * 16 * 16 + 36);
    assert!(size_of::<FilterTable<16>>() >= size_of::<Table2d<16>>());
    assert!(size_of::<FilterTable<16>>() <= size_of::<Table2d<16>>() + 4);
}

/// `with_sigma` accepts exactly the `f32` σ whose `α = 1/(2σ²)` is a finite, normal `f32`, and
/// its error carries σ and those bounds.
#[test]
fn sigma_bounds_are_those_of_a_normal_alpha() {
    use gaussian::{MAX_SIGMA, MIN_SIGMA};
    let alpha_ok = |s: f32| {
        let a = 1.0 / (2.0 * f64::from(s) * f64::from(s));
        s > 0.0 && a >= f64::from(f32::MIN_POSITIVE) && a <= f64::from(f32::MAX)
    };
    let step = |s: f32, by: i32| f32::from_bits(s.to_bits().wrapping_add_signed(by));
    // At the ends σ passes its own check; the Gaussian is then refused for its negligible
    // integral, a later check.
    for s in [MIN_SIGMA, MAX_SIGMA] {
        assert!(alpha_ok(s), "{s:e}");
        assert!(
            matches!(
                Gaussian::with_sigma([1.5, 1.5], s),
                Err(Error::OutOfRange {
                    what: "filter integral",
                    ..
                })
            ),
            "{s:e}"
        );
    }
    let range = Interval::closed(f64::from(MIN_SIGMA), f64::from(MAX_SIGMA));
    for s in [step(MIN_SIGMA, -1), step(MAX_SIGMA, 1), 1e-30, 1e30, -1.0] {
        assert!(!alpha_ok(s), "{s:e}");
        assert_eq!(
            Gaussian::with_sigma([1.5, 1.5], s),
            Err(Error::OutOfRange {
                what: "sigma",
                value: f64::from(s),
                range
            })
        );
    }
    assert_eq!(
        Gaussian::with_sigma([1.5, 1.5], 1e19)
            .unwrap_err()
            .to_string(),
        "sigma 1e19 is outside [3.8332338e-20, 6.521909e18]"
    );
}
