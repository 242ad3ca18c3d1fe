//! Echoing what a user typed or loaded, without echoing a flood: at most
//! [`QUOTE_CHARS`] characters of it, then how long it really was. A 15 MiB
//! text value in a PNG becomes a line, not a 15 MiB message and log entry.

/// Characters of a value a message shows.
pub const QUOTE_CHARS: usize = 80;

/// `s` in quotes (Rust's escaping, so control characters show), cut to
/// [`QUOTE_CHARS`] characters with its length when it is longer.
pub fn quoted(s: &str) -> String {
    let n = s.chars().count();
    if n <= QUOTE_CHARS {
        return format!("{s:?}");
    }
    let head: String = s.chars().take(QUOTE_CHARS).collect();
    format!("{head:?}... ({n} characters)")
}

/// `s` as it is (a key or flag name in backquotes), cut the same way.
pub fn clipped(s: &str) -> String {
    let n = s.chars().count();
    if n <= QUOTE_CHARS {
        return s.to_string();
    }
    let head: String = s.chars().take(QUOTE_CHARS).collect();
    format!("{head}... ({n} characters)")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_values_whole_long_ones_cut_with_their_length() {
        assert_eq!(quoted("pink"), "\"pink\"");
        assert_eq!(quoted("a\nb"), "\"a\\nb\"");
        let long = "x".repeat(100_000);
        let q = quoted(&long);
        assert_eq!(q, format!("\"{}\"... (100000 characters)", "x".repeat(80)));
        assert_eq!(
            clipped(&"é".repeat(81)),
            format!("{}... (81 characters)", "é".repeat(80))
        );
        assert_eq!(clipped("color"), "color");
    }
}
