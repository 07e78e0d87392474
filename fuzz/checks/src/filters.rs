//! `nyquist::filter`: spec parsing, constructors with any `f32` parameters, evaluation at any
//! offset, tables (build, lookup, footprint) and the importance sampler.

use nyquist::Error;
use nyquist::filter::{
    Axis, BlackmanHarris, Boxcar, Filter, FilterKind, FilterSampler, FilterTable, Gaussian,
    Interpolation, Lanczos, MAX_RADIUS, MAX_TAPS, Mitchell, PhaseTable, SeparableTable, Table2d,
    Triangle, sinc,
};

use crate::{Bytes, error_numbers_hold};

/// Filters: `FilterKind::parse` never panics on any string and what it accepts prints back to
/// itself; constructors return a filter or a typed error for any `f32`s (NaN, ∞ included); every
/// filter's radius is finite, in `(0, MAX_RADIUS]`; `eval` is finite everywhere, exactly 0 past
/// the radius and for NaN/∞ offsets; separable filters factor exactly; the integral is finite;
/// tables are finite, 0 past the radius, and `footprint` equals per-weight lookups; the
/// importance sampler draws offsets inside the support with finite weights and positive pdf.
pub fn filters(data: &[u8]) {
    let mut b = Bytes::new(data);
    let op = b.u8() % 9;
    let offsets: Vec<[f32; 2]> = (0..4).map(|_| [b.f32_mixed(), b.f32_mixed()]).collect();
    let interp = if b.bool() {
        Interpolation::Linear
    } else {
        Interpolation::Nearest
    };
    let foot = Footprint {
        d0: [b.f32_mixed(), b.f32_mixed()],
        nx: b.below(6) as usize,
        len: b.below(40) as usize,
    };
    let us: Vec<[f32; 2]> = (0..3).map(|_| [b.f32_mixed(), b.f32_mixed()]).collect();
    let params = [b.f32_mixed(), b.f32_mixed(), b.f32_mixed(), b.f32_mixed()];
    assert!(
        sinc(params[0]).is_finite(),
        "sinc({}) is not finite",
        params[0]
    );
    let ctx = Ctx {
        offsets,
        interp,
        foot,
        us,
    };
    let r = [params[0], params[1]];
    match op {
        0 => {
            let text = String::from_utf8_lossy(b.rest()).into_owned();
            match FilterKind::parse(&text) {
                Ok(kind) => {
                    let printed = kind.to_string();
                    let back = FilterKind::parse(&printed);
                    assert_eq!(
                        back,
                        Ok(kind),
                        "{text:?} parsed to {kind:?}, printed as {printed:?}"
                    );
                    assert!(!kind.name().is_empty());
                    check_filter(kind.name(), kind.as_dyn(), &ctx);
                }
                Err(e) => {
                    let _ = e.to_string();
                }
            }
        }
        1 => built("Boxcar", Boxcar::new(r), &ctx),
        2 => built("Triangle", Triangle::new(r), &ctx),
        3 => built("Gaussian", Gaussian::new(r, params[2]), &ctx),
        4 => built(
            "Gaussian::with_sigma",
            Gaussian::with_sigma(r, params[2]),
            &ctx,
        ),
        5 => built("Mitchell", Mitchell::new(r, params[2], params[3]), &ctx),
        6 => built("Lanczos", Lanczos::new(r, params[2]), &ctx),
        7 => built("BlackmanHarris", BlackmanHarris::new(r), &ctx),
        _ => {
            // A plugin filter with arbitrary (even non-finite) values: tables and the sampler
            // must still be built or refused with a typed error, and stay finite.
            let fix = |v: f32| {
                if v.is_finite() && v > MAX_RADIUS {
                    MAX_RADIUS
                } else {
                    v
                }
            };
            let plugin = Plugin {
                radius: [fix(r[0]), fix(r[1])],
                value: if params[2].is_finite() {
                    params[2].clamp(-1e6, 1e6)
                } else {
                    1.0
                },
                separable: params[3].is_sign_negative(),
            };
            check_tables("plugin", &plugin, &ctx);
        }
    }
}

struct Footprint {
    d0: [f32; 2],
    nx: usize,
    len: usize,
}

struct Ctx {
    offsets: Vec<[f32; 2]>,
    interp: Interpolation,
    foot: Footprint,
    us: Vec<[f32; 2]>,
}

#[derive(Debug)]
struct Plugin {
    radius: [f32; 2],
    value: f32,
    separable: bool,
}

/// A user filter that keeps the `Filter` contract (finite, 0 past the radius and for NaN/∞,
/// exactly separable when it says so) with arbitrary radius and scale, possibly negative.
impl Filter for Plugin {
    fn radius(&self) -> [f32; 2] {
        self.radius
    }
    fn eval(&self, x: f32, y: f32) -> f32 {
        if self.separable {
            return self.axis(0, x) * self.axis(1, y);
        }
        if outside(self.radius, x, y) {
            return 0.0;
        }
        let v = self.value * (1.0 + x / self.radius[0] * 0.25 - y / self.radius[1]);
        if v.is_finite() { v } else { 0.0 }
    }
    fn eval_1d(&self, axis: Axis, x: f32) -> Option<f32> {
        self.separable.then(|| self.axis(axis.index(), x))
    }
}

impl Plugin {
    fn axis(&self, k: usize, t: f32) -> f32 {
        if !(t.abs() <= self.radius[k]) {
            return 0.0;
        }
        let u = t / self.radius[k];
        let v = self.value.abs().sqrt()
            * (1.0 - u * u)
            * if k == 0 { self.value.signum() } else { 1.0 };
        if v.is_finite() { v } else { 0.0 }
    }
}

fn built<F: Filter + core::fmt::Debug>(name: &str, r: Result<F, Error>, ctx: &Ctx) {
    match r {
        Ok(f) => check_filter(name, &f, ctx),
        Err(e) => assert!(
            matches!(e, Error::OutOfRange { .. } | Error::NonFinite { .. })
                && error_numbers_hold(&e),
            "{name}: unexpected error {e:?}"
        ),
    }
}

fn outside(f: [f32; 2], x: f32, y: f32) -> bool {
    !(x.abs() <= f[0]) || !(y.abs() <= f[1])
}

fn check_filter(name: &str, f: &dyn Filter, ctx: &Ctx) {
    let r = f.radius();
    assert!(
        r.iter()
            .all(|&v| v.is_finite() && v > 0.0 && v <= MAX_RADIUS),
        "{name}: radius {r:?}"
    );
    let integral = f.integral();
    assert!(integral.is_finite(), "{name}: integral {integral}");
    let separable = f.is_separable();
    let mut points = ctx.offsets.clone();
    points.extend([[0.0, 0.0], [r[0], r[1]], [-r[0], r[1] * 0.5]]);
    for &[x, y] in &points {
        let v = f.eval(x, y);
        assert!(v.is_finite(), "{name}: eval({x}, {y}) = {v}");
        if outside(r, x, y) {
            assert_eq!(v, 0.0, "{name}: eval({x}, {y}) = {v} past radius {r:?}");
        }
        if separable {
            let ex = f
                .eval_1d(Axis::X, x)
                .expect("separable filters answer eval_1d everywhere");
            let ey = f
                .eval_1d(Axis::Y, y)
                .expect("separable filters answer eval_1d everywhere");
            assert!(
                ex.is_finite() && ey.is_finite(),
                "{name}: eval_1d({x}) = {ex}, ({y}) = {ey}"
            );
            assert_eq!(v, ex * ey, "{name}: eval({x}, {y}) = {v} ≠ {ex}·{ey}");
        } else {
            assert_eq!(
                f.eval_1d(Axis::X, x),
                None,
                "{name}: eval_1d answers for a non-separable filter"
            );
        }
    }
    check_tables(name, f, ctx);
}

/// Whether a table accepts the filter's integral: finite and at least `MIN_INTEGRAL`.
fn integral_ok(f: &dyn Filter) -> bool {
    let i = f.integral();
    i.is_finite() && i >= nyquist::filter::MIN_INTEGRAL
}

/// The tables' refusal of a negligible, negative or undefined integral.
fn is_integral_error(e: &Error) -> bool {
    matches!(
        e,
        Error::OutOfRange {
            what: "filter integral",
            ..
        } | Error::NonFinite {
            what: "filter integral"
        }
    )
}

fn check_tables(name: &str, f: &dyn Filter, ctx: &Ctx) {
    let r = f.radius();
    let radius_valid = r.iter().all(|&v| v.is_finite() && v > 0.0);
    // The tables refuse a negligible or undefined integral too; the sampler (over |f|) does not.
    let valid = radius_valid && integral_ok(f);
    match FilterTable::<16>::new(f, ctx.interp) {
        Ok(t) => {
            assert!(valid, "{name}: FilterTable accepted radius {r:?}");
            assert_eq!(t.radius(), r);
            assert!(
                t.integral().is_finite(),
                "{name}: table integral {}",
                t.integral()
            );
            assert_eq!(t.is_separable(), f.is_separable());
            let v = t.view();
            for &[x, y] in &ctx.offsets {
                let w = t.weight(x, y);
                assert!(w.is_finite(), "{name}: table weight({x}, {y}) = {w}");
                if outside(r, x, y) {
                    assert_eq!(
                        w, 0.0,
                        "{name}: table weight({x}, {y}) = {w} past radius {r:?}"
                    );
                }
                assert_eq!(w.to_bits(), v.weight(x, y).to_bits(), "{name}: view weight");
                for axis in [Axis::X, Axis::Y] {
                    let a = t.weight_1d(axis, x);
                    assert_eq!(a.is_some(), t.is_separable());
                    assert_eq!(a.map(f32::to_bits), v.weight_1d(axis, x).map(f32::to_bits));
                    if let Some(a) = a {
                        assert!(a.is_finite(), "{name}: weight_1d({x}) = {a}");
                    }
                }
            }
            let Footprint { d0, nx, len } = ctx.foot;
            let mut out = vec![9.0f32; len];
            let res = t.footprint(d0, nx, &mut out);
            let ok = nx > 0 && len > 0 && len % nx == 0;
            match res {
                Ok(()) => {
                    assert!(ok, "{name}: footprint accepted nx {nx}, len {len}");
                    let mut via_view = vec![8.0f32; len];
                    v.footprint(d0, nx, &mut via_view).unwrap();
                    for (k, &w) in out.iter().enumerate() {
                        let (i, j) = ((k % nx) as f32, (k / nx) as f32);
                        let want = t.weight(d0[0] + i, d0[1] + j);
                        assert!(w.is_finite(), "{name}: footprint weight {w}");
                        assert_eq!(
                            w, want,
                            "{name}: footprint({d0:?}, {nx})[{k}] = {w}, weight gives {want}"
                        );
                        assert_eq!(w.to_bits(), via_view[k].to_bits(), "{name}: view footprint");
                    }
                }
                Err(e) => {
                    assert!(!ok, "{name}: footprint rejected nx {nx}, len {len}: {e:?}");
                    assert!(
                        matches!(e, Error::BufferLength { .. }),
                        "{name}: footprint {e:?}"
                    );
                }
            }
            // The batch lookup equals the single lookups, on the table and on its view.
            let dx: Vec<f32> = ctx.offsets.iter().chain(&ctx.us).map(|p| p[0]).collect();
            let dy: Vec<f32> = ctx.offsets.iter().chain(&ctx.us).map(|p| p[1]).collect();
            let (mut batch, mut via_view) = (vec![7.0f32; dx.len()], vec![6.0f32; dx.len()]);
            t.weights(&dx, &dy, &mut batch).unwrap();
            v.weights(&dx, &dy, &mut via_view).unwrap();
            for i in 0..dx.len() {
                let want = t.weight(dx[i], dy[i]);
                assert_eq!(batch[i].to_bits(), want.to_bits(), "{name}: weights[{i}]");
                assert_eq!(
                    via_view[i].to_bits(),
                    want.to_bits(),
                    "{name}: view weights[{i}]"
                );
            }
            assert!(matches!(
                t.weights(&dx, &dy[1..], &mut batch),
                Err(Error::BufferLength { .. })
            ));
        }
        Err(e) => {
            assert!(!valid, "{name}: FilterTable rejected radius {r:?}: {e:?}");
            assert!(
                matches!(e, Error::OutOfRange { .. }) || is_integral_error(&e),
                "{name}: {e:?}"
            );
        }
    }
    let sep = SeparableTable::<8>::new(f, ctx.interp);
    assert_eq!(
        sep.is_ok(),
        valid && f.is_separable(),
        "{name}: SeparableTable::new {sep:?}"
    );
    check_phase_table(name, f, ctx);
    let t2 = Table2d::<8>::new(f, ctx.interp);
    assert_eq!(t2.is_ok(), valid, "{name}: Table2d::new");
    if let Ok(t2) = t2 {
        for &[x, y] in &ctx.offsets {
            let w = t2.weight(x, y);
            assert!(
                w.is_finite() && (!outside(r, x, y) || w == 0.0),
                "{name}: Table2d weight({x}, {y}) = {w}"
            );
        }
        assert!(t2.values().iter().flatten().all(|v| v.is_finite()));
    }
    // The sampler also refuses a support whose 16 × 16 cells have no normal f32 area.
    let cell = |v: f32| (2.0 * f64::from(v) / 16.0) as f32;
    let sampler_valid = radius_valid && cell(r[0]) * cell(r[1]) >= f32::MIN_POSITIVE;
    match FilterSampler::<&dyn Filter, 16>::new(f) {
        Ok(s) => {
            assert!(sampler_valid, "{name}: FilterSampler accepted radius {r:?}");
            assert_eq!(s.radius(), r);
            for &u in &ctx.us {
                let fs = s.sample(u);
                let [x, y] = fs.offset;
                assert!(
                    x.is_finite() && y.is_finite() && !outside(r, x, y),
                    "{name}: sample({u:?}) offset {:?} outside radius {r:?}",
                    fs.offset
                );
                assert!(
                    fs.weight.is_finite(),
                    "{name}: sample({u:?}) weight {}",
                    fs.weight
                );
                let pdf = s.pdf(fs.offset);
                assert!(
                    pdf >= 0.0 && pdf.is_finite(),
                    "{name}: pdf({:?}) = {pdf}",
                    fs.offset
                );
                // A sample with weight has a density: the offset stays in the cell it was
                // drawn from, also when rounding put it on an edge (a fixed bug).
                assert!(
                    fs.weight == 0.0 || pdf > 0.0,
                    "{name}: sample {fs:?} has weight but pdf 0 (radius {r:?})"
                );
            }
            for &[x, y] in &ctx.offsets {
                let pdf = s.pdf([x, y]);
                assert!(
                    pdf >= 0.0 && pdf.is_finite(),
                    "{name}: pdf({x}, {y}) = {pdf}"
                );
                if outside(r, x, y) {
                    assert_eq!(pdf, 0.0, "{name}: pdf({x}, {y}) = {pdf} past radius");
                }
            }
        }
        Err(e) => {
            assert!(
                !sampler_valid,
                "{name}: FilterSampler rejected radius {r:?}: {e:?}"
            );
            assert!(matches!(e, Error::OutOfRange { .. }), "{name}: {e:?}");
        }
    }
}

/// `PhaseTable`: built exactly for valid separable filters with radii below 8 (else
/// `NotSeparable` or `OutOfRange`, whose value lies outside its range); lookups finite and 0
/// past the radius; rows clamp their phase and agree with `tap`; `footprint` is, bit for bit,
/// the masked product of the two rows at the phase of `d0 + r` (its definition, replayed through
/// the public `row`).
fn check_phase_table(name: &str, f: &dyn Filter, ctx: &Ctx) {
    let r = f.radius();
    let fits = r
        .iter()
        .all(|&v| v.is_finite() && v > 0.0 && 2.0 * f64::from(v) < MAX_TAPS as f64)
        && integral_ok(f);
    let t = match PhaseTable::new(f) {
        Ok(t) => {
            assert!(
                fits && f.is_separable(),
                "{name}: PhaseTable accepted radius {r:?}"
            );
            t
        }
        Err(e) => {
            assert!(
                !(fits && f.is_separable()),
                "{name}: PhaseTable rejected radius {r:?}: {e:?}"
            );
            // A bad radius is reported before the integral, and that before separability.
            let valid = r.iter().all(|&v| v.is_finite() && v > 0.0);
            if valid && !integral_ok(f) {
                assert!(is_integral_error(&e), "{name}: {e:?}");
            } else if valid && !f.is_separable() {
                assert_eq!(
                    e,
                    Error::NotSeparable {
                        what: "phase table"
                    },
                    "{name}"
                );
            } else {
                assert!(matches!(e, Error::OutOfRange { .. }), "{name}: {e:?}");
                assert!(error_numbers_hold(&e), "{name}: {e:?}");
            }
            return;
        }
    };
    assert_eq!(t.radius(), r);
    assert!(t.integral().is_finite());
    for &[x, y] in &ctx.offsets {
        let w = t.weight(x, y);
        assert!(w.is_finite(), "{name}: phase weight({x}, {y}) = {w}");
        if outside(r, x, y) {
            assert_eq!(w, 0.0, "{name}: phase weight({x}, {y}) = {w} past {r:?}");
        }
        for (a, axis) in [Axis::X, Axis::Y].into_iter().enumerate() {
            let taps = (2.0 * f64::from(r[a])).floor() as usize + 1;
            assert_eq!(t.taps(axis), taps);
            let mut row = [f32::NAN; MAX_TAPS];
            assert_eq!(t.row(axis, x, &mut row), taps);
            let lanes = taps.next_multiple_of(4);
            assert!(
                row[..lanes].iter().all(|v| v.is_finite()),
                "{name}: row {row:?}"
            );
            let clamped = if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
            let mut want = [f32::NAN; MAX_TAPS];
            t.row(axis, clamped, &mut want);
            for k in 0..lanes {
                assert_eq!(row[k].to_bits(), want[k].to_bits(), "{name}: row clamp");
                assert_eq!(
                    t.tap(axis, x, k).to_bits(),
                    row[k].to_bits(),
                    "{name}: tap {k}"
                );
            }
        }
    }
    if let Some(c) = t.constant() {
        assert!(c.is_finite());
    }
    let Footprint { d0, nx, len } = ctx.foot;
    let mut out = vec![9.0f32; len];
    match t.footprint(d0, nx, &mut out) {
        Ok(()) => {
            assert!(
                nx > 0 && len % nx == 0,
                "{name}: phase footprint nx {nx}, len {len}"
            );
            // Replay: taps of the row at the phase of d0 + r, shifted by ⌊d0 + r⌋ (exact up to
            // ±2²², past which the first pixel is too far for these footprints to reach the
            // support), masked to the radius.
            let factor = |axis: Axis, a: usize, i: usize| -> f32 {
                let lim = 4_194_304.0f32;
                let c = (d0[a] + r[a]).max(-lim).min(lim);
                let shift = c.floor();
                let mut row = [0.0f32; MAX_TAPS];
                t.row(axis, c - shift, &mut row);
                let k = i as i64 + shift as i64;
                let w = if (0..MAX_TAPS as i64).contains(&k) {
                    row[k as usize]
                } else {
                    0.0
                };
                let d = (k - shift as i64) as f32 + d0[a];
                if d.abs() <= r[a] { w } else { w * 0.0 }
            };
            for (k, &w) in out.iter().enumerate() {
                let (i, j) = (k % nx, k / nx);
                // A one-weight footprint is the single lookup (the same cell).
                let want = if len == 1 {
                    t.weight(d0[0], d0[1])
                } else {
                    factor(Axis::X, 0, i) * factor(Axis::Y, 1, j)
                };
                assert_eq!(
                    w.to_bits(),
                    want.to_bits(),
                    "{name}: phase footprint({d0:?}, {nx})[{k}] = {w}, replay {want}"
                );
                let (dx, dy) = (d0[0] + i as f32, d0[1] + j as f32);
                if outside(r, dx, dy) {
                    assert_eq!(w, 0.0, "{name}: phase footprint past the radius");
                }
            }
        }
        Err(e) => {
            assert!(!(nx > 0 && len > 0 && len % nx == 0), "{name}: {e:?}");
            assert!(matches!(e, Error::BufferLength { .. }), "{name}: {e:?}");
        }
    }
}
