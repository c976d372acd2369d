#pragma once
// Writes DIR/defects.glb: the mannequin as the glTF writer writes it, with defects injected into
// its JSON and binary chunks (write_defects.cpp), and DIR/defects.expected: one line per defect,
// "<severity> <JSON pointer>", that `proxygi info --validate` must list.
#include <filesystem>
#include <string>

// Returns an empty string on success, else what failed.
std::string write_defects(const std::filesystem::path& dir);
