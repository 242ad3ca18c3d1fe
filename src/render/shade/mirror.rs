//! The water's mirror: the sight line to a point of the water, reflected
//! off its surface (tilted by the wind's streaks) and followed over the
//! heightfield to the land it meets, or out to the sky; how much of that
//! the water shows (Fresnel), and the sun's glitter where the reflected
//! line points near the sun.
//!
//! Everything here is in world units (x right, y towards the front, z up,
//! as the camera's), a function of the scene alone: never of pixels or of
//! the order faces are drawn in.

use std::sync::OnceLock;

use glam::{Vec2, Vec3};

use super::colour::{Rgb, to_u32};
use crate::render::framing::tops::finite;
use crate::terrain::Heightfield;

/// Samples of a profile skipped at once where the line passes over all of
/// them, and the coarser skip above that.
const BLOCK: usize = 16;
const SPAN: usize = 256;
/// Grid steps between a profile's samples.
const STEP: f32 = 0.75;
/// Water's reflectance looking straight down (Schlick's `F0`).
const F0: f32 = 0.02;
/// The mirror's share is Schlick's term times this, at most [`MOST`]:
/// stylised, so that it reads at the vista's angles.
const GAIN: f32 = 1.6;
/// The most the water mirrors (some of its own colour always shows).
const MOST: f32 = 0.8;
/// How much the strongest streak (ripple 1) takes from the mirror.
const STREAK: f32 = 0.7;
/// How far the streaks tilt the reflected line up or down (its slope per
/// unit of ripple): wind on the water smears reflections up and down.
const TILT: f32 = 0.045;
/// The tilt of the sparkling facets that throw the sun's glitter.
const GLINT_TILT: f32 = 0.12;
/// Cosine of the widest angle between a facet's reflected line and the sun
/// that still glints.
const GLINT_COS: f32 = 0.9975;
/// Only facets whose sparkle exceeds this glint (they sparkle apart).
const SPARKLE: f32 = 0.15;

/// The reflected sight line at one point of the water.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Reflection {
    /// Where it leaves the water (world units).
    pub from: Vec3,
    /// Its direction (unit, pointing up).
    pub dir: Vec3,
    /// How much of what it meets the water shows, 0..=1.
    pub share: f32,
}

/// The mirror of one scene's water.
///
/// A line reflected off level water keeps the direction it had across the
/// ground, so it runs in the vertical plane through the eye and the point
/// it left the water at. The ground under each such plane (a fan of them
/// around the eye, each a profile of heights out from the eye, made the
/// first time a line needs it) is all a line has to be followed over: a
/// march along one row of numbers, skipping spans it passes over.
#[derive(Debug)]
pub(crate) struct Mirror {
    eye: Vec3,
    /// Width of a grid step in height units.
    cell: f32,
    /// The eye over the ground, in grid steps.
    origin: Vec2,
    /// The fan: the angle towards the grid's middle, the first direction's
    /// angle from it, the angle between two, and each direction's profile.
    mid: f32,
    first: f32,
    apart: f32,
    profiles: Vec<OnceLock<Profile>>,
    /// Towards the sun, in world units.
    sun: Vec3,
    /// The sun's direct colour, 0..=1.
    sun_colour: Rgb,
}

/// The ground under one direction of the fan, out from the eye.
#[derive(Debug, Default)]
struct Profile {
    /// How far from the eye the first sample lies, in grid steps (samples
    /// are [`STEP`] apart).
    start: f32,
    heights: Vec<f32>,
    /// The highest of each [`BLOCK`] and each [`SPAN`] samples.
    block_top: Vec<f32>,
    span_top: Vec<f32>,
}

impl Mirror {
    /// The mirror of `field` seen from `eye` (world units), a grid step
    /// `cell` units wide, lit by `sun` (the palette's frame: y towards the
    /// back) of colour `sun_colour`.
    pub(crate) fn new(field: &Heightfield, eye: Vec3, cell: f32, sun: Vec3, sun_colour: Rgb) -> Self {
        let cell = if cell.is_finite() && cell > 0.0 { cell } else { 1.0 };
        let origin = Vec2::new(eye.x, eye.y) / cell;
        let last = field.size().saturating_sub(1) as f32;
        let corners = [(0.0, 0.0), (last, 0.0), (0.0, last), (last, last)]
            .map(|(x, y)| Vec2::new(x, y) - origin);
        let inside = (0.0..=last).contains(&origin.x) && (0.0..=last).contains(&origin.y);
        // Angles are measured from the direction to the grid's middle: when
        // the grid lies to one side of the eye, none of them wraps.
        let mid = angle(Vec2::splat(0.5 * last) - origin);
        let (first, end) = if inside || !mid.is_finite() {
            (-std::f32::consts::PI, std::f32::consts::PI)
        } else {
            let turns = corners.map(|c| wrapped(angle(c) - mid));
            let lo = turns.iter().copied().fold(f32::INFINITY, f32::min);
            let hi = turns.iter().copied().fold(f32::NEG_INFINITY, f32::max);
            (lo, hi)
        };
        let mid = if mid.is_finite() { mid } else { 0.0 };
        // A grid step apart at the far corner.
        let far = corners.iter().map(|c| c.length()).fold(1.0, f32::max);
        let count = (((end - first) * far) as usize).clamp(2, 1 << 16);
        Mirror {
            eye,
            cell,
            origin,
            mid,
            first,
            apart: (end - first) / (count - 1) as f32,
            profiles: (0..count).map(|_| OnceLock::new()).collect(),
            sun: Vec3::new(sun.x, -sun.y, sun.z).normalize_or(Vec3::Z),
            sun_colour,
        }
    }

    /// The sight line to the water at grid position `g` on a surface at
    /// height `level`, reflected off a surface tilted by `ripple` (-1..1).
    /// `None` where the eye does not look down at it.
    pub(crate) fn reflect(&self, g: Vec2, level: f32, ripple: f32) -> Option<Reflection> {
        let from = Vec3::new(g.x * self.cell, g.y * self.cell, level);
        let d = (from - self.eye).try_normalize()?;
        let down = -d.z;
        if !(down > 0.0) {
            return None;
        }
        let flat = Vec2::new(d.x, d.y).length();
        // The streaks tilt the water, raising or lowering the line.
        let up = (down + TILT * ripple * flat).max(0.2 * down);
        let dir = Vec3::new(d.x, d.y, up).try_normalize()?;
        let schlick = F0 + (1.0 - F0) * (1.0 - down).powi(5);
        let share = (GAIN * schlick).min(MOST) * (1.0 - STREAK * ripple.abs());
        Some(Reflection { from, dir, share })
    }

    /// Where a line from `from` (world units) rising as `dir` does (a
    /// reflected line: away from the eye across the ground) first meets
    /// the ground of `field`: the grid position and the height, or `None`
    /// where it leaves the grid or rises above all the land.
    pub(crate) fn trace(&self, field: &Heightfield, from: Vec3, dir: Vec3) -> Option<(Vec2, f32)> {
        let run = Vec2::new(dir.x, dir.y).length();
        if !(run > 1e-6 && dir.z > 0.0) {
            return None;
        }
        let away = Vec2::new(from.x, from.y) / self.cell - self.origin;
        let i = ((wrapped(angle(away) - self.mid) - self.first) / self.apart).round();
        if !(i >= 0.0 && i < self.profiles.len() as f32) {
            return None;
        }
        let along = self.along(i as usize);
        let profile = self.profiles[i as usize].get_or_init(|| Profile::under(field, self.origin, along));
        let s0 = away.length();
        // Height gained per grid step along the ground.
        let rise = dir.z / run * self.cell;
        let s = profile.meets(s0, from.z, rise)?;
        Some((self.origin + along * s, from.z + rise * (s - s0)))
    }

    /// The unit direction across the ground of the fan's `i`th profile.
    fn along(&self, i: usize) -> Vec2 {
        let a = self.mid + self.first + self.apart * i as f32;
        Vec2::new(a.sin(), -a.cos())
    }

    /// The sun's glitter on a facet at the end of `dir` tilted by `sparkle`
    /// and `sideways` (-1..1, the fine ripples): the sun's colour, and how
    /// strongly it shows (0..=1).
    pub(crate) fn glint(&self, dir: Vec3, sparkle: f32, sideways: f32) -> Option<(u32, f32)> {
        if sparkle < SPARKLE {
            return None;
        }
        let tilted = Vec3::new(
            dir.x + GLINT_TILT * sideways,
            dir.y,
            dir.z + GLINT_TILT * (sparkle - 0.5),
        );
        let cos = tilted.try_normalize()?.dot(self.sun);
        if cos <= GLINT_COS {
            return None;
        }
        let t = ((cos - GLINT_COS) / (1.0 - GLINT_COS)).min(1.0);
        let strength = t * t * ((sparkle - SPARKLE) / (1.0 - SPARKLE)).min(1.0).sqrt();
        Some((to_u32(self.sun_colour), strength))
    }
}

/// The angle of ground direction `v`, from the back (-y) towards the right.
fn angle(v: Vec2) -> f32 {
    v.x.atan2(-v.y)
}

/// `a` turned into -pi..pi.
fn wrapped(a: f32) -> f32 {
    use std::f32::consts::{PI, TAU};
    (a + PI).rem_euclid(TAU) - PI
}

impl Profile {
    /// The ground of `field` under the line from `origin` along unit
    /// direction `along` (grid steps), where it crosses the grid.
    fn under(field: &Heightfield, origin: Vec2, along: Vec2) -> Self {
        let last = field.size().saturating_sub(1) as f32;
        let Some((enter, leave)) = crossing(origin, along, last) else {
            return Profile::default();
        };
        let start = enter;
        let count = ((leave - enter) / STEP) as usize + 1;
        let heights: Vec<f32> = (0..count)
            .map(|k| ground(field, origin + along * (start + k as f32 * STEP)))
            .collect();
        let tops = |n: usize| heights.chunks(n).map(|c| c.iter().copied().fold(f32::NEG_INFINITY, f32::max)).collect();
        Profile {
            start,
            block_top: tops(BLOCK),
            span_top: tops(SPAN),
            heights,
        }
    }

    /// How far from the eye (grid steps) a line leaving height `z0` at
    /// `s0` steps and rising `rise` a step first is below the ground.
    fn meets(&self, s0: f32, z0: f32, rise: f32) -> Option<f32> {
        let z = |k: usize| z0 + rise * (self.start + k as f32 * STEP - s0);
        let n = self.heights.len();
        // The first sample past the point the line leaves.
        let mut k = ((s0 - self.start) / STEP).floor().max(0.0) as usize + 1;
        while k < n {
            let zk = z(k);
            if k % SPAN == 0 && self.span_top[k / SPAN] < zk {
                k += SPAN;
            } else if k % BLOCK == 0 && self.block_top[k / BLOCK] < zk {
                k += BLOCK;
            } else if self.heights[k] >= zk {
                // Between the last sample above the ground and this one.
                let (above, below) = (z(k - 1) - self.heights[k - 1], self.heights[k] - zk);
                let f = above / (above + below).max(1e-9);
                return Some(self.start + (k as f32 - 1.0 + f.clamp(0.0, 1.0)) * STEP);
            } else {
                k += 1;
            }
        }
        None
    }
}

/// The distances (grid steps) along the line from `p` along unit `u` at
/// which it enters and leaves the grid `0..=last`, if it crosses it ahead.
fn crossing(p: Vec2, u: Vec2, last: f32) -> Option<(f32, f32)> {
    let (mut enter, mut leave) = (0.0f32, f32::INFINITY);
    for (c, d) in [(p.x, u.x), (p.y, u.y)] {
        if d.abs() < 1e-9 {
            if !(0.0..=last).contains(&c) {
                return None;
            }
            continue;
        }
        let (a, b) = ((0.0 - c) / d, (last - c) / d);
        enter = enter.max(a.min(b));
        leave = leave.min(a.max(b));
    }
    (enter < leave).then_some((enter, leave))
}

/// The ground's height at grid position `p`, bilinear between points.
#[inline]
fn ground(field: &Heightfield, p: Vec2) -> f32 {
    let size = field.size();
    let last = size - 1;
    let (x, y) = (p.x.max(0.0), p.y.max(0.0));
    let (x0, y0) = (
        (x as usize).min(last.saturating_sub(1)),
        (y as usize).min(last.saturating_sub(1)),
    );
    let (fx, fy) = ((x - x0 as f32).min(1.0), (y - y0 as f32).min(1.0));
    let heights = field.heights();
    let at = |x: usize, y: usize| finite(heights[y * size + x]);
    let (x1, y1) = ((x0 + 1).min(last), (y0 + 1).min(last));
    let top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * fx;
    let bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * fx;
    top + (bottom - top) * fy
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sea 1 deep with one square tower `height` tall around grid point
    /// (`x`, `y`), on a 65-point grid of unit steps.
    fn tower(x: usize, y: usize, height: f32) -> Heightfield {
        let mut f = Heightfield::flat(6, 64.0);
        for gy in 0..f.size() {
            for gx in 0..f.size() {
                let near = gx.abs_diff(x) <= 2 && gy.abs_diff(y) <= 2;
                f.set(gx, gy, if near { height } else { -1.0 });
            }
        }
        f
    }

    const EYE: Vec3 = Vec3::new(32.0, 100.0, 10.0);

    fn mirror(field: &Heightfield) -> Mirror {
        Mirror::new(field, EYE, 1.0, Vec3::new(0.0, 1.0, 0.2), [1.0; 3])
    }

    /// A line leaving the water at (`x`, `y`) away from the eye, rising
    /// `slope` per unit across the ground.
    fn away(x: f32, y: f32, slope: f32) -> (Vec3, Vec3) {
        let from = Vec3::new(x, y, 0.0);
        let run = (Vec2::new(x, y) - Vec2::new(EYE.x, EYE.y)).normalize();
        (from, Vec3::new(run.x, run.y, slope).normalize())
    }

    #[test]
    fn a_line_towards_a_tower_meets_it_and_others_do_not() {
        let f = tower(32, 10, 30.0);
        let m = mirror(&f);
        let (from, dir) = away(32.0, 40.0, 0.1);
        let (g, h) = m.trace(&f, from, dir).expect("meets the tower");
        // Between the tower's front row (12) and the next (13): 30 - 31 t = 0.1 (28 - t).
        assert!((g.y - 12.88).abs() < 0.3 && (g.x - 32.0).abs() < 0.1, "{g}");
        assert!((h - 2.7).abs() < 0.3, "{h}");
        let (from, dir) = away(10.0, 40.0, 0.1);
        assert!(m.trace(&f, from, dir).is_none(), "beside the tower");
        // Steeper than the tower's top seen from here: over it.
        let (from, dir) = away(32.0, 40.0, 1.2);
        assert!(m.trace(&f, from, dir).is_none(), "over the tower");
        // Beyond the tower, looking away from it.
        let (from, dir) = away(32.0, 5.0, 0.01);
        assert!(m.trace(&f, from, dir).is_none(), "behind the tower");
    }

    #[test]
    fn skipping_spans_misses_no_tower() {
        // Low towers anywhere along the line: the skips must not miss them.
        for (x, y) in [(32, 16), (32, 3), (36, 33), (20, 8), (32, 47)] {
            let f = tower(x, y, 5.0);
            let m = mirror(&f);
            let from = Vec2::new(x as f32, y as f32 + 12.0);
            let (from, dir) = away(from.x, from.y, 0.05);
            let hit = m.trace(&f, from, dir);
            assert!(hit.is_some(), "tower at ({x}, {y}) missed");
        }
    }

    #[test]
    fn the_fan_covers_the_grid_from_an_eye_on_any_side() {
        let f = tower(32, 32, 20.0);
        for eye in [Vec3::new(32.0, 100.0, 10.0), Vec3::new(-40.0, -30.0, 10.0), Vec3::new(32.0, 32.0, 40.0)] {
            let m = Mirror::new(&f, eye, 1.0, Vec3::Z, [1.0; 3]);
            // From the water on the far side of the tower from the eye...
            let back = (Vec2::new(32.0, 32.0) - Vec2::new(eye.x, eye.y)).normalize_or(Vec2::X);
            let p = Vec2::new(32.0, 32.0) - back * 10.0;
            let p = if eye.x == 32.0 && eye.y == 32.0 { Vec2::new(22.0, 32.0) } else { p };
            let run = (p - Vec2::new(eye.x, eye.y)).normalize();
            let dir = Vec3::new(run.x, run.y, 0.05).normalize();
            // ...a line away from the eye only meets it if it heads for it.
            let hit = m.trace(&f, Vec3::new(p.x, p.y, 0.0), dir);
            let heads = (Vec2::new(32.0, 32.0) - p).dot(run) > 0.0;
            assert_eq!(hit.is_some(), heads, "eye {eye}");
        }
    }

    #[test]
    fn the_mirror_is_stronger_at_grazing_angles_and_weaker_in_streaks() {
        let f = tower(32, 10, 5.0);
        let m = mirror(&f);
        let near = m.reflect(Vec2::new(32.0, 95.0), 0.0, 0.0);
        let far = m.reflect(Vec2::new(32.0, 5.0), 0.0, 0.0).unwrap();
        // At the eye's feet it looks straight down: almost no mirror.
        assert!(near.unwrap().share < 0.1);
        assert!(far.share > 0.3, "{}", far.share);
        let streak = m.reflect(Vec2::new(32.0, 5.0), 0.0, 0.9).unwrap();
        assert!(streak.share < 0.5 * far.share);
    }
}
