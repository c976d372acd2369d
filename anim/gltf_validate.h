#pragma once
// glTF validation in the style of the Khronos glTF-Validator: every problem found in a file, not
// only the first one the importer stops at, each with a severity, a JSON-pointer-like path into
// the file ("/accessors/3", "/meshes/0/primitives/1/attributes/WEIGHTS_0") and a message.
//
//   auto report = proxygi::anim::validate_gltf("hero.glb");
//   for (const auto& issue : report.issues) print(issue.severity, issue.pointer, issue.message);
//   return report.errors() > 0 ? 2 : 0;
//
// Errors: what the importer refuses or the glTF spec forbids — the file cannot be parsed or read
// within the limits; an index out of range (node, mesh, skin, accessor, bufferView, buffer,
// material, texture, image, sampler); a node with two parents or in a cycle; an accessor that does
// not fit its bufferView or buffer, holds NaN/Inf, or whose min/max differ from its data; vertex
// indices >= the vertex count; attributes of one primitive with different counts; skin weights
// whose sum differs from 1; joint indices >= the joint count of a skin the mesh is drawn with;
// inverse bind matrices not one per joint or not invertible; key times not strictly increasing;
// sampler outputs not matching their inputs; non-triangle primitives (proxygi draws triangles).
// Warnings: what renders, but may not be what the author meant — tinygltf's warnings, nodes
// without a name or sharing one (rigs bind by index, people read names), skins without inverse
// bind matrices (identity is assumed).
// If the importer refuses the file for a reason none of the checks names, that reason is listed
// as an error too, so a file without errors always imports.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "anim/gltf_import.h"

namespace proxygi::anim {

struct ValidationIssue {
  enum class Severity { error, warning };
  Severity severity = Severity::error;
  std::string pointer;  // JSON pointer into the file, "" for the file as a whole
  std::string message;
};

struct ValidationReport {
  std::string source;  // the file as named
  std::vector<ValidationIssue> issues;  // by check: file, references, nodes, accessors, primitives, skins, animations
  std::size_t errors() const;
  std::size_t warnings() const;
};

const char* severity_name(ValidationIssue::Severity severity);  // "error", "warning"

ValidationReport validate_gltf(const std::filesystem::path& path, const ImportLimits& limits = {});

}  // namespace proxygi::anim
