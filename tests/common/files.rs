//! Files changed behind a program's back, for tests of what it notices.
#![allow(dead_code)]

use std::path::Path;

/// Puts `text` in place of the file at `path` the way another program
/// would: a new file renamed over it, keeping the old modification time
/// (as `cp -p` or `rsync -t` do), so only the content says that it changed.
pub fn replace_keeping_mtime(path: &Path, text: &str) {
    let mtime = std::fs::metadata(path).unwrap().modified().unwrap();
    let tmp = path.with_extension("other");
    std::fs::write(&tmp, text).unwrap();
    std::fs::File::options()
        .write(true)
        .open(&tmp)
        .unwrap()
        .set_modified(mtime)
        .unwrap();
    std::fs::rename(&tmp, path).unwrap();
}
