//! Cross-crate conformance tests: one test binary, a module per topic.

mod helpers;
mod sequences;
mod stratify;
