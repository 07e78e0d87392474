//! Naive oracles shared by the unit tests (test builds only).

mod radical_oracle;
pub(crate) mod sobol_oracle;
