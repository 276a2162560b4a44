#include "scene/GltfAccessorReader.h"

#include <algorithm>
#include <cstring>

namespace gi::scene {
namespace {

constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE;
constexpr int kUnsignedByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT;
constexpr int kUnsignedShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUnsignedInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

// Byte size of a component type glTF 2.0 allows in an accessor; 0 for anything else
// (including INT and DOUBLE, which tinygltf accepts but glTF does not).
int componentSize(int componentType) {
    switch (componentType) {
    case kByte:
    case kUnsignedByte: return 1;
    case kShort:
    case kUnsignedShort: return 2;
    case kUnsignedInt:
    case kFloat: return 4;
    default: return 0;
    }
}

bool isIndexComponentType(int componentType) {
    return componentType == kUnsignedByte || componentType == kUnsignedShort ||
           componentType == kUnsignedInt;
}

std::string indexed(const char* array, long long index) {
    return std::string(array) + "[" + std::to_string(index) + "]";
}

std::string byteCount(bool overflowed, std::uint64_t value) {
    return overflowed ? std::string("more than 2^64") : std::to_string(value);
}

// end = offset + count * size, with overflow reported instead of wrapped.
bool spanEnd(std::uint64_t offset, std::uint64_t count, std::uint64_t size, std::uint64_t& end) {
    std::uint64_t bytes = 0;
    return !__builtin_mul_overflow(count, size, &bytes) &&
           !__builtin_add_overflow(offset, bytes, &end);
}

struct ByteSpan {
    const std::uint8_t* data = nullptr;
    std::uint64_t size = 0;
    std::uint64_t stride = 0; // the view's byteStride, 0 when tightly packed
    std::string name;         // "bufferViews[i]"
};

// The bytes of buffer view `view`, after checking the view lies inside its buffer.
bool bufferViewBytes(const tinygltf::Model& model, int view, const std::string& user,
        ByteSpan& out, std::string& error) {
    if (view < 0 || std::size_t(view) >= model.bufferViews.size()) {
        error = user + ": bufferView " + std::to_string(view) + " does not exist (the file has " +
                std::to_string(model.bufferViews.size()) + " bufferViews)";
        return false;
    }
    const tinygltf::BufferView& bufferView = model.bufferViews[std::size_t(view)];
    out.name = indexed("bufferViews", view);
    if (bufferView.buffer < 0 || std::size_t(bufferView.buffer) >= model.buffers.size()) {
        error = out.name + ": buffer " + std::to_string(bufferView.buffer) +
                " does not exist (the file has " + std::to_string(model.buffers.size()) +
                " buffers)";
        return false;
    }
    const tinygltf::Buffer& buffer = model.buffers[std::size_t(bufferView.buffer)];
    std::uint64_t end = 0;
    const bool overflowed = !spanEnd(bufferView.byteOffset, 1, bufferView.byteLength, end);
    if (overflowed || end > buffer.data.size()) {
        error = out.name + ": byteOffset + byteLength (" + byteCount(overflowed, end) +
                ") exceeds " + indexed("buffers", bufferView.buffer) + ".byteLength (" +
                std::to_string(buffer.data.size()) + ")";
        return false;
    }
    out.data = buffer.data.data() + bufferView.byteOffset;
    out.size = bufferView.byteLength;
    out.stride = bufferView.byteStride;
    return true;
}

float readFloatComponent(const std::uint8_t* p, int componentType, bool normalized) {
    switch (componentType) {
    case kFloat: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    case kByte: {
        std::int8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? std::max(float(v) / 127.0f, -1.0f) : float(v);
    }
    case kUnsignedByte: return normalized ? float(*p) / 255.0f : float(*p);
    case kShort: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
    }
    case kUnsignedShort: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? float(v) / 65535.0f : float(v);
    }
    case kUnsignedInt: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return normalized ? float(double(v) / 4294967295.0) : float(v);
    }
    default: return 0.0f;
    }
}

std::uint32_t readUintComponent(const std::uint8_t* p, int componentType) {
    switch (componentType) {
    case kUnsignedByte: return *p;
    case kUnsignedShort: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    case kUnsignedInt: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    default: return 0;
    }
}

// Everything needed to read one accessor, validated.
struct Layout {
    std::string name;             // "accessors[i]"
    int componentType = 0;
    int components = 0;
    int componentBytes = 0;
    bool normalized = false;
    std::uint64_t count = 0;
    const std::uint8_t* data = nullptr; // first element; nullptr = all zeros (no bufferView)
    std::uint64_t stride = 0;
};

bool resolveLayout(const tinygltf::Model& model, int index, std::uint64_t maxCount,
        Layout& layout, std::string& error) {
    if (index < 0 || std::size_t(index) >= model.accessors.size()) {
        error = indexed("accessors", index) + ": does not exist (the file has " +
                std::to_string(model.accessors.size()) + " accessors)";
        return false;
    }
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
    layout.name = indexed("accessors", index);
    layout.componentType = accessor.componentType;
    layout.componentBytes = componentSize(accessor.componentType);
    if (layout.componentBytes == 0) {
        error = layout.name + ": componentType " + std::to_string(accessor.componentType) +
                " is not one glTF 2.0 allows";
        return false;
    }
    layout.components = accessorComponentCount(accessor.type);
    if (layout.components < 1 || layout.components > 4) {
        error = layout.name + ": type " + accessorTypeName(accessor.type) +
                " is not SCALAR, VEC2, VEC3 or VEC4";
        return false;
    }
    layout.normalized = accessor.normalized;
    layout.count = accessor.count;
    const std::uint64_t elementBytes = std::uint64_t(layout.components) * layout.componentBytes;

    if (accessor.bufferView >= 0) {
        ByteSpan view;
        if (!bufferViewBytes(model, accessor.bufferView, layout.name, view, error)) return false;
        layout.stride = view.stride == 0 ? elementBytes : view.stride;
        if (layout.stride < elementBytes) {
            error = view.name + ": byteStride " + std::to_string(view.stride) +
                    " is smaller than the " + std::to_string(elementBytes) +
                    "-byte elements of " + layout.name;
            return false;
        }
        if (accessor.byteOffset > view.size) {
            error = layout.name + ": byteOffset " + std::to_string(accessor.byteOffset) +
                    " exceeds " + view.name + ".byteLength (" + std::to_string(view.size) + ")";
            return false;
        }
        if (layout.count > 0) {
            std::uint64_t end = 0;
            bool overflowed = !spanEnd(accessor.byteOffset, layout.count - 1, layout.stride, end);
            overflowed = overflowed || __builtin_add_overflow(end, elementBytes, &end);
            if (overflowed || end > view.size) {
                error = layout.name + ": byteOffset + (count-1)*stride + elementSize (" +
                        byteCount(overflowed, end) + ") exceeds " + view.name +
                        ".byteLength (" + std::to_string(view.size) + ")";
                return false;
            }
        }
        layout.data = view.data + accessor.byteOffset;
    } else if (!accessor.sparse.isSparse) {
        // glTF: an accessor without a bufferView reads as zeros (useful only with sparse).
        layout.data = nullptr;
    }
    if (layout.count > maxCount) {
        error = layout.name + ": count " + std::to_string(layout.count) +
                " exceeds the loader's limit of " + std::to_string(maxCount) + " elements";
        return false;
    }
    return true;
}

// Applies the accessor's sparse substitution through `write(element, bytes)`.
template <class Write>
bool applySparse(const tinygltf::Model& model, int index, const Layout& layout, Write write,
        std::string& error) {
    const auto& sparse = model.accessors[std::size_t(index)].sparse;
    if (!sparse.isSparse) return true;
    if (sparse.count < 1 || std::uint64_t(sparse.count) > layout.count) {
        error = layout.name + ": sparse.count " + std::to_string(sparse.count) +
                " is outside [1, count = " + std::to_string(layout.count) + "]";
        return false;
    }
    const std::uint64_t n = std::uint64_t(sparse.count);
    const int indexType = sparse.indices.componentType;
    if (!isIndexComponentType(indexType)) {
        error = layout.name + ": sparse.indices.componentType " + std::to_string(indexType) +
                " is not UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT";
        return false;
    }
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) {
        error = layout.name + ": sparse byteOffset is negative";
        return false;
    }
    ByteSpan indices, values;
    if (!bufferViewBytes(model, sparse.indices.bufferView, layout.name + ".sparse.indices",
                indices, error) ||
            !bufferViewBytes(model, sparse.values.bufferView, layout.name + ".sparse.values",
                    values, error)) {
        return false;
    }
    const std::uint64_t indexBytes = std::uint64_t(componentSize(indexType));
    const std::uint64_t elementBytes = std::uint64_t(layout.components) * layout.componentBytes;
    std::uint64_t end = 0;
    bool overflowed = !spanEnd(std::uint64_t(sparse.indices.byteOffset), n, indexBytes, end);
    if (overflowed || end > indices.size) {
        error = layout.name + ": sparse.indices byteOffset + count*componentSize (" +
                byteCount(overflowed, end) + ") exceeds " + indices.name + ".byteLength (" +
                std::to_string(indices.size) + ")";
        return false;
    }
    overflowed = !spanEnd(std::uint64_t(sparse.values.byteOffset), n, elementBytes, end);
    if (overflowed || end > values.size) {
        error = layout.name + ": sparse.values byteOffset + count*elementSize (" +
                byteCount(overflowed, end) + ") exceeds " + values.name + ".byteLength (" +
                std::to_string(values.size) + ")";
        return false;
    }
    const std::uint8_t* indexData = indices.data + sparse.indices.byteOffset;
    const std::uint8_t* valueData = values.data + sparse.values.byteOffset;
    for (std::uint64_t k = 0; k < n; ++k) {
        const std::uint32_t element = readUintComponent(indexData + k * indexBytes, indexType);
        if (element >= layout.count) {
            error = layout.name + ": sparse index " + std::to_string(element) + " (entry " +
                    std::to_string(k) + ") is out of range (count " +
                    std::to_string(layout.count) + ")";
            return false;
        }
        write(std::size_t(element), valueData + k * elementBytes);
    }
    return true;
}

} // namespace

int accessorComponentCount(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
    }
}

const char* accessorTypeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "unknown";
    }
}

bool readAccessorFloats(const tinygltf::Model& model, int accessor, std::uint64_t maxCount,
        AccessorFloats& out, std::string& error) {
    Layout layout;
    if (!resolveLayout(model, accessor, maxCount, layout, error)) return false;
    const int components = layout.components;
    out.components = components;
    out.count = std::size_t(layout.count);
    out.values.assign(out.count * std::size_t(components), 0.0f);
    auto readElement = [&](std::size_t element, const std::uint8_t* bytes) {
        float* dst = out.values.data() + element * std::size_t(components);
        for (int c = 0; c < components; ++c) {
            dst[c] = readFloatComponent(bytes + c * layout.componentBytes, layout.componentType,
                    layout.normalized);
        }
    };
    if (layout.data != nullptr) {
        for (std::size_t i = 0; i < out.count; ++i) readElement(i, layout.data + i * layout.stride);
    }
    return applySparse(model, accessor, layout, readElement, error);
}

bool readAccessorIndices(const tinygltf::Model& model, int accessor, std::uint64_t maxCount,
        std::vector<std::uint32_t>& out, std::string& error) {
    Layout layout;
    if (!resolveLayout(model, accessor, maxCount, layout, error)) return false;
    if (layout.components != 1 || !isIndexComponentType(layout.componentType) ||
            layout.normalized) {
        error = layout.name + ": indices must be SCALAR, not normalized, UNSIGNED_BYTE, " +
                "UNSIGNED_SHORT or UNSIGNED_INT (got " +
                accessorTypeName(model.accessors[std::size_t(accessor)].type) +
                ", componentType " + std::to_string(layout.componentType) + ")";
        return false;
    }
    out.assign(std::size_t(layout.count), 0u);
    auto readElement = [&](std::size_t element, const std::uint8_t* bytes) {
        out[element] = readUintComponent(bytes, layout.componentType);
    };
    if (layout.data != nullptr) {
        for (std::size_t i = 0; i < out.size(); ++i) {
            readElement(i, layout.data + i * layout.stride);
        }
    }
    return applySparse(model, accessor, layout, readElement, error);
}

} // namespace gi::scene
