#include "gi/atlas/AtlasCache.h"

#include "core/Hasher.h"

#include <unistd.h>

#include <bit>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <type_traits>

namespace gi::atlas {
namespace {

using core::Hasher;

constexpr char kMagic[8] = {'V', 'X', 'A', 'T', 'L', 'A', 'S', '\0'};

class Writer {
public:
    template <class T> void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* p = reinterpret_cast<const char*>(&v);
        mBytes.insert(mBytes.end(), p, p + sizeof v);
    }
    std::vector<char>& bytes() { return mBytes; }

private:
    std::vector<char> mBytes;
};

class Reader {
public:
    Reader(const char* data, std::size_t size) : mData(data), mSize(size) {}
    template <class T> bool value(T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        if (mSize - mOffset < sizeof v) return false;
        std::memcpy(&v, mData + mOffset, sizeof v);
        mOffset += sizeof v;
        return true;
    }
    std::size_t remaining() const { return mSize - mOffset; }

private:
    const char* mData;
    std::size_t mSize;
    std::size_t mOffset = 0;
};

std::string environment(const char* name) {
    const char* value = std::getenv(name);
    return value ? std::string(value) : std::string();
}

} // namespace

std::string atlasCacheKey(const AtlasMesh& mesh, const AtlasOptions& options) {
    Hasher h;
    h.value(kAtlasCacheFormat);
    h.vector(mesh.positions);
    h.vector(mesh.indices);
    h.value(mesh.hasTexcoord1);
    if (mesh.hasTexcoord1 && options.useTexcoord1) h.vector(mesh.texcoords1);
    h.value(options.resolution);
    h.value(options.gutter);
    h.value(options.useTexcoord1);
    h.value(options.maxChartAngleDeg);
    return h.hex();
}

AtlasCache::AtlasCache(std::filesystem::path directory) : mDirectory(std::move(directory)) {}

std::filesystem::path AtlasCache::defaultDirectory() {
    if (const std::string dir = environment("VOXATLAS_CACHE_DIR"); !dir.empty()) {
        return std::filesystem::path(dir) / "atlas";
    }
    if (const std::string xdg = environment("XDG_CACHE_HOME"); !xdg.empty()) {
        return std::filesystem::path(xdg) / "voxatlas" / "atlas";
    }
    if (const std::string home = environment("HOME"); !home.empty()) {
        return std::filesystem::path(home) / ".cache" / "voxatlas" / "atlas";
    }
    std::error_code ec;
    const std::filesystem::path temp = std::filesystem::temp_directory_path(ec);
    return (ec ? std::filesystem::path("/tmp") : temp) / "voxatlas-atlas";
}

std::filesystem::path AtlasCache::entryPath(const std::string& key) const {
    return mDirectory / (key + ".atlas");
}

bool AtlasCache::load(const std::string& key, const AtlasMesh& mesh, Atlas& atlas) const {
    std::ifstream file(entryPath(key), std::ios::binary);
    if (!file) return false;
    const std::vector<char> data(
            (std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    constexpr std::size_t kChecksumBytes = 16;
    if (data.size() < sizeof kMagic + kChecksumBytes) return false;
    const std::size_t body = data.size() - kChecksumBytes;
    Hasher checksum;
    checksum.bytes(data.data(), body);
    std::uint64_t stored[2];
    std::memcpy(stored, data.data() + body, sizeof stored);
    if (stored[0] != checksum.low() || stored[1] != checksum.high()) return false;

    Reader in(data.data(), body);
    char magic[8];
    std::uint32_t format = 0, fromTexcoord1 = 0;
    char storedKey[32];
    Atlas result;
    std::uint64_t vertexCount = 0, indexCount = 0, chartCount = 0;
    if (!in.value(magic) || std::memcmp(magic, kMagic, sizeof kMagic) != 0) return false;
    if (!in.value(format) || format != kAtlasCacheFormat) return false;
    if (!in.value(storedKey) || key.size() != sizeof storedKey ||
            std::memcmp(storedKey, key.data(), sizeof storedKey) != 0) {
        return false;
    }
    if (!in.value(result.resolution) || !in.value(result.gutter) || !in.value(fromTexcoord1) ||
            !in.value(result.texelSize) || !in.value(result.surfaceArea) ||
            !in.value(vertexCount) || !in.value(indexCount) || !in.value(chartCount)) {
        return false;
    }
    constexpr std::size_t kVertexBytes = 16, kChartBytes = 4 * 4 + 3 * 4 + 8 + 4;
    if (indexCount != mesh.indices.size() || vertexCount > in.remaining() / kVertexBytes ||
            chartCount > in.remaining() / kChartBytes ||
            in.remaining() !=
                    vertexCount * kVertexBytes + indexCount * 4 + chartCount * kChartBytes) {
        return false;
    }
    result.fromTexcoord1 = fromTexcoord1 != 0;
    result.vertices.resize(vertexCount);
    for (AtlasVertex& v : result.vertices) {
        if (!in.value(v.source) || !in.value(v.chart) || !in.value(v.uv.x) || !in.value(v.uv.y))
            return false;
        if (v.source >= mesh.positions.size() || v.chart >= chartCount) return false;
    }
    result.indices.resize(indexCount);
    for (std::uint32_t& i : result.indices) {
        if (!in.value(i) || i >= vertexCount) return false;
    }
    result.charts.resize(chartCount);
    for (AtlasChart& c : result.charts) {
        if (!in.value(c.origin.x) || !in.value(c.origin.y) || !in.value(c.size.x) ||
                !in.value(c.size.y) || !in.value(c.normal.x) || !in.value(c.normal.y) ||
                !in.value(c.normal.z) || !in.value(c.area) || !in.value(c.triangles)) {
            return false;
        }
    }
    atlas = std::move(result);
    return true;
}

bool AtlasCache::store(const std::string& key, const Atlas& atlas, std::string& error) const {
    if (key.size() != 32) {
        error = "atlas cache key must have 32 characters";
        return false;
    }
    Writer out;
    out.value(kMagic);
    out.value(kAtlasCacheFormat);
    char storedKey[32];
    std::memcpy(storedKey, key.data(), sizeof storedKey);
    out.value(storedKey);
    out.value(atlas.resolution);
    out.value(atlas.gutter);
    out.value(std::uint32_t(atlas.fromTexcoord1 ? 1 : 0));
    out.value(atlas.texelSize);
    out.value(atlas.surfaceArea);
    out.value(std::uint64_t(atlas.vertices.size()));
    out.value(std::uint64_t(atlas.indices.size()));
    out.value(std::uint64_t(atlas.charts.size()));
    for (const AtlasVertex& v : atlas.vertices) {
        out.value(v.source);
        out.value(v.chart);
        out.value(v.uv.x);
        out.value(v.uv.y);
    }
    for (const std::uint32_t i : atlas.indices) out.value(i);
    for (const AtlasChart& c : atlas.charts) {
        out.value(c.origin.x);
        out.value(c.origin.y);
        out.value(c.size.x);
        out.value(c.size.y);
        out.value(c.normal.x);
        out.value(c.normal.y);
        out.value(c.normal.z);
        out.value(c.area);
        out.value(c.triangles);
    }
    Hasher checksum;
    checksum.bytes(out.bytes().data(), out.bytes().size());
    out.value(checksum.low());
    out.value(checksum.high());

    std::error_code ec;
    std::filesystem::create_directories(mDirectory, ec);
    if (ec) {
        error = "cannot create " + mDirectory.string() + ": " + ec.message();
        return false;
    }
    const std::filesystem::path target = entryPath(key);
    const std::filesystem::path temporary =
            target.string() + ".tmp" + std::to_string(long(::getpid()));
    {
        std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
        file.write(out.bytes().data(), std::streamsize(out.bytes().size()));
        if (!file) {
            file.close();
            std::filesystem::remove(temporary, ec);
            error = "cannot write " + temporary.string();
            return false;
        }
    }
    std::filesystem::rename(temporary, target, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        error = "cannot rename " + temporary.string() + " to " + target.string();
        return false;
    }
    return true;
}

bool loadOrBuildAtlas(const AtlasMesh& mesh, const AtlasOptions& options, const AtlasCache* cache,
        Atlas& atlas, AtlasBuildInfo& info, std::string& error) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    info = AtlasBuildInfo{};
    std::string key;
    if (cache) {
        key = atlasCacheKey(mesh, options);
        info.cacheFile = cache->entryPath(key).string();
        if (cache->load(key, mesh, atlas)) {
            info.cacheHit = true;
            info.seconds = std::chrono::duration<double>(Clock::now() - start).count();
            return true;
        }
    }
    if (mesh.hasTexcoord1 && options.useTexcoord1) {
        std::string why;
        if (!texcoord1IsAtlas(mesh, options.resolution, why)) info.texcoord1Rejection = why;
    }
    if (!buildAtlas(mesh, options, atlas, error)) return false;
    if (cache && !cache->store(key, atlas, info.cacheError)) info.cacheFile.clear();
    info.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return true;
}

} // namespace gi::atlas
