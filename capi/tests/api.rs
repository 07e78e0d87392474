//! The C API called from Rust: status mapping, pointer checks, and properties over arbitrary
//! input (never a panic; every value in `[0, 1)`; results equal to the core's).

mod common;

use std::ffi::{CStr, CString};
use std::ptr;

use common::Clipped;
use nyquist::Error;
use nyquist::filter::{Filter, FilterKind};
use nyquist::sequence::{Halton, Sequence, Sobol};
use nyquist_capi::*;
use proptest::prelude::*;

#[test]
fn every_core_error_maps_to_its_status() {
    use NyqStatus::*;
    let cases = [
        (Error::ZeroSize { what: "n" }, NYQ_ERR_ZERO_SIZE),
        (Error::NonFinite { what: "r" }, NYQ_ERR_NON_FINITE),
        (
            Error::OutOfRange {
                what: "r",
                value: 2.0,
                range: nyquist::error::Interval::closed(0.0, 1.0),
            },
            NYQ_ERR_OUT_OF_RANGE,
        ),
        (
            Error::NotInRange {
                what: "dims",
                value: 2000,
                min: 1,
                max: 1024,
            },
            NYQ_ERR_OUT_OF_RANGE,
        ),
        (
            Error::Invalid {
                what: "a",
                value: 190,
                rule: "is not coprime to n =",
                other: 1024,
            },
            NYQ_ERR_OUT_OF_RANGE,
        ),
        (
            Error::NotSeparable {
                what: "phase table",
            },
            NYQ_ERR_OUT_OF_RANGE,
        ),
        (
            Error::DimensionOutOfRange { dim: 3, dims: 2 },
            NYQ_ERR_OUT_OF_RANGE,
        ),
        (
            Error::BufferLength {
                multiple_of: 2,
                actual: 3,
            },
            NYQ_ERR_BUFFER,
        ),
        (
            Error::BufferTooShort {
                needed: 4,
                actual: 3,
            },
            NYQ_ERR_BUFFER,
        ),
        (
            Error::TooMany {
                what: "n",
                value: 5000,
                max: 4096,
            },
            NYQ_ERR_TOO_MANY,
        ),
    ];
    for (e, s) in cases {
        assert_eq!(NyqStatus::from(e), s, "{e}");
    }
}

#[test]
fn every_status_has_its_own_message() {
    let messages: Vec<&str> = (0..=8u32)
        .map(|s| {
            // SAFETY: the messages are static NUL-terminated strings.
            unsafe { CStr::from_ptr(nyq_status_message(s)) }
                .to_str()
                .unwrap()
        })
        .collect();
    let mut unique = messages.clone();
    unique.sort();
    unique.dedup();
    assert_eq!(unique.len(), 9, "{messages:?}");
    assert!(!messages.contains(&"unknown status"));
    // SAFETY: as above.
    let unknown = unsafe { CStr::from_ptr(nyq_status_message(9)) };
    assert_eq!(unknown.to_str(), Ok("unknown status"));
}

#[test]
fn misaligned_pointers_are_buffer_errors_and_nothing_is_written() {
    let mut words = [0u32; 8];
    let misaligned = words
        .as_mut_ptr()
        .cast::<u8>()
        .wrapping_add(1)
        .cast::<f32>();
    // SAFETY: the pointer is misaligned, which the API checks before any access.
    unsafe {
        assert_eq!(
            nyq_radical_inverse(0, 1, misaligned),
            NyqStatus::NYQ_ERR_BUFFER
        );
        assert_eq!(
            nyq_stratified_1d(misaligned, 4, true, 0),
            NyqStatus::NYQ_ERR_BUFFER
        );
    }
    assert_eq!(words, [0; 8]);
}

#[test]
fn outputs_are_untouched_on_error() {
    let mut x = 42.0f32;
    let bad = NyqSequence {
        kind: NyqSequenceKind::NYQ_SEQ_HALTON as u32,
        dims: 2,
        points: 0,
        seed: 0,
        multiplier: 0,
    };
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(
            nyq_sequence_sample(&bad, 0, 5, &mut x),
            NyqStatus::NYQ_ERR_OUT_OF_RANGE
        );
        assert_eq!(
            nyq_radical_inverse(2000, 1, &mut x),
            NyqStatus::NYQ_ERR_OUT_OF_RANGE
        );
    }
    assert_eq!(x, 42.0);
    let mut f: *mut NyqFilter = ptr::null_mut();
    // SAFETY: valid pointers.
    let s = unsafe { nyq_filter_create(c"gaussian:alpha=1,sigma=1".as_ptr(), &mut f) };
    assert_eq!((s, f.is_null()), (NyqStatus::NYQ_ERR_PARSE, true));
}

#[test]
fn sequence_fill_equals_the_cores_samples() {
    let sobol = NyqSequence {
        kind: NyqSequenceKind::NYQ_SEQ_SOBOL as u32,
        dims: 5,
        points: 0,
        seed: 0,
        multiplier: 0,
    };
    let core = Sobol::new(5).unwrap();
    let mut buf = vec![0.0f32; 5 * 100];
    let mut n = 0u64;
    // SAFETY: valid pointers, `buf` holds its length.
    let s = unsafe { nyq_sequence_fill(&sobol, 1000, 5, buf.as_mut_ptr(), buf.len(), &mut n) };
    assert_eq!((s, n), (NyqStatus::NYQ_OK, 100));
    for (i, p) in buf.chunks_exact(5).enumerate() {
        for (d, &x) in p.iter().enumerate() {
            assert_eq!(x, core.sample(1000 + i as u64, d as u32));
        }
    }
}

/// Arbitrary `NyqSequence` values, including bad kinds, sizes and counts.
fn any_sequence() -> impl Strategy<Value = NyqSequence> {
    (
        0u32..20,
        0u32..1100,
        prop_oneof![Just(0u64), 1u64..100, any::<u64>()],
        any::<u64>(),
        prop_oneof![Just(0u64), 1u64..100, any::<u64>()],
    )
        .prop_map(|(kind, dims, points, seed, multiplier)| NyqSequence {
            kind,
            dims,
            points,
            seed,
            multiplier,
        })
}

proptest! {
    #[test]
    fn sequence_sample_is_ok_in_range_or_an_error(
        seq in any_sequence(),
        index in prop_oneof![0u64..64, any::<u64>()],
        dim in 0u32..1100,
    ) {
        let mut x = f32::NAN;
        // SAFETY: valid pointers.
        let s = unsafe { nyq_sequence_sample(&seq, index, dim, &mut x) };
        if s == NyqStatus::NYQ_OK {
            prop_assert!((0.0..1.0).contains(&x), "{x}");
            prop_assert!(dim < seq.dims);
        } else {
            prop_assert!(x.is_nan(), "written on error");
        }
    }

    #[test]
    fn halton_through_the_api_is_the_cores(index in any::<u64>(), dim in 0u32..8) {
        let seq = NyqSequence { kind: NyqSequenceKind::NYQ_SEQ_HALTON as u32, dims: 8, points: 0, seed: 0, multiplier: 0 };
        let mut x = 0.0f32;
        // SAFETY: valid pointers.
        prop_assert_eq!(unsafe { nyq_sequence_sample(&seq, index, dim, &mut x) }, NyqStatus::NYQ_OK);
        prop_assert_eq!(x, Halton::new(8).unwrap().sample(index, dim));
    }

    /// `nyq_halton_sample` and `nyq_halton_fill` are `nyq_sequence_sample` and
    /// `nyq_sequence_fill` of `NYQ_SEQ_HALTON`: the same status and, when it is `NYQ_OK`, the
    /// same bits, for any dimension count, index, dimension and buffer length.
    #[test]
    fn halton_functions_are_the_sequence_functions_of_halton(
        dims in prop_oneof![0u32..10, 0u32..1100],
        index in prop_oneof![0u64..300, any::<u64>()],
        dim in prop_oneof![0u32..10, 0u32..1100],
        len in 0usize..40,
    ) {
        let seq = NyqSequence { kind: NyqSequenceKind::NYQ_SEQ_HALTON as u32, dims, points: 0, seed: 0, multiplier: 0 };
        let (mut x, mut y) = (f32::NAN, f32::NAN);
        // SAFETY: valid pointers.
        let (a, b) = unsafe { (nyq_halton_sample(dims, index, dim, &mut x), nyq_sequence_sample(&seq, index, dim, &mut y)) };
        prop_assert_eq!(a, b);
        prop_assert_eq!(x.to_bits(), y.to_bits());
        let (mut p, mut q) = (vec![f32::NAN; len.max(1)], vec![f32::NAN; len.max(1)]);
        let (mut n, mut m) = (u64::MAX, u64::MAX);
        // SAFETY: `p` and `q` hold at least `len` floats.
        let (a, b) = unsafe {
            (
                nyq_halton_fill(index, dims, p.as_mut_ptr(), len, &mut n),
                nyq_sequence_fill(&seq, index, dims, q.as_mut_ptr(), len, &mut m),
            )
        };
        prop_assert_eq!((a, n), (b, m));
        if a == NyqStatus::NYQ_OK {
            prop_assert_eq!(p.iter().map(|v| v.to_bits()).collect::<Vec<_>>(), q.iter().map(|v| v.to_bits()).collect::<Vec<_>>());
        }
    }

    /// `nyq_sampler_create_owen_sobol` is `nyq_sampler_create("owen-sobol", …)`: the same
    /// status and, for every call on the handle (and on its clone), the same bits.
    #[test]
    fn the_owen_sobol_constructor_is_the_named_sampler(
        size in (0u32..3, 0u32..3),
        spp in 0u32..70,
        seed in any::<u64>(),
        pixel in (any::<u32>(), any::<u32>()),
        index in any::<u32>(),
        dim in prop_oneof![0u32..16, 1000u32..1100, any::<u32>()],
    ) {
        let (mut a, mut b): (*mut NyqSampler, *mut NyqSampler) = (ptr::null_mut(), ptr::null_mut());
        // SAFETY: valid pointers; each handle is destroyed once.
        unsafe {
            let sa = nyq_sampler_create_owen_sobol(size.0, size.1, spp, seed, &mut a);
            let sb = nyq_sampler_create(c"owen-sobol".as_ptr(), size.0, size.1, spp, seed, &mut b);
            prop_assert_eq!(sa, sb);
            if sa != NyqStatus::NYQ_OK {
                prop_assert!(a.is_null() && b.is_null());
                return Ok(());
            }
            let mut c: *mut NyqSampler = ptr::null_mut();
            prop_assert_eq!(nyq_sampler_clone(a, &mut c), NyqStatus::NYQ_OK);
            let mut values = Vec::new();
            for h in [a, b, c] {
                let mut v = [0.0f32; 19];
                let mut n = [0u32; 2];
                nyq_sampler_samples_per_pixel(h, &mut n[0]);
                nyq_sampler_pixel_samples(h, pixel.0, pixel.1, &mut n[1]);
                nyq_sampler_start_pixel_sample(h, pixel.0, pixel.1, index, dim);
                nyq_sampler_get_1d(h, &mut v[0]);
                nyq_sampler_get_2d(h, v[1..].as_mut_ptr());
                nyq_sampler_get_pixel_2d(h, v[3..].as_mut_ptr());
                nyq_sampler_get_array_1d(h, v[5..].as_mut_ptr(), 3);
                nyq_sampler_get_array_2d(h, v[8..].as_mut_ptr(), 6);
                let mut cs = NyqCameraSample { p_film: [0.0; 2], lens: [0.0; 2], time: 0.0 };
                nyq_sampler_camera_sample(h, pixel.0, pixel.1, index, &mut cs);
                v[14..].copy_from_slice(&[cs.p_film[0], cs.p_film[1], cs.lens[0], cs.lens[1], cs.time]);
                values.push((n, v.map(f32::to_bits)));
                nyq_sampler_destroy(h);
            }
            prop_assert_eq!(values[0], values[1]);
            prop_assert_eq!(values[2], values[1]);
        }
    }

    #[test]
    fn filter_specs_parse_as_the_core_does(
        spec in "(box|tent|triangle|gaussian|mitchell|lanczos|[a-z]{0,5})(:(radius|rx|ry|sigma|alpha|b|c|tau|[a-z]{1,3})=[-0-9.x]{0,4}(,(radius|b|c|tau|sigma)=[0-9.]{0,4}){0,2})?",
    ) {
        let c = CString::new(spec.clone()).unwrap();
        let mut f: *mut NyqFilter = ptr::null_mut();
        // SAFETY: valid pointers; the handle is destroyed once.
        let s = unsafe { nyq_filter_create(c.as_ptr(), &mut f) };
        match FilterKind::parse(&spec) {
            Ok(k) => {
                prop_assert_eq!(s, NyqStatus::NYQ_OK);
                let mut w = f32::NAN;
                // SAFETY: `f` is live.
                unsafe {
                    prop_assert_eq!(nyq_filter_eval(f, 0.25, -0.5, &mut w), NyqStatus::NYQ_OK);
                    nyq_filter_destroy(f);
                }
                prop_assert_eq!(w, k.eval(0.25, -0.5));
            }
            Err(_) => prop_assert_eq!((s, f.is_null()), (NyqStatus::NYQ_ERR_PARSE, true)),
        }
    }

    #[test]
    fn samplers_give_values_in_range_for_any_input(
        name in prop::sample::select(vec!["random", "uniform", "stratified", "halton", "hammersley", "zero-two", "sobol", "best-candidate", "adaptive", "owen-sobol", "owen-sobol-bn", "zsobol", "pmj02", "pmj02-bn", "bluenoise-dithered", "fibonacci", "r2", "korobov", "lattice-bn", "bogus"]),
        size in (0u32..70, 0u32..70),
        spp in 0u32..70,
        seed in any::<u64>(),
        pixel in (any::<u32>(), any::<u32>()),
        index in any::<u32>(),
        dim in any::<u32>(),
    ) {
        let c = CString::new(name).unwrap();
        let mut s: *mut NyqSampler = ptr::null_mut();
        // SAFETY: valid pointers; the handle is destroyed once.
        unsafe {
            if nyq_sampler_create(c.as_ptr(), size.0, size.1, spp, seed, &mut s) != NyqStatus::NYQ_OK {
                prop_assert!(s.is_null());
                return Ok(());
            }
            let mut v = [f32::NAN; 5];
            prop_assert_eq!(nyq_sampler_start_pixel_sample(s, pixel.0, pixel.1, index, dim), NyqStatus::NYQ_OK);
            prop_assert_eq!(nyq_sampler_get_1d(s, &mut v[0]), NyqStatus::NYQ_OK);
            prop_assert_eq!(nyq_sampler_get_2d(s, v[1..].as_mut_ptr()), NyqStatus::NYQ_OK);
            prop_assert_eq!(nyq_sampler_get_pixel_2d(s, v[3..].as_mut_ptr()), NyqStatus::NYQ_OK);
            nyq_sampler_destroy(s);
            prop_assert!(v.iter().all(|x| (0.0..1.0).contains(x)), "{v:?}");
        }
    }

    #[test]
    fn callback_filters_tabulate_any_callback(rx in -1.0f32..40.0, ry in -1.0f32..40.0, mode in 0u32..4) {
        unsafe extern "C" fn wild(user: *mut std::ffi::c_void, x: f32, y: f32) -> f32 {
            // SAFETY: `user` points to the `u32` mode below, alive during creation.
            match unsafe { *user.cast::<u32>() } {
                0 => f32::NAN,
                1 => f32::INFINITY,
                2 => -x * y,
                _ => 1e30,
            }
        }
        let mut mode = mode;
        let mut f: *mut NyqFilter = ptr::null_mut();
        // SAFETY: `wild` reads `mode`, alive during the call; the handle is destroyed once.
        unsafe {
            let s = nyq_filter_create_callback(Some(wild), (&raw mut mode).cast(), rx, ry, &mut f);
            let radius_ok = rx >= nyquist::filter::MIN_RADIUS && ry >= nyquist::filter::MIN_RADIUS;
            // NaN and ∞ everywhere have no usable integral (not finite, or 0 once the numeric
            // rule drops the non-finite values), −x·y integrates to 0: refused.
            let refused = [NyqStatus::NYQ_ERR_NON_FINITE, NyqStatus::NYQ_ERR_OUT_OF_RANGE];
            match mode {
                _ if !radius_ok => {}
                0..=2 => prop_assert!(refused.contains(&s), "mode {}: {:?}", mode, s),
                _ => prop_assert_eq!(s, NyqStatus::NYQ_OK),
            }
            if s != NyqStatus::NYQ_OK {
                prop_assert!(f.is_null());
                return Ok(());
            }
            let (mut w, mut i) = (f32::NAN, f32::NAN);
            let mut fs = NyqFilterSample { offset: [f32::NAN; 2], weight: f32::NAN };
            prop_assert_eq!(nyq_filter_lookup(f, 1, 0.1, 0.2, &mut w), NyqStatus::NYQ_OK);
            prop_assert_eq!(nyq_filter_integral(f, &mut i), NyqStatus::NYQ_OK);
            prop_assert_eq!(nyq_filter_sample(f, 0.3, 0.9, &mut fs), NyqStatus::NYQ_OK);
            nyq_filter_destroy(f);
            prop_assert!(w.is_finite() && i.is_finite() && fs.weight.is_finite(), "{w} {i} {fs:?}");
            prop_assert!(fs.offset[0].abs() <= rx && fs.offset[1].abs() <= ry, "{fs:?}");
        }
    }
}

#[test]
fn a_callback_filter_is_its_table_after_creation() {
    fn bump(x: f32, y: f32) -> f32 {
        (1.0 - x * x) * (1.0 - y * y)
    }
    unsafe extern "C" fn bump_c(_: *mut std::ffi::c_void, x: f32, y: f32) -> f32 {
        bump(x, y)
    }
    let exact = Clipped {
        radius: 1.0,
        eval: bump,
    };
    let table: nyquist::filter::FilterTable =
        nyquist::filter::FilterTable::new(&exact, nyquist::filter::Interpolation::Nearest).unwrap();
    let mut f: *mut NyqFilter = ptr::null_mut();
    // SAFETY: `bump_c` ignores its user pointer; the handle is destroyed once.
    unsafe {
        assert_eq!(
            nyq_filter_create_callback(Some(bump_c), ptr::null_mut(), 1.0, 1.0, &mut f),
            NyqStatus::NYQ_OK
        );
        for (x, y) in [
            (0.0, 0.0),
            (0.33, -0.71),
            (0.99, 0.5),
            (1.01, 0.0),
            (f32::NAN, 0.0),
        ] {
            let mut w = f32::NAN;
            assert_eq!(nyq_filter_lookup(f, 0, x, y, &mut w), NyqStatus::NYQ_OK);
            assert_eq!(w, table.weight(x, y), "({x}, {y})");
        }
        let mut i = 0.0;
        nyq_filter_integral(f, &mut i);
        assert_eq!(i, exact.integral());
        assert!((i - 16.0 / 9.0).abs() < 1e-3, "{i}");
        nyq_filter_destroy(f);
    }
}

#[test]
fn null_pointers_are_reported_before_other_errors() {
    let bad = NyqSequence {
        kind: 99,
        dims: 0,
        points: 0,
        seed: 0,
        multiplier: 0,
    };
    let mut f: *mut NyqFilter = ptr::null_mut();
    let mut n = 0u32;
    // SAFETY: every pointer is null or valid; the handle is destroyed once.
    unsafe {
        assert_eq!(
            nyq_radical_inverse(5000, 1, ptr::null_mut()),
            NyqStatus::NYQ_ERR_NULL
        );
        assert_eq!(nyq_prime(5000, ptr::null_mut()), NyqStatus::NYQ_ERR_NULL);
        assert_eq!(
            nyq_sequence_sample(&bad, 0, 9, ptr::null_mut()),
            NyqStatus::NYQ_ERR_NULL
        );
        assert_eq!(
            nyq_sequence_fill(&bad, 0, 0, ptr::null_mut(), 0, ptr::null_mut()),
            NyqStatus::NYQ_ERR_NULL
        );
        assert_eq!(
            nyq_halton_sample(0, 0, 9, ptr::null_mut()),
            NyqStatus::NYQ_ERR_NULL
        );
        assert_eq!(
            nyq_halton_fill(0, 0, ptr::null_mut(), 0, ptr::null_mut()),
            NyqStatus::NYQ_ERR_NULL
        );
        let mut buf = [0.0f32; 4];
        assert_eq!(
            nyq_halton_fill(0, 0, buf.as_mut_ptr(), 4, ptr::null_mut()),
            NyqStatus::NYQ_ERR_NULL
        );
        assert_eq!(
            nyq_sampler_create_owen_sobol(0, 0, 0, 0, ptr::null_mut()),
            NyqStatus::NYQ_ERR_NULL
        );
        assert_eq!(
            nyq_latin_hypercube(ptr::null_mut(), 0, 0, 0, &mut n),
            NyqStatus::NYQ_ERR_NULL
        );
        assert_eq!(
            nyq_sampler_create(c"bogus".as_ptr(), 0, 0, 0, 0, ptr::null_mut()),
            NyqStatus::NYQ_ERR_NULL
        );
        assert_eq!(
            nyq_filter_create_callback(None, ptr::null_mut(), f32::NAN, 0.0, &mut f),
            NyqStatus::NYQ_ERR_NULL
        );
        assert_eq!(
            nyq_filter_create(c"box".as_ptr(), &mut f),
            NyqStatus::NYQ_OK
        );
        assert_eq!(
            nyq_filter_lookup(f, 9, 0.0, 0.0, ptr::null_mut()),
            NyqStatus::NYQ_ERR_NULL
        );
        nyq_filter_destroy(f);
    }
}

/// The Fibonacci lattice, R_d and Korobov through the C API give the core's values; a point
/// count that is not a Fibonacci number, or a multiplier not coprime to N, is out of range.
#[test]
fn lattices_through_the_c_api() {
    use nyquist::lattice::{FibonacciLattice, Kronecker};
    use nyquist::sequence::Sequence;
    let fib = NyqSequence {
        kind: NyqSequenceKind::NYQ_SEQ_FIBONACCI_ROTATED as u32,
        dims: 2,
        points: 89,
        seed: 3,
        multiplier: 0,
    };
    let rd = NyqSequence {
        kind: NyqSequenceKind::NYQ_SEQ_RD as u32,
        dims: 3,
        points: 0,
        seed: 0,
        multiplier: 0,
    };
    let (f, r) = (
        FibonacciLattice::new(11).unwrap().rotated(3),
        Kronecker::new(3).unwrap(),
    );
    for i in [0u64, 1, 50, 88] {
        for d in 0..2 {
            let mut x = 0.0f32;
            // SAFETY: valid pointers to a sequence and one float.
            assert_eq!(
                unsafe { nyq_sequence_sample(&fib, i, d, &mut x) },
                NyqStatus::NYQ_OK
            );
            assert_eq!(x, f.sample(i, d));
            assert_eq!(
                unsafe { nyq_sequence_sample(&rd, i, d, &mut x) },
                NyqStatus::NYQ_OK
            );
            assert_eq!(x, r.sample(i, d));
        }
    }
    let kor = NyqSequence {
        kind: NyqSequenceKind::NYQ_SEQ_KOROBOV as u32,
        dims: 3,
        points: 1024,
        seed: 0,
        multiplier: 189,
    };
    let k = nyquist::lattice::Korobov::new(1024, 189, 3).unwrap();
    for i in [0u64, 5, 1023] {
        let mut x = 0.0f32;
        // SAFETY: valid pointers to a sequence and one float.
        assert_eq!(
            unsafe { nyq_sequence_sample(&kor, i, 2, &mut x) },
            NyqStatus::NYQ_OK
        );
        assert_eq!(x, k.sample(i, 2));
    }
    let even = NyqSequence {
        multiplier: 190,
        ..kor
    };
    let mut x = 0.0f32;
    // SAFETY: as above.
    assert_eq!(
        unsafe { nyq_sequence_sample(&even, 0, 0, &mut x) },
        NyqStatus::NYQ_ERR_OUT_OF_RANGE
    );
    let bad = NyqSequence { points: 90, ..fib };
    let mut x = 0.0f32;
    // SAFETY: as above.
    assert_eq!(
        unsafe { nyq_sequence_sample(&bad, 0, 0, &mut x) },
        NyqStatus::NYQ_ERR_OUT_OF_RANGE
    );
}

/// Every kind gives the values of the core's `NamedSequence` it names: the plain kinds ignore
/// `seed`, the randomized ones randomize for every seed (0 included), and a Korobov multiplier
/// of 0 is the one nyquist picks (Stroud's table for 101 points in 3 dimensions).
#[test]
fn every_kind_is_the_cores_named_sequence() {
    use nyquist::sequence::{NamedSequence, Sequence, SequenceSpec};
    let kinds = [
        (NyqSequenceKind::NYQ_SEQ_VAN_DER_CORPUT, "vdc", false, 0),
        (NyqSequenceKind::NYQ_SEQ_HALTON, "halton", false, 0),
        (
            NyqSequenceKind::NYQ_SEQ_HALTON_ZAREMBA,
            "halton-zaremba",
            false,
            0,
        ),
        (NyqSequenceKind::NYQ_SEQ_HALTON_SCRAMBLED, "halton", true, 0),
        (NyqSequenceKind::NYQ_SEQ_HAMMERSLEY, "hammersley", false, 16),
        (NyqSequenceKind::NYQ_SEQ_SOBOL, "sobol", false, 0),
        (NyqSequenceKind::NYQ_SEQ_SOBOL_SCRAMBLED, "sobol", true, 0),
        (NyqSequenceKind::NYQ_SEQ_ZERO_TWO, "zero-two", false, 0),
        (
            NyqSequenceKind::NYQ_SEQ_ZERO_TWO_SCRAMBLED,
            "zero-two",
            true,
            0,
        ),
        (
            NyqSequenceKind::NYQ_SEQ_HAMMERSLEY_ZAREMBA,
            "hammersley-zaremba",
            false,
            16,
        ),
        (NyqSequenceKind::NYQ_SEQ_FIBONACCI, "fibonacci", false, 21),
        (NyqSequenceKind::NYQ_SEQ_RD, "rd", false, 0),
        (NyqSequenceKind::NYQ_SEQ_KOROBOV, "korobov", false, 101),
        (
            NyqSequenceKind::NYQ_SEQ_FIBONACCI_ROTATED,
            "fibonacci",
            true,
            21,
        ),
        (NyqSequenceKind::NYQ_SEQ_RD_ROTATED, "rd", true, 0),
        (
            NyqSequenceKind::NYQ_SEQ_KOROBOV_ROTATED,
            "korobov",
            true,
            101,
        ),
        (NyqSequenceKind::NYQ_SEQ_OWEN_SOBOL, "owen-sobol", true, 0),
        (NyqSequenceKind::NYQ_SEQ_PMJ02, "pmj02", false, 0),
        (NyqSequenceKind::NYQ_SEQ_PMJ02_SCRAMBLED, "pmj02", true, 0),
    ];
    for (k, (kind, name, randomized, points)) in kinds.into_iter().enumerate() {
        assert_eq!(kind as usize, k);
        let dims = match name {
            "vdc" => 1,
            "zero-two" | "pmj02" | "fibonacci" => 2,
            _ => 3,
        };
        for seed in [0u64, 77] {
            let c = NyqSequence {
                kind: kind as u32,
                dims,
                points,
                seed,
                multiplier: 0,
            };
            let core = NamedSequence::new(
                name,
                SequenceSpec {
                    dims,
                    points: (points != 0).then_some(points),
                    seed: randomized.then_some(seed),
                    multiplier: None,
                },
            )
            .unwrap();
            let (mut got, mut n) = (vec![0.0f32; 8 * dims as usize], 0u64);
            let len = got.len();
            // SAFETY: valid pointers; `got` holds `len` floats.
            let status = unsafe { nyq_sequence_fill(&c, 1, dims, got.as_mut_ptr(), len, &mut n) };
            assert_eq!(status, NyqStatus::NYQ_OK, "{name}");
            let mut want = vec![0.0f32; len];
            core.fill(1, dims, &mut want).unwrap();
            assert_eq!(got, want, "{name} seed {seed}");
        }
    }
    let korobov = |multiplier| NyqSequence {
        kind: NyqSequenceKind::NYQ_SEQ_KOROBOV as u32,
        dims: 3,
        points: 101,
        seed: 0,
        multiplier,
    };
    let tabled = nyquist::lattice::Korobov::tabled(101, 3)
        .unwrap()
        .multiplier();
    let mut a = [0.0f32; 3];
    let mut b = [0.0f32; 3];
    let mut n = 0u64;
    // SAFETY: valid pointers; three floats each.
    unsafe {
        assert_eq!(
            nyq_sequence_fill(&korobov(0), 1, 3, a.as_mut_ptr(), 3, &mut n),
            NyqStatus::NYQ_OK
        );
        assert_eq!(
            nyq_sequence_fill(&korobov(tabled), 1, 3, b.as_mut_ptr(), 3, &mut n),
            NyqStatus::NYQ_OK
        );
    }
    assert_eq!(a, b);
}

/// Adds `samples` (index, filter weight, value) to a C struct and to the core's `PixelStats`.
fn stats_of(samples: &[(u64, f64, [f64; 3])]) -> (NyqPixelStats, nyquist::pixel_stats::PixelStats) {
    let mut c = NyqPixelStats::default();
    let mut core = nyquist::pixel_stats::PixelStats::default();
    for (index, f, x) in samples {
        // SAFETY: `c` is a valid struct and `x` holds 3 doubles.
        let s = unsafe { nyq_pixel_stats_add(&mut c, *index, *f, x.as_ptr()) };
        assert_eq!(s, NyqStatus::NYQ_OK);
        core.add(*index, *f, *x).unwrap();
    }
    (c, core)
}

/// The C struct's fields equal the core's, bit for bit.
fn assert_same(c: &NyqPixelStats, core: &nyquist::pixel_stats::PixelStats) {
    assert_eq!(c.sum, core.sum);
    assert_eq!(c.weight, core.weight);
    assert_eq!(c.weight2_sum, core.moments.weight2_sum());
    assert_eq!(c.mean, core.moments.mean());
    assert_eq!(c.deviation_sum, core.moments.deviation_sum());
    assert_eq!(c.half_b_sum, core.half_b_sum);
    assert_eq!(c.half_b_weight, core.half_b_weight);
}

proptest! {
    #[test]
    fn pixel_stats_through_the_c_api_are_the_cores(
        samples in proptest::collection::vec(
            (0u64..64, -0.5f64..2.0, proptest::array::uniform3(-10.0f64..10.0)),
            0..24,
        ),
        cut in 0usize..24,
        floor in 0.0f64..1.0,
    ) {
        let cut = cut.min(samples.len());
        let (c, core) = stats_of(&samples);
        assert_same(&c, &core);
        let (mut a, mut a_core) = stats_of(&samples[..cut]);
        let (b, b_core) = stats_of(&samples[cut..]);
        // SAFETY: valid structs.
        prop_assert_eq!(unsafe { nyq_pixel_stats_merge(&mut a, &b) }, NyqStatus::NYQ_OK);
        a_core.merge(&b_core);
        assert_same(&a, &a_core);

        let want = core.estimate();
        let mut e = NyqEstimate::default();
        // SAFETY: valid structs.
        prop_assert_eq!(unsafe { nyq_pixel_stats_estimate(&c, &mut e) }, NyqStatus::NYQ_OK);
        prop_assert_eq!(e.value, want.value);
        prop_assert_eq!((e.has_variance, e.variance), (want.variance.is_some(), want.variance.unwrap_or_default()));
        let [half_a, half_b] = want.halves.unwrap_or_default();
        prop_assert_eq!((e.has_halves, e.half_a, e.half_b), (want.halves.is_some(), half_a, half_b));
        for (kind, estimate) in [
            (NyqErrorEstimate::NYQ_ERROR_HALVES, nyquist::pixel_stats::ErrorEstimate::Halves),
            (NyqErrorEstimate::NYQ_ERROR_VARIANCE, nyquist::pixel_stats::ErrorEstimate::Variance),
        ] {
            let mut r = 0.0;
            // SAFETY: valid structs.
            let s = unsafe { nyq_pixel_stats_relative_error(&c, kind as u32, floor, &mut r) };
            prop_assert_eq!(s, NyqStatus::NYQ_OK);
            let want = want.relative_error(estimate, floor).unwrap_or(f64::INFINITY);
            prop_assert!(r == want || (r.is_nan() && want.is_nan()), "{} against {}", r, want);
        }
    }
}

#[test]
fn pixel_stats_refuse_bad_input_and_keep_the_struct() {
    use NyqStatus::*;
    let (good, _) = stats_of(&[(0, 1.0, [1.0; 3]), (2, 0.5, [3.0, 2.0, 1.0])]);
    let one = [1.0f64; 3];
    let mut s = good;
    let mut e = NyqEstimate::default();
    let mut r = 7.0;
    let mut h = 9u32;
    // SAFETY: every non-null pointer is to a valid value of its type (or 3 doubles).
    unsafe {
        assert_eq!(nyq_sample_half(3, ptr::null_mut()), NYQ_ERR_NULL);
        assert_eq!(nyq_sample_half(3, &mut h), NYQ_OK);
        assert_eq!(h, 1);
        assert_eq!(nyq_sample_half(5, &mut h), NYQ_OK);
        assert_eq!(h, 0);
        assert_eq!(
            nyq_pixel_stats_add(ptr::null_mut(), 0, 1.0, ptr::null()),
            NYQ_ERR_NULL
        );
        assert_eq!(
            nyq_pixel_stats_add(&mut s, 0, 1.0, ptr::null()),
            NYQ_ERR_NULL
        );
        assert_eq!(
            nyq_pixel_stats_add(&mut s, 0, f64::NAN, one.as_ptr()),
            NYQ_ERR_NON_FINITE
        );
        let inf = [1.0, f64::INFINITY, 1.0];
        assert_eq!(
            nyq_pixel_stats_add(&mut s, 0, 1.0, inf.as_ptr()),
            NYQ_ERR_NON_FINITE
        );
        let bytes = [0u64; 4];
        let misaligned = bytes.as_ptr().cast::<u8>().wrapping_add(1).cast::<f64>();
        assert_eq!(
            nyq_pixel_stats_add(&mut s, 0, 1.0, misaligned),
            NYQ_ERR_BUFFER
        );
        assert_eq!(nyq_pixel_stats_merge(&mut s, ptr::null()), NYQ_ERR_NULL);
        assert_eq!(nyq_pixel_stats_merge(ptr::null_mut(), &good), NYQ_ERR_NULL);
        assert_eq!(nyq_pixel_stats_estimate(&s, ptr::null_mut()), NYQ_ERR_NULL);
        assert_eq!(nyq_pixel_stats_estimate(ptr::null(), &mut e), NYQ_ERR_NULL);
        assert_eq!(
            nyq_pixel_stats_relative_error(&s, 2, 0.0, &mut r),
            NYQ_ERR_OUT_OF_RANGE
        );
        assert_eq!(
            nyq_pixel_stats_relative_error(&s, 0, -0.1, &mut r),
            NYQ_ERR_OUT_OF_RANGE
        );
        assert_eq!(
            nyq_pixel_stats_relative_error(&s, 0, f64::NAN, &mut r),
            NYQ_ERR_NON_FINITE
        );
        assert_eq!(
            nyq_pixel_stats_relative_error(ptr::null(), 9, f64::NAN, &mut r),
            NYQ_ERR_NULL
        );
        assert_eq!(
            nyq_pixel_stats_relative_error(&s, 9, f64::NAN, ptr::null_mut()),
            NYQ_ERR_NULL
        );
    }
    assert_eq!((s, e, r), (good, NyqEstimate::default(), 7.0));

    // Structs no samples give: each field broken in turn.
    type Breaks = fn(&mut NyqPixelStats);
    let broken: [(Breaks, NyqStatus); 7] = [
        (|s| s.sum[2] = f64::NAN, NYQ_ERR_NON_FINITE),
        (|s| s.weight = f64::INFINITY, NYQ_ERR_NON_FINITE),
        (|s| s.weight2_sum = -1.0, NYQ_ERR_OUT_OF_RANGE),
        (|s| s.mean[1] = f64::NEG_INFINITY, NYQ_ERR_NON_FINITE),
        (|s| s.deviation_sum[0] = -1e-9, NYQ_ERR_OUT_OF_RANGE),
        (|s| s.half_b_sum[1] = f64::NAN, NYQ_ERR_NON_FINITE),
        (|s| s.half_b_weight = f64::NAN, NYQ_ERR_NON_FINITE),
    ];
    for (i, (breaks, status)) in broken.into_iter().enumerate() {
        let mut bad = good;
        breaks(&mut bad);
        let kept = bad;
        let mut s = good;
        // SAFETY: valid structs and values.
        unsafe {
            assert_eq!(
                nyq_pixel_stats_add(&mut bad, 1, 1.0, one.as_ptr()),
                status,
                "field {i}"
            );
            assert_eq!(nyq_pixel_stats_merge(&mut s, &bad), status, "field {i}");
            assert_eq!(nyq_pixel_stats_merge(&mut bad, &good), status, "field {i}");
            assert_eq!(nyq_pixel_stats_estimate(&bad, &mut e), status, "field {i}");
            assert_eq!(
                nyq_pixel_stats_relative_error(&bad, 1, 0.0, &mut r),
                status,
                "field {i}"
            );
        }
        assert_eq!(
            bad.sum.map(f64::to_bits),
            kept.sum.map(f64::to_bits),
            "field {i}"
        );
        assert_eq!(s, good, "field {i}");
    }
}

#[test]
fn pixel_stats_merged_with_themselves_count_each_sample_twice() {
    let samples = [
        (0, 1.0, [1.0; 3]),
        (1, 0.5, [4.0; 3]),
        (2, 2.0, [2.0; 3]),
        (3, 1.0, [0.5; 3]),
    ];
    let (mut s, _) = stats_of(&samples);
    let twice: Vec<_> = samples.iter().chain(&samples).copied().collect();
    let (_, want) = stats_of(&twice);
    let p: *mut NyqPixelStats = &mut s;
    // SAFETY: `p` points to a valid struct; the function allows `other == stats`.
    assert_eq!(unsafe { nyq_pixel_stats_merge(p, p) }, NyqStatus::NYQ_OK);
    assert_eq!(
        (s.sum, s.weight, s.weight2_sum),
        (want.sum, want.weight, want.moments.weight2_sum())
    );
    assert_eq!(s.half_b_sum, want.half_b_sum);
    for c in 0..3 {
        assert!((s.deviation_sum[c] - want.moments.deviation_sum()[c]).abs() < 1e-12);
    }
}
