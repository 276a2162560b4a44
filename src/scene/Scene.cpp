#include "scene/Scene.h"

#include <cmath>

namespace gi::scene {

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const Instance& instance : instances) n += primitives[instance.primitive].indices.size() / 3;
    return n;
}

std::size_t Scene::vertexCount() const {
    std::size_t n = 0;
    for (const Instance& instance : instances) n += primitives[instance.primitive].positions.size();
    return n;
}

} // namespace gi::scene
