//! The tropical world's reefs: on some of its mountains a ring of coral
//! stands round a lagoon. Either a barrier reef round the island itself
//! (its volcano standing in a turquoise lagoon, as Bora Bora's) or an
//! atoll out in the sea beside it (a lagoon with no island in it). The
//! ring's crest is a chain of low islets of coral sand, broken by passes
//! where the reef stays awash; the lagoon inside is shallow, the sea
//! outside falls away to the deep.
//!
//! Laid after the water line (heights are then the drawn ones, sea level
//! at 0) and before the lakes. Which reef, where and how wide is drawn
//! from the seed and from a coarse look at the land on the points every
//! grid shares, and the ring is a function of each point's place as a
//! fraction of the grid: the same reef at every detail. Only `+`, `*`,
//! `/` and `sqrt` (the angles are powers of a unit complex number), so
//! the same bits on every platform.

use super::Heightfield;
use super::coast::smoothstep;
use super::normalize::min_max;
use super::splitmix::mix;

/// Mixed into the seed for the reef's draws, apart from every other.
const REEF_KEY: u64 = 0x7265_6566_2072_696e;

/// The reefs a tropical mountain may have.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reef {
    /// Steep islands alone in the sea.
    None,
    /// A barrier reef round the island, its lagoon between.
    Barrier,
    /// An atoll in the open sea beside the island.
    Atoll,
}

/// The reef the tropical mountain of `identity` has
/// ([`Heightfield::identity`]: the camera that looks down on it draws
/// from the same number): a third of each.
pub fn of(identity: u64) -> Reef {
    match mix(identity ^ REEF_KEY) % 3 {
        0 => Reef::None,
        1 => Reef::Barrier,
        _ => Reef::Atoll,
    }
}

/// The barrier reef's radius (least, most), in grid widths: wide enough
/// to ring a volcano's lower slopes.
const BARRIER_RADIUS: (f32, f32) = (0.22, 0.3);
/// The island inside a barrier reef: its radius, as a share of the
/// reef's (its slopes sink into the lagoon over [`SINK`]).
const BARRIER_ISLAND: f32 = 0.6;
/// The atoll's radius (least, most), in grid widths.
const ATOLL_RADIUS: (f32, f32) = (0.13, 0.19);
/// Half the ring's width, as a share of its radius.
const RING_SHARE: f32 = 0.22;
/// How far round the ring wanders in and out of its circle, as a share
/// of the radius (an oval, a dent): no reef is a true circle.
const WANDER: f32 = 0.1;
/// The islets' highest crest, as a share of the highest peak: sand a
/// little above the waves, a few palms on the widest.
const ISLET_HIGH: f32 = 0.05;
/// The reef's crest in the passes between islets: awash, as a share of
/// the sea's depth (pale turquoise over the coral).
const PASS_DEPTH: f32 = 0.012;
/// The lagoon's floor, as a share of the sea's depth: turquoise shallows
/// over sand.
const LAGOON_DEPTH: f32 = 0.06;
/// How much shallower the lagoon's coral heads stand, as a share of its
/// depth.
const HEADS: f32 = 0.75;
/// The deep sea outside the reef, as a share of the sea's depth.
const OCEAN_DEPTH: f32 = 0.85;
/// The sea's depth is at least this share of the highest peak (a field
/// with hardly any sea still gets a deep one round its reef).
const LEAST_DEPTH: f32 = 0.3;
/// Ring half-widths over which the outer slope falls to the deep sea.
const DROP: f32 = 2.5;
/// Ring half-widths outside the crest from which the sea floor fades back
/// to its own depth, and by which it has.
const FADE: (f32, f32) = (4.0, 8.0);
/// Coral heads across the grid's width.
const HEAD_CELLS: f32 = 22.0;

/// A reef laid on a field: its ring and the heights it is shaped to.
#[derive(Debug, Clone, Copy)]
struct Ring {
    /// Centre, in grid widths from the back left corner.
    centre: (f32, f32),
    /// Mean radius, in grid widths.
    radius: f32,
    /// Half the ring's width, in grid widths.
    half_width: f32,
    /// Four unit complex numbers: the phases of the ring's wander (turns
    /// 2 and 3) and of its islets (turns 5, 8, 13).
    phases: [(f32, f32); 5],
    /// The islets' crest and the passes' (height units).
    islet: f32,
    pass: f32,
    /// The lagoon's floor and the deep sea's (height units, below 0).
    lagoon: f32,
    ocean: f32,
    /// The seed's draw for the lagoon's coral heads.
    heads: u64,
}

/// Lays the reef of the tropical mountain `field` ([`of`] its identity),
/// whose water line is at 0; a field without relief is left as it is.
/// The land away from the one island the reef keeps sinks into the deep
/// sea: a reef stands in open water.
pub(crate) fn lay(field: &mut Heightfield, threads: usize) {
    let seed = field.identity();
    let reef = of(seed);
    if reef == Reef::None {
        return;
    }
    let Some((ring, island)) = ring(field, seed, reef, threads) else {
        return;
    };
    let n = field.size();
    let last = (n - 1) as f32;
    let reach = ring.radius * (1.0 + WANDER) + FADE.1 * ring.half_width;
    let per = n.div_ceil(threads.max(1)).max(1);
    std::thread::scope(|s| {
        for (k, part) in field.heights_mut().chunks_mut(per * n).enumerate() {
            s.spawn(move || {
                for (dy, row) in part.chunks_exact_mut(n).enumerate() {
                    let y = (k * per + dy) as f32 / last;
                    let near = (y - ring.centre.1).abs() <= reach;
                    for (x, h) in row.iter_mut().enumerate() {
                        let p = (x as f32 / last, y);
                        let sunk = island.sunk(*h, p, ring.ocean);
                        *h = match near {
                            true => ring.shaped(sunk, p),
                            false => sunk,
                        };
                    }
                }
            });
        }
    });
}

/// The one island a reef keeps: the land farther from its centre sinks.
#[derive(Debug, Clone, Copy)]
struct Island {
    /// Centre, in grid widths.
    centre: (f32, f32),
    /// The land within this many grid widths stands as it is.
    radius: f32,
}

/// What the island's heights are scaled by: lower, so the camera can
/// stand high enough over the sea to look down into the lagoon.
const LOWER: f32 = 0.8;
/// Grid widths over which the land beyond an island's radius sinks.
const SINK: f32 = 0.1;
/// The island an atoll lies beside: its radius (least, most) in grid
/// widths.
const ISLAND_RADIUS: (f32, f32) = (0.2, 0.28);

impl Island {
    /// Ground `h` at `p`, sunk into a sea `ocean` deep as far as it lies
    /// off the island.
    #[inline]
    fn sunk(&self, h: f32, p: (f32, f32), ocean: f32) -> f32 {
        let (dx, dy) = (p.0 - self.centre.0, p.1 - self.centre.1);
        let d = (dx * dx + dy * dy).sqrt();
        let w = smoothstep(self.radius, self.radius + SINK, d);
        let h = if h > 0.0 { h * LOWER } else { h };
        h + (h.min(ocean) - h) * w
    }
}

/// The ring of `reef` on `field` drawn from `seed` (its identity), and
/// the island it keeps; none where the field has no relief.
fn ring(field: &Heightfield, seed: u64, reef: Reef, threads: usize) -> Option<(Ring, Island)> {
    let (lo, top) = {
        let e = min_max(field.heights(), threads);
        (e.lo, e.hi)
    };
    if !(top > 0.0 && top.is_finite() && lo.is_finite()) {
        return None;
    }
    let deep = (-lo).max(LEAST_DEPTH * top);
    let draw = mix(seed ^ REEF_KEY ^ 0x5a5a);
    let unit = |k: u32| ((mix(draw ^ u64::from(k)) >> 40) as f32) / (1u64 << 24) as f32;
    let within = |(a, b): (f32, f32), t: f32| a + (b - a) * t;
    let land = Land::of(field);
    let (centre, radius, island) = match reef {
        Reef::Barrier => {
            let radius = within(BARRIER_RADIUS, unit(1));
            let centre = land.peak_within(margin(radius));
            let island = Island {
                centre,
                radius: BARRIER_ISLAND * radius,
            };
            (centre, radius, island)
        }
        _ => {
            let radius = within(ATOLL_RADIUS, unit(1));
            let island = Island {
                centre: land.peak_within(0.15),
                radius: within(ISLAND_RADIUS, unit(2)),
            };
            (open_sea(&island, radius, draw), radius, island)
        }
    };
    let phase = |k: u32| {
        let (a, b) = (unit(10 + 2 * k) - 0.5, unit(11 + 2 * k) - 0.5);
        let l = (a * a + b * b).sqrt().max(1e-6);
        (a / l, b / l)
    };
    let ring = Ring {
        centre,
        radius,
        half_width: RING_SHARE * radius,
        phases: [phase(0), phase(1), phase(2), phase(3), phase(4)],
        islet: ISLET_HIGH * LOWER * top,
        pass: -PASS_DEPTH * deep,
        lagoon: -LAGOON_DEPTH * deep,
        ocean: -OCEAN_DEPTH * deep,
        heads: draw,
    };
    Some((ring, island))
}

/// How far from the grid's sides the centre of a ring of `radius` stays,
/// in grid widths, so that all the ring is seen.
fn margin(radius: f32) -> f32 {
    (radius * (1.0 + WANDER + RING_SHARE)).min(0.5)
}

/// The atoll's centre beside `island`: of a few places drawn from `draw`
/// (not at the grid's sides, nor in the front rows nor at the back where
/// it is small), the one nearest the front whose ring of `radius` clears
/// the island; failing any, the one farthest from it.
fn open_sea(island: &Island, radius: f32, draw: u64) -> (f32, f32) {
    let clear = island.radius + SINK + 1.4 * radius;
    let m = margin(radius);
    let apart = |c: (f32, f32)| {
        let (dx, dy) = (c.0 - island.centre.0, c.1 - island.centre.1);
        (dx * dx + dy * dy).sqrt()
    };
    let candidates: Vec<(f32, f32)> = (0..16u64)
        .map(|k| {
            let z = mix(draw ^ (k + 100));
            let unit = |shift: u32| ((z >> shift) & 0xffff) as f32 / 65535.0;
            let y = (0.3f32.max(m), 0.72f32.min(1.0 - m));
            (m + (1.0 - 2.0 * m) * unit(0), y.0 + (y.1 - y.0) * unit(16))
        })
        .collect();
    let clearing = candidates.iter().filter(|&&c| apart(c) >= clear);
    let front = clearing.fold(None, |best: Option<(f32, f32)>, &c| match best {
        Some(b) if b.1 >= c.1 => Some(b),
        _ => Some(c),
    });
    front.unwrap_or_else(|| {
        let far = |a: &&(f32, f32), b: &&(f32, f32)| apart(**a).total_cmp(&apart(**b));
        *candidates.iter().max_by(far).unwrap_or(&(0.5, 0.5))
    })
}

impl Ring {
    /// The height at `p` (grid widths) of ground `h` with the reef laid.
    #[inline]
    fn shaped(&self, h: f32, p: (f32, f32)) -> f32 {
        if !h.is_finite() {
            return h;
        }
        let (dx, dy) = (p.0 - self.centre.0, p.1 - self.centre.1);
        let d = (dx * dx + dy * dy).sqrt();
        // Off the ring, the waves round it need not be worked out: far
        // outside it the ground is as it was, well inside it the lagoon's
        // floor (the same heights as below, sooner).
        if d > self.radius * (1.0 + WANDER) + FADE.1 * self.half_width {
            return h;
        }
        if d < self.radius * (1.0 - WANDER) - self.half_width {
            return h.max(self.lagoon_floor(p));
        }
        let u = match d > 1e-6 {
            true => (dx / d, dy / d),
            false => (1.0, 0.0),
        };
        let few = Turns::of(u, 4);
        let wander = 0.6 * few.along(2, self.phases[0]) + 0.4 * few.along(3, self.phases[1]);
        let s = (d - self.radius * (1.0 + WANDER * wander)) / self.half_width;
        if s > FADE.1 {
            return h;
        }
        let bell = 1.0 - smoothstep(0.15, 1.0, s.abs());
        // The islets' waves only on the ring itself.
        let crest = match bell > 0.0 {
            true => self.crest(&Turns::of(u, 14)),
            false => 0.0,
        };
        if s <= 0.0 {
            let floor = self.lagoon_floor(p);
            return h.max(floor + (crest - floor) * bell);
        }
        let floor = self.lagoon + (self.ocean - self.lagoon) * smoothstep(0.0, DROP, s);
        let near = 1.0 - smoothstep(FADE.0, FADE.1, s);
        let ground = match h < 0.0 {
            true => h + (h.min(floor) - h) * near,
            false => h,
        };
        ground.max(floor + (crest - floor) * bell)
    }

    /// The ring's crest at the angle of `turns`: islets where the waves
    /// of the three turns add up, the reef awash in the passes between.
    fn crest(&self, turns: &Turns) -> f32 {
        let g = 0.45 * turns.along(5, self.phases[2])
            + 0.35 * turns.along(8, self.phases[3])
            + 0.2 * turns.along(13, self.phases[4]);
        self.pass + (self.islet - self.pass) * smoothstep(-0.3, 0.4, g)
    }

    /// The lagoon's floor at `p`: sand, and coral heads standing in it.
    fn lagoon_floor(&self, p: (f32, f32)) -> f32 {
        let head = value_noise(self.heads, p.0 * HEAD_CELLS, p.1 * HEAD_CELLS);
        self.lagoon * (1.0 - HEADS * smoothstep(0.55, 0.9, head))
    }
}

/// The powers of a unit complex number `u` (the angle round the ring)
/// that the ring's waves are drawn with: `u^k` for k up to 13.
struct Turns([(f32, f32); 14]);

impl Turns {
    /// The first `count` powers of `u` (the rest left at 1).
    fn of(u: (f32, f32), count: usize) -> Self {
        let mut p = [(1.0, 0.0); 14];
        for k in 1..count.min(14) {
            let (a, b) = p[k - 1];
            p[k] = (a * u.0 - b * u.1, a * u.1 + b * u.0);
        }
        Turns(p)
    }

    /// `cos(k * angle - phase)`: a wave of `k` turns round the ring.
    #[inline]
    fn along(&self, k: usize, phase: (f32, f32)) -> f32 {
        let (a, b) = self.0[k];
        a * phase.0 + b * phase.1
    }
}

/// A coarse look at the land on points every grid shares (33 a side at
/// most), for its highest points.
struct Land {
    /// Points a side.
    side: usize,
    /// The heights, row by row.
    heights: Vec<f32>,
}

/// Points a side of [`Land`]'s look.
const LOOK: usize = 33;

/// How far forward an island stands at most, in grid widths: one at the
/// front would hide the reef.
const FARTHEST_FORWARD: f32 = 0.6;

impl Land {
    fn of(field: &Heightfield) -> Self {
        let n = field.size();
        let stride = ((n - 1) / (LOOK - 1)).max(1);
        let side = (n - 1) / stride + 1;
        let heights = (0..side * side)
            .map(|k| field.get(k % side * stride, k / side * stride))
            .collect();
        Land { side, heights }
    }

    /// The highest point (in grid widths) at least `m` from every side of
    /// the grid and no farther forward than [`FARTHEST_FORWARD`] (if the
    /// margin allows): the island a ring of [`margin`] `m` is laid round
    /// or beside, all of it on the grid.
    fn peak_within(&self, m: f32) -> (f32, f32) {
        let last = (self.side - 1) as f32;
        let forward = FARTHEST_FORWARD.max(m);
        let (mut best, mut peak) = (f32::NEG_INFINITY, (0.5, 0.5));
        for (k, &h) in self.heights.iter().enumerate() {
            let p = ((k % self.side) as f32 / last, (k / self.side) as f32 / last);
            let inside = p.0 >= m && p.0 <= 1.0 - m && p.1 >= m && p.1 <= forward.min(1.0 - m);
            if inside && h > best {
                (best, peak) = (h, p);
            }
        }
        peak
    }
}

/// Smooth value noise from 0 to 1 at (`x`, `y`) (cells of 1): the same
/// at every grid, from `seed`.
fn value_noise(seed: u64, x: f32, y: f32) -> f32 {
    let (fx, fy) = (x.floor(), y.floor());
    let (tx, ty) = (smoothstep(0.0, 1.0, x - fx), smoothstep(0.0, 1.0, y - fy));
    let corner = |i: i64, j: i64| {
        let z = mix(seed ^ (i as u64).wrapping_mul(0x9E37_79B9) ^ (j as u64) << 32);
        (z >> 40) as f32 / (1u64 << 24) as f32
    };
    let (i, j) = (fx as i64, fy as i64);
    let top = corner(i, j) + (corner(i + 1, j) - corner(i, j)) * tx;
    let bottom = corner(i, j + 1) + (corner(i + 1, j + 1) - corner(i, j + 1)) * tx;
    top + (bottom - top) * ty
}
