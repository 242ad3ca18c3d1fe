//! What a water face mirrors: the land its reflected sight line meets,
//! shaded as the scene shades that land's points, or the sky it escapes
//! to; mixed into the water's own colour by the mirror's share, weaker
//! where the wind's streaks are strong, with the sun's glitter where the
//! line points near the sun.

use glam::{Vec2, Vec3};

use crate::render::base::colour::blend_packed;
use crate::render::scene::Scene;
use crate::render::shade::index;
use crate::render::shade::mirror::{Look, Mirror, Mirrored, Seen};

/// How much the strongest streak (ripple 1) takes from the mirror.
const STREAK: f32 = 0.4;
/// How much finer than the streaks the glittering facets are, across and
/// along the view (world-sized, as the streaks are).
const FACETS: (f32, f32) = (7.3, 2.9);

impl Scene<'_> {
    /// `water` (the face's own colour, hazed) at grid position `g` of a
    /// surface at `level`, whose streak there is `ripple`, with what it
    /// mirrors; `lit` (0..=1) of the sun reaches it, so water in the shadow
    /// of the land before the sun does not glitter.
    pub(super) fn mirrored(
        &self,
        mirror: &Mirror,
        water: u32,
        (g, level): (Vec2, f32),
        ripple: f32,
        lit: f32,
    ) -> u32 {
        let Some(look) = self.look(mirror, (g, level), ripple) else {
            return water;
        };
        let out = blend_packed(water, look.colour, mirror_weight(&look, ripple));
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
        ripple: f32,
    ) -> Mirrored {
        let Some(look) = self.look(mirror, (g, level), ripple) else {
            return Mirrored {
                land: water,
                sky: water,
                margin: 0.0,
                near_sun: None,
            };
        };
        let weight = mirror_weight(&look, ripple);
        Mirrored {
            land: blend_packed(water, look.land, weight),
            sky: blend_packed(water, look.sky, weight),
            margin: look.margin,
            near_sun: look.near_sun,
        }
    }

    /// What the water at grid position `g` of a surface at `level`, whose
    /// streak there is `ripple`, mirrors.
    fn look(&self, mirror: &Mirror, (g, level): (Vec2, f32), ripple: f32) -> Option<Look> {
        let seen = |seen: Seen| match seen {
            Seen::Land { at, height } => self.mirrored_land(at, height, level),
            Seen::Sky(dir) => self.sky_towards(dir),
        };
        mirror.look(&self.field, g, level, ripple, seen)
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

    /// The land at grid position `p`, height `h`, seen in water at `level`:
    /// its nearest point's colour, hazed as far as its image below the
    /// water lies from the eye.
    fn mirrored_land(&self, p: Vec2, h: f32, level: f32) -> u32 {
        let last = self.cells() as f32;
        let (x, y) = (p.x.round().clamp(0.0, last), p.y.round().clamp(0.0, last));
        let land = self.land_point(index(x), index(y));
        self.hazed(land, self.haze_at(p.x, p.y, 2.0 * level - h))
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
/// its streak is `ripple`.
fn mirror_weight(look: &Look, ripple: f32) -> u32 {
    let share = look.share * (1.0 - STREAK * ripple.abs());
    (share * 256.0) as u32
}
