// The per-frame form of the reconstruction operator: truncated and in single precision, it must
// stay within the bound it documents of the full operator, on real frames, whether it is built
// from R or straight from the eigendecomposition (for each prior).
#include "emit/model/compact_operator.hpp"
#include "emit/model/method.hpp"

#include <gtest/gtest.h>
#include <Eigen/SVD>

#include "emit/core/errors.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/model/jacobian.hpp"
#include "emit/model/reconstruction_model.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/twin.hpp"

namespace emit {
namespace {

// Single precision adds to the truncation bound a rounding of about k·2⁻²⁴ ≈ 1e-5 (k ≤ 240
// products of float values, relative to s₁‖δV‖); 3e-5 leaves room for its accumulation.
constexpr double float_rounding = 3e-5;

struct Frames {
  Sensor sensor = default_sensor();
  ReconstructionModel model;
  Matrix J;
  Matrix R;  ///< the dense operator
  std::vector<Vector> differences;
  Frames() {
    sensor.mesh.element_size_mm = 3.0;
    model = build_reconstruction_model(sensor, operator_options(Method::paper), "");
    J = compute_jacobian(model.mesh, model.measurements);
    R = build_reconstruction_operator(J, model.mesh, model.options);
    Twin twin(sensor);
    const Frame reference = twin.frame({});
    for (const auto& presses : std::vector<std::vector<Press>>{{{30, 30, 5, 10}},
                                                               {{8, 50, 4, 20}},
                                                               {{15, 15, 5, 5}, {45, 40, 5, 30}},
                                                               {{55, 30, 3, 2}}})
      differences.push_back(frame_difference(model.measurements, twin.frame(presses), reference));
  }
};

/// ‖compact·δV − R·δV‖ / (s₁‖δV‖), the worst over the frames.
double worst_relative_change(const Frames& f, const Matrix& R, const CompactOperator& compact) {
  CompactOperatorScratch scratch;
  Vector image;
  double worst = 0;
  for (const Vector& dV : f.differences) {
    compact.apply(dV, image, scratch);
    const Vector full = R * dV;
    worst = std::max(worst, (image - full).norm() / (compact.largest_singular_value() * dV.norm()));
  }
  return worst;
}

TEST(CompactOperator, StaysWithinItsBoundOfTheFullOperator) {
  const Frames f;
  const CompactOperator& compact = f.model.op;
  // The point of it: far fewer than M = 240 singular values matter (~106 on the default mesh).
  EXPECT_LT(compact.rank(), compact.cols() / 2);
  EXPECT_LE(compact.truncation_bound(), 1.0 / 4096);
  const double change = worst_relative_change(f, f.R, compact);
  std::printf("rank %lld of %lld, bound %.2e, worst change on frames %.2e\n", static_cast<long long>(compact.rank()),
              static_cast<long long>(compact.cols()), compact.truncation_bound(), change);
  EXPECT_LE(change, compact.truncation_bound() + float_rounding);
}

TEST(CompactOperator, KeepsEverySingularValueWithoutACutoff) {
  const Frames f;
  const OperatorFamily family(f.J, f.model.mesh, Prior::identity);
  const CompactOperator untruncated = family.compact_operator_for(f.model.options.lambda2, 0.0);
  EXPECT_EQ(untruncated.truncation_bound(), 0.0);
  EXPECT_LE(worst_relative_change(f, f.R, untruncated), float_rounding);
}

// Built from the eigendecomposition (no R formed), for the priors whose Q⁻¹Jᵀ columns are not
// orthogonal too: the same bound against each prior's dense R, and R's own SVD's largest
// singular value and count above the cutoff (the same numbers computed another way; one value
// sitting at the cutoff may fall either side of it).
TEST(CompactOperator, FromTheEigendecompositionForEachPrior) {
  const Frames f;
  for (const Method m : {Method::paper, Method::noser, Method::laplacian}) {
    const OperatorOptions options = operator_options(m);
    const std::string method = method_name(m);
    const OperatorFamily family(f.J, f.model.mesh, options.prior, options.noser_exponent);
    const double lambda2 = family.lambda2_for(options);  // the rule's (options.lambda2 is 0)
    const Matrix R = family.operator_for(lambda2);
    const CompactOperator direct = family.compact_operator_for(lambda2, options.rank_cutoff);
    EXPECT_EQ(direct.lambda2(), lambda2) << method;
    const Vector s = Eigen::BDCSVD<Matrix>(R).singularValues();  // descending
    const auto above = (s.array() > options.rank_cutoff * s[0]).count();
    EXPECT_NEAR(direct.largest_singular_value(), s[0], 1e-9 * s[0]) << method;
    EXPECT_NEAR(static_cast<double>(direct.rank()), static_cast<double>(above), 1.0) << method;
    EXPECT_LE(worst_relative_change(f, R, direct), direct.truncation_bound() + float_rounding) << method;
  }
}

TEST(CompactOperator, RejectsABadCutoffMismatchedFactorsAndAFrameOfTheWrongSize) {
  const Frames f;
  const OperatorFamily family(f.J, f.model.mesh, Prior::identity);
  EXPECT_THROW(family.compact_operator_for(1e4, 1.0), InvalidInput);
  EXPECT_THROW(family.compact_operator_for(1e4, -0.1), InvalidInput);
  EXPECT_THROW(CompactOperator(Eigen::MatrixXf(10, 3), Eigen::MatrixXf(4, 8), 0, 1), InvalidInput);
  CompactOperatorScratch scratch;
  Vector image;
  EXPECT_THROW(f.model.op.apply(Vector::Zero(7), image, scratch), InvalidInput);
}

}  // namespace
}  // namespace emit
