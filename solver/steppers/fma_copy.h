// Whether this build compiles the AVX2 + FMA copy of solver/steppers/dop853_fma.h: read by the
// copy's unit and by machine_code.cc only, so the choice changes two files.
#pragma once

// Whether this build compiles the copy for AVX2 + FMA: x86-64, GCC-compatible, optimised and not
// under AddressSanitizer. Unoptimised or instrumented code leaves small template functions of
// shared types out of line (the ASan build emitted CrossingTolerance<double>::operator() from the
// copy with AVX code, caught by cpu_clone_symbols), so there the copy is baseline code and
// cpu_has_fma_clone() is false.
#if defined(__x86_64__) && defined(__GNUC__) && defined(__OPTIMIZE__) && \
    !defined(__SANITIZE_ADDRESS__)
#define IVV_FMA_COPY 1
#else
#define IVV_FMA_COPY 0
#endif
