//! The known name nearest to a misspelt one, and the words that offer it:
//! the one owner of every "did you mean" (a key in a file or in `--set`, a
//! flag on the command line).

/// `; did you mean `NAME`?` for the name among `known` nearest to `typed`,
/// or nothing when none is near enough to be what was meant.
pub fn did_you_mean<S: AsRef<str>>(typed: &str, known: impl IntoIterator<Item = S>) -> String {
    offer(nearest(typed, known).as_ref().map(AsRef::as_ref))
}

/// `; did you mean `NAME`?` for a name found by [`nearest`] and written as
/// the user would type it (a flag with its dashes), or nothing.
pub fn offer(name: Option<&str>) -> String {
    name.map(|s| format!("; did you mean `{s}`?"))
        .unwrap_or_default()
}

/// The name among `known` nearest to `typed` (fewest characters added,
/// removed or changed), if it is within 2 edits, or a third of its length
/// for a long name; the first of equally near ones.
///
/// It allocates nothing and stops on each name once it is out of reach: a
/// hostile file of many unknown keys runs this for each. Names longer than [`LONGEST`] characters are never
/// near (no key or flag is nearly that long).
pub fn nearest<S: AsRef<str>>(typed: &str, known: impl IntoIterator<Item = S>) -> Option<S> {
    let mut typed_chars = ['\0'; LONGEST];
    let typed = chars(typed, &mut typed_chars)?;
    let mut best: Option<(usize, S)> = None;
    for name in known {
        let mut name_chars = ['\0'; LONGEST];
        let Some(candidate) = chars(name.as_ref(), &mut name_chars) else {
            continue;
        };
        let mut reach = 2.max(name.as_ref().len() / 3);
        if let Some((d, _)) = &best {
            // Only a nearer name replaces the one found.
            match d.checked_sub(1) {
                Some(closer) => reach = reach.min(closer),
                None => break,
            }
        }
        if let Some(d) = distance_within(typed, candidate, reach) {
            best = Some((d, name));
        }
    }
    best.map(|(_, name)| name)
}

/// The longest name compared, in characters.
pub const LONGEST: usize = 64;

/// The characters of `text` in `buf`, lowercased, or `None` if there are
/// too many. Every name is lowercase, and a name typed in capitals
/// (`COLOR`, `--SET`, `RENDER`: caps lock, or a Windows habit) was
/// further than any misspelling, and offered nothing.
fn chars<'a>(text: &str, buf: &'a mut [char; LONGEST]) -> Option<&'a [char]> {
    let mut n = 0;
    for c in text.chars().flat_map(char::to_lowercase) {
        *buf.get_mut(n)? = c;
        n += 1;
    }
    Some(&buf[..n])
}

/// The edit distance between `a` and `b` if it is at most `reach`.
fn distance_within(a: &[char], b: &[char], reach: usize) -> Option<usize> {
    if a.len().abs_diff(b.len()) > reach {
        return None;
    }
    // One row of the Wagner-Fischer table: row[j] is the distance between
    // the part of `a` seen so far and b[..j].
    let mut row = [0usize; LONGEST + 1];
    for (j, cell) in row.iter_mut().enumerate().take(b.len() + 1) {
        *cell = j;
    }
    for (i, ca) in a.iter().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        let mut least = row[0];
        for (j, cb) in b.iter().enumerate() {
            let replace = diagonal + usize::from(ca != cb);
            diagonal = row[j + 1];
            row[j + 1] = replace.min(row[j + 1] + 1).min(row[j] + 1);
            least = least.min(row[j + 1]);
        }
        // Every later row is at least this row's least.
        if least > reach {
            return None;
        }
    }
    Some(row[b.len()]).filter(|&d| d <= reach)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The plain definition, for comparing.
    fn levenshtein(a: &str, b: &str) -> usize {
        let b: Vec<char> = b.chars().collect();
        let mut prev: Vec<usize> = (0..=b.len()).collect();
        for (i, ca) in a.chars().enumerate() {
            let mut cur = vec![i + 1];
            for (j, cb) in b.iter().enumerate() {
                let sub = prev[j] + usize::from(ca != *cb);
                cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
            }
            prev = cur;
        }
        prev[b.len()]
    }

    #[test]
    fn the_bounded_distance_agrees_with_the_definition_within_reach() {
        let words = [
            "",
            "a",
            "color",
            "colour",
            "kitten",
            "sitting",
            "sea_level",
            "sealevel",
            "level_sea",
            "draw_seconds",
            "ß",
            "straße",
            "strasse",
            "cragginess",
            "craggy",
        ];
        for a in words {
            for b in words {
                let full = levenshtein(a, b);
                let (mut x, mut y) = (['\0'; LONGEST], ['\0'; LONGEST]);
                let (xa, yb) = (chars(a, &mut x).unwrap(), chars(b, &mut y).unwrap());
                for reach in 0..8 {
                    let want = (full <= reach).then_some(full);
                    assert_eq!(distance_within(xa, yb, reach), want, "{a} {b} {reach}");
                }
            }
        }
    }

    #[test]
    fn the_nearest_is_within_reach_and_the_first_of_equals() {
        let known = ["color", "cragginess", "sea_level", "shadows", "sun"];
        assert_eq!(nearest("colour", known), Some("color"));
        assert_eq!(nearest("craggyness", known), Some("cragginess"));
        assert_eq!(nearest("sea-level", known), Some("sea_level"));
        assert_eq!(nearest("zzzzzz", known), None);
        assert_eq!(nearest("shadow", known), Some("shadows"));
        assert_eq!(nearest("sun", known), Some("sun"));
        assert_eq!(nearest("ab", ["ax", "ay"]), Some("ax"));
        assert_eq!(nearest(&"c".repeat(100_000), known), None);
        assert_eq!(nearest("color", ["c".repeat(1000)]), None);
        assert_eq!(nearest("COLOR", known), Some("color"));
        assert_eq!(nearest("Sea_Levle", known), Some("sea_level"));
    }
}
