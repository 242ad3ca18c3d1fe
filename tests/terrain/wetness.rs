//! Where water runs: a valley's floor drains the slopes on either side
//! and is wet, its ridges drain only themselves and are dry.

use mountains::terrain::{Heightfield, Wetness};

/// A valley running from the back down to the sea at the front: its
/// floor at column `n / 2`, its sides rising to ridges at both edges.
fn valley(n: usize) -> Heightfield {
    let mid = (n / 2) as f32;
    let heights = (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f32, (k / n) as f32);
            5.0 + 0.6 * (x - mid).abs() + 0.05 * (n as f32 - y)
        })
        .collect();
    Heightfield::from_heights(n, 250.0, heights).expect("a field")
}

#[test]
fn water_gathers_on_a_valley_floor_and_leaves_the_ridges_dry() {
    for n in [65, 129, 513] {
        let field = valley(n);
        let wet = Wetness::of(&field);
        let (mid, low) = (n / 2, n * 3 / 4);
        let floor = wet.at(mid, low);
        let ridge = wet.at(0, low).max(wet.at(n - 1, low));
        let slope = wet.at(n / 16, low);
        assert!(floor > 0.9, "{n}: the floor only {floor}");
        assert!(ridge < 0.1, "{n}: the ridges {ridge}");
        assert!(slope > ridge && slope < floor, "{n}: the slope {slope}");
        // Down the valley the floor drains more and more.
        assert!(wet.at(mid, n / 8) <= floor, "{n}");
    }
}
