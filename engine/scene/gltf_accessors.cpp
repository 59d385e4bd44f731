// Checked glTF accessor access: accessor → bufferView → buffer ranges, types and strides are all
// validated up front, so reading element i afterwards can never leave the buffer.
#include "scene/errors.hpp"
#include "scene/gltf_internal.hpp"

#include <algorithm>
#include <cstring>

namespace ppr::scene::detail {

namespace {

std::string componentName(int c) {
    switch (c) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "componentType " + std::to_string(c);
    }
}

std::string typeName(int t) {
    switch (t) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "type " + std::to_string(t);
    }
}

// Whether (type, componentType, normalized) is what glTF allows for this use, and the expectation text.
bool typeAllowed(const tinygltf::Accessor& a, AccessorKind kind, std::string& expected) {
    const int c = a.componentType;
    switch (kind) {
    case AccessorKind::Vec3Float:
        expected = "FLOAT VEC3";
        return a.type == TINYGLTF_TYPE_VEC3 && c == TINYGLTF_COMPONENT_TYPE_FLOAT;
    case AccessorKind::Vec4Float:
        expected = "FLOAT VEC4";
        return a.type == TINYGLTF_TYPE_VEC4 && c == TINYGLTF_COMPONENT_TYPE_FLOAT;
    case AccessorKind::TexCoord:
        expected = "VEC2 of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT";
        return a.type == TINYGLTF_TYPE_VEC2 &&
               (c == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                (a.normalized && (c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)));
    case AccessorKind::Index:
        expected = "SCALAR of UNSIGNED_BYTE/UNSIGNED_SHORT/UNSIGNED_INT";
        return a.type == TINYGLTF_TYPE_SCALAR &&
               (c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    }
    return false;
}

template <typename T>
T load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);  // glTF data need not be aligned for T
    return v;
}

}  // namespace

AccessorView viewAccessor(const GltfFile& file, int index, AccessorKind kind, const std::string& what) {
    const auto& m = file.model;
    const std::string prefix = file.name + ": " + what + ": ";
    if (index < 0 || size_t(index) >= m.accessors.size())
        fail(prefix + "accessor " + std::to_string(index) + " out of range (" + std::to_string(m.accessors.size()) + " accessors)");
    const tinygltf::Accessor& a = m.accessors[size_t(index)];
    const std::string acc = prefix + "accessor " + std::to_string(index) + ": ";
    std::string expected;
    if (!typeAllowed(a, kind, expected))
        fail(acc + "expected " + expected + ", got " + (a.normalized ? "normalized " : "") + componentName(a.componentType) +
             " " + typeName(a.type));
    if (a.sparse.isSparse) fail(acc + "sparse accessors are not supported");
    if (a.count > kMaxElements)
        fail(acc + "count " + std::to_string(a.count) + " exceeds the limit of " + std::to_string(kMaxElements));

    AccessorView view;
    view.count = a.count;
    view.componentType = a.componentType;
    view.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
    view.normalized = a.normalized;
    if (a.count == 0) return view;
    if (a.bufferView < 0) fail(acc + "has no bufferView (implicit all-zero accessors are not supported)");
    if (size_t(a.bufferView) >= m.bufferViews.size())
        fail(acc + "bufferView " + std::to_string(a.bufferView) + " out of range (" + std::to_string(m.bufferViews.size()) + " bufferViews)");
    const tinygltf::BufferView& bv = m.bufferViews[size_t(a.bufferView)];
    const std::string bvName = "bufferView " + std::to_string(a.bufferView);
    if (bv.buffer < 0 || size_t(bv.buffer) >= m.buffers.size())
        fail(acc + bvName + ": buffer " + std::to_string(bv.buffer) + " out of range (" + std::to_string(m.buffers.size()) + " buffers)");
    const size_t bufferSize = m.buffers[size_t(bv.buffer)].data.size();
    if (bv.byteOffset > bufferSize || bv.byteLength > bufferSize - bv.byteOffset)
        fail(acc + bvName + ": bytes [" + std::to_string(bv.byteOffset) + ", +" + std::to_string(bv.byteLength) +
             ") exceed buffer " + std::to_string(bv.buffer) + " of " + std::to_string(bufferSize) + " bytes");

    const size_t componentSize = size_t(tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType)));
    const size_t elementSize = componentSize * size_t(view.components);
    view.stride = bv.byteStride ? bv.byteStride : elementSize;
    if (view.stride < elementSize || view.stride > 252 || view.stride % componentSize != 0)
        fail(acc + bvName + ": byteStride " + std::to_string(bv.byteStride) + " invalid for " + std::to_string(elementSize) +
             "-byte elements");
    // count <= kMaxElements and stride <= 252 keep this product far from overflow.
    const size_t span = view.stride * (a.count - 1) + elementSize;
    if (a.byteOffset > bv.byteLength || span > bv.byteLength - a.byteOffset)
        fail(acc + "needs " + std::to_string(span) + " bytes at offset " + std::to_string(a.byteOffset) + " of " + bvName +
             ", which has " + std::to_string(bv.byteLength));
    view.data = m.buffers[size_t(bv.buffer)].data.data() + bv.byteOffset + a.byteOffset;
    return view;
}

void readFloats(const AccessorView& v, size_t element, float* out) {
    const unsigned char* p = v.data + element * v.stride;
    for (int c = 0; c < v.components; ++c) {
        switch (v.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: out[c] = load<float>(p + 4 * c); break;
        // glTF normalisation rules (spec 3.11): unsigned c / max; signed max(c / max, -1).
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: out[c] = float(p[c]) / 255.0f; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: out[c] = float(load<uint16_t>(p + 2 * c)) / 65535.0f; break;
        case TINYGLTF_COMPONENT_TYPE_BYTE: out[c] = std::max(float(int8_t(p[c])) / 127.0f, -1.0f); break;
        case TINYGLTF_COMPONENT_TYPE_SHORT: out[c] = std::max(float(load<int16_t>(p + 2 * c)) / 32767.0f, -1.0f); break;
        default: out[c] = 0.0f;  // excluded by viewAccessor's type check
        }
    }
}

uint32_t readIndex(const AccessorView& v, size_t element) {
    const unsigned char* p = v.data + element * v.stride;
    switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<uint16_t>(p);
    default: return load<uint32_t>(p);
    }
}

}  // namespace ppr::scene::detail
