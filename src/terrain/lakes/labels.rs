//! Which region a flooded point belongs to, without a number per point
//! (a 4097 grid's heights fill 64 MB; the flood may add a tenth).

/// An empty slot.
const EMPTY: u32 = u32::MAX;

/// The region of each flooded point, found from a few remembered ones: a
/// point with a lower flooded neighbour belongs to that neighbour's region
/// (the flood joins every region a point touches), so only the points
/// without one (a pit, found among the pits, or a point of a flat floor)
/// are written down for good.
/// The others are found by walking down to one of those, with the last
/// answers kept in a small lossy cache so that the walk is short.
pub(super) struct Labels {
    /// Points without a lower flooded neighbour, and their regions
    /// (open addressing, at most half full).
    roots: Vec<(u32, u32)>,
    filled: usize,
    /// Recent answers, one per slot.
    recent: Vec<(u32, u32)>,
}

/// Bits of the cache's slot index.
const RECENT_BITS: u32 = 14;

impl Labels {
    /// No point labelled yet.
    pub(super) fn new() -> Self {
        Labels {
            roots: vec![(EMPTY, 0); 1024],
            filled: 0,
            recent: vec![(EMPTY, 0); 1 << RECENT_BITS],
        }
    }

    /// Point `i` joins `region`; written down for good if `root` (no lower
    /// neighbour was flooded before it, and it is no pit).
    pub(super) fn set(&mut self, i: u32, region: u32, root: bool) {
        self.recent[recent_slot(i)] = (i, region);
        if root {
            self.insert(i, region);
        }
    }

    /// The region of flooded point `i` if known without a walk.
    #[inline]
    pub(super) fn known(&self, i: u32) -> Option<u32> {
        let (at, region) = self.recent[recent_slot(i)];
        (at == i).then_some(region)
    }

    /// The region of a point written down as a root.
    pub(super) fn root(&self, i: u32) -> u32 {
        let mask = self.roots.len() - 1;
        let mut s = slot(i, mask);
        loop {
            let (at, region) = self.roots[s];
            assert!(at != EMPTY, "a flooded point without a region");
            if at == i {
                return region;
            }
            s = (s + 1) & mask;
        }
    }

    /// Remembers `region` as the answer for point `i`.
    #[inline]
    pub(super) fn remember(&mut self, i: u32, region: u32) {
        self.recent[recent_slot(i)] = (i, region);
    }

    fn insert(&mut self, i: u32, region: u32) {
        if (self.filled + 1) * 2 > self.roots.len() {
            let grown = vec![(EMPTY, 0); self.roots.len() * 2];
            let old = std::mem::replace(&mut self.roots, grown);
            self.filled = 0;
            for (at, region) in old.into_iter().filter(|e| e.0 != EMPTY) {
                self.insert(at, region);
            }
        }
        let mask = self.roots.len() - 1;
        let mut s = slot(i, mask);
        while self.roots[s].0 != EMPTY {
            s = (s + 1) & mask;
        }
        self.roots[s] = (i, region);
        self.filled += 1;
    }
}

/// The map's first slot for point `i` (Fibonacci hashing).
#[inline]
fn slot(i: u32, mask: usize) -> usize {
    (u64::from(i).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 32) as usize & mask
}

/// The cache's slot for point `i`.
#[inline]
fn recent_slot(i: u32) -> usize {
    (i.wrapping_mul(0x9E37_79B9) >> (32 - RECENT_BITS)) as usize
}
