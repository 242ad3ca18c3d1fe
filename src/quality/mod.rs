//! Measuring a picture against a reference: the figures BENCHMARKS.md
//! reports (PSNR, SSIM, error along the skyline and the coast, visible
//! facet edges), used by examples/quality.rs and checked on known images
//! by their own tests.
//! Pure arithmetic on pixels: nothing here draws or reads files.

pub mod facets;
pub mod image;
pub mod metrics;
pub mod registration;
