//! Cross-crate conformance tests: one test binary, a module per topic.

mod helpers;
mod padding;
mod sequences;
mod stratify;
