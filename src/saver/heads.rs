//! The monitors ("heads") the full-screen saver covers, whatever told us
//! about them (RandR monitors, Xinerama, winit), cleaned into one list.

/// One monitor: a rectangle of the desktop in physical pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Head {
    /// Left edge on the desktop.
    pub x: i32,
    /// Top edge on the desktop.
    pub y: i32,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The monitor the system calls primary.
    pub primary: bool,
}

impl Head {
    fn right(&self) -> i64 {
        i64::from(self.x) + i64::from(self.width)
    }

    fn bottom(&self) -> i64 {
        i64::from(self.y) + i64::from(self.height)
    }

    /// True when `self` lies entirely inside `other` (equal counts).
    fn inside(&self, other: &Head) -> bool {
        self.x >= other.x
            && self.y >= other.y
            && self.right() <= other.right()
            && self.bottom() <= other.bottom()
    }

    fn same_place(&self, other: &Head) -> bool {
        (self.x, self.y, self.width, self.height) == (other.x, other.y, other.width, other.height)
    }
}

/// One window per visible area: empty heads go; a head inside another (a
/// mirrored or cloned display, a smaller display showing part of a larger
/// one) goes, since the larger window already covers it. The primary head
/// comes first (it gets the input grab and, with `monitors = "primary"`, the
/// only mountain), the rest left to right, then top to bottom.
pub fn clean(heads: &[Head]) -> Vec<Head> {
    let candidates: Vec<Head> = heads
        .iter()
        .copied()
        .filter(|h| h.width > 0 && h.height > 0)
        .collect();
    // Of two heads at the same place, a primary one stays, else the first.
    let loses_tie = |i: usize, j: usize| {
        let (head, other) = (&candidates[i], &candidates[j]);
        if head.primary == other.primary {
            j < i
        } else {
            other.primary
        }
    };
    let mut kept: Vec<Head> = Vec::new();
    for (i, head) in candidates.iter().enumerate() {
        let covered = candidates.iter().enumerate().any(|(j, other)| {
            i != j && head.inside(other) && (!head.same_place(other) || loses_tie(i, j))
        });
        if !covered {
            kept.push(*head);
        }
    }
    if !kept.is_empty() && !kept.iter().any(|h| h.primary) {
        let first = (0..kept.len()).min_by_key(|&i| (kept[i].x, kept[i].y));
        kept[first.unwrap_or(0)].primary = true;
    }
    kept.sort_by_key(|h| (!h.primary, h.x, h.y));
    kept
}

/// Of two descriptions of the same desktop, the one that tells more heads
/// apart: RandR can report a single screen where Xinerama (or a driver's
/// own multi-head mode) reports several, and the other way round. On a tie
/// the first wins.
pub fn choose(first: &[Head], second: &[Head]) -> Vec<Head> {
    let (a, b) = (clean(first), clean(second));
    if b.len() > a.len() { b } else { a }
}

/// What to do with the open windows when the heads change.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Change {
    /// Move and resize window `index` to cover `head`.
    Fit(usize, Head),
    /// Close window `index` (its monitor went).
    Close(usize),
    /// Open a window on a new monitor.
    Open(Head),
}

/// Turns the windows covering `old` into windows covering `new`, moving as
/// few as it can: window 0 (it holds the input grab) always takes `new[0]`,
/// the primary; another window whose monitor is still in the same place
/// stays as it is (its mountain goes on); the rest move to the remaining
/// heads; windows left over close (from the last, so indices stay valid)
/// and heads left over get new windows. An empty `new` (a moment between
/// two configurations) changes nothing.
pub fn plan(old: &[Head], new: &[Head]) -> Vec<Change> {
    let (Some(first), Some(_)) = (new.first(), old.first()) else {
        return new.iter().map(|h| Change::Open(*h)).collect();
    };
    let mut taken = vec![false; old.len()];
    taken[0] = true;
    let mut changes = Vec::new();
    if !old[0].same_place(first) {
        changes.push(Change::Fit(0, *first));
    }
    let mut unplaced = Vec::new();
    for head in &new[1..] {
        let stays = (1..old.len()).find(|&j| !taken[j] && old[j].same_place(head));
        match stays {
            Some(j) => taken[j] = true,
            None => unplaced.push(*head),
        }
    }
    for head in unplaced {
        match (1..old.len()).find(|&j| !taken[j]) {
            Some(j) => {
                taken[j] = true;
                changes.push(Change::Fit(j, head));
            }
            None => changes.push(Change::Open(head)),
        }
    }
    let closes = (1..old.len())
        .rev()
        .filter(|&j| !taken[j])
        .map(Change::Close);
    let opens_at = changes.iter().position(|c| matches!(c, Change::Open(_)));
    let at = opens_at.unwrap_or(changes.len());
    changes.splice(at..at, closes);
    changes
}

#[cfg(test)]
mod tests {
    use super::*;

    fn head(x: i32, y: i32, width: u32, height: u32) -> Head {
        Head {
            x,
            y,
            width,
            height,
            primary: false,
        }
    }

    fn primary(h: Head) -> Head {
        Head { primary: true, ..h }
    }

    #[test]
    fn side_by_side_heads_all_stay_left_to_right_with_a_primary() {
        let heads = [head(1920, 0, 1280, 1024), head(0, 0, 1920, 1080)];
        assert_eq!(
            clean(&heads),
            vec![primary(head(0, 0, 1920, 1080)), head(1920, 0, 1280, 1024)]
        );
    }

    #[test]
    fn the_primary_head_comes_first_wherever_it_is() {
        let heads = [head(0, 0, 800, 600), primary(head(800, 0, 800, 600))];
        assert_eq!(
            clean(&heads),
            vec![primary(head(800, 0, 800, 600)), head(0, 0, 800, 600)]
        );
    }

    #[test]
    fn mirrored_heads_get_one_window() {
        let heads = [head(0, 0, 1920, 1080), primary(head(0, 0, 1920, 1080))];
        assert_eq!(clean(&heads), vec![primary(head(0, 0, 1920, 1080))]);
        let twins = [head(0, 0, 1920, 1080), head(0, 0, 1920, 1080)];
        assert_eq!(clean(&twins), vec![primary(head(0, 0, 1920, 1080))]);
        let both = [
            primary(head(0, 0, 1920, 1080)),
            primary(head(0, 0, 1920, 1080)),
        ];
        assert_eq!(clean(&both), vec![primary(head(0, 0, 1920, 1080))]);
    }

    #[test]
    fn a_head_inside_another_goes_even_if_primary() {
        let heads = [primary(head(0, 0, 1024, 768)), head(0, 0, 1920, 1080)];
        assert_eq!(clean(&heads), vec![primary(head(0, 0, 1920, 1080))]);
    }

    #[test]
    fn empty_heads_go() {
        let heads = [head(0, 0, 0, 1080), head(0, 0, 640, 0), head(5, 5, 10, 10)];
        assert_eq!(clean(&heads), vec![primary(head(5, 5, 10, 10))]);
        assert!(clean(&[]).is_empty());
    }

    #[test]
    fn overlapping_but_not_enclosed_heads_both_stay() {
        let heads = [head(0, 0, 1000, 800), head(900, 0, 1000, 800)];
        assert_eq!(clean(&heads).len(), 2);
    }

    #[test]
    fn choose_takes_the_description_with_more_heads() {
        let one = [head(0, 0, 1600, 600)];
        let two = [head(0, 0, 800, 600), head(800, 0, 800, 600)];
        assert_eq!(choose(&one, &two).len(), 2);
        assert_eq!(choose(&two, &one).len(), 2);
        assert_eq!(choose(&one, &[]), vec![primary(head(0, 0, 1600, 600))]);
        let same = [head(0, 0, 1024, 768)];
        assert_eq!(choose(&one, &same), vec![primary(head(0, 0, 1600, 600))]);
    }

    #[test]
    fn plan_fits_moved_heads_closes_gone_ones_and_opens_new_ones() {
        let (a, b, c) = (
            head(0, 0, 800, 600),
            head(800, 0, 800, 600),
            head(1600, 0, 800, 600),
        );
        let smaller = head(0, 0, 640, 480);
        assert_eq!(plan(&[a, b], &[a, b]), vec![]);
        assert_eq!(plan(&[a], &[smaller]), vec![Change::Fit(0, smaller)]);
        assert_eq!(
            plan(&[a, b, c], &[smaller]),
            vec![Change::Fit(0, smaller), Change::Close(2), Change::Close(1)]
        );
        assert_eq!(
            plan(&[a], &[a, b, c]),
            vec![Change::Open(b), Change::Open(c)]
        );
        assert_eq!(plan(&[a, b], &[]), vec![]);
    }

    #[test]
    fn plan_leaves_windows_of_unchanged_monitors_alone() {
        let (a, b, c) = (
            head(0, 0, 800, 600),
            head(800, 0, 800, 600),
            head(1600, 0, 800, 600),
        );
        // The middle monitor goes: only its window closes.
        assert_eq!(plan(&[a, b, c], &[a, c]), vec![Change::Close(1)]);
        // A monitor comes back in the middle: a new window, the others stay.
        assert_eq!(plan(&[a, c], &[a, b, c]), vec![Change::Open(b)]);
        // The primary moves to the right monitor: window 0 (the grab) follows
        // it, the window that covered it moves to the left one.
        let (pa, pc) = (primary(a), primary(c));
        assert_eq!(
            plan(&[pa, c], &[pc, a]),
            vec![Change::Fit(0, pc), Change::Fit(1, a)]
        );
        // Windows left over close before new ones open.
        let d = head(0, 600, 800, 600);
        assert_eq!(
            plan(&[a, b, c], &[a, d]),
            vec![Change::Fit(1, d), Change::Close(2)]
        );
        assert_eq!(plan(&[], &[a]), vec![Change::Open(a)]);
    }
}
