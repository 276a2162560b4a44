#include "reference/EmbreeRayCaster.h"

namespace gi::reference {

std::optional<scene::RayHit> EmbreeRayCaster::cast(const glm::vec3& origin,
        const glm::vec3& direction, float minDistance, float maxDistance) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayHit = makeRayHit(origin, direction, minDistance, maxDistance);
    rtcIntersect1(mState.rtcScene, &context, &rayHit);
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    const std::uint32_t triangle = mState.firstTriangle[rayHit.hit.geomID] + rayHit.hit.primID;
    const glm::vec3& normal = mState.triangleInfo[triangle].normal;
    return scene::RayHit{rayHit.ray.tfar, glm::dot(normal, direction) < 0.0f};
}

scene::DefaultsReport addDefaultsFromGeometry(scene::Scene& scene, std::string& warning) {
    if (!scene.lights.empty() && !scene.cameras.empty()) return {};
    std::string error;
    const std::unique_ptr<EmbreeState> state = buildEmbreeState(scene, error);
    if (!state) {
        warning = "the scene's defaults were chosen without looking at its geometry: " + error;
        return scene::addDefaults(scene, scene::NothingHitCaster());
    }
    return scene::addDefaults(scene, EmbreeRayCaster(*state));
}

scene::Camera defaultCameraFromGeometry(const scene::Scene& scene) {
    std::string error;
    const std::unique_ptr<EmbreeState> state = buildEmbreeState(scene, error);
    if (!state) return scene::defaultCamera(scene, scene::NothingHitCaster());
    return scene::defaultCamera(scene, EmbreeRayCaster(*state));
}

} // namespace gi::reference
