//! Grid points' colours worked out once and shared by every thread that
//! asks: the water's mirror stands each of its samples for a width of the
//! land, the mean of a few grid points, and neighbouring samples (across
//! the fan and along it) ask for the same points again: on seeds 2, 4 and
//! 8 at 1080p each point was worked out 6 to 12 times.
//!
//! A fixed table, filled as points are asked for: each slot holds a point
//! and its colour in one atomic word, so a reader sees a slot whole or
//! empty. A point whose slots near its hash are taken is worked out each
//! time, as before. A colour is a function of the scene alone, so the
//! pictures do not depend on which thread keeps a point first.

use std::sync::OnceLock;
use std::sync::atomic::{AtomicU64, Ordering};

use crate::terrain::splitmix::mix;

/// Slots of the table: 256 KiB, made the first time a point is asked for
/// (a 1080p slide's mirror asks for about 14,000 points).
const SLOTS: usize = 1 << 15;
/// Slots looked at for a point, from its hash on.
const PROBES: usize = 8;
/// An empty slot (no point is this: a point's column and row are under
/// 2^16, and a colour's top byte is 0).
const EMPTY: u64 = u64::MAX;

/// Packed colours of grid points, kept as they are worked out.
#[derive(Debug, Default)]
pub(crate) struct KeptPoints {
    slots: OnceLock<Box<[AtomicU64]>>,
}

impl KeptPoints {
    /// The colour of grid point (`x`, `y`): kept, or `colour()` (which
    /// must give the same whenever it is asked).
    pub(crate) fn get_or(&self, x: usize, y: usize, colour: impl FnOnce() -> u32) -> u32 {
        let (Ok(x), Ok(y)) = (u16::try_from(x), u16::try_from(y)) else {
            return colour();
        };
        let key = u64::from(y) << 16 | u64::from(x);
        let slots = self
            .slots
            .get_or_init(|| (0..SLOTS).map(|_| AtomicU64::new(EMPTY)).collect());
        let start = mix(key) as usize;
        for probe in 0..PROBES {
            let slot = &slots[(start + probe) & (SLOTS - 1)];
            match slot.load(Ordering::Relaxed) {
                EMPTY => {
                    let c = colour() & 0x00ff_ffff;
                    // Another thread may have taken the slot meanwhile:
                    // for this point (the same colour) or another.
                    let _ = slot.compare_exchange(
                        EMPTY,
                        key << 32 | u64::from(c),
                        Ordering::Relaxed,
                        Ordering::Relaxed,
                    );
                    return c;
                }
                held if held >> 32 == key => return held as u32,
                _ => {}
            }
        }
        colour()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    fn colour_of(x: usize, y: usize) -> u32 {
        (mix((x * 7919 + y) as u64) & 0x00ff_ffff) as u32
    }

    #[test]
    fn a_point_is_worked_out_once_and_given_back_as_it_was() {
        let kept = KeptPoints::default();
        let asked = Cell::new(0);
        let ask = |x: usize, y: usize| {
            kept.get_or(x, y, || {
                asked.set(asked.get() + 1);
                colour_of(x, y)
            })
        };
        let points: Vec<(usize, usize)> = (0..5000).map(|i| (i * 37 % 2049, i / 3)).collect();
        for round in 0..3 {
            for &(x, y) in &points {
                assert_eq!(ask(x, y), colour_of(x, y), "round {round}: ({x}, {y})");
            }
        }
        assert!(
            asked.get() < 5100,
            "{} worked out for 5000 points",
            asked.get()
        );
        // Points past a grid's largest side are worked out each time.
        assert_eq!(ask(70_000, 3), colour_of(70_000, 3));
        assert_eq!(ask(70_000, 3), colour_of(70_000, 3));
    }

    #[test]
    fn a_full_table_still_gives_every_colour() {
        let kept = KeptPoints::default();
        for round in 0..2 {
            for i in 0..(SLOTS + SLOTS / 2) {
                let (x, y) = (i % 4096, i / 4096);
                assert_eq!(
                    kept.get_or(x, y, || colour_of(x, y)),
                    colour_of(x, y),
                    "{round}"
                );
            }
        }
    }

    #[test]
    fn threads_asking_at_once_get_the_same_colours() {
        let kept = KeptPoints::default();
        let colours: Vec<Vec<u32>> = std::thread::scope(|s| {
            let ask = || {
                (0..20_000)
                    .map(|i| {
                        let (x, y) = (i * 13 % 1025, i % 341);
                        kept.get_or(x, y, || colour_of(x, y))
                    })
                    .collect::<Vec<u32>>()
            };
            let a = s.spawn(ask);
            let b = s.spawn(ask);
            vec![a.join().unwrap(), b.join().unwrap()]
        });
        let want: Vec<u32> = (0..20_000)
            .map(|i| colour_of(i * 13 % 1025, i % 341))
            .collect();
        assert_eq!(colours[0], want);
        assert_eq!(colours[1], want);
    }
}
