//! Everything that makes a mountain's heights. Pure: no windows, no clocks.

mod brownian;
mod cliffs;
mod coast;
pub(crate) mod curves;
mod erosion;
mod fft;
pub mod heightfield;
pub mod heightmap;
pub mod lakes;
pub(crate) mod neighbours;
pub(crate) mod noise;
mod normalize;
mod params;
pub(crate) mod splitmix;
mod square;
mod subdivide;
mod triangle;
pub mod wetness;

pub use cliffs::STEP_SHARE as CLIFF_STEP_SHARE;
pub use cliffs::Strata;
pub use heightfield::Heightfield;
pub use lakes::Lakes;
pub use wetness::Wetness;

use params::Params;
use subdivide::{Audited, Extremes, Job, Plain, Put};

use crate::settings::{Generator, Settings, worlds};

/// Builds the mountain the settings describe from one seed, bit for bit the
/// same on every platform, build and thread count.
///
/// # Units
/// Heights are in *height units*, sea level at 0, and
/// [`Heightfield::extent`] is the width of the grid in the same units, so
/// `height / extent` is the true slope. The extent depends only on the
/// generator, never on the detail level: a detail change refines the same
/// mountain (a point keeps its random value at every detail level, so a
/// coarser grid is the finer one with points left out).
/// - Square and Diamond (Mountain Terrain 3.0): the corners start within
///   `±elevation/2` (elevation 100 by default) and cragginess adds at most
///   `±cragginess` more. Diamond starts instead from a 5x5 lattice (see
///   `square::LATTICE_DEPTH`), which gives every map several massifs. With the defaults (cragginess 96) the highest peak
///   averages about 45 above the generator's zero (30-70 by seed) and the
///   relief about 90, over an extent of [`SQUARE_EXTENT`]: peaks 16-24% of
///   the width, tall enough to read as mountains from the vista's low
///   camera (at 400 wide they read as a bumpy plateau). `height` scales the relief by `height / 5`, so the default
///   5 leaves it as generated and cragginess still makes taller or flatter
///   mountains, as in Mountain Terrain.
/// - Triangle (Fractal Mountain Climbing): the highest point is exactly
///   `height * TRIANGLE_PEAK_PER_HEIGHT` (100 for the default 5) over an
///   extent of [`TRIANGLE_EXTENT`] (20% of the width), after the contour
///   power. If the sea is more than four times deeper than the land is high
///   (a Bay profile, or a high sea level), the deepest point is put at
///   `-4 * peak` instead and the land stays lower than `peak`.
/// - Brownian (spectral synthesis, see `brownian.rs`): a surface with a
///   standard deviation of 16 at the default `hurst` 0.8 (a relief of about
///   90, as the square generators') over [`SQUARE_EXTENT`]; other `hurst`
///   values keep the height differences across 1/64 of the width, so a
///   rough surface is lower, not a forest of needles. `height` scales it
///   as it does the square generators'.
///
/// # Sea level
/// `settings.sea_level` moves the water line by a fraction of the relief on
/// its side of the generator's zero: `0.5` raises it halfway from the
/// generator's zero to the highest point, `1` to the highest point (all
/// sea), `-0.5` lowers it halfway to the lowest point, `-1` to the lowest
/// point (no sea). For the triangle generator this happens before the
/// contour and height scaling, so the highest point above the new water
/// line still gets the chosen height. Heights are then shifted so the
/// water line is 0 in the output.
pub fn generate(settings: &Settings, seed: u64) -> Heightfield {
    generate_with_threads(settings, seed, default_threads())
}

/// [`generate`] on at most `threads` threads (0 counts as 1). The result
/// is the same for every thread count.
pub fn generate_with_threads(settings: &Settings, seed: u64, threads: usize) -> Heightfield {
    let params = params_for(settings, seed);
    let mut field = Heightfield::flat(params.exponent, params.extent());
    fill(&mut field, &params, seed, threads);
    field
}

/// [`generate`] into an existing field, reusing its memory when its size
/// fits (else it is replaced): a slide show that recycles the previous
/// mountain's field skips the cost of fresh pages (for a large field the
/// kernel's zeroed pages cost about as much as the generator's filling
/// them). Every point is overwritten; the result is the
/// same bits as `generate`.
pub fn generate_into(settings: &Settings, seed: u64, field: &mut Heightfield) {
    let params = params_for(settings, seed);
    if field.exponent() == params.exponent {
        field.set_extent(params.extent());
    } else {
        *field = Heightfield::flat(params.exponent, params.extent());
    }
    fill(field, &params, seed, default_threads());
}

/// The tallest a world's drawn land stands above its water line, in grid
/// widths. The vista frames land up to about half the width tall with
/// its back edge across the frame (`render::framing::vista`); taller, a
/// slide showed the whole grid as a block floating in the sky (3 of
/// seeds 1-480: alpine and desert ranges drawn 7 or 8 high over a low
/// sea, 0.51-0.61 widths tall). The tallest of the others stand 0.49.
pub const DRAWN_TALLEST: f32 = 0.45;

/// The parameters `settings` give the mountain of `seed` in its world
/// (`worlds::drawn`).
fn params_for(settings: &Settings, seed: u64) -> Params {
    let mut params = Params::from_settings(&worlds::drawn(settings, Some(seed)));
    params.tallest = worlds::height_drawn(settings, Some(seed)).then_some(DRAWN_TALLEST);
    params
}

/// Runs the generator and the finishing passes over `field`.
fn fill(field: &mut Heightfield, params: &Params, seed: u64, threads: usize) {
    let threads = threads.max(1);
    let alongside = erodes_alongside(params, threads);
    fill_wearing(field, params, seed, threads, alongside);
}

/// Whether the erosion `p` asks for runs alongside the subdivision: if
/// there is a thread to spare for it, the droplets running one after
/// another while the finer levels are made.
fn erodes_alongside(p: &Params, threads: usize) -> bool {
    p.erosion > 0.0 && threads > 1
}

/// [`fill`], eroding alongside the subdivision if `alongside`, else after
/// it (as the saved data sets of before were made).
fn fill_wearing(
    field: &mut Heightfield,
    params: &Params,
    seed: u64,
    threads: usize,
    alongside: bool,
) {
    field.set_seed(Some(seed));
    let extremes = subdivide_all(field, params, seed, threads, &Plain, alongside);
    let extremes = match alongside {
        // Worn: the subdivision's extremes no longer hold.
        true => None,
        false => weather(field, params, seed, threads, extremes),
    };
    finish(field, params, threads, extremes);
    if let Some(tallest) = params.tallest {
        lower_to(field, tallest);
    }
    cliffs::terrace(field, params.cliffs, threads);
    find_lakes(field, params);
}

/// Lowers the land of `field` (all its heights alike: the same mountain,
/// less tall) where it stands more than `tallest` grid widths above its
/// water line, as measured on the lattice every detail shares
/// ([`SHARED_EXPONENT`]), so a mountain is lowered alike at every size.
fn lower_to(field: &mut Heightfield, tallest: f32) {
    let cells = field.size() - 1;
    let step = (cells >> SHARED_EXPONENT).max(1);
    let top = (0..=cells)
        .step_by(step)
        .flat_map(|y| field.row(y).iter().step_by(step).copied())
        .filter(|h| h.is_finite())
        .fold(0.0f32, f32::max);
    let most = tallest * field.extent();
    if top > most {
        let k = most / top;
        field.heights_mut().iter_mut().for_each(|h| *h *= k);
    }
}

/// The lakes of the finished field, if asked for (`lakes = true`).
fn find_lakes(field: &mut Heightfield, p: &Params) {
    let lakes = p
        .lakes
        .then(|| std::sync::Arc::new(Lakes::of(field.heights(), field.size())));
    field.set_lakes(lakes);
}

/// Grids of this exponent or finer hold the same mountain on their nested
/// `2^SHARED_EXPONENT + 1`-point lattice at every detail (up to the water
/// line's small shift, a percentile of each grid's own heights): erosion
/// runs on that lattice whatever the detail. Coarser grids are eroded on
/// themselves, into a somewhat different mountain.
pub const SHARED_EXPONENT: u32 = erosion::COARSE_CELLS.ilog2();

/// Width of the grid of the square generators, in height units.
pub const SQUARE_EXTENT: f32 = 250.0;
/// Width of the grid of the triangle generator, in height units.
pub const TRIANGLE_EXTENT: f32 = 500.0;
/// Height units of the triangle generator's highest point per step of
/// `settings.height`.
pub const TRIANGLE_PEAK_PER_HEIGHT: f32 = 20.0;

/// What [`generate_audited`] found out about one run of a generator.
#[derive(Debug, Clone)]
pub struct Audit {
    /// The finished field: bit for bit what [`generate`] returns.
    pub field: Heightfield,
    /// Stores onto a grid point that was already set: each one could
    /// open a crack between the triangles that share the point.
    pub rewrites: usize,
    /// Grid points left unset (or computed from an unset point).
    pub unset: usize,
}

/// Runs [`generate`] with every grid write checked, for tests: the field
/// starts as NaN, a store onto a point that is no longer NaN counts as a
/// rewrite, and points still NaN after the subdivision count as unset.
/// Slower than `generate`; the generator code it runs is the same.
pub fn generate_audited(settings: &Settings, seed: u64, threads: usize) -> Audit {
    let settings = &worlds::drawn(settings, Some(seed));
    let params = Params::from_settings(settings);
    let threads = threads.max(1);
    let mut field = Heightfield::flat(params.exponent, params.extent());
    field.heights_mut().fill(f32::NAN);
    field.set_seed(Some(seed));
    let audit = Audited::default();
    let extremes = subdivide_all(&mut field, &params, seed, threads, &audit, false);
    let unset = field.heights().iter().filter(|h| h.is_nan()).count();
    let extremes = weather(&mut field, &params, seed, threads, extremes);
    finish(&mut field, &params, threads, extremes);
    cliffs::terrace(&mut field, params.cliffs, threads);
    find_lakes(&mut field, &params);
    Audit {
        field,
        rewrites: audit.rewrites.into_inner(),
        unset,
    }
}

/// Threads `generate` uses: the machine's, up to 8 (the work is memory-bound).
/// Erosion, if asked for, after the subdivision and before the water line is
/// placed (so the coast is found on the worn land); the subdivision's
/// extremes no longer hold after it.
fn weather(
    field: &mut Heightfield,
    p: &Params,
    seed: u64,
    threads: usize,
    extremes: Option<Extremes>,
) -> Option<Extremes> {
    if p.erosion > 0.0 {
        erosion::erode(field, p.erosion, seed, threads);
        return None;
    }
    extremes
}

fn default_threads() -> usize {
    crate::cores::cores().min(8)
}

/// Sets the starting points and runs the chosen generator's subdivision,
/// and its erosion if `alongside` (else the caller erodes, [`weather`]);
/// returns the field's extremes if the subdivision saw them all.
fn subdivide_all<P: Put>(
    field: &mut Heightfield,
    p: &Params,
    seed: u64,
    threads: usize,
    put: &P,
    alongside: bool,
) -> Option<Extremes> {
    // The erosion's strength and where its rain falls.
    let wear = alongside.then_some((p.erosion, seed));
    let size = field.size();
    let noise = noise::Noise::new(seed, p.exponent)
        .spread(p.spread)
        .still_edges(p.still_edges);
    let heights = field.heights_mut();
    match p.generator {
        Generator::Square | Generator::Diamond => {
            let ordering = if p.generator == Generator::Square {
                square::Ordering::Midpoint
            } else {
                square::Ordering::Diamond
            };
            let rule = square::Square {
                ordering,
                cragginess: p.cragginess,
                edge_share: p.edge_share,
            };
            let first_depth = rule.start(heights, size, p.elevation, &noise, put);
            // Only a moved water line needs the extremes.
            let job = Job::new(&rule, put, noise, threads, p.sea_level != 0.0);
            subdivide_wearing(field, first_depth, &job, wear)
        }
        Generator::Triangle => {
            let rule = triangle::Triangle::new(p.roughness, p.profile);
            rule.first_level(heights, size, &noise, put);
            let job = Job::new(&rule, put, noise, threads, true);
            subdivide_wearing(field, 1, &job, wear)
        }
        Generator::Brownian => {
            brownian::synthesise(heights, p.exponent, p.hurst, seed, threads);
            if alongside {
                erosion::erode(field, p.erosion, seed, threads);
            }
            None
        }
    }
}

/// The subdivision's levels from `first_depth` on, with the droplets of
/// `wear` (the erosion's strength and seed) on a thread of their own from
/// the level that makes the points they wear on, alongside the finer
/// levels, which never write those points again: the same field as
/// eroding after the subdivision, sooner.
fn subdivide_wearing<R: subdivide::Rule, P: Put>(
    field: &mut Heightfield,
    first_depth: u32,
    job: &Job<'_, R, P>,
    wear: Option<(f32, u64)>,
) -> Option<Extremes> {
    let size = field.size();
    let Some((strength, seed)) = wear else {
        return subdivide::subdivide(field.heights_mut(), size, first_depth, job);
    };
    let levels = erosion::levels_above(field.exponent());
    let (depth, _) =
        subdivide::subdivide_down_to(field.heights_mut(), size, first_depth, 2 << levels, job);
    let lattice = field.coarsened(levels);
    let (_, change) = crate::threads::both(
        || subdivide::subdivide(field.heights_mut(), size, depth, job),
        move || erosion::wear(lattice, strength, seed),
    );
    if let Some(change) = change {
        erosion::add(field, &change, job.threads);
    }
    None
}

/// Applies sea level, contour and height to the subdivided field.
fn finish(field: &mut Heightfield, p: &Params, threads: usize, extremes: Option<Extremes>) {
    match p.generator {
        Generator::Square | Generator::Diamond | Generator::Brownian => {
            normalize::finish_square(field, p, threads, extremes)
        }
        Generator::Triangle => normalize::finish_triangle(field, p, threads, extremes),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tallest of `field`'s land, in grid widths.
    fn tallest(field: &Heightfield) -> f32 {
        field.max() / field.extent()
    }

    /// Seeds 264, 353 and 379 drew alpine and desert ranges 7 or 8 high
    /// over a low sea, 0.51-0.61 widths tall: too tall for the vista, their
    /// slides showed the whole grid as a block in the sky. A person's own
    /// height is left as set.
    #[test]
    fn a_worlds_drawn_land_is_no_taller_than_the_vista_frames() {
        let at = |height: Option<u32>| Settings {
            detail: crate::settings::Detail::Level(8),
            height: height.unwrap_or(Settings::default().height),
            ..Settings::default()
        };
        for seed in [264, 353, 379] {
            let drawn = generate(&at(None), seed);
            assert!(
                tallest(&drawn) <= DRAWN_TALLEST * 1.001,
                "seed {seed}: {}",
                tallest(&drawn)
            );
            let own = worlds::drawn(&at(None), Some(seed)).height;
            let set = generate(&at(Some(own)), seed);
            assert!(!worlds::height_drawn(&at(Some(own)), Some(seed)));
            assert!(tallest(&set) >= tallest(&drawn), "seed {seed}");
        }
        let set = generate(&at(Some(8)), 264);
        assert!(tallest(&set) > DRAWN_TALLEST, "{}", tallest(&set));
    }

    #[test]
    fn eroding_alongside_the_subdivision_makes_the_same_field_as_after_it() {
        let bits = |f: &Heightfield| f.heights().iter().map(|h| h.to_bits()).collect::<Vec<_>>();
        // Subdivided, then eroded: the order before the droplets ran
        // alongside the finer levels.
        let after = |s: &Settings, seed: u64| {
            let params = params_for(s, seed);
            let mut field = Heightfield::flat(params.exponent, params.extent());
            fill_wearing(&mut field, &params, seed, 2, false);
            field
        };
        for generator in [Generator::Square, Generator::Diamond, Generator::Triangle] {
            for detail in [6, 7, 8, 10] {
                for seed in [1, 42] {
                    let s = Settings {
                        generator,
                        detail: crate::settings::Detail::Level(detail),
                        ..Settings::default()
                    };
                    assert!(
                        params_for(&s, seed).erosion > 0.0,
                        "{generator:?}: no erosion"
                    );
                    let after = after(&s, seed);
                    for threads in [2, 3] {
                        let alongside = generate_with_threads(&s, seed, threads);
                        assert!(
                            bits(&alongside) == bits(&after),
                            "{generator:?} detail {detail} seed {seed}, {threads} threads"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn the_subdivision_sees_the_true_extremes_when_asked() {
        for generator in [Generator::Square, Generator::Diamond, Generator::Triangle] {
            for (detail, sea_level) in [(4, 0.0), (7, 0.3), (10, 0.0), (10, -0.2)] {
                for threads in [1, 2, 5] {
                    let s = Settings {
                        generator,
                        detail: crate::settings::Detail::Level(detail),
                        sea_level,
                        ..Settings::default()
                    };
                    let params = Params::from_settings(&s);
                    let mut field = Heightfield::flat(params.exponent, params.extent());
                    let seen = subdivide_all(&mut field, &params, 17, threads, &Plain, false);
                    let truth = normalize::min_max(field.heights(), 1);
                    let wanted = generator == Generator::Triangle || sea_level != 0.0;
                    let case = format!("{generator:?} {detail} {sea_level} {threads}");
                    assert_eq!(seen, wanted.then_some(truth), "{case}");
                }
            }
        }
    }
}
