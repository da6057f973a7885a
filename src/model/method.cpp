#include "emit/model/method.hpp"

#include "emit/core/errors.hpp"

namespace emit {

const char* method_name(Method method) {
  switch (method) {
    case Method::fit: return "fit";
    case Method::shapes: return "shapes";
    case Method::paper: return "paper";
    case Method::noser: return "noser";
    case Method::laplacian: return "laplacian";
  }
  return "?";
}

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const Method method : all_methods) names.emplace_back(method_name(method));
  return names;
}

Method parse_method(const std::string& name) {
  std::string choices;
  for (const Method method : all_methods) {
    if (name == method_name(method)) return method;
    choices += (choices.empty() ? "" : ", ") + std::string(method_name(method));
  }
  throw InvalidInput("unknown method \"" + name + "\" (" + choices + ")");
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
