//! Measures of point sets: the L2 and exact star discrepancies, SciPy's discrepancy update and
//! geometric discrepancies, the t-value of a base-2 net and the periodogram.

use numpy::{IntoPyArray, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2};
use numpy::{PyReadonlyArray3, PyUntypedArrayMethods};
use pyo3::prelude::*;

use nyquist::analysis::{
    L2Kind, L2Sums, PointSet, l2_point_sums, l2_sums, l2_sums_rows, net_t_value,
    net_t_value_scratch_len, star_discrepancy, star_discrepancy_scratch_len,
};

use crate::{filled, value_error};

/// A read-only `(n, d)` array as a validated point set.
fn point_set<'a>(sample: &'a PyReadonlyArray2<'_, f64>) -> PyResult<PointSet<'a>> {
    let dims = sample.shape()[1];
    let coords = sample.as_slice().map_err(value_error)?;
    PointSet::new(coords, dims).map_err(value_error)
}

fn l2_kind(method: &str) -> Option<L2Kind> {
    Some(match method {
        "CD" => L2Kind::Centered,
        "WD" => L2Kind::WrapAround,
        "MD" => L2Kind::Mixture,
        "L2-star" => L2Kind::Star,
        _ => return None,
    })
}

/// The discrepancy of `sample` (an `(n, d)` float64 array in `[0, 1]`) by `method`: `"CD"`
/// (centered L2), `"WD"` (wrap-around L2) and `"MD"` (mixture L2) squared, `"L2-star"` not
/// squared — as SciPy's `qmc.discrepancy` returns them — or `"star"`, the exact star
/// discrepancy. `iterative` normalises the L2 discrepancies by `n + 1` instead of `n`, SciPy's
/// preparation for `update_discrepancy`.
#[pyfunction]
#[pyo3(signature = (sample, method, iterative=false))]
pub fn discrepancy(
    py: Python<'_>,
    sample: PyReadonlyArray2<'_, f64>,
    method: &str,
    iterative: bool,
) -> PyResult<f64> {
    let points = point_set(&sample)?;
    if let Some(kind) = l2_kind(method) {
        let n = points.len() as f64 + f64::from(u8::from(iterative));
        // D² is a small difference of O(1) sums, so rounding can make it slightly negative: the
        // discrepancy clamps it at 0, as the core's functions do. With `iterative` it is not a
        // discrepancy but a partial sum for `update_discrepancy`, and SciPy returns it as is.
        let squared = py.detach(|| parallel_l2_sums(&points, kind).squared(n));
        let squared = if iterative { squared } else { squared.max(0.0) };
        return Ok(if kind == L2Kind::Star {
            squared.max(0.0).sqrt()
        } else {
            squared
        });
    }
    if method != "star" {
        return Err(value_error(format!(
            "method '{method}' is not one of 'CD', 'WD', 'MD', 'L2-star', 'star'"
        )));
    }
    if iterative {
        return Err(value_error(
            "iterative=True: the star discrepancy has no update formula",
        ));
    }
    let len = star_discrepancy_scratch_len(points.len(), points.dims())
        .ok_or_else(|| value_error("the star discrepancy's scratch does not fit"))?;
    let mut scratch = filled(len, 0.0)?;
    py.detach(|| star_discrepancy(&points, &mut scratch))
        .map_err(value_error)
}

/// The core's `l2_sums` on every thread: the rows split into one range per thread with equal
/// shares of the triangle of pairs (row `i` costs `N − i`), each summed by `l2_sums_rows`, the
/// parts added. One thread below 2048 points.
fn parallel_l2_sums(points: &PointSet<'_>, kind: L2Kind) -> L2Sums {
    let n = points.len();
    let threads = std::thread::available_parallelism().map_or(1, |t| t.get());
    if n < 2048 || threads == 1 {
        return l2_sums(points, kind);
    }
    // Pairs before row r: r·n − r(r − 1)/2; the k-th cut is the first row past k/threads of
    // all n(n + 1)/2.
    let before = |r: usize| (r * n - r * r.saturating_sub(1) / 2) as f64;
    let total = before(n);
    let mut cuts = vec![0];
    for k in 1..threads {
        let target = total * k as f64 / threads as f64;
        let (mut lo, mut hi) = (*cuts.last().unwrap_or(&0), n);
        while lo < hi {
            let mid = (lo + hi) / 2;
            if before(mid) < target {
                lo = mid + 1
            } else {
                hi = mid
            }
        }
        cuts.push(lo);
    }
    cuts.push(n);
    let parts: Vec<L2Sums> = std::thread::scope(|scope| {
        let handles: Vec<_> = cuts
            .windows(2)
            .map(|w| {
                let rows = w[0]..w[1];
                scope.spawn(move || l2_sums_rows(points, kind, rows))
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
            .collect()
    });
    let mut sums = parts[0];
    for p in &parts[1..] {
        sums.single += p.single;
        sums.pairs += p.pairs;
    }
    sums
}

/// SciPy's `update_discrepancy`: the squared centered L2 discrepancy of `sample` plus `x_new`,
/// given `initial` = the squared discrepancy of `sample` computed with `iterative=True`. O(n·d)
/// (the core's `l2_point_sums`).
#[pyfunction]
pub fn update_discrepancy(
    py: Python<'_>,
    x_new: PyReadonlyArray1<'_, f64>,
    sample: PyReadonlyArray2<'_, f64>,
    initial: f64,
) -> PyResult<f64> {
    let points = point_set(&sample)?;
    let x = x_new.as_slice().map_err(value_error)?;
    let n = points.len() as f64 + 1.0;
    let added = py
        .detach(|| l2_point_sums(&points, x, L2Kind::Centered))
        .map_err(value_error)?;
    Ok(initial + added.squared(n))
}

/// A distance between two points.
type Metric = fn(&[f64], &[f64]) -> f64;

fn metric(name: &str) -> PyResult<Metric> {
    Ok(match name {
        "euclidean" => |a, b| {
            a.iter()
                .zip(b)
                .map(|(x, y)| (x - y) * (x - y))
                .sum::<f64>()
                .sqrt()
        },
        "cityblock" => |a, b| a.iter().zip(b).map(|(x, y)| (x - y).abs()).sum(),
        "chebyshev" => |a, b| {
            a.iter()
                .zip(b)
                .map(|(x, y)| (x - y).abs())
                .fold(0.0, f64::max)
        },
        other => {
            return Err(value_error(format!(
                "metric '{other}' is not one of 'euclidean', 'cityblock', 'chebyshev'"
            )));
        }
    })
}

/// SciPy's `geometric_discrepancy`: `"mindist"`, the smallest distance between two distinct
/// points, or `"mst"`, the mean edge length of a minimum spanning tree of the complete graph
/// (Prim's algorithm, O(n²·d), zero-length edges included). Returns the value and whether two
/// points coincide.
#[pyfunction]
pub fn geometric_discrepancy(
    py: Python<'_>,
    sample: PyReadonlyArray2<'_, f64>,
    method: &str,
    metric_name: &str,
) -> PyResult<(f64, bool)> {
    let points = point_set(&sample)?;
    let dist = metric(metric_name)?;
    let d = points.dims();
    let c = points.coords();
    let p = |i: usize| &c[i * d..(i + 1) * d];
    let n = points.len();
    match method {
        "mindist" => {
            let (best, duplicate) = py.detach(|| {
                let (mut best, mut duplicate) = (f64::INFINITY, false);
                for i in 0..n {
                    for j in i + 1..n {
                        let r = dist(p(i), p(j));
                        if r == 0.0 {
                            duplicate = true;
                        } else if r < best {
                            best = r;
                        }
                    }
                }
                (best, duplicate)
            });
            if best.is_infinite() {
                return Err(value_error(
                    "Sample has no two distinct points, so no smallest distance between them",
                ));
            }
            Ok((best, duplicate))
        }
        "mst" => Ok(py.detach(|| {
            // Prim: `near[k]` is the shortest edge from point k to the tree so far.
            let mut near = vec![f64::INFINITY; n];
            let mut in_tree = vec![false; n];
            let (mut total, mut duplicate) = (0.0, false);
            let mut next = 0;
            for step in 0..n {
                in_tree[next] = true;
                if step > 0 {
                    total += near[next];
                    duplicate |= near[next] == 0.0;
                }
                let current = next;
                let mut best = f64::INFINITY;
                for k in 0..n {
                    if in_tree[k] {
                        continue;
                    }
                    near[k] = near[k].min(dist(p(current), p(k)));
                    if near[k] < best || best.is_infinite() {
                        best = near[k];
                        next = k;
                    }
                }
            }
            (total / (n - 1).max(1) as f64, duplicate)
        })),
        other => Err(value_error(format!(
            "'{other}' is not a valid method. It must be one of {{'mindist', 'mst'}}"
        ))),
    }
}

/// The t-value of `sample` (2^m points in `[0, 1)^d`) as a digital net in base 2: the smallest
/// t for which every elementary box of volume 2^(t − m) holds exactly 2^t points (the core's
/// `net_t_value`).
#[pyfunction]
pub fn t_value(py: Python<'_>, sample: PyReadonlyArray2<'_, f64>) -> PyResult<u32> {
    let points = point_set(&sample)?;
    let len = net_t_value_scratch_len(points.len(), points.dims())
        .ok_or_else(|| value_error("the t-value's scratch does not fit"))?;
    let mut scratch = filled(len, 0u32)?;
    py.detach(|| net_t_value(&points, &mut scratch))
        .map_err(value_error)
}

/// The periodogram of 2-D point sets (an `(k, n, 2)` array: `k` realisations of `n` points),
/// averaged over the realisations, on the integer frequencies `[−F, F]²` (nyquist-film's
/// `periodogram`): the power `(2F + 1, 2F + 1)` (row `f_y + F`, column `f_x + F`, DC at the
/// centre), the radial mean over annuli `0..=F`, and the anisotropy of each annulus in dB.
#[pyfunction]
#[allow(clippy::type_complexity)]
pub fn periodogram<'py>(
    py: Python<'py>,
    sets: PyReadonlyArray3<'py, f64>,
    max_freq: u32,
) -> PyResult<(
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
)> {
    let shape = sets.shape().to_vec();
    if shape[2] != 2 {
        return Err(value_error(format!(
            "points have {} coordinates; the periodogram takes 2-D points",
            shape[2]
        )));
    }
    let flat = sets.as_slice().map_err(value_error)?;
    let (pairs, _) = flat.as_chunks::<2>();
    let n = shape[1];
    let spectrum = py
        .detach(|| {
            let realisations: Vec<&[[f64; 2]]> = pairs.chunks(n.max(1)).collect();
            nyquist_film::periodogram::periodogram(&realisations, max_freq)
        })
        .map_err(value_error)?;
    let side = 2 * max_freq as usize + 1;
    Ok((
        spectrum.power.into_pyarray(py).reshape([side, side])?,
        spectrum.radial_mean.into_pyarray(py),
        spectrum.anisotropy_db.into_pyarray(py),
    ))
}
