#pragma once
/// \file method.hpp
/// The reconstruction methods, by name in one place: the CLI's --method, the calibration each
/// needs, and the linear operator each applies (README, "Reconstruction methods").
#include <string>
#include <vector>

#include "emit/model/reconstruction_operator.hpp"

namespace emit {

enum class Method {
  fit,        ///< model-based contact fitting (frame/contact_fitter.hpp), seeded by the paper method's image
  shapes,     ///< contact fitting, each contact then refitted as an ellipse (frame/shape_refiner.hpp)
  paper,      ///< paper eq. 7 with Q = I, a 50 % threshold, eq. 8
  noser,      ///< eq. 7 with the NOSER prior
  laplacian,  ///< eq. 7 with the element Laplacian as the prior (smooth images)
};

/// The linear methods apply an operator to each frame (eq. 7); contact fitting fits a model.
constexpr bool is_linear(Method method) { return method != Method::fit && method != Method::shapes; }

/// Every method, in the order the CLI and the docs list them.
inline constexpr Method all_methods[] = {Method::fit, Method::shapes, Method::paper, Method::noser, Method::laplacian};

/// "fit", "shapes", "paper", "noser", "laplacian".
const char* method_name(Method method);

/// Every method's name, in all_methods' order (the CLI's --method choices, Python's emit.methods()).
std::vector<std::string> method_names();

/// The method named `name`. \throw InvalidInput naming it and the methods there are.
Method parse_method(const std::string& name);

/// The linear operator a method applies: its prior, with λ² left to the rule (lambda_rule.hpp)
/// at the multiple of the spectrum's scale `emit eval` measured best on the 60 mm, 30 mm,
/// circle and 120 mm sheets (paper 1.63, noser 2.4, laplacian 1.27). Contact fitting is seeded by the paper
/// method's image, so `fit` and `shapes` get the paper method's operator.
OperatorOptions operator_options(Method method);

}  // namespace emit
