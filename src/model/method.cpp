#include "emit/model/method.hpp"

#include "emit/core/errors.hpp"

namespace emit {

const char* method_name(Method method) {
  switch (method) {
    case Method::fit: return "fit";
    case Method::paper: return "paper";
    case Method::noser: return "noser";
    case Method::laplacian: return "laplacian";
  }
  return "?";
}

Method parse_method(const std::string& name) {
  for (Method method : {Method::fit, Method::paper, Method::noser, Method::laplacian})
    if (name == method_name(method)) return method;
  throw InvalidInput("unknown method \"" + name + "\" (fit, paper, noser, laplacian)");
}

OperatorOptions operator_options(Method method) {
  OperatorOptions options;  // Q = I: the paper's method
  options.relative_lambda2 = 1.63;
  if (method == Method::noser) {
    options.prior = Prior::noser;
    options.relative_lambda2 = 2.4;
  } else if (method == Method::laplacian) {
    options.prior = Prior::laplacian;
    options.relative_lambda2 = 1.27;
  }
  return options;
}

}  // namespace emit
