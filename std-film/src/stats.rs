//! Counters: what tiles took in ([`FilmStats`]) and what resolving found ([`ResolveStats`]).

/// Counters kept by tiles and summed by the film.
///
/// ```
/// let s = nyquist_film::FilmStats::default();
/// assert_eq!(s.samples + s.rejected + s.clamped + s.splats, 0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FilmStats {
    /// Samples added (accepted).
    pub samples: u64,
    /// Samples dropped because a radiance component or the weight was NaN or infinite.
    pub rejected: u64,
    /// Accepted samples scaled down by the `max_component` clamp.
    pub clamped: u64,
    /// Splats added (accepted).
    pub splats: u64,
}

impl FilmStats {
    pub(crate) fn add(&mut self, o: &FilmStats) {
        self.samples += o.samples;
        self.rejected += o.rejected;
        self.clamped += o.clamped;
        self.splats += o.splats;
    }
}

/// What resolving the film into an image found.
///
/// ```
/// let r = nyquist_film::ResolveStats::default();
/// assert_eq!(r.negative_components + r.uncovered_pixels, 0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ResolveStats {
    /// Final pixel components below zero (from negative filter lobes), written as 0.
    pub negative_components: u64,
    /// Pixels whose weight sum was ≤ 0 and that resolved to 0 (before splats).
    pub zero_weight_pixels: u64,
    /// Pixels inside no merged tile's bounds (a tile is missing), resolved from whatever reached
    /// them; 0 once every tile is merged, or when samples were added to the film itself
    /// ([`Film::add_sample`](crate::Film::add_sample)).
    pub uncovered_pixels: u64,
}
