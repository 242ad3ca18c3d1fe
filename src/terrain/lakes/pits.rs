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
/// Each row is tested whole, branch-free (the compiler keeps it in vector
/// registers), into one flag a point, and only then are the few pits read
/// out.
fn pits_in(h: &[f32], n: usize, rows: std::ops::Range<usize>) -> (Vec<u32>, f32, f32) {
    let mut found = Vec::new();
    let (mut lo, mut hi) = ([f32::INFINITY; LANES], [0.0f32; LANES]);
    let mut flags = vec![0u8; n];
    for y in rows {
        let row = &h[y * n..(y + 1) * n];
        extremes(row, &mut lo, &mut hi);
        if y == 0 || y + 1 == n {
            continue;
        }
        let (above, below) = (&h[(y - 1) * n..y * n], &h[(y + 1) * n..(y + 2) * n]);
        flag_pits(above, row, below, &mut flags);
        for (x0, chunk) in flags.chunks(8).enumerate() {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            let mut bits = u64::from_le_bytes(word);
            while bits != 0 {
                let x = x0 * 8 + bits.trailing_zeros() as usize / 8;
                found.push((y * n + x) as u32);
                bits &= bits - 1;
            }
        }
    }
    let lo = lo.into_iter().fold(f32::INFINITY, f32::min);
    let hi = hi.into_iter().fold(0.0f32, f32::max);
    (found, lo, hi)
}

/// Lanes of the running extremes (independent, so they vectorise).
const LANES: usize = 8;

/// Lowers `lo` and raises `hi` lane by lane to the land of `row` (above
/// sea level and finite; NaN is neither).
fn extremes(row: &[f32], lo: &mut [f32; LANES], hi: &mut [f32; LANES]) {
    let mut chunks = row.chunks_exact(LANES);
    for chunk in &mut chunks {
        for ((&v, l), h) in chunk.iter().zip(lo.iter_mut()).zip(hi.iter_mut()) {
            widen(v, l, h);
        }
    }
    for (&v, (l, h)) in chunks
        .remainder()
        .iter()
        .zip(lo.iter_mut().zip(hi.iter_mut()))
    {
        widen(v, l, h);
    }
}

/// One lane of [`extremes`], with selects only (no branch to vectorise
/// around).
#[inline(always)]
fn widen(v: f32, lo: &mut f32, hi: &mut f32) {
    let land = (v > 0.0) & (v < f32::INFINITY);
    let low = if land { v } else { f32::INFINITY };
    let high = if land { v } else { 0.0 };
    *lo = if low < *lo { low } else { *lo };
    *hi = if high > *hi { high } else { *hi };
}

/// Sets `flags[x]` to 1 where point `x` of `row` is a pit (land, and none
/// of its eight neighbours in `above`, `row` and `below` lower or without
/// data: a NaN neighbour fails every comparison), else 0. The border
/// columns are no pits.
fn flag_pits(above: &[f32], row: &[f32], below: &[f32], flags: &mut [u8]) {
    let n = row.len();
    flags[0] = 0;
    flags[n - 1] = 0;
    let inner = flags[1..n - 1].iter_mut().enumerate();
    for (x, flag) in inner {
        let v = row[x + 1];
        let pit = (v > 0.0)
            & (above[x] >= v)
            & (above[x + 1] >= v)
            & (above[x + 2] >= v)
            & (row[x] >= v)
            & (row[x + 2] >= v)
            & (below[x] >= v)
            & (below[x + 1] >= v)
            & (below[x + 2] >= v);
        *flag = u8::from(pit);
    }
}
