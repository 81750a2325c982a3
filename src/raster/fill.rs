//! The band's clear as one fill per buffer ([`fill_words`]).

/// A value of four bytes that is nothing but its bits: a packed colour or a depth, which
/// [`fill_words`] writes as `u32`s.
pub(super) trait Word: Copy {
    /// The value's bits.
    #[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
    fn word(self) -> u32;
}

impl Word for [u8; 4] {
    fn word(self) -> u32 {
        u32::from_le_bytes(self)
    }
}

impl Word for f32 {
    fn word(self) -> u32 {
        self.to_bits()
    }
}

/// Sets every value of `values` to `value`: the band's clear of its colour and depth, which
/// writes every byte of a band (a band of the 1080p fast path is about 0.5 MB) once per frame.
/// On x86_64 one `rep stosd`, whose fast-string stores write whole cache lines (about a fifth
/// less time than the 16-byte vector stores of `slice::fill` in a stand-alone test clearing
/// 1080p bands here, the lines staying in cache for the drawing); elsewhere `slice::fill`.
/// The same values either way.
#[inline]
pub(super) fn fill_words<T: Word>(values: &mut [T], value: T) {
    const { assert!(size_of::<T>() == 4) };
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: `rep stosd` stores `eax` (the value's bits) into `rcx` consecutive 4-byte
        // values from `rdi`: the slice's own values (`T` is 4 bytes, checked above, and these
        // bits are `value`'s own); the direction flag is clear at every call (the ABI), the
        // flags are otherwise untouched and no stack is used.
        unsafe {
            std::arch::asm!(
                "rep stosd",
                inout("rcx") values.len() => _,
                inout("rdi") values.as_mut_ptr() => _,
                in("eax") value.word(),
                options(nostack, preserves_flags),
            );
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    values.fill(value);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The clear's fill writes exactly the values of the slice it is given, every one of them
    /// (odd lengths, an empty slice), and nothing beside them.
    #[test]
    fn fill_words_sets_every_value_and_nothing_else() {
        for len in [0usize, 1, 3, 17, 1000] {
            let mut colors = vec![[7u8, 7, 7, 7]; len + 2];
            fill_words(&mut colors[1..=len], [1, 2, 3, 255]);
            assert_eq!(colors[0], [7; 4], "{len}");
            assert_eq!(colors[len + 1], [7; 4], "{len}");
            assert!(
                colors[1..=len].iter().all(|&c| c == [1, 2, 3, 255]),
                "{len}"
            );
            let mut depths = vec![0.5f32; len + 2];
            fill_words(&mut depths[1..=len], 1.0);
            assert_eq!((depths[0], depths[len + 1]), (0.5, 0.5), "{len}");
            assert!(
                depths[1..=len]
                    .iter()
                    .all(|&d| d.to_bits() == 1.0f32.to_bits()),
                "{len}"
            );
        }
    }
}
