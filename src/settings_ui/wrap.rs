//! Text cut and wrapped to fit a width in characters: labels and values
//! cut short, the help wrapped at spaces, a path that keeps its file name.

/// Cuts `s` to at most `chars` characters, marking the cut with "..".
pub(super) fn fit(s: &str, chars: usize) -> String {
    if s.chars().count() <= chars {
        return s.to_string();
    }
    let keep: String = s.chars().take(chars.saturating_sub(2)).collect();
    format!("{keep}..")
}

/// Splits `s` into lines of at most `width` characters at spaces.
pub(super) fn wrap(s: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut cur = String::new();
    for word in s.split_whitespace() {
        let word = fit_middle(word, width);
        if !cur.is_empty() && cur.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut cur));
        }
        if !cur.is_empty() {
            cur.push(' ');
        }
        cur.push_str(&word);
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    lines
}

/// `word` shortened to `chars` by leaving out its middle: a path keeps its
/// start and its file name.
pub(super) fn fit_middle(word: &str, chars: usize) -> String {
    let n = word.chars().count();
    if n <= chars || chars < 5 {
        return fit(word, chars);
    }
    let tail = (chars - 2) / 2;
    let head = chars - 2 - tail;
    let start: String = word.chars().take(head).collect();
    let end: String = word.chars().skip(n - tail).collect();
    format!("{start}..{end}")
}

/// Which of `help` (lines, each to be wrapped) and `message` to show in
/// `rows` rows of `width` characters: the whole message, wrapped, comes
/// first in priority (an error must not be cut mid-sentence), the help fills
/// the rows left above it. Returns the wrapped help lines and message lines.
pub(super) fn help_then_message(
    help: &[String],
    message: &str,
    width: usize,
    rows: usize,
) -> (Vec<String>, Vec<String>) {
    let mut message = wrap(message, width);
    message.truncate(rows);
    let room = rows - message.len();
    let help = help
        .iter()
        .flat_map(|l| wrap(l, width))
        .take(room)
        .collect();
    (help, message)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_path_keeps_its_start_and_its_file_name() {
        let path = "/home/someone/a/very/long/folder/name/for/the/preferences/mountains.toml";
        let short = fit_middle(path, 30);
        assert_eq!(short.chars().count(), 30);
        assert!(short.starts_with("/home/someone"), "{short}");
        assert!(short.ends_with("mountains.toml"), "{short}");
        assert_eq!(fit_middle("short", 30), "short");
    }

    #[test]
    fn the_message_is_shown_whole_and_the_help_gives_way() {
        let help: Vec<String> = (0..5).map(|i| format!("help line {i}")).collect();
        let message = "cannot save /home/someone/.config/mountains/mountains.toml: \
                       No space left on device. Free some space and press OK again.";
        let (h, m) = help_then_message(&help, message, 30, 6);
        assert_eq!(m.join(" ").split_whitespace().last(), Some("again."));
        assert_eq!(h.len() + m.len(), 6);
        assert!(m.len() >= 3 && h.len() <= 3, "{h:?} {m:?}");
        // With room for everything, nothing is dropped.
        let (h, m) = help_then_message(&help, message, 30, 20);
        assert_eq!(h.len(), 5);
        assert!(m.len() >= 3);
    }
}
