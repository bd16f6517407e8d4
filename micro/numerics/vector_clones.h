// SOFTGLASS_VECTOR_CLONES marks a hot loop nest to be compiled three times — for
// x86-64 with AVX-512 (the x86-64-v4 level), with AVX2 and FMA (v3), and for the
// baseline the binary targets — one of which is chosen when the program loads,
// from the processor it runs on (GCC's function multiversioning: an ifunc
// resolver). The binary stays portable while a recent processor runs the
// vectorised square roots, divisions and powers 4 or 8 wide instead of 2.
// Used on the contact-force kernel and on the passes over the particles of the
// explicit step (moving; the velocities with the error estimate): with them, an
// explicit Hertz step at N = 1000 takes 36 ns per particle instead of 45. On a
// member function template the attribute belongs on the declaration in the
// class: on the definition alone GCC inlined the template uncloned, and the
// velocity pass ran baseline code unnoticed until 2026-12-02. The implicit
// solver is not cloned (built whole for x86-64-v4 it ran the trade bench's
// implicit runs no faster), except for the films' law over arrays that its
// evaluation of Φ calls (model/film.cpp).
// The variants may differ in the last bits (the wider ones contract a·b + c
// into one fused multiply-add), as results do between compilers — unless the
// file is compiled with -ffp-contract=off, as model/film.cpp is.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define SOFTGLASS_VECTOR_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define SOFTGLASS_VECTOR_CLONES
#endif
