//! Stratified, Latin-hypercube and shuffled samples over caller buffers (filled in by the foundation work).
