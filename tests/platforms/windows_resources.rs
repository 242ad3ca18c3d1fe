//! What Windows shows of the cross-built .scr, read from the exe's PE
//! resources (build.rs puts them there): its name in the Screen Saver
//! Settings list (string 1), its version information, its icon. They need
//! the cross-built exe (see `wine::CROSS_BUILD`, at least as new as the
//! sources); without it they skip, unless `MOUNTAINS_REQUIRE_WINE=1`, as in
//! tests/platforms/wine.rs.

use crate::common::pe;
use crate::common::wine;

use pe::{Pe, RT_GROUP_ICON, RT_ICON, RT_STRING, RT_VERSION, VersionInfo};

/// The cross-built exe's bytes, or `None` to skip.
fn exe() -> Option<Vec<u8>> {
    let path = wine::cross_built_exe()?;
    Some(std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display())))
}

/// The one resource `kind`/`id`, whatever its language.
fn only<'a>(pe: &Pe<'a>, kind: u16, id: u16, what: &str) -> pe::Resource<'a> {
    let mut found = pe
        .resource(kind, id)
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    assert!(
        pe.has_resources(),
        "the exe has no resources at all (no {what})"
    );
    assert_eq!(found.len(), 1, "{what}: one language wanted");
    found.remove(0)
}

#[test]
#[ignore = "needs the cross-built exe: cargo build --release --target x86_64-pc-windows-gnu"]
fn windows_exe_is_named_mountains_by_string_1() {
    let Some(bytes) = exe() else {
        return;
    };
    let pe = Pe::parse(&bytes).expect("a PE file");
    // Ids 0 to 15 are in block 1.
    let block = only(&pe, RT_STRING, 1, "string table block 1");
    let name = pe::table_string(block.data, 1).expect("string 1");
    assert_eq!(name, "Mountains", "the Screen Saver list would show this");
    assert_eq!(block.language, 0x0409, "string table language");
}

#[test]
#[ignore = "needs the cross-built exe: cargo build --release --target x86_64-pc-windows-gnu"]
fn windows_exe_has_version_information_from_cargo_toml() {
    let Some(bytes) = exe() else {
        return;
    };
    let pe = Pe::parse(&bytes).expect("a PE file");
    let version = only(&pe, RT_VERSION, 1, "version information");
    let info = VersionInfo::parse(version.data).expect("a VS_VERSIONINFO");
    eprintln!("version strings: {:?}", info.strings);
    let cargo: Vec<u16> = env!("CARGO_PKG_VERSION")
        .split('.')
        .map(|n| n.parse().expect("a numeric version"))
        .collect();
    assert_eq!(info.file_version[..3], cargo[..], "FILEVERSION");
    assert_eq!(
        info.string("FileDescription"),
        Some("Mountains screensaver")
    );
    assert_eq!(info.string("ProductName"), Some("Mountains"));
    assert_eq!(info.string("FileVersion"), Some(env!("CARGO_PKG_VERSION")));
    assert_eq!(info.string("OriginalFilename"), Some("mountains.scr"));
}

#[test]
#[ignore = "needs the cross-built exe: cargo build --release --target x86_64-pc-windows-gnu"]
fn windows_exe_has_an_icon_of_16_32_48_and_256_pixels() {
    let Some(bytes) = exe() else {
        return;
    };
    let pe = Pe::parse(&bytes).expect("a PE file");
    let groups = pe.ids(RT_GROUP_ICON).expect("icon groups");
    // Explorer shows the group with the lowest id.
    assert_eq!(groups, [1], "one icon group, id 1");
    let group = only(&pe, RT_GROUP_ICON, 1, "icon group 1");
    let entries = pe::icon_group(group.data).expect("an icon group");
    let sizes: Vec<(u16, u16)> = entries.iter().map(|e| e.size).collect();
    assert_eq!(sizes, [(16, 16), (32, 32), (48, 48), (256, 256)]);
    for entry in &entries {
        assert_eq!(entry.bits, 32, "{entry:?}: 32 bits per pixel (alpha)");
        let picture = only(&pe, RT_ICON, entry.icon_id, "an icon picture");
        // 256 px: a PNG; smaller: a BITMAPINFOHEADER (40 bytes) of that size.
        let header_ok = if entry.size.0 == 256 {
            picture.data.starts_with(b"\x89PNG")
        } else {
            picture.data.get(..4) == Some(&40u32.to_le_bytes()[..])
        };
        assert!(header_ok, "{entry:?}: not a picture of the kind expected");
    }
}
