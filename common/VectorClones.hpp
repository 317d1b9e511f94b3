// A function marked ARP_VECTOR_CLONES is compiled twice, for x86-64 with AVX-512 (x86-64-v4) and for the
// baseline, and the loader picks the clone the machine runs: its loops vectorise with 64-byte vectors,
// gathers and double <-> 64-bit integer conversions where the CPU has them, and the binary still runs
// anywhere. Off under ASan (the sanitizer build checks the one baseline body), off x86-64, and off with
// clang: clang 14 names a clone set's dispatcher `f.ifunc` and emits no `f`, so a call from another
// source file does not link (the fuzz build, clang, failed so from 2026-11-26, DepthCode::codes).
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define ARP_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "default")))
#else
#define ARP_VECTOR_CLONES
#endif
