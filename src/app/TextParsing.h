// Strict parsing of command-line values: the whole text must be the number (or the comma list
// of them), and floats must be finite.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace gi::app {

// The pieces between separators; a trailing separator gives a trailing empty piece.
[[nodiscard]] std::vector<std::string> split(const std::string& text, char separator);

[[nodiscard]] bool parseFloat(const std::string& text, float& value);
[[nodiscard]] bool parseInt(const std::string& text, int& value);
// Exactly `count` comma-separated floats.
[[nodiscard]] bool parseFloats(const std::string& text, std::size_t count,
        std::vector<float>& values);
[[nodiscard]] bool parseVec3(const std::string& text, glm::vec3& v);

} // namespace gi::app
