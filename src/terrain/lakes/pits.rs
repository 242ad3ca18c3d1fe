//! The pits of a field: where a basin's water starts to rise.

use super::open::entry;

/// The pits of `heights` (`n` a side), lowest first (ties by index), and
/// the lowest and highest land: every point off the border with all eight
/// neighbours land and none of them lower. Every basin holds one (a flat
/// floor may hold several; they join as they fill). The two halves of the
/// rows are searched at once.
pub(super) fn pits(heights: &[f32], n: usize) -> (Vec<u32>, f32, f32) {
    let half = n / 2;
    let ((mut found, lo, hi), (theirs, lo2, hi2)) = crate::threads::both(
        || pits_in(heights, n, 0..half),
        || pits_in(heights, n, half..n),
    );
    found.extend(theirs);
    found.shrink_to_fit();
    found.sort_unstable_by_key(|&i| entry(heights, i));
    (found, lo.min(lo2), hi.max(hi2))
}

/// [`pits`] in rows `rows`, unsorted, with the land's extremes there.
fn pits_in(h: &[f32], n: usize, rows: std::ops::Range<usize>) -> (Vec<u32>, f32, f32) {
    let mut found = Vec::new();
    let (mut lo, mut hi) = (f32::INFINITY, 0.0f32);
    // Per column, the lower of the rows above and below.
    let mut column = vec![0.0f32; n];
    for y in rows {
        let row = &h[y * n..(y + 1) * n];
        for &v in row.iter().filter(|v| **v > 0.0 && v.is_finite()) {
            (lo, hi) = (lo.min(v), hi.max(v));
        }
        if y == 0 || y + 1 == n {
            continue;
        }
        let (above, below) = (&h[(y - 1) * n..y * n], &h[(y + 1) * n..(y + 2) * n]);
        for ((c, &a), &b) in column.iter_mut().zip(above).zip(below) {
            *c = sunk(a).min(sunk(b));
        }
        for x0 in (1..n - 1).step_by(64) {
            let mut mask = 0u64;
            for x in x0..(x0 + 64).min(n - 1) {
                let v = row[x];
                let around = column[x - 1]
                    .min(column[x])
                    .min(column[x + 1])
                    .min(sunk(row[x - 1]))
                    .min(sunk(row[x + 1]));
                mask |= u64::from(v > 0.0 && around >= v) << (x - x0);
            }
            while mask != 0 {
                found.push((y * n + x0 + mask.trailing_zeros() as usize) as u32);
                mask &= mask - 1;
            }
        }
    }
    (found, lo, hi)
}

/// A height for the search: NaN (no data, like the sea an outlet) below
/// everything, so a point beside it is no pit.
#[inline]
fn sunk(h: f32) -> f32 {
    if h.is_nan() { f32::NEG_INFINITY } else { h }
}
