// The reconstruction operator in measurement space equals paper eq. 7's K×K form.
#include "emit/model/reconstruction_operator.hpp"
#include "emit/model/method.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "emit/core/errors.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/model/jacobian.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "tolerances.hpp"

namespace emit {
namespace {

struct Small {
  Mesh mesh;
  Matrix J;
  Small() {
    MeshOptions options;
    options.element_size_mm = 8.0;
    mesh = generate_mesh(default_sensor(), options);
    J = compute_jacobian(mesh, make_measurement_set(16));
  }
};

Matrix dense_prior(const Small& s, const OperatorOptions& options) {
  switch (options.prior) {
    case Prior::identity: return Matrix::Identity(s.J.cols(), s.J.cols());
    case Prior::noser:
      return Vector(s.J.colwise().squaredNorm().transpose().array().pow(options.noser_exponent)).asDiagonal();
    case Prior::laplacian: {
      const Matrix L(element_laplacian(s.mesh));
      Matrix Q = L.transpose() * L;
      Q.diagonal().array() += 1e-3 * Q.diagonal().mean();
      return Q;
    }
  }
  return {};
}

class OperatorForms : public ::testing::TestWithParam<Prior> {};

// (JᵀJ + λ²Q)⁻¹Jᵀ = Q⁻¹Jᵀ(JQ⁻¹Jᵀ + λ²I)⁻¹ (push-through identity): the two agree to the
// round-off of solving a system of condition ~ ‖JᵀJ‖/λ².
TEST_P(OperatorForms, MeasurementSpaceEqualsEquation7) {
  const Small s;
  OperatorOptions options;
  options.prior = GetParam();
  options.lambda2 = 10.0;
  const Matrix R = build_reconstruction_operator(s.J, s.mesh, options);
  const Matrix Q = dense_prior(s, options);
  const Matrix direct = (s.J.transpose() * s.J + options.lambda2 * Q).ldlt().solve(s.J.transpose());
  EXPECT_LE((R - direct).cwiseAbs().maxCoeff(), 1e-8 * direct.cwiseAbs().maxCoeff()) << prior_name(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Priors, OperatorForms, ::testing::Values(Prior::identity, Prior::noser, Prior::laplacian),
                         [](const auto& info) { return prior_name(info.param); });

TEST(ReconstructionOperator, MethodsAndBadLambda) {
  EXPECT_EQ(operator_options(Method::paper).lambda2, 0.0);  // chosen by the rule (lambda_rule.hpp)
  EXPECT_EQ(operator_options(Method::paper).prior, Prior::identity);
  EXPECT_EQ(operator_options(Method::fit).prior, Prior::identity);  // fit is seeded by the paper's image
  EXPECT_EQ(operator_options(Method::noser).prior, Prior::noser);
  EXPECT_EQ(operator_options(Method::laplacian).prior, Prior::laplacian);
  for (Method m : {Method::fit, Method::paper, Method::noser, Method::laplacian})
    EXPECT_EQ(parse_method(method_name(m)), m);
  EXPECT_THROW(parse_method("magic"), InvalidInput);
  const Small s;
  OperatorOptions bad;
  bad.lambda2 = -1;
  EXPECT_THROW(build_reconstruction_operator(s.J, s.mesh, bad), InvalidInput);
}

// The element Laplacian annihilates constants and each interior triangle has 3 neighbours.
TEST(ReconstructionOperator, ElementLaplacian) {
  const Small s;
  const SparseMatrix L = element_laplacian(s.mesh);
  EXPECT_EQ((L * Vector::Ones(L.cols())).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(L.diagonal().maxCoeff(), 3.0);
}

}  // namespace
}  // namespace emit
