// glTF writer: Character → tinygltf::Model → bytes. tinygltf stays inside this file.
#include "anim/gltf_writer.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

// Same configuration as anim/tinygltf_implementation.cpp (images never decoded or encoded by
// tinygltf: the writer embeds its own PNG bytes through a bufferView).
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_USE_CPP14
#include <tiny_gltf.h>

#include "base/atomic_file.h"

namespace proxygi::anim {
namespace {

// ---- Minimal PNG encoder: RGBA8, filter 0, zlib "stored" (uncompressed) deflate blocks. ----

std::uint32_t crc32(const std::uint8_t* data, std::size_t size, std::uint32_t crc = 0) {
  crc = ~crc;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

void put_be32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

void put_chunk(std::vector<std::uint8_t>& png, const char type[4], const std::vector<std::uint8_t>& data) {
  put_be32(png, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = png.size();
  png.insert(png.end(), type, type + 4);
  png.insert(png.end(), data.begin(), data.end());
  put_be32(png, crc32(png.data() + start, png.size() - start));
}

std::vector<std::uint8_t> encode_png(const Image& image) {
  const std::size_t row = static_cast<std::size_t>(image.width) * 4;
  std::vector<std::uint8_t> raw;  // each scanline prefixed by filter type 0
  raw.reserve((row + 1) * static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y) {
    raw.push_back(0);
    const std::uint8_t* line = image.rgba.data() + static_cast<std::size_t>(y) * row;
    raw.insert(raw.end(), line, line + row);
  }
  std::vector<std::uint8_t> zlib = {0x78, 0x01};
  std::uint32_t a = 1, b = 0;  // Adler-32
  for (const std::uint8_t byte : raw) {
    a = (a + byte) % 65521u;
    b = (b + a) % 65521u;
  }
  for (std::size_t offset = 0; offset < raw.size() || offset == 0; offset += 65535) {
    const std::size_t length = std::min<std::size_t>(65535, raw.size() - offset);
    zlib.push_back(offset + length >= raw.size() ? 1 : 0);  // BFINAL, BTYPE = 00
    zlib.push_back(static_cast<std::uint8_t>(length));
    zlib.push_back(static_cast<std::uint8_t>(length >> 8));
    zlib.push_back(static_cast<std::uint8_t>(~length));
    zlib.push_back(static_cast<std::uint8_t>(~length >> 8));
    zlib.insert(zlib.end(), raw.begin() + static_cast<std::ptrdiff_t>(offset),
                raw.begin() + static_cast<std::ptrdiff_t>(offset + length));
    if (raw.empty()) break;
  }
  put_be32(zlib, (b << 16) | a);

  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<std::uint8_t> header;
  put_be32(header, static_cast<std::uint32_t>(image.width));
  put_be32(header, static_cast<std::uint32_t>(image.height));
  header.insert(header.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, filter 0, no interlace
  put_chunk(png, "IHDR", header);
  put_chunk(png, "IDAT", zlib);
  put_chunk(png, "IEND", {});
  return png;
}

// ---- Model building ----

class ModelBuilder {
 public:
  explicit ModelBuilder(tinygltf::Model& model) : model_(model) { model_.buffers.emplace_back(); }

  // Appends bytes as a new bufferView (4-byte aligned) and returns its index.
  int add_view(const void* data, std::size_t size, int target) {
    std::vector<unsigned char>& bytes = model_.buffers[0].data;
    bytes.resize((bytes.size() + 3) & ~std::size_t{3}, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = bytes.size();
    view.byteLength = size;
    view.target = target;
    const auto* first = static_cast<const unsigned char*>(data);
    bytes.insert(bytes.end(), first, first + size);
    model_.bufferViews.push_back(view);
    return static_cast<int>(model_.bufferViews.size()) - 1;
  }

  // Float accessor of `count` elements of `type` (components each); min/max when asked.
  int add_floats(const float* data, std::size_t count, int type, int components, int target, bool bounds) {
    tinygltf::Accessor accessor;
    accessor.bufferView = add_view(data, count * static_cast<std::size_t>(components) * sizeof(float), target);
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.count = count;
    accessor.type = type;
    if (bounds && count > 0) {
      accessor.minValues.assign(static_cast<std::size_t>(components), std::numeric_limits<double>::max());
      accessor.maxValues.assign(static_cast<std::size_t>(components), std::numeric_limits<double>::lowest());
      for (std::size_t i = 0; i < count; ++i) {
        for (std::size_t c = 0; c < static_cast<std::size_t>(components); ++c) {
          const double v = data[i * static_cast<std::size_t>(components) + c];
          accessor.minValues[c] = std::min(accessor.minValues[c], v);
          accessor.maxValues[c] = std::max(accessor.maxValues[c], v);
        }
      }
    }
    model_.accessors.push_back(accessor);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  int add_integers(const void* data, std::size_t count, int component_type, std::size_t component_size, int type,
                   int components, int target) {
    tinygltf::Accessor accessor;
    accessor.bufferView = add_view(data, count * static_cast<std::size_t>(components) * component_size, target);
    accessor.componentType = component_type;
    accessor.count = count;
    accessor.type = type;
    model_.accessors.push_back(accessor);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

 private:
  tinygltf::Model& model_;
};

std::vector<double> to_doubles(const float* data, std::size_t count) { return std::vector<double>(data, data + count); }

bool is_identity(const glm::mat4& m) { return m == glm::mat4(1.0f); }

const char* interpolation_name(Interpolation interpolation) {
  switch (interpolation) {
    case Interpolation::step: return "STEP";
    case Interpolation::linear: return "LINEAR";
    case Interpolation::cubic_spline: return "CUBICSPLINE";
  }
  return "LINEAR";
}

const char* path_name(ChannelPath path) {
  switch (path) {
    case ChannelPath::translation: return "translation";
    case ChannelPath::rotation: return "rotation";
    case ChannelPath::scale: return "scale";
    case ChannelPath::weights: return "weights";
  }
  return "translation";
}

void add_primitive(ModelBuilder& builder, const Primitive& primitive, tinygltf::Primitive& out) {
  const std::size_t count = primitive.positions.size();
  out.mode = TINYGLTF_MODE_TRIANGLES;
  out.material = primitive.material;
  out.attributes["POSITION"] = builder.add_floats(&primitive.positions[0].x, count, TINYGLTF_TYPE_VEC3, 3,
                                                  TINYGLTF_TARGET_ARRAY_BUFFER, true);
  if (!primitive.normals.empty()) {
    out.attributes["NORMAL"] = builder.add_floats(&primitive.normals[0].x, count, TINYGLTF_TYPE_VEC3, 3,
                                                  TINYGLTF_TARGET_ARRAY_BUFFER, false);
  }
  if (!primitive.uvs.empty()) {
    out.attributes["TEXCOORD_0"] = builder.add_floats(&primitive.uvs[0].x, count, TINYGLTF_TYPE_VEC2, 2,
                                                      TINYGLTF_TARGET_ARRAY_BUFFER, false);
  }
  // Influences in sets of four (JOINTS_n / WEIGHTS_n), zero-padded.
  const std::size_t influences = static_cast<std::size_t>(std::max(primitive.influences_per_vertex, 0));
  for (std::size_t set = 0; set * 4 < influences; ++set) {
    std::vector<std::uint16_t> joints(count * 4, 0);
    std::vector<float> weights(count * 4, 0.0f);
    for (std::size_t v = 0; v < count; ++v) {
      for (std::size_t k = 0; k < 4 && set * 4 + k < influences; ++k) {
        joints[v * 4 + k] = primitive.joints[v * influences + set * 4 + k];
        weights[v * 4 + k] = primitive.weights[v * influences + set * 4 + k];
      }
    }
    out.attributes["JOINTS_" + std::to_string(set)] =
        builder.add_integers(joints.data(), count, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, sizeof(std::uint16_t),
                             TINYGLTF_TYPE_VEC4, 4, TINYGLTF_TARGET_ARRAY_BUFFER);
    out.attributes["WEIGHTS_" + std::to_string(set)] =
        builder.add_floats(weights.data(), count, TINYGLTF_TYPE_VEC4, 4, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  }
  out.indices = builder.add_integers(primitive.indices.data(), primitive.indices.size(),
                                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, sizeof(std::uint32_t), TINYGLTF_TYPE_SCALAR,
                                     1, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  for (const MorphTarget& target : primitive.morph_targets) {
    std::map<std::string, int> attributes;
    if (!target.position_deltas.empty()) {
      attributes["POSITION"] = builder.add_floats(&target.position_deltas[0].x, count, TINYGLTF_TYPE_VEC3, 3,
                                                  TINYGLTF_TARGET_ARRAY_BUFFER, true);
    }
    if (!target.normal_deltas.empty()) {
      attributes["NORMAL"] = builder.add_floats(&target.normal_deltas[0].x, count, TINYGLTF_TYPE_VEC3, 3,
                                                TINYGLTF_TARGET_ARRAY_BUFFER, false);
    }
    out.targets.push_back(std::move(attributes));
  }
}

Result<tinygltf::Model> build_model(const Character& character) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "proxygi";
  ModelBuilder builder(model);

  for (const Node& node : character.nodes) {
    tinygltf::Node out;
    out.name = node.name;
    out.children = node.children;
    out.mesh = node.mesh;
    out.skin = node.skin;
    out.weights = std::vector<double>(node.morph_weights.begin(), node.morph_weights.end());
    if (node.matrix) {
      out.matrix = to_doubles(&(*node.matrix)[0][0], 16);
    } else {
      const Transform& t = node.rest;
      if (t.translation != glm::vec3(0.0f)) out.translation = to_doubles(&t.translation.x, 3);
      if (t.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) out.rotation = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
      if (t.scale != glm::vec3(1.0f)) out.scale = to_doubles(&t.scale.x, 3);
    }
    model.nodes.push_back(std::move(out));
  }
  tinygltf::Scene scene;
  scene.nodes = character.roots;
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  for (std::size_t m = 0; m < character.meshes.size(); ++m) {
    const Mesh& mesh = character.meshes[m];
    tinygltf::Mesh out;
    out.name = mesh.name;
    out.weights = std::vector<double>(mesh.default_morph_weights.begin(), mesh.default_morph_weights.end());
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const Primitive& primitive = mesh.primitives[p];
      const std::size_t slots = primitive.positions.size() * static_cast<std::size_t>(std::max(primitive.influences_per_vertex, 0));
      if (primitive.positions.empty() || primitive.joints.size() != slots || primitive.weights.size() != slots ||
          (!primitive.normals.empty() && primitive.normals.size() != primitive.positions.size()) ||
          (!primitive.uvs.empty() && primitive.uvs.size() != primitive.positions.size())) {
        return make_error(character.source + ": mesh " + std::to_string(m) + " primitive " + std::to_string(p) +
                          ": attribute sizes are inconsistent");
      }
      out.primitives.emplace_back();
      add_primitive(builder, primitive, out.primitives.back());
    }
    model.meshes.push_back(std::move(out));
  }

  for (const Material& material : character.materials) {
    tinygltf::Material out;
    out.name = material.name;
    out.doubleSided = material.double_sided;
    const glm::vec4& c = material.base_color_factor;
    out.pbrMetallicRoughness.baseColorFactor = {c.r, c.g, c.b, c.a};
    // Character has no metal/roughness: proxygi shades every surface as diffuse.
    out.pbrMetallicRoughness.metallicFactor = 0.0;
    out.pbrMetallicRoughness.roughnessFactor = 1.0;
    if (material.base_color_image >= 0) {
      out.pbrMetallicRoughness.baseColorTexture.index = material.base_color_image;  // texture i ↔ image i
      out.pbrMetallicRoughness.baseColorTexture.texCoord = material.base_color_texcoord;
    }
    model.materials.push_back(std::move(out));
  }
  for (std::size_t i = 0; i < character.images.size(); ++i) {
    const Image& image = character.images[i];
    tinygltf::Image out;
    out.name = image.name;
    out.mimeType = "image/png";
    Image blank;  // images the importer left undecoded become one white pixel
    blank.width = blank.height = 1;
    blank.rgba = {255, 255, 255, 255};
    const bool decoded = image.width > 0 && image.height > 0 &&
                         image.rgba.size() == static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4;
    const std::vector<std::uint8_t> png = encode_png(decoded ? image : blank);
    out.bufferView = builder.add_view(png.data(), png.size(), 0);
    model.images.push_back(std::move(out));
    tinygltf::Texture texture;
    texture.source = static_cast<int>(i);
    model.textures.push_back(texture);
  }

  for (const Skin& skin : character.skins) {
    tinygltf::Skin out;
    out.name = skin.name;
    out.joints = skin.joints;
    out.skeleton = skin.skeleton;
    // All-identity inverse binds are left out: glTF reads a missing accessor as identities.
    if (!std::all_of(skin.inverse_bind_matrices.begin(), skin.inverse_bind_matrices.end(), is_identity)) {
      if (skin.inverse_bind_matrices.size() != skin.joints.size()) {
        return make_error(character.source + ": skin '" + skin.name + "': inverse bind matrix count differs from joints");
      }
      out.inverseBindMatrices = builder.add_floats(&skin.inverse_bind_matrices[0][0][0], skin.joints.size(),
                                                   TINYGLTF_TYPE_MAT4, 16, 0, false);
    }
    model.skins.push_back(std::move(out));
  }

  for (const Clip& clip : character.clips) {
    tinygltf::Animation out;
    out.name = clip.name;
    for (const Channel& channel : clip.channels) {
      const std::size_t keys = channel.times.size();
      const std::size_t per_key = static_cast<std::size_t>(channel.components) *
                                  (channel.interpolation == Interpolation::cubic_spline ? 3u : 1u);
      if (keys == 0 || channel.values.size() != keys * per_key) {
        return make_error(character.source + ": clip '" + clip.name + "': channel values do not match its keys");
      }
      tinygltf::AnimationSampler sampler;
      sampler.interpolation = interpolation_name(channel.interpolation);
      sampler.input = builder.add_floats(channel.times.data(), keys, TINYGLTF_TYPE_SCALAR, 1, 0, true);
      const int type = channel.path == ChannelPath::rotation ? TINYGLTF_TYPE_VEC4
                       : channel.path == ChannelPath::weights ? TINYGLTF_TYPE_SCALAR
                                                               : TINYGLTF_TYPE_VEC3;
      const int components = channel.path == ChannelPath::weights ? 1 : channel.components;
      sampler.output = builder.add_floats(channel.values.data(), channel.values.size() / static_cast<std::size_t>(components),
                                          type, components, 0, false);
      out.samplers.push_back(sampler);
      tinygltf::AnimationChannel target;
      target.sampler = static_cast<int>(out.samplers.size()) - 1;
      target.target_node = channel.node;
      target.target_path = path_name(channel.path);
      out.channels.push_back(target);
    }
    model.animations.push_back(std::move(out));
  }
  model.buffers[0].data.resize((model.buffers[0].data.size() + 3) & ~std::size_t{3}, 0);
  if (model.buffers[0].data.empty()) model.buffers.clear();  // glTF forbids zero-length buffers
  return model;
}

Result<std::string> encode(const Character& character, bool binary) {
  Result<tinygltf::Model> model = build_model(character);
  if (!model) return model.error();
  tinygltf::TinyGLTF writer;
  std::ostringstream stream;
  if (!writer.WriteGltfSceneToStream(&*model, stream, /*prettyPrint=*/!binary, binary)) {
    return make_error(character.source + ": tinygltf failed to serialize the model");
  }
  return stream.str();
}

Status write_encoded(const Character& character, const std::filesystem::path& path, bool binary) {
  Result<std::string> bytes = encode(character, binary);
  if (!bytes) return bytes.error();
  return write_file_atomically(path, std::string_view(*bytes));
}

}  // namespace

Result<std::vector<std::uint8_t>> encode_glb(const Character& character) {
  Result<std::string> bytes = encode(character, true);
  if (!bytes) return bytes.error();
  return std::vector<std::uint8_t>(bytes->begin(), bytes->end());
}

Status write_glb(const Character& character, const std::filesystem::path& path) {
  return write_encoded(character, path, true);
}

Status write_gltf(const Character& character, const std::filesystem::path& path) {
  return write_encoded(character, path, false);
}

Status write_character(const Character& character, const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".glb") return write_glb(character, path);
  if (extension == ".gltf") return write_gltf(character, path);
  return make_error(path.string() + ": unknown glTF extension '" + extension + "' (use .glb or .gltf)");
}

}  // namespace proxygi::anim
