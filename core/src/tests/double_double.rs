//! Double-double arithmetic (an unevaluated sum hi + lo of two f64, about 106 bits): reference
//! values for the f64 pixel statistics (`pixel_stats`, the film), exact enough that their distance
//! is their error.
//! Knuth's TwoSum and the FMA-based TwoProduct (Dekker 1971, "A floating-point technique for
//! extending the available precision"; Hida, Li and Bailey's QD library for the operations).

/// `hi + lo` with `|lo| ≤ ulp(hi)/2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dd {
    pub hi: f64,
    pub lo: f64,
}

fn two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    let v = s - a;
    Dd {
        hi: s,
        lo: (a - (s - v)) + (b - v),
    }
}

fn quick_two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    Dd {
        hi: s,
        lo: b - (s - a),
    }
}

fn two_prod(a: f64, b: f64) -> Dd {
    let p = a * b;
    Dd {
        hi: p,
        lo: a.mul_add(b, -p),
    }
}

impl Dd {
    pub fn from(v: f64) -> Dd {
        Dd { hi: v, lo: 0.0 }
    }

    pub fn add(self, o: Dd) -> Dd {
        let s = two_sum(self.hi, o.hi);
        let t = two_sum(self.lo, o.lo);
        let s = quick_two_sum(s.hi, s.lo + t.hi);
        quick_two_sum(s.hi, s.lo + t.lo)
    }

    pub fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    pub fn sub(self, o: Dd) -> Dd {
        self.add(o.neg())
    }

    pub fn mul(self, o: Dd) -> Dd {
        let p = two_prod(self.hi, o.hi);
        quick_two_sum(p.hi, p.lo + (self.hi * o.lo + self.lo * o.hi))
    }

    pub fn div(self, o: Dd) -> Dd {
        let q1 = self.hi / o.hi;
        let r = self.sub(o.mul(Dd::from(q1)));
        let q2 = r.hi / o.hi;
        let r = r.sub(o.mul(Dd::from(q2)));
        let q3 = r.hi / o.hi;
        quick_two_sum(q1, q2).add(Dd::from(q3))
    }

    /// The nearest f64.
    pub fn round(self) -> f64 {
        self.hi + self.lo
    }
}

/// The distance from `got` to `want` in units of the last place of `want`.
pub fn ulps(got: f64, want: f64) -> f64 {
    let ulp = f64::from_bits(want.abs().to_bits() + 1) - want.abs();
    (got - want).abs() / ulp
}

/// The variance of the weighted mean of `(f, x)` pairs, Σ f²(x − I)² / ((Σ f)² − Σ f²) with
/// I = Σ f·x / Σ f, by two passes in double-double.
pub fn variance_of_mean(samples: &[(f64, f64)]) -> f64 {
    let zero = Dd::from(0.0);
    let (mut w1, mut w2, mut sx) = (zero, zero, zero);
    for &(f, x) in samples {
        let f = Dd::from(f);
        w1 = w1.add(f);
        w2 = w2.add(f.mul(f));
        sx = sx.add(f.mul(Dd::from(x)));
    }
    let mean = sx.div(w1);
    let mut q = zero;
    for &(f, x) in samples {
        let d = Dd::from(f).mul(Dd::from(x).sub(mean));
        q = q.add(d.mul(d));
    }
    q.div(w1.mul(w1).sub(w2)).round()
}

#[test]
fn double_double_keeps_what_f64_loses() {
    // (1 + 2⁻⁶⁰) − 1 is 0 in f64 and 2⁻⁶⁰ here; 1/3·3 is 1 to 2⁻¹⁰⁵.
    let tiny = 2f64.powi(-60);
    assert_eq!(
        Dd::from(1.0).add(Dd::from(tiny)).sub(Dd::from(1.0)).round(),
        tiny
    );
    let third = Dd::from(1.0).div(Dd::from(3.0));
    let one = third.mul(Dd::from(3.0)).sub(Dd::from(1.0));
    assert!(one.round().abs() < 2f64.powi(-104), "{one:?}");
    assert_eq!(ulps(1.0 + f64::EPSILON, 1.0), 1.0);
    // Equal weights: s²/n; 1, 2, 3, 4 give 5/12.
    let v = variance_of_mean(&[(0.5, 1.0), (0.5, 2.0), (0.5, 3.0), (0.5, 4.0)]);
    assert!(ulps(v, 5.0 / 12.0) <= 0.5, "{v}");
}
