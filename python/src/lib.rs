//! `nyquist._core`: the Rust side of the Python package. Each function validates its arguments
//! with the core's own checks (a bad one raises `ValueError` with the core's one-line message),
//! releases the GIL while it computes, and returns a NumPy array that owns the `Vec` it was
//! computed into (no copy). The Python layer (`nyquist/qmc.py`) gives these SciPy's
//! `stats.qmc` interface.

use numpy::{IntoPyArray, PyArray2, PyArrayMethods};
use pyo3::exceptions::{PyMemoryError, PyValueError};
use pyo3::prelude::*;

mod design;
mod measures;
mod pixel;

use nyquist::hash::hash2;
use nyquist::radical::positional_radical_inverse_column_f64;
use nyquist::scramble::{Scramble, fast_owen_scramble};
use nyquist::sequence::{
    Halton, NamedSequence, SOBOL_DIMS, ScrambledHalton, Sequence, SequenceSpec, Sobol,
};

/// A `ValueError` with the core error's message.
pub(crate) fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// `len` copies of `value`, or a `MemoryError` when the allocation fails (instead of the
/// abort a failed `vec!` would be).
pub(crate) fn filled<T: Clone>(len: usize, value: T) -> PyResult<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| {
        PyMemoryError::new_err(format!(
            "{len} values of {} bytes do not fit in memory",
            std::mem::size_of::<T>()
        ))
    })?;
    v.resize(len, value);
    Ok(v)
}

/// The number of values of an `n × d` array, or a `ValueError` when it does not fit.
pub(crate) fn values(n: u64, d: u32) -> PyResult<usize> {
    usize::try_from(n)
        .ok()
        .and_then(|n| n.checked_mul(d as usize))
        .ok_or_else(|| value_error(format!("n {n} × d {d} values do not fit in memory")))
}

/// Checks that points `first .. first + n` exist in a set of `count` points.
fn check_range(first: u64, n: u64, count: u64, what: &str) -> PyResult<()> {
    match first.checked_add(n) {
        Some(end) if end <= count => Ok(()),
        _ => Err(value_error(format!(
            "points {first}..{} are past the {count} points of {what}",
            first as u128 + n as u128
        ))),
    }
}

/// Wraps `v` (row-major, `n × d`) as an `(n, d)` array without copying.
fn array(py: Python<'_>, v: Vec<f64>, n: u64, d: u32) -> PyResult<Bound<'_, PyArray2<f64>>> {
    v.into_pyarray(py).reshape([n as usize, d as usize])
}

/// The index of the `k`-th point in Gray-code order: `k ^ (k >> 1)`.
fn gray(k: u64) -> u64 {
    k ^ (k >> 1)
}

/// Points `first .. first + n` of the `d`-dimensional Sobol sequence (Joe–Kuo 6.21201
/// direction numbers), as an `(n, d)` float64 array, in Gray-code order, SciPy's: point k is the
/// sequence's point `k ^ (k >> 1)`, so every power-of-two prefix is the same set as in natural
/// order. With a seed each coordinate is Owen-scrambled: Burley's hash-based nested uniform
/// scramble (the core's `fast_owen_scramble`), keyed per dimension by `hash2(seed, dimension)`.
/// `bits` (1 to 32) keeps that many leading bits of each coordinate, as SciPy's `bits` does.
#[pyfunction]
#[pyo3(signature = (n, d, first=0, seed=None, bits=32))]
fn sobol<'py>(
    py: Python<'py>,
    n: u64,
    d: u32,
    first: u64,
    seed: Option<u64>,
    bits: u32,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let len = values(n, d)?;
    // Every 64-bit index is a point: the range must end by 2⁶⁴.
    if n > 0 && first.checked_add(n - 1).is_none() {
        return Err(value_error(format!(
            "points {first}..{} are past the 2**64 points of the Sobol sequence",
            u128::from(first) + u128::from(n)
        )));
    }
    if !(1..=64).contains(&bits) {
        return Err(value_error(format!("bits {bits} is outside 1..=64")));
    }
    let s = Sobol::new(d).map_err(value_error)?;
    let keys: Option<Vec<u32>> = seed.map(|seed| {
        (0..u64::from(d))
            .map(|dim| hash2(seed, dim) as u32)
            .collect()
    });
    let mut v = filled(len, 0.0)?;
    let dims = d as usize;
    py.detach(|| {
        par_rows(&mut v, dims, first, |f, b| {
            sobol_gray(&s, f, d, bits, keys.as_deref(), b)
        })
    });
    array(py, v, n, d)
}

/// Splits the rows of `out` (`d` values each, the first at index `first`) over the machine's
/// threads, in contiguous blocks of at least 2¹⁴ rows, and runs `fill(first_row, block)` on
/// each; one block on one thread when the work is small.
pub(crate) fn par_rows(
    out: &mut [f64],
    d: usize,
    first: u64,
    fill: impl Fn(u64, &mut [f64]) + Sync,
) {
    let rows = out.len() / d.max(1);
    let threads = std::thread::available_parallelism().map_or(1, |t| t.get());
    let blocks = threads.min(rows / (1 << 14)).max(1);
    if blocks == 1 {
        fill(first, out);
        return;
    }
    let per = rows.div_ceil(blocks);
    std::thread::scope(|scope| {
        for (k, block) in out.chunks_mut(per * d).enumerate() {
            let fill = &fill;
            scope.spawn(move || fill(first + (k * per) as u64, block));
        }
    });
}

/// Sobol points in Gray-code order into `out` (rows of `d`, the first row point `first`),
/// Owen-scrambled with one key per dimension when `keys` is given, keeping `bits` bits: from
/// one point to the next the Gray code flips bit `t` (the trailing zeros of k + 1), so every
/// coordinate changes by the XOR of its direction column `t`. Row by row, so the writes are
/// sequential.
fn sobol_gray(s: &Sobol, first: u64, d: u32, bits: u32, keys: Option<&[u32]>, out: &mut [f64]) {
    let d_us = d as usize;
    // Dimensions past 1024 are the core's padding, not linear in the index: computed point by
    // point below. The first ones step by the Gray code: columns[t][dim], the direction number
    // t (of 64) of dimension dim.
    let linear = d.min(SOBOL_DIMS);
    let columns: Vec<u32> = (0..64)
        .flat_map(|t| (0..linear).map(move |dim| s.sample_u32(1 << t, dim)))
        .collect();
    let mut x: Vec<u32> = (0..d).map(|dim| s.sample_u32(gray(first), dim)).collect();
    let mask = keep(bits);
    for (j, row) in out.chunks_exact_mut(d_us).enumerate() {
        let k = first + j as u64;
        for (dim, v) in x.iter_mut().enumerate().skip(linear as usize) {
            *v = s.sample_u32(gray(k), dim as u32);
        }
        match keys {
            None => {
                for (o, &v) in row.iter_mut().zip(&x) {
                    *o = f64::from(v & mask) * (1.0 / 4_294_967_296.0);
                }
            }
            Some(keys) => {
                for ((o, &v), &key) in row.iter_mut().zip(&x).zip(keys) {
                    let scrambled = fast_owen_scramble(v, key);
                    *o = f64::from(scrambled & mask) * (1.0 / 4_294_967_296.0);
                }
            }
        }
        // The step to point k + 1 (after the last point, never used).
        let t = (k.wrapping_add(1).trailing_zeros() as usize).min(63);
        let l = linear as usize;
        for (v, c) in x.iter_mut().zip(&columns[t * l..(t + 1) * l]) {
            *v ^= c;
        }
    }
}

/// The mask that keeps the top `bits` of a 32-bit value (SciPy's `bits`; from 32 on, every bit
/// of nyquist's 32-bit values).
fn keep(bits: u32) -> u32 {
    if bits >= 32 {
        u32::MAX
    } else {
        !(u32::MAX >> bits)
    }
}

/// Points of `s` (its first `d` dimensions) into `out`, rows of `d`, the first row point
/// `first`.
fn fill_rows(s: &(impl Sequence + Sync), first: u64, d: u32, out: &mut [f64]) {
    for (index, row) in (first..).zip(out.chunks_exact_mut(d as usize)) {
        for (dim, x) in (0..d).zip(row) {
            *x = s.sample_f64(index, dim);
        }
    }
}

/// Points `first ..` of `s` into `out`, `(n, d)` row-major, on every thread.
fn fill_f64(s: &(impl Sequence + Sync), first: u64, d: u32, out: &mut [f64]) {
    par_rows(out, d as usize, first, |f, block| fill_rows(s, f, d, block));
}

/// Points `first .. first + n` of the `d`-dimensional Halton sequence (radical inverses in
/// the first `d` primes), as an `(n, d)` float64 array; with a seed, randomized by `scramble`:
/// - `"permute-positions"`: each digit position through its own random permutation (Owen's
///   randomized Halton, SciPy's law; the core's `positional_radical_inverse_column_f64`), for
///   the first 2⁴² points;
/// - `"permute-digits"`: one permutation per base (the core's `ScrambledHalton::fill_f64`);
/// - `"fast-owen"` or `"owen"`: nested uniform digit permutations, value by value.
#[pyfunction]
#[pyo3(signature = (n, d, first=0, seed=None, scramble="permute-positions"))]
fn halton<'py>(
    py: Python<'py>,
    n: u64,
    d: u32,
    first: u64,
    seed: Option<u64>,
    scramble: &str,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let len = values(n, d)?;
    check_range(first, n, u64::MAX, "the Halton sequence")?;
    let Some(seed) = seed else {
        let s = Halton::new(d).map_err(value_error)?;
        let mut v = filled(len, 0.0)?;
        py.detach(|| fill_f64(&s, first, d, &mut v));
        return array(py, v, n, d);
    };
    let strategy = match scramble {
        "permute-positions" => None,
        "permute-digits" => Some(Scramble::PermuteDigits),
        "fast-owen" => Some(Scramble::FastOwen),
        "owen" => Some(Scramble::Owen),
        other => {
            return Err(value_error(format!(
                "scramble '{other}' is not one of 'permute-positions', 'permute-digits', 'fast-owen', 'owen'"
            )));
        }
    };
    let s = ScrambledHalton::with_strategy(d, strategy.unwrap_or(Scramble::None), seed)
        .map_err(value_error)?;
    if strategy.is_none() {
        check_range(
            first,
            n,
            1 << 42,
            "a Halton sequence with permuted digit positions",
        )?;
    }
    let mut v = filled(len, 0.0)?;
    if len == 0 {
        return array(py, v, n, d);
    }
    let failed = std::sync::Mutex::new(None);
    let dims = d as usize;
    py.detach(|| {
        par_rows(&mut v, dims, first, |f, block| {
            let done = match strategy {
                None => positional_rows(f, d, seed, block),
                Some(_) => s.fill_f64(f, d, block).map(|_| ()),
            };
            if let Err(e) = done {
                *failed.lock().unwrap_or_else(|p| p.into_inner()) = Some(e);
            }
        })
    });
    if let Some(e) = failed.into_inner().unwrap_or_else(|p| p.into_inner()) {
        return Err(value_error(e));
    }
    array(py, v, n, d)
}

/// Halton points `first ..` with permuted digit positions into `out` (rows of `d`): each
/// dimension of a block of 4096 rows by the core's column writer, so the block stays in cache
/// (256 KB at d = 8) and each column's set-up (up to 53 digits and their permutations) is paid
/// once per 4096 values.
fn positional_rows(first: u64, d: u32, seed: u64, out: &mut [f64]) -> Result<(), nyquist::Error> {
    const BLOCK: usize = 4096;
    let dims = d as usize;
    for (b, block) in out.chunks_mut(BLOCK * dims).enumerate() {
        let start = first + (b * BLOCK) as u64;
        for (dim, column) in (0..d).zip(0..dims) {
            positional_radical_inverse_column_f64(dim, start, seed, &mut block[column..], dims)?;
        }
    }
    Ok(())
}

/// Points `first .. first + n` of the named point set `name` (any of the core's
/// `SEQUENCE_NAMES`: `pmj02`, `zero-two`, `fibonacci`, `korobov`, `rd`, …) in `d` dimensions, as
/// an `(n, d)` float64 array: `points` is the size of a finite set (required by `fibonacci`,
/// `korobov`, `hammersley`), `seed` the family's randomization (Owen scramble, digital shift or
/// Cranley–Patterson rotation), `multiplier` Korobov's.
#[pyfunction]
#[pyo3(signature = (name, n, d, first=0, seed=None, points=None, multiplier=None))]
#[allow(clippy::too_many_arguments)]
fn sequence<'py>(
    py: Python<'py>,
    name: &str,
    n: u64,
    d: u32,
    first: u64,
    seed: Option<u64>,
    points: Option<u64>,
    multiplier: Option<u64>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let len = values(n, d)?;
    let spec = SequenceSpec {
        dims: d,
        points,
        seed,
        multiplier,
    };
    let s = NamedSequence::new(name, spec).map_err(value_error)?;
    let count = s.point_count().unwrap_or(u64::MAX);
    check_range(first, n, count, &format!("the {name} set"))?;
    let mut v = filled(len, 0.0)?;
    py.detach(|| fill_f64(&s, first, d, &mut v));
    array(py, v, n, d)
}

/// The extension module.
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(sobol, m)?)?;
    m.add_function(wrap_pyfunction!(halton, m)?)?;
    m.add_function(wrap_pyfunction!(sequence, m)?)?;
    m.add_function(wrap_pyfunction!(measures::discrepancy, m)?)?;
    m.add_function(wrap_pyfunction!(measures::update_discrepancy, m)?)?;
    m.add_function(wrap_pyfunction!(measures::geometric_discrepancy, m)?)?;
    m.add_function(wrap_pyfunction!(measures::t_value, m)?)?;
    m.add_function(wrap_pyfunction!(measures::periodogram, m)?)?;
    m.add_function(wrap_pyfunction!(design::latin_hypercube, m)?)?;
    m.add_class::<design::PoissonDiskState>()?;
    m.add_function(wrap_pyfunction!(pixel::pixel_samples, m)?)?;
    m.add_class::<pixel::Filter>()?;
    Ok(())
}
