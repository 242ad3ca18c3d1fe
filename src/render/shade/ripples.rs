//! Wind on open water: streaks of lighter and darker water, long across the
//! view and thin along it, so a wide sea reads as water rather than as one
//! smooth gradient. Faces of waves turned towards the viewer mirror the sky
//! by the horizon; those turned away show the darker water below.
//!
//! The streaks belong to the world, not to the grid: their size is in height
//! units and their pattern is drawn from the mountain's identity, so a seed
//! has the same sea at every frame size, detail and `low_detail`.

use crate::render::base::colour::blend_packed;
use crate::terrain::Heightfield;
use crate::terrain::curves::hermite;
use crate::terrain::heightfield::MAX_EXPONENT;
use crate::terrain::noise::Noise;

/// Length of the streaks (one noise cell across the view), in height units:
/// a ninth of the square generators' width.
const ACROSS: f32 = crate::terrain::SQUARE_EXTENT / 9.0;
/// Thinness of the streaks (one noise cell along the view), in height units.
const ALONG: f32 = crate::terrain::SQUARE_EXTENT / 140.0;
/// How much finer the second layer's streaks are along the view than the
/// first's.
const FINER_ALONG: f32 = 2.1;
/// Strongest blend towards the sky or the dark, in 1/256ths.
const STRENGTH: f32 = 40.0;

/// Lattice points a side of the noise's table; the noise repeats after
/// this many lattice cells (a power of two: the wrap is a mask).
const LATTICE: usize = 64;

/// The ripples of one sea, mirroring `sky` (the horizon colour); each
/// mountain's sea has its own.
#[derive(Debug, Clone)]
pub(crate) struct Ripples {
    sky: u32,
    /// Noise cells per grid step across the view and along it: the streaks'
    /// size in the world, in this grid's steps.
    across: f32,
    along: f32,
    /// What the pattern is drawn from.
    seed: u64,
    /// The noise's values at the lattice points, -1..1, row by row: drawn
    /// once, not four times per sample on every water face of a frame.
    lattice: Box<[f32; LATTICE * LATTICE]>,
}

impl Ripples {
    /// The ripples of `field`'s sea mirroring packed `sky`: the pattern
    /// drawn from the field's identity, the streaks sized in its units.
    pub(crate) fn new(sky: u32, field: &Heightfield) -> Self {
        let cells = field.size().saturating_sub(1).max(1) as f32;
        let extent = field.extent();
        // As the view does, a field of no usable width is a unit a step.
        let width = if extent.is_finite() && extent > 0.0 {
            extent
        } else {
            cells
        };
        Self::drawn(sky, width / cells, field.identity())
    }

    /// Ripples on a grid whose steps are `step` height units, mirroring
    /// packed `sky`, their pattern drawn from `seed`.
    fn drawn(sky: u32, step: f32, seed: u64) -> Self {
        let noise = Noise::new(seed, MAX_EXPONENT);
        let mut lattice = Box::new([0.0; LATTICE * LATTICE]);
        for (j, row) in lattice.chunks_exact_mut(LATTICE).enumerate() {
            noise.fill_row(j, 0, 1, 1.0, row);
        }
        Ripples {
            sky,
            across: step / ACROSS,
            along: step / ALONG,
            seed,
            lattice,
        }
    }

    /// How thick along the view the streaks of the finer layer are, in
    /// grid steps (one noise cell).
    pub(crate) fn finer_rows(&self) -> f32 {
        1.0 / (FINER_ALONG * self.along)
    }

    /// What the pattern is drawn from (the field's identity).
    pub(crate) fn seed(&self) -> u64 {
        self.seed
    }

    /// Ripples that paint every water face `colour` exactly (a noise far
    /// above 1 blends all the way): how the class picture of `classes.rs`
    /// tells water from land, with no test in the drawing's own path.
    pub(crate) fn covering(colour: u32) -> Self {
        Ripples {
            sky: colour,
            across: 1.0,
            along: 1.0,
            seed: 0,
            lattice: Box::new([256.0; LATTICE * LATTICE]),
        }
    }

    /// `colour` of the water where the ripple is `n` (see [`Ripples::value`]).
    #[inline]
    pub(crate) fn with(&self, colour: u32, n: f32) -> u32 {
        let t = (n.abs() * STRENGTH) as u32;
        if n > 0.0 {
            blend_packed(colour, self.sky, t)
        } else {
            // Black: darker water of the same hue under every colour filter.
            blend_packed(colour, 0, t)
        }
    }

    /// The ripple at grid position (`x`, `y`), in -1..1: above 0 the water
    /// mirrors the sky, below it is darker. Sized in the world, so the same
    /// place has the same ripple at every detail.
    #[inline]
    pub(crate) fn value(&self, x: f32, y: f32) -> f32 {
        self.value_seen(x, y, 1.0)
    }

    /// [`Ripples::value`] with its finer layer at `fine` (0..=1) of its
    /// strength. The finer layer breaks up the wide streaks' rows where the
    /// water is seen small; where it is seen wide, each of its rows, thin
    /// along the view and long across it, was drawn as a line across the
    /// whole frame a few pixels from the next, as if the picture were
    /// interlaced.
    #[inline]
    pub(crate) fn value_seen(&self, x: f32, y: f32, fine: f32) -> f32 {
        let (u, v) = (x * self.across, y * self.along);
        // A second, finer layer slanted across the first breaks up its rows.
        let finer = self.noise(2.3 * u + 0.7 * v, FINER_ALONG * v + 17.0);
        0.65 * self.noise(u, v) + 0.35 * fine * finer
    }

    /// Smooth value noise in -1..1 on the lattice, for `u`, `v` >= 0 (grid
    /// positions are): truncation is the floor there, without a libm call
    /// (and `as i32`, not `as usize`, whose conversion is a branchy
    /// sequence on x86).
    #[inline]
    fn noise(&self, u: f32, v: f32) -> f32 {
        let (a, b) = (u as i32, v as i32);
        let (fu, fv) = (hermite(u - a as f32), hermite(v - b as f32));
        let at = |da: i32, db: i32| {
            let mask = LATTICE as i32 - 1;
            let (i, j) = (a.wrapping_add(da) & mask, b.wrapping_add(db) & mask);
            self.lattice[(j * LATTICE as i32 + i) as usize]
        };
        let top = at(0, 0) + (at(1, 0) - at(0, 0)) * fu;
        let bottom = at(0, 1) + (at(1, 1) - at(0, 1)) * fu;
        top + (bottom - top) * fv
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::SQUARE_EXTENT;

    /// Ripples on a square generator's field of `cells` a side.
    fn square(sky: u32, cells: usize, seed: u64) -> Ripples {
        Ripples::drawn(sky, SQUARE_EXTENT / cells as f32, seed)
    }

    /// Mean change of the ripple over `step` cells across (x) and along (y).
    fn mean_change(r: &Ripples, step: f32) -> (f32, f32) {
        let (mut across, mut along, mut n) = (0.0, 0.0, 0.0);
        for i in 0..200 {
            for j in 0..200 {
                let (x, y) = (i as f32 * 5.1, j as f32 * 5.1);
                let n0 = r.value(x, y);
                across += (r.value(x + step, y) - n0).abs();
                along += (r.value(x, y + step) - n0).abs();
                n += 1.0;
            }
        }
        (across / n, along / n)
    }

    #[test]
    fn streaks_are_long_across_the_view_and_thin_along_it() {
        let r = square(0x00ff_ffff, 1024, 1);
        let (across, along) = mean_change(&r, 2.0);
        assert!(along > 4.0 * across, "along {along} across {across}");
        assert!(along > 0.05, "the water hardly changes: {along}");
    }

    #[test]
    fn ripples_stay_in_range_and_follow_the_world_not_the_detail() {
        let (fine, coarse) = (square(0, 1024, 1), square(0, 256, 1));
        for k in 0..5000 {
            let (x, y) = ((k * 37 % 1024) as f32 + 0.3, (k * 91 % 1024) as f32 + 0.6);
            let n = fine.value(x, y);
            assert!((-1.0..=1.0).contains(&n), "{n}");
            // The same place on a grid four times coarser: the same ripple.
            assert!((coarse.value(x / 4.0, y / 4.0) - n).abs() < 1e-4);
        }
    }

    #[test]
    fn each_mountain_has_its_own_sea() {
        let (a, b) = (square(0, 1024, 1), square(0, 1024, 2));
        let same = (0..1000)
            .filter(|&k| {
                let (x, y) = ((k * 37 % 1024) as f32, (k * 91 % 1024) as f32);
                a.value(x, y) == b.value(x, y)
            })
            .count();
        assert!(same < 10, "{same} of 1000 places alike");
        assert_eq!(
            a.value(100.5, 200.5),
            square(0, 1024, 1).value(100.5, 200.5)
        );
    }

    #[test]
    fn covering_ripples_paint_every_water_face_one_colour() {
        let r = Ripples::covering(0x0000_ffff);
        for k in 0..2000 {
            let (x, y) = ((k * 37 % 1024) as f32 + 0.3, (k * 91 % 1024) as f32 + 0.6);
            let water = (k as u32).wrapping_mul(0x9e37_79b9) & 0x00ff_ffff;
            assert_eq!(r.with(water, r.value(x, y)), 0x0000_ffff, "at {x}, {y}");
        }
    }

    #[test]
    fn crests_mirror_the_sky_and_troughs_darken() {
        let r = square(0x00ff_ffff, 1024, 1);
        let water = 0x0020_4080;
        let (mut lighter, mut darker) = (0, 0);
        for k in 0..400 {
            let c = r.with(water, r.value(512.0, k as f32 * 0.7));
            let sum = |c: u32| (c >> 16 & 0xff) + (c >> 8 & 0xff) + (c & 0xff);
            match sum(c).cmp(&sum(water)) {
                std::cmp::Ordering::Greater => lighter += 1,
                std::cmp::Ordering::Less => darker += 1,
                _ => {}
            }
        }
        assert!(
            lighter > 50 && darker > 50,
            "{lighter} lighter, {darker} darker"
        );
    }

    #[test]
    fn a_seed_has_the_same_sea_on_every_grid_and_streaks_keep_their_size() {
        let field = |exponent: u32, extent: f32, seed: Option<u64>| {
            let mut f = Heightfield::flat(exponent, extent);
            f.set_seed(seed);
            f
        };
        let fine = Ripples::new(0, &field(10, 250.0, Some(9)));
        let coarse = Ripples::new(0, &field(8, 250.0, Some(9)));
        assert_eq!(fine.seed(), coarse.seed());
        assert_ne!(
            fine.seed(),
            Ripples::new(0, &field(10, 250.0, Some(10))).seed()
        );
        // A field twice as wide on the same grid: its steps are twice as
        // long, so a streak spans half as many of them.
        let wide = Ripples::new(0, &field(10, 500.0, Some(9)));
        for k in 0..2000 {
            let (x, y) = ((k * 37 % 1024) as f32 + 0.3, (k * 91 % 1024) as f32 + 0.6);
            let n = fine.value(x, y);
            assert!((coarse.value(x / 4.0, y / 4.0) - n).abs() < 1e-4);
            assert!((wide.value(x / 2.0, y / 2.0) - n).abs() < 1e-4);
        }
    }
}
