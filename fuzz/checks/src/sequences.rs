//! `nyquist::sequence`: every point set through the `Sequence` trait, any index, dimension and
//! seed, plus the set-specific entry points.

use nyquist::Error;
use nyquist::scramble::{Scramble, scramble_u32};
use nyquist::sequence::{
    Halton, HaltonZaremba, Hammersley, HammersleyZaremba, OwenSobol, Pmj02, SOBOL_DIMS,
    ScrambledHalton, Sequence, Sobol, VanDerCorput, ZeroTwo, check_fill, pmj02_build, sobol_u32,
    sobol_u64,
};

use crate::{Bytes, in_unit, in_unit_f64};

/// Sequences: `sample`/`sample_f64` in `[0, 1)`; `dim >= dims()` wraps to `dim % dims()`;
/// `index >= point_count` wraps; `fill` writes exactly `out.len() / dims` points equal to
/// `sample` bit for bit, or fails exactly as `check_fill` says; constructors reject `dims == 0`.
pub fn sequences(data: &[u8]) {
    let mut b = Bytes::new(data);
    let dims = match b.u8() % 4 {
        0 => b.below(8),
        1 => b.below(1100),
        2 => b.u32(),
        _ => SOBOL_DIMS - 1 + b.below(2),
    };
    let index = if b.bool() {
        u64::from(b.u16())
    } else {
        b.u64()
    };
    let dim = if b.bool() { b.below(64) } else { b.u32() };
    let seed = b.u64();
    let n = if b.bool() {
        u64::from(b.u16())
    } else {
        b.u64()
    };
    let first = if b.bool() {
        u64::MAX - u64::from(b.u8())
    } else {
        b.u64()
    };
    let fill_dims = b.below(12);
    let len = b.below(96) as usize;

    let check =
        |name: &str, s: &dyn Sequence| check_sequence(name, s, index, dim, first, fill_dims, len);
    check("VanDerCorput", &VanDerCorput);
    built("Halton", dims, Halton::new(dims), &check);
    built("HaltonZaremba", dims, HaltonZaremba::new(dims), &check);
    built("OwenSobol", dims, OwenSobol::new(dims, seed), &check);
    if let Ok(s) = OwenSobol::new(dims, seed) {
        // The 4-wide and run forms equal single values.
        let (i, d) = (index, dim);
        let four = s.sample_4d(i, d);
        let mut run = [0.0f32; 4];
        s.sample_dims(i, d, &mut run);
        for k in 0..4u32 {
            let one = s.sample(i, d.wrapping_add(k));
            assert_eq!(
                four[k as usize].to_bits(),
                one.to_bits(),
                "OwenSobol sample_4d"
            );
            assert_eq!(
                run[k as usize].to_bits(),
                one.to_bits(),
                "OwenSobol sample_dims"
            );
        }
    }
    // Scrambles are nested: values sharing their first k digits still do.
    let (x, k) = (index as u32, (n % 33) as u32);
    for how in Scramble::ALL {
        let y = scramble_u32(x, seed as u32, how);
        let z = scramble_u32(
            x ^ (u32::MAX >> k.min(31) >> u32::from(k == 32)),
            seed as u32,
            how,
        );
        if k > 0 {
            assert_eq!(y >> (32 - k), z >> (32 - k), "{how:?} k {k}");
        }
    }
    built(
        "ScrambledHalton",
        dims,
        ScrambledHalton::new(dims, seed),
        &check,
    );
    let strategy = Scramble::ALL[(seed % 4) as usize];
    built(
        "ScrambledHalton::with_strategy",
        dims,
        ScrambledHalton::with_strategy(dims, strategy, seed),
        &check,
    );
    check("Pmj02", &Pmj02::new());
    check("Pmj02::scrambled", &Pmj02::scrambled(seed));
    // The in-place construction: any buffer length errs or builds a prefix of the baked table's
    // kind, every value a fraction.
    let mut buf = [[0u32; 2]; 96];
    match pmj02_build(seed as u32, &mut buf[..len]) {
        Ok(()) => assert!(len > 0),
        Err(e) => assert_eq!((len, e), (0, Error::ZeroSize { what: "points" })),
    }
    built("Hammersley", dims, Hammersley::new(n, dims), &check);
    built(
        "HammersleyZaremba",
        dims,
        HammersleyZaremba::new(n, dims),
        &check,
    );
    if Hammersley::new(n, dims.max(1)).is_ok() {
        assert!(n > 0, "Hammersley::new accepted n = 0");
    }
    built("Sobol", dims, Sobol::new(dims), &check);
    let scrambled = Sobol::with_digital_shift(dims, seed);
    if let Ok(s) = &scrambled {
        assert!(s.is_shifted());
        let v = s.sample_u32(index, dim);
        let x = f64::from(s.sample(index, dim));
        let exact = f64::from(v) / 4_294_967_296.0;
        assert!(
            (x - exact).abs() <= 2.0f64.powi(-24),
            "Sobol::sample = {x} is not sample_u32 = {v} as a fraction"
        );
    }
    built("Sobol::with_digital_shift", dims, scrambled, &check);
    if let Ok(s) = Sobol::new(dims) {
        assert!(!s.is_shifted());
        // Unscrambled: the table's value for the 64-bit index and the wrapped dimension, below
        // 1024 dimensions (past them, the padding).
        let d = dim % dims;
        if d < 1024 {
            assert_eq!(s.sample_u32(index, dim), sobol_u64(index, d));
            if index >> 32 == 0 {
                assert_eq!(s.sample_u32(index, dim), sobol_u32(index as u32, d));
            }
        }
    }
    let _ = sobol_u32(index as u32, dim); // total for any dimension
    let z = ZeroTwo::from_seed(seed);
    check("ZeroTwo", &z);
    let [u, v] = z.sample_2d(index as u32);
    assert!(
        in_unit(u) && in_unit(v),
        "ZeroTwo::sample_2d({index}) = [{u}, {v}]"
    );
    let _ = z.sample_2d_u32(index as u32);
}

fn built<S: Sequence>(
    name: &str,
    dims: u32,
    r: Result<S, Error>,
    check: &dyn Fn(&str, &dyn Sequence),
) {
    match r {
        Ok(s) => {
            assert!(dims > 0, "{name}::new accepted dims = 0");
            assert_eq!(s.dims(), dims, "{name}: dims()");
            check(name, &s);
        }
        Err(e) => assert!(
            matches!(
                e,
                Error::ZeroSize { .. }
                    | Error::DimensionOutOfRange { .. }
                    | Error::OutOfRange { .. }
                    | Error::NotInRange { .. }
                    | Error::TooMany { .. }
            ),
            "{name}::new({dims}): unexpected error {e:?}"
        ),
    }
}

fn check_sequence(
    name: &str,
    s: &dyn Sequence,
    index: u64,
    dim: u32,
    first: u64,
    fill_dims: u32,
    len: usize,
) {
    let d = s.dims();
    assert!(d >= 1, "{name}: dims() = 0");
    let x = s.sample(index, dim);
    assert!(
        in_unit(x),
        "{name}.sample({index}, {dim}) = {x} (point count {:?})",
        s.point_count()
    );
    let x64 = s.sample_f64(index, dim);
    assert!(
        in_unit_f64(x64),
        "{name}.sample_f64({index}, {dim}) = {x64}"
    );
    assert_eq!(
        x.to_bits(),
        s.sample(index, dim % d).to_bits(),
        "{name}: dimension {dim} must wrap to {}",
        dim % d
    );
    if let Some(count) = s.point_count() {
        assert!(count > 0, "{name}: point_count() = Some(0)");
        assert_eq!(
            x.to_bits(),
            s.sample(index % count, dim).to_bits(),
            "{name}: index {index} must wrap modulo {count}"
        );
    }
    let mut out = vec![7.0f32; len];
    let want = check_fill(d, s.point_count(), first, fill_dims, len);
    let got = s.fill(first, fill_dims, &mut out);
    assert_eq!(got, want, "{name}.fill({first}, {fill_dims}, len {len})");
    if let Ok(points) = got {
        assert_eq!(
            points,
            (len / fill_dims as usize) as u64,
            "{name}: fill count"
        );
        for (k, p) in out.chunks_exact(fill_dims as usize).enumerate() {
            for (j, &v) in p.iter().enumerate() {
                let want = s.sample(first + k as u64, j as u32);
                assert_eq!(
                    v.to_bits(),
                    want.to_bits(),
                    "{name}.fill({first}, {fill_dims}): point {k} dim {j} = {v}, sample gives {want}"
                );
            }
        }
    } else {
        assert!(
            out.iter().all(|&v| v == 7.0),
            "{name}: a failed fill wrote to out"
        );
    }
}
