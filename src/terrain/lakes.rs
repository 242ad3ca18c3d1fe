//! Mountain lakes: basins above the sea filled to their lowest lip.
//!
//! Water drains off the grid's border and into the sea (every point at or
//! below sea level, 0). A point's water stands at the lowest height it must
//! rise to before it can leave that way: over every path to an outlet, the
//! least of the path's highest point. Where that is above the ground the
//! point is under a lake, and the lake is every such point joined to it
//! (all of them share that surface: a lake's surface is its lowest lip,
//! exactly, and no lake point stands above it). Basins of fewer than
//! [`MIN_AREA_SHARE`] of the points are left dry (a pit a few points wide
//! does not read as water).
//!
//! They are found from the basins and the lips between them ([`spill`]):
//! a few passes over each band of rows while it is in the cache
//! ([`band`]), on both cores, the bands joined where ways cross them
//! ([`bands`]), and a joining of the basins over their lips, lowest first.
//! Nothing is kept a point but a bit. A field over [`spill::MOST_POINTS`]
//! (a 4097 grid), whose bands' kept rows and lips would outgrow a tenth of
//! it, is flooded from its pits instead ([`rise`]), with two bits a point;
//! the two ways find the same lakes.

mod ahead;
mod band;
mod bands;
mod bits;
mod fill;
mod grid;
mod labels;
mod lips;
mod open;
mod pits;
mod raised;
mod rise;
mod spill;
mod wide;

/// The two ways the lakes are found: from the basins' lips (fast, found in
/// bands of `rows` rows), or by the water rising from the pits (with two
/// bits a point, for the largest fields).
#[derive(Clone, Copy)]
enum Way {
    Spill { rows: usize },
    Rise,
}

/// Least share of the grid's points a basin covers to be drawn as a lake.
pub const MIN_AREA_SHARE: f64 = 1e-4;

/// The lakes of one field: their surfaces, and which points of each row
/// lie under them.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Lakes {
    size: usize,
    levels: Vec<f32>,
    /// Per row, the runs of lake points, left to right.
    rows: Vec<Vec<Run>>,
}

/// Points `start..end` of a row, under lake `lake`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Run {
    /// First column under water.
    pub start: u32,
    /// One past the last column under water.
    pub end: u32,
    /// Which lake (an index into [`Lakes::level`]).
    pub lake: u32,
}

impl Lakes {
    /// The lakes of a field of `size` points a side (`heights`, row-major):
    /// basins above the sea of at least [`MIN_AREA_SHARE`] of its points
    /// (and at least 4), filled to their lip.
    pub fn of(heights: &[f32], size: usize) -> Self {
        let least = ((heights.len() as f64 * MIN_AREA_SHARE).ceil() as usize).max(4);
        Lakes::at_least(heights, size, least)
    }

    /// [`Lakes::of`] keeping basins of at least `least` points.
    pub fn at_least(heights: &[f32], size: usize, least: usize) -> Self {
        let way = if heights.len() <= spill::MOST_POINTS {
            Way::Spill {
                rows: bands::band_rows(size),
            }
        } else {
            Way::Rise
        };
        Lakes::found(heights, size, least, way)
    }

    /// [`Lakes::at_least`], found `way`.
    fn found(heights: &[f32], size: usize, least: usize, way: Way) -> Self {
        assert_eq!(heights.len(), size * size, "a square field");
        assert!(
            heights.len() <= 1 << 25,
            "at most 2^25 points (a 4097 grid has 2^24)"
        );
        let mut lakes = Lakes {
            size,
            ..Lakes::default()
        };
        let mut found = |level, points: &mut [u32]| lakes.add(points, level);
        match way {
            Way::Spill { rows } => spill::lakes(heights, size, least.max(1), rows, &mut found),
            Way::Rise => rise::basins(heights, size, least.max(1), found),
        }
        lakes.in_order_of_level();
        lakes
    }

    /// Points per side of the field these lakes belong to.
    pub fn size(&self) -> usize {
        self.size
    }

    /// How many lakes there are.
    pub fn count(&self) -> usize {
        self.levels.len()
    }

    /// The surface height of lake `lake`: its basin's lowest lip.
    pub fn level(&self, lake: u32) -> f32 {
        self.levels[lake as usize]
    }

    /// The runs of lake points in row `y`, left to right.
    pub fn row(&self, y: usize) -> &[Run] {
        self.rows.get(y).map_or(&[], |r| r.as_slice())
    }

    /// The lake over point (`x`, `y`), if any.
    pub fn lake_at(&self, x: usize, y: usize) -> Option<u32> {
        let runs = self.row(y);
        let i = runs.partition_point(|r| (r.end as usize) <= x);
        runs.get(i)
            .filter(|r| r.start as usize <= x)
            .map(|r| r.lake)
    }

    /// The water surface over point (`x`, `y`): its lake's level, or sea
    /// level (0) where there is no lake.
    pub fn surface_at(&self, x: usize, y: usize) -> f32 {
        self.lake_at(x, y).map_or(0.0, |l| self.level(l))
    }

    /// Points under each lake.
    pub fn areas(&self) -> Vec<usize> {
        let mut areas = vec![0; self.count()];
        for run in self.rows.iter().flatten() {
            areas[run.lake as usize] += (run.end - run.start) as usize;
        }
        areas
    }

    /// These lakes on the field turned `quarters` quarter turns as
    /// `render`'s turned view turns it: point (x, y) of the turned field
    /// is point `source(x, y)` of this one.
    pub fn turned(&self, source: impl Fn(usize, usize) -> (usize, usize)) -> Self {
        let n = self.size;
        let mut rows = vec![Vec::new(); n];
        for (y, row) in rows.iter_mut().enumerate() {
            let mut open: Option<Run> = None;
            for x in 0..n {
                let (sx, sy) = source(x, y);
                match (self.lake_at(sx, sy), &mut open) {
                    (Some(l), Some(r)) if r.lake == l && r.end as usize == x => r.end += 1,
                    (lake, open) => {
                        row.extend(open.take());
                        *open = lake.map(|lake| Run {
                            start: x as u32,
                            end: x as u32 + 1,
                            lake,
                        });
                    }
                }
            }
            row.extend(open);
        }
        Lakes {
            size: n,
            levels: self.levels.clone(),
            rows,
        }
    }
}

impl Lakes {
    /// The same lakes with their levels multiplied by `f` (for a field
    /// whose heights are).
    pub(crate) fn scaled(&self, f: f32) -> Lakes {
        Lakes {
            levels: self.levels.iter().map(|l| l * f).collect(),
            ..self.clone()
        }
    }

    /// The lakes numbered by level, lowest first (the order a flood from
    /// the outlets would meet them in; ties by their first point).
    fn in_order_of_level(&mut self) {
        let mut first = vec![u32::MAX; self.count()];
        for (y, row) in self.rows.iter().enumerate() {
            for run in row {
                let at = &mut first[run.lake as usize];
                *at = (*at).min((y * self.size) as u32 + run.start);
            }
        }
        let mut order: Vec<u32> = (0..self.count() as u32).collect();
        order.sort_by(|&a, &b| {
            let (a, b) = (a as usize, b as usize);
            self.levels[a]
                .total_cmp(&self.levels[b])
                .then(first[a].cmp(&first[b]))
        });
        let mut new_index = vec![0u32; order.len()];
        for (new, &old) in order.iter().enumerate() {
            new_index[old as usize] = new as u32;
        }
        self.levels = order.iter().map(|&l| self.levels[l as usize]).collect();
        for run in self.rows.iter_mut().flatten() {
            run.lake = new_index[run.lake as usize];
        }
    }

    /// Adds the lake over `points` (grid indices) at `level`.
    fn add(&mut self, points: &mut [u32], level: f32) {
        let n = self.size;
        if self.rows.is_empty() {
            self.rows = vec![Vec::new(); n];
        }
        let lake = self.levels.len() as u32;
        self.levels.push(level);
        points.sort_unstable();
        let mut runs = points.chunk_by(|&a, &b| b == a + 1 && !(b as usize).is_multiple_of(n));
        for run in &mut runs {
            let first = run[0] as usize;
            let (x, y) = (first % n, first / n);
            let row = &mut self.rows[y];
            let at = row.partition_point(|r| (r.start as usize) < x);
            row.insert(
                at,
                Run {
                    start: x as u32,
                    end: (x + run.len()) as u32,
                    lake,
                },
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both ways on `heights`, at several least areas, the lips' with
    /// bands of several heights (down to two rows, where most ways leave
    /// their band, and up to the whole field).
    fn both_ways_agree(heights: &[f32], n: usize, what: &str) {
        for least in [1, 4, 30] {
            let rise = Lakes::found(heights, n, least, Way::Rise);
            for rows in [2, 3, 5, 16, bands::band_rows(n), n] {
                let spill = Lakes::found(heights, n, least, Way::Spill { rows });
                assert_eq!(spill, rise, "{what}, least {least}, bands of {rows} rows");
            }
        }
    }

    /// A field of `n` a side with heights in `levels` steps (many equal
    /// neighbours, flat floors and lips) from `seed`, some of it sea.
    fn stepped(n: usize, levels: u64, seed: u64) -> Vec<f32> {
        (0..(n * n) as u64)
            .map(|i| {
                let h = crate::terrain::splitmix::mix(seed ^ i.wrapping_mul(0x9E37_79B9));
                (h % levels) as f32 - 1.0
            })
            .collect()
    }

    #[test]
    fn the_lips_find_the_lakes_the_rising_water_finds() {
        for seed in 0..6 {
            for levels in [3, 6, 50, 1000] {
                both_ways_agree(&stepped(40, levels, seed), 40, "stepped");
            }
        }
        for seed in 1..=4 {
            let s = crate::settings::Settings {
                detail: crate::settings::Detail::Level(7),
                lakes: true,
                ..Default::default()
            };
            let field = crate::terrain::generate(&s, seed);
            both_ways_agree(field.heights(), field.size(), "generated");
        }
    }
}
