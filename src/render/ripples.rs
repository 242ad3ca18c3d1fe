//! Wind on open water: streaks of lighter and darker water, long across the
//! view and thin along it, so a wide sea reads as water rather than as one
//! smooth gradient. Faces of waves turned towards the viewer mirror the sky
//! by the horizon; those turned away show the darker water below.

use super::colour::blend_packed;
use crate::terrain::heightfield::MAX_EXPONENT;
use crate::terrain::noise::Noise;

/// Streaks across the grid's width (their length).
const ACROSS: f32 = 9.0;
/// Streaks along the grid's depth (their thinness).
const ALONG: f32 = 140.0;
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
    /// Grid cells a side, to put the streaks in the grid's own proportions.
    cells: f32,
    /// The noise's values at the lattice points, -1..1, row by row: drawn
    /// once, not four times per sample on every water face of a frame.
    lattice: Box<[f32; LATTICE * LATTICE]>,
}

impl Ripples {
    /// Ripples on a grid of `cells` a side mirroring packed `sky`, their
    /// pattern drawn from `seed` (the field's fingerprint: the same mountain
    /// always has the same sea).
    pub(crate) fn new(sky: u32, cells: usize, seed: u64) -> Self {
        let noise = Noise::new(seed, MAX_EXPONENT);
        let mut lattice = Box::new([0.0; LATTICE * LATTICE]);
        for (j, row) in lattice.chunks_exact_mut(LATTICE).enumerate() {
            noise.fill_row(j, 0, 1, 1.0, row);
        }
        Ripples {
            sky,
            cells: cells.max(1) as f32,
            lattice,
        }
    }

    /// Ripples that paint every water face `colour` exactly (a noise far
    /// above 1 blends all the way): how the class picture of `classes.rs`
    /// tells water from land, with no test in the drawing's own path.
    pub(crate) fn covering(colour: u32) -> Self {
        Ripples {
            sky: colour,
            cells: 1.0,
            lattice: Box::new([256.0; LATTICE * LATTICE]),
        }
    }

    /// `colour` of the water at grid position (`x`, `y`) (in cells), with
    /// its ripple.
    #[inline]
    pub(crate) fn on(&self, colour: u32, x: f32, y: f32) -> u32 {
        let n = self.value(x, y);
        let t = (n.abs() * STRENGTH) as u32;
        if n > 0.0 {
            blend_packed(colour, self.sky, t)
        } else {
            // Black: darker water of the same hue under every colour filter.
            blend_packed(colour, 0, t)
        }
    }

    /// The ripple at grid position (`x`, `y`), in -1..1: above 0 the water
    /// mirrors the sky, below it is darker. In the grid's own proportions,
    /// so the same at every detail.
    #[inline]
    fn value(&self, x: f32, y: f32) -> f32 {
        let (u, v) = (x / self.cells * ACROSS, y / self.cells * ALONG);
        // A second, finer layer slanted across the first breaks up its rows.
        0.65 * self.noise(u, v) + 0.35 * self.noise(2.3 * u + 0.7 * v, 2.1 * v + 17.0)
    }

    /// Smooth value noise in -1..1 on the lattice, for `u`, `v` >= 0 (grid
    /// positions are): truncation is the floor there, without a libm call
    /// (and `as i32`, not `as usize`, which costs three times as much).
    #[inline]
    fn noise(&self, u: f32, v: f32) -> f32 {
        let (a, b) = (u as i32, v as i32);
        let (fu, fv) = (smooth(u - a as f32), smooth(v - b as f32));
        let at = |da: i32, db: i32| {
            let mask = LATTICE as i32 - 1;
            let (i, j) = ((a + da) & mask, (b + db) & mask);
            self.lattice[(j * LATTICE as i32 + i) as usize]
        };
        let top = at(0, 0) + (at(1, 0) - at(0, 0)) * fu;
        let bottom = at(0, 1) + (at(1, 1) - at(0, 1)) * fu;
        top + (bottom - top) * fv
    }
}

#[inline]
fn smooth(t: f32) -> f32 {
    t * t * (3.0 - 2.0 * t)
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let r = Ripples::new(0x00ff_ffff, 1024, 1);
        let (across, along) = mean_change(&r, 2.0);
        assert!(along > 4.0 * across, "along {along} across {across}");
        assert!(along > 0.05, "the water hardly changes: {along}");
    }

    #[test]
    fn ripples_stay_in_range_and_follow_the_grid_not_the_detail() {
        let (fine, coarse) = (Ripples::new(0, 1024, 1), Ripples::new(0, 256, 1));
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
        let (a, b) = (Ripples::new(0, 1024, 1), Ripples::new(0, 1024, 2));
        let same = (0..1000)
            .filter(|&k| {
                let (x, y) = ((k * 37 % 1024) as f32, (k * 91 % 1024) as f32);
                a.value(x, y) == b.value(x, y)
            })
            .count();
        assert!(same < 10, "{same} of 1000 places alike");
        assert_eq!(
            a.value(100.5, 200.5),
            Ripples::new(0, 1024, 1).value(100.5, 200.5)
        );
    }

    #[test]
    fn covering_ripples_paint_every_water_face_one_colour() {
        let r = Ripples::covering(0x0000_ffff);
        for k in 0..2000 {
            let (x, y) = ((k * 37 % 1024) as f32 + 0.3, (k * 91 % 1024) as f32 + 0.6);
            let water = (k as u32).wrapping_mul(0x9e37_79b9) & 0x00ff_ffff;
            assert_eq!(r.on(water, x, y), 0x0000_ffff, "at {x}, {y}");
        }
    }

    #[test]
    fn crests_mirror_the_sky_and_troughs_darken() {
        let r = Ripples::new(0x00ff_ffff, 1024, 1);
        let water = 0x0020_4080;
        let (mut lighter, mut darker) = (0, 0);
        for k in 0..400 {
            let c = r.on(water, 512.0, k as f32 * 0.7);
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
}
