//! Visible facet edges: steps of colour between neighbouring flat-colour
//! facets of the land, judged by the CIE76 colour difference.
//!
//! Definitions (the figures BENCHMARKS.md reports):
//! - a *facet* is a 4-connected run of land pixels of exactly one colour;
//! - a land pixel lies on a *visible facet edge* when one of its four
//!   neighbours is land in another facet, both facets hold at least
//!   [`FACET_MIN_PX`] pixels, and the two colours differ by CIE76
//!   dE > [`JND`] (one just-noticeable difference);
//! - a *visible step* is the same without the facet condition: any land
//!   neighbour more than [`JND`] away (what shading that is not flat, or
//!   noise, would still show).

use super::image::channels;

/// One just-noticeable difference in CIE76 dE.
pub const JND: f32 = 2.3;
/// The smallest facet counted: a flat face, not a pixel of an edge's stair.
pub const FACET_MIN_PX: u32 = 6;

/// CIE L*a*b* (D65) of an sRGB colour with channels 0..=255.
pub fn lab(c: [f32; 3]) -> [f32; 3] {
    let lin = c.map(|v| {
        let v = v / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    });
    let xyz = [
        (0.412_456_4 * lin[0] + 0.357_576_1 * lin[1] + 0.180_437_5 * lin[2]) / 0.950_47,
        0.212_672_9 * lin[0] + 0.715_152_2 * lin[1] + 0.072_175 * lin[2],
        (0.019_333_9 * lin[0] + 0.119_192 * lin[1] + 0.950_304_1 * lin[2]) / 1.088_83,
    ];
    let f = xyz.map(|t| {
        if t > 216.0 / 24389.0 {
            t.cbrt()
        } else {
            (24389.0 / 27.0 * t + 16.0) / 116.0
        }
    });
    [
        116.0 * f[1] - 16.0,
        500.0 * (f[0] - f[1]),
        200.0 * (f[1] - f[2]),
    ]
}

/// CIE76 colour difference: the distance in L*a*b*.
pub fn delta_e(a: [f32; 3], b: [f32; 3]) -> f32 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// What [`measure`] finds on the land of a picture.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Facets {
    /// Land pixels looked at.
    pub land: u64,
    /// Share of land pixels on a visible facet edge.
    pub edge_share: f64,
    /// Share of land pixels with a visible step to a land neighbour.
    pub step_share: f64,
    /// Share of land pixels in facets of at least [`FACET_MIN_PX`] pixels.
    pub flat_share: f64,
    /// Share of neighbouring land pairs (across and down) over [`JND`].
    pub pair_share: f64,
}

/// The facets of packed `pixels` (`width` wide) on the pixels `land` marks.
pub fn measure(pixels: &[u32], land: &[bool], width: usize) -> Facets {
    let labels = facet_labels(pixels, land, width);
    let mut size = vec![0u32; pixels.len()];
    for (i, &l) in labels.iter().enumerate() {
        if land[i] {
            size[l as usize] += 1;
        }
    }
    let labs: Vec<[f32; 3]> = pixels.iter().map(|&p| lab(channels(p))).collect();
    let mut edge = vec![false; pixels.len()];
    let mut step = vec![false; pixels.len()];
    let (mut pairs, mut over) = (0u64, 0u64);
    let height = pixels.len() / width.max(1);
    for y in 0..height {
        for x in 0..width {
            let i = y * width + x;
            if !land[i] {
                continue;
            }
            let right = (x + 1 < width).then_some(i + 1);
            let below = (y + 1 < height).then_some(i + width);
            for j in [right, below].into_iter().flatten() {
                if !land[j] {
                    continue;
                }
                pairs += 1;
                if pixels[i] == pixels[j] || delta_e(labs[i], labs[j]) <= JND {
                    continue;
                }
                over += 1;
                step[i] = true;
                step[j] = true;
                let (a, b) = (labels[i] as usize, labels[j] as usize);
                if a != b && size[a] >= FACET_MIN_PX && size[b] >= FACET_MIN_PX {
                    edge[i] = true;
                    edge[j] = true;
                }
            }
        }
    }
    let land_n = land.iter().filter(|&&l| l).count() as u64;
    let share = |n: usize| n as f64 / land_n.max(1) as f64;
    let flat = (0..pixels.len())
        .filter(|&i| land[i] && size[labels[i] as usize] >= FACET_MIN_PX)
        .count();
    Facets {
        land: land_n,
        edge_share: share(edge.iter().filter(|&&e| e).count()),
        step_share: share(step.iter().filter(|&&s| s).count()),
        flat_share: share(flat),
        pair_share: over as f64 / pairs.max(1) as f64,
    }
}

/// Each land pixel's facet, named by one of its pixels (union-find over
/// equal neighbours, across and down).
fn facet_labels(pixels: &[u32], land: &[bool], width: usize) -> Vec<u32> {
    let mut parent: Vec<u32> = (0..pixels.len() as u32).collect();
    fn root(parent: &mut [u32], mut i: u32) -> u32 {
        while parent[i as usize] != i {
            let up = parent[parent[i as usize] as usize];
            parent[i as usize] = up;
            i = up;
        }
        i
    }
    for i in 0..pixels.len() {
        if !land[i] {
            continue;
        }
        let x = i % width;
        let right = (x + 1 < width).then_some(i + 1);
        let below = (i + width < pixels.len()).then_some(i + width);
        for j in [right, below].into_iter().flatten() {
            if land[j] && pixels[j] == pixels[i] {
                let (a, b) = (root(&mut parent, i as u32), root(&mut parent, j as u32));
                parent[a.max(b) as usize] = a.min(b);
            }
        }
    }
    (0..pixels.len() as u32)
        .map(|i| root(&mut parent, i))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lab_and_delta_e_match_known_values() {
        let white = lab([255.0; 3]);
        assert!((white[0] - 100.0).abs() < 0.01 && white[1].abs() < 0.01 && white[2].abs() < 0.01);
        assert_eq!(lab([0.0; 3]), [0.0, 0.0, 0.0]);
        // sRGB red is L 53.24, a 80.09, b 67.20.
        let red = lab([255.0, 0.0, 0.0]);
        assert!(delta_e(red, [53.24, 80.09, 67.20]) < 0.05, "{red:?}");
        // One level of grey near the middle is under one JND.
        assert!(delta_e(lab([128.0; 3]), lab([129.0; 3])) < JND);
        assert!(delta_e(lab([128.0; 3]), lab([136.0; 3])) > JND);
    }

    #[test]
    fn two_flat_facets_show_their_edge_and_a_gentle_ramp_none() {
        // A 10 x 6 picture: left half grey 100, right half grey 140.
        let (w, h) = (10, 6);
        let grey = |v: u32| v << 16 | v << 8 | v;
        let two: Vec<u32> = (0..w * h)
            .map(|i| grey(if i % w < 5 { 100 } else { 140 }))
            .collect();
        let land = vec![true; w * h];
        let f = measure(&two, &land, w);
        // Columns 4 and 5 lie on the edge: 2 of 10 columns.
        assert!((f.edge_share - 0.2).abs() < 1e-12, "{f:?}");
        assert_eq!(f.step_share, f.edge_share);
        assert_eq!(f.flat_share, 1.0);
        // 6 of the 54 across pairs plus 0 of the 50 down pairs.
        assert!((f.pair_share - 6.0 / 104.0).abs() < 1e-12);
        // A ramp of one level a column: each column is a facet of 6 px, and
        // no edge between them shows.
        let ramp: Vec<u32> = (0..w * h).map(|i| grey(100 + (i % w) as u32)).collect();
        let r = measure(&ramp, &land, w);
        assert_eq!((r.edge_share, r.step_share, r.pair_share), (0.0, 0.0, 0.0));
        // Small facets (single pixels of a checkerboard) are steps, not facet edges.
        let checker: Vec<u32> = (0..w * h)
            .map(|i| grey(if (i % w + i / w) % 2 == 0 { 100 } else { 140 }))
            .collect();
        let c = measure(&checker, &land, w);
        assert_eq!((c.edge_share, c.step_share, c.flat_share), (0.0, 1.0, 0.0));
        // Pixels that are not land are not looked at.
        let none = measure(&two, &vec![false; w * h], w);
        assert_eq!(none.land, 0);
        assert_eq!(none.edge_share, 0.0);
    }
}
