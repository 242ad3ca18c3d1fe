//! Peak memory of a 4097x4097 generation: the field itself plus at most 10%
//! (no second full-size buffer: the Brownian generator transforms in place),
//! measured by a counting allocator.

use mountains::settings::Detail;
use mountains::settings::{Generator, Settings};
use mountains::terrain::generate_with_threads;

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
