//! The page's five views and the name lists its menus are built from. Each builds the
//! arguments of the `nyquist` subcommand that computes the same thing, runs the library code
//! behind that subcommand, and returns the command line with the result.

use crate::query::{Query, choice, described};
use crate::{Reply, jlist, jn, js};
use anyhow::{Result, anyhow, bail};
use nyquist::filter::{Axis, Filter, FilterKind, FilterSampler, FilterTable, Interpolation};
use nyquist::sampler::Sampler;
use nyquist_lab::analysis::{
    self as analyze, AnalyzeSpec as AnalyzeArgs, Measure, Quiet, StarMethod,
};
use nyquist_lab::points::{self, PointSetName as PointSet};
use nyquist_lab::render::{self, SamplerName};
use nyquist_lab::scene::Scene;
use nyquist_lab::study::convergence::{self as converge, ConvergeSpec as ConvergeArgs};
use nyquist_lab::study::unit_square::SquareIntegrand as Integrand;

/// Points in the Points view (every measure is at most quadratic in the count).
const MAX_POINTS: u64 = 16384;
/// Points per realisation in the Spectrum view.
const MAX_SPECTRUM_POINTS: u64 = 4096;
/// Periodogram terms (realisations × points × frequencies) the Spectrum view computes.
const MAX_SPECTRUM_TERMS: f64 = 4e9;
/// Pixels of the Aliasing view's image.
const MAX_PIXELS: u64 = 1024 * 1024;
/// Highest dimension index a pair may name (the first 32 dimensions).
const MAX_DIM: u64 = 31;
/// Grid points per axis of the Filters view's footprint.
const MAX_GRID: u64 = 257;
/// Importance samples drawn in the Filters view.
const MAX_FILTER_SAMPLES: u64 = 65536;
/// Samples a convergence study in the page may take.
const MAX_STUDY_SAMPLES: u64 = 1 << 28;

/// The menus: point sets (`points`), pixel samplers (`render`), scenes, integrands, the
/// samplers `converge` takes, and the filter names, each with its one-line help.
pub fn names() -> Reply {
    let pairs = |v: Vec<(String, String)>| {
        let items: Vec<String> = v
            .iter()
            .map(|(n, h)| format!("{{\"name\":{},\"help\":{}}}", js(n), js(h)))
            .collect();
        format!("[{}]", items.join(","))
    };
    let plain = |v: &[&str]| {
        let items: Vec<String> = v.iter().map(|n| js(n)).collect();
        format!("[{}]", items.join(","))
    };
    let json = format!(
        "{{\"point_sets\":{},\"samplers\":{},\"scenes\":{},\"integrands\":{},\"converge_samplers\":{},\"filters\":{}}}",
        pairs(described::<PointSet>()),
        pairs(described::<SamplerName>()),
        pairs(described::<Scene>()),
        pairs(described::<Integrand>()),
        plain(&nyquist::sampler::NAMES),
        plain(&nyquist::filter::FILTER_NAMES),
    );
    Reply {
        json,
        data: Vec::new(),
    }
}

/// `analyze` arguments for a generated set projected onto dimensions `x`, `y`.
struct SetQuery {
    args: AnalyzeArgs,
    /// The command-line flags that select the same points.
    flags: String,
    x: u32,
    y: u32,
}

fn set_query(q: &Query, max_count: u64) -> Result<SetQuery> {
    let sampler: PointSet = q.choice("sampler", "halton")?;
    let name = sampler.name();
    // No seed: the deterministic sets stay deterministic (as on the command line).
    let seed = match q.has("seed") {
        true => Some(q.int("seed", 0, 0, u64::MAX)?),
        false => None,
    };
    let x = q.int("x", 0, 0, MAX_DIM)? as u32;
    let y = q.int("y", 1, 0, MAX_DIM)? as u32;
    if x == y {
        bail!("x={x}, y={y}: pick two different dimensions");
    }
    let dims = x.max(y) + 1;
    let mut flags = format!("--sampler {name}");
    let (count, spp) = if q.has("spp") {
        let spp = q.int("spp", 16, 1, max_count)? as u32;
        flags.push_str(&format!(" --spp {spp}"));
        (None, Some(spp))
    } else {
        let count = q.int("count", 256, 1, max_count)?;
        flags.push_str(&format!(" --count {count}"));
        (Some(count), None)
    };
    let grid = match q.has("grid") {
        true => {
            let g = q.text("grid", "");
            let parsed = points::parse_grid(&g).map_err(|e| anyhow!("grid={g}: {e}"))?;
            flags.push_str(&format!(" --grid {g}"));
            Some(parsed)
        }
        false => None,
    };
    // Halton, Hammersley, Sobol and ZSobol spread one sequence over the whole image: their
    // pixel samples depend on its size.
    let resolution = match (spp, sampler) {
        (Some(_), PointSet::Halton | PointSet::Hammersley | PointSet::Sobol | PointSet::ZSobol) => {
            let r = q.text("resolution", "64x64");
            let parsed = points::parse_grid(&r).map_err(|e| anyhow!("resolution={r}: {e}"))?;
            flags.push_str(&format!(" --resolution {r}"));
            Some(parsed)
        }
        _ => None,
    };
    flags.push_str(&format!(" --dims {dims}"));
    if let Some(seed) = seed {
        flags.push_str(&format!(" --seed {seed}"));
    }
    flags.push_str(&format!(" --project {x},{y}"));
    let args = AnalyzeArgs {
        input: None,
        input_flag: None,
        sampler: Some(sampler),
        count,
        dims: Some(dims.max(2)),
        seed,
        skip: None,
        grid,
        spp,
        resolution,
        project: vec![x, y],
        measures: Vec::new(),
        star_method: StarMethod::Auto,
        star_grid: None,
        json: true,
        spectrum: None,
        freq: None,
        realisations: 1,
    };
    Ok(SetQuery { args, flags, x, y })
}

/// The strata an overlay draws: the set's own grid for `stratified`/`uniform`, else the
/// square (or 2^⌈k/2⌉ × 2^⌊k/2⌋) grid with one cell per point, if the count allows one.
fn strata(sampler: PointSet, grid: Option<(u32, u32)>, n: usize) -> Option<[u64; 2]> {
    if matches!(sampler, PointSet::Stratified | PointSet::Uniform)
        && let Some((gx, gy)) = grid
    {
        return Some([u64::from(gx), u64::from(gy)]);
    }
    let n = n as u64;
    let r = n.isqrt();
    if r * r == n {
        return Some([r, r]);
    }
    if n.is_power_of_two() {
        let k = n.trailing_zeros();
        return Some([1 << k.div_ceil(2), 1 << (k / 2)]);
    }
    None
}

/// The two closest points (indices), by a sweep over x; `None` for fewer than two points.
fn closest_pair(p: &[[f64; 2]]) -> Option<(usize, usize)> {
    let mut order: Vec<usize> = (0..p.len()).collect();
    // By x, then index: the order a stable sort gives, without a stable sort's code.
    order.sort_unstable_by(|&a, &b| p[a][0].total_cmp(&p[b][0]).then(a.cmp(&b)));
    let mut best: Option<(f64, usize, usize)> = None;
    for (k, &i) in order.iter().enumerate() {
        for &j in &order[k + 1..] {
            let dx = p[j][0] - p[i][0];
            if best.is_some_and(|(d, _, _)| dx * dx >= d) {
                break;
            }
            let dy = p[j][1] - p[i][1];
            let d = dx * dx + dy * dy;
            if best.is_none_or(|(b, _, _)| d < b) {
                best = Some((d, i.min(j), i.max(j)));
            }
        }
    }
    best.map(|(_, i, j)| (i, j))
}

/// Points: the set's projection onto dimensions `x`, `y` and what `analyze --json` prints for
/// it (star, L2-star, centered and wrap-around L2 discrepancies, minimum distance and ρ).
///
/// Parameters: `sampler` (a `points` name), `count` (1 ..= 16384) or `spp` (pixel-sampler
/// mode), `seed`, `x`, `y` (0 ..= 31), `grid` (`NXxNY`, for stratified/uniform), `split`
/// (1 ..= 64, `owen-sobol` with `spp`: each sample's `Domain::split(1, split, k)`, its
/// dimensions `x`, `y`). Data: `x0, y0, x1, y1, …`, then the sub-samples' pairs, parent by
/// parent.
pub fn points(q: &Query) -> Result<Reply> {
    let mut s = set_query(q, MAX_POINTS)?;
    let split = match q.has("split") {
        true => Some(domain_split(q, &s)?),
        false => None,
    };
    s.args.measures = vec![
        Measure::Star,
        Measure::L2Star,
        Measure::CenteredL2,
        Measure::WraparoundL2,
        Measure::MinDistance,
    ];
    let analysis = analyze::report(&s.args, &mut Quiet::default())?;
    let (coords, _, _) = analyze::load(&s.args, s.args.seed)?;
    let pairs: Vec<[f64; 2]> = coords.chunks_exact(2).map(|c| [c[0], c[1]]).collect();
    let pair =
        closest_pair(&pairs).map_or_else(|| "null".to_owned(), |(i, j)| format!("[{i},{j}]"));
    let sampler = s.args.sampler.unwrap_or(PointSet::Halton);
    let strata = strata(sampler, s.args.grid, pairs.len())
        .map_or_else(|| "null".to_owned(), |[a, b]| format!("[{a},{b}]"));
    let cli = format!(
        "nyquist analyze {} --measures star,l2-star,centered-l2,wraparound-l2,min-distance --json",
        s.flags
    );
    let mut data: Vec<f32> = coords.iter().map(|&v| v as f32).collect();
    let split_json = match &split {
        Some((k, sub)) => {
            data.extend(sub);
            format!("{{\"k\":{k}}}")
        }
        None => "null".to_owned(),
    };
    Ok(Reply {
        json: format!(
            "{{\"cli\":{},\"x\":{},\"y\":{},\"count\":{},\"closest_pair\":{pair},\"strata\":{strata},\"split\":{split_json},\"analysis\":{}}}",
            js(&cli),
            s.x,
            s.y,
            pairs.len(),
            analysis.trim_end()
        ),
        data,
    })
}

/// The `split` of the Points view: for each of the pixel's `spp` samples of `owen-sobol`
/// (pixel (0, 0), the set's seed), its `k` sub-samples `Domain::split(1, k, j)` at dimensions
/// `x`, `y`.
fn domain_split(q: &Query, s: &SetQuery) -> Result<(u32, Vec<f32>)> {
    let k = q.int("split", 4, 1, 64)? as u32;
    let (Some(PointSet::OwenSobol), Some(spp)) = (s.args.sampler, s.args.spp) else {
        bail!(
            "split={k}: a domain split shows owen-sobol's pixel samples: sampler=owen-sobol with spp"
        );
    };
    if u64::from(spp) * u64::from(k) > MAX_POINTS {
        bail!("split={k}: spp × split is more than {MAX_POINTS} points");
    }
    let mut sampler = nyquist::sampler::OwenSobolSampler::new(spp, s.args.seed.unwrap_or(0))?;
    let mut sub = Vec::with_capacity(2 * (spp * k) as usize);
    for i in 0..spp {
        sampler.start_pixel_sample([0, 0], i, 0);
        let parent = sampler.pixel_domain();
        for j in 0..k {
            let d = parent.split(1, k, j)?;
            sub.extend([d.get_1d(s.x), d.get_1d(s.y)]);
        }
    }
    Ok((k, sub))
}

/// The expected periodogram of jittered points on an `nx × ny` grid at integer frequency `f`:
/// `1 − sinc²(π fx/nx)·sinc²(π fy/ny)` for `f ≠ 0`, and `N` at `f = 0` (the periodogram's DC).
fn jittered_power(fx: i64, fy: i64, nx: u64, ny: u64) -> f64 {
    if fx == 0 && fy == 0 {
        return (nx * ny) as f64;
    }
    let sinc = |t: f64| if t == 0.0 { 1.0 } else { libm::sin(t) / t };
    let a = sinc(std::f64::consts::PI * fx as f64 / nx as f64);
    let b = sinc(std::f64::consts::PI * fy as f64 / ny as f64);
    1.0 - a * a * b * b
}

/// The radial mean of [`jittered_power`] over the periodogram's annuli (`round(|f|) = r`).
fn jittered_radial(max_freq: u32, nx: u64, ny: u64) -> Vec<f64> {
    let f = i64::from(max_freq);
    let bins = max_freq as usize + 1;
    let (mut sum, mut count) = (vec![0.0; bins], vec![0u32; bins]);
    for fy in -f..=f {
        for fx in -f..=f {
            let r = ((fx * fx + fy * fy) as f64).sqrt().round() as usize;
            if r < bins {
                sum[r] += jittered_power(fx, fy, nx, ny);
                count[r] += 1;
            }
        }
    }
    sum.iter()
        .zip(&count)
        .map(|(s, &c)| s / f64::from(c))
        .collect()
}

/// Spectrum: the periodogram of the projection averaged over `realisations` seeds, its radial
/// mean and anisotropy (as `analyze --spectrum … --json` prints them), and for `stratified`
/// in dimensions 0, 1 the closed form of jittered sampling.
///
/// Parameters: those of [`points`] (count ≤ 4096), `freq` (1 ..= 64), `realisations`
/// (1 ..= 1024). Data: the `(2F+1)²` powers, row `fy = −F` first, `fx = −F … F` in a row.
pub fn spectrum(q: &Query, progress: &(dyn Fn(u32, u32) + Sync)) -> Result<Reply> {
    let mut s = set_query(q, MAX_SPECTRUM_POINTS)?;
    let freq = q.int("freq", 32, 1, 64)? as u32;
    let realisations = q.int("realisations", 16, 1, 1024)? as u32;
    s.args.freq = Some(freq);
    s.args.realisations = realisations;
    let (coords, dims, _) = analyze::load(&s.args, s.args.seed)?;
    let n = coords.len() / dims;
    let side = 2.0 * f64::from(freq) + 1.0;
    let terms = f64::from(realisations) * n as f64 * side * side;
    if terms > MAX_SPECTRUM_TERMS {
        bail!(
            "realisations={realisations} × {n} points × {side}² frequencies is {terms:.1e} terms; \
             the page computes at most {MAX_SPECTRUM_TERMS:.0e}"
        );
    }
    let (spec, identical) =
        analyze::periodogram(&s.args, &coords, dims, &mut |d, t| progress(d, t))?;
    let sampler = s.args.sampler.unwrap_or(PointSet::Halton);
    let jittered = match (sampler, s.x, s.y, strata(sampler, s.args.grid, n)) {
        (PointSet::Stratified, 0, 1, Some([nx, ny])) if nx * ny == n as u64 => {
            jlist(jittered_radial(freq, nx, ny))
        }
        _ => "null".to_owned(),
    };
    let cli = format!(
        "nyquist analyze {} --spectrum spectrum.png --freq {freq} --realisations {realisations} --json",
        s.flags
    );
    Ok(Reply {
        json: format!(
            "{{\"cli\":{},\"count\":{n},\"max_freq\":{},\"realisations\":{},\"identical\":{identical},\"radial_mean\":{},\"anisotropy_db\":{},\"jittered_radial_mean\":{jittered}}}",
            js(&cli),
            spec.max_freq,
            spec.realisations,
            jlist(spec.radial_mean.iter().copied()),
            jlist(spec.anisotropy_db.iter().copied()),
        ),
        data: spec.power.iter().map(|&p| p as f32).collect(),
    })
}

/// Aliasing: a scene rendered through a sampler and a filter, beside its reference, with the
/// RMSE `compare --json` prints for the same cell.
///
/// Parameters: `scene`, `size` (`WxH`, at most 1024² pixels), `sampler` (a `render` name),
/// `filter` (a spec), `spp` (1 ..= 4096), `seed`. Data: the image (`W·H` values, row 0 first),
/// then the reference pixel means (`W·H`).
pub fn aliasing(q: &Query, progress: &(dyn Fn(u32, u32) + Sync)) -> Result<Reply> {
    let scene: Scene = q.choice("scene", "zoneplate")?;
    let size_text = q.text("size", "256x256");
    let size = render::parse_size(&size_text).map_err(|e| anyhow!("size={size_text}: {e}"))?;
    let pixels = u64::from(size[0]) * u64::from(size[1]);
    if pixels > MAX_PIXELS {
        bail!("size={size_text}: {pixels} pixels; the page renders at most {MAX_PIXELS}");
    }
    let sampler_name: SamplerName = q.choice("sampler", "stratified")?;
    let spec = q.text("filter", "box");
    let filter = render::parse_filter(&spec).map_err(|e| anyhow!("filter={spec}: {e}"))?;
    let spp = q.int("spp", 16, 1, 4096)? as u32;
    let seed = q.int("seed", 0, 0, u64::MAX)?;
    let sampler = render::build_sampler(sampler_name, spp, size, seed, None)?;
    let tiles = render::tile_count(size) as u32;
    let boxed = FilterKind::parse("box").map_err(|e| anyhow!("{e}"))?;
    let keys = [
        reference_key(scene, size, &boxed),
        reference_key(scene, size, &filter),
    ];
    // Tiles to render: the references that are neither closed forms nor kept from an earlier
    // request (the box's counted once when the filter is the box), then the image.
    let to_render = if scene == Scene::Zoneplate {
        0
    } else {
        let kept = |k: &String| REFERENCES.with_borrow(|r| r.iter().any(|(key, _)| key == k));
        let distinct = if keys[0] == keys[1] { 1 } else { 2 };
        keys[..distinct]
            .iter()
            .zip([&boxed, &filter])
            .filter(|(k, f)| !kept(k) && !render::exact_reference(scene, f))
            .count() as u32
    };
    let total = tiles * (to_render + 1);
    let mut done = 0;
    let mut tick = || {
        done += 1;
        progress(done.min(total), total);
    };
    progress(0, total);
    let means = reference(scene, size, None, &keys[0], &mut tick)?
        .ok_or_else(|| anyhow!("scene={}: no reference", scene.name()))?;
    let filtered = reference(scene, size, Some(&filter), &keys[1], &mut tick)?;
    let r = render::render(scene, size, &sampler, &filter, 1, &mut tick)?;
    // A reference read from the command line's cache folder (native builds) ticks nothing.
    progress(total, total);
    let e = render::rmse(&r.image, &means);
    let sampling = filtered
        .as_ref()
        .map_or(f64::NAN, |f| render::rmse(&r.image, f));
    let cli = format!(
        "nyquist compare --scene {} --size {}x{} --samplers {} --filters {spec} --spp {spp} --seed {seed} --json",
        scene.name(),
        size[0],
        size[1],
        sampler_name.name(),
    );
    let mut data: Vec<f32> = render::channel0(&r.image)
        .iter()
        .map(|&v| v as f32)
        .collect();
    data.extend(means.iter().map(|&v| v as f32));
    Ok(Reply {
        json: format!(
            "{{\"cli\":{},\"scene\":{},\"width\":{},\"height\":{},\"sampler\":{},\"filter\":{},\"spp\":{},\"samples\":{},\"rmse\":{},\"psnr\":{},\"sampling_rmse\":{},\"reference\":{}}}",
            js(&cli),
            js(scene.name()),
            size[0],
            size[1],
            js(sampler_name.name()),
            js(&filter.to_string()),
            sampler.samples_per_pixel(),
            r.stats.samples,
            jn(e),
            jn(render::psnr(e)),
            jn(sampling),
            js(&render::reference_kind(scene)),
        ),
        data,
    })
}

/// References kept for later requests (the command line keeps them in a cache folder; the
/// browser has none): the last few, by [`reference_key`].
const KEPT_REFERENCES: usize = 4;

type Kept = Vec<(String, Option<Vec<f64>>)>;

thread_local! {
    static REFERENCES: std::cell::RefCell<Kept> = const { std::cell::RefCell::new(Vec::new()) };
}

/// What a reference depends on: the scene, the size and the filter's full spec.
fn reference_key(scene: Scene, size: [u32; 2], filter: &FilterKind) -> String {
    format!("{} {}x{} {filter}", scene.name(), size[0], size[1])
}

/// [`render::reference_with_progress`], kept under `key` for the next requests.
fn reference(
    scene: Scene,
    size: [u32; 2],
    filter: Option<&FilterKind>,
    key: &str,
    tick: &mut dyn FnMut(),
) -> Result<Option<Vec<f64>>> {
    if let Some(kept) =
        REFERENCES.with_borrow(|r| r.iter().find(|(k, _)| k == key).map(|(_, v)| v.clone()))
    {
        return Ok(kept);
    }
    let image = render::reference_with_progress(scene, size, filter, 1, tick)?;
    if scene != Scene::Zoneplate {
        REFERENCES.with_borrow_mut(|r| {
            if r.len() == KEPT_REFERENCES {
                r.remove(0);
            }
            r.push((key.to_owned(), image.clone()));
        });
    }
    Ok(image)
}

/// Filters: the profile and frequency response (as `filter --plot` draws them), the footprint
/// on a grid (the values `filter --grid G` prints), the integral (as `filter` prints it), the
/// 16 × 16 table's largest error against direct evaluation on that grid, and points drawn by
/// importance sampling with their weights `f/pdf`.
///
/// Parameters: `filter` (spec), `grid` (2 ..= 257), `samples` (1 ..= 65536), `seed`. Data:
/// the `G²` footprint values (row `y = −ry` first), then `2·samples` offsets `x, y`, then
/// `samples` weights.
pub fn filters(q: &Query) -> Result<Reply> {
    let spec = q.text("filter", "mitchell");
    let kind = FilterKind::parse(&spec).map_err(|e| anyhow!("filter={spec}: {e}"))?;
    let g = q.int("grid", 65, 2, MAX_GRID)? as u32;
    let n = q.int("samples", 4096, 1, MAX_FILTER_SAMPLES)? as usize;
    let seed = q.int("seed", 0, 0, u64::MAX)?;
    let f: &dyn Filter = kind.as_dyn();
    let [rx, ry] = f.radius();
    // The grid of `nyquist filter --grid G`: G points per axis over [−r, r], ends included.
    let at = |k: u32, r: f32| {
        (-f64::from(r) + 2.0 * f64::from(r) * f64::from(k) / f64::from(g - 1)) as f32
    };
    let table: FilterTable = FilterTable::new(&kind, Interpolation::Linear)
        .map_err(|e| anyhow!("filter={spec}: cannot tabulate: {e}"))?;
    let mut data = Vec::with_capacity((g * g) as usize + 3 * n);
    let (mut table_error, mut peak) = (0.0f64, 0.0f64);
    for j in 0..g {
        for i in 0..g {
            let (x, y) = (at(i, rx), at(j, ry));
            let v = f.eval(x, y);
            data.push(v + 0.0);
            table_error = table_error.max(f64::from((table.weight(x, y) - v).abs()));
            peak = peak.max(f64::from(v.abs()));
        }
    }
    const STEPS: usize = 400;
    let profile: Vec<String> = (0..=STEPS)
        .map(|i| {
            let x = -f64::from(rx) + 2.0 * f64::from(rx) * i as f64 / STEPS as f64;
            format!(
                "[{},{}]",
                jn(x),
                jn(nyquist_lab::filter::profile(f, x as f32))
            )
        })
        .collect();
    let dc = nyquist_lab::filter::spectrum(f, 0.0).max(1e-300);
    let response: Vec<String> = (0..=STEPS / 2)
        .map(|i| {
            let nu = 2.0 * i as f64 / (STEPS / 2) as f64;
            format!(
                "[{},{}]",
                jn(nu),
                jn(nyquist_lab::filter::spectrum(f, nu) / dc)
            )
        })
        .collect();
    let sampler: FilterSampler<FilterKind> =
        FilterSampler::new(kind).map_err(|e| anyhow!("filter={spec}: {e}"))?;
    let mut rng = nyquist::rng::default_rng(seed);
    let drawn: Vec<_> = (0..n)
        .map(|_| {
            let u = [
                nyquist::rng::uniform_f32(&mut rng),
                nyquist::rng::uniform_f32(&mut rng),
            ];
            sampler.sample(u)
        })
        .collect();
    data.extend(drawn.iter().flat_map(|s| s.offset));
    data.extend(drawn.iter().map(|s| s.weight));
    let mean_weight = drawn.iter().map(|s| f64::from(s.weight)).sum::<f64>() / n as f64;
    let separable = f.eval_1d(Axis::X, 0.0).is_some();
    let cli = format!("nyquist filter --filter {spec} --grid {g}");
    Ok(Reply {
        json: format!(
            "{{\"cli\":{},\"filter\":{},\"radius\":[{},{}],\"integral\":{},\"separable\":{separable},\"grid\":{g},\"peak\":{},\"table_max_error\":{},\"table_size\":16,\"samples\":{n},\"mean_weight\":{},\"profile\":[{}],\"response\":[{}]}}",
            js(&cli),
            js(&kind.to_string()),
            rx,
            ry,
            f.integral(),
            jn(peak),
            jn(table_error),
            jn(mean_weight),
            profile.join(","),
            response.join(","),
        ),
        data,
    })
}

/// Convergence: `converge --json` for the chosen samplers and integrands (RMSE against N,
/// least-squares slopes).
///
/// Parameters: `samplers`, `integrands` (comma lists), `min`, `max` (powers of two, N range),
/// `runs` (1 ..= 1024), `seed`, and `hint` (`--spp-hint`: every sampler made for `hint` spp,
/// drawing each N). No data.
pub fn convergence(q: &Query, progress: &(dyn Fn(u32, u32) + Sync)) -> Result<Reply> {
    let samplers = q.list("samplers", "random,stratified,halton,sobol,pmj02");
    let integrand_names = q.list("integrands", "disk,triangle,step,gaussian,bilinear");
    let integrands = integrand_names
        .iter()
        .map(|n| choice::<Integrand>("integrands", n))
        .collect::<Result<Vec<_>>>()?;
    let min = q.int("min", 16, 1, 1 << 16)? as u32;
    let max = q.int("max", 1024, 2, 1 << 16)? as u32;
    let runs = q.int("runs", 16, 1, 1024)? as u32;
    let seed = q.int("seed", 0, 0, u64::MAX)?;
    let hint = if q.has("hint") {
        Some(q.int("hint", 16, 1, 1 << 16)? as u32)
    } else {
        None
    };
    let args = ConvergeArgs {
        samplers: samplers.clone(),
        integrands,
        min_spp: min,
        max_spp: max,
        runs,
        seed,
        threads: None,
        plot: None,
        json: true,
        dims: None,
        spp_hint: hint,
    };
    let per_run: u64 = (min.trailing_zeros()..=max.trailing_zeros())
        .map(|k| 1u64 << k)
        .sum();
    let work = per_run * u64::from(runs) * samplers.len() as u64;
    if work > MAX_STUDY_SAMPLES {
        bail!(
            "runs={runs} × N = {min}..{max} × {} samplers is {work} samples; the page takes at most {MAX_STUDY_SAMPLES}",
            samplers.len()
        );
    }
    let cli = format!(
        "nyquist converge --samplers {} --integrands {} --min-spp {min} --max-spp {max} --runs {runs} --seed {seed}{} --json",
        samplers.join(","),
        integrand_names.join(","),
        hint.map_or_else(String::new, |h| format!(" --spp-hint {h}"))
    );
    let study =
        converge::json_report(&args, 1, &|done, total| progress(done as u32, total as u32))?;
    Ok(Reply {
        json: format!("{{\"cli\":{},\"study\":{}}}", js(&cli), study.trim_end()),
        data: Vec::new(),
    })
}
