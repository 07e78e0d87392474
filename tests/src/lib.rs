//! Shared checks for the cross-crate tests in `tests/it/`: point-set properties that several
//! suites assert (elementary intervals, strata, permutations).
#![forbid(unsafe_code)]
#![deny(missing_docs)]

/// Whether the `2^m` points `(x, y)` put exactly one point in every elementary interval
/// `[a/2^i, (a+1)/2^i) × [b/2^(m−i), (b+1)/2^(m−i))` for every `i` in `0..=m`.
/// Returns the first failing `(i, cell)` on failure.
///
/// ```
/// let pts = [(0.0, 0.0), (0.5, 0.5), (0.25, 0.75), (0.75, 0.25)];
/// assert_eq!(nyquist_tests::elementary_intervals(&pts, 2), Ok(()));
/// assert!(nyquist_tests::elementary_intervals(&[(0.1, 0.1), (0.2, 0.2)], 1).is_err());
/// ```
pub fn elementary_intervals(points: &[(f64, f64)], m: u32) -> Result<(), (u32, usize)> {
    let n = 1usize << m;
    assert_eq!(points.len(), n, "need exactly 2^m points");
    for i in 0..=m {
        let (nx, ny) = (1usize << i, 1usize << (m - i));
        let mut seen = vec![false; n];
        for &(x, y) in points {
            let cx = ((x * nx as f64) as usize).min(nx - 1);
            let cy = ((y * ny as f64) as usize).min(ny - 1);
            let cell = cy * nx + cx;
            if std::mem::replace(&mut seen[cell], true) {
                return Err((i, cell));
            }
        }
    }
    Ok(())
}

/// Whether each of `n` strata `[k/n, (k+1)/n)` holds exactly one of `values`.
///
/// ```
/// assert!(nyquist_tests::one_per_stratum(&[0.1, 0.7, 0.4], 3));
/// assert!(!nyquist_tests::one_per_stratum(&[0.1, 0.2, 0.9], 3));
/// ```
pub fn one_per_stratum(values: &[f32], n: usize) -> bool {
    let mut seen = vec![false; n];
    values.len() == n
        && values.iter().all(|&v| {
            (0.0..1.0).contains(&v) && {
                let s = ((v as f64 * n as f64) as usize).min(n - 1);
                !std::mem::replace(&mut seen[s], true)
            }
        })
}
