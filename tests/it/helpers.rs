//! The shared checkers must themselves catch failures.

use nyquist_tests::{elementary_intervals, one_per_stratum};

#[test]
fn elementary_interval_checker_rejects_a_collision_in_one_shape_only() {
    // A (0,2)-net in base 2 for m = 2 ...
    let good = [(0.0, 0.0), (0.5, 0.25), (0.25, 0.5), (0.75, 0.75)];
    assert_eq!(elementary_intervals(&good, 2), Ok(()));
    // ... and the diagonal, which is stratified in 4 × 1 and 1 × 4 but not in 2 × 2.
    let diagonal = [(0.0, 0.0), (0.5, 0.5), (0.25, 0.25), (0.75, 0.75)];
    assert_eq!(elementary_intervals(&diagonal, 2), Err((1, 0)));
}

#[test]
fn stratum_checker_requires_every_stratum() {
    assert!(one_per_stratum(&[0.0, 0.5], 2));
    assert!(!one_per_stratum(&[0.0, 0.4], 2));
    assert!(!one_per_stratum(&[0.0, 1.0], 2));
}
