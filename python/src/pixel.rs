//! The renderer's side: pixel samplers by (pixel, sample, dimension), and reconstruction
//! filters with their tables and importance sampling.

use numpy::PyUntypedArrayMethods;
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::prelude::*;

use nyquist::filter::{Filter as _, FilterKind, FilterSampler, Interpolation, Table2d};
use nyquist::sampler::{NamedSampler, Sampler};
use nyquist::scramble::Scramble;

use crate::{filled, value_error, values};

fn scramble_of(name: &str) -> PyResult<Scramble> {
    Ok(match name {
        "none" => Scramble::None,
        "permute-digits" => Scramble::PermuteDigits,
        "fast-owen" => Scramble::FastOwen,
        "owen" => Scramble::Owen,
        other => {
            return Err(value_error(format!(
                "scramble '{other}' is not one of 'none', 'permute-digits', 'fast-owen', 'owen'"
            )));
        }
    })
}

/// Samples `first .. first + n` of pixel `pixel` from the named pixel sampler (any of the
/// core's `sampler::NAMES`: `zsobol`, `pmj02`, `sobol`, `best-candidate`, …) built for an
/// image of `size` pixels at `spp` samples per pixel, as an `(n, d)` float64 array of the
/// sampler's `f32` values. Each row is one pixel sample: its first two values are the image
/// sample (`get_pixel_2d`), then 2-D draws (`get_2d`), and a last 1-D draw (`get_1d`) when `d`
/// is odd; `d = 1` gives `get_1d` alone. `scramble` chooses the scramble of `halton`,
/// `hammersley`, `sobol` and `zsobol`.
#[pyfunction]
#[pyo3(signature = (name, pixel, n, d, *, first=0, size=(1, 1), spp=None, seed=0, scramble=None))]
#[allow(clippy::too_many_arguments)]
pub fn pixel_samples<'py>(
    py: Python<'py>,
    name: &str,
    pixel: (u32, u32),
    n: u32,
    d: u32,
    first: u32,
    size: (u32, u32),
    spp: Option<u32>,
    seed: u64,
    scramble: Option<&str>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let size = [size.0, size.1];
    let spp = match spp {
        Some(s) => s,
        None => first.checked_add(n).ok_or_else(|| {
            value_error(format!(
                "samples {first}..{} are past the 2^32 samples a pixel has",
                u64::from(first) + u64::from(n)
            ))
        })?,
    }
    .max(1);
    let mut sampler = match scramble {
        None => NamedSampler::new(name, size, spp, seed),
        Some(s) => NamedSampler::with_scramble(name, size, spp, seed, scramble_of(s)?),
    }
    .map_err(value_error)?;
    if pixel.0 >= size[0] || pixel.1 >= size[1] {
        return Err(value_error(format!(
            "pixel ({}, {}) is outside the {}×{} image",
            pixel.0, pixel.1, size[0], size[1]
        )));
    }
    let end = u64::from(first) + u64::from(n);
    if end > u64::from(sampler.samples_per_pixel()) {
        return Err(value_error(format!(
            "samples {first}..{end} are past the {} samples per pixel of this {name} sampler",
            sampler.samples_per_pixel()
        )));
    }
    let dims = d as usize;
    let mut out = filled(values(u64::from(n), d)?, 0.0f64)?;
    py.detach(|| {
        for (s, row) in (first..).zip(out.chunks_exact_mut(dims.max(1))) {
            sampler.start_pixel_sample([pixel.0, pixel.1], s, 0);
            let mut k = 0;
            if dims >= 2 {
                let [a, b] = sampler.get_pixel_2d();
                row[0] = f64::from(a);
                row[1] = f64::from(b);
                k = 2;
            }
            while k + 2 <= dims {
                let [a, b] = sampler.get_2d();
                row[k] = f64::from(a);
                row[k + 1] = f64::from(b);
                k += 2;
            }
            if k < dims {
                row[k] = f64::from(sampler.get_1d());
            }
        }
    });
    out.into_pyarray(py).reshape([n as usize, dims])
}

/// A filter table's values and sample points, as `Filter.table` returns them.
type TableArrays<'py> = (
    Bound<'py, PyArray2<f32>>,
    Bound<'py, PyArray1<f32>>,
    Bound<'py, PyArray1<f32>>,
);

/// Importance samples' offsets and weights, as `Filter.sample` returns them.
type FilterSamples<'py> = (Bound<'py, PyArray2<f32>>, Bound<'py, PyArray1<f32>>);

/// A reconstruction filter from a spec such as `"mitchell"`, `"gaussian:sigma=0.5"` or
/// `"lanczos:radius=3,tau=3"` (the CLI's `--filter`; the core's `FilterKind::parse`).
///
/// - `name`, `spec`, `radius` (half-widths in pixels), `integral`, `separable`;
/// - `evaluate(x, y)`: the filter at offsets from the pixel centre;
/// - `table(n=16)`: the film's `n × n` table `(values, xs, ys)`;
/// - `sample(u)`: importance samples `(offsets, weights)` from `(n, 2)` uniforms, with
///   `weights = f / pdf` (the core's `FilterSampler` on a 32 × 32 grid); `pdf(offsets)`.
#[pyclass(module = "nyquist._core", frozen)]
pub struct Filter {
    kind: FilterKind,
    sampler: FilterSampler<FilterKind, 32>,
}

#[pymethods]
impl Filter {
    #[new]
    fn new(spec: &str) -> PyResult<Self> {
        let kind = FilterKind::parse(spec).map_err(value_error)?;
        let sampler = FilterSampler::new(kind).map_err(value_error)?;
        Ok(Filter { kind, sampler })
    }

    /// The canonical spec, which parses back to the same filter.
    fn __repr__(&self) -> String {
        format!("Filter({:?})", self.kind.to_string())
    }

    /// The filter's name (`"mitchell"`, …).
    #[getter]
    fn name(&self) -> &'static str {
        self.kind.name()
    }

    /// The spec string (`FilterKind`'s `Display`).
    #[getter]
    fn spec(&self) -> String {
        self.kind.to_string()
    }

    /// The support's half-widths `(rx, ry)` in pixels.
    #[getter]
    fn radius(&self) -> (f32, f32) {
        let [x, y] = self.kind.radius();
        (x, y)
    }

    /// `∫∫ f` over the support.
    #[getter]
    fn integral(&self) -> f32 {
        self.kind.integral()
    }

    /// Whether `f(x, y) = f_x(x)·f_y(y)`.
    #[getter]
    fn separable(&self) -> bool {
        self.kind.is_separable()
    }

    /// `f(x, y)` at each pair of offsets (pixels from the centre); 0 outside the support.
    fn evaluate<'py>(
        &self,
        py: Python<'py>,
        x: PyReadonlyArray1<'py, f64>,
        y: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray1<f32>>> {
        let (x, y) = (
            x.as_slice().map_err(value_error)?,
            y.as_slice().map_err(value_error)?,
        );
        if x.len() != y.len() {
            return Err(value_error(format!(
                "x has {} values and y {}",
                x.len(),
                y.len()
            )));
        }
        let v: Vec<f32> = x
            .iter()
            .zip(y)
            .map(|(&a, &b)| self.kind.eval(a as f32, b as f32))
            .collect();
        Ok(v.into_pyarray(py))
    }

    /// The film's table: the filter tabulated at `n × n` points of its support (`n` 8, 16, 32
    /// or 64; the core's `Table2d`), as `(values, xs, ys)`: `values[j, i]` is `f(xs[i], ys[j])`.
    #[pyo3(signature = (n=16))]
    fn table<'py>(&self, py: Python<'py>, n: usize) -> PyResult<TableArrays<'py>> {
        fn build<const N: usize>(kind: &FilterKind) -> PyResult<(Vec<f32>, Vec<f32>, Vec<f32>)> {
            let t: Table2d<N> = Table2d::new(kind, Interpolation::Linear).map_err(value_error)?;
            let values = t.values().iter().flatten().copied().collect();
            let axis = |a| (0..N).map(|i| t.sample_point(a, i)).collect();
            Ok((
                values,
                axis(nyquist::filter::Axis::X),
                axis(nyquist::filter::Axis::Y),
            ))
        }
        let (values, xs, ys) = match n {
            8 => build::<8>(&self.kind)?,
            16 => build::<16>(&self.kind)?,
            32 => build::<32>(&self.kind)?,
            64 => build::<64>(&self.kind)?,
            other => {
                return Err(value_error(format!(
                    "n {other} is not one of 8, 16, 32, 64"
                )));
            }
        };
        Ok((
            values.into_pyarray(py).reshape([n, n])?,
            xs.into_pyarray(py),
            ys.into_pyarray(py),
        ))
    }

    /// Importance samples of the filter from `u`, an `(n, 2)` array in `[0, 1)²`: `(offsets,
    /// weights)`, offsets `(n, 2)` in pixels and weights `f(offset) / pdf(offset)` (negative in
    /// a negative lobe), so `mean(weights · g(offsets))` estimates `∫∫ f·g`.
    fn sample<'py>(
        &self,
        py: Python<'py>,
        u: PyReadonlyArray2<'py, f64>,
    ) -> PyResult<FilterSamples<'py>> {
        if u.shape()[1] != 2 {
            return Err(value_error("u must have shape (n, 2)"));
        }
        let flat = u.as_slice().map_err(value_error)?;
        if let Some(&bad) = flat.iter().find(|v| !(0.0..1.0).contains(*v)) {
            return Err(value_error(format!("u value {bad} is outside [0, 1)")));
        }
        let n = flat.len() / 2;
        let mut offsets = Vec::with_capacity(2 * n);
        let mut weights = Vec::with_capacity(n);
        for p in flat.chunks_exact(2) {
            let below_one = |v: f64| (v as f32).min(nyquist::ONE_MINUS_EPSILON);
            let s = self.sampler.sample([below_one(p[0]), below_one(p[1])]);
            offsets.extend_from_slice(&s.offset);
            weights.push(s.weight);
        }
        Ok((
            offsets.into_pyarray(py).reshape([n, 2])?,
            weights.into_pyarray(py),
        ))
    }

    /// The sampling density at each offset of an `(n, 2)` array (0 outside the support).
    fn pdf<'py>(
        &self,
        py: Python<'py>,
        offsets: PyReadonlyArray2<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray1<f32>>> {
        if offsets.shape()[1] != 2 {
            return Err(value_error("offsets must have shape (n, 2)"));
        }
        let flat = offsets.as_slice().map_err(value_error)?;
        let v: Vec<f32> = flat
            .chunks_exact(2)
            .map(|p| self.sampler.pdf([p[0] as f32, p[1] as f32]))
            .collect();
        Ok(v.into_pyarray(py))
    }
}
