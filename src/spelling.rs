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
pub fn nearest<S: AsRef<str>>(typed: &str, known: impl IntoIterator<Item = S>) -> Option<S> {
    known
        .into_iter()
        .map(|k| (edit_distance(typed, k.as_ref()), k))
        .filter(|(d, k)| *d <= 2.max(k.as_ref().len() / 3))
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k)
}

fn edit_distance(a: &str, b: &str) -> usize {
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
