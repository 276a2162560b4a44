// The median of a list of numbers (the mean of the middle two for an even count; 0 for none):
// how frame and pass times are summarised, robust to the odd stalled frame.
#pragma once

#include <algorithm>
#include <vector>

namespace gi::core {

[[nodiscard]] inline double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const std::size_t middle = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(middle), values.end());
    const double upper = values[middle];
    if (values.size() % 2) return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + std::ptrdiff_t(middle));
    return 0.5 * (lower + upper);
}

} // namespace gi::core
