#pragma once
// Private to the importer: the one checked view through which every accessor is read. It checks
// the accessor against its bufferView and buffer with 64-bit offset math, honours byteStride,
// reads bufferView-less accessors as zeros, applies sparse substitutions (indices strictly
// increasing and < count), decodes normalized integers (glTF "animations" decode table) and
// refuses NaN/Inf. Errors read "<what>: accessor <i>: <problem>".
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "anim/import_context.h"

namespace proxygi::anim::detail {

struct FloatAccessor {
  std::vector<float> values;  // count * components, element-major
  std::size_t count = 0;
  int components = 0;
};

struct UintAccessor {
  std::vector<std::uint32_t> values;  // count * components
  std::size_t count = 0;
  int components = 0;
};

// Floats from FLOAT components, or from the integer component types listed in
// `component_types` when the accessor is normalized. `types` are TINYGLTF_TYPE_* values.
Result<FloatAccessor> read_float_accessor(ImportContext& ctx, int accessor, const std::string& what,
                                          const std::vector<int>& types,
                                          const std::vector<int>& component_types);

// Unsigned integers (not normalized) of the listed component types.
Result<UintAccessor> read_uint_accessor(ImportContext& ctx, int accessor, const std::string& what,
                                        const std::vector<int>& types,
                                        const std::vector<int>& component_types);

// The bytes of bufferView `view` after checking it against its buffer (images use this).
Result<std::span<const std::uint8_t>> buffer_view_bytes(const ImportContext& ctx, int view,
                                                        const std::string& what);

std::string component_type_name(int component_type);
std::string type_name(int type);

}  // namespace proxygi::anim::detail
