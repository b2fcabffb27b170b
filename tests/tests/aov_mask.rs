//! `AovMask` at its edges: index `MAX_AOVS` and above is outside the mask (never
//! contained, ignored on insert and collect), and the mask is exactly `MAX_AOVS` bits
//! wide (it is copied into every match result, so its size is part of the contract).

use lpe::{AovMask, MAX_AOVS};

#[test]
fn indices_past_the_width_are_outside_the_mask() {
    assert_eq!(MAX_AOVS, 256);
    let mut m = AovMask::EMPTY;
    m.insert(255);
    m.insert(256);
    m.insert(1000);
    assert!(m.contains(255));
    assert!(!m.contains(256));
    assert!(!m.contains(usize::MAX));
    assert_eq!(m.count(), 1);
    assert_eq!(m.iter().collect::<Vec<_>>(), [255]);

    let c: AovMask = [0usize, 64, 256, 7].into_iter().collect();
    assert_eq!(c.iter().collect::<Vec<_>>(), [0, 7, 64]);
    assert_eq!(c.count(), 3);
    assert!(!c.is_empty());
    assert!(AovMask::EMPTY.is_empty());
    assert_eq!(AovMask::default(), AovMask::EMPTY);
}

#[test]
fn the_mask_is_max_aovs_bits_wide() {
    assert_eq!(std::mem::size_of::<AovMask>(), MAX_AOVS / 8);
}
