//! No setting, however wild, panics a generator or leaves a non-finite height.

use mountains::settings::Detail;
use mountains::settings::{Generator, Profile, Settings};
use mountains::terrain::generate;
use proptest::prelude::*;

fn any_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        any::<f32>(),
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(0.0),
        -10.0f32..10.0,
    ]
}

fn any_generator() -> impl Strategy<Value = Generator> {
    prop_oneof![
        Just(Generator::Square),
        Just(Generator::Diamond),
        Just(Generator::Triangle)
    ]
}

fn any_profile() -> impl Strategy<Value = Profile> {
    prop_oneof![
        Just(Profile::Slope),
        Just(Profile::Peak),
        Just(Profile::Bay),
        Just(Profile::Massif)
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn any_settings_give_a_finite_field(
        generator in any_generator(),
        profile in any_profile(),
        cragginess in any::<u32>(),
        elevation in any_f32(),
        roughness in any_f32(),
        contour in any_f32(),
        height in any::<u32>(),
        detail in 0u32..=7,
        low_detail in any::<bool>(),
        sea_level in any_f32(),
        seed in any::<u64>(),
    ) {
        let s = Settings {
            generator, profile, cragginess, elevation, roughness, contour, height,
            detail: Detail::Level(detail),
            low_detail,
            sea_level,
            ..crate::common::terrain_setup::temperate()
        };
        let f = generate(&s, seed);
        // 9x9: seed 000's fewest Iterations (3), the smallest grid.
        prop_assert!(f.size() >= 9);
        prop_assert!(f.heights().iter().all(|h| h.is_finite()));
        prop_assert!(f.extent() > 0.0);
    }
}

#[test]
fn an_out_of_range_detail_is_clamped() {
    let small = generate(
        &Settings {
            detail: Detail::Level(0),
            ..crate::common::terrain_setup::temperate()
        },
        1,
    );
    // Seed 000's Iterations menu starts at 3: 9x9.
    assert_eq!(small.size(), 9);
    let huge = generate(
        &Settings {
            detail: Detail::Level(u32::MAX),
            generator: Generator::Square,
            ..crate::common::terrain_setup::temperate()
        },
        1,
    );
    assert_eq!(huge.size(), 4097);
}
