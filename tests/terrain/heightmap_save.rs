//! `save` writes atomically: a failure never truncates or replaces a file.

use crate::common::heightmaps;

use heightmaps::{field, temp_dir};
use mountains::terrain::heightmap::{ErrorKind, load, save};

fn entries(dir: &std::path::Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn target_that_is_a_directory_is_left_alone() {
    let dir = temp_dir("save-dir-target");
    let target = dir.join("taken.png");
    std::fs::create_dir(&target).unwrap();
    std::fs::write(target.join("keep.txt"), b"precious").unwrap();
    let e = save(
        &target,
        &field(4, 400.0),
        Some(1),
        &crate::common::terrain_setup::temperate(),
    )
    .unwrap_err();
    assert_eq!(e.kind, ErrorKind::Io);
    assert!(
        e.to_string().starts_with(&target.display().to_string()),
        "{e}"
    );
    assert_eq!(std::fs::read(target.join("keep.txt")).unwrap(), b"precious");
    assert_eq!(
        entries(&dir),
        ["taken.png"],
        "a temporary file was left behind"
    );
}

#[test]
fn failed_encode_keeps_the_existing_file() {
    let dir = temp_dir("save-keeps-old");
    let target = dir.join("old.png");
    std::fs::write(&target, b"the user's old file").unwrap();
    let mut bad = field(4, 400.0);
    bad.set(0, 0, f32::INFINITY);
    let e = save(
        &target,
        &bad,
        None,
        &crate::common::terrain_setup::temperate(),
    )
    .unwrap_err();
    assert_eq!(e.kind, ErrorKind::BadField);
    assert_eq!(std::fs::read(&target).unwrap(), b"the user's old file");
    assert_eq!(entries(&dir), ["old.png"]);
}

#[test]
fn missing_folder_is_an_error_naming_the_file() {
    let dir = temp_dir("save-missing-folder");
    let target = dir.join("no/such/folder/m.png");
    let e = save(
        &target,
        &field(4, 400.0),
        None,
        &crate::common::terrain_setup::temperate(),
    )
    .unwrap_err();
    assert_eq!(e.kind, ErrorKind::Io);
    assert!(e.problem.starts_with("cannot write: "), "{e}");
    assert!(e.to_string().contains("m.png"), "{e}");
}

/// A data set, a picture and a screenshot that cannot be written are
/// said in one wording, the file first: a data set's "cannot be written"
/// beside a picture's "cannot write" read as two faults.
#[test]
fn a_failed_write_is_said_alike_for_data_sets_and_pictures() {
    let dir = temp_dir("save-alike");
    let target = dir.join("no/such/folder/m.png");
    let setup = crate::common::terrain_setup::temperate();
    let data_set = save(&target, &field(4, 400.0), None, &setup).unwrap_err();
    let frame = mountains::render::Frame::new(4, 3).unwrap();
    let screenshot = mountains::snapshot::write_png(&target, &frame).unwrap_err();
    assert_eq!(data_set.to_string(), screenshot);
    let picture =
        mountains::snapshot::write_picture(&target, &frame, mountains::cli::output::Format::Png)
            .unwrap_err();
    assert_eq!(format!("-o {data_set}"), picture);
    let missing = std::io::Error::from(std::io::ErrorKind::NotFound);
    let said = mountains::fsutil::cannot_write(&missing);
    assert!(said.starts_with("cannot write: "), "{said}");
    assert!(screenshot.starts_with(&format!("{}: cannot write: ", target.display())));
}

#[test]
fn success_replaces_the_file_whole() {
    let dir = temp_dir("save-replaces");
    let target = dir.join("m.png");
    std::fs::write(&target, vec![b'x'; 1 << 20]).unwrap();
    save(
        &target,
        &field(5, 400.0),
        Some(8),
        &crate::common::terrain_setup::temperate(),
    )
    .unwrap();
    let d = load(&target).unwrap();
    assert_eq!(d.seed, Some(8));
    assert_eq!(entries(&dir), ["m.png"]);
}
