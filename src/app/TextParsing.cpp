#include "app/TextParsing.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace gi::app {

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream stream(text);
    while (std::getline(stream, part, separator)) parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.emplace_back();
    return parts;
}

bool parseFloat(const std::string& text, float& value) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

bool parseInt(const std::string& text, int& value) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size();
}

bool parseFloats(const std::string& text, std::size_t count, std::vector<float>& values) {
    const std::vector<std::string> parts = split(text, ',');
    if (parts.size() != count) return false;
    values.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        if (!parseFloat(parts[i], values[i])) return false;
    }
    return true;
}

bool parseVec3(const std::string& text, glm::vec3& v) {
    std::vector<float> values;
    if (!parseFloats(text, 3, values)) return false;
    v = {values[0], values[1], values[2]};
    return true;
}

} // namespace gi::app

