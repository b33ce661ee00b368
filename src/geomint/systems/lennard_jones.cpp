// The Lennard-Jones cluster of 004 Fig. 6 (lennard_jones.hpp): its grid, the stiffness there and the perturbed starts.
#include "geomint/systems/lennard_jones.hpp"

#include <random>

#include "geomint/integrators/takahashi_imada_systems.hpp"
#include "geomint/observables/stiffness.hpp"

namespace geomint {

Vec<2> lennard_jones_grid(int k) { return Vec<2>(1 + k % 3, 1 + k / 3); }

double lennard_jones_grid_stiffness() {
  Vec<18> grid_q;
  for (int k = 0; k < 9; ++k) grid_q.segment<2>(2 * k) = lennard_jones_grid(k);
  return max_hessian_eigenvalue(LennardJones<9>{}, grid_q);
}

PhaseState<18> lennard_jones_grid_start(std::uint64_t seed, double perturbation, std::size_t i) {
  std::seed_seq seq{seed, static_cast<std::uint64_t>(i)};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> u(-perturbation, perturbation);
  PhaseState<18> z;
  for (int k = 0; k < 9; ++k) z.q[2 * k] = lennard_jones_grid(k)[0] + u(rng), z.q[2 * k + 1] = lennard_jones_grid(k)[1] + u(rng);
  return z;
}

}  // namespace geomint
