// SOFTGLASS_VECTOR_CLONES marks a hot loop nest to be compiled three times — for
// x86-64 with AVX-512 (the x86-64-v4 level), with AVX2 and FMA (v3), and for the
// baseline the binary targets — one of which is chosen when the program loads,
// from the processor it runs on (GCC's function multiversioning: an ifunc
// resolver). The binary stays portable while a recent processor runs the
// vectorised square roots, divisions and powers 4 or 8 wide instead of 2.
// Used on the contact-force kernel and on the passes over the particles of the
// explicit step (moving; the velocities with the error estimate), where the
// wider registers pay (bench/results/lammps_comparison-2026-11-28.md). On a
// member function template the attribute belongs on the declaration in the
// class: on the definition alone GCC inlines the template uncloned, and the
// pass runs baseline code with nothing to show it. The implicit solver is not
// cloned (a whole x86-64-v4 build ran the trade bench's implicit runs no
// faster, same log), except for the films' law over arrays that its
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
