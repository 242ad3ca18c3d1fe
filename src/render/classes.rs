//! Which pixels of a frame show sky, water and land: the frame drawn with
//! the sky and the water each in a colour of its own, for measuring the
//! picture (examples/quality.rs) where the coast and the skyline are.
//!
//! Only colours change: the same scene, framing and painting order as
//! `render_full`, so each pixel's class is the surface `render_full`
//! leaves there.

use super::base::frame::Frame;
use super::painter::draw_full;
use super::scene::{FieldRef, Scene, Style};
use super::shade::ripples::Ripples;
use super::shade::sky::Sky;
use crate::settings::Settings;
use crate::terrain::Heightfield;

/// The colour of sky pixels in a class picture (no land colour is pure magenta).
pub const SKY: u32 = 0x00ff_00ff;
/// The colour of water pixels in a class picture (no land colour is pure cyan).
pub const WATER: u32 = 0x0000_ffff;

/// What a pixel of a frame shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Class {
    /// Nothing drawn: the sky behind the land.
    Sky,
    /// Open water: the sea, or a lake over a basin.
    Water,
    /// Land, its cut faces included.
    Land,
}

impl Class {
    /// The class of a pixel of a class picture.
    pub fn of(pixel: u32) -> Class {
        match pixel {
            SKY => Class::Sky,
            WATER => Class::Water,
            _ => Class::Land,
        }
    }
}

/// Draws the class picture of `field` under `settings` into `frame`: the
/// scene `render_full` draws, sky in [`SKY`], water in [`WATER`], land in
/// its own (unhazed) colours. `None` for the looks that are not filled with
/// shaded colours (Ridges, Mono, Sonar, Outline), which have no such
/// classes to tell apart.
#[doc(hidden)]
pub fn render_classes(field: &Heightfield, settings: &Settings, frame: &mut Frame) -> Option<()> {
    if settings.color == crate::settings::ColorMode::Ridges {
        return None;
    }
    let mut scene = Scene::new(FieldRef::Borrowed(field), settings, frame.size());
    if scene.style != Style::Shaded {
        return None;
    }
    scene.sky = Sky::new(SKY, SKY, 1.0);
    // Haze would fade the water's colour towards the sky's.
    scene.haze = None;
    scene.ripples = Some(Ripples::covering(WATER));
    // Nor may the water mirror anything.
    scene.mirror = None;
    // Each pixel one class: no mixing across the coast or the skyline.
    scene.clean_edges = false;
    draw_full(&scene, frame);
    Some(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::render_full;
    use crate::settings::Detail;

    #[test]
    fn the_class_picture_has_the_frames_sky_and_its_land_and_water_apart() {
        // The temperate coast, whose sea reaches the frame's bottom (seed
        // 42's varied world is the desert, framed over its dry basin).
        let settings = Settings {
            detail: Detail::Level(7),
            world: crate::settings::World::Temperate,
            ..Settings::default()
        };
        let field = crate::terrain::generate(&settings, 42);
        let (w, h) = (160, 90);
        let mut frame = Frame::new(w, h).unwrap();
        let mut classes = Frame::new(w, h).unwrap();
        render_full(&field, &settings, &mut frame);
        render_classes(&field, &settings, &mut classes).unwrap();
        let mut counts = [0usize; 3];
        for (&c, &f) in classes.pixels().iter().zip(frame.pixels()) {
            let class = Class::of(c);
            counts[class as usize] += 1;
            // Land is drawn as it is, but for the haze: never in a sentinel.
            assert_ne!(f, SKY);
            assert_ne!(f, WATER);
        }
        assert!(
            counts.iter().all(|&n| n > 0),
            "sky, water, land: {counts:?}"
        );
        // The sky rows at the top are sky in both pictures.
        assert_eq!(Class::of(classes.pixels()[0]), Class::Sky);
        assert_eq!(
            Class::of(classes.pixels()[(w * h - 1) as usize]),
            Class::Water
        );
    }
}
