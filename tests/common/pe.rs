//! A small reader of a Windows exe's resources (the PE resource directory),
//! enough to check what Windows shows of the .scr: its version information,
//! its string table and its icons. Every read is bounds-checked; a file that
//! is not what it should be gives an `Err` naming what was wrong.
#![allow(dead_code)]

/// Resource types (winuser.h `RT_*`).
pub const RT_ICON: u16 = 3;
/// A string table block: 16 strings, block `n` holding ids `16(n-1)..16n`.
pub const RT_STRING: u16 = 6;
/// An icon group: the sizes of one icon and the RT_ICON ids of each.
pub const RT_GROUP_ICON: u16 = 14;
/// VS_VERSIONINFO.
pub const RT_VERSION: u16 = 16;

/// The index of the resource data directory in the optional header.
const RESOURCE_DIRECTORY: usize = 2;

/// A PE file and where its resources are.
pub struct Pe<'a> {
    bytes: &'a [u8],
    /// (virtual address, virtual size, file offset) of each section.
    sections: Vec<(u32, u32, u32)>,
    /// The resource directory's virtual address; 0 if the file has none.
    resources: u32,
}

/// One resource's data and its language.
pub struct Resource<'a> {
    /// The language id (0x0409: English, United States).
    pub language: u16,
    /// The resource's bytes.
    pub data: &'a [u8],
}

fn u16_at(b: &[u8], at: usize) -> Result<u16, String> {
    b.get(at..at + 2)
        .map(|s| u16::from_le_bytes([s[0], s[1]]))
        .ok_or_else(|| format!("a 16-bit field at {at:#x} is past the end ({:#x})", b.len()))
}

fn u32_at(b: &[u8], at: usize) -> Result<u32, String> {
    b.get(at..at + 4)
        .map(|s| u32::from_le_bytes([s[0], s[1], s[2], s[3]]))
        .ok_or_else(|| format!("a 32-bit field at {at:#x} is past the end ({:#x})", b.len()))
}

impl<'a> Pe<'a> {
    /// Reads the headers of a PE32+ (64-bit) file.
    pub fn parse(bytes: &'a [u8]) -> Result<Pe<'a>, String> {
        if bytes.get(..2) != Some(b"MZ") {
            return Err("no MZ header: not a Windows executable".into());
        }
        let pe = u32_at(bytes, 0x3c)? as usize;
        if bytes.get(pe..pe + 4) != Some(b"PE\0\0") {
            return Err(format!("no PE signature at {pe:#x}"));
        }
        let coff = pe + 4;
        let sections = u16_at(bytes, coff + 2)? as usize;
        let optional = coff + 20;
        let optional_size = u16_at(bytes, coff + 16)? as usize;
        if u16_at(bytes, optional)? != 0x20b {
            return Err("not a PE32+ (64-bit) optional header".into());
        }
        // PE32+: the data directories start 112 bytes in, 8 bytes each.
        let directories = u32_at(bytes, optional + 108)? as usize;
        let resources = if directories > RESOURCE_DIRECTORY {
            u32_at(bytes, optional + 112 + 8 * RESOURCE_DIRECTORY)?
        } else {
            0
        };
        let table = optional + optional_size;
        let sections = (0..sections)
            .map(|i| {
                let s = table + 40 * i;
                Ok((
                    u32_at(bytes, s + 12)?,
                    u32_at(bytes, s + 8)?,
                    u32_at(bytes, s + 20)?,
                ))
            })
            .collect::<Result<_, String>>()?;
        Ok(Pe {
            bytes,
            sections,
            resources,
        })
    }

    /// True if the file has a resource directory at all.
    pub fn has_resources(&self) -> bool {
        self.resources != 0
    }

    /// The file offset of a virtual address.
    fn offset(&self, rva: u32) -> Result<usize, String> {
        self.sections
            .iter()
            .find(|(va, size, _)| rva >= *va && rva - va < *size)
            .map(|(va, _, raw)| (raw + (rva - va)) as usize)
            .ok_or_else(|| format!("address {rva:#x} is in no section"))
    }

    /// The numeric ids under a directory (its named entries are skipped)
    /// with their offsets from the root, as (id, offset, is a directory).
    fn entries(&self, dir: u32) -> Result<Vec<(u16, u32, bool)>, String> {
        let at = self.offset(self.resources + dir)?;
        let named = u16_at(self.bytes, at + 12)? as usize;
        let ids = u16_at(self.bytes, at + 14)? as usize;
        (named..named + ids)
            .map(|i| {
                let e = at + 16 + 8 * i;
                let name = u32_at(self.bytes, e)?;
                let target = u32_at(self.bytes, e + 4)?;
                Ok((name as u16, target & 0x7fff_ffff, target & 0x8000_0000 != 0))
            })
            .collect()
    }

    /// The directory under `dir` with numeric id `id`, if there is one.
    fn subdirectory(&self, dir: u32, id: u16) -> Result<Option<u32>, String> {
        let found = self.entries(dir)?.into_iter().find(|e| e.0 == id);
        match found {
            Some((_, offset, true)) => Ok(Some(offset)),
            Some(_) => Err(format!(
                "resource entry {id} is data where a directory belongs"
            )),
            None => Ok(None),
        }
    }

    /// The ids of the resources of type `kind`.
    pub fn ids(&self, kind: u16) -> Result<Vec<u16>, String> {
        if !self.has_resources() {
            return Ok(Vec::new());
        }
        match self.subdirectory(0, kind)? {
            Some(dir) => Ok(self.entries(dir)?.into_iter().map(|e| e.0).collect()),
            None => Ok(Vec::new()),
        }
    }

    /// Resource `id` of type `kind`, in every language it comes in.
    pub fn resource(&self, kind: u16, id: u16) -> Result<Vec<Resource<'a>>, String> {
        if !self.has_resources() {
            return Ok(Vec::new());
        }
        let Some(names) = self.subdirectory(0, kind)? else {
            return Ok(Vec::new());
        };
        let Some(languages) = self.subdirectory(names, id)? else {
            return Ok(Vec::new());
        };
        self.entries(languages)?
            .into_iter()
            .map(|(language, offset, _)| {
                let entry = self.offset(self.resources + offset)?;
                let rva = u32_at(self.bytes, entry)?;
                let size = u32_at(self.bytes, entry + 4)? as usize;
                let start = self.offset(rva)?;
                let data = self
                    .bytes
                    .get(start..start + size)
                    .ok_or_else(|| format!("resource {kind}/{id} runs past the file's end"))?;
                Ok(Resource { language, data })
            })
            .collect()
    }
}

/// String `id` of a string table, given the block that holds it
/// (`RT_STRING` resource `id / 16 + 1`): each entry is a length in UTF-16
/// units and that many units.
pub fn table_string(block: &[u8], id: u16) -> Result<String, String> {
    let mut at = 0;
    for _ in 0..id % 16 {
        at += 2 + 2 * u16_at(block, at)? as usize;
    }
    let len = u16_at(block, at)? as usize;
    utf16(block, at + 2, len)
}

fn utf16(b: &[u8], at: usize, units: usize) -> Result<String, String> {
    let units = (0..units)
        .map(|i| u16_at(b, at + 2 * i))
        .collect::<Result<Vec<u16>, String>>()?;
    String::from_utf16(&units).map_err(|e| format!("a string at {at:#x}: {e}"))
}

/// A VS_VERSIONINFO: its fixed part and its strings.
pub struct VersionInfo {
    /// VS_FIXEDFILEINFO's file version: major, minor, patch, build.
    pub file_version: [u16; 4],
    /// Every StringFileInfo value, as (key, value), in file order.
    pub strings: Vec<(String, String)>,
}

impl VersionInfo {
    /// Reads a VS_VERSIONINFO resource.
    pub fn parse(data: &[u8]) -> Result<VersionInfo, String> {
        let root = Node::read(data, 0)?;
        if root.key != "VS_VERSION_INFO" {
            return Err(format!("the version resource starts with {:?}", root.key));
        }
        let fixed = root.value_at;
        if root.value_len < 52 || u32_at(data, fixed)? != 0xfeef_04bd {
            return Err("no VS_FIXEDFILEINFO (signature 0xfeef04bd)".into());
        }
        let (ms, ls) = (u32_at(data, fixed + 8)?, u32_at(data, fixed + 12)?);
        let file_version = [(ms >> 16) as u16, ms as u16, (ls >> 16) as u16, ls as u16];
        let mut strings = Vec::new();
        root.walk(data, &mut |node| {
            // Text values (type 1) are counted in UTF-16 units, NUL included.
            // Blocks (StringFileInfo, a language) are text-typed but hold no value.
            if node.text && node.value_len > 0 {
                let value = utf16(data, node.value_at, node.value_len)?;
                let value = value.trim_end_matches('\0').to_string();
                strings.push((node.key.clone(), value));
            }
            Ok(())
        })?;
        Ok(VersionInfo {
            file_version,
            strings,
        })
    }

    /// The value of `key` (e.g. "FileDescription"), if present.
    pub fn string(&self, key: &str) -> Option<&str> {
        self.strings
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }
}

/// One block of a VS_VERSIONINFO: length, value length, type, key, value,
/// children, each part aligned to 4 bytes.
struct Node {
    end: usize,
    key: String,
    text: bool,
    value_at: usize,
    /// In bytes for binary values, in UTF-16 units for text.
    value_len: usize,
    children_at: usize,
}

fn align4(at: usize) -> usize {
    (at + 3) & !3
}

impl Node {
    fn read(data: &[u8], at: usize) -> Result<Node, String> {
        let length = u16_at(data, at)? as usize;
        let value_len = u16_at(data, at + 2)? as usize;
        let text = u16_at(data, at + 4)? == 1;
        if length < 6 || at + length > data.len() {
            return Err(format!("a version block at {at:#x} has length {length}"));
        }
        let mut end_of_key = at + 6;
        while u16_at(data, end_of_key)? != 0 {
            end_of_key += 2;
        }
        let key = utf16(data, at + 6, (end_of_key - at - 6) / 2)?;
        let value_at = align4(end_of_key + 2);
        let value_bytes = if text { 2 * value_len } else { value_len };
        Ok(Node {
            end: at + length,
            key,
            text,
            value_at,
            value_len,
            children_at: align4(value_at + value_bytes),
        })
    }

    /// Calls `visit` on every block under this one, depth first.
    fn walk(
        &self,
        data: &[u8],
        visit: &mut dyn FnMut(&Node) -> Result<(), String>,
    ) -> Result<(), String> {
        let mut at = self.children_at;
        while at + 6 <= self.end {
            let child = Node::read(data, at)?;
            visit(&child)?;
            child.walk(data, visit)?;
            at = align4(child.end);
        }
        Ok(())
    }
}

/// One picture of an icon group: its size in pixels and its RT_ICON id.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GroupEntry {
    /// Width and height (256 is stored as 0).
    pub size: (u16, u16),
    /// Bits per pixel.
    pub bits: u16,
    /// The RT_ICON resource with the picture.
    pub icon_id: u16,
}

/// Reads a GRPICONDIR: a 6-byte header, then 14 bytes per picture.
pub fn icon_group(data: &[u8]) -> Result<Vec<GroupEntry>, String> {
    if u16_at(data, 2)? != 1 {
        return Err("the icon group's type is not 1 (icon)".into());
    }
    let count = u16_at(data, 4)? as usize;
    (0..count)
        .map(|i| {
            let e = 6 + 14 * i;
            let side = |b: u8| if b == 0 { 256 } else { u16::from(b) };
            let (w, h) = (
                *data.get(e).ok_or("icon group cut short")?,
                *data.get(e + 1).ok_or("icon group cut short")?,
            );
            Ok(GroupEntry {
                size: (side(w), side(h)),
                bits: u16_at(data, e + 6)?,
                icon_id: u16_at(data, e + 12)?,
            })
        })
        .collect()
}
