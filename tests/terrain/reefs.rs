//! The tropical world's reefs: some of its mountains have a ring of low
//! islets round a shallow lagoon in a deep sea (an atoll beside the
//! island, or a barrier reef round it), drawn from the mountain's seed,
//! the same at every detail and on any thread count.

use mountains::settings::{Detail, Settings, World};
use mountains::terrain::reef::{self, Reef};
use mountains::terrain::{Heightfield, generate_with_threads};

/// The tropical mountain of `seed` on a grid of `2^detail + 1` points.
fn tropical(seed: u64, detail: u32, threads: usize) -> Heightfield {
    let s = Settings {
        world: World::Tropical,
        detail: Detail::Level(detail),
        ..Settings::default()
    };
    generate_with_threads(&s, seed, threads)
}

/// Rays cast from a lagoon's middle.
const RAYS: usize = 32;
/// The widest an islet is across, in grid widths.
const ISLET: f32 = 0.08;

/// The middle of the field's lagoon (in grid widths) and how many of
/// [`RAYS`] rays from it cross a ring: from the lagoon's shallow water
/// onto a narrow strip of land (an islet: at most [`ISLET`] of the grid
/// across, not the far shore of a bay) and on out to the deep sea. The lagoon is the largest connected stretch of
/// shallow water (less than a tenth of the deepest depth) off the grid's
/// border; none, no ring.
fn ring(field: &Heightfield) -> Option<((f32, f32), usize)> {
    let n = field.size();
    let deepest = -field.min();
    let shallow = |h: f32| h <= 0.0 && h > -0.1 * deepest;
    let lagoon = largest_inner(field, shallow)?;
    let (cx, cy) = lagoon
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x as f32, b + y as f32));
    let centre = (cx / lagoon.len() as f32, cy / lagoon.len() as f32);
    let mut ringed = 0;
    for k in 0..RAYS {
        let angle = k as f32 / RAYS as f32 * std::f32::consts::TAU;
        let (dx, dy) = (angle.cos(), angle.sin());
        let (mut wet, mut land, mut across) = (false, false, 0);
        for step in 1..n {
            let (x, y) = (centre.0 + dx * step as f32, centre.1 + dy * step as f32);
            if x < 0.0 || y < 0.0 || x > (n - 1) as f32 || y > (n - 1) as f32 {
                break;
            }
            let h = field.get(x.round() as usize, y.round() as usize);
            if shallow(h) {
                wet = true;
            } else if h > 0.0 && wet {
                across += 1;
                land = true;
                if across as f32 > ISLET * n as f32 {
                    break;
                }
            } else if h <= -0.3 * deepest {
                ringed += usize::from(land);
                break;
            }
        }
    }
    let last = (n - 1) as f32;
    Some(((centre.0 / last, centre.1 / last), ringed))
}

/// The points of the largest 4-connected region where `inside` holds of
/// the height and that touches no border of the grid.
fn largest_inner(field: &Heightfield, inside: impl Fn(f32) -> bool) -> Option<Vec<(usize, usize)>> {
    let n = field.size();
    let mut seen = vec![false; n * n];
    let mut best: Option<Vec<(usize, usize)>> = None;
    for start in 0..n * n {
        if seen[start] || !inside(field.heights()[start]) {
            continue;
        }
        seen[start] = true;
        let (mut stack, mut region, mut border) = (vec![start], Vec::new(), false);
        while let Some(i) = stack.pop() {
            let (x, y) = (i % n, i / n);
            region.push((x, y));
            border |= x == 0 || y == 0 || x == n - 1 || y == n - 1;
            let next = [
                (x > 0).then(|| i - 1),
                (x + 1 < n).then_some(i + 1),
                (y > 0).then(|| i - n),
                (y + 1 < n).then_some(i + n),
            ];
            for j in next.into_iter().flatten() {
                if !seen[j] && inside(field.heights()[j]) {
                    seen[j] = true;
                    stack.push(j);
                }
            }
        }
        if !border && best.as_ref().is_none_or(|b| region.len() > b.len()) {
            best = Some(region);
        }
    }
    best
}

/// Whether a ring stands round the lagoon: a quarter of the rays or more
/// cross an islet (the rest pass between them, over the awash reef).
fn ringed(field: &Heightfield) -> bool {
    ring(field).is_some_and(|(_, rays)| rays * 4 >= RAYS)
}

/// Every tropical mountain whose draw gives it a reef has a ring of
/// islets round a lagoon, and a good share of them do; the others (and
/// the same seeds in the temperate world) mostly have none.
#[test]
fn some_tropical_mountains_stand_in_a_ring_of_islets_round_a_lagoon() {
    let (mut reefs, mut rings_without) = (0, 0);
    for seed in 1..=24u64 {
        let field = tropical(seed, 8, 2);
        let drawn = reef::of(field.identity());
        if drawn == Reef::None {
            rings_without += usize::from(ringed(&field));
            continue;
        }
        reefs += 1;
        assert!(
            ringed(&field),
            "seed {seed} ({drawn:?}): no ring round a lagoon, {:?}",
            ring(&field)
        );
    }
    assert!(reefs * 3 >= 24, "only {reefs} of 24 have a reef");
    assert!(rings_without <= 2, "{rings_without} rings without a reef");
    let temperate = (1..=24u64)
        .filter(|&seed| {
            let s = Settings {
                world: World::Temperate,
                detail: Detail::Level(8),
                ..Settings::default()
            };
            ringed(&generate_with_threads(&s, seed, 2))
        })
        .count();
    assert!(temperate <= 2, "{temperate} temperate mountains ringed");
}

/// A reef lies where it lies at every detail (its lagoon's middle within
/// a fiftieth of the grid) and is bit for bit the same on any thread
/// count.
#[test]
fn a_reef_is_the_same_at_every_detail_and_thread_count() {
    let seeds: Vec<u64> = (1..=40u64)
        .filter(|&s| reef::of(tropical(s, 4, 1).identity()) != Reef::None)
        .take(6)
        .collect();
    assert_eq!(seeds.len(), 6);
    for seed in seeds {
        let middles: Vec<(f32, f32)> = [7, 8, 9]
            .map(|detail| ring(&tropical(seed, detail, 2)).expect("a lagoon").0)
            .to_vec();
        for m in &middles[1..] {
            let off = (m.0 - middles[0].0).abs().max((m.1 - middles[0].1).abs());
            assert!(off < 0.02, "seed {seed}: lagoons at {middles:?}");
        }
        let bits = |f: Heightfield| f.heights().iter().map(|h| h.to_bits()).collect::<Vec<_>>();
        assert!(
            bits(tropical(seed, 8, 1)) == bits(tropical(seed, 8, 3)),
            "seed {seed}: the thread count changes the reef"
        );
    }
}
