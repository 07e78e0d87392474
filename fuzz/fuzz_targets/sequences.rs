//! Radical inverses and point sets: any base index, any u64 index, any seed. The contract: no
//! panic, every value in [0, 1), never NaN, and `fill` agrees with `sample`.
#![no_main]

use libfuzzer_sys::fuzz_target;
use nyquist::radical;
use nyquist::sequence::{Halton, HaltonZaremba, Hammersley, Sequence, Sobol, ZeroTwo};

fn in_unit(x: f32) -> bool {
    (0.0..1.0).contains(&x)
}

fuzz_target!(|input: (u32, u64, u64, u32)| {
    let (dim, index, seed, dims) = input;
    assert!(in_unit(radical::radical_inverse(dim, index)));
    assert!((0.0..1.0).contains(&radical::radical_inverse_f64(dim, index)));
    assert!(in_unit(radical::folded_radical_inverse(dim, index)));
    assert!(in_unit(radical::scrambled_radical_inverse(dim, index, seed)));
    let dims = dims % 1100;
    if let Ok(h) = Halton::new(dims) {
        assert!(in_unit(h.sample(index, dim)));
        let mut buf = [0.0f32; 4];
        if h.fill(index, 1, &mut buf).is_ok() {
            assert_eq!(buf[0].to_bits(), h.sample(index, 0).to_bits());
        }
    }
    if let Ok(h) = HaltonZaremba::new(dims) {
        assert!(in_unit(h.sample(index, dim)));
    }
    if let Ok(h) = Hammersley::new(seed, dims) {
        assert!(in_unit(h.sample(index, dim)));
    }
    if let Ok(s) = Sobol::new(dims) {
        assert!(in_unit(s.sample(index, dim)));
    }
    assert!(in_unit(ZeroTwo::from_seed(seed).sample(index, dim)));
});
