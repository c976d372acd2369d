#include "anim/import_accessor.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace proxygi::anim::detail {
namespace {

int component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;  // MAT2/MAT3 (column padding rules) are used by no semantic we read
  }
}

bool contains(const std::vector<int>& list, int value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

// Bytes of one bufferView region, checked against its buffer: data == nullptr means zeros.
struct Region {
  const std::uint8_t* data = nullptr;
  std::uint64_t stride = 0;
};

// Checks that `count` elements of `element_size` bytes starting at `offset` inside bufferView
// `view_index` (with its byteStride when `strided`) fit the view and the view fits its buffer.
Result<Region> checked_region(const ImportContext& ctx, int view_index, std::int64_t offset,
                              std::uint64_t count, std::uint64_t element_size, bool strided,
                              const std::string& what) {
  const auto& views = ctx.model.bufferViews;
  if (view_index < 0 || static_cast<std::size_t>(view_index) >= views.size()) {
    return error_at(what, "bufferView " + std::to_string(view_index) + " out of range (" +
                              std::to_string(views.size()) + " bufferViews)");
  }
  const tinygltf::BufferView& view = views[static_cast<std::size_t>(view_index)];
  const std::string view_what = what + ": bufferView " + std::to_string(view_index);
  const auto& buffers = ctx.model.buffers;
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= buffers.size()) {
    return error_at(view_what, "buffer " + std::to_string(view.buffer) + " out of range (" +
                                   std::to_string(buffers.size()) + " buffers)");
  }
  const std::uint64_t buffer_size = buffers[static_cast<std::size_t>(view.buffer)].data.size();
  const std::uint64_t view_offset = view.byteOffset;
  const std::uint64_t view_length = view.byteLength;
  if (view_length > buffer_size || view_offset > buffer_size - view_length) {
    return error_at(view_what, "range [" + std::to_string(view_offset) + ", +" +
                                   std::to_string(view_length) + ") exceeds buffer " +
                                   std::to_string(view.buffer) + " (" +
                                   std::to_string(buffer_size) + " bytes)");
  }
  std::uint64_t stride = element_size;
  if (strided && view.byteStride != 0) {
    if (static_cast<std::uint64_t>(view.byteStride) < element_size) {
      return error_at(view_what, "byteStride " + std::to_string(view.byteStride) +
                                     " smaller than the element size " +
                                     std::to_string(element_size));
    }
    stride = static_cast<std::uint64_t>(view.byteStride);
  }
  if (offset < 0 || static_cast<std::uint64_t>(offset) > view_length) {
    return error_at(view_what, "byteOffset " + std::to_string(offset) + " outside the view (" +
                                   std::to_string(view_length) + " bytes)");
  }
  // count <= max_accessor_elements (2^32 at most) and stride <= 2^31: no 64-bit overflow.
  const std::uint64_t needed = stride * (count - 1) + element_size;
  if (needed > view_length - static_cast<std::uint64_t>(offset)) {
    return error_at(view_what, std::to_string(count) + " elements of " +
                                   std::to_string(element_size) + " bytes (stride " +
                                   std::to_string(stride) + ") at byteOffset " +
                                   std::to_string(offset) + " exceed the view's " +
                                   std::to_string(view_length) + " bytes");
  }
  const auto& data = buffers[static_cast<std::size_t>(view.buffer)].data;
  return Region{data.data() + view_offset + static_cast<std::uint64_t>(offset), stride};
}

// Raw component value (no normalization) as double: exact for every glTF component type.
double load_component(const std::uint8_t* p, int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: { std::int8_t v; std::memcpy(&v, p, 1); return v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
    case TINYGLTF_COMPONENT_TYPE_SHORT: { std::int16_t v; std::memcpy(&v, p, 2); return v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t v; std::memcpy(&v, p, 2); return v; }
    case TINYGLTF_COMPONENT_TYPE_INT: { std::int32_t v; std::memcpy(&v, p, 4); return v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t v; std::memcpy(&v, p, 4); return v; }
    case TINYGLTF_COMPONENT_TYPE_FLOAT: { float v; std::memcpy(&v, p, 4); return v; }
    default: return 0.0;
  }
}

// glTF decode table for normalized integers: signed max(c / max, -1), unsigned c / max.
double normalize(double raw, int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return std::max(raw / 127.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return raw / 255.0;
    case TINYGLTF_COMPONENT_TYPE_SHORT: return std::max(raw / 32767.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return raw / 65535.0;
    default: return raw;
  }
}

// Reads the accessor as raw doubles (count * components) after every check.
struct RawAccessor {
  std::vector<double> values;
  std::size_t count = 0;
  int components = 0;
  int component_type = 0;
  bool normalized = false;
};

Result<RawAccessor> read_raw(ImportContext& ctx, int index, const std::string& what_in,
                             const std::vector<int>& types,
                             const std::vector<int>& component_types) {
  const auto& accessors = ctx.model.accessors;
  if (index < 0 || static_cast<std::size_t>(index) >= accessors.size()) {
    return error_at(what_in, "accessor " + std::to_string(index) + " out of range (" +
                                 std::to_string(accessors.size()) + " accessors)");
  }
  const std::string what = what_in + ": accessor " + std::to_string(index);
  const tinygltf::Accessor& accessor = accessors[static_cast<std::size_t>(index)];
  if (!contains(types, accessor.type)) {
    return error_at(what, "type " + type_name(accessor.type) + " not allowed here");
  }
  if (!contains(component_types, accessor.componentType)) {
    return error_at(what, "componentType " + component_type_name(accessor.componentType) +
                              " not allowed here");
  }
  const int components = component_count(accessor.type);
  const int size = component_size(accessor.componentType);
  if (accessor.count == 0) return error_at(what, "count is 0");
  if (accessor.count > ctx.limits.max_accessor_elements) {
    return error_at(what, "count " + std::to_string(accessor.count) + " exceeds the limit of " +
                              std::to_string(ctx.limits.max_accessor_elements));
  }
  const std::uint64_t total = static_cast<std::uint64_t>(accessor.count) *
                              static_cast<std::uint64_t>(components);
  if (ctx.elements_decoded + total > ctx.limits.max_total_elements) {
    return error_at(what, "decoding it would exceed the limit of " +
                              std::to_string(ctx.limits.max_total_elements) +
                              " accessor components per import");
  }
  ctx.elements_decoded += total;

  // Check the base data before allocating anything for it.
  const std::uint64_t element_size = static_cast<std::uint64_t>(components * size);
  Region base;
  if (accessor.bufferView >= 0) {
    if (accessor.byteOffset > static_cast<std::size_t>(std::numeric_limits<std::int64_t>::max())) {
      return error_at(what, "byteOffset " + std::to_string(accessor.byteOffset) + " too large");
    }
    auto region = checked_region(ctx, accessor.bufferView,
                                 static_cast<std::int64_t>(accessor.byteOffset), accessor.count,
                                 element_size, /*strided=*/true, what);
    if (!region) return region.error();
    base = *region;
  }
  // Without bufferView the base is zeros (meant for sparse accessors; tolerated otherwise).
  RawAccessor raw;
  raw.count = accessor.count;
  raw.components = components;
  raw.component_type = accessor.componentType;
  raw.normalized = accessor.normalized;
  raw.values.assign(total, 0.0);
  if (base.data != nullptr) {
    for (std::size_t i = 0; i < accessor.count; ++i) {
      const std::uint8_t* element = base.data + base.stride * i;
      for (int c = 0; c < components; ++c) {
        raw.values[i * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] =
            load_component(element + c * size, accessor.componentType);
      }
    }
  }

  if (accessor.sparse.isSparse) {
    const auto& sparse = accessor.sparse;
    const std::string sparse_what = what + ": sparse";
    if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > accessor.count) {
      return error_at(sparse_what, "count " + std::to_string(sparse.count) +
                                       " not in [1, " + std::to_string(accessor.count) + "]");
    }
    const int index_type = sparse.indices.componentType;
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
      return error_at(sparse_what, "indices componentType " + component_type_name(index_type) +
                                       " not allowed");
    }
    const auto sparse_count = static_cast<std::uint64_t>(sparse.count);
    auto indices = checked_region(ctx, sparse.indices.bufferView, sparse.indices.byteOffset,
                                  sparse_count, static_cast<std::uint64_t>(component_size(index_type)),
                                  /*strided=*/false, sparse_what + " indices");
    if (!indices) return indices.error();
    auto values = checked_region(ctx, sparse.values.bufferView, sparse.values.byteOffset,
                                 sparse_count, element_size, /*strided=*/false,
                                 sparse_what + " values");
    if (!values) return values.error();
    double previous = -1.0;
    for (std::uint64_t k = 0; k < sparse_count; ++k) {
      const double target = load_component(indices->data + indices->stride * k, index_type);
      if (target <= previous) {
        return error_at(sparse_what, "index " + std::to_string(static_cast<std::uint64_t>(target)) +
                                         " at position " + std::to_string(k) +
                                         " is not strictly increasing");
      }
      if (target >= static_cast<double>(accessor.count)) {
        return error_at(sparse_what, "index " + std::to_string(static_cast<std::uint64_t>(target)) +
                                         " out of range (count " +
                                         std::to_string(accessor.count) + ")");
      }
      previous = target;
      const auto element = static_cast<std::size_t>(target);
      for (int c = 0; c < components; ++c) {
        raw.values[element * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] =
            load_component(values->data + values->stride * k + static_cast<std::uint64_t>(c * size),
                           accessor.componentType);
      }
    }
  }
  return raw;
}

}  // namespace

std::string component_type_name(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "DOUBLE";
    default: return std::to_string(component_type);
  }
}

std::string type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return std::to_string(type);
  }
}

Result<std::span<const std::uint8_t>> buffer_view_bytes(const ImportContext& ctx, int view,
                                                        const std::string& what) {
  if (view >= 0 && static_cast<std::size_t>(view) < ctx.model.bufferViews.size() &&
      ctx.model.bufferViews[static_cast<std::size_t>(view)].byteLength == 0) {
    return error_at(what, "bufferView " + std::to_string(view) + " is empty");
  }
  auto region = checked_region(ctx, view, 0, 1, 1, /*strided=*/false, what);
  if (!region) return region.error();
  return std::span<const std::uint8_t>(region->data,
                                       ctx.model.bufferViews[static_cast<std::size_t>(view)].byteLength);
}

Result<FloatAccessor> read_float_accessor(ImportContext& ctx, int index, const std::string& what,
                                          const std::vector<int>& types,
                                          const std::vector<int>& component_types) {
  auto raw = read_raw(ctx, index, what, types, component_types);
  if (!raw) return raw.error();
  const std::string accessor_what = what + ": accessor " + std::to_string(index);
  const bool is_float = raw->component_type == TINYGLTF_COMPONENT_TYPE_FLOAT;
  if (!is_float && !raw->normalized) {
    return error_at(accessor_what, "componentType " + component_type_name(raw->component_type) +
                                       " must be normalized here");
  }
  FloatAccessor out;
  out.count = raw->count;
  out.components = raw->components;
  out.values.resize(raw->values.size());
  for (std::size_t i = 0; i < raw->values.size(); ++i) {
    const double value = is_float ? raw->values[i] : normalize(raw->values[i], raw->component_type);
    if (!std::isfinite(value)) {
      return error_at(accessor_what, "element " + std::to_string(i / static_cast<std::size_t>(raw->components)) +
                                         " is not finite");
    }
    out.values[i] = static_cast<float>(value);
  }
  return out;
}

Result<UintAccessor> read_uint_accessor(ImportContext& ctx, int index, const std::string& what,
                                        const std::vector<int>& types,
                                        const std::vector<int>& component_types) {
  auto raw = read_raw(ctx, index, what, types, component_types);
  if (!raw) return raw.error();
  if (raw->normalized) {
    return error_at(what + ": accessor " + std::to_string(index), "must not be normalized");
  }
  UintAccessor out;
  out.count = raw->count;
  out.components = raw->components;
  out.values.resize(raw->values.size());
  for (std::size_t i = 0; i < raw->values.size(); ++i) {
    out.values[i] = static_cast<std::uint32_t>(raw->values[i]);  // unsigned types only
  }
  return out;
}

}  // namespace proxygi::anim::detail
