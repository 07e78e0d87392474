//! `nyquist::bluenoise` and `nyquist::lattice`: void-and-cluster masks, Poisson-disk sets,
//! lattices and Kronecker sequences.

use nyquist::Error;
use nyquist::analysis::Topology;
use nyquist::bluenoise::{PoissonDisk, VoidAndCluster};
use nyquist::lattice::{FibonacciLattice, KOROBOV_TABLE, Korobov, Kronecker};
use nyquist::sequence::Sequence;

use crate::{Bytes, in_unit, in_unit_f64};

/// Masks up to 24 × 24: the fast and the straightforward method give the same ranks, a
/// permutation; Poisson-disk sets with radius in [0.05, 1]: every pair at least r apart, every
/// point in [0, 1)²; lattices and R_d: every value in [0, 1), constructors refuse only what
/// their docs name; `Korobov::tabled` builds exactly the rows of `KOROBOV_TABLE`, and
/// `Korobov::searched_2d` returns a valid multiplier, the exhaustive search's for n ≤ 64.
pub fn bluenoise(data: &[u8]) {
    let mut b = Bytes::new(data);
    let (w, h, seed) = (b.below(24), b.below(24), b.u64());
    match VoidAndCluster::new(w, h, seed) {
        Ok(vc) => {
            let n = vc.pixels();
            let (el, sl) = vc.scratch_len();
            let (mut fast, mut slow) = (vec![0u32; n], vec![0u32; n]);
            vc.generate(&mut fast, &mut vec![0.0; el], &mut vec![0; sl])
                .expect("buffers of scratch_len");
            vc.generate_straightforward(&mut slow, &mut vec![0.0; n], &mut vec![0; n])
                .expect("buffers of N");
            assert_eq!(
                fast, slow,
                "{w}x{h} seed {seed}: fast and straightforward differ"
            );
            let mut sorted = fast.clone();
            sorted.sort_unstable();
            assert!(
                sorted.iter().copied().eq(0..n as u32),
                "{w}x{h}: not a permutation"
            );
        }
        Err(e) => assert!(
            (w == 0 || h == 0) && matches!(e, Error::ZeroSize { .. }),
            "{w}x{h}: {e:?}"
        ),
    }

    let r = 0.05 + 0.95 * f64::from(b.u16()) / 65535.0;
    let torus = b.bool();
    let topology = if torus {
        Topology::Torus
    } else {
        Topology::Square
    };
    let pd = PoissonDisk::new(r, topology, b.u64()).expect("radius in range");
    let pd = if b.bool() { pd.maximal() } else { pd };
    let (g, a) = pd.scratch_len();
    let mut pts = vec![0.0; 2 * g];
    let count = pd
        .generate(&mut pts, &mut vec![0; g], &mut vec![0; a])
        .expect("buffers of scratch_len");
    assert!(count >= 1);
    for i in 0..count {
        assert!(in_unit_f64(pts[2 * i]) && in_unit_f64(pts[2 * i + 1]));
        for j in 0..i {
            let mut d2 = 0.0;
            for k in 0..2 {
                let mut d = (pts[2 * i + k] - pts[2 * j + k]).abs();
                if torus {
                    d = d.min(1.0 - d);
                }
                d2 += d * d;
            }
            assert!(
                d2 >= r * r,
                "r {r} {topology:?}: points {i}, {j} at {}",
                d2.sqrt()
            );
        }
    }

    let (index, dim) = (b.u64(), b.u32());
    let m = b.below(100);
    match FibonacciLattice::new(m) {
        Ok(f) => {
            let f = if b.bool() { f.rotated(b.u64()) } else { f };
            assert!(in_unit(f.sample(index, dim)) && in_unit_f64(f.sample_f64(index, dim)));
        }
        Err(e) => assert!(
            !(3..=93).contains(&m)
                && e == Error::NotInRange {
                    what: "m",
                    value: u64::from(m),
                    min: 3,
                    max: 93
                }
        ),
    }
    let (n, mult, dims) = (b.u64(), b.u64(), b.below(1100));
    if let Ok(k) = Korobov::new(n, mult, dims) {
        assert!(in_unit(k.sample(index, dim)) && in_unit_f64(k.sample_f64(index, dim)));
    }
    match Kronecker::new(dims) {
        Ok(k) => {
            let k = if b.bool() { k.rotated(b.u64()) } else { k };
            assert!(in_unit(k.sample(index, dim)) && in_unit_f64(k.sample_f64(index, dim)));
        }
        Err(_) => assert!(dims == 0 || dims > 1024),
    }
    // Stroud's table: a lattice exactly for its (n, dims) rows, with the row's first multiplier.
    let (tn, tdims) = (u64::from(b.below(10100)), b.below(8));
    let row = KOROBOV_TABLE.iter().find(|r| r.n == tn && r.dims == tdims);
    match (Korobov::tabled(tn, tdims), row) {
        (Ok(k), Some(r)) => assert_eq!(k.multiplier(), r.multipliers[0]),
        (Err(_), None) => {}
        (got, row) => panic!("tabled({tn}, {tdims}) = {got:?} for row {row:?}"),
    }
    // The two-dimensional search: a multiplier coprime to n in 1 ..= max(1, n/2), the
    // exhaustive search's for small n.
    let sn = u64::from(b.below(3000));
    match Korobov::searched_2d(sn) {
        Ok(k) => {
            let a = k.multiplier();
            assert!(
                sn == 1 || (a >= 1 && a <= (sn / 2).max(1) && gcd(a, sn) == 1),
                "{sn}: {a}"
            );
            if sn <= 64 {
                assert_eq!(Some(k), Korobov::searched(sn, 2).ok(), "{sn}");
            }
            assert!(in_unit(k.sample(index, 1)));
        }
        Err(e) => assert_eq!((sn, e), (0, nyquist::Error::ZeroSize { what: "n" })),
    }
}

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 { a } else { gcd(b, a % b) }
}
