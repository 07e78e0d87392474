//! Naive oracles shared by the unit tests (test builds only).

pub(crate) mod double_double;
mod radical_oracle;
pub(crate) mod sobol_oracle;

/// Pearson's χ² statistic of `counts` against equal expected counts (their mean): the sum of
/// `(c − e)² / e`. Callers compare it with the critical value of `counts.len() − 1` degrees of
/// freedom at their stated false-alarm rate.
pub(crate) fn chi_square_uniform(counts: &[u32]) -> f64 {
    let total: f64 = counts.iter().map(|&c| f64::from(c)).sum();
    let expect = total / counts.len() as f64;
    counts
        .iter()
        .map(|&c| (f64::from(c) - expect).powi(2) / expect)
        .sum()
}
