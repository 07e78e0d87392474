//! End-to-end tests of `nyquist render`.

mod common;

use common::{
    assert_one_line_error, files, json_field, nyquist, nyquist_cached, read_pfm, stdout, temp_dir,
};

/// `render FLAG ARGS` with the reference cache in `cache`, which must succeed; its stdout.
fn render_with(flag: &str, args: &[&str], cache: &std::path::Path) -> String {
    let mut all = vec!["render", flag];
    all.extend_from_slice(args);
    let o = nyquist_cached(&all, cache);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    stdout(&o)
}

/// `render --json`: the JSON line.
fn metrics(args: &[&str], cache: &std::path::Path) -> String {
    render_with("--json", args, cache)
}

/// `render --metrics`: the text.
fn human_metrics(args: &[&str], cache: &std::path::Path) -> String {
    render_with("--metrics", args, cache)
}

#[test]
fn uniform_one_spp_box_is_the_zone_plate_at_pixel_centres_exactly() {
    let dir = temp_dir("render-exact");
    let out = dir.join("zp.pfm");
    // W ≠ H: the formula divides by the width.
    let o = nyquist(&[
        "render",
        "--scene",
        "zoneplate",
        "--sampler",
        "uniform",
        "--spp",
        "1",
        "--filter",
        "box",
        "--size",
        "40x24",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (w, h, v) = read_pfm(&out);
    assert_eq!((w, h), (40, 24));
    for y in 0..h {
        for x in 0..w {
            // L = ½ + ½·cos(π r²/W), r measured from (W/2, H/2) to the pixel centre.
            let (dx, dy) = (x as f64 + 0.5 - 20.0, y as f64 + 0.5 - 12.0);
            let l = 0.5 + 0.5 * (std::f64::consts::PI * (dx * dx + dy * dy) / 40.0).cos();
            assert_eq!(v[y * w + x], l as f32, "pixel ({x}, {y})");
        }
    }
}

#[test]
fn stratified_256_spp_box_matches_the_fresnel_reference() {
    let cache = temp_dir("render-fresnel");
    let j = metrics(
        &[
            "--sampler",
            "stratified",
            "--spp",
            "256",
            "--filter",
            "box",
            "--size",
            "48x48",
        ],
        &cache,
    );
    let rmse = json_field(&j, "rmse");
    assert!(rmse < 2e-3, "{rmse}");
    assert_eq!(json_field(&j, "samples"), (48 * 48 * 256) as f64);
    assert_eq!(json_field(&j, "rejected"), 0.0);
    assert!(json_field(&j, "samples_per_second") > 0.0);
    let psnr = json_field(&j, "psnr");
    assert!((psnr + 20.0 * rmse.log10()).abs() < 1e-9);
    // The zone plate needs no cache.
    assert!(files(&cache).is_empty());
}

#[test]
fn sampling_rmse_measures_against_the_same_filter() {
    let cache = temp_dir("render-sampling");
    // With the box, the filtered reference (1D quadrature) is the Fresnel pixel means.
    let j = metrics(&["--spp", "4", "--size", "32x32"], &cache);
    assert!(
        (json_field(&j, "rmse") - json_field(&j, "sampling_rmse")).abs() < 1e-5,
        "{j}"
    );
    // Mitchell converges to its own blurred image, not to the pixel means: the blur stays in
    // the rmse, the sampling error goes (its floor, ~1.8e-3, is the film's filter table).
    let j = metrics(
        &["--filter", "mitchell", "--spp", "256", "--size", "48x48"],
        &cache,
    );
    assert!(json_field(&j, "sampling_rmse") < 3e-3, "{j}");
    assert!(json_field(&j, "rmse") > 0.03, "{j}");
}

#[test]
fn rmse_falls_as_spp_rises_for_stratified_and_sobol() {
    let cache = temp_dir("render-converge");
    for sampler in ["stratified", "sobol"] {
        let e: Vec<f64> = ["1", "4", "16", "64"]
            .iter()
            .map(|spp| {
                let j = metrics(
                    &["--sampler", sampler, "--spp", spp, "--size", "48x48"],
                    &cache,
                );
                json_field(&j, "rmse")
            })
            .collect();
        assert!(e.windows(2).all(|p| p[1] < p[0]), "{sampler}: {e:?}");
        // Stratification beats the 1/√n of independent samples by a clear margin.
        assert!(e[3] < e[0] / 8.0, "{sampler}: {e:?}");
    }
}

#[test]
fn output_is_byte_identical_for_one_and_two_threads() {
    let dir = temp_dir("render-threads");
    for (scene, sampler, filter, ext) in [
        ("zoneplate", "stratified", "mitchell", "pfm"),
        ("zoneplate", "sobol", "gaussian:alpha=2", "png"),
        ("checkerboard", "halton", "lanczos", "exr"),
        ("stripes", "random", "triangle", "pfm"),
        ("disk", "adaptive", "box", "pfm"),
        ("edge", "best-candidate", "mitchell", "png"),
    ] {
        let render = |threads: &str| {
            let out = dir.join(format!("{scene}-{sampler}-{threads}.{ext}"));
            let o = nyquist(&[
                "render",
                "--scene",
                scene,
                "--sampler",
                sampler,
                "--spp",
                "4",
                "--filter",
                filter,
                "--size",
                "70x50",
                "--threads",
                threads,
                "--seed",
                "3",
                "-o",
                out.to_str().unwrap(),
            ]);
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
            std::fs::read(out).unwrap()
        };
        assert_eq!(render("1"), render("2"), "{scene} {sampler} {filter}");
    }
}

#[test]
fn checkerboard_far_field_averages_to_one_half() {
    let dir = temp_dir("render-checker");
    let out = dir.join("c.pfm");
    let o = nyquist(&[
        "render",
        "--scene",
        "checkerboard",
        "--sampler",
        "stratified",
        "--spp",
        "64",
        "--size",
        "64x64",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let (w, _, v) = read_pfm(&out);
    // The horizon is at y = 0.3·64 = 19.2; rows 20 and 21 see dozens of checks per pixel.
    for y in [20usize, 21] {
        let row = &v[y * w..(y + 1) * w];
        let mean = row.iter().map(|&p| f64::from(p)).sum::<f64>() / w as f64;
        assert!((mean - 0.5).abs() < 0.02, "row {y}: {mean}");
        assert!(
            row.iter().all(|&p| (p - 0.5).abs() < 0.2),
            "row {y}: {row:?}"
        );
    }
    // Near the camera the checks are large: pure black and white pixels.
    let bottom = &v[63 * w..];
    assert!(bottom.contains(&0.0) && bottom.contains(&1.0));
}

#[test]
fn stripes_blur_with_the_time_sample_and_freeze_without_it() {
    let dir = temp_dir("render-stripes");
    let run = |sampler: &str, spp: &str| {
        let out = dir.join(format!("s-{sampler}.pfm"));
        let o = nyquist(&[
            "render",
            "--scene",
            "stripes",
            "--sampler",
            sampler,
            "--spp",
            spp,
            "--size",
            "64x32",
            "-o",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success());
        read_pfm(&out)
    };
    // uniform at 1 spp samples every pixel at time ½: a frozen frame of hard stripes.
    let (_, _, frozen) = run("uniform", "1");
    assert!(frozen.iter().all(|&p| p == 0.0 || p == 1.0));
    // 64 stratified times per pixel: the bottom row moves two periods, a uniform grey blur.
    let (w, h, blurred) = run("stratified", "64");
    let bottom = &blurred[(h - 1) * w..];
    assert!(bottom.iter().all(|&p| (p - 0.5).abs() < 0.15), "{bottom:?}");
    // The top row hardly moves: still stripes of full contrast.
    let top = &blurred[..w];
    let (lo, hi) = top
        .iter()
        .fold((1.0f32, 0.0f32), |(l, h), &p| (l.min(p), h.max(p)));
    assert!(lo < 0.1 && hi > 0.9, "{top:?}");
}

#[test]
fn other_scenes_measure_against_a_cached_reference() {
    let cache = temp_dir("render-cache");
    let a = metrics(
        &["--scene", "disk", "--spp", "4", "--size", "32x32"],
        &cache,
    );
    let cached = cache.join("nyquist");
    assert_eq!(files(&cached).len(), 1, "{:?}", files(&cached));
    // The second run reads the cache and gets the same numbers.
    let b = metrics(
        &["--scene", "disk", "--spp", "4", "--size", "32x32"],
        &cache,
    );
    assert_eq!(json_field(&a, "rmse"), json_field(&b, "rmse"));
    assert!(json_field(&a, "rmse") > 0.0 && json_field(&a, "rmse") < 0.1);
}

/// The dots scene's error spectrum: blue for the three `-bn` samplers, white for `owen-sobol`,
/// exact reference (nothing cached), and the radial power in 16 annuli. On a 128² image the
/// ratio's standard error is about 0.05 for white error (`error_low_frequency_ratio_se`; 800
/// frequencies in the band, half of them independent), so white error is within four of them
/// of 1 (a false alarm one time in 16,000) and a blue sampler's 0.36 … 0.50 at 4 spp
/// (docs/blue-noise.md) is more than four below 1.
#[test]
fn dots_measure_the_screen_space_error_spectrum() {
    let cache = temp_dir("render-dots");
    let ratio = |sampler: &str| {
        let j = metrics(
            &[
                "--scene",
                "dots",
                "--sampler",
                sampler,
                "--spp",
                "4",
                "--size",
                "128x128",
            ],
            &cache,
        );
        assert!(j.contains("\"error_radial_spectrum\":["), "{j}");
        let radial = j.split("\"error_radial_spectrum\":[").nth(1).unwrap();
        let radial = radial.split(']').next().unwrap();
        assert_eq!(radial.split(',').count(), 16, "{radial}");
        // What a low-pass leaves is part of the error: above 0, below the whole RMSE.
        let left = json_field(&j, "error_low_frequency_rmse");
        assert!(left > 0.0 && left < json_field(&j, "rmse"), "{j}");
        let se = json_field(&j, "error_low_frequency_ratio_se");
        assert!((0.0..0.1).contains(&se), "{j}");
        (json_field(&j, "error_low_frequency_ratio"), se)
    };
    for blue in ["owen-sobol-bn", "pmj02-bn", "lattice-bn"] {
        let (r, se) = ratio(blue);
        assert!(r < 0.75 && r + 4.0 * se < 1.0, "{blue}: {r} ± {se}");
    }
    let (white, se) = ratio("owen-sobol");
    assert!((white - 1.0).abs() < 4.0 * se, "{white} ± {se}");
    let cached = cache.join("nyquist");
    assert!(
        !cached.exists() || files(&cached).is_empty(),
        "the dots' reference is exact: nothing to cache"
    );
}

/// An 8 × 8 image has no frequency below a quarter of Nyquist: the ratio reads "-", as an
/// empty annulus does, and `--json` gives null; nothing prints NaN.
#[test]
fn a_tiny_image_has_no_low_band_and_says_so() {
    let cache = temp_dir("render-tiny");
    let s = human_metrics(&["--size", "8x8"], &cache);
    assert!(
        s.lines()
            .any(|l| l.starts_with("error spectrum low-frequency ratio - ")),
        "{s}"
    );
    assert!(!s.contains("NaN"), "{s}");
    let j = metrics(&["--size", "8x8"], &cache);
    assert!(j.contains("\"error_low_frequency_ratio\":null"), "{j}");
    assert!(j.contains("\"error_low_frequency_ratio_se\":null"), "{j}");
}

#[test]
fn human_metrics_print_every_number() {
    let cache = temp_dir("render-human");
    let s = human_metrics(&["--size", "16x16"], &cache);
    for key in [
        "rmse",
        "psnr",
        "sampling rmse",
        "error spectrum",
        "radial power",
        "samples/s",
        "rejected",
    ] {
        assert!(s.lines().any(|l| l.starts_with(key)), "{key} in {s}");
    }
}

#[test]
fn bad_input_is_one_line_exit_2_and_writes_nothing() {
    let dir = temp_dir("render-errors");
    let out = dir.join("x.png");
    let o = out.to_str().unwrap();
    let missing = dir.join("no/such/folder/x.png");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--sampler", "nope"], "--sampler"),
        (vec!["--scene", "teapot"], "--scene"),
        (
            vec!["--sampler", "best-candidate", "--spp", "5000"],
            "--spp 5000: best-candidate takes at most 4096",
        ),
        (vec!["--spp", "0"], "--spp"),
        (vec!["--spp", "1.5"], "--spp"),
        (vec!["--filter", "mitchel"], "--filter"),
        (vec!["--filter", "gaussian:alpha=-1"], "--filter"),
        (vec!["--filter", "box:radius=0"], "--filter"),
        (vec!["--size", "0x10"], "--size"),
        (vec!["--size", "64"], "--size"),
        (vec!["--size", "99999x2"], "--size"),
        (vec!["--size", "16384x16384"], "--size"),
        (vec!["--threads", "0"], "--threads"),
        (vec!["--seed", "x"], "--seed"),
    ];
    for (args, mentions) in cases {
        let mut all = vec!["render", "-o", o];
        all.extend_from_slice(&args);
        assert_one_line_error(&nyquist(&all), mentions);
        assert!(files(&dir).is_empty(), "{args:?} left {:?}", files(&dir));
    }
    let bad_ext = dir.join("x.jpg");
    assert_one_line_error(
        &nyquist(&["render", "-o", bad_ext.to_str().unwrap()]),
        "--output",
    );
    assert_one_line_error(
        &nyquist(&["render", "-o", missing.to_str().unwrap()]),
        "--output",
    );
    assert_one_line_error(&nyquist(&["render", "--size", "8x8"]), "--output");
    assert!(files(&dir).is_empty(), "{:?}", files(&dir));
}

#[test]
fn help_has_an_example() {
    let o = nyquist(&["render", "--help"]);
    assert!(o.status.success());
    assert!(stdout(&o).contains("Example: nyquist render"));
}

/// `--scramble` picks the scramble of halton, sobol and zsobol: each of the four gives its own
/// image (hammersley takes it too, for its dimensions from 2 on, which a zone plate does not
/// read); for halton and sobol `none` ignores the seed (zsobol's seed also permutes its Morton
/// digits); samplers without a choice refuse it (one line, exit 2, nothing written). `compare`
/// applies it to those rows only.
#[test]
fn scramble_chooses_among_four_and_is_refused_elsewhere() {
    let dir = temp_dir("render-scramble");
    let render = |sampler: &str, scramble: &str, seed: &str| {
        let out = dir.join(format!("{sampler}-{scramble}-{seed}.pfm"));
        let o = nyquist(&[
            "render",
            "--sampler",
            sampler,
            "--spp",
            "16",
            "--size",
            "32x32",
            "--seed",
            seed,
            "--scramble",
            scramble,
            "-o",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        read_pfm(&out).2
    };
    for sampler in ["halton", "sobol", "zsobol"] {
        let images: Vec<Vec<f32>> = ["none", "permute", "fast-owen", "owen"]
            .iter()
            .map(|s| render(sampler, s, "5"))
            .collect();
        for a in 0..4 {
            for b in a + 1..4 {
                assert!(
                    images[a] != images[b],
                    "{sampler}: scrambles {a} and {b} agree"
                );
            }
        }
        if sampler != "zsobol" {
            let unscrambled = render(sampler, "none", "6") == images[0];
            assert!(unscrambled, "{sampler}: `none` depends on the seed");
        }
        assert!(
            render(sampler, "owen", "6") != images[3],
            "{sampler}: owen ignores the seed"
        );
    }
    for sampler in ["random", "stratified", "owen-sobol", "pmj02"] {
        let out = dir.join("refused.png");
        let o = nyquist(&[
            "render",
            "--sampler",
            sampler,
            "--scramble",
            "owen",
            "-o",
            out.to_str().unwrap(),
        ]);
        assert_one_line_error(&o, "--scramble");
        assert!(!out.exists(), "{sampler} wrote {out:?}");
    }
    let o = nyquist(&[
        "compare",
        "--samplers",
        "random,sobol",
        "--spp",
        "1",
        "--size",
        "16x16",
        "--scramble",
        "owen",
        "--json",
        "-o",
        dir.join("c.png").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

/// The planes of an OpenEXR file, by name.
fn exr_planes(path: &std::path::Path) -> Vec<(String, Vec<f32>)> {
    let bytes = std::fs::read(path).unwrap();
    nyquist_film::output::exr::read_exr_planes(&mut bytes.as_slice())
        .unwrap()
        .2
}

#[test]
fn layers_go_into_one_exr_of_named_planes_and_leave_the_image_as_it_was() {
    let dir = temp_dir("render-layers-exr");
    let (plain, layered) = (dir.join("plain.exr"), dir.join("layered.exr"));
    let base = [
        "render",
        "--scene",
        "checkerboard",
        "--sampler",
        "sobol",
        "--size",
        "24x16",
    ];
    let run = |extra: &[&str], out: &std::path::Path| {
        let mut all = base.to_vec();
        all.extend_from_slice(extra);
        all.extend_from_slice(&["-o", out.to_str().unwrap()]);
        let o = nyquist(&all);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    };
    run(&[], &plain);
    run(
        &["--variance", "--ab", "--aov", "albedo,normal,depth"],
        &layered,
    );
    assert_eq!(files(&dir), ["layered.exr", "plain.exr"]);
    let (plain, layered) = (exr_planes(&plain), exr_planes(&layered));
    let names: Vec<&str> = layered.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        [
            "B",
            "G",
            "R",
            "albedo.B",
            "albedo.G",
            "albedo.R",
            "depth.Z",
            "half_a.B",
            "half_a.G",
            "half_a.R",
            "half_b.B",
            "half_b.G",
            "half_b.R",
            "normal.X",
            "normal.Y",
            "normal.Z",
            "variance.B",
            "variance.G",
            "variance.R"
        ]
    );
    // The image is the plain render's, bit for bit.
    for c in ["R", "G", "B"] {
        let get = |p: &[(String, Vec<f32>)]| p.iter().find(|(n, _)| n == c).unwrap().1.clone();
        let bits = |v: Vec<f32>| v.into_iter().map(f32::to_bits).collect::<Vec<_>>();
        assert_eq!(bits(get(&plain)), bits(get(&layered)), "{c}");
    }
    let plane = |name: &str| &layered.iter().find(|(n, _)| n == name).unwrap().1;
    // The checkerboard's horizon is at 30 % of the height (row 4.8): rows 0–3 see only sky,
    // rows from 6 on only ground, whose normal is up and whose depth grows toward the horizon.
    let (w, depth, ny) = (24, plane("depth.Z"), plane("normal.Y"));
    assert!(depth[..4 * w].iter().all(|&d| d == 1e10));
    assert!(ny[..4 * w].iter().all(|&n| n == 0.0));
    assert!(ny[6 * w..].iter().all(|&n| (n - 1.0).abs() < 1e-6));
    for y in 6..15 {
        assert!(depth[y * w] > depth[(y + 1) * w], "row {y}");
    }
    // The checks' albedo is the radiance of a uniformly lit pattern: the image itself.
    let image_r = plain.iter().find(|(n, _)| n == "R").unwrap().1.clone();
    for (a, r) in plane("albedo.R").iter().zip(&image_r) {
        assert!((a - r).abs() < 1e-5, "{a} against {r}");
    }
    assert!(plane("variance.R").iter().all(|&v| v >= 0.0));
}

#[test]
fn layers_beside_a_png_are_one_file_per_group() {
    let dir = temp_dir("render-layers-png");
    let out = dir.join("out.png");
    let o = nyquist(&[
        "render",
        "--size",
        "16x16",
        "--variance",
        "--ab",
        "--aov",
        "depth,albedo",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(
        files(&dir),
        [
            "out.albedo.png",
            "out.depth.png",
            "out.half_a.png",
            "out.half_b.png",
            "out.png",
            "out.variance.png"
        ]
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("layers written to"), "{err}");
    // To stdout only as one EXR stream; a group given twice is refused; nothing is written.
    let dir = temp_dir("render-layers-refused");
    let o = nyquist(&["render", "--variance", "-o", "-", "--format", "png"]);
    assert_one_line_error(&o, "--output -: the layers of --variance, --ab and --aov");
    let x = dir.join("x.png");
    let o = nyquist(&[
        "render",
        "--aov",
        "depth,albedo,depth",
        "-o",
        x.to_str().unwrap(),
    ]);
    assert_one_line_error(&o, "--aov depth,albedo,depth: depth is given twice");
    assert_one_line_error(
        &nyquist(&["render", "--aov", "id", "-o", x.to_str().unwrap()]),
        "--aov",
    );
    assert!(files(&dir).is_empty(), "{:?}", files(&dir));
    let o = nyquist(&[
        "render", "--size", "8x8", "--ab", "-o", "-", "--format", "exr",
    ]);
    assert!(o.status.success());
    assert_eq!(&o.stdout[..4], &[0x76, 0x2f, 0x31, 0x01]);
}

#[test]
fn predicted_rmse_matches_the_error_of_independent_samples() {
    // With independent random samples both estimates are unbiased for the variance of each
    // pixel's value, so their root mean over 4096 pixels should match the measured sampling
    // RMSE: the mean of 4096 squared errors has a relative spread of about 2.2 % (halves) and
    // 1 % (variance) here, so ±15 % is far outside chance (false alarms below 10⁻⁹).
    let dir = temp_dir("render-predicted");
    let json = metrics(
        &[
            "--sampler",
            "random",
            "--spp",
            "16",
            "--size",
            "64x64",
            "--variance",
            "--ab",
        ],
        &dir,
    );
    let sampling = json_field(&json, "sampling_rmse");
    for key in ["predicted_rmse_variance", "predicted_rmse_halves"] {
        let predicted = json_field(&json, key);
        let ratio = predicted / sampling;
        assert!(
            (0.85..1.15).contains(&ratio),
            "{key} {predicted} against {sampling}"
        );
    }
    // One sample per pixel has no variance: null, and a line that says why.
    let json = metrics(
        &[
            "--sampler",
            "uniform",
            "--spp",
            "1",
            "--size",
            "8x8",
            "--variance",
        ],
        &dir,
    );
    assert!(json.contains("\"predicted_rmse_variance\":null"), "{json}");
    let o = nyquist_cached(
        &[
            "render",
            "--spp",
            "1",
            "--size",
            "8x8",
            "--variance",
            "--metrics",
        ],
        &dir,
    );
    assert!(stdout(&o).contains(
        "predicted rmse - (√ mean variance, --variance: no pixel has two samples in it)"
    ));
}

#[test]
fn adaptive_sampling_lowers_the_error_at_the_same_budget_and_maps_its_samples() {
    let dir = temp_dir("render-adaptive");
    let base = [
        "--scene",
        "disk",
        "--sampler",
        "owen-sobol",
        "--spp",
        "64",
        "--size",
        "64x64",
    ];
    let uniform = json_field(&metrics(&base, &dir), "sampling_rmse");
    let map = dir.join("map.png");
    let mut args = base.to_vec();
    args.extend_from_slice(&["--adaptive", "0.01", "--spp-map", map.to_str().unwrap()]);
    let json = metrics(&args, &dir);
    let adaptive = json_field(&json, "sampling_rmse");
    let mean = json_field(&json, "mean_spp");
    assert!(mean <= 64.0, "{json}");
    // Measured: 0.00080 against 0.0028 (3.5 times lower) at 63.98 spp on average.
    assert!(
        adaptive < 0.5 * uniform,
        "adaptive {adaptive}, uniform {uniform}"
    );
    let png = std::fs::read(&map).unwrap();
    let decoder = png::Decoder::new(std::io::Cursor::new(png));
    let info = decoder.read_info().unwrap().info().clone();
    assert_eq!((info.width, info.height), (64, 64));
    // The same bytes on one thread and on three.
    let out = |threads: &str| {
        let path = dir.join(format!("a{threads}.pfm"));
        let mut all = vec!["render", "--threads", threads, "-o", path.to_str().unwrap()];
        all.extend_from_slice(&args[..args.len() - 2]);
        let o = nyquist(&all);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read(path).unwrap()
    };
    assert_eq!(out("1"), out("3"));
}

#[test]
fn adaptive_sampling_refuses_what_it_cannot_do() {
    let dir = temp_dir("render-adaptive-refused");
    let x = dir.join("x.png");
    let x = x.to_str().unwrap();
    assert_one_line_error(
        &nyquist(&[
            "render",
            "--adaptive",
            "0.01",
            "--sampler",
            "stratified",
            "-o",
            x,
        ]),
        "--adaptive 0.01: --sampler stratified lays out a fixed set for its spp",
    );
    assert_one_line_error(
        &nyquist(&["render", "--spp-map", "m.png", "-o", x]),
        "--spp-map m.png: only with --adaptive",
    );
    assert_one_line_error(
        &nyquist(&["render", "--adaptive", "-1", "-o", x]),
        "--adaptive -1: not in 0 ..= 1000000",
    );
    assert_one_line_error(
        &nyquist(&[
            "render",
            "--adaptive",
            "0.1",
            "--sampler",
            "sobol",
            "--spp",
            "1",
            "-o",
            x,
        ]),
        "--adaptive 0.1: --spp 1 leaves no second sample",
    );
    assert!(files(&dir).is_empty(), "{:?}", files(&dir));
}

/// `--spp-hint`: the sampler is made for the hint and draws `--spp` samples past it. Owen-Sobol's
/// samples do not depend on its spp, so the image is the one of `--spp` alone; ZSobol's past
/// the hint are new epochs, closer to the reference than the hint's own render. A sampler
/// that wraps at its spp is refused.
#[test]
fn spp_hint_draws_past_the_samplers_spp() {
    let cache = temp_dir("render-spp-hint");
    let rmse = |args: &[&str]| -> f64 {
        let mut all = vec!["--size", "48x32", "--scene", "zoneplate"];
        all.extend_from_slice(args);
        json_field(&metrics(&all, &cache), "rmse")
    };
    let plain = rmse(&["--sampler", "owen-sobol", "--spp", "32"]);
    let hinted = rmse(&["--sampler", "owen-sobol", "--spp", "32", "--spp-hint", "8"]);
    assert_eq!(plain, hinted);
    let eight = rmse(&["--sampler", "zsobol", "--spp", "8"]);
    let past = rmse(&["--sampler", "zsobol", "--spp", "64", "--spp-hint", "8"]);
    assert!(past < eight / 2.0, "{past} against {eight}");
    let o = nyquist(&[
        "render",
        "--sampler",
        "zero-two",
        "--spp",
        "64",
        "--spp-hint",
        "8",
        "--metrics",
    ]);
    assert_one_line_error(&o, "--spp-hint");
}
