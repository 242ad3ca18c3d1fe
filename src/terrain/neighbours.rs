//! The eight neighbours of a grid point, in one order for every pass that
//! walks them (the lakes' steps, the rain's sharing): a file of its own, so
//! the passes below the heightfield need not import the field that holds
//! their results.

/// The eight neighbours of a grid point as (column, row) steps, in place
/// order: the order the lakes' steps and the rain's sharing read them in.
pub(crate) const NEIGHBOURS: [(isize, isize); 8] = [
    (-1, -1),
    (0, -1),
    (1, -1),
    (-1, 0),
    (1, 0),
    (-1, 1),
    (0, 1),
    (1, 1),
];
