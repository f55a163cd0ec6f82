//! libFuzzer entry point; the body is `harness/readers.rs`, which
//! `tests/fuzz_corpus.rs` also runs over the committed corpus on stable.
#![no_main]

#[path = "../harness/readers.rs"]
mod harness;

libfuzzer_sys::fuzz_target!(|data: &[u8]| harness::run(data));
