// Order statistics of measurements (timings, fractions): the benchmarks' medians and tails.
#pragma once

#include <vector>

namespace rs {

/// The median of `v`: its middle value, or the mean of the two middle values when their
/// count is even; 0 when `v` is empty.
double median(std::vector<double> v);

/// The q-quantile (0 <= q <= 1) of `v` by nearest rank: q = 1 is the largest value; 0 when
/// `v` is empty.
double quantile(std::vector<double> v, double q);

}  // namespace rs
