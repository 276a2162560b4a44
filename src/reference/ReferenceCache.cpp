#include "reference/ReferenceCache.h"

#include "core/Hasher.h"
#include "core/ImageIO.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <type_traits>

namespace gi::reference {
namespace {

using core::Hasher;

constexpr int kMaxDimension = 65536;
const char* const kImageNames[] = {"direct", "indirect", "final", "coverage"};

std::string checksum(const std::vector<float>& values) {
    Hasher hasher;
    hasher.vector(values);
    return hasher.hex();
}

void hashScene(const scene::Scene& scene, Hasher& h) {
    h.value(std::uint64_t(scene.instances.size()));
    for (const scene::Instance& instance : scene.instances) {
        h.value(instance.primitive);
        h.value(instance.worldFromLocal);
    }
    h.value(std::uint64_t(scene.primitives.size()));
    for (const scene::Primitive& primitive : scene.primitives) {
        h.vector(primitive.positions);
        h.vector(primitive.normals);
        h.vector(primitive.texcoords0);
        h.vector(primitive.texcoords1);
        h.vector(primitive.colors);
        h.vector(primitive.indices);
        h.value(primitive.material);
    }
    h.value(std::uint64_t(scene.materials.size()));
    for (const scene::Material& m : scene.materials) {
        h.value(m.baseColorFactor);
        h.value(m.baseColorTexture);
        h.value(m.baseColorTexCoord);
        h.value(m.emissiveFactor);
        h.value(m.emissiveTexture);
        h.value(m.emissiveTexCoord);
        h.value(m.alphaMode);
        h.value(m.alphaCutoff);
        h.value(m.doubleSided);
    }
    h.value(std::uint64_t(scene.textures.size()));
    for (const scene::Texture& t : scene.textures) {
        h.value(t.width);
        h.value(t.height);
        h.value(t.srgb);
        h.value(t.wrapS);
        h.value(t.wrapT);
        h.vector(t.rgba8);
    }
    h.value(std::uint64_t(scene.lights.size()));
    for (const scene::Light& light : scene.lights) {
        h.value(light.type);
        h.value(light.position);
        h.value(light.direction);
        h.value(light.color);
        h.value(light.intensity);
        h.value(light.innerConeAngle);
        h.value(light.outerConeAngle);
        h.value(std::uint64_t(light.emitters.size()));
        for (const scene::EmitterTriangle& t : light.emitters) {
            h.value(t.p0);
            h.value(t.p1);
            h.value(t.p2);
            h.value(t.radiance);
            h.value(t.twoSided);
            h.value(t.instance);
            h.value(t.triangle);
            h.value(t.material);
        }
    }
}

std::filesystem::path entryFile(const std::filesystem::path& dir, const std::string& key,
        const std::string& suffix) {
    return dir / (key + suffix);
}

bool readText(const std::filesystem::path& path, std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream buffer;
    buffer << in.rdbuf();
    text = buffer.str();
    return bool(in) || in.eof();
}

nlohmann::json numberOrNull(double value) {
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

bool readNumberOrNull(const nlohmann::json& json, const char* name, double& value) {
    const auto it = json.find(name);
    if (it == json.end()) return false;
    if (it->is_null()) {
        value = std::numeric_limits<double>::quiet_NaN();
        return true;
    }
    if (!it->is_number()) return false;
    value = it->get<double>();
    return true;
}

bool readInt(const nlohmann::json& json, const char* name, std::int64_t min, std::int64_t max,
        std::int64_t& value) {
    const auto it = json.find(name);
    if (it == json.end() || !it->is_number_integer()) return false;
    value = it->get<std::int64_t>();
    return value >= min && value <= max;
}

bool readUnsigned(const nlohmann::json& json, const char* name, std::uint64_t& value) {
    const auto it = json.find(name);
    if (it == json.end() || !it->is_number_unsigned()) return false;
    value = it->get<std::uint64_t>();
    return true;
}

bool finite(const std::vector<float>& values) {
    for (float v : values) {
        if (!std::isfinite(v)) return false;
    }
    return true;
}

std::string temporaryName(const std::filesystem::path& path) {
    return path.string() + ".partial-" + std::to_string(::getpid());
}

} // namespace

std::string referenceCacheKey(const scene::Scene& scene, const scene::CameraView& camera,
        int width, int height, const ReferenceSettings& settings) {
    Hasher h;
    h.string("voxatlas reference");
    h.value(kReferenceCacheFormat);
    hashScene(scene, h);
    h.value(camera.view);
    h.value(camera.projection);
    h.value(width);
    h.value(height);
    h.value(settings.spp);
    h.value(settings.bounces);
    h.value(settings.seed);
    // Area keys stay as they were before the choice existed, so their entries remain valid.
    if (settings.pixel == kReferencePixelCentre) h.string("pixel centre");
    // Lambertian keys stay as they were before the glossy model existed, so their entries
    // remain valid; glossy ones add the model and every material's metallic and roughness.
    if (settings.glossy) {
        h.string("glTF metallic-roughness");
        for (const scene::Material& m : scene.materials) {
            h.value(m.metallicFactor);
            h.value(m.roughnessFactor);
        }
    }
    return h.hex();
}

ReferenceCache::ReferenceCache(std::filesystem::path directory)
    : mDirectory(std::move(directory)) {}

std::filesystem::path ReferenceCache::defaultDirectory() {
    auto env = [](const char* name) -> std::string {
        const char* value = std::getenv(name);
        return value ? std::string(value) : std::string();
    };
    if (const std::string dir = env("VOXATLAS_CACHE_DIR"); !dir.empty()) return dir;
    if (const std::string xdg = env("XDG_CACHE_HOME"); !xdg.empty()) {
        return std::filesystem::path(xdg) / "voxatlas" / "reference";
    }
    if (const std::string home = env("HOME"); !home.empty()) {
        return std::filesystem::path(home) / ".cache" / "voxatlas" / "reference";
    }
    std::error_code ec;
    const std::filesystem::path temp = std::filesystem::temp_directory_path(ec);
    return (ec ? std::filesystem::path("/tmp") : temp) / "voxatlas-reference";
}

bool ReferenceCache::load(const std::string& key, ReferenceResult& out) const {
    std::string text;
    if (!readText(entryFile(mDirectory, key, ".json"), text)) return false;
    const nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
    if (json.is_discarded() || !json.is_object()) return false;
    std::int64_t format = 0, width = 0, height = 0, spp = 0, bounces = 0;
    if (!readInt(json, "format", kReferenceCacheFormat, kReferenceCacheFormat, format) ||
            json.value("key", std::string()) != key ||
            !readInt(json, "width", 1, kMaxDimension, width) ||
            !readInt(json, "height", 1, kMaxDimension, height) ||
            !readInt(json, "spp", 1, std::numeric_limits<int>::max(), spp) ||
            !readInt(json, "bounces", 0, std::numeric_limits<int>::max(), bounces)) {
        return false;
    }
    ReferenceResult result;
    result.spp = int(spp);
    result.bounces = int(bounces);
    const auto noise = json.find("noise");
    const auto rays = json.find("rays");
    const auto checksums = json.find("checksums");
    if (noise == json.end() || rays == json.end() || checksums == json.end() ||
            !noise->is_object() || !rays->is_object() || !checksums->is_object() ||
            !readNumberOrNull(*noise, "direct", result.noise.direct) ||
            !readNumberOrNull(*noise, "indirect", result.noise.indirect) ||
            !readNumberOrNull(*noise, "final", result.noise.final) ||
            !readUnsigned(*rays, "primary", result.rays.primary) ||
            !readUnsigned(*rays, "shadow", result.rays.shadow) ||
            !readUnsigned(*rays, "bounce", result.rays.bounce) ||
            !readUnsigned(*rays, "light", result.rays.light) ||
            !readNumberOrNull(json, "seconds", result.seconds)) {
        return false;
    }
    core::Image* targets[] = {&result.direct, &result.indirect, &result.final, nullptr};
    core::Image coverage;
    for (int i = 0; i < 4; ++i) {
        core::Image image;
        std::string error;
        if (!core::readHdr(entryFile(mDirectory, key, std::string(".") + kImageNames[i] + ".pfm"),
                    image, error) ||
                image.width != width || image.height != height || !finite(image.rgb) ||
                checksums->value(kImageNames[i], std::string()) != checksum(image.rgb)) {
            return false;
        }
        *(targets[i] ? targets[i] : &coverage) = std::move(image);
    }
    result.coverage.resize(std::size_t(width) * std::size_t(height));
    for (std::size_t p = 0; p < result.coverage.size(); ++p) {
        const float c = coverage.rgb[3 * p];
        if (!(c >= 0.0f && c <= 1.0f) || coverage.rgb[3 * p + 1] != c ||
                coverage.rgb[3 * p + 2] != c) {
            return false;
        }
        result.coverage[p] = c;
    }
    out = std::move(result);
    return true;
}

bool ReferenceCache::store(const std::string& key, const ReferenceResult& result,
        std::string& error) const {
    const std::size_t pixels = std::size_t(result.width()) * std::size_t(result.height());
    if (result.final.empty() || result.coverage.size() != pixels) {
        error = "reference cache: nothing to store";
        return false;
    }
    std::error_code ec;
    std::filesystem::create_directories(mDirectory, ec);
    if (ec) {
        error = mDirectory.string() + ": cannot create the reference cache directory (" +
                ec.message() + ")";
        return false;
    }
    // The JSON is the entry's commit record: remove a stale one first, write it last.
    const std::filesystem::path jsonPath = entryFile(mDirectory, key, ".json");
    std::filesystem::remove(jsonPath, ec);

    core::Image coverage(result.width(), result.height());
    for (std::size_t p = 0; p < pixels; ++p) {
        coverage.rgb[3 * p] = coverage.rgb[3 * p + 1] = coverage.rgb[3 * p + 2] =
                result.coverage[p];
    }
    const core::Image* images[] = {&result.direct, &result.indirect, &result.final, &coverage};
    nlohmann::json checksums = nlohmann::json::object();
    for (int i = 0; i < 4; ++i) {
        const std::string path =
                entryFile(mDirectory, key, std::string(".") + kImageNames[i] + ".pfm").string();
        if (!core::writeHdr(path, *images[i], error)) return false;
        checksums[kImageNames[i]] = checksum(images[i]->rgb);
    }
    const nlohmann::json json = {{"format", kReferenceCacheFormat}, {"key", key},
            {"width", result.width()}, {"height", result.height()}, {"spp", result.spp},
            {"bounces", result.bounces},
            {"noise", {{"direct", numberOrNull(result.noise.direct)},
                              {"indirect", numberOrNull(result.noise.indirect)},
                              {"final", numberOrNull(result.noise.final)}}},
            {"seconds", numberOrNull(result.seconds)},
            {"rays", {{"primary", result.rays.primary}, {"shadow", result.rays.shadow},
                             {"bounce", result.rays.bounce}, {"light", result.rays.light}}},
            {"checksums", checksums}};
    const std::string temporary = temporaryName(jsonPath);
    {
        std::ofstream out(temporary, std::ios::binary);
        out << json.dump(2) << '\n';
        out.close();
        if (!out) {
            std::filesystem::remove(temporary, ec);
            error = jsonPath.string() + ": cannot write reference cache entry";
            return false;
        }
    }
    std::filesystem::rename(temporary, jsonPath, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        error = jsonPath.string() + ": cannot write reference cache entry (" + ec.message() + ")";
        return false;
    }
    return true;
}

ReferenceResult renderReferenceCached(const scene::Scene& scene, const scene::CameraView& camera,
        int width, int height, const ReferenceSettings& settings, const ReferenceCache& cache,
        CachedRenderStatus& status, std::string& error, const ProgressCallback& progress) {
    status = {};
    const std::string key = referenceCacheKey(scene, camera, width, height, settings);
    ReferenceResult result;
    if (cache.load(key, result)) {
        status.hit = true;
        if (progress) progress(1.0);
        return result;
    }
    const ReferenceRenderer renderer(scene);
    if (!renderer.valid()) {
        error = renderer.error();
        return {};
    }
    result = renderer.render(camera, width, height, settings, progress);
    if (result.final.empty()) {
        error = "reference render produced no image (" + std::to_string(width) + "x" +
                std::to_string(height) + ")";
        return {};
    }
    if (!cache.store(key, result, status.storeError) && status.storeError.empty()) {
        status.storeError = "reference cache: store failed";
    }
    return result;
}

} // namespace gi::reference
