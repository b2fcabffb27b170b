//! Bitsets stored as `u64` words: bit `i` is bit `i % 64` of word `i / 64`. NFA states,
//! follow rows, class signatures and AOV masks all use this layout.

#[inline]
pub(crate) fn set(bits: &mut [u64], i: usize) {
    bits[i / 64] |= 1 << (i % 64);
}

#[inline]
pub(crate) fn get(bits: &[u64], i: usize) -> bool {
    bits[i / 64] >> (i % 64) & 1 == 1
}

/// The set bits, in increasing order. Takes words by value so that callers can iterate
/// a combination of bitsets (`a & b`) without materializing it.
pub(crate) fn ones(words: impl IntoIterator<Item = u64>) -> impl Iterator<Item = usize> {
    words.into_iter().enumerate().flat_map(|(w, mut x)| {
        std::iter::from_fn(move || {
            (x != 0).then(|| {
                let b = x.trailing_zeros() as usize;
                x &= x - 1;
                w * 64 + b
            })
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn set_get_and_ones_agree() {
        let mut b = [0u64; 3];
        for i in [0, 63, 64, 130, 191] {
            set(&mut b, i);
        }
        assert!(get(&b, 63) && get(&b, 64) && !get(&b, 5) && !get(&b, 1));
        assert_eq!(ones(b).collect::<Vec<_>>(), [0, 63, 64, 130, 191]);
        assert_eq!(ones([0u64; 2]).count(), 0);
    }
}
