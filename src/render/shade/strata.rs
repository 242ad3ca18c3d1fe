//! Rock strata on steep faces: bands that follow height, so they run
//! across a face, not down it.
//!
//! A cliff of the grid is one or two cells tall and hundreds of pixels
//! high at 4K, while its columns are a few pixels wide: each column's
//! corners are blended down the whole face, and the light of neighbouring
//! columns (their normals differ a lot across a rough face) reads as
//! curtains one grid column wide. Strata give such a face structure along
//! its height, where the grid has none, at each pixel.
//!
//! The beds are the mountain's own ([`Strata`], the desert's terraces'
//! beds: there the bands line up with the benches), each a shade lighter
//! or darker, with thinner beds drawn within them and a faint parting
//! line at the foot of each. Where the land is not terraced the beds dip
//! a little, each mountain its own way, and bend in long folds: level
//! lines evenly spaced round a peak read as a contour map, not as rock. A table of the tone over height is built once
//! a scene, with coarser copies of it (each the mean of two entries of the
//! one below, as a texture's mip levels): a face reads the copy whose
//! entries are as thick as one pixel's span of height, so far faces blur
//! their bands to their mean instead of aliasing into moiré.

use std::f32::consts::TAU;

use glam::Vec2;

use super::index;
use crate::render::base::colour::{lanes, smoothstep};
use crate::terrain::Strata;
use crate::terrain::splitmix;

/// Where a point's steepness (the palette's, 1 at the field's 90th
/// percentile) starts to show strata, and where they are full.
const ROCK_FROM: f32 = 0.7;
const ROCK_FULL: f32 = 1.2;
/// How much a band lightens or darkens its rock at most (a share of its
/// colour).
pub(crate) const DEPTH: f32 = 0.2;
/// Base colours this pale (luminance 0..=1) and paler are snow or ice,
/// not rock: the strata fade out between the two.
const PALE_FROM: f32 = 0.62;
const PALE_FULL: f32 = 0.78;
/// The steepest dip of the beds (rise per unit across), the folds'
/// height, in mean beds, and their waves across a grid's width.
const DIP: f32 = 0.2;
const FOLD: f32 = 0.8;
const FOLD_WAVES: [f32; 2] = [7.0, 3.1];
/// The thinner beds' thickness as a share of the mountain's beds.
const FINE: f32 = 0.15;
/// The tone's share from the mountain's beds, from the thinner beds and
/// from the parting lines at their feet.
const COARSE_WEIGHT: f32 = 0.5;
const FINE_WEIGHT: f32 = 0.4;
const PARTING_WEIGHT: f32 = 0.25;
/// A parting line's width, as a share of its thin bed.
const PARTING: f32 = 0.2;
/// Table entries in the thinnest bed of the thinner beds (the thinnest is
/// under half the mean: see `cliffs.rs`).
const ENTRIES_PER_BED: f32 = 6.0;
/// The table covers heights up to this many grid widths (above, the last
/// entry holds).
const TOP: f32 = 1.0;
/// Mixed into the seed for the thinner beds and the beds' tones.
const FINE_KEY: u64 = 0x6669_6e65_6265_6473;
const TONE_KEY: u64 = 0x746f_6e65_7374_6f6e;

/// How strongly a point of steepness `steep` (the palette's: 1 at the
/// field's 90th percentile) shows strata: 0 on gentle ground, 1 on the
/// steep faces that read as rock.
#[inline]
pub(crate) fn weight(steep: f32) -> f32 {
    smoothstep(ROCK_FROM, ROCK_FULL, steep)
}

/// How bare a point of base colour `base` is (1 rock, 0 snow or ice).
#[inline]
pub(crate) fn bare(base: u32) -> f32 {
    let c = lanes(base);
    let luma = (0.114 * c.x + 0.587 * c.y + 0.299 * c.z) / 255.0;
    1.0 - smoothstep(PALE_FROM, PALE_FULL, luma)
}

/// The tone of the mountain's rock over height, at every level of detail.
pub(crate) struct RockStrata {
    /// Level `l` holds the tone (-1..=1, about 0 on average) of heights
    /// `i * step * 2^l`, each entry the mean of two of the level below.
    levels: Vec<Box<[f32]>>,
    /// Each level's largest tone either way.
    peaks: Vec<f32>,
    /// Height between entries of level 0.
    step: f32,
    /// How the beds rise per grid step across and towards the back (0
    /// where they are level).
    dip: Vec2,
    /// The folds: their height (0 where the beds are level), and each
    /// wave's turns per grid step and phase.
    fold: f32,
    waves: [(Vec2, f32); 2],
}

/// [`RockStrata`] read at one level of detail (between two levels): the
/// tone of one face's pixels.
pub(crate) struct Sampler<'s> {
    table: &'s [f32],
    /// Entries per height unit.
    scale: f32,
    /// The largest tone in the table, either way.
    pub(crate) peak: f32,
}

impl RockStrata {
    /// The strata of the mountain of `seed` on a grid `extent` wide and
    /// `size` points a side; their beds `level` (the terraces' own) or
    /// dipping and folded.
    pub(crate) fn new(seed: u64, extent: f32, size: usize, level: bool) -> Self {
        let beds = Strata::of(seed, extent);
        let thin = Strata::of(seed ^ FINE_KEY, extent * FINE);
        let thinnest = crate::terrain::CLIFF_STEP_SHARE * extent * FINE * 0.45;
        let step = (thinnest / ENTRIES_PER_BED).max(f32::MIN_POSITIVE);
        let n = ((extent * TOP / step) as usize).clamp(2, 1 << 16);
        let mut base: Box<[f32]> = (0..n)
            .map(|i| tone(&beds, &thin, seed, (i as f32 + 0.5) * step))
            .collect();
        // About 0 on average: a face too far for its bands keeps its colour.
        let mean = base.iter().sum::<f32>() / n as f32;
        base.iter_mut()
            .for_each(|t| *t = (*t - mean).clamp(-1.0, 1.0));
        let mut levels = vec![base];
        while let Some(last) = levels.last().filter(|l| l.len() >= 2) {
            let next = last
                .chunks(2)
                .map(|p| p.iter().sum::<f32>() / p.len() as f32);
            let next: Box<[f32]> = next.collect();
            levels.push(next);
        }
        let draw = |k: u64| {
            let d = splitmix::mix(seed ^ TONE_KEY ^ k.wrapping_mul(0x9e37_79b9_7f4a_7c15));
            splitmix::unit(d)
        };
        let cell = extent / size.saturating_sub(1).max(1) as f32;
        let turn = |a: f32| Vec2::new(a.cos(), a.sin());
        let (dip, fold) = if level {
            (Vec2::ZERO, 0.0)
        } else {
            let tilt = turn(TAU * draw(1)) * DIP * draw(2) * cell;
            (tilt, FOLD * crate::terrain::CLIFF_STEP_SHARE * extent)
        };
        // Each wave's turns per grid step: its waves a grid width over the
        // grid's points, whatever the detail.
        let waves = [0, 1].map(|i| {
            let k = turn(TAU * draw(3 + i)) * FOLD_WAVES[i as usize];
            (k * TAU / size.max(2) as f32, TAU * draw(5 + i))
        });
        let peaks = levels
            .iter()
            .map(|l| l.iter().fold(0.0f32, |m, t| m.max(t.abs())))
            .collect();
        RockStrata {
            levels,
            peaks,
            step,
            dip,
            fold,
            waves,
        }
    }

    /// Where grid point `g` of height `h` lies among the beds: its height
    /// less the beds' dip and folds there.
    #[inline]
    pub(crate) fn bed_height(&self, h: f32, g: Vec2) -> f32 {
        if self.fold == 0.0 {
            return h;
        }
        let [(k0, p0), (k1, p1)] = self.waves;
        let folds = (k0.dot(g) + p0).sin() + 0.5 * (k1.dot(g) + p1).sin();
        h - self.dip.dot(g) - self.fold * folds
    }

    /// The tone of a face over which one pixel spans `per_pixel` height
    /// units: the level whose entries are nearest that thick (one level a
    /// face: a pixel reads one table, the cost that matters here).
    #[inline]
    pub(crate) fn sampler(&self, per_pixel: f32) -> Sampler<'_> {
        let lod = (per_pixel / self.step).max(1.0).log2() + 0.5;
        let at = index(lod).min(self.levels.len() - 1);
        Sampler {
            table: &self.levels[at],
            scale: 1.0 / (self.step * (1u32 << at.min(31)) as f32),
            peak: self.peaks[at],
        }
    }
}

impl Sampler<'_> {
    /// The tone (-1..=1) at height `h`, blended between entries.
    #[inline(always)]
    pub(crate) fn tone(&self, h: f32) -> f32 {
        let last = self.table.len() - 1;
        let u = (h * self.scale - 0.5).max(0.0);
        let i = index(u).min(last);
        let f = (u - i as f32).min(1.0);
        let (a, b) = (self.table[i], self.table[(i + 1).min(last)]);
        a + (b - a) * f
    }
}

/// The tone at height `h`: its bed's and its thin bed's shade and the
/// parting line at the foot of its thin bed.
fn tone(beds: &Strata, thin: &Strata, seed: u64, h: f32) -> f32 {
    let shade = |(bottom, _): (f32, f32)| {
        let draw = splitmix::mix(seed ^ TONE_KEY ^ u64::from(bottom.to_bits()));
        splitmix::signed_unit(draw)
    };
    let (bottom, top) = thin.bed(h);
    let share = (h - bottom) / (top - bottom);
    let parting = 1.0 - smoothstep(0.0, PARTING, share);
    let t = COARSE_WEIGHT * shade(beds.bed(h)) + FINE_WEIGHT * shade(thin.bed(h))
        - PARTING_WEIGHT * parting;
    t.clamp(-1.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tone_changes_with_height_and_blurs_to_its_mean_far_off() {
        let s = RockStrata::new(28, 250.0, 1025, true);
        let near = s.sampler(0.01);
        let tones: Vec<f32> = (0..2000)
            .map(|i| near.tone(10.0 + i as f32 * 0.01))
            .collect();
        let spread = |t: &[f32]| {
            let mean = t.iter().sum::<f32>() / t.len() as f32;
            (t.iter().map(|v| (v - mean).powi(2)).sum::<f32>() / t.len() as f32).sqrt()
        };
        assert!(spread(&tones) > 0.2, "near bands {}", spread(&tones));
        let far = s.sampler(50.0);
        let far: Vec<f32> = (0..2000)
            .map(|i| far.tone(10.0 + i as f32 * 0.01))
            .collect();
        assert!(spread(&far) < 0.1, "far bands {}", spread(&far));
        assert!(tones.iter().all(|t| (-1.0..=1.0).contains(t)));
    }

    #[test]
    fn steep_rock_alone_shows_strata() {
        assert_eq!(weight(0.3), 0.0);
        assert_eq!(weight(1.5), 1.0);
        assert_eq!(bare(0x00ff_ffff), 0.0);
        assert_eq!(bare(0x0060_4030), 1.0);
    }

    #[test]
    fn terraced_beds_stay_level_and_others_dip() {
        let g = Vec2::new(300.0, 700.0);
        let level = RockStrata::new(5, 250.0, 1025, true);
        assert_eq!(level.bed_height(40.0, g), 40.0);
        let dipping = RockStrata::new(5, 250.0, 1025, false);
        assert_ne!(dipping.bed_height(40.0, g), 40.0);
    }
}
