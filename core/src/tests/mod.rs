//! Naive oracles shared by the unit tests (test builds only).
mod radical_oracle;
