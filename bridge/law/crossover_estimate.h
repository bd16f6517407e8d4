// The crossover strain of an amplitude sweep, estimated from the flow law
// alone (docs/oscillation.md, "The crossover against the flow curve's yield
// strain").
//
// An elastic–perfectly-plastic solid of modulus G0 and flow stress σ_f,
// strained γ0 sin θ, follows σ = G0 γ up to ±σ_f and flows there: past
// x = γ0/γ_f = 1 (γ_f = σ_f/G0) its periodic loop is a parallelogram. On the
// half cycle θ ∈ [π/2, 3π/2] (the other half is its mirror image) it unloads
// elastically, σ = σ_f − G0 γ0 (1 − sin θ), until σ = −σ_f at
// sin θ₁ = 1 − 2/x, and then flows at −σ_f. With σ = γ0 (G′ sin θ + G″ cos θ)
// + higher harmonics, the first harmonic is
//     G′ γ0 = (2/π) ∫_{π/2}^{3π/2} σ sin θ dθ,   G″ γ0 = (2/π) ∫_{π/2}^{3π/2} σ cos θ dθ,
// integrals of sin, sin², cos and sin cos over the two segments, in closed
// form. G′ falls from G0 as x grows, G″ rises from 0 and then falls like
// 4/(πx), G′ faster (like x^{−3/2}): they cross once, at x* (computed here).
//
// A soft glass's flow stress depends on the rate. At the cycle's peak rate
// γ0 ω, the universal law gives σ_f = σ_y (1 + k (γ0 ω̃)^½/γ_y) (ω̃ = ωη_s/E*),
// so the crossover strain γ_c solves γ_c = x* (γ_y + k (γ_c ω̃)^½): a
// quadratic in s = γ_c^½ with the positive root
//     s = ½ [a + (a² + 4 x* γ_y)^½],   a = x* k ω̃^½.
// On the project's own amplitude sweeps (N = 250, φ = 0.80 and 0.85, ω̃ =
// 2.31e-7), with k and γ_y of the bundled law, this is within 10 % of the
// simulated crossover (−10 %, +2 %).
#pragma once

namespace softglass::bridge {

/// First-harmonic moduli in units of G0.
struct ElastoplasticModuli {
  double storage = 1.0, loss = 0.0;
};

/// G′/G0 and G″/G0 of the elastic–perfectly-plastic loop at x = γ0/γ_f > 0
/// (purely elastic, 1 and 0, for x ≤ 1).
ElastoplasticModuli elastoplastic_moduli(double amplitude_ratio);

/// x* where the loop's G′ = G″.
double elastoplastic_crossover_ratio();

/// The crossover strain at the reduced frequency ω̃ ≥ 0 of a material with
/// yield strain γ_y > 0 and universal constant k ≥ 0 (above).
double crossover_strain_estimate(double yield_strain, double k, double reduced_frequency);

}  // namespace softglass::bridge
