//! Screen-space blue noise, measured: for each sampler, error images of `size × size` pixels
//! (each pixel's estimate of an integrand from its own samples, minus the integral) at 1 … 32
//! spp, on 2-D integrands of the first pair of dimensions, the second pair and the first pair of
//! the next 4-D block (OpenQMC: the next domain), and on 4-D integrands of the first block.
//!
//! Two numbers per image: the per-pixel RMSE, and the low-frequency ratio (the mean
//! periodogram power below a quarter of the Nyquist radius over the mean power at every
//! non-zero frequency: 1 for white error, lower for blue).
//!
//! `cargo run --release --manifest-path peers/Cargo.toml -- --blue-noise [--size N]
//! [--frame F] [--images DIR]`

use nyquist::sampler::{OwenSobolBlueSampler, OwenSobolSampler, RandomSampler, Sampler};

/// Four values per (pixel, sample), pixel-major, for block `block` (dimensions `4b .. 4b+4`).
type Draw = Box<dyn Fn(u32, u32, u32, u32) -> Vec<f32>>;

/// A sampler's values through the nyquist `Sampler` interface.
fn nyquist_draw<S: Sampler + Clone + 'static>(s: S) -> Draw {
    Box::new(move |size, spp, frame, block| {
        let _ = frame;
        let mut s = s.clone();
        let mut out = Vec::with_capacity((size * size * spp * 4) as usize);
        for y in 0..size {
            for x in 0..size {
                for i in 0..spp {
                    s.start_pixel_sample([x, y], i, 4 * block);
                    for _ in 0..4 {
                        out.push(s.get_1d());
                    }
                }
            }
        }
        out
    })
}

#[cfg(peer_openqmc)]
fn openqmc_draw(kind: i32) -> Draw {
    Box::new(move |size, spp, frame, block| crate::openqmc::bn_draw(kind, size, frame, spp, block))
}

/// The samplers compared, by name.
fn sources(frame: u32) -> Vec<(&'static str, Draw)> {
    #[cfg_attr(not(peer_openqmc), allow(unused_mut))]
    let mut v: Vec<(&'static str, Draw)> = vec![
        (
            "nyquist owen-sobol-bn",
            nyquist_draw(OwenSobolBlueSampler::new(1, 0).unwrap().with_frame(frame)),
        ),
        (
            "nyquist owen-sobol",
            nyquist_draw(OwenSobolSampler::new(1, 0).unwrap().with_frame(frame)),
        ),
        (
            "white (random)",
            nyquist_draw(RandomSampler::new(1, 0).unwrap()),
        ),
    ];
    #[cfg(peer_openqmc)]
    {
        v.push(("OpenQMC sobolbn", openqmc_draw(0)));
        v.push(("OpenQMC pmjbn", openqmc_draw(1)));
        v.push(("OpenQMC latticebn", openqmc_draw(2)));
        v.push(("OpenQMC sobol", openqmc_draw(3)));
    }
    #[cfg(not(peer_openqmc))]
    eprintln!("OpenQMC: not built (set NYQUIST_OPENQMC; README.md)");
    v
}

/// A test integrand over the four values of a block.
#[derive(Clone, Copy)]
struct Integrand {
    name: &'static str,
    block: u32,
    f: fn(&[f32]) -> f64,
}

fn disk(x: f32, y: f32) -> f64 {
    // Area ½, centred: the 2021 paper's disk.
    let (dx, dy) = (f64::from(x) - 0.5, f64::from(y) - 0.5);
    f64::from(u8::from(dx * dx + dy * dy < 0.5 / std::f64::consts::PI))
}

fn gaussian(x: f32, y: f32) -> f64 {
    let (dx, dy) = (f64::from(x) - 0.5, f64::from(y) - 0.5);
    (-(dx * dx + dy * dy) / (2.0 * 0.15 * 0.15)).exp()
}

fn integrands() -> Vec<Integrand> {
    vec![
        Integrand {
            name: "disk, dims 0-1",
            block: 0,
            f: |v| disk(v[0], v[1]),
        },
        Integrand {
            name: "gaussian, dims 0-1",
            block: 0,
            f: |v| gaussian(v[0], v[1]),
        },
        Integrand {
            name: "disk, dims 2-3",
            block: 0,
            f: |v| disk(v[2], v[3]),
        },
        Integrand {
            name: "gaussian, dims 2-3",
            block: 0,
            f: |v| gaussian(v[2], v[3]),
        },
        Integrand {
            name: "disk, next block 0-1",
            block: 1,
            f: |v| disk(v[0], v[1]),
        },
        Integrand {
            name: "heaviside 4-D",
            block: 0,
            f: |v| {
                let s: f64 = v.iter().map(|&x| f64::from(x) - 0.5).sum::<f64>()
                    + 0.3 * (f64::from(v[0]) - f64::from(v[3]));
                f64::from(u8::from(s < 0.0))
            },
        },
        Integrand {
            name: "gaussian 4-D",
            block: 0,
            f: |v| {
                let r2: f64 = v.iter().map(|&x| (f64::from(x) - 0.5).powi(2)).sum();
                (-r2 / (2.0 * 0.25 * 0.25)).exp()
            },
        },
    ]
}

/// The integral of `f`, from 2²⁰ Owen-scrambled Sobol points of four dimensions.
fn reference(f: fn(&[f32]) -> f64) -> f64 {
    let mut s = OwenSobolSampler::new(1, 12345).unwrap();
    let n = 1u32 << 20;
    let mut sum = 0.0;
    for i in 0..n {
        s.start_pixel_sample([0, 0], i, 0);
        let v = [s.get_1d(), s.get_1d(), s.get_1d(), s.get_1d()];
        sum += f(&v);
    }
    sum / f64::from(n)
}

/// The low-frequency ratio of a square image (module docs), by a separable DFT.
pub fn low_frequency_ratio(image: &[f64], size: usize) -> f64 {
    let mean = image.iter().sum::<f64>() / image.len() as f64;
    let tw: Vec<(f64, f64)> = (0..size)
        .map(|k| {
            let a = -std::f64::consts::TAU * k as f64 / size as f64;
            (a.cos(), a.sin())
        })
        .collect();
    let mut rows = vec![(0.0, 0.0); size * size];
    for y in 0..size {
        for u in 0..size {
            let (mut re, mut im) = (0.0, 0.0);
            for x in 0..size {
                let (c, s) = tw[(u * x) % size];
                let v = image[y * size + x] - mean;
                re += v * c;
                im += v * s;
            }
            rows[y * size + u] = (re, im);
        }
    }
    let (mut low, mut nlow, mut all) = (0.0, 0usize, 0.0);
    for v in 0..size {
        for u in 0..size {
            if (u, v) == (0, 0) {
                continue;
            }
            let (mut re, mut im) = (0.0, 0.0);
            for y in 0..size {
                let (c, s) = tw[(v * y) % size];
                let (a, b) = rows[y * size + u];
                re += a * c - b * s;
                im += a * s + b * c;
            }
            let p = re * re + im * im;
            all += p;
            let fu = u.min(size - u) as f64;
            let fv = v.min(size - v) as f64;
            if (fu * fu + fv * fv).sqrt() < size as f64 / 8.0 {
                low += p;
                nlow += 1;
            }
        }
    }
    (low / nlow.max(1) as f64) / (all / (size * size - 1) as f64)
}

/// Runs the study and prints its tables.
pub fn run(size: u32, frame: u32, images: Option<&std::path::Path>) {
    const SPPS: [u32; 6] = [1, 2, 4, 8, 16, 32];
    let integrands = integrands();
    let exact: Vec<f64> = integrands.iter().map(|g| reference(g.f)).collect();
    let sources = sources(frame);
    // results[source][integrand][spp] = (rmse, ratio)
    let mut results = vec![vec![vec![(0.0, 0.0); SPPS.len()]; integrands.len()]; sources.len()];
    for (si, (name, draw)) in sources.iter().enumerate() {
        eprintln!("blue noise: {name}");
        for (k, &spp) in SPPS.iter().enumerate() {
            for block in [0, 1] {
                let values = draw(size, spp, frame, block);
                for (ii, g) in integrands.iter().enumerate() {
                    if g.block != block {
                        continue;
                    }
                    let err: Vec<f64> = values
                        .chunks(4 * spp as usize)
                        .map(|px| {
                            px.chunks(4).map(|v| (g.f)(v)).sum::<f64>() / f64::from(spp) - exact[ii]
                        })
                        .collect();
                    let rmse = (err.iter().map(|e| e * e).sum::<f64>() / err.len() as f64).sqrt();
                    results[si][ii][k] = (rmse, low_frequency_ratio(&err, size as usize));
                    if let Some(dir) = images
                        && spp == 4
                        && ii == 1
                    {
                        write_error_image(dir, name, &err, size);
                    }
                }
            }
        }
    }
    println!(
        "Screen-space error, {size} × {size} pixels, frame {frame}: per-pixel RMSE and \
         low-frequency ratio (1 = white) at 1, 2, 4, 8, 16, 32 spp.\n"
    );
    for (ii, g) in integrands.iter().enumerate() {
        println!("### {}\n", g.name);
        println!(
            "| sampler | {} |",
            SPPS.map(|s| format!("{s} spp")).join(" | ")
        );
        println!("|---|{}", "---:|".repeat(SPPS.len()));
        for (si, (name, _)) in sources.iter().enumerate() {
            let cells: Vec<String> = results[si][ii]
                .iter()
                .map(|(rmse, ratio)| format!("{rmse:.4} / {ratio:.2}"))
                .collect();
            println!("| {name} | {} |", cells.join(" | "));
        }
        println!();
    }
}

/// `½ + 4·error` as grey, a PNG named after the sampler (the Gaussian of the first pair at 4
/// spp).
fn write_error_image(dir: &std::path::Path, name: &str, err: &[f64], size: u32) {
    use nyquist_film::output::png::{PngColor, PngLayout, write_png_pixels};
    let grey: Vec<u8> = err
        .iter()
        .map(|e| ((0.5 + 4.0 * e).clamp(0.0, 1.0) * 255.0).round() as u8)
        .collect();
    let file = dir.join(format!(
        "blue-error-{}.png",
        name.to_lowercase()
            .replace(['(', ')'], "")
            .replace(' ', "-")
    ));
    let mut out = Vec::new();
    write_png_pixels(&mut out, &PngLayout::new(size, size, PngColor::Grey), &grey).unwrap();
    std::fs::write(&file, out).unwrap();
    eprintln!("wrote {}", file.display());
}
