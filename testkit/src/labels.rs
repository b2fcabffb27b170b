//! Labels that differ from each other in one byte only, at every position and of every
//! length from 0 to past the width of a label key, UTF-8 included: for tests that label
//! interning, class splitting and every classifier keep such labels apart (a key fault
//! shows only on labels alike in the bytes the key reads).

/// Bytes from which labels are built; `Z` and `Y` are left out, so a label with one of
/// them at a position differs from the base there.
const BYTES: &[u8] = b"abcdefghijklmnopqrstuvwxyz0123456789ABCDEFGHIJKLMNOPQRSTUVWX";

/// A group of labels: the set's labels (base first) and labels the set does not name.
pub struct Group {
    /// The labels a set names, the base first.
    pub named: Vec<String>,
    /// Labels one byte off the base elsewhere, which the set does not name.
    pub unnamed: Vec<String>,
}

fn set_byte(base: &str, i: usize, b: u8) -> String {
    let mut v = base.as_bytes().to_vec();
    v[i] = b;
    String::from_utf8(v).unwrap()
}

/// For every length from 0 to 40 bytes (past the 16 bytes RenderMan's label key holds
/// whole): the base, the base with each one byte changed, one byte shorter and one longer.
pub fn ascii_groups() -> Vec<Group> {
    (0..=40)
        .map(|len| {
            let base = String::from_utf8(BYTES[..len].to_vec()).unwrap();
            let mut named = vec![base.clone()];
            named.extend((0..len).map(|i| set_byte(&base, i, b'Z')));
            if len > 0 {
                named.push(base[..len - 1].to_string());
            }
            named.push(format!("{base}Z"));
            let mut unnamed: Vec<String> = (0..len).map(|i| set_byte(&base, i, b'Y')).collect();
            unnamed.push(format!("{base}Y"));
            Group { named, unnamed }
        })
        .collect()
}

/// UTF-8 labels of 0 to 13 three-byte characters: the variants change one character's
/// last byte. `光` is E5 85 89; `兊` (E5 85 8A) and `兌` (E5 85 8C) differ from it in the last byte.
pub fn utf8_groups() -> Vec<Group> {
    (0..=13)
        .map(|n| {
            let base: String = "光".repeat(n);
            let swap = |k: usize, c: &str| -> String {
                base.chars()
                    .enumerate()
                    .map(|(i, x)| if i == k { c.to_string() } else { x.to_string() })
                    .collect()
            };
            let mut named = vec![base.clone()];
            named.extend((0..n).map(|k| swap(k, "兊")));
            named.push(format!("{base}光"));
            let mut unnamed: Vec<String> = (0..n).map(|k| swap(k, "兌")).collect();
            unnamed.push(format!("{base}兌"));
            Group { named, unnamed }
        })
        .collect()
}

/// Every group, ASCII then UTF-8.
pub fn groups() -> Vec<Group> {
    ascii_groups().into_iter().chain(utf8_groups()).collect()
}

/// Labels [`groups`] checks, counted per set: 41 ASCII groups of 2n+3 labels (n = 0..=40;
/// one more, the shorter base, for n > 0) and 14 UTF-8 groups of 2n+3 (n = 0..=13).
pub const LABELS_CHECKED: usize = 41 * 3 + 2 * 820 + 40 + 14 * 3 + 2 * 91;
