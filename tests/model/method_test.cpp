// The methods by name (model/method.hpp): names round trip, an unknown one is refused naming the
// choices, and each linear method gets its documented prior and λ².
#include "emit/model/method.hpp"

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"

namespace emit {
namespace {

TEST(Method, NamesRoundTrip) {
  for (Method method : {Method::fit, Method::paper, Method::noser, Method::laplacian})
    EXPECT_EQ(parse_method(method_name(method)), method);
  EXPECT_STREQ(method_name(Method::laplacian), "laplacian");
  EXPECT_FALSE(is_linear(Method::fit));
  EXPECT_TRUE(is_linear(Method::noser));
}

TEST(Method, UnknownNameListsTheMethods) {
  try {
    parse_method("Paper");
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "unknown method \"Paper\" (fit, shapes, paper, noser, laplacian)");
  }
}

// The header's figures: λ² left to the rule (0) at paper and fit 1.63, noser 2.4, laplacian
// 1.27 times the spectrum's scale.
TEST(Method, OperatorOptionsAreTheDocumentedOnes) {
  EXPECT_EQ(operator_options(Method::paper).prior, Prior::identity);
  EXPECT_EQ(operator_options(Method::paper).lambda2, 0.0);
  EXPECT_EQ(operator_options(Method::paper).relative_lambda2, 1.63);
  EXPECT_EQ(operator_options(Method::fit).prior, Prior::identity);
  EXPECT_EQ(operator_options(Method::fit).relative_lambda2, 1.63);
  EXPECT_EQ(operator_options(Method::noser).prior, Prior::noser);
  EXPECT_EQ(operator_options(Method::noser).relative_lambda2, 2.4);
  EXPECT_EQ(operator_options(Method::laplacian).prior, Prior::laplacian);
  EXPECT_EQ(operator_options(Method::laplacian).relative_lambda2, 1.27);
}

}  // namespace
}  // namespace emit
