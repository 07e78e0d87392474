//! `nyquist::stratify`: stratified 1D/2D, Latin hypercubes (stateful and stateless) and shuffles
//! for any buffer length and dimension count.

use nyquist::Error;
use nyquist::rng::default_rng;
use nyquist::stratify::{
    Jitter, LatinHypercube, latin_hypercube, shuffle, stratified_1d, stratified_2d,
};

use crate::{Bytes, in_unit};

/// The stratum of `x` among `n`: exact, since `x` has 24 significant bits and `n < 2³²`.
fn stratum(x: f32, n: u32) -> u64 {
    (f64::from(x) * f64::from(n)).floor() as u64
}

/// Every column of a point-major buffer hits each of its `n` strata exactly once.
fn assert_latin(what: &str, out: &[f32], dims: usize, n: u32) {
    for d in 0..dims {
        let mut hit = vec![false; n as usize];
        for p in out.chunks_exact(dims) {
            assert!(in_unit(p[d]), "{what}: value {} not in [0, 1)", p[d]);
            let s = stratum(p[d], n) as usize;
            assert!(
                !hit[s],
                "{what}: dimension {d} hits stratum {s} twice (n = {n})"
            );
            hit[s] = true;
        }
    }
}

/// Stratification: every call returns `Ok` or the typed error its docs name for that input —
/// never a panic; on `Ok`, every value is in `[0, 1)` and in its stratum (1D: sample `k` in
/// `[k/n, (k+1)/n)`; 2D: point `j·nx + i` in cell `(i, j)`; LHS: every dimension's `n` strata hit
/// once); `LatinHypercube::fill` is deterministic; `shuffle` permutes whole blocks.
pub fn stratify(data: &[u8]) {
    let mut b = Bytes::new(data);
    let op = b.u8() % 5;
    let seed = b.u64();
    let jitter = if b.bool() {
        Jitter::Jittered
    } else {
        Jitter::Centered
    };
    let mut rng = default_rng(seed);
    match op {
        0 => {
            let len = b.below(2000) as usize;
            let mut out = vec![5.0f32; len];
            let r = stratified_1d(&mut out, jitter, &mut rng);
            if len == 0 {
                assert!(
                    matches!(r, Err(Error::ZeroSize { .. })),
                    "stratified_1d(empty): {r:?}"
                );
                return;
            }
            assert_eq!(r, Ok(()), "stratified_1d(len {len})");
            for (k, &x) in out.iter().enumerate() {
                assert!(in_unit(x), "stratified_1d: {x}");
                assert_eq!(
                    stratum(x, len as u32),
                    k as u64,
                    "stratified_1d: sample {k} = {x} of {len}"
                );
            }
        }
        1 => {
            let (nx, ny) = if b.bool() {
                (b.below(40), b.below(40))
            } else {
                (b.u32(), b.u32())
            };
            let needed = (nx as usize)
                .checked_mul(ny as usize)
                .and_then(|c| c.checked_mul(2));
            let exact = needed.unwrap_or(usize::MAX);
            let len = match b.u8() % 3 {
                0 => exact,
                1 => exact.saturating_add(b.below(2) as usize).saturating_sub(1),
                _ => b.below(4000) as usize,
            }
            .min(8000);
            let mut out = vec![5.0f32; len];
            let r = stratified_2d(&mut out, nx, ny, jitter, &mut rng);
            let want = if nx == 0 || ny == 0 {
                Err("zero")
            } else {
                match needed {
                    None => Err("too many"),
                    Some(n) if len < n => Err("short"),
                    Some(n) if len > n => Err("long"),
                    Some(_) => Ok(()),
                }
            };
            match (&r, want) {
                (Ok(()), Ok(())) => {
                    for (k, p) in out.chunks_exact(2).enumerate() {
                        let (i, j) = (k as u64 % u64::from(nx), k as u64 / u64::from(nx));
                        assert!(in_unit(p[0]) && in_unit(p[1]), "stratified_2d: {p:?}");
                        assert_eq!(
                            (stratum(p[0], nx), stratum(p[1], ny)),
                            (i, j),
                            "stratified_2d {nx}×{ny}: point {k} = {p:?}"
                        );
                    }
                }
                (Err(Error::ZeroSize { .. }), Err("zero"))
                | (Err(Error::TooMany { .. }), Err("too many"))
                | (Err(Error::BufferTooShort { .. }), Err("short"))
                | (Err(Error::BufferLength { .. }), Err("long")) => {}
                (r, w) => panic!("stratified_2d({nx}, {ny}, len {len}) = {r:?}, expected {w:?}"),
            }
        }
        2 | 3 => {
            let dims = if b.bool() { b.below(6) } else { b.u32() };
            let len = b.below(3000) as usize;
            let mut out = vec![5.0f32; len];
            let valid = dims > 0 && len > 0 && len.is_multiple_of(dims as usize);
            let r = if op == 2 {
                latin_hypercube(&mut out, dims, &mut rng)
            } else {
                match LatinHypercube::new(dims, seed) {
                    Ok(lhs) => {
                        assert!(dims > 0);
                        assert_eq!(lhs.dims(), dims);
                        let n = (len as u32) / dims.max(1);
                        assert_eq!(lhs.required_len(n), Some(n as usize * dims as usize));
                        let r = lhs.fill(&mut out);
                        let mut again = vec![6.0f32; len];
                        let r2 = lhs.fill(&mut again);
                        assert_eq!(r, r2);
                        if r.is_ok() {
                            assert_eq!(out, again, "LatinHypercube::fill is not deterministic");
                        }
                        r
                    }
                    Err(e) => {
                        assert_eq!(dims, 0, "LatinHypercube::new({dims}): {e:?}");
                        assert!(matches!(e, Error::ZeroSize { .. }));
                        return;
                    }
                }
            };
            match r {
                Ok(n) => {
                    assert!(valid, "LHS (op {op}) accepted dims {dims}, len {len}");
                    assert_eq!(n as usize, len / dims as usize, "LHS point count");
                    assert_latin("LHS", &out, dims as usize, n);
                }
                Err(e) => {
                    assert!(
                        !valid,
                        "LHS (op {op}) rejected dims {dims}, len {len}: {e:?}"
                    );
                    assert!(
                        matches!(e, Error::ZeroSize { .. } | Error::BufferLength { .. }),
                        "LHS: {e:?}"
                    );
                }
            }
        }
        _ => {
            let dims = match b.u8() % 3 {
                0 => b.below(5) as usize,
                1 => b.u64() as usize,
                _ => 1,
            };
            let count = match b.u8() % 3 {
                0 => b.below(500) as usize,
                1 => b.u64() as usize,
                _ => usize::MAX,
            };
            let len = match b.u8() % 2 {
                0 => count.saturating_mul(dims).min(4000),
                _ => b.below(4000) as usize,
            };
            let mut buf: Vec<u32> = (0..len as u32).collect();
            let r = shuffle(&mut buf, count, dims, &mut rng);
            let want = if dims == 0 {
                "zero"
            } else {
                match count.checked_mul(dims) {
                    None => "too many",
                    Some(_) if len % dims != 0 => "length",
                    Some(n) if len < n => "short",
                    Some(n) if len > n => "long",
                    Some(_) => "ok",
                }
            };
            match (&r, want) {
                (Ok(()), "ok") => {
                    let mut seen = vec![false; count];
                    for block in buf.chunks_exact(dims) {
                        let id = block[0] as usize / dims;
                        assert_eq!(
                            block[0] as usize % dims,
                            0,
                            "shuffle split a block: {block:?}"
                        );
                        for (k, &v) in block.iter().enumerate() {
                            assert_eq!(
                                v as usize,
                                id * dims + k,
                                "shuffle split a block: {block:?}"
                            );
                        }
                        assert!(!seen[id], "shuffle duplicated block {id}");
                        seen[id] = true;
                    }
                }
                (Err(Error::ZeroSize { .. }), "zero")
                | (Err(Error::TooMany { .. }), "too many")
                | (Err(Error::BufferLength { .. }), "length")
                | (Err(Error::BufferTooShort { .. }), "short")
                | (Err(Error::NotInRange { .. }), "long") => {
                    let same = buf.iter().enumerate().all(|(i, &v)| v as usize == i);
                    assert!(same, "shuffle changed the buffer and failed");
                }
                (r, w) => {
                    panic!("shuffle(len {len}, count {count}, dims {dims}) = {r:?}, expected {w}")
                }
            }
        }
    }
}
