//! The build script: the crate is compiled again when a language catalogue changes.
//! `rust_i18n::i18n!` (src/lib.rs) reads `locales/` while the crate compiles, but cargo does
//! not know the crate depends on those files: an edited catalogue left binaries with the old
//! strings (a test binary's figures then disagreed with the app's).

fn main() {
    println!("cargo:rerun-if-changed=locales");
}
