// The benchmarks' order statistics: medians and nearest-rank quantiles.
#include "core/statistics.h"

#include <gtest/gtest.h>

namespace rs {
namespace {

TEST(Statistics, MedianIsTheMiddleValueOrTheMeanOfTheTwoMiddleOnes) {
    EXPECT_EQ(median({3.0, 1.0, 2.0}), 2.0);
    EXPECT_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
    EXPECT_EQ(median({7.0}), 7.0);
    EXPECT_EQ(median({}), 0.0);
}

TEST(Statistics, QuantileIsTheNearestRank) {
    std::vector<double> v;
    for (int k = 10; k >= 0; --k) v.push_back(double(k));  // 0 ... 10, out of order
    EXPECT_EQ(quantile(v, 0.0), 0.0);
    EXPECT_EQ(quantile(v, 0.9), 9.0);
    EXPECT_EQ(quantile(v, 0.94), 9.0);  // rank 9.4 rounds to 9
    EXPECT_EQ(quantile(v, 0.96), 10.0);
    EXPECT_EQ(quantile(v, 1.0), 10.0);
    EXPECT_EQ(quantile({}, 0.5), 0.0);
}

}  // namespace
}  // namespace rs
