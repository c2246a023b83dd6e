#include "hyst/inverse/inverse_butterfly_strain.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <unsupported/Eigen/Polynomials>

namespace hyst {
namespace {

// The real roots of q'(P) = sum_n n q_n P^(n-1), increasing.
std::vector<double> slope_roots(const std::vector<double>& q) {
  Eigen::VectorXd slope(static_cast<Eigen::Index>(q.size()));
  for (std::size_t n = 0; n < q.size(); ++n)
    slope[static_cast<Eigen::Index>(n)] = static_cast<double>(n + 1) * q[n];
  Eigen::Index degree = slope.size() - 1;
  while (degree > 0 && slope[degree] == 0.0)
    --degree;
  std::vector<double> roots;
  if (degree == 0) return roots;
  Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(slope.head(degree + 1));
  solver.realRoots(roots);
  std::sort(roots.begin(), roots.end());
  return roots;
}

}  // namespace

InverseButterflyStrain::InverseButterflyStrain(ButterflyStrain model,
                                               const NumericalInverseOptions& options)
    : search_(std::move(model), options),
      critical_(slope_roots(search_.forward().params().polarisation_coefficients)),
      hold_default_(std::clamp(0.0, search_.input_min(), search_.input_max())) {}

bool InverseButterflyStrain::invertible_from(const State& state) const noexcept {
  const Preisach& polarisation = model().polarisation_model();
  const double p_lo = polarisation.preview(state, input_min());
  const double p_hi = polarisation.preview(state, input_max());
  for (double critical : critical_) {
    if (critical > p_lo && critical < p_hi) return false;
  }
  // No vertex inside: q' has one sign on [p_lo, p_hi]; the field term must not oppose it.
  const double d = model().params().field_coefficient;
  const double slope = model().strain_slope(0.5 * (p_lo + p_hi));
  return d * slope >= 0.0;
}

}  // namespace hyst
