//! What a water face mirrors: the land its reflected sight line meets,
//! shaded as the scene shades that land's points (the mean of those
//! across the width a point of the water stands for there), or the sky it
//! escapes to; mixed into the water's own colour by the mirror's share,
//! weaker where the wind roughens the water, with the sun's glitter
//! where the line points near the sun. The streaks tilt the mirror only
//! where the water is seen small (fine streaks), not near the viewer, and
//! their finer layer shows only where its streaks are seen thin.

use glam::{Vec2, Vec3};

use crate::render::base::colour::blend_packed;
use crate::render::scene::Scene;
use crate::render::shade::index;
use crate::render::shade::mirror::{Look, Mirror, Mirrored, Seen};

/// How much the roughest water (ripple 1) takes from the mirror; the
/// calmest (ripple -1) takes nothing.
const STREAK: f32 = 0.4;
/// How much finer than the streaks the glittering facets are, across and
/// along the view (world-sized, as the streaks are).
const FACETS: (f32, f32) = (7.3, 2.9);
/// The most grid points a mirrored point's colour is the mean of.
const TAPS: usize = 6;
/// How wide a grid step of the water may be seen (in the frame's steps,
/// `Scene::frame_step`: at 1080p 1.9 px) for the streaks to tilt its
/// mirror wholly, and from how wide they do not at all; and how tall a
/// streak of their finer layer may be seen for it to show wholly, and
/// from how tall it does not.
const SHOWN_FULL: f32 = 1.0;
const SHOWN_NONE: f32 = 3.0;

/// The wind's streak at a point of the water: its ripple (-1..1, see
/// `Ripples::value_seen`) and how much of the tilt it gives the mirror
/// shows there ([`Scene::streak_shares`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct Streak {
    pub(super) ripple: f32,
    pub(super) tilt: f32,
}

impl Scene<'_> {
    /// `water` (the face's own colour, hazed) at grid position `g` of a
    /// surface at `level`, whose streak there is `streak`, with what it
    /// mirrors; `lit` (0..=1) of the sun reaches it, so water in the shadow
    /// of the land before the sun does not glitter.
    pub(super) fn mirrored(
        &self,
        mirror: &Mirror,
        water: u32,
        (g, level): (Vec2, f32),
        streak: Streak,
        lit: f32,
    ) -> u32 {
        let Some(look) = self.look(mirror, (g, level), streak) else {
            return water;
        };
        let out = blend_packed(water, look.colour, mirror_weight(&look, streak.ripple));
        match self.glitter(mirror, look.near_sun, g, lit) {
            Some((sun, weight)) => blend_packed(out, sun, weight),
            None => out,
        }
    }

    /// [`Scene::mirrored`] on both sides of the mirrored outline, without
    /// the glitter: what a point of the water keeps for the faces around it
    /// to blend (see [`Mirrored`]).
    pub(super) fn mirrored_sides(
        &self,
        mirror: &Mirror,
        water: u32,
        (g, level): (Vec2, f32),
        streak: Streak,
    ) -> Mirrored {
        let Some(look) = self.look(mirror, (g, level), streak) else {
            return Mirrored {
                land: water,
                sky: water,
                margin: 0.0,
                near_sun: None,
            };
        };
        let weight = mirror_weight(&look, streak.ripple);
        Mirrored {
            land: blend_packed(water, look.land, weight),
            sky: blend_packed(water, look.sky, weight),
            margin: look.margin,
            near_sun: look.near_sun,
        }
    }

    /// What the water at grid position `g` of a surface at `level`, whose
    /// streak there is `streak`, mirrors.
    fn look(&self, mirror: &Mirror, (g, level): (Vec2, f32), streak: Streak) -> Option<Look> {
        let seen = |seen: Seen| match seen {
            Seen::Land { at, height, across } => self.mirrored_land(at, height, level, across),
            Seen::Sky(dir) => self.sky_towards(dir),
        };
        let tilt = streak.ripple * streak.tilt;
        mirror.look(&self.field, g, level, tilt, seen)
    }

    /// How much of the streaks' finer layer the water at grid position `g`
    /// on `level` shows (0..=1), its streaks `rows` grid steps thick along
    /// the view (1 for `rows` 0: none asked), and how much of the streaks'
    /// tilt its mirror takes (0..=1;
    /// 1 where it is not `mirrored`). The tilt shifts each point's image up
    /// or down: where a grid step of the water spans many pixels, each cell
    /// mirrored a slice of its own, a mosaic; it fades there. Seen many
    /// pixels thick, each of the finer
    /// streaks was drawn as a line across the frame (`Ripples::value_seen`);
    /// it fades there. Measured on the streaks, not on the grid's steps, so
    /// the same water shows the same streaks at every detail. The point is
    /// projected once for both.
    pub(super) fn streak_shares(&self, g: Vec2, level: f32, rows: f32, mirrored: bool) -> [f32; 2] {
        let a = self.view.project(g.x, g.y, level);
        // How much of a detail spanning grid vector `d` from `g` shows:
        // all of it seen up to [`SHOWN_FULL`] frame steps long, none from
        // [`SHOWN_NONE`].
        let shown = |d: Vec2| {
            let b = self.view.project(g.x + d.x, g.y + d.y, level);
            let steps = (b - a).length() / self.frame_step;
            // Not a number (no frame): the whole, as before the fade (a NaN
            // share would tilt the line the most the mirror allows).
            if steps.is_nan() {
                return 1.0;
            }
            1.0 - ((steps - SHOWN_FULL) / (SHOWN_NONE - SHOWN_FULL)).clamp(0.0, 1.0)
        };
        let fine = match rows > 0.0 {
            true => shown(Vec2::Y * rows),
            false => 1.0,
        };
        [fine, if mirrored { shown(Vec2::X) } else { 1.0 }]
    }

    /// The sun's glitter at grid position `g` where the reflected line
    /// points near the sun (`near_sun`): its colour and its weight (of 256)
    /// over the water; `lit` (0..=1) of the sun reaches it, so water in the
    /// shadow of the land before the sun does not glitter.
    pub(super) fn glitter(
        &self,
        mirror: &Mirror,
        near_sun: Option<Vec3>,
        g: Vec2,
        lit: f32,
    ) -> Option<(u32, u32)> {
        let (Some(ripples), Some(dir)) = (&self.ripples, near_sun) else {
            return None;
        };
        let (fx, fy) = FACETS;
        let sparkle = ripples.value(g.x * fx, g.y * fy);
        let sideways = ripples.value(g.x * fy + 31.0, g.y * fx + 7.0);
        let (sun, strength) = mirror.glint(dir, sparkle, sideways)?;
        Some((sun, (strength * lit * 256.0) as u32))
    }

    /// The land at grid position `p` (on a grid row), height `h`, seen in
    /// water at `level`, standing for the land `across` grid steps wide
    /// there: the mean of its row's points over that width, each weighted
    /// by how much of the width is nearest to it (so the colour moves
    /// smoothly as `p` moves); over [`TAPS`] steps wide, of [`TAPS`]
    /// points spread evenly across it (each its nearest grid point), and
    /// past the grid's edge its edge point again. Hazed as far as its
    /// image below the water lies from the eye.
    fn mirrored_land(&self, p: Vec2, h: f32, level: f32, across: f32) -> u32 {
        // At least a point's own step: the weights below then sum to over 0.
        let across = across.max(1.0);
        let last = self.cells();
        let y = index(p.y.round().clamp(0.0, last as f32));
        // Points `step` apart (one grid step, or more where the width
        // would take more than TAPS), each standing for a step's width.
        let step = (across / (TAPS - 1) as f32).max(1.0);
        let (from, to) = ((p.x - 0.5 * across) / step, (p.x + 0.5 * across) / step);
        let (first, end) = ((from + 0.5).floor() as i64, (to + 0.5).floor() as i64);
        let (mut sum, mut total) = ([0.0f32; 3], 0.0);
        for c in (first..=end).map(|c| c as f32) {
            let weight = to.min(c + 0.5) - from.max(c - 0.5);
            if weight > 0.0 {
                let x = index((c * step).round().clamp(0.0, last as f32));
                let colour = match &self.mirror {
                    Some(m) => m.land_point(x, y, || self.land_point(x, y)),
                    None => self.land_point(x, y),
                };
                for (ch, s) in sum.iter_mut().enumerate() {
                    *s += weight * ((colour >> (16 - 8 * ch)) & 0xff) as f32;
                }
                total += weight;
            }
        }
        let [r, g, b] = sum.map(|s| (s / total).round() as u32);
        self.hazed(
            r << 16 | g << 8 | b,
            self.haze_at(p.x, p.y, 2.0 * level - h),
        )
    }

    /// The sky seen along world direction `dir` (pointing up).
    fn sky_towards(&self, dir: Vec3) -> u32 {
        match self.view.vanishing(dir) {
            Some(p) => self.sky.colour_at(p.x, p.y),
            // Behind the camera: high overhead, the zenith's side.
            None => self.sky.colour_at(0.0, -1e6),
        }
    }
}

/// How much of what it mirrors (of 256) the water with `look` shows where
/// its streak is `ripple`: less the rougher the water, rising smoothly
/// from the calmest to the roughest. A share falling with the ripple's
/// size either way (`|ripple|`) peaked where the ripple crosses 0: every
/// such place drew a thin line of whole mirror between two bands of less,
/// twice as many lines as streaks.
fn mirror_weight(look: &Look, ripple: f32) -> u32 {
    let rough = 0.5 * (1.0 + ripple);
    let share = look.share * (1.0 - STREAK * rough * rough);
    (share * 256.0) as u32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::Size;
    use crate::render::scene::FieldRef;
    use crate::settings::{Clouds, Settings, ViewKind, World};
    use crate::terrain::Heightfield;

    /// A sea with a ridged cone standing in it towards the back of a
    /// 257-point grid: ridges one grid step apart, so its points' colours
    /// change from each to the next.
    fn ridged_peak() -> Heightfield {
        let mut f = Heightfield::flat(8, 800.0);
        let n = f.size();
        for y in 0..n {
            for x in 0..n {
                let d = ((x as f32 - 128.0).powi(2) + (y as f32 - 60.0).powi(2)).sqrt();
                let ridge = if x % 2 == 0 { 4.0 } else { 0.0 };
                f.set(x, y, (60.0 * (1.0 - d / 50.0) + ridge).max(-6.0));
            }
        }
        f
    }

    fn scene(field: &Heightfield, size: Size) -> Scene<'_> {
        let settings = Settings {
            view: ViewKind::Vista,
            clouds: Clouds::Amount(0.0),
            world: World::Temperate,
            ..Settings::default()
        };
        Scene::new(FieldRef::Borrowed(field), &settings, size)
    }

    /// The mirrored land stands for a width of the land: a point a grid
    /// step wide is its nearest point's colour, a wider one the mean of
    /// the points across it (the ridges' stripes averaged out, where one
    /// point a corner showed near water as blocks), and the colour moves
    /// smoothly as the point moves.
    #[test]
    fn mirrored_land_is_the_mean_across_its_width() {
        let field = ridged_peak();
        let scene = scene(&field, Size::new(640, 360));
        let (x, y) = (120, 70);
        let p = Vec2::new(x as f32, y as f32);
        let at = |p: Vec2, across: f32| scene.mirrored_land(p, 30.0, 0.0, across);
        let hazed = |c: u32| scene.hazed(c, scene.haze_at(p.x, p.y, -30.0));
        let (a, b) = (scene.land_point(x, y), scene.land_point(x + 1, y));
        let channel = |c: u32, ch: u32| ((c >> ch) & 0xff) as i32;
        let far = |c: u32, d: u32| [0, 8, 16].map(|ch| (channel(c, ch) - channel(d, ch)).abs());
        assert!(
            far(a, b).iter().any(|&d| d > 20),
            "the ridges' points differ"
        );
        assert_eq!(at(p, 1.0), hazed(a));
        // Five steps wide: the points x - 2 to x + 2.
        let sum = (x - 2..=x + 2).fold([0.0f32; 3], |mut sum, gx| {
            let c = scene.land_point(gx, y);
            for (ch, s) in [16, 8, 0].into_iter().zip(sum.iter_mut()) {
                *s += channel(c, ch) as f32 / 5.0;
            }
            sum
        });
        let [r, g, bl] = sum.map(|s| s.round() as u32);
        let mean = hazed(r << 16 | g << 8 | bl);
        let wide = at(p, 5.0);
        assert!(
            far(wide, mean).iter().all(|&d| d <= 1),
            "{wide:06x} against {mean:06x}"
        );
        let stripes = far(a, b);
        assert!(
            far(wide, a).iter().zip(stripes).all(|(&d, s)| d < s),
            "between the stripes"
        );
        // A tenth of a step along, the colour moves by about a tenth of the
        // stripes' difference at most.
        for across in [2.0, 3.5, 8.0] {
            for k in 0..10 {
                let (u, v) = (
                    at(p + Vec2::X * (k as f32 / 10.0), across),
                    at(p + Vec2::X * ((k + 1) as f32 / 10.0), across),
                );
                let (step, stripes) = (far(u, v), far(a, b));
                for ch in 0..3 {
                    assert!(
                        step[ch] <= stripes[ch] / 5 + 2,
                        "{across} at {k}: {step:?} of {stripes:?}"
                    );
                }
            }
        }
    }

    /// The streaks tilt the mirror of water whose grid steps are seen
    /// narrow (fine streaks; at least half their tilt where a step is seen
    /// under halfway from [`SHOWN_FULL`] to [`SHOWN_NONE`] wide), and not of
    /// water whose steps are seen wide (near the viewer, where each cell
    /// mirrored a slice of its own: a mosaic). Seed 8's winter sea reaches
    /// from the one to the other.
    #[test]
    fn the_streaks_tilt_only_the_mirror_of_water_seen_small() {
        let size = Size::new(480, 270);
        let prefs = Settings {
            seed: Some(8),
            ..Settings::default()
        };
        let settings = crate::render::detail::for_frame(&prefs, size);
        let field = crate::terrain::generate(&settings, 8);
        let scene = Scene::new(FieldRef::Borrowed(&field), &settings, size);
        let mirror = scene.mirror.as_ref().expect("a mirror");
        let (mut narrow, mut tilted_narrow, mut wide) = (0, 0, 0);
        let n = scene.cells();
        for (x, y) in (0..=n)
            .step_by(4)
            .flat_map(|y| (0..=n).step_by(4).map(move |x| (x, y)))
        {
            let g = Vec2::new(x as f32, y as f32);
            let at = scene.view.project(g.x, g.y, 0.0);
            let seen = at.x >= 0.0 && at.y >= 0.0 && at.x < 480.0 && at.y < 270.0;
            if field.get(x, y) >= 0.0 || !seen {
                continue;
            }
            let streak = |ripple: f32| Streak {
                ripple,
                tilt: scene.streak_shares(g, 0.0, 0.0, true)[1],
            };
            let Some(still) = scene.look(mirror, (g, 0.0), streak(0.0)) else {
                continue;
            };
            let tilted = scene.look(mirror, (g, 0.0), streak(1.0)).expect("water");
            let moved = (still.colour, still.margin) != (tilted.colour, tilted.margin);
            let steps = (scene.view.project(g.x + 1.0, g.y, 0.0) - at).length() / scene.frame_step;
            if steps < 0.5 * (SHOWN_FULL + SHOWN_NONE) {
                narrow += 1;
                tilted_narrow += usize::from(moved);
            } else if steps > SHOWN_NONE {
                wide += 1;
                assert!(!moved, "({x}, {y}), {steps} steps wide");
            }
        }
        assert!(narrow > 50 && wide > 50, "{narrow} narrow, {wide} wide");
        assert!(
            tilted_narrow * 2 > narrow,
            "{tilted_narrow} of {narrow} tilted"
        );
    }
}
