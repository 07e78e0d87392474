//! Checks run on every contender's output before it is timed, so that a broken shim is reported
//! instead of measured.

/// Every value in `[0, 1)`.
pub fn unit_range(what: &str, v: &[f32]) -> Result<(), String> {
    match v.iter().position(|x| !(0.0..1.0).contains(x)) {
        None => Ok(()),
        Some(i) => Err(format!("{what}: value {i} = {} is outside [0, 1)", v[i])),
    }
}

/// `n` values (a stride apart, from `first`) fall one into each of `n` equal intervals: what
/// the first `n` points of a (0, 2)-sequence or of a scrambled Sobol dimension do. A value within
/// 2⁻¹⁶ above an interval's lower edge may count in the interval below (at 0: the last one):
/// film positions are `pixel + u` in `f32`, whose rounding can carry `u` onto the next interval,
/// and a peer's `u` just below 1 can round onto the next pixel's corner, a fractional part of 0
/// (nyquist's `camera_sample` keeps it below the corner: `sampler::film_coordinate`).
pub fn stratified(
    what: &str,
    v: &[f32],
    first: usize,
    stride: usize,
    n: usize,
) -> Result<(), String> {
    const EDGE: f32 = 1.0 / 65536.0;
    let mut seen = vec![false; n];
    let mut near_edge = Vec::new();
    for k in 0..n {
        let x = v[first + k * stride].fract() * n as f32;
        let bin = (x as usize).min(n - 1);
        let lower = x - (bin as f32) < EDGE * n as f32;
        if lower {
            near_edge.push(bin);
        } else if std::mem::replace(&mut seen[bin], true) {
            return Err(format!(
                "{what}: {n} values are not stratified (two in interval {bin})"
            ));
        }
    }
    for bin in near_edge {
        let free = [bin, (bin + n - 1) % n].into_iter().find(|&b| !seen[b]);
        match free {
            Some(b) => seen[b] = true,
            None => {
                return Err(format!(
                    "{what}: {n} values are not stratified (two in interval {bin})"
                ));
            }
        }
    }
    Ok(())
}

/// The mean of the values a stride apart from `first` is within `tol` of `mean`.
pub fn mean(
    what: &str,
    v: &[f32],
    first: usize,
    stride: usize,
    want: f64,
    tol: f64,
) -> Result<(), String> {
    let picked: Vec<f64> = v
        .iter()
        .skip(first)
        .step_by(stride)
        .map(|&x| x as f64)
        .collect();
    let m = picked.iter().sum::<f64>() / picked.len() as f64;
    if (m - want).abs() <= tol {
        Ok(())
    } else {
        Err(format!("{what}: mean {m:.4}, expected {want} ± {tol}"))
    }
}

/// Camera samples, 5 floats each (film x, film y, time, lens u, lens v), of `px × px` pixels
/// from `origin` at `spp` samples each, pixel-major: every film position inside its pixel, the
/// other values in `[0, 1)`, each dimension's mean near ½, and, when `stratified_dims` says so,
/// each pixel's film x (and y) stratified over its `spp` samples.
pub fn camera(
    what: &str,
    v: &[f32],
    origin: [u32; 2],
    px: u32,
    spp: u32,
    stratified_dims: usize,
) -> Result<(), String> {
    let per_pixel = 5 * spp as usize;
    for (k, pixel) in v.chunks_exact(per_pixel).enumerate() {
        let (x, y) = (origin[0] + k as u32 % px, origin[1] + k as u32 / px);
        for s in pixel.chunks_exact(5) {
            let (fx, fy) = (s[0] - x as f32, s[1] - y as f32);
            if !(0.0..1.0).contains(&fx) || !(0.0..1.0).contains(&fy) {
                return Err(format!(
                    "{what}: film position ({}, {}) outside pixel ({x}, {y})",
                    s[0], s[1]
                ));
            }
            unit_range(what, &s[2..])?;
        }
        for d in 0..stratified_dims {
            stratified(
                &format!("{what}, pixel ({x}, {y}), film dim {d}"),
                pixel,
                d,
                5,
                spp as usize,
            )?;
        }
    }
    let fract: Vec<f32> = v.iter().map(|x| x.fract()).collect();
    for d in 0..5 {
        mean(&format!("{what}, dim {d}"), &fract, d, 5, 0.5, 0.05)?;
    }
    Ok(())
}

/// `b` holds the values of `a` (the expected ones) to within `tol` (absolute), index by index.
pub fn close(what: &str, a: &[f32], b: &[f32], tol: f32) -> Result<(), String> {
    if a.len() != b.len() {
        return Err(format!("{what}: {} values against {}", a.len(), b.len()));
    }
    match (0..a.len()).find(|&i| !((a[i] - b[i]).abs() <= tol)) {
        None => Ok(()),
        Some(i) => Err(format!(
            "{what}: value {i} is {}, expected {} (tolerance {tol})",
            b[i], a[i]
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stratified_takes_one_value_per_interval() {
        let v: Vec<f32> = (0..16)
            .map(|i| ((i * 7) % 16) as f32 / 16.0 + 0.01)
            .collect();
        assert!(stratified("v", &v, 0, 1, 16).is_ok());
        let mut twice = v.clone();
        twice[3] = twice[4];
        assert!(stratified("v", &twice, 0, 1, 16).is_err());
    }

    #[test]
    fn stratified_lets_a_value_on_an_edge_count_below() {
        // Interval 1 is empty and interval 2 holds 0.125 (its lower edge) and 0.13.
        let mut v: Vec<f32> = (0..16).map(|i| i as f32 / 16.0 + 0.01).collect();
        v[1] = 0.125;
        assert!(stratified("v", &v, 0, 1, 16).is_ok());
        // 1 wrapped to 0 fills the last interval.
        let mut w: Vec<f32> = (0..16).map(|i| i as f32 / 16.0 + 0.01).collect();
        w[15] = 0.0;
        assert!(stratified("w", &w, 0, 1, 16).is_ok());
        // Not past the edge's reach.
        v[1] = 0.126;
        assert!(stratified("v", &v, 0, 1, 16).is_err());
    }

    #[test]
    fn stratified_reads_with_a_stride() {
        let v: Vec<f32> = (0..8).flat_map(|i| [i as f32 / 8.0, 0.5]).collect();
        assert!(stratified("v", &v, 0, 2, 8).is_ok());
        assert!(stratified("v", &v, 1, 2, 8).is_err());
    }

    #[test]
    fn camera_rejects_a_sample_outside_its_pixel_or_a_lopsided_mean() {
        let (origin, spp) = ([10, 20], 4u32);
        let good: Vec<f32> = (0..spp)
            .flat_map(|i| {
                let u = (i as f32 + 0.5) / spp as f32;
                [10.0 + u, 20.0 + 1.0 - u, u, 1.0 - u, u]
            })
            .collect();
        assert!(camera("c", &good, origin, 1, spp, 2).is_ok());
        let mut outside = good.clone();
        outside[0] = 11.0;
        assert!(camera("c", &outside, origin, 1, spp, 0).is_err());
        let mut out_of_range = good.clone();
        out_of_range[2] = 1.0;
        assert!(camera("c", &out_of_range, origin, 1, spp, 0).is_err());
        let zeros: Vec<f32> = (0..spp).flat_map(|_| [10.5, 20.5, 0.0, 0.0, 0.0]).collect();
        assert!(camera("c", &zeros, origin, 1, spp, 0).is_err());
    }

    #[test]
    fn close_and_mean_and_range() {
        assert!(close("c", &[1.0, 2.0], &[1.0, 2.05], 0.1).is_ok());
        assert!(close("c", &[1.0, 2.0], &[1.0, 2.2], 0.1).is_err());
        assert!(close("c", &[1.0], &[f32::NAN], 0.1).is_err());
        assert!(close("c", &[1.0], &[1.0, 2.0], 0.1).is_err());
        assert!(mean("m", &[0.25, 0.75, 0.5], 0, 1, 0.5, 0.01).is_ok());
        assert!(mean("m", &[0.25, 0.25], 0, 1, 0.5, 0.01).is_err());
        assert!(unit_range("u", &[0.0, 0.999]).is_ok());
        assert!(unit_range("u", &[1.0]).is_err());
        assert!(unit_range("u", &[-0.0, f32::NAN]).is_err());
    }
}
