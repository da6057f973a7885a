#include "emit/model/lambda_rule.hpp"

#include <cmath>
#include <string>

#include "emit/core/errors.hpp"

namespace emit {

double spectrum_scale(const Vector& eigenvalues) {
  if (eigenvalues.size() < 2) return 0.0;
  double largest = 0, second = 0;
  for (Index i = 0; i < eigenvalues.size(); ++i) {
    const double s = eigenvalues[i];
    if (s > largest) second = largest, largest = s;
    else if (s > second) second = s;
  }
  return second;
}

double automatic_lambda2(const Vector& eigenvalues, double relative) {
  if (!(relative > 0) || !std::isfinite(relative))
    throw InvalidInput("the relative lambda2 must be positive, got " + std::to_string(relative));
  const double scale = spectrum_scale(eigenvalues);
  if (!(scale > 0))
    throw InvalidInput("the Jacobian has no spectrum to choose lambda2 from (its second eigenvalue is 0)");
  return relative * scale;
}

}  // namespace emit
