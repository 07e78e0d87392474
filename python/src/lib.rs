//! `nyquist._core`: the Rust side of the Python package. Each function validates its arguments
//! with the core's own checks (a bad one raises `ValueError` with the core's one-line message),
//! releases the GIL while it computes, and returns a NumPy array that owns the `Vec` it was
//! computed into (no copy). The Python layer (`nyquist/qmc.py`) gives these SciPy's
//! `stats.qmc` interface.

use numpy::{IntoPyArray, PyArray2, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

mod design;
mod measures;
mod pixel;

use nyquist::scramble::Scramble;
use nyquist::sequence::{
    Halton, NamedSequence, OwenSobol, ScrambledHalton, Sequence, SequenceSpec, Sobol,
};

/// A `ValueError` with the core error's message.
pub(crate) fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
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
/// direction numbers), as an `(n, d)` float64 array. Unscrambled (`seed` None) the points come
/// in Gray-code order, SciPy's: point k is the sequence's point `k ^ (k >> 1)`, so every
/// power-of-two prefix is the same set as in natural order. With a seed they are Owen-scrambled
/// (nyquist's hash-based nested uniform scramble, by index, natural order). `bits` (1 to 32)
/// keeps that many leading bits of each coordinate, as SciPy's `bits` does.
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
    check_range(first, n, 1 << 32, "the Sobol sequence")?;
    if !(1..=32).contains(&bits) {
        return Err(value_error(format!("bits {bits} is outside 1..=32")));
    }
    let mut v = vec![0.0; len];
    let dims = d as usize;
    match seed {
        None => {
            let s = Sobol::new(d).map_err(value_error)?;
            py.detach(|| par_rows(&mut v, dims, first, |f, b| sobol_gray(&s, f, d, bits, b)));
        }
        Some(seed) => {
            let s = OwenSobol::new(d, seed).map_err(value_error)?;
            py.detach(|| {
                par_rows(&mut v, dims, first, |f, b| {
                    owen_sobol_rows(&s, f, d, bits, b)
                })
            });
        }
    }
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

/// Unscrambled Sobol points in Gray-code order into `out` (rows of `d`, the first row point
/// `first`), keeping `bits` bits: from one point to the next the Gray code flips bit `t` (the
/// trailing zeros of k + 1), so every coordinate changes by the XOR of its direction column
/// `t`. Row by row, so the writes are sequential.
fn sobol_gray(s: &Sobol, first: u64, d: u32, bits: u32, out: &mut [f64]) {
    let d_us = d as usize;
    // columns[t][dim]: the direction number t of dimension dim.
    let columns: Vec<u32> = (0..32)
        .flat_map(|t| (0..d).map(move |dim| s.sample_u32(1 << t, dim)))
        .collect();
    let mut x: Vec<u32> = (0..d).map(|dim| s.sample_u32(gray(first), dim)).collect();
    let mask = keep(bits);
    for (k, row) in (first..).zip(out.chunks_exact_mut(d_us)) {
        for (o, &v) in row.iter_mut().zip(&x) {
            *o = f64::from(v & mask) * (1.0 / 4_294_967_296.0);
        }
        // k + 1 < 2³² here except after the last point, whose step is never used.
        let t = ((k + 1).trailing_zeros() as usize).min(31);
        for (v, c) in x.iter_mut().zip(&columns[t * d_us..(t + 1) * d_us]) {
            *v ^= c;
        }
    }
}

/// The mask that keeps the top `bits` of a 32-bit value (SciPy's `bits`).
fn keep(bits: u32) -> u32 {
    if bits >= 32 {
        u32::MAX
    } else {
        !(u32::MAX >> bits)
    }
}

/// Owen-scrambled Sobol points into `out` (rows of `d`, the first row point `first`), keeping
/// `bits` bits.
fn owen_sobol_rows(s: &OwenSobol, first: u64, d: u32, bits: u32, out: &mut [f64]) {
    let mask = keep(bits);
    for (index, row) in (first..).zip(out.chunks_exact_mut(d as usize)) {
        for (dim, o) in (0..d).zip(row) {
            *o = f64::from(s.sample_u32(index as u32, dim) & mask) * (1.0 / 4_294_967_296.0);
        }
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

/// Points `first .. first + n` of `s`, `(n, d)` row-major, on every thread.
fn fill_f64(s: &(impl Sequence + Sync), first: u64, d: u32, len: usize) -> Vec<f64> {
    let mut out = vec![0.0; len];
    par_rows(&mut out, d as usize, first, |f, block| {
        fill_rows(s, f, d, block)
    });
    out
}

/// Points `first .. first + n` of the `d`-dimensional Halton sequence (radical inverses in
/// the first `d` primes), as an `(n, d)` float64 array; with a seed, Owen-scrambled in each
/// base (nested uniform digit permutations, nyquist's `ScrambledHalton` with `Scramble::Owen`).
#[pyfunction]
#[pyo3(signature = (n, d, first=0, seed=None))]
fn halton<'py>(
    py: Python<'py>,
    n: u64,
    d: u32,
    first: u64,
    seed: Option<u64>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let len = values(n, d)?;
    check_range(first, n, u64::MAX, "the Halton sequence")?;
    let v = match seed {
        None => {
            let s = Halton::new(d).map_err(value_error)?;
            py.detach(|| fill_f64(&s, first, d, len))
        }
        Some(seed) => {
            let s = ScrambledHalton::with_strategy(d, Scramble::Owen, seed).map_err(value_error)?;
            py.detach(|| fill_f64(&s, first, d, len))
        }
    };
    array(py, v, n, d)
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
    let v = py.detach(|| fill_f64(&s, first, d, len));
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
