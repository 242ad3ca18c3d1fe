//! Cast shadows: walls, flat fields, agreement with ray marching, all sizes.

use glam::Vec3;
use mountains::render::shadow::{ShadowMap, cast};
use mountains::terrain::Heightfield;

/// Lights from each side, 30 degrees up, a little off the axes so both
/// sweep directions and both interpolation signs are used.
fn lights() -> Vec<Vec3> {
    let mut v = Vec::new();
    for (hx, hy) in [
        (-1.0, 0.3),
        (1.0, -0.4),
        (0.35, 1.0),
        (-0.45, -1.0),
        (-0.7, 0.7),
        (1.0, 0.0),
        (0.0, -1.0),
    ] {
        let flat = Vec3::new(hx, hy, 0.0).normalize() * 0.866;
        v.push(Vec3::new(flat.x, flat.y, 0.5));
    }
    v
}

/// Grid direction (column, row steps) of the light: rows grow to the front.
fn grid_dir(light: Vec3) -> (f32, f32) {
    let n = (light.x.hypot(light.y)).max(1e-9);
    (light.x / n, -light.y / n)
}

#[test]
fn flat_field_is_all_lit() {
    let field = Heightfield::flat(6, 64.0);
    for light in lights() {
        let map = cast(&field, light);
        for y in 0..65 {
            for x in 0..65 {
                assert_eq!(map.lit(x, y), 1.0, "{light} at {x},{y}");
            }
        }
    }
}

#[test]
fn a_wall_shades_the_ground_behind_it_not_in_front() {
    for light in lights() {
        let (dx, dy) = grid_dir(light);
        // A wall 8 high across the light's main direction, through the centre.
        let mut field = Heightfield::flat(6, 64.0);
        for i in 0..65 {
            if dy.abs() >= dx.abs() {
                field.set(i, 32, 8.0);
            } else {
                field.set(32, i, 8.0);
            }
        }
        let map = cast(&field, light);
        // Shadow length on the ground: 8 / tan(30 degrees) = 13.9 cells.
        let at = |t: f32| {
            let (x, y) = (32.0 - dx * t, 32.0 - dy * t);
            map.lit(x.round() as usize, y.round() as usize)
        };
        for t in [3.0, 6.0, 9.0, 11.0] {
            assert!(
                at(t) < 0.05,
                "{light}: {t} cells behind the wall lit {}",
                at(t)
            );
        }
        for t in [17.0, 22.0, 28.0] {
            assert_eq!(at(t), 1.0, "{light}: {t} cells behind, past the shadow");
        }
        for t in [-3.0, -10.0, -25.0] {
            assert_eq!(at(t), 1.0, "{light}: {} cells in front of the wall", -t);
        }
    }
}

#[test]
fn shadow_edges_are_soft_but_narrow() {
    let mut field = Heightfield::flat(7, 128.0);
    for x in 0..129 {
        field.set(x, 40, 20.0);
    }
    let map = cast(&field, Vec3::new(0.0, 0.866, 0.5));
    let column: Vec<f32> = (41..129).map(|y| map.lit(64, y)).collect();
    let partial = column.iter().filter(|&&l| l > 0.0 && l < 1.0).count();
    assert!(
        (1..=4).contains(&partial),
        "penumbra of {partial} points: {column:?}"
    );
    for w in column.windows(2) {
        assert!(
            w[1] >= w[0],
            "light must grow away from the wall: {column:?}"
        );
    }
}

/// A bumpy, value-stable test field.
fn bumpy(exponent: u32) -> Heightfield {
    let n = (1usize << exponent) + 1;
    let mut f = Heightfield::flat(exponent, n as f32 - 1.0);
    let k = 64.0 / (n - 1) as f32;
    for y in 0..n {
        for x in 0..n {
            let (u, v) = (x as f32 * k, y as f32 * k);
            let h = 6.0 * (u * 0.31).sin() * (v * 0.23).cos() + 3.0 * (u * 0.9 + v * 0.7).sin();
            f.set(x, y, h / k);
        }
    }
    f
}

/// Brute force: march from the point towards the light, in half cells,
/// and see whether the terrain rises above the ray.
fn marched(field: &Heightfield, light: Vec3, x: usize, y: usize) -> bool {
    let n = field.size() as f32;
    let (dx, dy) = grid_dir(light);
    let spacing = field.extent() / (n - 1.0);
    let tan = light.z / light.x.hypot(light.y);
    let bilinear = |px: f32, py: f32| {
        let (x0, y0) = (px.floor() as usize, py.floor() as usize);
        let (x1, y1) = (
            (x0 + 1).min(field.size() - 1),
            (y0 + 1).min(field.size() - 1),
        );
        let (fx, fy) = (px - x0 as f32, py - y0 as f32);
        let top = field.get(x0, y0) * (1.0 - fx) + field.get(x1, y0) * fx;
        let bottom = field.get(x0, y1) * (1.0 - fx) + field.get(x1, y1) * fx;
        top * (1.0 - fy) + bottom * fy
    };
    let h = field.get(x, y);
    let mut t = 0.5;
    loop {
        let (px, py) = (x as f32 + dx * t, y as f32 + dy * t);
        if px < 0.0 || py < 0.0 || px > n - 1.0 || py > n - 1.0 {
            return true;
        }
        if bilinear(px, py) > h + t * spacing * tan {
            return false;
        }
        t += 0.5;
    }
}

#[test]
fn agrees_with_ray_marching() {
    let field = bumpy(6);
    for light in lights() {
        let map = cast(&field, light);
        let (mut agree, mut shaded) = (0, 0);
        for y in 0..65 {
            for x in 0..65 {
                let lit = marched(&field, light, x, y);
                agree += (lit == (map.lit(x, y) == 1.0)) as usize;
                shaded += !lit as usize;
            }
        }
        assert!(
            shaded > 200,
            "{light}: the test field must cast shadows ({shaded})"
        );
        // The sweep interpolates the horizon between grid points, which
        // blurs it sideways a little; the marcher reads the surface
        // bilinearly. They differ along shadow edges only.
        assert!(
            agree * 100 >= 65 * 65 * 90,
            "{light}: {agree} of 4225 agree"
        );
        // A sweep from the wrong side would not come close.
        let wrong = cast(&field, Vec3::new(-light.x, -light.y, light.z));
        let mut wrong_agree = 0;
        for y in 0..65 {
            for x in 0..65 {
                let lit = marched(&field, light, x, y);
                wrong_agree += (lit == (wrong.lit(x, y) == 1.0)) as usize;
            }
        }
        assert!(
            wrong_agree + 400 < agree,
            "{light}: {wrong_agree} vs {agree}"
        );
    }
}

fn check_range(map: &ShadowMap, n: usize) {
    assert_eq!(map.size(), n);
    for (x, y) in [(0, 0), (n - 1, n - 1), (n / 2, n / 3), (n - 1, 0)] {
        let l = map.lit(x, y);
        assert!((0.0..=1.0).contains(&l), "{l} at {x},{y}");
    }
}

#[test]
fn every_size_and_odd_lights_work() {
    let odd = [
        Vec3::Z,
        Vec3::NEG_Z,
        Vec3::X,
        Vec3::ZERO,
        Vec3::splat(f32::NAN),
        Vec3::new(1.0, 1.0, 1e-9),
        Vec3::new(1.0, 1.0, 1e9),
        Vec3::new(f32::INFINITY, 0.0, 1.0),
    ];
    for exponent in 4..=12 {
        let field = bumpy(exponent);
        let n = field.size();
        let lights = if exponent <= 8 {
            [lights(), odd.to_vec()].concat()
        } else {
            lights()[..2].to_vec()
        };
        for light in lights {
            check_range(&cast(&field, light), n);
        }
    }
}

#[test]
fn overhead_light_casts_nothing_and_a_set_sun_lights_nothing() {
    let field = bumpy(5);
    let overhead = cast(&field, Vec3::Z);
    let set = cast(&field, Vec3::new(1.0, 0.0, -0.1));
    for y in 0..33 {
        for x in 0..33 {
            assert_eq!(overhead.lit(x, y), 1.0);
            assert_eq!(set.lit(x, y), 0.0);
        }
    }
}

#[test]
fn bad_heights_do_not_panic() {
    let mut field = bumpy(5);
    field.set(3, 3, f32::NAN);
    field.set(10, 3, f32::INFINITY);
    field.set(20, 20, f32::NEG_INFINITY);
    for light in lights() {
        check_range(&cast(&field, light), 33);
    }
}
