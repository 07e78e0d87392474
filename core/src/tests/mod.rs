//! Naive oracles shared by the unit tests (test builds only).

pub(crate) mod sobol_oracle;
