#include "render/ShadowMethodReport.h"

#include "gi/voxel/VoxelTextures.h"
#include "gl/MemoryRegistry.h"
#include "gl/Shared.h"
#include "render/LineSpaceLayout.h"
#include "render/ShadowCasters.h"
#include "render/ShadowPass.h"

#include <algorithm>
#include <cstdio>

namespace gi::render {

const char* shadowMethodName(int method) {
    switch (method) {
    case SHADOW_METHOD_BVH: return "bvh";
    case SHADOW_METHOD_LINESPACE: return "linespace";
    case SHADOW_METHOD_VOXEL: return "voxel";
    default: return "shadowmap";
    }
}

std::string describeShadowMethod(const ShadowMethodReport& report) {
    std::string line = "shadows: " + report.method;
    if (report.rays > 0) line += ", " + std::to_string(report.rays) + " rays";
    if (!report.structure.empty()) line += ", " + report.structure;
    char tail[96];
    if (report.buildMs > 0.0) {
        std::snprintf(tail, sizeof tail, ", built in %.0f ms", report.buildMs);
        line += tail;
    }
    const char* prefix = report.bound ? ", at most " : ", ";
    if (report.bytes < 1024 * 1024) {
        std::snprintf(tail, sizeof tail, "%s%.1f KiB", prefix, double(report.bytes) / 1024.0);
    } else {
        std::snprintf(tail, sizeof tail, "%s%.2f MiB", prefix, double(report.bytes) / (1024.0 * 1024.0));
    }
    return line + tail;
}

ShadowMethodReport plannedShadowMethod(const scene::Scene& scene,
        const std::vector<scene::Light>& lights, const Settings& settings) {
    ShadowMethodReport report;
    if (!settings.shadow.enabled) {
        report.method = "off";
        return report;
    }
    const int method = settings.shadow.method;
    report.method = shadowMethodName(method);
    const bool rays = method == SHADOW_METHOD_BVH || method == SHADOW_METHOD_LINESPACE;
    report.rays = rays ? settings.shadow.rays : 0;
    if (method == SHADOW_METHOD_SHADOWMAP) {
        report.structure = "a map per light at " + ShadowPass::resolutionText(lights, settings.shadow);
        report.bytes = gl::totalBytes(ShadowPass::memoryFor(lights, settings.shadow));
    } else if (method == SHADOW_METHOD_VOXEL) {
        const int levels = kShadowConeLevels;
        report.structure = "occupancy " + std::to_string(settings.voxel.resolution) + "^3 x " +
                std::to_string(levels) + " levels";
        report.bytes = gl::totalBytes(voxel::VoxelTextures::memoryFor(
                settings.voxel.resolution, levels, false, false, true));
    } else {
        const std::vector<glm::vec4> corners = shadowCasterCorners(scene);
        const std::size_t triangles = corners.size() / 3;
        if (method == SHADOW_METHOD_BVH) {
            // At most one leaf per triangle: 2 t - 1 nodes of two vec4, three vec4 per triangle.
            report.structure = "BVH over " + std::to_string(triangles) + " triangles";
            report.bytes = (2 * triangles * 2 + triangles * 3) * 16;
        } else {
            const LineSpaceSettings& ls = settings.lineSpace;
            report.structure = "LS(" + std::to_string(ls.n) + "," + std::to_string(ls.depth) +
                    ") over " + std::to_string(triangles) + " triangles";
            report.bytes = std::size_t(lineSpaceBytesBound(lineSpaceLayout(scene.bounds, ls.n, ls.depth), corners));
        }
        report.bound = true;
    }
    return report;
}

} // namespace gi::render
