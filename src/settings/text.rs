//! The text of a preferences file, and the form it is kept in. Besides
//! UTF-8 (with or without a byte-order mark), a file may be UTF-16 with a
//! mark: what Windows PowerShell 5 writes with `>` and `Out-File`, and
//! Notepad's "Unicode". Such a file is read as its text (it was ignored,
//! the defaults used, with "not valid UTF-8 text"), and a save writes
//! every file back in its own form, mark and all. (UTF-16 without a mark
//! reads as UTF-8 with a NUL after each character: refused as such.)

/// How a preferences file's text is stored.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Form {
    /// UTF-8, as written from the commented defaults.
    Utf8,
    /// UTF-8 after a byte-order mark (older Notepad's "UTF-8").
    Utf8Bom,
    /// UTF-16 with a byte-order mark, little-endian (Windows').
    Utf16Le,
    /// UTF-16 with a byte-order mark, big-endian.
    Utf16Be,
}

/// Where a file's bytes stop being text in its form: the line and column
/// (from 1, in characters) of the first that is not, and what is wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NotText {
    /// The line, from 1.
    pub line: usize,
    /// The column, from 1, in characters.
    pub column: usize,
    /// What is wrong: not valid UTF-8 or UTF-16 text.
    pub message: &'static str,
}

/// What [`NotText`] says of bytes that are not UTF-8 text.
const NOT_UTF8: &str = "not valid UTF-8 text";
/// What [`NotText`] says of bytes behind a UTF-16 mark that are not UTF-16
/// text.
const NOT_UTF16: &str = "not valid UTF-16 text";
/// What [`NotText`] says of UTF-8 that holds a NUL, which no TOML may:
/// most likely UTF-16 written without its byte-order mark.
const NUL_IN_TEXT: &str =
    "a NUL byte, which text has none of (UTF-16 without its byte-order mark? save it as UTF-8)";

/// What [`NotText`] says of a PNG given as a preferences file (`--config
/// h.png`, meant for `--open`).
const A_PNG: &str = "a PNG image, not text (a data set is opened with --open FILE)";

/// The text of a preferences file's `bytes`, and its form.
pub fn decode(mut bytes: Vec<u8>) -> Result<(String, Form), NotText> {
    if bytes.starts_with(&crate::fsutil::PNG_SIGNATURE) {
        return Err(not_text("", A_PNG));
    }
    let form = match bytes.as_slice() {
        [0xff, 0xfe, ..] => Form::Utf16Le,
        [0xfe, 0xff, ..] => Form::Utf16Be,
        [0xef, 0xbb, 0xbf, ..] => {
            bytes.drain(..3);
            return utf8(bytes, Form::Utf8Bom);
        }
        _ => return utf8(bytes, Form::Utf8),
    };
    let message = NOT_UTF16;
    let body = &bytes[2..];
    // An odd byte at the end is no character: refused after the rest.
    let (whole, odd) = body.split_at(body.len() & !1);
    let units = whole.chunks_exact(2).map(|p| match form {
        Form::Utf16Le => u16::from_le_bytes([p[0], p[1]]),
        _ => u16::from_be_bytes([p[0], p[1]]),
    });
    let mut text = String::with_capacity(whole.len() / 2);
    for c in char::decode_utf16(units) {
        match c {
            Ok(c) => text.push(c),
            Err(_) => return Err(not_text(&text, message)),
        }
    }
    match odd.is_empty() {
        true => Ok((text, form)),
        false => Err(not_text(&text, message)),
    }
}

/// The text of UTF-8 `bytes` (after any mark), kept in `form`.
fn utf8(bytes: Vec<u8>, form: Form) -> Result<(String, Form), NotText> {
    // The text up to where it breaks as UTF-8, if it does.
    let (text, broken) = match String::from_utf8(bytes) {
        Ok(text) => (text, false),
        Err(e) => {
            let valid = e.utf8_error().valid_up_to();
            let mut bytes = e.into_bytes();
            bytes.truncate(valid);
            (String::from_utf8(bytes).unwrap_or_default(), true)
        }
    };
    // UTF-16 without its mark breaks as UTF-8 (at its first accent) only
    // after its first NUL: named as what it most likely is.
    match (text.find('\0'), broken) {
        (Some(nul), _) => Err(not_text(&text[..nul], NUL_IN_TEXT)),
        (None, true) => Err(not_text(&text, NOT_UTF8)),
        (None, false) => Ok((text, form)),
    }
}

/// `text` stored in `form` (with its byte-order mark, if the form has one).
pub fn encode(text: &str, form: Form) -> Vec<u8> {
    let units = text.encode_utf16();
    match form {
        Form::Utf8 => text.as_bytes().to_vec(),
        Form::Utf8Bom => [0xef, 0xbb, 0xbf].into_iter().chain(text.bytes()).collect(),
        Form::Utf16Le => [0xff, 0xfe]
            .into_iter()
            .chain(units.flat_map(u16::to_le_bytes))
            .collect(),
        Form::Utf16Be => [0xfe, 0xff]
            .into_iter()
            .chain(units.flat_map(u16::to_be_bytes))
            .collect(),
    }
}

/// The 1-based line and column of byte `offset` in `text`.
pub(crate) fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let col = before
        .rfind('\n')
        .map_or(before, |i| &before[i + 1..])
        .chars()
        .count()
        + 1;
    (line, col)
}

/// The place just after `before`, the text read so far.
fn not_text(before: &str, message: &'static str) -> NotText {
    let (line, column) = line_col(before, before.len());
    NotText {
        line,
        column,
        message,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf8_is_read_as_it_is() {
        let (text, form) = decode(b"seed = 5\r\n".to_vec()).unwrap();
        assert_eq!((text.as_str(), form), ("seed = 5\r\n", Form::Utf8));
        let err = decode(b"# ok\n# caf\xe9\n".to_vec()).unwrap_err();
        assert_eq!((err.line, err.column), (2, 6));
        assert_eq!(err.message, "not valid UTF-8 text");
    }

    /// UTF-16 without its mark reads as UTF-8 full of NULs: said as what
    /// it most likely is, where the first one stands.
    #[test]
    fn utf16_without_its_mark_is_named() {
        for text in ["seed = 5\n", "# café\nseed = 5\n"] {
            let bytes: Vec<u8> = text.encode_utf16().flat_map(u16::to_le_bytes).collect();
            let err = decode(bytes).unwrap_err();
            assert_eq!(
                (err.line, err.column, err.message),
                (1, 2, NUL_IN_TEXT),
                "{text}"
            );
        }
    }

    #[test]
    fn utf16_with_its_mark_is_read_both_ways_and_written_back_the_same() {
        let text = "# café ☃\r\nseed = 5\r\n";
        for form in [Form::Utf16Le, Form::Utf16Be] {
            let bytes = encode(text, form);
            assert_eq!(bytes.len(), 2 + 2 * text.encode_utf16().count());
            assert_eq!(decode(bytes.clone()).unwrap(), (text.to_string(), form));
            let (back, _) = decode(bytes.clone()).unwrap();
            assert_eq!(encode(&back, form), bytes);
        }
        // PowerShell 5's `'seed = 5' > mountains.toml`.
        let mut bytes = vec![0xff, 0xfe];
        for c in "seed = 5\r\n".bytes() {
            bytes.extend([c, 0]);
        }
        assert_eq!(decode(bytes).unwrap().0, "seed = 5\r\n");
    }

    #[test]
    fn a_utf8_mark_is_kept_and_a_mark_alone_is_an_empty_file() {
        let bytes = b"\xef\xbb\xbfseed = 5\n".to_vec();
        let (text, form) = decode(bytes.clone()).unwrap();
        assert_eq!((text.as_str(), form), ("seed = 5\n", Form::Utf8Bom));
        assert_eq!(encode(&text, form), bytes);
        for mark in [&[0xef, 0xbb, 0xbf][..], &[0xff, 0xfe], &[0xfe, 0xff]] {
            let (text, form) = decode(mark.to_vec()).unwrap();
            assert!(text.is_empty());
            assert_eq!(encode("", form), mark);
        }
    }

    #[test]
    fn broken_utf16_is_refused_where_it_breaks() {
        // A lone high surrogate on line 2, after "ab".
        let mut bytes = encode("x\nab", Form::Utf16Le);
        bytes.extend(0xd800u16.to_le_bytes());
        bytes.extend(encode("c", Form::Utf16Le)[2..].iter());
        let err = decode(bytes).unwrap_err();
        assert_eq!((err.line, err.column), (2, 3), "{err:?}");
        assert_eq!(err.message, "not valid UTF-16 text");
        // An odd byte at the end.
        let mut bytes = encode("seed = 5\n", Form::Utf16Le);
        bytes.push(b'x');
        let err = decode(bytes).unwrap_err();
        assert_eq!((err.line, err.column), (2, 1), "{err:?}");
    }
}
