//! Rows of the key table by their kind. Code that needs a key's range or
//! its row (the generator's clamps, the palette, the keyboard's actions)
//! refers to it through one of these constants, each its row's constant
//! (`keys::HEIGHT`) seen as a whole number, a number or any key; a test
//! checks each one's kind against its row.

use super::keys::{self, Key, Kind, Value};

/// A key of any kind.
#[derive(Clone, Copy, Debug)]
pub struct AnyKey(&'static Key);

/// A whole-number key.
#[derive(Clone, Copy, Debug)]
pub struct IntKey(&'static Key);

/// A number key.
#[derive(Clone, Copy, Debug)]
pub struct FloatKey(&'static Key);

/// `color`: the colour mode.
pub const COLOR: AnyKey = AnyKey(&keys::COLOR);
/// `relative_depth`: water coloured by its depth.
pub const RELATIVE_DEPTH: AnyKey = AnyKey(&keys::RELATIVE_DEPTH);
/// `low_detail`: the coarser grid.
pub const LOW_DETAIL: AnyKey = AnyKey(&keys::LOW_DETAIL);
/// `cragginess`: how sharply the square generators crease.
pub const CRAGGINESS: IntKey = IntKey(&keys::CRAGGINESS);
/// `height`: the mountain's height, 1 to 10.
pub const HEIGHT: IntKey = IntKey(&keys::HEIGHT);
/// `elevation`: the square generators' corner heights.
pub const ELEVATION: FloatKey = FloatKey(&keys::ELEVATION);
/// `roughness`: the triangle generator's smoothness base.
pub const ROUGHNESS: FloatKey = FloatKey(&keys::ROUGHNESS);
/// `contour`: the triangle generator's power on heights.
pub const CONTOUR: FloatKey = FloatKey(&keys::CONTOUR);
/// `hurst`: the Brownian surface's roughness.
pub const HURST: FloatKey = FloatKey(&keys::HURST);
/// `erosion`: how much the land is worn.
pub const EROSION: FloatKey = FloatKey(&keys::EROSION);
/// `sea_level`: where the sea stands.
pub const SEA_LEVEL: FloatKey = FloatKey(&keys::SEA_LEVEL);
/// `cliffs`: terraces and cliffs, 0 to 1.
pub const CLIFFS: FloatKey = FloatKey(&keys::CLIFFS);

macro_rules! same_key {
    ($($t:ty),*) => {$(
        /// Two handles are equal when they name the same key.
        impl PartialEq for $t {
            fn eq(&self, other: &Self) -> bool {
                self.0.name == other.0.name
            }
        }

        impl Eq for $t {}
    )*};
}

same_key!(AnyKey, IntKey, FloatKey);

impl AnyKey {
    /// The key's row in the table.
    pub fn row(self) -> &'static Key {
        self.0
    }
}

impl IntKey {
    /// The key's row in the table.
    pub fn row(self) -> &'static Key {
        self.0
    }

    /// The key's least and greatest values.
    pub fn range(self) -> (i64, i64) {
        match self.row().kind {
            Kind::Int { min, max } => (min, max),
            other => unreachable!("`{}` is {other:?}, not a whole number", self.0.name),
        }
    }

    /// `value` clamped into the key's range: for code given `Settings`
    /// built by hand rather than read through the table (the generator,
    /// the palette), so no value can stall it.
    pub fn clamp(self, value: u32) -> u32 {
        let (min, max) = self.range();
        i64::from(value).clamp(min, max) as u32
    }
}

impl FloatKey {
    /// The key's row in the table.
    pub fn row(self) -> &'static Key {
        self.0
    }

    /// The key's least and greatest values.
    pub fn range(self) -> (f64, f64) {
        match self.row().kind {
            Kind::Float { min, max } => (min, max),
            other => unreachable!("`{}` is {other:?}, not a number", self.0.name),
        }
    }

    /// `value` clamped into the key's range, or the key's default if it is
    /// NaN (see [`IntKey::clamp`]).
    pub fn clamp(self, value: f32) -> f32 {
        let (min, max) = self.range();
        if !value.is_nan() {
            return value.clamp(min as f32, max as f32);
        }
        match (self.row().default)() {
            Value::Float(default) => default as f32,
            other => unreachable!("`{}` defaults to {other:?}", self.0.name),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_handle_names_a_key_of_its_kind() {
        for key in [COLOR, RELATIVE_DEPTH, LOW_DETAIL] {
            assert!(keys::find(key.0.name).is_some(), "{key:?}");
        }
        for key in [CRAGGINESS, HEIGHT] {
            assert!(
                matches!(
                    keys::find(key.0.name).map(|k| k.kind),
                    Some(Kind::Int { .. })
                ),
                "{key:?}"
            );
        }
        let floats = [
            ELEVATION, ROUGHNESS, CONTOUR, HURST, EROSION, SEA_LEVEL, CLIFFS,
        ];
        for key in floats {
            let row = keys::find(key.0.name);
            assert!(
                matches!(row.map(|k| k.kind), Some(Kind::Float { .. })),
                "{key:?}"
            );
            assert!(
                matches!(row.map(|k| (k.default)()), Some(Value::Float(_))),
                "{key:?}"
            );
        }
    }

    #[test]
    fn clamps_keep_values_in_the_tables_range() {
        let (min, max) = CRAGGINESS.range();
        assert_eq!(CRAGGINESS.clamp(u32::MAX), max as u32);
        assert_eq!(CRAGGINESS.clamp(0), min.max(0) as u32);
        let (lo, hi) = EROSION.range();
        assert_eq!(EROSION.clamp(1e9), hi as f32);
        assert_eq!(EROSION.clamp(-1e9), lo as f32);
        let Value::Float(default) = (EROSION.row().default)() else {
            unreachable!()
        };
        assert_eq!(EROSION.clamp(f32::NAN), default as f32);
    }
}
