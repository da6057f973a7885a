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
    EXPECT_STREQ(e.what(), "unknown method \"Paper\" (fit, paper, noser, laplacian)");
  }
}

// The header's figures: paper and fit Q = I at 10⁴, noser 1.5·10³, laplacian 6·10⁵.
TEST(Method, OperatorOptionsAreTheDocumentedOnes) {
  EXPECT_EQ(operator_options(Method::paper).prior, Prior::identity);
  EXPECT_EQ(operator_options(Method::paper).lambda2, 1e4);
  EXPECT_EQ(operator_options(Method::fit).prior, Prior::identity);
  EXPECT_EQ(operator_options(Method::fit).lambda2, 1e4);
  EXPECT_EQ(operator_options(Method::noser).prior, Prior::noser);
  EXPECT_EQ(operator_options(Method::noser).lambda2, 1.5e3);
  EXPECT_EQ(operator_options(Method::laplacian).prior, Prior::laplacian);
  EXPECT_EQ(operator_options(Method::laplacian).lambda2, 6e5);
}

}  // namespace
}  // namespace emit
