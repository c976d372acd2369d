// import_gltf: tinygltf parses (sandboxed file access, images kept encoded), then the import
// steps convert and validate everything into a Character. Errors get the file name prefix here.
#include "anim/gltf_import.h"

#include <climits>
#include <cstring>
#include <exception>
#include <string_view>

#include "anim/import_context.h"
#include "anim/import_sandbox.h"
#include "base/atomic_file.h"
#include "base/log.h"

namespace proxygi::anim {
namespace {

using detail::ImportContext;

// tinygltf image callback: keeps data: URI bytes encoded for our own decoder. bufferView images
// are read later through the checked bufferView path (tinygltf does not bound-check that view).
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
  if (image->bufferView >= 0) return true;
  if (bytes == nullptr || size <= 0) return false;
  image->image.assign(bytes, bytes + size);
  return true;
}

// tinygltf's multi-line error text as one line.
std::string one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (char& c : text) {
    if (c == '\n') c = ';';
  }
  return text.empty() ? "tinygltf could not parse the file" : text;
}

// Extensions that change how data must be read are refused; others only add information.
Status check_required_extensions(const tinygltf::Model& model) {
  for (const std::string& name : model.extensionsRequired) {
    if (name.rfind("KHR_materials_", 0) == 0 || name == "KHR_texture_transform") continue;
    return make_error("requires extension " + name + ", which proxygi does not support");
  }
  return {};
}

Status check_counts(const tinygltf::Model& model, std::uint32_t limit) {
  const std::pair<const char*, std::size_t> counts[] = {
      {"nodes", model.nodes.size()},         {"meshes", model.meshes.size()},
      {"skins", model.skins.size()},         {"materials", model.materials.size()},
      {"images", model.images.size()},       {"textures", model.textures.size()},
      {"animations", model.animations.size()}, {"accessors", model.accessors.size()},
      {"bufferViews", model.bufferViews.size()}, {"buffers", model.buffers.size()}};
  for (const auto& [name, count] : counts) {
    if (count > limit) {
      return make_error(std::to_string(count) + " " + name + " exceed the limit of " + std::to_string(limit));
    }
  }
  return {};
}

Result<Character> convert(ImportContext& ctx) {
  PROXYGI_IMPORT_TRY(check_required_extensions(ctx.model));
  PROXYGI_IMPORT_TRY(check_counts(ctx.model, ctx.limits.max_objects));
  Character character;
  PROXYGI_IMPORT_TRY(detail::import_hierarchy(ctx, character));
  PROXYGI_IMPORT_TRY(detail::import_materials(ctx, character));
  PROXYGI_IMPORT_TRY(detail::import_meshes(ctx, character));
  PROXYGI_IMPORT_TRY(detail::import_skins(ctx, character));
  PROXYGI_IMPORT_TRY(detail::import_animations(ctx, character));
  return character;
}

}  // namespace

namespace detail {

Status load_model(std::span<const std::uint8_t> bytes, const std::filesystem::path& base_dir, const ImportLimits& limits,
                  tinygltf::Model& model, std::filesystem::path& root, std::string& warning) {
  if (bytes.size() > limits.max_file_bytes || bytes.size() > UINT_MAX) {
    return make_error("file of " + settings::readable_bytes(bytes.size()) + " exceeds the limit of " +
                      settings::readable_bytes(limits.max_file_bytes));
  }
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  root.clear();
  if (!base_dir.empty()) {
    std::error_code error;
    root = std::filesystem::weakly_canonical(std::filesystem::absolute(base_dir, error), error);
    if (error) root.clear();
  }
  const std::string_view json =
      binary ? detail::glb_json_chunk(bytes.data(), bytes.size())
             : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  PROXYGI_IMPORT_TRY(detail::check_uris(json, root));

  detail::Sandbox sandbox{root, limits.max_file_bytes};
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_encoded_image, nullptr);
  loader.SetFsCallbacks(detail::sandbox_callbacks(&sandbox));
  std::string error;
  // Never an empty base dir: tinygltf would then resolve URIs against the process's CWD.
  const std::string tinygltf_base = root.empty() ? std::string("/nonexistent-proxygi-sandbox") : root.string();
  bool loaded = false;
  try {
    const auto length = static_cast<unsigned int>(bytes.size());
    loaded = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), length, tinygltf_base)
                    : loader.LoadASCIIFromString(&model, &error, &warning,
                                                 reinterpret_cast<const char*>(bytes.data()), length,
                                                 tinygltf_base);
  } catch (const std::exception& exception) {
    return make_error(std::string("tinygltf: ") + exception.what());
  }
  // tinygltf 2.7 writes an error for a skin without inverseBindMatrices yet succeeds: only the
  // return value decides.
  if (!loaded) return make_error(one_line(error));
  return {};
}

}  // namespace detail

namespace {

Result<Character> import_unprefixed(std::span<const std::uint8_t> bytes, const std::filesystem::path& base_dir,
                                    const ImportLimits& limits) {
  tinygltf::Model model;
  std::filesystem::path root;
  std::string warning;
  PROXYGI_IMPORT_TRY(detail::load_model(bytes, base_dir, limits, model, root, warning));
  if (!warning.empty()) log_debug("tinygltf: " + one_line(warning));
  ImportContext ctx{model, limits, root};
  return convert(ctx);
}

}  // namespace

Result<Character> import_gltf_bytes(std::span<const std::uint8_t> bytes, const std::string& name,
                                    const std::filesystem::path& base_dir, const ImportLimits& limits) {
  auto character = import_unprefixed(bytes, base_dir, limits);
  if (!character) return make_error(name + ": " + character.message());
  character->source = name;
  return character;
}

Result<Character> import_gltf(const std::filesystem::path& path, const ImportLimits& limits) {
  auto bytes = read_file(path, limits.max_file_bytes);
  if (!bytes) return bytes.error();
  std::filesystem::path folder = path.parent_path();
  if (folder.empty()) folder = ".";
  return import_gltf_bytes(*bytes, path.string(), folder, limits);
}

}  // namespace proxygi::anim
