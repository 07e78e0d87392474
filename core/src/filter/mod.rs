//! Reconstruction filters (filled in by the filters work).
