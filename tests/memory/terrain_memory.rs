//! Peak memory of a 4097x4097 generation: the field itself plus at most 10%
//! (no second full-size buffer: the Brownian generator transforms in place),
//! measured by a counting allocator.

use mountains::settings::Detail;
use mountains::settings::{Generator, Settings};
use mountains::terrain::{Lakes, generate_with_threads};

use crate::common::counting;

#[test]
fn a_4097_field_needs_at_most_a_tenth_more_than_itself() {
    let _alone = counting::alone();
    let field_bytes = 4097 * 4097 * std::mem::size_of::<f32>();
    let all = [
        Generator::Square,
        Generator::Diamond,
        Generator::Triangle,
        Generator::Brownian,
    ];
    for generator in all {
        let s = Settings {
            generator,
            detail: Detail::Level(12),
            contour: 1.5,
            sea_level: 0.1,
            ..Settings::default()
        };
        let before = counting::reset_peak();
        let field = generate_with_threads(&s, 3, 2);
        let extra = counting::peak() - before;
        assert_eq!(field.size(), 4097);
        assert!(extra >= field_bytes, "the count missed the field itself");
        assert!(
            extra <= field_bytes + field_bytes / 10,
            "{generator:?}: peak {extra} bytes for a {field_bytes}-byte field"
        );
    }
}

/// Finding the lakes of a 2049 field (a 4K slide's, made during the hold
/// beside the frame on screen) takes at most a third of the field's own
/// memory: no number a point, only each band of rows' ways and the lips of
/// its lowest spanning forest. A basin number a point took 16.8 MB alone.
#[test]
fn the_lakes_of_a_2049_field_need_at_most_a_third_of_it() {
    let _alone = counting::alone();
    let field_bytes = 2049 * 2049 * std::mem::size_of::<f32>();
    // Seeds 1 and 5: alpine worlds, the most lakes of seeds 1-12.
    for seed in [1, 5] {
        let s = Settings {
            detail: Detail::Level(11),
            ..Settings::default()
        };
        let field = generate_with_threads(&s, seed, 2);
        let before = counting::reset_peak();
        let lakes = Lakes::of(field.heights(), field.size());
        let extra = counting::peak() - before;
        assert!(lakes.count() > 0, "seed {seed}: no lakes to find");
        assert!(
            extra <= field_bytes / 3,
            "seed {seed}: finding the lakes took {extra} bytes, a field is {field_bytes}"
        );
        eprintln!("seed {seed}: {} lakes in {extra} bytes", lakes.count());
    }
}
