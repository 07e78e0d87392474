//! Radical inverses (filled in by the foundation work).
