#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| geocert_fuzz::targets::linear(data));
