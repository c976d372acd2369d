// The one translation unit that compiles tinygltf (Debian's header, v2.7.0). Image decoding and
// writing are off: tinygltf only hands over the encoded bytes, which anim/ decodes with stb under
// its own size limits (tinygltf's built-in stb path has known CVEs; see notes/gltf-conformance.md).
// No tinygltf type leaves anim/.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_USE_CPP14
#include <tiny_gltf.h>
