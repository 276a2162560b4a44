#include "app/LightSpec.h"

#include "app/TextParsing.h"

#include <array>
#include <cmath>
#include <vector>

namespace gi::app {
namespace {

bool parseDirection(const std::string& part, glm::vec3& direction) {
    glm::vec3 d;
    if (!parseVec3(part, d) || glm::length(d) < 1e-12f) return false;
    direction = glm::normalize(d);
    return true;
}

// A colour (r,g,b) and a scale, both non-negative and finite.
bool parseColorAndScale(const std::string& color, const std::string& scale, glm::vec3& rgb,
        float& value) {
    return parseVec3(color, rgb) && parseFloat(scale, value) && value >= 0.0f &&
           rgb.r >= 0.0f && rgb.g >= 0.0f && rgb.b >= 0.0f;
}

bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// rect:cx,cy,cz:ux,uy,uz:vx,vy,vz:r,g,b:radiance. The corners run counter-clockwise seen
// from the side cross(u, v) points to, which is the emitting side (DESIGN: front faces emit).
bool parseRect(const std::vector<std::string>& parts, const std::string& text,
        scene::Light& light, std::string& error) {
    glm::vec3 centre, u, v, color;
    float radiance = 0.0f;
    if (!parseVec3(parts[1], centre) || !parseVec3(parts[2], u) || !parseVec3(parts[3], v) ||
            !parseColorAndScale(parts[4], parts[5], color, radiance)) {
        return false;
    }
    const glm::vec3 normal = glm::cross(u, v);
    const float area = glm::length(normal);
    const glm::vec3 corners[4] = {centre - 0.5f * u - 0.5f * v, centre + 0.5f * u - 0.5f * v,
            centre + 0.5f * u + 0.5f * v, centre - 0.5f * u + 0.5f * v};
    bool finite = std::isfinite(area) && isFinite(normal);
    for (const glm::vec3& corner : corners) finite = finite && isFinite(corner);
    if (!(area > 0.0f) || !finite) {
        error = "--light '" + text + "': the rectangle's edges u and v must span a non-zero, "
                "finite area";
        return false;
    }
    light.type = scene::LightType::Area;
    light.position = centre;
    light.direction = normal / area;
    for (const auto& [a, b, c] : {std::array{0, 1, 2}, std::array{0, 2, 3}}) {
        scene::EmitterTriangle triangle;
        triangle.p0 = corners[a];
        triangle.p1 = corners[b];
        triangle.p2 = corners[c];
        triangle.radiance = color * radiance;
        light.emitters.push_back(triangle);
    }
    return true;
}

} // namespace

bool parseLightSpec(const std::string& text, scene::Light& light, std::string& error) {
    const std::vector<std::string> parts = split(text, ':');
    const std::string kind = parts.empty() ? "" : parts[0];
    error = "--light '" + text + "': expected point:x,y,z:r,g,b:intensity, "
            "spot:x,y,z:dx,dy,dz:r,g,b:intensity[:inner_deg,outer_deg], "
            "dir:dx,dy,dz:r,g,b:intensity, sky:r,g,b:intensity or "
            "rect:cx,cy,cz:ux,uy,uz:vx,vy,vz:r,g,b:radiance (non-negative colours and "
            "intensities)";
    light = scene::Light{};
    light.name = "command-line " + kind;
    if (kind == "point" && parts.size() == 4) {
        light.type = scene::LightType::Point;
        if (!parseVec3(parts[1], light.position) ||
                !parseColorAndScale(parts[2], parts[3], light.color, light.intensity)) {
            return false;
        }
    } else if (kind == "dir" && parts.size() == 4) {
        light.type = scene::LightType::Directional;
        if (!parseDirection(parts[1], light.direction) ||
                !parseColorAndScale(parts[2], parts[3], light.color, light.intensity)) {
            return false;
        }
    } else if (kind == "spot" && (parts.size() == 5 || parts.size() == 6)) {
        light.type = scene::LightType::Spot;
        if (!parseVec3(parts[1], light.position) || !parseDirection(parts[2], light.direction) ||
                !parseColorAndScale(parts[3], parts[4], light.color, light.intensity)) {
            return false;
        }
        if (parts.size() == 6) {
            std::vector<float> cone;
            if (!parseFloats(parts[5], 2, cone) || cone[0] < 0.0f || cone[1] <= cone[0] ||
                    cone[1] > 90.0f) {
                error = "--light '" + text + "': cone angles must satisfy 0 <= inner < outer <= 90";
                return false;
            }
            light.innerConeAngle = glm::radians(cone[0]);
            light.outerConeAngle = glm::radians(cone[1]);
        }
    } else if (kind == "sky" && parts.size() == 3) {
        light.type = scene::LightType::Sky;
        if (!parseColorAndScale(parts[1], parts[2], light.color, light.intensity)) return false;
    } else if (kind == "rect" && parts.size() == 6) {
        if (!parseRect(parts, text, light, error)) return false;
    } else {
        return false;
    }
    error.clear();
    return true;
}

} // namespace gi::app
