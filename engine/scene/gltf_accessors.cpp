// Checked glTF accessor access: accessor → bufferView → buffer ranges, types and strides are all
// validated up front, so reading element i afterwards can never leave the buffer.
#include "scene/errors.hpp"
#include "scene/gltf_internal.hpp"

#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

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
    case AccessorKind::Color:
        expected = "VEC3/VEC4 of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT";
        return (a.type == TINYGLTF_TYPE_VEC3 || a.type == TINYGLTF_TYPE_VEC4) &&
               (c == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                (a.normalized && (c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)));
    case AccessorKind::ScalarFloat:
        expected = "FLOAT SCALAR";
        return a.type == TINYGLTF_TYPE_SCALAR && c == TINYGLTF_COMPONENT_TYPE_FLOAT;
    case AccessorKind::Rotation:
        expected = "VEC4 of FLOAT or normalized BYTE/UNSIGNED_BYTE/SHORT/UNSIGNED_SHORT";
        return a.type == TINYGLTF_TYPE_VEC4 &&
               (c == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                (a.normalized && (c == TINYGLTF_COMPONENT_TYPE_BYTE || c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                  c == TINYGLTF_COMPONENT_TYPE_SHORT || c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)));
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

// The length of bufferView `index` after checking it lies inside its buffer; fails naming it.
size_t checkedBufferView(const tinygltf::Model& m, int index, const std::string& where) {
    const std::string bvName = "bufferView " + std::to_string(index);
    if (index < 0 || size_t(index) >= m.bufferViews.size())
        fail(where + bvName + " out of range (" + std::to_string(m.bufferViews.size()) + " bufferViews)");
    const tinygltf::BufferView& bv = m.bufferViews[size_t(index)];
    if (bv.buffer < 0 || size_t(bv.buffer) >= m.buffers.size())
        fail(where + bvName + ": buffer " + std::to_string(bv.buffer) + " out of range (" + std::to_string(m.buffers.size()) + " buffers)");
    const size_t bufferSize = m.buffers[size_t(bv.buffer)].data.size();
    if (bv.byteOffset > bufferSize || bv.byteLength > bufferSize - bv.byteOffset)
        fail(where + bvName + ": bytes [" + std::to_string(bv.byteOffset) + ", +" + std::to_string(bv.byteLength) + ") exceed buffer " +
             std::to_string(bv.buffer) + " of " + std::to_string(bufferSize) + " bytes");
    return bv.byteLength;
}

// `bytes` bytes at `offset` of bufferView `index`, checked; fails naming the view.
const unsigned char* checkedRange(const tinygltf::Model& m, int index, size_t offset, size_t bytes, const std::string& where) {
    const size_t length = checkedBufferView(m, index, where);
    if (offset > length || bytes > length - offset)
        fail(where + "needs " + std::to_string(bytes) + " bytes at offset " + std::to_string(offset) + " of bufferView " +
             std::to_string(index) + ", which has " + std::to_string(length));
    const tinygltf::BufferView& bv = m.bufferViews[size_t(index)];
    return m.buffers[size_t(bv.buffer)].data.data() + bv.byteOffset + offset;
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
    if (a.count > kMaxElements)
        fail(acc + "count " + std::to_string(a.count) + " exceeds the limit of " + std::to_string(kMaxElements));

    AccessorView view;
    view.count = a.count;
    view.componentType = a.componentType;
    view.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
    view.normalized = a.normalized;
    if (a.count == 0) return view;
    const size_t componentSize = size_t(tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType)));
    const size_t elementSize = componentSize * size_t(view.components);

    if (a.bufferView >= 0) {
        const std::string bvName = "bufferView " + std::to_string(a.bufferView);
        const size_t viewLength = checkedBufferView(m, a.bufferView, acc);
        const tinygltf::BufferView& bv = m.bufferViews[size_t(a.bufferView)];
        view.stride = bv.byteStride ? bv.byteStride : elementSize;
        if (view.stride < elementSize || view.stride > 252 || view.stride % componentSize != 0)
            fail(acc + bvName + ": byteStride " + std::to_string(bv.byteStride) + " invalid for " + std::to_string(elementSize) +
                 "-byte elements");
        // count <= kMaxElements and stride <= 252 keep this product far from overflow.
        const size_t span = view.stride * (a.count - 1) + elementSize;
        if (a.byteOffset > viewLength || span > viewLength - a.byteOffset)
            fail(acc + "needs " + std::to_string(span) + " bytes at offset " + std::to_string(a.byteOffset) + " of " + bvName +
                 ", which has " + std::to_string(viewLength));
        view.data = m.buffers[size_t(bv.buffer)].data.data() + bv.byteOffset + a.byteOffset;
    } else if (!a.sparse.isSparse) {
        fail(acc + "has no bufferView and is not sparse (nothing to read)");
    }
    if (!a.sparse.isSparse) return view;

    // Sparse (spec 3.6.2.3): the base (the bufferView's elements, or zeros without one) copied tightly
    // packed, then `count` elements replaced at strictly increasing indices.
    constexpr size_t kMaxMaterialisedBytes = size_t(512) << 20;  // a tiny hostile file must not ask for gigabytes
    if (a.count * elementSize > kMaxMaterialisedBytes)
        fail(acc + "sparse: " + std::to_string(a.count * elementSize) + " bytes exceed the limit of " + std::to_string(kMaxMaterialisedBytes));
    auto owned = std::make_shared<std::vector<unsigned char>>(a.count * elementSize, 0);
    if (view.data)
        for (size_t i = 0; i < a.count; ++i) std::memcpy(owned->data() + i * elementSize, view.data + i * view.stride, elementSize);
    const auto& sp = a.sparse;
    const std::string where = acc + "sparse: ";
    if (sp.count < 1 || size_t(sp.count) > a.count)
        fail(where + "count " + std::to_string(sp.count) + " outside 1.." + std::to_string(a.count));
    const int ic = sp.indices.componentType;
    if (ic != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ic != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && ic != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(where + "indices: expected UNSIGNED_BYTE/UNSIGNED_SHORT/UNSIGNED_INT, got " + componentName(ic));
    const size_t indexSize = size_t(tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(ic)));
    const unsigned char* indices = checkedRange(m, sp.indices.bufferView, size_t(std::max(sp.indices.byteOffset, 0)),
                                                size_t(sp.count) * indexSize, where + "indices: ");
    const unsigned char* values = checkedRange(m, sp.values.bufferView, size_t(std::max(sp.values.byteOffset, 0)),
                                               size_t(sp.count) * elementSize, where + "values: ");
    AccessorView indexView;
    indexView.data = indices;
    indexView.stride = indexSize;
    indexView.componentType = ic;
    uint64_t previous = 0;
    for (size_t k = 0; k < size_t(sp.count); ++k) {
        const uint32_t target = readIndex(indexView, k);
        if (target >= a.count || (k > 0 && target <= previous))
            fail(where + "index " + std::to_string(target) + " (entry " + std::to_string(k) + ") is out of range or not increasing");
        previous = target;
        std::memcpy(owned->data() + size_t(target) * elementSize, values + k * elementSize, elementSize);
    }
    view.owned = owned;
    view.data = owned->data();
    view.stride = elementSize;
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
