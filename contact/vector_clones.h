// Function multiversioning for tribo's cell loops: a function marked TRIBO_VECTOR_CLONES is
// compiled for AVX-512 (x86-64-v4), AVX2 and baseline x86-64, and the CPU picks one at load time.
// The loops it is for are selects, min/max, sums and short fixed-length moves: baseline SSE2 has
// no blend and two lanes and runs them compute-bound at 2–3× AVX2's time, and AVX-512's eight
// lanes and mask registers take the normal solve's trial pass from 14 % to 8 % of an elastic
// 1024² solve (bench/README.md), while the FFTs they sit between already run FFTW's AVX codelets.
// Build such loops with -fno-trapping-math (contact/CMakeLists.txt), or GCC keeps their selects
// as branches and does not vectorise them.
#pragma once

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define TRIBO_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define TRIBO_VECTOR_CLONES
#endif
