//! `nyquist::analysis`: point-set validation, the L2 discrepancies, the exact star discrepancy
//! (1D, 2D, enumeration), its grid bounds and the minimum distance, for any point set —
//! duplicates, points on 0 and 1, and invalid coordinates included.

use nyquist::Error;
use nyquist::analysis::{
    MAX_DIMS, PointSet, Topology, centered_l2_discrepancy, l2_star_discrepancy, min_distance,
    min_distance_scratch_len, star_bounds_scratch_len, star_discrepancy, star_discrepancy_1d,
    star_discrepancy_2d, star_discrepancy_bounds, star_discrepancy_enumerate,
    star_discrepancy_scratch_len, wraparound_l2_discrepancy,
};

use crate::Bytes;

const EPS: f64 = 1e-9;

/// A coordinate: mostly valid values with many ties and boundary values, sometimes invalid.
fn coord(b: &mut Bytes<'_>, pool: &[f64]) -> f64 {
    match b.u8() {
        0..=39 => pool[b.u8() as usize % pool.len()],
        40..=59 => 0.0,
        60..=79 => 1.0,
        80..=89 => 0.5,
        90..=99 => f64::from(b.u8() % 9) / 8.0,
        100 => f64::NAN,
        101 => f64::INFINITY,
        102 => -1e-300,
        103 => 1.0 + f64::EPSILON,
        104 => f64::from_bits(b.u64()),
        105..=110 => 1.0 - f64::EPSILON / 2.0,
        111..=115 => 5e-324,
        _ => f64::from(b.u32()) / f64::from(u32::MAX),
    }
}

/// Analysis: `PointSet::new` accepts exactly the sets its docs allow and names the problem
/// otherwise; on a valid set every discrepancy is finite and in range (L2 ≥ 0, L2-star ≤ 1,
/// star in `[1/(2N), 1]`), the dedicated 1D/2D star functions agree with enumeration, the grid
/// bounds bracket the exact value within `1 − (1 − 1/m)^d`, the minimum distance equals a brute
/// force over all pairs (0 for duplicates), and short scratch buffers give `BufferTooShort`.
pub fn analysis(data: &[u8]) {
    let mut b = Bytes::new(data);
    let dims = match b.u8() % 8 {
        0 => b.below(40) as usize,
        1 | 2 => 1,
        3 | 4 => 2,
        5 => 3,
        _ => 1 + b.below(4) as usize,
    };
    let m = b.below(12);
    let torus = b.bool();
    let short = b.u8().is_multiple_of(8);
    let pool: Vec<f64> = (0..4).map(|_| f64::from(b.u16()) / 65535.0).collect();
    let mut coords = Vec::new();
    let max = if dims > 3 { 24 } else { 96 };
    while coords.len() < max * dims.max(1) && !b.rest_is_empty() {
        coords.push(coord(&mut b, &pool));
    }
    if b.bool() && !coords.is_empty() {
        coords.pop(); // a length that may not be a multiple of dims
    }
    let valid_values = coords.iter().all(|x| (0.0..=1.0).contains(x));
    let valid = dims > 0 && !coords.is_empty() && coords.len() % dims == 0 && valid_values;
    let set = match PointSet::new(&coords, dims) {
        Ok(set) => {
            assert!(
                valid,
                "PointSet::new accepted {} coords in {dims} dims: {coords:?}",
                coords.len()
            );
            set
        }
        Err(e) => {
            assert!(!valid, "PointSet::new rejected a valid set: {e:?}");
            assert!(
                matches!(
                    e,
                    Error::ZeroSize { .. }
                        | Error::BufferLength { .. }
                        | Error::NonFinite { .. }
                        | Error::OutOfRange { .. }
                        | Error::NotInRange { .. }
                ),
                "PointSet::new: {e:?}"
            );
            if coords.iter().any(|x| !x.is_finite())
                && dims > 0
                && !coords.is_empty()
                && coords.len() % dims == 0
            {
                assert!(
                    matches!(
                        e,
                        Error::NonFinite { .. }
                            | Error::OutOfRange { .. }
                            | Error::NotInRange { .. }
                    ),
                    "PointSet::new with non-finite values: {e:?}"
                );
            }
            return;
        }
    };
    let n = set.len();
    assert_eq!(n * dims, coords.len());
    assert_eq!(set.dims(), dims);
    assert!(!set.is_empty());
    assert_eq!(set.point(n + 1), set.point(1 % n));
    // The f32 route gives a valid set too.
    let narrow: Vec<f32> = coords.iter().map(|&x| x as f32).collect();
    let mut wide = vec![0.0f64; narrow.len()];
    assert!(PointSet::from_f32(&narrow, dims, &mut wide).is_ok());
    let mut too_small = vec![0.0f64; narrow.len() - 1];
    assert!(matches!(
        PointSet::from_f32(&narrow, dims, &mut too_small),
        Err(Error::BufferTooShort { .. })
    ));

    let l2 = l2_star_discrepancy(&set);
    let cl2 = centered_l2_discrepancy(&set);
    let wl2 = wraparound_l2_discrepancy(&set);
    assert!(
        l2.is_finite() && (0.0..=1.0 + EPS).contains(&l2),
        "L2-star {l2}"
    );
    assert!(cl2.is_finite() && cl2 >= 0.0, "centered L2 {cl2}");
    assert!(wl2.is_finite() && wl2 >= 0.0, "wrap-around L2 {wl2}");
    // Centered: ≤ (13/12)^(d/2) + …; a loose bound that any sane value meets.
    assert!(
        cl2 <= 2.0f64.powi(dims as i32),
        "centered L2 {cl2} in {dims} dims"
    );
    assert!(
        wl2 <= 2.0f64.powi(dims as i32),
        "wrap-around L2 {wl2} in {dims} dims"
    );
    // Order does not matter.
    let reversed: Vec<f64> = coords.chunks_exact(dims).rev().flatten().copied().collect();
    let rset = PointSet::new(&reversed, dims).unwrap();
    assert!(
        (l2_star_discrepancy(&rset) - l2).abs() <= EPS,
        "L2-star depends on order"
    );

    // Exact star discrepancy, where enumeration is cheap enough for a fuzz iteration (its
    // estimated cost d · N · ∏_{k<d−1} (distinct values on axis k + 1), as the docs define it).
    let mut cost = (dims * n) as f64;
    for k in 0..dims.saturating_sub(1) {
        let mut axis: Vec<u64> = set
            .coords()
            .iter()
            .skip(k)
            .step_by(dims)
            .map(|x| x.to_bits())
            .collect();
        axis.sort_unstable();
        axis.dedup();
        cost *= (axis.len() + 1) as f64;
    }
    if cost > 2e6 {
        return;
    }
    let need = star_discrepancy_scratch_len(n, dims).expect("scratch length");
    let mut scratch = vec![0.0f64; need];
    let exact = match star_discrepancy(&set, &mut scratch) {
        Ok(d) => {
            assert!((0.0..=1.0).contains(&d), "star discrepancy {d}");
            assert!(
                d >= 0.5 / n as f64 - EPS,
                "star discrepancy {d} < 1/(2N), N = {n}"
            );
            Some(d)
        }
        Err(e) => {
            assert!(dims >= 3, "star_discrepancy failed in {dims} dims: {e:?}");
            assert!(
                matches!(
                    e,
                    Error::TooMany { .. } | Error::OutOfRange { .. } | Error::NotInRange { .. }
                ),
                "{e:?}"
            );
            None
        }
    };
    // The 1D and 2D functions need less than the common length; enumeration needs all of it.
    if short && dims >= 3 && exact.is_some() {
        let mut s = vec![0.0f64; need - 1];
        assert!(
            matches!(
                star_discrepancy(&set, &mut s),
                Err(Error::BufferTooShort { .. })
            ),
            "star_discrepancy with short scratch"
        );
    }
    let d1 = star_discrepancy_1d(&set, &mut scratch);
    let d2 = star_discrepancy_2d(&set, &mut scratch);
    assert_eq!(
        d1.is_ok(),
        dims == 1,
        "star_discrepancy_1d in {dims} dims: {d1:?}"
    );
    assert_eq!(
        d2.is_ok(),
        dims == 2,
        "star_discrepancy_2d in {dims} dims: {d2:?}"
    );
    if dims > 2 {
        assert!(matches!(
            d1,
            Err(Error::OutOfRange { .. } | Error::NotInRange { .. })
        ));
        assert!(matches!(
            d2,
            Err(Error::OutOfRange { .. } | Error::NotInRange { .. })
        ));
    }
    let en = star_discrepancy_enumerate(&set, &mut scratch);
    match (en, exact) {
        (Ok(e), Some(x)) => assert!(
            (e - x).abs() <= EPS,
            "enumeration {e} vs star_discrepancy {x}"
        ),
        (Err(e), _) => assert!(
            matches!(
                e,
                Error::TooMany { .. } | Error::OutOfRange { .. } | Error::NotInRange { .. }
            ),
            "enumerate: {e:?}"
        ),
        (Ok(e), None) => panic!("enumeration gave {e} where star_discrepancy failed"),
    }
    if dims > MAX_DIMS {
        assert!(exact.is_none());
    }

    // Grid bounds.
    match star_bounds_scratch_len(dims, m) {
        Some(len) if len <= 1 << 20 => {
            let mut s = vec![0u32; len];
            match star_discrepancy_bounds(&set, m, &mut s) {
                Ok(bd) => {
                    let (lo, hi) = (bd.lower, bd.upper);
                    assert!(
                        lo.is_finite()
                            && hi.is_finite()
                            && 0.0 <= lo + EPS
                            && lo <= hi + EPS
                            && hi <= 1.0 + EPS,
                        "bounds {bd:?}"
                    );
                    let gap = 1.0 - (1.0 - 1.0 / f64::from(m)).powi(dims as i32);
                    assert!(
                        hi - lo <= gap + EPS,
                        "bounds {bd:?} wider than {gap} (m = {m})"
                    );
                    if let Some(x) = exact {
                        assert!(
                            lo <= x + EPS && x <= hi + EPS,
                            "bounds {bd:?} miss the exact {x}"
                        );
                    }
                }
                Err(e) => assert!(
                    matches!(e, Error::OutOfRange { .. } | Error::NotInRange { .. }),
                    "star_discrepancy_bounds({dims} dims, m = {m}): {e:?}"
                ),
            }
            if len > 0 {
                let mut s = vec![0u32; len - 1];
                assert!(star_discrepancy_bounds(&set, m, &mut s).is_err());
            }
        }
        Some(_) => {}
        None => {
            let r = star_discrepancy_bounds(&set, m, &mut []);
            assert!(r.is_err(), "bounds with m = {m}, {dims} dims: {r:?}");
            if m == 0 {
                assert!(matches!(r, Err(Error::ZeroSize { .. })), "{r:?}");
            }
        }
    }

    // Minimum distance.
    let topology = if torus {
        Topology::Torus
    } else {
        Topology::Square
    };
    let need = min_distance_scratch_len(n).unwrap();
    let mut s = vec![0u64; need];
    match min_distance(&set, topology, &mut s) {
        Ok(md) => {
            assert_eq!(dims, 2, "min_distance accepted {dims} dims");
            let brute = brute_min_distance(&coords, torus);
            assert!(
                (md.distance - brute).abs() <= EPS,
                "min_distance {} vs brute force {brute} ({topology:?}, {n} points)",
                md.distance
            );
            assert!(
                md.relative_radius.is_finite() && md.relative_radius >= 0.0,
                "rho {}",
                md.relative_radius
            );
            let mut short = vec![0u64; need - 1];
            assert!(matches!(
                min_distance(&set, topology, &mut short),
                Err(Error::BufferTooShort { .. })
            ));
        }
        Err(e) => {
            assert_ne!(dims, 2, "min_distance failed on a 2D set: {e:?}");
            assert!(
                matches!(e, Error::OutOfRange { .. } | Error::NotInRange { .. }),
                "{e:?}"
            );
        }
    }
}

fn brute_min_distance(coords: &[f64], torus: bool) -> f64 {
    let pts: Vec<[f64; 2]> = coords.chunks_exact(2).map(|p| [p[0], p[1]]).collect();
    let mut best = if torus { 0.5f64.sqrt() } else { 2.0f64.sqrt() };
    for i in 0..pts.len() {
        for j in i + 1..pts.len() {
            let mut d2 = 0.0;
            for k in 0..2 {
                let mut d = (pts[i][k] - pts[j][k]).abs();
                if torus {
                    d = d.min(1.0 - d);
                }
                d2 += d * d;
            }
            best = best.min(d2.sqrt());
        }
    }
    best
}
