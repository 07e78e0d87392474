//! Blue-noise threshold masks (dither arrays) by Ulichney's void-and-cluster method, and
//! Poisson-disk sets by Bridson's algorithm ([`PoissonDisk`]).
//!
//! A mask of `W × H` pixels is a permutation of the ranks `0 … W·H − 1`; thresholding it at any
//! level `t` (the pixels of rank `< t·W·H`) gives a binary pattern whose ones are spread as
//! evenly as the method can: its power spectrum has little energy at low frequencies (blue
//! noise). Masks tile: the energy is measured on the torus, so the pattern continues across
//! the edges.
//!
//! [`VoidAndCluster`] builds one channel into caller buffers (ranks `u32`, energy `f32`, and
//! `u32` working space sized by [`VoidAndCluster::scratch_len`]); channel `c` of a multi-channel
//! mask is the mask of [`VoidAndCluster::channel`]`(c)`, an independent seed, so channels are
//! uncorrelated. [`rank_to_value`] maps a rank to `(rank + ½)/N` in `[0, 1)`.
//!
//! Source: R. Ulichney, "The void-and-cluster method for dither array generation", *Proc. SPIE*
//! 1913 (1993), with the Gaussian energy filter of σ = 1.5 the paper recommends.

mod poisson_disk;
mod void_and_cluster;

pub use poisson_disk::{MIN_RADIUS, PoissonDisk};
pub use void_and_cluster::{
    KERNEL_RADIUS, MAX_MASK_PIXELS, SIGMA, VoidAndCluster, rank_to_value, ranks_to_values,
};

#[cfg(test)]
pub(crate) mod tests;
