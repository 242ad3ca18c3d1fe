//! Helpers shared by the terrain tests.
#![allow(dead_code)]

use mountains::settings::{Detail, Generator, Profile, Settings, WaterLine, World};

/// Every generator.
pub const GENERATORS: [Generator; 3] = [Generator::Square, Generator::Diamond, Generator::Triangle];

/// Every triangle profile.
pub const PROFILES: [Profile; 4] = [Profile::Slope, Profile::Peak, Profile::Bay, Profile::Massif];

/// Default settings with a generator and detail level, the water line at
/// the generator's zero, contour 1 and no erosion: the laws below are the
/// subdivision's, and the coast pass (tests/terrain/coast.rs) and erosion
/// (tests/terrain/erosion.rs) move heights after it.
pub fn settings(generator: Generator, detail: u32) -> Settings {
    Settings {
        generator,
        detail: Detail::Level(detail),
        water_line: WaterLine::Generator,
        erosion: 0.0,
        // The laws are written for heights as subdivided (seed 000's
        // menu, hence the default, starts at 1.5).
        contour: 1.0,
        ..temperate()
    }
}

/// The default settings in the temperate world: the generators' laws, the
/// coast, the lakes and what a data set records are measured on the keys'
/// own values, not on those a world lays under them (the worlds have their
/// tests in tests/render/worlds.rs).
pub fn temperate() -> Settings {
    Settings {
        world: World::Temperate,
        ..Settings::default()
    }
}

/// The new points of depth `k` on a grid of `last + 1` points a side, as
/// (x, y, kind), where kind says which parents the point has.
pub fn new_points(last: usize, k: u32) -> Vec<(usize, usize, Kind)> {
    let step = last >> k;
    let h = step / 2;
    let mut points = Vec::new();
    for y in (0..=last).step_by(h) {
        for x in (0..=last).step_by(h) {
            let (odd_x, odd_y) = ((x / h) % 2 == 1, (y / h) % 2 == 1);
            let kind = match (odd_x, odd_y) {
                (true, true) => Kind::Centre,
                (false, true) => Kind::Vertical,
                (true, false) => Kind::Horizontal,
                (false, false) => continue,
            };
            points.push((x, y, kind));
        }
    }
    points
}

/// Where a new point lies in the square its level splits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// The centre of the square (the triangles' diagonal midpoint).
    Centre,
    /// The midpoint of a vertical edge.
    Vertical,
    /// The midpoint of a horizontal edge.
    Horizontal,
}
