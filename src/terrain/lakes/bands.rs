//! The field's basins and the lips between them, found a band of rows at a
//! time (see [`super::band`]) on both cores, then joined: each band's
//! exits followed on in the bands that own their points, until every end
//! is a pit of the field or the outlets.

use super::band::{Band, EXIT, OUTLET, band};
use super::lips::Lip;

/// Points a band holds at most, about: with the heights it reads, its
/// ways stay in a core's cache.
const BAND_POINTS: usize = 1 << 17;

/// Rows a band of a field `n` a side holds.
pub(super) fn band_rows(n: usize) -> usize {
    (BAND_POINTS / n).max(2)
}

/// The basins of `heights` (`n` a side) found in bands of `rows` rows:
/// the pits in place order (pit `k`'s basin is `k + 1`, the outlets' is
/// 0); the lips between the basins, in two lists, each lowest first; and
/// each basin's number of points. If `raise`, the basins are those of the
/// field with its pits of one point raised (see [`super::raised`]).
pub(super) fn basins(
    heights: &[f32],
    n: usize,
    rows: usize,
    raise: bool,
) -> (Vec<u32>, [Vec<Lip>; 2], Vec<u32>) {
    let starts = starts(n, rows);
    let half = starts.len() / 2;
    let run = |from: usize, to: usize| {
        let mut ways = Vec::new();
        let mut bands: Vec<Band> = Vec::with_capacity(to - from);
        for b in from..to {
            let end = starts.get(b + 1).copied().unwrap_or(n);
            let above = bands.last().map(Band::last_row);
            let band = band(heights, n, starts[b]..end, (above, raise), &mut ways);
            bands.push(band);
        }
        bands
    };
    let (mut bands, theirs) = crate::threads::both(|| run(0, half), || run(half, starts.len()));
    bands.extend(theirs);

    join(bands, n, half)
}

/// The first rows of the bands: `rows` each, the last taking what is left
/// over (so each has at least two rows, as [`Band::end_at`] needs).
fn starts(n: usize, rows: usize) -> Vec<usize> {
    let count = (n / rows).max(1);
    (0..count).map(|b| b * rows).collect()
}

/// The bands' pits, lips and sizes in the field's basin numbers. The lips
/// of the bands before `half` go in the first list. Each band's lips are
/// let go once copied: the field's lips are held about once.
fn join(mut bands: Vec<Band>, n: usize, half: usize) -> (Vec<u32>, [Vec<Lip>; 2], Vec<u32>) {
    let basins = Basins::new(&bands, n);
    let mut sizes = vec![0; basins.count];
    for (band, basin) in bands.iter().zip(&basins.of) {
        for (&size, &basin) in band.sizes.iter().zip(basin) {
            sizes[basin as usize] += size;
        }
    }
    let pits = bands.iter().flat_map(|b| b.ends.iter().copied());
    let pits = pits.filter(|&e| e & EXIT == 0).collect();
    let list = |bands: &mut [Band], basins: &[Vec<u32>]| {
        let mut list = Vec::new();
        for (band, basin) in bands.iter_mut().zip(basins) {
            let mut lips = std::mem::take(&mut band.lips);
            lips.retain_mut(|(_, x, y)| {
                (*x, *y) = (basin[*x as usize], basin[*y as usize]);
                x != y
            });
            list.reserve_exact(lips.len());
            list.extend_from_slice(&lips);
        }
        list
    };
    let (top, bottom) = bands.split_at_mut(half);
    let (mut top, mut bottom) = (
        list(top, &basins.of[..half]),
        list(bottom, &basins.of[half..]),
    );
    crate::threads::both(
        || top.sort_unstable_by_key(|l| l.0),
        || bottom.sort_unstable_by_key(|l| l.0),
    );
    (pits, [top, bottom], sizes)
}

/// The field's basin of each end of each band.
struct Basins {
    /// Per band, per end, its basin.
    of: Vec<Vec<u32>>,
    /// The field's basins: the pits and the outlets.
    count: usize,
}

/// An exit whose basin is not yet known.
const UNKNOWN: u32 = u32::MAX;

impl Basins {
    /// Numbers the bands' pits in place order and follows every exit.
    fn new(bands: &[Band], n: usize) -> Self {
        let mut count = 1;
        let mut of = Vec::with_capacity(bands.len());
        for band in bands {
            let mut basins = Vec::with_capacity(band.ends.len() + 1);
            basins.push(OUTLET);
            for &end in &band.ends {
                basins.push(if end & EXIT != 0 { UNKNOWN } else { count });
                count += u32::from(end & EXIT == 0);
            }
            of.push(basins);
        }
        let mut basins = Basins {
            of,
            count: count as usize,
        };
        for (b, band) in bands.iter().enumerate() {
            for k in 0..band.ends.len() {
                basins.follow(bands, b, k + 1, n);
            }
        }
        basins
    }

    /// Follows end `end` of band `b` (if an exit) from band to band to its
    /// basin. A way runs only downhill, so it ends; the exits passed on it
    /// learn their basin too.
    fn follow(&mut self, bands: &[Band], b: usize, end: usize, n: usize) {
        let (mut b, mut end) = (b, end);
        let mut passed = Vec::new();
        let basin = loop {
            let basin = self.of[b][end];
            if basin != UNKNOWN {
                break basin;
            }
            passed.push((b, end));
            let p = (bands[b].ends[end - 1] & !EXIT) as usize;
            b = bands.partition_point(|band| band.rows.start <= p / n) - 1;
            end = bands[b].end_at(p, n) as usize;
        };
        for (b, end) in passed {
            self.of[b][end] = basin;
        }
    }
}
