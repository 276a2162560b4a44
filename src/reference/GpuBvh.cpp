#include "reference/GpuBvh.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>

namespace gi::reference {
namespace {

// The builder's own tree, allocated from Embree's thread-local allocator and freed with it.
struct BuildNode {
    bool leaf = false;
};

struct InnerNode : BuildNode {
    BuildNode* children[2] = {nullptr, nullptr};
    RTCBounds bounds[2] = {};
};

struct LeafNode : BuildNode {
    unsigned count = 0;
    unsigned triangles[kMaxLeafTriangles] = {};
};

void* createNode(RTCThreadLocalAllocator allocator, unsigned childCount, void*) {
    if (childCount != 2) return nullptr;   // maxBranchingFactor is 2
    void* memory = rtcThreadLocalAlloc(allocator, sizeof(InnerNode), 16);
    return new (memory) InnerNode();
}

void setNodeChildren(void* node, void** children, unsigned childCount, void*) {
    for (unsigned i = 0; i < childCount && i < 2; ++i) {
        static_cast<InnerNode*>(node)->children[i] = static_cast<BuildNode*>(children[i]);
    }
}

void setNodeBounds(void* node, const RTCBounds** bounds, unsigned childCount, void*) {
    for (unsigned i = 0; i < childCount && i < 2; ++i) static_cast<InnerNode*>(node)->bounds[i] = *bounds[i];
}

void* createLeaf(RTCThreadLocalAllocator allocator, const RTCBuildPrimitive* primitives,
        size_t count, void*) {
    void* memory = rtcThreadLocalAlloc(allocator, sizeof(LeafNode), 16);
    LeafNode* leaf = new (memory) LeafNode();
    leaf->leaf = true;
    leaf->count = unsigned(std::min<size_t>(count, kMaxLeafTriangles));
    for (unsigned i = 0; i < leaf->count; ++i) leaf->triangles[i] = primitives[i].primID;
    return leaf;
}

float intBits(int value) { return std::bit_cast<float>(value); }

// Writes `node` with its bounds at the end of bvh.nodes, then its subtree, depth first;
// leaves copy their triangles to bvh.triangles. Returns the subtree's depth.
int flatten(const BuildNode* node, const RTCBounds& bounds, const std::vector<glm::vec4>& corners,
        GpuBvh& bvh) {
    const std::size_t index = bvh.nodes.size() / 2;
    bvh.nodes.push_back(glm::vec4(bounds.lower_x, bounds.lower_y, bounds.lower_z, 0.0f));
    bvh.nodes.push_back(glm::vec4(bounds.upper_x, bounds.upper_y, bounds.upper_z, 0.0f));
    if (node->leaf) {
        const auto* leaf = static_cast<const LeafNode*>(node);
        bvh.nodes[2 * index].w = intBits(-int(leaf->count));
        bvh.nodes[2 * index + 1].w = intBits(int(bvh.triangles.size() / 3));
        for (unsigned i = 0; i < leaf->count; ++i) {
            for (int k = 0; k < 3; ++k) bvh.triangles.push_back(corners[3 * leaf->triangles[i] + unsigned(k)]);
        }
        return 1;
    }
    const auto* inner = static_cast<const InnerNode*>(node);
    const int left = flatten(inner->children[0], inner->bounds[0], corners, bvh);
    bvh.nodes[2 * index].w = intBits(int(bvh.nodes.size() / 2));
    const int right = flatten(inner->children[1], inner->bounds[1], corners, bvh);
    return 1 + std::max(left, right);
}

} // namespace

bool buildGpuBvh(const std::vector<glm::vec4>& corners, GpuBvh& bvh, std::string& error) {
    const auto start = std::chrono::steady_clock::now();
    bvh = GpuBvh{};
    std::vector<RTCBuildPrimitive> primitives;
    for (std::size_t t = 0; t + 2 < corners.size(); t += 3) {
        const glm::vec3 a(corners[t]), b(corners[t + 1]), c(corners[t + 2]);
        const glm::vec3 lo = glm::min(a, glm::min(b, c));
        const glm::vec3 hi = glm::max(a, glm::max(b, c));
        RTCBuildPrimitive build{};
        build.lower_x = lo.x, build.lower_y = lo.y, build.lower_z = lo.z;
        build.upper_x = hi.x, build.upper_y = hi.y, build.upper_z = hi.z;
        build.geomID = 0;
        build.primID = unsigned(t / 3);
        primitives.push_back(build);
    }
    if (primitives.empty()) {
        // One empty leaf with inverted bounds: every ray misses it.
        bvh.nodes = {glm::vec4(1.0f, 1.0f, 1.0f, intBits(0)), glm::vec4(-1.0f, -1.0f, -1.0f, intBits(0))};
        return true;
    }
    RTCDevice device = rtcNewDevice(nullptr);
    if (!device) {
        error = "Embree could not create a device for the GPU BVH";
        return false;
    }
    RTCBVH handle = rtcNewBVH(device);
    RTCBuildArguments arguments = rtcDefaultBuildArguments();
    arguments.buildQuality = RTC_BUILD_QUALITY_MEDIUM;
    arguments.maxBranchingFactor = 2;
    arguments.maxDepth = 48;
    arguments.minLeafSize = 1;
    arguments.maxLeafSize = kMaxLeafTriangles;
    arguments.bvh = handle;
    arguments.primitives = primitives.data();
    arguments.primitiveCount = primitives.size();
    arguments.primitiveArrayCapacity = primitives.size();
    arguments.createNode = createNode;
    arguments.setNodeChildren = setNodeChildren;
    arguments.setNodeBounds = setNodeBounds;
    arguments.createLeaf = createLeaf;
    RTCBounds rootBounds{};
    rootBounds.lower_x = rootBounds.lower_y = rootBounds.lower_z = INFINITY;
    rootBounds.upper_x = rootBounds.upper_y = rootBounds.upper_z = -INFINITY;
    for (const RTCBuildPrimitive& p : primitives) {
        rootBounds.lower_x = std::min(rootBounds.lower_x, p.lower_x);
        rootBounds.lower_y = std::min(rootBounds.lower_y, p.lower_y);
        rootBounds.lower_z = std::min(rootBounds.lower_z, p.lower_z);
        rootBounds.upper_x = std::max(rootBounds.upper_x, p.upper_x);
        rootBounds.upper_y = std::max(rootBounds.upper_y, p.upper_y);
        rootBounds.upper_z = std::max(rootBounds.upper_z, p.upper_z);
    }
    const auto* root = static_cast<const BuildNode*>(rtcBuildBVH(&arguments));
    bool ok = root != nullptr;
    if (ok) {
        bvh.triangles.reserve(corners.size());
        bvh.depth = flatten(root, rootBounds, corners, bvh);
    } else {
        error = "Embree could not build the GPU BVH (error " +
                std::to_string(int(rtcGetDeviceError(device))) + ")";
    }
    rtcReleaseBVH(handle);
    rtcReleaseDevice(device);
    bvh.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return ok;
}

} // namespace gi::reference
