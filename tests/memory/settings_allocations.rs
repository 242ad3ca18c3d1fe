//! The preferences' key table, measured by the counting allocator.

use crate::common::counting::allocations_of;
use mountains::settings::keys;

/// An unknown key costs only its message: the nearest-name search behind
/// "did you mean" allocates nothing, however long the name typed (it made
/// a vector for every row of every comparison, and checking a file of
/// 100,000 unknown keys took 6 s). The message stays right.
#[test]
fn an_unknown_key_costs_only_its_message() {
    let long = "x".repeat(10_000);
    for (typed, offered) in [
        ("colour", Some("color")),
        ("sea-level", Some("sea_level")),
        ("no_such_key_at_all", None),
        (long.as_str(), None),
    ] {
        let (found, allocations) = allocations_of(|| keys::known(typed));
        let Err(message) = found else {
            panic!("{typed:.20} is no key")
        };
        let hint = offered.map(|k| format!("did you mean `{k}`?"));
        assert_eq!(
            message.contains("did you mean"),
            hint.is_some(),
            "{message}"
        );
        if let Some(hint) = hint {
            assert!(message.contains(&hint), "{message}");
        }
        assert!(
            allocations <= 4,
            "{} characters: {allocations} allocations for {message:.80}",
            typed.len()
        );
    }
}
