//! End-to-end tests of `nyquist mask`.

mod common;

use common::{assert_one_line_error, files, nyquist, temp_dir};

/// Decodes a PNG: (width, height, channels, samples as u16).
fn decode(path: &std::path::Path) -> (u32, u32, usize, Vec<u16>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    let channels = info.color_type.samples();
    let samples = match info.bit_depth {
        png::BitDepth::Sixteen => buf[..info.buffer_size()]
            .chunks_exact(2)
            .map(|b| u16::from_be_bytes([b[0], b[1]]))
            .collect(),
        _ => buf[..info.buffer_size()]
            .iter()
            .map(|&b| u16::from(b))
            .collect(),
    };
    (info.width, info.height, channels, samples)
}

/// 128² RGBA, 8 bits: every level 0 … 255 appears exactly 64 times per channel; 16 bits: every
/// channel is a permutation of the 16384 levels 4·r; the EXR is written; same seed, same bytes.
#[test]
fn mask_png_levels_are_exact_and_exr_is_written() {
    let dir = temp_dir("mask");
    let (p8, p16, exr) = (dir.join("m8.png"), dir.join("m16.png"), dir.join("m.exr"));
    let o = nyquist(&[
        "mask",
        "--size",
        "128",
        "--channels",
        "4",
        "--seed",
        "3",
        "-o",
        p8.to_str().unwrap(),
        "-o",
        exr.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (w, h, c, s) = decode(&p8);
    assert_eq!((w, h, c), (128, 128, 4));
    for ch in 0..4 {
        let mut count = [0u32; 256];
        s.iter()
            .skip(ch)
            .step_by(4)
            .for_each(|&v| count[v as usize] += 1);
        assert!(count.iter().all(|&k| k == 64), "channel {ch}");
    }
    let exr_bytes = std::fs::read(&exr).unwrap();
    assert_eq!(&exr_bytes[..4], &[0x76, 0x2f, 0x31, 0x01]);
    let o = nyquist(&[
        "mask",
        "--size",
        "128",
        "--channels",
        "4",
        "--seed",
        "3",
        "--bits",
        "16",
        "-o",
        p16.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let (_, _, _, s16) = decode(&p16);
    for ch in 0..4 {
        let mut levels: Vec<u16> = s16.iter().skip(ch).step_by(4).copied().collect();
        levels.sort_unstable();
        assert!(levels.iter().enumerate().all(|(i, &v)| v as usize == 4 * i));
        // The 8-bit file is the same mask: level ⌊r/64⌋ = ⌊(4r)/256⌋.
        for (a, b) in s
            .iter()
            .skip(ch)
            .step_by(4)
            .zip(s16.iter().skip(ch).step_by(4))
        {
            assert_eq!(*a, b >> 8);
        }
    }
    let again = dir.join("again.png");
    nyquist(&[
        "mask",
        "--size",
        "128",
        "--channels",
        "4",
        "--seed",
        "3",
        "-o",
        again.to_str().unwrap(),
    ]);
    assert_eq!(std::fs::read(&again).unwrap(), std::fs::read(&p8).unwrap());
}

/// Non-square sizes and one channel give a grey PNG of that size.
#[test]
fn non_square_grey_mask() {
    let dir = temp_dir("mask-rect");
    let p = dir.join("r.png");
    let spec = dir.join("s.png");
    let o = nyquist(&[
        "mask",
        "--size",
        "48x20",
        "-o",
        p.to_str().unwrap(),
        "--spectrum",
        spec.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (w, h, c, _) = decode(&p);
    assert_eq!((w, h, c), (48, 20, 1));
    assert_eq!(decode(&spec).0, 48);
}

/// Every bad flag: one line naming it, exit 2, no file left.
#[test]
fn bad_flags_are_one_line_and_leave_nothing() {
    let dir = temp_dir("mask-errors");
    let out = dir.join("m.png");
    let o = out.to_str().unwrap();
    for (args, mentions) in [
        (vec!["--size", "0", "-o", o], "--size"),
        (vec!["--size", "2048", "-o", o], "1024"),
        (vec!["--size", "1025x4", "-o", o], "1025x4"),
        (vec!["--channels", "5", "-o", o], "--channels"),
        (vec!["--channels", "0", "-o", o], "--channels"),
        (vec!["--bits", "12", "-o", o], "--bits"),
        (vec!["-o", "x.tif"], "--output"),
        (
            vec!["--size", "512", "--spectrum", "s.png", "-o", o],
            "--spectrum",
        ),
        (vec!["--spectrum", "s.exr", "-o", o], "--spectrum"),
        (vec![], "--output"),
    ] {
        let mut all = vec!["mask"];
        all.extend_from_slice(&args);
        assert_one_line_error(&nyquist(&all), mentions);
    }
    assert!(files(&dir).is_empty(), "{:?}", files(&dir));
}

/// `render --error` writes the grey error image at the render's size; its mean is mid grey
/// within 2 levels (the error of an unbiased sampler averages out) and a flat image would
/// be a failure; a bad path is one line naming --error.
#[test]
fn render_writes_the_error_image() {
    let dir = temp_dir("render-error");
    let p = dir.join("e.png");
    let o = nyquist(&[
        "render",
        "--scene",
        "zoneplate",
        "--sampler",
        "bluenoise-dithered",
        "--spp",
        "4",
        "--size",
        "64x48",
        "--threads",
        "1",
        "--error",
        p.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (w, h, c, s) = decode(&p);
    assert_eq!((w, h, c), (64, 48, 1));
    let mean = s.iter().map(|&v| f64::from(v)).sum::<f64>() / s.len() as f64;
    assert!((mean - 127.5).abs() < 2.0, "{mean}");
    assert!(s.iter().any(|&v| v != s[0]));
    let bad = dir.join("e.tif");
    assert_one_line_error(
        &nyquist(&["render", "--size", "8x8", "--error", bad.to_str().unwrap()]),
        "--error",
    );
    assert_eq!(files(&dir), vec!["e.png".to_string()]);
}
